/* test_sweep.c - the squares a moving polygon covers (sweep.h), against oracles
 * written apart from sweep.c:
 *   - a pose within r: every square tested by the exact distance between the closed
 *     square and the polygon (segment to segment, in squared form);
 *   - a pose at r = 0: projection_oracle.h, square by square;
 *   - a push: a square is covered exactly when its open interior, swept back along
 *     the push (an open convex hexagon), meets the closed polygon, decided by
 *     clipping the polygon's edges to the hexagon (Cyrus-Beck) as the projection
 *     oracle clips them to a square;
 *   - a turn: never less than the union of 400 poses along it.
 * Random polygons (triangles, L-shapes, stars) with coordinates on a half-square
 * lattice, so that edges lie on grid lines and corners touch, and off it. */
#include <stdlib.h>
#include <string.h>

#include "oracle.h"
#include "projection_oracle.h"
#include "test.h"
#include "utak/plan/sweep.h"

/* A set of cells in a window [-R, R]^2, filled by a span sink. */
enum { R = 40, SIDE = 2 * R + 1 };

typedef struct Cells {
	uint8_t on[SIDE * SIDE];
} Cells;

static void cells_span(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	Cells *c = ctx;
	for (int32_t x = x0; x <= x1; x++) {
		TEST_CHECK(x >= -R && x <= R && y >= -R && y <= R);
		c->on[(y + R) * SIDE + x + R] = 1;
	}
}

static bool cells_has(const Cells *c, int x, int y) { return c->on[(y + R) * SIDE + x + R]; }

static double coordinate(bool lattice)
{
	return lattice ? oracle_rand_below(25) * 0.5 - 6 : (oracle_rand_below(24001) - 12000) / 1000.0;
}

/* random_polygon(p, lattice): a simple polygon of 3 to 8 vertices within [-8, 8]^2. */
static void random_polygon(Polygon *p, bool lattice)
{
	do {
		int kind = oracle_rand_below(3);
		if (kind == 0) {
			p->count = 3;
			for (int i = 0; i < 3; i++)
				p->v[i] = vec2(coordinate(lattice), coordinate(lattice));
		} else if (kind == 1) {
			double x = coordinate(lattice), y = coordinate(lattice);
			double a = 1 + oracle_rand_below(6), b = 1 + oracle_rand_below(6), t = 0.5 + oracle_rand_below(3) * 0.5;
			*p = (Polygon){6, {{x, y}, {x + a, y}, {x + a, y + t}, {x + t, y + t}, {x + t, y + b}, {x, y + b}}};
		} else {
			double cx = coordinate(lattice) / 2, cy = coordinate(lattice) / 2;
			p->count = 8;
			for (int i = 0; i < 8; i++) {
				double r = i % 2 ? 1 + oracle_rand_below(3) : 3 + oracle_rand_below(4);
				/* Off the axes: a star point on a grid line by rounding
				 * would make the oracles disagree by 1e-16. */
				double a = i * 3.14159265358979323846 / 4 + 0.1234;
				p->v[i] = vec2(cx + r * cos(a), cy + r * sin(a));
			}
		}
	} while (!geom_polygon_is_simple(p));
}

/* square_distance2(p, x, y): the squared distance between the closed square and p. */
static double square_distance2(const Polygon *p, int x, int y)
{
	Vec2 sq[4] = {vec2(x, y), vec2(x + 1, y), vec2(x + 1, y + 1), vec2(x, y + 1)};
	if (geom_point_in_polygon(p, vec2(x + 0.5, y + 0.5)))
		return 0;
	double least = INFINITY;
	for (int i = 0; i < p->count; i++) {
		Vec2 a = p->v[i], b = p->v[(i + 1) % p->count];
		for (int k = 0; k < 4; k++) {
			Vec2 c = sq[k], d = sq[(k + 1) % 4];
			if (geom_segments_meet(a, b, c, d))
				return 0;
			Vec2 ends[4] = {a, b, c, d};
			for (int e = 0; e < 4; e++) {
				Vec2 q = ends[e], s0 = e < 2 ? c : a, s1 = e < 2 ? d : b;
				double dx = s1.x - s0.x, dy = s1.y - s0.y, len2 = dx * dx + dy * dy;
				double t = len2 > 0 ? ((q.x - s0.x) * dx + (q.y - s0.y) * dy) / len2 : 0;
				t = t < 0 ? 0 : t > 1 ? 1 : t;
				double ex = s0.x + t * dx - q.x, ey = s0.y + t * dy - q.y;
				least = fmin(least, ex * ex + ey * ey);
			}
		}
		if (a.x >= x && a.x <= x + 1 && a.y >= y && a.y <= y + 1)
			return 0;
	}
	return least;
}

