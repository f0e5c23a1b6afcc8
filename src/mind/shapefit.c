/* shapefit.c - fitting rectangles, triangles and L-shapes to a set of squares at
 * any angle (shape.h, shapefit.h). CONTROLLER SIDE.
 *
 * ALGORITHM (analysis by synthesis: the model whose projection through the TABLE's
 * digital rule gives what the eye saw).
 * - The measure descended on (fit_cost): for each square of the set, how far the
 *   model stays from it, and for each square outside, how deep the model reaches
 *   into it, over the band of squares round the set's boundary. Both come from the
 *   separating axis theorem on convex pieces (the L-shape is two rectangles): the
 *   largest gap between the projections of the piece and of the square on the
 *   piece's normals and on x and y. It is 0 exactly when the model's digital
 *   representation is the set, and continuous, so a descent can follow it.
 * - A rectangle or L-shape (shapefit_box): every angle of a quarter turn in steps of
 *   FIT_SCAN_STEP, the model started on the rectangle enclosing the hull at that
 *   angle (the L's notch where that rectangle is emptiest, sampled), its offsets
 *   found coarsely; full coordinate descent from the FIT_STARTS cheapest; the
 *   angle refined by halving the step.
 * - A triangle (shapefit_triangle): from the largest triangle on the hull's
 *   vertices, descent on each side's angle and offset, then on the vertices (a
 *   vertex moved turns both its sides about their other ends), a few rounds.
 * COMPLEXITY: a cost is O(B) for a band of B squares (about 3 per boundary square);
 * a rectangle's fit costs one to three thousand, an L-shape's as many again.
 * Measured here: a 4 x 4 square about 0.5 ms, an L-shape a few ms (-O2). */
#include "utak/mind/shapefit.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

/* Samples per square when the set is read in its rectangle's frame. */
#define SHAPE_SAMPLES 4
/* Coordinate descent (step 7): first steps, squares and radians, halved this often. */
#define FIT_STEP 0.25
#define FIT_STEP_ANGLE 0.05
#define FIT_HALVINGS 4
/* The angle scan of a rectangle or L-shape (fit_box): steps of FIT_SCAN_STEP
 * radians (3 degrees) over a quarter turn; descent from the FIT_STARTS cheapest;
 * FIT_REFINE halvings of the step round the best. */
#define FIT_SCAN_STEP 0.0523599
#define FIT_SCAN_HALVINGS 0
#define FIT_STARTS 3
#define FIT_REFINE 4
/* The hull of the squares' centres lies about this far inside the object's sides. */
#define FIT_HULL_INSIDE 0.5
/* A square belongs to a model that reaches into it, not one that only touches
 * its border (geom.h): the fit asks it to reach in at least this far. */
#define FIT_REACH 0.02
/* A triangle's sides start this far outside the hull's (half a square for the
 * centres' hull, nearer for the corners'); the fit is made again from where it
 * ends this many times. */
#define FIT_TRIANGLE_START 0.25
#define FIT_TRIANGLE_ROUNDS 3
/* The narrowest side or arm a model may have, squares. */
#define FIT_MIN_SIDE 0.5
/* Passes of a descent at one step size before the step is halved anyway. A start
 * lies within a square or two of its fit, a few passes at FIT_STEP; without a bound
 * a descent over a set of many squares could creep on by gains of a hair for
 * minutes (a 141 x 49 generated world, whose coarse walls made a set of hundreds of
 * squares: 16 minutes of CPU in one run of go round). */
#define FIT_MAX_PASSES 64

/* shapefit_rect_along(h, n, ux, uy): the rectangle enclosing the hull with sides along the
 * unit vector (ux, uy) and across it. */
Rect shapefit_rect_along(const Vec2 *h, int32_t n, double ux, double uy)
{
	double vx = -uy, vy = ux;
	double u0 = INFINITY, u1 = -INFINITY, v0 = INFINITY, v1 = -INFINITY;
	for (int32_t k = 0; k < n; k++) {
		double pu = h[k].x * ux + h[k].y * uy, pv = h[k].x * vx + h[k].y * vy;
		u0 = pu < u0 ? pu : u0;
		u1 = pu > u1 ? pu : u1;
		v0 = pv < v0 ? pv : v0;
		v1 = pv > v1 ? pv : v1;
	}
	return (Rect){u0 * ux + v0 * vx, u0 * uy + v0 * vy, ux, uy, vx, vy, u1 - u0, v1 - v0};
}

