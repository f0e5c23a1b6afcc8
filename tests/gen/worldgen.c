/* worldgen.c - random worlds nobody tuned for: rooms with doors, objects at any
 * angle, irregular pieces and clutter, tables up to 200 x 200 (issue 13, "Tests").
 *
 *   worldgen SEED                 one world on standard output
 *   worldgen -n COUNT -o DIR SEED COUNT worlds, DIR/gSEED.w for SEED, SEED+1, ...
 *
 * A second generator beside the awk one of tests/random-tasks.test.sh, written
 * without looking at worlds/: what the tasks of paper 2.3 meet in a world someone
 * else drew. Each world is valid by utak(5) (checked with the simulator's own
 * reader and TABLE before it is written; a refused attempt is drawn again from the
 * next sub-seed) and starts with comment lines the test scripts read:
 *
 *   # worldgen SEED: LAYOUT, W x H, N rooms
 *   # shapes: square brick ...        the kinds placed (a task's target exists)
 *
 * LAYOUTS. open: one room, sometimes a chamfered (slanted) verge and slanted wall
 * stubs; split: one wall, 1 to 3 squares thick, with one or two doors; grid: a
 * wall each way, crossing, with a door in each of the four pieces (or three), four
 * rooms; tee: a wall across and one half-wall, three rooms; hall: a large open
 * room with piers (one room, however big). Doors are 2 to 8 squares wide, never
 * wider than half the smaller room beside them, so that each room "widens well
 * beyond" its door (doc/verdicts.md): N rooms is the number the judge must find.
 *
 * OBJECTS. A square (90%; a second one 20%), a brick (70%), an L-shape (50%), a
 * triangle (50%), up to three irregular polygons (5 to 8 corners) and clutter
 * (pieces of 1 to 2.5 squares), each turned by any angle (30% of them by a
 * multiple of 90 degrees). Objects keep a gap of one square from everything
 * (80%) or may touch a wall or another object (20%: the pocket, the pile). Doors
 * and the squares beside them are kept clear of all but clutter. Utak stands on a
 * square whose eight neighbours are free, facing any of the four headings.
 *
 * Deterministic: splitmix64 from the seed, coordinates printed to 3 decimals. */
#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gen.h"
#include "utak/base/task.h"

/* Table sides: small, medium and large tables, the largest the issue names. */
#define WORLDGEN_MIN_SIDE 32
#define WORLDGEN_MAX_SIDE 200
/* A door is 2 to 8 squares wide... */
#define WORLDGEN_DOOR_MIN 2
#define WORLDGEN_DOOR_MAX 8
/* The smallest room side (free squares) that gets a door. */
#define WORLDGEN_ROOM_MIN 9
/* ...and kept clear, with this many squares each side of its wall, of everything
 * but clutter. */
#define WORLDGEN_DOOR_KEEP 3
/* Tries to place one object before it is left out. */
#define WORLDGEN_TRIES 80
/* Attempts at a whole world before giving up (never reached in practice). */
#define WORLDGEN_ATTEMPTS 64

enum { OCC_FREE = 0, OCC_FIXED = 1, OCC_OBJECT = 2 };

typedef struct Gen {
	GenRng rng;
	int32_t w, h;
	uint8_t *occ;  /* w * h: OCC_* of each square, as projected so far */
	uint8_t *keep; /* w * h: 1 where doors must stay clear */
	GenText walls, objects;
	const char *layout;
	int32_t rooms;
	int has[5]; /* shapes placed, by Shape */
	int32_t count;
} Gen;

/* ---- occupancy ------------------------------------------------------------------ */

typedef struct Spans {
	int32_t n, cap;
	int32_t *y, *x0, *x1;
} Spans;

static void spans_add(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	Spans *s = ctx;
	if (s->n == s->cap) {
		s->cap = s->cap ? 2 * s->cap : 64;
		s->y = util_realloc(s->y, (size_t)s->cap, sizeof *s->y);
		s->x0 = util_realloc(s->x0, (size_t)s->cap, sizeof *s->x0);
		s->x1 = util_realloc(s->x1, (size_t)s->cap, sizeof *s->x1);
	}
	s->y[s->n] = y, s->x0[s->n] = x0, s->x1[s->n] = x1;
	s->n++;
}

