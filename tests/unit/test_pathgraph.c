/* test_pathgraph.c - the pathgraph and its search (pathgraph.h, paper 4.3): edges along
 * skeleton cells, the line test against hand cases and dense sampling, paths in free
 * space exactly when a flood fill joins the ends, k distinct paths round a ring, a
 * rebuilt pathgraph equal to a fresh one, the build equal to a brute-force one. */
#include <stdlib.h>
#include <string.h>

#include "oracle.h"
#include "test.h"
#include "utak/plan/pathgraph.h"

/* Sampling step for the brute line check, in cells. */
#define SAMPLE_STEP 1e-3

/* brute_segment_free: every sample point of ab lies in a free cell. */
static bool brute_segment_free(const Grid *g, Vec2 a, Vec2 b)
{
	double len = hypot(b.x - a.x, b.y - a.y);
	int n = (int)(len / SAMPLE_STEP) + 2;
	for (int i = 0; i <= n; i++) {
		double t = (double)i / n;
		double x = a.x + t * (b.x - a.x), y = a.y + t * (b.y - a.y);
		if (!grid_free_at(g, (int)floor(x), (int)floor(y)))
			return false;
	}
	return true;
}

static bool path_in_free_space(const Grid *g, const Path *p)
{
	for (int i = 1; i < p->count; i++) {
		if (!pathgraph_segment_free(g, p->pts[i - 1], p->pts[i]))
			return false;
		if (!brute_segment_free(g, p->pts[i - 1], p->pts[i]))
			return false;
	}
	return true;
}

TEST_CASE(line_test_by_hand)
{
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const rows[] = {
	    ".....",
	    "..#..",
	    ".#...",
	    ".....",
	};
	/* clang-format on */
	Grid g;
	oracle_grid_from(&g, rows, 4);
	/* blocked: (2, 2) and (1, 1); they touch at the corner (2, 2) */
	TEST_CHECK(!pathgraph_segment_free(&g, vec2(1.5, 2.5), vec2(2.5, 1.5))); /* the pinch */
	TEST_CHECK(!pathgraph_segment_free(&g, vec2(0.5, 3.5), vec2(3.5, 0.5))); /* through it */
	TEST_CHECK(pathgraph_segment_free(&g, vec2(0.5, 0.5), vec2(4.5, 0.5)));  /* row 0 */
	TEST_CHECK(!pathgraph_segment_free(&g, vec2(0.5, 1.5), vec2(4.5, 1.5))); /* crosses (1,1) */
	TEST_CHECK(pathgraph_segment_free(&g, vec2(2.5, 0.5), vec2(4.5, 2.5)));  /* corner (3,1) */
	TEST_CHECK(pathgraph_segment_free(&g, vec2(0.5, 0.5), vec2(1.5, 0.5)));
	/* touching one blocked cell at its corner is allowed: corner (3,3) of (2,2) */
	TEST_CHECK(pathgraph_segment_free(&g, vec2(2.5, 3.5), vec2(3.5, 2.5)));
	/* along the edge y = 2 between (1,1) blocked and (1,2) free: allowed... */
	TEST_CHECK(pathgraph_segment_free(&g, vec2(1.0, 2.0), vec2(1.8, 2.0)));
	/* ...but not into the pinch corner (2,2) at its end */
	TEST_CHECK(!pathgraph_segment_free(&g, vec2(1.0, 2.0), vec2(2.0, 2.0)));
	/* leaving the grid */
	TEST_CHECK(!pathgraph_segment_free(&g, vec2(0.5, 0.5), vec2(-0.5, 0.5)));
	grid_free(&g);
	/* along the edge between two blocked cells */
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const wall[] = {
	    "...",
	    "###",
	    "###",
	    "...",
	};
	/* clang-format on */
	oracle_grid_from(&g, wall, 4);
	TEST_CHECK(!pathgraph_segment_free(&g, vec2(0.2, 2.0), vec2(2.8, 2.0)));
	TEST_CHECK(pathgraph_segment_free(&g, vec2(0.2, 3.0), vec2(2.8, 3.0)));
	grid_free(&g);
}

TEST_CASE(line_test_agrees_with_dense_sampling)
{
	oracle_seed = 3;
	int disagree = 0, total = 0, free_count = 0;
	for (int trial = 0; trial < 40; trial++) {
		Grid g;
		oracle_random_grid(&g, 24, 20, 15, 2);
		for (int k = 0; k < 200; k++) {
			Vec2 a = vec2(oracle_rand_below(24000) / 1000.0,
			              oracle_rand_below(20000) / 1000.0);
			Vec2 b = vec2(oracle_rand_below(24000) / 1000.0,
			              oracle_rand_below(20000) / 1000.0);
			bool fast = pathgraph_segment_free(&g, a, b),
			     brute = brute_segment_free(&g, a, b);
			/* the sampling can miss a sliver of a blocked cell, never the reverse */
			TEST_CHECK(!(fast && !brute));
			disagree += fast != brute;
			free_count += fast;
			total++;
		}
		grid_free(&g);
	}
	TEST_CHECK(free_count > total / 20);
	TEST_CHECK(disagree * 100 < total);
}

