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
 * MEMORY  the room map (4 bytes a cell) and a queue of as many entries while working.
 * COMPLEXITY  O(w h + cells of the pathgraph's edges). */
#include "utak/rooms.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/util.h"

enum { ROOMS_DOOR_MARK = -2 }; /* a door cell in the room map while labelling */

void rooms_init(Rooms *r) { *r = (Rooms){0}; }

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
static int32_t rooms_run(const Grid *g, int32_t x, int32_t y, int dx, int dy, int32_t *x0, int32_t *y0,
			 int32_t *x1, int32_t *y1)
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

/* rooms_peak(d, from, step, end, floor_d2): the largest dist2 going from index from by
 * step until the profile comes down to floor_d2 or below, or index end is passed. */
static int32_t rooms_peak(const int32_t *d, int32_t from, int step, int32_t end, int32_t floor_d2)
{
	int32_t peak = 0;
	for (int32_t k = from; step > 0 ? k <= end : k >= end; k += step) {
		if (d[k] <= floor_d2)
			break;
		if (d[k] > peak)
			peak = d[k];
	}
	return peak;
}

static bool rooms_door_rule(int32_t valley, int32_t left, int32_t right)
{
	double r = sqrt((double)valley), p = sqrt((double)(left < right ? left : right));
	return p >= ROOMS_DOOR_RATIO * r && p - r >= ROOMS_DOOR_RISE;
}

/* rooms_find_doors(r, pg): step (1); the doors' rooms are filled in later. */
static void rooms_find_doors(Rooms *r, const Pathgraph *pg)
{
	const int32_t *dist2 = pg->skeleton->dist2;
	int32_t *d = NULL;
	int dcap = 0, door_cap = 0;
	for (int32_t e = 0; e < pg->edge_count; e++) {
		const PathgraphEdge *ed = &pg->edges[e];
		const int32_t *c = pg->cells + ed->first;
		int32_t m = ed->count;
		d = util_grow(d, &dcap, m, sizeof *d);
		for (int32_t k = 0; k < m; k++)
			d[k] = dist2[c[k]];
		for (int32_t i = 1; i <= m - 2;) {
			int32_t j = i;
			while (j + 1 <= m - 2 && d[j + 1] == d[i])
				j++;
			int32_t mid = (i + j) / 2;
			bool chain = pg->cell_ref[c[mid]] >= pg->vertex_count;
			if (chain && d[i - 1] > d[i] && d[j + 1] > d[i] &&
			    rooms_door_rule(d[i], rooms_peak(d, i - 1, -1, 0, d[i]),
					    rooms_peak(d, j + 1, 1, m - 1, d[i]))) {
				r->doors = util_grow(r->doors, &door_cap, r->door_count + 1, sizeof *r->doors);
				RoomsDoor *door = &r->doors[r->door_count++];
				*door = (RoomsDoor){.x = c[mid] % pg->w, .y = c[mid] / pg->w, .edge = e,
						    .room_a = -1, .room_b = -1};
				int32_t hx0, hy0, hx1, hy1, vx0, vy0, vx1, vy1;
				int32_t hw = rooms_run(pg->grid, door->x, door->y, 1, 0, &hx0, &hy0, &hx1, &hy1);
				int32_t vw = rooms_run(pg->grid, door->x, door->y, 0, 1, &vx0, &vy0, &vx1, &vy1);
				if (hw <= vw) {
					door->width = hw;
					door->ax = hx0, door->ay = hy0, door->bx = hx1, door->by = hy1;
				} else {
					door->width = vw;
					door->ax = vx0, door->ay = vy0, door->bx = vx1, door->by = vy1;
				}
				/* where the door's neighbours along the edge are, for step (2) */
				door->room_a = c[mid - 1];
				door->room_b = c[mid + 1];
			}
			i = j + 1;
		}
	}
	free(d);
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
			if (s->dist2[c] > s->dist2[best] || (s->dist2[c] == s->dist2[best] && c < best))
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
static const char ROOMS_SYMBOLS[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";

void rooms_dump(const Rooms *r, const Grid *g, FILE *out)
{
	const int32_t w = r->w, h = r->h;
	char *map = util_alloc((size_t)w * h + 1, 1);
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++) {
			int32_t id = rooms_at(r, x, y);
			char c = '#';
			if (grid_free_at(g, x, y))
				c = id >= 0 && id < (int32_t)sizeof ROOMS_SYMBOLS - 1 ? ROOMS_SYMBOLS[id] : '?';
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
		fprintf(out, "door %d %d %d %d %d %d\n", (int)k, (int)d->x, (int)d->y, (int)d->width,
			(int)d->room_a, (int)d->room_b);
	}
}
