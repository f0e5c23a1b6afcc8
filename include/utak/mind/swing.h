/* swing.h - the JOINED doubt settled by a quarter turn where a pull cannot settle it
 * (paper 2.2: a turn rotates only the object held, about Utak's point; paper 3.4.2:
 * the eye cannot part objects that touch; issue 13 item 6: where his model cannot
 * tell, he goes and looks). CONTROLLER SIDE: the world model and the impressions
 * only.
 *
 * WHY. joined.h settles "the brick (L-shape, triangle) may be two objects pressed
 * together" by a pull (apart.h): drawn two squares back, one object leaves floor
 * behind, a pair leaves the piece not held. But a pull moves Utak, and only a look
 * that places him shows it went its whole way (a pull that halted looks like a whole
 * one: everything he sees rode with him). On open floor the walls are seen only in
 * 2 x 2 and 4 x 4 cells, their edges known to two squares, and no look places him:
 * room.w's brick (the paper's Figure 1) was doubted so, whatever a pull showed.
 * A TURN DOES NOT MOVE HIM. Holding the object, he turns it a quarter turn about
 * his own point and looks: his place is the same before and after, so the look needs
 * nothing that stays put to be read.
 *
 * THE TEST (swing_vacated_clear). S: the object's squares before, as offsets from
 * Utak's square. R(S): each square of S turned a quarter about the centre of his
 * square ((x, y) -> (-y, x) counter-clockwise). His point may lie anywhere in his
 * square, and a turn about it places the polygon within 1.0 of the turn about the
 * centre (|I - R| = sqrt 2 times at most sqrt 2 / 2), so no square the turned object
 * owns lies outside G: R(S) grown by a ring of squares. The VACATED squares, S less
 * G (and less his own), must all read floor in the look after the turn, each in a
 * cell of 1 or 2 x 2 squares none of whose squares lies in G and all of whose
 * squares outside S are believed floor: then APART_ONE (one object). One that reads
 * occupied: APART_LEFT (a piece stayed); one in a coarser cell, or in a cell the
 * turned object may reach: APART_UNSEEN.
 * WHY SOUND. Say the object is two, P held and Q not. Q stays where it was. If the
 * turn went its whole way, Q's squares outside G read occupied: LEFT, unless every
 * square of Q lies in G, that is, within a square of where some square of S lands
 * turned. Q lies beyond P's reach only if it lies farther from Utak than all of P
 * (P touches him, and a convex piece spans every distance between its nearest and
 * farthest points) or beside P's arc; at a distance r no part of P reaches, G holds
 * only what Q itself becomes turned, r sqrt 2 away from where it was, farther than
 * a ring once r > 1. Within P's reach and its arc, Q stood in P's way: the turn
 * halted. If the turn halted (against Q, or anything), P stands short of R(P), and
 * the squares S less G it still covers read occupied: LEFT. A single object whose
 * turn halted is one object still: ONE is true of it. And Q must not be the piece
 * touch grasps: the grasp takes the first object colour touch shows (paper 2.2), so
 * every object colour touch shows must be on the object's node (as probe.h asks).
 * WHEN. joined.h's pull could not be made from where Utak stands, or was made and
 * showed neither one object nor a piece left (APART_SHORT, APART_UNSEEN), and:
 *   - he touches the object (touch's colours all on it), its squares at most
 *     SWING_MAX_SQUARES, every one within SWING_REACH of him, and the turned ones too;
 *   - for one of the two ways (counter-clockwise first), the turn's sweep is free:
 *     every square the object's squares pass over, sampled every SWING_SAMPLE_DEG
 *     degrees and grown by a ring, is the object's, his own, or believed floor seen
 *     closely (the fovea, or a 2 x 2 cell that read none occupied).
 * HOW. Grasp, turn a quarter, look (the test), turn back, release: four cycles.
 * Not ONE, he lets go without turning back: the turn may have halted, how far it
 * went he cannot tell, and a quarter back would swing what he holds past where it
 * was (the world keeps the object turned, or the piece held turned part way).
 * A verdict of ONE is kept for the object (swing_one), by ident, the centre of its
 * rectangle and its squares, as apart.h keeps a pull's. Asked once per object. */
