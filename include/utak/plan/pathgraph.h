/* pathgraph.h - the pathgraph of a skeleton, and path-finding on it (paper 4.3, Figure 3).
 *
 * "The vertices of the pathgraph correspond to the junctions (cells or sets) of the
 * skeletal graph, and an edge between two vertices of the pathgraph corresponds to the
 * chain of cells in the skeletal graph between the corresponding junctions" (4.3).
 * Here the vertices are:
 *   - a junction: a junction cell (skeleton degree >= 3, skeleton.h), or a junction set
 *     (4-adjacent junction cells, merged), placed at its cell farthest from obstacles;
 *   - an end: an end point of the skeleton (degree 1);
 *   - a loop: one cell (the first in row-major order) of a loop that has no junction,
 *     as around a lone obstacle, so that the loop can be an edge;
 *   - a point: a skeleton that is a single cell (degree 0).
 * An edge is the chain of skeleton cells between two vertices, stored from the cell of
 * its first vertex to the cell of its second, every two consecutive cells 4-adjacent
 * (through the cells of a junction set when a chain meets the set away from the
 * vertex's own cell). Its length is that of the polyline through the cell centres that
 * cuts every staircase corner whose two orthogonal cells are free (a diagonal step,
 * sqrt 2, as the grid planner would take it); its clearance is the smallest clearance
 * (skeleton.h: centre to nearest blocked centre, in cells) of its cells.
 *
 * Search (paper 4.3): S' and D' are the skeleton cells nearest to S and D (Euclidean,
 * from the point to the cell centre) that are reachable in a straight free line (see
 * pathgraph_segment_free), among the cells of S's free component. When no skeleton
 * cell of the component is in sight, S' is the skeleton cell nearest along a 4-connected
 * walk through free cells, and the path follows that walk. S' and D' lying inside an
 * edge split it into two (three when both lie on it) for the search, which is A* over
 * the vertices with the straight-line distance as the estimate. The result is a Path
 * (path.h) in grid units: S, S', the skeleton cells (centres; corners cut as above;
 * collinear points merged), D', D. Path.expanded counts the vertices the search
 * expanded.
 *
 * The k best paths are Yen's k shortest loopless paths (J. Y. Yen, "Finding the K
 * shortest loopless paths in a network", Management Science 17(11), 1971) over the
 * pathgraph with S' and D' spliced in. Two loopless paths of a graph with the topology
 * of the space go round the obstacles differently, so they are topologically distinct.
 *
 * The Pathgraph borrows the Skeleton and Grid it was built from: they must outlive it
 * and stay unchanged. Queries use scratch space inside the Pathgraph, so one Pathgraph
 * serves one query at a time. */
#ifndef UTAK_PATHGRAPH_H
#define UTAK_PATHGRAPH_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/base/geom.h"
#include "utak/plan/grid.h"
#include "utak/plan/path.h"
#include "utak/plan/skeleton.h"

typedef enum PathgraphKind {
	PATHGRAPH_JUNCTION = 0,
	PATHGRAPH_END = 1,
	PATHGRAPH_LOOP = 2,
	PATHGRAPH_POINT = 3
} PathgraphKind;

typedef struct PathgraphVertex {
	int32_t x, y; /* its cell, in grid cells */
	PathgraphKind kind;
	int32_t set_size; /* cells in the junction set; 1 for other kinds */
	int32_t dist2;    /* skeleton dist2 of its cell */
} PathgraphVertex;

typedef struct PathgraphEdge {
	int32_t v0, v1;    /* its vertices (v0 == v1 for a loop) */
	int32_t first;     /* its cells are Pathgraph.cells[first .. first + count) */
	int32_t count;     /* >= 2: the cells of v0 and v1 and the chain between */
	double length;     /* in cells, corners cut as above */
	int32_t min_dist2; /* smallest dist2 of its cells: clearance^2 */
} PathgraphEdge;

typedef struct Pathgraph {
	int32_t w, h;             /* the grid's size */
	const Grid *grid;         /* borrowed */
	const Skeleton *skeleton; /* borrowed */
	int32_t vertex_count, edge_count;
	PathgraphVertex *vertices;
	PathgraphEdge *edges;
	int32_t cell_count;               /* cells of all edges */
	int32_t *cells;                   /* grid indices y * w + x, edge after edge */
	int32_t *incident_start;          /* vertex_count + 1: edges of v are */
	int32_t *incident;                /* incident[incident_start[v] .. incident_start[v + 1]) */
	int32_t *cell_edge;               /* cell_count: the edge each entry of cells belongs to */
	struct PathgraphScratch *scratch; /* the queries' working space (pathfind.c; pathgraph_work.h) */
} Pathgraph;

