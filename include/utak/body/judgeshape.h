/* judgeshape.h - the judge's name for an object's shape, from its TRUE polygon by
 * exact geometry (doc/verdicts.md "Objects and their shapes"; paper 2.3's tasks
 * name objects by shape). SIMULATOR SIDE: independent of the controller's
 * mind/shape.c, with which it shares a meaning but no code.
 *
 * THE RULE (orientation-free: every measure is invariant under rotation and
 * translation):
 *   0. Size: a polygon less than JUDGE_SHAPE_MIN_WIDTH squares wide (its extent
 *      across its narrowest direction) is unnamed: the TABLE represents it by
 *      squares that as many other shapes cover, so no eye could name it, and the
 *      controller names nothing that small either (shape.h, SHAPE_MIN_SIDE; a
 *      crumb of 1.2 x 1.9 squares covering a 3 x 3 block was "the square" nearest
 *      the start and the real square beyond it was not).
 *   1. Merge: drop a vertex closer than JUDGE_SHAPE_MERGE squares to the previous
 *      kept one, and a vertex whose turn is under JUDGE_SHAPE_STRAIGHT degrees
 *      (collinear), until none is left to drop.
 *   2. Corners: 3 -> triangle. 4, every interior angle within JUDGE_SHAPE_RIGHT
 *      degrees of 90 -> square when long/short side (mean of opposite sides) <=
 *      JUDGE_SHAPE_SQUARE, brick when >= JUDGE_SHAPE_BRICK, unnamed between.
 *      6, every angle within JUDGE_SHAPE_RIGHT of 90 or of 270, exactly one of
 *      them reflex (270) -> L-shape. Anything else is unnamed (SHAPE_NONE). */
#ifndef UTAK_JUDGESHAPE_H
#define UTAK_JUDGESHAPE_H

#include "utak/base/geom.h"
#include "utak/base/task.h"

#define JUDGE_SHAPE_MIN_WIDTH 2.0	/* squares: narrower is too small to name */
#define JUDGE_SHAPE_MERGE 0.05		/* squares: near-duplicate vertices */
#define JUDGE_SHAPE_STRAIGHT 3.0	/* degrees: a turn smaller is no corner */
#define JUDGE_SHAPE_RIGHT 10.0		/* degrees from 90 (or 270) still right */
#define JUDGE_SHAPE_SQUARE 1.2		/* long/short side at most: a square */
#define JUDGE_SHAPE_BRICK 1.5		/* long/short side at least: a brick */

/* judge_shape_name(p): the shape of polygon p by the rule above. */
Shape judge_shape_name(const Polygon *p);

/* judge_shape_centroid(p): the area centroid of p (the shoelace formula's first
 * moments); the mean of the vertices if p has no area. */
Vec2 judge_shape_centroid(const Polygon *p);

#endif
