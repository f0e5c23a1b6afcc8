/* coarsewall.c - wall seen only in coarse cells that juts out further than any
 * wall's face so seen can (paper 3.4.1, 3.4.2; coarsewall.h says why and what).
 * CONTROLLER SIDE: reads the screen and the world model's evidence only. */
#include "utak/mind/coarsewall.h"

#include <math.h>
#include <stdlib.h>

#include "utak/base/util.h"
#include "utak/mind/controller.h"
#include "utak/mind/goals.h"

/* necks(s, axis, neck): neck[k] = 1 where cell k is occupied and not an object's
 * (SCREEN_VERGE), in a run of such cells along the axis (0: x, 1: y) bounded on
 * both ends by believed floor and at most COARSEWALL_MOST_WIDTH long. A run that
 * ends at the unknown is no neck: the unseen beside it may be more wall. */
static void necks(const Screen *s, int axis, uint8_t *neck)
{
	int32_t lines = axis == 0 ? s->h : s->w, len = axis == 0 ? s->w : s->h;
	for (int32_t l = 0; l < lines; l++) {
		int32_t t = 0;
		while (t < len) {
			int32_t i = axis == 0 ? t : l, j = axis == 0 ? l : t;
			if (screen_label(s, i, j) != SCREEN_VERGE) {
				neck[(int64_t)j * s->w + i] = 0;
				t++;
				continue;
			}
			int32_t end = t; /* the run t..end-1 */
			while (end < len && screen_label(s, axis == 0 ? end : l,
			                                 axis == 0 ? l : end) == SCREEN_VERGE)
				end++;
			bool before = screen_label(s, axis == 0 ? t - 1 : l,
			                           axis == 0 ? l : t - 1) == SCREEN_SPACE;
			bool after = screen_label(s, axis == 0 ? end : l, axis == 0 ? l : end) ==
			             SCREEN_SPACE;
			uint8_t v = before && after && end - t <= COARSEWALL_MOST_WIDTH;
			for (int32_t u = t; u < end; u++)
				neck[axis == 0 ? (int64_t)l * s->w + u : (int64_t)u * s->w + l] = v;
			t = end;
		}
	}
}

/* bump_along(s, neck, i, j, di, dj): cell (i, j) is a neck (of neck[],
 * whose rows run across (di, dj)) in a bump jutting against (di, dj) from a wall:
 * walking against (di, dj) through necks reaches believed floor, walking along it
 * through necks reaches an occupied cell whose row is no neck (the wall),
 * and the necks between, (i, j) with them, number COARSEWALL_LEAST_HEIGHT to
 * COARSEWALL_MOST_HEIGHT. */
static bool bump_along(const Screen *s, const uint8_t *neck, int32_t i, int32_t j, int di, int dj)
{
	int32_t height = 1;
	int32_t a = i - di, b = j - dj;
	for (;; a -= di, b -= dj) {
		bool inside = a >= 0 && b >= 0 && a < s->w && b < s->h;
		if (!inside || !neck[(int64_t)b * s->w + a])
			break;
		if (++height > COARSEWALL_MOST_HEIGHT)
			return false;
	}
	if (screen_label(s, a, b) != SCREEN_SPACE)
		return false; /* no front of floor: the run ends at the unknown or the wall */
	/* A JAMB: across floor no wider than a door (COARSEWALL_DOOR), the run meets
	 * another neck of wall in line with it: a wall with a door in it, seen
	 * coarsely, not something standing off a wall's face (random g158: a wall 1
	 * thick, read 2 wide by cells of 2 x 2, from the verge to a door). */
	for (int t = 0; t < COARSEWALL_DOOR; t++) {
		int32_t fa = a - t * di, fb = b - t * dj;
		int32_t label = screen_label(s, fa, fb);
		if (label == SCREEN_VERGE && fa >= 0 && fb >= 0 && fa < s->w && fb < s->h &&
		    neck[(int64_t)fb * s->w + fa])
			return false;
		if (label != SCREEN_SPACE)
			break;
	}
	for (a = i + di, b = j + dj;; a += di, b += dj) {
		bool inside = a >= 0 && b >= 0 && a < s->w && b < s->h;
		if (!inside || !neck[(int64_t)b * s->w + a])
			break;
		if (++height > COARSEWALL_MOST_HEIGHT)
			return false;
	}
	return screen_label(s, a, b) == SCREEN_VERGE && height >= COARSEWALL_LEAST_HEIGHT;
}

