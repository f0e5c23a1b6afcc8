/* hallsplit.h - whether a blob seen only coarsely may be a wall that parts the hall
 * Utak started in, before he claims its corner, or the corner he pushed an object
 * into (tasks (i) and (v); paper 3.4.2: an occupied set the eye
 * has not resolved may be the verge, and the eye cannot tell a free-standing pier
 * from an object; issue 13 items 3 and 6: a corner is the starting room's, and Utak
 * claims only what his model can tell). CONTROLLER SIDE: it reads the world model,
 * its screen and what touch felt.
 *
 * WHY. The verdict's rooms (doc/verdicts.md) count objects as space and walls as
 * walls, and cut a hall wherever it narrows between two regions that each widen
 * well beyond it: a free-standing pier or wall stub, with the hall's walls, parts a
 * hall 42 wide in two. The model reads every occupied set apart from the verge as
 * an object, space to rooms, so it holds no narrowing there; and a blob seen only
 * by the outer zones of the retina has not even shown its outline. Walking along
 * one wall of such a hall, with its far side never seen, Utak would claim the
 * corner of the other half as his own: a false success.
 *
 * THE RULE. An object node not held, not felt (objects_felt: touch settles it), and
 * with no square seen in the fovea, PARTS the start from a point p when, on the room
 * map of the screen's fixed space seen with that node taken for wall, merged by the
 * verdict's door rule keeping every narrowing that MAY be a door (each side wide,
 * or seen in part and so perhaps wider: carryroom_merge_maybe), the start and p lie
 * in different rooms. Utak then cannot tell the corner is his room's: he claims it
 * with a doubt (controller.c). For a push (task (v)) the points are the held
 * object's squares that reach the corner, not Utak's: the judge counts the
 * object's squares in the start's room; the doubt stands when the node parts the
 * start from every one of them (push.c held_room_split).
 * A STUB SEEN IN THE FOVEA. The eye reads a free-standing stub seen closely exactly
 * as an object: on 88 of 151 made-up variants of tests/worlds/hall-stub.w (the
 * stub, a square and Utak's start moved) it was seen in the fovea before any
 * coarse blob raised the doubt, and Utak claimed the other half's corner (a false
 * success). So the rule asks too of each object node not held, not felt, and not
 * felt as wall, seen in the fovea or not, taken for wall alone, whether it parts
 * the start from p, on the map above or on the verdict's watershed restated
 * (carryroom_watershed, as in SETTLING below): objects touch has felt (a letter),
 * held, or grasped (felt then), are known to be no wall; no other sign in the
 * impression tells a wall from an object (doc/verdicts.md: only the fixed parts,
 * TABLE colour B, make rooms). COST: a trip on the runs where an object, were it
 * wall, would part the hall: 16 of the 410 corner runs of the rates' sets (one
 * run, /tmp/rk15), +0.78 cycles a corner run on average; 5 of them end with a
 * doubt touch could not settle (a pier felt B, the hall wider on his model where
 * the far side is unseen, or a piece with no way to it within 4 trips: the
 * figures of /tmp/rk15, when the trips limit was 4; it is now HALL_TRIPS, 8).
 *
 * SETTLING (task (i)). Rather than claim the corner with that doubt, Utak goes and
 * touches the blob (paper 3.4.2: touch reads an object's letter, a wall's B), then
 * judges the claim again from the corner: a blob felt to be an object is no longer
 * asked about (objects_felt), one felt to be wall is wall to his rooms from then
 * on (objects_feel: wall_ident, screen.c counts it as verge). WHY TOUCH, not a
 * look: the eye reads a free-standing stub in the fovea exactly as an object.
 * WHY TOUCHING WAS UNRELIABLE (hall8 tried it and left the doubt), found on random
 * g51: the coarse blob was an object (touch felt its letter), and the walls that
 * truly part the hall were two piers offset across it, seen in the fovea and so
 * never asked about (the rule above); nor does the room map (rooms.h, a door is a
 * valley along a skeleton edge) find a door across their diagonal gap, where the
 * judge's watershed does. Settling the blob alone made g51 a false success. So,
 * from the first trip on, the SUSPECTS are every object node not settled by touch,
 * seen in the fovea or not, and one felt while a square of it in a blob gone to
 * (HallRun.blob) is still seen only coarsely (an object and a stub beside it read
 * as one: a look from nearby parts them; once each, HallRun.looked); each is
 * taken for wall alone and all at once (the door rule is not monotone: a wall
 * more may make a side too narrow to widen beyond a narrowing), on the room map
 * above and on the verdict's watershed restated on the same space
 * (carryroom_watershed, the unseen as space). Those
 * that part the hall alone are gone to, else those without which all together no
 * longer part it, else all, the nearest by steps first, at most HALL_TRIPS trips
 * a task; a trip that felt nothing sets off again from where it ended. With none
 * left that parts the hall, the claim still needs, by the watershed on the fixed
 * space (walls touch found as verge), Utak in the start's room and no floor seen
 * in it more than the slack better (hs_beaten: a pier felt B made rooms.h cut a
 * hall where the judge's ratio counts no door, random g256). A suspect with no
 * way to it, or past the trips, leaves the doubt. He does not yet go on to the
 * corner of his own half when a wall touch found parts the hall: his room map may
 * still join the halves (hall-stub.w, hall-blob-wall.w end in honest doubts).
 * COST: the trips, only on runs where the rule above doubts the claim (it is
 * unchanged where it does not): 12-65 cycles on the random corners it settled.
 * Task (v) keeps the doubt: settling would mean letting go of the square seated
 * in the corner, and fetching it again if the blob were wall.
 * LOOKING (task (i)). The watershed takes the unseen for space: floor seen beyond
 * a wall whose door he has not seen may join the start's room only through squares
 * never seen (random g16: the wall between two rooms seen from one end, its far
 * part and its door unseen; he doubted a corner the judge counts reached). When
 * hs_beaten doubts the claim, the way from Utak to the floor that beats it within
 * the start's watershed room crossing the fewest squares never seen (0-1 breadth-
 * first search) is found; if it crosses none, the rooms join on floor seen and the
 * doubt stands; else Utak goes to look at the first unseen square along it that no
 * goal reached has looked at (a reachable cell within GOALS_LOOK of it), and
 * judges the corner again on return, at most HALL_LOOKS looks a task. A look only
 * adds what the eye saw: the claim is still made by hs_beaten's rule alone.
 * CLOSED (task (i); corner25). The watershed takes the unseen for space, so a wall
 * of the start's room never seen lets the room run on into the unseen, and beyond
 * it into any room; a door between it and floor seen beyond may then be no door by
 * the verdict's ratio, the start's room (narrower than what it joins) flooding
 * into its neighbour (random g241: 16 squares of the start room's far wall never
 * seen; g41, g266 likewise). The fewest-unseen way of LOOKING runs through that
 * door over floor seen, and its looks went to the beating floor itself, square by
 * square, never to the wall that decides. So, before LOOKING, the watershed is
 * restated once more with every square never seen taken for wall: when on it Utak
 * is in the start's room and no floor seen in that room beats his square by more
 * than the slack, the doubt owes to the unseen, and he goes to look at the
 * never-seen square beside that closed room nearest him by steps
 * (hallsplit_frontier) not looked at from a goal reached, from a reachable cell
 * within GOALS_LOOK of it, within HALL_LOOKS (one budget with LOOKING), and
 * judges again on return. The claim is still made by hs_beaten's rule alone, on
 * the open watershed: the closed one only chooses where to look.
 * FACES (task (i); corner25). The other way the model errs about a door is a wall
 * seen only coarsely and placed a square or more into the room (an object beside
 * it joined to it by a coarse cell reads as wall too): the room then reads
 * narrower than it is, its peak clearance under twice the door's, and the door
 * no door (random g291: the start room 15 wide, its door 7, read 14 wide where an
 * object by the wall joined it). So, when CLOSED finds nothing to look at, the
 * watershed is restated with every verge square not seen in the fovea that has
 * floor seen beside it (a coarse face) taken for floor; when on it the claim
 * holds, he looks at the face square beside the start's room on that map nearest
 * him, as CLOSED does, within HALL_FACE_LOOKS; the fovea places the wall, or shows
 * the floor, and the claim is judged again by hs_beaten alone.
 * COST (corner25, one run each): of the 320 random and perturbed corner runs, 4
 * change: random g41, g241, g266, g291 "go ne-corner" lose the doubt (107 -> 94,
 * 62 -> 27, 129 -> 180, 205 -> 83 cycles), and g16 takes 72 cycles for 68.
 * FAINT (task (i); stub13). A free-standing stub one to three squares thick seen
 * only by the 4 x 4 and 2 x 2 cells that straddle it reads as floor (its squares
 * below half of each cell), so no node stands for it and the rule above never
 * asks it; but a cell not zero says something in it is occupied (worldmodel.c),
 * and its squares keep a probability above 0: FAINT squares. On 47 of 150
 * hall-stub variants (/tmp/c11adv) Utak claimed the other half's corner. So, with
 * no node left that parts the hall, each 8-connected set of faint squares alone,
 * and all of them at once (the door rule is not monotone), is taken for wall, on
 * the room map (carryroom_merge_maybe) and the watershed restated, as the rule
 * above takes a node (hs_joint_parts); where one parts the start from p, Utak
 * goes to look at its square nearest him not looked at from a goal reached (the
 * fovea reads a wall one square thick as it is), at most HALL_FAINT_LOOKS a task,
 * and judges the corner again; with none left to take, he doubts. And the claim
 * is checked on the watershed (hs_beaten) from the first arrival, not only once
 * a trip has been made: his own restated rule finding floor of his room that
 * beats the corner (or his point out of that room) is reason enough to doubt.
 * COST (stub13, one run each): 2 of 60 random corners doubted by FAINT (g61,
 * g91: bits seen coarsely), 4 more by hs_beaten from the first arrival (g41,
 * g241, g266, g291); none of 100 perturbed or 250 noisy corners changed.
 * COMPLEXITY: the rule O(w h) a room map of the screen for each object node seen
 * only coarsely; settling O(S w h log(w h)) for S suspects, per judgement;
 * looking, per judgement hs_beaten doubts, O(w h log(w h)) (the watershed), O(w h)
 * the 0-1 search (hallsplit_fewest) and a reach, and O(w h) more for each square
 * not seen in the fovea along the way found (goals_near, to look at it from). */
