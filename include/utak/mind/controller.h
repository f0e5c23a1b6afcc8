/* controller.h - the robot-controller: Utak's mind and its action cycle (paper 3.1).
 * CONTROLLER SIDE.
 *
 * The controller is handed the first impression, then, each time it decides an
 * action, the impression received when Utak halts; it hands back motor commands.
 * That is all it knows of the world (impression.h). main.c runs the cycle:
 *
 *   controller_start(c, first)           steps 1-7: model, task, plan
 *   while controller_decide(c, &cmd)      steps 8-9: done?  next action
 *       (the simulator carries out cmd)  step 10
 *       controller_perceive(c, &cmd, imp) steps 11-13: accommodate, viable?, re-plan
 */
#ifndef UTAK_CONTROLLER_H
#define UTAK_CONTROLLER_H

#include <stdbool.h>
#include <stdio.h>

#include "utak/impression.h"
#include "utak/plan/path.h"
#include "utak/mind/planner.h"
#include "utak/mind/apart.h"
#include "utak/mind/joined.h"
#include "utak/mind/seam.h"
#include "utak/mind/swing.h"
#include "utak/mind/hallsplit.h"
#include "utak/mind/probe.h"
#include "utak/mind/rival.h"
#include "utak/mind/regions.h"
#include "utak/mind/screen.h"
#include "utak/mind/shape.h"
#include "utak/base/task.h"
#include "utak/mind/worldmodel.h"

/* The longest single move or push, in squares: a leg short enough that what Utak
 * sees on the way (the fovea reaches 4 squares ahead) can change the plan before
 * he walks into it. */
#define CONTROLLER_MAX_LEG 4.0
/* A longer move, at most this many squares, where every square it sweeps is believed
 * floor seen wholly empty (p at most CONTROLLER_LEG_P) with at least the confidence
 * one look at a wholly empty peripheral cell gives (paper 3.1 step 9): across open
 * floor seen, what Utak sees on the way adds nothing the plan needs, and the eye's
 * field (16 squares ahead) still overlaps the last impression enough to place him
 * (paper 3.5). A cell with anything in it (a crumb the coarse eye shows as a grey
 * level) stops the long move there. Travelling only; pushes keep the short leg. */
#define CONTROLLER_LONG_LEG 12.0
#define CONTROLLER_LEG_P 0.01
#define CONTROLLER_LEG_CONF 0.29
/* ... and so is every square within this many of the squares it sweeps: near
 * walls and objects Utak keeps to the short leg and looks at them on the way (the
 * fovea's half width is 4). */
#define CONTROLLER_LEG_MARGIN 3
/* Utak has arrived at a point when his believed point is this close to it. */
#define CONTROLLER_ARRIVED 0.25
/* A corner is reached this many squares short of the best floor seen in the room
 * (the judge's slack, judge.h). */
#define CONTROLLER_CORNER_SLACK 1
/* Going round an object: the waypoints stand this far outside its rectangle. */
#define CONTROLLER_ROUND_MARGIN 1.5
/* Going round is done when the believed path winds round the object more than this
 * (the judge's test); else Utak goes round it again, at most this many more times. */
#define CONTROLLER_ROUND_TURNS 0.99
#define CONTROLLER_ROUND_LOOPS 2
/* Going home, Utak's position may be corrected by what his first impression showed
 * at most this many times (round_recognise_home): each correction is a re-plan. */
#define CONTROLLER_HOME_FIXES 4
/* ... and he doubts he is home when his position may be off by this much, one
 * standard deviation of motion's error on an axis (round_home_doubt): a third of
 * the judge's JUDGE_HOME (1.5), which a Gaussian error passes about once in 100. */
#define CONTROLLER_HOME_SD 0.5
/* Frontier goals remembered as reached (older ones are forgotten first). */
#define CONTROLLER_MAX_VISITED 256
/* Squares remembered as bumped into (later ones are dropped). */
#define CONTROLLER_MAX_BUMPED 1024
/* Cycles without progress (the believed position unchanged) before giving up (a
 * push into a corner is seated from there instead: push_seat_here). */
#define CONTROLLER_STUCK_CYCLES 4
/* Pushes remembered, and how often a push may come back to the same square before
 * the controller calls it going round in circles (push_in_circles: into a corner,
 * the object is then seated from there; otherwise the task fails). */
#define CONTROLLER_MAX_PUSHES 512
#define CONTROLLER_CIRCLES 6
/* Travelling, a goal is given up as if reached when Utak stands on one square for
 * the CONTROLLER_ROUND_TRIP_VISITS-th time within his last CONTROLLER_ROUND_TRIP_WINDOW
 * moves and those moves showed nothing new (controller.c, round_trips). */
