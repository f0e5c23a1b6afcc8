/* nextroom.h - "in the next room" by the verdict's own rooms on Utak's model, and
 * what he must establish before claiming a room only that rule shows (paper 2.3
 * task (ii); issue 13). CONTROLLER SIDE: used by goals.c's next_room.
 *
 * WHY. rooms.h cuts the space at narrowings along the skeleton and carryroom_merge
 * keeps those the judge's door rule keeps; but the judge's rooms are a watershed
 * of clearance over the whole TABLE (judgerooms.h), whose door may lie at another
 * narrowing (random g197: another row of piers) or exist where rooms.h finds none
 * (random g257, g292: a corner of a hall parted by piers across diagonals). Every
 * place Utak claims lies past a door line by the watershed restated on his model
 * (carryroom_beyond); and a room that only the watershed shows he claims only
 * once he has established what it rests on: touch of every object in it and in
 * his starting room (a free-standing pier reads as an object, paper 3.4.2, and a
 * wall there would narrow the rooms the rule weighs), and the faces in its doors'
 * doorways seen in the fovea (a wall seen coarsely may lie a square off, or be
 * none: random g277). */
#ifndef UTAK_NEXTROOM_H
#define UTAK_NEXTROOM_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"
#include "utak/mind/goals.h"
#include "utak/mind/roomdoubt.h"

/* nextroom_beyond(c, g, rm, si, sj, ok): per cell of g, whether it lies beyond a
 * door line of another room than the start's (cell (si, sj)) by the verdict's own
 * watershed (carryroom_beyond) on both readings of the model: the space seen
 * (rm->known, the unseen wall), and the fixed space with the unseen counted space
 * (the screen's fixed). Objects are space in both, as the judge counts them. The
 * first holds no room that is one only because the unseen is taken for floor; the
 * second no door that the unseen, were it floor, would go round or widen. */
void nextroom_beyond(const Controller *c, const Grid *g, const RoomMap *rm, int32_t si, int32_t sj, bool *ok);

/* nextroom_cell(g, dist, ok): the reachable cell of g (dist >= 0) that is ok with
 * its 8 neighbours too (a square's slip of the model, and he still past the
 * line), nearest by steps (ties to the least index); -1 when none. */
int32_t nextroom_cell(const Grid *g, const int32_t *dist, const bool *ok);

/* nextroom_unfelt(c, g, rm, si, sj, at, dist, goal, keep): before claiming cell at
 * (beyond a door line by the watershed alone, nextroom_beyond) the next room: an
 * object node not felt (nor held) with a square in the start's room or at's, by
 * the watershed on the space seen, may be a free-standing wall (paper 3.4.2: only
 * touch tells them apart, objects.c objects_feel), and a wall there would narrow
 * the rooms the door rule weighs (random g197: two piers read as objects made the
 * stretch between two rows of piers part of the far room). True with *goal the
 * reachable cell beside the nearest such node by steps, not yet reached; when one
 * is left that cannot be reached, *keep is set to -1 (no claim). */
bool nextroom_unfelt(const Controller *c, const Grid *g, const RoomMap *rm, int32_t si, int32_t sj, int32_t at,
		     const int32_t *dist, Vec2 *goal, int32_t *keep);

/* nextroom_jambs(c, g, rm, at, dist, goal, keep): before claiming cell at (as for
 * nextroom_unfelt): every door cell of the watershed on the space seen that
 * borders at's room (a cell of it within 2), and the squares within its doorway
 * (its clearance, read up to CARRYROOM_CHAMFER over, and CARRYROOM_DOORWAY_REACH)
 * that are not floor and face floor (4-adjacent): each seen in the fovea. A wall
 * seen only coarsely may lie a square or more off, or be none (random g277: a
 * coarse phantom beside a hall made a door of nothing); the door rule weighs its
 * clearance. True with *goal the
 * reachable cell nearest the nearest such square (goals_near), not yet reached;
 * when one is left that cannot be looked at so, *keep is set to -1 (no claim). */
bool nextroom_jambs(const Controller *c, const Grid *g, const RoomMap *rm, int32_t at, const int32_t *dist,
		    Vec2 *goal, int32_t *keep);

/* nextroom_felt(c, dist, si, sj, goal): roomdoubt_felt's second reading
 * (roomdoubt.h): every object node not felt (nor held) taken for wall at once, the space seen cut by
 * the verdict's watershed (carryroom_watershed): where the start's room (of cell
 * (si, sj)) then has floor beyond a door line of another room (carryroom_beyond),
 * the nodes within a door cell's doorway (its clearance, read up to
 * CARRYROOM_CHAMFER over, and CARRYROOM_DOORWAY_REACH) are the ones whose touch
 * settles it. WHY: a room cut off by three piers in a row (random g292) is parted
 * by no one of them alone. */
RoomDoubt nextroom_felt(const Controller *c, const int32_t *dist, int32_t si, int32_t sj, Vec2 *goal);

/* nextroom_goal(c, g, dist, rm, si, sj, ui, uj, out): task (ii)'s goal on this
 * cycle's grid g (dist: steps from Utak's cell (ui, uj); rm: its room map; the
 * start at (si, sj)), into out, by THE NEXT ROOM (nextroom.c); returns whether the
 * goal is a look at an unsettled door's side. goals_choose asks it. */
bool nextroom_goal(const Controller *c, const Grid *g, const int32_t *dist, const RoomMap *rm, int32_t si, int32_t sj,
		   int32_t ui, int32_t uj, GoalResult *out);

#endif
