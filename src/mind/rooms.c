/* rooms.c - rooms and doors: the free space cut at the skeleton's narrow points (see
 * rooms.h for the door rule and what a room is; issue 4, after paper 4.2).
 *
 * ALGORITHM  (1) scan the clearance profile of every pathgraph edge for valleys and
 *    keep those that pass the door rule; (2) label the 4-components of the skeleton
 *    without the door cells by flood fill: the rooms; drop the doors whose two
 *    neighbouring skeleton cells got the same room; (3) a breadth-first search through
 *    the free cells from all rooms' skeleton cells at once (sources queued in row-major
 *    order) gives every free cell of the grid its room.
 * INVARIANTS  every free cell has a room, every blocked cell -1; a door's two rooms
 *    differ; a room's cells are 4-connected.
 * MEMORY  the room map (4 bytes a cell); while working, a queue and a stamp map (4
 *    bytes a cell each).
 * COMPLEXITY  O(w h + cells of the pathgraph's edges), plus for each valley looked at
 *    past an edge's end a search bounded by its reach (rooms.h). */
#include "utak/mind/rooms.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

enum { ROOMS_DOOR_MARK = -2 }; /* a door cell in the room map while labelling */

void rooms_init(Rooms *r)
{
	*r = (Rooms){0};
}

void rooms_free(Rooms *r)
{
	free(r->room);
	free(r->rooms);
	free(r->doors);
	*r = (Rooms){0};
}

int32_t rooms_at(const Rooms *r, int32_t x, int32_t y)
{
	if (x < 0 || y < 0 || x >= r->w || y >= r->h)
		return -1;
	return r->room[(size_t)y * r->w + x];
}

/* rooms_run(g, x, y, dx, dy, &x0, &y0, &x1, &y1): the run of free cells through (x, y)
 * along (dx, dy); returns its length. */
static int32_t rooms_run(const Grid *g, int32_t x, int32_t y, int dx, int dy, int32_t *x0,
                         int32_t *y0, int32_t *x1, int32_t *y1)
{
	int32_t a = 0, b = 0;
	while (grid_free_at(g, x - (a + 1) * dx, y - (a + 1) * dy))
		a++;
	while (grid_free_at(g, x + (b + 1) * dx, y + (b + 1) * dy))
		b++;
	*x0 = x - a * dx;
	*y0 = y - a * dy;
	*x1 = x + b * dx;
	*y1 = y + b * dy;
	return a + b + 1;
}

/* rooms_cross(g, x, y, cross): the width across (x, y), the shorter of its runs of free
 * cells along x and along y, whose ends go into cross = {ax, ay, bx, by}. */
static int32_t rooms_cross(const Grid *g, int32_t x, int32_t y, int32_t cross[4])
{
	int32_t h[4], v[4];
	int32_t hw = rooms_run(g, x, y, 1, 0, &h[0], &h[1], &h[2], &h[3]);
	int32_t vw = rooms_run(g, x, y, 0, 1, &v[0], &v[1], &v[2], &v[3]);
	memcpy(cross, hw <= vw ? h : v, 4 * sizeof *cross);
	return hw <= vw ? hw : vw;
}

/* The search for a side's peak beyond the end of the edge (see rooms_side_peak). */
typedef struct PeakSearch {
	const Pathgraph *pg;
	int32_t *stamp;  /* w * h: the search that last reached a cell */
	int32_t current; /* this search's stamp */
	int32_t *queue;  /* w * h */
} PeakSearch;

static bool rooms_door_rule(int32_t valley, int32_t peak)
{
	double r = sqrt((double)valley), p = sqrt((double)peak);
	return p >= ROOMS_DOOR_RATIO * r && p - r >= ROOMS_DOOR_RISE;
}

/* rooms_side_peak(ps, c, d, from, step, end, valley): the peak of one side of a
 * valley: the largest dist2 going along the edge's cells c (dist2 d) from index from
 * by step until the profile comes down to valley or below. When the walk reaches the
 * edge's end first, the side goes on past the vertex: a breadth-first search along
 * the skeleton from the end cell, through cells above the valley, at most
 * ROOMS_REACH_FACTOR * clearance + ROOMS_REACH_SLACK steps, stopping as soon as the
 * door rule is met. */