/* Independent of pathgraph_validate: the edges' cells, by the definitions. */
static bool edges_follow_skeleton(const Pathgraph *pg, const Skeleton *s)
{
	uint8_t *covered = calloc((size_t)(s->w * s->h), 1);
	for (int v = 0; v < pg->vertex_count; v++) {
		const PathgraphVertex *p = &pg->vertices[v];
		if (!skeleton_on(s, p->x, p->y))
			return false;
		covered[p->y * s->w + p->x] = 1;
	}
	for (int e = 0; e < pg->edge_count; e++) {
		const PathgraphEdge *ed = &pg->edges[e];
		const int32_t *c = pg->cells + ed->first;
		const PathgraphVertex *a = &pg->vertices[ed->v0], *b = &pg->vertices[ed->v1];
		if (c[0] != a->y * s->w + a->x || c[ed->count - 1] != b->y * s->w + b->x)
			return false;
		for (int k = 0; k < ed->count; k++) {
			int x = c[k] % s->w, y = c[k] / s->w;
			if (!skeleton_on(s, x, y))
				return false;
			covered[c[k]] = 1;
			if (k > 0) {
				int px = c[k - 1] % s->w, py = c[k - 1] / s->w;
				if (abs(px - x) + abs(py - y) != 1)
					return false;
			}
		}
	}
	bool ok = true;
	for (int i = 0; i < s->w * s->h; i++)
		ok = ok && (covered[i] == (s->on[i] != 0));
	free(covered);
	return ok;
}

TEST_CASE(pathgraph_edges_on_random_grids)
{
	oracle_seed = 11;
	for (int trial = 0; trial < 150; trial++) {
		Grid g;
		oracle_random_grid(&g, 2 + oracle_rand_below(40), 2 + oracle_rand_below(40),
		                   oracle_rand_below(35), oracle_rand_below(6));
		Skeleton s;
		Pathgraph pg;
		skeleton_init(&s);
		pathgraph_init(&pg);
		skeleton_compute(&s, &g);
		pathgraph_build(&pg, &s, &g);
		TEST_CHECK(pathgraph_validate(&pg));
		TEST_CHECK(edges_follow_skeleton(&pg, &s));
		pathgraph_free(&pg);
		skeleton_free(&s);
		grid_free(&g);
	}
}

/* Two pathgraphs alike, array for array (cell_ref over the whole grid). */
static bool pathgraphs_equal(const Pathgraph *a, const Pathgraph *b)
{
	if (a->w != b->w || a->h != b->h || a->vertex_count != b->vertex_count ||
	    a->edge_count != b->edge_count || a->cell_count != b->cell_count)
		return false;
	for (int v = 0; v < a->vertex_count; v++) {
		const PathgraphVertex *p = &a->vertices[v], *q = &b->vertices[v];
		if (p->x != q->x || p->y != q->y || p->kind != q->kind ||
		    p->set_size != q->set_size || p->dist2 != q->dist2)
			return false;
	}
	for (int e = 0; e < a->edge_count; e++) {
		const PathgraphEdge *p = &a->edges[e], *q = &b->edges[e];
		if (p->v0 != q->v0 || p->v1 != q->v1 || p->first != q->first ||
		    p->count != q->count || p->length != q->length || p->min_dist2 != q->min_dist2)
			return false;
	}
	for (int k = 0; k < a->cell_count; k++)
		if (a->cells[k] != b->cells[k] || a->cell_edge[k] != b->cell_edge[k])
			return false;
	for (int v = 0; v <= a->vertex_count; v++)
		if (a->incident_start[v] != b->incident_start[v])
			return false;
	for (int k = 0; k < a->incident_start[a->vertex_count]; k++)
		if (a->incident[k] != b->incident[k])
			return false;
	for (int i = 0; i < a->w * a->h; i++)
		if (pathgraph_cell_ref(a, i) != pathgraph_cell_ref(b, i))
			return false;
	return true;
}

/* A Pathgraph rebuilt again and again over grids of one size (keeping its memory and
 * clearing only what the last build set) equals one built afresh on each: sparse and
 * dense skeletons in turn, loops without a junction among them. */
