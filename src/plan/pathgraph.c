/* pathgraph.c - the pathgraph of a skeleton and path-finding on it (paper 4.3, Figure 3;
 * see pathgraph.h for what the vertices, edges and paths are).
 *
 * ALGORITHM
 * Build: (1) every skeleton cell of degree other than 2 is a vertex cell; 4-adjacent
 *    junction cells are merged into a junction set by flood fill, placed at its cell of
 *    largest dist2, and a breadth-first tree inside the set leads from any of its cells
 *    to that one. (2) From every vertex cell, every skeleton neighbour that is an
 *    unvisited chain cell (degree 2) starts a walk along the chain to the next vertex
 *    cell: that chain is an edge. Two vertex cells of different vertices that touch are
 *    joined by an edge without chain cells. (3) Chain cells still unvisited lie on loops
 *    without a junction: the first of each in row-major order becomes a loop vertex
 *    and the loop an edge from it to itself. Vertices are numbered by their first cell
 *    in row-major order (loop vertices after the others), edges as found: the result
 *    depends on nothing else.
 * Query: S' and D' by breadth-first search over free cells from S and D (4-connected,
 *    the topology of skeleton.h), testing each skeleton cell met with the line test
 *    and stopping once no nearer visible cell can be met (a cell in sight at distance e
 *    is at most sqrt(2) e + 1 steps away). Then A* (Hart, Nilsson and Raphael 1968, the
 *    paper's reference [8]) over the vertices plus S' and D', the edges holding S' or
 *    D' replaced by their pieces. k paths: Yen (1971), see pathgraph.h.
 *
 * INVARIANTS (pathgraph_validate): edge cells run from the cell of v0 to the cell of
 *    v1 along 4-adjacent skeleton cells; every skeleton cell is a vertex cell or an
 *    inner cell of exactly one edge; incident[] lists each edge under both its vertices
 *    (once for a loop).
 *
 * MEMORY  cell_ref (4 bytes a grid cell); the edges' cells (4 + 4 bytes each); vertices
 *    and edges; and, for the queries, 12 bytes a grid cell of search scratch (a visit
 *    stamp, a parent and a queue entry: stamps spare clearing between queries).
 *
 * COMPLEXITY  build O(w h) for the scan plus O(skeleton cells); a query O(cells searched
 *    for S' and D' + V log V + length of the edges holding S' and D' + cells of the
 *    path); k paths O(k L) such searches for routes of L arcs.
 *
 * MEASURED  instructions of a rebuild on 1024 x 1024 (callgrind, pathgraph_build on the
 *    bench-compare grids): the vertex scan a word of eight cells at a time, the chain
 *    walk written out and the clearing of the last build's cells alone took them from
 *    13.9 to 5.9 million on rooms, 15.5 to 6.9 on rects, 59.8 to 31.0 on the maze,
 *    11.6 to 4.6 on Boston_0_1024, 9.1 to 3.2 on den520d (the same graph, cell for
 *    cell). Earlier, by bench/skelbench.c (CPU time, best of 3): build 2.8-3.8
 *    ms (rooms, random rectangles), 10.6 ms (maze: 250 000 skeleton cells); a corner
 *    to corner query 0.18-0.2 ms, 1.4 ms in the maze, whose path has 60 000 cells to
 *    write out; 116 (maze) to 600 (rooms) times fewer vertices expanded than a grid
 *    A* expands cells on the same query. */
#include "utak/plan/pathgraph.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/plan/heap.h"
#include "utak/base/util.h"
#include "utak/plan/visibility.h"

/* The length of a diagonal step (M_SQRT2 is not in C11). */
#define PATHGRAPH_SQRT2 1.41421356237309504880

/* ---------------------------------------------------------------- growable arrays */

typedef struct IntList {
	int32_t *v;
	int count, cap;
} IntList;

