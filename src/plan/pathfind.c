/* pathfind.c - finding paths on the pathgraph (paper 4.3, Figure 3): S' and D', the
 * skeleton cells that S and D see; A* over the vertices with the edges holding S' and
 * D' split into pieces; the route written out as a polyline; k distinct routes. The
 * graph itself is built by pathgraph.c; see pathgraph.h for what the vertices, edges
 * and paths are, and pathgraph.c's header for the algorithm, invariants, memory and
 * measured costs of both halves.
 *
 * ALGORITHM  S' and D' by breadth-first search over free cells from S and D
 *    (4-connected, the topology of skeleton.h), testing each skeleton cell met with
 *    the line test and stopping once no nearer visible cell can be met (a cell in
 *    sight at distance e is at most sqrt(2) e + 1 steps away). Then A* (Hart, Nilsson
 *    and Raphael 1968, the paper's reference [8]) over the vertices plus S' and D'.
 *    k paths: Yen (1971), see pathgraph.h. */
#include "utak/plan/pathgraph.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/plan/heap.h"
#include "utak/plan/visibility.h"
#include "pathgraph_work.h"

/* ---------------------------------------------------------------- the line test */

/* One line test serves all of utak (visibility.h): it judges the segment without its
 * end points, because the visibility graph and the rope bend at lattice corners. The
 * pathgraph's callers test a whole segment, ends included, so an end at a pinch point
 * (where free space does not connect) makes the segment not free. */
bool pathgraph_segment_free(const Grid *g, Vec2 a, Vec2 b)
{
	return visibility_segment_free(g, a, b) && !visibility_pinch_point(g, a) &&
	       !visibility_pinch_point(g, b);
}

/* ---------------------------------------------------------------- query scratch */

/* pathgraph_scratch(pg): the query scratch, made or grown to the current graph. It
 * survives pathgraph_build, so that a planner that rebuilds the pathgraph of a screen
 * of one size touches no new memory; stamps only grow, so stale entries never match. */
static struct PathgraphScratch *pathgraph_scratch(Pathgraph *pg)
{
	if (!pg->scratch)
		pg->scratch = util_alloc(1, sizeof *pg->scratch);
	struct PathgraphScratch *sc = pg->scratch;
	size_t n = (size_t)pg->w * pg->h;
	if (sc->grid_cells != n || !sc->visit) {
		free(sc->visit);
		free(sc->parent);
		free(sc->queue);
		sc->grid_cells = n;
		sc->visit = util_alloc(n + 1, sizeof *sc->visit);
		sc->parent = util_alloc(n + 1, sizeof *sc->parent);
		sc->queue = util_alloc(n + 1, sizeof *sc->queue);
		sc->visit_stamp = 0;
	}
	if (sc->node_cap < pg->vertex_count + 2) {
		size_t nodes = (size_t)pg->vertex_count + 2;
		free(sc->g);
		free(sc->pred_arc);
		free(sc->pred_node);
		free(sc->seen);
		free(sc->closed);
		free(sc->node_ban);
		sc->node_cap = (int32_t)nodes;
		sc->g = util_alloc(nodes, sizeof *sc->g);
		sc->pred_arc = util_alloc(nodes, sizeof *sc->pred_arc);
		sc->pred_node = util_alloc(nodes, sizeof *sc->pred_node);
		sc->seen = util_alloc(nodes, sizeof *sc->seen);
		sc->closed = util_alloc(nodes, sizeof *sc->closed);
		sc->node_ban = util_alloc(nodes, sizeof *sc->node_ban);
	}
	if (sc->arc_cap < pg->edge_count + PATHGRAPH_MAX_PIECES) {
		free(sc->arc_ban);
		sc->arc_cap = pg->edge_count + PATHGRAPH_MAX_PIECES;
		sc->arc_ban = util_alloc((size_t)sc->arc_cap, sizeof *sc->arc_ban);
	}
	return sc;
}

/* ---------------------------------------------------------------- S' and D' */

/* pathgraph_entry_search(pg, p, &cell, walk): see pathgraph_entry; for a walk, the
 * cells from p's cell to the entry cell go into walk (emptied first). */
