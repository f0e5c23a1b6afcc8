/* geom.c - points, polygons and their projection onto the TABLE's squares (paper 2.1).
 *
 * ALGORITHM (projection). A square belongs to a polygon P when its open interior
 * meets closed P (utak(5)). If no edge of P enters the open square, the square
 * lies wholly inside or wholly outside P, and its centre tells which. So the
 * squares of P are
 *     (squares whose open interior an edge passes through)
 *   u (squares whose centre is inside P),
 * computed row by row: for each row of squares, each edge is clipped to the open
 * strip of the row and the columns its piece crosses are marked; then the line
 * through the row's centres is crossed with the edges (even-odd rule, half-open
 * at vertices) and the columns between pairs of crossings are marked. The verge
 * of paper 2.1 (squares NOT wholly inside the verge outline) is the same with the
 * second set complemented: edge squares u squares whose centre is outside.
 *
 * Edges that run along grid lines cross no open square, so an axis-aligned
 * polygon with integer corners claims exactly the squares inside it.
 *
 * COMPLEXITY: O(rows x edges + squares claimed) per polygon, rows clipped to the
 * TABLE. MEMORY: one scratch row the width of the polygon's box. */
#include "utak/base/geom.h"

#include <math.h>
#include <stdlib.h>

#include "utak/base/util.h"

double geom_orient(Vec2 a, Vec2 b, Vec2 c) { return vec2_cross(vec2_sub(b, a), vec2_sub(c, a)); }

double geom_polygon_area(const Polygon *p)
{
	double twice = 0;
	for (int32_t i = 0; i < p->count; i++) {
		Vec2 a = p->v[i], b = p->v[(i + 1) % p->count];
		twice += vec2_cross(a, b);
	}
	return twice / 2;
}

Box geom_polygon_box(const Polygon *p)
{
	Box b = {p->v[0], p->v[0]};
	for (int32_t i = 1; i < p->count; i++) {
		b.lo.x = fmin(b.lo.x, p->v[i].x);
		b.lo.y = fmin(b.lo.y, p->v[i].y);
		b.hi.x = fmax(b.hi.x, p->v[i].x);
		b.hi.y = fmax(b.hi.y, p->v[i].y);
	}
	return b;
}

/* on_segment: c, known collinear with ab, lies within ab's box. */
static bool on_segment(Vec2 a, Vec2 b, Vec2 c)
{
	return fmin(a.x, b.x) <= c.x && c.x <= fmax(a.x, b.x) && fmin(a.y, b.y) <= c.y &&
	       c.y <= fmax(a.y, b.y);
}

static int sign(double v) { return (v > 0) - (v < 0); }

double geom_winding(const Vec2 *pts, int n, Vec2 c)
{
	double total = 0;
	for (int i = 0; i < n; i++) {
		Vec2 a = vec2_sub(pts[i], c), b = vec2_sub(pts[(i + 1) % n], c);
		total += atan2(vec2_cross(a, b), vec2_dot(a, b));
	}
	return total / (2 * 3.14159265358979323846);
}

bool geom_segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d)
{
	int o1 = sign(geom_orient(a, b, c)), o2 = sign(geom_orient(a, b, d));
	int o3 = sign(geom_orient(c, d, a)), o4 = sign(geom_orient(c, d, b));
	if (o1 != o2 && o3 != o4)
		return true;
	return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
	       (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

bool geom_polygon_is_simple(const Polygon *p)
{
	int32_t n = p->count;
	if (n < 3 || geom_polygon_area(p) == 0)
		return false;
	for (int32_t i = 0; i < n; i++) {
		Vec2 a = p->v[i], b = p->v[(i + 1) % n], c = p->v[(i + 2) % n];
		if (a.x == b.x && a.y == b.y)
			return false;
		/* Neighbouring edges may share only their vertex: not fold back on each other. */
		if (geom_orient(a, b, c) == 0 && vec2_dot(vec2_sub(a, b), vec2_sub(c, b)) > 0)
			return false;
		for (int32_t j = i + 2; j < n; j++) {
			if (i == 0 && j == n - 1)
				continue; /* the last edge neighbours the first */
			if (geom_segments_meet(a, b, p->v[j], p->v[(j + 1) % n]))
				return false;
		}
	}
	return true;
}

bool geom_point_in_polygon(const Polygon *p, Vec2 q)
{
	bool in = false;
	for (int32_t i = 0, j = p->count - 1; i < p->count; j = i++) {
		Vec2 a = p->v[i], b = p->v[j];
		if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y))
			in = !in;
	}
	return in;
}

