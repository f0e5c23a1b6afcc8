/* pathwalk.c - the pathgraph's edges: the walk of the skeleton's chains (paper 4.3,
 * Figure 3: the arcs of the skeleton between its junctions and ends), steps (2) and
 * (3) of pathgraph_build; steps (0) and (1) (the ranks and the vertices) and the
 * incidence lists are pathgraph.c, the state both share pathgraph_build.h.
 *
 * ALGORITHM  (2) From every vertex cell (vertex after vertex, pathgraph.c's order),
 *    every skeleton 4-neighbour that is an unwalked chain cell (degree 2) starts a
 *    walk along the chain to the next cell of degree other than 2: that chain is an
 *    edge, from its vertex's root cell through the junction set's breadth-first tree
 *    (toward[], by rank), along the chain, and up the far vertex's tree to its root.
 *    A step reads the cell's four neighbours from the skeleton's bit plane (three
 *    16-bit loads) and the direction on from a table (PATHGRAPH_NEXT), keeps the
 *    cell's rank (east or west one on; north or south a popcount of the plane word),
 *    and writes the record's ref (ref_base + its place in cells[]). A state for each
 *    direction of the step in, straight on tested first; a run east or west goes at
 *    once, its length from 64 bits of three rows; a step north or south prefetches
 *    dist2 16 rows on (three lines). The edge's length (a diagonal across each cut
 *    corner, pathgraph_run_length's rule, the same additions) and clearance (least
 *    dist2) are measured as it goes: each chain cell is touched once. Two vertex
 *    cells of different vertices that touch make an edge without chain cells. (3)
 *    Chain cells still unwalked lie on loops without a junction: the first of each in
 *    row-major order becomes a loop vertex and the loop an edge from it to itself;
 *    then the chain cells' refs move up past the loop vertices. Source: a chain
 *    follower written for this project (the paper gives no algorithm for the graph).
 *
 * COMPLEXITY  O(skeleton cells), plus one pass over the plane's words in step (3) only
 *    when some loop is left.
 *
 * MEASURED  (the whole build's history is pathgraph.c's MEASURED; most of it is this
 *    walk) On the maze at 1024 with the caches warm, the walk is 58% of the build
 *    (perf), its steps north and south the most (each a new line of dist2); 13-15 ns
 *    a skeleton cell on the maze, 24-28 on rooms, rects and Boston_0_1024 at 4096
 *    (staircases, a turn a step), where 47-60% of the walk waits on the loads of
 *    dist2 (the cell's and the cut corner's); the prefetch 16 rows on made the build
 *    1.06-1.26 times faster at 2048 and 4096. Split from pathgraph.c (1011 lines) in
 *    issue 16's sixth round with no change of code: see pathgraph.c's MEASURED for
 *    the before and after. Then the root path by toward[] at the rank in hand rather
 *    than the vertex's set_size (ROOT BY TOWARD there: the maze at 4096 40.9 -> 39.4
 *    ms, the other grids within the noise); and a build in raster order instead of
 *    this walk, measured 3.3 to 5.1 times slower (STREAMING there). */
#include <assert.h>
#include <stdbool.h>
#include <stdint.h>

#include "pathgraph_build.h"
#include "pathgraph_work.h"
#include "utak/base/util.h"

/* ---------------------------------------------------------------- edges */

/* An edge's length and clearance, measured as its cells are appended: the length by
 * pathgraph_run_length's rule (a diagonal across each cut corner, decided left to
 * right) taken one cell at a time, so that the additions, and so the double, are
 * those of pathgraph_run_length. */
typedef struct EdgeRun {
	int32_t a, b; /* the last two cells */
	bool ready;   /* the step out of b is undecided: the next cell decides it */
	double length;
	int32_t min_dist2;
} EdgeRun;

/* edgerun_push(r, dist2, c): cell c after r's last (a 4-neighbour of it). The steps
 * a -> b -> c cut a corner when one is along x and the other along y (s == +-1 tells
 * a step along x: w >= 2, and a grid one cell wide has none) and the fourth cell of
 * their 2x2 block, a + (c - b), is free (pathgraph_corner_cut). Free is told by
 * dist2 > 0 (skeleton.h: 0 exactly on blocked cells), which the walk's loads of
 * dist2 around the corner have mostly brought in already, where the grid's byte
 * would be a load of its own. */
