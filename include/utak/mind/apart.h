/* apart.h - settling the MERGED doubt by motion: one object, or two the eye joined
 * (paper 2.2: grasp and push move only the held object; paper 3.4.2: the eye cannot
 * part two objects that touch; issue 13 item 6). CONTROLLER SIDE: it acts on the
 * impressions and the world model only; rival.c runs it when the doubt it settles
 * names an object Utak stands beside.
 *
 * WHY. objects.h's MERGED: an object of the model nearer the start, not read the
 * square, whose squares are no convex polygon's and hold a 2 x 2 block where a
 * square may lie, may be a square merged in the model with a neighbour. No look
 * tells: the squares are the same either way. Motion tells. A grasp takes ONE
 * object and a push moves only it (objects do not stick; the simulator refuses a
 * step that would put the held object on another's square, motion.c): grasped
 * and drawn back, one polygon comes away whole and leaves nothing behind; a square
 * merged with a neighbour stays where it was, or comes away alone.
 *
 * HOW. Beside the set S (node j's squares, remembered when grasped), touching a
 * square of it along an axis (the four touch cells beside him) with APART_WAY
 * squares of believed floor behind him: GRASP, PUSH by TUG_STEP straight back
 * (tug.h's step and its test of the way, tug_way_free), look; PUSH by TUG_STEP
 * again, look; PUSH back by what he believes he drew, RELEASE (the world left as
 * it was found, so that a loop round the square, judged where it stood, is not
 * disturbed).
 * THE TEST, on the impression after the first pull, with t the pull (the whole
 * square vector commanded): every square of V = S \ (S + t), the squares that
 * one polygon drawn by t leaves empty, lies in a retinal cell of one or 2 x 2
 * squares (fovea or intermediate zone) that reads level 0: every square of the
 * cell is floor (eye.h: one occupied square of 4 already reads 2; a 4 x 4 cell
 * reads 0 over one occupied square, so it does not count). And both pulls moved
 * Utak by the whole step (within APART_SLACK of it, his believed position).
 * WHY IT IS SOUND. Say S is two objects, the one drawn, A, and the one that
 * stayed, P (or several: take P the rest). A moved by exactly t (the first pull
 * went its whole way: the second pull moved too, and a pull halted by P leaves A
 * against P, so that the next pull along the same line cannot move: the second
 * pull is there to show the first was not halted short of t, which the eye cannot
 * tell from a fraction of a square). Then P's squares are still occupied, and so
 * is A + t, disjoint from P. A finite set is not its own translate: some p of P
 * has p - t outside P; p - t is not in A either (A + t would hold p, which P
 * holds); so p is in V, and reads occupied. A grasp that took an object outside S
 * moves none of S: all of V reads occupied. A pull that does not go its way (the
 * object wedged, or more than one step of the way blocked) settles nothing.
 * Checked against the simulator itself as the oracle (tests/unit/test_apart.c:
 * a square against an L, in every pose of a sweep, pulled by the body's own
 * motion, never passes; an L alone does, wherever V lies in the field).
 * WHAT IT SETTLES. Passed: S is one polygon; not convex (MERGED's notch), so no
 * square; the MERGED doubt on it is gone (apart_one, remembered per object like
 * rival.c's probes: by ident, or by the centre of its rectangle within
 * OBJECTS_SAME, with the set S: apart_no_square). Not passed: the doubt stands,
 * and is not tried again (rival.c's tried list) but where motion is noisy
 * (apart_redo). Noise (--noise) makes the pull a fraction off the grid: then V
 * may read occupied where the object's squares changed, and the test fails, the
 * doubt standing (never the other way: it asks only for floor where S would have
 * left floor); the pull is then made again, at most APART_REDO times.
 * COST: five cycles beside the object, and the way there and back (rival.h). */
#ifndef UTAK_APART_H
#define UTAK_APART_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/impression.h"

