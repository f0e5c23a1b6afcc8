/* probe.h - shape by motion: is what the eye saw of an object before and after a push
 * of a fraction of a square what a square would show? (paper 3.3: a shape read
 * from the squares an object covers is a hypothesis until confirmed; issue 13,
 * items 1, 2 and 6). CONTROLLER SIDE: pure geometry on what Utak has seen and the
 * displacement he commanded; it reads neither the TABLE nor the world.
 *
 * WHY. The TABLE is a grid of squares, and the eye counts the squares an object
 * owns (those whose open interior meets its polygon, geom.h). From any number of
 * views of an object that stands still Utak learns only which squares it owns, and
 * a polygon of more corners whose cut corners fall within a square's squares owns
 * exactly the squares the square owns (objects.h; worldgen's irregular pieces do,
 * 6 of 7 that Utak took for the square). Motion re-rasterises: pushed by a
 * fraction of a square the object owns other squares, and which ones depends on
 * its true outline. A square pushed by half a square owns squares a square at the
 * new offset owns; a piece often does not.
 *
 * THE HYPOTHESIS is "the square" as the verdicts name it (doc/verdicts.md): a
 * rectangle whose long side is at most PROBE_ASPECT times its short one, at any
 * angle and offset, sides at least PROBE_MIN_SIDE. (The verdicts allow corners 10
 * degrees off a right angle; a rectangle stands for them: such a quadrilateral's
 * squares differ from a rectangle's by a square at most at the sizes probed.)
 *
 * THE TEST (probe_square_consistent). Given the squares B the object owned before
 * the push (every one seen in the fovea, and the squares round B seen free), the
 * displacement d commanded, how far motion may have erred from it (slack, squares
 * on each axis), and what the eye saw after the push (cells of 1 or 2 squares a
 * side, model frame, each with how many of its squares the object owns: the
 * eye's gray level of a cell of 1 or 4 squares is that count exactly, eye.h),
 * is there a rectangle Q of the hypothesis with proj(Q) = B and proj(Q + d + e),
 * |e| <= slack on each axis, giving every cell's count? e is ONE displacement for
 * the whole look: the object is rigid and was pushed as one, so every cell of a
 * look sees it moved by the same error. Decided by branch and bound over Q's five
 * parameters (angle, two sides, centre): a box of parameters is dropped only when
 * every rectangle in it is sure to contradict a square of B, of B's ring, or a
 * cell's count (the rectangles of a box lie within a distance R of the box's
 * middle one, so they all contain it shrunk by R and lie within it grown by R).
 * Each look's e is weighed in pieces within the box (probe.c, look_errors): a
 * piece of e is dropped when some cell of that look contradicts every rectangle
 * of the box moved by every e of the piece; a box none of whose pieces survive for
 * some look is dropped; the survivors' hull is what the box's smaller boxes start
 * from (an e ruled out for every rectangle of a box is ruled out for every
 * rectangle of its parts). A box that survives until R < PROBE_EPS holds a
 * rectangle and an e per look that agree to within 2 PROBE_EPS squares:
 * CONSISTENT. (probe7 grew the rectangle by the whole slack for each cell on its
 * own, which let each cell see it at its own displacement, up to twice the slack
 * apart: random g258's piece, a 2.6 square with one corner cut off by a side of
 * 1.4, passed for a square, a false success. One e per look rejects it:
 * tests/unit/test_probe.c, tests/worlds/cut-square.w.) So INCONSISTENT is a proof that
 * no square of the hypothesis explains what was seen (up to floating-point
 * rounding): a true square is never rejected, whatever its angle and offset
 * (tests/unit/test_probe.c). When the search would take more than `budget` boxes
 * it stops: UNDECIDED, which the caller treats as consistent (no claim is dropped
 * on a search that did not finish).
 *
 * COST: each box weighs the cells round B and the cells seen after, O(|B| + cells);
 * the search visits a few thousand boxes for a true square and up to the budget
 * for a piece. MEMORY: a stack of boxes of depth O(log(range / PROBE_EPS)) x 5. */
#ifndef UTAK_PROBE_H
#define UTAK_PROBE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/impression.h"