/* shapefit_largest_triangle(h, n, best): the area of the largest triangle on three of the
 * hull's vertices, and in best[] their indices. */
double shapefit_largest_triangle(const Vec2 *h, int32_t n, int32_t best[3])
{
	double most = 0;
	best[0] = 0, best[1] = n > 1 ? 1 : 0, best[2] = n > 2 ? 2 : 0;
	for (int32_t i = 0; i < n; i++)
		for (int32_t j = i + 1; j < n; j++)
			for (int32_t k = j + 1; k < n; k++) {
				double twice = geom_orient(h[i], h[j], h[k]);
				if (twice > most) {
					most = twice;
					best[0] = i, best[1] = j, best[2] = k;
				}
			}
	return most / 2;
}

/* A sampling of the set in the rectangle's frame: cols x rows samples, (0, 0) at
 * the rectangle's corner o. */
typedef struct Samples {
	int32_t cols, rows;
	uint8_t *full;
} Samples;

static Samples sample_in_rect(const ShapeMask *m, const Rect *r)
{
	Samples s = {(int32_t)ceil(r->a * SHAPE_SAMPLES), (int32_t)ceil(r->b * SHAPE_SAMPLES), NULL};
	s.full = util_alloc((size_t)s.cols * (size_t)s.rows + 1, 1);
	for (int32_t j = 0; j < s.rows; j++)
		for (int32_t i = 0; i < s.cols; i++) {
			double du = (i + 0.5) / SHAPE_SAMPLES, dv = (j + 0.5) / SHAPE_SAMPLES;
			double x = r->ox + du * r->ux + dv * r->vx, y = r->oy + du * r->uy + dv * r->vy;
			s.full[(int64_t)j * s.cols + i] = shapefit_mask_at(m, (int32_t)floor(x), (int32_t)floor(y));
		}
	return s;
}

/* Sample (i, j) seen from corner c (0..3: bit 0 flips the columns, bit 1 the rows). */
static bool sample_full(const Samples *s, int c, int32_t i, int32_t j)
{
	if (c & 1)
		i = s->cols - 1 - i;
	if (c & 2)
		j = s->rows - 1 - j;
	return s->full[(int64_t)j * s->cols + i];
}

/* corner_notch(s, c, min, &nu, &nv): the largest empty rectangle anchored at corner
 * c whose sides are both at least min samples: nu x nv samples; its area (0 none). */
static int64_t corner_notch(const Samples *s, int c, int32_t min, int32_t *nu, int32_t *nv)
{
	int64_t best = 0;
	int32_t run_min = s->cols;
	*nu = *nv = 0;
	for (int32_t j = 0; j < s->rows; j++) {
		int32_t run = 0;
		while (run < s->cols && !sample_full(s, c, run, j))
			run++;
		run_min = run < run_min ? run : run_min;
		if (run_min < min)
			break;
		int64_t area = (int64_t)run_min * (j + 1);
		if (j + 1 >= min && area > best) {
			best = area;
			*nu = run_min;
			*nv = j + 1;
		}
	}
	return best;
}



static Vec2 fit_normal(double angle) { return vec2(cos(angle), sin(angle)); }

/* fit_rect_normal(f, k): the normal of the rectangle's side k. */
static Vec2 fit_rect_normal(const FitModel *f, int k)
{
	Vec2 n = fit_normal(f->side[0].angle);
	static const int8_t turn[4][2][2] = {{{1, 0}, {0, 1}}, {{0, -1}, {1, 0}}, {{-1, 0}, {0, -1}}, {{0, 1}, {-1, 0}}};
	k &= 3;
	return vec2(turn[k][0][0] * n.x + turn[k][0][1] * n.y, turn[k][1][0] * n.x + turn[k][1][1] * n.y);
}

