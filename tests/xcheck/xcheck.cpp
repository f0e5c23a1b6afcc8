/* xcheck.cpp - TABLETOP's collision against an exact one: the digital
 * representation (paper 2.1) checked against Box2D's overlap test (issue 6).
 *
 * TABLETOP decides that two shapes collide when their digital representations
 * meet: some TABLE square is claimed by both (geom_project; utak(5): a square
 * belongs to a polygon when its open interior meets the polygon). The paper calls
 * this "correct to within certain limitations" (2.1). This program measures the
 * limitation. For random pairs of polygons in random poses it compares TABLETOP's
 * verdict with Box2D's exact one (b2TestOverlap, Box2D 2.4 from Debian's
 * libbox2d-dev), and with the exact distance between the two polygons.
 *
 * THE BAND. If both polygons meet the same open unit square, they are less than
 * its diagonal, sqrt 2, apart; if they overlap, the overlap has an interior and
 * some square meets it. So the two verdicts may differ only when the polygons are
 * less than sqrt 2 apart: TABLETOP sees a collision where there is a gap (both
 * reach into one square), or none where they only touch (along a grid line).
 * A disagreement at a distance of sqrt 2 or more is a bug, and fails the check.
 *
 * ALGORITHM. Polygons: convex (points on an ellipse), star-shaped and concave
 * (random radii), L and U shapes, thin slivers; sizes 0.3 to 6 squares; poses:
 * any angle and position, or a quarter of the time grid-aligned (integer or
 * half-integer corners, multiples of 90 degrees), where touching is common.
 * Box2D takes convex polygons of at most 8 points, so each polygon is cut into
 * triangles by ear clipping (written here) and the pair overlaps when any two
 * triangles do. Units: one TABLE square is one Box2D metre, well inside the sizes
 * Box2D is tuned for; the shapes' skin (m_radius, b2_polygonRadius = 0.01 m) is
 * set to 0 so that Box2D tests the polygons themselves. Box2D works in float, so
 * its verdict is trusted only beyond XCHECK_FLOAT_TOL of contact: a Box2D verdict
 * of overlap where the exact distance is farther than that also fails the check
 * (it would mean a wrong triangulation or a wrong distance here).
 *
 * OUTPUT: pairs, agreements, disagreements within the band, disagreements outside
 * it (must be 0); exit status 1 if any outside. Fixed seed: the same figures on
 * every run. */
#include <box2d/box2d.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

extern "C" {
#include "utak/base/geom.h"
}

/* The grid the pairs are projected on, in squares: room for two polygons of up to
 * 6 squares and the gap between them, anywhere away from the edge. */
static const int GRID = 64;
static const int PAIRS = 100000;
static const double BAND = 1.4142135623730951; /* a square's diagonal */
/* Box2D's float coordinates near 40 carry about 4e-6 of rounding. */
static const double XCHECK_FLOAT_TOL = 1e-4;

/* ---- a small generator of our own, the same on every platform ---------------- */

static uint64_t rng_state = 20261121;

static uint32_t rng_next()
{
	rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
	return (uint32_t)(rng_state >> 33);
}

static double rng_real(double lo, double hi) { return lo + (hi - lo) * (rng_next() / 2147483648.0); }
static int rng_int(int n) { return (int)(rng_next() % (uint32_t)n); }

/* ---- shapes ------------------------------------------------------------------ */

typedef std::vector<Vec2> Shape; /* a simple polygon, counter-clockwise */

static double area2(const Shape &s)
{
	double a = 0;
	for (size_t i = 0; i < s.size(); i++)
		a += vec2_cross(s[i], s[(i + 1) % s.size()]);
	return a;
}