static inline void intlist_push(IntList *l, int32_t x)
{
	if (l->count == l->cap) /* the call only when full: the walks push every cell */
		l->v = util_grow(l->v, &l->cap, l->count + 1, sizeof *l->v);
	l->v[l->count++] = x;
}

/* ---------------------------------------------------------------- query scratch */

/* A piece of an edge split by S' or D', or a step inside a vertex (edge -1). */
typedef struct PathgraphPiece {
	int32_t u, v;         /* nodes: vertices, or vertex_count (S') / vertex_count + 1 (D') */
	int32_t edge;         /* the edge it is part of, or -1 for a walk inside a vertex */
	int32_t pos_u, pos_v; /* its cells: edge cells at positions pos_u .. pos_v */
	int32_t cell;         /* for edge -1: the S' or D' cell, walked from to the vertex */
	double cost;
	int32_t min_dist2;
} PathgraphPiece;

enum { PATHGRAPH_MAX_PIECES = 4 };

/* A route: arcs (edge ids, or edge_count + piece index) and the nodes they join. */
typedef struct Route {
	int len;        /* arcs */
	int32_t *nodes; /* len + 1 */
	int32_t *arcs;  /* len */
	double cost;
} Route;

struct PathgraphScratch {
	size_t grid_cells;               /* the grid size the next three are made for */
	int32_t *visit, *parent, *queue; /* grid-sized, for the S' and D' searches */
	int32_t visit_stamp;
	int32_t node_cap; /* >= vertex_count + 2 */
	int32_t arc_cap;  /* >= edge_count + PATHGRAPH_MAX_PIECES */
	double *g;
	int32_t *pred_arc, *pred_node, *seen, *closed, *node_ban;
	int32_t search_stamp, ban_stamp;
	int32_t *arc_ban; /* edge_count + PATHGRAPH_MAX_PIECES */
	Heap heap;
	PathgraphPiece pieces[PATHGRAPH_MAX_PIECES];
	int piece_count;
	int32_t skip_edge[2];   /* the edges replaced by pieces, or -1 */
	int32_t goal;           /* the goal node of the running search */
	double min_d2;          /* the query's clearance, squared */
	IntList walk_s, walk_d; /* S to S' and D to D' walks when out of sight */
	IntList cells;          /* the route's cells, while making the polyline */
	int64_t expanded;
	/* Kept between builds of a grid of one size (pathgraph_build): the junction
	 * sets' parent directions (w h bytes, zero but on the cells of built_vcells)
	 * and every vertex cell of the last build, so that the next build clears
	 * cell_ref and toward on those cells and the edges' cells alone instead of
	 * the whole grid (4 + 1 bytes a cell: a fifth of a build on 1024 x 1024). */
	uint8_t *toward;
	size_t toward_cells;
	IntList built_vcells;
	bool built_valid; /* cell_ref is -1 outside built_vcells and the edges' cells */
};

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

/* ---------------------------------------------------------------- lengths */

static int32_t pathgraph_cx(const Pathgraph *pg, int32_t i)
{
	return i % pg->w;
}
static int32_t pathgraph_cy(const Pathgraph *pg, int32_t i)
{
	return i / pg->w;
}

/* pathgraph_corner_cut(pg, a, b, c): the 4-adjacent steps a -> b -> c make a staircase
 * corner that a diagonal step a -> c may cut: the steps are perpendicular and both
 * cells orthogonal to the diagonal (b, and a + (c - b) opposite it) are free. The
 * fourth cell of the 2x2 block that a, b, c span is inside the grid. */
static bool pathgraph_corner_cut(const Pathgraph *pg, int32_t a, int32_t b, int32_t c)
{
	int32_t s1 = b - a, s2 = c - b, w = pg->w;
	bool perpendicular = (s1 == 1 || s1 == -1) ? (s2 == w || s2 == -w) : (s2 == 1 || s2 == -1);
	return perpendicular && pg->grid->cells[a + s2] == GRID_FREE;
}

