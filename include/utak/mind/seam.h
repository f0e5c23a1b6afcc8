/* seam.h - the SEAM doubt on the object Utak would claim as "the square": it may be
 * two or more objects pressed together, which the eye cannot part, and motion
 * settles it, with nothing fixed in view (paper 3.4.2: two objects that touch make
 * one set of occupied squares; paper 2.2: a grasp takes one object, and a push
 * moves only it; issue 13 item 6: "where his model cannot tell, he goes and
 * looks"). CONTROLLER SIDE: it acts on the impressions and the world model only.
 *
 * WHY. Two 6 x 3 bricks pressed together own exactly the squares of a 6 x 6 square;
 * so do four 3 x 3 squares, two right triangles along a diagonal, a brick and a
 * block of wall. No look tells, and the probe (probe.h) pushes by a quarter square
 * and weighs its looks at the displacement it commanded: a push of one piece into
 * the other halts, the eye cannot see a quarter square's halt, and a rectangle of
 * square proportions explained every look (14 of 18 runs of the three square tasks
 * on such a pair claimed it, a false success each). joined.h's pull settles it for
 * other shapes but needs something fixed in view to tell a halted pull from a
 * whole one, and a lone square on open floor has nothing.
 *
 * THE IDEA. Utak and the object he holds move rigidly: whatever the push does, one
 * object's image, RELATIVE TO UTAK, does not change (it rides with him, or neither
 * moved). Only a part he does not hold can change it: it stays where it was while he
 * moves, and so shows, in his frame, shifted by what he really moved. A halt cannot
 * hide a pair from every push: two pieces meeting along a line, a piece blocked by
 * the other along t is free along -t (a seam along t lets it slide both ways). So
 * Utak grasps, pushes by SEAM_STEP squares along a line and back, then the other way
 * and back (along the axis he touches it on, and across it when there is room), and
 * after each push compares the look with one rigid object.
 * TOUCH FIRST. An object has one colour and the wall's is B: where touch, beside it,
 * feels B or two letters on squares the model holds as the object, it is not one
 * object, and no push is needed (a brick against a block of wall reads a square; a
 * same letter proves nothing: two objects may share one, utak(5)).
 * THE TEST (seam_look_fits). With S the object's squares at the grasp and D the
 * displacement of Utak's believed square since then, one object of those squares
 * now owns a set within a square of S + D on each axis (what Utak's point moved
 * within his square moves it on the eye's grid by less than a square): every
 * square of S + D whose 8 neighbours are all in S + D is surely occupied (a convex
 * polygon owning all 9 squares of a 3 x 3 block covers the middle one); every
 * square farther than one from S + D is surely what the model believed before the
 * grasp, where it and its 8 neighbours were believed floor (or were S's own, left
 * behind); Utak's own square is occupied. A cell of 1 or 2 x 2 squares whose gray
 * level no count between its sure squares and its sure and unsure ones gives
 * contradicts one object: PARTED. Every look of the pushes fitting: ONE.
 * WHY SOUND. Say S is A (held) and P (not held). P shows, in the model's frame (his
 * believed square), at P + D - (what he truly moved). A push that moved A by its
 * whole step (the free one of two opposite) leaves P two squares (SEAM_STEP) from
 * where one object would put it, beyond the test's band of one: P's far side reads
 * occupied where one object leaves floor, or its near side floor where one object
 * surely is. A halt shows nothing, so never a false ONE from it. The world refuses
 * two objects on one square (utak(5)), so pieces pressed together meet along the
 * squares' edges, and each square is one piece's. A lone square whose push halted
 * on something unseen, or a model wrong about the floor round it, may read PARTED:
 * a claim lost, never a false one. Checked with the simulator as the oracle
 * (tests/unit/test_seam.c: pairs of bricks split at and off the middle, four small
 * squares, an L and a square in its notch, never claimed; a lone square at 0, 20
 * and 35 degrees claimed; the test itself on the simulator's own looks).
 * LIMITS. A piece locked against the others both ways along both lines (a plus with
 * a square in each corner) moves in none, and is taken for one object: the claim
 * then rests on the probe as before. Where no two opposite pushes can be made from
 * any reachable square beside it, the claim goes on as before too.
 * THEN. ONE: the claim goes on (the probe, probe.h). PARTED: the object is not the
 * square (objects.c names it nothing, as a probe's disproof), and the task goes on:
 * another object, or an honest failure. The pieces are let go where the test
 * ended; no object whose rectangle's centre lies within SEAM_REACH of where they
 * were is taken for the square after (objects.c): a piece may itself be a square
 * (four small squares), but the task means the one nearest the start as they lay,
 * and the pushes have moved them (adversarial worlds: claiming a piece parted and
 * read anew was 2 false successes).
 * UNDER ERRING MOTION. The test's pushes move Utak and the object together, but
 * each errs, and off the grid the squares they own change: so no claim rests on
 * where the pushes left him. "go square": the claim "touches the square" is made
 * only on touch AFTER the last push and release (the probe's, which comes after
 * this test: seam_felt_after); touch feeling nothing of it, he goes beside it
 * again first (square-tight.w under noise 0.05, seed 7, and tworooms.w, seed 4:
 * two false successes before, claimed a square off it). "go round square": the
 * claim is that he is home, by his own reckoning, which each push leaves off by
 * its error; where the disparity has shown motion to err (worldmodel_motion_error
 * > 0) the test is not made there (square-tight.w, seeds 5 and 9: home 1.6 off,
 * believed). "push square": the claim rests on the corner, seen and felt after.
 * WHERE. "go square": beside the object, before the probe (controller.c, arrive);
 * "go round square": where the loop closed, or from home and home again; "push
 * square": before the first grasp. From where he stands when the first object touch
 * shows is the object's, else from the nearest square it can be made from, by what
 * the model believes, once (as joined.h's pull).
 * COST: a grasp, four or eight pushes, a release (up to ten cycles), once per
 * object claimed. */