/* random_shape: about the origin, counter-clockwise; kind names it for the report. */
static Shape random_shape(int *kind)
{
	static const double ell[6][2] = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 4}, {0, 4}};
	static const double u[8][2] = {{0, 0}, {4, 0}, {4, 3}, {3, 3}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
	Shape s;
	*kind = rng_int(5);
	double size = rng_real(0.3, 3);
	if (*kind == 0) { /* convex: points on an ellipse */
		int n = 3 + rng_int(6);
		double ry = size * rng_real(0.3, 1);
		for (int i = 0; i < n; i++) {
			double t = 6.283185307179586 * (i + rng_real(0, 0.5)) / n;
			s.push_back(vec2(size * std::cos(t), ry * std::sin(t)));
		}
	} else if (*kind == 1) { /* star-shaped, usually concave */
		int n = 4 + rng_int(9);
		for (int i = 0; i < n; i++) {
			double t = 6.283185307179586 * (i + rng_real(0, 0.5)) / n, r = size * rng_real(0.3, 1);
			s.push_back(vec2(r * std::cos(t), r * std::sin(t)));
		}
	} else if (*kind == 2 || *kind == 3) { /* L or U */
		const double(*v)[2] = *kind == 2 ? ell : u;
		int n = *kind == 2 ? 6 : 8;
		double k = size / 2.5;
		for (int i = 0; i < n; i++)
			s.push_back(vec2((v[i][0] - 1.5) * k, (v[i][1] - 1.5) * k));
	} else { /* a thin sliver, thinner than a square */
		double l = size * 2, t = rng_real(0.05, 0.9);
		s = {vec2(-l / 2, -t / 2), vec2(l / 2, -t / 2), vec2(l / 2, t / 2), vec2(-l / 2, t / 2)};
	}
	return s;
}

/* place(s, aligned): turned and moved to somewhere on the grid. */
static Shape place(const Shape &s, Vec2 at, double deg)
{
	double c, sn;
	geom_cos_sin(deg, &c, &sn);
	Shape out;
	for (Vec2 p : s)
		out.push_back(vec2_add(at, geom_rotate(p, vec2(0, 0), c, sn)));
	return out;
}

/* ---- TABLETOP's verdict --------------------------------------------------------- */

struct Marks {
	uint8_t cell[GRID * GRID];
	uint8_t bit;
	bool both;
};

static void mark_span(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	Marks *m = (Marks *)ctx;
	for (int32_t x = x0; x <= x1; x++) {
		m->both |= (m->cell[y * GRID + x] & ~m->bit) != 0;
		m->cell[y * GRID + x] |= m->bit;
	}
}

static Polygon to_polygon(const Shape &s)
{
	Polygon p = {};
	p.count = (int32_t)s.size();
	for (size_t i = 0; i < s.size(); i++)
		p.v[i] = s[i];
	return p;
}

/* digital_meet(a, b): some square is claimed by both projections. */
static bool digital_meet(const Shape &a, const Shape &b)
{
	static Marks m;
	for (int i = 0; i < GRID * GRID; i++)
		m.cell[i] = 0;
	m.both = false;
	Polygon pa = to_polygon(a), pb = to_polygon(b);
	m.bit = 1;
	geom_project(&pa, GRID, GRID, mark_span, &m);
	m.bit = 2;
	geom_project(&pb, GRID, GRID, mark_span, &m);
	return m.both;
}

/* ---- the exact distance ---------------------------------------------------------- */

static double point_in(const Shape &s, Vec2 q)
{
	bool in = false;
	for (size_t i = 0, j = s.size() - 1; i < s.size(); j = i++)
		if ((s[i].y > q.y) != (s[j].y > q.y) &&
		    q.x < s[i].x + (q.y - s[i].y) * (s[j].x - s[i].x) / (s[j].y - s[i].y))
			in = !in;
	return in;
}

/* exact_distance(a, b): 0 when they meet (edges cross, or one holds the other),
 * else the least distance from a vertex of one to an edge of the other, which for
 * two disjoint polygons is their distance. */
static double exact_distance(const Shape &a, const Shape &b)
{
	size_t n = a.size(), m = b.size();
	for (size_t i = 0; i < n; i++)
		for (size_t j = 0; j < m; j++)
			if (geom_segments_meet(a[i], a[(i + 1) % n], b[j], b[(j + 1) % m]))
				return 0;
	if (point_in(a, b[0]) || point_in(b, a[0]))
		return 0;
	double d = INFINITY;
	for (size_t i = 0; i < n; i++)
		for (size_t j = 0; j < m; j++) {
			d = std::fmin(d, geom_point_segment_distance(a[i], b[j], b[(j + 1) % m]));
			d = std::fmin(d, geom_point_segment_distance(b[j], a[i], a[(i + 1) % n]));
		}
	return d;
}

/* ---- Box2D's verdict --------------------------------------------------------------- */