/* pathgraph_run_length(pg, cells, count, step): the length of the polyline through the
 * cells cells[0], cells[step], ... (count of them; step 1 or -1), corners cut. */
static double pathgraph_run_length(const Pathgraph *pg, const int32_t *cells, int32_t count,
                                   int step)
{
	double len = 0;
	int32_t i = 1;
	while (i < count) {
		if (i + 1 < count && pathgraph_corner_cut(pg, cells[(i - 1) * step],
		                                          cells[i * step], cells[(i + 1) * step])) {
			len += PATHGRAPH_SQRT2;
			i += 2;
		} else {
			len += 1;
			i += 1;
		}
	}
	return len;
}

/* ---------------------------------------------------------------- build */

void pathgraph_init(Pathgraph *pg)
{
	*pg = (Pathgraph){0};
}

static void pathgraph_free_scratch(struct PathgraphScratch *sc)
{
	if (!sc)
		return;
	free(sc->visit);
	free(sc->parent);
	free(sc->queue);
	free(sc->g);
	free(sc->pred_arc);
	free(sc->pred_node);
	free(sc->seen);
	free(sc->closed);
	free(sc->node_ban);
	free(sc->arc_ban);
	heap_free(&sc->heap);
	free(sc->walk_s.v);
	free(sc->walk_d.v);
	free(sc->cells.v);
	free(sc->toward);
	free(sc->built_vcells.v);
	free(sc);
}

void pathgraph_free(Pathgraph *pg)
{
	free(pg->vertices);
	free(pg->edges);
	free(pg->cells);
	free(pg->incident_start);
	free(pg->incident);
	free(pg->cell_ref);
	free(pg->cell_edge);
	pathgraph_free_scratch(pg->scratch);
	*pg = (Pathgraph){0};
}

/* 4-neighbour offsets, east north west south, and their grid-index steps. */
static const int8_t PATHGRAPH_DX[4] = {1, 0, -1, 0};
static const int8_t PATHGRAPH_DY[4] = {0, 1, 0, -1};

/* Marks in cell_ref while building. */
enum { PATHGRAPH_REF_NONE = -1, PATHGRAPH_REF_CHAIN = -2 };

typedef struct Builder {
	Pathgraph *pg;
	const Skeleton *s;
	uint8_t *toward; /* junction-set cells: 1 + direction to the parent, 0 at the root */
	IntList vcells;  /* cells of every vertex, vertex after vertex */
	IntList vstart;  /* vertex v's cells: vcells[vstart[v] .. vstart[v + 1]) */
	IntList cells;   /* edge cells */
	int vertex_cap, edge_cap;
	int32_t chain_cells; /* chain cells visited so far */
} Builder;

/* builder_neighbour(b, i, x, d): the skeleton cell next to cell i (in column x) in
 * direction d, or -1. The column is passed in, tracked by the callers, because a
 * division per step (i % w) would cost more than the rest of the walk. */
static int32_t builder_neighbour(const Builder *b, int32_t i, int32_t x, int d)
{
	const int32_t w = b->pg->w;
	const uint8_t *on = b->s->on;
	switch (d) {
	case 0:
		return x + 1 < w && on[i + 1] ? i + 1 : -1;
	case 1:
		return i + w < w * b->pg->h && on[i + w] ? i + w : -1;
	case 2:
		return x > 0 && on[i - 1] ? i - 1 : -1;
	default:
		return i >= w && on[i - w] ? i - w : -1;
	}
}

/* builder_degree(b, i, x): skeleton 4-neighbours of cell i in column x. */
static int builder_degree(const Builder *b, int32_t i, int32_t x)
{
	const int32_t w = b->pg->w;
	const uint8_t *on = b->s->on;
	return (x + 1 < w && on[i + 1]) + (x > 0 && on[i - 1]) +
	       (i + w < w * b->pg->h && on[i + w]) + (i >= w && on[i - w]);
}

