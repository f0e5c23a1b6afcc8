/* roomdoubt.h - whether Utak's model can tell which room a point lies in, and where
 * to look when it cannot (paper 3.3: a hypothesis of low confidence is confirmed or
 * dropped when seen closer; 3.4.2: an occupied set the eye has not resolved may be
 * the verge). CONTROLLER SIDE: it reads the world model and its screen.
 *
 * WHY. A wall seen only by the outer zones of the retina (2 x 2 or 4 x 4 squares a
 * cell) is misread: a cell half on the wall shares its level over all its squares,
 * so a wall two squares thick can read as floor where a cell straddles it, and a
 * block of wall cut off so can read as a small object, which counts as space for
 * rooms. Two rooms then join through a gap that is not there, and Utak, believing
 * himself in the corner of the room he started in, stands in the next room's.
 *
 * THE RULE. The DOUBTFUL squares are those seen only coarsely (never in the fovea)
 * that are either occupied, object or not, or floor beside (8-neighbour) an
 * occupied square: what a coarse cell across a wall's face would misplace. An
 * object not felt (objects_felt) with a doubtful square that comes within a coarse
 * cell of the verge (ROOMDOUBT_COARSE_CELL, along a row, a column or a diagonal
 * of doubtful squares) is doubtful whole, its squares seen in the fovea too: a
 * stub of wall one square thick, seen from afar, reads as an object parted from
 * the wall by a cell's misread floor, and objects are space to rooms (for
 * roomdoubt_check, not roomdoubt_door). The
 * PESSIMISTIC room map takes every doubtful square for wall, and merges rooms by the
 * verdict's door rule (carryroom.h). When the start and a point p are in the same
 * room there, they are in one room whatever the doubtful squares turn out to be
 * (coarse evidence only ever moves a wall's face by the cell it shares), and Utak
 * may claim. Otherwise the model cannot tell, and Utak goes to look, from within
 * GOALS_LOOK, at the doubtful square that parts the two rooms (beside both) nearest
 * him and not yet looked at (no visited point within GOALS_LOOK + 1): the fovea
 * then reads it at one square a cell, and it is no longer doubtful. */
#ifndef UTAK_ROOMDOUBT_H
#define UTAK_ROOMDOUBT_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/carryroom.h"
#include "utak/mind/controller.h"

typedef enum RoomDoubt {
	ROOMDOUBT_NONE, /* the model tells: p is, or is not, in the start's room */
	ROOMDOUBT_LOOK, /* it cannot tell: look from *goal */
	ROOMDOUBT_STUCK /* it cannot tell, and there is nothing left to look at */
} RoomDoubt;

/* The side of the coarsest cell of the retina, in squares (4 x 4 in the periphery):
 * how far a face seen so can lie from where it reads. */
#define ROOMDOUBT_COARSE_CELL 4

/* How near a square must be for one impression to show it whatever Utak's heading:
 * the retina spans 32 squares, centred on him (its inscribed circle has radius 16),
 * less a coarse cell for the squares at its rim that a peripheral cell shares. */
#define ROOMDOUBT_VIEW 12

/* roomdoubt_check(c, dist, p, goal): whether the model can tell that point p lies in
 * the start's room (the rule above) on c->screen; dist the steps from Utak over the
 * free space (goals_reach). COMPLEXITY: O(w h) a room map of the screen. */
RoomDoubt roomdoubt_check(const Controller *c, const int32_t *dist, Vec2 p, Vec2 *goal);