static int pathgraph_entry_search(Pathgraph *pg, Vec2 p, int32_t *cell, IntList *walk)
{
	struct PathgraphScratch *sc = pathgraph_scratch(pg);
	walk->count = 0;
	if (!(p.x >= 0 && p.y >= 0 && p.x < pg->w && p.y < pg->h))
		return 0;
	int32_t px = (int32_t)floor(p.x), py = (int32_t)floor(p.y);
	if (!grid_free_at(pg->grid, px, py))
		return 0;
	if (sc->visit_stamp == INT32_MAX) {
		memset(sc->visit, 0, (size_t)pg->w * pg->h * sizeof *sc->visit);
		sc->visit_stamp = 0;
	}
	int32_t stamp = ++sc->visit_stamp;
	const int32_t w = pg->w;
	const uint8_t *on = pg->skeleton->on;
	int32_t head = 0, tail = 0, start = py * w + px;
	sc->queue[tail++] = start;
	sc->visit[start] = stamp;
	sc->parent[start] = -1;
	int32_t best = -1, first = -1;
	double best_e2 = HUGE_VAL;
	for (int32_t depth = 0; head < tail; depth++) {
		/* a cell in sight at distance e is at most sqrt(2) e + 1 steps away */
		if (best >= 0 && depth > PATHGRAPH_SQRT2 * sqrt(best_e2) + 2)
			break;
		int32_t layer_end = tail;
		while (head < layer_end) {
			int32_t c = sc->queue[head++], cx = c % w, cy = c / w;
			if (on[c]) {
				if (first < 0)
					first = c;
				Vec2 centre = vec2(cx + 0.5, cy + 0.5);
				double e2 = vec2_dot(vec2_sub(centre, p), vec2_sub(centre, p));
				if (e2 < best_e2 && pathgraph_segment_free(pg->grid, p, centre)) {
					best = c;
					best_e2 = e2;
				}
			}
			for (int d = 0; d < 4; d++) {
				int32_t nx = cx + PATHGRAPH_DX[d], ny = cy + PATHGRAPH_DY[d];
				if (!grid_free_at(pg->grid, nx, ny))
					continue;
				int32_t nb = ny * w + nx;
				if (sc->visit[nb] != stamp) {
					sc->visit[nb] = stamp;
					sc->parent[nb] = c;
					sc->queue[tail++] = nb;
				}
			}
		}
	}
	if (best >= 0) {
		*cell = best;
		return 1;
	}
	if (first < 0)
		return 0;
	for (int32_t c = first; c >= 0; c = sc->parent[c])
		intlist_push(walk, c);
	for (int i = 0, j = walk->count - 1; i < j; i++, j--) {
		int32_t t = walk->v[i];
		walk->v[i] = walk->v[j];
		walk->v[j] = t;
	}
	*cell = first;
	return 2;
}

int pathgraph_entry(Pathgraph *pg, Vec2 p, int32_t *x, int32_t *y)
{
	struct PathgraphScratch *sc = pathgraph_scratch(pg);
	int32_t cell = -1;
	int r = pathgraph_entry_search(pg, p, &cell, &sc->walk_s);
	if (r) {
		*x = cell % pg->w;
		*y = cell / pg->w;
	}
	return r;
}

/* pathgraph_vertex_walk(pg, c, v, out): appends the cells from c to vertex v's cell,
 * through the cells of v (a junction set), breadth-first. */
static void pathgraph_vertex_walk(Pathgraph *pg, int32_t c, int32_t v, IntList *out)
{
	struct PathgraphScratch *sc = pg->scratch;
	const int32_t w = pg->w;
	int32_t goal = pg->vertices[v].y * w + pg->vertices[v].x;
	int32_t stamp = ++sc->visit_stamp;
	int32_t head = 0, tail = 0;
	sc->queue[tail++] = goal;
	sc->visit[goal] = stamp;
	sc->parent[goal] = -1;
	while (head < tail && sc->visit[c] != stamp) {
		int32_t q = sc->queue[head++], qx = q % w, qy = q / w;
		for (int d = 0; d < 4; d++) {
			int32_t nx = qx + PATHGRAPH_DX[d], ny = qy + PATHGRAPH_DY[d];
			if (nx < 0 || ny < 0 || nx >= w || ny >= pg->h)
				continue;
			int32_t nb = ny * w + nx;
			if (pathgraph_cell_ref(pg, nb) == v && sc->visit[nb] != stamp) {
				sc->visit[nb] = stamp;
				sc->parent[nb] = q;
				sc->queue[tail++] = nb;
			}
		}
	}
	assert(sc->visit[c] == stamp);
	for (int32_t q = c; q >= 0; q = sc->parent[q])
		intlist_push(out, q);
}

