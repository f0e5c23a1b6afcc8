/* doorlook.c - a look at the squares that can settle doorsure's doubt of a corner,
 * before the doubt (paper 2.3 task (i), 3.4; doorlook.h). CONTROLLER SIDE: the
 * screen and the controller's own record of goals reached. */
#include "utak/mind/doorlook.h"

#include "utak/mind/controller.h"
#include "utak/mind/faint.h"
#include "utak/mind/goals.h"

bool doorlook_choose(Controller *c, const int32_t *dist, const uint8_t *mark, Vec2 *look)
{
	const Screen *s = &c->screen;
	int32_t w = s->w, h = s->h, ui, uj, best = INT32_MAX;
	if (c->door_looks >= DOORLOOK_LOOKS || w <= 0 || h <= 0 || !goals_cell_of(s, c->model.utak, &ui, &uj))
		return false;
	int64_t n = (int64_t)w * h, here = (int64_t)uj * w + ui;
	bool found = false;
	for (int64_t k = 0; k < n; k++) {
		if (dist[k] < 0 || dist[k] >= best || dist[k] > DOORLOOK_REACH || k == here)
			continue;
		int32_t i = (int32_t)(k % w), j = (int32_t)(k / w);
		bool shows = false;
		for (int32_t b = j - FAINT_FOVEA_REACH; b <= j + FAINT_FOVEA_REACH && !shows; b++)
			for (int32_t a = i - FAINT_FOVEA_REACH; a <= i + FAINT_FOVEA_REACH && !shows; a++)
				shows = a >= 0 && b >= 0 && a < w && b < h && mark[(int64_t)b * w + a];
		if (!shows)
			continue;
		Vec2 from = goals_centre(s->x0 + i, s->y0 + j);
		bool visited = false;
		for (int v = 0; v < c->visited_count && !visited; v++)
			visited = goals_distance(from, c->visited[v]) < 0.5; /* looked from there: it did not settle */
		if (visited)
			continue;
		best = dist[k];
		*look = from;
		found = true;
	}
	if (found)
		c->door_looks++;
	return found;
}
