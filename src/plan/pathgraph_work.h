/* pathgraph_work.h - the working state shared by pathgraph.c (building the pathgraph)
 * and pathfind.c (finding paths on it), paper 4.3: growable lists, the query scratch
 * kept in a Pathgraph, and the length of a run of skeleton cells, which both the
 * build (an edge's length) and the queries (the pieces of a split edge) measure the
 * same way. Private to the pathgraph module: not installed under include/, and
 * nothing outside src/plan/pathgraph.c and pathfind.c includes it. */
#ifndef UTAK_PATHGRAPH_WORK_H
#define UTAK_PATHGRAPH_WORK_H

#include <stdbool.h>
#include <stdint.h>

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