TEST_CASE(rebuilt_pathgraph_equals_a_fresh_one)
{
	oracle_seed = 31;
	int loops = 0, builds = 0;
	for (int size = 0; size < 12; size++) {
		const int w = 2 + oracle_rand_below(70), h = 2 + oracle_rand_below(70);
		Pathgraph kept;
		pathgraph_init(&kept);
		for (int trial = 0; trial < 12; trial++) {
			Grid g;
			if (trial % 3 == 2) { /* walled rooms, a block in each: loops */
				grid_init(&g, w, h, GRID_FREE);
				for (int y = 0; y < h; y++)
					for (int x = 0; x < w; x++)
						if (x % 12 == 0 || y % 12 == 0 ||
						    (x % 12 >= 5 && x % 12 <= 7 && y % 12 >= 5 &&
						     y % 12 <= 7))
							g.cells[y * w + x] = GRID_BLOCKED;
			} else {
				oracle_random_grid(&g, w, h, oracle_rand_below(50),
				                   oracle_rand_below(6));
			}
			Skeleton s;
			Pathgraph fresh;
			skeleton_init(&s);
			pathgraph_init(&fresh);
			skeleton_compute(&s, &g);
			pathgraph_build(&kept, &s, &g);
			pathgraph_build(&fresh, &s, &g);
			TEST_CHECK(pathgraph_validate(&kept));
			TEST_CHECK(pathgraphs_equal(&kept, &fresh));
			for (int v = 0; v < fresh.vertex_count; v++)
				loops += fresh.vertices[v].kind == PATHGRAPH_LOOP;
			builds++;
			pathgraph_free(&fresh);
			skeleton_free(&s);
			grid_free(&g);
		}
		pathgraph_free(&kept);
	}
	fprintf(stderr, "  %d builds, %d loop vertices\n", builds, loops);
	TEST_CHECK(builds == 144 && loops > 20);
}

/* ---------------------------------------------------------------- the build by brute force */

/* The pathgraph by its definitions (pathgraph.h and pathgraph_dump's numbering), built
 * plainly from the skeleton's bytes: the oracle of pathgraph_build, which works from the
 * skeleton's bit plane and ranks instead. */
typedef struct Brute {
	const Skeleton *s;
	const Grid *g;
	int nv, ne, ncells, cells_cap;
	PathgraphVertex *v; /* at most one a cell */
	PathgraphEdge *e;   /* at most four a cell: one a vertex cell's side */
	int *vfirst;        /* vertex k's cells: vcells[vfirst[k] .. vfirst[k + 1]) */
	int32_t *vcells;    /* breadth-first from each vertex's own cell */
	int nvcells;
	int32_t *cells;     /* edge cells, edge after edge */
	int32_t *ref;       /* w h: -1, a vertex, or -2 - k for cells[k] (fixed at the end) */
	int8_t *parent_dir; /* junction-set cells: direction to the parent, -1 at the root */
} Brute;

static const int BRUTE_DX[4] = {1, 0, -1, 0}, BRUTE_DY[4] = {0, 1, 0, -1};

/* brute_nb(b, i, d): the skeleton cell next to cell i in direction d, or -1. */
static int32_t brute_nb(const Brute *b, int32_t i, int d)
{
	const int w = b->s->w, x = i % w + BRUTE_DX[d], y = i / w + BRUTE_DY[d];
	return skeleton_on(b->s, x, y) ? y * w + x : -1;
}

static int brute_degree(const Brute *b, int32_t i)
{
	int n = 0;
	for (int d = 0; d < 4; d++)
		n += brute_nb(b, i, d) >= 0;
	return n;
}

static int brute_vertex(Brute *b, int32_t cell, PathgraphKind kind)
{
	const int id = b->nv++;
	b->v[id] = (PathgraphVertex){cell % b->s->w, cell / b->s->w, kind, 1, b->s->dist2[cell]};
	b->ref[cell] = id;
	b->vfirst[id] = b->nvcells;
	b->vcells[b->nvcells++] = cell;
	return id;
}

/* brute_to_root(b, c, out, n): appends the cells from c to its vertex's own cell. */
static int brute_to_root(const Brute *b, int32_t c, int32_t *out, int n)
{
	for (;;) {
		out[n++] = c;
		if (b->parent_dir[c] < 0)
			return n;
		c = brute_nb(b, c, b->parent_dir[c]);
	}
}

/* brute_edge(b, v0, v1, path, n): an edge of the cells path[0 .. n), measured by the
 * definitions: a diagonal across each staircase corner whose fourth cell is free,
 * corners decided left to right; clearance the least dist2. */
static void brute_edge(Brute *b, int v0, int v1, const int32_t *path, int n)
{
	const int w = b->s->w;
	TEST_CHECK(b->ncells + n <= b->cells_cap);
	if (b->ncells + n > b->cells_cap)
		return;
	PathgraphEdge *e = &b->e[b->ne++];
	*e = (PathgraphEdge){v0, v1, b->ncells, n, 0.0, INT32_MAX};
	for (int k = 0; k < n; k++) {
		b->cells[b->ncells + k] = path[k];
		if (b->s->dist2[path[k]] < e->min_dist2)
			e->min_dist2 = b->s->dist2[path[k]];
		if (k > 0 && k < n - 1 && b->ref[path[k]] == -1)
			b->ref[path[k]] = -2 - (b->ncells + k);
	}
	for (int k = 1; k < n;) {
		bool cut = false;
		if (k + 1 < n) {
			const int32_t a = path[k - 1], m = path[k], c = path[k + 1];
			const int ax = a % w, ay = a / w, mx = m % w, my = m / w, cx = c % w,
			          cy = c / w;
			const bool turn = (mx - ax) * (cx - mx) + (my - ay) * (cy - my) == 0;
			cut = turn && grid_free_at(b->g, ax + cx - mx, ay + cy - my);
		}
		e->length += cut ? 1.41421356237309504880 : 1.0;
		k += cut ? 2 : 1;
	}
	b->ncells += n;
}

