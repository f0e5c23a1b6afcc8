/* visibility.c - Shakey's visibility graph on a grid, and the one line-of-sight test
 * of utak (paper 4.1; Nilsson 1969). See visibility.h for the definitions.
 *
 * ALGORITHM:
 *  - Line of sight: walk the columns (unit x-intervals) the segment's interior
 *    crosses, and in each the rows its y-range crosses: rule (1). A segment on a
 *    horizontal grid line checks the two cells of each unit edge instead: rule (2).
 *    At each integer x strictly inside, if the segment's y there is an integer it
 *    passes through a lattice point: rule (3). A vertical segment is the same walk
 *    with x and y exchanged. The y at an integer x is computed as
 *    ay + ((x - ax) dy) / dx: for half-integer inputs the product is exact and the
 *    division is exact whenever the true value is representable, so "is y an
 *    integer" is decided exactly.
 *  - Graph: the convex corners, and an edge between two corners that see each other
 *    and at which the line is tangent (it does not run on into the corner's blocked
 *    cell): a shortest path bends only around an obstacle, with the obstacle on the
 *    inside of the bend, so other edges are never used (the reduced visibility
 *    graph of supporting and separating lines; see J.-C. Latombe, "Robot Motion
 *    Planning", 1991, ch. 4).
 *  - Build: instead of testing all V^2 pairs, a sweep from each corner u visits the
 *    squares at growing Chebyshev distance from it, keeping the arcs of directions
 *    still open (vis_sweep): blocked squares cut out their shadows, and the corners
 *    in open directions are the candidates, each settled by the exact line test
 *    (the arcs are kept slightly too wide, so they can only add candidates). It is
 *    recursive shadow casting, as in roguelike field-of-view computation, with
 *    exact verification. A ray left open only between two touching shadows is
 *    walked directly (vis_slivers). Both builders were checked to give the same
 *    edges on every map of ../shared/data/movingai (the O(V^2) one took 57 s on
 *    maze512-1-0 and about 300 s on random512-10-0, the sweep 1.7 s and 26 s).
 *  - Query: S and D are joined to the corners they see (S to D directly when free),
 *    then A* (Hart, Nilsson and Raphael 1968) with the straight-line distance to D,
 *    which is consistent, so nodes close once.
 *
 * INVARIANTS: adj holds each tangent, free corner-corner edge twice, once per end;
 * each row of adj is sorted.
 * MEMORY: 10 bytes per corner, 8 bytes per edge, 23 bytes per node for a query.
 * COMPLEXITY: build O(sum over corners of the area each sees, plus E L) for E edges
 * of L cells (O(V w h) in the worst case, an open map); query O(V L + E log V).
 */
#include "utak/plan/visibility.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/plan/heap.h"
#include "utak/base/util.h"

/* ---- the line-of-sight test -------------------------------------------------- */

/* vis_blocked(g, x, y, t): cell (x, y) of g, or (y, x) when t (the transposed
 * walk), is blocked or outside. Coordinates arrive as doubles holding integers. */
static inline bool vis_blocked(const Grid *g, double x, double y, bool t)
{
	double cx = t ? y : x, cy = t ? x : y;
	if (cx < 0 || cy < 0 || cx >= g->w || cy >= g->h)
		return true;
	return g->cells[(size_t)cy * (size_t)g->w + (size_t)cx] != GRID_FREE;
}

/* vis_pinch(g, x, y, t): lattice point (x, y) has two diagonally opposite blocked
 * cells around it. Symmetric under exchanging x and y. */
static inline bool vis_pinch(const Grid *g, double x, double y, bool t)
{
	return (vis_blocked(g, x - 1, y - 1, t) && vis_blocked(g, x, y, t)) ||
	       (vis_blocked(g, x, y - 1, t) && vis_blocked(g, x - 1, y, t));
}