static inline void edgerun_push(EdgeRun *r, const int32_t *dist2, int32_t c)
{
	if (r->ready) {
		int32_t s1 = r->b - r->a, s2 = c - r->b;
		bool cut =
		    ((uint32_t)(s1 + 1) <= 2) != ((uint32_t)(s2 + 1) <= 2) && dist2[r->a + s2] > 0;
		r->length += cut ? PATHGRAPH_SQRT2 : 1.0;
		r->ready = !cut;
	} else {
		r->ready = true;
	}
	r->a = r->b;
	r->b = c;
	if (dist2[c] < r->min_dist2)
		r->min_dist2 = dist2[c];
}

/* builder_reserve(b, more): room in pg->cells and pg->cell_edge for more cells. */
static void builder_reserve(Builder *b, int64_t more)
{
	Pathgraph *pg = b->pg;
	int64_t need = b->count + more + 1;
	if (need <= b->sc->cells_cap)
		return;
	int cap = b->sc->cells_cap; /* past INT32_MAX, util_grow reports out of memory */
	pg->cells =
	    util_grow(pg->cells, &cap, need > INT32_MAX ? INT32_MAX : (int)need, sizeof *pg->cells);
	pg->cell_edge = util_realloc(pg->cell_edge, (size_t)cap, sizeof *pg->cell_edge);
	b->sc->cells_cap = cap;
}

/* builder_root_path(b, c, cb, rk, r, forward): appends to the edge (and to r) the cells
 * from a vertex's cell c (plane bit cb, rank rk) to the root of its set (toward[]): from
 * the root to c when !forward (the start of an edge, c where it leaves the set: r starts
 * there), else from c to the root. toward[rk] is 0 at a root, so a one-cell vertex
 * costs one load of toward, whose address (the rank) the walk has in hand: it goes
 * out beside the load of the far vertex's record rather than after it (ROOT BY
 * TOWARD, pathgraph.c's MEASURED). */
static void builder_root_path(Builder *b, int32_t c, int32_t cb, int32_t rk, EdgeRun *r,
                              bool forward)
{
	int32_t *p = b->pg->cells + b->count;
	const int32_t w = b->pg->w, *dist2 = b->s->dist2;
	const int32_t step[4] = {1, w, -1, -w};
	const int32_t bstep[4] = {1, b->row_bits, -1, -b->row_bits};
	int32_t n = 0, at = c, atb = cb;
	p[n++] = at;
	for (uint8_t t = b->toward[rk]; t != 0;
	     t = b->toward[pathgraph_rank(b->plane, b->base, atb)]) {
		at += step[t - 1];
		atb += bstep[t - 1];
		p[n++] = at;
	}
	int32_t i = 0;
	if (!forward) {
		for (int32_t lo = 0, hi = n - 1; lo < hi; lo++, hi--) {
			int32_t t = p[lo];
			p[lo] = p[hi];
			p[hi] = t;
		}
		*r = (EdgeRun){-1, p[0], false, 0.0, dist2[p[0]]};
		i = 1;
	}
	for (; i < n; i++)
		edgerun_push(r, dist2, p[i]);
	b->count += n;
}

/* builder_end_edge(b, v0, v1, first, r): the edge of cells[first .. count). */
static void builder_end_edge(Builder *b, int32_t v0, int32_t v1, int32_t first, const EdgeRun *r)
{
	Pathgraph *pg = b->pg;
	pg->edges = util_grow(pg->edges, &b->sc->edge_cap, pg->edge_count + 1, sizeof *pg->edges);
	const int32_t e = pg->edge_count++;
	pg->edges[e] = (PathgraphEdge){
	    v0, v1, first, b->count - first, r->length + (r->ready ? 1.0 : 0.0), r->min_dist2};
	/* four at a time, which the compiler makes one vector store (at -O2 it leaves
	 * a loop of unknown count scalar): a maze's edges hold 255 000 cells at 1024 */
	int32_t *cell_edge = pg->cell_edge;
	int32_t k = first;
	const int32_t end = b->count;
	for (; k + 4 <= end; k += 4) {
		cell_edge[k] = e;
		cell_edge[k + 1] = e;
		cell_edge[k + 2] = e;
		cell_edge[k + 3] = e;
	}
	for (; k < end; k++)
		cell_edge[k] = e;
}

