/* judgerooms.h - the judge's rooms, doors and doorways, from the verge and the walls
 * of the real TABLE (doc/verdicts.md "Rooms, doors, doorways"; paper 2.3's tasks
 * (ii), (vi)-(viii)). SIMULATOR SIDE: its own code, sharing the controller's
 * meaning (mind/rooms.c) but none of its code; it uses only base/ and body/.
 *
 * THE RULE. Only verge squares (TABLE_VERGE: verge and walls, colour B) are
 * fixed; floor and objects are free space.
 *   Clearance c(s) of a free square s: the distance from its centre to the nearest
 *   verge square's centre, by the 8-neighbour chamfer (steps 1 and sqrt 2; it is
 *   at most 8% over the Euclidean distance), squares off the TABLE being verge.
 *   Rooms by flooding from the widest places down (a watershed of clearance, in
 *   order of decreasing c, ties by square index): a square joins the region(s) of
 *   its 4-neighbours already flooded. Where it would join two regions that BOTH
 *   widen well beyond it, peak clearance p >= JUDGE_ROOM_RATIO * c and
 *   p >= c + JUDGE_ROOM_MARGIN, it is a DOOR square and joins neither: they stay
 *   two rooms. Otherwise the regions merge (a bay, a pier's shadow, a corridor end
 *   joins the room it opens into), so a large open room is one room whatever its
 *   piers and bays.
 *   The DOORWAY of a door square d of clearance c: every free square within
 *   c + JUDGE_DOORWAY_REACH (Euclidean, centre to centre) of d whose own
 *   clearance is at most c + JUDGE_DOORWAY_SLACK, and whose width across (the
 *   shorter of its runs of non-verge squares along x and along y) is at most the
 *   door square's own width across plus JUDGE_DOORWAY_WIDEN: the passage between
 *   the faces of the narrowing, not the open room just beyond its mouth, where the
 *   run across reaches the room's far walls. Doorway squares belong to no room
 *   (JUDGE_ROOM_NONE). (The widths are axis-parallel: exact for a door through an
 *   axis-parallel wall; a diagonal door's passage reads up to sqrt 2 too wide.)
 *   Utak's starting room when he starts in a doorway: the room of the nearest
 *   square (Euclidean, ties by index) that belongs to a room. */
#ifndef UTAK_JUDGEROOMS_H
#define UTAK_JUDGEROOMS_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/body/table.h"

#define JUDGE_ROOM_RATIO 2.0	/* a room's peak clearance at least twice the door's */
#define JUDGE_ROOM_MARGIN 2.0	/* and at least 2 squares more */
#define JUDGE_DOORWAY_REACH 1.0	/* squares beyond the door's half-width */
#define JUDGE_DOORWAY_SLACK 0.2	/* clearance over the door's: still the passage */
#define JUDGE_DOORWAY_WIDEN 1	/* squares of width over the door's: still the passage */
enum { JUDGE_ROOM_NONE = -1 };	/* verge, or a doorway */

typedef struct JudgeRooms {
	int32_t w, h;
	int32_t *room;		/* w * h: room 0.. or JUDGE_ROOM_NONE */
	float *clearance;	/* w * h: c(s), 0 on verge */
	int32_t count;		/* rooms */
	int32_t doors;		/* door squares */
} JudgeRooms;

/* judge_rooms_find(r, t): the rooms of TABLE t by the rule above.
 * COMPLEXITY: O(w h) for the clearance, O(w h log(w h)) for the flood order,
 * O(doors x reach^2) for the doorways. MEMORY: 21 bytes per square while it works (room,
 * clearance, flood order, union-find parent, peak, state), 8 after. */
void judge_rooms_find(JudgeRooms *r, const Table *t);
void judge_rooms_free(JudgeRooms *r);

/* judge_rooms_at(r, x, y): the room of square (x, y), JUDGE_ROOM_NONE off the
 * TABLE, on verge or in a doorway. */
int32_t judge_rooms_at(const JudgeRooms *r, int32_t x, int32_t y);

/* judge_rooms_nearest(r, x, y): the room of the nearest square that has one. */
int32_t judge_rooms_nearest(const JudgeRooms *r, int32_t x, int32_t y);

/* THE BEND (push around-corner). A room is an L-SHAPED CORRIDOR when, within its
 * bounding box (axis-aligned: the TABLE's corridors run along its axes), the squares
 * not in the room are exactly one rectangle holding one corner of the box (the
 * outer rectangle beside the bend), and each leg is at most JUDGE_LEG_WIDTH wide
 * and at least JUDGE_LEG_LENGTH times as long as wide. With the box [x0, x1] x
 * [y0, y1] and the missing rectangle, say, [xa, x1] x [ya, y1] (the NE corner):
 * leg A is [x0, xa - 1] x [y0, y1], leg B is [x0, x1] x [y0, ya - 1], and the BEND
 * is their intersection [x0, xa - 1] x [y0, ya - 1]. */
#define JUDGE_LEG_WIDTH 12	/* squares: wider is a room, not a corridor */
#define JUDGE_LEG_LENGTH 1.5	/* a leg's length over its width, at least */

typedef struct JudgeBend {
	int32_t leg[2][4];	/* x0, y0, x1, y1 (inclusive) of legs A and B */
	int32_t bend[4];	/* the intersection of the legs */
} JudgeBend;

/* judge_rooms_bend(r, room, b): whether room is an L-shaped corridor; its legs and
 * bend in b if so. COMPLEXITY: O(w h). */
bool judge_rooms_bend(const JudgeRooms *r, int32_t room, JudgeBend *b);

#endif
