/* judgeshape.c - the judge's shape names from true polygons (doc/verdicts.md;
 * paper 2.3). SIMULATOR SIDE; the rule and its constants are in judgeshape.h.
 *
 * ALGORITHM: merge near-duplicate and collinear vertices (repeat until stable),
 * then classify by corner count and interior angles (the turn at each vertex,
 * signed by the polygon's orientation), and for four corners by the ratio of the
 * mean lengths of opposite sides. COMPLEXITY: O(n^2) for n <= GEOM_MAX_VERTICES. */
#include "utak/body/judgeshape.h"

#include <math.h>

static const double judge_shape_pi = 3.14159265358979323846;

/* turn(a, b, c): the signed turn at b, degrees in (-180, 180]. */
static double turn(Vec2 a, Vec2 b, Vec2 c)
{
	Vec2 u = vec2_sub(b, a), v = vec2_sub(c, b);
	return atan2(vec2_cross(u, v), vec2_dot(u, v)) * 180.0 / judge_shape_pi;
}

/* merge(p, q): p with near-duplicate and collinear vertices dropped, into q. */
static void merge(const Polygon *p, Polygon *q)
{
	*q = *p;
	for (bool changed = true; changed && q->count > 3;) {
		changed = false;
		for (int32_t i = 0; i < q->count && q->count > 3; i++) {
			Vec2 a = q->v[(i + q->count - 1) % q->count], b = q->v[i], c = q->v[(i + 1) % q->count];
			Vec2 d = vec2_sub(b, a);
			if (hypot(d.x, d.y) < JUDGE_SHAPE_MERGE || fabs(turn(a, b, c)) < JUDGE_SHAPE_STRAIGHT) {
				for (int32_t j = i; j + 1 < q->count; j++)
					q->v[j] = q->v[j + 1];
				q->count--;
				changed = true;
				i--;
			}
		}
	}
}

static double side(const Polygon *q, int32_t i)
{
	Vec2 d = vec2_sub(q->v[(i + 1) % q->count], q->v[i]);
	return hypot(d.x, d.y);
}

/* min_width(p): the polygon's least width, its extent across the narrowest
 * direction. That direction is normal to an edge of the convex hull, and no edge's
 * normal gives less than the least width, so the least over every edge is exact. */
static double min_width(const Polygon *p)
{
	double best = INFINITY;
	for (int32_t i = 0; i < p->count; i++) {
		Vec2 e = vec2_sub(p->v[(i + 1) % p->count], p->v[i]);
		double len = hypot(e.x, e.y);
		if (len < 1e-12)
			continue;
		double lo = INFINITY, hi = -INFINITY;
		for (int32_t j = 0; j < p->count; j++) {
			double d = vec2_cross(e, vec2_sub(p->v[j], p->v[i])) / len;
			lo = d < lo ? d : lo;
			hi = d > hi ? d : hi;
		}
		best = hi - lo < best ? hi - lo : best;
	}
	return best;
}

Shape judge_shape_name(const Polygon *p)
{
	if (min_width(p) < JUDGE_SHAPE_MIN_WIDTH - 1e-9)
		return SHAPE_NONE; /* too small for the TABLE's squares to show its corners */
	Polygon q;
	merge(p, &q);
	if (q.count == 3)
		return SHAPE_TRIANGLE;
	if (q.count != 4 && q.count != 6)
		return SHAPE_NONE;
	/* Turns signed so that a convex corner turns positive (counter-clockwise). */
	double sign = geom_polygon_area(&q) >= 0 ? 1 : -1;
	int reflex = 0;
	for (int32_t i = 0; i < q.count; i++) {
		double t = sign * turn(q.v[(i + q.count - 1) % q.count], q.v[i], q.v[(i + 1) % q.count]);
		if (fabs(t - 90) <= JUDGE_SHAPE_RIGHT)
			continue;
		if (fabs(t + 90) <= JUDGE_SHAPE_RIGHT)
			reflex++;
		else
			return SHAPE_NONE;
	}
	if (q.count == 6)
		return reflex == 1 ? SHAPE_LSHAPE : SHAPE_NONE;
	if (reflex)
		return SHAPE_NONE;
	double a = (side(&q, 0) + side(&q, 2)) / 2, b = (side(&q, 1) + side(&q, 3)) / 2;
	double r = a > b ? a / b : b / a;
	if (r <= JUDGE_SHAPE_SQUARE)
		return SHAPE_SQUARE;
	if (r >= JUDGE_SHAPE_BRICK)
		return SHAPE_BRICK;
	return SHAPE_NONE;
}

Vec2 judge_shape_centroid(const Polygon *p)
{
	double a = 0, cx = 0, cy = 0, mx = 0, my = 0;
	for (int32_t i = 0; i < p->count; i++) {
		Vec2 u = p->v[i], v = p->v[(i + 1) % p->count];
		double c = vec2_cross(u, v);
		a += c;
		cx += (u.x + v.x) * c;
		cy += (u.y + v.y) * c;
		mx += u.x;
		my += u.y;
	}
	if (fabs(a) < 1e-12)
		return vec2(mx / p->count, my / p->count);
	return vec2(cx / (3 * a), cy / (3 * a));
}