static void spans_free(Spans *s)
{
	free(s->y), free(s->x0), free(s->x1);
}

static uint8_t occ_at(const Gen *g, int32_t x, int32_t y)
{
	if (x < 0 || y < 0 || x >= g->w || y >= g->h)
		return OCC_FIXED;
	return g->occ[(int64_t)y * g->w + x];
}

/* fits(g, p, gap, clutter): every square of p is free (and not a door's, unless
 * clutter); with gap, every square around them is free too. */
static int fits(const Gen *g, const Polygon *p, int gap, int clutter)
{
	for (int32_t i = 0; i < p->count; i++)
		if (p->v[i].x < 1 || p->v[i].y < 1 || p->v[i].x > g->w - 1 || p->v[i].y > g->h - 1)
			return 0;
	Spans s = {0};
	geom_project(p, g->w, g->h, spans_add, &s);
	int ok = s.n > 0;
	for (int32_t k = 0; k < s.n && ok; k++)
		for (int32_t x = s.x0[k]; x <= s.x1[k] && ok; x++) {
			int32_t y = s.y[k];
			if (occ_at(g, x, y) != OCC_FREE || (!clutter && g->keep[(int64_t)y * g->w + x]))
				ok = 0;
			for (int32_t dy = -1; dy <= 1 && ok && gap; dy++)
				for (int32_t dx = -1; dx <= 1 && ok; dx++)
					if (occ_at(g, x + dx, y + dy) != OCC_FREE)
						ok = 0;
		}
	spans_free(&s);
	return ok;
}

static void stamp(Gen *g, const Polygon *p, uint8_t what)
{
	Spans s = {0};
	geom_project(p, g->w, g->h, spans_add, &s);
	for (int32_t k = 0; k < s.n; k++)
		for (int32_t x = s.x0[k]; x <= s.x1[k]; x++)
			g->occ[(int64_t)s.y[k] * g->w + x] = what;
	spans_free(&s);
}