double geom_point_segment_distance(Vec2 q, Vec2 a, Vec2 b)
{
	Vec2 ab = vec2_sub(b, a), aq = vec2_sub(q, a);
	double len2 = vec2_dot(ab, ab), f = len2 > 0 ? vec2_dot(aq, ab) / len2 : 0;
	f = f < 0 ? 0 : f > 1 ? 1 : f;
	Vec2 d = vec2_sub(aq, vec2_scale(ab, f));
	return hypot(d.x, d.y);
}

Vec2 geom_rotate(Vec2 p, Vec2 centre, double c, double s)
{
	Vec2 d = vec2_sub(p, centre);
	return vec2(centre.x + c * d.x - s * d.y, centre.y + s * d.x + c * d.y);
}

void geom_cos_sin(double deg, double *c, double *s)
{
	double turns = fmod(deg, 360.0);
	if (turns < 0)
		turns += 360.0;
	if (turns == 0 || turns == 90 || turns == 180 || turns == 270) {
		static const double qc[4] = {1, 0, -1, 0}, qs[4] = {0, 1, 0, -1};
		int q = (int)(turns / 90);
		*c = qc[q];
		*s = qs[q];
		return;
	}
	double rad = turns * (3.14159265358979323846 / 180.0);
	*c = cos(rad);
	*s = sin(rad);
}

/* ---- projection ----------------------------------------------------------- */

/* mark_edges(p, row, x0, mark, n): marks, in mark[0..n) for columns x0..x0+n-1,
 * the squares of row `row` whose open interior an edge of p passes through. */
static void mark_edges(const Polygon *p, int32_t row, int32_t x0, uint8_t *mark, int32_t n)
{
	double ylo = row, yhi = row + 1.0;
	for (int32_t i = 0; i < p->count; i++) {
		Vec2 a = p->v[i], b = p->v[(i + 1) % p->count];
		if (a.y > b.y) {
			Vec2 t = a;
			a = b;
			b = t;
		}
		double cmin, cmax; /* the piece's x extent within the open strip */
		if (a.y == b.y) {
			if (!(a.y > ylo && a.y < yhi))
				continue;
			cmin = fmin(a.x, b.x);
			cmax = fmax(a.x, b.x);
		} else {
			if (!(a.y < yhi && b.y > ylo))
				continue;
			double y0 = fmax(a.y, ylo), y1 = fmin(b.y, yhi);
			double k = (b.x - a.x) / (b.y - a.y);
			double xa = y0 == a.y ? a.x : a.x + (y0 - a.y) * k;
			double xb = y1 == b.y ? b.x : a.x + (y1 - a.y) * k;
			cmin = fmin(xa, xb);
			cmax = fmax(xa, xb);
		}
		int64_t c0, c1;
		if (cmin == cmax) {
			/* A vertical piece: it enters the open square only off the grid line. */
			if (cmin == floor(cmin))
				continue;
			c0 = c1 = (int64_t)floor(cmin);
		} else {
			c0 = (int64_t)floor(cmin);
			c1 = (int64_t)ceil(cmax) - 1;
		}
		if (c0 < x0)
			c0 = x0;
		if (c1 > (int64_t)x0 + n - 1)
			c1 = (int64_t)x0 + n - 1;
		for (int64_t c = c0; c <= c1; c++)
			mark[c - x0] = 1;
	}
}

