/* doorsure.c - a corner claimed only where every reading of the model the eye leaves
 * open puts it in the starting room (paper 2.3 task (i); doorsure.h). CONTROLLER
 * SIDE: the screen and the world model's evidence only. */
#include "utak/mind/doorsure.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/controller.h"
#include "utak/mind/faint.h"
#include "utak/mind/goals.h"
#include "utak/mind/thinwall.h"

int32_t doorsure_start_room(const Grid *g, const int32_t *room, int32_t si, int32_t sj)
{
	int64_t n = (int64_t)g->w * g->h;
	if (si >= 0 && sj >= 0 && si < g->w && sj < g->h && room[(int64_t)sj * g->w + si] >= 0)
		return room[(int64_t)sj * g->w + si];
	double best = INFINITY;
	int32_t r = -1;
	for (int64_t i = 0; i < n; i++) {
		if (room[i] < 0)
			continue;
		double dx = (double)(i % g->w - si), dy = (double)(i / g->w - sj), d = dx * dx + dy * dy;
		if (d < best) {
			best = d;
			r = room[i];
		}
	}
	return r;
}

/* ---- the corner --------------------------------------------------------------- */

/* coarse(c, k): screen cell k was seen, but never in the fovea. */
static bool coarse(const Controller *c, int64_t k)
{
	const Screen *s = &c->screen;
	Evidence e = worldmodel_evidence(&c->model, s->x0 + (int32_t)(k % s->w), s->y0 + (int32_t)(k / s->w));
	return e.res > WORLDMODEL_UNSEEN && e.res < WORLDMODEL_RES_FOVEA;
}

/* mark_unsettled(c, g, room, start, mark): marks (1) each cell seen only coarsely,
 * faint floor or occupied, within one (8-neighbour) of a door cell of this reading
 * (free on g, no region), or within one of a cell of the start's region and of a
 * cell of another: the squares whose closer look can change this reading. */
static void mark_unsettled(const Controller *c, const Grid *g, const int32_t *room, int32_t start, uint8_t *mark)
{
	const Screen *s = &c->screen;
	int32_t w = s->w, h = s->h;
	for (int32_t j = 0; j < h; j++)
		for (int32_t i = 0; i < w; i++) {
			int64_t k = (int64_t)j * w + i;
			if (mark[k] || !coarse(c, k))
				continue;
			if (s->label[k] == SCREEN_SPACE && !faint_cell(&c->model, s, k))
				continue; /* floor a zero cell read: settled */
			bool door = false, own = false, other = false;
			for (int32_t b = j - 1; b <= j + 1; b++)
				for (int32_t a = i - 1; a <= i + 1; a++) {
					if (a < 0 || b < 0 || a >= w || b >= h)
						continue;
					int64_t q = (int64_t)b * w + a;
					if (g->cells[q] != GRID_FREE)
						continue;
					if (room[q] < 0)
						door = true;
					else if (room[q] == start)
						own = true;
					else
						other = true;
				}
			if (door || (own && other))
				mark[k] = 1;
		}
}

/* across(g, i, j): the width across of free cell (i, j) of g: the shorter run of
 * free cells through it along x and along y (the judge's, doc/verdicts.md). */
static int32_t across(const Grid *g, int32_t i, int32_t j)
{
	int32_t a = i, b = i, c = j, d = j;
	while (a > 0 && g->cells[(int64_t)j * g->w + a - 1] == GRID_FREE)
		a--;
	while (b < g->w - 1 && g->cells[(int64_t)j * g->w + b + 1] == GRID_FREE)
		b++;
	while (c > 0 && g->cells[(int64_t)(c - 1) * g->w + i] == GRID_FREE)
		c--;
	while (d < g->h - 1 && g->cells[(int64_t)(d + 1) * g->w + i] == GRID_FREE)
		d++;
	return b - a + 1 < d - c + 1 ? b - a + 1 : d - c + 1;
}

/* in_doorway(g, room, p): free cell p of g lies in the doorway of a door cell of
 * this reading (room -1), the judge's rule restated (doc/verdicts.md: within the
 * door cell's clearance and DOORSURE_DOORWAY_REACH of it, its own clearance at most
 * the door's and DOORSURE_DOORWAY_SLACK, its width across at most the door cell's
 * and DOORSURE_DOORWAY_WIDEN), each with a square of margin: the model's door line
 * may lie a square or two along the passage from the judge's. */
static bool in_doorway(const Grid *g, const int32_t *room, int64_t p)
{
	int32_t w = g->w, h = g->h, pi = (int32_t)(p % w), pj = (int32_t)(p / w);
	int64_t n = (int64_t)w * h;
	float *cl = util_alloc((size_t)n, sizeof *cl);
	int32_t *other = util_alloc((size_t)n, sizeof *other);
	carryroom_watershed_clear(g, other, cl); /* the clearance: the same on every slack */
	free(other);
	bool in = false;
	int32_t wide = across(g, pi, pj);
	for (int64_t d = 0; d < n && !in; d++) {
		if (g->cells[d] != GRID_FREE || room[d] >= 0 || d == p)
			continue;
		int32_t di = (int32_t)(d % w), dj = (int32_t)(d / w);
		double reach = cl[d] + DOORSURE_DOORWAY_REACH;
		in = hypot(di - pi, dj - pj) <= reach && cl[p] <= cl[d] + DOORSURE_DOORWAY_SLACK &&
		     wide <= across(g, di, dj) + DOORSURE_DOORWAY_WIDEN;
	}
	free(cl);
	return in;
}

