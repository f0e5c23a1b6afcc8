/* rope.c - rope-tightening, the open problem of paper 5: a found path pulled taut to
 * the shortest path of its homotopy class. See rope.h for the contract.
 *
 * ALGORITHM:
 *  1. Sleeve. Free space is cut into row runs (maximal horizontal runs of free cells
 *     in one row, open rectangles 1 high) joined by portals (the overlap, on the
 *     grid line between them, of two runs in adjacent rows). Each portal's two ends
 *     are run ends, that is corners of blocked cells (or of the grid), so each portal
 *     is a chord from obstacle to obstacle, and two runs share at most one portal.
 *     The input is followed piece by piece (split at every horizontal grid line it
 *     crosses, and a piece lying on a grid line at every integer x), and the run of
 *     the midpoint of each piece is recorded. Consecutive equal runs are merged and a
 *     crossing straight back (A, B, A) cancels: the remaining reduced sequence is the
 *     sleeve. Because every portal is a chord, it separates the universal cover of
 *     free space, and the taut path of the homotopy class crosses exactly the
 *     portals of the reduced sequence, once each, in order (Hershberger and
 *     Snoeyink 1994): the shortest path homotopic to the input is the shortest path
 *     inside the sleeve.
 *  2. Funnel. The shortest path through a sleeve of convex cells is found from the
 *     portals alone by the funnel algorithm (Lee and Preparata 1984), here in the
 *     compact form popularised by M. Mononen ("simple stupid funnel", 2010): keep an
 *     apex and the left and right edges of the cone of directions that still pass
 *     every portal so far; a new portal end that narrows the cone replaces an edge,
 *     and one that crosses the opposite edge makes that edge's end the next vertex
 *     of the path, which becomes the apex.
 *
 * INVARIANTS: sleeve runs are (row, first cell, end cell) with cells first..end-1
 * free and the cells beside them blocked; consecutive sleeve runs lie in adjacent
 * rows and share a portal of positive length (a zero-length one would be a pinch
 * point, which a free input cannot cross). Every point the funnel outputs is S, D or
 * a portal end, a lattice point.
 *
 * MEMORY: the sleeve (12 bytes per run) and the portals (32 bytes each).
 * ORIENTATION: "left" of a direction is where vec2_cross(direction, p) > 0. Moving
 * towards +y, left is -x. */
#include "utak/plan/rope.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

#include "utak/base/util.h"
#include "utak/plan/visibility.h"

/* A row run: cells [x0, x1) of row y, all free, with blocked cells (or the grid's
 * edge) at x0 - 1 and x1. */
typedef struct RopeRun {
	int32_t y, x0, x1;
} RopeRun;

typedef struct RopeSleeve {
	RopeRun *run;
	int count, cap;
	bool bad; /* the input left free space: a run missing or two runs unjoined */
} RopeSleeve;

static bool rope_free(const Grid *g, int32_t x, int32_t y)
{
	return grid_free_at(g, x, y);
}

/* rope_run_at(g, x, y): the run holding free cell (x, y). */
static RopeRun rope_run_at(const Grid *g, int32_t x, int32_t y)
{
	RopeRun r = {y, x, x + 1};
	while (rope_free(g, r.x0 - 1, y))
		r.x0--;
	while (rope_free(g, r.x1, y))
		r.x1++;
	return r;
}

/* rope_sleeve_add(sl, g, x, y): the path is in free cell (x, y) next: extend the
 * reduced run sequence. */
static void rope_sleeve_add(RopeSleeve *sl, const Grid *g, int32_t x, int32_t y)
{
	if (sl->count > 0) {
		const RopeRun *top = &sl->run[sl->count - 1];
		if (top->y == y && top->x0 <= x && x < top->x1)
			return; /* still in the same run */
	}
	RopeRun r = rope_run_at(g, x, y);
	if (sl->count >= 2) {
		const RopeRun *under = &sl->run[sl->count - 2];
		if (under->y == r.y && under->x0 == r.x0) {
			sl->count--; /* straight back through the same portal: cancel */
			return;
		}
	}
	if (sl->count >= 1) {
		const RopeRun *top = &sl->run[sl->count - 1];
		int32_t lo = top->x0 > r.x0 ? top->x0 : r.x0, hi = top->x1 < r.x1 ? top->x1 : r.x1;
		if (abs(top->y - r.y) != 1 || hi <= lo) {
			sl->bad = true;
			return;
		}
	}
	sl->run = util_grow(sl->run, &sl->cap, sl->count + 1, sizeof *sl->run);
	sl->run[sl->count++] = r;
}

/* rope_sleeve_point(sl, g, m): the path passes point m, which lies inside a row (not
 * on a horizontal grid line) or on a horizontal grid line but not at integer x. */
static void rope_sleeve_point(RopeSleeve *sl, const Grid *g, Vec2 m)
{
	double fx = floor(m.x), fy = floor(m.y);
	int32_t x = (int32_t)fx, y = (int32_t)fy;
	if (m.y == fy) {
		/* On a horizontal grid line: either side that is free (they join here). */
		if (rope_free(g, x, y - 1))
			y--;
	} else if (m.x == fx) {
		/* On a vertical grid line inside a row: either free side (same run). */
		if (rope_free(g, x - 1, y))
			x--;
	}
	if (!rope_free(g, x, y)) {
		sl->bad = true;
		return;
	}
	rope_sleeve_add(sl, g, x, y);
}

