/* geom.h - points, polygons and their projection onto a grid of squares (paper 2.1).
 *
 * The Cartesian representation of paper 2.1: a shape is a list of points, its
 * edges the pairs of consecutive points (and last-first). Coordinates are in TABLE
 * squares: one unit is one square, square (i, j) is [i, i+1] x [j, j+1].
 *
 * The digital representation (utak(5)): a square belongs to a polygon when the
 * square's open interior meets the closed polygon (its interior or its edges). A
 * polygon touching a square only along the square's border does not claim it, so
 * the axis-aligned square (10,10)-(14,14) claims exactly 16 squares. */
#ifndef UTAK_GEOM_H
#define UTAK_GEOM_H

#include <stdbool.h>
#include <stdint.h>

/* The most vertices a polygon may have: a limit of the world file (man utak.5),
 * large enough for any hand-drawn shape, small enough to copy polygons by value. */
#define GEOM_MAX_VERTICES 64

/* A point or a displacement, in TABLE squares (or in whatever frame the caller says). */
typedef struct Vec2 {
	double x, y;
} Vec2;

static inline Vec2 vec2(double x, double y) { return (Vec2){x, y}; }
static inline Vec2 vec2_add(Vec2 a, Vec2 b) { return (Vec2){a.x + b.x, a.y + b.y}; }
static inline Vec2 vec2_sub(Vec2 a, Vec2 b) { return (Vec2){a.x - b.x, a.y - b.y}; }
static inline Vec2 vec2_scale(Vec2 a, double s) { return (Vec2){a.x * s, a.y * s}; }
static inline double vec2_dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
/* vec2_cross: z of the 3-D cross product; > 0 when b is counter-clockwise of a. */
static inline double vec2_cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

/* A simple polygon, either winding. */
typedef struct Polygon {
	int32_t count;			/* number of vertices, 3..GEOM_MAX_VERTICES */
	Vec2 v[GEOM_MAX_VERTICES];	/* vertices in order */
} Polygon;

/* An axis-aligned box [lo.x, hi.x] x [lo.y, hi.y]. */
typedef struct Box {
	Vec2 lo, hi;
} Box;

/* geom_orient(a, b, c): > 0 when a, b, c turn left, < 0 right, 0 collinear. The
 * one orientation predicate every other test in this file is built on. */
double geom_orient(Vec2 a, Vec2 b, Vec2 c);

/* geom_polygon_area: signed area, > 0 for counter-clockwise. */
double geom_polygon_area(const Polygon *p);
/* geom_winding(pts, n, c): how many times the closed polyline pts[0..n-1] (its last
 * point joined back to its first) winds round c, counter-clockwise positive: the
 * sum of the angles each segment turns through as seen from c, over 2 pi. Not an
 * integer when c lies on the polyline. */
double geom_winding(const Vec2 *pts, int n, Vec2 c);
Box geom_polygon_box(const Polygon *p);
/* geom_polygon_is_simple: no two edges meet except neighbours at their shared
 * vertex; no zero-length edge; non-zero area. O(n^2), n <= GEOM_MAX_VERTICES. */
bool geom_polygon_is_simple(const Polygon *p);
/* geom_point_in_polygon: strictly inside (points on an edge may go either way). */
bool geom_point_in_polygon(const Polygon *p, Vec2 q);
/* geom_point_segment_distance: the distance from q to the closed segment ab. */
double geom_point_segment_distance(Vec2 q, Vec2 a, Vec2 b);
/* geom_segments_cross: the closed segments ab and cd share a point. */
bool geom_segments_meet(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

/* geom_rotate(p, centre, c, s): p rotated about centre by the angle whose cosine
 * and sine are c and s (counter-clockwise for s > 0). */
Vec2 geom_rotate(Vec2 p, Vec2 centre, double c, double s);
/* geom_cos_sin(deg, &c, &s): cosine and sine of deg degrees, exact for multiples of
 * 90 so that a quarter turn leaves integer coordinates integer. */
void geom_cos_sin(double deg, double *c, double *s);

/* Projection (rasterisation). A span is a run of squares x0..x1 (inclusive) in
 * row y, reported in increasing y and, within a row, increasing x; runs do not
 * overlap. Only squares inside [0, w) x [0, h) are reported. */
typedef void GeomSpanFn(void *ctx, int32_t y, int32_t x0, int32_t x1);

/* geom_project(p, w, h, fn, ctx): the squares whose open interior meets p. */
void geom_project(const Polygon *p, int32_t w, int32_t h, GeomSpanFn *fn, void *ctx);
/* geom_project_outside(p, w, h, fn, ctx): the squares NOT wholly inside p, i.e.
 * whose open interior meets the open exterior of p: the verge of paper 2.1. */
void geom_project_outside(const Polygon *p, int32_t w, int32_t h, GeomSpanFn *fn, void *ctx);

#endif