static int32_t builder_add_vertex(Builder *b, int32_t cell, PathgraphKind kind)
{
	Pathgraph *pg = b->pg;
	pg->vertices =
	    util_grow(pg->vertices, &b->vertex_cap, pg->vertex_count + 1, sizeof *pg->vertices);
	int32_t v = pg->vertex_count++;
	pg->vertices[v] = (PathgraphVertex){cell % pg->w, cell / pg->w, kind, 1, b->s->dist2[cell]};
	pg->cell_ref[cell] = v;
	return v;
}

/* builder_junction_set(b, seed): floods the junction set of seed into a new vertex,
 * placed at its cell of largest dist2 (the first such in flood order), and records in
 * toward[] the breadth-first tree from that cell. */
static void builder_junction_set(Builder *b, int32_t seed)
{
	Pathgraph *pg = b->pg;
	int32_t v = builder_add_vertex(b, seed, PATHGRAPH_JUNCTION);
	int first = b->vcells.count;
	intlist_push(&b->vcells, seed);
	for (int k = first; k < b->vcells.count; k++) {
		int32_t c = b->vcells.v[k], x = c % pg->w;
		for (int d = 0; d < 4; d++) {
			int32_t nb = builder_neighbour(b, c, x, d);
			if (nb >= 0 && pg->cell_ref[nb] == PATHGRAPH_REF_NONE &&
			    builder_degree(b, nb, x + PATHGRAPH_DX[d]) >= 3) {
				pg->cell_ref[nb] = v;
				intlist_push(&b->vcells, nb);
			}
		}
	}
	int32_t root = seed;
	for (int k = first; k < b->vcells.count; k++)
		if (b->s->dist2[b->vcells.v[k]] > b->s->dist2[root])
			root = b->vcells.v[k];
	/* re-order the set's cells breadth-first from the root, recording parents */
	int n = b->vcells.count - first;
	b->vcells.count = first;
	intlist_push(&b->vcells, root);
	b->toward[root] = 0;
	for (int k = first; k < b->vcells.count; k++) {
		int32_t c = b->vcells.v[k], x = c % pg->w;
		for (int d = 0; d < 4; d++) {
			int32_t nb = builder_neighbour(b, c, x, d);
			if (nb >= 0 && nb != root && pg->cell_ref[nb] == v && b->toward[nb] == 0) {
				b->toward[nb] = (uint8_t)(1 + (d + 2) % 4);
				intlist_push(&b->vcells, nb);
			}
		}
	}
	assert(b->vcells.count - first == n);
	(void)n;
	pg->vertices[v].x = root % pg->w;
	pg->vertices[v].y = root / pg->w;
	pg->vertices[v].set_size = b->vcells.count - first;
	pg->vertices[v].dist2 = b->s->dist2[root];
}

/* builder_to_root(b, c, out): appends the cells from c to its vertex's cell (c first). */
static void builder_to_root(Builder *b, int32_t c, IntList *out)
{
	for (;;) {
		intlist_push(out, c);
		uint8_t t = b->toward[c];
		if (t == 0)
			return;
		int d = t - 1;
		c += PATHGRAPH_DX[d] + PATHGRAPH_DY[d] * b->pg->w;
	}
}

static void builder_add_edge(Builder *b, int32_t v0, int32_t v1, int first)
{
	Pathgraph *pg = b->pg;
	pg->edges = util_grow(pg->edges, &b->edge_cap, pg->edge_count + 1, sizeof *pg->edges);
	PathgraphEdge *e = &pg->edges[pg->edge_count++];
	e->v0 = v0;
	e->v1 = v1;
	e->first = first;
	e->count = b->cells.count - first;
	e->length = pathgraph_run_length(pg, b->cells.v + first, e->count, 1);
	e->min_dist2 = INT32_MAX;
	for (int k = first; k < b->cells.count; k++)
		if (b->s->dist2[b->cells.v[k]] < e->min_dist2)
			e->min_dist2 = b->s->dist2[b->cells.v[k]];
}

