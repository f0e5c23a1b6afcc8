/* test_gridpath.c - grid A* (gridpath.h, paper 4.1) against two independent oracles:
 * a plain Dijkstra over the same 8-connected graph on random grids, and the
 * published optima of Moving AI scenarios (the copies in tests/data/movingai, so a
 * fresh clone tests itself: missing data is a failure, not a skip). */
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "utak/plan/gridpath.h"
#include "utak/plan/movingai.h"

/* A tiny deterministic generator (xorshift32), so the grids are the same everywhere. */
static uint32_t rng_state = 12345u;
static uint32_t rng_next(void)
{
	rng_state ^= rng_state << 13;
	rng_state ^= rng_state >> 17;
	rng_state ^= rng_state << 5;
	return rng_state;
}

/* The oracle: Dijkstra by linear scan for the minimum (O(n^2), no heap, no
 * heuristic), over the graph as the README defines it, written independently of
 * gridpath.c. Returns -1 when unreachable. */
static double dijkstra_length(const Grid *g, int sx, int sy, int gx, int gy)
{
	int n = g->w * g->h;
	double *dist = malloc((size_t)n * sizeof *dist);
	char *done = calloc((size_t)n, 1);
	for (int i = 0; i < n; i++)
		dist[i] = INFINITY;
	dist[sy * g->w + sx] = 0;
	for (;;) {
		int best = -1;
		for (int i = 0; i < n; i++)
			if (!done[i] && dist[i] < INFINITY && (best < 0 || dist[i] < dist[best]))
				best = i;
		if (best < 0)
			break;
		done[best] = 1;
		int x = best % g->w, y = best / g->w;
		for (int dy = -1; dy <= 1; dy++)
			for (int dx = -1; dx <= 1; dx++) {
				if (dx == 0 && dy == 0)
					continue;
				if (!grid_free_at(g, x + dx, y + dy))
					continue;
				if (dx != 0 && dy != 0 &&
				    (!grid_free_at(g, x + dx, y) || !grid_free_at(g, x, y + dy)))
					continue;
				double c = dx != 0 && dy != 0 ? sqrt(2.0) : 1.0;
				int j = (y + dy) * g->w + x + dx;
				if (dist[best] + c < dist[j])
					dist[j] = dist[best] + c;
			}
	}
	double r = dist[gy * g->w + gx];
	free(dist);
	free(done);
	return r < INFINITY ? r : -1;
}

/* check_path: the path is a chain of legal 8-connected steps between the endpoints
 * whose length is the reported length. */
static int check_path(const Grid *g, const Path *p, int sx, int sy, int gx, int gy, double len)
{
	if (p->count < 1)
		return 0;
	if (p->pts[0].x != sx + 0.5 || p->pts[0].y != sy + 0.5)
		return 0;
	if (p->pts[p->count - 1].x != gx + 0.5 || p->pts[p->count - 1].y != gy + 0.5)
		return 0;
	for (int i = 0; i < p->count; i++) {
		int x = (int)floor(p->pts[i].x), y = (int)floor(p->pts[i].y);
		if (!grid_free_at(g, x, y))
			return 0;
		if (i == 0)
			continue;
		int dx = x - (int)floor(p->pts[i - 1].x), dy = y - (int)floor(p->pts[i - 1].y);
		if (abs(dx) > 1 || abs(dy) > 1 || (dx == 0 && dy == 0))
			return 0;
		if (dx != 0 && dy != 0 &&
		    (!grid_free_at(g, x - dx, y) || !grid_free_at(g, x, y - dy)))
			return 0;
	}
	return fabs(path_length(p) - len) < 1e-9;
}

TEST_CASE(gridpath_octile_by_hand)
{
	TEST_NEAR(gridpath_octile(3, -5), 2 + 3 * sqrt(2.0), 1e-12);
	TEST_NEAR(gridpath_octile(0, 0), 0, 0);
	TEST_NEAR(gridpath_octile(-7, 0), 7, 0);
}