#ifndef UTAK_SEAM_H
#define UTAK_SEAM_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/impression.h"

/* Squares per push: two, beyond the test's band of one. */
#define SEAM_STEP 2
/* Squares of S remembered, at most: a larger object is not tested. */
#define SEAM_MAX_SQUARES 400
/* The window of the model's beliefs kept at the grasp, round Utak's square. */
#define SEAM_WINDOW 40
/* Pushes of one test, at most: there and back along two lines, both ways. */
#define SEAM_MOVES 8
/* Squares round a parted object's rectangle within which no object is taken for
 * the square: its pieces, pushed up to SEAM_STEP off, and a square beyond. */
#define SEAM_REACH (SEAM_STEP + 1)
/* Objects tested in a task, remembered. */
#define SEAM_KEPT 8

typedef enum SeamVerdict {
	SEAM_UNTRIED,
	SEAM_ONE,    /* every look fitted one object, pushed both ways along a line */
	SEAM_PARTED, /* a look no one object explains: pieces pressed together */
	SEAM_UNSEEN, /* nothing held after the grasp: nothing settled */
} SeamVerdict;

typedef struct SeamRun {
	bool active;
	bool grasp_due;
	int32_t ident;   /* the node tested (model ident) ... */
	Vec2 at;         /* ... the centre of its rectangle at the grasp ... */
	int32_t squares; /* ... and its squares then */
	int32_t n;       /* S: its squares at the grasp */
	int32_t sx[SEAM_MAX_SQUARES], sy[SEAM_MAX_SQUARES];
	int32_t ox, oy;  /* Utak's believed square at the grasp */
	int32_t wx, wy;  /* the window's lower-left square */
	uint8_t floor_before[SEAM_WINDOW * SEAM_WINDOW];
	int moves, next; /* the pushes (unit steps along the model's axes) */
	int8_t mx[SEAM_MOVES], my[SEAM_MOVES];
	Box box;              /* the object's rectangle at the test */
	SeamVerdict verdict;
	bool going;           /* going where the test can be made from: */
	Vec2 goal;            /* ... that square's centre, model frame ... */
	int32_t going_ident;  /* ... and the node to test (model ident) */
	char note[200];
	int kept;
	int32_t kept_ident[SEAM_KEPT];
	Vec2 kept_at[SEAM_KEPT];
	int32_t kept_squares[SEAM_KEPT];
	Box kept_box[SEAM_KEPT];
	SeamVerdict kept_verdict[SEAM_KEPT];
} SeamRun;