/* rope_sleeve_segment(sl, g, a, b): follows segment ab, piece by piece. */
static void rope_sleeve_segment(RopeSleeve *sl, const Grid *g, Vec2 a, Vec2 b)
{
	if (a.x == b.x && a.y == b.y)
		return;
	double t_prev = 0;
	if (a.y != b.y) {
		/* Pieces between successive horizontal grid lines crossed. */
		double step = a.y < b.y ? 1 : -1;
		double line = a.y < b.y ? floor(a.y) + 1 : ceil(a.y) - 1;
		for (;; line += step) {
			double t = (line - a.y) / (b.y - a.y);
			if (!(t < 1))
				break;
			double tm = 0.5 * (t_prev + t);
			rope_sleeve_point(sl, g,
			                  vec2(a.x + (b.x - a.x) * tm, a.y + (b.y - a.y) * tm));
			t_prev = t;
		}
	} else if (a.y == floor(a.y)) {
		/* On a horizontal grid line: pieces between successive integer x. */
		double step = a.x < b.x ? 1 : -1;
		double line = a.x < b.x ? floor(a.x) + 1 : ceil(a.x) - 1;
		for (;; line += step) {
			double t = (line - a.x) / (b.x - a.x);
			if (!(t < 1))
				break;
			rope_sleeve_point(sl, g, vec2(a.x + (b.x - a.x) * 0.5 * (t_prev + t), a.y));
			t_prev = t;
		}
	}
	double tm = 0.5 * (t_prev + 1);
	rope_sleeve_point(sl, g, vec2(a.x + (b.x - a.x) * tm, a.y + (b.y - a.y) * tm));
}

/* ---- the funnel ----------------------------------------------------------------- */

typedef struct RopePortal {
	Vec2 left, right;
} RopePortal;

static inline double rope_cross(Vec2 apex, Vec2 a, Vec2 b)
{
	return vec2_cross(vec2_sub(a, apex), vec2_sub(b, apex));
}

static inline bool rope_equal(Vec2 a, Vec2 b)
{
	return a.x == b.x && a.y == b.y;
}

/* rope_push_point: appends q unless it repeats the last point. */
static void rope_push_point(Path *out, Vec2 q)
{
	if (out->count > 0 && rope_equal(out->pts[out->count - 1], q))
		return;
	path_push(out, q);
}

/* rope_funnel(portal, n, out): the shortest path through portals 0..n-1, of which the
 * first is (S, S) and the last (D, D). */
static void rope_funnel(const RopePortal *portal, int n, Path *out)
{
	Vec2 apex = portal[0].left, left = apex, right = apex;
	int apex_i = 0, left_i = 0, right_i = 0;
	rope_push_point(out, apex);
	for (int i = 1; i < n; i++) {
		Vec2 l = portal[i].left, r = portal[i].right;
		/* The right edge: narrow it when r is on or left of it. */
		if (rope_cross(apex, right, r) >= 0) {
			if (rope_equal(apex, right) || rope_cross(apex, left, r) < 0) {
				right = r;
				right_i = i;
			} else {
				/* r crosses the left edge: the left end is the next corner. */
				apex = left;
				apex_i = left_i;
				rope_push_point(out, apex);
				right = left = apex;
				right_i = left_i = apex_i;
				i = apex_i;
				continue;
			}
		}
		/* The left edge, symmetrically. */
		if (rope_cross(apex, left, l) <= 0) {
			if (rope_equal(apex, left) || rope_cross(apex, right, l) > 0) {
				left = l;
				left_i = i;
			} else {
				apex = right;
				apex_i = right_i;
				rope_push_point(out, apex);
				right = left = apex;
				right_i = left_i = apex_i;
				i = apex_i;
				continue;
			}
		}
	}
	rope_push_point(out, portal[n - 1].left);
}

RopeStatus rope_tighten(const Grid *g, const Path *in, Path *out)
{
	path_clear(out);
	if (in->count == 0 || !visibility_path_free(g, in))
		return ROPE_BAD_INPUT;
	Vec2 s = in->pts[0], d = in->pts[in->count - 1];
	RopeSleeve sl = {0};
	for (int i = 1; i < in->count && !sl.bad; i++)
		rope_sleeve_segment(&sl, g, in->pts[i - 1], in->pts[i]);
	if (sl.bad) {
		/* Unreachable for a free input (see INVARIANTS); kept as a guard. */
		free(sl.run);
		return ROPE_BAD_INPUT;
	}
	int n = sl.count > 0 ? sl.count + 1 : 2;
	RopePortal *portal = util_alloc((size_t)n, sizeof *portal);
	portal[0] = (RopePortal){s, s};
	for (int i = 1; i < sl.count; i++) {
		const RopeRun *a = &sl.run[i - 1], *b = &sl.run[i];
		double lo = a->x0 > b->x0 ? a->x0 : b->x0, hi = a->x1 < b->x1 ? a->x1 : b->x1;
		double line = a->y > b->y ? a->y : b->y;
		/* Moving up (+y) the low-x end is on the left; moving down, the high-x end. */
		portal[i] = b->y > a->y ? (RopePortal){vec2(lo, line), vec2(hi, line)}
		                        : (RopePortal){vec2(hi, line), vec2(lo, line)};
	}
	portal[n - 1] = (RopePortal){d, d};
	rope_funnel(portal, n, out);
	out->expanded = n - 2;
	free(portal);
	free(sl.run);
	return ROPE_OK;
}
