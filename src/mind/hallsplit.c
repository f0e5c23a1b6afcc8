/* hallsplit.c - whether a blob the eye has seen only coarsely may be a wall that parts
 * the hall Utak started in, before he claims its corner (paper 3.4.2; issue 13 items
 * 3 and 6; the rule is in hallsplit.h). CONTROLLER SIDE: the world model, its screen
 * and what touch has felt.
 *
 * ALGORITHM. For each object node not held, not felt, and with no square seen in the
 * fovea: the room map of the screen's fixed space seen, that node taken for wall
 * (goals_roommap_find), merged by the verdict's door rule keeping every narrowing
 * that may yet be a door (carryroom_merge_maybe); the node parts the start from p
 * when their merged rooms differ. The first such node, by index, is reported.
 * MEMORY: one room map of the screen at a time, freed before the next.
 * COMPLEXITY: O(w h) for each object node seen only coarsely (a room map each). */
#include "utak/mind/hallsplit.h"

#include <stdlib.h>

#include "utak/base/util.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/goals.h"
#include "utak/mind/objects.h"

bool hallsplit_parts(const Controller *c, Vec2 p, Vec2 *at)
{
	return hallsplit_parts_all(c, &p, 1, at);
}

/* hs_parted(cr, rm, s, a, p, n): whether room a (the start's, >= 0) is none of the
 * merged rooms of the n points p; a point on no room is not parted. */
static bool hs_parted(const CarryRooms *cr, const RoomMap *rm, const Screen *s, int32_t a, const Vec2 *p,
		      int32_t n)
{
	for (int32_t i = 0; i < n; i++) {
		int32_t pi, pj;
		if (!goals_cell_of(s, p[i], &pi, &pj))
			return false;
		int32_t b = carryroom_at(cr, rm, pi, pj);
		if (b < 0 || b == a)
			return false;
	}
	return n > 0;
}

bool hallsplit_parts_all(const Controller *c, const Vec2 *p, int32_t np, Vec2 *at)
{
	const Screen *s = &c->screen;
	const WorldModel *m = &c->model;
	int32_t si, sj;
	if (np <= 0 || !goals_cell_of(s, c->start, &si, &sj))
		return false;
	int64_t n = (int64_t)s->w * s->h;
	for (int32_t k = 0; k < m->node_count; k++) {
		if (m->node[k].kind != NODE_OBJECT || m->node[k].held || objects_felt(c, k))
			continue;
		/* The room map with k taken for wall, if no square of k has been seen in
		 * the fovea; `first` is k's first square, for the doubt's words. */
		RoomMap rm;
		grid_init(&rm.known, s->w, s->h, GRID_BLOCKED);
		int64_t first = -1;
		bool fine = false;
		for (int64_t q = 0; q < n && !fine; q++) {
			int32_t x = s->x0 + (int32_t)(q % s->w), y = s->y0 + (int32_t)(q / s->w);
			if (s->label[q] == k) {
				first = first < 0 ? q : first;
				fine = worldmodel_evidence(m, x, y).res >= WORLDMODEL_RES_FOVEA;
			} else if (s->label[q] != SCREEN_UNKNOWN && s->fixed.cells[q] == GRID_FREE)
				rm.known.cells[q] = GRID_FREE;
		}
		if (first < 0 || fine) {
			grid_free(&rm.known);
			continue;
		}
		goals_roommap_find(&rm);
		CarryRooms cr;
		carryroom_merge_maybe(&rm, s, &cr);
		int32_t a = carryroom_at(&cr, &rm, si, sj);
		bool parted = a >= 0 && hs_parted(&cr, &rm, s, a, p, np);
		carryroom_free(&cr);
		goals_roommap_free(&rm);
		if (parted) {
			*at = goals_centre(s->x0 + (int32_t)(first % s->w), s->y0 + (int32_t)(first / s->w));
			return true;
		}
	}
	return false;
}