TEST_CASE(gridpath_equals_dijkstra_on_random_grids)
{
	Path p;
	path_init(&p);
	for (int trial = 0; trial < 300; trial++) {
		int w = 1 + (int)(rng_next() % 24), h = 1 + (int)(rng_next() % 24);
		int density = (int)(rng_next() % 45);
		Grid g;
		grid_init(&g, w, h, GRID_FREE);
		for (int i = 0; i < w * h; i++)
			if ((int)(rng_next() % 100) < density)
				g.cells[i] = GRID_BLOCKED;
		GridPathSearch s;
		gridpath_init(&s, &g);
		for (int q = 0; q < 8; q++) {
			int sx = (int)(rng_next() % (uint32_t)w),
			    sy = (int)(rng_next() % (uint32_t)h);
			int gx = (int)(rng_next() % (uint32_t)w),
			    gy = (int)(rng_next() % (uint32_t)h);
			double len;
			GridPathStatus st = gridpath_find(&s, sx, sy, gx, gy, &p, &len);
			if (!grid_free_at(&g, sx, sy) || !grid_free_at(&g, gx, gy)) {
				TEST_CHECK(st == GRIDPATH_BAD_ENDPOINT);
				TEST_CHECK(p.count == 0 && len == -1);
				continue;
			}
			double want = dijkstra_length(&g, sx, sy, gx, gy);
			if (want < 0) {
				TEST_CHECK(st == GRIDPATH_NO_PATH);
				TEST_CHECK(p.count == 0);
				continue;
			}
			TEST_CHECK(st == GRIDPATH_FOUND);
			TEST_NEAR(len, want, 1e-9);
			TEST_CHECK(check_path(&g, &p, sx, sy, gx, gy, len));
			TEST_CHECK(p.expanded >= 1);
		}
		gridpath_free(&s);
		grid_free(&g);
	}
	path_free(&p);
}

/* Plain A* skips the steps its parent makes needless (gridpath.c, PARENT'S
 * NEIGHBOURS: one step from the parent, two straight steps from it, or a diagonal
 * the parent could take first), which corridors, lattices and diagonal stripes meet
 * at every turn: against Dijkstra on such grids, corridors 1 to 3 wide. */
TEST_CASE(gridpath_equals_dijkstra_on_corridor_grids)
{
	Path p;
	path_init(&p);
	int queries = 0;
	for (int trial = 0; trial < 240; trial++) {
		int w = 4 + (int)(rng_next() % 37), h = 4 + (int)(rng_next() % 37);
		int pitch = 2 + (int)(rng_next() % 3), gap = 30 + (int)(rng_next() % 50);
		int kind = trial % 3;
		Grid g;
		grid_init(&g, w, h, GRID_FREE);
		for (int y = 0; y < h; y++)
			for (int x = 0; x < w; x++) {
				int wall = kind == 0   ? (x % pitch == 0 || y % pitch == 0)
				           : kind == 1 ? ((x + y) % (pitch + 1) == 0 ||
				                          x % (pitch + 2) == 0)
				                       : ((x + 2 * y) % (pitch + 2) == 0);
				if (wall && (int)(rng_next() % 100) < gap)
					g.cells[y * w + x] = GRID_BLOCKED;
			}
		GridPathSearch s;
		gridpath_init(&s, &g);
		for (int q = 0; q < 6; q++) {
			int sx = (int)(rng_next() % (uint32_t)w),
			    sy = (int)(rng_next() % (uint32_t)h);
			int gx = (int)(rng_next() % (uint32_t)w),
			    gy = (int)(rng_next() % (uint32_t)h);
			if (!grid_free_at(&g, sx, sy) || !grid_free_at(&g, gx, gy))
				continue;
			double len;
			GridPathStatus st = gridpath_find(&s, sx, sy, gx, gy, &p, &len);
			double want = dijkstra_length(&g, sx, sy, gx, gy);
			queries++;
			if (want < 0) {
				TEST_CHECK(st == GRIDPATH_NO_PATH);
				continue;
			}
			TEST_CHECK(st == GRIDPATH_FOUND);
			TEST_NEAR(len, want, 1e-9);
			TEST_CHECK(check_path(&g, &p, sx, sy, gx, gy, len));
		}
		gridpath_free(&s);
		grid_free(&g);
	}
	TEST_CHECK(queries > 800);
	path_free(&p);
}