/* builder_edge_from(b, v, c, nb, nb_x): the edge leaving vertex v's cell c through nb,
 * which is in column nb_x. */
static void builder_edge_from(Builder *b, int32_t v, int32_t c, int32_t nb, int32_t nb_x)
{
	Pathgraph *pg = b->pg;
	int first = b->cells.count;
	/* from v's own cell to c: the tree path c -> root, reversed */
	builder_to_root(b, c, &b->cells);
	for (int i = first, j = b->cells.count - 1; i < j; i++, j--) {
		int32_t t = b->cells.v[i];
		b->cells.v[i] = b->cells.v[j];
		b->cells.v[j] = t;
	}
	const int32_t w = pg->w, wh = pg->w * pg->h;
	const uint8_t *on = b->s->on;
	int32_t prev = c, cur = nb, x = nb_x;
	while (pg->cell_ref[cur] == PATHGRAPH_REF_NONE) {
		pg->cell_ref[cur] = PATHGRAPH_REF_CHAIN;
		b->chain_cells++;
		intlist_push(&b->cells, cur);
		/* the first skeleton neighbour other than prev, east north west south
		 * (builder_neighbour's order, written out: a call per direction was a
		 * third of the walk) */
		int32_t next = -1, next_x = x;
		if (x + 1 < w && on[cur + 1] && cur + 1 != prev) {
			next = cur + 1;
			next_x = x + 1;
		} else if (cur + w < wh && on[cur + w] && cur + w != prev) {
			next = cur + w;
		} else if (x > 0 && on[cur - 1] && cur - 1 != prev) {
			next = cur - 1;
			next_x = x - 1;
		} else if (cur >= w && on[cur - w] && cur - w != prev) {
			next = cur - w;
		}
		prev = cur;
		cur = next;
		x = next_x;
	}
	int32_t u = pg->cell_ref[cur];
	assert(u >= 0);
	builder_to_root(b, cur, &b->cells);
	builder_add_edge(b, v, u, first);
}

/* builder_vertex_at(b, i, d): the vertex whose first cell is i, of degree d != 2. */
static void builder_vertex_at(Builder *b, int32_t i, int d)
{
	intlist_push(&b->vstart, b->vcells.count);
	if (d >= 3) {
		builder_junction_set(b, i);
	} else {
		builder_add_vertex(b, i, d == 1 ? PATHGRAPH_END : PATHGRAPH_POINT);
		intlist_push(&b->vcells, i);
	}
}

/* Eight cells a word in the vertex scan where the compiler has bit-scan builtins
 * and stores bytes little-end first (as gridpath.c); elsewhere cell by cell. */
#if defined(__GNUC__) && defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#define PATHGRAPH_SCAN_WORDS 1
static inline uint64_t pathgraph_load8(const uint8_t *p)
{
	uint64_t v;
	memcpy(&v, p, sizeof v);
	return v;
}
#else
#define PATHGRAPH_SCAN_WORDS 0
#endif

