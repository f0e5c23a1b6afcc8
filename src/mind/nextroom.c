/* nextroom.c - "in the next room" by the verdict's own rooms on Utak's model, and
 * what he must establish before claiming a room only that rule shows (paper 2.3
 * task (ii); issue 13: rooms and doors that are rooms and doors; the rules are in
 * nextroom.h). CONTROLLER SIDE: the screen, the world model and its room map.
 *
 * ALGORITHM. nextroom_beyond: carryroom_beyond on the space seen and on the fixed
 * space, ANDed. nextroom_unfelt: a watershed of the space seen, the start's room
 * (nearest cell in a room), the object nodes with a square in either room, the
 * nearest reachable cell beside one (goals_beside). nextroom_jambs: the same
 * watershed with clearances; round each door cell bordering the room, the faces
 * within its doorway not seen in the fovea, the nearest to Utak looked at from the
 * nearest reachable cell (goals_near). nextroom_felt: the space seen less every
 * object not felt, carryroom_beyond on it, the objects within a door cell's
 * doorway, the nearest reachable cell beside one.
 * COMPLEXITY: O(w h log(w h)) a watershed, O(D r^2) the doorways (D door cells, r
 * a doorway's reach). MEMORY: a screen's grid, rooms and clearances (12 bytes a
 * cell), freed before returning. */
#include "utak/mind/nextroom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/objects.h"
#include "utak/mind/roomdoubt.h"

/* nextroom_beyond: nextroom.h. */
void nextroom_beyond(const Controller *c, const Grid *g, const RoomMap *rm, int32_t si, int32_t sj, bool *ok)
{
	const Screen *s = &c->screen;
	int64_t cells = (int64_t)g->w * g->h;
	memset(ok, 0, (size_t)cells * sizeof *ok);
	if (rm->known.w != g->w || rm->known.h != g->h || s->fixed.w != g->w || s->fixed.h != g->h)
		return;
	bool *one = util_alloc((size_t)cells, sizeof *one);
	if (carryroom_beyond(&rm->known, si, sj, ok) > 0 && carryroom_beyond(&s->fixed, si, sj, one) > 0)
		for (int64_t k = 0; k < cells; k++)
			ok[k] = ok[k] && one[k];
	else
		memset(ok, 0, (size_t)cells * sizeof *ok);
	free(one);
}

/* nextroom_cell: nextroom.h. */
int32_t nextroom_cell(const Grid *g, const int32_t *dist, const bool *ok)
{
	int32_t at = -1;
	for (int64_t k = 0; k < (int64_t)g->w * g->h; k++) {
		int32_t i = (int32_t)(k % g->w), j = (int32_t)(k / g->w);
		bool all = dist[k] >= 0 && ok[k];
		for (int32_t dj = -1; dj <= 1 && all; dj++)
			for (int32_t di = -1; di <= 1 && all; di++)
				all = i + di >= 0 && j + dj >= 0 && i + di < g->w && j + dj < g->h &&
				      ok[(j + dj) * g->w + i + di];
		if (all && (at < 0 || dist[k] < dist[at]))
			at = (int32_t)k;
	}
	return at;
}

/* nextroom_unfelt: nextroom.h. */
bool nextroom_unfelt(const Controller *c, const Grid *g, const RoomMap *rm, int32_t si, int32_t sj, int32_t at,
		     const int32_t *dist, Vec2 *goal, int32_t *keep)
{
	const Screen *s = &c->screen;
	const WorldModel *m = &c->model;
	int64_t cells = (int64_t)g->w * g->h;
	int32_t *room = util_alloc((size_t)cells, sizeof *room);
	carryroom_watershed(&rm->known, room);
	int32_t start = -1;
	double near = INFINITY;
	for (int64_t k = 0; k < cells; k++) {
		double d = hypot((double)(k % g->w) - si, (double)(k / g->w) - sj);
		if (room[k] >= 0 && d < near)
			near = d, start = room[k];
	}
	bool *in = util_alloc((size_t)(m->node_count > 0 ? m->node_count : 1), sizeof *in);
	for (int32_t k = 0; k < m->node_count; k++)
		in[k] = false;
	for (int64_t k = 0; k < cells; k++) {
		int32_t l = s->label[k];
		if (l >= 0 && l < m->node_count && room[k] >= 0 && (room[k] == start || room[k] == room[at]))
			in[l] = m->node[l].kind == NODE_OBJECT && !m->node[l].held && !objects_felt(c, l);
	}
	bool left = false, found = false;
	int32_t best_d = INT32_MAX;
	for (int32_t k = 0; k < m->node_count; k++) {
		if (!in[k])
			continue;
		left = true;
		Vec2 p;
		int32_t pi, pj;
		if (goals_beside(c, k, dist, &p) && goals_cell_of(s, p, &pi, &pj) && dist[pj * g->w + pi] < best_d) {
			best_d = dist[pj * g->w + pi];
			*goal = p;
			found = true;
		}
	}
	if (left && !found)
		*keep = -1;
	free(in);
	free(room);
	return found;
}

