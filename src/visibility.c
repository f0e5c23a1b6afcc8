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
 *  - Query: S and D are joined to the corners they see (S to D directly when free),
 *    then A* (Hart, Nilsson and Raphael 1968) with the straight-line distance to D,
 *    which is consistent, so nodes close once.
 *
 * INVARIANTS: adj holds each tangent, free corner-corner edge twice, once per end;
 * the rows of first[] are sorted by construction (i ascending, then j ascending).
 * MEMORY: 10 bytes per corner, 8 bytes per edge, 23 bytes per node for a query.
 * COMPLEXITY: build O(V^2 L) for V corners and segments L cells long (early exit
 * on the first blocked cell keeps L small on cluttered maps); query O(V L + E log V).
 */
#include "utak/visibility.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/util.h"

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

bool visibility_path_free(const Grid *g, const Path *p)
{
	if (p->count == 0)
		return false;
	if (p->count == 1)
		return visibility_segment_free(g, p->pts[0], p->pts[0]);
	for (int i = 1; i < p->count; i++) {
		if (!visibility_segment_free(g, p->pts[i - 1], p->pts[i]))
			return false;
		Vec2 q = p->pts[i];
		if (i + 1 < p->count && q.x == floor(q.x) && q.y == floor(q.y) &&
		    vis_pinch(g, q.x, q.y, false))
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

/* ---- the graph ---------------------------------------------------------------- */

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

	/* Every tangent, free pair (i < j), then the compressed rows in both directions. */
	int32_t *pair = NULL;
	int pair_count = 0, pair_cap = 0;
	int32_t *degree = util_alloc((size_t)n + 1, sizeof *degree);
	for (int32_t i = 0; i < n; i++)
		for (int32_t j = i + 1; j < n; j++) {
			double dx = (double)vg->x[j] - vg->x[i], dy = (double)vg->y[j] - vg->y[i];
			if (vis_into(dx, dy, vg->qx[j], vg->qy[j]) ||
			    vis_into(-dx, -dy, vg->qx[i], vg->qy[i]))
				continue;
			if (!visibility_segment_free(grid, vec2(vg->x[i], vg->y[i]),
			                             vec2(vg->x[j], vg->y[j])))
				continue;
			if (pair_count > INT32_MAX / 2 - 2) {
				/* More edges than an int32_t index holds: refuse, not truncate. */
				free(pair);
				free(degree);
				visibility_free(vg);
				*vg = (VisibilityGraph){.grid = grid};
				return VISIBILITY_TOO_LARGE;
			}
			pair = util_grow(pair, &pair_cap, pair_count + 2, sizeof *pair);
			pair[pair_count++] = i;
			pair[pair_count++] = j;
			degree[i]++;
			degree[j]++;
		}
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

typedef struct VisOpen {
	double f;
	int32_t node;
} VisOpen;

typedef struct VisHeap {
	VisOpen *e;
	int count, cap;
} VisHeap;

static void vis_heap_push(VisHeap *h, VisOpen e)
{
	h->e = util_grow(h->e, &h->cap, h->count + 1, sizeof *h->e);
	int i = h->count++;
	while (i > 0 && e.f < h->e[(i - 1) / 2].f) {
		h->e[i] = h->e[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	h->e[i] = e;
}

static VisOpen vis_heap_pop(VisHeap *h)
{
	VisOpen top = h->e[0], last = h->e[--h->count];
	int i = 0;
	for (;;) {
		int c = 2 * i + 1;
		if (c >= h->count)
			break;
		if (c + 1 < h->count && h->e[c + 1].f < h->e[c].f)
			c++;
		if (!(h->e[c].f < last.f))
			break;
		h->e[i] = h->e[c];
		i = c;
	}
	if (h->count > 0)
		h->e[i] = last;
	return top;
}

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

	VisHeap heap = {0};
	vg->g[S] = 0;
	vg->parent[S] = -1;
	vg->state[S] = VIS_OPEN;
	vis_heap_push(&heap, (VisOpen){vis_dist(s, d), S});
	int64_t expanded = 0;
	while (heap.count > 0) {
		VisOpen e = vis_heap_pop(&heap);
		int32_t u = e.node;
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
			vis_heap_push(&heap, (VisOpen){gv + vis_dist(pv, d), v});
		}
	}
	free(heap.e);
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