/* PATHGRAPH_NEXT[back][m]: for a cell whose skeleton 4-neighbours are the bits of m (a
 * pathgraph_plane_mask: west 0, north 1, east 2, south 3) and that was entered from
 * direction back (east north west south): the direction on, when the cell is a chain
 * cell (two neighbours, back one of them); else -1, a vertex cell. */
static const int8_t PATHGRAPH_NEXT[4][16] = {
    {-1, -1, -1, -1, -1, 2, 1, -1, -1, -1, -1, -1, 3, -1, -1, -1},
    {-1, -1, -1, 2, -1, -1, 0, -1, -1, -1, 3, -1, -1, -1, -1, -1},
    {-1, -1, -1, 1, -1, 0, -1, -1, -1, 3, -1, -1, -1, -1, -1, -1},
    {-1, -1, -1, -1, -1, -1, -1, -1, -1, 2, 1, -1, 0, -1, -1, -1},
};

/* builder_edge_from(b, v, c, cb, crk, d, stop): the edge leaving vertex v's cell c
 * (plane bit cb, rank crk) in direction d, into a chain cell not yet walked: along the
 * chain to the next cell that is not a chain cell (of degree other than 2, so a vertex
 * cell, step 1) or is stop (a loop vertex's cell, builder_loops; else -1), measuring it
 * on the way. Each chain cell's record takes ref_base + its place in cells[] as its
 * ref. */
