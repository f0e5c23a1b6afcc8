/* planner.c - the spatial planner (paper 3.6, 4.1-4.3, 5). CONTROLLER SIDE.
 *
 * PLANNER_SKELETON: the distance transform and skeleton of the screen's space
 * (skeleton.c), its pathgraph (pathgraph.c), the shortest path along it from S
 * through S' and D' to D, then rope-tightening (rope.c) to the shortest path of the
 * same homotopy class. PLANNER_GRID: A* on the 8-connected screen (gridpath.c).
 * PLANNER_VISIBILITY: the visibility graph (visibility.c). */
#include "utak/mind/planner.h"

#include <math.h>
#include <string.h>

#include "utak/plan/gridpath.h"
#include "utak/plan/rope.h"
#include "utak/plan/visibility.h"

void planner_init(Planner *p, PlannerKind kind)
{
	*p = (Planner){.kind = kind};
	skeleton_init(&p->skeleton);
	pathgraph_init(&p->pathgraph);
	path_init(&p->found);
	path_init(&p->taut);
}

void planner_free(Planner *p)
{
	pathgraph_free(&p->pathgraph);
	skeleton_free(&p->skeleton);
	grid_free(&p->grid);
	path_free(&p->found);
	path_free(&p->taut);
}

static void planner_copy_grid(Planner *p, const Grid *g)
{
	if (p->grid.w != g->w || p->grid.h != g->h) {
		grid_free(&p->grid);
		grid_init(&p->grid, g->w, g->h, GRID_BLOCKED);
	}
	memcpy(p->grid.cells, g->cells, (size_t)g->w * (size_t)g->h);
}

static void path_copy(Path *to, const Path *from)
{
	path_clear(to);
	for (int i = 0; i < from->count; i++)
		path_push(to, from->pts[i]);
	to->expanded = from->expanded;
}

bool planner_plan(Planner *p, const Grid *g, Vec2 from, Vec2 to)
{
	planner_copy_grid(p, g);
	path_clear(&p->found);
	path_clear(&p->taut);
	p->found_length = p->taut_length = -1;
	p->expanded = 0;
	bool ok = false;
	switch (p->kind) {
	case PLANNER_SKELETON: {
		/* The pathgraph borrows the grid and skeleton: both live in p. */
		pathgraph_free(&p->pathgraph);
		pathgraph_init(&p->pathgraph);
		skeleton_compute(&p->skeleton, &p->grid);
		pathgraph_build(&p->pathgraph, &p->skeleton, &p->grid);
		p->have_graph = true;
		PathgraphQuery q = pathgraph_query_default();
		ok = pathgraph_find_path(&p->pathgraph, from, to, &q, &p->found);
		p->expanded = p->found.expanded;
		if (ok && rope_tighten(&p->grid, &p->found, &p->taut) != ROPE_OK)
			path_copy(&p->taut, &p->found);
		break;
	}
	case PLANNER_GRID: {
		GridPathSearch s;
		gridpath_init(&s, &p->grid);
		double len;
		ok = gridpath_find(&s, (int32_t)floor(from.x), (int32_t)floor(from.y), (int32_t)floor(to.x),
				   (int32_t)floor(to.y), &p->found, &len) == GRIDPATH_FOUND;
		p->expanded = p->found.expanded;
		gridpath_free(&s);
		if (ok) {
			/* A* joins cell centres: begin and end at the points themselves. */
			p->found.pts[0] = from;
			p->found.pts[p->found.count - 1] = to;
			path_copy(&p->taut, &p->found);
		}
		break;
	}
	case PLANNER_VISIBILITY: {
		VisibilityGraph vg;
		if (visibility_init(&vg, &p->grid, VISIBILITY_MAX_VERTICES) == VISIBILITY_FOUND) {
			double len;
			ok = visibility_find(&vg, from, to, &p->found, &len) == VISIBILITY_FOUND;
			p->expanded = p->found.expanded;
			if (ok)
				path_copy(&p->taut, &p->found);
		}
		visibility_free(&vg);
		break;
	}
	}
	if (ok) {
		p->found_length = path_length(&p->found);
		p->taut_length = path_length(&p->taut);
	}
	return ok;
}