/* The model prepared for measuring: up to two convex pieces (the L-shape's two
 * arms), each the intersection of half-planes n . p <= o, with its extent lo along
 * each n and its extent along x and y (from its vertices): what the separating
 * axis test needs. */
typedef struct FitPlanes {
	int pieces, count[2];
	double nx[2][4], ny[2][4], o[2][4], lo[2][4], h[2][4];
	double x0[2], x1[2], y0[2], y1[2];
} FitPlanes;

/* fit_piece(fp, piece, n, o, count): a convex piece of count half-planes n . p <= o
 * (consecutive sides meeting at its vertices); false when they make no polygon. */
static bool fit_piece(FitPlanes *fp, int piece, const Vec2 *n, const double *o, int count)
{
	Vec2 v[4];
	for (int k = 0; k < count; k++) {
		const Vec2 a = n[k], b = n[(k + 1) % count];
		double det = a.x * b.y - a.y * b.x;
		if (det < 1e-9) /* consecutive normals must turn counter-clockwise */
			return false;
		v[k] = vec2((o[k] * b.y - o[(k + 1) % count] * a.y) / det, (a.x * o[(k + 1) % count] - b.x * o[k]) / det);
	}
	fp->count[piece] = count;
	fp->x0[piece] = fp->y0[piece] = INFINITY;
	fp->x1[piece] = fp->y1[piece] = -INFINITY;
	for (int k = 0; k < count; k++) {
		fp->x0[piece] = fmin(fp->x0[piece], v[k].x);
		fp->x1[piece] = fmax(fp->x1[piece], v[k].x);
		fp->y0[piece] = fmin(fp->y0[piece], v[k].y);
		fp->y1[piece] = fmax(fp->y1[piece], v[k].y);
	}
	for (int k = 0; k < count; k++) {
		fp->nx[piece][k] = n[k].x;
		fp->ny[piece][k] = n[k].y;
		fp->o[piece][k] = o[k];
		fp->h[piece][k] = (fabs(n[k].x) + fabs(n[k].y)) / 2;
		double lo = INFINITY;
		for (int j = 0; j < count; j++)
			lo = fmin(lo, vec2_dot(n[k], v[j]));
		fp->lo[piece][k] = lo;
		/* Every vertex must lie on the inner side of every half-plane. */
		for (int j = 0; j < count; j++)
			if (vec2_dot(n[k], v[j]) > o[k] + 1e-6)
				return false;
	}
	return true;
}

static bool fit_planes(const FitModel *f, FitPlanes *fp)
{
	*fp = (FitPlanes){0};
	Vec2 n[4];
	double o[4];
	if (f->kind == FIT_TRIANGLE) {
		fp->pieces = 1;
		for (int k = 0; k < 3; k++) {
			n[k] = fit_normal(f->side[k].angle);
			o[k] = f->side[k].offset + vec2_dot(n[k], f->side[k].at);
		}
		return fit_piece(fp, 0, n, o, 3);
	}
	fp->pieces = f->kind == FIT_LSHAPE ? 2 : 1;
	for (int piece = 0; piece < fp->pieces; piece++) {
		for (int k = 0; k < 4; k++) {
			n[k] = fit_rect_normal(f, k);
			o[k] = f->side[k].offset + vec2_dot(n[k], f->side[0].at);
			/* The L-shape's arms: the rectangle cut back from side `corner`
			 * by notch[0], and from side corner + 1 by notch[1]. */
			if (f->kind == FIT_LSHAPE && k == ((f->corner + piece) & 3))
				o[k] -= f->notch[piece];
		}
		if (!fit_piece(fp, piece, n, o, 4))
			return false;
	}
	return true;
}

/* fit_square_distance(fp, x, y): how far the model stays from the unit square
 * centred at (x, y), negative when it reaches into it: by the separating axis
 * theorem (two convex sets are apart iff their projections are apart on some
 * edge normal of either), the largest gap between the projections of a piece and
 * of the square over the piece's normals and the square's (x and y), which is
 * minus the least overlap when they meet; the least over the pieces. */
