/* roomlean.c - a door a claim rests on whose jamb touch has felt to be an object
 * (paper 3.4.2; the rule is in roomlean.h). CONTROLLER SIDE: the world model's
 * evidence, the screen, touch (objects_feel's list of squares felt an object) and
 * Utak's trail.
 *
 * ALGORITHM. Two room maps of the screen, each merged by the verdict's rule where
 * both sides are seen whole (carryroom_merge_seen): the fixed space seen, and the
 * optimistic one (with the coarse squares that may be floor). For each door of the
 * start's merged room whose other side holds what the claim rests on, the run
 * across it is walked from the door's cell over fixed space seen to its two
 * jambs, and each is looked up in Utak's trail and in touch's list.
 * MEMORY: a room map of the screen at a time and a flag a cell, freed before
 * returning. COMPLEXITY: O(w h) each map, O(w h) for each door of the start's room,
 * O(T + F) for each jamb (T trail points, F squares felt). */
#include "utak/mind/roomlean.h"

#include <stdlib.h>

#include "utak/base/util.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/goals.h"
#include "utak/mind/objects.h"

/* seen_free(s, i, j): screen cell (i, j) is fixed space seen (objects space). */
static bool seen_free(const Screen *s, int32_t i, int32_t j)
{
	return i >= 0 && j >= 0 && i < s->w && j < s->h && s->label[j * s->w + i] != SCREEN_UNKNOWN &&
	       s->fixed.cells[j * s->w + i] == GRID_FREE;
}

/* rests(c, rm, cr, a, q, got, target): whether door q's side other than merged room
 * a (that side merged by the verdict's rule: not beyond its own doors) holds the
 * screen cell `target` when it is >= 0, else floor seen that scores above got +
 * CONTROLLER_CORNER_SLACK. */
static bool rests(const Controller *c, const RoomMap *rm, const CarryRooms *cr, int32_t a, int32_t q, int64_t got,
		  int64_t target)
{
	const Screen *s = &c->screen;
	const RoomsDoor *d = &rm->rooms.doors[q];
	int32_t ra = cr->merged[d->room_a], other = ra == a ? cr->merged[d->room_b] : ra;
	if (target >= 0)
		return carryroom_at(cr, rm, (int32_t)(target % s->w), (int32_t)(target / s->w)) == other;
	for (int64_t k = 0; k < (int64_t)s->w * s->h; k++) {
		int32_t i = (int32_t)(k % s->w), j = (int32_t)(k / s->w);
		if (s->label[k] == SCREEN_SPACE && carryroom_at(cr, rm, i, j) == other &&
		    goals_corner_score(c->task.corner, s->x0 + i, s->y0 + j) > got + CONTROLLER_CORNER_SLACK)
			return true;
	}
	return false;
}

/* jamb_state(c, i, j): the jamb at screen cell (i, j): JAMB_NONE when it is no verge
 * square on the screen; JAMB_UNTOUCHED when Utak has not stood beside it (no trail
 * point within 1.5 of its centre: touch reads his 8 neighbours); JAMB_OBJECT when
 * touch felt an object's letter on it; else JAMB_WALL. */
enum { JAMB_NONE, JAMB_UNTOUCHED, JAMB_WALL, JAMB_OBJECT };
static int jamb_state(const Controller *c, int32_t i, int32_t j)
{
	const Screen *s = &c->screen;
	if (i < 0 || j < 0 || i >= s->w || j >= s->h || s->label[j * s->w + i] != SCREEN_VERGE)
		return JAMB_NONE;
	int32_t x = s->x0 + i, y = s->y0 + j;
	Vec2 jc = goals_centre(x, y);
	bool touched = false;
	for (int v = 0; v < c->trail.count && !touched; v++)
		touched = goals_distance(jc, c->trail.pts[v]) <= 1.5;
	if (!touched)
		return JAMB_UNTOUCHED;
	return objects_square_listed(c->felt_x, c->felt_y, c->felt_squares, x, y) ? JAMB_OBJECT : JAMB_WALL;
}

/* lean(c, got, target, dist, at, look): roomlean_corner (target < 0) and
 * roomlean_next (target Utak's screen cell): ROOMLEAN_DOUBT with *at the jamb, or,
 * with dist, ROOMLEAN_LOOK with *look the free cell beside an untouched jamb within
 * ROOMLEAN_REACH steps of Utak, not gone to before (the nearest by steps). */
