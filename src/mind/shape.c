/* shape.c - naming an object by its shape at any angle (paper 2.3; doc/verdicts.md).
 * CONTROLLER SIDE. The measures and their tolerances are in shape.h.
 *
 * ALGORITHM.
 * 1. The squares in their bounding box, SHAPE_MARGIN squares of margin round it;
 *    holes (empty squares the margin cannot reach, 4-connected) filled.
 * 2. The convex hulls of the boundary squares' centres and of their corner
 *    points, by Andrew's monotone chain (A. M. Andrew, "Another efficient
 *    algorithm for convex hulls in two dimensions", 1979), in exact integer
 *    arithmetic (half squares), collinear points dropped.
 * 3. The minimum-area enclosing rectangle of the centres' hull: one of its sides
 *    lies along a hull edge (Freeman and Shapira 1975), so each edge is tried.
 * 4. Notch depth: the deepest point of the set's outline (a lattice point with
 *    squares of the set and outside it round it) inside the corners' hull.
 * 5. The fits (shapefit.c): a rectangle where the centres' hull fills its
 *    rectangle and there is no deep notch; where none fits, a triangle, then an
 *    L-shape where there is a notch; the best within tolerance names the set.
 * INVARIANTS: the hulls are counter-clockwise with no three collinear vertices. */
#include "utak/mind/shape.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>

#include "utak/base/geom.h"
#include "utak/base/util.h"
#include "utak/mind/shapefit.h"

typedef struct Point {
	int64_t x, y;
} Point;

/* mask_fill_holes(m): empty cells the margin cannot reach become part of the set;
 * returns how many squares the set then has. */
static int32_t mask_fill_holes(ShapeMask *m)
{
	int64_t n = (int64_t)m->w * m->h;
	uint8_t *outside = util_alloc((size_t)n, 1);
	int64_t *stack = util_alloc((size_t)n, sizeof *stack);
	int64_t top = 0;
	stack[top++] = 0; /* cell (0, 0) is margin */
	outside[0] = 1;
	while (top > 0) {
		int64_t k = stack[--top];
		int32_t i = (int32_t)(k % m->w), j = (int32_t)(k / m->w);
		static const int8_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
		for (int d = 0; d < 4; d++) {
			int32_t a = i + step[d][0], b = j + step[d][1];
			if (a < 0 || b < 0 || a >= m->w || b >= m->h)
				continue;
			int64_t kk = (int64_t)b * m->w + a;
			if (!m->in[kk] && !outside[kk]) {
				outside[kk] = 1;
				stack[top++] = kk;
			}
		}
	}
	int32_t count = 0;
	for (int64_t k = 0; k < n; k++) {
		if (!outside[k])
			m->in[k] = 1;
		count += m->in[k];
	}
	free(stack);
	free(outside);
	return count;
}

/* mask_band(m): the cells within SHAPE_BAND (Chebyshev) of a cell of the other
 * kind: where a model near the set can disagree with it. */
static void mask_band(ShapeMask *m)
{
	m->band = util_alloc((size_t)m->w * (size_t)m->h, sizeof *m->band);
	m->band_count = 0;
	for (int32_t j = 0; j < m->h; j++)
		for (int32_t i = 0; i < m->w; i++) {
			bool in = shapefit_mask_at(m, i, j), near = false;
			for (int32_t dj = -SHAPE_BAND; dj <= SHAPE_BAND && !near; dj++)
				for (int32_t di = -SHAPE_BAND; di <= SHAPE_BAND && !near; di++)
					near = shapefit_mask_at(m, i + di, j + dj) != in;
			if (near)
				m->band[m->band_count++] = j * m->w + i;
		}
}