/* brute_walk(b, v, c, d, stop, path): from vertex v's cell c into the chain cell in
 * direction d, to the next cell of degree other than 2 or to stop. */
static void brute_walk(Brute *b, int v, int32_t c, int d, int32_t stop, int32_t *path)
{
	int n = brute_to_root(b, c, path, 0);
	for (int lo = 0, hi = n - 1; lo < hi; lo++, hi--) {
		int32_t t = path[lo];
		path[lo] = path[hi];
		path[hi] = t;
	}
	int32_t prev = c, cur = brute_nb(b, c, d);
	while (cur != stop && brute_degree(b, cur) == 2) {
		path[n++] = cur;
		b->ref[cur] = -3; /* walked; its place set by brute_edge */
		int32_t next = -1;
		for (int k = 0; k < 4; k++) {
			int32_t nb = brute_nb(b, cur, k);
			if (nb >= 0 && nb != prev)
				next = nb;
		}
		prev = cur;
		cur = next;
	}
	for (int k = 0; k < n; k++)
		if (b->ref[path[k]] == -3)
			b->ref[path[k]] = -1;
	n = brute_to_root(b, cur, path, n);
	brute_edge(b, v, b->ref[cur], path, n);
}

static void brute_build(Brute *b, const Skeleton *s, const Grid *g)
{
	const int n = s->w * s->h;
	b->s = s;
	b->g = g;
	b->nv = b->ne = b->ncells = b->nvcells = 0;
	b->vcells = malloc(sizeof(int32_t) * (size_t)(n + 1));
	b->cells_cap = 16 * n + 64;
	b->cells = malloc(sizeof(int32_t) * (size_t)b->cells_cap);
	b->v = malloc(sizeof *b->v * (size_t)(n + 1));
	b->e = malloc(sizeof *b->e * (size_t)(4 * n + 1));
	b->vfirst = malloc(sizeof *b->vfirst * (size_t)(n + 2));
	b->ref = malloc(sizeof(int32_t) * (size_t)(n + 1));
	b->parent_dir = malloc((size_t)(n + 1));
	int32_t *path = malloc(sizeof(int32_t) * (size_t)(2 * n + 2));
	memset(b->parent_dir, -1, (size_t)n);
	for (int i = 0; i < n; i++)
		b->ref[i] = -1;
	for (int32_t i = 0; i < n; i++) {
		if (!s->on[i] || b->ref[i] != -1 || brute_degree(b, i) == 2)
			continue;
		int deg = brute_degree(b, i);
		if (deg < 3) {
			brute_vertex(b, i, deg == 1 ? PATHGRAPH_END : PATHGRAPH_POINT);
			continue;
		}
		/* a junction set: flood, root at the first cell of largest dist2, then the
		 * breadth-first tree from the root */
		int id = brute_vertex(b, i, PATHGRAPH_JUNCTION), first = b->vfirst[id];
		for (int k = first; k < b->nvcells; k++)
			for (int d = 0; d < 4; d++) {
				int32_t nb = brute_nb(b, b->vcells[k], d);
				if (nb >= 0 && b->ref[nb] == -1 && brute_degree(b, nb) >= 3) {
					b->ref[nb] = id;
					b->vcells[b->nvcells++] = nb;
				}
			}
		int32_t root = i;
		for (int k = first; k < b->nvcells; k++)
			if (s->dist2[b->vcells[k]] > s->dist2[root])
				root = b->vcells[k];
		const int size = b->nvcells - first;
		b->nvcells = first;
		b->vcells[b->nvcells++] = root;
		for (int k = first; k < b->nvcells; k++)
			for (int d = 0; d < 4; d++) {
				int32_t nb = brute_nb(b, b->vcells[k], d);
				if (nb >= 0 && nb != root && b->ref[nb] == id &&
				    b->parent_dir[nb] < 0) {
					b->parent_dir[nb] = (int8_t)((d + 2) % 4);
					b->vcells[b->nvcells++] = nb;
				}
			}
		TEST_CHECK(b->nvcells - first == size);
		b->v[id] = (PathgraphVertex){root % s->w, root / s->w, PATHGRAPH_JUNCTION, size,
		                             s->dist2[root]};
	}
	const int nv = b->nv;
	b->vfirst[nv] = b->nvcells;
	for (int v = 0; v < nv; v++)
		for (int k = b->vfirst[v]; k < b->vfirst[v + 1]; k++) {
			const int32_t c = b->vcells[k];
			for (int d = 0; d < 4; d++) {
				int32_t nb = brute_nb(b, c, d);
				if (nb < 0)
					continue;
				if (b->ref[nb] == -1) {
					brute_walk(b, v, c, d, -1, path);
				} else if (b->ref[nb] >= 0 && b->ref[nb] != v && c < nb) {
					int m = brute_to_root(b, c, path, 0);
					for (int lo = 0, hi = m - 1; lo < hi; lo++, hi--) {
						int32_t t = path[lo];
						path[lo] = path[hi];
						path[hi] = t;
					}
					m = brute_to_root(b, nb, path, m);
					brute_edge(b, v, b->ref[nb], path, m);
				}
			}
		}
	for (int32_t i = 0; i < n; i++)
		if (s->on[i] && b->ref[i] == -1) {
			int id = brute_vertex(b, i, PATHGRAPH_LOOP), d = 0;
			while (brute_nb(b, i, d) < 0)
				d++;
			brute_walk(b, id, i, d, i, path);
		}
	for (int32_t i = 0; i < n; i++)
		if (b->ref[i] <= -2)
			b->ref[i] = b->nv + (-2 - b->ref[i]);
	free(path);
}