PATHGRAPH_CLONES static void builder_edge_from(Builder *b, int32_t v, int32_t c, int32_t cb,
                                               int32_t crk, int d, int32_t stop)
{
	Pathgraph *pg = b->pg;
	builder_reserve(b, (int64_t)b->chain_left + 2 * (int64_t)b->max_set + 2);
	const int32_t first = b->count;
	EdgeRun r;
	builder_root_path(b, c, cb, crk, &r, false); /* from v's own cell to c */
	const int32_t w = pg->w, ref_base = b->ref_base, rb = b->row_bits;
	const int32_t step[4] = {1, w, -1, -w};
	const uint8_t *plane = b->plane;
	const int32_t *base = b->base;
	const int32_t *dist2 = b->s->dist2;
	PathgraphCell *cell = b->cell;
	int32_t *cells = pg->cells;
	int32_t k = b->count, cur, rk;
	/* r in locals (the stores to the records and cells could alias it); pend is the
	 * direction of the step into the last cell when r.ready, else -1 */
	int pend = -1;
	if (r.ready) {
		const int32_t s1 = r.b - r.a;
		pend = s1 == 1 ? 0 : s1 == w ? 1 : s1 == -1 ? 2 : 3;
	}
	int32_t md = r.min_dist2;
	double length = r.length;
	cur = c;
	rk = crk;
	/* A state for each direction of the step into cur, each adding its constants to
	 * cur, its plane bit cb and (east and west) its rank rk, and a branch on the
	 * direction on (the switch) rather than cur += step[next]: the branch predictor
	 * runs ahead along a corridor, and the loads of the cells ahead overlap where the
	 * data dependence of the index on each mask would make them wait in turn (see
	 * MEASURED). Straight on is tested first: one predictable branch down a corridor.
	 * The neighbours come from the plane (three loads, all near: an eighth of a byte
	 * a cell), the dist2 from the grid-sized dist2 (the one array the size of the
	 * grid the walk reads), the ref from the cell's record, found by its rank: a
	 * step north or south counts the bits before it in its word. The cut corner's
	 * fourth cell is free by its dist2 (only at turns). */
/* A step north or south asks for dist2 PATHGRAPH_AHEAD_ROWS rows on in the same
 * direction: each row is a new page of dist2 at 4096 (16 KB a row), where the
 * hardware's prefetchers stop. It asks for three lines there, the cell's and those
 * PATHGRAPH_AHEAD_ROWS cells east and west of it, so that a walk that drifts east or
 * west by up to a cell a row on its way (a staircase of 45 degrees or steeper: the
 * diagonals of a room) finds its line fetched as well as a straight corridor does
 * (see MEASURED: one line 8 rows on took 7-9% off at 4096 and on the 1024 maze;
 * three lines 16 rows on made the build 1.09-1.24 times faster again at 4096, the
 * scaling round, but on den520d, unchanged). No fault is
 * possible: a prefetch of an address past the array is a hint, taken as an integer,
 * not a pointer into it. */
#define PATHGRAPH_AHEAD_ROWS 16
#if defined(__GNUC__)
#define PATHGRAPH_AHEAD(D, STEP)                                                                   \
	do {                                                                                       \
		if ((D)&1) {                                                                       \
			const uintptr_t at_ = (uintptr_t)(dist2 + cur) +                           \
			                      (uintptr_t)(PATHGRAPH_AHEAD_ROWS * (STEP)) * 4;      \
			__builtin_prefetch((const void *)(at_ - 4 * PATHGRAPH_AHEAD_ROWS));        \
			__builtin_prefetch((const void *)at_);                                     \
			__builtin_prefetch((const void *)(at_ + 4 * PATHGRAPH_AHEAD_ROWS));        \
		}                                                                                  \
	} while (0)
#else
#define PATHGRAPH_AHEAD(D, STEP) ((void)0)
#endif
#define PATHGRAPH_WALK_STEP(D, STEP, BSTEP, RANK)                                                  \
	walk_##D:                                                                                  \
	{                                                                                          \
		cur += (STEP);                                                                     \
		cb += (BSTEP);                                                                     \
		PATHGRAPH_AHEAD(D, STEP);                                                          \
		rk = (RANK);                                                                       \
		const int next = PATHGRAPH_NEXT[(D) ^ 2][pathgraph_plane_mask(plane, cb, rb)];     \
		if (next < 0 || cur == stop)                                                       \
			goto walk_end;                                                             \
		PathgraphCell *const rec = &cell[rk];                                              \
		rec->ref = ref_base + k;                                                           \
		cells[k++] = cur;                                                                  \
		if (pend >= 0) {                                                                   \
			const bool cut = ((pend ^ (D)) & 1) && dist2[cur - step[pend]] > 0;        \
			length += cut ? PATHGRAPH_SQRT2 : 1.0;                                     \
			pend = cut ? -1 : (D);                                                     \
		} else {                                                                           \
			pend = (D);                                                                \
		}                                                                                  \
		if (dist2[cur] < md)                                                               \
			md = dist2[cur];                                                           \
		if (next == (D)) {                                                                 \
			PATHGRAPH_RUN_##D;                                                         \
			goto walk_##D;                                                             \
		}                                                                                  \
		switch (next) {                                                                    \
		case 0:                                                                            \
			goto walk_0;                                                               \
		case 1:                                                                            \
			goto walk_1;                                                               \
		case 2:                                                                            \
			goto walk_2;                                                               \
		default:                                                                           \
			goto walk_3;                                                               \
		}                                                                                  \
	}
/* A run east or west: after a cell that goes on straight east (west), the cells on
 * that are chain cells going on straight too (a skeleton cell with skeleton cells
 * west and east and none north or south), found at once from 64 bits of the plane's
 * rows (up to 56 of them), written and measured in a loop of their own: no mask, no
 * table and no branch on the direction a cell. Not in a loop's walk (stop >= 0), so
 * that none passes stop. The cell after the run is a step of its own. */
#define PATHGRAPH_RUN_BODY(SIGN, D)                                                                \
	if (n > 0) {                                                                               \
		if (pend >= 0)                                                                     \
			length += 1.0;                                                             \
		pend = (D);                                                                        \
		for (int j = 1; j < n; j++)                                                        \
			length += 1.0;                                                             \
		for (int j = 1; j <= n; j++) {                                                     \
			const int32_t c2 = cur SIGN j;                                             \
			cell[rk SIGN j].ref = ref_base + k;                                        \
			cells[k++] = c2;                                                           \
			if (dist2[c2] < md)                                                        \
				md = dist2[c2];                                                    \
		}                                                                                  \
		cur = cur SIGN n;                                                                  \
		cb = cb SIGN n;                                                                    \
		rk = rk SIGN n;                                                                    \
	}
#define PATHGRAPH_RUN_0                                                                            \
	if (stop < 0) {                                                                            \
		const int32_t x = cb + 1;                                                          \
		const uint8_t *p = plane + (x >> 3);                                               \
		const unsigned sh = (unsigned)x & 7;                                               \
		const uint64_t row = pathgraph_load64(p) >> sh;                                    \
		const uint64_t side =                                                              \
		    (pathgraph_load64(p + rowb) | pathgraph_load64(p - rowb)) >> sh;               \
		const int n = pathgraph_ctz64(~(row & row >> 1 & ~side) | UINT64_C(1) << 56);      \
		PATHGRAPH_RUN_BODY(+, 0)                                                           \
	} else                                                                                     \
		(void)0
#define PATHGRAPH_RUN_2                                                                            \
	if (stop < 0) {                                                                            \
		const int32_t x = cb - 1;                                                          \
		const uint8_t *p = plane + (x >> 3) - 7;                                           \
		const unsigned sh = 7 - ((unsigned)x & 7);                                         \
		const uint64_t row = pathgraph_load64(p) << sh;                                    \
		const uint64_t side = (pathgraph_load64(p + rowb) | pathgraph_load64(p - rowb))    \
		                      << sh;                                                       \
		const int n = pathgraph_clz64(~(row & row << 1 & ~side) | UINT64_C(1) << 7);       \
		PATHGRAPH_RUN_BODY(-, 2)                                                           \
	} else                                                                                     \
		(void)0
#define PATHGRAPH_RUN_1 (void)0
#define PATHGRAPH_RUN_3 (void)0
	const size_t rowb = (size_t)rb / 8;
	switch (d) {
	case 0:
		goto walk_0;
	case 1:
		goto walk_1;
	case 2:
		goto walk_2;
	default:
		goto walk_3;
	}
/* builder_rank with the walk's locals (b's fields could be stored to, for all the
 * compiler knows, by the stores to the records and cells). */
#define PATHGRAPH_WALK_RANK(cb)                                                                    \
	(base[(cb) >> 6] + PATHGRAPH_POPCOUNT(pathgraph_load64(plane + 8 * (size_t)((cb) >> 6)) &  \
	                                      ((UINT64_C(1) << ((cb)&63)) - 1)))
	PATHGRAPH_WALK_STEP(0, 1, 1, rk + 1)
	PATHGRAPH_WALK_STEP(1, w, rb, PATHGRAPH_WALK_RANK(cb))
	PATHGRAPH_WALK_STEP(2, -1, -1, rk - 1)
	PATHGRAPH_WALK_STEP(3, -w, -rb, PATHGRAPH_WALK_RANK(cb))
#undef PATHGRAPH_WALK_STEP
#undef PATHGRAPH_WALK_RANK
#undef PATHGRAPH_RUN_BODY
#undef PATHGRAPH_RUN_0
#undef PATHGRAPH_RUN_1
#undef PATHGRAPH_RUN_2
#undef PATHGRAPH_RUN_3
walk_end:
	/* a chain cell was walked (c's neighbour): the edge has two cells or more */
	r = (EdgeRun){cells[k - 2], cells[k - 1], pend >= 0, length, md};
	b->chain_left -= k - b->count;
	b->count = k;
	const int32_t u = cell[rk].ref;
	assert(u >= 0 && u < pg->vertex_count);
	builder_root_path(b, cur, cb, rk, &r, true);
	builder_end_edge(b, v, u, first, &r);
}

