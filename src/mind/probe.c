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
 * one meets, drops the box. Each look then has its own error of motion e, one
 * for all its cells (probe.h): the box carries, for each look, the interval of e
 * not yet ruled out; look_errors weighs it whole (Q0 moved by d + the interval's
 * middle, grown and shrunk by R + the interval's half diagonal), then, on the
 * cells that leaves open, in halves, down to pieces no wider than R; a cell whose
 * count lies outside what the two allow drops a piece, no piece left drops the
 * box, and the survivors' hull is the interval the box's parts inherit. The
 * search is depth first, splitting the parameter that contributes most to R.
 * When Utak's point is not known in his square, each place of it (a piece of his
 * square) is a bit of a box's mask, cleared where the box's cells contradict it;
 * a place may put a look's grid on one of a few squares (its error of motion
 * within the slack of a cut), each weighed once a box whatever the places that
 * share it; the squares before the push, the same for every place, are weighed
 * once a box. The least width the looks show is probewidth.c's. */
#include "utak/mind/probe.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/eye.h"
#include "utak/base/util.h"
#include "utak/mind/controller.h"
#include "utak/mind/goals.h"
#include "utak/mind/seam.h"
#include "utak/mind/objects.h"
#include "probe_work.h"

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


typedef struct ProbeBox {
	double lo[P_COUNT], hi[P_COUNT];
	uint32_t alive; /* the places of the eye's grid not yet ruled out in it (bits) */
	/* Each look's error of motion (x, y) not yet ruled out for every rectangle of
	 * the box, at every place of the grid alive: [elo, ehi] on each axis. */
	double elo[PROBE_LOOKS][2], ehi[PROBE_LOOKS][2];
} ProbeBox;

/* A square of the look before the push: owned (1) or not (0). */
typedef struct ProbeSquare {
	int32_t x, y, owned;
} ProbeSquare;

