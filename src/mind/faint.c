/* faint.c - floor the coarse cells read, but not as empty (paper 3.4.2; faint.h).
 * CONTROLLER SIDE. */
#include "utak/mind/faint.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/coarsewall.h"
#include "utak/mind/controller.h"
#include "utak/mind/goals.h"

/* faint_cell: faint.h. The estimate is the mean of the readings (worldmodel.c
 * wm_update), so one reading above zero keeps it above zero until a finer one
 * replaces it. */
bool faint_cell(const WorldModel *m, const Screen *s, int64_t k)
{
	if (s->label[k] != SCREEN_SPACE)
		return false;
	Evidence e = worldmodel_evidence(m, s->x0 + (int32_t)(k % s->w), s->y0 + (int32_t)(k / s->w));
	return e.res > WORLDMODEL_UNSEEN && e.res < WORLDMODEL_RES_FOVEA && e.p > 0;
}

/* occupied_near(s, i, j, res): some cell the screen holds occupied lies within
 * the reach of a coarse cell of resolution res over cell (i, j) (3 squares for
 * cells of 4, 1 for cells of 2, Chebyshev): the level that left (i, j) faint may
 * be that square's share. WHY: the model's estimate is the mean of its readings
 * (worldmodel.c), and one taken before a finer look settled the occupied square
 * next to it is not taken back: a row of floor 3 squares off the verge, read by
 * cells of 4 that held 4 verge squares each, stayed faint after cells of 2 had
 * shown the squares between floor and the verge (perturbed hidden-p4,
 * going round the square: a doubt no look could lift, the square being far). */
static bool occupied_near(const Screen *s, int32_t i, int32_t j, int res)
{
	int32_t r = res == WORLDMODEL_RES_PERIPHERAL ? 3 : 1;
	for (int32_t b = j - r; b <= j + r; b++)
		for (int32_t a = i - r; a <= i + r; a++) {
			int32_t label = screen_label(s, a, b);
			if (label != SCREEN_SPACE && label != SCREEN_UNKNOWN)
				return true;
		}
	return false;
}

/* faint_marks(m, s, centre, radius) (faint.h): faint cells under radius from
 * centre whose 8-connected set touches nothing occupied, and none within a
 * coarse cell's reach of something occupied (occupied_near). WHY the set: a
 * coarse cell across the edge of a wall or an object seen only coarsely holds a share of its squares, and leaves
 * faint floor along every such edge (a strip along the verge, 1 to 3 squares
 * deep); sent to look at each, Utak spent 20 to 40 more cycles on worlds/ tasks
 * and still found more as he walked. An object apart from any other shows as a
 * set of its own. LIMIT: a square of the judge's sizes hidden faint within about
 * 4 squares of a wall or another object joins their set and is not asked
 * about here (objects.h, THE NEARER UNSEEN; README, Reliability). */
uint8_t *faint_marks(const WorldModel *m, const Screen *s, Vec2 centre, double radius)
{
	int64_t n = (int64_t)s->w * s->h;
	uint8_t *mark = util_alloc((size_t)n, 1);
	int64_t *stack = util_alloc((size_t)n, sizeof *stack);
	for (int64_t k = 0; k < n; k++)
		mark[k] = faint_cell(m, s, k) ? 2 : 0; /* 2: faint, not yet labelled */
	for (int64_t k0 = 0; k0 < n; k0++) {
		if (mark[k0] != 2)
			continue;
		/* One 8-connected set: first collected (marked 3), then kept (1) or
		 * dropped (0) whole. */
		int64_t top = 0, count = 0;
		bool touches = false;
		stack[top++] = k0;
		mark[k0] = 3;
		while (top > count) {
			int64_t k = stack[count++];
			int32_t i = (int32_t)(k % s->w), j = (int32_t)(k / s->w);
			for (int dy = -1; dy <= 1; dy++)
				for (int dx = -1; dx <= 1; dx++) {
					int32_t a = i + dx, b = j + dy;
					int32_t label = screen_label(s, a, b);
					if (label != SCREEN_SPACE && label != SCREEN_UNKNOWN) {
						/* outside the screen is SCREEN_VERGE too: the screen
						 * holds every square seen and a margin, so a set at its
						 * edge is at the TABLE's */
						touches = true;
						continue;
					}
					int64_t q = (int64_t)b * s->w + a;
					if (label == SCREEN_SPACE && mark[q] == 2) {
						mark[q] = 3;
						stack[top++] = q;
					}
				}
		}
		for (int64_t t = 0; t < count; t++) {
			int64_t k = stack[t];
			int32_t i = (int32_t)(k % s->w), j = (int32_t)(k / s->w);
			Vec2 at = goals_centre(s->x0 + i, s->y0 + j);
			mark[k] = !touches && (radius == INFINITY || goals_distance(at, centre) < radius) &&
				  !occupied_near(s, i, j, worldmodel_evidence(m, s->x0 + i, s->y0 + j).res);
		}
	}
	free(stack);
	return mark;
}

