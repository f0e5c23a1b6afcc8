/* probewidth.c - the least width of any polygon that gave a probe's looks (paper
 * 3.3: a shape read from the squares an object covers is a hypothesis until
 * confirmed; issue 13 items 1 and 6; the meaning and the bound in probe.h,
 * probe_least_width). CONTROLLER SIDE: pure geometry on what Utak saw and the
 * pushes he commanded. */
#include <math.h>
#include <stdlib.h>

#include "utak/base/util.h"
#include "utak/mind/probe.h"
#include "probe_work.h"

/* A region a look showed the object meets: the open square box of side `size`
 * centred at (cx, cy), placed as if the eye's grid had not moved. */
typedef struct ProbeRegion {
	double cx, cy, size;
} ProbeRegion;

/* region_reach(reg, first, looks, nlooks, ux, uy, hi, lo, seen): along u, each
 * look's regions (look 0 before the pushes, look l + 1 looks[l]; first[] as in
 * probe_least_width) less the push as commanded, the grid where it was: the
 * object surely reaches beyond hi[l] (the far edge of its farthest region's near
 * side) and begins before lo[l]; seen[l]: the look has regions at all. */
static void region_reach(const ProbeRegion *reg, const int32_t *first, const ProbeLook *looks, int32_t nlooks,
			 double ux, double uy, double *hi, double *lo, bool *seen)
{
	double l1 = fabs(ux) + fabs(uy);
	for (int32_t l = 0; l <= nlooks; l++) {
		hi[l] = -INFINITY, lo[l] = INFINITY;
		for (int32_t i = first[l]; i < first[l + 1]; i++) {
			double c = ux * reg[i].cx + uy * reg[i].cy, h = 0.5 * reg[i].size * l1;
			hi[l] = fmax(hi[l], c - h);
			lo[l] = fmin(lo[l], c + h);
		}
		seen[l] = first[l + 1] > first[l];
		if (l > 0) {
			double push = ux * looks[l - 1].d.x + uy * looks[l - 1].d.y;
			hi[l] -= push;
			lo[l] -= push;
		}
	}
}

/* look_error(looks, j, k): how far motion's error may move look k's regions
 * against look j's, along each axis (looks numbered as in region_reach: 0 is B,
 * no error): the two slacks; or, with a rate (ProbeLook.rate) at every look
 * between, that of the pushes between them (the root of their squared lengths
 * times the rate), when less. */
static double look_error(const ProbeLook *looks, int32_t j, int32_t k)
{
	if (j == k)
		return 0;
	if (j > k) {
		int32_t t = j;
		j = k;
		k = t;
	}
	double both = (j ? looks[j - 1].slack : 0) + looks[k - 1].slack;
	double rate = looks[k - 1].rate, sq = 0;
	for (int32_t l = j + 1; l <= k && rate > 0; l++) {
		Vec2 from = l > 1 ? looks[l - 2].d : vec2(0, 0), to = looks[l - 1].d;
		sq += (to.x - from.x) * (to.x - from.x) + (to.y - from.y) * (to.y - from.y);
		rate = looks[l - 1].rate > 0 ? fmax(rate, looks[l - 1].rate) : 0;
	}
	return rate > 0 ? fmin(both, rate * sqrt(sq)) : both;
}

