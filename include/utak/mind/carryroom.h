/* carryroom.h - where a carried object must end, by the verdicts' meaning, on Utak's
 * own model: the rooms that count as rooms, and the legs and bend of an L-shaped
 * corridor (paper 2.3 tasks (vi)-(ix); the judge's rule is judgerooms.h's, which the
 * controller may not include: the rule is restated here and applied to the model).
 * CONTROLLER SIDE: it reads the room map of the screen (goals.h), nothing else.
 *
 * WHY. rooms.h cuts the space at any narrowing with a little room behind it: an
 * emptied pocket of a wall, a bay, a corridor's end. The verdict (judgerooms.h)
 * counts a door only between two spaces that BOTH widen well beyond it. Were Utak to
 * believe the pocket a next room, he would push the object into it and believe the
 * task done while the judge says it is not; so his claim uses the judge's meaning.
 *
 * THE ROOMS. Every door of rooms.h is weighed in order of decreasing clearance (the
 * distance from its cell's centre to the nearest blocked centre; ties by index),
 * as the judge's watershed meets them: with each side's PEAK (the largest clearance
 * of any cell of the rooms merged so far on that side), the door stays a door when
 * both peaks p satisfy p >= CARRYROOM_RATIO * c and p >= c + CARRYROOM_MARGIN (c the
 * door's clearance); else its two sides are merged into one room. A merged room is
 * named by the least rooms.h index in it.
 *
 * THE BEND (push around-corner), the judge's rule with a tolerance for the eye: a
 * merged room is an L-shaped corridor when, within the bounding box of its free
 * cells (or that box trimmed by up to CARRYROOM_TRIM edge lines a side, each holding
 * fewer than half the room's cells of the line inside it: a wall the eye misplaced
 * outwards; the trimmed room cells count as mismatched), the cells not in it are one rectangle holding a corner of the box, give or
 * take at most CARRYROOM_BEND_SLACK cells per cell of the box's half perimeter (a
 * wall seen from afar is misplaced by a square or so), and each leg is at most
 * CARRYROOM_LEG_WIDTH + CARRYROOM_EYE_SLACK wide (its width the median, over its
 * lines beyond the bend, of the room's cells across it) and at least
 * CARRYROOM_LEG_LENGTH times as long as wide (by the box). The EYE SLACK is a
 * square: a wall seen from afar, and then kept, may lie a square off, and a leg 12
 * wide (the judge's limit) is read 13 (corridor-north.w's far leg). So a corridor
 * exactly 13 wide is one to Utak and not to the judge: the one place where his
 * belief may be a false success; on a model that is exact the rule is the judge's
 * otherwise (test_carryroom.c).
 * The legs and the bend are the judge's (judgerooms.h: leg A the columns beside
 * the missing rectangle, full height; leg B the rows beside it, full width; the
 * bend their intersection); of the four corners the one whose best rectangle has
 * the fewest mismatched cells wins, ties to the earlier corner (SW, SE, NW, NE). */
#ifndef UTAK_CARRYROOM_H
#define UTAK_CARRYROOM_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/goals.h"

#define CARRYROOM_RATIO 2.0	 /* judgerooms.h's JUDGE_ROOM_RATIO */
#define CARRYROOM_MARGIN 2.0	 /* judgerooms.h's JUDGE_ROOM_MARGIN */
#define CARRYROOM_LEG_WIDTH 12	 /* judgerooms.h's JUDGE_LEG_WIDTH */
#define CARRYROOM_LEG_LENGTH 1.5 /* judgerooms.h's JUDGE_LEG_LENGTH */
#define CARRYROOM_BEND_SLACK 0.5 /* mismatched cells per cell of half perimeter */
#define CARRYROOM_TRIM 2	 /* edge lines a side the box may lose */
#define CARRYROOM_EYE_SLACK 1	 /* squares a leg may read wider than the judge's limit */

typedef struct CarryRooms {
	int32_t count;	 /* rooms.h's rooms */
	int32_t *merged; /* per rooms.h room: its merged room (the least index in it) */
	bool *door;	 /* per rooms.h door: still a door by the verdict's rule */
	bool *undecided; /* per rooms.h door: kept a door only because a side is seen in part
			    (carryroom_merge_seen) */
	double *peak;	 /* per merged room (indexed by its name): its largest clearance */
} CarryRooms;

/* carryroom_merge(rm, out): the rooms of rm by the verdict's rule (above).
 * COMPLEXITY: O(w h + doors log doors). */
void carryroom_merge(const RoomMap *rm, CarryRooms *out);
/* carryroom_merge_seen(rm, s, out): as carryroom_merge, but a narrowing that fails
 * the rule joins its two sides only when both, as merged so far, are seen whole (no
 * cell beside a square of s never seen); else it stays a door, undecided. A room
 * seen in part reads narrower than it is and may yet widen into a room of its own:
 * merged too soon, it would make the next room's corner look like the starting
 * room's. Used for the corner of Utak's starting room (goals.c, roomdoubt.c).
 * COMPLEXITY: O(w h + doors log doors). */
