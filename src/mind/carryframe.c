/* carryframe.c - "past the door line" in every frame the TABLE may have: the
 * verdict's watershed restated on Utak's model four times, turned by each quarter
 * turn, ANDed (paper 2.3, tasks (vi), (vii), (ix); carryframe.h says why).
 * CONTROLLER SIDE: grids of the screen only.
 *
 * ALGORITHM. For each quarter turn q: the grid turned (cell (x, y) of w x h to
 * (y, w-1-x) of h x w, q times), carryroom_beyond on it from the start cell turned
 * the same way, less the cells along a face round each door cell of the turned
 * grid's watershed (along), each cell's answer read back through the same map; a
 * cell is beyond only if it is in all four.
 * COMPLEXITY: 4 carryroom_beyond and 4 watersheds, O(w h log(w h)) each, and
 * O(D r^2) round the D door cells (r their reach). MEMORY: 10 bytes a cell. */
#include "utak/mind/carryframe.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/carryroom.h"

/* turned(x, y, w, h, q, u, v): cell (x, y) of a w x h grid after q clockwise
 * quarter turns (the grid then h x w for odd q). */
static void turned(int32_t x, int32_t y, int32_t w, int32_t h, int q, int32_t *u, int32_t *v)
{
	switch (q) {
	case 0: *u = x, *v = y; break;
	case 1: *u = y, *v = w - 1 - x; break;
	case 2: *u = w - 1 - x, *v = h - 1 - y; break;
	default: *u = h - 1 - y, *v = x; break;
	}
}

/* along(t, ans): ans (per cell of t) less every cell a door square of the judge's
 * may put in its doorway where the door's squares fall elsewhere than on t: round
 * each door cell d of t's watershed (clearance c), the cells within
 * CARRYFRAME_ALONG c + CARRYFRAME_ALONG_MORE of it whose clearance is at most c +
 * CARRYFRAME_ALONG_SLACK. WHY: at a door whose jamb runs on as a straight face
 * (a door at a wall's end, against the verge), the cells along that face beyond
 * the door's mouth share their clearance, and the judge's order of squares, or a
 * face read a square off, moves the door square along it by up to the door's
 * width; the doorway round it (its clearance and a square more, only cells no
 * clearer than it, judgerooms.h) then reaches cells carryroom_beyond counts past
 * the line. */
static void along(const Grid *t, bool *ans)
{
	int32_t w = t->w, h = t->h;
	int64_t n = (int64_t)w * h;
	int32_t *room = util_alloc((size_t)(n > 0 ? n : 1), sizeof *room);
	float *cl = util_alloc((size_t)(n > 0 ? n : 1), sizeof *cl);
	carryroom_watershed_clear(t, room, cl);
	for (int64_t d = 0; d < n; d++) {
		if (t->cells[d] != GRID_FREE || room[d] >= 0)
			continue;
		double c = cl[d], reach = CARRYFRAME_ALONG * c + CARRYFRAME_ALONG_MORE;
		int32_t dx = (int32_t)(d % w), dy = (int32_t)(d / w), r = (int32_t)ceil(reach);
		for (int32_t y = dy - r; y <= dy + r; y++)
			for (int32_t x = dx - r; x <= dx + r; x++)
				if (x >= 0 && y >= 0 && x < w && y < h && hypot(x - dx, y - dy) <= reach &&
				    cl[(int64_t)y * w + x] <= c + CARRYFRAME_ALONG_SLACK)
					ans[(int64_t)y * w + x] = false;
	}
	free(room);
	free(cl);
}

int64_t carryframe_beyond(const Grid *g, int32_t si, int32_t sj, bool *out)
{
	int64_t cells = (int64_t)g->w * g->h, count = 0;
	for (int64_t k = 0; k < cells; k++)
		out[k] = true;
	for (int q = 0; q < 4; q++) {
		int32_t tw = q % 2 ? g->h : g->w, th = q % 2 ? g->w : g->h, u, v;
		Grid t;
		grid_init(&t, tw, th, GRID_BLOCKED);
		for (int32_t y = 0; y < g->h; y++)
			for (int32_t x = 0; x < g->w; x++) {
				turned(x, y, g->w, g->h, q, &u, &v);
				t.cells[v * tw + u] = g->cells[y * g->w + x];
			}
		int32_t su, sv;
		turned(si, sj, g->w, g->h, q, &su, &sv);
		bool *ans = util_alloc((size_t)(cells > 0 ? cells : 1), sizeof *ans);
		bool any = carryroom_beyond(&t, su, sv, ans) > 0;
		if (any)
			along(&t, ans);
		for (int32_t y = 0; y < g->h; y++)
			for (int32_t x = 0; x < g->w; x++) {
				turned(x, y, g->w, g->h, q, &u, &v);
				out[y * g->w + x] = out[y * g->w + x] && any && ans[v * tw + u];
			}
		free(ans);
		grid_free(&t);
	}
	for (int64_t k = 0; k < cells; k++)
		count += out[k];
	return count;
}
