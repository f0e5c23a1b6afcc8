/* test_shape.c - naming objects by shape (shape.h): the projections of hand-drawn
 * squares, bricks, L-shapes and triangles, on and off the grid, and rotated. */
#include <string.h>

#include "test.h"
#include "utak/base/geom.h"
#include "utak/mind/shape.h"

static uint8_t mask[64 * 64];
static int32_t mx0, my0, mx1, my1;

static void span(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	(void)ctx;
	for (int32_t x = x0; x <= x1; x++)
		mask[y * 64 + x] = 1;
	mx0 = x0 < mx0 ? x0 : mx0;
	mx1 = x1 > mx1 ? x1 : mx1;
	my0 = y < my0 ? y : my0;
	my1 = y > my1 ? y : my1;
}

/* classify(p): projects p and classifies the squares within their rectangle. */
static Shape classify(int n, const double *xy, double dx, double dy)
{
	Polygon p = {.count = n};
	for (int i = 0; i < n; i++)
		p.v[i] = vec2(xy[2 * i] + dx, xy[2 * i + 1] + dy);
	memset(mask, 0, sizeof mask);
	mx0 = my0 = 64;
	mx1 = my1 = -1;
	geom_project(&p, 64, 64, span, NULL);
	static uint8_t box[64 * 64];
	int32_t w = mx1 - mx0 + 1, h = my1 - my0 + 1;
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++)
			box[y * w + x] = mask[(y + my0) * 64 + x + mx0];
	return shape_classify(box, w, h);
}

TEST_CASE(shapes_of_the_worlds)
{
	static const double square[] = {6, 20, 10, 20, 10, 24, 6, 24};
	static const double brick[] = {24, 19, 33, 19, 33, 22, 24, 22};
	static const double lshape[] = {8, 4, 11, 4, 11, 8, 17, 8, 17, 11, 8, 11};
	static const double pen_l[] = {38, 18, 41, 18, 41, 21, 46, 21, 46, 24, 38, 24};
	static const double triangle[] = {44.5 - 30, 18.2, 52.3 - 30, 20.1, 46.1 - 30, 25.7};
	static const double right_tri[] = {8, 17, 14, 17, 10, 23};
	/* On the grid and shifted off it by fractions of a square. */
	for (int k = 0; k < 4; k++) {
		double dx = 0.25 * k, dy = 0.3 * k;
		TEST_CHECK(classify(4, square, dx, dy) == SHAPE_SQUARE);
		TEST_CHECK(classify(4, brick, dx, dy) == SHAPE_BRICK);
		TEST_CHECK(classify(6, lshape, dx, dy) == SHAPE_LSHAPE);
		TEST_CHECK(classify(6, pen_l, dx, dy) == SHAPE_LSHAPE);
		TEST_CHECK(classify(3, triangle, dx, dy) == SHAPE_TRIANGLE);
		TEST_CHECK(classify(3, right_tri, dx, dy) == SHAPE_TRIANGLE);
	}
}

TEST_CASE(rectangles_by_aspect)
{
	uint8_t full[12 * 12];
	memset(full, 1, sizeof full);
	TEST_CHECK(shape_classify(full, 5, 5) == SHAPE_SQUARE);
	TEST_CHECK(shape_classify(full, 5, 4) == SHAPE_SQUARE);
	TEST_CHECK(shape_classify(full, 9, 3) == SHAPE_BRICK);
	TEST_CHECK(shape_classify(full, 3, 9) == SHAPE_BRICK);
	TEST_CHECK(shape_classify(full, 0, 3) == SHAPE_NONE);
	uint8_t none[16] = {0};
	TEST_CHECK(shape_classify(none, 4, 4) == SHAPE_NONE);
	/* A ring (a rectangle with a hole in the middle) is no L. */
	uint8_t ring[25];
	memset(ring, 1, sizeof ring);
	ring[12] = 0;
	TEST_CHECK(shape_classify(ring, 5, 5) == SHAPE_SQUARE); /* 24 of 25: a square seen coarsely */
	uint8_t plus[25] = {0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 1, 1, 1, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0};
	TEST_CHECK(shape_classify(plus, 5, 5) == SHAPE_NONE);
}

/* Squares given as coordinates (a held object's offsets from Utak: negative, in no
 * order): a 4 x 4 block is a square, 4 x 2 a brick, the 4 x 4 block less a 2 x 2
 * corner an L, and nothing is no shape. */
TEST_CASE(shape_of_coordinates)
{
	int32_t x[16], y[16], n = 0;
	for (int32_t j = 0; j < 16; j++) {
		x[n] = -1 - (j * 3) % 4; /* every column once per row, shuffled */
		y[n++] = -(j / 4);
	}
	TEST_CHECK(shape_of_squares(x, y, 16) == SHAPE_SQUARE);
	TEST_CHECK(shape_of_squares(x, y, 8) == SHAPE_BRICK); /* the first two rows */
	n = 0;
	for (int32_t j = 0; j < 16; j++)
		if (!(x[j] <= -3 && y[j] <= -2)) { /* drop the 2 x 2 at one corner */
			x[n] = x[j];
			y[n++] = y[j];
		}
	TEST_CHECK(n == 12);
	TEST_CHECK(shape_of_squares(x, y, n) == SHAPE_LSHAPE);
	TEST_CHECK(shape_of_squares(x, y, 0) == SHAPE_NONE);
}

int main(void)
{
	TEST_RUN(shapes_of_the_worlds);
	TEST_RUN(rectangles_by_aspect);
	TEST_RUN(shape_of_coordinates);
	return TEST_EXIT();
}