/* The verdicts' square: long side / short side at most this (JUDGE_SHAPE_SQUARE). */
#define PROBE_ASPECT 1.2
/* Sides under this are not searched: a polygon under 2 wide is unnamed (the
 * verdicts' JUDGE_SHAPE_MIN_WIDTH), less a margin for the quadrilaterals the
 * judge names square that a rectangle only stands for (THE HYPOTHESIS): a corner
 * 10 degrees off a right angle leans a side by tan 10 = 0.18 of the side across
 * it, and the rectangle that owns their squares best runs about half way, so a
 * quadrilateral 2 wide may be stood for by a rectangle 2 - 0.18 wide (measured,
 * tests/unit/test_probe.c judge_quadrilaterals_kept: at 2 the probe rejected 3 of
 * 60 such quadrilaterals 2 to 2.15 wide, at 1.86 2 of 150, at 1.82 1 of 150, the
 * one it rejects at 1.5 as well). A polygon the probe rejects is no square of
 * sides 1.82 or more: 1.55 squares are rejected 17 times in 30, 1.65 ones 6,
 * 1.75 ones never (three looks, the slack Utak assumes, every cell seen). */
#define PROBE_MIN_SIDE 1.82
/* The search splits boxes of sides from here, as it did when that was the least
 * side searched: the boxes are the same, and a box one of whose sides lies wholly
 * under PROBE_MIN_SIDE (its upper bound below it) is dropped, so no verdict but one on such a rectangle changes
 * (a box is taken as consistent within PROBE_EPS, and other boxes would take
 * other rectangles within it: a 2.8 square cut 0.4 deep read consistent from
 * boxes split from 1.82). */
#define PROBE_LATTICE_SIDE 1.5
/* A box of parameters whose rectangles all lie within this of its middle one, and
 * that nothing seen contradicts, is taken as consistent (squares). */
#define PROBE_EPS 0.01

/* A look after a push: the object's displacement from where it owned B, as
 * commanded (model frame, squares), and how far motion may have erred from it on
 * each axis (squares). At most PROBE_LOOKS looks are judged together. */
#define PROBE_LOOKS 4
typedef struct ProbeLook {
	Vec2 d;
	double slack;
	/* With `unplaced` (below): the places of the eye's grid, a square either way
	 * or none on each axis, that what else the look showed allows: bit
	 * (sy + 1) * 3 + (sx + 1) for a grid moved by (sx, sy); PROBE_ANY_SHIFT
	 * when nothing rules any out. */
	uint16_t shifts;
	/* The slack per root of the squared lengths pushed (PROBE_SLACK_RATE, or
	 * more under noise the disparity has shown), when the looks' pushes are
	 * taken one after another (look l's from look l - 1's d, the first's from
	 * where the object was): then motion's error between looks j and k is that
	 * of the pushes between them, within rate times the root of their squared
	 * lengths (the errors of the pushes before j move both looks alike, as the
	 * slack of each look already assumes: a Gaussian error per push, motion.h).
	 * 0: not so, and the error between two looks is within their two slacks. */
	double rate;
} ProbeLook;
#define PROBE_ANY_SHIFT 0x1ff

/* A cell the eye saw in look `look`: squares [x, x + size) x [y, y + size) of the
 * model frame (size 1 or 2), and how many of them the object owns. */
typedef struct ProbeCell {
	int32_t x, y, size, count, look;
} ProbeCell;

typedef enum ProbeVerdict { PROBE_CONSISTENT, PROBE_INCONSISTENT, PROBE_UNDECIDED } ProbeVerdict;

/* probe_square_consistent(bx, by, nb, looks, nlooks, cells, ncells, unplaced,
 * budget): the test above, with every look at once (one rectangle must explain
 * them all). B is the nb squares (bx[i], by[i]); the squares 8-adjacent to B and
 * not in it are taken as not owned before the pushes. The cells are placed as if
 * the eye's grid had not moved; with `unplaced`, Utak's point may lie anywhere in
 * his square before the pushes (a move that halted against the object leaves it
 * on the square's edge), so that a push of a quarter square may carry it, and
 * the eye's grid, into the next square: every place of it in the square is tried
 * (the square cut where some look's commanded d would change the grid: at most 9
 * pieces for the diagonal quarter-square pushes; within a look's slack of a cut,
 * its error of motion may put the grid on either side, and both are tried for
 * that look; a place its `shifts` rules out is not tried, and a piece with none
 * left for some look is dropped), and the verdict is CONSISTENT if one piece is,
 * INCONSISTENT if all are. `budget` is for all the searches together. nb 0 or
 * more than PROBE_MAX_SQUARES, or a cell of no look: UNDECIDED. */