/* builder_edges(b): step (2), the chains between the vertices of step (1). */
PATHGRAPH_CLONES static void builder_edges(Builder *b)
{
	Pathgraph *pg = b->pg;
	const int32_t nv = pg->vertex_count;
	const int32_t step[4] = {1, pg->w, -1, -pg->w};
	const int32_t bstep[4] = {1, b->row_bits, -1, -b->row_bits};
	for (int32_t v = 0; v < nv; v++)
		for (int k = b->vstart.v[v]; k < b->vstart.v[v + 1]; k++) {
			const int32_t c = b->vcells.v[k], cb = builder_bit(b, c);
			const int32_t crk = builder_rank(b, cb);
			const unsigned m = pathgraph_plane_mask(b->plane, cb, b->row_bits);
			for (int d = 0; d < 4; d++) {
				if (!(m >> PATHGRAPH_MASK_BIT[d] & 1))
					continue;
				const int32_t nb = c + step[d];
				const int32_t nrk = d == 0   ? crk + 1
				                    : d == 2 ? crk - 1
				                             : builder_rank(b, cb + bstep[d]);
				const int32_t ref = b->cell[nrk].ref;
				if (ref == PATHGRAPH_REF_NONE) {
					builder_edge_from(b, v, c, cb, crk, d, -1);
				} else if (ref >= 0 && ref < nv && ref != v && c < nb) {
					/* two vertices' cells touching: an edge without chain cells
					 */
					builder_reserve(b, 2 * (int64_t)b->max_set);
					int32_t first = b->count;
					EdgeRun r;
					builder_root_path(b, c, cb, crk, &r, false);
					builder_root_path(b, nb, cb + bstep[d], nrk, &r, true);
					builder_end_edge(b, v, ref, first, &r);
				}
			}
		}
}