bool visibility_segment_free(const Grid *g, Vec2 a, Vec2 b)
{
	if (a.x == b.x && a.y == b.y) {
		/* A point: free when a cell whose closed square holds it is free. */
		double x0 = floor(a.x), y0 = floor(a.y);
		double x1 = a.x == x0 ? x0 - 1 : x0, y1 = a.y == y0 ? y0 - 1 : y0;
		return !vis_blocked(g, x0, y0, false) || !vis_blocked(g, x1, y0, false) ||
		       !vis_blocked(g, x0, y1, false) || !vis_blocked(g, x1, y1, false);
	}
	/* Walk along u, the axis in which the segment is not constant; v is the other. */
	bool t = a.x == b.x;
	double au = t ? a.y : a.x, av = t ? a.x : a.y;
	double bu = t ? b.y : b.x, bv = t ? b.x : b.y;
	if (au > bu) {
		double s = au;
		au = bu;
		bu = s;
		s = av;
		av = bv;
		bv = s;
	}
	/* A segment reaching strictly outside the grid meets an outside cell's interior,
	 * or runs between two outside cells. After this test every column and row the
	 * walk below reads is inside the grid, except the neighbours of a segment lying
	 * on the grid's border line, which go through vis_blocked's bounds test. */
	const double umax = t ? g->h : g->w, vmax = t ? g->w : g->h;
	if (au < 0 || bu > umax || fmin(av, bv) < 0 || fmax(av, bv) > vmax)
		return false;
	const uint8_t *cells = g->cells;
	const size_t su = t ? (size_t)g->w : 1, sv = t ? 1 : (size_t)g->w;
	const double du = bu - au, dv = bv - av;
	const bool on_line = dv == 0 && av == floor(av);
	double vl = av; /* v where the segment enters the current column */
	for (double u = floor(au); u < bu; u++) {
		/* Column u holds the open piece (max(u, au), min(u + 1, bu)) of the segment. */
		bool last = !(u + 1 < bu);
		double vr = last ? bv : av + ((u + 1 - au) * dv) / du;
		if (dv == 0) {
			if (on_line ? vis_blocked(g, u, av, t) && vis_blocked(g, u, av - 1, t)
			            : cells[(size_t)u * su + (size_t)floor(av) * sv] != GRID_FREE)
				return false;
		} else {
			double lo = vl < vr ? vl : vr, hi = vl < vr ? vr : vl;
			const uint8_t *col = cells + (size_t)u * su;
			for (double v = floor(lo); v < hi; v++)
				if (col[(size_t)v * sv] != GRID_FREE)
					return false;
		}
		/* The lattice line u + 1, strictly inside the segment, at height vr. */
		if (!last && vr == floor(vr) && vis_pinch(g, u + 1, vr, t))
			return false;
		vl = vr;
	}
	return true;
}

bool visibility_pinch_point(const Grid *g, Vec2 p)
{
	return p.x == floor(p.x) && p.y == floor(p.y) && vis_pinch(g, p.x, p.y, false);
}

bool visibility_path_free(const Grid *g, const Path *p)
{
	if (p->count == 0)
		return false;
	if (p->count == 1)
		return visibility_segment_free(g, p->pts[0], p->pts[0]);
	for (int i = 1; i < p->count; i++) {
		if (!visibility_segment_free(g, p->pts[i - 1], p->pts[i]))
			return false;
		if (i + 1 < p->count && visibility_pinch_point(g, p->pts[i]))
			return false;
	}
	return true;
}

/* ---- corners ------------------------------------------------------------------ */

static inline bool vis_cell_blocked(const Grid *g, int32_t x, int32_t y)
{
	return !grid_free_at(g, x, y);
}

/* vis_corner(g, X, Y, &qx, &qy): lattice point (X, Y) is a convex corner: exactly one
 * of its four cells is blocked, the one toward (qx, qy). */
static bool vis_corner(const Grid *g, int32_t X, int32_t Y, int8_t *qx, int8_t *qy)
{
	int n = 0;
	for (int dy = -1; dy <= 0; dy++)
		for (int dx = -1; dx <= 0; dx++)
			if (vis_cell_blocked(g, X + dx, Y + dy)) {
				n++;
				*qx = dx == 0 ? 1 : -1;
				*qy = dy == 0 ? 1 : -1;
			}
	return n == 1;
}

