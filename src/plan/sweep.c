/* sweep.c - the squares a moving polygon covers (paper 2.1's digital representation,
 * for carry.c). See sweep.h for the rule and its guarantees.
 *
 * ALGORITHM. A pose with r == 0 is geom_project, the TABLE's own projection, so the
 * planner and the simulator cannot disagree about a pose. Within r > 0: the
 * projection, and along each edge, row by row, the squares nearer than r to it
 * (the closed square meets the edge: Liang-Barsky clipping, Liang and Barsky 1984;
 * else the distance between a segment and a box that do not meet is attained at an
 * end of one of them, both being convex, so it is the least of the segment's ends
 * to the box and the box's corners to the segment). A push adds the poses at both
 * ends and each edge's parallelogram; a turn adds its samples.
 *
 * INVARIANT: win->cell[(y + radius) * side + x + radius] is 1 exactly when cell
 * (x, y) has been marked since the last clear. */
#include "utak/plan/sweep.h"

#include <assert.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

#include "utak/base/util.h"

/* ---- r == 0: the TABLE's projection ------------------------------------------ */

typedef struct SweepShifted {
	SweepSpanFn *fn;
	void *ctx;
	int32_t sx, sy; /* cell of the caller = projected cell - shift */
} SweepShifted;

static void sweep_unshift(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	SweepShifted *s = ctx;
	s->fn(s->ctx, y - s->sy, x0 - s->sx, x1 - s->sx);
}

/* sweep_project(p, fn, ctx): the squares of p by geom_project, p moved by a whole
 * number of squares so that its box lies inside the projected grid with a square to
 * spare (a shift by whole squares keeps every grid coincidence of the coordinates). */
static void sweep_project(const Polygon *p, SweepSpanFn *fn, void *ctx)
{
	Box b = geom_polygon_box(p);
	assert(fabs(b.lo.x) < 1e9 && fabs(b.lo.y) < 1e9 && fabs(b.hi.x) < 1e9 && fabs(b.hi.y) < 1e9);
	SweepShifted s = {fn, ctx, 1 - (int32_t)floor(b.lo.x), 1 - (int32_t)floor(b.lo.y)};
	Polygon q = *p;
	for (int32_t i = 0; i < q.count; i++)
		q.v[i] = vec2(q.v[i].x + s.sx, q.v[i].y + s.sy);
	int32_t w = (int32_t)ceil(b.hi.x) + s.sx + 2, h = (int32_t)ceil(b.hi.y) + s.sy + 2;
	geom_project(&q, w, h, sweep_unshift, &s);
}

/* ---- r > 0: within a distance --------------------------------------------------- */

/* sweep_segment_meets_box(a, b, lo): segment ab meets the closed square [lo, lo+1]^2. */
static bool sweep_segment_meets_box(Vec2 a, Vec2 b, Vec2 lo)
{
	double t0 = 0, t1 = 1, dx = b.x - a.x, dy = b.y - a.y;
	const double p[4] = {-dx, dx, -dy, dy};
	const double q[4] = {a.x - lo.x, lo.x + 1 - a.x, a.y - lo.y, lo.y + 1 - a.y};
	for (int i = 0; i < 4; i++) {
		if (p[i] == 0) {
			if (q[i] < 0)
				return false;
			continue;
		}
		double t = q[i] / p[i];
		if (p[i] < 0 && t > t0)
			t0 = t;
		if (p[i] > 0 && t < t1)
			t1 = t;
	}
	return t0 <= t1;
}

/* sweep_point_box_distance2(q, lo): the squared distance from q to the closed square
 * [lo, lo+1]^2 (squared, so that the inner loops need no square root). */
static double sweep_point_box_distance2(Vec2 q, Vec2 lo)
{
	double dx = fmax(0, fmax(lo.x - q.x, q.x - (lo.x + 1)));
	double dy = fmax(0, fmax(lo.y - q.y, q.y - (lo.y + 1)));
	return dx * dx + dy * dy;
}

/* sweep_point_segment_distance2(q, a, b): the squared distance from q to segment ab. */
static double sweep_point_segment_distance2(Vec2 q, Vec2 a, Vec2 b)
{
	Vec2 ab = vec2_sub(b, a), aq = vec2_sub(q, a);
	double len2 = vec2_dot(ab, ab), f = len2 > 0 ? vec2_dot(aq, ab) / len2 : 0;
	f = f < 0 ? 0 : f > 1 ? 1 : f;
	Vec2 d = vec2_sub(aq, vec2_scale(ab, f));
	return vec2_dot(d, d);
}

