/* test_cspace.c - configuration-space erosion (cspace.h) against a brute-force
 * placement: for every cell, the shape is put at the cell's centre and every square
 * near it is tested by clipping the shape to the square (Sutherland-Hodgman) and
 * measuring the area left: a closed polygon meets an open square exactly when their
 * intersection has positive area. Random grids, random triangles, L-shapes and star
 * polygons with coordinates on a half-unit lattice, so that exact touching occurs. */
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "utak/plan/cspace.h"

static uint32_t rng_state = 1013904223u;
static uint32_t rng_next(void)
{
	rng_state ^= rng_state << 13;
	rng_state ^= rng_state >> 17;
	rng_state ^= rng_state << 5;
	return rng_state;
}

/* Half-units in [-k, k]. */
static double rng_half(int k)
{
	return ((int)(rng_next() % (uint32_t)(4 * k + 1)) - 2 * k) * 0.5;
}

/* clip_area: the area of polygon p (n vertices) inside the square [x0, x0+1] x
 * [y0, y0+1], by clipping against its four sides in turn. */
static double clip_area(const Vec2 *p, int n, double x0, double y0)
{
	Vec2 a[4 * GEOM_MAX_VERTICES + 8], b[4 * GEOM_MAX_VERTICES + 8];
	int na = n;
	memcpy(a, p, (size_t)n * sizeof *p);
	for (int side = 0; side < 4; side++) {
		int nb = 0;
		for (int i = 0; i < na; i++) {
			Vec2 s = a[i], e = a[(i + 1) % na];
			/* Signed distance inside the half-plane of this side. */
			double ds = side == 0   ? s.x - x0
			            : side == 1 ? x0 + 1 - s.x
			            : side == 2 ? s.y - y0
			                        : y0 + 1 - s.y;
			double de = side == 0   ? e.x - x0
			            : side == 1 ? x0 + 1 - e.x
			            : side == 2 ? e.y - y0
			                        : y0 + 1 - e.y;
			if (ds >= 0)
				b[nb++] = s;
			if ((ds >= 0) != (de >= 0)) {
				double t = ds / (ds - de);
				b[nb++] = vec2(s.x + (e.x - s.x) * t, s.y + (e.y - s.y) * t);
			}
		}
		na = nb;
		memcpy(a, b, (size_t)nb * sizeof *b);
		if (na == 0)
			return 0;
	}
	double area = 0;
	for (int i = 0; i < na; i++)
		area += vec2_cross(a[i], a[(i + 1) % na]);
	return fabs(area) / 2;
}

/* brute_fits: the shape at the centre of (cx, cy) covers only free cells. */
static bool brute_fits(const Grid *g, const Polygon *shape, int cx, int cy)
{
	Vec2 p[GEOM_MAX_VERTICES];
	double minx = INFINITY, miny = INFINITY, maxx = -INFINITY, maxy = -INFINITY;
	for (int i = 0; i < shape->count; i++) {
		p[i] = vec2(shape->v[i].x + cx + 0.5, shape->v[i].y + cy + 0.5);
		minx = fmin(minx, p[i].x);
		maxx = fmax(maxx, p[i].x);
		miny = fmin(miny, p[i].y);
		maxy = fmax(maxy, p[i].y);
	}
	for (int y = (int)floor(miny) - 1; y <= (int)floor(maxy) + 1; y++)
		for (int x = (int)floor(minx) - 1; x <= (int)floor(maxx) + 1; x++)
			if (!grid_free_at(g, x, y) && clip_area(p, shape->count, x, y) > 1e-12)
				return false;
	return true;
}

static void random_shape(Polygon *s)
{
	switch (rng_next() % 3) {
	case 0: /* a triangle of non-zero area */
		do {
			s->count = 3;
			for (int i = 0; i < 3; i++)
				s->v[i] = vec2(rng_half(2), rng_half(2));
		} while (vec2_cross(vec2_sub(s->v[1], s->v[0]), vec2_sub(s->v[2], s->v[0])) == 0);
		break;
	case 1: { /* an L: a box with a corner box cut away */
		double x0 = -rng_half(2) - 0.5, y0 = -rng_half(2) - 0.5;
		x0 = x0 > -0.5 ? -0.5 : x0;
		y0 = y0 > -0.5 ? -0.5 : y0;
		double x2 = 0.5 + fabs(rng_half(2)), y2 = 0.5 + fabs(rng_half(2));
		double x1 = x0 + (x2 - x0) * 0.5, y1 = y0 + (y2 - y0) * 0.5;
		Vec2 v[6] = {{x0, y0}, {x2, y0}, {x2, y1}, {x1, y1}, {x1, y2}, {x0, y2}};
		s->count = 6;
		memcpy(s->v, v, sizeof v);
		break;
	}
	default: { /* a star polygon: increasing angles, random radii (always simple) */
		s->count = 3 + (int)(rng_next() % 8);
		for (int i = 0; i < s->count; i++) {
			double a = 2 * acos(-1.0) * (i + 0.2 + 0.6 * (rng_next() % 1000) / 1000.0) /
			           s->count;
			double r = 0.3 + 2.5 * (rng_next() % 1000) / 1000.0;
			s->v[i] = vec2(r * cos(a), r * sin(a));
		}
		break;
	}
	}
}

