/* carry.h - carrying a held object in (x, y, theta): Utak and what he holds as one
 * rigid body on an occupancy grid (paper 2.2: push and turn; 3.6: planning on the
 * screen; 5: the open problem of the L-shaped object in a doorway; the abstract:
 * object-moving on "the skeleton of the shape of empty space and of the shape of
 * the moved object").
 *
 * THE BODY. While Utak holds an object, `push` translates him and it together and
 * `turn` rotates the object about his point, which stays put (impression.h,
 * motion.c). So the body has three degrees of freedom: Utak's point (x, y) and the
 * object's angle theta, counter-clockwise from the pose it had when the plan began.
 * The grid is the controller's screen (or any occupancy grid; grid.h: cell (x, y)
 * is the square [x, x+1] x [y, y+1]); its axes are Utak's frame (x to his right, y
 * ahead), so a displacement on it is a push command as it stands. The cells the
 * held object now covers, and Utak's own, must be marked free in it: they move
 * with him (the controller's cspace_of does the same).
 *
 * CONFIGURATIONS (the lattice). Utak's point at p0 + (i, j) for whole i, j, where p0
 * is his point now (so the lattice keeps his offset inside his square, and every
 * lattice point is his point moved by whole squares), times N angles (params.angles,
 * N a multiple of 4, at most 360, CARRY_ANGLES_DEFAULT by default): angle k is the
 * whole number of degrees nearest k 360 / N, so every turn is a whole number of
 * degrees and the quarter turns are among the angles. The body at (i, j, k) is the
 * object turned by angle k about Utak's point, placed there, plus Utak's square;
 * its cells are its FOOTPRINT, by the TABLE's rule (sweep.h, geom_project: a square
 * is covered when its open interior meets the closed polygon), the same for every
 * (i, j), so each angle's slice of the configuration space is the grid eroded by
 * one footprint (cspace.c's erosion), evaluated lazily, cell by cell, as the search
 * asks.
 *
 * EXACT AND TOLERANT POSES. The simulator turns an object from where it is, not
 * from where it began, so after a turn that is not a whole quarter its vertices
 * differ from the planner's by rounding (~1e-13), and an edge the planner puts on
 * a grid line may lie a hair beyond it and cover one more row of squares. So each
 * configuration is EXACT (the object has been turned by whole quarter turns only:
 * geom_cos_sin is exact there, and pushes by whole squares are exact, so the
 * simulator's vertices are the planner's bit for bit, and the TABLE's rule applies
 * as it stands) or TOLERANT (covered within SWEEP_EPS: rounding cannot uncover
 * anything). The start is exact unless params.exact_start is false.
 *
 * MOVES. A push of one square along an axis (from any configuration to the same
 * kind; the body's sweep over one square is exactly the union of its two
 * footprints); a turn of one angle step about Utak's point, allowed when the whole
 * swept area is free, checked by samples no point of the object travels more than
 * SWEEP_TRAVEL (a quarter square) between, each covered within half that travel,
 * so the check is conservative for the continuous turn, which contains every pose
 * motion.c samples (sweep.h); a turn step always leads to a tolerant
 * configuration, except that from an exact one a whole quarter turn (N / 4 steps,
 * each step's sweep free) leads to the exact one. Costs: CARRY_UNIT per square
 * pushed; a turn step CARRY_UNIT x (the distance the object's farthest point
 * travels, in squares) x params.turn_weight, rounded, at least 1.
 *
 * SEARCH. A* over the lattice (Hart, Nilsson and Raphael 1968) with the admissible
 * and consistent estimate CARRY_UNIT x (the 4-connected steps from Utak's cell to
 * the nearest cell from which the object could lie in the goal, through cells free
 * for his square); ties go to the deeper state, then to the heap's fixed order, so
 * the same input gives the same plan. It is exhaustive: when no goal configuration
 * is reachable on the lattice, every reachable one has been expanded, and the
 * answer is CARRY_NO_PATH with the reason in words. It never gives up on a budget.
 *
 * PRUNING (params.use_route, use_clearance, use_disc; all on by default), by the
 * skeleton of empty space and the shape of the object (the abstract's proposal).
 * The object's shape gives its reach (its farthest point from Utak's point, about
 * which every turn goes) and a disc inside it (the largest found on a grid of
 * samples: a lower bound on any doorway it passes). (1) The route: on the
 * skeleton's pathgraph of the grid (skeleton.h, pathgraph.h, paper 4.3), the
 * shortest way from Utak to the deepest cell of the goal region over skeleton edges
 * wide enough for that disc: which door, which corridor. The search first runs in a
 * corridor of Utak cells within reach + CARRY_CORRIDOR_MARGIN of the route; only if
 * that finds nothing does it go on, so the pruning never loses a path (and a plan
 * found in the corridor can cost more than the best). (2) The clearance: where the
 * distance transform shows no blocked square within the reach (plus the sweeps'
 * thickening) of Utak's point, every angle and every turn is free, and no footprint
 * is tested. (3) The disc: before the whole grid is searched, if that disc cannot
 * slide from where it is to anywhere it would lie wholly in the goal region
 * (8-connected cells, on a grid twice as fine, where an upper bound of the free
 * space's clearance reaches its radius), no carry exists: a proof, sound for any
 * shape, that ends the exhaustive search before it starts. (The hull's narrowest
 * width proves nothing: an L-shape passes doors narrower than its hull.)
 * CarryStats says what happened; `make bench-carry` measures what each saves.
 *
 * THE PLAN (carrypath.c). The lattice path is cut into pushes (one angle) and turns
 * (one place).
 * Turns are merged where a turn, a push and a turn can become one turn before or
 * after the push (fewest turns; greedy, so not always the least number), then each
 * run of pushes is shortened by string pulling: from each waypoint, the farthest
 * later cell of the run reached by one straight push whose whole swept area is
 * free (sweep_cover_push: exact; tolerant for a push along neither axis, whose
 * intermediate poses the simulator rounds) and whose path for Utak's point is free.
 * (rope.c's funnel is not used: its bends fall on cell corners, where the object's
 * footprint is not the lattice's.) The result is a list of poses and the motor
 * commands between them: MOTOR_PUSH with (dx, dy) in grid units (Utak's frame) and
 * MOTOR_TURN with a whole number of degrees, counter-clockwise positive, each
 * taking the body exactly from one checked pose to the next. Every pose, sweep
 * and push of it has been checked against the grid.
 *
 * REASONS, when no path exists, in this order: the start does not fit (a square
 * the object or Utak covers is not free); the goal region has no free square, or
 * no room for the object at any angle; Utak's square cannot reach it at all; the
 * object is wider at its narrowest (the least width of its convex hull) than the
 * widest axis-aligned square that can slide from the object's squares to the goal
 * region (for a door along the axes, its width): "the L-shaped object is 5.0 wide at
 * its narrowest, the way to the goal region 4.0 at its narrowest"; else it is
 * narrow enough but no way at N angles turns it through. (The width compared is
 * only the explanation; what decides is the exhaustive search or the disc's proof.)
 *
 * USE (the controller, the mind's side: it needs no more than the screen).
 *  1. The grid: the screen's free cells, the held object's cells and Utak's square
 *     freed, the squares bumped into blocked (as cspace_of builds it); the goal
 *     region: a grid of the same size (e.g. the cells of the other room, or those
 *     past the door, or those of the far leg of the corridor), and accept for
 *     anything more (e.g. which way the object must face).
 *  2. The object: a simple polygon in screen units, as believed (e.g. the outline of
 *     its squares; at most GEOM_MAX_VERTICES points), and Utak's point in screen
 *     units (the model point less the screen's origin: the fraction inside his
 *     square is kept). exact_start says whether those coordinates are the
 *     simulator's to the bit; the controller's are estimates, so it may leave it on
 *     (a tolerant start only makes the plan keep a hair further from the walls).
 *  3. Before grasping: carry_grasp over the free cells beside the object (a grasp
 *     decides the centre of every turn): the cheapest grasp from which the whole
 *     carry exists, with its plan. When none serves, plan a release and a re-grasp:
 *     carry from a grasp that serves part of the way to an intermediate goal (a
 *     region, or accept: a pose from which another grasp's carry exists), release,
 *     and carry_grasp again from there.
 *  4. While carrying: issue plan.cmd[i] one at a time (MOTOR_PUSH dx dy and
 *     MOTOR_TURN deg as they stand); after each the body should be at plan.pose[i+1],
 *     which the viability check (steps 12-13) compares with the world model, and
 *     plans again (carry_init on the new screen) when they disagree or a command
 *     halts. carry_plan_print gives the lines for the trace.
 *  5. The tasks: "in the next room" and "through the door" are goal regions;
 *     carry_pose_inside judges a believed pose against a region off the lattice.
 *
 * MEMORY. A CarryPlanner owns its working space (util_alloc): per grid cell about
 * 25 bytes of caches (the skeleton's and pathgraph's too, once a route is sought),
 * and per configuration (N + 4 per cell) 7 bytes, allocated zeroed and touched only
 * where the search goes (a 512 x 512 screen at 64 angles: 125 MB of address space,
 * of which a carry touches the pages its search reaches); the disc's proof 18 bytes per grid cell for
 * its duration. Freed by carry_free. A plan's arrays are its CarryResult's
 * (carry_result_free).
 * COMPLEXITY: O(C log C) for the C configurations the search reaches, each checked
 * in O(R) for a footprint of R row runs; O(N (S n + A)) to build the footprints of
 * an object of n vertices, perimeter S and area A squares, with S samples per turn
 * step; the route and the disc O(w h).
 * MEASURED (make bench-carry, README.md): at 64 angles, 1.5 to 7.5 ms for a carry on
 * a 128 x 128 screen, 19 to 65 ms on 512 x 512; impossible ones 1.6 to 59 ms with
 * the disc's proof, 2.2 s at 512 x 512 without it (an exhaustive search). */
