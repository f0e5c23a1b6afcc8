/* probe.c - shape by motion: the test of whether what the eye saw before and after a
 * push of a fraction of a square is what a square would show (paper 3.3; issue 13
 * items 1, 2 and 6; the meaning and the method in probe.h). CONTROLLER SIDE.
 *
 * ALGORITHM. A rectangle Q is (angle a in [0, 90) degrees, sides w and h, centre c).
 * It owns square (x, y) when it meets the square's open interior; for two convex
 * sets that is: no separating axis among their edge normals, here the grid's x
 * and y and Q's own u = (cos a, sin a) and v = (-sin a, cos a) (rect_meets). A box
 * of parameters is a product of intervals; every rectangle in it lies within
 * R = |dc| + dw/2 + dh/2 + da x (half the largest diagonal) of the box's middle
 * rectangle Q0 (dc, dw, dh, da: the box's half-widths), so it contains Q0 shrunk
 * by R on every side and lies within Q0 grown by R (both rectangles). A square
 * of B that the grown one does not meet, or a square of B's ring that the shrunk
 * one meets, or a cell seen after the push whose count lies outside what the two
 * allow (moved by d, and grown and shrunk by the slack too), drops the box. The
 * search is depth first, splitting the parameter that contributes most to R. */
#include "utak/mind/probe.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

/* A rectangle to test squares against: centre, axis, half sides. */
typedef struct ProbeRect {
	double cx, cy, c, s, hw, hh;
} ProbeRect;

/* rect_meets(q, x, y): closed rectangle q meets the open square (x, x+1) x (y, y+1). */
static bool rect_meets(const ProbeRect *q, int32_t x, int32_t y)
{
	if (q->hw <= 0 || q->hh <= 0)
		return false;
	double ex = q->hw * q->c + q->hh * q->s, ey = q->hw * q->s + q->hh * q->c;
	if (q->cx + ex <= x || q->cx - ex >= x + 1 || q->cy + ey <= y || q->cy - ey >= y + 1)
		return false;
	/* Q's own axes; c, s >= 0 for a in [0, 90]. */
	double uq = q->c * q->cx + q->s * q->cy, ucell = q->c * x + q->s * y;
	if (uq + q->hw <= ucell || uq - q->hw >= ucell + q->c + q->s)
		return false;
	double vq = -q->s * q->cx + q->c * q->cy, vcell = -q->s * x + q->c * y;
	if (vq + q->hh <= vcell - q->s || vq - q->hh >= vcell + q->c)
		return false;
	return true;
}

enum { P_A, P_W, P_H, P_X, P_Y, P_COUNT };

/* A quarter turn, radians: a rectangle turned by it is one with its sides swapped. */
#define PROBE_QUARTER 1.57079632679489661923

typedef struct ProbeBox {
	double lo[P_COUNT], hi[P_COUNT];
} ProbeBox;

/* A square of the look before the push: owned (1) or not (0). */
typedef struct ProbeSquare {
	int32_t x, y, owned;
} ProbeSquare;

typedef struct ProbeSearch {
	const ProbeSquare *before;
	int32_t nbefore;
	const ProbeCell *cells;
	int32_t ncells;
	Vec2 d;
	double slack;
} ProbeSearch;

/* box_radius(b, contrib): R for box b (above), and each parameter's share of it. */
static double box_radius(const ProbeBox *b, double contrib[P_COUNT])
{
	double half_diag = 0.5 * hypot(b->hi[P_W], b->hi[P_H]);
	contrib[P_A] = 0.5 * (b->hi[P_A] - b->lo[P_A]) * half_diag;
	contrib[P_W] = 0.25 * (b->hi[P_W] - b->lo[P_W]);
	contrib[P_H] = 0.25 * (b->hi[P_H] - b->lo[P_H]);
	contrib[P_X] = 0.5 * (b->hi[P_X] - b->lo[P_X]);
	contrib[P_Y] = 0.5 * (b->hi[P_Y] - b->lo[P_Y]);
	return contrib[P_A] + contrib[P_W] + contrib[P_H] + hypot(contrib[P_X], contrib[P_Y]);
}

/* box_fails(s, b, r): every rectangle of the hypothesis in box b (radius r)
 * contradicts what was seen. */