#define PROBE_MAX_SQUARES 400
ProbeVerdict probe_square_consistent(const int32_t *bx, const int32_t *by, int32_t nb, const ProbeLook *looks,
				     int32_t nlooks, const ProbeCell *cells, int32_t ncells, bool unplaced,
				     int64_t budget);
/* probe_rect_consistent(..., amin, amax, budget): the same test over the
 * rectangles whose long side / short side lies in (amin, amax] (sides at least
 * PROBE_MIN_SIDE); probe_square_consistent is it over [1, PROBE_ASPECT]. Over
 * (PROBE_ASPECT, INFINITY) it asks OBLONG: may a rectangle the judge names no
 * square (judgeshape.c: long/short over 1.2) have given the same squares and
 * looks? A square's squares alone (no look) nearly always may: a 2.27 x 3.04
 * rectangle owns the same 4 x 4 squares as a 3.5 square. Not yet asked by the
 * controller: a doubt on it before the probe doubts nearly every square claim
 * (issue 13, the aspect12 helper's report). */
ProbeVerdict probe_rect_consistent(const int32_t *bx, const int32_t *by, int32_t nb, const ProbeLook *looks,
				   int32_t nlooks, const ProbeCell *cells, int32_t ncells, bool unplaced,
				   double amin, double amax, int64_t budget);

/* probe_least_width(bx, by, nb, looks, nlooks, cells, ncells, unplaced): a lower
 * bound on the width (least extent across any direction, doc/verdicts.md) of
 * EVERY polygon P, of any shape, that owned the squares B before the pushes and
 * gave each look's counts (the same input as probe_square_consistent; 0 when it
 * can say nothing). WHY: a set of squares standing still bounds P's width only
 * by how far the squares' centres spread less a square's own extent
 * (shape.h, min_width): a 2.2 square covering a 3 x 3 block may be a 1.1 sliver
 * for all the eye can tell, and no such polygon has a name. Motion narrows it:
 * P + d_k + e_k meets every open region (square, or cell of which it owns some)
 * look k shows, so across a direction u, for a region A of look j and B of look
 * k (look "0" is B before the pushes, d 0, e 0, the grid where it was),
 *   extent_u(P) > u.(cB - d_k) - u.(cA - d_j) - (sA + sB)/2 (|ux| + |uy|)
 *                 - (slack_j + slack_k) (|ux| + |uy|)   (none when j = k),
 * the most over the pairs, and the least over every place of Utak's point and
 * every place of each look's grid it allows (a place of a look's grid that puts
 * a region beyond where the object, within B's closed squares before, can
 * reach is none). The bound is taken across PROBE_WIDTH_DIRECTIONS directions
 * (the axes among them); between two of them the extent changes by at most the
 * object's diameter (B's box's diagonal) times the angle, and the least that
 * allows is the bound (probewidth.c). Sound: no polygon that gave these
 * looks is narrower (tests/unit/test_probe.c, least_width_is_sound, against the
 * exact width of 600 polygons projected as the TABLE does). With three quarter-
 * square looks it shows a square 2.25 on a side two wide 6 times in 40, 2.35 20,
 * 2.45 34, 2.15 never: the step and the slack of motion leave the rest in doubt.
 * With a rate (ProbeLook.rate), two looks' regions are set against each other
 * with the error of the pushes between them, when less than their two slacks
 * (random g18's 2.24 square: shown 1.88 wide, was 1.81). */
#define PROBE_WIDTH_DIRECTIONS 720
double probe_least_width(const int32_t *bx, const int32_t *by, int32_t nb, const ProbeLook *looks, int32_t nlooks,
			 const ProbeCell *cells, int32_t ncells, bool unplaced);