/* Squares of S remembered, at most: a larger set is not pulled. */
#define APART_MAX_SQUARES 400
/* Believed floor needed behind Utak: both pulls. */
#define APART_WAY 4
/* A pull went its whole way when Utak's believed point moved within this of it. */
#define APART_SLACK 0.5
/* Squares believed occupied, not the object's, that the look after a motion must
 * cover in its finer cells (apart.c, anchored): what places Utak. */
#define APART_ANCHORS 8
/* Objects settled as one, remembered in a task. */
#define APART_KEPT 8
/* Pulls made again, in a task, where motion has shown itself noisy (apart_redo). */
#define APART_REDO 2

/* A set of squares remembered as a bitmap: row r, bit b is square (x0 + b, y0 + r).
 * A set whose rectangle is wider or taller than APART_BOX is not kept. */
#define APART_BOX 64
typedef struct ApartSet {
	int32_t x0, y0, n;
	uint64_t row[APART_BOX];
} ApartSet;

typedef enum ApartStage {
	APART_IDLE,
	APART_GRASPED, /* the grasp next (grasp_due), then the first pull */
	APART_PULLED,  /* the first pull made: judged, then the second */
	APART_PULLED2, /* the second made: back */
	APART_BACK,    /* pushed back: release */
} ApartStage;

typedef enum ApartVerdict {
	APART_UNTRIED,
	APART_ONE,     /* S came away whole: one polygon */
	APART_LEFT,    /* some square of V reads occupied: part stayed, or none came */
	APART_UNSEEN,  /* some square of V not in a fine enough cell, or the grasp took nothing */
	APART_SHORT,   /* a pull did not go its whole way */
} ApartVerdict;

typedef struct ApartRun {
	ApartStage stage;
	bool grasp_due;           /* begun: the grasp is the next command */
	ApartVerdict verdict;
	int32_t ident;            /* the node pulled (model ident) ... */
	Vec2 at;                  /* ... the centre of its rectangle at the grasp ... */
	int32_t squares;          /* ... and its squares then */
	int dx, dy;               /* the pull's direction (unit, model frame = Utak's) */
	Vec2 from;                /* where the last pull set off (believed) */
	double drawn;             /* how far he believes he drew, both pulls */
	bool clear;               /* the first pull's test passed */
	int32_t n;                /* S: node j's squares at the grasp */
	int32_t sx[APART_MAX_SQUARES], sy[APART_MAX_SQUARES];
	/* Objects shown one (APART_ONE): ident, the centre of the rectangle, and the
	 * set S pulled (ApartSet: apart_one matches the node against it). */
	int kept;
	int32_t one_ident[APART_KEPT];
	Vec2 one_at[APART_KEPT];
	int32_t one_squares[APART_KEPT];
	ApartSet one_set[APART_KEPT];
	int redone;               /* pulls made again this task (apart_redo) */
} ApartRun;

struct Controller;

/* apart_vacated_clear(sx, sy, n, tx, ty, ux, uy, imp, floor_at, ctx): THE TEST above
 * on impression imp, taken with Utak on model square (ux, uy), for the set S of n
 * squares drawn by (tx, ty): APART_ONE when every cell over a square of S \ (S + t)
 * is of 1 or 2 x 2 squares and reads the level of S + t's squares in it (the other
 * squares of S floor, any square of neither believed floor: floor_at(ctx, x, y));
 * APART_LEFT when one reads otherwise; APART_UNSEEN when one is coarser, or holds a
 * square of neither not believed floor. A pure function (unit-tested). */
ApartVerdict apart_vacated_clear(const int32_t *sx, const int32_t *sy, int32_t n, int32_t tx, int32_t ty, int32_t ux,
				 int32_t uy, const Impression *imp, bool (*floor_at)(const void *ctx, int32_t x, int32_t y),
				 const void *ctx);

/* apart_goal(c, j, dist, goal): the reachable square (screen distances dist) nearest
 * Utak from which node j can be pulled as HOW says, by what the model believes (the
 * first occupied square touch would feel there is j's, along an axis, and the way
 * behind is floor); false when there is none. */