TEST_CASE(gridpath_refuses_bad_endpoints)
{
	Grid g;
	grid_init(&g, 4, 3, GRID_FREE);
	g.cells[1 * 4 + 2] = GRID_BLOCKED;
	GridPathSearch s;
	gridpath_init(&s, &g);
	Path p;
	path_init(&p);
	double len;
	TEST_CHECK(gridpath_find(&s, -1, 0, 3, 2, &p, &len) == GRIDPATH_BAD_ENDPOINT);
	TEST_CHECK(gridpath_find(&s, 0, 0, 4, 2, &p, &len) == GRIDPATH_BAD_ENDPOINT);
	TEST_CHECK(gridpath_find(&s, 0, 0, 2, 1, &p, &len) == GRIDPATH_BAD_ENDPOINT);
	TEST_CHECK(gridpath_find(&s, 1, 1, 1, 1, &p, &len) == GRIDPATH_FOUND);
	TEST_CHECK(len == 0 && p.count == 1);
	/* Around the block: (1,1) -> (3,1) may not cut the block's corners, so no
	 * diagonal step touches it: 4 straight steps, not 2 sqrt 2. */
	TEST_CHECK(gridpath_find(&s, 1, 1, 3, 1, &p, &len) == GRIDPATH_FOUND);
	TEST_NEAR(len, 4, 1e-12);
	path_free(&p);
	gridpath_free(&s);
	grid_free(&g);
}

/* The published optima of a few scenarios of each mapf map: every 7th problem. */
TEST_CASE(gridpath_matches_published_optima)
{
	static const char *const maps[] = {"room-32-32-4", "maze-32-32-2", "random-32-32-10",
	                                   "warehouse-10-20-10-2-1"};
	char err[MOVINGAI_ERROR_SIZE], mpath[256], spath[256];
	Path p;
	path_init(&p);
	for (size_t m = 0; m < sizeof maps / sizeof maps[0]; m++) {
		snprintf(mpath, sizeof mpath, "tests/data/movingai/maps/mapf/%s.map", maps[m]);
		snprintf(spath, sizeof spath,
		         "tests/data/movingai/scenarios/mapf/scen-even/%s-even-1.scen",
		         maps[m]);
		Grid g;
		MovingAiScen scen;
		bool ok = movingai_read_map(mpath, &g, err);
		if (!ok)
			fprintf(stderr, "  %s\n", err);
		TEST_CHECK(ok);
		ok = movingai_read_scen(spath, &g, &scen, err);
		if (!ok)
			fprintf(stderr, "  %s\n", err);
		TEST_CHECK(ok);
		TEST_CHECK(scen.count > 20);
		GridPathSearch s;
		gridpath_init(&s, &g);
		for (int i = 0; i < scen.count; i += 7) {
			const MovingAiProblem *pr = &scen.problems[i];
			double len;
			TEST_CHECK(gridpath_find(&s, pr->sx, pr->sy, pr->gx, pr->gy, &p, &len) ==
			           GRIDPATH_FOUND);
			TEST_NEAR(len, pr->optimum, movingai_tolerance(pr->optimum));
			TEST_CHECK(check_path(&g, &p, pr->sx, pr->sy, pr->gx, pr->gy, len));
		}
		gridpath_free(&s);
		movingai_scen_free(&scen);
		grid_free(&g);
	}
	path_free(&p);
}