#ifndef UTAK_HALLSPLIT_H
#define UTAK_HALLSPLIT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/base/geom.h"

/* Trips to touch a blob a task, at most, and blobs remembered (their rectangles).
 * 8: a trip that ends beside a blob seen coarsely, a square or two off, where touch
 * does not reach it, sets off again and counts; with 4, random g121, g211 and g276
 * of the rates (and perturbed clutter-p1) spent them so and kept the doubt, and are
 * claimed with 8 (103 -> 111, 51 -> 54, 65 -> 204, 47 -> 54 cycles). */
#define HALL_TRIPS 8
#define HALL_BLOBS HALL_TRIPS
/* Looks a task, at most, at unseen squares that alone join floor that beats the
 * corner to the start's room by the verdict's watershed (LOOKING, CLOSED and
 * FACES below). */
#define HALL_LOOKS 4
/* Looks a task, at most, at faint squares that, taken for wall, part the hall
 * (FAINT above). */
#define HALL_FAINT_LOOKS 4
/* Looks a task, at most, at coarse faces of the start room's walls (FACES above),
 * a budget of their own: spent from HALL_LOOKS, they left LOOKING none on
 * variants of random g291 where LOOKING's look decides (the door made 8 wide and
 * moved: 132 cycles claimed before, a doubt after four looks at faces). */