bool faint_within(const Controller *c, Vec2 centre, double radius)
{
	const Screen *s = &c->screen;
	int64_t n = (int64_t)s->w * s->h;
	uint8_t *mark = faint_marks(&c->model, s, centre, radius);
	bool any = false;
	for (int64_t k = 0; k < n && !any; k++)
		any = mark[k];
	free(mark);
	return any;
}

/* dilate(in, out, w, h, r, dx, dy): out[k] = some in within r cells of k along
 * (dx, dy), one axis of a square's dilation (van Herk's running window is not
 * needed here: r is 3). */
static void dilate(const uint8_t *in, uint8_t *out, int32_t w, int32_t h, int32_t r, int dx, int dy)
{
	for (int32_t j = 0; j < h; j++)
		for (int32_t i = 0; i < w; i++) {
			uint8_t v = 0;
			for (int32_t t = -r; t <= r && !v; t++) {
				int32_t a = i + t * dx, b = j + t * dy;
				v = a >= 0 && b >= 0 && a < w && b < h && in[(int64_t)b * w + a];
			}
			out[(int64_t)j * w + i] = v;
		}
}

bool faint_look(const Controller *c, const int32_t *dist, Vec2 centre, double radius, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int64_t n = (int64_t)s->w * s->h;
	uint8_t *mark = faint_marks(&c->model, s, centre, radius), *row = util_alloc((size_t)n, 1);
	/* and wall seen coarsely that juts out as no face so seen does, nearer than a
	 * claim: an object may be merged with it (coarsewall.h); the same look settles
	 * it. Not asked anywhere (radius INFINITY: no object of the shape found): a
	 * square merged with a wall makes no claim false there, and every bump of the
	 * TABLE would be visited (perturbed slant-p3, its square lost after a push). */
	if (radius != INFINITY)
		coarsewall_marks(&c->model, s, centre, radius, mark);
	bool any = false;
	for (int64_t k = 0; k < n && !any; k++)
		any = mark[k];
	int64_t best = -1;
	if (any) {
		/* The cells from which the fovea covers a marked one: the marks grown by
		 * FAINT_FOVEA_REACH each way (a square's dilation, one axis at a time). */
		dilate(mark, row, s->w, s->h, FAINT_FOVEA_REACH, 1, 0);
		dilate(row, mark, s->w, s->h, FAINT_FOVEA_REACH, 0, 1);
		int32_t best_d = INT32_MAX;
		for (int64_t k = 0; k < n; k++) {
			/* dist 0 is where he stands: a faint square the fovea covers from
			 * there would not be faint, so a mark there is one the model could
			 * not record (beyond its window) and going nowhere would not help. */
			if (!mark[k] || dist[k] <= 0 || dist[k] >= best_d)
				continue;
			Vec2 here = goals_centre(s->x0 + (int32_t)(k % s->w), s->y0 + (int32_t)(k / s->w));
			bool visited = false;
			for (int v = 0; v < c->visited_count && !visited; v++)
				visited = goals_distance(here, c->visited[v]) < 1.0;
			if (!visited) {
				best = k;
				best_d = dist[k];
			}
		}
	}
	free(mark);
	free(row);
	if (best < 0)
		return false;
	*goal = goals_centre(s->x0 + (int32_t)(best % s->w), s->y0 + (int32_t)(best / s->w));
	return true;
}