static double fit_square_distance(const FitPlanes *fp, double x, double y)
{
	/* Plain comparisons, not fmax: this is the inner loop of every fit, and the
	 * values are never NaN. */
#define FIT_MAX(a, b) ((a) > (b) ? (a) : (b))
	double best = INFINITY;
	for (int piece = 0; piece < fp->pieces; piece++) {
		double gap = FIT_MAX(x - 0.5 - fp->x1[piece], fp->x0[piece] - x - 0.5);
		gap = FIT_MAX(gap, y - 0.5 - fp->y1[piece]);
		gap = FIT_MAX(gap, fp->y0[piece] - y - 0.5);
		for (int k = 0; k < fp->count[piece]; k++) {
			double c = fp->nx[piece][k] * x + fp->ny[piece][k] * y, h = fp->h[piece][k];
			gap = FIT_MAX(gap, c - h - fp->o[piece][k]);
			gap = FIT_MAX(gap, fp->lo[piece][k] - c - h);
		}
		best = gap < best ? gap : best;
	}
#undef FIT_MAX
	return best;
}

/* fit_valid(f): the parameters make a shape: sides apart, a notch inside. */
static bool fit_valid(const FitModel *f)
{
	if (f->kind == FIT_TRIANGLE)
		return true; /* fit_polygon checks the triangle */
	for (int k = 0; k < 2; k++)
		if (f->side[k].offset + f->side[k + 2].offset < FIT_MIN_SIDE)
			return false;
	if (f->kind == FIT_LSHAPE) {
		int a = f->corner & 3, b = (f->corner + 1) & 3;
		double across_a = f->side[a].offset + f->side[(a + 2) & 3].offset;
		double across_b = f->side[b].offset + f->side[(b + 2) & 3].offset;
		if (f->notch[0] <= 0 || f->notch[1] <= 0 || f->notch[0] > across_a - FIT_MIN_SIDE ||
		    f->notch[1] > across_b - FIT_MIN_SIDE)
			return false;
	}
	return true;
}

/* fit_meet(n1, o1, n2, o2): where the lines n1 . p = o1 and n2 . p = o2 cross. */
static Vec2 fit_meet(Vec2 n1, double o1, Vec2 n2, double o2)
{
	double det = n1.x * n2.y - n1.y * n2.x;
	return vec2((o1 * n2.y - o2 * n1.y) / det, (n1.x * o2 - n2.x * o1) / det);
}

/* fit_polygon(f, out): the model's polygon, counter-clockwise; false when the
 * parameters make none. */
static bool fit_polygon(const FitModel *f, Polygon *out)
{
	if (!fit_valid(f))
		return false;
	if (f->kind == FIT_TRIANGLE) {
		Vec2 n[3];
		double o[3];
		for (int k = 0; k < 3; k++) {
			n[k] = fit_normal(f->side[k].angle);
			o[k] = f->side[k].offset + vec2_dot(n[k], f->side[k].at);
		}
		out->count = 3;
		for (int k = 0; k < 3; k++) {
			double det = n[k].x * n[(k + 1) % 3].y - n[k].y * n[(k + 1) % 3].x;
			if (fabs(det) < 1e-6)
				return false;
			out->v[k] = fit_meet(n[k], o[k], n[(k + 1) % 3], o[(k + 1) % 3]);
		}
		double area = geom_polygon_area(out);
		/* The sides' normals must point out: the triangle lies inside each. */
		for (int k = 0; k < 3; k++) {
			Vec2 mid = vec2((out->v[0].x + out->v[1].x + out->v[2].x) / 3, (out->v[0].y + out->v[1].y + out->v[2].y) / 3);
			if (vec2_dot(n[k], mid) - o[k] >= 0)
				return false;
		}
		if (area < 0) {
			Vec2 t = out->v[0];
			out->v[0] = out->v[2];
			out->v[2] = t;
		}
		return fabs(area) > FIT_MIN_SIDE;
	}
	Vec2 c = f->side[0].at, n[4];
	for (int k = 0; k < 4; k++)
		n[k] = fit_rect_normal(f, k);
	/* Corner k between sides k and k + 1 (perpendicular): c + d_k n_k + d_k+1 n_k+1. */
#define FIT_CORNER(ka, da, kb, db) vec2_add(c, vec2_add(vec2_scale(n[ka], da), vec2_scale(n[kb], db)))
	out->count = 0;
	for (int k = 0; k < 4; k++) {
		int k1 = (k + 1) & 3;
		double dk = f->side[k].offset, dk1 = f->side[k1].offset;
		if (f->kind == FIT_LSHAPE && k == (f->corner & 3)) {
			out->v[out->count++] = FIT_CORNER(k, dk, k1, dk1 - f->notch[1]);
			out->v[out->count++] = FIT_CORNER(k, dk - f->notch[0], k1, dk1 - f->notch[1]);
			out->v[out->count++] = FIT_CORNER(k, dk - f->notch[0], k1, dk1);
		} else {
			out->v[out->count++] = FIT_CORNER(k, dk, k1, dk1);
		}
	}
#undef FIT_CORNER
	return true;
}

