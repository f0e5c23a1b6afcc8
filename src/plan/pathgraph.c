/* pathgraph.c - the pathgraph of a skeleton (paper 4.3, Figure 3); finding paths on it is
 * pathfind.c. See pathgraph.h for what the vertices, edges and paths are.
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

#include "utak/base/util.h"
#include "utak/plan/heap.h"
#include "pathgraph_work.h"

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