#ifndef UTAK_CARRY_H
#define UTAK_CARRY_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/base/geom.h"
#include "utak/impression.h"
#include "utak/plan/grid.h"

/* 72 angles: 5 degrees apart, so every angle is a whole number of degrees and one
 * step moves a point 3 squares from the pivot by a quarter square. */
#define CARRY_ANGLES_DEFAULT 72
#define CARRY_ANGLES_MAX 360
/* The cost of pushing one square; a fine unit, so that a turn's cost (a fraction of
 * a square of travel) is not lost to rounding. */
#define CARRY_UNIT 64
/* Utak cells within the object's reach plus this many squares of the skeleton
 * route form the pruned search's corridor: room to step aside to turn. */
#define CARRY_CORRIDOR_MARGIN 3.0
/* Room for the reason of a failure, in characters. */
#define CARRY_WHY 256

typedef struct CarryParams {
	int32_t angles;		/* N: a multiple of 4, 4..CARRY_ANGLES_MAX */
	double turn_weight;	/* a square of the far end's travel costs this many pushed squares */
	bool exact_start;	/* the object's coordinates are exactly the simulator's (see above) */
	bool use_route;		/* prune by the skeleton route first (see PRUNING) */
	bool use_clearance;	/* settle configurations by clearance (see PRUNING) */
	bool use_disc;		/* prove impossibility by the inscribed disc (see PRUNING) */
} CarryParams;

