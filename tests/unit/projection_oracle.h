/* projection_oracle.h - an independent oracle for the projection of paper 2.1, for tests.
 *
 * Does the open interior of square (x, y) meet the closed polygon p? Decided square
 * by square from first principles: a vertex strictly inside the square, or an edge
 * whose chord through the closed square has its midpoint strictly inside (for a
 * convex square, a chord that enters the interior has its midpoint there), or the
 * square's centre inside p (the square then lies wholly inside). geom.c decides the
 * same thing row by row, with different arithmetic. */
#ifndef UTAK_TEST_PROJECTION_ORACLE_H
#define UTAK_TEST_PROJECTION_ORACLE_H

#include <stdbool.h>

#include "utak/base/geom.h"

/* Liang-Barsky: the chord of segment ab inside the closed box [x0,x0+1]x[y0,y0+1]. */
static inline bool clip(Vec2 a, Vec2 b, double x0, double y0, Vec2 *ca, Vec2 *cb)
{
	double t0 = 0, t1 = 1, dx = b.x - a.x, dy = b.y - a.y;
	double p[4] = {-dx, dx, -dy, dy}, q[4] = {a.x - x0, x0 + 1 - a.x, a.y - y0, y0 + 1 - a.y};
	for (int i = 0; i < 4; i++) {
		if (p[i] == 0) {
			if (q[i] < 0)
				return false;
			continue;
		}
		double r = q[i] / p[i];
		if (p[i] < 0 && r > t0)
			t0 = r;
		if (p[i] > 0 && r < t1)
			t1 = r;
	}
	if (t0 > t1)
		return false;
	*ca = vec2(a.x + t0 * dx, a.y + t0 * dy);
	*cb = vec2(a.x + t1 * dx, a.y + t1 * dy);
	return true;
}

static inline bool strictly_in_square(Vec2 q, int x, int y) { return q.x > x && q.x < x + 1 && q.y > y && q.y < y + 1; }

/* oracle(p, x, y): the open square (x, y) meets closed p. */
static inline bool oracle(const Polygon *p, int x, int y)
{
	for (int i = 0; i < p->count; i++) {
		if (strictly_in_square(p->v[i], x, y))
			return true;
		Vec2 ca, cb;
		if (clip(p->v[i], p->v[(i + 1) % p->count], x, y, &ca, &cb) &&
		    strictly_in_square(vec2((ca.x + cb.x) / 2, (ca.y + cb.y) / 2), x, y))
			return true;
	}
	return geom_point_in_polygon(p, vec2(x + 0.5, y + 0.5));
}

/* oracle_outside(p, x, y): square (x, y) is not wholly inside p (the verge rule):
 * its open interior meets p's boundary, or its centre is outside p. */
static inline bool oracle_outside(const Polygon *p, int x, int y)
{
	for (int i = 0; i < p->count; i++) {
		Vec2 ca, cb;
		if (strictly_in_square(p->v[i], x, y) ||
		    (clip(p->v[i], p->v[(i + 1) % p->count], x, y, &ca, &cb) &&
		     strictly_in_square(vec2((ca.x + cb.x) / 2, (ca.y + cb.y) / 2), x, y)))
			return true;
	}
	return !geom_point_in_polygon(p, vec2(x + 0.5, y + 0.5));
}

#endif
