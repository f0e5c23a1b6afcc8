/* fovealook.c - where to stand so that the fovea shows a square (paper 2.2, 3.3).
 * CONTROLLER SIDE. The rule is in fovealook.h. */
#include "utak/mind/fovealook.h"

#include "utak/base/eye.h"

bool fovealook_place(const Screen *s, const int32_t *dist, int32_t x, int32_t y, FovealookCount count, void *ctx,
		     Vec2 *goal)
{
	int32_t best = -1, best_d = 0, best_n = 0;
	/* Utak on (px, py) sees (x, y) at offset (x - px, y - py), in the fovea
	 * when both lie in -EYE_FOVEA_HALF .. EYE_FOVEA_HALF - 1 (eye.h). */
	for (int32_t py = y - (EYE_FOVEA_HALF - 1); py <= y + EYE_FOVEA_HALF; py++)
		for (int32_t px = x - (EYE_FOVEA_HALF - 1); px <= x + EYE_FOVEA_HALF; px++) {
			int32_t i = px - s->x0, j = py - s->y0;
			if (i < 0 || j < 0 || i >= s->w || j >= s->h)
				continue;
			int32_t at = j * s->w + i, d = dist[at];
			if (d < 0)
				continue;
			int32_t n = count ? count(ctx, px, py) : 0;
			if (best < 0 || n > best_n || (n == best_n && (d < best_d || (d == best_d && at < best)))) {
				best = at;
				best_d = d;
				best_n = n;
			}
		}
	if (best < 0)
		return false;
	*goal = vec2(s->x0 + best % s->w + 0.5, s->y0 + best / s->w + 0.5);
	return true;
}