/* ---------------------------------------------------------------- the search graph */

/* pathgraph_add_piece(pg, u, v, edge, pos_u, pos_v, cell): a piece joining nodes u and
 * v (see PathgraphPiece), with its cost and clearance. */
static void pathgraph_add_piece(Pathgraph *pg, int32_t u, int32_t v, int32_t edge, int32_t pos_u,
                                int32_t pos_v, int32_t cell)
{
	struct PathgraphScratch *sc = pg->scratch;
	assert(sc->piece_count < PATHGRAPH_MAX_PIECES);
	PathgraphPiece *p = &sc->pieces[sc->piece_count++];
	*p = (PathgraphPiece){u, v, edge, pos_u, pos_v, cell, 0, INT32_MAX};
	const int32_t *d2 = pg->skeleton->dist2;
	if (edge < 0) {
		sc->cells.count = 0;
		pathgraph_vertex_walk(pg, cell, u < pg->vertex_count ? u : v, &sc->cells);
		p->cost = pathgraph_run_length(pg, sc->cells.v, sc->cells.count, 1);
		for (int k = 0; k < sc->cells.count; k++)
			if (d2[sc->cells.v[k]] < p->min_dist2)
				p->min_dist2 = d2[sc->cells.v[k]];
		return;
	}
	const int32_t *c = pg->cells + pg->edges[edge].first;
	int step = pos_u <= pos_v ? 1 : -1;
	p->cost = pathgraph_run_length(pg, c + pos_u, abs(pos_v - pos_u) + 1, step);
	for (int32_t k = pos_u;; k += step) {
		if (d2[c[k]] < p->min_dist2)
			p->min_dist2 = d2[c[k]];
		if (k == pos_v)
			break;
	}
}

/* pathgraph_splice(pg, s_cell, d_cell): S' and D' into the search graph as nodes
 * vertex_count and vertex_count + 1, with the pieces of the edges that hold them. */
static void pathgraph_splice(Pathgraph *pg, int32_t s_cell, int32_t d_cell)
{
	struct PathgraphScratch *sc = pg->scratch;
	const int32_t V = pg->vertex_count, S = V, D = V + 1;
	sc->piece_count = 0;
	sc->skip_edge[0] = sc->skip_edge[1] = -1;
	int32_t ends[2] = {s_cell, d_cell}, nodes[2] = {S, D};
	int32_t edge[2], pos[2];
	for (int i = 0; i < 2; i++) {
		int32_t ref = pathgraph_cell_ref(pg, ends[i]);
		assert(ref >= 0);
		edge[i] = ref < V ? -1 : pg->cell_edge[ref - V];
		pos[i] = ref < V ? -1 : ref - V - pg->edges[edge[i]].first;
	}
	/* vertex cells: a walk inside the vertex */
	if (edge[0] < 0)
		pathgraph_add_piece(pg, pathgraph_cell_ref(pg, s_cell), S, -1, 0, 0, s_cell);
	if (edge[1] < 0)
		pathgraph_add_piece(pg, pathgraph_cell_ref(pg, d_cell), D, -1, 0, 0, d_cell);
	if (edge[0] >= 0 && edge[0] == edge[1]) {
		const PathgraphEdge *e = &pg->edges[edge[0]];
		int lo = pos[0] < pos[1] ? 0 : 1, hi = 1 - lo;
		pathgraph_add_piece(pg, e->v0, nodes[lo], edge[0], 0, pos[lo], -1);
		pathgraph_add_piece(pg, nodes[lo], nodes[hi], edge[0], pos[lo], pos[hi], -1);
		pathgraph_add_piece(pg, nodes[hi], e->v1, edge[0], pos[hi], e->count - 1, -1);
		sc->skip_edge[0] = edge[0];
		return;
	}
	for (int i = 0; i < 2; i++) {
		if (edge[i] < 0)
			continue;
		const PathgraphEdge *e = &pg->edges[edge[i]];
		pathgraph_add_piece(pg, e->v0, nodes[i], edge[i], 0, pos[i], -1);
		pathgraph_add_piece(pg, nodes[i], e->v1, edge[i], pos[i], e->count - 1, -1);
		sc->skip_edge[i] = edge[i];
	}
}

