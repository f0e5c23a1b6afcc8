/* test_rope.c - rope-tightening (rope.h, paper 5) against independent checks: the
 * result is free (the line test on every segment), no longer than the input, keeps
 * the end points, is no shorter than the any-angle optimum, is a fixed point, keeps
 * the homotopy class (winding number around an obstacle), and equals the visibility
 * optimum of the grid cut on the other side of the obstacle (the shortest path of
 * that class) or a hand-computed length. */
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "utak/plan/gridpath.h"
#include "utak/plan/rope.h"
#include "utak/plan/visibility.h"

static uint32_t rng_state = 88172645u;
static uint32_t rng_next(void)
{
	rng_state ^= rng_state << 13;
	rng_state ^= rng_state >> 17;
	rng_state ^= rng_state << 5;
	return rng_state;
}

static void block(Grid *g, int x0, int y0, int x1, int y1)
{
	for (int y = y0; y < y1; y++)
		for (int x = x0; x < x1; x++)
			g->cells[y * g->w + x] = GRID_BLOCKED;
}

/* winding(loop, c): how many times the closed polygon (in, then out reversed) turns
 * counter-clockwise around c, by summing signed angles (c is never on the polygon). */
static int winding(const Path *in, const Path *out, Vec2 c)
{
	double total = 0;
	int n = in->count + out->count;
	for (int i = 0; i < n; i++) {
		int j = (i + 1) % n;
		Vec2 a = i < in->count ? in->pts[i] : out->pts[out->count - 1 - (i - in->count)];
		Vec2 b = j < in->count ? in->pts[j] : out->pts[out->count - 1 - (j - in->count)];
		Vec2 u = vec2_sub(a, c), v = vec2_sub(b, c);
		total += atan2(vec2_cross(u, v), vec2_dot(u, v));
	}
	return (int)lround(total / (2 * acos(-1.0)));
}

/* check_tight: the properties every result has. */
static void check_tight(const Grid *g, const Path *in, const Path *out)
{
	TEST_CHECK(out->count >= 1);
	TEST_CHECK(visibility_path_free(g, out));
	TEST_CHECK(path_length(out) <= path_length(in) + 1e-9);
	TEST_CHECK(out->pts[0].x == in->pts[0].x && out->pts[0].y == in->pts[0].y);
	TEST_CHECK(out->pts[out->count - 1].x == in->pts[in->count - 1].x &&
	           out->pts[out->count - 1].y == in->pts[in->count - 1].y);
	/* Interior vertices are lattice points. */
	for (int i = 1; i + 1 < out->count; i++)
		TEST_CHECK(out->pts[i].x == floor(out->pts[i].x) &&
		           out->pts[i].y == floor(out->pts[i].y));
	/* A fixed point: tightening again changes nothing. */
	Path again;
	path_init(&again);
	TEST_CHECK(rope_tighten(g, out, &again) == ROPE_OK);
	TEST_NEAR(path_length(&again), path_length(out), 1e-9);
	path_free(&again);
}