void pathgraph_build(Pathgraph *pg, const Skeleton *s, const Grid *g)
{
	/* keep the query scratch, and the cell map of a grid of the same size */
	const size_t n = (size_t)s->w * (size_t)s->h;
	if (!pg->scratch)
		pg->scratch = util_alloc(1, sizeof *pg->scratch);
	struct PathgraphScratch *scratch = pg->scratch;
	int32_t *cell_ref = pg->cell_ref && pg->w == s->w && pg->h == s->h ? pg->cell_ref : NULL;
	const bool clear_listed = cell_ref && scratch->built_valid && scratch->toward_cells == n;
	if (clear_listed) {
		/* the last build's cells back to -1 (and toward to 0): see built_vcells */
		for (int32_t k = 0; k < pg->cell_count; k++)
			cell_ref[pg->cells[k]] = PATHGRAPH_REF_NONE;
		for (int k = 0; k < scratch->built_vcells.count; k++) {
			cell_ref[scratch->built_vcells.v[k]] = PATHGRAPH_REF_NONE;
			scratch->toward[scratch->built_vcells.v[k]] = 0;
		}
	} else if (cell_ref) {
		memset(cell_ref, 0xff, n * sizeof *cell_ref); /* all PATHGRAPH_REF_NONE */
	}
	if (scratch->toward_cells != n || !scratch->toward) {
		free(scratch->toward);
		scratch->toward = util_alloc(n, 1);
		scratch->toward_cells = n;
	} else if (!clear_listed) {
		memset(scratch->toward, 0, n);
	}
	scratch->built_valid = false;
	pg->scratch = NULL;
	if (cell_ref)
		pg->cell_ref = NULL;
	pathgraph_free(pg);
	pg->scratch = scratch;
	pg->w = s->w;
	pg->h = s->h;
	pg->grid = g;
	pg->skeleton = s;
	if (!cell_ref) {
		cell_ref = util_alloc(n + 1, sizeof *pg->cell_ref);
		memset(cell_ref, 0xff, n * sizeof *cell_ref); /* all PATHGRAPH_REF_NONE */
	}
	pg->cell_ref = cell_ref;
	Builder b = {.pg = pg, .s = s};
	b.toward = scratch->toward;
	b.vcells = scratch->built_vcells; /* its memory, reused */
	b.vcells.count = 0;

	/* (1) vertices, in row-major order of their first cell. Most cells are off the
	 * skeleton: the scan skips eight at a time where they are all zero; and most
	 * skeleton cells are chain cells, told by their degree from the rows around. */
	for (int32_t y = 0; y < pg->h; y++) {
		const uint8_t *on = s->on + (size_t)y * pg->w;
		const uint8_t *below = y > 0 ? on - pg->w : NULL;
		const uint8_t *above = y + 1 < pg->h ? on + pg->w : NULL;
		for (int32_t x = 0; x < pg->w;) {
#if PATHGRAPH_SCAN_WORDS
			/* eight cells a word, inside the row: the degrees of all eight as
			 * byte sums (each at most 4, so no carries), and only the cells of
			 * degree other than 2 visited below */
			if (x >= 1 && x + 9 <= pg->w) {
				const uint64_t ones = 0x0101010101010101ULL;
				uint64_t here = pathgraph_load8(on + x);
				if (here == 0) {
					x += 8;
					continue;
				}
				uint64_t deg = pathgraph_load8(on + x - 1) + pathgraph_load8(on + x + 1) +
				               (below ? pathgraph_load8(below + x) : 0) +
				               (above ? pathgraph_load8(above + x) : 0);
				uint64_t t = deg ^ (2 * ones); /* a byte nonzero: degree not 2 */
				uint64_t cand = here & ((t | t >> 1 | t >> 2) & ones);
				while (cand) {
					const int32_t cx = x + __builtin_ctzll(cand) / 8;
					cand &= cand - 1;
					const int32_t i = y * pg->w + cx;
					if (pg->cell_ref[i] == PATHGRAPH_REF_NONE)
						builder_vertex_at(&b, i, on[cx - 1] + on[cx + 1] +
						                             (below && below[cx]) +
						                             (above && above[cx]));
				}
				x += 8;
				continue;
			}
#endif
			if (!on[x]) {
				x++;
				continue;
			}
			int d = (x > 0 && on[x - 1]) + (x + 1 < pg->w && on[x + 1]) +
			        (below && below[x]) + (above && above[x]);
			int32_t i = y * pg->w + x;
			if (d != 2 && pg->cell_ref[i] == PATHGRAPH_REF_NONE)
				builder_vertex_at(&b, i, d);
			x++;
		}
	}
	intlist_push(&b.vstart, b.vcells.count);
	/* (2) the chains between them */
	for (int32_t v = 0; v < pg->vertex_count; v++)
		for (int k = b.vstart.v[v]; k < b.vstart.v[v + 1]; k++) {
			int32_t c = b.vcells.v[k], x = c % pg->w;
			for (int d = 0; d < 4; d++) {
				int32_t nb = builder_neighbour(&b, c, x, d);
				if (nb < 0)
					continue;
				int32_t ref = pg->cell_ref[nb];
				if (ref == PATHGRAPH_REF_NONE) {
					builder_edge_from(&b, v, c, nb, x + PATHGRAPH_DX[d]);
				} else if (ref >= 0 && ref != v && c < nb) {
					int first = b.cells.count;
					builder_to_root(&b, c, &b.cells);
					for (int i = first, j = b.cells.count - 1; i < j;
					     i++, j--) {
						int32_t t = b.cells.v[i];
						b.cells.v[i] = b.cells.v[j];
						b.cells.v[j] = t;
					}
					builder_to_root(&b, nb, &b.cells);
					builder_add_edge(&b, v, ref, first);
				}
			}
		}
	/* (3) loops without a junction: only when some skeleton cell is still unvisited */
	bool all_visited = b.vcells.count + b.chain_cells == s->count;
	for (size_t i = 0; i < n && !all_visited; i++) {
		if (!s->on[i] || pg->cell_ref[i] != PATHGRAPH_REF_NONE)
			continue;
		int32_t v = builder_add_vertex(&b, (int32_t)i, PATHGRAPH_LOOP);
		int32_t x = (int32_t)(i % (size_t)pg->w), nb = -1, d = 0;
		for (; nb < 0; d++)
			nb = builder_neighbour(&b, (int32_t)i, x, d);
		builder_edge_from(&b, v, (int32_t)i, nb, x + PATHGRAPH_DX[d - 1]);
	}

	/* the edges' cells, and the chain cells' references to them */
	pg->cells = b.cells.v;
	pg->cell_count = b.cells.count;
	pg->cell_edge = util_alloc((size_t)pg->cell_count + 1, sizeof *pg->cell_edge);
	for (int32_t e = 0; e < pg->edge_count; e++) {
		const PathgraphEdge *ed = &pg->edges[e];
		for (int32_t k = ed->first; k < ed->first + ed->count; k++) {
			pg->cell_edge[k] = e;
			if (pg->cell_ref[pg->cells[k]] == PATHGRAPH_REF_CHAIN)
				pg->cell_ref[pg->cells[k]] = pg->vertex_count + k;
		}
	}
	/* incidence lists */
	pg->incident_start = util_alloc((size_t)pg->vertex_count + 1, sizeof *pg->incident_start);
	pg->incident = util_alloc((size_t)pg->edge_count * 2 + 1, sizeof *pg->incident);
	for (int32_t e = 0; e < pg->edge_count; e++) {
		pg->incident_start[pg->edges[e].v0]++;
		if (pg->edges[e].v1 != pg->edges[e].v0)
			pg->incident_start[pg->edges[e].v1]++;
	}
	int32_t sum = 0;
	for (int32_t v = 0; v < pg->vertex_count; v++) {
		int32_t c = pg->incident_start[v];
		pg->incident_start[v] = sum;
		sum += c;
	}
	pg->incident_start[pg->vertex_count] = sum;
	int32_t *fill = util_alloc((size_t)pg->vertex_count + 1, sizeof *fill);
	for (int32_t e = 0; e < pg->edge_count; e++) {
		int32_t a = pg->edges[e].v0, c = pg->edges[e].v1;
		pg->incident[pg->incident_start[a] + fill[a]++] = e;
		if (c != a)
			pg->incident[pg->incident_start[c] + fill[c]++] = e;
	}
	free(fill);
	scratch->built_vcells = b.vcells;
	scratch->built_valid = true;
	free(b.vstart.v);
}

