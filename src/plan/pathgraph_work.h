/* pathgraph_work.h - the working state shared by pathgraph.c (building the pathgraph)
 * and pathfind.c (finding paths on it), paper 4.3: growable lists, the query scratch
 * kept in a Pathgraph, and the length of a run of skeleton cells, which both the
 * build (an edge's length) and the queries (the pieces of a split edge) measure the
 * same way. Private to the pathgraph module: not installed under include/, and
 * nothing outside src/plan/pathgraph.c, pathwalk.c (the build), pathfind.c and
 * pathcheck.c includes it. */
#ifndef UTAK_PATHGRAPH_WORK_H
#define UTAK_PATHGRAPH_WORK_H

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/plan/heap.h"
#include "utak/plan/pathgraph.h"

/* The length of a diagonal step (M_SQRT2 is not in C11). */
#define PATHGRAPH_SQRT2 1.41421356237309504880

/* 4-neighbour offsets, east north west south, and their grid-index steps. */
static const int8_t PATHGRAPH_DX[4] = {1, 0, -1, 0};
static const int8_t PATHGRAPH_DY[4] = {0, 1, 0, -1};

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

/* ---------------------------------------------------------------- the skeleton's cells */

/* A skeleton cell's record, kept in rank order (the rank of a cell: the skeleton cells
 * before it in row-major order, so the records are as many as the skeleton's cells):
 * its cell_ref (pathgraph.h: pathgraph_cell_ref). Its dist2 is not copied here: a
 * copy made in row-major order waits on a page walk a cell where the skeleton runs
 * north-south (the grid's rows 16 KB apart at 4096), and doubled the build on
 * Boston_0_1024 at 4096, while the walks read dist2 in chain order, a constant
 * stride down a corridor that the hardware prefetches. */
typedef struct PathgraphCell {
	int32_t ref;
} PathgraphCell;

/* pathgraph_load64(p): the 64 bits at p, bit k of the word bit k & 7 of byte p[k >> 3]
 * (Skeleton.plane's order: one load where bytes are stored little-end first). */
static inline uint64_t pathgraph_load64(const uint8_t *p)
{
	uint64_t v;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
	memcpy(&v, p, sizeof v);
#else
	v = 0;
	for (int k = 7; k >= 0; k--)
		v = v << 8 | p[k];
#endif
	return v;
}

/* pathgraph_pop64(x): the bits set in x (the instruction where the target has one; the
 * default x86-64 target has none, and GCC's builtin is then a call). */
static inline int32_t pathgraph_pop64(uint64_t x)
{
#if defined(__GNUC__) && defined(__POPCNT__)
	return __builtin_popcountll(x);
#else
	x = x - (x >> 1 & 0x5555555555555555u);
	x = (x & 0x3333333333333333u) + (x >> 2 & 0x3333333333333333u);
	x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fu;
	return (int32_t)((x * 0x0101010101010101u) >> 56);
#endif
}

/* pathgraph_rank(plane, base, cb): the rank of the skeleton cell of plane bit cb, base
 * holding the rank of each plane word's first bit (PathgraphScratch.rank_base). */
static inline int32_t pathgraph_rank(const uint8_t *plane, const int32_t *base, int32_t cb)
{
	const uint64_t word = pathgraph_load64(plane + 8 * (size_t)(cb >> 6));
	return base[cb >> 6] + pathgraph_pop64(word & ((UINT64_C(1) << (cb & 63)) - 1));
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
	/* The memory of the build's list of vertex cells (pathgraph.c's Builder.vcells),
	 * kept for the next build. */
	IntList built_vcells;
	/* The skeleton cells' records in rank order (cell_cap of them), their junction-set
	 * parent directions in rank order too (toward_cap bytes: written for vertex cells
	 * alone, by each build), and the rank of the first bit of each word of the
	 * skeleton's plane (rank_words of them; only the words that hold grid cells are
	 * written). */
	PathgraphCell *cell_of;
	int cell_cap;
	uint8_t *toward;
	int toward_cap;
	int32_t *rank_base;
	size_t rank_words;
	IntList cand; /* the build's cells of degree other than 2 (pathgraph.c, step 1) */
	/* The capacities of the Pathgraph's arrays (vertices, edges, cells and cell_edge,
	 * incident_start, incident), kept by the next build rather than freed and grown
	 * again, and the builder's list of where each vertex's cells start. */
	int vertex_cap, edge_cap, cells_cap, incident_start_cap, incident_cap;
	IntList vstart;
};

/* ---------------------------------------------------------------- lengths */

static inline int32_t pathgraph_cx(const Pathgraph *pg, int32_t i)
{
	return i % pg->w;
}
static inline int32_t pathgraph_cy(const Pathgraph *pg, int32_t i)
{
	return i / pg->w;
}

/* pathgraph_corner_cut(pg, a, b, c): the 4-adjacent steps a -> b -> c make a staircase
 * corner that a diagonal step a -> c may cut: the steps are perpendicular and both
 * cells orthogonal to the diagonal (b, and a + (c - b) opposite it) are free. The
 * fourth cell of the 2x2 block that a, b, c span is inside the grid. */
static inline bool pathgraph_corner_cut(const Pathgraph *pg, int32_t a, int32_t b, int32_t c)
{
	/* a step along x is +-1 and one along y +-w (a grid one cell wide has none
	 * along x, so no corner); the test as the build's edgerun_push makes it */
	int32_t s1 = b - a, s2 = c - b;
	bool perpendicular = ((uint32_t)(s1 + 1) <= 2) != ((uint32_t)(s2 + 1) <= 2);
	return perpendicular && pg->grid->cells[a + s2] == GRID_FREE;
}

/* pathgraph_run_length(pg, cells, count, step): the length of the polyline through the
 * cells cells[0], cells[step], ... (count of them; step 1 or -1), corners cut. */
static inline double pathgraph_run_length(const Pathgraph *pg, const int32_t *cells, int32_t count,
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

#endif