/* mark_centres(p, row, x0, mark, n, outside): marks the squares of the row whose
 * centre lies inside p (or, with outside, not inside p). */
static void mark_centres(const Polygon *p, int32_t row, int32_t x0, uint8_t *mark, int32_t n,
			 bool outside)
{
	double yc = row + 0.5, xs[GEOM_MAX_VERTICES];
	int32_t k = 0;
	for (int32_t i = 0; i < p->count; i++) {
		Vec2 a = p->v[i], b = p->v[(i + 1) % p->count];
		if ((a.y <= yc) != (b.y <= yc)) {
			double x = a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y);
			int32_t j = k++;
			while (j > 0 && xs[j - 1] > x) {
				xs[j] = xs[j - 1];
				j--;
			}
			xs[j] = x;
		}
	}
	/* Inside runs are (xs[0], xs[1]), (xs[2], xs[3]), ...; centre c + 0.5 is
	 * strictly between a pair when floor(xa - 0.5) < c < ceil(xb - 0.5). */
	int64_t next = x0; /* first column not yet decided, for `outside` */
	for (int32_t i = 0; i + 1 < k; i += 2) {
		int64_t c0 = (int64_t)floor(xs[i] - 0.5) + 1, c1 = (int64_t)ceil(xs[i + 1] - 0.5) - 1;
		if (outside) {
			for (int64_t c = next; c < c0 && c < (int64_t)x0 + n; c++)
				mark[c - x0] = 1;
			if (c1 + 1 > next)
				next = c1 + 1;
		} else {
			if (c0 < x0)
				c0 = x0;
			if (c1 > (int64_t)x0 + n - 1)
				c1 = (int64_t)x0 + n - 1;
			for (int64_t c = c0; c <= c1; c++)
				mark[c - x0] = 1;
		}
	}
	if (outside)
		for (int64_t c = next; c < (int64_t)x0 + n; c++)
			if (c >= x0)
				mark[c - x0] = 1;
}

static void project_rows(const Polygon *p, int32_t w, int32_t h, bool outside, GeomSpanFn *fn,
			 void *ctx)
{
	int32_t x0 = 0, x1 = w - 1, y0 = 0, y1 = h - 1;
	if (!outside) {
		/* Only the polygon's box can hold its squares. */
		Box b = geom_polygon_box(p);
		x0 = (int32_t)fmax(0, floor(b.lo.x) - 1);
		y0 = (int32_t)fmax(0, floor(b.lo.y) - 1);
		x1 = (int32_t)fmin(w - 1, ceil(b.hi.x));
		y1 = (int32_t)fmin(h - 1, ceil(b.hi.y));
	}
	if (x0 > x1 || y0 > y1)
		return;
	int32_t n = x1 - x0 + 1;
	uint8_t *mark = util_alloc((size_t)n, 1);
	for (int32_t row = y0; row <= y1; row++) {
		for (int32_t i = 0; i < n; i++)
			mark[i] = 0;
		mark_edges(p, row, x0, mark, n);
		mark_centres(p, row, x0, mark, n, outside);
		for (int32_t i = 0; i < n;) {
			if (!mark[i]) {
				i++;
				continue;
			}
			int32_t j = i;
			while (j + 1 < n && mark[j + 1])
				j++;
			fn(ctx, row, x0 + i, x0 + j);
			i = j + 1;
		}
	}
	free(mark);
}

void geom_project(const Polygon *p, int32_t w, int32_t h, GeomSpanFn *fn, void *ctx)
{
	project_rows(p, w, h, false, fn, ctx);
}

void geom_project_outside(const Polygon *p, int32_t w, int32_t h, GeomSpanFn *fn, void *ctx)
{
	project_rows(p, w, h, true, fn, ctx);
}