static void brute_free(Brute *b)
{
	free(b->vcells);
	free(b->cells);
	free(b->v);
	free(b->e);
	free(b->vfirst);
	free(b->ref);
	free(b->parent_dir);
}

/* brute_equal(b, pg): the build's graph is the oracle's, vertex for vertex, edge for
 * edge (lengths to the last bit: the same additions in the same order), cell for cell,
 * and so is every grid cell's pathgraph_cell_ref. */
static bool brute_equal(const Brute *b, const Pathgraph *pg)
{
	if (pg->vertex_count != b->nv || pg->edge_count != b->ne || pg->cell_count != b->ncells)
		return false;
	for (int v = 0; v < b->nv; v++) {
		const PathgraphVertex *p = &pg->vertices[v], *q = &b->v[v];
		if (p->x != q->x || p->y != q->y || p->kind != q->kind ||
		    p->set_size != q->set_size || p->dist2 != q->dist2)
			return false;
	}
	for (int e = 0; e < b->ne; e++) {
		const PathgraphEdge *p = &pg->edges[e], *q = &b->e[e];
		if (p->v0 != q->v0 || p->v1 != q->v1 || p->first != q->first ||
		    p->count != q->count || p->length != q->length || p->min_dist2 != q->min_dist2)
			return false;
	}
	for (int k = 0; k < b->ncells; k++)
		if (pg->cells[k] != b->cells[k])
			return false;
	for (int i = 0; i < pg->w * pg->h; i++)
		if (pathgraph_cell_ref(pg, i) != b->ref[i])
			return false;
	return true;
}

/* The build (from the skeleton's bit plane, 64 cells a word) equals the brute-force
 * one on random grids, among them widths at and around the plane's word boundaries
 * (63, 64, 65, 127, 128, 129 cells; a row's bits start on a word), kept and rebuilt
 * on grids of one size and afresh. */
TEST_CASE(build_equals_brute_force)
{
	oracle_seed = 41;
	static const int widths[] = {1, 2, 3, 7, 8, 9, 63, 64, 65, 127, 128, 129};
	int builds = 0, loops = 0, junction_sets = 0;
	for (int wi = 0; wi < (int)(sizeof widths / sizeof widths[0]); wi++) {
		Pathgraph kept;
		pathgraph_init(&kept);
		const int w = widths[wi], h = 1 + oracle_rand_below(40);
		for (int trial = 0; trial < 8; trial++) {
			Grid g;
			if (trial % 4 == 3) { /* walled rooms, a block in each: loops */
				grid_init(&g, w, h, GRID_FREE);
				for (int y = 0; y < h; y++)
					for (int x = 0; x < w; x++)
						if (x % 10 == 0 || y % 10 == 0 ||
						    (x % 10 >= 4 && x % 10 <= 6 && y % 10 >= 4 &&
						     y % 10 <= 6))
							g.cells[y * w + x] = GRID_BLOCKED;
			} else {
				oracle_random_grid(&g, w, h, oracle_rand_below(45),
				                   oracle_rand_below(5));
			}
			Skeleton s;
			skeleton_init(&s);
			skeleton_compute(&s, &g);
			Pathgraph fresh;
			pathgraph_init(&fresh);
			pathgraph_build(&fresh, &s, &g);
			pathgraph_build(&kept, &s, &g);
			Brute *b = calloc(1, sizeof *b);
			brute_build(b, &s, &g);
			TEST_CHECK(brute_equal(b, &fresh));
			TEST_CHECK(brute_equal(b, &kept));
			TEST_CHECK(pathgraph_validate(&fresh));
			for (int v = 0; v < b->nv; v++) {
				loops += b->v[v].kind == PATHGRAPH_LOOP;
				junction_sets += b->v[v].set_size > 1;
			}
			builds++;
			brute_free(b);
			free(b);
			pathgraph_free(&fresh);
			skeleton_free(&s);
			grid_free(&g);
		}
		pathgraph_free(&kept);
	}
	fprintf(stderr, "  %d builds, %d loop vertices, %d junction sets\n", builds, loops,
	        junction_sets);
	TEST_CHECK(builds == 96 && loops > 10 && junction_sets > 10);
}

