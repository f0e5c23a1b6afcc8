/* test_probe.c - shape by motion (probe.h, paper 3.3; issue 13 items 1, 2 and 6),
 * against exact rasterisation: a polygon is projected onto squares by the TABLE's
 * own rule (geom_project, what the eye sees), pushed by a fraction of a square
 * (plus an error within the slack, as noisy motion would), and projected again;
 * probe_square_consistent is handed the squares before and the counts after, in
 * cells of 1 square (the fovea) or 2 x 2 (the intermediate zone).
 *   A true square (a rectangle of aspect up to 1.2, the verdicts' square) at every
 *   angle in steps of 5 degrees and at sub-square offsets is never rejected.
 *   Worldgen's irregular pieces that Utak took for the square in four random
 *   worlds (their polygons copied here), each of which covers a square's squares
 *   standing still, are rejected by pushes of a quarter square diagonally. */
#include <math.h>
#include <string.h>

#include "test.h"
#include "utak/base/geom.h"
#include "utak/mind/probe.h"

enum { FIELD = 64, MOST = FIELD * FIELD, BUDGET = 200000 };
static int32_t sq_x[MOST], sq_y[MOST], sq_n;

static void span(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	(void)ctx;
	for (int32_t x = x0; x <= x1; x++) {
		sq_x[sq_n] = x;
		sq_y[sq_n++] = y;
	}
}

static Polygon moved(const Polygon *p, double dx, double dy)
{
	Polygon q = *p;
	for (int i = 0; i < q.count; i++)
		q.v[i] = vec2(q.v[i].x + dx, q.v[i].y + dy);
	return q;
}

/* probe(p, d, e, slack, size): p seen, pushed by d + e, seen again in cells of
 * `size`, and judged with displacement d and the slack. */
static ProbeVerdict probe(const Polygon *p, Vec2 d, Vec2 e, double slack, int32_t size)
{
	static int32_t bx[MOST], by[MOST];
	static uint8_t own[MOST];
	static ProbeCell cells[MOST];
	sq_n = 0;
	geom_project(p, FIELD, FIELD, span, NULL);
	int32_t nb = sq_n;
	memcpy(bx, sq_x, sizeof bx[0] * (size_t)nb);
	memcpy(by, sq_y, sizeof by[0] * (size_t)nb);
	Polygon q = moved(p, d.x + e.x, d.y + e.y);
	sq_n = 0;
	geom_project(&q, FIELD, FIELD, span, NULL);
	memset(own, 0, sizeof own);
	int32_t x0 = FIELD, y0 = FIELD, x1 = 0, y1 = 0;
	for (int32_t i = 0; i < sq_n; i++) {
		own[sq_y[i] * FIELD + sq_x[i]] = 1;
		x0 = sq_x[i] < x0 ? sq_x[i] : x0;
		y0 = sq_y[i] < y0 ? sq_y[i] : y0;
		x1 = sq_x[i] > x1 ? sq_x[i] : x1;
		y1 = sq_y[i] > y1 ? sq_y[i] : y1;
	}
	int32_t nc = 0;
	for (int32_t y = (y0 - 2) & ~1; y <= y1 + 2; y += size)
		for (int32_t x = (x0 - 2) & ~1; x <= x1 + 2; x += size) {
			int32_t n = 0;
			for (int32_t j = 0; j < size; j++)
				for (int32_t i = 0; i < size; i++)
					n += own[(y + j) * FIELD + x + i];
			cells[nc++] = (ProbeCell){x, y, size, n};
		}
	return probe_square_consistent(bx, by, nb, d, slack, cells, nc, BUDGET);
}

static Polygon rect(double w, double h, double deg, double cx, double cy)
{
	double c = cos(deg * 3.14159265358979323846 / 180), s = sin(deg * 3.14159265358979323846 / 180);
	double xs[4] = {-w / 2, w / 2, w / 2, -w / 2}, ys[4] = {-h / 2, -h / 2, h / 2, h / 2};
	Polygon p = {.count = 4};
	for (int i = 0; i < 4; i++)
		p.v[i] = vec2(cx + c * xs[i] - s * ys[i], cy + s * xs[i] + c * ys[i]);
	return p;
}

