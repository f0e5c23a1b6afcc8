/* cspace.c - configuration-space obstacles by erosion of the grid (paper 3.6 and 5:
 * room for a moved object). See cspace.h for the definitions.
 *
 * ALGORITHM: (1) the footprint: every square near the shape is tested against the
 * closed shape: covered when a shape edge meets the square's open interior
 * (Liang-Barsky clipping with strict bounds, Liang and Barsky 1984), or when the
 * square's centre is strictly inside the shape (crossing-number test), which
 * settles the squares no edge enters (wholly inside or wholly outside). Covered
 * cells of a row become runs. (2) The erosion: per row, the prefix sums of blocked
 * cells; a placement at (x, y) fits when, for every run, the range of cells it
 * names is inside the grid and holds no blocked cell (one subtraction per run).
 * This is the classic separable-box trick (summed-area ranges) applied to a
 * footprint cut into runs.
 *
 * INVARIANTS: footprint runs are sorted by (dy, dx0) and disjoint; prefix[y][x] is
 * the number of blocked cells among row y's columns 0 .. x-1.
 * COMPLEXITY: footprint O(A n) for A squares in the shape's box and n vertices;
 * erosion O(w h R) for R runs. */
#include "utak/plan/cspace.h"

#include <assert.h>
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

#include "utak/base/util.h"

void cspace_footprint_init(CSpaceFootprint *fp)
{
	*fp = (CSpaceFootprint){0};
}

void cspace_footprint_free(CSpaceFootprint *fp)
{
	free(fp->run);
	*fp = (CSpaceFootprint){0};
}

/* cspace_footprint_add(fp, dy, dx): adds cell (dx, dy); calls come in increasing
 * (dy, dx), so a cell right after the last run's end extends it. */
static void cspace_footprint_add(CSpaceFootprint *fp, int32_t dy, int32_t dx)
{
	if (fp->count > 0) {
		CSpaceRun *last = &fp->run[fp->count - 1];
		if (last->dy == dy && last->dx1 + 1 == dx) {
			last->dx1 = dx;
			return;
		}
	}
	fp->run = util_grow(fp->run, &fp->cap, fp->count + 1, sizeof *fp->run);
	fp->run[fp->count++] = (CSpaceRun){dy, dx, dx};
}

/* cspace_edge_meets_open_square(a, b, x0, y0): segment ab meets (x0, x0+1) x (y0, y0+1). */
static bool cspace_edge_meets_open_square(Vec2 a, Vec2 b, double x0, double y0)
{
	double lo = -INFINITY, hi = INFINITY;
	const double p[2] = {a.x, a.y}, d[2] = {b.x - a.x, b.y - a.y}, m[2] = {x0, y0};
	for (int k = 0; k < 2; k++) {
		if (d[k] == 0) {
			if (!(m[k] < p[k] && p[k] < m[k] + 1))
				return false;
			continue;
		}
		double t1 = (m[k] - p[k]) / d[k], t2 = (m[k] + 1 - p[k]) / d[k];
		if (t1 > t2) {
			double t = t1;
			t1 = t2;
			t2 = t;
		}
		lo = t1 > lo ? t1 : lo;
		hi = t2 < hi ? t2 : hi;
	}
	/* Some t in the open (lo, hi) and in the closed [0, 1]. */
	return lo < hi && lo < 1 && hi > 0;
}

/* cspace_strictly_inside(p, q): q is inside p, by crossing number (q not on an edge). */
static bool cspace_strictly_inside(const Polygon *p, Vec2 q)
{
	bool in = false;
	for (int i = 0, j = p->count - 1; i < p->count; j = i++) {
		Vec2 a = p->v[j], b = p->v[i];
		if ((a.y > q.y) != (b.y > q.y) &&
		    q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y))
			in = !in;
	}
	return in;
}