/* Arc ids: an edge id, or edge_count + a piece index. */
static double pathgraph_arc_cost(const Pathgraph *pg, int32_t arc)
{
	return arc < pg->edge_count ? pg->edges[arc].length
	                            : pg->scratch->pieces[arc - pg->edge_count].cost;
}

/* pathgraph_node_centre(pg, node, s_cell, d_cell): where a node is, in grid units. */
static Vec2 pathgraph_cell_centre(const Pathgraph *pg, int32_t c)
{
	return vec2(c % pg->w + 0.5, c / pg->w + 0.5);
}

/* ---------------------------------------------------------------- A* */

typedef struct SearchEnds {
	int32_t s_cell, d_cell; /* the cells of S' and D' */
} SearchEnds;

static Vec2 pathgraph_node_centre(const Pathgraph *pg, const SearchEnds *se, int32_t node)
{
	if (node < pg->vertex_count)
		return vec2(pg->vertices[node].x + 0.5, pg->vertices[node].y + 0.5);
	return pathgraph_cell_centre(pg, node == pg->vertex_count ? se->s_cell : se->d_cell);
}

/* pathgraph_relax(pg, se, node, arc, other, cost, min_dist2): one arc out of node. */
static void pathgraph_relax(Pathgraph *pg, const SearchEnds *se, int32_t node, int32_t arc,
                            int32_t other, double cost, int32_t min_dist2)
{
	struct PathgraphScratch *sc = pg->scratch;
	if (sc->arc_ban[arc] == sc->ban_stamp || sc->node_ban[other] == sc->ban_stamp ||
	    sc->closed[other] == sc->search_stamp || (double)min_dist2 < sc->min_d2)
		return;
	double ng = sc->g[node] + cost;
	if (sc->seen[other] == sc->search_stamp && ng >= sc->g[other])
		return;
	sc->seen[other] = sc->search_stamp;
	sc->g[other] = ng;
	sc->pred_arc[other] = arc;
	sc->pred_node[other] = node;
	Vec2 a = pathgraph_node_centre(pg, se, other), b = pathgraph_node_centre(pg, se, sc->goal);
	heap_push(&sc->heap, ng + sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y)),
	                    other);
}

/* pathgraph_astar(pg, se, src, dst, route): the shortest route from src to dst avoiding
 * banned arcs and nodes (ban_stamp) and thin edges; false when there is none. */
static bool pathgraph_astar(Pathgraph *pg, const SearchEnds *se, int32_t src, int32_t dst,
                            Route *route)
{
	struct PathgraphScratch *sc = pg->scratch;
	const int32_t V = pg->vertex_count, E = pg->edge_count;
	int32_t stamp = ++sc->search_stamp;
	sc->goal = dst;
	heap_clear(&sc->heap);
	sc->seen[src] = stamp;
	sc->g[src] = 0;
	sc->pred_arc[src] = -1;
	sc->pred_node[src] = -1;
	heap_push(&sc->heap, 0, src);
	bool found = false;
	while (sc->heap.count > 0) {
		int32_t node = heap_pop(&sc->heap);
		if (sc->closed[node] == stamp)
			continue;
		sc->closed[node] = stamp;
		sc->expanded++;
		if (node == dst) {
			found = true;
			break;
		}
		if (node < V)
			for (int32_t k = pg->incident_start[node]; k < pg->incident_start[node + 1];
			     k++) {
				int32_t e = pg->incident[k];
				const PathgraphEdge *ed = &pg->edges[e];
				if (ed->v0 == ed->v1 || e == sc->skip_edge[0] ||
				    e == sc->skip_edge[1])
					continue;
				pathgraph_relax(pg, se, node, e, ed->v0 == node ? ed->v1 : ed->v0,
				                ed->length, ed->min_dist2);
			}
		for (int i = 0; i < sc->piece_count; i++) {
			const PathgraphPiece *p = &sc->pieces[i];
			if (p->u == p->v)
				continue;
			if (p->u == node)
				pathgraph_relax(pg, se, node, E + i, p->v, p->cost, p->min_dist2);
			else if (p->v == node)
				pathgraph_relax(pg, se, node, E + i, p->u, p->cost, p->min_dist2);
		}
	}
	if (!found)
		return false;
	int len = 0;
	for (int32_t n = dst; n != src; n = sc->pred_node[n])
		len++;
	route->len = len;
	route->nodes = util_realloc(route->nodes, (size_t)len + 1, sizeof *route->nodes);
	route->arcs = util_realloc(route->arcs, (size_t)len + 1, sizeof *route->arcs);
	route->cost = sc->g[dst];
	int i = len;
	for (int32_t n = dst; i >= 0; n = sc->pred_node[n]) {
		route->nodes[i] = n;
		if (i > 0)
			route->arcs[i - 1] = sc->pred_arc[n];
		i--;
	}
	return true;
}

