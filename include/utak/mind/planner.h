/* planner.h - the spatial planner: a path for Utak on the screen (paper 3.6, 4, 5).
 * CONTROLLER SIDE.
 *
 * One entry point for the paper's three path-finders (4.1), all returning the same
 * structure: the skeleton of empty space (4.2-4.3, the paper's method and the
 * default), A* on the 8-connected screen (Hart, Nilsson and Raphael), and Shakey's
 * visibility graph (the Euclidean optimum). The skeleton's path is pulled taut by
 * rope-tightening (5). Points are in screen units (grid.h). */
#ifndef UTAK_PLANNER_H
#define UTAK_PLANNER_H

#include <stdbool.h>
#include <stdio.h>

#include "utak/plan/grid.h"
#include "utak/plan/path.h"
#include "utak/plan/pathgraph.h"
#include "utak/plan/skeleton.h"

typedef enum PlannerKind { PLANNER_SKELETON, PLANNER_GRID, PLANNER_VISIBILITY } PlannerKind;

typedef struct Planner {
	PlannerKind kind;
	Grid grid;		/* a copy of the grid last planned on */
	Skeleton skeleton;	/* PLANNER_SKELETON: of that grid */
	Pathgraph pathgraph;
	bool have_graph;
	Path found;		/* the path the planner found (skeleton: along the pathgraph) */
	Path taut;		/* skeleton: rope-tightened; others: the same as found */
	double found_length, taut_length;
	int64_t expanded;	/* vertices (skeleton, visibility) or cells (grid) expanded */
} Planner;

void planner_init(Planner *p, PlannerKind kind);
void planner_free(Planner *p);
/* planner_plan(p, g, from, to): plans from `from` to `to` (screen units) on g.
 * Returns false when there is no path (or an end is not free). */
bool planner_plan(Planner *p, const Grid *g, Vec2 from, Vec2 to);

/* planner_segment_strict(g, a, b): every cell whose closed square meets segment ab
 * is free. Stricter than the planners' line test, which lets a path touch a
 * blocked cell's edge or corner: Utak's square is the one holding his point, and a
 * point on a cell's border may belong to the blocked cell beyond it. */
bool planner_segment_strict(const Grid *g, Vec2 a, Vec2 b);
/* planner_waypoints(g, path, out): the points Utak walks through: the path pulled
 * taut by greedy string pulling under planner_segment_strict (keeping a vertex
 * wherever no strictly free shortcut exists). */
void planner_waypoints(const Grid *g, const Path *path, Path *out);

const char *planner_name(PlannerKind k);
/* planner_parse(name, &k): "skeleton", "grid" or "visibility". */
bool planner_parse(const char *name, PlannerKind *k);

/* planner_dump_path(p, from_x, from_y, f): the last plan: planner, lengths (3
 * decimals), expansions, and the points of the taut path in screen units. */
void planner_dump_path(const Planner *p, FILE *f);

#endif