bool apart_goal(const struct Controller *c, int32_t j, const int32_t *dist, Vec2 *goal);

/* apart_begin(c, j): the pull of node j begun (its grasp in *cmd on the next
 * apart_decide), when Utak touches one of its squares along an axis with the way
 * behind him believed floor; false, nothing begun, when he does not. */
bool apart_begin(struct Controller *c, int32_t j);

/* apart_decide(c, cmd): the next command while a pull is under way; false when it
 * has ended (c->apart.verdict says how). */
bool apart_decide(struct Controller *c, MotorCommand *cmd);

/* apart_redo(c): the pull just ended LEFT or SHORT where motion has shown itself
 * noisy (worldmodel_motion_error > 0), at most APART_REDO times a task: true, and
 * counted, when the pull is to be made again (rival.c goes to where one can be
 * made, apart_goal, and begins it there as it did the first).
 * WHY (paper: "where his model cannot tell, he goes and looks"; issue 13): under
 * --noise a pull goes a fraction of a square astray, and Utak's belief of where he
 * stood when he grasped may be a square off (the look after the pull corrects it,
 * and the pull reads SHORT), and an object whose edges lie on the grid, drawn a
 * fraction short, still owns the squares its trailing edge grazes (LEFT). Noise
 * spoils the look, not the rule: the next pull, from where the look placed him,
 * of the object pushed back a fraction off the grid, is judged by THE TEST as the
 * first was and is as sound (a part that stayed reads occupied on every try). Where
 * motion is exact, a pull made again would read as the first did: not made. */
bool apart_redo(struct Controller *c);

/* apart_set_make(set, sx, sy, n): the n squares as a set; false when their
 * rectangle does not fit APART_BOX (nothing kept). */
bool apart_set_make(ApartSet *set, const int32_t *sx, const int32_t *sy, int32_t n);

/* apart_set_holds(set, x, y): square (x, y) is one of the set's. */
bool apart_set_holds(const ApartSet *set, int32_t x, int32_t y);

/* apart_still_one(set, nx, ny, n): a node of the n squares (nx, ny) is still the set
 * shown one (APART_ONE): every square of it is one of the set's or beside one (the
 * eight round it), and those not the set's hold no 2 x 2 block. A pure function
 * (unit-tested).
 * WHY NOT THE COUNT (issue 13): the set came away whole; pushed back by what Utak
 * believes he drew, under --noise it lands a fraction off the grid and owns a row
 * or column more, and seen again from elsewhere its node gains or loses a square
 * at its edge (his belief of where he stood a square off): the node's count
 * changes though nothing new joined it (room.w, the L: 49 to 57 squares; the
 * doubt stood on 6 of 46 noisy runs whose pull had settled it). WHY SOUND: what
 * MERGED fears is a square of the task's (a 2 x 2 block at least, objects.h)
 * merged with it: squares not pulled that hold no 2 x 2 block hold no such square,
 * and one that overlapped the set would have been pulled with it, where THE TEST
 * shows a part that stays; only Utak moves objects, and one he pushes is the
 * task's own node, which MERGED does not ask about. A node grown past a square
 * round the set (another object seen joined to it) is not the set: the doubt
 * stands. */
bool apart_still_one(const ApartSet *set, const int32_t *nx, const int32_t *ny, int32_t n);

/* apart_one(c, j): node j was shown one object by a pull this task (and has as
 * many squares as then: JOINED, joined.h, fears any object pressed to it, however
 * thin). */
bool apart_one(const struct Controller *c, int32_t j);

/* apart_no_square(c, j): node j was shown one object by a pull this task, and is
 * still the set pulled (apart_still_one): MERGED's doubt (objects.h) is gone. */
bool apart_no_square(const struct Controller *c, int32_t j);

/* apart_verdict_text(v): what the verdict means, for the trace and the doubt. */
const char *apart_verdict_text(ApartVerdict v);

#endif
