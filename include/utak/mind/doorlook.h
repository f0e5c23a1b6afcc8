/* doorlook.h - where doorsure.h would doubt a corner, a look first at the squares
 * that can tell (paper 2.3 task (i), and 3.4: "where his model cannot tell, he goes
 * and looks"; issue 13). CONTROLLER SIDE: the screen and the model's evidence only.
 *
 * WHY. Most of doorsure's doubts on achieved runs rest on squares seen only
 * coarsely: a wall 1 thick seen from afar (faint floor), a door's jambs a 4 x 4
 * cell may place a cell back. The fovea settles them. So, asked only where the
 * claim would otherwise be made (after every other check of the corner has let it
 * stand: roomclaim.c roomclaim_door_doubt), Utak first goes to the reachable cell
 * nearest him from which the fovea (FAINT_FOVEA_REACH each way) shows a square a
 * doubting reading marked (doorsure_corner_marks), then back to the corner, where
 * every check is asked again. The rule that decides is doorsure's, unchanged: a
 * look only adds evidence, and when no look is left he doubts as before.
 *
 * SAFETY. The earlier look (0e799b9) was asked before the other checks of the
 * corner and sent Utak away from a corner they had not yet let stand; here the
 * look is the last thing asked, so it only ever replaces a doubt. And no claim
 * rests on a look set off on and not reached (Controller.door_look_pending):
 * another check's look, or the map moving the place out of reach, may take the
 * goal on the way, and what then changes the readings is not the look. Without
 * this rule the simplest two-room worlds (a wall 1 thick seen from afar, the
 * model losing it outright: doorsure.h, LIMITS) had new false successes: the
 * look's goal dropped after a step or two, Utak back at the same square, the
 * squares seen on the way turned the one doubting reading sure, and he claimed a
 * corner of the room beyond the door (a generated two-room grid, 10 of 1728 runs). Such
 * a look is set off on again, at most DOORLOOK_RETRIES times a task, while it can be
 * reached; else he doubts. A look is not taken from a cell reached before
 * (controller visited list), nor farther than DOORLOOK_REACH steps, and at most
 * DOORLOOK_LOOKS a task: the way there and back must leave cycles for the claim. */
#ifndef UTAK_DOORLOOK_H
#define UTAK_DOORLOOK_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/base/geom.h"

struct Controller;

#define DOORLOOK_LOOKS 6  /* looks a task, at most */
#define DOORLOOK_REACH 60 /* steps from Utak to the place a look is taken from, at most */
#define DOORLOOK_RETRIES 2 /* a look given up on the way set off on again, at most, a task */

/* doorlook_choose(c, dist, mark, look): the reachable cell (dist: breadth-first
 * steps from Utak over the screen, -1 unreachable) nearest Utak, not his own, not
 * one reached before, within DOORLOOK_REACH, from which the fovea shows a square of
 * mark (screen-sized, doorsure_corner_marks); its centre in *look. False when none,
 * or the task's looks are spent; true counts a look. COMPLEXITY: O(w h F^2), F the
 * fovea's reach. */
bool doorlook_choose(struct Controller *c, const int32_t *dist, const uint8_t *mark, Vec2 *look);

#endif