static Vec2 random_free_point(const Grid *g)
{
	for (;;) {
		int x = oracle_rand_below(g->w), y = oracle_rand_below(g->h);
		if (grid_free_at(g, x, y))
			return vec2(x + oracle_rand_below(1000) / 1000.0,
			            y + oracle_rand_below(1000) / 1000.0);
	}
}

TEST_CASE(paths_exist_iff_connected_and_lie_in_free_space)
{
	oracle_seed = 21;
	int found = 0, none = 0;
	for (int trial = 0; trial < 120; trial++) {
		Grid g;
		oracle_random_grid(&g, 4 + oracle_rand_below(40), 4 + oracle_rand_below(40),
		                   oracle_rand_below(40), oracle_rand_below(6));
		int free_cells = 0;
		for (int i = 0; i < g.w * g.h; i++)
			free_cells += g.cells[i] == GRID_FREE;
		if (free_cells == 0) {
			grid_free(&g);
			continue;
		}
		int *lab = malloc(sizeof(int) * (size_t)(g.w * g.h));
		oracle_label(g.cells, g.w, g.h, 4, lab);
		Skeleton s;
		Pathgraph pg;
		Path p;
		skeleton_init(&s);
		pathgraph_init(&pg);
		path_init(&p);
		skeleton_compute(&s, &g);
		pathgraph_build(&pg, &s, &g);
		for (int q = 0; q < 20; q++) {
			Vec2 a = random_free_point(&g), b = random_free_point(&g);
			bool joined =
			    lab[(int)a.y * g.w + (int)a.x] == lab[(int)b.y * g.w + (int)b.x];
			PathgraphQuery opt = pathgraph_query_default();
			bool ok = pathgraph_find_path(&pg, a, b, &opt, &p);
			TEST_CHECK(ok == joined);
			if (!ok) {
				TEST_CHECK(p.count == 0);
				none++;
				continue;
			}
			found++;
			TEST_CHECK(p.pts[0].x == a.x && p.pts[0].y == a.y);
			TEST_CHECK(p.pts[p.count - 1].x == b.x && p.pts[p.count - 1].y == b.y);
			bool inside = path_in_free_space(&g, &p);
			if (!inside) {
				skeleton_dump(&s, &g, stderr);
				for (int i = 0; i < p.count; i++)
					fprintf(stderr, "  (%.3f, %.3f)\n", p.pts[i].x, p.pts[i].y);
			}
			TEST_CHECK(inside);
		}
		path_free(&p);
		pathgraph_free(&pg);
		skeleton_free(&s);
		free(lab);
		grid_free(&g);
	}
	TEST_CHECK(found > 100 && none > 10);
}

/* the rows are a picture of the grid, north on top */
/* clang-format off */
static const char *const RING[] = {
    "....................",
    "....................",
    "....................",
    "....................",
    "........####........",
    "........####........",
    "........####........",
    "....................",
    "....................",
    "....................",
    "....................",
};
/* clang-format on */

TEST_CASE(two_distinct_paths_round_a_ring)
{
	Grid g;
	oracle_grid_from(&g, RING, 11);
	Skeleton s;
	Pathgraph pg;
	skeleton_init(&s);
	pathgraph_init(&pg);
	skeleton_compute(&s, &g);
	pathgraph_build(&pg, &s, &g);
	Path p[4];
	for (int i = 0; i < 4; i++)
		path_init(&p[i]);
	PathgraphQuery opt = pathgraph_query_default();
	int n = pathgraph_find_paths(&pg, vec2(1.5, 5.5), vec2(18.5, 5.5), &opt, 4, p);
	TEST_CHECK(n == 2);
	TEST_CHECK(path_length(&p[0]) <= path_length(&p[1]));
	/* one passes above the obstacle, one below */
	bool above = false, below = false;
	for (int k = 0; k < 2; k++)
		for (int i = 1; i < p[k].count; i++)
			for (int j = 0; j <= 100; j++) {
				Vec2 a = p[k].pts[i - 1], b = p[k].pts[i];
				double x = a.x + (b.x - a.x) * j / 100,
				       y = a.y + (b.y - a.y) * j / 100;
				if (x > 8 && x < 12) {
					above = above || y > 7;
					below = below || y < 4;
				}
			}
	TEST_CHECK(above && below);
	for (int k = 0; k < 2; k++)
		TEST_CHECK(path_in_free_space(&g, &p[k]));
	for (int i = 0; i < 4; i++)
		path_free(&p[i]);
	pathgraph_free(&pg);
	skeleton_free(&s);
	grid_free(&g);
}