/* coarse(m, s, i, j): cell (i, j) is occupied, not an object's, and read only in
 * cells of 2 x 2 or 4 x 4 squares. */
static bool coarse(const WorldModel *m, const Screen *s, int32_t i, int32_t j)
{
	return screen_label(s, i, j) == SCREEN_VERGE &&
	       worldmodel_evidence(m, s->x0 + i, s->y0 + j).res < WORLDMODEL_RES_FOVEA;
}

void coarsewall_marks(const WorldModel *m, const Screen *s, Vec2 centre, double radius,
                      uint8_t *mark)
{
	int64_t n = (int64_t)s->w * s->h;
	uint8_t *row = util_alloc((size_t)n, 1), *col = util_alloc((size_t)n, 1),
	        *bump = util_alloc((size_t)n, 1);
	/* the direction each bump cell juts from its wall (1 + d of step[d]) */
	static const int8_t step[4][2] = {{0, 1}, {0, -1}, {1, 0}, {-1, 0}};
	necks(s, 0, row);
	necks(s, 1, col);
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			int64_t k = (int64_t)j * s->w + i;
			/* rows along x are necks of bumps jutting along y, and columns
			 * along y of bumps jutting along x */
			for (int d = 0; d < 4 && !bump[k]; d++)
				if ((d < 2 ? row : col)[k] &&
				    bump_along(s, d < 2 ? row : col, i, j, step[d][0], step[d][1]))
					bump[k] = (uint8_t)(1 + d);
		}
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			int64_t k = (int64_t)j * s->w + i;
			if (!bump[k])
				continue;
			if (radius != INFINITY &&
			    !(goals_distance(goals_centre(s->x0 + i, s->y0 + j), centre) < radius))
				continue;
			/* one of a 2 x 2 block of bump cells: where a square 2 wide may lie */
			bool block = false;
			for (int dj = -1; dj <= 0 && !block; dj++)
				for (int di = -1; di <= 0 && !block; di++) {
					int32_t a = i + di, b = j + dj;
					if (a < 0 || b < 0 || a + 1 >= s->w || b + 1 >= s->h)
						continue;
					block = bump[(int64_t)b * s->w + a] &&
					        bump[(int64_t)b * s->w + a + 1] &&
					        bump[(int64_t)(b + 1) * s->w + a] &&
					        bump[(int64_t)(b + 1) * s->w + a + 1];
				}
			if (!block)
				continue;
			/* Where the eye may have missed the floor that parts an object
			 * from the wall: the bump's own cells read coarsely, and the
			 * wall's first COARSEWALL_FACE_SLACK cells behind it read so (a
			 * face seen coarsely stands out that far: the gap may be there). */
			if (coarse(m, s, i, j))
				mark[k] = 1;
			int di = step[bump[k] - 1][0], dj = step[bump[k] - 1][1];
			int32_t a = i + di, b = j + dj;
			while (a >= 0 && b >= 0 && a < s->w && b < s->h &&
			       bump[(int64_t)b * s->w + a])
				a += di, b += dj;
			for (int t = 0; t < COARSEWALL_FACE_SLACK && coarse(m, s, a, b);
			     t++, a += di, b += dj)
				mark[(int64_t)b * s->w + a] = 1;
		}
	free(row);
	free(col);
	free(bump);
}

bool coarsewall_within(const Controller *c, Vec2 centre, double radius)
{
	const Screen *s = &c->screen;
	int64_t n = (int64_t)s->w * s->h;
	uint8_t *mark = util_alloc((size_t)n, 1);
	for (int64_t k = 0; k < n; k++)
		mark[k] = 0;
	coarsewall_marks(&c->model, s, centre, radius, mark);
	bool any = false;
	for (int64_t k = 0; k < n && !any; k++)
		any = mark[k];
	free(mark);
	return any;
}
