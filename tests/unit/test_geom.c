/* test_geom.c - polygons and their projection onto squares (geom.h; paper 2.1).
 *
 * Hand-computed cases, and the independent oracle of oracle.h, which decides
 * square by square what geom.c decides row by row. */
#include <stdlib.h>
#include <string.h>

#include "projection_oracle.h"
#include "test.h"
#include "utak/base/geom.h"

enum { W = 24, H = 20 };

static uint8_t grid[H][W];

static void span_mark(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	int *count = ctx;
	for (int32_t x = x0; x <= x1; x++) {
		TEST_CHECK(grid[y][x] == 0); /* spans never overlap */
		grid[y][x] = 1;
		++*count;
	}
}

static int project(const Polygon *p, bool outside)
{
	memset(grid, 0, sizeof grid);
	int count = 0;
	if (outside)
		geom_project_outside(p, W, H, span_mark, &count);
	else
		geom_project(p, W, H, span_mark, &count);
	return count;
}

static Polygon poly(int n, const double *xy)
{
	Polygon p = {.count = n};
	for (int i = 0; i < n; i++)
		p.v[i] = vec2(xy[2 * i], xy[2 * i + 1]);
	return p;
}

static void check_against_oracle(const Polygon *p)
{
	project(p, false);
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++)
			TEST_CHECK(grid[y][x] == oracle(p, x, y));
	project(p, true);
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++)
			TEST_CHECK(grid[y][x] == oracle_outside(p, x, y));
}

TEST_CASE(axis_aligned_square_claims_16)
{
	Polygon p = poly(4, (double[]){10, 10, 14, 10, 14, 14, 10, 14});
	TEST_CHECK(project(&p, false) == 16);
	for (int y = 10; y < 14; y++)
		for (int x = 10; x < 14; x++)
			TEST_CHECK(grid[y][x] == 1);
	/* Clockwise winding claims the same squares. */
	Polygon q = poly(4, (double[]){10, 10, 10, 14, 14, 14, 14, 10});
	TEST_CHECK(project(&q, false) == 16);
}

TEST_CASE(half_offset_square_claims_25)
{
	/* (10.5,10.5)-(14.5,14.5): edges cut through squares 10 and 14: 5 x 5. */
	Polygon p = poly(4, (double[]){10.5, 10.5, 14.5, 10.5, 14.5, 14.5, 10.5, 14.5});
	TEST_CHECK(project(&p, false) == 25);
	TEST_CHECK(grid[10][10] && grid[14][14] && !grid[15][15] && !grid[9][10]);
}

TEST_CASE(triangle_by_hand)
{
	/* Right triangle (2,2) (6,2) (2,6): square (x, y) has interior points with
	 * px + py just above x + y, so it meets the triangle (px + py <= 8) exactly
	 * when x + y < 8. With x, y >= 2 that is 4 + 3 + 2 + 1 = 10 squares; the
	 * hypotenuse runs along the diagonals of the 4 squares with x + y = 7. */
	Polygon p = poly(3, (double[]){2, 2, 6, 2, 2, 6});
	TEST_CHECK(project(&p, false) == 10);
	TEST_CHECK(grid[2][2] && grid[2][5] && grid[5][2] && grid[3][3] && !grid[4][4] && !grid[3][5]);
	check_against_oracle(&p);
}

TEST_CASE(vertex_on_grid_line)
{
	/* A diamond with vertices on grid lines: centre (8,8), radius 2. Its edges
	 * run along square diagonals: the 8 squares they cross plus the 4 around the
	 * centre... the diamond |x-8| + |y-8| <= 2 meets 12 squares' interiors. */
	Polygon p = poly(4, (double[]){8, 6, 10, 8, 8, 10, 6, 8});
	TEST_CHECK(project(&p, false) == 12);
	check_against_oracle(&p);
}