/* fit_cost(m, f): how far the model is from giving the set as its digital
 * representation, a continuous measure to descend on: for each square of the set,
 * how far the model stays from it; for each square outside, how deep the model
 * reaches into it (a square belongs when the model meets it, geom.h). Only the
 * squares of the band round the set's boundary (m->band) are weighed: a model near
 * the set explains the rest. 0 when the model explains the set. */
static double fit_cost(const ShapeMask *m, const FitModel *f)
{
	if (!fit_valid(f))
		return INFINITY;
	FitPlanes fp;
	if (!fit_planes(f, &fp))
		return INFINITY;
	double cost = 0;
	for (int32_t b = 0; b < m->band_count; b++) {
		int32_t k = m->band[b], i = k % m->w, j = k / m->w;
		double d = fit_square_distance(&fp, i + 0.5, j + 0.5);
		if (m->in[k] && d > -FIT_REACH)
			cost += d + FIT_REACH; /* the model should reach into this square */
		else if (!m->in[k] && d < 0)
			cost -= d; /* ... and stay out of this one */
	}
	return cost;
}

/* shapefit_error(m, squares, f): the squares on which the model's digital representation
 * and the set differ; INT32_MAX when the model makes no polygon. */
typedef struct FitCount {
	const ShapeMask *m;
	int32_t agree, model;
} FitCount;

static void fit_span(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	FitCount *f = ctx;
	f->model += x1 - x0 + 1;
	for (int32_t x = x0; x <= x1; x++)
		f->agree += f->m->in[(int64_t)y * f->m->w + x];
}

int32_t shapefit_error(const ShapeMask *m, int32_t squares, const FitModel *f)
{
	Polygon p;
	if (!fit_polygon(f, &p))
		return INT32_MAX;
	FitCount c = {m, 0, 0};
	geom_project(&p, m->w, m->h, fit_span, &c);
	return (c.model - c.agree) + (squares - c.agree);
}

/* A parameter of a model, for descent. */
static double *fit_param(FitModel *f, int i, double *step)
{
	if (f->kind == FIT_TRIANGLE) { /* angle and offset of each side */
		*step = i % 2 ? FIT_STEP : FIT_STEP_ANGLE;
		return i % 2 ? &f->side[i / 2].offset : &f->side[i / 2].angle;
	}
	*step = FIT_STEP;
	return i < 4 ? &f->side[i].offset : &f->notch[i - 4];
}

/* fit_descend(m, f, first, count, first_halving, most_halvings): coordinate descent
 * on fit_cost over parameters
 * first .. first + count - 1, each step tried both ways and kept when it lowers the
 * cost, the steps halved when none does; returns the cost reached. */
static double fit_descend(const ShapeMask *m, FitModel *f, int first, int count, int first_halving,
			  int most_halvings)
{
	double best = fit_cost(m, f), scale = ldexp(1.0, -first_halving);
	for (int halvings = first_halving, passes = 0; halvings <= most_halvings && best > 0; passes++) {
		bool improved = false;
		for (int i = first; i < first + count; i++)
			for (int dir = -1; dir <= 1; dir += 2) {
				double step, *p = fit_param(f, i, &step), keep = *p;
				*p += dir * step * scale;
				double c = fit_cost(m, f);
				if (c < best - 1e-9) {
					best = c;
					improved = true;
				} else {
					*p = keep;
				}
			}
		if (!improved || passes == FIT_MAX_PASSES) {
			scale /= 2;
			halvings++;
			passes = -1;
		}
	}
	return best;
}

