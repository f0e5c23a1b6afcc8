/* test_visibility.c - the line-of-sight test and Shakey's visibility graph
 * (visibility.h, paper 4.1) against independent oracles: an exact dense sampling of
 * the segment, hand-computed paths, grid A* (an upper bound), the straight line (a
 * lower bound), and a brute-force shortest path over ALL lattice points. */
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "utak/plan/gridpath.h"
#include "utak/plan/visibility.h"

static uint32_t rng_state = 2463534242u;
static uint32_t rng_next(void)
{
	rng_state ^= rng_state << 13;
	rng_state ^= rng_state >> 17;
	rng_state ^= rng_state << 5;
	return rng_state;
}

static bool blocked(const Grid *g, int64_t x, int64_t y)
{
	return !grid_free_at(g, (int32_t)x, (int32_t)y);
}

/* floor_div: floor(a / b) for b > 0, correct for negative a. */
static int64_t floor_div(int64_t a, int64_t b)
{
	return a >= 0 ? a / b : -((-a + b - 1) / b);
}

/* sampled_free: the oracle. Endpoints are given doubled (half-integers become
 * integers). The segment is sampled at N = 8 |Dx| |Dy| (or 8 |D|) equal steps: every
 * crossing of a grid line falls on a sample (crossings are at multiples of N / |Dx|
 * and N / |Dy|), and distinct crossings are at least 8 samples apart, so between two
 * crossings there is a sample strictly inside the cell or edge the segment runs in.
 * Each interior sample is classified exactly in integers: inside a cell (the cell
 * must be free), on an edge (its two cells not both blocked), or on a lattice point
 * (not a pinch point). */
static bool sampled_free(const Grid *g, int64_t ax2, int64_t ay2, int64_t bx2, int64_t by2)
{
	int64_t dx = bx2 - ax2, dy = by2 - ay2;
	int64_t n = 8 * (dx ? llabs(dx) : 1) * (dy ? llabs(dy) : 1);
	for (int64_t k = 1; k < n; k++) {
		/* The sample's coordinates are X / (2n) and Y / (2n). */
		int64_t X = ax2 * n + dx * k, Y = ay2 * n + dy * k;
		int64_t fx = floor_div(X, 2 * n), fy = floor_div(Y, 2 * n);
		bool xi = X == fx * 2 * n, yi = Y == fy * 2 * n;
		if (!xi && !yi) {
			if (blocked(g, fx, fy))
				return false;
		} else if (xi && !yi) {
			if (blocked(g, fx - 1, fy) && blocked(g, fx, fy))
				return false;
		} else if (!xi && yi) {
			if (blocked(g, fx, fy - 1) && blocked(g, fx, fy))
				return false;
		} else if ((blocked(g, fx - 1, fy - 1) && blocked(g, fx, fy)) ||
		           (blocked(g, fx, fy - 1) && blocked(g, fx - 1, fy)))
			return false;
	}
	return true;
}

static void random_grid(Grid *g, int w, int h, int density)
{
	grid_init(g, w, h, GRID_FREE);
	for (int i = 0; i < w * h; i++)
		if ((int)(rng_next() % 100) < density)
			g->cells[i] = GRID_BLOCKED;
}

TEST_CASE(segment_test_agrees_with_sampling)
{
	int checked = 0, free_count = 0;
	for (int trial = 0; trial < 400; trial++) {
		Grid g;
		int w = 1 + (int)(rng_next() % 10), h = 1 + (int)(rng_next() % 10);
		random_grid(&g, w, h, (int)(rng_next() % 50));
		for (int q = 0; q < 200; q++) {
			/* Half-integers from -1 to w + 1, and often axis-parallel or diagonal. */
			int64_t c[4];
			for (int i = 0; i < 4; i++)
				c[i] = (int64_t)(rng_next() %
				                 (uint32_t)(2 * ((i % 2 ? h : w) + 2) + 1)) -
				       2;
			switch (rng_next() % 4) {
			case 0:
				c[2] = c[0];
				break;
			case 1:
				c[3] = c[1];
				break;
			case 2:
				c[3] = c[1] + (c[2] - c[0]);
				break;
			default:
				break;
			}
			if (c[0] == c[2] && c[1] == c[3])
				continue;
			bool want = sampled_free(&g, c[0], c[1], c[2], c[3]);
			bool got = visibility_segment_free(&g, vec2(c[0] / 2.0, c[1] / 2.0),
			                                   vec2(c[2] / 2.0, c[3] / 2.0));
			if (want != got)
				fprintf(stderr,
				        "  %dx%d grid, (%g,%g)-(%g,%g): sampled %d, test %d\n", w,
				        h, c[0] / 2.0, c[1] / 2.0, c[2] / 2.0, c[3] / 2.0, want,
				        got);
			TEST_CHECK(want == got);
			checked++;
			free_count += got;
		}
		grid_free(&g);
	}
	/* The random cases exercise both answers. */
	TEST_CHECK(free_count > checked / 10 && free_count < checked * 9 / 10);
}

