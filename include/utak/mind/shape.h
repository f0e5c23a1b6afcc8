/* shape.h - naming an object by its shape: square, brick, L-shape, triangle (paper 2.3).
 *
 * The tasks name objects by shape ("the square", "the brick", "the L-shaped
 * object"). The controller names the objects of its world model, and the judge
 * the objects of the real world, by the same rule applied to the squares an
 * object covers, so that both mean the same thing by "the square". */
#ifndef UTAK_SHAPE_H
#define UTAK_SHAPE_H

#include <stdint.h>

#include "utak/base/task.h"

/* A rectangle is a shape that fills at least this share of its containing
 * rectangle (digitisation rounds corners up, never down, so a true rectangle
 * fills all of it; 0.85 leaves room for a square's corner seen coarsely). */
#define SHAPE_RECT_FILL 0.85
/* A rectangle whose long side is at most this many times its short side is a
 * square: a 4 x 4 square off the grid covers 5 x 5 squares, or 5 x 4 (1.25). */
#define SHAPE_SQUARE_ASPECT 1.3

/* shape_classify(mask, w, h): the shape of the set of squares mask[y * w + x] != 0
 * within a w x h containing rectangle (the set touches all four sides of it):
 *   square, brick    - fills the rectangle; by aspect ratio;
 *   lshape           - the rectangle less one smaller rectangle at one corner;
 *   triangle         - fills between a quarter and three quarters of it otherwise;
 *   SHAPE_NONE       - anything else. */
Shape shape_classify(const uint8_t *mask, int32_t w, int32_t h);

/* shape_of_squares(x, y, n): shape_classify of the n distinct squares (x[i], y[i]),
 * in their containing rectangle; SHAPE_NONE when n is 0. */
Shape shape_of_squares(const int32_t *x, const int32_t *y, int32_t n);

#endif