typedef struct ProbeSearch {
	ProbeSquare *before; /* reordered as the search goes: the last to drop a box first */
	int32_t nbefore;
	ProbeCell *cells; /* grouped by look: look l's are first[l] .. first[l + 1] - 1 */
	int32_t ncells, first[PROBE_LOOKS + 1];
	const ProbeLook *looks;
	int32_t nlooks;
	/* Place k of Utak's point: where it may put the eye's grid at look l, a mask
	 * of the nine places a square either way or none on each axis (bit
	 * (sy + 1) * 3 + sx + 1: look l's cells are squares (x + sx, y + sy)). */
	uint16_t place[PROBE_SHIFTS][PROBE_LOOKS];
	int nshifts;
	/* The rectangles searched: long side / short side within (amin, amax]
	 * (the square's [1, PROBE_ASPECT], or the oblong's (PROBE_ASPECT, inf)). */
	double amin, amax;
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

/* The most cells of one look (the fovea and the intermediate zone: every cell of
 * a look lies in it, for a look is one impression). */
#define PROBE_CELLS_A_LOOK 256

/* look_agrees(s, sx, sy, l, q, r, e, only, nonly, open, nopen): every cell of look
 * l (or only the nonly of them listed in `only`, when it is not NULL), the grid
 * moved by (sx, sy), allows some rectangle within r of q moved by look l's d and by e. With
 * `open`, the cells a rectangle within r may own more or fewer squares of (the
 * only ones a finer e can tell anything by) are listed in it. */
static bool look_agrees(ProbeSearch *s, int32_t sx, int32_t sy, int32_t l, const ProbeRect *q, double r,
			const double e[2],
			const int32_t *only, int32_t nonly, int32_t *open, int32_t *nopen)
{
	Vec2 d = s->looks[l].d;
	ProbeRect in = {q->cx + d.x + e[0], q->cy + d.y + e[1], q->c, q->s, q->hw - r, q->hh - r};
	ProbeRect out = {in.cx, in.cy, q->c, q->s, q->hw + r, q->hh + r};
	int32_t n = only ? nonly : s->first[l + 1] - s->first[l];
	if (nopen)
		*nopen = 0;
	for (int32_t j = 0; j < n; j++) {
		int32_t i = only ? only[j] : s->first[l] + j;
		ProbeCell *k = &s->cells[i];
		int32_t least = 0, most = 0;
		for (int32_t y = k->y + sy; y < k->y + sy + k->size; y++)
			for (int32_t x = k->x + sx; x < k->x + sx + k->size; x++) {
				least += rect_meets(&in, x, y);
				most += rect_meets(&out, x, y);
			}
		if (k->count < least || k->count > most) {
			if (!only && i > s->first[l]) { /* to the front of its look: tried first next time */
				ProbeCell t = s->cells[s->first[l]];
				s->cells[s->first[l]] = *k;
				*k = t;
			}
			return false;
		}
		if (open && least < most)
			open[(*nopen)++] = i;
	}
	return true;
}

/* The most pieces an error of motion is cut into while a box is weighed. */
#define PROBE_ERROR_PIECES 16

/* look_errors(s, sx, sy, l, q, r, elo, ehi, lo, hi): the errors of motion in [elo,
 * ehi] (x and y) with which look l, the grid moved by (sx, sy), may agree with some rectangle
 * within r of q: false when none may; else their hull, in lo and hi. The whole
 * interval is weighed first (a piece of half-sides (hx, hy) about e moves the
 * rectangle by at most hypot(hx, hy) from q + d + e: weighed grown and shrunk by
 * that and r); then, only on the cells it leaves open, halves of it, the longer
 * side first, until a piece is no wider than r (the rectangle's own doubt: finer
 * pieces would gain little) or PROBE_EPS, or PROBE_ERROR_PIECES are weighed (the
 * rest kept whole: sound, only less sharp). */
static bool look_errors(ProbeSearch *s, int32_t sx, int32_t sy, int32_t l, const ProbeRect *q, double r, const double elo[2],
			const double ehi[2], double lo[2], double hi[2])
{
	int32_t open[PROBE_CELLS_A_LOOK], nopen = 0;
	double hx0 = 0.5 * (ehi[0] - elo[0]), hy0 = 0.5 * (ehi[1] - elo[1]);
	double e0[2] = {elo[0] + hx0, elo[1] + hy0};
	bool room = s->first[l + 1] - s->first[l] <= PROBE_CELLS_A_LOOK;
	if (!look_agrees(s, sx, sy, l, q, r + hypot(hx0, hy0), e0, NULL, 0, room ? open : NULL, &nopen))
		return false;
	lo[0] = elo[0], lo[1] = elo[1], hi[0] = ehi[0], hi[1] = ehi[1];
	double fine = fmax(r, PROBE_EPS);
	if (!room || nopen == 0 || hypot(hx0, hy0) <= fine)
		return true;
	double stack[PROBE_ERROR_PIECES + 8][4];
	int top = 0, weighed = 0;
	bool any = false;
	lo[0] = lo[1] = INFINITY;
	hi[0] = hi[1] = -INFINITY;
	stack[top][0] = elo[0], stack[top][1] = elo[1], stack[top][2] = ehi[0], stack[top][3] = ehi[1];
	top++;
	bool first = true;
	while (top > 0) {
		double *p = stack[--top];
		double x0 = p[0], y0 = p[1], x1 = p[2], y1 = p[3];
		double hx = 0.5 * (x1 - x0), hy = 0.5 * (y1 - y0);
		double e[2] = {x0 + hx, y0 + hy};
		bool whole = weighed >= PROBE_ERROR_PIECES || top + 2 > PROBE_ERROR_PIECES + 8;
		if (!whole && !first) {
			weighed++;
			if (!look_agrees(s, sx, sy, l, q, r + hypot(hx, hy), e, open, nopen, NULL, NULL))
				continue;
		}
		first = false;
		if (whole || hypot(hx, hy) <= fine) {
			any = true;
			lo[0] = fmin(lo[0], x0), lo[1] = fmin(lo[1], y0);
			hi[0] = fmax(hi[0], x1), hi[1] = fmax(hi[1], y1);
			continue;
		}
		int ax = hx >= hy ? 0 : 1;
		double m = 0.5 * (p[ax] + p[ax + 2]);
		double lo_half[4] = {x0, y0, x1, y1}, hi_half[4] = {x0, y0, x1, y1};
		lo_half[ax + 2] = m;
		hi_half[ax] = m;
		memcpy(stack[top++], hi_half, sizeof hi_half);
		memcpy(stack[top++], lo_half, sizeof lo_half);
	}
	return any;
}

/* box_alive(s, b, r): the places of the eye's grid (among b->alive) for which some
 * rectangle of the hypothesis in box b (radius r) may agree with all that was
 * seen; 0 when every one contradicts it. */
static uint32_t box_alive(ProbeSearch *s, ProbeBox *b, double r)
{
	/* No rectangle in the box has the proportions searched, or is wide enough. */
	if (b->lo[P_W] > s->amax * b->hi[P_H] || b->lo[P_H] > s->amax * b->hi[P_W] ||
	    (b->hi[P_W] <= s->amin * b->lo[P_H] && b->hi[P_H] <= s->amin * b->lo[P_W]) ||
	    b->hi[P_W] < PROBE_MIN_SIDE || b->hi[P_H] < PROBE_MIN_SIDE)
		return 0;
	double a = 0.5 * (b->lo[P_A] + b->hi[P_A]);
	double w = 0.5 * (b->lo[P_W] + b->hi[P_W]), h = 0.5 * (b->lo[P_H] + b->hi[P_H]);
	double cx = 0.5 * (b->lo[P_X] + b->hi[P_X]), cy = 0.5 * (b->lo[P_Y] + b->hi[P_Y]);
	double c = cos(a), sn = sin(a);
	ProbeRect in = {cx, cy, c, sn, 0.5 * w - r, 0.5 * h - r};
	ProbeRect out = {cx, cy, c, sn, 0.5 * w + r, 0.5 * h + r};
	for (int32_t i = 0; i < s->nbefore; i++) {
		ProbeSquare *q = &s->before[i];
		if (q->owned ? !rect_meets(&out, q->x, q->y) : rect_meets(&in, q->x, q->y)) {
			if (i > 0) { /* one step nearer the front: what drops boxes is tried early */
				ProbeSquare t = s->before[i - 1];
				s->before[i - 1] = *q;
				*q = t;
			}
			return 0;
		}
	}
	/* After each push: each look on its own (each has its own error of motion),
	 * at each place of the grid alive. */
	uint32_t alive = b->alive;
	double lo[PROBE_LOOKS][2], hi[PROBE_LOOKS][2];
	for (int32_t l = 0; l < s->nlooks; l++)
		lo[l][0] = lo[l][1] = INFINITY, hi[l][0] = hi[l][1] = -INFINITY;
	ProbeRect mid = {cx, cy, c, sn, 0.5 * w, 0.5 * h};
	/* A look's errors depend on the place of Utak's point only through where it
	 * may put that look's grid: each of the nine is weighed once a box (state 0
	 * not yet, 1 agrees, 2 does not). */
	uint8_t state[PROBE_LOOKS][9] = {{0}};
	double clo[PROBE_LOOKS][9][2], chi[PROBE_LOOKS][9][2];
	for (int g = 0; g < s->nshifts; g++) {
		if (!(alive >> g & 1))
			continue;
		for (int32_t l = 0; l < s->nlooks && (alive >> g & 1); l++) {
			bool agrees = false;
			for (int at = 0; at < 9; at++) {
				if (!(s->place[g][l] >> at & 1))
					continue;
				if (!state[l][at])
					state[l][at] = look_errors(s, at % 3 - 1, at / 3 - 1, l, &mid, r, b->elo[l], b->ehi[l],
								   clo[l][at], chi[l][at])
							   ? 1
							   : 2;
				if (state[l][at] == 1) {
					agrees = true;
					for (int ax = 0; ax < 2; ax++) {
						lo[l][ax] = fmin(lo[l][ax], clo[l][at][ax]);
						hi[l][ax] = fmax(hi[l][ax], chi[l][at][ax]);
					}
				}
			}
			if (!agrees)
				alive &= ~(1u << g);
		}
	}
	if (alive)
		for (int32_t l = 0; l < s->nlooks; l++)
			for (int ax = 0; ax < 2; ax++) {
				b->elo[l][ax] = lo[l][ax];
				b->ehi[l][ax] = hi[l][ax];
			}
	return alive;
}

static ProbeVerdict search(ProbeSearch *s, int32_t x0, int32_t y0, int32_t x1, int32_t y1, int64_t budget);

/* probe_grid_places(looks, nlooks, unplaced, place) (probe_work.h): the places of Utak's point in his
 * square that the looks tell apart, each with the places of the eye's grid it
 * allows at each look (probe.h, probe_square_consistent: `unplaced`); their
 * number. Placed (not unplaced): one, the grid where it was at every look. */
int probe_grid_places(const ProbeLook *looks, int32_t nlooks, bool unplaced, uint16_t place[][PROBE_LOOKS])
{
	int n = 1;
	for (int32_t l = 0; l < nlooks; l++) /* placed: the grid where it was */
		place[0][l] = 1u << 4;
	if (unplaced) {
		/* Utak's point is somewhere in his square, (f, g) from its lower-left
		 * corner; after look l's push it is in the square floor(f + d.x),
		 * floor(g + d.y) from his first, and the eye's grid with it. Each axis
		 * is cut where one of those changes; a place of the grid for each piece
		 * of the one axis with each of the other. */
		double cut[2][PROBE_LOOKS + 2];
		int ncut[2];
		for (int a = 0; a < 2; a++) {
			ncut[a] = 0;
			cut[a][ncut[a]++] = 0;
			for (int32_t l = 0; l < nlooks; l++) {
				double d = a == 0 ? looks[l].d.x : looks[l].d.y;
				double t = -d - floor(-d); /* floor(f + d) changes at f = t */
				if (t > 0)
					cut[a][ncut[a]++] = t;
			}
			cut[a][ncut[a]++] = 1;
			for (int i = 1; i < ncut[a]; i++) /* insertion sort: a few cuts */
				for (int j = i; j > 0 && cut[a][j - 1] > cut[a][j]; j--) {
					double t = cut[a][j];
					cut[a][j] = cut[a][j - 1];
					cut[a][j - 1] = t;
				}
		}
		n = 0;
		for (int i = 0; i + 1 < ncut[0]; i++)
			for (int j = 0; j + 1 < ncut[1]; j++) {
				if (cut[0][i + 1] - cut[0][i] <= 0 || cut[1][j + 1] - cut[1][j] <= 0)
					continue; /* two cuts at one place */
				/* The point in this piece, and motion's error within the
				 * look's slack, put the grid at floor(f + d + e) on each axis:
				 * within the slack of a cut, on either side of it. */
				bool allowed = true;
				for (int32_t l = 0; l < nlooks; l++) {
					double sl = looks[l].slack;
					int32_t lo[2], hi[2];
					for (int a = 0; a < 2; a++) {
						const double *piece = a == 0 ? &cut[0][i] : &cut[1][j];
						double d = a == 0 ? looks[l].d.x : looks[l].d.y;
						lo[a] = (int32_t)floor(piece[0] + d - sl);
						hi[a] = (int32_t)ceil(piece[1] + d + sl) - 1;
						lo[a] = lo[a] < -1 ? -1 : lo[a]; /* a slack under 3/4 of a square: */
						hi[a] = hi[a] > 1 ? 1 : hi[a];	 /* never beyond */
					}
					uint16_t mask = 0;
					for (int32_t sy = lo[1]; sy <= hi[1]; sy++)
						for (int32_t sx = lo[0]; sx <= hi[0]; sx++)
							mask |= (uint16_t)(1u << ((sy + 1) * 3 + sx + 1));
					place[n][l] = mask & looks[l].shifts;
					allowed &= place[n][l] != 0;
				}
				n += allowed;
			}
	}
	return n;
}

ProbeVerdict probe_square_consistent(const int32_t *bx, const int32_t *by, int32_t nb, const ProbeLook *looks,
				     int32_t nlooks, const ProbeCell *cells, int32_t ncells, bool unplaced,
				     int64_t budget)
{
	return probe_rect_consistent(bx, by, nb, looks, nlooks, cells, ncells, unplaced, 0, PROBE_ASPECT, budget);
}

ProbeVerdict probe_rect_consistent(const int32_t *bx, const int32_t *by, int32_t nb, const ProbeLook *looks,
				   int32_t nlooks, const ProbeCell *cells, int32_t ncells, bool unplaced,
				   double amin, double amax, int64_t budget)
{
	if (nb <= 0 || nb > PROBE_MAX_SQUARES || nlooks < 0 || nlooks > PROBE_LOOKS)
		return PROBE_UNDECIDED;
	for (int32_t i = 0; i < ncells; i++)
		if (cells[i].look < 0 || cells[i].look >= nlooks)
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
	/* The cells grouped by look. */
	ProbeCell *grouped = util_alloc(ncells > 0 ? (size_t)ncells : 1, sizeof *grouped);
	ProbeSearch *s = util_alloc(1, sizeof *s);
	*s = (ProbeSearch){before, n, grouped, ncells, {0}, looks, nlooks, {{0}}, 1, amin, amax};
	int32_t placed = 0;
	for (int32_t l = 0; l < nlooks; l++) {
		s->first[l] = placed;
		for (int32_t i = 0; i < ncells; i++)
			if (cells[i].look == l)
				grouped[placed++] = cells[i];
	}
	s->first[nlooks] = placed;
	s->nshifts = probe_grid_places(looks, nlooks, unplaced, s->place);
	ProbeVerdict verdict = search(s, x0, y0, x1, y1, budget);
	free(grouped);
	free(s);
	free(before);
	free(mark);
	return verdict;
}

/* search(s, x0, y0, x1, y1, budget): branch and bound (above) for B in the box
 * x0..x1, y0..y1 (squares), every place of the eye's grid at once (a box carries
 * those not yet ruled out in it), at most `budget` boxes. */
static ProbeVerdict search(ProbeSearch *s, int32_t x0, int32_t y0, int32_t x1, int32_t y1, int64_t budget)
{
	/* The rectangle lies within B's squares: its centre in their box, its sides
	 * no longer than the box's diagonal. */
	double most_side = hypot(x1 - x0 + 1, y1 - y0 + 1);
	enum { STACK = 1024 };
	ProbeBox *stack = util_alloc(STACK, sizeof *stack);
	int top = 0;
	ProbeVerdict verdict = PROBE_INCONSISTENT;
	if (most_side >= PROBE_MIN_SIDE) {
		ProbeBox b = {.lo = {0, PROBE_LATTICE_SIDE, PROBE_LATTICE_SIDE, x0, y0},
			      .hi = {PROBE_QUARTER, most_side, most_side, x1 + 1, y1 + 1},
			      .alive = (uint32_t)((1ull << s->nshifts) - 1)};
		for (int32_t l = 0; l < s->nlooks; l++) /* each look's error: its slack either way */
			for (int a = 0; a < 2; a++) {
				b.elo[l][a] = -s->looks[l].slack;
				b.ehi[l][a] = s->looks[l].slack;
			}
		stack[top++] = b;
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
		b.alive = box_alive(s, &b, r);
		if (!b.alive)
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
	return verdict;
}

/* ---- the probe in the action cycle (probe.h) --------------------------------------- */

/* window_floor(p, x, y): square (x, y) was floor before the probe (inside the window). */
static bool window_floor(const ProbeRun *p, int32_t x, int32_t y)
{
	int32_t i = x - p->wx, j = y - p->wy;
	return i >= 0 && j >= 0 && i < PROBE_WINDOW && j < PROBE_WINDOW && p->floor_before[j * PROBE_WINDOW + i];
}

/* owned_before(p, x, y): square (x, y) is one of the object's before the probe. */
static bool owned_before(const ProbeRun *p, int32_t x, int32_t y)
{
	for (int32_t i = 0; i < p->nb; i++)
		if (p->bx[i] == x && p->by[i] == y)
			return true;
	return false;
}

/* free_for_probe(c, x, y): square (x, y) is believed floor, seen in the fovea (a
 * cell of one square: what it says of the square is exact); or it is Utak's own (a
 * held object may come onto it, paper 2.2). Squares bumped into (c->bumped_x) are
 * not refused: they are the floor squares beside what halted a move, and the
 * fovea has said what they are. */
static bool free_for_probe(const Controller *c, int32_t x, int32_t y)
{
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	if (x == ux && y == uy)
		return true;
	return worldmodel_belief(&c->model, x, y) == BELIEF_FLOOR &&
	       worldmodel_evidence(&c->model, x, y).res == WORLDMODEL_RES_FOVEA;
}

/* room_toward(c, p, sx, sy): every square the object may move onto, pushed less than
 * a square toward (sx, sy) on each axis, is free (free_for_probe). */
static bool room_toward(const Controller *c, const ProbeRun *p, int sx, int sy)
{
	static const int8_t part[3][2] = {{1, 0}, {0, 1}, {1, 1}};
	for (int32_t i = 0; i < p->nb; i++)
		for (int k = 0; k < 3; k++) {
			int32_t x = p->bx[i] + part[k][0] * sx, y = p->by[i] + part[k][1] * sy;
			if (!owned_before(p, x, y) && !free_for_probe(c, x, y))
				return false;
		}
	return true;
}

bool probe_begin(Controller *c, int32_t k)
{
	if (c->task.kind != TASK_GO_SHAPE)
		return false;
	return probe_begin_object(c, k);
}

bool probe_begin_object(Controller *c, int32_t k)
{
	return probe_begin_step(c, k, PROBE_STEP);
}

bool probe_begin_step(Controller *c, int32_t k, double step)
{
	ProbeRun *p = &c->probe;
	const WorldModel *m = &c->model;
	if (p->runs >= PROBE_RUNS || k < 0 || m->node[k].kind != NODE_OBJECT)
		return false;
	ObjectReading o = objects_read(c, k);
	if (!o.confirmed || o.squares > PROBE_MAX_SQUARES)
		return false;
	/* WIDTH ONLY (probe.h): for another shape, a probe only where its squares
	 * leave its width in doubt (a crumb), and only the width is asked. */
	bool width_only = c->task.shape != SHAPE_SQUARE;
	if (width_only && !objects_narrow(c, k))
		return false;
	/* Its squares, and the window round them (3 squares of margin). */
	const Box *r = &m->node[k].rect;
	int32_t x0 = (int32_t)floor(r->lo.x), y0 = (int32_t)floor(r->lo.y);
	int32_t x1 = (int32_t)ceil(r->hi.x), y1 = (int32_t)ceil(r->hi.y);
	if (x1 - x0 + 6 > PROBE_WINDOW || y1 - y0 + 6 > PROBE_WINDOW)
		return false;
	p->nb = 0;
	for (int32_t y = y0; y < y1; y++)
		for (int32_t x = x0; x < x1; x++)
			if (worldmodel_node_at(m, x, y) == k && p->nb < PROBE_MAX_SQUARES) {
				p->bx[p->nb] = x;
				p->by[p->nb++] = y;
			}
	if (p->nb != o.squares)
		return false;
	/* Its ring is floor (or Utak's square): else it may own squares it seems not to. */
	for (int32_t i = 0; i < p->nb; i++)
		for (int32_t dy = -1; dy <= 1; dy++)
			for (int32_t dx = -1; dx <= 1; dx++) {
				int32_t x = p->bx[i] + dx, y = p->by[i] + dy;
				if (!owned_before(p, x, y) && !free_for_probe(c, x, y))
					return false;
			}
	/* The grasp takes the first object colour touch shows: it must be this one's. */
	if (!objects_touched_only(c, k))
		return false;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	static const int8_t way[4][2] = {{1, 1}, {-1, -1}, {1, -1}, {-1, 1}};
	p->corners = 0;
	for (int w = 0; w < 4 && p->corners < PROBE_TAKES; w++)
		if (room_toward(c, p, way[w][0], way[w][1]))
			p->corner[p->corners++] = vec2(step * way[w][0], step * way[w][1]);
	if (p->corners == 0)
		return false;
	p->step = step;
	p->wx = x0 - 3;
	p->wy = y0 - 3;
	for (int32_t j = 0; j < PROBE_WINDOW; j++)
		for (int32_t i = 0; i < PROBE_WINDOW; i++) {
			int32_t x = p->wx + i, y = p->wy + j;
			p->floor_before[j * PROBE_WINDOW + i] =
			    (x != ux || y != uy) && worldmodel_belief(m, x, y) == BELIEF_FLOOR;
		}
	p->ident = m->node[k].ident;
	p->at = o.centroid;
	p->narrow = o.reading.min_width < OBJECTS_NAMED_WIDTH - 1e-9;
	p->width_only = width_only;
	p->look = 0;
	p->ncells = 0;
	p->changed = false;
	p->ux = ux;
	p->uy = uy;
	p->verdict = PROBE_UNDECIDED;
	p->runs++;
	p->stage = PROBE_GRASP;
	return true;
}

/* judge(c, p): the looks judged together (probe.h, HOW and THEN). */
static void judge(Controller *c, ProbeRun *p)
{
	p->verdict = PROBE_UNDECIDED;
	p->width = 0;
	int looks = p->look;
	if (!p->changed || looks <= 0)
		return; /* no look to judge, or none that showed anything either way */
	double err = worldmodel_motion_error(&c->model);
	double rate = err > 0 ? fmax(PROBE_SLACK_RATE, 4 * err) : PROBE_SLACK_RATE;
	double pushed_sq = 0;
	Vec2 from = vec2(0, 0);
	for (int l = 0; l < looks; l++) {
		pushed_sq += vec2_dot(vec2_sub(p->corner[l], from), vec2_sub(p->corner[l], from));
		from = p->corner[l];
		p->looks[l] = (ProbeLook){p->corner[l], rate * sqrt(pushed_sq), p->shifts[l], rate};
	}
	if (!p->width_only) /* else the square's test does not apply: UNDECIDED */
		p->verdict = probe_square_consistent(p->bx, p->by, p->nb, p->looks, looks, p->cells, p->ncells, true,
						     PROBE_BUDGET);
	p->width = probe_least_width(p->bx, p->by, p->nb, p->looks, looks, p->cells, p->ncells, true);
}

bool probe_decide(Controller *c, MotorCommand *cmd)
{
	ProbeRun *p = &c->probe;
	Vec2 at = p->look > 0 ? p->corner[p->look - 1] : vec2(0, 0); /* where it is now, believed */
	switch (p->stage) {
	case PROBE_IDLE:
		return false;
	case PROBE_GRASP:
		*cmd = (MotorCommand){.kind = MOTOR_GRASP};
		p->stage = PROBE_PUSH;
		return true;
	case PROBE_PUSH:
		if (p->look < p->corners) {
			Vec2 d = vec2_sub(p->corner[p->look], at);
			*cmd = (MotorCommand){.kind = MOTOR_PUSH, .dx = d.x, .dy = d.y};
			return true;
		}
		*cmd = (MotorCommand){.kind = MOTOR_PUSH, .dx = -at.x, .dy = -at.y}; /* every corner looked from */
		p->stage = PROBE_RELEASE;
		return true;
	case PROBE_RELEASE:
		*cmd = (MotorCommand){.kind = MOTOR_RELEASE};
		p->stage = PROBE_FINISH;
		return true;
	case PROBE_FINISH:
		break;
	}
	if (probe_end(c) == PROBE_INCONSISTENT) {
		c->target = 0; /* not the square: the task goes on without it */
		c->have_plan = false;
	} else if (!seam_felt_after(c)) {
		c->have_plan = false; /* touch no longer feels it: beside it again first (seam.h) */
	} else {
		c->phase = PHASE_DONE;
	}
	return false;
}

ProbeVerdict probe_end(Controller *c)
{
	ProbeRun *p = &c->probe;
	p->stage = PROBE_IDLE; /* judged on the release's impression (probe_perceive) */
	if (p->verdict == PROBE_INCONSISTENT && p->disproved_count < PROBE_DISPROVED) {
		p->disproved_ident[p->disproved_count] = p->ident;
		p->disproved_at[p->disproved_count++] = p->at;
	}
	if (p->width > 0 && p->measured_count < PROBE_DISPROVED) {
		p->measured_ident[p->measured_count] = p->ident;
		p->measured_at[p->measured_count] = p->at;
		p->measured_width[p->measured_count++] = p->width;
	}
	return p->verdict;
}

/* count_of(level, total): how many of a cell's `total` squares are occupied, from
 * its gray level (exact for cells of 1 and 4 squares, eye.h); -1 when no count gives
 * that level. */
static int32_t count_of(int level, int32_t total)
{
	for (int32_t n = 0; n <= total; n++)
		if (eye_level(n, total) == level)
			return n;
	return -1;
}

/* grid_shifts(c, p, bx0, by0, bx1, by1): the places of the eye's grid (ProbeLook
 * shifts) that the rest of this look allows: a place is ruled out when a cell of
 * the fovea away from the object (two squares or more beyond its box bx0..bx1,
 * by0..by1), all of whose squares the model holds from the fovea (floor, or
 * occupied by what does not move), shows other than the model predicts with the
 * grid there (Utak's own square, which the eye sees occupied, included). Where
 * every place is ruled out (the model was wrong somewhere), none is. */
static uint16_t grid_shifts(const Controller *c, const ProbeRun *p, int32_t bx0, int32_t by0, int32_t bx1, int32_t by1)
{
	const WorldModel *m = &c->model;
	uint16_t shifts = 0;
	for (int32_t sy = -1; sy <= 1; sy++)
		for (int32_t sx = -1; sx <= 1; sx++) {
			bool fits = true;
			for (int32_t i = 0; i < RETINA_FOVEA && fits; i++) {
				EyeCell e = eye_cell(i);
				int32_t x = p->ux + sx + e.ox, y = p->uy + sy + e.oy;
				if (x >= bx0 - 2 && x <= bx1 + 2 && y >= by0 - 2 && y <= by1 + 2)
					continue; /* the object may be there */
				bool utak = x == p->ux + sx && y == p->uy + sy;
				if (!utak && worldmodel_evidence(m, x, y).res != WORLDMODEL_RES_FOVEA)
					continue;
				bool occupied = utak || worldmodel_belief(m, x, y) == BELIEF_OCCUPIED;
				fits = (c->impression.level[i] != 0) == occupied;
			}
			if (fits)
				shifts |= (uint16_t)(1u << ((sy + 1) * 3 + sx + 1));
		}
	return shifts ? shifts : PROBE_ANY_SHIFT;
}

/* at_rest_fits(p, first, shifts): the look's cells (from index `first`) show what
 * the object standing where it was, unmoved, would show through the eye's grid at
 * some place `shifts` allows. WHY: Utak holds what he pushes and moves with it, and
 * the grid moves with him; where his point and the object's edges cross a square's
 * edge on the same pushes, the cells, placed from his square before the probe,
 * show the same counts as before (perturbed clutter-p4's brick, its edges and his
 * point both about half way into their squares, pushed by half a square): the
 * object did move, and it shows where the grid's place is fixed by what else the
 * look showed. Only a look that no grid place lets the unmoved object explain
 * shows motion; the others may be a grasp that failed (probe.h, THEN). */
static bool at_rest_fits(const ProbeRun *p, int32_t first, uint16_t shifts)
{
	for (int32_t sy = -1; sy <= 1; sy++)
		for (int32_t sx = -1; sx <= 1; sx++) {
			if (!(shifts & (1u << ((sy + 1) * 3 + sx + 1))))
				continue;
			bool fits = true;
			for (int32_t i = first; i < p->ncells && fits; i++) {
				const ProbeCell *q = &p->cells[i];
				int32_t n = 0;
				for (int32_t j = 0; j < q->size; j++)
					for (int32_t k = 0; k < q->size; k++)
						n += owned_before(p, q->x + sx + k, q->y + sy + j);
				fits = n == q->count;
			}
			if (fits)
				return true;
		}
	return false;
}

/* keep_look(c, p): the cells of the look after the push to corner p->look that
 * the object may reach and that hold only its squares and floor, wherever in his
 * square Utak's point was (probe_square_consistent, unplaced): the cell's squares
 * and every square next to them were the object's or floor before the probe, and
 * none is Utak's own square (the eye sees it occupied; the cells beside him are
 * kept, else the object's near side is never seen after a push). The
 * cells are placed from the square Utak stood on before the probe, whatever the
 * model believes since (its disparity search sees the object's squares change
 * beside him, which its whole squares cannot predict). */
static void keep_look(Controller *c, ProbeRun *p)
{
	int32_t bx0 = p->bx[0], by0 = p->by[0], bx1 = p->bx[0], by1 = p->by[0];
	for (int32_t i = 1; i < p->nb; i++) {
		bx0 = p->bx[i] < bx0 ? p->bx[i] : bx0;
		by0 = p->by[i] < by0 ? p->by[i] : by0;
		bx1 = p->bx[i] > bx1 ? p->bx[i] : bx1;
		by1 = p->by[i] > by1 ? p->by[i] : by1;
	}
	int32_t first = p->ncells;
	for (int32_t i = 0; i < PROBE_LOOK_CELLS; i++) {
		EyeCell e = eye_cell(i);
		int32_t x = p->ux + e.ox, y = p->uy + e.oy;
		if (x + e.size <= bx0 - 2 || x > bx1 + 2 || y + e.size <= by0 - 2 || y > by1 + 2)
			continue;
		/* The eye's own square (its offset 0, 0) is Utak's, seen occupied
		 * wherever his point went: the cell of it is not kept. Every other
		 * cell's squares are his square before the probe only when he has
		 * left it (the grid moves with him): floor then, or the object's. */
		bool usable = !(e.ox == 0 && e.oy == 0);
		for (int32_t j = -1; j <= e.size && usable; j++)
			for (int32_t k = -1; k <= e.size && usable; k++) {
				int32_t sx = x + k, sy = y + j;
				usable = (sx == p->ux && sy == p->uy) || owned_before(p, sx, sy) || window_floor(p, sx, sy);
			}
		int32_t before = 0;
		for (int32_t j = 0; j < e.size; j++)
			for (int32_t k = 0; k < e.size; k++)
				before += owned_before(p, x + k, y + j);
		int32_t count = count_of(c->impression.level[i], e.size * e.size);
		if (!usable || count < 0)
			continue;
		p->changed |= count != before;
		p->cells[p->ncells++] = (ProbeCell){x, y, e.size, count, p->look};
	}
	p->shifts[p->look] = grid_shifts(c, p, bx0, by0, bx1, by1);
	p->changed |= !at_rest_fits(p, first, p->shifts[p->look]);
	p->look++;
}

void probe_width_note(const ProbeRun *p, char *note, size_t size)
{
	size_t n = strlen(note);
	if (p->narrow && n < size)
		snprintf(note + n, size - n, "; the looks show it at least %.2f wide (a name needs %.0f)", p->width,
			 OBJECTS_NAMED_WIDTH);
}

bool probe_perceive(Controller *c, const MotorCommand *cmd, char *note, size_t size)
{
	ProbeRun *p = &c->probe;
	if (p->stage == PROBE_IDLE)
		return false;
	switch (cmd->kind) {
	case MOTOR_GRASP:
		snprintf(note, size, "; probe: grasped the %s, to push it %d way%s by a quarter square and back (probe.h%s)",
			 task_shape_name(c->task.shape), p->corners, p->corners > 1 ? "s" : "",
			 p->width_only ? ", its width only" : "");
		break;
	case MOTOR_PUSH:
		if (p->stage == PROBE_PUSH) {
			int32_t before = p->ncells;
			keep_look(c, p);
			snprintf(note, size, "; probe: looked at it (%d cells)", (int)(p->ncells - before));
		} else {
			snprintf(note, size, "; probe: pushed back");
		}
		break;
	default:
		judge(c, p);
		snprintf(note, size, "; probe: released; its squares %s", probe_said(p));
		probe_width_note(p, note, size);
		if (p->verdict != PROBE_INCONSISTENT && !seam_felt_after(c)) {
			size_t n = strlen(note);
			snprintf(note + n, size - n, "; touch feels it no more: beside it again before the claim (seam.h)");
		}
		break;
	}
	c->have_plan = false;
	return true;
}
const char *probe_said(const ProbeRun *p)
{
	static const char *const said[3] = {"fit a square: the claim stands", "fit no square: it is not the square",
					    "do not decide: the claim stands"};
	return p->width_only ? "were measured, not weighed against a square: the claim is judged again"
			     : said[p->verdict];
}

bool probe_disproved(const Controller *c, int32_t ident, Vec2 at)
{
	const ProbeRun *p = &c->probe;
	for (int i = 0; i < p->disproved_count; i++)
		if (objects_same(p->disproved_ident[i], p->disproved_at[i], ident, at))
			return true;
	return false;
}

double probe_width(const Controller *c, int32_t ident, Vec2 at)
{
	const ProbeRun *p = &c->probe;
	double most = 0;
	for (int i = 0; i < p->measured_count; i++)
		if (objects_same(p->measured_ident[i], p->measured_at[i], ident, at))
			most = fmax(most, p->measured_width[i]);
	return most;
}