/* roomdoubt_door(c, dist, goal): for "go next-room" when the model shows no door out
 * of the start's room and nothing is left unseen: whether the PESSIMISTIC map (the
 * rule above, with Utak's own cell kept free) shows a narrowing (a door of
 * rooms.h: the gentler rule, since a look costs a few cycles and a door missed
 * the task; the claim still waits for the verdict's rule on the model itself)
 * between the start's room and another. A wall seen
 * coarsely can read as floor where a cell straddles it, or as an object (space to
 * rooms), and two rooms then read as one through a gap that is not there. If so,
 * Utak looks, from within GOALS_LOOK, at the nearest square not yet looked at of a
 * set of doubtful squares (8-connected: a wall is thicker than one square) beside
 * both the start's room and such another, on the start's side; ROOMDOUBT_STUCK
 * when none is left to look at. COMPLEXITY: O(w h). */
RoomDoubt roomdoubt_door(const Controller *c, const int32_t *dist, Vec2 *goal);

/* roomdoubt_beyond(c, dist, goal): at a corner Utak would claim, whether the start's
 * room may go on past a narrowing that is a door only because a side of it is seen
 * in part (carryroom_merge_seen), into space that may hold a better corner (a cell
 * of that side, or a square never seen beside it, scores above the best of the
 * start's room). If so, *goal is where to look from: the reachable cell nearest
 * that side's centre, not yet looked from. The verdict's rooms join across any
 * narrowing that is no door (a wall stub, a bay): without the look, Utak would
 * claim the corner of half a room. COMPLEXITY: O(w h) a room map of the screen,
 * O(w h) for each undecided door. */
RoomDoubt roomdoubt_beyond(const Controller *c, const int32_t *dist, Vec2 *goal);

/* roomdoubt_jambs(c, dist, goal): at a corner Utak would claim, whether a door out of
 * the start's room that the verdict's rule keeps on the model (decided or not),
 * leading to space with a better corner, may owe its narrowness to squares seen only
 * coarsely: occupied squares, never seen in the fovea, facing floor, within half the
 * door's width and ROOMDOUBT_COARSE_CELL of the run across it. A coarse cell across
 * a wall's face reads occupied over floor it shares, and such cells that join an
 * object to the verge make the object part of the wall (paper 3.4.2): a passage as
 * wide as the room then reads as a door, and Utak would claim the corner of half a
 * room. The squares matter when, the coarse faces on each side of the run taken up
 * to a cell less a square back (3 squares at 4 x 4, 1 at 2 x 2) and half of each
 * added to the door's clearance, the start's room would no longer widen well beyond
 * it by the verdict's rule (carryroom.h); the other side's peak is not asked, since
 * a side seen in part is roomdoubt_beyond's. If so, *goal is where to look from at
 * the nearest such square not yet looked at (roomdoubt_check's look);
 * ROOMDOUBT_STUCK when none is left to look at. COMPLEXITY: O(w h) a room map of
 * the screen, O(w h) for each door. */
RoomDoubt roomdoubt_jambs(const Controller *c, const int32_t *dist, Vec2 *goal);

/* A passage at most this wide (the verdict's widest leg of a corridor, carryroom.h,
 * and the eye's square of slack) that runs into the unseen may turn there. */
#define ROOMDOUBT_PASSAGE (CARRYROOM_LEG_WIDTH + CARRYROOM_EYE_SLACK)
/* How far from the last look at a passage the unseen beside the room is still its
 * continuation: twice the view, the passage's next look and the one after. */
#define ROOMDOUBT_FOLLOW (2 * ROOMDOUBT_VIEW)