TEST_CASE(segment_test_by_hand)
{
	/* Two blocked cells touching at the corner (2, 2): a pinch point. */
	Grid g;
	grid_init(&g, 4, 4, GRID_FREE);
	g.cells[1 * 4 + 1] = GRID_BLOCKED;
	g.cells[2 * 4 + 2] = GRID_BLOCKED;
	TEST_CHECK(!visibility_segment_free(&g, vec2(1, 3), vec2(3, 1)));    /* through the pinch */
	TEST_CHECK(visibility_segment_free(&g, vec2(0.5, 2.5), vec2(2, 2))); /* ends at it */
	TEST_CHECK(!visibility_segment_free(&g, vec2(0, 2), vec2(4, 2)));    /* along, through it */
	TEST_CHECK(visibility_segment_free(&g, vec2(0, 1), vec2(4, 1)));     /* grazes one cell */
	TEST_CHECK(visibility_segment_free(&g, vec2(0.5, 0.5), vec2(3.5, 0.5)));
	TEST_CHECK(!visibility_segment_free(&g, vec2(0.5, 1.5), vec2(3.5, 1.5)));
	/* A single blocked cell's corner may be touched in passing. */
	g.cells[2 * 4 + 2] = GRID_FREE;
	TEST_CHECK(visibility_segment_free(&g, vec2(0.5, 3.5), vec2(3.5, 0.5)));
	TEST_CHECK(visibility_segment_free(&g, vec2(1, 3), vec2(3, 1)));
	/* A polyline may not bend through a pinch point either. */
	g.cells[2 * 4 + 2] = GRID_BLOCKED;
	Path p;
	path_init(&p);
	path_push(&p, vec2(1.5, 2.5));
	path_push(&p, vec2(2, 2));
	path_push(&p, vec2(2.5, 1.5));
	TEST_CHECK(visibility_segment_free(&g, p.pts[0], p.pts[1]));
	TEST_CHECK(visibility_segment_free(&g, p.pts[1], p.pts[2]));
	TEST_CHECK(!visibility_path_free(&g, &p));
	path_free(&p);
	g.cells[2 * 4 + 2] = GRID_FREE;
	/* Along the outside of the grid: two blocked (outside) cells. */
	TEST_CHECK(!visibility_segment_free(&g, vec2(0, -1), vec2(0, 5)));
	TEST_CHECK(visibility_segment_free(&g, vec2(0, 2), vec2(0, 3)));
	grid_free(&g);
}