/* sweep_segment_box_distance2(a, b, lo): squared, from segment ab to the closed square. */
static double sweep_segment_box_distance2(Vec2 a, Vec2 b, Vec2 lo)
{
	if (sweep_segment_meets_box(a, b, lo))
		return 0;
	double d = fmin(sweep_point_box_distance2(a, lo), sweep_point_box_distance2(b, lo));
	const Vec2 corner[4] = {lo, vec2(lo.x + 1, lo.y), vec2(lo.x + 1, lo.y + 1), vec2(lo.x, lo.y + 1)};
	for (int k = 0; k < 4; k++)
		d = fmin(d, sweep_point_segment_distance2(corner[k], a, b));
	return d;
}

/* sweep_range(lo, hi, r, &c0, &c1): the cells whose squares can come within r of
 * [lo, hi] on one axis. */
static void sweep_range(double lo, double hi, double r, int32_t *c0, int32_t *c1)
{
	*c0 = (int32_t)floor(lo - r) - 1;
	*c1 = (int32_t)floor(hi + r) + 1;
}

/* No run open (cells may have any coordinate, negative ones included). */
#define SWEEP_NO_RUN INT32_MIN

/* sweep_emit(fn, ctx, y, x, run): ends a run of covered cells in row y at x - 1. */
static void sweep_emit(SweepSpanFn *fn, void *ctx, int32_t y, int32_t x, int32_t *run)
{
	if (*run != SWEEP_NO_RUN)
		fn(ctx, y, *run, x - 1);
	*run = SWEEP_NO_RUN;
}

/* sweep_near_segment(a, b, r, fn, ctx): the cells whose closed square comes nearer
 * than r to segment ab, row by row: in each row only the columns the segment,
 * thickened by r, can reach are tested. */
static void sweep_near_segment(Vec2 a, Vec2 b, double r, SweepSpanFn *fn, void *ctx)
{
	int32_t y0, y1;
	sweep_range(fmin(a.y, b.y), fmax(a.y, b.y), r, &y0, &y1);
	for (int32_t y = y0; y <= y1; y++) {
		/* The segment's x extent within the rows y - r .. y + 1 + r. */
		double lo = y - r, hi = y + 1 + r, t0 = 0, t1 = 1, dy = b.y - a.y;
		if (dy == 0) {
			if (a.y < lo || a.y > hi)
				continue;
		} else {
			double ta = (lo - a.y) / dy, tb = (hi - a.y) / dy;
			t0 = fmax(0, fmin(ta, tb));
			t1 = fmin(1, fmax(ta, tb));
			if (t0 > t1)
				continue;
		}
		double xa = a.x + t0 * (b.x - a.x), xb = a.x + t1 * (b.x - a.x);
		int32_t x0, x1, run = SWEEP_NO_RUN;
		sweep_range(fmin(xa, xb), fmax(xa, xb), r, &x0, &x1);
		for (int32_t x = x0; x <= x1; x++) {
			bool near = sweep_segment_box_distance2(a, b, vec2(x, y)) < r * r;
			if (near && run == SWEEP_NO_RUN)
				run = x;
			else if (!near)
				sweep_emit(fn, ctx, y, x, &run);
		}
		sweep_emit(fn, ctx, y, x1 + 1, &run);
	}
}

/* sweep_near_polygon(p, r, fn, ctx): a closed square comes nearer than r to p when
 * it meets p's interior (its open interior meets p: the projection) or comes nearer
 * than r to an edge (it touches p, or p's nearest point to it is on an edge). */
static void sweep_near_polygon(const Polygon *p, double r, SweepSpanFn *fn, void *ctx)
{
	sweep_project(p, fn, ctx);
	for (int32_t i = 0; i < p->count; i++)
		sweep_near_segment(p->v[i], p->v[(i + 1) % p->count], r, fn, ctx);
}

/* ---- the covers ------------------------------------------------------------------ */

void sweep_cover_polygon(const Polygon *p, double r, SweepSpanFn *fn, void *ctx)
{
	assert(r >= 0);
	if (r == 0)
		sweep_project(p, fn, ctx);
	else
		sweep_near_polygon(p, r, fn, ctx);
}