TEST_CASE(pose_within_r_against_distances)
{
	oracle_seed = 31;
	static const double rs[3] = {SWEEP_EPS, 0.125, 0.4};
	for (int t = 0; t < 300; t++) {
		Polygon p;
		random_polygon(&p, t % 2 == 0);
		double r = rs[t % 3];
		static Cells got;
		memset(&got, 0, sizeof got);
		sweep_cover_polygon(&p, r, cells_span, &got);
		for (int y = -12; y <= 12; y++)
			for (int x = -12; x <= 12; x++)
				TEST_CHECK(cells_has(&got, x, y) == (square_distance2(&p, x, y) < r * r));
	}
}

TEST_CASE(pose_exact_against_the_projection_oracle)
{
	/* Shifted far off the origin and to negative coordinates: the projection
	 * by whole-square shifts keeps every coincidence. */
	oracle_seed = 32;
	for (int t = 0; t < 300; t++) {
		Polygon p;
		random_polygon(&p, t % 2 == 0);
		static Cells got;
		memset(&got, 0, sizeof got);
		sweep_cover_polygon(&p, 0, cells_span, &got);
		for (int y = -12; y <= 12; y++)
			for (int x = -12; x <= 12; x++)
				TEST_CHECK(cells_has(&got, x, y) == oracle(&p, x, y));
	}
}

/* inside_open(h, n, q): q strictly inside the convex polygon h (counter-clockwise). */
static bool inside_open(const Vec2 *h, int n, Vec2 q)
{
	for (int i = 0; i < n; i++)
		if (!(geom_orient(h[i], h[(i + 1) % n], q) > 0))
			return false;
	return true;
}

/* chord_in(h, n, a, b, &mid): Cyrus-Beck: the part of segment ab inside the closed
 * convex polygon h; its midpoint in mid. False when none. */
static bool chord_in(const Vec2 *h, int n, Vec2 a, Vec2 b, Vec2 *mid)
{
	double t0 = 0, t1 = 1;
	for (int i = 0; i < n; i++) {
		Vec2 e0 = h[i], e1 = h[(i + 1) % n];
		double fa = geom_orient(e0, e1, a), fb = geom_orient(e0, e1, b);
		/* inside is f >= 0; f(t) = fa + t (fb - fa) */
		if (fa < 0 && fb < 0)
			return false;
		if (fa == fb)
			continue;
		double t = fa / (fa - fb);
		if (fb < fa)
			t1 = fmin(t1, t);
		else
			t0 = fmax(t0, t);
	}
	if (t0 > t1)
		return false;
	double tm = (t0 + t1) / 2;
	*mid = vec2(a.x + tm * (b.x - a.x), a.y + tm * (b.y - a.y));
	return true;
}

/* swept_oracle(p, d, x, y): the open square (x, y) meets p + t d for some t in [0, 1]. */
static bool swept_oracle(const Polygon *p, Vec2 d, int x, int y)
{
	/* The open square swept back by -t d: the convex hull of its corners and
	 * the corners moved by -d, counter-clockwise (gift wrapping of 8 points). */
	Vec2 pts[8], h[8];
	for (int k = 0; k < 4; k++) {
		pts[k] = vec2(x + (k == 1 || k == 2), y + (k >= 2));
		pts[k + 4] = vec2(pts[k].x - d.x, pts[k].y - d.y);
	}
	int start = 0;
	for (int k = 1; k < 8; k++)
		if (pts[k].x < pts[start].x || (pts[k].x == pts[start].x && pts[k].y < pts[start].y))
			start = k;
	int n = 0, cur = start;
	do {
		h[n++] = pts[cur];
		int next = (cur + 1) % 8;
		for (int k = 0; k < 8; k++) {
			double o = geom_orient(pts[cur], pts[next], pts[k]);
			double dk = hypot(pts[k].x - pts[cur].x, pts[k].y - pts[cur].y);
			double dn = hypot(pts[next].x - pts[cur].x, pts[next].y - pts[cur].y);
			if (o < 0 || (o == 0 && dk > dn))
				next = k;
		}
		cur = next;
	} while (cur != start && n < 8);
	for (int i = 0; i < p->count; i++) {
		if (inside_open(h, n, p->v[i]))
			return true;
		Vec2 mid;
		if (chord_in(h, n, p->v[i], p->v[(i + 1) % p->count], &mid) && inside_open(h, n, mid))
			return true;
	}
	/* No edge enters the hull: it is wholly inside p or wholly outside. */
	Vec2 c = {0, 0};
	for (int i = 0; i < n; i++)
		c = vec2(c.x + h[i].x / n, c.y + h[i].y / n);
	return geom_point_in_polygon(p, c);
}