/* fit_triangle_on(f, v): the triangle model whose sides run through the
 * counter-clockwise vertices v (each side's angle turning about its middle). */
static void fit_triangle_on(FitModel *f, const Vec2 v[3])
{
	*f = (FitModel){.kind = FIT_TRIANGLE};
	for (int k = 0; k < 3; k++) {
		Vec2 a = v[k], b = v[(k + 1) % 3];
		f->side[k].at = vec2((a.x + b.x) / 2, (a.y + b.y) / 2);
		f->side[k].angle = atan2(-(b.x - a.x), b.y - a.y); /* right of a -> b: out */
	}
}

/* fit_descend_vertices(m, f, v): coordinate descent on the triangle's vertices v
 * (each move turns both sides at that corner about their other ends, which a
 * side's own angle and offset cannot do in one step); f and v become the fit.
 * Returns the cost. */
static double fit_descend_vertices(const ShapeMask *m, FitModel *f, Vec2 v[3])
{
	fit_triangle_on(f, v);
	double best = fit_cost(m, f), step = FIT_STEP;
	for (int halvings = 0, passes = 0; halvings <= FIT_HALVINGS && best > 0; passes++) {
		bool improved = false;
		for (int i = 0; i < 6; i++)
			for (int dir = -1; dir <= 1; dir += 2) {
				double *p = i % 2 ? &v[i / 2].y : &v[i / 2].x, keep = *p;
				*p += dir * step;
				FitModel t;
				fit_triangle_on(&t, v);
				double c = fit_cost(m, &t);
				if (c < best - 1e-9) {
					best = c;
					*f = t;
					improved = true;
				} else {
					*p = keep;
				}
			}
		if (!improved || passes == FIT_MAX_PASSES) {
			step /= 2;
			halvings++;
			passes = -1;
		}
	}
	return best;
}

/* shapefit_triangle(m, h, n, f): a triangle fitted, from the largest on the vertices of
 * hull h: descent on each side's angle and offset, then on its vertices, from the
 * triangle as it then is, FIT_TRIANGLE_ROUNDS times. Returns the cost. */
double shapefit_triangle(const ShapeMask *m, const Vec2 *h, int32_t n, FitModel *f)
{
	int32_t tri[3];
	shapefit_largest_triangle(h, n, tri);
	Vec2 v[3] = {h[tri[0]], h[tri[1]], h[tri[2]]};
	fit_triangle_on(f, v);
	for (int k = 0; k < 3; k++)
		f->side[k].offset = FIT_TRIANGLE_START;
	double cost = INFINITY;
	for (int round = 0; round < FIT_TRIANGLE_ROUNDS && cost > 0; round++) {
		cost = fit_descend(m, f, 0, 6, 0, FIT_HALVINGS);
		Polygon p;
		if (cost == 0 || !fit_polygon(f, &p))
			break;
		/* fit_polygon's vertex k is where sides k and k + 1 meet: side k runs
		 * from vertex k - 1 to vertex k. */
		for (int k = 0; k < 3; k++)
			v[k] = p.v[(k + 2) % 3];
		cost = fit_descend_vertices(m, f, v);
	}
	return cost;
}

/* shapefit_box_start(m, r, kind, f): a rectangle model on rectangle r (the hull's), or
 * an L-shape: r less a notch at the corner where the largest empty rectangle of
 * the set sampled in r is anchored (at least half a square each way). False for
 * an L-shape when no corner of r is empty. */
