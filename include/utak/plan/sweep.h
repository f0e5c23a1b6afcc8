/* sweep.h - the squares a moving polygon covers: at one pose, along a push and
 * through a turn (paper 2.1's digital representation, for the planner of a carried
 * object, carry.h).
 *
 * THE RULE. A square is covered by a closed set S when the square's open interior
 * meets S: the TABLE's rule (utak(5), geom.h), which at a single pose is
 * geom_project itself. Covered WITHIN r (r > 0) means the closed square comes
 * nearer than r to S: the cover of S thickened by r, used where the simulator's
 * arithmetic may put the shape a rounding error away from where exact arithmetic
 * puts it, and to cover a turn between checked samples (below).
 *
 * PUSH. A polygon P translated by t d, t in [0, 1], covers the union of those
 * poses: P, P + d, and the parallelogram each edge sweeps (an edge parallel to d
 * sweeps a segment that P, P + d and its neighbours' parallelograms already hold).
 * This is the exact swept region, so a push checked here cannot meet anything the
 * simulator's half-square steps (motion.c) would meet.
 *
 * TURN. A polygon turning about a pivot is checked at samples so close that no
 * point of it travels more than SWEEP_TRAVEL between two; each sample is covered
 * within half that travel (plus SWEEP_EPS). Every pose between two samples lies
 * within half the travel of the nearer sample (a point at distance rho from the
 * pivot moves rho * angle, and the polygon's farthest point is a vertex), so the
 * union covers the whole continuous turn: conservative, never optimistic. The
 * simulator checks a turn at steps of half a square of vertex travel (motion.c,
 * MOTION_STEP); those poses all lie in this cover.
 *
 * FRAME. Cell (x, y) is the square [x, x+1] x [y, y+1] of the polygons' coordinates
 * (grid.h). A caller wanting offsets from a reference cell places the shape there
 * (carry.c puts Utak's point in cell (0, 0)).
 *
 * COMPLEXITY: a pose O(n A) for n vertices and A squares of the shape's box (with
 * r = 0, geom_project's O(rows x n + A)); a push O(n (A + L w)) for a push of length
 * L across a shape w wide; a turn O(samples x n A). */
#ifndef UTAK_SWEEP_H
#define UTAK_SWEEP_H

#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/plan/cspace.h"

/* The most any point of a turning polygon moves between two checked samples, in
 * squares: the issue asks for a quarter square (half the simulator's step). */
#define SWEEP_TRAVEL 0.25
/* The tolerance for rounding: a polygon whose vertices the simulator computes by a
 * different sequence of operations (a turn after a turn) lies within ~1e-13 of
 * where the planner puts it; 1e-7 is far below anything a world means and far
 * above any rounding. */
#define SWEEP_EPS 1e-7

/* Cells arrive as spans: cells x0..x1 (inclusive) of row y, in whatever order and
 * possibly more than once (a push and a turn are unions of covers); the sink must
 * not mind repeats. Coordinates are not clipped: a sink decides what lies outside
 * its grid. */
typedef void SweepSpanFn(void *ctx, int32_t y, int32_t x0, int32_t x1);

/* sweep_cover_polygon(p, r, fn, ctx): the cells covered by p (r == 0: the TABLE's
 * rule, by geom_project), or within r of it (r > 0). */
void sweep_cover_polygon(const Polygon *p, double r, SweepSpanFn *fn, void *ctx);
/* sweep_cover_segment(a, b, r, fn, ctx): the cells within r > 0 of the closed
 * segment ab: the squares a point moving from a to b can be in, rounding included. */
void sweep_cover_segment(Vec2 a, Vec2 b, double r, SweepSpanFn *fn, void *ctx);
/* sweep_cover_push(p, d, r, fn, ctx): the cells covered (within r) by p translated
 * by t d for every t in [0, 1]. */
void sweep_cover_push(const Polygon *p, Vec2 d, double r, SweepSpanFn *fn, void *ctx);
/* sweep_cover_turn(rel, pivot, deg0, deg1, fn, ctx): the cells covered by
 * pivot + rot(deg)(rel) for every deg between deg0 and deg1 (degrees, either order),
 * by the sampling above. rel is the polygon relative to the pivot at its unturned
 * pose. */
void sweep_cover_turn(const Polygon *rel, Vec2 pivot, double deg0, double deg1, SweepSpanFn *fn,
		      void *ctx);

/* sweep_turned(rel, pivot, deg): pivot + rot(deg)(rel), vertex by vertex, with the
 * simulator's arithmetic (motion.c: geom_cos_sin, then geom_rotate's expression). */
Polygon sweep_turned(const Polygon *rel, Vec2 pivot, double deg);
/* sweep_reach(rel): the largest distance of a vertex (so of any point) of rel from
 * the origin: how far a turn about the origin carries it. */
double sweep_reach(const Polygon *rel);

/* A window of cells -radius .. radius on each axis around cell (0, 0), as a sink
 * (sweep_window_span) that marks cells, and its marks as footprint runs. Cells
 * outside it are an error (assert): make the radius at least the shape's reach
 * plus 2. Memory: (2 radius + 1)^2 bytes, the caller's (init/free). */
typedef struct SweepWindow {
	int32_t radius;
	int32_t side;	/* 2 radius + 1 */
	uint8_t *cell;	/* side * side, row-major from (-radius, -radius): 1 marked */
} SweepWindow;

void sweep_window_init(SweepWindow *win, int32_t radius);
void sweep_window_free(SweepWindow *win);
/* sweep_window_clear(win): no cell marked. */
void sweep_window_clear(SweepWindow *win);
/* sweep_window_span: a SweepSpanFn; ctx is the SweepWindow. */
void sweep_window_span(void *ctx, int32_t y, int32_t x0, int32_t x1);
/* sweep_window_runs(win, fp): the marked cells as footprint runs (cspace.h). */
void sweep_window_runs(const SweepWindow *win, CSpaceFootprint *fp);

#endif