void sweep_cover_segment(Vec2 a, Vec2 b, double r, SweepSpanFn *fn, void *ctx)
{
	assert(r > 0);
	sweep_near_segment(a, b, r, fn, ctx);
}

void sweep_cover_push(const Polygon *p, Vec2 d, double r, SweepSpanFn *fn, void *ctx)
{
	sweep_cover_polygon(p, r, fn, ctx);
	if (d.x == 0 && d.y == 0)
		return;
	Polygon moved = *p;
	for (int32_t i = 0; i < p->count; i++)
		moved.v[i] = vec2_add(p->v[i], d);
	sweep_cover_polygon(&moved, r, fn, ctx);
	for (int32_t i = 0; i < p->count; i++) {
		Vec2 a = p->v[i], b = p->v[(i + 1) % p->count];
		if (vec2_cross(vec2_sub(b, a), d) == 0)
			continue; /* parallel to the push: see sweep.h */
		Polygon band = {.count = 4, .v = {a, b, vec2_add(b, d), vec2_add(a, d)}};
		sweep_cover_polygon(&band, r, fn, ctx);
	}
}

Polygon sweep_turned(const Polygon *rel, Vec2 pivot, double deg)
{
	double c, s;
	geom_cos_sin(deg, &c, &s);
	Polygon p = *rel;
	for (int32_t i = 0; i < p.count; i++) {
		Vec2 d = rel->v[i];
		/* geom_rotate's expression, term for term. */
		p.v[i] = vec2(pivot.x + c * d.x - s * d.y, pivot.y + s * d.x + c * d.y);
	}
	return p;
}

double sweep_reach(const Polygon *rel)
{
	double r = 0;
	for (int32_t i = 0; i < rel->count; i++)
		r = fmax(r, hypot(rel->v[i].x, rel->v[i].y));
	return r;
}

void sweep_cover_turn(const Polygon *rel, Vec2 pivot, double deg0, double deg1, SweepSpanFn *fn,
		      void *ctx)
{
	double span = fabs(deg1 - deg0) * (3.14159265358979323846 / 180.0);
	double travel = sweep_reach(rel) * span;
	int64_t samples = (int64_t)fmax(1, ceil(travel / SWEEP_TRAVEL));
	double r = travel / (2.0 * (double)samples) + SWEEP_EPS;
	for (int64_t k = 0; k <= samples; k++) {
		double deg = k == samples ? deg1 : deg0 + (deg1 - deg0) * (double)k / (double)samples;
		Polygon p = sweep_turned(rel, pivot, deg);
		sweep_cover_polygon(&p, r, fn, ctx);
	}
}

/* ---- the window ------------------------------------------------------------------ */

void sweep_window_init(SweepWindow *win, int32_t radius)
{
	assert(radius >= 1 && radius < 1 << 14);
	win->radius = radius;
	win->side = 2 * radius + 1;
	win->cell = util_alloc((size_t)win->side * (size_t)win->side, 1);
}

void sweep_window_free(SweepWindow *win)
{
	free(win->cell);
	*win = (SweepWindow){0};
}

void sweep_window_clear(SweepWindow *win)
{
	for (size_t i = 0; i < (size_t)win->side * (size_t)win->side; i++)
		win->cell[i] = 0;
}

void sweep_window_span(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	SweepWindow *win = ctx;
	assert(y >= -win->radius && y <= win->radius && x0 >= -win->radius && x1 <= win->radius);
	uint8_t *row = win->cell + (size_t)(y + win->radius) * (size_t)win->side + win->radius;
	for (int32_t x = x0; x <= x1; x++)
		row[x] = 1;
}

void sweep_window_runs(const SweepWindow *win, CSpaceFootprint *fp)
{
	fp->count = 0;
	for (int32_t y = -win->radius; y <= win->radius; y++) {
		const uint8_t *row = win->cell + (size_t)(y + win->radius) * (size_t)win->side;
		for (int32_t i = 0; i < win->side;) {
			if (!row[i]) {
				i++;
				continue;
			}
			int32_t j = i;
			while (j + 1 < win->side && row[j + 1])
				j++;
			fp->run = util_grow(fp->run, &fp->cap, fp->count + 1, sizeof *fp->run);
			fp->run[fp->count++] = (CSpaceRun){y, i - win->radius, j - win->radius};
			i = j + 1;
		}
	}
}