TEST_CASE(visibility_around_one_block_by_hand)
{
	/* A 2 x 6 block, x in [4, 6), y in [2, 8), in a 10 x 10 grid: from the left
	 * middle to the right middle, over the top via its corners (4, 8) and (6, 8). */
	Grid g;
	grid_init(&g, 10, 10, GRID_FREE);
	for (int y = 2; y < 8; y++)
		for (int x = 4; x < 6; x++)
			g.cells[y * 10 + x] = GRID_BLOCKED;
	VisibilityGraph vg;
	TEST_CHECK(visibility_init(&vg, &g, 100) == VISIBILITY_FOUND);
	TEST_CHECK(vg.count == 4);
	Path p;
	path_init(&p);
	double len;
	TEST_CHECK(visibility_find(&vg, vec2(1.5, 5.5), vec2(8.5, 5.5), &p, &len) ==
	           VISIBILITY_FOUND);
	TEST_NEAR(len, 2 + 5 * sqrt(2.0), 1e-12);
	TEST_CHECK(p.count == 4);
	TEST_CHECK(p.pts[1].x == 4 && p.pts[1].y == 8 && p.pts[2].x == 6 && p.pts[2].y == 8);
	/* In sight: the straight line. */
	TEST_CHECK(visibility_find(&vg, vec2(1.5, 0.5), vec2(8.5, 1.5), &p, &len) ==
	           VISIBILITY_FOUND);
	TEST_NEAR(len, hypot(7, 1), 1e-12);
	TEST_CHECK(p.count == 2);
	/* Endpoints in a blocked cell. */
	TEST_CHECK(visibility_find(&vg, vec2(4.5, 5.5), vec2(8.5, 5.5), &p, &len) ==
	           VISIBILITY_BAD_ENDPOINT);
	TEST_CHECK(p.count == 0 && len == -1);
	/* The limit refuses cleanly. */
	VisibilityGraph small;
	TEST_CHECK(visibility_init(&small, &g, 3) == VISIBILITY_TOO_LARGE);
	TEST_CHECK(small.count == 0);
	visibility_free(&small);
	path_free(&p);
	visibility_free(&vg);
	grid_free(&g);
}

/* brute_length: the shortest polyline from s to d whose corners are any lattice
 * points but pinch points (a polyline bending at a pinch point could squeeze through
 * it; visibility.h forbids that), over free segments: Dijkstra on the complete graph
 * of the lattice points, no tangent pruning. -1 when none. */
static double brute_length(const Grid *g, Vec2 s, Vec2 d)
{
	int lw = g->w + 1, n = lw * (g->h + 1) + 2;
	Vec2 *pt = malloc((size_t)n * sizeof *pt);
	double *dist = malloc((size_t)n * sizeof *dist);
	char *done = calloc((size_t)n, 1);
	for (int i = 0; i < n - 2; i++)
		pt[i] = vec2(i % lw, i / lw);
	pt[n - 2] = s;
	pt[n - 1] = d;
	for (int i = 0; i < n; i++)
		dist[i] = INFINITY;
	dist[n - 2] = 0;
	for (;;) {
		int u = -1;
		for (int i = 0; i < n; i++)
			if (!done[i] && dist[i] < INFINITY && (u < 0 || dist[i] < dist[u]))
				u = i;
		if (u < 0 || u == n - 1)
			break;
		done[u] = 1;
		if (u < n - 2) {
			int x = u % lw, y = u / lw;
			if ((blocked(g, x - 1, y - 1) && blocked(g, x, y)) ||
			    (blocked(g, x, y - 1) && blocked(g, x - 1, y)))
				continue;
		}
		for (int v = 0; v < n; v++) {
			if (done[v])
				continue;
			double c = hypot(pt[v].x - pt[u].x, pt[v].y - pt[u].y);
			if (dist[u] + c < dist[v] - 1e-12 &&
			    visibility_segment_free(g, pt[u], pt[v]))
				dist[v] = dist[u] + c;
		}
	}
	double r = dist[n - 1];
	free(pt);
	free(dist);
	free(done);
	return r < INFINITY ? r : -1;
}