/* A query's options. */
typedef struct PathgraphQuery {
	double min_clearance; /* skip edges whose clearance is below this (cells); 0: none */
} PathgraphQuery;

static inline PathgraphQuery pathgraph_query_default(void)
{
	return (PathgraphQuery){0.0};
}

void pathgraph_init(Pathgraph *pg);
void pathgraph_free(Pathgraph *pg);
/* pathgraph_build(pg, s, g): the pathgraph of skeleton s of grid g (see above); s made
 * by skeleton_compute, whose bit plane (Skeleton.plane) the build reads instead of the
 * grid. */
void pathgraph_build(Pathgraph *pg, const Skeleton *s, const Grid *g);

/* pathgraph_cell_ref(pg, i): what grid cell i (y * w + x, inside the grid) is in the
 * built pathgraph: -1 off the skeleton, v < vertex_count for a cell of vertex v,
 * vertex_count + k for cells[k] (an inner cell of an edge). Constant time: the build
 * keeps one record per skeleton cell, found by its rank in the skeleton's bit plane,
 * rather than an array over the grid. */
int32_t pathgraph_cell_ref(const Pathgraph *pg, int32_t i);

/* pathgraph_find_path(pg, from, to, q, out): the shortest path from S = from to D = to
 * (points in grid units) along the pathgraph, into out (cleared first); q NULL means
 * pathgraph_query_default(). Returns false,
 * with out empty, when S or D is not in a free cell of the grid, or no path exists
 * (different free components, or no edges with enough clearance). */
bool pathgraph_find_path(Pathgraph *pg, Vec2 from, Vec2 to, const PathgraphQuery *q, Path *out);

/* pathgraph_find_paths(pg, from, to, q, k, out): up to k topologically distinct paths
 * into out[0 .. k) (each cleared; caller's Paths, path_init'ed), in order of their
 * length along the pathgraph. The polyline drops the steps into and out of a junction
 * set or S' and cuts corners where two edges meet, so path_length can be a cell or so
 * shorter and its order differ between near-equal paths. Returns how many were found.
 * out[i].expanded counts the vertices expanded by all the searches up to path i (Yen's
 * method runs one search per node of each path found). */
int pathgraph_find_paths(Pathgraph *pg, Vec2 from, Vec2 to, const PathgraphQuery *q, int k,
                         Path *out);

/* pathgraph_entry(pg, p, &x, &y): S' for the point p: the cell (x, y) where a path from
 * p joins the skeleton. Returns 0 when p is not in a free cell, 1 when (x, y) is in a
 * straight free line from p, 2 when it is reached by the 4-connected walk. */
int pathgraph_entry(Pathgraph *pg, Vec2 p, int32_t *x, int32_t *y);

/* pathgraph_segment_free(g, a, b): utak's one line test (visibility_segment_free,
 * visibility.h) applied to the closed segment ab (grid units): free when it meets the
 * open interior of no blocked cell, runs along no edge between two blocked cells, and
 * passes through no lattice corner that two diagonally touching blocked cells share
 * (free space does not connect there, skeleton.h), its end points included. Touching
 * a blocked cell at its edge or corner is allowed. Cells outside the grid are
 * blocked. */
bool pathgraph_segment_free(const Grid *g, Vec2 a, Vec2 b);

/* pathgraph_validate(pg): edges join their vertices' cells along 4-adjacent skeleton
 * cells, lengths and clearances agree with the cells, the incidence lists and cell_ref
 * agree with the edges. Returns false on the first failure. */
bool pathgraph_validate(const Pathgraph *pg);

/* pathgraph_dump(pg, out): one line per vertex, then one per edge:
 *   pathgraph: V vertices, E edges
 *   vertex ID X Y KIND SETSIZE CLEARANCE      (KIND junction|end|loop|point)
 *   edge ID V0 V1 LENGTH MINCLEARANCE CELLS
 * lengths and clearances in cells with 3 decimals, ids in order of construction
 * (junction, end and point vertices by their first cell in row-major order, then the
 * loop vertices likewise; edges as the build walks them). */
void pathgraph_dump(const Pathgraph *pg, FILE *out);

#endif