/* ---- the probe in the action cycle ------------------------------------------------
 *
 * WHEN. Utak probes the object he is about to claim as "the square" of task "go
 * square" (controller.c, arrive), on the evidence of its squares alone: every
 * such object could be another polygon, for a square owns the same squares as an
 * octagon whose four cut corners lie within the squares of the square's corners,
 * and a square's corner lies inside a square (not on its edges) but for a set of
 * poses of measure zero. So "could be another polygon" is every such claim; the
 * probe is made when it can be made safely, and the claim stands as before
 * otherwise (no claim is worse for a probe that could not be made):
 *   (probe_begin is "go square"'s own claim; rival.h probes, through
 *   probe_begin_object, the object claimed when its own squares may be a
 *   polygon's under 2 wide or a probe in the task has shown pieces the eye
 *   takes for squares, and a rival)
 *   the object is seen whole in the fovea, its squares number at most
 *   PROBE_MAX_SQUARES within a box that leaves 3 squares of margin in
 *   PROBE_WINDOW, and every square 8-adjacent to them is believed floor, seen in
 *   the fovea (or is Utak's); every object colour touch shows is on the object
 *   (the grasp takes the first, paper 2.2); and for at least one of the four
 *   diagonal pushes of PROBE_STEP squares on each axis, every square the object
 *   may move onto is believed floor, seen in the fovea, or is Utak's. At most
 *   PROBE_RUNS probes a task.
 * HOW. Grasp; push the object to each such corner in turn, at most PROBE_TAKES of
 * them (the corners (+s, +s), (-s, -s), (+s, -s), (-s, +s), s = PROBE_STEP, the
 * first that have room, in that order: opposite corners first, for they show
 * more together than neighbours (with Utak's point known: two opposite corners
 * reject the unit test's pieces from every heading in 66 of 72 tries, two
 * neighbouring ones 63, one 57); from one corner to another the object sweeps
 * only squares of the two corners' room). Utak's point moves with it, anywhere in his square
 * to begin with (a move halted against the object leaves it on the square's
 * edge), so the eye's grid may move by a square with him or stay: the test tries
 * both (unplaced). After each push, the cells of the fovea and the intermediate
 * zone that hold only the object's squares and floor (keep_look, probe.c; the
 * eye's own square excepted, always Utak's: the cells beside it, which show the
 * object's near side, are kept; left out, as every cell within a square of his
 * first square once was, that side was never seen after a push, and a 1.6 bit
 * was never disproved nor a 2.5 square shown two wide in 32 poses each) are kept; then the object is pushed back to where it was, and let go, and
 * probe_square_consistent judges all the looks at once. Motion's error adds up
 * from push to push: look l's slack is PROBE_SLACK_RATE (or four times the motion
 * error the disparity has shown, if more) times the root of the sum of the
 * squared lengths of the pushes up to it (a Gaussian error per push, motion.h).
 * Cycles: a grasp, a push per look, the push back and the release: with three
 * looks, six more than the claim alone.
 * THEN. The looks' least width (probe_least_width) is kept for the object
 * (probe_width): two or more, its squares are no narrow polygon's, and that doubt
 * is gone (objects.h, A CRUMB). Consistent, or undecided (the search did not
 * finish; the looks showed no change at all: the grasp may have failed): the
 * claim stands. Inconsistent: the
 * object is not the square (probe_disproved: objects.c names it nothing), and
 * the task goes on: another object, a look further, or an honest failure. */
#define PROBE_STEP 0.25
/* A second probe's push, where the first showed no change (rival.h, HALF A
 * SQUARE): an edge at a fraction f of a square is carried across a square's edge
 * by +s when f >= 1 - s, by -s when f < s, so pushes of a quarter both ways miss
 * every edge with f in [0.25, 0.75) on both axes (clutter.w moved by fractions:
 * bricks at .34 and .36 showed nothing), and +-0.5 carry every edge across one
 * (f >= 0.5, or f < 0.5). Still under a square: the same room suffices. */