/* seam_look_fits(sx, sy, n, dx, dy, ux, uy, imp, floor_at, ctx): THE TEST on
 * impression imp, taken with Utak on model square (ux, uy), for one object of the n
 * squares S displaced by (dx, dy) squares: false when a cell of 1 or 2 x 2 squares
 * contradicts it; floor_at(ctx, x, y) is the model's belief before the grasp. A
 * pure function (unit-tested). */
bool seam_look_fits(const int32_t *sx, const int32_t *sy, int32_t n, int32_t dx, int32_t dy, int32_t ux, int32_t uy,
		    const Impression *imp, bool (*floor_at)(const void *ctx, int32_t x, int32_t y), const void *ctx);

struct Controller;

/* seam_open(c, k): a square task, node k an object read the square and seen whole,
 * and not yet tested. */
bool seam_open(struct Controller *c, int32_t k);

/* seam_begin(c, k): seam_open: begun (the grasp the next command) when the test can
 * be made from where Utak stands, else the way begun to the nearest square it can
 * be made from, by what the model believes, when the way is known; false, nothing
 * begun, when neither (then the claim goes on as before). */
bool seam_begin(struct Controller *c, int32_t k);

/* seam_goal(c, out): while going there, the goal (goals.c). */
struct GoalResult;
bool seam_goal(struct Controller *c, struct GoalResult *out);

/* seam_arrive(c): arrived where the test can be made from: begun if it can be (else
 * not tried again, and the claim judged as before); false when Utak was not going
 * there. */
bool seam_arrive(struct Controller *c);

/* seam_loop_closed(c): "go round": where the loop closed (its last point before
 * home), round the task's object, seam_begin on it: tested from there, beside it,
 * then home (as joined.h's pull). */
bool seam_loop_closed(struct Controller *c);

/* seam_decide(c, cmd): the next command while a test is under way; false when none
 * is (the claim is then judged again where he stands). */
bool seam_decide(struct Controller *c, MotorCommand *cmd);

/* seam_parted(c, ident, at, squares): an object (ident, or the centre of its
 * rectangle at within OBJECTS_SAME of one, of as many squares) a test showed is
 * pieces pressed together, or one whose rectangle's centre lies within SEAM_REACH
 * of such an object's rectangle (one of its pieces: see THEN). */
bool seam_parted(const struct Controller *c, int32_t ident, Vec2 at, int32_t squares);

/* seam_nearer(c, k, why, size): an object a test showed is pieces lies nearer the
 * start than node k (the centres of their rectangles): one of its pieces may be a
 * square, the one the task means (the nearest), so a claim on k is doubted; why
 * says so. objects_doubt asks it first. */
bool seam_nearer(const struct Controller *c, int32_t k, char *why, size_t size);

/* seam_felt_after(c): "go square", the claim about to be made after pushes (the
 * probe's, probe.h, the last of which may leave him a square off: a push moves
 * Utak and the object together, but under erring motion, off the grid, so that
 * on the squares touch reads they need not touch any more): true when touch, on
 * the impression after the release, feels an object's letter on a square the model
 * holds as the object he claims. The claim "touches the square" rests on that
 * evidence, after the pushes, or is not made: he goes back beside it first
 * (probe.c). For other tasks, true (touch is not what they claim). */
bool seam_felt_after(struct Controller *c);

/* seam_note(c, note, size): the trace's note on the last command of a test; false
 * when none was under way. */
bool seam_note(struct Controller *c, char *note, size_t size);

#endif