#define CONTROLLER_ROUND_TRIP_WINDOW 8
#define CONTROLLER_ROUND_TRIP_VISITS 3
/* Seating an object in a corner: at most this many one-square pushes along each
 * axis, each until one makes no headway (the eye places walls seen from afar a
 * square or two off; the object pressed against them is where they really are). */
#define CONTROLLER_SEAT_PUSHES 8
/* ... and, once motion has shown itself noisy (worldmodel_motion_error > 0), this
 * many more tries along an axis after a push that made no headway: pressed against
 * one wall, a push along it halts at once whenever its error (paper 3.5) turns it
 * into that wall, though the way along it is open. */
#define CONTROLLER_SEAT_RETRIES 2

/* Clearing the way into a corner (pushclear.h): another movable object that keeps
 * the one pushed from the corner is moved out of the way at most this many times a
 * task; the squares the pushed object would sweep into the corner, kept free of it,
 * are at most this many. */
#define CONTROLLER_CLEAR_TRIES 2
#define CONTROLLER_CLEAR_KEEP 4096
/* Shapes read lately (objects.c), by object ident and a key of the squares read. */
#define CONTROLLER_MEMOS 64
typedef struct ShapeMemo {
	int32_t ident;
	uint64_t key;
	ShapeReading reading;
	bool guessed;	/* the reading is at the fovea's scale, the object's too coarse */
	int8_t square_fits; /* a square's squares may be these, standing still (objects.h,
			       ANOTHER NAME): 1, 0, or -1 not yet asked */
} ShapeMemo;

typedef enum ControllerPhase {
	PHASE_TRAVEL,	/* walking to a goal point (or exploring toward one) */
	PHASE_GRASP,	/* beside the object: grasp it */
	PHASE_PUSH,	/* holding it: pushing it to its goal */
	PHASE_SEAT,	/* at the corner: pressing it in, one axis at a time */
	PHASE_RELEASE,	/* it is there: let go */
	PHASE_DONE,	/* the task is complete, as far as Utak believes */
	PHASE_FAILED,	/* the task cannot be done, for the reason in `why` */
} ControllerPhase;

/* Objects remembered as once seen whole in the fovea (objects.h), at most. */
#define CONTROLLER_EXAMINED 256
/* Squares of occupied sets joined to the verge that touch has felt an object's
 * colour on (objects_feel), and squares a tug has been tried at (tug.h), at most:
 * a few per object against a wall. */
#define CONTROLLER_FELT_SQUARES 64
/* Corrections of Utak's place remembered (round.c: the last this many impressions). */
#define CONTROLLER_FIXES 8