int32_t visibility_count_corners(const Grid *g)
{
	int32_t n = 0;
	int8_t qx, qy;
	/* Lattice points on the border have two outside (blocked) cells: never corners. */
	for (int32_t Y = 1; Y < g->h; Y++)
		for (int32_t X = 1; X < g->w; X++)
			n += vis_corner(g, X, Y, &qx, &qy);
	return n;
}

/* vis_into(dx, dy, qx, qy): the direction (dx, dy) points strictly into the open
 * quadrant (qx, qy). */
static inline bool vis_into(double dx, double dy, int8_t qx, int8_t qy)
{
	return dx * qx > 0 && dy * qy > 0;
}

/* ---- the sweep: which corners a corner sees --------------------------------- */

#define VIS_PI 3.14159265358979323846
#define VIS_TWO_PI (2 * VIS_PI)
/* Angles are doubles from atan2: a shadow is shrunk, and a candidate's direction
 * accepted, with this slack, so that rounding can only let through extra
 * candidates (which the exact line test then judges), never drop a visible one.
 * Distinct directions to lattice points within 16384 squares differ by more than
 * 1e-9 rad, so the slack admits no more than the rays that graze a shadow's edge. */
#define VIS_ANGLE_EPS 1e-9
/* An arc narrower than this whose ends are one lattice direction is a sliver (see
 * VisArc): a few slacks wide. */
#define VIS_SLIVER 1e-8

/* A closed arc [a, b] of directions, 0 <= a <= b <= 2 pi, with the lattice vectors
 * (from the swept corner) whose directions its ends are: the corners of the squares
 * whose shadows made them. An arc whose two ends are the same lattice direction is
 * a SLIVER: the single ray between two shadows that touch. */
typedef struct VisArc {
	double a, b;
	int32_t ax, ay, bx, by;
} VisArc;

/* The shadow of a square: the open arc of directions from start over length, whose
 * ends are the directions of the lattice vectors sv and ev. */
typedef struct VisShadow {
	double start, length;
	int32_t sv[2], ev[2];
} VisShadow;

/* The sweep's scratch: the directions still open from the corner being swept,
 * sorted and disjoint, and the shadows of one ring. */
typedef struct VisSweep {
	VisArc *arc, *next;
	int count, cap, next_cap;
	VisShadow *shadow;
	int shadow_count, shadow_cap;
} VisSweep;

static double vis_angle(double dx, double dy)
{
	double t = atan2(dy, dx);
	return t < 0 ? t + VIS_TWO_PI : t;
}

/* vis_arcs_remove(sw, s, e, sv, ev): removes the open interval (s, e) from the arcs;
 * sv and ev are the lattice vectors of its ends. */
static void vis_arcs_remove(VisSweep *sw, double s, double e, const int32_t sv[2],
                            const int32_t ev[2])
{
	int n = 0;
	sw->next = util_grow(sw->next, &sw->next_cap, 2 * sw->count + 1, sizeof *sw->next);
	for (int i = 0; i < sw->count; i++) {
		VisArc r = sw->arc[i];
		if (r.b <= s || r.a >= e) {
			sw->next[n++] = r;
			continue;
		}
		if (r.a <= s)
			sw->next[n++] = (VisArc){r.a, s, r.ax, r.ay, sv[0], sv[1]};
		if (e <= r.b)
			sw->next[n++] = (VisArc){e, r.b, ev[0], ev[1], r.bx, r.by};
	}
	VisArc *t = sw->arc;
	int tc = sw->cap;
	sw->arc = sw->next;
	sw->cap = sw->next_cap;
	sw->next = t;
	sw->next_cap = tc;
	sw->count = n;
}

/* vis_arcs_cut(sw, shadow): removes the open arc of directions of a shadow, from its
 * start (in [0, 2 pi)) counter-clockwise over its length (< pi), shrunk by the
 * slack. */