bool shapefit_box_start(const ShapeMask *m, const Rect *r, int kind, FitModel *f)
{
	*f = (FitModel){.kind = kind};
	Vec2 c = vec2(r->ox + (r->a * r->ux + r->b * r->vx) / 2, r->oy + (r->a * r->uy + r->b * r->vy) / 2);
	f->side[0].at = c;
	f->side[0].angle = atan2(r->uy, r->ux);
	/* The centres' hull lies about half a square inside the object's sides. */
	f->side[0].offset = f->side[2].offset = r->a / 2 + FIT_HULL_INSIDE;
	f->side[1].offset = f->side[3].offset = r->b / 2 + FIT_HULL_INSIDE;
	if (kind != FIT_LSHAPE)
		return true;
	Samples s = sample_in_rect(m, r);
	int32_t min = SHAPE_SAMPLES / 2, nu = 0, nv = 0, best = -1;
	int64_t best_area = 0;
	for (int k = 0; k < 4; k++) {
		int32_t u, v;
		int64_t area = corner_notch(&s, k, min, &u, &v);
		if (area > best_area) {
			best_area = area;
			best = k, nu = u, nv = v;
		}
	}
	free(s.full);
	if (best < 0)
		return false;
	/* Sample corner k is at the +u end when bit 0 is set, the +v end when bit 1:
	 * sides 0 (+u), 1 (+v), 2 (-u), 3 (-v); the corner between sides j, j + 1. */
	static const int8_t corner_of[4] = {2, 3, 1, 0};
	f->corner = corner_of[best];
	/* notch[0] cuts from side corner, notch[1] from side corner + 1. */
	bool u_first = (f->corner & 1) == 0; /* sides 0 and 2 are across u */
	f->notch[0] = (double)(u_first ? nu : nv) / SHAPE_SAMPLES;
	f->notch[1] = (double)(u_first ? nv : nu) / SHAPE_SAMPLES;
	return true;
}

/* shapefit_box(m, h, n, kind, f): a rectangle or L-shape fitted (its frame repeats every
 * quarter turn): the model started afresh on the hull's enclosing rectangle at
 * every angle of a scan of the quarter turn in FIT_SCAN_STEP steps, and costed as
 * started; from the FIT_STARTS cheapest, offsets descended in full; the best of
 * those refined by halving FIT_SCAN_STEP FIT_REFINE times. Returns the cost
 * (INFINITY when no model could be started); f becomes the fit. */
double shapefit_box(const ShapeMask *m, const Vec2 *h, int32_t n, int kind, FitModel *f)
{
	enum { MOST = 64 };
	FitModel start[MOST];
	double cost[MOST], quarter = 2 * atan(1.0);
	int count = 0, params = kind == FIT_LSHAPE ? 6 : 4;
	for (double angle = 0; angle < quarter - 1e-9 && count < MOST; angle += FIT_SCAN_STEP) {
		Rect r = shapefit_rect_along(h, n, cos(angle), sin(angle));
		if (shapefit_box_start(m, &r, kind, &start[count])) {
			cost[count] = fit_descend(m, &start[count], 0, params, 0, FIT_SCAN_HALVINGS);
			if (cost[count] == 0) { /* it explains the set already */
				*f = start[count];
				return 0;
			}
			count++;
		}
	}
	FitModel best = {.kind = kind};
	double best_cost = INFINITY;
	for (int s = 0; s < FIT_STARTS && s < count && best_cost > 0; s++) {
		int pick = -1; /* the cheapest start not yet taken */
		for (int k = 0; k < count; k++)
			if (cost[k] < INFINITY && (pick < 0 || cost[k] < cost[pick]))
				pick = k;
		if (pick < 0)
			break;
		cost[pick] = INFINITY;
		FitModel t = start[pick];
		double c = fit_descend(m, &t, 0, params, 0, FIT_HALVINGS);
		if (c < best_cost) {
			best_cost = c;
			best = t;
		}
	}
	if (best_cost == INFINITY)
		return INFINITY;
	double step = FIT_SCAN_STEP;
	for (int r = 0; r < FIT_REFINE && best_cost > 0; r++) {
		step /= 2;
		FitModel here = best;
		for (int dir = -1; dir <= 1; dir += 2) {
			FitModel t = here;
			t.side[0].angle = here.side[0].angle + dir * step;
			/* Near the best already: the offsets move by small steps. */
			double c = fit_descend(m, &t, 0, params, FIT_HALVINGS - 2, FIT_HALVINGS);
			if (c < best_cost) {
				best_cost = c;
				best = t;
			}
		}
	}
	*f = best;
	return best_cost;
}
