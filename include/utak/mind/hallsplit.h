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
 * start from every one of them (push.c held_room_split). He does not go and touch the blob: a touch visit
 * (tried) cost 14-29% more cycles on the random corner runs, and the coarse blob,
 * seen closer, splits into other nodes (a stub beside an object reads as one blob
 * from afar), so the touch often felt the object and left the wall unsettled. A
 * node once seen in the fovea is not asked about: the model's reading of it as an
 * object stands (the cost of asking about every object not felt is a doubt on a
 * quarter of the corner runs). COMPLEXITY: O(w h) a room map of the screen for each
 * object node seen only coarsely. */
#ifndef UTAK_HALLSPLIT_H
#define UTAK_HALLSPLIT_H

#include <stdbool.h>

#include "utak/mind/controller.h"

/* hallsplit_parts(c, p, at): whether a node parts the start from p on c->screen (the
 * rule above); *at is a square of the first such node, by node index. */
bool hallsplit_parts(const Controller *c, Vec2 p, Vec2 *at);
/* hallsplit_parts_all(c, p, n, at): the same for n points: whether one node parts
 * the start from every one of them (false when n is 0, or when a point lies on no
 * room of the map). Task (v): the held object's squares that reach the corner, for
 * the judge counts the object's squares in the start's room, not Utak's (push.c). */
bool hallsplit_parts_all(const Controller *c, const Vec2 *p, int32_t n, Vec2 *at);

#endif