#define HALL_FACE_LOOKS 2

/* A hall doubt being settled by touch (SETTLING above); in the Controller. */
typedef struct HallRun {
	bool going;		/* the goal is the free square beside a blob, kept until reached */
	Vec2 at;		/* ... that square's centre, model frame */
	Vec2 claim;		/* the point whose claim is in doubt */
	int trips;		/* trips begun this task */
	Box blob[HALL_BLOBS];	/* rectangles (model squares, inclusive) of the blobs gone to */
	int blob_count;
	int32_t looked[HALL_TRIPS];	/* idents of felt objects looked at (once each) */
	int looked_count;
	bool look;		/* the trip on is a look at unseen squares (LOOKING), not a touch */
	int looks;		/* such looks begun this task */
	int faint_looks;	/* looks begun this task at faint squares (FAINT) */
	int face_looks;		/* looks begun this task at coarse faces (FACES) */
	char note[200];		/* a trip begun, for the trace (controller.c prints it) */
	char why[200];		/* HALL_DOUBT: the doubt's words */
} HallRun;

typedef enum HallVerdict {
	HALL_CLEAR,	/* no blob parts the hall: the claim stands */
	HALL_GOING,	/* one may: Utak goes to touch it (c->hall.at the goal) */
	HALL_DOUBT,	/* one may, and touch cannot settle it: the claim is doubted */
} HallVerdict;