static RoomLean lean(const Controller *c, int64_t got, int64_t target, const int32_t *dist, Vec2 *at, Vec2 *look)
{
	const Screen *s = &c->screen;
	int32_t si, sj;
	if (!goals_cell_of(s, c->start, &si, &sj))
		return ROOMLEAN_NONE;
	int64_t n = (int64_t)s->w * s->h;
	bool found = false;
	int32_t near = INT32_MAX;
	/* Both readings: the space seen (goals_roommap_build), and the optimistic
	 * one, where a coarse cell's misread squares may join rooms the first parts
	 * and so leave a narrowing of it the only door. */
	for (int map = 0; map < 2 && !found; map++) {
		RoomMap rm;
		if (map == 0) {
			goals_roommap_build(&rm, s);
		} else {
			grid_init(&rm.known, s->w, s->h, GRID_BLOCKED);
			for (int64_t k = 0; k < n; k++) {
				int32_t i = (int32_t)(k % s->w), j = (int32_t)(k / s->w);
				if (s->label[k] != SCREEN_UNKNOWN &&
				    (s->fixed.cells[k] == GRID_FREE || roomdoubt_maybe_floor(&c->model, s->x0 + i, s->y0 + j)))
					rm.known.cells[k] = GRID_FREE;
			}
			goals_roommap_find(&rm);
		}
		CarryRooms cr;
		carryroom_merge_seen(&rm, s, &cr);
		int32_t a = carryroom_at(&cr, &rm, si, sj);
		for (int32_t q = 0; a >= 0 && q < rm.rooms.door_count && !found; q++) {
			const RoomsDoor *d = &rm.rooms.doors[q];
			if (!cr.door[q] || (cr.merged[d->room_a] != a && cr.merged[d->room_b] != a) ||
			    !seen_free(s, d->x, d->y) || !rests(c, &rm, &cr, a, q, got, target))
				continue;
			int32_t ux = (d->bx > d->ax) - (d->bx < d->ax), uy = (d->by > d->ay) - (d->by < d->ay);
			if (!ux && !uy) {
				/* A run of one cell: across it is the way both of whose
				 * neighbours are blocked. */
				bool across_x = !grid_free_at(&rm.known, d->ax - 1, d->ay) && !grid_free_at(&rm.known, d->ax + 1, d->ay);
				bool across_y = !grid_free_at(&rm.known, d->ax, d->ay - 1) && !grid_free_at(&rm.known, d->ax, d->ay + 1);
				ux = across_x, uy = !across_x && across_y;
				if (!ux && !uy)
					continue;
			}
			/* The jambs on the space seen: from the door's cell along the run
			 * to the first square not seen free each way (on the optimistic
			 * map the run may end inside a wall seen coarsely). */
			for (int e = 0; e < 2 && !found; e++) {
				int32_t sx = e ? ux : -ux, sy = e ? uy : -uy, i = d->x, j = d->y;
				while (seen_free(s, i + sx, j + sy))
					i += sx, j += sy;
				int state = jamb_state(c, i + sx, j + sy);
				if (state == JAMB_OBJECT) {
					found = true;
					*at = goals_centre(s->x0 + i + sx, s->y0 + j + sy);
				} else if (state == JAMB_UNTOUCHED && dist && dist[j * s->w + i] >= 0 &&
					   dist[j * s->w + i] <= ROOMLEAN_REACH && dist[j * s->w + i] < near) {
					Vec2 from = goals_centre(s->x0 + i, s->y0 + j);
					bool gone = false;
					for (int v = 0; v < c->visited_count && !gone; v++)
						gone = goals_distance(from, c->visited[v]) <= 1;
					if (!gone) {
						near = dist[j * s->w + i];
						*look = from;
					}
				}
			}
		}
		carryroom_free(&cr);
		goals_roommap_free(&rm);
	}
	return found ? ROOMLEAN_DOUBT : near < INT32_MAX ? ROOMLEAN_LOOK : ROOMLEAN_NONE;
}

RoomLean roomlean_corner(const Controller *c, int64_t got, const int32_t *dist, Vec2 *at, Vec2 *look)
{
	return lean(c, got, -1, dist, at, look);
}

RoomLean roomlean_next(const Controller *c, const int32_t *dist, Vec2 *at, Vec2 *look)
{
	int32_t ui, uj;
	if (!goals_cell_of(&c->screen, c->model.utak, &ui, &uj))
		return ROOMLEAN_NONE;
	return lean(c, 0, (int64_t)uj * c->screen.w + ui, dist, at, look);
}