TEST_CASE(cspace_polygon_equals_brute_force)
{
	for (int trial = 0; trial < 250; trial++) {
		int w = 1 + (int)(rng_next() % 16), h = 1 + (int)(rng_next() % 16);
		Grid g, out;
		grid_init(&g, w, h, GRID_FREE);
		grid_init(&out, w, h, GRID_BLOCKED);
		int density = (int)(rng_next() % 25);
		for (int i = 0; i < w * h; i++)
			if ((int)(rng_next() % 100) < density)
				g.cells[i] = GRID_BLOCKED;
		Polygon shape;
		random_shape(&shape);
		cspace_erode(&g, &shape, &out);
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				bool want = brute_fits(&g, &shape, x, y);
				if (want != (out.cells[y * w + x] == GRID_FREE))
					fprintf(stderr,
					        "  trial %d cell (%d, %d): brute force %d\n", trial,
					        x, y, want);
				TEST_CHECK(want == (out.cells[y * w + x] == GRID_FREE));
			}
		grid_free(&g);
		grid_free(&out);
	}
}

TEST_CASE(cspace_footprint_by_hand)
{
	/* The unit square centred on the reference point covers its own cell only
	 * (it touches the neighbours along their borders); shifted by a half, four. */
	Polygon sq = {4, {{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}};
	CSpaceFootprint fp;
	cspace_footprint_init(&fp);
	cspace_footprint_polygon(&fp, &sq);
	TEST_CHECK(fp.count == 1 && fp.run[0].dy == 0 && fp.run[0].dx0 == 0 && fp.run[0].dx1 == 0);
	for (int i = 0; i < 4; i++)
		sq.v[i] = vec2_add(sq.v[i], vec2(0.5, 0.5));
	cspace_footprint_polygon(&fp, &sq);
	TEST_CHECK(fp.count == 2 && fp.run[0].dx0 == 0 && fp.run[0].dx1 == 1 && fp.run[1].dy == 1);
	/* Discs: radius 0.5 touches the edge neighbours only; 0.6 reaches them; 0.75
	 * reaches the diagonal ones (sqrt 0.5 = 0.707 away). */
	cspace_footprint_disc(&fp, 0.5);
	TEST_CHECK(fp.count == 1 && fp.run[0].dx0 == 0 && fp.run[0].dx1 == 0);
	cspace_footprint_disc(&fp, 0.6);
	TEST_CHECK(fp.count == 3 && fp.run[1].dx0 == -1 && fp.run[1].dx1 == 1 &&
	           fp.run[0].dx0 == 0);
	cspace_footprint_disc(&fp, 0.75);
	TEST_CHECK(fp.count == 3 && fp.run[0].dx0 == -1 && fp.run[2].dx1 == 1);
	cspace_footprint_free(&fp);
}

TEST_CASE(cspace_disc_equals_brute_force)
{
	for (int trial = 0; trial < 200; trial++) {
		int w = 1 + (int)(rng_next() % 20), h = 1 + (int)(rng_next() % 20);
		Grid g, out;
		grid_init(&g, w, h, GRID_FREE);
		grid_init(&out, w, h, GRID_BLOCKED);
		for (int i = 0; i < w * h; i++)
			if (rng_next() % 100 < 8)
				g.cells[i] = GRID_BLOCKED;
		/* Radii on a quarter lattice hit exact touching; others in between. */
		double r = trial % 2 ? (rng_next() % 13) * 0.25 : (rng_next() % 1000) * 0.003;
		cspace_erode_disc(&g, r, &out);
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				/* Brute force: the disc about the centre against every square,
				 * including outside ones, by the distance to the square. */
				double cx = x + 0.5, cy = y + 0.5;
				bool fits = true;
				for (int yy = y - 5; yy <= y + 5 && fits; yy++)
					for (int xx = x - 5; xx <= x + 5 && fits; xx++) {
						if (grid_free_at(&g, xx, yy))
							continue;
						double nx = fmin(fmax(cx, xx), xx + 1) - cx;
						double ny = fmin(fmax(cy, yy), yy + 1) - cy;
						bool inside = xx < cx && cx < xx + 1 && yy < cy &&
						              cy < yy + 1;
						if (inside || nx * nx + ny * ny < r * r)
							fits = false;
					}
				TEST_CHECK(fits == (out.cells[y * w + x] == GRID_FREE));
			}
		grid_free(&g);
		grid_free(&out);
	}
}

int main(void)
{
	TEST_RUN(cspace_polygon_equals_brute_force);
	TEST_RUN(cspace_footprint_by_hand);
	TEST_RUN(cspace_disc_equals_brute_force);
	return TEST_EXIT();
}