#define PROBE_HALF_STEP 0.5
/* Looks a probe takes at most (corners with room): each costs a cycle. With
 * Utak's point not known in his square, two looks left the pieces of random
 * worlds g123 and g208 in doubt (some place of the grid explained them), three
 * reject them (tests/rates.sh's worlds; four do no better there). g258's
 * 2.6-square pentagon with one corner cut passed while the slack was spread over
 * each cell on its own; with one error of motion per look (THE TEST) three looks
 * reject it. Not every cut corner is seen: a 2.8 square cut 0.4 or 0.5 deep is
 * rejected at 7 or 8 of 27 poses (was 4 and 2); a fourth look, or pushes of a
 * third or a half square, did no better on them, and even a slack of 0 with
 * Utak's point known rejects only 9 of 27 at 0.4: where the cut lies, the few
 * offsets a probe shows leave some square owning the same squares. The verdicts
 * name no square one with a corner cut by legs of 0.04 or more (judgeshape.c
 * merges corners only 0.05 apart), and no reading of a probe's looks could
 * tell most such cuts: the same square sharp and cut owns exactly the same
 * squares before and after the three pushes in 1160 of 1224 poses for legs of
 * 0.05 at one corner, 672 for 0.3, 170 for 0.6, 4 for 1.0 (all four corners cut:
 * 950, 165, 9, 0); the square's search rejects an octagon of legs 0.3 in none of
 * 12 poses, one corner cut 1.4 in 11, and 1.6 or more in 18 of 18
 * (tests/unit/test_cutcorner.c). So Utak claims "the square" of squares cut
 * under about a square, a false success to the verdicts (issue 13, chamfer13's
 * report: a tolerance of the verdicts tied to the TABLE's square). */
#define PROBE_TAKES 3
/* Slack per square of push, when the disparity has shown no larger error: two
 * standard deviations of an error of 0.05 squares per square pushed (the noise
 * the project is measured at, README "Reliability"). Four would leave most
 * pieces in doubt (random g53's, slack 0.14 on the second look). The disparity
 * overstates noise of 0.05 (it showed 0.10 to 0.16 on worlds/ with 0.05), so
 * under noise that it has seen the slack is larger, 4 x its estimate. */
#define PROBE_SLACK_RATE 0.1
/* Probes a task, at most: the claim's own, up to RIVAL_MAX rivals', and a second
 * of a rival by half a square (rival.h); four ran out on perturbed clutter-p1's
 * third rival before its second probe. */
#define PROBE_RUNS 8
#define PROBE_WINDOW 32
/* The search's budget of boxes (about 0.2 s a million, -O2): a true square is
 * found in a few thousand, a piece disproved in up to a million or so. */
#define PROBE_BUDGET 3000000
/* Objects disproved in a task, at most (by ident, and by where they were). */
#define PROBE_DISPROVED 16
/* Cells of one look: the fovea and the intermediate zone. */
#define PROBE_LOOK_CELLS (RETINA_FOVEA + RETINA_INTERMEDIATE)

typedef enum ProbeStage {
	PROBE_IDLE,
	PROBE_GRASP,	/* next: grasp */
	PROBE_PUSH,	/* next: the push to corner `look`, or back when all are seen */
	PROBE_RELEASE,	/* next: let go */
	PROBE_FINISH,	/* next: judge, and claim or drop */
} ProbeStage;