static void vis_arcs_cut(VisSweep *sw, const VisShadow *sh)
{
	double s = sh->start + VIS_ANGLE_EPS, e = sh->start + sh->length - VIS_ANGLE_EPS;
	if (!(s < e))
		return;
	if (e <= VIS_TWO_PI)
		vis_arcs_remove(sw, s, e, sh->sv, sh->ev);
	else {
		/* Across direction 0 (= 2 pi), which the open arc contains. */
		vis_arcs_remove(sw, s, VIS_TWO_PI + 1, sh->sv, sh->ev);
		vis_arcs_remove(sw, -1, e - VIS_TWO_PI, sh->sv, sh->ev);
	}
}

/* vis_arcs_hold(sw, t): direction t is in an arc (with the slack). */
static bool vis_arcs_hold(const VisSweep *sw, double t)
{
	for (int i = 0; i < sw->count; i++) {
		const VisArc *r = &sw->arc[i];
		if ((r->a - VIS_ANGLE_EPS <= t && t <= r->b + VIS_ANGLE_EPS) ||
		    (t < VIS_ANGLE_EPS && r->b >= VIS_TWO_PI - VIS_ANGLE_EPS))
			return true;
	}
	return false;
}

/* vis_shadow(sw, dx, dy): records the shadow of the square [dx, dx+1] x [dy, dy+1]
 * (relative to the corner swept, which is not inside it): the open arc of
 * directions whose rays enter its open interior. */
static void vis_shadow(VisSweep *sw, int32_t dx, int32_t dy)
{
	double c = atan2(dy + 0.5, dx + 0.5), lo = INFINITY, hi = -INFINITY;
	VisShadow sh = {0};
	for (int k = 0; k < 4; k++) {
		int32_t px = dx + (k & 1), py = dy + (k >> 1);
		if (px == 0 && py == 0)
			continue; /* the swept corner itself is a corner of the square */
		double d = atan2(py, px) - c;
		d = d > VIS_PI ? d - VIS_TWO_PI : d < -VIS_PI ? d + VIS_TWO_PI : d;
		if (d < lo) {
			lo = d;
			sh.sv[0] = px;
			sh.sv[1] = py;
		}
		if (d > hi) {
			hi = d;
			sh.ev[0] = px;
			sh.ev[1] = py;
		}
	}
	double start = c + lo;
	sh.start = start < 0             ? start + VIS_TWO_PI
	           : start >= VIS_TWO_PI ? start - VIS_TWO_PI
	                                 : start;
	sh.length = hi - lo;
	sw->shadow =
	    util_grow(sw->shadow, &sw->shadow_cap, sw->shadow_count + 1, sizeof *sw->shadow);
	sw->shadow[sw->shadow_count++] = sh;
}

/* The four sides of a ring, counter-clockwise from +x: each is the lattice points
 * u + D f + j l, j in [-D, D], seen in directions within 45 degrees of f. */