static int32_t rooms_side_peak(PeakSearch *ps, const int32_t *c, const int32_t *d, int32_t from,
                               int step, int32_t end, int32_t valley)
{
	int32_t peak = 0;
	bool past_end = step < 0 ? from < end : from > end; /* the run reaches the edge's end */
	for (int32_t k = from; !past_end; k += step) {
		if (d[k] <= valley)
			return peak;
		if (d[k] > peak)
			peak = d[k];
		if (k == end)
			break;
	}
	if (rooms_door_rule(valley, peak))
		return peak;
	const Skeleton *s = ps->pg->skeleton;
	const int32_t w = s->w;
	int32_t reach = (int32_t)(ROOMS_REACH_FACTOR * sqrt((double)valley) + ROOMS_REACH_SLACK);
	int32_t stamp = ++ps->current;
	int32_t head = 0, tail = 0;
	ps->queue[tail++] = c[end];
	ps->stamp[c[end]] = stamp;
	for (int32_t depth = 0; head < tail && depth < reach; depth++) {
		for (int32_t layer_end = tail; head < layer_end;) {
			int32_t q = ps->queue[head++], qx = q % w, qy = q / w;
			static const int DX[4] = {1, 0, -1, 0}, DY[4] = {0, 1, 0, -1};
			for (int k = 0; k < 4; k++) {
				int32_t nx = qx + DX[k], ny = qy + DY[k];
				if (!skeleton_on(s, nx, ny))
					continue;
				int32_t nb = ny * w + nx;
				if (ps->stamp[nb] == stamp || s->dist2[nb] <= valley)
					continue;
				ps->stamp[nb] = stamp;
				ps->queue[tail++] = nb;
				if (s->dist2[nb] > peak) {
					peak = s->dist2[nb];
					if (rooms_door_rule(valley, peak))
						return peak;
				}
			}
		}
	}
	return peak;
}

/* rooms_find_doors(r, pg): step (1); the doors' rooms are filled in later. */
static void rooms_find_doors(Rooms *r, const Pathgraph *pg)
{
	const int32_t *dist2 = pg->skeleton->dist2;
	const size_t n = (size_t)pg->w * pg->h;
	PeakSearch ps = {pg, util_alloc(n + 1, sizeof(int32_t)), 0,
	                 util_alloc(n + 1, sizeof(int32_t))};
	int32_t *d = NULL;
	int dcap = 0, door_cap = 0;
	for (int32_t e = 0; e < pg->edge_count; e++) {
		const PathgraphEdge *ed = &pg->edges[e];
		const int32_t *c = pg->cells + ed->first;
		int32_t m = ed->count;
		d = util_grow(d, &dcap, m, sizeof *d);
		for (int32_t k = 0; k < m; k++)
			d[k] = dist2[c[k]];
		for (int32_t i = 0; i < m;) {
			int32_t j = i;
			while (j + 1 < m && d[j + 1] == d[i])
				j++;
			/* a run may take in a vertex at an end of the edge: a junction can sit
			 * in a doorway; that side is then looked for past the vertex */
			if ((i == 0 || d[i - 1] > d[i]) && (j == m - 1 || d[j + 1] > d[i]) &&
			    rooms_door_rule(d[i], rooms_side_peak(&ps, c, d, i - 1, -1, 0, d[i])) &&
			    rooms_door_rule(d[i],
			                    rooms_side_peak(&ps, c, d, j + 1, 1, m - 1, d[i]))) {
				/* the door is the narrowest chain cell of the run, the one nearest
				 * its middle among equals: a run of equal clearance can follow a
				 * wall into the room before it passes the gap */
				int32_t best = -1, best_width = INT32_MAX, best_off = INT32_MAX;
				int32_t cross[4] = {0, 0, 0, 0}, best_cross[4] = {0, 0, 0, 0};
				for (int32_t k = i; k <= j; k++) {
					if (pathgraph_cell_ref(pg, c[k]) < pg->vertex_count)
						continue;
					int32_t width = rooms_cross(pg->grid, c[k] % pg->w,
					                            c[k] / pg->w, cross);
					int32_t off = abs(2 * k - (i + j));
					if (width < best_width ||
					    (width == best_width && off < best_off)) {
						best = k;
						best_width = width;
						best_off = off;
						memcpy(best_cross, cross, sizeof cross);
					}
				}
				if (best < 0) {
					i = j + 1;
					continue;
				}
				int32_t mid = best;
				r->doors = util_grow(r->doors, &door_cap, r->door_count + 1,
				                     sizeof *r->doors);
				RoomsDoor *door = &r->doors[r->door_count++];
				*door = (RoomsDoor){.x = c[mid] % pg->w,
				                    .y = c[mid] / pg->w,
				                    .edge = e,
				                    .width = best_width,
				                    .ax = best_cross[0],
				                    .ay = best_cross[1],
				                    .bx = best_cross[2],
				                    .by = best_cross[3]};
				/* where the door's neighbours along the edge are, for step (2) */
				door->room_a = c[mid - 1];
				door->room_b = c[mid + 1];
			}
			i = j + 1;
		}
	}
	free(d);
	free(ps.stamp);
	free(ps.queue);
}

