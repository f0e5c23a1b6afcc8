/* shape.c - naming an object by its shape (paper 2.3: "the square", "the brick", "the
 * L-shaped object"). CONTROLLER SIDE, and used by the judge on the real world.
 *
 * ALGORITHM. On the squares an object covers, within their containing rectangle:
 * the fill ratio separates rectangles from the rest; the aspect ratio separates
 * squares from bricks; an L-shape is a rectangle with one rectangular notch taken
 * from a corner, so the empty squares of its containing rectangle form one block
 * that touches two adjacent sides and fills its own containing rectangle; a
 * triangle leaves its empty squares in at most three slanted pieces, beyond its
 * sides. COMPLEXITY: O(w h). */
#include "utak/mind/shape.h"

#include <stdbool.h>
#include <stdlib.h>

#include "utak/base/util.h"

/* empty_pieces(mask, w, h): the number of 4-connected pieces of empty squares. */
static int32_t empty_pieces(const uint8_t *mask, int32_t w, int32_t h)
{
	int64_t n = (int64_t)w * h;
	uint8_t *seen = util_alloc((size_t)n, 1);
	int64_t *stack = util_alloc((size_t)n, sizeof *stack);
	int32_t pieces = 0;
	for (int64_t start = 0; start < n; start++) {
		if (mask[start] || seen[start])
			continue;
		pieces++;
		int64_t top = 0;
		stack[top++] = start;
		seen[start] = 1;
		while (top > 0) {
			int64_t i = stack[--top];
			int32_t x = (int32_t)(i % w), y = (int32_t)(i / w);
			const int64_t next[4] = {x > 0 ? i - 1 : -1, x < w - 1 ? i + 1 : -1, y > 0 ? i - w : -1,
						 y < h - 1 ? i + w : -1};
			for (int k = 0; k < 4; k++)
				if (next[k] >= 0 && !mask[next[k]] && !seen[next[k]]) {
					seen[next[k]] = 1;
					stack[top++] = next[k];
				}
		}
	}
	free(seen);
	free(stack);
	return pieces;
}

Shape shape_classify(const uint8_t *mask, int32_t w, int32_t h)
{
	if (w <= 0 || h <= 0)
		return SHAPE_NONE;
	int64_t full = 0, empty = 0;
	int32_t ex0 = w, ey0 = h, ex1 = -1, ey1 = -1; /* box of the empty squares */
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++) {
			if (mask[(int64_t)y * w + x]) {
				full++;
				continue;
			}
			empty++;
			ex0 = x < ex0 ? x : ex0;
			ey0 = y < ey0 ? y : ey0;
			ex1 = x > ex1 ? x : ex1;
			ey1 = y > ey1 ? y : ey1;
		}
	double area = (double)w * h, fill = full / area;
	if (fill >= SHAPE_RECT_FILL) {
		double aspect = w > h ? (double)w / h : (double)h / w;
		return aspect <= SHAPE_SQUARE_ASPECT ? SHAPE_SQUARE : SHAPE_BRICK;
	}
	if (full == 0)
		return SHAPE_NONE;
	/* One notch at a corner: the empty squares' box touches a vertical and a
	 * horizontal side of the rectangle, is nearly all empty, and is smaller than
	 * the rectangle both ways (so the shape keeps an arm along each side). */
	int64_t box = (int64_t)(ex1 - ex0 + 1) * (ey1 - ey0 + 1);
	bool at_x_side = ex0 == 0 || ex1 == w - 1, at_y_side = ey0 == 0 || ey1 == h - 1;
	bool smaller = ex1 - ex0 + 1 < w && ey1 - ey0 + 1 < h;
	if (at_x_side && at_y_side && smaller && empty >= SHAPE_RECT_FILL * (double)box)
		return SHAPE_LSHAPE;
	/* A triangle's empty squares lie beyond its three sides: at most three pieces
	 * (a plus sign, say, leaves four). */
	if (fill >= 0.25 && fill <= 0.75 && empty_pieces(mask, w, h) <= 3)
		return SHAPE_TRIANGLE;
	return SHAPE_NONE;
}

Shape shape_of_squares(const int32_t *x, const int32_t *y, int32_t n)
{
	if (n <= 0)
		return SHAPE_NONE;
	int32_t x0 = x[0], y0 = y[0], x1 = x[0], y1 = y[0];
	for (int32_t i = 1; i < n; i++) {
		x0 = x[i] < x0 ? x[i] : x0;
		y0 = y[i] < y0 ? y[i] : y0;
		x1 = x[i] > x1 ? x[i] : x1;
		y1 = y[i] > y1 ? y[i] : y1;
	}
	int32_t w = x1 - x0 + 1, h = y1 - y0 + 1;
	uint8_t *mask = util_alloc((size_t)w * (size_t)h, 1);
	for (int32_t i = 0; i < n; i++)
		mask[(int64_t)(y[i] - y0) * w + (x[i] - x0)] = 1;
	Shape s = shape_classify(mask, w, h);
	free(mask);
	return s;
}