static int64_t cross(Point o, Point a, Point b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

static int point_order(const void *pa, const void *pb)
{
	const Point *a = pa, *b = pb;
	if (a->x != b->x)
		return a->x < b->x ? -1 : 1;
	return (a->y > b->y) - (a->y < b->y);
}

/* hull_of(m, &count): the convex hull of the corners of the set's squares,
 * counter-clockwise, in mask cell units. */
static Point *hull_of(const ShapeMask *m, bool centres, int32_t *count)
{
	int32_t cap = 0;
	for (int32_t j = 0; j < m->h; j++)
		for (int32_t i = 0; i < m->w; i++)
			cap += shapefit_mask_at(m, i, j) ? 4 : 0;
	Point *p = util_alloc((size_t)cap + 1, sizeof *p);
	int32_t n = 0;
	for (int32_t j = 0; j < m->h; j++)
		for (int32_t i = 0; i < m->w; i++) {
			if (!shapefit_mask_at(m, i, j))
				continue;
			/* Only the squares on the boundary can give hull points. */
			if (shapefit_mask_at(m, i - 1, j) && shapefit_mask_at(m, i + 1, j) && shapefit_mask_at(m, i, j - 1) && shapefit_mask_at(m, i, j + 1))
				continue;
			if (centres)
				p[n++] = (Point){2 * i + 1, 2 * j + 1};
			else
				for (int c = 0; c < 4; c++)
					p[n++] = (Point){2 * (i + (c & 1)), 2 * (j + (c >> 1))};
		}
	qsort(p, (size_t)n, sizeof *p, point_order);
	Point *h = util_alloc((size_t)n * 2 + 2, sizeof *h);
	int32_t k = 0;
	for (int32_t i = 0; i < n; i++) { /* lower chain */
		while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0)
			k--;
		h[k++] = p[i];
	}
	for (int32_t i = n - 2, lower = k + 1; i >= 0; i--) { /* upper chain */
		while (k >= lower && cross(h[k - 2], h[k - 1], p[i]) <= 0)
			k--;
		h[k++] = p[i];
	}
	free(p);
	*count = k > 1 ? k - 1 : k; /* the last point repeats the first */
	return h;
}

static double hull_area(const Vec2 *h, int32_t n)
{
	double twice = 0;
	for (int32_t i = 0; i < n; i++)
		twice += h[i].x * h[(i + 1) % n].y - h[(i + 1) % n].x * h[i].y;
	return twice / 2;
}

/* hull_vertices(m, centres, &count): hull_of in squares. */
static Vec2 *hull_vertices(const ShapeMask *m, bool centres, int32_t *count)
{
	Point *hp = hull_of(m, centres, count);
	Vec2 *h = util_alloc((size_t)*count + 1, sizeof *h);
	for (int32_t i = 0; i < *count; i++)
		h[i] = vec2(hp[i].x / 2.0, hp[i].y / 2.0); /* hull_of works in half squares */
	free(hp);
	return h;
}

/* depth_in_hull(h, n, x, y): how far (x, y) lies inside the hull: the least distance
 * to an edge's line (negative outside). */
static double depth_in_hull(const Vec2 *h, int32_t n, double x, double y)
{
	double depth = INFINITY;
	for (int32_t i = 0; i < n; i++) {
		Vec2 a = h[i], b = h[(i + 1) % n];
		double ex = b.x - a.x, ey = b.y - a.y;
		double d = (ex * (y - a.y) - ey * (x - a.x)) / hypot(ex, ey);
		depth = d < depth ? d : depth;
	}
	return depth;
}

static Rect min_area_rect(const Vec2 *h, int32_t n)
{
	Rect best = {0};
	double best_area = INFINITY;
	for (int32_t i = 0; i < n; i++) {
		Vec2 p = h[i], q = h[(i + 1) % n];
		double len = hypot(q.x - p.x, q.y - p.y);
		Rect r = shapefit_rect_along(h, n, (q.x - p.x) / len, (q.y - p.y) / len);
		if (r.a * r.b < best_area - 1e-9) {
			best_area = r.a * r.b;
			best = r;
		}
	}
	return best;
}

/* notch_depth(m, h, n): the deepest point of the set's outline inside the hull. */
static double notch_depth(const ShapeMask *m, const Vec2 *h, int32_t n)
{
	double deepest = 0;
	for (int32_t y = 0; y <= m->h; y++)
		for (int32_t x = 0; x <= m->w; x++) {
			int in = shapefit_mask_at(m, x - 1, y - 1) + shapefit_mask_at(m, x, y - 1) + shapefit_mask_at(m, x - 1, y) + shapefit_mask_at(m, x, y);
			if (in == 0 || in == 4)
				continue;
			double d = depth_in_hull(h, n, x, y);
			deepest = d > deepest ? d : deepest;
		}
	return deepest;
}

/* spread_less_square(h, n, t): how far the points h spread across the direction
 * at t radians, less a square's own extent across it. */
static double spread_less_square(const Vec2 *h, int32_t n, double t)
{
	double ux = cos(t), uy = sin(t), lo = INFINITY, hi = -INFINITY;
	for (int32_t i = 0; i < n; i++) {
		double p = h[i].x * ux + h[i].y * uy;
		lo = fmin(lo, p);
		hi = fmax(hi, p);
	}
	return hi - lo - (fabs(ux) + fabs(uy));
}

