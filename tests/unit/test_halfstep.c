/* test_halfstep.c - the second probe by half a square (probe.h PROBE_HALF_STEP,
 * rival.h HALF A SQUARE; paper 3.3, shape by motion; issue 13 item 6), against
 * exact rasterisation by the TABLE's own rule (geom_project, probe_looks.h).
 *   A brick 4 x 2 (clutter.w's) whose edges lie between a quarter and three
 *   quarters into their squares owns exactly the squares it owned before when
 *   pushed a quarter square either way on each axis (so a quarter-square probe
 *   shows no change: nothing to judge), and owns other squares pushed half a
 *   square; the probe's looks at half a square reject it as a square every time,
 *   Utak's point anywhere in his square (not told to the test).
 *   A true square (the verdicts' square: aspect up to 1.17, sides 2 to 3.6), at
 *   every 15 degrees and sub-square offsets, pushed by half a square, exact or
 *   noisy (0.05 a square pushed), is never rejected: the second probe can only
 *   disprove a square, never lift a doubt on one. */
#include <math.h>
#include <string.h>

#include "test.h"
#include "utak/base/geom.h"
#include "utak/mind/probe.h"

#include "probe_looks.h"

static Polygon rect(double w, double h, double deg, double cx, double cy)
{
	double c = cos(deg * 3.14159265358979323846 / 180), s = sin(deg * 3.14159265358979323846 / 180);
	double xs[4] = {-w / 2, w / 2, w / 2, -w / 2}, ys[4] = {-h / 2, -h / 2, h / 2, h / 2};
	Polygon p = {.count = 4};
	for (int i = 0; i < 4; i++)
		p.v[i] = vec2(cx + c * xs[i] - s * ys[i], cy + s * xs[i] + c * ys[i]);
	return p;
}

/* The corners the controller pushes to, in order (probe.c): a quarter, and half. */
static const Vec2 quarter[3] = {{0.25, 0.25}, {-0.25, -0.25}, {0.25, -0.25}};
static const Vec2 half[3] = {{PROBE_HALF_STEP, PROBE_HALF_STEP},
			     {-PROBE_HALF_STEP, -PROBE_HALF_STEP},
			     {PROBE_HALF_STEP, -PROBE_HALF_STEP}};

/* owned(p, dx, dy, mark): the squares p owns moved by (dx, dy), into mark. */
static int32_t owned(const Polygon *p, double dx, double dy, uint8_t *mark)
{
	Polygon q = moved(p, dx, dy);
	sq_n = 0;
	geom_project(&q, FIELD, FIELD, span, NULL);
	memset(mark, 0, MOST);
	for (int32_t i = 0; i < sq_n; i++)
		mark[sq_y[i] * FIELD + sq_x[i]] = 1;
	return sq_n;
}

TEST_CASE(quarter_blind_half_rejects_brick)
{
	static uint8_t before[MOST], after[MOST];
	uint64_t seed = 29;
	for (int i = 0; i < 12; i++) {
		/* Edges 0.27 to 0.73 into their squares; Utak's point anywhere. */
		double fx = 0.27 + 0.46 * uniform(&seed), fy = 0.27 + 0.46 * uniform(&seed);
		bool tall = i % 2;
		Polygon p = rect(tall ? 2 : 4, tall ? 4 : 2, 0, 30 + fx + (tall ? 1 : 2), 30 + fy + (tall ? 2 : 1));
		Vec2 f = vec2(uniform(&seed), uniform(&seed));
		owned(&p, 0, 0, before);
		int moved_half = 0;
		for (int k = 0; k < 3; k++) {
			owned(&p, quarter[k].x, quarter[k].y, after);
			TEST_CHECK(memcmp(before, after, MOST) == 0);
			owned(&p, half[k].x, half[k].y, after);
			moved_half += memcmp(before, after, MOST) != 0;
		}
		TEST_CHECK(moved_half > 0);
		observe(&p, half, 3, 0, f, 1, &seed);
		TEST_CHECK(probe_square_consistent(bx, by, nb, looks, 3, cells, nc, true, BUDGET) ==
			   PROBE_INCONSISTENT);
	}
}

TEST_CASE(true_squares_never_rejected_by_half)
{
	uint64_t seed = 30;
	for (int deg = 0; deg < 90; deg += 15)
		for (int k = 0; k < 4; k++) {
			double side = 2.0 + 0.4 * k, aspect = k % 2 ? 1.17 : 1.0;
			Polygon p = rect(side, side * aspect, deg, 30.2 + 0.17 * k + 0.05 * deg / 15,
					 30.6 - 0.13 * k + 0.03 * deg / 15);
			Vec2 f = vec2(uniform(&seed), uniform(&seed));
			double sigma = k < 2 ? 0 : 0.05;
			observe(&p, half, 3, sigma, f, k == 3 ? 2 : 1, &seed);
			TEST_CHECK(probe_square_consistent(bx, by, nb, looks, 3, cells, nc, true, BUDGET) !=
				   PROBE_INCONSISTENT);
		}
}

int main(void)
{
	TEST_RUN(quarter_blind_half_rejects_brick);
	TEST_RUN(true_squares_never_rejected_by_half);
	return TEST_EXIT();
}