static const int8_t vis_side_f[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
static const int8_t vis_side_l[4][2] = {{0, 1}, {-1, 0}, {0, -1}, {1, 0}};

/* vis_side_range(arc, k, D, margin, &j0, &j1): the positions j on side k of ring D
 * whose directions can meet arc, widened by margin; false when none. */
static bool vis_side_range(VisArc arc, int k, int32_t D, int32_t margin, int32_t *j0, int32_t *j1)
{
	double centre = k * (VIS_PI / 2);
	for (int shift = -1; shift <= 1; shift++) {
		double lo = arc.a + shift * VIS_TWO_PI - centre;
		double hi = arc.b + shift * VIS_TWO_PI - centre;
		lo = lo > -VIS_PI / 4 ? lo : -VIS_PI / 4;
		hi = hi < VIS_PI / 4 ? hi : VIS_PI / 4;
		if (lo > hi + VIS_ANGLE_EPS)
			continue;
		double a = floor(D * tan(lo)) - margin, b = ceil(D * tan(hi)) + margin;
		*j0 = a > -D ? (int32_t)a : -D;
		*j1 = b < D ? (int32_t)b : D;
		return *j0 <= *j1;
	}
	return false;
}

/* vis_try(vg, stamp, u, v, dx, dy, add, ctx): v, seen from u along (dx, dy) by a
 * free segment, becomes an edge when new and tangent at both ends. */
static void vis_try(const VisibilityGraph *vg, int32_t *stamp, int32_t u, int32_t v, int32_t dx,
                    int32_t dy, void (*add)(void *, int32_t, int32_t), void *ctx)
{
	if (v <= u || stamp[v] == u)
		return;
	stamp[v] = u;
	if (!vis_into(dx, dy, vg->qx[v], vg->qy[v]) && !vis_into(-dx, -dy, vg->qx[u], vg->qy[u]))
		add(ctx, u, v);
}

static int32_t vis_gcd(int32_t a, int32_t b)
{
	a = a < 0 ? -a : a;
	b = b < 0 ? -b : b;
	while (b) {
		int32_t t = a % b;
		a = b;
		b = t;
	}
	return a;
}

/* vis_slivers: replaces every sliver (a single ray left open between two shadows
 * that touch) by a walk along that ray: its lattice points, one step of the reduced
 * lattice vector at a time, for as long as the segment from u stays free. Left in
 * the arcs, a sliver would keep the sweep going to the edge of the grid; most are
 * rays through the shared corner of two blocked cells, blocked at once. */
static void vis_slivers(const VisibilityGraph *vg, const int32_t *corner_at, int32_t *stamp,
                        VisSweep *sw, int32_t u, void (*add)(void *, int32_t, int32_t), void *ctx)
{
	const Grid *g = vg->grid;
	const int32_t lw = g->w + 1;
	int n = 0;
	for (int i = 0; i < sw->count; i++) {
		VisArc r = sw->arc[i];
		bool sliver = r.b - r.a < VIS_SLIVER &&
		              (int64_t)r.ax * r.by == (int64_t)r.ay * r.bx &&
		              (int64_t)r.ax * r.bx + (int64_t)r.ay * r.by > 0;
		if (!sliver) {
			sw->arc[n++] = r;
			continue;
		}
		int32_t k = vis_gcd(r.ax, r.ay), sx = r.ax / k, sy = r.ay / k;
		Vec2 p = vec2(vg->x[u], vg->y[u]);
		for (int32_t m = 1;; m++) {
			Vec2 q = vec2(p.x + sx, p.y + sy);
			if (q.x < 0 || q.y < 0 || q.x > g->w || q.y > g->h)
				break;
			/* u..q is free when u..p is, p is no pinch point, and p..q is free. */
			if ((m > 1 && vis_pinch(g, p.x, p.y, false)) ||
			    !visibility_segment_free(g, p, q))
				break;
			int32_t v = corner_at[(size_t)q.y * lw + (size_t)q.x];
			if (v >= 0)
				vis_try(vg, stamp, u, v, m * sx, m * sy, add, ctx);
			p = q;
		}
	}
	sw->count = n;
}

/* vis_sweep(vg, corner_at, stamp, sw, u, add, ctx): calls add(ctx, u, v) for every
 * corner v > u that u sees along a line tangent at both ends.
 *
 * Rings of growing Chebyshev radius D are swept outward from u, keeping the arcs
 * of directions no blocked square has shadowed yet. A blocked square lying within
 * radius D hides, from u, every lattice point at radius D whose direction enters the
 * square's open interior: the ray meets the interior before it arrives. So in ring
 * D, first the blocked cells of the ring (those whose far side is at radius D) cast
 * their shadows, then the corners of the ring in still-open directions become
 * candidates, each judged by the exact line test. Only the parts of a ring in open
 * directions are visited, and the sweep stops when no direction is open, so the
 * work is about the area u sees, not the number of corners. */
static void vis_sweep(const VisibilityGraph *vg, const int32_t *corner_at, int32_t *stamp,
                      VisSweep *sw, int32_t u, void (*add)(void *, int32_t, int32_t), void *ctx)
{
	const Grid *g = vg->grid;
	const int32_t ux = vg->x[u], uy = vg->y[u], lw = g->w + 1;
	int32_t dmax = ux > g->w - ux ? ux : g->w - ux;
	dmax = dmax > uy ? dmax : uy;
	dmax = dmax > g->h - uy ? dmax : g->h - uy;
	sw->count = 0;
	sw->arc = util_grow(sw->arc, &sw->cap, 1, sizeof *sw->arc);
	sw->arc[sw->count++] = (VisArc){0, VIS_TWO_PI, 1, 0, 1, 0};
	/* Cells are visited with two positions of slack on each side: a ring cell's
	 * angular extent is up to D / (D - 1) times its span on the ring's side. */
	const int32_t cell_margin = 2, point_margin = 1;
	for (int32_t D = 1; D <= dmax && sw->count > 0; D++) {
		sw->shadow_count = 0;
		for (int k = 0; k < 4; k++) {
			const int f0 = vis_side_f[k][0], f1 = vis_side_f[k][1];
			const int l0 = vis_side_l[k][0], l1 = vis_side_l[k][1];
			for (int i = 0; i < sw->count; i++) {
				int32_t j0, j1;
				if (!vis_side_range(sw->arc[i], k, D, cell_margin, &j0, &j1))
					continue;
				if (j1 > D - 1)
					j1 = D - 1;
				for (int32_t j = j0; j <= j1; j++) {
					/* The cell spanning f in [D-1, D], l in [j, j+1]: its
					 * lowest corner, relative to u. */
					int32_t ax = (D - 1) * f0 + j * l0,
					        bx = D * f0 + (j + 1) * l0;
					int32_t ay = (D - 1) * f1 + j * l1,
					        by = D * f1 + (j + 1) * l1;
					int32_t cx = ax < bx ? ax : bx, cy = ay < by ? ay : by;
					if (grid_free_at(g, ux + cx, uy + cy))
						continue;
					/* Outside cells cast no shadow worth keeping: no lattice
					 * point of the grid lies behind them. */
					if (ux + cx < 0 || uy + cy < 0 || ux + cx >= g->w ||
					    uy + cy >= g->h)
						continue;
					vis_shadow(sw, cx, cy);
				}
			}
		}
		for (int i = 0; i < sw->shadow_count; i++)
			vis_arcs_cut(sw, &sw->shadow[i]);
		vis_slivers(vg, corner_at, stamp, sw, u, add, ctx);
		for (int k = 0; k < 4 && sw->count > 0; k++) {
			const int f0 = vis_side_f[k][0], f1 = vis_side_f[k][1];
			const int l0 = vis_side_l[k][0], l1 = vis_side_l[k][1];
			for (int i = 0; i < sw->count; i++) {
				int32_t j0, j1;
				if (!vis_side_range(sw->arc[i], k, D, point_margin, &j0, &j1))
					continue;
				for (int32_t j = j0; j <= j1; j++) {
					int32_t dx = D * f0 + j * l0, dy = D * f1 + j * l1;
					int32_t px = ux + dx, py = uy + dy;
					if (px < 1 || py < 1 || px >= g->w || py >= g->h)
						continue;
					int32_t v = corner_at[(size_t)py * lw + px];
					if (v <= u || stamp[v] == u ||
					    !vis_arcs_hold(sw, vis_angle(dx, dy)) ||
					    !visibility_segment_free(g, vec2(ux, uy), vec2(px, py)))
						continue;
					vis_try(vg, stamp, u, v, dx, dy, add, ctx);
				}
			}
		}
	}
}

/* The edge list the sweep fills: pairs (u, v), u < v, and each corner's degree. */
typedef struct VisPairs {
	int32_t *pair;
	int count, cap;
	int32_t *degree;
	bool overflow;
} VisPairs;

static void vis_pairs_add(void *ctx, int32_t u, int32_t v)
{
	VisPairs *p = ctx;
	if (p->overflow || p->count > INT32_MAX / 2 - 2) {
		p->overflow = true; /* more edges than an int32_t index holds */
		return;
	}
	p->pair = util_grow(p->pair, &p->cap, p->count + 2, sizeof *p->pair);
	p->pair[p->count++] = u;
	p->pair[p->count++] = v;
	p->degree[u]++;
	p->degree[v]++;
}

/* ---- the graph ---------------------------------------------------------------- */

static int vis_cmp_int32(const void *a, const void *b)
{
	int32_t x = *(const int32_t *)a, y = *(const int32_t *)b;
	return (x > y) - (x < y);
}

VisibilityStatus visibility_init(VisibilityGraph *vg, const Grid *grid, int32_t max_vertices)
{
	*vg = (VisibilityGraph){.grid = grid};
	int32_t n = visibility_count_corners(grid);
	if (n > max_vertices)
		return VISIBILITY_TOO_LARGE;
	vg->count = n;
	vg->x = util_alloc((size_t)n, sizeof *vg->x);
	vg->y = util_alloc((size_t)n, sizeof *vg->y);
	vg->qx = util_alloc((size_t)n, sizeof *vg->qx);
	vg->qy = util_alloc((size_t)n, sizeof *vg->qy);
	int32_t k = 0;
	int8_t qx, qy;
	for (int32_t Y = 1; Y < grid->h; Y++)
		for (int32_t X = 1; X < grid->w; X++)
			if (vis_corner(grid, X, Y, &qx, &qy)) {
				vg->x[k] = X;
				vg->y[k] = Y;
				vg->qx[k] = qx;
				vg->qy[k] = qy;
				k++;
			}

	/* Every tangent, free pair (u < v) by a sweep from each corner, then the
	 * compressed rows in both directions. */
	const size_t lattice = (size_t)(grid->w + 1) * (size_t)(grid->h + 1);
	int32_t *corner_at = util_alloc(lattice, sizeof *corner_at);
	for (size_t i = 0; i < lattice; i++)
		corner_at[i] = -1;
	for (int32_t i = 0; i < n; i++)
		corner_at[(size_t)vg->y[i] * (grid->w + 1) + vg->x[i]] = i;
	int32_t *stamp = util_alloc((size_t)n + 1, sizeof *stamp);
	for (int32_t i = 0; i < n; i++)
		stamp[i] = -1;
	VisPairs pairs = {.degree = util_alloc((size_t)n + 1, sizeof(int32_t))};
	VisSweep sw = {0};
	for (int32_t u = 0; u < n && !pairs.overflow; u++)
		vis_sweep(vg, corner_at, stamp, &sw, u, vis_pairs_add, &pairs);
	free(sw.arc);
	free(sw.next);
	free(sw.shadow);
	free(stamp);
	free(corner_at);
	if (pairs.overflow) {
		free(pairs.pair);
		free(pairs.degree);
		visibility_free(vg);
		*vg = (VisibilityGraph){.grid = grid};
		return VISIBILITY_TOO_LARGE;
	}
	int32_t *pair = pairs.pair, *degree = pairs.degree;
	int pair_count = pairs.count;
	vg->edges = pair_count / 2;
	vg->first = util_alloc((size_t)n + 1, sizeof *vg->first);
	for (int32_t i = 0; i < n; i++)
		vg->first[i + 1] = vg->first[i] + degree[i];
	vg->adj = util_alloc((size_t)pair_count, sizeof *vg->adj);
	memcpy(degree, vg->first, (size_t)n * sizeof *degree); /* reused as fill cursors */
	for (int p = 0; p < pair_count; p += 2) {
		vg->adj[degree[pair[p]]++] = pair[p + 1];
		vg->adj[degree[pair[p + 1]]++] = pair[p];
	}
	/* The sweep finds neighbours in the order it meets them: sort each row, so the
	 * graph does not depend on how it was built. */
	for (int32_t i = 0; i < n; i++)
		qsort(vg->adj + vg->first[i], (size_t)(vg->first[i + 1] - vg->first[i]),
		      sizeof *vg->adj, vis_cmp_int32);
	free(pair);
	free(degree);
	vg->g = util_alloc((size_t)n + 2, sizeof *vg->g);
	vg->parent = util_alloc((size_t)n + 2, sizeof *vg->parent);
	vg->state = util_alloc((size_t)n + 2, sizeof *vg->state);
	vg->to_goal = util_alloc((size_t)n + 2, sizeof *vg->to_goal);
	return VISIBILITY_FOUND;
}

void visibility_free(VisibilityGraph *vg)
{
	free(vg->x);
	free(vg->y);
	free(vg->qx);
	free(vg->qy);
	free(vg->first);
	free(vg->adj);
	free(vg->g);
	free(vg->parent);
	free(vg->state);
	free(vg->to_goal);
	*vg = (VisibilityGraph){0};
}

/* ---- the query ---------------------------------------------------------------- */

static inline double vis_dist(Vec2 a, Vec2 b)
{
	return hypot(b.x - a.x, b.y - a.y);
}

enum { VIS_UNSEEN = 0, VIS_OPEN, VIS_CLOSED };

VisibilityStatus visibility_find(VisibilityGraph *vg, Vec2 s, Vec2 d, Path *path, double *length)
{
	path_clear(path);
	*length = -1;
	const Grid *grid = vg->grid;
	if (!visibility_segment_free(grid, s, s) || !visibility_segment_free(grid, d, d))
		return VISIBILITY_BAD_ENDPOINT;
	const int32_t n = vg->count, S = n, D = n + 1;
	if (visibility_segment_free(grid, s, d)) {
		path_push(path, s);
		path_push(path, d);
		path->expanded = 1;
		*length = vis_dist(s, d);
		return VISIBILITY_FOUND;
	}
	/* Which corners S and D see; only tangent lines at the corner end. */
	int32_t *from_start = util_alloc((size_t)n + 1, sizeof *from_start);
	int32_t start_count = 0;
	for (int32_t i = 0; i < n; i++) {
		Vec2 c = vec2(vg->x[i], vg->y[i]);
		vg->to_goal[i] = -1;
		vg->state[i] = VIS_UNSEEN;
		if (!vis_into(c.x - s.x, c.y - s.y, vg->qx[i], vg->qy[i]) &&
		    visibility_segment_free(grid, s, c))
			from_start[start_count++] = i;
		if (!vis_into(c.x - d.x, c.y - d.y, vg->qx[i], vg->qy[i]) &&
		    visibility_segment_free(grid, c, d))
			vg->to_goal[i] = vis_dist(c, d);
	}
	vg->state[S] = vg->state[D] = VIS_UNSEEN;

	Heap heap;
	heap_init(&heap);
	vg->g[S] = 0;
	vg->parent[S] = -1;
	vg->state[S] = VIS_OPEN;
	heap_push(&heap, vis_dist(s, d), S);
	int64_t expanded = 0;
	while (heap.count > 0) {
		int32_t u = heap_pop(&heap);
		if (vg->state[u] == VIS_CLOSED)
			continue;
		vg->state[u] = VIS_CLOSED;
		expanded++;
		if (u == D)
			break;
		Vec2 pu = u == S ? s : vec2(vg->x[u], vg->y[u]);
		int32_t count = u == S ? start_count : vg->first[u + 1] - vg->first[u];
		const int32_t *next = u == S ? from_start : vg->adj + vg->first[u];
		/* The corners, then D when u sees it. */
		for (int32_t k = 0; k <= count; k++) {
			int32_t v;
			double step;
			Vec2 pv;
			if (k < count) {
				v = next[k];
				pv = vec2(vg->x[v], vg->y[v]);
				step = vis_dist(pu, pv);
			} else {
				if (u == S || vg->to_goal[u] < 0)
					break;
				v = D;
				pv = d;
				step = vg->to_goal[u];
			}
			if (vg->state[v] == VIS_CLOSED)
				continue;
			double gv = vg->g[u] + step;
			if (vg->state[v] == VIS_OPEN && !(gv < vg->g[v]))
				continue;
			vg->state[v] = VIS_OPEN;
			vg->g[v] = gv;
			vg->parent[v] = u;
			heap_push(&heap, gv + vis_dist(pv, d), v);
		}
	}
	heap_free(&heap);
	free(from_start);
	path->expanded = expanded;
	if (vg->state[D] != VIS_CLOSED)
		return VISIBILITY_NO_PATH;
	int32_t steps = 0;
	for (int32_t v = D; v != S; v = vg->parent[v])
		steps++;
	for (int32_t i = 0; i <= steps; i++)
		path_push(path, s);
	int32_t i = steps;
	for (int32_t v = D; v != S; v = vg->parent[v])
		path->pts[i--] = v == D ? d : vec2(vg->x[v], vg->y[v]);
	*length = vg->g[D];
	return VISIBILITY_FOUND;
}