typedef struct ProbeRun {
	ProbeStage stage;
	int32_t ident;		/* the object probed (model ident) */
	Vec2 at;		/* ... its centroid, model frame */
	int32_t nb;		/* its squares before, model frame */
	int32_t bx[PROBE_MAX_SQUARES], by[PROBE_MAX_SQUARES];
	/* What was floor round it before (1) in the window of PROBE_WINDOW squares
	 * whose lower-left square is (wx, wy). */
	int32_t wx, wy;
	uint8_t floor_before[PROBE_WINDOW * PROBE_WINDOW];
	/* The corners pushed to (displacements from where it was, model frame), the
	 * one being pushed to, and the looks taken there. */
	Vec2 corner[PROBE_LOOKS];
	int corners, look;
	double step; /* ... each a push of this on each axis (PROBE_STEP, or PROBE_HALF_STEP) */
	ProbeLook looks[PROBE_LOOKS];
	uint16_t shifts[PROBE_LOOKS]; /* the places of the eye's grid each look allows */
	ProbeCell cells[PROBE_LOOKS * PROBE_LOOK_CELLS];
	int32_t ncells;
	int32_t ux, uy;		/* Utak's square before the probe, model frame */
	bool changed;		/* some look showed a count other than before, or what no
				   place of the eye's grid it allows lets the unmoved object
				   show (at_rest_fits, probe.c) */
	ProbeVerdict verdict;
	int runs;
	int32_t disproved_ident[PROBE_DISPROVED];
	Vec2 disproved_at[PROBE_DISPROVED];
	int disproved_count;
	/* The least width the looks show (probe_least_width; 0 when they show
	 * none), and the widths shown of the objects probed in the task, by ident
	 * and by where they were (probe_width). */
	double width;
	bool narrow; /* its squares standing still may be a polygon's under 2 wide */
	bool width_only; /* WIDTH ONLY: a brick, L-shape or triangle, its width asked alone */
	int32_t measured_ident[PROBE_DISPROVED];
	Vec2 measured_at[PROBE_DISPROVED];
	double measured_width[PROBE_DISPROVED];
	int measured_count;
} ProbeRun;

struct Controller;
/* probe_begin(c, k): a probe of object node k begun (see WHEN); false when none
 * can be made. */
bool probe_begin(struct Controller *c, int32_t k);
/* probe_begin_object(c, k): the same for any task whose object is the square
 * ("go round square", "push square" too: rival.h probes the object Utak would
 * claim and its rival before the claim); probe_begin is it for "go square".
 * WIDTH ONLY: for a task on another shape (brick, L-shape, triangle), a probe of
 * the object he would claim is begun only when its squares standing still leave
 * its width under 2 (objects_narrow: a 9 x 3 brick's 27 squares are those of a
 * sliver 1.01 wide too, the middle row and two thin edges, and the verdicts name
 * no polygon under 2 wide), made as above, and judged by its width alone
 * (probe_least_width): the square's test does not apply, so the verdict is
 * UNDECIDED and nothing is dropped; a width of 2 or more lifts that doubt
 * (objects.h, A CRUMB), and the claim is judged again (rival.h, NARROW). */
bool probe_begin_object(struct Controller *c, int32_t k);
/* probe_begin_step(c, k, step): probe_begin_object with pushes of `step` squares
 * on each axis (0 < step < 1; PROBE_HALF_STEP for a second probe, rival.h). */
bool probe_begin_step(struct Controller *c, int32_t k, double step);
/* probe_decide(c, cmd): the probe's next command; false when none is under way,
 * or when it has just ended (the claim made, c->phase DONE, or the object
 * dropped and the plan to be made again). */
bool probe_decide(struct Controller *c, MotorCommand *cmd);
/* probe_end(c): a probe whose release was perceived (stage PROBE_FINISH) ended: a
 * disproved object recorded (probe_disproved), the verdict returned, and nothing
 * claimed or dropped: probe_decide does that for the task's own claim, rival.h
 * for a rival or for an object probed before one. */
ProbeVerdict probe_end(struct Controller *c);
/* probe_perceive(c, cmd, note, size): after each command of a probe: the look
 * after a push to a corner kept; what was done, for the cycle's note. False when
 * no probe is under way. */
bool probe_perceive(struct Controller *c, const MotorCommand *cmd, char *note, size_t size);
/* probe_width_note(p, note, size): after a release, the width the looks showed,
 * appended to the cycle's note when the object's squares standing still left it
 * in doubt (p->narrow). */
void probe_width_note(const ProbeRun *p, char *note, size_t size);
/* probe_said(p): what the release of probe p tells of the object's squares, for
 * the cycle's note. */
const char *probe_said(const ProbeRun *p);
/* probe_disproved(c, ident, at): an object (ident, or centroid at within
 * OBJECTS_SAME of one) that a probe showed is not the square. */
bool probe_disproved(const struct Controller *c, int32_t ident, Vec2 at);
/* probe_width(c, ident, at): the least width a probe's looks showed of an object
 * (ident, or centroid at within OBJECTS_SAME of one): every polygon that gave
 * them is at least so wide (probe_least_width); 0 when none was probed. */
double probe_width(const struct Controller *c, int32_t ident, Vec2 at);

#endif