void rooms_find(Rooms *r, const Pathgraph *pg)
{
	rooms_free(r);
	const Skeleton *s = pg->skeleton;
	const Grid *g = pg->grid;
	const int32_t w = pg->w, h = pg->h;
	const size_t n = (size_t)w * h;
	r->w = w;
	r->h = h;
	r->room = util_alloc(n + 1, sizeof *r->room);
	for (size_t i = 0; i < n; i++)
		r->room[i] = -1;
	rooms_find_doors(r, pg);
	for (int32_t k = 0; k < r->door_count; k++)
		r->room[(size_t)r->doors[k].y * w + r->doors[k].x] = ROOMS_DOOR_MARK;

	/* (2) rooms: the skeleton's pieces between doors */
	int32_t *queue = util_alloc(n + 1, sizeof *queue);
	static const int DX[4] = {1, 0, -1, 0}, DY[4] = {0, 1, 0, -1};
	int room_cap = 0;
	for (size_t i = 0; i < n; i++) {
		if (!s->on[i] || r->room[i] != -1)
			continue;
		int32_t id = r->room_count++;
		r->rooms = util_grow(r->rooms, &room_cap, r->room_count, sizeof *r->rooms);
		r->rooms[id] = (RoomsRoom){.x = (int32_t)(i % w), .y = (int32_t)(i / w)};
		int32_t best = (int32_t)i;
		size_t head = 0, tail = 0;
		queue[tail++] = (int32_t)i;
		r->room[i] = id;
		while (head < tail) {
			int32_t c = queue[head++], cx = c % w, cy = c / w;
			if (s->dist2[c] > s->dist2[best] ||
			    (s->dist2[c] == s->dist2[best] && c < best))
				best = c;
			for (int k = 0; k < 4; k++) {
				int32_t nx = cx + DX[k], ny = cy + DY[k];
				if (skeleton_on(s, nx, ny) && r->room[(size_t)ny * w + nx] == -1) {
					r->room[(size_t)ny * w + nx] = id;
					queue[tail++] = ny * w + nx;
				}
			}
		}
		r->rooms[id].x = best % w;
		r->rooms[id].y = best / w;
		r->rooms[id].clearance = sqrt((double)s->dist2[best]);
	}
	/* keep the doors whose sides are different rooms, with the rooms in order */
	int32_t kept = 0;
	for (int32_t k = 0; k < r->door_count; k++) {
		RoomsDoor door = r->doors[k];
		int32_t a = r->room[door.room_a], b = r->room[door.room_b];
		r->room[(size_t)door.y * w + door.x] = -1;
		if (a == b || a < 0 || b < 0)
			continue;
		door.room_a = a < b ? a : b;
		door.room_b = a < b ? b : a;
		r->doors[kept++] = door;
	}
	r->door_count = kept;

	/* (3) every free cell to the room whose skeleton it reaches first */
	size_t head = 0, tail = 0;
	for (size_t i = 0; i < n; i++)
		if (r->room[i] >= 0)
			queue[tail++] = (int32_t)i;
	while (head < tail) {
		int32_t c = queue[head++], cx = c % w, cy = c / w;
		for (int k = 0; k < 4; k++) {
			int32_t nx = cx + DX[k], ny = cy + DY[k];
			if (grid_free_at(g, nx, ny) && r->room[(size_t)ny * w + nx] == -1) {
				r->room[(size_t)ny * w + nx] = r->room[c];
				queue[tail++] = ny * w + nx;
			}
		}
	}
	for (size_t i = 0; i < n; i++)
		if (r->room[i] >= 0)
			r->rooms[r->room[i]].cells++;
	free(queue);
}

int32_t rooms_doors_of(const Rooms *r, int32_t room, int32_t *out, int32_t cap)
{
	int32_t count = 0;
	for (int32_t k = 0; k < r->door_count; k++) {
		if (r->doors[k].room_a != room && r->doors[k].room_b != room)
			continue;
		if (count < cap)
			out[count] = k;
		count++;
	}
	return count;
}

/* The symbols of the rooms map, in room order. */
static const char ROOMS_SYMBOLS[] =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";

void rooms_dump(const Rooms *r, const Grid *g, FILE *out)
{
	const int32_t w = r->w, h = r->h;
	char *map = util_alloc((size_t)w * h + 1, 1);
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++) {
			int32_t id = rooms_at(r, x, y);
			char c = '#';
			if (grid_free_at(g, x, y))
				c = id >= 0 && id < (int32_t)sizeof ROOMS_SYMBOLS - 1
				        ? ROOMS_SYMBOLS[id]
				        : '?';
			map[(size_t)y * w + x] = c;
		}
	for (int32_t k = 0; k < r->door_count; k++) {
		const RoomsDoor *d = &r->doors[k];
		int32_t dx = d->bx > d->ax, dy = d->by > d->ay;
		for (int32_t x = d->ax, y = d->ay;; x += dx, y += dy) {
			map[(size_t)y * w + x] = '=';
			if (x == d->bx && y == d->by)
				break;
		}
	}
	for (int32_t y = h - 1; y >= 0; y--) {
		fwrite(map + (size_t)y * w, 1, (size_t)w, out);
		fputc('\n', out);
	}
	free(map);
	fprintf(out, "rooms: %d rooms, %d doors\n", (int)r->room_count, (int)r->door_count);
	for (int32_t k = 0; k < r->room_count; k++) {
		const RoomsRoom *m = &r->rooms[k];
		fprintf(out, "room %d %d %d %d %.3f\n", (int)k, (int)m->x, (int)m->y, (int)m->cells,
		        m->clearance);
	}
	for (int32_t k = 0; k < r->door_count; k++) {
		const RoomsDoor *d = &r->doors[k];
		fprintf(out, "door %d %d %d %d %d %d\n", (int)k, (int)d->x, (int)d->y,
		        (int)d->width, (int)d->room_a, (int)d->room_b);
	}
}