/* ear_clip(s): triangles covering the simple counter-clockwise polygon s. An ear
 * is a convex corner whose triangle holds no other vertex; a simple polygon of
 * more than 3 points always has one (the two-ears theorem). O(n^3), n <= 12. */
static std::vector<Shape> ear_clip(Shape s)
{
	std::vector<Shape> out;
	while (s.size() > 3) {
		size_t n = s.size(), ear = n;
		for (size_t i = 0; i < n && ear == n; i++) {
			Vec2 a = s[(i + n - 1) % n], b = s[i], c = s[(i + 1) % n];
			if (geom_orient(a, b, c) <= 0)
				continue;
			bool empty = true;
			for (size_t j = 0; j < n && empty; j++) {
				if (j == i || j == (i + 1) % n || j == (i + n - 1) % n)
					continue;
				Vec2 q = s[j];
				empty = !(geom_orient(a, b, q) >= 0 && geom_orient(b, c, q) >= 0 && geom_orient(c, a, q) >= 0);
			}
			if (empty)
				ear = i;
		}
		if (ear == n) { /* only from rounding on a near-degenerate polygon */
			std::fprintf(stderr, "xcheck: no ear found\n");
			std::exit(2);
		}
		out.push_back({s[(ear + n - 1) % n], s[ear], s[(ear + 1) % n]});
		s.erase(s.begin() + (long)ear);
	}
	out.push_back(s);
	return out;
}

/* Triangles thinner than this (area over longest edge, squares) are left out:
 * Box2D would weld their points and, failing to make a hull, substitute a 2 x 2
 * box. They lie within this distance of the polygon's other pieces' edges, so
 * leaving them out moves no verdict by more than XCHECK_FLOAT_TOL. */
static const double SLIVER = 1e-5;
static long slivers;

static std::vector<b2PolygonShape> to_box2d(const Shape &s)
{
	std::vector<b2PolygonShape> pieces;
	for (const Shape &t : ear_clip(s)) {
		double longest = 0;
		for (int i = 0; i < 3; i++)
			longest = std::fmax(longest, std::hypot(t[(i + 1) % 3].x - t[i].x, t[(i + 1) % 3].y - t[i].y));
		if (area2(t) / 2 / longest < SLIVER) {
			slivers++;
			continue;
		}
		b2Vec2 v[3];
		for (int i = 0; i < 3; i++)
			v[i].Set((float)t[i].x, (float)t[i].y);
		b2PolygonShape p;
		p.Set(v, 3);
		if (p.m_count != 3) {
			std::fprintf(stderr, "xcheck: Box2D refused a triangle\n");
			std::exit(2);
		}
		p.m_radius = 0; /* the polygon itself, not its skin */
		pieces.push_back(p);
	}
	return pieces;
}

static bool box2d_overlap(const Shape &a, const Shape &b)
{
	std::vector<b2PolygonShape> pa = to_box2d(a), pb = to_box2d(b);
	b2Transform id;
	id.SetIdentity();
	for (const b2PolygonShape &x : pa)
		for (const b2PolygonShape &y : pb)
			if (b2TestOverlap(&x, 0, &y, 0, id, id))
				return true;
	return false;
}

/* ---- the check --------------------------------------------------------------------- */