TEST_CASE(four_distinct_paths_round_two_obstacles)
{
	/* above or below each of two obstacles: 2 x 2 loopless ways, and no more */
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const rows[] = {
	    "..............................",
	    "..............................",
	    "..............................",
	    "..............................",
	    "........###........###........",
	    "........###........###........",
	    "........###........###........",
	    "..............................",
	    "..............................",
	    "..............................",
	    "..............................",
	};
	/* clang-format on */
	Grid g;
	oracle_grid_from(&g, rows, 11);
	Skeleton s;
	Pathgraph pg;
	skeleton_init(&s);
	pathgraph_init(&pg);
	skeleton_compute(&s, &g);
	pathgraph_build(&pg, &s, &g);
	Path p[6];
	for (int i = 0; i < 6; i++)
		path_init(&p[i]);
	int n = pathgraph_find_paths(&pg, vec2(1.5, 5.5), vec2(28.5, 5.5), NULL, 6, p);
	TEST_CHECK(n == 4);
	/* each passes each obstacle on one side: which side, sampled at its middle */
	int seen = 0;
	for (int k = 0; k < n; k++) {
		TEST_CHECK(path_in_free_space(&g, &p[k]));
		int code = 0;
		for (int i = 1; i < p[k].count; i++)
			for (int j = 0; j <= 100; j++) {
				Vec2 a = p[k].pts[i - 1], b = p[k].pts[i];
				double x = a.x + (b.x - a.x) * j / 100,
				       y = a.y + (b.y - a.y) * j / 100;
				if (x > 9 && x < 10)
					code |= y > 7 ? 1 : 2;
				if (x > 20 && x < 21)
					code |= y > 7 ? 4 : 8;
			}
		/* one side per obstacle: 1 or 2, and 4 or 8 */
		TEST_CHECK((code & 3) == 1 || (code & 3) == 2);
		TEST_CHECK((code & 12) == 4 || (code & 12) == 8);
		seen |= 1 << code;
	}
	/* all four combinations */
	TEST_CHECK(seen == ((1 << 5) | (1 << 6) | (1 << 9) | (1 << 10)));
	for (int i = 0; i < 6; i++)
		path_free(&p[i]);
	pathgraph_free(&pg);
	skeleton_free(&s);
	grid_free(&g);
}

TEST_CASE(minimum_clearance_avoids_the_narrow_way)
{
	/* a wide way over the top and a gap one cell wide through the middle wall */
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const rows[] = {
	    "......................",
	    "......................",
	    "......................",
	    "......................",
	    "#########.############",
	    "#########.############",
	    "......................",
	    "......................",
	    "......................",
	    "......................",
	    "......................",
	};
	/* clang-format on */
	Grid g;
	oracle_grid_from(&g, rows, 11);
	/* close the top way except at the right end */
	Skeleton s;
	Pathgraph pg;
	Path p;
	skeleton_init(&s);
	pathgraph_init(&pg);
	path_init(&p);
	skeleton_compute(&s, &g);
	pathgraph_build(&pg, &s, &g);
	PathgraphQuery opt = pathgraph_query_default();
	TEST_CHECK(pathgraph_find_path(&pg, vec2(9.5, 8.5), vec2(9.5, 2.5), &opt, &p));
	TEST_CHECK(path_in_free_space(&g, &p));
	opt.min_clearance = 1.5; /* the gap's cells have clearance 1 */
	TEST_CHECK(!pathgraph_find_path(&pg, vec2(9.5, 8.5), vec2(9.5, 2.5), &opt, &p));
	TEST_CHECK(p.count == 0);
	path_free(&p);
	pathgraph_free(&pg);
	skeleton_free(&s);
	grid_free(&g);

	/* now with a second, wide way round the right end of the wall */
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const rows2[] = {
	    "......................",
	    "......................",
	    "......................",
	    "......................",
	    "#########.#######.....",
	    "#########.#######.....",
	    "......................",
	    "......................",
	    "......................",
	    "......................",
	    "......................",
	};
	/* clang-format on */
	oracle_grid_from(&g, rows2, 11);
	skeleton_compute(&s, &g);
	pathgraph_build(&pg, &s, &g);
	opt.min_clearance = 0;
	TEST_CHECK(pathgraph_find_path(&pg, vec2(9.5, 8.5), vec2(9.5, 2.5), &opt, &p));
	double narrow = path_length(&p);
	opt.min_clearance = 1.5;
	TEST_CHECK(pathgraph_find_path(&pg, vec2(9.5, 8.5), vec2(9.5, 2.5), &opt, &p));
	TEST_CHECK(path_length(&p) > narrow + 4);
	TEST_CHECK(path_in_free_space(&g, &p));
	path_free(&p);
	pathgraph_free(&pg);
	skeleton_free(&s);
	grid_free(&g);
}

TEST_CASE(entry_is_in_sight_in_a_room)
{
	Grid g;
	oracle_grid_from(&g, RING, 11);
	Skeleton s;
	Pathgraph pg;
	skeleton_init(&s);
	pathgraph_init(&pg);
	skeleton_compute(&s, &g);
	pathgraph_build(&pg, &s, &g);
	int32_t x, y;
	TEST_CHECK(pathgraph_entry(&pg, vec2(0.5, 0.5), &x, &y) == 1);
	TEST_CHECK(skeleton_on(&s, x, y));
	TEST_CHECK(pathgraph_segment_free(&g, vec2(0.5, 0.5), vec2(x + 0.5, y + 0.5)));
	TEST_CHECK(pathgraph_entry(&pg, vec2(9.5, 5.5), &x, &y) == 0); /* in the obstacle */
	TEST_CHECK(pathgraph_entry(&pg, vec2(-3, 5.5), &x, &y) == 0);  /* off the grid */
	pathgraph_free(&pg);
	skeleton_free(&s);
	grid_free(&g);
}