/* carry_params_default(): N = CARRY_ANGLES_DEFAULT, turn_weight 1, exact start,
 * both prunings on. */
CarryParams carry_params_default(void);

/* One configuration of the body, as the plan reports it. */
typedef struct CarryPose {
	Vec2 at;	/* Utak's point, grid units */
	int32_t x, y;	/* his cell: floor(at) */
	int32_t deg;	/* the object's angle, whole degrees counter-clockwise, 0..359 */
	bool exact;	/* an exact configuration (see above) */
} CarryPose;

/* A goal predicate over configurations, called only for configurations that are
 * free and already wholly inside the goal region (below). */
typedef bool CarryAcceptFn(void *ctx, const CarryPose *pose);

/* The goal: the object wholly inside a region of cells, and optionally more. */
typedef struct CarryGoal {
	const Grid *inside;	/* the grid's size; GRID_FREE marks the goal region */
	bool utak_inside;	/* Utak's own square must lie in the region too */
	CarryAcceptFn *accept;	/* a further condition, or NULL */
	void *ctx;		/* for accept */
} CarryGoal;

/* What is carried: the held object where it stands now, and Utak's point. */
typedef struct CarryObject {
	Polygon shape;		/* grid units: a simple polygon not containing at */
	Vec2 at;		/* Utak's point, grid units */
	const char *name;	/* for reasons, e.g. "the brick"; NULL: "the object" */
} CarryObject;

/* A plan: count poses and count - 1 commands; cmd[i] takes pose[i] to pose[i + 1]. */
typedef struct CarryPlan {
	int count, cap;
	CarryPose *pose;
	MotorCommand *cmd;	/* MOTOR_PUSH (dx, dy grid units) or MOTOR_TURN (deg) */
	int64_t cost;		/* the lattice path's cost, CARRY_UNIT a square */
	double pushed;		/* the pushes' total length, squares */
	int32_t turned;		/* the turns' total, degrees (absolute values) */
	int32_t turns;		/* turn commands */
	int32_t pushes;		/* push commands */
} CarryPlan;

/* What the search did, summed over its runs (route corridor, then whole grid). */
typedef struct CarryStats {
	int64_t expanded;	/* configurations taken from the open list */
	int64_t checked;	/* footprints or sweeps tested against the grid */
	int64_t settled;	/* footprints and sweeps settled free by clearance */
	int32_t searches;	/* 1, or 2 when the corridor search found nothing */
	bool routed;		/* a skeleton route was found for the corridor */
	bool found_in_corridor;	/* the plan came from the corridor search */
	int64_t corridor_cells;	/* Utak cells in the corridor */
	bool disc_proof;	/* no path, proved by the inscribed disc before any search */
} CarryStats;