bool planner_segment_strict(const Grid *g, Vec2 a, Vec2 b)
{
	/* The closed squares a segment meets: walk the cells of its box and test each
	 * against the segment by separating axes (the box's and the segment's normal).
	 * Segments here are short (a few dozen cells), so the box walk is cheap. */
	int32_t x0 = (int32_t)floor(fmin(a.x, b.x)), x1 = (int32_t)floor(fmax(a.x, b.x));
	int32_t y0 = (int32_t)floor(fmin(a.y, b.y)), y1 = (int32_t)floor(fmax(a.y, b.y));
	/* A coordinate exactly on a grid line also touches the cell below or left of it. */
	if (fmin(a.x, b.x) == floor(fmin(a.x, b.x)))
		x0--;
	if (fmin(a.y, b.y) == floor(fmin(a.y, b.y)))
		y0--;
	Vec2 d = vec2_sub(b, a);
	for (int32_t y = y0; y <= y1; y++)
		for (int32_t x = x0; x <= x1; x++) {
			/* Does the closed square [x, x+1] x [y, y+1] meet the segment? The
			 * boxes overlap (by construction, up to the shifted row/column), so
			 * only the segment's normal can separate them. */
			if (x + 1 < fmin(a.x, b.x) || x > fmax(a.x, b.x) || y + 1 < fmin(a.y, b.y) || y > fmax(a.y, b.y))
				continue;
			double s0 = vec2_cross(d, vec2_sub(vec2(x, y), a)), s1 = vec2_cross(d, vec2_sub(vec2(x + 1, y), a));
			double s2 = vec2_cross(d, vec2_sub(vec2(x, y + 1), a));
			double s3 = vec2_cross(d, vec2_sub(vec2(x + 1, y + 1), a));
			bool all_pos = s0 > 0 && s1 > 0 && s2 > 0 && s3 > 0, all_neg = s0 < 0 && s1 < 0 && s2 < 0 && s3 < 0;
			if (all_pos || all_neg)
				continue;
			if (!grid_free_at(g, x, y))
				return false;
		}
	return true;
}

void planner_waypoints(const Grid *g, const Path *path, Path *out)
{
	path_clear(out);
	if (path->count == 0)
		return;
	int i = 0;
	path_push(out, path->pts[0]);
	while (i < path->count - 1) {
		int j = path->count - 1;
		while (j > i + 1 && !planner_segment_strict(g, path->pts[i], path->pts[j]))
			j--;
		path_push(out, path->pts[j]);
		i = j;
	}
}

const char *planner_name(PlannerKind k)
{
	static const char *const names[] = {"skeleton", "grid", "visibility"};
	return names[k];
}

bool planner_parse(const char *name, PlannerKind *k)
{
	for (int i = 0; i < 3; i++)
		if (strcmp(name, planner_name((PlannerKind)i)) == 0) {
			*k = (PlannerKind)i;
			return true;
		}
	return false;
}

void planner_dump_path(const Planner *p, FILE *f)
{
	fprintf(f, "path: planner %s, ", planner_name(p->kind));
	if (p->found_length < 0) {
		fprintf(f, "no path\n");
		return;
	}
	fprintf(f, "length %.3f", p->found_length);
	if (p->kind == PLANNER_SKELETON)
		fprintf(f, ", rope-tightened %.3f", p->taut_length);
	fprintf(f, ", %lld %s expanded, %d points\n", (long long)p->expanded,
		p->kind == PLANNER_GRID ? "cells" : "vertices", p->taut.count);
	for (int i = 0; i < p->taut.count; i++)
		fprintf(f, "  %.3f %.3f\n", p->taut.pts[i].x, p->taut.pts[i].y);
}