/* ---------------------------------------------------------------- the polyline */

/* pathgraph_push_cell(l, c): appends c, dropping a repeat and undoing a step back. The
 * caller has made room (pathgraph_polyline): this runs once per cell of a path. */
static void pathgraph_push_cell(IntList *l, int32_t c)
{
	if (l->count >= 1 && l->v[l->count - 1] == c)
		return;
	if (l->count >= 2 && l->v[l->count - 2] == c) {
		l->count--;
		return;
	}
	assert(l->count < l->cap);
	l->v[l->count++] = c;
}

/* pathgraph_push_point(out, q): appends q, dropping a repeat and merging a point that
 * lies straight between its neighbours (the polyline covers the same points). */
static void pathgraph_push_point(Path *out, Vec2 q)
{
	if (out->count >= 1 && out->pts[out->count - 1].x == q.x &&
	    out->pts[out->count - 1].y == q.y)
		return;
	if (out->count >= 2) {
		Vec2 a = out->pts[out->count - 2], b = out->pts[out->count - 1];
		Vec2 ab = vec2_sub(b, a), bq = vec2_sub(q, b);
		if (vec2_cross(ab, bq) == 0 && vec2_dot(ab, bq) > 0) {
			out->pts[out->count - 1] = q;
			return;
		}
	}
	path_push(out, q);
}

/* pathgraph_arc_cells(pg, arc, from, l): appends the cells of arc, entered at node from. */
static void pathgraph_arc_cells(Pathgraph *pg, int32_t arc, int32_t from, IntList *l)
{
	struct PathgraphScratch *sc = pg->scratch;
	if (arc < pg->edge_count) {
		const PathgraphEdge *e = &pg->edges[arc];
		const int32_t *c = pg->cells + e->first;
		for (int32_t k = 0; k < e->count; k++)
			pathgraph_push_cell(l, c[e->v0 == from ? k : e->count - 1 - k]);
		return;
	}
	const PathgraphPiece *p = &sc->pieces[arc - pg->edge_count];
	bool forward = p->u == from;
	if (p->edge < 0) {
		/* the walk runs from the S' or D' cell to the vertex's cell */
		IntList walk = {0};
		int32_t vertex = p->u < pg->vertex_count ? p->u : p->v;
		pathgraph_vertex_walk(pg, p->cell, vertex, &walk);
		bool from_vertex = from == vertex;
		for (int k = 0; k < walk.count; k++)
			pathgraph_push_cell(l, walk.v[from_vertex ? walk.count - 1 - k : k]);
		free(walk.v);
		return;
	}
	const int32_t *c = pg->cells + pg->edges[p->edge].first;
	int32_t a = forward ? p->pos_u : p->pos_v, b = forward ? p->pos_v : p->pos_u;
	int step = a <= b ? 1 : -1;
	for (int32_t k = a;; k += step) {
		pathgraph_push_cell(l, c[k]);
		if (k == b)
			break;
	}
}