TEST_CASE(push_against_the_swept_square)
{
	oracle_seed = 33;
	for (int t = 0; t < 300; t++) {
		Polygon p;
		random_polygon(&p, t % 2 == 0);
		Vec2 d = t % 3 == 0 ? vec2(oracle_rand_below(9) - 4, 0)
			 : t % 3 == 1 ? vec2(oracle_rand_below(9) - 4, oracle_rand_below(9) - 4)
				      : vec2(coordinate(false) / 2, coordinate(false) / 2);
		static Cells got;
		memset(&got, 0, sizeof got);
		sweep_cover_push(&p, d, 0, cells_span, &got);
		for (int y = -16; y <= 16; y++)
			for (int x = -16; x <= 16; x++)
				TEST_CHECK(cells_has(&got, x, y) == swept_oracle(&p, d, x, y));
	}
}

TEST_CASE(turn_covers_every_pose_along_it)
{
	oracle_seed = 34;
	for (int t = 0; t < 120; t++) {
		Polygon p;
		random_polygon(&p, t % 2 == 0);
		Vec2 pivot = vec2(coordinate(false) / 4, coordinate(false) / 4);
		Polygon rel = p;
		for (int i = 0; i < p.count; i++)
			rel.v[i] = vec2_sub(p.v[i], pivot);
		double deg0 = oracle_rand_below(360), deg1 = deg0 + oracle_rand_below(61) - 30;
		static Cells got;
		memset(&got, 0, sizeof got);
		sweep_cover_turn(&rel, pivot, deg0, deg1, cells_span, &got);
		for (int k = 0; k <= 400; k++) {
			Polygon q = sweep_turned(&rel, pivot, deg0 + (deg1 - deg0) * k / 400.0);
			Box b = geom_polygon_box(&q);
			for (int y = (int)floor(b.lo.y) - 1; y <= (int)floor(b.hi.y) + 1; y++)
				for (int x = (int)floor(b.lo.x) - 1; x <= (int)floor(b.hi.x) + 1; x++)
					TEST_CHECK(!oracle(&q, x, y) || cells_has(&got, x, y));
		}
	}
}

TEST_CASE(window_runs_hold_the_marked_cells)
{
	oracle_seed = 35;
	SweepWindow win;
	sweep_window_init(&win, 12);
	CSpaceFootprint fp;
	cspace_footprint_init(&fp);
	for (int t = 0; t < 50; t++) {
		Polygon p;
		random_polygon(&p, true);
		sweep_window_clear(&win);
		sweep_cover_polygon(&p, 0, sweep_window_span, &win);
		sweep_window_runs(&win, &fp);
		int count = 0;
		for (int i = 0; i < fp.count; i++) {
			TEST_CHECK(i == 0 || fp.run[i].dy > fp.run[i - 1].dy ||
				   (fp.run[i].dy == fp.run[i - 1].dy && fp.run[i].dx0 > fp.run[i - 1].dx1 + 1));
			for (int x = fp.run[i].dx0; x <= fp.run[i].dx1; x++) {
				TEST_CHECK(oracle(&p, x, fp.run[i].dy));
				count++;
			}
		}
		int want = 0;
		for (int y = -12; y <= 12; y++)
			for (int x = -12; x <= 12; x++)
				want += oracle(&p, x, y);
		TEST_CHECK(count == want);
	}
	cspace_footprint_free(&fp);
	sweep_window_free(&win);
}

int main(void)
{
	TEST_RUN(pose_within_r_against_distances);
	TEST_RUN(pose_exact_against_the_projection_oracle);
	TEST_RUN(push_against_the_swept_square);
	TEST_RUN(turn_covers_every_pose_along_it);
	TEST_RUN(window_runs_hold_the_marked_cells);
	return TEST_EXIT();
}