static bool box_fails(const ProbeSearch *s, const ProbeBox *b, double r)
{
	/* No rectangle in the box is square enough. */
	if (b->lo[P_W] > PROBE_ASPECT * b->hi[P_H] || b->lo[P_H] > PROBE_ASPECT * b->hi[P_W])
		return true;
	double a = 0.5 * (b->lo[P_A] + b->hi[P_A]);
	double w = 0.5 * (b->lo[P_W] + b->hi[P_W]), h = 0.5 * (b->lo[P_H] + b->hi[P_H]);
	double cx = 0.5 * (b->lo[P_X] + b->hi[P_X]), cy = 0.5 * (b->lo[P_Y] + b->hi[P_Y]);
	double c = cos(a), sn = sin(a);
	ProbeRect in = {cx, cy, c, sn, 0.5 * w - r, 0.5 * h - r};
	ProbeRect out = {cx, cy, c, sn, 0.5 * w + r, 0.5 * h + r};
	for (int32_t i = 0; i < s->nbefore; i++) {
		const ProbeSquare *q = &s->before[i];
		if (q->owned ? !rect_meets(&out, q->x, q->y) : rect_meets(&in, q->x, q->y))
			return true;
	}
	/* After the push: moved by d, and by up to slack more on each axis. */
	double ra = r + s->slack * sqrt(2.0);
	ProbeRect in2 = {cx + s->d.x, cy + s->d.y, c, sn, 0.5 * w - ra, 0.5 * h - ra};
	ProbeRect out2 = {cx + s->d.x, cy + s->d.y, c, sn, 0.5 * w + ra, 0.5 * h + ra};
	for (int32_t i = 0; i < s->ncells; i++) {
		const ProbeCell *k = &s->cells[i];
		int32_t least = 0, most = 0;
		for (int32_t y = k->y; y < k->y + k->size; y++)
			for (int32_t x = k->x; x < k->x + k->size; x++) {
				least += rect_meets(&in2, x, y);
				most += rect_meets(&out2, x, y);
			}
		if (k->count < least || k->count > most)
			return true;
	}
	return false;
}

ProbeVerdict probe_square_consistent(const int32_t *bx, const int32_t *by, int32_t nb, Vec2 d, double slack,
				     const ProbeCell *cells, int32_t ncells, int64_t budget)
{
	if (nb <= 0 || nb > PROBE_MAX_SQUARES)
		return PROBE_UNDECIDED;
	int32_t x0 = bx[0], x1 = bx[0], y0 = by[0], y1 = by[0];
	for (int32_t i = 1; i < nb; i++) {
		x0 = bx[i] < x0 ? bx[i] : x0;
		x1 = bx[i] > x1 ? bx[i] : x1;
		y0 = by[i] < y0 ? by[i] : y0;
		y1 = by[i] > y1 ? by[i] : y1;
	}
	/* B and its ring, in a window one square wider each way; the ring first: the
	 * squares a rectangle must not reach drop most boxes. */
	int32_t ww = x1 - x0 + 3, wh = y1 - y0 + 3;
	uint8_t *mark = util_alloc((size_t)ww * (size_t)wh, 1);
	memset(mark, 0, (size_t)ww * (size_t)wh);
	for (int32_t i = 0; i < nb; i++)
		mark[(by[i] - y0 + 1) * ww + (bx[i] - x0 + 1)] = 1;
	ProbeSquare *before = util_alloc((size_t)ww * (size_t)wh, sizeof *before);
	int32_t n = 0;
	for (int pass = 0; pass < 2; pass++)
		for (int32_t j = 0; j < wh; j++)
			for (int32_t i = 0; i < ww; i++) {
				bool owned = mark[j * ww + i];
				bool ring = false;
				for (int32_t dj = -1; dj <= 1 && !owned && !ring; dj++)
					for (int32_t di = -1; di <= 1 && !ring; di++) {
						int32_t ii = i + di, jj = j + dj;
						ring = ii >= 0 && jj >= 0 && ii < ww && jj < wh && mark[jj * ww + ii];
					}
				if ((pass == 0 && ring) || (pass == 1 && owned))
					before[n++] = (ProbeSquare){x0 - 1 + i, y0 - 1 + j, owned};
			}
	ProbeSearch s = {before, n, cells, ncells, d, slack};
	/* The rectangle lies within B's squares: its centre in their box, its sides
	 * no longer than the box's diagonal. */
	double most_side = hypot(x1 - x0 + 1, y1 - y0 + 1);
	enum { STACK = 1024 };
	ProbeBox *stack = util_alloc(STACK, sizeof *stack);
	int top = 0;
	ProbeVerdict verdict = PROBE_INCONSISTENT;
	if (most_side >= PROBE_MIN_SIDE) {
		stack[top++] = (ProbeBox){{0, PROBE_MIN_SIDE, PROBE_MIN_SIDE, x0, y0},
					  {PROBE_QUARTER, most_side, most_side, x1 + 1, y1 + 1}};
	}
	int64_t visited = 0;
	while (top > 0) {
		if (++visited > budget) {
			verdict = PROBE_UNDECIDED;
			break;
		}
		ProbeBox b = stack[--top];
		double contrib[P_COUNT];
		double r = box_radius(&b, contrib);
		if (box_fails(&s, &b, r))
			continue;
		if (r < PROBE_EPS) {
			verdict = PROBE_CONSISTENT;
			break;
		}
		int split = 0;
		for (int k = 1; k < P_COUNT; k++)
			if (contrib[k] > contrib[split])
				split = k;
		if (top + 2 > STACK) { /* cannot happen: depth is bounded by log2(range / EPS) */
			verdict = PROBE_UNDECIDED;
			break;
		}
		double mid = 0.5 * (b.lo[split] + b.hi[split]);
		ProbeBox lo = b, hi = b;
		lo.hi[split] = mid;
		hi.lo[split] = mid;
		stack[top++] = hi;
		stack[top++] = lo;
	}
	free(stack);
	free(before);
	free(mark);
	return verdict;
}
