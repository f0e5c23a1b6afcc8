/* plan.c - the planner library on its own (libutak-plan, man utak-plan(3)): the
 * paper's skeleton planner (4.2-4.3) and its rope-tightened path (5) on a Moving AI
 * map, with the 8-connected A* optimum (4.1) beside them.
 *
 *   cc plan.c $(pkg-config --cflags --libs utak-plan) -o plan
 *   ./plan arena.map 3 3 45 40
 *
 * Cells are squares of side 1; a path's points are in cell units, the point (x + 0.5,
 * y + 0.5) the centre of cell (x, y). Exit status 1 when there is no path. */
#include <stdio.h>
#include <stdlib.h>

#include "utak/plan/gridpath.h"
#include "utak/plan/movingai.h"
#include "utak/plan/pathgraph.h"
#include "utak/plan/rope.h"
#include "utak/plan/skeleton.h"

int main(int argc, char **argv)
{
	if (argc != 6) {
		fprintf(stderr, "usage: plan MAP SX SY GX GY\n");
		return 2;
	}
	char err[MOVINGAI_ERROR_SIZE];
	Grid grid;
	if (!movingai_read_map(argv[1], &grid, err)) {
		fprintf(stderr, "plan: %s\n", err);
		return 2;
	}
	int32_t sx = atoi(argv[2]), sy = atoi(argv[3]), gx = atoi(argv[4]), gy = atoi(argv[5]);
	if (!grid_free_at(&grid, sx, sy) || !grid_free_at(&grid, gx, gy)) {
		fprintf(stderr, "plan: start and goal must be free cells of the map\n");
		return 2;
	}

	/* The skeleton of free space, its pathgraph, and the path along it from S
	 * through the nearest skeleton points S' and D' to D. */
	Skeleton skeleton;
	Pathgraph graph;
	Path found, taut, best;
	skeleton_init(&skeleton);
	pathgraph_init(&graph);
	path_init(&found), path_init(&taut), path_init(&best);
	skeleton_compute(&skeleton, &grid);
	pathgraph_build(&graph, &skeleton, &grid);
	PathgraphQuery query = pathgraph_query_default();
	int status = 0;
	if (!pathgraph_find_path(&graph, (Vec2){sx + 0.5, sy + 0.5}, (Vec2){gx + 0.5, gy + 0.5}, &query, &found)) {
		printf("no path from (%d, %d) to (%d, %d)\n", sx, sy, gx, gy);
		status = 1;
	} else {
		/* Rope-tightening: the shortest path of the same class round the obstacles. */
		if (rope_tighten(&grid, &found, &taut) != ROPE_OK)
			fprintf(stderr, "plan: the path could not be tightened\n");
		printf("skeleton path: %d points, length %.3f\n", found.count, path_length(&found));
		printf("rope-tightened: %d points, length %.3f\n", taut.count, path_length(&taut));
		for (int i = 0; i < taut.count; i++)
			printf("  (%.2f, %.2f)\n", taut.pts[i].x, taut.pts[i].y);
	}

	/* The 8-connected optimum, no corner cutting (the Moving AI convention). */
	GridPathSearch search;
	double optimum = 0;
	gridpath_init(&search, &grid);
	if (gridpath_find(&search, sx, sy, gx, gy, &best, &optimum) == GRIDPATH_FOUND)
		printf("grid A* optimum: length %.3f\n", optimum);
	gridpath_free(&search);

	path_free(&found), path_free(&taut), path_free(&best);
	pathgraph_free(&graph);
	skeleton_free(&skeleton);
	grid_free(&grid);
	return status;
}