static Polygon rect(double x0, double y0, double x1, double y1)
{
	Polygon p = {4, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
	return p;
}

/* ---- walls and rooms -------------------------------------------------------------- */

static void wall(Gen *g, const Polygon *p)
{
	stamp(g, p, OCC_FIXED);
	gen_printf(&g->walls, "wall");
	gen_points(&g->walls, p);
}

static void wall_rect(Gen *g, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
	if (x1 > x0 && y1 > y0) {
		Polygon p = rect(x0, y0, x1, y1);
		wall(g, &p);
	}
}

static void keep_clear(Gen *g, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
	for (int32_t y = y0 < 0 ? 0 : y0; y < y1 && y < g->h; y++)
		for (int32_t x = x0 < 0 ? 0 : x0; x < x1 && x < g->w; x++)
			g->keep[(int64_t)y * g->w + x] = 1;
}

/* door_width(g, room): a door for rooms whose smaller side (free squares) is room:
 * at most (room - 1) / 2 squares, so that each room's clearance, (room + 1) / 2 from
 * its middle square to its walls, is at least twice the door's half-width, (d + 1) / 2,
 * and at least 2 more (room >= WORLDGEN_ROOM_MIN): the judge's door rule. */
static int32_t door_width(Gen *g, int32_t room)
{
	int32_t most = (room - 1) / 2 < WORLDGEN_DOOR_MAX ? (room - 1) / 2 : WORLDGEN_DOOR_MAX;
	return room < WORLDGEN_ROOM_MIN || most < WORLDGEN_DOOR_MIN ? -1 : gen_int(&g->rng, WORLDGEN_DOOR_MIN, most);
}

/* vwall(g, x, t, y0, y1, doors, room): a wall t thick at x..x+t from y0 to y1
 * (squares y0..y1-1) with `doors` doors (1 or 2), each at least 2 squares from its
 * ends; room is the smaller side of the rooms beside it. Returns the doors made. */
static int vwall(Gen *g, int32_t x, int32_t t, int32_t y0, int32_t y1, int doors, int32_t room)
{
	int32_t len = y1 - y0, d[2], at[2];
	int made = 0;
	for (int k = 0; k < doors; k++) {
		d[k] = door_width(g, room);
		if (d[k] < 0)
			return 0;
	}
	if (doors == 2 && d[0] + d[1] + 10 > len)
		doors = 1;
	if (d[0] + 4 > len)
		return 0;
	if (doors == 1) {
		at[0] = y0 + gen_int(&g->rng, 2, len - d[0] - 2);
	} else {
		int32_t half = len / 2;
		at[0] = y0 + gen_int(&g->rng, 2, half - d[0] - 2 > 2 ? half - d[0] - 2 : 2);
		at[1] = y0 + half + gen_int(&g->rng, 2, len - half - d[1] - 2 > 2 ? len - half - d[1] - 2 : 2);
	}
	int32_t from = y0;
	for (int k = 0; k < doors; k++) {
		wall_rect(g, x, from, x + t, at[k]);
		keep_clear(g, x - WORLDGEN_DOOR_KEEP, at[k] - 1, x + t + WORLDGEN_DOOR_KEEP, at[k] + d[k] + 1);
		from = at[k] + d[k];
		made++;
	}
	wall_rect(g, x, from, x + t, y1);
	return made;
}

/* hwall: vwall with x and y exchanged. */
static int hwall(Gen *g, int32_t y, int32_t t, int32_t x0, int32_t x1, int doors, int32_t room)
{
	int32_t len = x1 - x0, d = door_width(g, room);
	if (d < 0 || d + 4 > len)
		return 0;
	int made = 0;
	if (doors == 2 && 2 * d + 10 <= len) {
		int32_t half = len / 2;
		int32_t a = x0 + gen_int(&g->rng, 2, half - d - 2 > 2 ? half - d - 2 : 2);
		int32_t b = x0 + half + gen_int(&g->rng, 2, len - half - d - 2 > 2 ? len - half - d - 2 : 2);
		wall_rect(g, x0, y, a, y + t);
		wall_rect(g, a + d, y, b, y + t);
		wall_rect(g, b + d, y, x1, y + t);
		keep_clear(g, a - 1, y - WORLDGEN_DOOR_KEEP, a + d + 1, y + t + WORLDGEN_DOOR_KEEP);
		keep_clear(g, b - 1, y - WORLDGEN_DOOR_KEEP, b + d + 1, y + t + WORLDGEN_DOOR_KEEP);
		made = 2;
	} else {
		int32_t a = x0 + gen_int(&g->rng, 2, len - d - 2);
		wall_rect(g, x0, y, a, y + t);
		wall_rect(g, a + d, y, x1, y + t);
		keep_clear(g, a - 1, y - WORLDGEN_DOOR_KEEP, a + d + 1, y + t + WORLDGEN_DOOR_KEEP);
		made = 1;
	}
	return made;
}

static int32_t min32(int32_t a, int32_t b)
{
	return a < b ? a : b;
}

/* A thin rotated slab, unattached, in an open room: a slanted wall. */
static void slanted_stub(Gen *g)
{
	for (int tries = 0; tries < WORLDGEN_TRIES; tries++) {
		double len = gen_range(&g->rng, 5, 16), thick = gen_range(&g->rng, 1, 2.5);
		double a = gen_range(&g->rng, 0, 2 * GEN_PI), c = cos(a), s = sin(a);
		double cx = gen_range(&g->rng, 6, g->w - 6), cy = gen_range(&g->rng, 6, g->h - 6);
		Polygon p = rect(-len / 2, -thick / 2, len / 2, thick / 2);
		for (int i = 0; i < 4; i++) {
			Vec2 v = p.v[i];
			p.v[i] = vec2(gen_round(cx + c * v.x - s * v.y), gen_round(cy + s * v.x + c * v.y));
		}
		/* Three squares of floor all round, so that it makes no door. */
		Polygon grown = p;
		for (int i = 0; i < 4; i++)
			grown.v[i] = vec2_add(vec2(cx, cy), vec2_scale(vec2_sub(p.v[i], vec2(cx, cy)), 1.0 + 8.0 / len));
		if (fits(g, &grown, 1, 0) && fits(g, &p, 1, 0)) {
			wall(g, &p);
			return;
		}
	}
}

static void pier(Gen *g)
{
	for (int tries = 0; tries < WORLDGEN_TRIES; tries++) {
		int32_t a = gen_int(&g->rng, 2, 7), b = gen_int(&g->rng, 2, 7);
		int32_t x = gen_int(&g->rng, 4, g->w - a - 4), y = gen_int(&g->rng, 4, g->h - b - 4);
		Polygon keep = rect(x - 3, y - 3, x + a + 3, y + b + 3);
		if (fits(g, &keep, 0, 0)) {
			wall_rect(g, x, y, x + a, y + b);
			return;
		}
	}
}

/* layout(g): the fixed walls; sets g->layout and g->rooms, and the verge line in
 * verge (empty for the default ring). */
static void layout(Gen *g, GenText *verge)
{
	int32_t W = g->w, H = g->h;
	double u = gen_unit(&g->rng);
	/* Room sides in free squares: the TABLE less its verge ring, less walls. */
	if (u < 0.25 || W < 40 || H < 32) {
		g->layout = "open", g->rooms = 1;
		if (gen_chance(&g->rng, 0.3)) {
			/* A chamfered tabletop: four slanted edges. */
			double c = gen_int(&g->rng, 3, min32(W, H) / 5);
			Polygon v = {8,
				     {{1 + c, 1},
				      {W - 1 - c, 1},
				      {W - 1, 1 + c},
				      {W - 1, H - 1 - c},
				      {W - 1 - c, H - 1},
				      {1 + c, H - 1},
				      {1, H - 1 - c},
				      {1, 1 + c}}};
			gen_printf(verge, "verge");
			gen_points(verge, &v);
			/* Mark what lies outside it, as the reader will. */
			for (int32_t y = 0; y < H; y++)
				for (int32_t x = 0; x < W; x++) {
					double px = x + 0.5, py = y + 0.5;
					double e = px - 1 < W - 1 - px ? px - 1 : W - 1 - px;
					double f = py - 1 < H - 1 - py ? py - 1 : H - 1 - py;
					if (e < 0.5 || f < 0.5 || e + f < c + 1.5)
						g->occ[(int64_t)y * W + x] = OCC_FIXED;
				}
		}
		int stubs = gen_int(&g->rng, 0, W * H > 4000 ? 2 : 0);
		for (int k = 0; k < stubs; k++)
			slanted_stub(g);
	} else if (u < 0.55) {
		g->layout = "split", g->rooms = 2;
		int32_t t = gen_int(&g->rng, 1, 3);
		if (gen_chance(&g->rng, 0.5)) {
			int32_t x = gen_int(&g->rng, (int32_t)(W * 0.35), (int32_t)(W * 0.65));
			int32_t room = min32(min32(x - 1, W - 1 - x - t), H - 2);
			if (!vwall(g, x, t, 1, H - 1, gen_chance(&g->rng, 0.3) ? 2 : 1, room))
				g->rooms = 1;
		} else {
			int32_t y = gen_int(&g->rng, (int32_t)(H * 0.35), (int32_t)(H * 0.65));
			int32_t room = min32(min32(y - 1, H - 1 - y - t), W - 2);
			if (!hwall(g, y, t, 1, W - 1, gen_chance(&g->rng, 0.3) ? 2 : 1, room))
				g->rooms = 1;
		}
	} else if (u < 0.75 && W >= 48 && H >= 40) {
		/* A wall each way, crossing at (x, y): four rooms, a door in each piece
		 * (one piece may go without: the rooms stay connected through the rest). */
		int grid = gen_chance(&g->rng, 0.6);
		g->layout = grid ? "grid" : "tee";
		g->rooms = grid ? 4 : 3;
		int32_t t = gen_int(&g->rng, 1, 2);
		int32_t x = gen_int(&g->rng, (int32_t)(W * 0.35), (int32_t)(W * 0.65));
		int32_t y = gen_int(&g->rng, (int32_t)(H * 0.35), (int32_t)(H * 0.65));
		int32_t left = x - 1, right = W - 1 - x - t, low = y - 1, high = H - 1 - y - t;
		int skip = grid && gen_chance(&g->rng, 0.4) ? gen_int(&g->rng, 0, 3) : -1;
		int ok = 1;
		/* The horizontal wall, in two pieces: left and right of the crossing. */
		if (skip == 0)
			wall_rect(g, 1, y, x, y + t);
		else
			ok &= hwall(g, y, t, 1, x, 1, min32(left, min32(low, high))) > 0;
		if (skip == 1)
			wall_rect(g, x + t, y, W - 1, y + t);
		else
			ok &= hwall(g, y, t, x + t, W - 1, 1, min32(right, min32(low, high))) > 0;
		wall_rect(g, x, y, x + t, y + t);
		/* The vertical wall: below the crossing, and above it for a grid. */
		if (skip == 2)
			wall_rect(g, x, 1, x + t, y);
		else
			ok &= vwall(g, x, t, 1, y, 1, min32(low, min32(left, right))) > 0;
		if (grid) {
			if (skip == 3)
				wall_rect(g, x, y + t, x + t, H - 1);
			else
				ok &= vwall(g, x, t, y + t, H - 1, 1, min32(high, min32(left, right))) > 0;
		}
		if (!ok)
			g->rooms = -1; /* a piece without room for a door: drawn again */
	} else {
		g->layout = "hall", g->rooms = 1;
		int piers = gen_int(&g->rng, 2, 6);
		for (int k = 0; k < piers; k++)
			pier(g);
	}
}

/* ---- objects ------------------------------------------------------------------- */

/* The shapes, drawn about the origin (TABLE squares). */
static Polygon shape_square(double s)
{
	return rect(-s / 2, -s / 2, s / 2, s / 2);
}

static Polygon shape_brick(double a, double b)
{
	return rect(-a / 2, -b / 2, a / 2, b / 2);
}

static Polygon shape_lshape(double a, double b, double ta, double tb)
{
	Polygon p = {6, {{0, 0}, {a, 0}, {a, tb}, {ta, tb}, {ta, b}, {0, b}}};
	for (int i = 0; i < 6; i++)
		p.v[i] = vec2_sub(p.v[i], vec2(a / 3, b / 3));
	return p;
}

/* A triangle inscribed in a circle of radius r, no angle under 25 degrees (each
 * arc between its corners at least 50 degrees). */
static Polygon shape_triangle(GenRng *rng, double r)
{
	double a1 = gen_range(rng, 50, 260), a2 = a1 + gen_range(rng, 50, 310 - a1);
	double deg[3] = {0, a1, a2}, turn = gen_range(rng, 0, 360);
	Polygon p = {.count = 3};
	for (int i = 0; i < 3; i++)
		p.v[i] = vec2(r * cos((deg[i] + turn) * GEN_PI / 180), r * sin((deg[i] + turn) * GEN_PI / 180));
	return p;
}

/* An irregular polygon: n corners round the origin at jittered angles and radii
 * (star-shaped about the origin, hence simple). */
static Polygon shape_irregular(GenRng *rng, double r)
{
	Polygon p = {.count = gen_int(rng, 5, 8)};
	for (int i = 0; i < p.count; i++) {
		double a = (i + gen_range(rng, -0.3, 0.3)) * 2 * GEN_PI / p.count;
		double q = r * gen_range(rng, 0.55, 1.0);
		p.v[i] = vec2(q * cos(a), q * sin(a));
	}
	return p;
}

/* place(g, name, colour, shape, clutter): the shape turned and moved to a free
 * place; 0 when none was found. */
static int place(Gen *g, const char *name, char colour, Polygon shape, int clutter)
{
	int gap = !gen_chance(&g->rng, 0.2);
	for (int tries = 0; tries < WORLDGEN_TRIES; tries++) {
		double deg = gen_chance(&g->rng, 0.3) ? 90.0 * gen_int(&g->rng, 0, 3) : gen_range(&g->rng, 0, 360);
		double c, s;
		geom_cos_sin(deg, &c, &s);
		double cx = gen_range(&g->rng, 2, g->w - 2), cy = gen_range(&g->rng, 2, g->h - 2);
		Polygon p = shape;
		for (int i = 0; i < p.count; i++) {
			Vec2 v = shape.v[i];
			p.v[i] = vec2(gen_round(cx + c * v.x - s * v.y), gen_round(cy + s * v.x + c * v.y));
		}
		if (!geom_polygon_is_simple(&p) || !fits(g, &p, gap, clutter))
			continue;
		stamp(g, &p, OCC_OBJECT);
		gen_printf(&g->objects, "object %s %c", name, colour);
		gen_points(&g->objects, &p);
		g->count++;
		return 1;
	}
	return 0;
}

static char colour(Gen *g)
{
	static const char letters[] = "ACDEFGHIJKLMNOPQRSTUVWXYZ";
	return letters[gen_int(&g->rng, 0, (int32_t)sizeof letters - 2)];
}

static void objects(Gen *g)
{
	GenRng *r = &g->rng;
	/* Bigger tables, somewhat bigger objects (up to twice). */
	double grow = 1.0 + gen_unit(r) * fmin(1.0, (fmin(g->w, g->h) - WORLDGEN_MIN_SIDE) / 120.0);
	int squares = gen_chance(r, 0.9) + gen_chance(r, 0.2);
	for (int k = 0; k < squares; k++) {
		char name[24];
		snprintf(name, sizeof name, "square%d", k + 1);
		if (place(g, name, colour(g), shape_square(gen_range(r, 3, 6) * grow), 0))
			g->has[SHAPE_SQUARE] = 1;
	}
	if (gen_chance(r, 0.7)) {
		double b = gen_range(r, 2, 3.5) * grow, a = b * gen_range(r, 1.6, 3.0);
		g->has[SHAPE_BRICK] |= place(g, "brick", colour(g), shape_brick(a, b), 0);
	}
	if (gen_chance(r, 0.5)) {
		double a = gen_range(r, 4, 8) * grow, b = gen_range(r, 4, 8) * grow;
		double ta = gen_range(r, 0.35, 0.6) * a, tb = gen_range(r, 0.35, 0.6) * b;
		g->has[SHAPE_LSHAPE] |= place(g, "lshape", colour(g), shape_lshape(a, b, ta, tb), 0);
	}
	if (gen_chance(r, 0.5))
		g->has[SHAPE_TRIANGLE] |= place(g, "triangle", colour(g), shape_triangle(r, gen_range(r, 2.5, 4.5) * grow), 0);
	int odd = gen_int(r, 0, 3);
	for (int k = 0; k < odd; k++) {
		char name[24];
		snprintf(name, sizeof name, "piece%d", k + 1);
		place(g, name, colour(g), shape_irregular(r, gen_range(r, 2, 5) * grow), 0);
	}
	int clutter = gen_int(r, 0, (int)fmin(30, g->w * g->h / 600.0));
	for (int k = 0; k < clutter; k++) {
		char name[24];
		snprintf(name, sizeof name, "bit%d", k + 1);
		double z = gen_range(r, 1, 2.5);
		int kind = gen_int(r, 0, 2);
		Polygon p = kind == 0 ? shape_square(z) : kind == 1 ? shape_brick(z, z * gen_range(r, 0.4, 0.8)) : shape_triangle(r, z * 0.7);
		place(g, name, colour(g), p, 1);
	}
}

/* utak(g, out): a square whose eight neighbours are free; 0 when there is none. */
static int utak(Gen *g, GenText *out)
{
	static const char *const headings[4] = {"north", "east", "south", "west"};
	for (int tries = 0; tries < 10 * WORLDGEN_TRIES; tries++) {
		int32_t x = gen_int(&g->rng, 1, g->w - 2), y = gen_int(&g->rng, 1, g->h - 2);
		int ok = 1;
		for (int dy = -1; dy <= 1 && ok; dy++)
			for (int dx = -1; dx <= 1 && ok; dx++)
				ok = occ_at(g, x + dx, y + dy) == OCC_FREE;
		if (ok) {
			gen_printf(out, "utak %d.5 %d.5 %s\n", x, y, headings[gen_int(&g->rng, 0, 3)]);
			return 1;
		}
	}
	return 0;
}

/* ---- one world ------------------------------------------------------------------ */

static int side(GenRng *r)
{
	double u = gen_unit(r);
	if (u < 0.4)
		return gen_int(r, WORLDGEN_MIN_SIDE, 60);
	if (u < 0.75)
		return gen_int(r, 60, 120);
	return gen_int(r, 120, WORLDGEN_MAX_SIDE);
}

/* generate(seed, out): the world of this seed, as text. */
static void generate(uint64_t seed, GenText *out)
{
	static const char *const names[5] = {"", "square", "brick", "lshape", "triangle"};
	for (int attempt = 0; attempt < WORLDGEN_ATTEMPTS; attempt++) {
		Gen g = {.rng = {seed * 0x100000001B3ull + (uint64_t)attempt}};
		g.w = side(&g.rng), g.h = side(&g.rng);
		g.occ = util_alloc((size_t)g.w * (size_t)g.h, 1);
		g.keep = util_alloc((size_t)g.w * (size_t)g.h, 1);
		for (int32_t y = 0; y < g.h; y++)
			for (int32_t x = 0; x < g.w; x++)
				if (x == 0 || y == 0 || x == g.w - 1 || y == g.h - 1)
					g.occ[(int64_t)y * g.w + x] = OCC_FIXED;
		GenText verge = {0}, me = {0};
		layout(&g, &verge);
		int ok = g.rooms > 0;
		if (ok) {
			objects(&g);
			ok = utak(&g, &me);
		}
		out->len = 0;
		if (ok) {
			gen_printf(out, "# worldgen %llu: %s, %d x %d, %d room%s\n# shapes:", (unsigned long long)seed,
				   g.layout, g.w, g.h, g.rooms, g.rooms == 1 ? "" : "s");
			for (int s = 1; s < 5; s++)
				if (g.has[s])
					gen_printf(out, " %s", names[s]);
			gen_printf(out, "\ntable %d %d\n%s%s%s%s", g.w, g.h, verge.s ? verge.s : "",
				   g.walls.s ? g.walls.s : "", g.objects.s ? g.objects.s : "", me.s);
		}
		free(g.occ), free(g.keep), free(verge.s), free(me.s), free(g.walls.s), free(g.objects.s);
		char why[DIAG_SIZE];
		if (ok && gen_valid(out->s, out->len, why, sizeof why))
			return;
	}
	fprintf(stderr, "worldgen: seed %llu: no valid world in %d attempts\n", (unsigned long long)seed,
		WORLDGEN_ATTEMPTS);
	exit(1);
}

static int usage(void)
{
	fputs("usage: worldgen SEED | worldgen -n COUNT -o DIR SEED\n", stderr);
	return 2;
}

static int number(const char *s, unsigned long long *v)
{
	char *end;
	errno = 0;
	*v = strtoull(s, &end, 10);
	return !errno && end != s && !*end && *s != '-';
}

int main(int argc, char **argv)
{
	unsigned long long count = 0, seed;
	const char *dir = NULL;
	int i = 1;
	for (; i + 1 < argc && argv[i][0] == '-'; i += 2) {
		if (strcmp(argv[i], "-n") == 0 && number(argv[i + 1], &count))
			continue;
		if (strcmp(argv[i], "-o") == 0) {
			dir = argv[i + 1];
			continue;
		}
		return usage();
	}
	if (i + 1 != argc || !number(argv[i], &seed) || (dir == NULL) != (count == 0))
		return usage();
	GenText t = {0};
	if (!dir) {
		generate(seed, &t);
		fwrite(t.s, 1, t.len, stdout);
	}
	for (unsigned long long k = 0; k < count; k++) {
		char path[4096];
		snprintf(path, sizeof path, "%s/g%llu.w", dir, seed + k);
		generate(seed + k, &t);
		FILE *f = fopen(path, "w");
		if (!f || fwrite(t.s, 1, t.len, f) != t.len || fclose(f)) {
			fprintf(stderr, "worldgen: cannot write %s\n", path);
			return 1;
		}
	}
	free(t.s);
	return 0;
}
