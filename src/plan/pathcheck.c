/* pathcheck.c - the pathgraph's invariants and its dump (paper 4.3, Figure 3):
 * pathgraph_validate, the checks of a graph pathgraph.c built (its INVARIANTS, against
 * the skeleton and by brute force: each edge's cells, clearance and length again,
 * every cell's ref), for the tests; pathgraph_dump, the graph as text (the
 * controller's dump of its planner). Split from pathgraph.c, which builds the graph. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "pathgraph_work.h"
#include "utak/plan/pathgraph.h"
#include "utak/plan/skeleton.h"

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
			int32_t ref = pathgraph_cell_ref(pg, c[k]);
			bool inner_ok = ref == pg->vertex_count + ed->first + k ||
			                (ref >= 0 && ref < pg->vertex_count);
			if (!inner_ok)
				return false;
		}
		if (mind != ed->min_dist2 ||
		    fabs(ed->length - pathgraph_run_length(pg, c, ed->count, 1)) > 1e-9)
			return false;
	}
	/* the plane the build read is the skeleton, and every skeleton cell is a vertex
	 * cell or the edge cell its ref names */
	for (int32_t y = 0; y < pg->h; y++)
		for (int32_t x = 0; x < pg->w; x++) {
			const int32_t i = y * pg->w + x;
			const int64_t cb = skeleton_plane_bit(pg->w, x, y);
			if ((s->plane[cb >> 3] >> (cb & 7) & 1) != (s->on[i] != 0))
				return false;
			const int32_t ref = pathgraph_cell_ref(pg, i);
			if ((ref >= 0) != (s->on[i] != 0) ||
			    ref >= pg->vertex_count + pg->cell_count ||
			    (ref >= pg->vertex_count && pg->cells[ref - pg->vertex_count] != i))
				return false;
		}
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