TEST_CASE(rope_around_one_block_keeps_its_side)
{
	/* A 4 x 4 block, x and y in [4, 8), in a 12 x 12 grid; S below, D above. */
	Grid g;
	grid_init(&g, 12, 12, GRID_FREE);
	block(&g, 4, 4, 8, 8);
	Path left, right, out;
	path_init(&left);
	path_init(&right);
	path_init(&out);
	Vec2 pts_left[] = {{6.5, 1.5}, {2.5, 2.5}, {1.5, 6}, {2.5, 9.5}, {6.5, 10.5}};
	Vec2 pts_right[] = {{6.5, 1.5}, {10.5, 1.5}, {10.5, 10.5}, {6.5, 10.5}};
	for (int i = 0; i < 5; i++)
		path_push(&left, pts_left[i]);
	for (int i = 0; i < 4; i++)
		path_push(&right, pts_right[i]);
	/* Left: via the corners (4, 4) and (4, 8), 2.5 sqrt 2 + 4 + 2.5 sqrt 2; right:
	 * via (8, 4) and (8, 8), 1.5 across and 2.5 up at each end. */
	TEST_CHECK(rope_tighten(&g, &left, &out) == ROPE_OK);
	check_tight(&g, &left, &out);
	TEST_NEAR(path_length(&out), 4 + 5 * sqrt(2.0), 1e-12);
	TEST_CHECK(out.count == 4 && out.pts[1].x == 4 && out.pts[2].x == 4);
	TEST_CHECK(winding(&left, &out, vec2(6, 6)) == 0);
	TEST_CHECK(rope_tighten(&g, &right, &out) == ROPE_OK);
	check_tight(&g, &right, &out);
	TEST_NEAR(path_length(&out), 4 + 2 * sqrt(1.5 * 1.5 + 2.5 * 2.5), 1e-12);
	TEST_CHECK(out.count == 4 && out.pts[1].x == 8 && out.pts[2].x == 8);
	TEST_CHECK(winding(&right, &out, vec2(6, 6)) == 0);
	/* Once round the block anticlockwise, then up the right: the rope keeps the
	 * extra turn. */
	Path loop;
	path_init(&loop);
	Vec2 pts_loop[] = {{6.5, 1.5}, {10.5, 2.5}, {10.5, 10.5}, {1.5, 10.5},
	                   {1.5, 1.5}, {10.5, 1.5}, {10.5, 9.5},  {6.5, 10.5}};
	for (int i = 0; i < 8; i++)
		path_push(&loop, pts_loop[i]);
	TEST_CHECK(rope_tighten(&g, &loop, &out) == ROPE_OK);
	check_tight(&g, &loop, &out);
	TEST_CHECK(winding(&loop, &out, vec2(6, 6)) == 0);
	TEST_CHECK(path_length(&out) > 16); /* at least once round the 4 x 4 block */
	/* Bad input: through the block. */
	Path through;
	path_init(&through);
	path_push(&through, vec2(6.5, 1.5));
	path_push(&through, vec2(6.5, 10.5));
	TEST_CHECK(rope_tighten(&g, &through, &out) == ROPE_BAD_INPUT);
	TEST_CHECK(out.count == 0);
	path_free(&through);
	path_free(&loop);
	path_free(&left);
	path_free(&right);
	path_free(&out);
	grid_free(&g);
}

/* random_walk(g, sx, sy, steps, p): a wandering path of free cell centres by legal
 * 8-connected steps (gridpath.h's rule), which may loop and double back. */
static void random_walk(const Grid *g, int sx, int sy, int steps, Path *p)
{
	path_clear(p);
	int x = sx, y = sy;
	path_push(p, vec2(x + 0.5, y + 0.5));
	for (int i = 0; i < steps; i++) {
		int dx = (int)(rng_next() % 3) - 1, dy = (int)(rng_next() % 3) - 1;
		if (!grid_free_at(g, x + dx, y + dy) || !grid_free_at(g, x + dx, y) ||
		    !grid_free_at(g, x, y + dy))
			continue;
		x += dx;
		y += dy;
		path_push(p, vec2(x + 0.5, y + 0.5));
	}
}