/* roomdoubt_frontier(c, dist, toward, goal): at a corner Utak would claim, whether
 * the start's room (by the verdict's rule on the model, carryroom_merge) runs into
 * the unseen as a PASSAGE: a square never seen 4-adjacent to a cell of the room at
 * most ROOMDOUBT_PASSAGE wide across (its shorter run along x and y between walls
 * seen, the unseen counted as space; unbounded where no wall is seen). A corridor that goes on beyond the eye's reach may turn toward the corner
 * (paper 2.3's "around the corner"), and no bound on the unseen rules that out;
 * seen from its dead end, with the far part read coarsely, it looks closed. The
 * edge of the seen across an open room is not asked for, nor a passage of a room
 * that meets the unseen wide too (an open room seen in part, with a gap between
 * a wall and a blob not yet resolved at its edge): that would mean sweeping every
 * room whole before any corner, a cost Utak does not pay (a doubt left, README).
 * So the room must meet the unseen only through passages. A passage is FOLLOWED: with `follow`
 * (the last look taken at one, controller.h), every square never seen beside the
 * room within ROOMDOUBT_FOLLOW of it is asked for too, since where a passage turns
 * or opens out its walls are not yet seen and it reads wide.
 * If so, *goal is a seen cell of the room, reachable (dist), within ROOMDOUBT_VIEW
 * of such a square (one impression from there shows it): of those, the least by
 * steps from Utak less distance from `toward` (the corner aimed at), so that the
 * room is swept from its far side toward the corner and the looks near the
 * corner fall on the way. A square within ROOMDOUBT_VIEW of a visited point stays unseen
 * however near he comes (beyond the screen's margin): it is not looked for again;
 * ROOMDOUBT_STUCK when only such squares are left. COMPLEXITY: O(w h) a room map of
 * the screen, O(F ROOMDOUBT_VIEW^2) for F unseen squares beside the room. */
RoomDoubt roomdoubt_frontier(const Controller *c, const int32_t *dist, Vec2 toward, const Vec2 *follow, Vec2 *goal);

/* roomdoubt_felt(c, dist, goal): for "go next-room" when the model shows no door out
 * of the start's room: whether an object node not yet felt, taken for wall, would
 * part the start's room from another by the verdict's door rule (carryroom_merge).
 * An occupied set apart from the verge reads as an object, and objects are space
 * to rooms; but a free-standing stretch of wall between two doors is such a set
 * too, and only touch tells them apart (paper 3.4.2: an object's letter is not B;
 * objects_feel keeps the walls, screen.c counts them as verge). If so, *goal is the
 * reachable cell beside such a node nearest Utak by steps, not yet reached
 * (goals_beside); ROOMDOUBT_STUCK when none can be reached. When no one node
 * does, all of them at once are taken for wall, and the space seen cut by the
 * verdict's watershed (carryroom_watershed): if the start's room then has floor
 * beyond a door line (carryroom_beyond), the nodes within a door cell's doorway
 * are the ones to touch (a room cut off by three piers in a row, random g292).
 * COMPLEXITY: a room map of the screen for each object node, and a watershed. */
RoomDoubt roomdoubt_felt(const Controller *c, const int32_t *dist, Vec2 *goal);

/* roomdoubt_next(c, rm, cr, room, dist, goal): for "go next-room", the doors of cr
 * (rm's rooms merged by the verdict's rule) that may owe their narrowness to
 * squares the eye has not settled are no doors to claim by: their two sides are
 * joined in cr (merged, peak, door). A door is UNSETTLED when a square facing floor
 * that may set its clearance (within that clearance and 1.5 of the door's cell, or
 * beside an end of the run across it) is unseen (the space may go on there: the
 * door's width is not known), or occupied and seen only coarsely, Utak never
 * within GOALS_LOOK + 1 of it, and with those coarse faces set back as for
 * roomdoubt_jambs a side would no longer widen well beyond it by the verdict's
 * rule. A coarse cell across an object near a wall, or a small object merged with
 * the unseen behind it, reads as a wall (paper 3.4.2); the judge counts objects
 * as space, and where the eye has not looked it knows nothing: a claim through
 * such a door is a false success. A door is unsettled too when a JAMB (the wall
 * square beyond an end of the run across it; and where that run is longer than
 * twice the door's clearance and 2, so that it does not lie across the narrowing,
 * a diagonal one, each verge square seen in the fovea, facing floor, within the
 * clearance and 1 of the door's cell: the faces that set its width) is a blob
 * seen in the fovea that the
 * model joins to the rest of the wall only through squares seen coarsely within
 * ROOMDOUBT_VIEW of the jamb (an object the eye did not see stand clear of the
 * wall, paper 3.4.2; the judge counts it as space), unless, the blob taken for
 * space (the run going on through it: half its extent along the run, or from the
 * door's cell through a face, more clearance), both sides would still widen well
 * beyond the door, or touch has shown the jamb B (Utak has stood beside it and
 * felt no object's colour there); until touched, the goal is the run's end
 * beside it (for a face, its free neighbour nearest the door's cell). A square Utak has stood near has been seen in
 * the fovea: read coarse again, it is only forgotten (worldmodel.h). For the
 * doors of `room` (its merged room, before the joins), *goal is where to look
 * from at the nearest such square not yet looked at (ROOMDOUBT_LOOK);
 * ROOMDOUBT_STUCK when such doors are left with nothing to look at;
 * ROOMDOUBT_NONE when there are none. COMPLEXITY: O(d (w + R)^2) for d doors of
 * run length w and reach R, O(T) a square for a trail of T points, O(w h) for
 * each look. */