/* pathgraph_polyline(pg, from, to, route, s_cell, d_cell, out): S, the cells, D. */
static void pathgraph_polyline(Pathgraph *pg, Vec2 from, Vec2 to, const Route *route,
                               int32_t s_cell, int32_t d_cell, Path *out)
{
	struct PathgraphScratch *sc = pg->scratch;
	IntList *l = &sc->cells;
	/* room for every cell: the walks, S' and D', each arc's cells (a walk inside a
	 * junction set has at most the set's cells) */
	int64_t need = (int64_t)sc->walk_s.count + sc->walk_d.count + 2;
	for (int i = 0; route && i < route->len; i++) {
		int32_t arc = route->arcs[i];
		if (arc < pg->edge_count) {
			need += pg->edges[arc].count;
		} else {
			const PathgraphPiece *p = &sc->pieces[arc - pg->edge_count];
			int32_t vertex = p->u < pg->vertex_count ? p->u : p->v;
			need += p->edge < 0 ? pg->vertices[vertex].set_size
			                    : abs(p->pos_v - p->pos_u) + 1;
		}
	}
	assert(need < INT32_MAX);
	l->count = 0;
	l->v = util_grow(l->v, &l->cap, (int)need, sizeof *l->v);
	for (int k = 0; k < sc->walk_s.count; k++)
		pathgraph_push_cell(l, sc->walk_s.v[k]);
	pathgraph_push_cell(l, s_cell);
	for (int i = 0; route && i < route->len; i++)
		pathgraph_arc_cells(pg, route->arcs[i], route->nodes[i], l);
	pathgraph_push_cell(l, d_cell);
	for (int k = sc->walk_d.count - 1; k >= 0; k--)
		pathgraph_push_cell(l, sc->walk_d.v[k]);

	/* cut the staircase corners, in place: c[i - 1] always holds the last cell kept */
	int32_t *c = l->v;
	int m = l->count, j = 1;
	for (int i = 1; i < m;) {
		if (i + 1 < m && pathgraph_corner_cut(pg, c[i - 1], c[i], c[i + 1])) {
			c[j++] = c[i + 1];
			i += 2;
		} else {
			c[j++] = c[i];
			i += 1;
		}
	}
	m = j;
	/* merge runs of equal steps: a step is told by its index difference (+-1, +-w,
	 * +-w +-1), which is unambiguous for w >= 3 */
	if (pg->w >= 3) {
		j = m > 0 ? 1 : 0;
		for (int i = 1; i < m; i++) {
			if (j >= 2 && c[j - 1] - c[j - 2] == c[i] - c[j - 1])
				c[j - 1] = c[i];
			else
				c[j++] = c[i];
		}
		m = j;
	}
	path_clear(out);
	out->pts = util_grow(out->pts, &out->cap, m + 2, sizeof *out->pts);
	pathgraph_push_point(out, from);
	for (int i = 0; i < m; i++) {
		Vec2 q = pathgraph_cell_centre(pg, c[i]);
		if (i == 0 || i == m - 1)
			pathgraph_push_point(out, q); /* may line up with S or D */
		else
			out->pts[out->count++] = q; /* turns only, by the merge above */
	}
	pathgraph_push_point(out, to);
}

/* ---------------------------------------------------------------- queries */

static void route_free(Route *r)
{
	free(r->nodes);
	free(r->arcs);
	*r = (Route){0};
}

static bool route_same(const Route *a, const Route *b)
{
	if (a->len != b->len)
		return false;
	for (int i = 0; i < a->len; i++)
		if (a->arcs[i] != b->arcs[i] || a->nodes[i] != b->nodes[i])
			return false;
	return true;
}

/* pathgraph_prepare(pg, from, to, q, se): S', D' and the search graph; false when S or
 * D is not in a free cell. */
static bool pathgraph_prepare(Pathgraph *pg, Vec2 from, Vec2 to, const PathgraphQuery *q,
                              SearchEnds *se)
{
	struct PathgraphScratch *sc = pathgraph_scratch(pg);
	sc->expanded = 0;
	sc->min_d2 = q && q->min_clearance > 0 ? q->min_clearance * q->min_clearance : 0;
	if (!pathgraph_entry_search(pg, from, &se->s_cell, &sc->walk_s) ||
	    !pathgraph_entry_search(pg, to, &se->d_cell, &sc->walk_d))
		return false;
	pathgraph_splice(pg, se->s_cell, se->d_cell);
	sc->ban_stamp++;
	return true;
}