double probe_least_width(const int32_t *bx, const int32_t *by, int32_t nb, const ProbeLook *looks, int32_t nlooks,
			 const ProbeCell *cells, int32_t ncells, bool unplaced)
{
	if (nb <= 0 || nb > PROBE_MAX_SQUARES || nlooks < 0 || nlooks > PROBE_LOOKS)
		return 0;
	for (int32_t i = 0; i < ncells; i++)
		if (cells[i].look < 0 || cells[i].look >= nlooks)
			return 0;
	/* Look 0 here is the look before the pushes (B: d 0, no error, the grid
	 * where it was); look l + 1 is looks[l]. A cell all of whose squares the
	 * object owns is a region for each; one it owns some of, one region. */
	int32_t most = nb;
	for (int32_t i = 0; i < ncells; i++)
		most += cells[i].count > 0 ? cells[i].size * cells[i].size : 0;
	ProbeRegion *reg = util_alloc((size_t)most, sizeof *reg);
	int32_t first[PROBE_LOOKS + 2], n = 0;
	int32_t x0 = bx[0], x1 = bx[0], y0 = by[0], y1 = by[0];
	first[0] = 0;
	for (int32_t i = 0; i < nb; i++) {
		reg[n++] = (ProbeRegion){bx[i] + 0.5, by[i] + 0.5, 1};
		x0 = bx[i] < x0 ? bx[i] : x0;
		x1 = bx[i] > x1 ? bx[i] : x1;
		y0 = by[i] < y0 ? by[i] : y0;
		y1 = by[i] > y1 ? by[i] : y1;
	}
	for (int32_t l = 0; l < nlooks; l++) {
		first[l + 1] = n;
		for (int32_t i = 0; i < ncells; i++) {
			const ProbeCell *k = &cells[i];
			if (k->look != l || k->count <= 0)
				continue;
			if (k->count < k->size * k->size)
				reg[n++] = (ProbeRegion){k->x + 0.5 * k->size, k->y + 0.5 * k->size, k->size};
			else
				for (int32_t j = 0; j < k->size; j++)
					for (int32_t m = 0; m < k->size; m++)
						reg[n++] = (ProbeRegion){k->x + m + 0.5, k->y + j + 0.5, 1};
		}
	}
	first[nlooks + 1] = n;
	uint16_t place[PROBE_SHIFTS][PROBE_LOOKS];
	int nplaces = probe_grid_places(looks, nlooks, unplaced, place);
	double err[PROBE_LOOKS + 1][PROBE_LOOKS + 1];
	for (int32_t j = 0; j <= nlooks; j++)
		for (int32_t k = 0; k <= nlooks; k++)
			err[j][k] = look_error(looks, j, k);
	/* A place of a look's grid that puts a region it showed beyond where the
	 * object can reach is none: before the pushes the object lay within B's
	 * closed squares, so along u no point of it lies beyond B's centres' reach
	 * plus half a square's extent (hi[0] + |ux| + |uy|), and after a push by d +
	 * e none beyond that plus u.(d + e). */
	uint16_t fits[PROBE_LOOKS];
	for (int32_t l = 0; l < nlooks; l++)
		fits[l] = PROBE_ANY_SHIFT;
	for (int t = 0; t < PROBE_WIDTH_DIRECTIONS; t++) {
		double a = PROBE_QUARTER * 2 * t / PROBE_WIDTH_DIRECTIONS;
		double ux = cos(a), uy = sin(a), l1 = fabs(ux) + fabs(uy);
		double hi[PROBE_LOOKS + 1], lo[PROBE_LOOKS + 1];
		bool seen[PROBE_LOOKS + 1];
		region_reach(reg, first, looks, nlooks, ux, uy, hi, lo, seen);
		for (int32_t l = 1; l <= nlooks; l++)
			for (int at = 0; at < 9 && seen[l]; at++) {
				double sh = ux * (at % 3 - 1) + uy * (at / 3 - 1), e = looks[l - 1].slack * l1;
				if (hi[l] + sh - e >= hi[0] + l1 || lo[l] + sh + e <= lo[0] - l1)
					fits[l - 1] &= (uint16_t)~(1u << at);
			}
	}
	int kept = 0;
	for (int g = 0; g < nplaces; g++) {
		bool any = true;
		for (int32_t l = 0; l < nlooks; l++) {
			place[kept][l] = place[g][l] & fits[l];
			any &= place[kept][l] != 0;
		}
		kept += any;
	}
	nplaces = kept; /* none: what was seen agrees with no place (the bound says nothing) */
	double least = INFINITY, *vals = util_alloc(PROBE_WIDTH_DIRECTIONS, sizeof *vals);
	for (int t = 0; t < PROBE_WIDTH_DIRECTIONS; t++)
		vals[t] = -INFINITY;
	for (int t = 0; t < PROBE_WIDTH_DIRECTIONS && nplaces > 0; t++) {
		double a = PROBE_QUARTER * 2 * t / PROBE_WIDTH_DIRECTIONS;
		double ux = cos(a), uy = sin(a), l1 = fabs(ux) + fabs(uy);
		double hi[PROBE_LOOKS + 1], lo[PROBE_LOOKS + 1];
		bool seen[PROBE_LOOKS + 1];
		region_reach(reg, first, looks, nlooks, ux, uy, hi, lo, seen);
		double worst = INFINITY; /* over the places of Utak's point */
		for (int g = 0; g < nplaces; g++) {
			/* Each look's grid at one of the places this place of Utak's
			 * point allows it (its error of motion near a cut), every
			 * choice tried: the least over them holds. */
			double sh[PROBE_LOOKS + 1][9];
			int nsh[PROBE_LOOKS + 1], pick[PROBE_LOOKS + 1] = {0};
			sh[0][0] = 0, nsh[0] = 1;
			for (int32_t l = 1; l <= nlooks; l++) {
				nsh[l] = 0;
				for (int at = 0; at < 9; at++)
					if (place[g][l - 1] >> at & 1)
						sh[l][nsh[l]++] = ux * (at % 3 - 1) + uy * (at / 3 - 1);
			}
			for (;;) {
				double best = -INFINITY; /* over the pairs of looks */
				for (int32_t j = 0; j <= nlooks; j++)
					for (int32_t k = 0; k <= nlooks; k++) {
						if (!seen[j] || !seen[k])
							continue;
						/* Each look's own error of motion moves all its
						 * regions together (none in one look's own
						 * spread); between two looks, look_error's, on
						 * each axis. */
						best = fmax(best, hi[k] + sh[k][pick[k]] - lo[j] - sh[j][pick[j]] - err[j][k] * l1);
					}
				worst = fmin(worst, best);
				int32_t l = 1; /* the next choice */
				while (l <= nlooks && ++pick[l] == nsh[l])
					pick[l++] = 0;
				if (l > nlooks)
					break;
			}
		}
		vals[t] = worst;
	}
	free(reg);
	/* Between two directions tried: the object's extent across u changes by at
	 * most its diameter (no more than B's box's diagonal: it lay within B's
	 * squares) times the angle, so between directions a and b, each bounded
	 * (vals), it is at least the larger of the two bounds so lessened: the least
	 * of that over the step lies where they meet, or at a direction tried when
	 * the other bound is higher by the diameter times the step or more. (The
	 * bound itself, the most of u.v over pairs of regions, may dip between two
	 * directions as deep as its vectors are long: the extent's own diameter is
	 * what limits the dip.) */
	double diam = hypot(x1 - x0 + 1, y1 - y0 + 1), step = 2 * PROBE_QUARTER / PROBE_WIDTH_DIRECTIONS;
	least = INFINITY;
	for (int t = 0; t < PROBE_WIDTH_DIRECTIONS; t++) {
		double fa = vals[t], fb = vals[(t + 1) % PROBE_WIDTH_DIRECTIONS]; /* the extent across u and -u alike */
		double at = (fa - fb + diam * step) / (2 * diam); /* from a, where the two meet */
		at = at < 0 ? 0 : at > step ? step : at;
		least = fmin(least, fmax(fa - diam * at, fb - diam * (step - at)));
	}
	free(vals);
	return nplaces > 0 && least > 0 ? least : 0;
}