TEST_CASE(thin_sliver)
{
	/* A sliver 0.01 thick lying inside row 5 claims the 6 squares it spans. */
	Polygon p = poly(4, (double[]){3.2, 5.5, 8.7, 5.5, 8.7, 5.51, 3.2, 5.51});
	TEST_CHECK(project(&p, false) == 6);
	for (int x = 3; x <= 8; x++)
		TEST_CHECK(grid[5][x]);
	/* The same sliver lying exactly on the grid line y = 5 still has area
	 * above the line: it claims row 5 only, not row 4. */
	Polygon q = poly(4, (double[]){3.2, 5, 8.7, 5, 8.7, 5.01, 3.2, 5.01});
	TEST_CHECK(project(&q, false) == 6);
	TEST_CHECK(!grid[4][5] && grid[5][5]);
	/* A slanted needle crossing many squares. */
	Polygon r = poly(3, (double[]){1.1, 1.3, 20.7, 17.9, 20.71, 17.8});
	check_against_oracle(&r);
}

TEST_CASE(verge_ring_default)
{
	/* The default verge of a W x H TABLE: the outermost ring of squares. */
	Polygon p = poly(4, (double[]){1, 1, W - 1, 1, W - 1, H - 1, 1, H - 1});
	TEST_CHECK(project(&p, true) == 2 * W + 2 * (H - 2));
	TEST_CHECK(grid[0][0] && grid[H - 1][W - 1] && !grid[1][1] && grid[5][0] && !grid[5][1]);
}

TEST_CASE(random_polygons_match_oracle)
{
	srand(12345);
	for (int trial = 0; trial < 400; trial++) {
		/* A star-shaped polygon around a random centre: always simple. */
		Polygon p = {.count = 3 + rand() % 10};
		double cx = 4 + rand() % 16, cy = 4 + rand() % 12;
		if (trial % 2)
			cx += (rand() % 8) * 0.125, cy += (rand() % 8) * 0.125; /* grid-aligned often */
		for (int i = 0; i < p.count; i++) {
			double a = 2 * 3.14159265358979 * (i + (rand() % 100) / 200.0) / p.count;
			double r = 0.3 + (rand() % 60) / 10.0;
			p.v[i] = vec2(cx + r * cos(a), cy + r * sin(a));
			if (trial % 3 == 0)
				p.v[i] = vec2(round(p.v[i].x * 2) / 2, round(p.v[i].y * 2) / 2);
		}
		if (!geom_polygon_is_simple(&p))
			continue;
		check_against_oracle(&p);
	}
}

TEST_CASE(simple_polygon_test)
{
	Polygon bowtie = poly(4, (double[]){0, 0, 4, 4, 4, 0, 0, 4});
	TEST_CHECK(!geom_polygon_is_simple(&bowtie));
	Polygon l = poly(6, (double[]){8, 4, 11, 4, 11, 8, 17, 8, 17, 11, 8, 11});
	TEST_CHECK(geom_polygon_is_simple(&l));
	Polygon flat = poly(3, (double[]){0, 0, 2, 0, 4, 0});
	TEST_CHECK(!geom_polygon_is_simple(&flat));
	Polygon spike = poly(4, (double[]){0, 0, 4, 0, 4, 4, 4, 2}); /* folds back along x = 4 */
	TEST_CHECK(!geom_polygon_is_simple(&spike));
	Polygon dup = poly(4, (double[]){0, 0, 4, 0, 4, 0, 0, 4});
	TEST_CHECK(!geom_polygon_is_simple(&dup));
	TEST_NEAR(geom_polygon_area(&l), 3 * 4 + 9 * 3, 1e-12);
}

TEST_CASE(quarter_turns_are_exact)
{
	double c, s;
	geom_cos_sin(90, &c, &s);
	TEST_CHECK(c == 0 && s == 1);
	geom_cos_sin(-90, &c, &s);
	TEST_CHECK(c == 0 && s == -1);
	geom_cos_sin(540, &c, &s);
	TEST_CHECK(c == -1 && s == 0);
	Vec2 q = geom_rotate(vec2(13, 10), vec2(10.5, 10.5), 0, 1);
	TEST_CHECK(q.x == 11 && q.y == 13);
}

int main(void)
{
	TEST_RUN(axis_aligned_square_claims_16);
	TEST_RUN(half_offset_square_claims_25);
	TEST_RUN(triangle_by_hand);
	TEST_RUN(vertex_on_grid_line);
	TEST_RUN(thin_sliver);
	TEST_RUN(verge_ring_default);
	TEST_RUN(random_polygons_match_oracle);
	TEST_RUN(simple_polygon_test);
	TEST_RUN(quarter_turns_are_exact);
	return TEST_EXIT();
}