static const Vec2 pushes[4] = {{0.25, 0.25}, {-0.25, 0.25}, {0.25, -0.25}, {-0.25, -0.25}};

/* Exact motion, the fovea's cells: no true square is rejected, and the search
 * finishes (finds one) for nearly all within the budget. */
TEST_CASE(true_squares_never_rejected)
{
	int undecided = 0;
	const double sides[2] = {3.3, 5.7};
	for (int k = 0; k < 2; k++)
		for (int deg = 0; deg < 90; deg += 5)
			for (int o = 0; o < 2; o++) {
				Polygon p = rect(sides[k], sides[k] * (o ? 1.17 : 1.0), deg, 30.13 + 0.41 * o, 30.37 + 0.29 * o);
				ProbeVerdict v = probe(&p, pushes[(deg / 5 + o) % 4], vec2(0, 0), 0, 1);
				TEST_CHECK(v != PROBE_INCONSISTENT);
				undecided += v == PROBE_UNDECIDED;
			}
	TEST_CHECK(undecided <= 4);
}

/* Noisy motion (an error within the slack) seen in 2 x 2 cells: never rejected. */
TEST_CASE(true_squares_noisy_coarse_never_rejected)
{
	const double slack = 0.03;
	for (int deg = 0; deg < 90; deg += 5)
		for (int o = 0; o < 2; o++) {
			Polygon p = rect(4.4, 4.4 * (o ? 1.1 : 1.0), deg, 30.61 + 0.23 * o, 30.07 + 0.5 * o);
			Vec2 e = vec2(slack * ((deg / 5) % 3 - 1), slack * ((deg / 5 + o) % 3 - 1) * 0.7);
			ProbeVerdict v = probe(&p, pushes[(deg / 5 + 2 * o) % 4], e, slack, 2);
			TEST_CHECK(v != PROBE_INCONSISTENT);
		}
}

/* The pieces (random worlds g53, g123, g208, g258 of tests/rates.sh) each cover
 * a square's squares where they stand (the probe, not pushed, finds them
 * consistent) and are rejected by every quarter-square diagonal push, or all but
 * one, exact motion seen in the fovea. */
TEST_CASE(pieces_rejected)
{
	static const double xy[4][16] = {
		{11.734, 139.007, 15.33, 141.853, 14.281, 144.553, 11.543, 144.367, 10.322, 141.365},
		{21.415, 39.821, 18.623, 38.767, 18.228, 36.365, 21.336, 35.705, 23.061, 37.374},
		{23.912, 4.972, 25.405, 5.968, 25.844, 7.73, 24.752, 8.686, 22.376, 9.438, 21.119, 8.04, 20.407, 5.522,
		 21.542, 4.555},
		{24.153, 22.414, 25.589, 21.022, 26.788, 20.694, 29.043, 21.152, 28.468, 23.227, 27.444, 24.271, 25.333,
		 24.64},
	};
	static const int count[4] = {5, 5, 8, 7};
	for (int k = 0; k < 4; k++) {
		Polygon p = {.count = count[k]};
		for (int i = 0; i < count[k]; i++) /* moved by whole squares: the same squares */
			p.v[i] = vec2(xy[k][2 * i] - floor(xy[k][0]) + 20, xy[k][2 * i + 1] - floor(xy[k][1]) + 20);
		TEST_CHECK(probe(&p, vec2(0, 0), vec2(0, 0), 0, 1) == PROBE_CONSISTENT);
		int rejected = 0;
		for (int j = 0; j < 4; j++)
			rejected += probe(&p, pushes[j], vec2(0, 0), 0, 1) == PROBE_INCONSISTENT;
		TEST_CHECK(rejected >= 3);
	}
}

/* Degenerate input: nothing to test. */
TEST_CASE(empty_is_undecided)
{
	int32_t x = 0;
	TEST_CHECK(probe_square_consistent(&x, &x, 0, vec2(0.25, 0.25), 0, NULL, 0, BUDGET) == PROBE_UNDECIDED);
}

int main(void)
{
	TEST_RUN(true_squares_never_rejected);
	TEST_RUN(true_squares_noisy_coarse_never_rejected);
	TEST_RUN(pieces_rejected);
	TEST_RUN(empty_is_undecided);
	return TEST_EXIT();
}