typedef enum CarryStatus {
	CARRY_FOUND = 0,	/* plan holds a path */
	CARRY_NO_PATH,		/* no path on the lattice; why says why */
	CARRY_BAD_INPUT,	/* a malformed problem (sizes, angles, polygon); why says what */
} CarryStatus;

typedef struct CarryResult {
	CarryStatus status;
	char why[CARRY_WHY];	/* the reason when not CARRY_FOUND, else "" */
	CarryPlan plan;
	CarryStats stats;
	double narrowest;	/* the object's narrowest width, squares */
	double reach;		/* its farthest point from Utak's point, squares */
	double disc;		/* the radius of a disc inside it (the largest found), squares */
	int32_t way;		/* when no path: the widest square (side, squares) that passes
				 * from the object to the goal region; -1 when not measured */
} CarryResult;

/* The planner for one grid: caches of the grid (distance transform, skeleton) and
 * the search's working space, kept between plans. */
typedef struct CarryPlanner {
	const Grid *grid;	/* borrowed: must outlive the planner, unchanged */
	CarryParams params;
	struct CarryWork *work;
} CarryPlanner;

/* carry_init(cp, grid, params): a planner for grid (params NULL: the defaults). */
void carry_init(CarryPlanner *cp, const Grid *grid, const CarryParams *params);
void carry_free(CarryPlanner *cp);

void carry_result_init(CarryResult *r);
void carry_result_free(CarryResult *r);

/* carry_plan(cp, obj, goal, out): the plan that carries obj into goal, as above.
 * out must have been carry_result_init'ed (its arrays are reused, and freed by
 * carry_result_free). goal->accept is called lazily, at most once per free
 * configuration wholly in the region. Returns out->status. */
CarryStatus carry_plan(CarryPlanner *cp, const CarryObject *obj, const CarryGoal *goal,
		       CarryResult *out);

/* How one grasp fares. */
typedef struct CarryGrasp {
	CarryStatus status;	/* CARRY_FOUND: the goal can be reached holding it from here */
	int64_t cost;		/* the plan's cost; INT64_MAX when none */
	int32_t turns;		/* turn commands of the plan */
	char why[CARRY_WHY];	/* why not, when not found */
} CarryGrasp;

/* carry_grasp(cp, shape, at, n, goal, each, best): for an object not yet held
 * (shape, grid units) and n candidate points for Utak (at[i], usually the centres of
 * free cells beside it), plans the carry from each. each[i] (caller's, n of them)
 * says how grasp i fares; best (may be NULL) receives the plan of the cheapest, ties
 * to the lower index. Returns that index, or -1 when no grasp serves. The grid
 * must have the object's cells free, as for a held object. */
int carry_grasp(CarryPlanner *cp, const Polygon *shape, const Vec2 *at, int n, const CarryGoal *goal,
		CarryGrasp *each, CarryResult *best);

/* carry_pose_free(cp, obj, at, deg): the per-configuration check at any pose, on or
 * off the lattice: obj's shape turned by deg degrees about obj->at, then moved with
 * Utak to at, covers only free cells of the grid (the TABLE's rule), and Utak's
 * square is free. */
bool carry_pose_free(const CarryPlanner *cp, const CarryObject *obj, Vec2 at, double deg);

/* carry_pose_inside(obj, region, at, deg): at that pose (as carry_pose_free), every
 * square the object covers is a GRID_FREE cell of region: the object wholly inside
 * it, by the TABLE's rule (the goal test of a CarryGoal, off the lattice). */
bool carry_pose_inside(const CarryObject *obj, const Grid *region, Vec2 at, double deg);

/* carry_command_part(leg, most, part): the next command to give of a plan's command
 * leg, as the action cycle gives them: a push longer than most squares is cut, so
 * that what is seen on the way can change the plan; part gets the first piece and
 * leg keeps the rest. The pieces are whole multiples of 1/CARRY_PART_GRAIN in each
 * axis (rounded from most/|leg| of the leg: within 1/128 of the straight push the
 * planner checked), exact in binary, so that they add up to the leg EXACTLY: the
 * plan's poses are on the lattice, and a square pushed by 1.35 + 1.35 + 1.35 + 0.95
 * ends a rounding error past a grid line, where by the TABLE's rule it meets a row of
 * squares more: one too many for a door just as wide as it. A turn, or a push of at
 * most most squares, is given whole. Returns true when leg is used up. */
#define CARRY_PART_GRAIN 64.0
bool carry_command_part(MotorCommand *leg, double most, MotorCommand *part);

/* carry_plan_print(plan, f): one line per command, "push DX DY" or "turn DEG",
 * then "carry: P pushes (L squares), T turns (D degrees)". */
void carry_plan_print(const CarryPlan *plan, FILE *f);

#endif