DoorSure doorsure_corner(const Controller *c, Vec2 at)
{
	return doorsure_corner_marks(c, at, NULL);
}

DoorSure doorsure_corner_marks(const Controller *c, Vec2 at, uint8_t *mark)
{
	const Screen *s = &c->screen;
	int32_t w = s->w, h = s->h, si, sj, pi, pj;
	if (w <= 0 || h <= 0 || !goals_cell_of(s, c->start, &si, &sj) || !goals_cell_of(s, at, &pi, &pj))
		return DOORSURE_DOUBT;
	int64_t n = (int64_t)w * h, p = (int64_t)pj * w + pi;
	Grid g;
	grid_init(&g, w, h, GRID_BLOCKED);
	int32_t *room = util_alloc((size_t)n, sizeof *room);
	uint8_t *jamb = util_alloc((size_t)n, 1);
	memset(jamb, 0, (size_t)n);
	/* Objects that may be a stretch of a thin wall, joined to the verge by faint
	 * floor (thinwall.h): wall on the readings that take faint floor for wall,
	 * and the faint floor joining them a look settles. */
	uint8_t *thin = util_alloc((size_t)n, 1), *thin_look = util_alloc((size_t)n, 1);
	uint8_t *thin_unseen = util_alloc((size_t)n, 1);
	memset(thin, 0, (size_t)n);
	memset(thin_look, 0, (size_t)n);
	memset(thin_unseen, 0, (size_t)n);
	thinwall_marks(&c->model, s, false, thin, thin_look);
	thinwall_marks(&c->model, s, true, thin_unseen, thin_look);
	bool parted = false;
	int32_t px = s->x0 + pi, py = s->y0 + pj;
	int64_t here = goals_corner_score(c->task.corner, px, py);
	/* With marks wanted every reading is asked (each doubting one marks what
	 * would settle it); the verdict is the same (any reading doubting). */
	for (int reading = 0; reading < 7 && (!parted || mark); reading++) {
		bool faint_wall = (reading & 1) || reading == 6, unseen_wall = reading >= 5;
		double slack = reading == 2 || reading == 3 || reading == 6 ? DOORSURE_SLACK : 0;
		memcpy(g.cells, s->fixed.cells, (size_t)n);
		if (faint_wall)
			for (int64_t k = 0; k < n; k++)
				if ((faint_cell(&c->model, s, k) || (unseen_wall ? thin_unseen[k] : thin[k]) ||
				     (unseen_wall && s->label[k] == SCREEN_UNKNOWN)) &&
				    k != p)
					g.cells[k] = GRID_BLOCKED; /* may be a thin wall seen from afar */
		if (reading == 4) {
			/* The door may be no door: its jambs seen only coarsely may lie
			 * up to a coarse cell back (a 4 x 4 cell's occupied share may be
			 * any of its squares), opening it. */
			carryroom_watershed_slack(&g, 0, room);
			for (int32_t j = 0; j < h; j++)
				for (int32_t i = 0; i < w; i++) {
					int64_t k = (int64_t)j * w + i;
					if (g.cells[k] == GRID_FREE || !coarse(c, k))
						continue;
					bool near_door = false;
					for (int32_t b = j - DOORSURE_JAMB; b <= j + DOORSURE_JAMB && !near_door; b++)
						for (int32_t a = i - DOORSURE_JAMB; a <= i + DOORSURE_JAMB && !near_door; a++) {
							int64_t q = (int64_t)b * w + a;
							near_door = a >= 0 && b >= 0 && a < w && b < h &&
								    s->fixed.cells[q] == GRID_FREE && room[q] < 0;
						}
					if (near_door)
						jamb[k] = 1;
				}
			for (int64_t k = 0; k < n; k++)
				if (jamb[k])
					g.cells[k] = GRID_FREE;
		}
		carryroom_watershed_slack(&g, slack, room);
		int32_t start = doorsure_start_room(&g, room, si, sj);
		bool apart = start < 0 || room[p] != start || in_doorway(&g, room, p);
		/* A better corner in the start's room on this reading: a free cell of
		 * it seen (floor or an object) more than the verdict's slack beyond his
		 * square. (Space never seen that may hold one is roomdoubt.h's.) */
		for (int64_t k = 0; k < n && start >= 0; k++)
			apart |= room[k] == start && s->label[k] != SCREEN_UNKNOWN &&
				 goals_corner_score(c->task.corner, s->x0 + (int32_t)(k % w), s->y0 + (int32_t)(k / w)) - here >
				     CONTROLLER_CORNER_SLACK;
		if (!apart)
			continue;
		parted = true;
		if (mark) {
			mark_unsettled(c, &g, room, start, mark);
			if (reading == 4)
				for (int64_t k = 0; k < n; k++)
					if (jamb[k])
						mark[k] = 1; /* the jambs that may lie back: a look settles them */
			if (faint_wall)
				for (int64_t k = 0; k < n; k++)
					if (thin_look[k])
						mark[k] = 1; /* the faint floor that may join a stretch of wall to the verge */
		}
	}
	free(thin_unseen);
	free(thin_look);
	free(thin);
	free(jamb);
	free(room);
	grid_free(&g);
	return parted ? DOORSURE_DOUBT : DOORSURE_SURE;
}