/* ---------------------------------------------------------------- validation */

static bool pathgraph_adjacent(const Pathgraph *pg, int32_t a, int32_t b)
{
	int32_t dx = abs(pathgraph_cx(pg, a) - pathgraph_cx(pg, b));
	int32_t dy = abs(pathgraph_cy(pg, a) - pathgraph_cy(pg, b));
	return dx + dy == 1;
}

bool pathgraph_validate(const Pathgraph *pg)
{
	const Skeleton *s = pg->skeleton;
	for (int32_t e = 0; e < pg->edge_count; e++) {
		const PathgraphEdge *ed = &pg->edges[e];
		if (ed->v0 < 0 || ed->v1 < 0 || ed->v0 >= pg->vertex_count ||
		    ed->v1 >= pg->vertex_count || ed->count < 2)
			return false;
		const int32_t *c = pg->cells + ed->first;
		const PathgraphVertex *a = &pg->vertices[ed->v0], *z = &pg->vertices[ed->v1];
		if (c[0] != a->y * pg->w + a->x || c[ed->count - 1] != z->y * pg->w + z->x)
			return false;
		int32_t mind = INT32_MAX;
		for (int32_t k = 0; k < ed->count; k++) {
			if (!s->on[c[k]])
				return false;
			if (k > 0 && !pathgraph_adjacent(pg, c[k - 1], c[k]))
				return false;
			if (s->dist2[c[k]] < mind)
				mind = s->dist2[c[k]];
			int32_t ref = pg->cell_ref[c[k]];
			bool inner_ok = ref == pg->vertex_count + ed->first + k ||
			                (ref >= 0 && ref < pg->vertex_count);
			if (!inner_ok)
				return false;
		}
		if (mind != ed->min_dist2 ||
		    fabs(ed->length - pathgraph_run_length(pg, c, ed->count, 1)) > 1e-9)
			return false;
	}
	for (size_t i = 0; i < (size_t)pg->w * pg->h; i++)
		if ((pg->cell_ref[i] >= 0) != (s->on[i] != 0))
			return false;
	for (int32_t v = 0; v < pg->vertex_count; v++)
		for (int32_t k = pg->incident_start[v]; k < pg->incident_start[v + 1]; k++) {
			const PathgraphEdge *ed = &pg->edges[pg->incident[k]];
			if (ed->v0 != v && ed->v1 != v)
				return false;
		}
	return true;
}

