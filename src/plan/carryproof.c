/* carryproof.c - why a carry cannot be: the disc's proof that the object cannot
 * pass, and the reason printed when no plan exists (paper 3.6 and 5: the open
 * problem of the L-shape in a doorway is one of telling "cannot" from "not found";
 * carry.h, PRUNING and RESULT). Split from carry.c, whose search calls these two
 * when the lattice search fails or is tried only after them.
 *
 * ALGORITHM. The disc's proof: a breadth-first search over cells CARRY_DISC_REFINE
 * times finer than the grid's, through the cells where the disc inside the object
 * fits by the exact distance transform (skeleton_edt), from the disc's centre to
 * any place it fits wholly inside the goal region; none reached proves that the
 * object cannot get there either (the disc moves with it, continuously). The
 * reason: whether the goal region has room for the object at any angle; then the
 * side of the largest axis-aligned square that can slide from the object's cells
 * to the goal region (2-D prefix sums, a breadth-first search per side), which for
 * a door along the axes is its width, against the object's narrowest width
 * (carry.c: rotating calipers).
 *
 * COMPLEXITY. The proof O(m^2 w h) for refinement m; the reason O(w h) for the
 * room, O(s w h) for the way's width up to side s. */
#include "carry_work.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/plan/skeleton.h"

/* CARRY_DISC_REFINE: the disc's proof works on cells this many times finer than the
 * grid's, so that its bound (below) is loose by at most 0.21 / CARRY_DISC_REFINE. */
#define CARRY_DISC_REFINE 2
/* refined_edt(k, in_goal, d2): the distance transform of the grid refined by
 * CARRY_DISC_REFINE (a fine cell blocked when its grid cell is blocked, or with
 * in_goal when it is outside the goal region), into d2 (fine cells, row-major). */
static void refined_edt(const CarryWork *k, bool in_goal, int32_t *d2)
{
	int32_t m = CARRY_DISC_REFINE, fw = k->w * m, fh = k->h * m;
	Grid fine;
	grid_init(&fine, fw, fh, GRID_BLOCKED);
	for (int32_t y = 0; y < fh; y++)
		for (int32_t x = 0; x < fw; x++) {
			size_t c = (size_t)(y / m) * k->w + (size_t)(x / m);
			bool open = k->grid_cells[c] == GRID_FREE && (!in_goal || k->goal->inside->cells[c] == GRID_FREE);
			fine.cells[(size_t)y * fw + x] = open ? GRID_FREE : GRID_BLOCKED;
		}
	skeleton_edt(&fine, d2);
	grid_free(&fine);
}

/* carry_disc_cannot_pass(k, centre, radius): the shape's proof (carry.h, PRUNING): true
 * when the disc of that radius at centre (inside the object, grid units) cannot get
 * from where it is to anywhere it could lie wholly inside the goal region, so
 * neither can the object. On the refined cells (side 1 / m): a point q of a cell
 * whose centre is D fine cells from the nearest blocked fine cell's centre is at most
 * (D - 1/2 + sqrt 2 / 2) / m from the blocked squares (q is within sqrt 2 / 2 of its
 * centre, and the blocked cell holds the disc of radius 1/2 about its own); so the
 * cells where that bound reaches the radius hold every place the disc's centre can
 * be. The disc moves continuously (every pose along a push or a turn is checked), so
 * its centre stays in their 8-connected component; the goal likewise, with the
 * distance to the squares outside the goal region. */
bool carry_disc_cannot_pass(CarryWork *k, Vec2 centre, double radius)
{
	int32_t m = CARRY_DISC_REFINE, fw = k->w * m, fh = k->h * m;
	/* D reaches the radius when D >= radius m + 1/2 - sqrt 2 / 2. */
	double need = radius * m + 0.5 - sqrt(2.0) / 2;
	int32_t cx = (int32_t)floor(centre.x * m), cy = (int32_t)floor(centre.y * m);
	if (need <= 1 || cx < 0 || cy < 0 || cx >= fw || cy >= fh)
		return false;
	size_t cells = (size_t)fw * (size_t)fh;
	int32_t *d2 = util_alloc(cells, sizeof *d2), *gd2 = util_alloc(cells, sizeof *gd2);
	refined_edt(k, false, d2);
	refined_edt(k, true, gd2);
	uint8_t *seen = util_alloc(cells, 1);
	int32_t *queue = util_alloc(cells, sizeof *queue);
	size_t head = 0, tail = 0;
	bool through = false;
	double need2 = need * need;
	seen[(size_t)cy * fw + cx] = 1;
	queue[tail++] = cy * fw + cx;
	while (head < tail && !through) {
		int32_t i = queue[head++], x = i % fw, y = i / fw;
		through = (double)gd2[i] >= need2;
		for (int32_t dy = -1; dy <= 1; dy++)
			for (int32_t dx = -1; dx <= 1; dx++) {
				int32_t nx = x + dx, ny = y + dy;
				if (nx < 0 || ny < 0 || nx >= fw || ny >= fh)
					continue;
				size_t j = (size_t)ny * fw + nx;
				if (!seen[j] && (double)d2[j] >= need2) {
					seen[j] = 1;
					queue[tail++] = (int32_t)j;
				}
			}
	}
	free(d2);
	free(gd2);
	free(seen);
	free(queue);
	return !through;
}