RoomDoubt roomdoubt_next(const Controller *c, const RoomMap *rm, CarryRooms *cr, int32_t room, const int32_t *dist,
			 Vec2 *goal);

/* roomdoubt_hidden(c, got, at): at a corner Utak would claim, the subject's best
 * corner score being `got`: whether floor seen that would score above got +
 * CONTROLLER_CORNER_SLACK, in a room of the model's (goals_roommap_build, merged by
 * carryroom_merge_seen) other than the start's and SEEN WHOLE (no cell of it beside
 * a square never seen), may be of the start's room after all. The OPTIMISTIC map
 * takes for floor, beside the fixed space seen, every occupied square seen only
 * coarsely within a cell less a square of floor seen (1 at 2 x 2, 3 at 4 x 4: what
 * a cell straddling a face reads occupied over), and merges its rooms by the
 * verdict's door rule (carryroom_merge); such floor in the start's room there is a
 * doubt, and *at is the best-scoring square of it. WHY: the eye looks down on the
 * table, so a corner is hidden only by never having been in the field, or in it
 * only coarsely. Coarse cells that join an object to a wall close the way round
 * it, and the space between it and the corner reads as a pocket behind a door of
 * its own; Utak, measuring against the best floor of his room, would claim a
 * corner that the room's true corner beats (a false success). A room seen in part
 * is left to roomdoubt_beyond and roomdoubt_frontier: it may yet widen into a
 * room of its own, and a wall seen coarsely between two rooms would otherwise
 * always read as a possible gap. COMPLEXITY: O(w h) two room maps of the screen. */
bool roomdoubt_hidden(const Controller *c, int64_t got, Vec2 *at);
/* roomdoubt_hidden_look(c, dist, got, goal): where roomdoubt_hidden doubts, a look
 * before the doubt (task (i): Utak is free to walk; for a push he would have to let
 * go first): the square that may be floor under a coarse cell (occupied on the
 * model, seen only coarsely, within a cell less a square of floor), on the
 * optimistic map's room of the start, beside the start's room or the room of the
 * floor that beats, nearest Utak and not looked at already; true and *goal the
 * reachable cell within GOALS_LOOK of it. A look only adds what the eye saw: the
 * claim is still made by roomdoubt_hidden alone. COMPLEXITY: as roomdoubt_hidden,
 * and O(w h) goals_near for each square kept. */
bool roomdoubt_hidden_look(const Controller *c, const int32_t *dist, int64_t got, Vec2 *goal);

/* roomdoubt_maybe_floor(m, x, y): square (x, y) is occupied on the model but seen only
 * coarsely, within a cell less a square of floor seen: it may be floor (the squares
 * roomdoubt_hidden's optimistic map takes for floor; roomlean.h). */
bool roomdoubt_maybe_floor(const WorldModel *m, int32_t x, int32_t y);

#endif
