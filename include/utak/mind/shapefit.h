/* shapefit.h - fitting a shape's model to the squares it covers: rectangles,
 * triangles and L-shapes at any angle, by analysis by synthesis (shape.h). CONTROLLER
 * SIDE: shape.c's helpers; nothing else calls these.
 *
 * A model is a polygon from a few parameters; it FITS a set of squares when its
 * digital representation (geom.h: the squares its interior or edges meet) is the
 * set, or differs from it on a few squares. shapefit.c finds the parameters by
 * descent on a continuous measure of the difference, from starts the set's convex
 * hull gives. Coordinates are in the cells of a ShapeMask. */
#ifndef UTAK_SHAPEFIT_H
#define UTAK_SHAPEFIT_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/base/geom.h"

/* The band of cells weighed when a model is fitted: this many cells either side of
 * the set's boundary. */
#define SHAPE_BAND 1
/* Empty squares round the set, room for a model to reach past it while fitted. */
#define SHAPE_MARGIN 3

/* The set, in a box with a margin of SHAPE_MARGIN empty squares. */
typedef struct ShapeMask {
	int32_t x0, y0, w, h; /* square (x0, y0) is mask cell (0, 0) */
	uint8_t *in;          /* w * h, row-major: 1 in the set */
	int32_t *band;        /* the cells within SHAPE_BAND of a cell of the other kind */
	int32_t band_count;
} ShapeMask;

/* shapefit_mask_at(m, i, j): cell (i, j) is in the set (false outside the box). */
static inline bool shapefit_mask_at(const ShapeMask *m, int32_t i, int32_t j)
{
	return i >= 0 && j >= 0 && i < m->w && j < m->h && m->in[(int64_t)j * m->w + i];
}

/* The minimum-area rectangle: corner o, unit axes u (side a) and v (side b). */
typedef struct Rect {
	double ox, oy, ux, uy, vx, vy, a, b;
} Rect;

/* The models: each an intersection of half-planes, or for the L-shape a rectangle
 * less a quadrant at one corner. A side is a line n . (p - at) = offset, its
 * normal n = (cos angle, sin angle) pointing out. */
enum { FIT_RECT, FIT_TRIANGLE, FIT_LSHAPE, FIT_KINDS };

typedef struct FitSide {
	double angle, offset; /* radians; squares */
	Vec2 at;              /* the point the offset is measured from */
} FitSide;

typedef struct FitModel {
	int kind;
	int corner;        /* FIT_LSHAPE: the notch is at the corner of sides corner, corner+1 */
	FitSide side[4];   /* rectangle, L: side k's normal at side[0].angle + k quarter
	                      turns, all measured from side[0].at; triangle: three sides */
	double notch[2];   /* FIT_LSHAPE: how deep the notch cuts in from those two sides */
} FitModel;

/* shapefit_rect_along(h, n, ux, uy): the rectangle enclosing the n points h with
 * sides along the unit vector (ux, uy) and across it. */
Rect shapefit_rect_along(const Vec2 *h, int32_t n, double ux, double uy);
/* shapefit_largest_triangle(h, n, best): the area of the largest triangle on three
 * of the convex polygon h's vertices, and in best[] their indices. */
double shapefit_largest_triangle(const Vec2 *h, int32_t n, int32_t best[3]);
/* shapefit_box_start(m, r, kind, f): a rectangle model (kind FIT_RECT) on rectangle
 * r, or an L-shape (FIT_LSHAPE) in r with its notch at r's emptiest corner; false
 * for an L-shape when no corner of r is empty. */
bool shapefit_box_start(const ShapeMask *m, const Rect *r, int kind, FitModel *f);
/* shapefit_box(m, h, n, kind, f): a rectangle or L-shape fitted to the set, from the
 * rectangles enclosing the hull h (n points) at every angle; the cost reached (0:
 * the model explains the set; INFINITY: none could be started). */
double shapefit_box(const ShapeMask *m, const Vec2 *h, int32_t n, int kind, FitModel *f);
/* shapefit_triangle(m, h, n, f): a triangle fitted to the set, from the largest on
 * the vertices of hull h; the cost reached. */
double shapefit_triangle(const ShapeMask *m, const Vec2 *h, int32_t n, FitModel *f);
/* shapefit_error(m, squares, f): the squares on which the model's digital
 * representation and the set (of `squares` squares) differ; INT32_MAX when the
 * model makes no polygon. */
int32_t shapefit_error(const ShapeMask *m, int32_t squares, const FitModel *f);

#endif