void carryroom_merge_seen(const RoomMap *rm, const Screen *s, CarryRooms *out);
/* carryroom_merge_maybe(rm, s, out): as carryroom_merge_seen, but a narrowing that
 * fails the rule stays a door, undecided, only while EACH side, as merged so far,
 * is wide by the rule or seen in part: a side seen whole and narrow cannot widen,
 * and the narrowing can be no door whatever the other side turns out to be. The
 * doors that MAY be doors, for a doubt (hallsplit.h). COMPLEXITY: as above. */
void carryroom_merge_maybe(const RoomMap *rm, const Screen *s, CarryRooms *out);
void carryroom_free(CarryRooms *cr);
/* carryroom_at(cr, rm, x, y): the merged room of cell (x, y), -1 blocked or off. */
int32_t carryroom_at(const CarryRooms *cr, const RoomMap *rm, int32_t x, int32_t y);

typedef struct CarryBend {
	int32_t leg[2][4]; /* x0, y0, x1, y1 (inclusive, cells) of legs A and B */
	int32_t bend[4];   /* their intersection */
	int32_t mismatch;  /* cells of the box that break the L */
} CarryBend;

/* carryroom_bend(cr, rm, room, b): whether merged room is an L-shaped corridor (the
 * rule above); its legs and bend in b if so. COMPLEXITY: O(w h). */
bool carryroom_bend(const CarryRooms *cr, const RoomMap *rm, int32_t room, CarryBend *b);

/* carryroom_watershed(g, room): the verdict's rooms restated whole on grid g (free
 * cells space, the rest and off the grid wall), not through rooms.h's doors: the
 * clearance of each free cell (its distance to the nearest blocked centre, 8-
 * neighbour chamfer, steps 1 and sqrt 2), the cells flooded by decreasing
 * clearance (ties by index), each joining the regions of its flooded 4-neighbours
 * unless two of them have a peak p >= CARRYROOM_RATIO c and p >= c +
 * CARRYROOM_MARGIN (c its clearance): then it is a door cell and joins none (the
 * narrow regions merge into the widest). room[i] names the region (one of its
 * cells' indices), -1 for a blocked or door cell. WHY: rooms.h finds a door as a valley along the
 * skeleton's pathgraph; where two piers stand offset across a hall, the narrowing
 * lies across a diagonal that no skeleton edge runs along, and rooms.h finds no
 * door where the judge's watershed does (random g51: hallsplit.h's settling).
 * Doorways are not marked. COMPLEXITY: O(w h log(w h)). MEMORY: 17 bytes a cell
 * while it works. */
void carryroom_watershed(const Grid *g, int32_t *room);
/* carryroom_watershed_clear(g, room, clear): the same, and each cell's clearance
 * (the chamfer's; 0 blocked) in clear (w h of them). */
void carryroom_watershed_clear(const Grid *g, int32_t *room, float *clear);
/* carryroom_watershed_slack(g, slack, room): the same with every region's peak
 * counted slack squares more (a door by a hair: doorsure.h); slack 0 is
 * carryroom_watershed. */
void carryroom_watershed_slack(const Grid *g, double slack, int32_t *room);

#define CARRYROOM_DOORWAY_REACH 1.0  /* judgerooms.h's JUDGE_DOORWAY_REACH */
#define CARRYROOM_DOORWAY_MARGIN 2.0 /* squares more: a wall on the model may lie a square or two off */
#define CARRYROOM_CHAMFER 1.08	     /* the chamfer's clearance over the Euclidean, at most */

/* carryroom_beyond(g, si, sj, out): per cell of g (w h of them in out), whether it
 * lies beyond the door line of a room other than the start's by the verdict's
 * watershed restated on g (carryroom_watershed): in a region other than the one
 * of the free cell nearest (si, sj) that is in a region (the judge's start room,
 * judge_rooms_nearest) and, when (si, sj) lies within a door cell's doorway (its
 * clearance, CARRYROOM_CHAMFER over, and CARRYROOM_DOORWAY_REACH), other than
 * every region within 2 of that door cell (the judge's nearest room to a start in
 * its doorway may be either side); and farther from every door cell than
 * CARRYROOM_CHAMFER times its clearance, CARRYROOM_DOORWAY_REACH and
 * CARRYROOM_DOORWAY_MARGIN (the judge's doorway, judgerooms.h, lies within the
 * door square's clearance and JUDGE_DOORWAY_REACH of it; its other bounds only
 * shrink it). Returns how many cells are. WHY: "in the next room" is claimed by
 * the verdict's own meaning of a room (issue 13: rooms.h's doors merged by
 * carryroom_merge may lie at another narrowing than the judge's, or find none
 * where it finds one, random g197 g297; nextroom.h).
 * COMPLEXITY: O(w h log(w h)) the watershed, O(w h) the start, O(doors r^2) the
 * doorways (r the doorway's reach). MEMORY: 22 bytes a cell while it works. */
int64_t carryroom_beyond(const Grid *g, int32_t si, int32_t sj, bool *out);

#endif