/* nextroom_jambs: nextroom.h. */
bool nextroom_jambs(const Controller *c, const Grid *g, const RoomMap *rm, int32_t at, const int32_t *dist,
		    Vec2 *goal, int32_t *keep)
{
	const Screen *s = &c->screen;
	const WorldModel *m = &c->model;
	int64_t cells = (int64_t)g->w * g->h;
	int32_t *room = util_alloc((size_t)cells, sizeof *room);
	float *clear = util_alloc((size_t)cells, sizeof *clear);
	carryroom_watershed_clear(&rm->known, room, clear);
	int32_t target = room[at];
	bool left = false, found = false;
	double best = INFINITY;
	for (int64_t q = 0; q < cells && target >= 0; q++) {
		if (rm->known.cells[q] != GRID_FREE || room[q] >= 0)
			continue;
		int32_t x0 = (int32_t)(q % g->w), y0 = (int32_t)(q / g->w);
		bool borders = false;
		for (int32_t y = y0 - 2; y <= y0 + 2 && !borders; y++)
			for (int32_t x = x0 - 2; x <= x0 + 2 && !borders; x++)
				borders = x >= 0 && y >= 0 && x < g->w && y < g->h && room[(int64_t)y * g->w + x] == target;
		if (!borders)
			continue;
		double reach = CARRYROOM_CHAMFER * clear[q] + CARRYROOM_DOORWAY_REACH;
		int32_t r = (int32_t)ceil(reach);
		for (int32_t y = y0 - r; y <= y0 + r; y++)
			for (int32_t x = x0 - r; x <= x0 + r; x++) {
				if (x < 0 || y < 0 || x >= g->w || y >= g->h || hypot(x - x0, y - y0) > reach ||
				    rm->known.cells[(int64_t)y * g->w + x] == GRID_FREE)
					continue;
				bool face = false;
				for (int u = 0; u < 4 && !face; u++) {
					int32_t fx = x + (u == 0) - (u == 1), fy = y + (u == 2) - (u == 3);
					face = fx >= 0 && fy >= 0 && fx < g->w && fy < g->h &&
					       rm->known.cells[(int64_t)fy * g->w + fx] == GRID_FREE;
				}
				if (!face)
					continue;
				Evidence e = worldmodel_evidence(m, s->x0 + x, s->y0 + y);
				if (e.res >= WORLDMODEL_RES_FOVEA)
					continue;
				left = true;
				Vec2 p, sq = goals_centre(s->x0 + x, s->y0 + y);
				double d = goals_distance(sq, m->utak);
				if (d < best && goals_near(c, sq, dist, &p) && goals_distance(p, sq) <= GOALS_LOOK) {
					best = d;
					*goal = p;
					found = true;
				}
			}
	}
	if (left && !found)
		*keep = -1;
	free(clear);
	free(room);
	return found;
}

/* nextroom_felt: nextroom.h. */
RoomDoubt nextroom_felt(const Controller *c, const int32_t *dist, int32_t si, int32_t sj, Vec2 *goal)
{
	const Screen *s = &c->screen;
	const WorldModel *m = &c->model;
	int64_t n = (int64_t)s->w * s->h;
	bool *blob = util_alloc((size_t)(m->node_count > 0 ? m->node_count : 1), sizeof *blob);
	for (int32_t k = 0; k < m->node_count; k++)
		blob[k] = m->node[k].kind == NODE_OBJECT && !m->node[k].held && !objects_felt(c, k);
	Grid g;
	grid_init(&g, s->w, s->h, GRID_BLOCKED);
	bool any = false;
	for (int64_t q = 0; q < n; q++) {
		int32_t l = s->label[q];
		bool b = l >= 0 && l < m->node_count && blob[l];
		any |= b;
		if (l != SCREEN_UNKNOWN && !b && s->fixed.cells[q] == GRID_FREE)
			g.cells[q] = GRID_FREE;
	}
	RoomDoubt verdict = ROOMDOUBT_NONE;
	bool *beyond = util_alloc((size_t)n, sizeof *beyond);
	if (any && carryroom_beyond(&g, si, sj, beyond) > 0) {
		int32_t *room = util_alloc((size_t)n, sizeof *room);
		float *clear = util_alloc((size_t)n, sizeof *clear);
		bool *near_door = util_alloc((size_t)(m->node_count > 0 ? m->node_count : 1), sizeof *near_door);
		for (int32_t k = 0; k < m->node_count; k++)
			near_door[k] = false;
		carryroom_watershed_clear(&g, room, clear);
		for (int64_t q = 0; q < n; q++) {
			if (g.cells[q] != GRID_FREE || room[q] >= 0)
				continue;
			int32_t x0 = (int32_t)(q % s->w), y0 = (int32_t)(q / s->w);
			double reach = CARRYROOM_CHAMFER * clear[q] + CARRYROOM_DOORWAY_REACH;
			int32_t r = (int32_t)ceil(reach);
			for (int32_t y = y0 - r; y <= y0 + r; y++)
				for (int32_t x = x0 - r; x <= x0 + r; x++) {
					int32_t l = screen_label(s, x, y);
					if (l >= 0 && l < m->node_count && blob[l] && hypot(x - x0, y - y0) <= reach)
						near_door[l] = true;
				}
		}
		int32_t best_d = INT32_MAX;
		for (int32_t k = 0; k < m->node_count; k++) {
			if (!near_door[k])
				continue;
			if (verdict == ROOMDOUBT_NONE)
				verdict = ROOMDOUBT_STUCK;
			Vec2 near;
			int32_t ni, nj;
			if (!goals_beside(c, k, dist, &near) || !goals_cell_of(s, near, &ni, &nj) ||
			    dist[nj * s->w + ni] >= best_d)
				continue;
			best_d = dist[nj * s->w + ni];
			*goal = near;
			verdict = ROOMDOUBT_LOOK;
		}
		free(near_door);
		free(clear);
		free(room);
	}
	free(beyond);
	grid_free(&g);
	free(blob);
	return verdict;
}