/* builder_loops(b): step (3), loops without a junction, only when some skeleton cell
 * is still unwalked: the first cell of each, row-major (from the plane, its empty
 * words skipped, the ranks counted along), a loop vertex, the loop an edge from it to
 * itself. Then the chain cells' refs, written as ref_base + k, move up past the loop
 * vertices (vertices number below edge cells): every ref at or past ref_base, in one
 * pass over the records, and the loop vertices' own cells set back. */
static void builder_loops(Builder *b)
{
	if (b->chain_left == 0)
		return;
	Pathgraph *pg = b->pg;
	const int32_t w = pg->w, h = pg->h, words = skeleton_plane_words(w);
	const int32_t last = 1 + (w - 1) / 64;
	const int32_t nv = pg->vertex_count;
	for (int32_t y = 0; y < h && b->chain_left > 0; y++) {
		const size_t wi = (size_t)(y + 1) * (size_t)words;
		const uint8_t *row = b->plane + wi * 8;
		for (int32_t j = 1; j <= last && b->chain_left > 0; j++) {
			uint64_t here = pathgraph_load64(row + 8 * j);
			int32_t rank = b->base[wi + (size_t)j];
			for (; here && b->chain_left > 0; here &= here - 1, rank++) {
				if (b->cell[rank].ref != PATHGRAPH_REF_NONE)
					continue;
				const int32_t i = y * w + (j - 1) * 64 + pathgraph_ctz64(here);
				int32_t v = builder_add_vertex(b, i, rank, PATHGRAPH_LOOP);
				b->chain_left--;
				const int32_t cb = builder_bit(b, i);
				const unsigned m = pathgraph_plane_mask(b->plane, cb, b->row_bits);
				int d = 0;
				while (!(m >> PATHGRAPH_MASK_BIT[d] & 1))
					d++;
				builder_edge_from(b, v, i, cb, rank, d, i);
			}
		}
	}
	const int32_t loops = pg->vertex_count - nv;
	for (int32_t k = 0; k < b->s->count; k++)
		if (b->cell[k].ref >= nv)
			b->cell[k].ref += loops;
	for (int32_t v = nv; v < pg->vertex_count; v++) {
		const PathgraphVertex *p = &pg->vertices[v];
		builder_cell(b, builder_bit(b, p->y * w + p->x))->ref = v;
	}
}

void pathgraph_build_edges(Builder *b)
{
	builder_edges(b);
	builder_loops(b);
}