TEST_CASE(rope_single_obstacle_reaches_the_optimum_of_its_class)
{
	Path in, out, vis;
	path_init(&in);
	path_init(&out);
	path_init(&vis);
	int compared = 0;
	for (int trial = 0; trial < 300; trial++) {
		int w = 8 + (int)(rng_next() % 12), h = 8 + (int)(rng_next() % 12);
		int bx0 = 2 + (int)(rng_next() % (uint32_t)(w - 5));
		int by0 = 2 + (int)(rng_next() % (uint32_t)(h - 5));
		int bx1 = bx0 + 1 + (int)(rng_next() % (uint32_t)(w - 3 - bx0));
		int by1 = by0 + 1 + (int)(rng_next() % (uint32_t)(h - 3 - by0));
		Grid g;
		grid_init(&g, w, h, GRID_FREE);
		block(&g, bx0, by0, bx1, by1);
		Vec2 centre = vec2(0.5 * (bx0 + bx1), 0.5 * (by0 + by1));
		/* S below the block, D above it. */
		int sx = (int)(rng_next() % (uint32_t)w), sy = (int)(rng_next() % (uint32_t)by0);
		int gx = (int)(rng_next() % (uint32_t)w);
		int gy = by1 + (int)(rng_next() % (uint32_t)(h - by1));
		if (trial % 2 == 0) {
			GridPathSearch as;
			gridpath_init(&as, &g);
			double len;
			TEST_CHECK(gridpath_find(&as, sx, sy, gx, gy, &in, &len) == GRIDPATH_FOUND);
			gridpath_free(&as);
		} else {
			/* A random walk, then straight on to D by A*: it may loop round. */
			random_walk(&g, sx, sy, 40 + (int)(rng_next() % 200), &in);
			Vec2 end = in.pts[in.count - 1];
			GridPathSearch as;
			gridpath_init(&as, &g);
			Path rest;
			path_init(&rest);
			double len;
			TEST_CHECK(gridpath_find(&as, (int)end.x, (int)end.y, gx, gy, &rest,
			                         &len) == GRIDPATH_FOUND);
			for (int i = 1; i < rest.count; i++)
				path_push(&in, rest.pts[i]);
			path_free(&rest);
			gridpath_free(&as);
		}
		TEST_CHECK(rope_tighten(&g, &in, &out) == ROPE_OK);
		check_tight(&g, &in, &out);
		TEST_CHECK(winding(&in, &out, centre) == 0);
		VisibilityGraph vg;
		TEST_CHECK(visibility_init(&vg, &g, VISIBILITY_MAX_VERTICES) == VISIBILITY_FOUND);
		double best;
		TEST_CHECK(visibility_find(&vg, in.pts[0], in.pts[in.count - 1], &vis, &best) ==
		           VISIBILITY_FOUND);
		TEST_CHECK(path_length(&out) >= best - 1e-9);
		visibility_free(&vg);
		/* The oracle: wall off one side of the block (its middle row, block to
		 * border); if the input avoids the wall, its class is "the other side", whose
		 * shortest path is the visibility optimum of the walled grid. */
		for (int side = 0; side < 2; side++) {
			Grid cut;
			grid_init(&cut, w, h, GRID_FREE);
			memcpy(cut.cells, g.cells, (size_t)w * h);
			int wy = (by0 + by1) / 2;
			if (side == 0)
				block(&cut, 0, wy, bx0, wy + 1);
			else
				block(&cut, bx1, wy, w, wy + 1);
			if (visibility_path_free(&cut, &in)) {
				TEST_CHECK(visibility_init(&vg, &cut, VISIBILITY_MAX_VERTICES) ==
				           VISIBILITY_FOUND);
				TEST_CHECK(visibility_find(&vg, in.pts[0], in.pts[in.count - 1],
				                           &vis, &best) == VISIBILITY_FOUND);
				TEST_NEAR(path_length(&out), best, 1e-9);
				visibility_free(&vg);
				compared++;
			}
			grid_free(&cut);
		}
		grid_free(&g);
	}
	TEST_CHECK(compared > 150);
	path_free(&in);
	path_free(&out);
	path_free(&vis);
}

TEST_CASE(rope_on_random_grids_is_free_and_never_longer)
{
	Path in, out, vis;
	path_init(&in);
	path_init(&out);
	path_init(&vis);
	int tightened = 0;
	for (int trial = 0; trial < 300; trial++) {
		int w = 4 + (int)(rng_next() % 20), h = 4 + (int)(rng_next() % 20);
		Grid g;
		grid_init(&g, w, h, GRID_FREE);
		int density = (int)(rng_next() % 40);
		for (int i = 0; i < w * h; i++)
			if ((int)(rng_next() % 100) < density)
				g.cells[i] = GRID_BLOCKED;
		int sx = (int)(rng_next() % (uint32_t)w), sy = (int)(rng_next() % (uint32_t)h);
		if (!grid_free_at(&g, sx, sy)) {
			grid_free(&g);
			continue;
		}
		random_walk(&g, sx, sy, 10 + (int)(rng_next() % 300), &in);
		TEST_CHECK(rope_tighten(&g, &in, &out) == ROPE_OK);
		check_tight(&g, &in, &out);
		VisibilityGraph vg;
		TEST_CHECK(visibility_init(&vg, &g, VISIBILITY_MAX_VERTICES) == VISIBILITY_FOUND);
		double best;
		TEST_CHECK(visibility_find(&vg, in.pts[0], in.pts[in.count - 1], &vis, &best) ==
		           VISIBILITY_FOUND);
		TEST_CHECK(path_length(&out) >= best - 1e-9);
		/* Tightening the optimum leaves it as it is. */
		Path again;
		path_init(&again);
		TEST_CHECK(rope_tighten(&g, &vis, &again) == ROPE_OK);
		TEST_NEAR(path_length(&again), best, 1e-9);
		path_free(&again);
		tightened += path_length(&out) < path_length(&in) - 1e-9;
		visibility_free(&vg);
		grid_free(&g);
	}
	TEST_CHECK(tightened > 100);
	path_free(&in);
	path_free(&out);
	path_free(&vis);
}

int main(void)
{
	TEST_RUN(rope_around_one_block_keeps_its_side);
	TEST_RUN(rope_single_obstacle_reaches_the_optimum_of_its_class);
	TEST_RUN(rope_on_random_grids_is_free_and_never_longer);
	return TEST_EXIT();
}