int pathgraph_find_paths(Pathgraph *pg, Vec2 from, Vec2 to, const PathgraphQuery *q, int k,
                         Path *out)
{
	for (int i = 0; i < k; i++)
		path_clear(&out[i]);
	SearchEnds se;
	if (k <= 0 || !pathgraph_prepare(pg, from, to, q, &se))
		return 0;
	struct PathgraphScratch *sc = pg->scratch;
	const int32_t S = pg->vertex_count, D = S + 1;
	if (se.s_cell == se.d_cell) {
		/* one cell of the skeleton serves both ends; is it clear enough? */
		if ((double)pg->skeleton->dist2[se.s_cell] < sc->min_d2)
			return 0;
		pathgraph_polyline(pg, from, to, NULL, se.s_cell, se.d_cell, &out[0]);
		return 1;
	}
	Route *found = util_alloc((size_t)k, sizeof *found);
	int nfound = 0;
	Route *cand = NULL;
	int ncand = 0, cand_cap = 0;
	if (pathgraph_astar(pg, &se, S, D, &found[0]))
		nfound = 1;
	if (nfound == 1) {
		pathgraph_polyline(pg, from, to, &found[0], se.s_cell, se.d_cell, &out[0]);
		out[0].expanded = sc->expanded;
	}
	/* Yen: spur from every node of the last path found */
	while (nfound > 0 && nfound < k) {
		const Route *prev = &found[nfound - 1];
		for (int j = 0; j < prev->len; j++) {
			sc->ban_stamp++;
			for (int r = 0; r < nfound; r++) {
				const Route *o = &found[r];
				if (o->len <= j)
					continue;
				bool same_root = true;
				for (int i = 0; i < j && same_root; i++)
					same_root = o->arcs[i] == prev->arcs[i] &&
					            o->nodes[i] == prev->nodes[i];
				if (same_root)
					sc->arc_ban[o->arcs[j]] = sc->ban_stamp;
			}
			for (int i = 0; i < j; i++)
				sc->node_ban[prev->nodes[i]] = sc->ban_stamp;
			Route spur = {0};
			if (!pathgraph_astar(pg, &se, prev->nodes[j], D, &spur)) {
				route_free(&spur);
				continue;
			}
			Route total = {.len = j + spur.len};
			total.nodes = util_alloc((size_t)total.len + 1, sizeof *total.nodes);
			total.arcs = util_alloc((size_t)total.len + 1, sizeof *total.arcs);
			total.cost = spur.cost;
			for (int i = 0; i < j; i++) {
				total.nodes[i] = prev->nodes[i];
				total.arcs[i] = prev->arcs[i];
				total.cost += pathgraph_arc_cost(pg, prev->arcs[i]);
			}
			for (int i = 0; i <= spur.len; i++)
				total.nodes[j + i] = spur.nodes[i];
			for (int i = 0; i < spur.len; i++)
				total.arcs[j + i] = spur.arcs[i];
			route_free(&spur);
			bool known = false;
			for (int r = 0; r < nfound && !known; r++)
				known = route_same(&found[r], &total);
			for (int r = 0; r < ncand && !known; r++)
				known = route_same(&cand[r], &total);
			if (known) {
				route_free(&total);
				continue;
			}
			cand = util_grow(cand, &cand_cap, ncand + 1, sizeof *cand);
			cand[ncand++] = total;
		}
		if (ncand == 0)
			break;
		int best = 0;
		for (int r = 1; r < ncand; r++)
			if (cand[r].cost < cand[best].cost)
				best = r;
		found[nfound] = cand[best];
		cand[best] = cand[--ncand];
		pathgraph_polyline(pg, from, to, &found[nfound], se.s_cell, se.d_cell,
		                   &out[nfound]);
		out[nfound].expanded = sc->expanded;
		nfound++;
	}
	for (int r = 0; r < ncand; r++)
		route_free(&cand[r]);
	free(cand);
	for (int r = 0; r < nfound; r++)
		route_free(&found[r]);
	free(found);
	return nfound;
}

bool pathgraph_find_path(Pathgraph *pg, Vec2 from, Vec2 to, const PathgraphQuery *q, Path *out)
{
	return pathgraph_find_paths(pg, from, to, q, 1, out) == 1;
}