/* ---------------------------------------------------------------- dump */

static const char *const PATHGRAPH_KIND_NAME[] = {"junction", "end", "loop", "point"};

void pathgraph_dump(const Pathgraph *pg, FILE *out)
{
	fprintf(out, "pathgraph: %d vertices, %d edges\n", (int)pg->vertex_count,
	        (int)pg->edge_count);
	for (int32_t v = 0; v < pg->vertex_count; v++) {
		const PathgraphVertex *p = &pg->vertices[v];
		fprintf(out, "vertex %d %d %d %s %d %.3f\n", (int)v, (int)p->x, (int)p->y,
		        PATHGRAPH_KIND_NAME[p->kind], (int)p->set_size, sqrt((double)p->dist2));
	}
	for (int32_t e = 0; e < pg->edge_count; e++) {
		const PathgraphEdge *ed = &pg->edges[e];
		fprintf(out, "edge %d %d %d %.3f %.3f %d\n", (int)e, (int)ed->v0, (int)ed->v1,
		        ed->length, sqrt((double)ed->min_dist2), (int)ed->count);
	}
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
			if (pg->cell_ref[nb] == v && sc->visit[nb] != stamp) {
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
		int32_t ref = pg->cell_ref[ends[i]];
		assert(ref >= 0);
		edge[i] = ref < V ? -1 : pg->cell_edge[ref - V];
		pos[i] = ref < V ? -1 : ref - V - pg->edges[edge[i]].first;
	}
	/* vertex cells: a walk inside the vertex */
	if (edge[0] < 0)
		pathgraph_add_piece(pg, pg->cell_ref[s_cell], S, -1, 0, 0, s_cell);
	if (edge[1] < 0)
		pathgraph_add_piece(pg, pg->cell_ref[d_cell], D, -1, 0, 0, d_cell);
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