#ifndef UTAK_SWING_H
#define UTAK_SWING_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/impression.h"
#include "utak/mind/apart.h"

#define SWING_MAX_SQUARES 128
/* Offsets from Utak's square a square of the object (before or turned, ring
 * included) may have: within the cells of 1 and 2 x 2 squares (the fovea and the
 * intermediate zone run from -8 to 7). */
#define SWING_REACH 6
#define SWING_SAMPLE_DEG 3.0
#define SWING_KEPT 4

typedef enum SwingStage { SWING_IDLE, SWING_GRASP, SWING_TURN, SWING_BACK, SWING_RELEASE } SwingStage;

typedef struct SwingRun {
	SwingStage stage;
	ApartVerdict verdict;
	int sign;	/* +1 counter-clockwise, -1 clockwise */
	int32_t ident;	/* the node turned (model ident), the centre of its rectangle, its squares */
	Vec2 at;
	int32_t squares;
	int32_t n;	/* S, offsets from Utak's square */
	int8_t sx[SWING_MAX_SQUARES], sy[SWING_MAX_SQUARES];
	/* Sure floor before the turn (believed floor, seen in the fovea or in a 2 x 2
	 * cell that read none), offsets -8..7 each way: row (oy + 8) * 16 + ox + 8. */
	bool floor_before[16 * 16];
	int kept;	/* objects a turn showed one */
	int32_t one_ident[SWING_KEPT];
	Vec2 one_at[SWING_KEPT];
	int32_t one_squares[SWING_KEPT];
} SwingRun;

struct Controller;

/* swing_vacated_clear(sx, sy, n, sign, imp, floor_at, ctx): THE TEST above on the
 * impression imp taken after the turn, S the n offsets (sx, sy) from Utak's square,
 * turned by sign quarter turns; floor_at(ctx, ox, oy) says whether the square at
 * offset (ox, oy) is believed floor. A pure function (unit-tested). */
ApartVerdict swing_vacated_clear(const int8_t *sx, const int8_t *sy, int32_t n, int sign, const Impression *imp,
				 bool (*floor_at)(const void *ctx, int32_t ox, int32_t oy), const void *ctx);

/* swing_begin(c, k): the turn of node k begun (WHEN; its grasp the next command);
 * false when it cannot be made from where Utak stands. */
bool swing_begin(struct Controller *c, int32_t k);

/* swing_goal(c, k, dist, &goal): the nearest square (fewest steps, dist over the
 * screen's cells from Utak's, goals_reach) from which node k could be turned:
 * floor seen closely, beside the object and no other, its squares within reach and
 * a way of turning free (WHEN); false when there is none. Touching the object at
 * its end, a brick 8 long lies 7 squares off and cannot be turned: beside its
 * middle, it can. */
bool swing_goal(const struct Controller *c, int32_t k, const int32_t *dist, Vec2 *goal);

/* swing_decide(c, cmd): the turn's next command; false when none is under way or it
 * has just ended (the verdict in c->swing.verdict). */
bool swing_decide(struct Controller *c, MotorCommand *cmd);

/* swing_perceive(c, cmd): after the quarter turn, the test on its impression. */
void swing_perceive(struct Controller *c, const MotorCommand *cmd);

/* swing_verdict_text(v): a turn's verdict, for the release's note. */
const char *swing_verdict_text(ApartVerdict v);

/* swing_one(c, j): a turn showed node j one object (ident, or the centre of its
 * rectangle within OBJECTS_SAME, and the same squares). */
bool swing_one(const struct Controller *c, int32_t j);

#endif
