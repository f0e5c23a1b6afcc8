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
 *
 * SETTLING (task (i)). Rather than claim the corner with that doubt, Utak goes and
 * touches the blob (paper 3.4.2: touch reads an object's letter, a wall's B), then
 * judges the claim again from the corner goal: a blob felt to be an object is no
 * longer asked about (objects_felt), one felt to be wall is wall to his rooms from
 * then on (objects_feel: wall_ident, screen.c counts it as verge), and the corner
 * is then the one of the hall's part he started in, where he goes on. WHY TOUCH,
 * not a look: the eye reads a free-standing stub in the fovea exactly as an
 * object; a look settles nothing the judge's rooms depend on.
 * WHY TOUCHING WAS UNRELIABLE (hall8 tried it and left the doubt): a blob seen
 * coarsely from afar is often a stub and an object beside it, read as one node;
 * seen closer, it splits into two nodes, touch feels the object's letter on one,
 * and the other, now seen in the fovea, was no longer asked about (the rule above)
 * though it was the wall that parts the hall: a false success. Now the rectangle
 * of each blob gone to is remembered (HallRun.blob), and a node with a square in
 * one is asked about whether or not the fovea has seen it since, until it is felt:
 * what the blob split into is settled piece by piece, at most HALL_TRIPS trips a
 * task. A blob with no reachable free square beside it, or past the trips, leaves
 * the doubt as it was. COST: the way to the blob and back, only on runs where the
 * doubt arises (the rule above is unchanged where it does not).
 * Task (v) keeps the doubt: settling would mean letting go of the square seated
 * in the corner, and fetching it again if the blob were wall.
 * COMPLEXITY: O(w h) a room map of the screen for each object node seen only
 * coarsely (or in a blob gone to). */
#ifndef UTAK_HALLSPLIT_H
#define UTAK_HALLSPLIT_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/base/geom.h"

/* Trips to touch a blob a task, at most, and blobs remembered (their rectangles). */
#define HALL_TRIPS 4
#define HALL_BLOBS HALL_TRIPS

/* A hall doubt being settled by touch (SETTLING above); in the Controller. */
typedef struct HallRun {
	bool going;		/* the goal is the free square beside a blob, kept until reached */
	Vec2 at;		/* ... that square's centre, model frame */
	Vec2 claim;		/* the point whose claim is in doubt */
	int trips;		/* trips begun this task */
	Box blob[HALL_BLOBS];	/* rectangles (model squares, inclusive) of the blobs gone to */
	int blob_count;
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

/* hallsplit_settle(c, p, at): task (i), Utak at p, arrived at the corner: HALL_CLEAR
 * when no blob parts the start from p; else a trip to touch the nearest such blob
 * (by steps) that has a reachable free square beside it not yet reached, begun
 * (HALL_GOING, c->hall set, c->have_plan cleared), or, none such or no trip left,
 * HALL_DOUBT, its words in c->hall.why. Once a trip has been made, a claim left
 * clear is still doubted when floor seen in the start's room by the verdict's
 * rule restated whole (carryroom_watershed) beats p by more than the slack. */
HallVerdict hallsplit_settle(struct Controller *c, Vec2 p, Vec2 *at);
/* hallsplit_goal(c, dist, out): while a trip is on, its goal (exploring: arriving
 * is a look, then the corner is chosen and judged again); false when none is, or
 * its square can no longer be reached (the trip is then over). */
bool hallsplit_goal(struct Controller *c, const int32_t *dist, struct GoalResult *out);
/* hallsplit_arrive(c): a goal reached: the trip, if one was on, is over; if what
 * it went to is still unsettled, the next trip sets off from here. */
void hallsplit_arrive(struct Controller *c);

#endif