void cspace_footprint_polygon(CSpaceFootprint *fp, const Polygon *shape)
{
	assert(shape->count >= 3 && shape->count <= GEOM_MAX_VERTICES);
	fp->count = 0;
	/* The shape at the centre of cell (0, 0). */
	Polygon p = *shape;
	double minx = INFINITY, miny = INFINITY, maxx = -INFINITY, maxy = -INFINITY;
	for (int i = 0; i < p.count; i++) {
		p.v[i] = vec2_add(p.v[i], vec2(0.5, 0.5));
		minx = fmin(minx, p.v[i].x);
		maxx = fmax(maxx, p.v[i].x);
		miny = fmin(miny, p.v[i].y);
		maxy = fmax(maxy, p.v[i].y);
	}
	for (double y = floor(miny) - 1; y <= floor(maxy) + 1; y++)
		for (double x = floor(minx) - 1; x <= floor(maxx) + 1; x++) {
			bool covered = cspace_strictly_inside(&p, vec2(x + 0.5, y + 0.5));
			for (int i = 0, j = p.count - 1; i < p.count && !covered; j = i++)
				covered = cspace_edge_meets_open_square(p.v[j], p.v[i], x, y);
			if (covered)
				cspace_footprint_add(fp, (int32_t)y, (int32_t)x);
		}
}

void cspace_footprint_disc(CSpaceFootprint *fp, double radius)
{
	assert(radius >= 0);
	fp->count = 0;
	int32_t reach = (int32_t)ceil(radius) + 1;
	for (int32_t dy = -reach; dy <= reach; dy++)
		for (int32_t dx = -reach; dx <= reach; dx++) {
			/* The nearest point of square (dx, dy) to the centre (0.5, 0.5). */
			double nx = fmax(0, fmax(dx - 0.5, 0.5 - (dx + 1)));
			double ny = fmax(0, fmax(dy - 0.5, 0.5 - (dy + 1)));
			/* The own square always (the centre is inside it); another when it comes
			 * strictly closer than the radius (at exactly the radius the disc only
			 * touches its border). */
			if ((dx == 0 && dy == 0) || nx * nx + ny * ny < radius * radius)
				cspace_footprint_add(fp, dy, dx);
		}
}

void cspace_erode_footprint(const Grid *in, const CSpaceFootprint *fp, Grid *out)
{
	assert(out->w == in->w && out->h == in->h && out->cells != in->cells);
	const int32_t w = in->w, h = in->h;
	int32_t *prefix = util_alloc((size_t)(w + 1) * (size_t)h, sizeof *prefix);
	for (int32_t y = 0; y < h; y++) {
		int32_t *row = prefix + (size_t)y * (w + 1);
		const uint8_t *cells = in->cells + (size_t)y * w;
		for (int32_t x = 0; x < w; x++)
			row[x + 1] = row[x] + (cells[x] != GRID_FREE);
	}
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++) {
			bool fits = true; /* an empty footprint covers nothing */
			for (int k = 0; k < fp->count && fits; k++) {
				const CSpaceRun *r = &fp->run[k];
				int32_t yy = y + r->dy, x0 = x + r->dx0, x1 = x + r->dx1;
				if (yy < 0 || yy >= h || x0 < 0 || x1 >= w) {
					fits = false;
					break;
				}
				const int32_t *row = prefix + (size_t)yy * (w + 1);
				fits = row[x1 + 1] - row[x0] == 0;
			}
			out->cells[(size_t)y * w + x] = fits ? GRID_FREE : GRID_BLOCKED;
		}
	free(prefix);
}

void cspace_erode(const Grid *in, const Polygon *shape_at_origin, Grid *out)
{
	CSpaceFootprint fp;
	cspace_footprint_init(&fp);
	cspace_footprint_polygon(&fp, shape_at_origin);
	cspace_erode_footprint(in, &fp, out);
	cspace_footprint_free(&fp);
}

void cspace_erode_disc(const Grid *in, double radius, Grid *out)
{
	CSpaceFootprint fp;
	cspace_footprint_init(&fp);
	cspace_footprint_disc(&fp, radius);
	cspace_erode_footprint(in, &fp, out);
	cspace_footprint_free(&fp);
}
