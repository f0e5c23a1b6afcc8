/* pushclear.h - clearing the way into a corner: another movable object keeps the one
 * being pushed from the corner, and Utak moves it out of the way first (paper 2.2:
 * every object on the table can be grasped and pushed; 2.3 task (v)). CONTROLLER
 * SIDE: called by push.c, goals.c and the action cycle (controller.c).
 *
 * When seating leaves the task's object more than a square short of the corner
 * (push_seat_finish), Utak asks his model whether a movable object is what keeps it
 * there. An object he may move is a set of occupied squares that stands apart from
 * everything else once what he holds is taken away (pressed against it and a wall,
 * the model joins all three to the verge), not felt to be wall (objects_wall), of
 * at least PUSHCLEAR_LEAST squares. On the configuration space of what he holds,
 * with those squares and his own counted as floor, the unseen as blocked and the
 * squares bumped into left out (a halted push marks a whole side of the held
 * object), the way of fewest steps to the cell that takes it farthest toward the
 * corner must gain more than the slack, and the first such object it meets (from
 * Utak) is the one in the way. Then: draw what he holds off what it is pressed
 * against (one push of at most 3 squares each way after which every neighbour of
 * its squares is believed floor, so that the model can tell it from the other
 * once he lets go) and release it (stage RELEASE); go beside the object in the
 * way and grasp it (FETCH); push it, on its own configuration space, to the
 * nearest place where none of its squares lies within a square of the way, and
 * release it (MOVE); then fetch the task's object again as at the start, and
 * seating judges the corner as ever (the doubt of the first grasp stands:
 * controller.c). Bounded: at most CONTROLLER_CLEAR_TRIES clearings a task; no
 * push to draw the object off, no side to push the other from, or touch that does
 * not find it there ends the clearing (the task's object is fetched again, and
 * fails honestly where it is still short), and a push of the object in the way
 * that stops working (no headway, or in circles) leaves it where it got to. A
 * corner the model shows free is never cleared: no way to it crosses an object. */
#ifndef UTAK_PUSHCLEAR_H
#define UTAK_PUSHCLEAR_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"
#include "utak/mind/goals.h"

/* The fewest squares an object in the way has: a smaller set is a square of an
 * object's edge the eye saw apart from the rest, nothing to grasp. */
#define PUSHCLEAR_LEAST 4

typedef enum PushClearStage {
	PUSHCLEAR_NONE,	   /* no clearing under way */
	PUSHCLEAR_RELEASE, /* letting go of the task's object */
	PUSHCLEAR_FETCH,   /* going beside the object in the way to grasp it */
	PUSHCLEAR_MOVE,	   /* pushing it out of the way */
} PushClearStage;

/* pushclear_begin(c, short_by): seating left the held object short_by short of the
 * corner (on this cycle's screen, as goals_corner_shortfall built it): true, with
 * the phase set to PHASE_RELEASE, when a movable object keeps it from the corner
 * and a clearing begins; false, changing nothing, otherwise. */
bool pushclear_begin(Controller *c, int64_t short_by);
/* pushclear_back_off(c, cmd): before letting go to clear the way, the push (once)
 * that draws the held object off what it is pressed against: true with it in cmd. */
bool pushclear_back_off(Controller *c, MotorCommand *cmd);
/* pushclear_note(c, buf, size): once a clearing, after its first command, a note
 * for the trace saying why (buf gets "; ..." and the length is returned; 0 and
 * nothing otherwise). */
int pushclear_note(Controller *c, char *buf, size_t size);
/* pushclear_released(c): Utak lets go (PHASE_RELEASE's command): true when the task
 * goes on (the next stage of a clearing), false when the release ends it. */
bool pushclear_released(Controller *c);
/* pushclear_node(c): the model node of the object in the way, -1 when it is no
 * longer found. */
int32_t pushclear_node(Controller *c);
/* pushclear_goal(c, dist, rm, start_room, out): the goal of a clearing's FETCH stage
 * (the side to grasp the object in the way from) or MOVE stage (where to push it;
 * where Utak stands when no place will do); false when no clearing is under way
 * or it has just been given up (the task's goal is then chosen as ever). */
bool pushclear_goal(Controller *c, const int32_t *dist, const RoomMap *rm, int32_t start_room, GoalResult *out);
/* pushclear_place(c, g, dist, ox, oy, n, goal): Utak's cell on g (the configuration
 * space of Utak holding the n squares at offsets (ox, oy); dist its steps from his
 * cell) nearest him where none of those squares lies within a square of the way
 * kept free; false when there is none. */
bool pushclear_place(const Controller *c, const Grid *g, const int32_t *dist, const int32_t *ox, const int32_t *oy,
		     int32_t n, Vec2 *goal);
/* pushclear_arrive(c): the goal of a FETCH or MOVE stage is reached: true when this
 * handled it (grasp, release, or another side to try). */
bool pushclear_arrive(Controller *c);
/* pushclear_stop(c): the push of the object in the way stopped working (no headway,
 * or in circles): true, with the phase set to PHASE_RELEASE, when it is under way. */
bool pushclear_stop(Controller *c);

#endif