/* The jump-point search (GRIDPATH_JUMP) against the Dijkstra oracle on random grids,
 * with open stretches (low density) where runs are long and cluttered ones where
 * forced neighbours are everywhere, and against plain A* on the same queries. */
TEST_CASE(gridpath_jump_equals_dijkstra_on_random_grids)
{
	Path p, q;
	path_init(&p);
	path_init(&q);
	for (int trial = 0; trial < 300; trial++) {
		int w = 1 + (int)(rng_next() % 24), h = 1 + (int)(rng_next() % 24);
		int density = (int)(rng_next() % 45);
		Grid g;
		grid_init(&g, w, h, GRID_FREE);
		for (int i = 0; i < w * h; i++)
			if ((int)(rng_next() % 100) < density)
				g.cells[i] = GRID_BLOCKED;
		GridPathSearch s, a;
		gridpath_init(&s, &g);
		gridpath_init(&a, &g);
		s.method = GRIDPATH_JUMP;
		for (int k = 0; k < 8; k++) {
			int sx = (int)(rng_next() % (uint32_t)w),
			    sy = (int)(rng_next() % (uint32_t)h);
			int gx = (int)(rng_next() % (uint32_t)w),
			    gy = (int)(rng_next() % (uint32_t)h);
			double len, alen;
			GridPathStatus st = gridpath_find(&s, sx, sy, gx, gy, &p, &len);
			GridPathStatus ast = gridpath_find(&a, sx, sy, gx, gy, &q, &alen);
			TEST_CHECK(st == ast);
			if (!grid_free_at(&g, sx, sy) || !grid_free_at(&g, gx, gy)) {
				TEST_CHECK(st == GRIDPATH_BAD_ENDPOINT);
				TEST_CHECK(p.count == 0 && len == -1);
				continue;
			}
			double want = dijkstra_length(&g, sx, sy, gx, gy);
			if (want < 0) {
				TEST_CHECK(st == GRIDPATH_NO_PATH);
				TEST_CHECK(p.count == 0);
				continue;
			}
			TEST_CHECK(st == GRIDPATH_FOUND);
			TEST_NEAR(len, want, 1e-9);
			TEST_CHECK(len == alen);
			TEST_CHECK(check_path(&g, &p, sx, sy, gx, gy, len));
			TEST_CHECK(p.expanded >= 1);
		}
		gridpath_free(&s);
		gridpath_free(&a);
		grid_free(&g);
	}
	path_free(&p);
	path_free(&q);
}

/* Against plain A* (checked against the oracle above), on grids 62 to 200 cells a
 * side, whose rows and columns span several 64-cell words of the jump search's bit
 * lines (gridpath.c, CACHE): runs, forced neighbours and the goal on either side of
 * a word's edge, and the legal steps of cells whose neighbourhood straddles one.
 * Low densities, so runs are long. (The O(n^2) oracle would take minutes here.) */
TEST_CASE(gridpath_jump_equals_astar_across_words)
{
	Path p, q;
	path_init(&p);
	path_init(&q);
	for (int trial = 0; trial < 60; trial++) {
		int w = 62 + (int)(rng_next() % 139), h = 62 + (int)(rng_next() % 139);
		int density = (int)(rng_next() % 25);
		Grid g;
		grid_init(&g, w, h, GRID_FREE);
		for (int i = 0; i < w * h; i++)
			if ((int)(rng_next() % 100) < density)
				g.cells[i] = GRID_BLOCKED;
		GridPathSearch s, a;
		gridpath_init(&s, &g);
		gridpath_init(&a, &g);
		s.method = GRIDPATH_JUMP;
		for (int k = 0; k < 16; k++) {
			int sx = (int)(rng_next() % (uint32_t)w),
			    sy = (int)(rng_next() % (uint32_t)h);
			int gx = (int)(rng_next() % (uint32_t)w),
			    gy = (int)(rng_next() % (uint32_t)h);
			double len, alen;
			GridPathStatus st = gridpath_find(&s, sx, sy, gx, gy, &p, &len);
			GridPathStatus ast = gridpath_find(&a, sx, sy, gx, gy, &q, &alen);
			TEST_CHECK(st == ast);
			TEST_CHECK(len == alen);
			if (st == GRIDPATH_FOUND)
				TEST_CHECK(check_path(&g, &p, sx, sy, gx, gy, len));
		}
		gridpath_free(&s);
		gridpath_free(&a);
		grid_free(&g);
	}
	path_free(&p);
	path_free(&q);
}