TEST_CASE(visibility_between_bounds_and_equal_to_brute_force)
{
	Path p, ap;
	path_init(&p);
	path_init(&ap);
	int found = 0;
	for (int trial = 0; trial < 150; trial++) {
		Grid g;
		int w = 2 + (int)(rng_next() % 9), h = 2 + (int)(rng_next() % 9);
		random_grid(&g, w, h, 10 + (int)(rng_next() % 35));
		VisibilityGraph vg;
		TEST_CHECK(visibility_init(&vg, &g, VISIBILITY_MAX_VERTICES) == VISIBILITY_FOUND);
		GridPathSearch as;
		gridpath_init(&as, &g);
		for (int q = 0; q < 6; q++) {
			int sx = (int)(rng_next() % (uint32_t)w),
			    sy = (int)(rng_next() % (uint32_t)h);
			int gx = (int)(rng_next() % (uint32_t)w),
			    gy = (int)(rng_next() % (uint32_t)h);
			Vec2 s = vec2(sx + 0.5, sy + 0.5), d = vec2(gx + 0.5, gy + 0.5);
			double len, alen;
			VisibilityStatus st = visibility_find(&vg, s, d, &p, &len);
			GridPathStatus ast = gridpath_find(&as, sx, sy, gx, gy, &ap, &alen);
			if (ast == GRIDPATH_BAD_ENDPOINT) {
				TEST_CHECK(st == VISIBILITY_BAD_ENDPOINT);
				continue;
			}
			/* Both see the same connectivity (4-connectivity of the free cells). */
			TEST_CHECK((st == VISIBILITY_NO_PATH) == (ast == GRIDPATH_NO_PATH));
			if (st != VISIBILITY_FOUND)
				continue;
			found++;
			TEST_CHECK(len <= alen + 1e-9);
			TEST_CHECK(len >= hypot(gx - sx, gy - sy) - 1e-9);
			TEST_NEAR(len, brute_length(&g, s, d), 1e-9);
			TEST_NEAR(path_length(&p), len, 1e-9);
			TEST_CHECK(p.pts[0].x == s.x && p.pts[0].y == s.y);
			TEST_CHECK(p.pts[p.count - 1].x == d.x && p.pts[p.count - 1].y == d.y);
			for (int i = 1; i < p.count; i++)
				TEST_CHECK(visibility_segment_free(&g, p.pts[i - 1], p.pts[i]));
			TEST_CHECK(visibility_path_free(&g, &p));
			/* Every step of the grid A* path is free by the same test. */
			for (int i = 1; i < ap.count; i++)
				TEST_CHECK(visibility_segment_free(&g, ap.pts[i - 1], ap.pts[i]));
			TEST_CHECK(visibility_path_free(&g, &ap));
		}
		gridpath_free(&as);
		visibility_free(&vg);
		grid_free(&g);
	}
	TEST_CHECK(found > 300);
	path_free(&p);
	path_free(&ap);
}

/* The graph's edges are exactly the pairs of corners whose segment is free and
 * tangent at both ends (visibility.h), found here by testing every pair: the
 * oracle for the sweep that builds the graph. */
TEST_CASE(visibility_edges_equal_all_pairs)
{
	int64_t total = 0;
	for (int trial = 0; trial < 120; trial++) {
		Grid g;
		int w = 2 + (int)(rng_next() % 30), h = 2 + (int)(rng_next() % 30);
		random_grid(&g, w, h, 2 + (int)(rng_next() % 40));
		VisibilityGraph vg;
		TEST_CHECK(visibility_init(&vg, &g, VISIBILITY_MAX_VERTICES) == VISIBILITY_FOUND);
		int64_t want = 0;
		for (int32_t i = 0; i < vg.count; i++) {
			int32_t k = vg.first[i];
			for (int32_t j = 0; j < vg.count; j++) {
				if (j == i)
					continue;
				double dx = vg.x[j] - vg.x[i], dy = vg.y[j] - vg.y[i];
				bool into_j = dx * vg.qx[j] > 0 && dy * vg.qy[j] > 0;
				bool into_i = -dx * vg.qx[i] > 0 && -dy * vg.qy[i] > 0;
				bool edge = !into_j && !into_i &&
				            visibility_segment_free(&g, vec2(vg.x[i], vg.y[i]),
				                                    vec2(vg.x[j], vg.y[j]));
				/* Rows are sorted: the next neighbour of i is j exactly when edge.
				 */
				bool listed = k < vg.first[i + 1] && vg.adj[k] == j;
				if (edge != listed)
					fprintf(stderr,
					        "  %dx%d: corners (%d,%d)-(%d,%d): pair test %d, "
					        "graph %d\n",
					        w, h, (int)vg.x[i], (int)vg.y[i], (int)vg.x[j],
					        (int)vg.y[j], edge, listed);
				TEST_CHECK(edge == listed);
				k += listed;
				want += edge;
			}
			TEST_CHECK(k == vg.first[i + 1]);
		}
		TEST_CHECK(want == 2 * vg.edges);
		total += want;
		visibility_free(&vg);
		grid_free(&g);
	}
	TEST_CHECK(total > 10000);
}

int main(void)
{
	TEST_RUN(segment_test_agrees_with_sampling);
	TEST_RUN(segment_test_by_hand);
	TEST_RUN(visibility_around_one_block_by_hand);
	TEST_RUN(visibility_between_bounds_and_equal_to_brute_force);
	TEST_RUN(visibility_edges_equal_all_pairs);
	return TEST_EXIT();
}