struct Controller;
struct GoalResult;

/* hallsplit_parts(c, p, at): whether a node parts the start from p on c->screen (the
 * rule above); *at is a square of the first such node, by node index. */
bool hallsplit_parts(const struct Controller *c, Vec2 p, Vec2 *at);
/* hallsplit_parts_all(c, p, n, at): the same for n points: whether one node parts
 * the start from every one of them (false when n is 0, or when a point lies on no
 * room of the map). Task (v): the held object's squares that reach the corner, for
 * the judge counts the object's squares in the start's room, not Utak's (push.c). */
bool hallsplit_parts_all(const struct Controller *c, const Vec2 *p, int32_t n, Vec2 *at);

/* hallsplit_faint_parts_all(c, p, n, at): FAINT's question for n points: whether a
 * set of faint squares (or all of them), taken for wall, parts the start from every
 * one of them; *at the square of that set nearest Utak not looked at from a goal
 * reached. For task (v) (the held object's squares that reach the corner), as
 * hallsplit_parts_all: push.c (held_room_split) doubts the corner when it parts,
 * with no look (the object is let go of where it is; on /tmp/c11adv's 150 hall-stub
 * variants, 1 of 13 push false successes closed, variant 27:
 * tests/worlds/hall-stub-faint-push.w). */
bool hallsplit_faint_parts_all(const struct Controller *c, const Vec2 *p, int32_t n, Vec2 *at);
/* hallsplit_settle(c, p, at): task (i), Utak at p, arrived at the corner: HALL_CLEAR
 * when no blob parts the start from p; else a trip to touch the nearest such blob
 * (by steps) that has a reachable free square beside it not yet reached, begun
 * (HALL_GOING, c->hall set, c->have_plan cleared), or, none such or no trip left,
 * HALL_DOUBT, its words in c->hall.why. A claim left clear is then asked of the
 * faint squares (FAINT: a look begun, HALL_GOING, or HALL_DOUBT), and still
 * doubted when floor seen in the start's room by the verdict's rule restated
 * whole (carryroom_watershed) beats p by more than the slack, or p is not in that
 * room. */
HallVerdict hallsplit_settle(struct Controller *c, Vec2 p, Vec2 *at);
/* hallsplit_goal(c, dist, out): while a trip is on, its goal (exploring: arriving
 * is a look, then the corner is chosen and judged again); false when none is, or
 * its square can no longer be reached (the trip is then over). */
bool hallsplit_goal(struct Controller *c, const int32_t *dist, struct GoalResult *out);
/* hallsplit_arrive(c): a goal reached: the trip, if one was on, is over; if what
 * it went to is still unsettled, the next trip sets off from here. */
void hallsplit_arrive(struct Controller *c);
/* hallsplit_fewest(w, h, pass, costly, u, b, from): on a w x h grid of cells, 4-
 * connected over the cells pass marks, the least number of costly cells a way from
 * cell u to cell b enters (u itself not counted), -1 when none joins them (or u or
 * b is not passable); from[] the way back (from[u] = -1), for the cells reached.
 * LOOKING's search (the costly cells those not seen in the fovea). COMPLEXITY:
 * O(w h) time (0-1 breadth-first search), 20 bytes a cell while it works. */
int32_t hallsplit_fewest(int32_t w, int32_t h, const bool *pass, const bool *costly, int64_t u, int64_t b,
			 int64_t *from);
/* hallsplit_frontier(w, h, unknown, room, a, dist, out): CLOSED and FACES: the cells q with
 * unknown[q] that have a 4-neighbour r in room a (room[r] == a) reachable
 * (dist[r] >= 0), each once, in order of the least such dist[r], then of q; their
 * count, the cells in out (w h of them). O(w h log(w h)). */
int64_t hallsplit_frontier(int32_t w, int32_t h, const bool *unknown, const int32_t *room, int32_t a,
			   const int32_t *dist, int64_t *out);
/* hallsplit_hidden_look(c): task (i), at the corner, where floor seen that beats it
 * may join the start's room by squares seen only coarsely (roomdoubt_hidden), a
 * look at them first (roomdoubt_hidden_look: c->room_look_at, kept by goals.c
 * until reached), at most HALL_LOOKS a task with LOOKING's looks; false when there
 * is none to take, and the doubt is then goals_corner_hidden's. */
bool hallsplit_hidden_look(struct Controller *c);

#endif