int main(int argc, char **argv)
{
	/* xcheck [PAIRS]: more pairs for a longer look; the default is what CI runs. */
	int pairs = argc > 1 ? std::atoi(argv[1]) : PAIRS;
	if (pairs <= 0) {
		std::fprintf(stderr, "usage: xcheck [PAIRS]\n");
		return 2;
	}
	/* Pairs with a gap, by its width in eighths of sqrt 2, and how many of them
	 * TABLETOP calls a collision: the band's profile. */
	long gap_pairs[9] = {0}, gap_collide[9] = {0};
	long agree = 0, in_band = 0, outside = 0, overlaps = 0, digital = 0, box2d_wrong = 0;
	long phantom = 0, missed = 0; /* in the band: TABLETOP sees a collision in a gap / misses a touch */
	static const char *const kinds[5] = {"convex", "star", "L", "U", "sliver"};
	long by_kind[5] = {0};
	for (int pair = 0; pair < pairs; pair++) {
		int ka, kb;
		Shape a = random_shape(&ka), b = random_shape(&kb);
		bool aligned = rng_int(4) == 0;
		Vec2 at = vec2(rng_real(20, 44), rng_real(20, 44));
		double ta = rng_real(0, 360), tb = rng_real(0, 360);
		/* B's centre within the reach of both, plus a little: many overlap,
		 * many nearly touch, some are apart. */
		double reach = 0;
		for (Vec2 p : a)
			reach = std::fmax(reach, std::hypot(p.x, p.y));
		for (Vec2 p : b)
			reach = std::fmax(reach, std::hypot(p.x, p.y));
		double dist = rng_real(0, 2 * reach + 2), dir = rng_real(0, 6.283185307179586);
		Vec2 bt = vec2(at.x + dist * std::cos(dir), at.y + dist * std::sin(dir));
		if (aligned) {
			at = vec2(std::round(at.x * 2) / 2, std::round(at.y * 2) / 2);
			bt = vec2(std::round(bt.x * 2) / 2, std::round(bt.y * 2) / 2);
			ta = 90.0 * rng_int(4);
			tb = 90.0 * rng_int(4);
			for (Vec2 &p : a)
				p = vec2(std::round(p.x * 2) / 2, std::round(p.y * 2) / 2);
			for (Vec2 &p : b)
				p = vec2(std::round(p.x * 2) / 2, std::round(p.y * 2) / 2);
			Polygon pa = to_polygon(a), pb = to_polygon(b);
			if (!geom_polygon_is_simple(&pa) || !geom_polygon_is_simple(&pb)) {
				pair--; /* rounding made it degenerate: draw again */
				continue;
			}
		}
		a = place(a, at, ta);
		b = place(b, bt, tb);
		if (area2(a) < 0 || area2(b) < 0) {
			std::fprintf(stderr, "xcheck: a shape is clockwise\n");
			return 2;
		}
		double d = exact_distance(a, b);
		bool box = box2d_overlap(a, b), tab = digital_meet(a, b);
		overlaps += box;
		digital += tab;
		/* Box2D reporting an overlap across a clear gap would mean a wrong
		 * triangulation here, or a wrong distance. (The other way round, Box2D
		 * missing an overlap, shows as a disagreement with TABLETOP.) */
		box2d_wrong += box && d > XCHECK_FLOAT_TOL;
		if (d > XCHECK_FLOAT_TOL) {
			int bucket = d < BAND ? (int)(d / BAND * 8) : 8;
			gap_pairs[bucket]++;
			gap_collide[bucket] += tab;
		}
		if (box == tab) {
			agree++;
		} else if (d < BAND) {
			in_band++;
			if (tab)
				phantom++;
			else
				missed++;
		} else {
			outside++;
			by_kind[ka]++;
			by_kind[kb]++;
			std::printf("OUTSIDE THE BAND: pair %d, distance %.6f, Box2D %s, TABLETOP %s\n", pair, d,
				    box ? "overlap" : "apart", tab ? "collision" : "apart");
		}
	}
	std::printf("pairs %d\n", pairs);
	std::printf("agreements %ld (%.3f%%)\n", agree, 100.0 * agree / pairs);
	std::printf("disagreements within the band (exact distance < sqrt 2) %ld: TABLETOP collides across a gap "
		    "%ld, misses a touch %ld\n",
		    in_band, phantom, missed);
	std::printf("disagreements outside the band %ld\n", outside);
	std::printf("Box2D overlaps %ld, TABLETOP collisions %ld, Box2D against exact distance beyond %g: %ld, "
		    "sliver triangles left out %ld\n",
		    overlaps, digital, XCHECK_FLOAT_TOL, box2d_wrong, slivers);
	std::printf("pairs with a gap, by width (squares): TABLETOP collisions / pairs\n");
	for (int k = 0; k < 9; k++)
		if (k < 8)
			std::printf("  [%.3f, %.3f): %ld / %ld\n", k * BAND / 8, (k + 1) * BAND / 8, gap_collide[k],
				    gap_pairs[k]);
		else
			std::printf("  >= %.3f: %ld / %ld (must be 0 / ...)\n", BAND, gap_collide[k], gap_pairs[k]);
	for (int k = 0; k < 5; k++)
		if (by_kind[k])
			std::printf("  outside the band involving %s: %ld\n", kinds[k], by_kind[k]);
	return outside == 0 && box2d_wrong == 0 ? 0 : 1;
}