/* S' by brute force: the entry is in sight (dense sampling), and no skeleton cell of
 * the component nearer to the point is in sight; when the entry is by a walk, no
 * skeleton cell of the component is in sight at all. */
TEST_CASE(entry_is_the_nearest_skeleton_cell_in_sight)
{
	oracle_seed = 31;
	int in_sight = 0, walked = 0;
	for (int trial = 0; trial < 150; trial++) {
		Grid g;
		oracle_random_grid(&g, 4 + oracle_rand_below(30), 4 + oracle_rand_below(30),
		                   oracle_rand_below(45), oracle_rand_below(6));
		int free_cells = 0;
		for (int i = 0; i < g.w * g.h; i++)
			free_cells += g.cells[i] == GRID_FREE;
		if (free_cells == 0) {
			grid_free(&g);
			continue;
		}
		int *lab = malloc(sizeof(int) * (size_t)(g.w * g.h));
		oracle_label(g.cells, g.w, g.h, 4, lab);
		Skeleton s;
		Pathgraph pg;
		skeleton_init(&s);
		pathgraph_init(&pg);
		skeleton_compute(&s, &g);
		pathgraph_build(&pg, &s, &g);
		for (int q = 0; q < 10; q++) {
			Vec2 p = random_free_point(&g);
			int32_t ex, ey;
			int how = pathgraph_entry(&pg, p, &ex, &ey);
			TEST_CHECK(how == 1 || how == 2);
			int comp = lab[(int)p.y * g.w + (int)p.x];
			TEST_CHECK(skeleton_on(&s, ex, ey) && lab[ey * g.w + ex] == comp);
			double best = hypot(ex + 0.5 - p.x, ey + 0.5 - p.y);
			if (how == 1) {
				in_sight++;
				TEST_CHECK(brute_segment_free(&g, p, vec2(ex + 0.5, ey + 0.5)));
			} else {
				walked++;
			}
			for (int i = 0; i < g.w * g.h; i++) {
				if (!s.on[i] || lab[i] != comp)
					continue;
				Vec2 c = vec2(i % g.w + 0.5, i / g.w + 0.5);
				if (how == 2 || hypot(c.x - p.x, c.y - p.y) < best - 1e-9)
					TEST_CHECK(!pathgraph_segment_free(&g, p, c));
			}
		}
		pathgraph_free(&pg);
		skeleton_free(&s);
		free(lab);
		grid_free(&g);
	}
	fprintf(stderr, "  entries: %d in sight, %d by a walk\n", in_sight, walked);
	TEST_CHECK(in_sight > 100 && walked > 0);
}

TEST_CASE(pathgraph_dump_of_a_corridor_by_hand)
{
	/* a corridor 3 wide: its skeleton is the middle row from x = 1 to 10, both ends
	 * end points, clearance 2 (to the outside rows) all along */
	Grid g;
	grid_init(&g, 12, 3, GRID_FREE);
	Skeleton s;
	Pathgraph pg;
	skeleton_init(&s);
	pathgraph_init(&pg);
	skeleton_compute(&s, &g);
	pathgraph_build(&pg, &s, &g);
	char *text = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&text, &len);
	pathgraph_dump(&pg, f);
	fclose(f);
	const char *want = "pathgraph: 2 vertices, 1 edges\n"
	                   "vertex 0 1 1 end 1 2.000\n"
	                   "vertex 1 10 1 end 1 2.000\n"
	                   "edge 0 0 1 9.000 2.000 10\n";
	if (strcmp(text, want) != 0)
		fprintf(stderr, "%s", text);
	TEST_CHECK(strcmp(text, want) == 0);
	free(text);
	pathgraph_free(&pg);
	skeleton_free(&s);
	grid_free(&g);
}

int main(void)
{
	TEST_RUN(line_test_by_hand);
	TEST_RUN(line_test_agrees_with_dense_sampling);
	TEST_RUN(pathgraph_edges_on_random_grids);
	TEST_RUN(rebuilt_pathgraph_equals_a_fresh_one);
	TEST_RUN(build_equals_brute_force);
	TEST_RUN(paths_exist_iff_connected_and_lie_in_free_space);
	TEST_RUN(two_distinct_paths_round_a_ring);
	TEST_RUN(four_distinct_paths_round_two_obstacles);
	TEST_RUN(minimum_clearance_avoids_the_narrow_way);
	TEST_RUN(entry_is_in_sight_in_a_room);
	TEST_RUN(entry_is_the_nearest_skeleton_cell_in_sight);
	TEST_RUN(pathgraph_dump_of_a_corridor_by_hand);
	return TEST_EXIT();
}
