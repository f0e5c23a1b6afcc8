/* carryoutline.c - the outline of the object to carry, traced from its squares on
 * the screen, and the polygon sums the carry needs (paper 3.6, 5: the carrying
 * tasks (vi)-(ix)). CONTROLLER SIDE: it reads the screen only. Split out of
 * carrytask.c (carryoutline.h says what each function does).
 *
 * ALGORITHM. Crack following round the 4-connected set (the set on the left,
 * turning left at pinch points): the outer boundary, a rectilinear simple polygon
 * that contains the object, as the TABLE's rule covers every square the object
 * meets; its convex hull when the boundary has too many vertices.
 * MEMORY: one byte a screen cell while tracing. COMPLEXITY: O(w h). */
#include "carryoutline.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

/* ct_in(set, w, h, x, y): square (x, y) of the set (outside: not). */
static bool ct_in(const uint8_t *set, int32_t w, int32_t h, int32_t x, int32_t y)
{
	return x >= 0 && y >= 0 && x < w && y < h && set[y * w + x];
}

/* ct_hull(set, w, h, out): the convex hull of the set's square corners (Andrew's
 * monotone chain): the fallback for an outline of too many vertices (a slanted
 * edge seen as a staircase). False when it too has too many. */
static bool ct_hull(const uint8_t *set, int32_t w, int32_t h, Polygon *out)
{
	int32_t n = 0;
	Vec2 *pt = util_alloc((size_t)(w + 1) * (size_t)(h + 1), sizeof *pt);
	for (int32_t x = 0; x <= w; x++) /* sorted by x, then y */
		for (int32_t y = 0; y <= h; y++)
			if (ct_in(set, w, h, x, y) || ct_in(set, w, h, x - 1, y) || ct_in(set, w, h, x, y - 1) ||
			    ct_in(set, w, h, x - 1, y - 1))
				pt[n++] = vec2(x, y);
	Vec2 *hull = util_alloc((size_t)2 * (size_t)n + 2, sizeof *hull);
	int32_t k = 0;
	for (int32_t i = 0; i < n; i++) {
		while (k >= 2 && geom_orient(hull[k - 2], hull[k - 1], pt[i]) <= 0)
			k--;
		hull[k++] = pt[i];
	}
	for (int32_t i = n - 2, lower = k + 1; i >= 0; i--) {
		while (k >= lower && geom_orient(hull[k - 2], hull[k - 1], pt[i]) <= 0)
			k--;
		hull[k++] = pt[i];
	}
	k--; /* the last point is the first */
	bool ok = k >= 3 && k <= GEOM_MAX_VERTICES;
	if (ok) {
		out->count = k;
		memcpy(out->v, hull, (size_t)k * sizeof *hull);
	}
	free(pt);
	free(hull);
	return ok;
}

/* ct_outline(set, w, h, out): the outer boundary of the 4-connected set holding the
 * lowest, leftmost square of set (w x h, one byte a square), counter-clockwise, its
 * vertices where it turns; the hull when that has more than GEOM_MAX_VERTICES. */
static bool ct_outline(const uint8_t *set, int32_t w, int32_t h, Polygon *out)
{
	int32_t sx = -1, sy = -1;
	for (int32_t at = 0; at < w * h && sx < 0; at++)
		if (set[at]) {
			sx = at % w;
			sy = at / w;
		}
	if (sx < 0)
		return false;
	/* Directions east, north, west, south; the set lies on the left of each edge.
	 * At a vertex heading d, the squares ahead are ahead-left and ahead-right. */
	static const int dxs[4] = {1, 0, -1, 0}, dys[4] = {0, 1, 0, -1};
	/* The bottom edge of the lowest, leftmost square is on the boundary (nothing
	 * lies below it), and its left end is a corner. */
	int32_t x = sx + 1, y = sy, d = 0, n = 0;
	out->v[n++] = vec2(sx, sy);
	bool ok = true;
	while (!(x == sx && y == sy)) {
		int32_t lx = d == 0 || d == 3 ? x : x - 1, ly = d == 0 || d == 1 ? y : y - 1;
		int32_t rx = d == 0 || d == 1 ? x : x - 1, ry = d == 1 || d == 2 ? y : y - 1;
		bool left = ct_in(set, w, h, lx, ly), right = ct_in(set, w, h, rx, ry);
		int nd = !left ? (d + 1) % 4 : right ? (d + 3) % 4 : d;
		if (nd != d) {
			if (n == GEOM_MAX_VERTICES) {
				ok = false;
				break;
			}
			out->v[n++] = vec2(x, y);
		}
		d = nd;
		x += dxs[d];
		y += dys[d];
	}
	out->count = n;
	if (!ok || n < 4)
		return ct_hull(set, w, h, out);
	return true;
}

bool carryoutline_object(const Controller *c, int32_t k, Polygon *out)
{
	const Screen *s = &c->screen;
	uint8_t *set = util_alloc((size_t)s->w * (size_t)s->h, 1);
	memset(set, 0, (size_t)s->w * (size_t)s->h);
	for (int32_t at = 0; at < s->w * s->h; at++)
		set[at] = s->label[at] == k;
	bool ok = ct_outline(set, s->w, s->h, out);
	free(set);
	return ok;
}

Polygon carryoutline_moved(const Polygon *p, Vec2 by)
{
	Polygon q = *p;
	for (int32_t i = 0; i < q.count; i++)
		q.v[i] = vec2_add(q.v[i], by);
	return q;
}

Vec2 carryoutline_centroid(const Polygon *p)
{
	double a = 0, cx = 0, cy = 0;
	for (int32_t i = 0; i < p->count; i++) {
		Vec2 u = p->v[i], v = p->v[(i + 1) % p->count];
		double cr = vec2_cross(u, v);
		a += cr;
		cx += (u.x + v.x) * cr;
		cy += (u.y + v.y) * cr;
	}
	return fabs(a) > 0 ? vec2(cx / (3 * a), cy / (3 * a)) : p->v[0];
}