typedef struct Controller {
	Task task;
	bool has_task;		/* false for --act runs: perception only */
	PlannerKind planner_kind;
	/* Perception (paper 3.3-3.5). */
	Impression impression;	/* the last one received */
	Regions regions;
	WorldModel model;
	/* Planning (paper 3.6, 4). */
	Screen screen;
	Grid space;		/* the grid the last plan was made on (screen or C-space) */
	Planner planner;
	Path route;		/* waypoints, model frame, the first one where Utak set off */
	int next;		/* the waypoint being walked to */
	Vec2 goal;		/* model frame */
	bool have_plan;
	ControllerPhase phase;
	Vec2 start;		/* Utak's believed point when the task began, model frame */
	int32_t target;		/* the task's object: its model ident, 0 none */
	Vec2 target_at;		/* ... and its centroid when last seen, model frame */
	char doubt[160];	/* why the object grasped may not be the task's (objects_doubt), or empty */
	Shape grasp_shape;	/* what the held squares read as when grasped (push_seat_finish) */
	int32_t examined[CONTROLLER_EXAMINED]; /* idents of objects once seen whole in the fovea */
	int examined_count;
	int32_t felt[CONTROLLER_EXAMINED];  /* idents touch has shown to be objects (a letter not B) */
	int felt_count;
	bool exploring;		/* the goal is a frontier of the unseen, not the task's */
	bool surveying;		/* a push into a corner: going to look at the corner first */
	bool room_look;		/* going to look at a wall that may part two rooms (roomdoubt.h) */
	Vec2 room_look_at;	/* ... from there, kept until reached */
	bool room_follow;	/* the start's room runs into the unseen as a passage:
				   followed from the last look at it (roomdoubt_frontier) */
	Vec2 room_follow_at;	/* ... that look */
	bool room_following;	/* ... and it is the current goal, kept until reached */
	int door_looks;		/* looks set off on where doorsure.h would doubt the corner (doorlook.h) */
	bool door_look_pending;	/* ... the last not yet reached: no claim until it is */
	Vec2 door_look_at;	/* ... the last, where it is taken from */
	int door_look_retries;	/* ... set off on again after the goal was dropped on the way */
	/* Frontier goals already reached: a frontier whose unknown stays unknown
	 * when Utak stands at it (it is out of the eye's reach) is not tried again. */
	Vec2 visited[CONTROLLER_MAX_VISITED];
	int visited_count;
	/* Goals given up because the eye showed their square occupied on the way
	 * there, while it was never seen in the fovea (controller.c, shun): a
	 * square at the fringe of an object seen coarsely reads floor from one
	 * place and occupied from the next; goals_near does not choose it again. */
	Vec2 shunned[CONTROLLER_MAX_VISITED];
	int shunned_count;
	/* Squares found blocked by bumping into them: where a move or push halted,
	 * the squares its shapes would have entered next. Touch of a kind: the eye
	 * may have read them as floor (a verge glimpsed coarsely). */
	int32_t bumped_x[CONTROLLER_MAX_BUMPED], bumped_y[CONTROLLER_MAX_BUMPED];
	int bumped_count;
	/* Going round: the points still to visit. */
	Vec2 round[6];
	int round_count, round_next;
	int round_loops;	/* loops added because the path did not wind round it */
	/* A loop walked home round an object not yet seen whole in the fovea: Utak
	 * looks at the parts unseen (round_look), then goes home, once a task. */
	bool round_looking, round_looked;
	int32_t round_ident;	/* the object they go round (its model ident) */
	int round_homed;	/* positions corrected by the first impression, going home */
	Path trail;		/* where Utak believed he stood, the start and after each cycle */
	/* Travelling: the squares stood on after the last moves that showed nothing
	 * new (controller.c, round_trips), the oldest first. */
	int32_t trip_x[CONTROLLER_ROUND_TRIP_WINDOW], trip_y[CONTROLLER_ROUND_TRIP_WINDOW];
	int trip_count;
	Box round_rect;		/* and its rectangle when they were laid out */
	/* Bookkeeping for the trace. */
	int cycle, replans, stuck;
	/* For observers (the picture and the replay; the controller never reads them):
	 * how many times the planner has been run, and the model square of cell (0, 0)
	 * of the grid it last ran on (the planner's points and cells are in that grid's
	 * units; the screen is built again every cycle and may have moved since). */
	int plans_made;
	int32_t plan_x0, plan_y0;
	/* Pushing: the squares Utak has stood on since he grasped, for going round in
	 * circles (CONTROLLER_CIRCLES visits to one square). */
	int32_t pushed_x[CONTROLLER_MAX_PUSHES], pushed_y[CONTROLLER_MAX_PUSHES];
	int pushed_count;
	/* Seating: the axis being pressed along (0 east-west, 1 north-south), the
	 * pushes made along it, and where the last one set off. */
	int seat_axis, seat_pushes, seat_misses;
	Vec2 seat_from;
	/* Squaring a slanted object up to the corner's walls (pushturn.h): the stage,
	 * tries made, the squares still to draw it back, the turn, and where the last
	 * push back set off; then fetching it again. */
	int turn_stage, turn_tries, turn_back_x, turn_back_y;
	double turn_deg;
	Vec2 turn_from;
	bool turn_first;
	bool turn_grasp_slant;	/* the held squares read at a slant when grasped, */
	double turn_grasp_deg;	/* ... the turn that would square them up then */
	bool turn_keep;		/* turned, he keeps hold (it still leads him) */
	bool turn_watch;	/* ... and the push after is watched (pushturn_watch) */
	bool turn_fetch;	/* let go of, turned: being fetched again */
	Vec2 turn_at;		/* ... its held squares' centre when let go of */
	Vec2 last_position;
	int32_t seen_before;	/* squares seen before the last impression */
	/* A tug (tug.h): its stage (0 none, 1 grasped, 2 pulling), the direction
	 * pulled (a unit step, model frame), squares pulled, and tugs tried. */
	int tug_stage;
	int tug_dx, tug_dy, tug_pulled, tug_tries;
	Vec2 tug_from;		/* where the last pull set off (believed, model frame) */
	int tug_wedged;		/* tugs whose pull did not move Utak: the object stuck */
	Vec2 tug_wedged_at;	/* ... the centre of the square grasped at the last */
	/* Squares (model frame) of occupied sets the model does not hold to be
	 * objects, where touch felt an object's colour (objects_feel), and those a
	 * tug has been tried at, each at most once (tug.h). */
	int32_t felt_x[CONTROLLER_FELT_SQUARES], felt_y[CONTROLLER_FELT_SQUARES];
	int felt_squares;
	/* The corrections of Utak's place the last CONTROLLER_FIXES impressions made
	 * (believed less predicted; 0 where none), a ring from fix_next (round.c,
	 * round_home_doubt). */
	Vec2 fix[CONTROLLER_FIXES];
	int fix_next;
	/* Squares of corners of the wall touch has felt B on (wallbump.h). */
	int32_t wall_felt_x[CONTROLLER_FELT_SQUARES], wall_felt_y[CONTROLLER_FELT_SQUARES];
	int wall_felt_squares;
	int32_t bump_tried_x[CONTROLLER_FELT_SQUARES], bump_tried_y[CONTROLLER_FELT_SQUARES];
	int bump_tried; /* ... and corner squares touch has reached */
	int bump_trips;  /* trips set off on for such corners (wallbump_going) */
	Vec2 bump_goal;  /* ... the last one's place */
	bool bump_home;  /* going round: home when the corners are felt */
	int32_t tugged_x[CONTROLLER_FELT_SQUARES], tugged_y[CONTROLLER_FELT_SQUARES];
	int tugged_squares;
	/* Shape by motion: the probe of the object about to be claimed (probe.h). */
	ProbeRun probe;
	/* Settling a doubt about another object by going to it (rival.h). */
	RivalRun rival;
	/* Pulling a rival of the MERGED doubt, to see it come away whole (apart.h). */
	ApartRun apart;
	/* Pulling the object he would claim, a shape other than the square, to see it
	 * come away whole (joined.h). */
	JoinedRun joined;
	/* ... or turning it a quarter about his point, where a pull cannot settle it
	 * (swing.h). */
	SwingRun swing;
	/* Pushing the square he would claim both ways, to see it one object (seam.h). */
	SeamRun seam;
	/* Settling a hall doubt by touching the blob (hallsplit.h). */
	HallRun hall;
	ShapeMemo memo[CONTROLLER_MEMOS];
	int memo_next;		/* the entry to write next (the oldest) */
	char note[2048];	/* what this cycle's perception and planning did (and the plan) */
	char why[300];		/* PHASE_FAILED: why */
	/* Clearing the way into a corner (pushclear.h): the stage (PushClearStage),
	 * clearings begun, the object moved out of the way (its model ident, and the
	 * centre of its rectangle when last found), and the squares (model frame)
	 * the task's object would sweep into the corner, where it must not be left. */
	int clear_stage, clear_tries;
	int32_t clear_ident;
	Vec2 clear_at;
	int32_t clear_keep_x[CONTROLLER_CLEAR_KEEP], clear_keep_y[CONTROLLER_CLEAR_KEEP];
	int clear_keep_count;
	int clear_back_x, clear_back_y; /* the push that draws the held object off first */
	bool clear_noted;	/* the trace has said why this clearing began */
	/* Tasks (vi)-(ix): carrying the object in (x, y, theta) (carrytask.h); NULL
	 * for the others. */
	struct CarryTask *carry;
} Controller;