/* box_count(prefix, w, x, y, s): cells counted in the s x s block from (x, y), by
 * 2-D prefix sums ((w + 1) (h + 1), prefix[y (w + 1) + x] counting [0, x) x [0, y)). */
static int64_t box_count(const int32_t *prefix, int32_t w, int32_t x, int32_t y, int32_t s)
{
	size_t r0 = (size_t)y * (size_t)(w + 1), r1 = (size_t)(y + s) * (size_t)(w + 1);
	return (int64_t)prefix[r1 + x + s] - prefix[r1 + x] - prefix[r0 + x + s] + prefix[r0 + x];
}

/* way_width(k, layer, sx, sy, most): the side of the largest axis-aligned square
 * (at most `most`) that can slide, square by square, from a place overlapping the
 * object's cells at configuration (sx, sy, layer) to a place wholly inside the goal
 * region: the narrowest place on the best way, for a door along the axes its width. */
static int32_t way_width(CarryWork *k, int32_t layer, int32_t sx, int32_t sy, int32_t most)
{
	int32_t w = k->w, h = k->h;
	size_t n = (size_t)(w + 1) * (size_t)(h + 1);
	int32_t *free_sum = util_alloc(n, sizeof *free_sum), *goal_sum = util_alloc(n, sizeof *goal_sum);
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++) {
			size_t i = (size_t)y * w + x, p = (size_t)(y + 1) * (w + 1) + (x + 1);
			bool f = k->grid_cells[i] == GRID_FREE;
			free_sum[p] = free_sum[p - 1] + free_sum[p - (w + 1)] - free_sum[p - (w + 1) - 1] + f;
			goal_sum[p] = goal_sum[p - 1] + goal_sum[p - (w + 1)] - goal_sum[p - (w + 1) - 1] +
				      (f && k->goal->inside->cells[i] == GRID_FREE);
		}
	uint8_t *seen = util_alloc(k->cells, 1);
	int32_t *queue = util_alloc(k->cells, sizeof *queue);
	int32_t side = 0;
	static const int32_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
	for (int32_t s = 1; s <= most && s <= w && s <= h; s++) {
		memset(seen, 0, k->cells);
		size_t head = 0, tail = 0;
		int64_t full = (int64_t)s * s;
		const CSpaceFootprint *fp = &k->object[layer];
		for (int r = 0; r < fp->count; r++)
			for (int32_t cx = sx + fp->run[r].dx0; cx <= sx + fp->run[r].dx1; cx++) {
				int32_t cy = sy + fp->run[r].dy;
				for (int32_t y = cy - s + 1; y <= cy; y++)
					for (int32_t x = cx - s + 1; x <= cx; x++) {
						if (x < 0 || y < 0 || x + s > w || y + s > h)
							continue;
						size_t i = (size_t)y * w + x;
						if (!seen[i] && box_count(free_sum, w, x, y, s) == full) {
							seen[i] = 1;
							queue[tail++] = (int32_t)i;
						}
					}
			}
		bool through = false;
		while (head < tail && !through) {
			int32_t i = queue[head++], x = i % w, y = i / w;
			through = box_count(goal_sum, w, x, y, s) == full;
			for (int m = 0; m < 4; m++) {
				int32_t nx = x + step[m][0], ny = y + step[m][1];
				if (nx < 0 || ny < 0 || nx + s > w || ny + s > h)
					continue;
				size_t j = (size_t)ny * w + nx;
				if (!seen[j] && box_count(free_sum, w, nx, ny, s) == full) {
					seen[j] = 1;
					queue[tail++] = (int32_t)j;
				}
			}
		}
		if (!through)
			break;
		side = s;
	}
	free(free_sum);
	free(goal_sum);
	free(seen);
	free(queue);
	return side;
}

void carry_explain(CarryWork *k, int32_t start_layer, int32_t sx, int32_t sy, const char *name,
		   CarryResult *out)
{
	bool room = false;
	for (size_t c = 0; c < k->cells && !room; c++) {
		if (k->steps[c] != 0)
			continue;
		for (int32_t l = 0; l < k->layers && !room; l++)
			room = carry_body_free(k, l, (int32_t)(c % (size_t)k->w), (int32_t)(c / (size_t)k->w)) &&
			       carry_goal_holds(k, l, (int32_t)(c % (size_t)k->w), (int32_t)(c / (size_t)k->w));
	}
	if (!room) {
		snprintf(out->why, sizeof out->why, "the goal region has no room for %s at any of %d angles", name,
			 k->angles);
		return;
	}
	int32_t most = (int32_t)ceil(out->narrowest) + 1;
	out->way = way_width(k, start_layer, sx, sy, most);
	if (out->way == 0)
		snprintf(out->why, sizeof out->why, "no free way leads from %s to the goal region", name);
	else if (out->narrowest > out->way + 1e-9)
		snprintf(out->why, sizeof out->why,
			 "%s is %.1f wide at its narrowest, the way to the goal region %d.0 at its narrowest",
			 name, out->narrowest, out->way);
	else
		snprintf(out->why, sizeof out->why,
			 "%s is %.1f wide at its narrowest and reaches %.1f from Utak's point: no way at %d angles "
			 "turns it through to the goal region",
			 name, out->narrowest, out->reach, k->angles);
}
