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
 * |e| <= slack on each axis, giving every cell's count? Decided by branch and
 * bound over Q's five parameters (angle, two sides, centre): a box of parameters
 * is dropped only when every rectangle in it is sure to contradict a square of B,
 * of B's ring, or a cell's count (the rectangles of a box lie within a distance R
 * of the box's middle one, so they all contain it shrunk by R and lie within it
 * grown by R); a box that survives until R < PROBE_EPS holds a rectangle that
 * agrees to within PROBE_EPS squares: CONSISTENT. So INCONSISTENT is a proof that
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
#include <stdint.h>

#include "utak/base/geom.h"

/* The verdicts' square: long side / short side at most this (JUDGE_SHAPE_SQUARE). */
#define PROBE_ASPECT 1.2
/* Sides under this are not searched (a polygon under 2 wide is unnamed). */
#define PROBE_MIN_SIDE 1.5
/* A box of parameters whose rectangles all lie within this of its middle one, and
 * that nothing seen contradicts, is taken as consistent (squares). */
#define PROBE_EPS 0.004

/* A cell the eye saw after the push: squares [x, x + size) x [y, y + size) of the
 * model frame (size 1 or 2), and how many of them the object owns. */
typedef struct ProbeCell {
	int32_t x, y, size, count;
} ProbeCell;

typedef enum ProbeVerdict { PROBE_CONSISTENT, PROBE_INCONSISTENT, PROBE_UNDECIDED } ProbeVerdict;

/* probe_square_consistent(bx, by, nb, d, slack, cells, ncells, budget): the test
 * above. B is the nb squares (bx[i], by[i]); the squares 8-adjacent to B and not in
 * it are taken as not owned before the push. nb 0, or more than PROBE_MAX_SQUARES:
 * UNDECIDED. */
#define PROBE_MAX_SQUARES 400
ProbeVerdict probe_square_consistent(const int32_t *bx, const int32_t *by, int32_t nb, Vec2 d, double slack,
				     const ProbeCell *cells, int32_t ncells, int64_t budget);

#endif
