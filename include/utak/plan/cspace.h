/* cspace.h - configuration-space obstacles on the grid: where a moved object fits
 * (paper 3.6 and 5: "a moved object needs room"; the planner moves a shape, not a
 * point, and the paper's open problem of the L-shaped object in a doorway).
 *
 * A shape is translated over the grid with its REFERENCE POINT (the origin of its
 * coordinates) at a cell's centre. Cell c is free in the configuration-space grid
 * when the shape so placed covers only free cells; it covers a cell when the cell's
 * open square meets the closed shape (the digital representation of utak(5) and
 * geom.h: touching a square along its border does not cover it). Cells outside the
 * grid count as blocked. This is the Minkowski sum of the blocked cells with the
 * reflected shape (Lozano-Perez 1983, "Spatial planning: a configuration space
 * approach"), sampled at the cell centres: a point planner (gridpath.h, the
 * skeleton) on the eroded grid plans for the shape.
 *
 * Because every cell centre sits at the same place inside its cell, the covered
 * cells are the same set of offsets for every c: the FOOTPRINT, computed once, kept
 * as row runs. Erosion is then, per run, a range test on per-row prefix sums of
 * blocked cells: O(w h R) for R runs (R is the footprint's height for a convex
 * shape), independent of the shape's width.
 *
 * ROTATION (a later issue: x, y, theta): rotate the shape about its reference point
 * with geom_rotate and call cspace_erode once per sampled angle; each call gives one
 * layer of the (x, y, theta) configuration grid. Note that the shape's footprint
 * need not hold the reference cell itself, if the shape does not cover its own
 * reference point; such a c may be free in the result while blocked in the input.
 *
 * Memory: the caller owns both grids; out must have in's size. The erosion allocates
 * (w + 1) h int32_t of prefix sums for the call. */
#ifndef UTAK_CSPACE_H
#define UTAK_CSPACE_H

#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/plan/grid.h"

/* Cells x + dx0 .. x + dx1 (inclusive) of row y + dy, for a shape at cell (x, y). */
typedef struct CSpaceRun {
	int32_t dy, dx0, dx1;
} CSpaceRun;

/* The cells a shape covers, as offsets from its reference cell; runs sorted by dy,
 * then dx0, not overlapping. */
typedef struct CSpaceFootprint {
	int count, cap;
	CSpaceRun *run;
} CSpaceFootprint;

void cspace_footprint_init(CSpaceFootprint *fp);
void cspace_footprint_free(CSpaceFootprint *fp);
/* cspace_footprint_polygon(fp, shape): the footprint of shape (a simple polygon in
 * grid units around its reference point, the origin). */
void cspace_footprint_polygon(CSpaceFootprint *fp, const Polygon *shape);
/* cspace_footprint_disc(fp, radius): the footprint of the closed disc of that radius
 * (>= 0) about the reference point: a clearance. */
void cspace_footprint_disc(CSpaceFootprint *fp, double radius);

/* cspace_erode_footprint(in, fp, out): out = the cells where fp fits in in's free
 * space (see above). out has in's size and may not be in. */
void cspace_erode_footprint(const Grid *in, const CSpaceFootprint *fp, Grid *out);
/* cspace_erode(in, shape, out): the same for a polygon. */
void cspace_erode(const Grid *in, const Polygon *shape_at_origin, Grid *out);
/* cspace_erode_disc(in, radius, out): the same for a disc: the cells whose centre has
 * clearance radius from every blocked cell's open square and the grid's outside. */
void cspace_erode_disc(const Grid *in, double radius, Grid *out);

#endif
