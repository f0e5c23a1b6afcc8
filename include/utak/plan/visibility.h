/* visibility.h - Shakey's visibility graph on a grid: the paper's first alternative
 * and the any-angle yardstick (paper 4.1; N.J. Nilsson, "A mobile automaton: an
 * application of artificial intelligence techniques", IJCAI 1969, the paper's [12]).
 *
 * "An optimal path between two points consists of a sequence of line segments
 * connecting extreme points of obstacles" (paper 4.1). On a grid the obstacles are
 * the blocked cells (and everything outside the grid), so the extreme points are the
 * CONVEX CORNERS: lattice points (X, Y) of which exactly one of the four cells around
 * them is blocked. The shortest path from S to D among the lines of visibility is the
 * true Euclidean (any-angle) shortest path through the free space, the yardstick
 * for rope-tightening and for every grid planner.
 *
 * THE LINE-OF-SIGHT TEST, used everywhere in utak (visibility graph, rope-tightening,
 * the tests): the segment from a to b is FREE when its relative interior (the
 * segment without its two end points)
 *   (1) meets no open interior of a blocked cell,
 *   (2) runs along no unit cell edge whose two cells are both blocked, and
 *   (3) passes through no PINCH POINT: a lattice point two diagonally opposite cells
 *       around which are blocked (two blocked cells touching only at a corner);
 * cells outside the grid count as blocked. Touching a blocked cell's edge or corner
 * is otherwise allowed. Rule (3) is the any-angle form of grid A*'s no-corner-
 * cutting rule: nothing squeezes between two blocked cells that touch at a corner;
 * so every step of a grid A* path (gridpath.h) is free by this test. A segment of
 * zero length is free when one of the cells whose closed square holds the point is
 * free. The end points must be where the caller wants them; the test does not look
 * at them otherwise. A POLYLINE is free when every segment is free and no
 * interior vertex is a pinch point (bending there could squeeze through it).
 * Coordinates are grid units (cell (x, y) is [x, x+1) x [y, y+1)). The test is
 * exact for coordinates that are multiples of 1/2 (cell centres and lattice
 * points, all utak uses) up to 2^20; for other values it follows the double
 * arithmetic.
 *
 * FEASIBILITY: the graph is built in full by a sweep from each corner over the
 * area it sees (visibility.c), so the build costs about the total area the corners
 * see, plus one line test per edge. visibility_init refuses (VISIBILITY_TOO_LARGE)
 * a grid with more corners than the caller's limit, before building anything.
 * Measured here (wall seconds on the shared 2-core machine, one thread): the Moving
 * AI maps of 32x32 to 256x257 (64 to 1305 corners) build in 2 to 250 ms;
 * maze512-1-0 (49154 corners, 95694 edges) 1.7 s; 8room_000 (22340, 84998) 2 s;
 * random512-10-0 (76173, 2.9 million edges) 26 s; Boston_0_1024 (16440 corners,
 * 0.9 million edges: long open streets, each corner sees far) 40 s. Every map
 * there is within VISIBILITY_MAX_VERTICES. A query joins S and D to the corners
 * with 2 V line tests (0.001 ms on arena, 5 ms on 8room_000, 30 ms on Boston) and
 * runs A* with the straight-line heuristic (admissible and consistent). */
#ifndef UTAK_VISIBILITY_H
#define UTAK_VISIBILITY_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/plan/grid.h"
#include "utak/plan/path.h"

/* The most corners visibility_init accepts in the benchmark (see FEASIBILITY):
 * 100 000 admits every map of ../shared/data/movingai (the most is random512-10-0,
 * 76173) and bounds the edge list (at most a few tens of millions of int32_t in
 * practice; more than an int32_t index holds is refused too). */
#define VISIBILITY_MAX_VERTICES 100000

typedef enum VisibilityStatus {
	VISIBILITY_FOUND = 0,    /* a shortest path was found (or the graph built) */
	VISIBILITY_NO_PATH,      /* S and D are free but not connected */
	VISIBILITY_BAD_ENDPOINT, /* S or D is not in free space */
	VISIBILITY_TOO_LARGE,    /* more corners than the limit: nothing was built */
} VisibilityStatus;

/* A visibility graph over a grid's convex corners. Corner i is the lattice point
 * (x[i], y[i]); its one blocked cell lies toward (qx[i], qy[i]) (each +1 or -1).
 * Edges are in compressed rows: the neighbours of i are adj[first[i] .. first[i+1]),
 * each edge stored in both directions, only the edges a shortest path can use (both
 * ends tangent: the line does not continue into its corner's blocked cell). */
typedef struct VisibilityGraph {
	const Grid *grid; /* borrowed: must outlive the graph, unchanged */
	int32_t count;    /* corners */
	int32_t *x, *y;   /* corner i, lattice coordinates (grid units) */
	int8_t *qx, *qy;  /* direction of the corner's blocked cell */
	int32_t *first;   /* count + 1 row starts into adj */
	int32_t *adj;     /* neighbour corners */
	int64_t edges;    /* undirected edges */
	/* Query scratch (count + 2 nodes: the corners, then S, then D). */
	double *g;
	int32_t *parent;
	uint8_t *state;
	double *to_goal; /* per corner: distance to D when D is visible, else -1 */
} VisibilityGraph;

/* visibility_segment_free(g, a, b): the line-of-sight test above. */
bool visibility_segment_free(const Grid *g, Vec2 a, Vec2 b);

/* visibility_pinch_point(g, p): p is a pinch point (rule (3) above): a lattice point
 * two diagonally opposite cells around which are blocked. For a caller that needs
 * the closed segment (pathgraph_segment_free): the test above leaves the ends out. */
bool visibility_pinch_point(const Grid *g, Vec2 p);

/* visibility_path_free(g, p): the polyline p is free (every segment free, no interior
 * vertex at a pinch point); a path of one point is free when the point is. */
bool visibility_path_free(const Grid *g, const Path *p);

/* visibility_count_corners(g): the convex corners of g, without building anything:
 * how a caller decides whether a visibility graph is affordable. */
int32_t visibility_count_corners(const Grid *g);

/* visibility_init(vg, grid, max_vertices): builds the graph; VISIBILITY_FOUND, or
 * VISIBILITY_TOO_LARGE (vg left empty but safe to free) when grid has more than
 * max_vertices corners. */
VisibilityStatus visibility_init(VisibilityGraph *vg, const Grid *grid, int32_t max_vertices);
void visibility_free(VisibilityGraph *vg);

/* visibility_find(vg, s, d, path, length): the Euclidean shortest path from s to d
 * (points in grid units, each in free space: the zero-length test above). On
 * VISIBILITY_FOUND path holds s, the corners passed, d, and *length its length;
 * otherwise path is empty and *length is -1. path->expanded counts the graph nodes
 * expanded. */
VisibilityStatus visibility_find(VisibilityGraph *vg, Vec2 s, Vec2 d, Path *path, double *length);

#endif
