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
	double least = INFINITY;
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
						/* Each look's own error of motion, within its
						 * slack on each axis, moves all its regions
						 * together (none in one look's own spread). */
						double err = j == k ? 0
								    : ((j ? looks[j - 1].slack : 0) + (k ? looks[k - 1].slack : 0)) * l1;
						best = fmax(best, hi[k] + sh[k][pick[k]] - lo[j] - sh[j][pick[j]] - err);
					}
				worst = fmin(worst, best);
				int32_t l = 1; /* the next choice */
				while (l <= nlooks && ++pick[l] == nsh[l])
					pick[l++] = 0;
				if (l > nlooks)
					break;
			}
		}
		least = fmin(least, worst);
	}
	/* Between two directions tried. Within a quadrant of u (the axes are
	 * tried) |ux| + |uy| is linear in u, so for each place and choice of grids
	 * the bound is the most of u.v over a fixed set of vectors v (pairs of
	 * regions): where the v that gives it is within a quarter turn of u all
	 * over the step, u.v is concave there and no less than at the step's ends,
	 * so neither is the bound. Else u.v < |v| sin(step) there; and the bound
	 * changes by at most max |v| times the angle, so once the least tried is
	 * twice that or more, no v can be so near a quarter turn from u: the least
	 * tried is the least. Under that, half a step's worth is taken off. */
	double cx0 = INFINITY, cx1 = -INFINITY, cy0 = INFINITY, cy1 = -INFINITY, most_d = 0, most_slack = 0;
	for (int32_t i = 0; i < n; i++) {
		cx0 = fmin(cx0, reg[i].cx), cx1 = fmax(cx1, reg[i].cx);
		cy0 = fmin(cy0, reg[i].cy), cy1 = fmax(cy1, reg[i].cy);
	}
	for (int32_t l = 0; l < nlooks; l++) {
		most_d = fmax(most_d, hypot(looks[l].d.x, looks[l].d.y));
		most_slack = fmax(most_slack, looks[l].slack);
	}
	free(reg);
	/* |v|: centres apart, two pushes, two grids moved a square each way, two
	 * cells' halves (2 x 2 at most), two slacks. */
	double most_v = hypot(cx1 - cx0, cy1 - cy0) + 2 * most_d + 6 * sqrt(2.0) + 2 * sqrt(2.0) * most_slack;
	double step = 2 * PROBE_QUARTER / PROBE_WIDTH_DIRECTIONS;
	if (least < 2 * most_v * step)
		least -= 0.5 * most_v * step;
	return nplaces > 0 && least > 0 ? least : 0;
}