/* least_width(h, n): the width every polygon whose digital representation has
 * these square centres on its hull exceeds (shape.h, min_width). Across a
 * direction u the centres of the squares a polygon P meets spread less than P
 * does plus a square's own extent across u, |ux| + |uy| (each square's open
 * interior meets P, and its centre lies within half that of the meeting point);
 * so P's width, its least extent, exceeds the least over u of the centres'
 * spread less |ux| + |uy|, and a polygon of thin parts can come as near to it as
 * it likes. That measure is, within each quadrant of u, the support function of
 * a fixed polygon (the centres' difference set, shifted), whose least value over
 * an arc, where positive, lies at the arc's ends or at a normal of one of its
 * edges, which are the normals of the hull's edges: those directions, and the
 * axes, are tried. Samples every SHAPE_WIDTH_STEP degrees catch a least value
 * at or under 0, where that does not hold. */
static double least_width(const Vec2 *h, int32_t n)
{
	if (n <= 0)
		return 0;
	const double rad = atan(1.0) / 45;
	double least = fmin(spread_less_square(h, n, 0), spread_less_square(h, n, 90 * rad));
	for (int32_t i = 0; i < n; i++) {
		Vec2 a = h[i], b = h[(i + 1) % n];
		if (a.x != b.x || a.y != b.y)
			least = fmin(least, spread_less_square(h, n, atan2(b.x - a.x, -(b.y - a.y))));
	}
	for (int k = 0; k * SHAPE_WIDTH_STEP < 180; k++)
		least = fmin(least, spread_less_square(h, n, k * SHAPE_WIDTH_STEP * rad));
	return fmax(0, least);
}