/* Every published optimum of every scenario file in tests/data/movingai: the jump
 * search finds it, a legal path of that length, and so does plain A* on the same
 * problem (the check of one against the other). */
TEST_CASE(gridpath_jump_matches_every_published_optimum)
{
	static const char *const files[][2] = {
	    {"dao/arena.map", "dao/arena.map.scen"},
	    {"mapf/room-32-32-4.map", "mapf/scen-even/room-32-32-4-even-1.scen"},
	    {"mapf/maze-32-32-2.map", "mapf/scen-even/maze-32-32-2-even-1.scen"},
	    {"mapf/random-32-32-10.map", "mapf/scen-even/random-32-32-10-even-1.scen"},
	    {"mapf/warehouse-10-20-10-2-1.map",
	     "mapf/scen-even/warehouse-10-20-10-2-1-even-1.scen"}};
	char err[MOVINGAI_ERROR_SIZE], mpath[256], spath[256];
	Path p, q;
	path_init(&p);
	path_init(&q);
	int checked = 0;
	for (size_t m = 0; m < sizeof files / sizeof files[0]; m++) {
		snprintf(mpath, sizeof mpath, "tests/data/movingai/maps/%s", files[m][0]);
		snprintf(spath, sizeof spath, "tests/data/movingai/scenarios/%s", files[m][1]);
		Grid g;
		MovingAiScen scen;
		bool ok = movingai_read_map(mpath, &g, err);
		if (!ok)
			fprintf(stderr, "  %s\n", err);
		TEST_CHECK(ok);
		ok = movingai_read_scen(spath, &g, &scen, err);
		if (!ok)
			fprintf(stderr, "  %s\n", err);
		TEST_CHECK(ok);
		GridPathSearch s, a;
		gridpath_init(&s, &g);
		gridpath_init(&a, &g);
		s.method = GRIDPATH_JUMP;
		for (int i = 0; i < scen.count; i++) {
			const MovingAiProblem *pr = &scen.problems[i];
			double len, alen;
			TEST_CHECK(gridpath_find(&s, pr->sx, pr->sy, pr->gx, pr->gy, &p, &len) ==
			           GRIDPATH_FOUND);
			TEST_CHECK(gridpath_find(&a, pr->sx, pr->sy, pr->gx, pr->gy, &q, &alen) ==
			           GRIDPATH_FOUND);
			TEST_NEAR(len, pr->optimum, movingai_tolerance(pr->optimum));
			TEST_CHECK(len == alen);
			TEST_CHECK(check_path(&g, &p, pr->sx, pr->sy, pr->gx, pr->gy, len));
			checked++;
		}
		gridpath_free(&s);
		gridpath_free(&a);
		movingai_scen_free(&scen);
		grid_free(&g);
	}
	TEST_CHECK(checked > 1000);
	path_free(&p);
	path_free(&q);
}

int main(void)
{
	TEST_RUN(gridpath_octile_by_hand);
	TEST_RUN(gridpath_equals_dijkstra_on_random_grids);
	TEST_RUN(gridpath_equals_dijkstra_on_corridor_grids);
	TEST_RUN(gridpath_refuses_bad_endpoints);
	TEST_RUN(gridpath_matches_published_optima);
	TEST_RUN(gridpath_jump_equals_dijkstra_on_random_grids);
	TEST_RUN(gridpath_jump_equals_astar_across_words);
	TEST_RUN(gridpath_jump_matches_every_published_optimum);
	return TEST_EXIT();
}