void controller_init(Controller *c, PlannerKind planner);
void controller_free(Controller *c);
/* controller_set_task(c, t): the task to carry out (step 6). */
void controller_set_task(Controller *c, const Task *t);
/* controller_start(c, first): steps 1-5 (default model, first impression, regions,
 * interpretation, accommodation) and, with a task, step 7 (the first plan). */
void controller_start(Controller *c, const Impression *first);
/* controller_decide(c, cmd): steps 8-9. False when there is nothing more to do
 * (phase DONE or FAILED); else the next command in *cmd. */
bool controller_decide(Controller *c, MotorCommand *cmd);
/* controller_perceive(c, cmd, imp): steps 11-13 after cmd was carried out. */
void controller_perceive(Controller *c, const MotorCommand *cmd, const Impression *imp);

/* controller_dump_screen / _skeleton / _pathgraph / _rooms / _path: the last plan's
 * screen and planner state (see screen.h, skeleton.h, pathgraph.h, rooms.h,
 * planner.h); each says so when there is no plan yet. */
void controller_dump_screen(Controller *c, FILE *f);
void controller_dump_skeleton(Controller *c, FILE *f);
void controller_dump_pathgraph(Controller *c, FILE *f);
void controller_dump_rooms(Controller *c, FILE *f);
void controller_dump_path(Controller *c, FILE *f);

#endif