Shape shape_read(const int32_t *x, const int32_t *y, int32_t n, double scale, ShapeReading *out)
{
	ShapeReading r = {SHAPE_NONE, 0, 0, 0, 0, 0, 0, 0, 0, 0, {0, 0, 0}, 0};
	if (n <= 0) {
		if (out)
			*out = r;
		return SHAPE_NONE;
	}
	int32_t x0 = x[0], y0 = y[0], x1 = x[0], y1 = y[0];
	for (int32_t i = 1; i < n; i++) {
		x0 = x[i] < x0 ? x[i] : x0;
		y0 = y[i] < y0 ? y[i] : y0;
		x1 = x[i] > x1 ? x[i] : x1;
		y1 = y[i] > y1 ? y[i] : y1;
	}
	ShapeMask m = {x0 - SHAPE_MARGIN, y0 - SHAPE_MARGIN, x1 - x0 + 1 + 2 * SHAPE_MARGIN,
		       y1 - y0 + 1 + 2 * SHAPE_MARGIN, NULL, NULL, 0};
	m.in = util_alloc((size_t)m.w * (size_t)m.h, 1);
	for (int32_t i = 0; i < n; i++)
		m.in[(int64_t)(y[i] - m.y0) * m.w + (x[i] - m.x0)] = 1;
	r.squares = mask_fill_holes(&m);
	mask_band(&m);
	int32_t hn, on;
	Vec2 *h = hull_vertices(&m, true, &hn), *outer = hull_vertices(&m, false, &on);
	double area = hn >= 3 ? hull_area(h, hn) : 0;
	r.min_width = least_width(h, hn);
	if (area > 0 && r.squares >= SHAPE_MIN_SQUARES) {
		Rect rect = min_area_rect(h, hn);
		int32_t tri[3];
		r.rect_fill = area / (rect.a * rect.b);
		r.triangle_fill = shapefit_largest_triangle(h, hn, tri) / area;
		(void)tri;
		r.notch_depth = notch_depth(&m, outer, on);
		/* The boundary squares: the yardstick of every tolerance. */
		int32_t boundary = 0;
		for (int32_t j = 0; j < m.h; j++)
			for (int32_t i = 0; i < m.w; i++)
				boundary += shapefit_mask_at(&m, i, j) && !(shapefit_mask_at(&m, i - 1, j) && shapefit_mask_at(&m, i + 1, j) &&
								   shapefit_mask_at(&m, i, j - 1) && shapefit_mask_at(&m, i, j + 1));
		int32_t tol = (int32_t)floor(SHAPE_FIT_TOLERANCE * scale * boundary) + SHAPE_FIT_SLACK;
		FitModel fits[FIT_KINDS];
		int32_t err[FIT_KINDS];
		/* A rectangle, unless the hull is far from filling its rectangle or the
		 * outline has a deep notch: then none fits, and the fit costs much. */
		err[FIT_RECT] = INT32_MAX;
		fits[FIT_RECT] = (FitModel){.kind = FIT_RECT};
		if (r.rect_fill >= SHAPE_RECT_HULL && r.notch_depth < SHAPE_RECT_NOTCH * scale &&
		    shapefit_box(&m, h, hn, FIT_RECT, &fits[FIT_RECT]) < INFINITY)
			err[FIT_RECT] = shapefit_error(&m, r.squares, &fits[FIT_RECT]);
		/* The others only when the rectangle does not fit, and the L-shape only
		 * when the triangle does not fit exactly and the outline has a notch:
		 * they cost more. */
		bool rect_fits = err[FIT_RECT] <= tol;
		/* A triangle, from the largest on the hulls' vertices (of the centres and
		 * of the corners: the better of the two fits). */
		err[FIT_TRIANGLE] = INT32_MAX;
		if (!rect_fits) {
			double best_cost = INFINITY;
			for (int start = 0; start < 2 && best_cost > 0; start++) {
				FitModel t;
				double c = shapefit_triangle(&m, start ? outer : h, start ? on : hn, &t);
				if (c < best_cost) {
					best_cost = c;
					fits[FIT_TRIANGLE] = t;
				}
			}
			err[FIT_TRIANGLE] = shapefit_error(&m, r.squares, &fits[FIT_TRIANGLE]);
		}
		/* An L-shape, from the enclosing rectangle less a notch at its emptiest
		 * corner. */
		err[FIT_LSHAPE] = INT32_MAX;
		if (!rect_fits && err[FIT_TRIANGLE] > 0 && r.notch_depth >= SHAPE_NOTCH_DEPTH * scale &&
		    shapefit_box(&m, h, hn, FIT_LSHAPE, &fits[FIT_LSHAPE]) < INFINITY) {
			const FitModel *l = &fits[FIT_LSHAPE];
			if (fmin(l->notch[0], l->notch[1]) >= SHAPE_L_NOTCH * scale)
				err[FIT_LSHAPE] = shapefit_error(&m, r.squares, l);
		}
		/* The best within tolerance; near ties (SHAPE_FIT_SLACK) to the simpler
		 * model, in the order rectangle, triangle, L-shape. */
		int best = -1;
		for (int k = 0; k < FIT_KINDS; k++)
			if (err[k] <= tol && (best < 0 || err[k] < err[best] - SHAPE_FIT_SLACK))
				best = k;
		for (int k = 0; k < FIT_KINDS; k++)
			r.fit_error[k] = err[k];
		if (err[FIT_RECT] == INT32_MAX) /* no rectangle fitted: sides from the hull's */
			shapefit_box_start(&m, &rect, FIT_RECT, &fits[FIT_RECT]);
		const FitModel *fr = &fits[best == FIT_LSHAPE ? FIT_LSHAPE : FIT_RECT];
		double a = fr->side[0].offset + fr->side[2].offset, b = fr->side[1].offset + fr->side[3].offset;
		double angle = fr->side[0].angle * 45 / atan(1.0) + (a >= b ? 90 : 0); /* side 0's normal is across a */
		r.length = fmax(a, b);
		r.width = fmin(a, b);
		r.aspect = r.length / r.width;
		angle = fmod(angle, 180);
		r.angle = angle < 0 ? angle + 180 : angle;
		if (best >= 0 && r.width >= SHAPE_MIN_SIDE * scale) {
			static const Shape named[FIT_KINDS] = {SHAPE_SQUARE, SHAPE_TRIANGLE, SHAPE_LSHAPE};
			static const int32_t corners[FIT_KINDS] = {4, 3, 6};
			r.shape = named[best];
			r.corners = corners[best];
			if (best == FIT_RECT && r.aspect > SHAPE_ASPECT_SPLIT)
				r.shape = SHAPE_BRICK;
		}
	}
	free(h);
	free(outer);
	free(m.in);
	free(m.band);
	if (out)
		*out = r;
	return r.shape;
}

Shape shape_of_squares(const int32_t *x, const int32_t *y, int32_t n)
{
	return shape_read(x, y, n, 1, NULL);
}
