/* test_pushturn.c - the turn that squares a held object up to a corner's walls
 * (pushturn.h; paper 2.2 the motor command turn, 2.3 task (v); issue 13, pushes
 * that stop short).
 *
 * pushturn_angle reads, from the squares a square or brick covers, the turn that
 * puts its sides along the axes. THE ORACLE is exact geometry: a square of side s
 * (4 to 8) or a brick (4 x 7) turned by a known angle a (0 to 89 degrees, every
 * degree) about a centre off the grid, digitised here by sampling each square on a
 * 16 x 16 grid of points against the exact polygon (not by geom.h's rule); the
 * true turn is -(a mod 90) or 90 - (a mod 90), the one of the two nearer zero.
 * Either turn squares it up near 45 degrees, so what is checked is the residual:
 * how far off the axes the sides lie after the turn. Checked: slanted 25 degrees
 * or more, a turn is given; within 2 degrees of the axes, none (PUSHTURN_MIN_DEG
 * 10); a turn given is at most 45 degrees, leaves the sides at most 12 degrees off
 * the axes (measured worst: 11, a 5-square side at 86 degrees read 15 off: the
 * staircase of a small square resolves no better) and, slanted 15 or more, less
 * off than before. A 4- or 5-square side 15 to 22 degrees off may read under
 * PUSHTURN_MIN_DEG and is left as it is. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "test.h"
#include "utak/mind/pushturn.h"

/* inside(px, py, c, s, a, l, w): point (px, py) lies inside the rectangle l x w
 * centred on c turned by a (cos c, sin s). */
static bool inside(double px, double py, double cx, double cy, double cs, double sn, double l, double w)
{
	double dx = px - cx, dy = py - cy;
	double u = cs * dx + sn * dy, v = -sn * dx + cs * dy;
	return fabs(u) < l / 2 && fabs(v) < w / 2;
}

/* digitise(l, w, deg, cx, cy, x, y): the squares the turned rectangle meets (any of
 * 16 x 16 sample points inside); returns their number. */
static int32_t digitise(double l, double w, double deg, double cx, double cy, int32_t *x, int32_t *y)
{
	double a = deg * 3.14159265358979323846 / 180.0, cs = cos(a), sn = sin(a);
	int32_t n = 0;
	for (int32_t j = (int32_t)floor(cy - l); j <= (int32_t)ceil(cy + l); j++)
		for (int32_t i = (int32_t)floor(cx - l); i <= (int32_t)ceil(cx + l); i++) {
			bool hit = false;
			for (int q = 0; q < 256 && !hit; q++)
				hit = inside(i + (q % 16 + 0.5) / 16, j + (q / 16 + 0.5) / 16, cx, cy, cs, sn, l, w);
			if (hit) {
				x[n] = i;
				y[n++] = j;
			}
		}
	return n;
}

TEST_CASE(pushturn_angle_squares_up_against_exact_geometry)
{
	int32_t *x = malloc(400 * sizeof *x), *y = malloc(400 * sizeof *y);
	TEST_CHECK(x && y);
	static const double sides[6][2] = {{4, 4}, {5, 5}, {6, 6}, {7, 7}, {8, 8}, {7, 4}};
	double worst = 0;
	for (int k = 0; k < 6; k++)
		for (int deg = 0; deg < 90; deg++) {
			double cx = 20.3 + 0.13 * (deg % 5), cy = 20.7 - 0.11 * (deg % 7);
			int32_t n = digitise(sides[k][0], sides[k][1], deg, cx, cy, x, y);
			double tilt = deg <= 45 ? deg : 90 - deg, got = 0;
			bool turn = pushturn_angle(x, y, n, &got);
			/* Where the turn leaves the sides: off the axes by the residual. */
			double residual = fmod(deg + got + 90 * 4 + 45, 90.0) - 45;
			if (tilt >= 25)
				TEST_CHECK(turn); /* slanted enough to cost a square: squared up */
			if (tilt <= 2)
				TEST_CHECK(!turn); /* along the axes: left alone */
			if (turn) {
				TEST_CHECK(fabs(got) <= 45);
				/* Better squared than before, by the staircase's error at worst. */
				TEST_CHECK(fabs(residual) <= 12);
				TEST_CHECK(tilt < 15 || fabs(residual) < tilt);
				worst = fmax(worst, fabs(residual));
			}
		}
	TEST_CHECK(worst > 0); /* the oracle is not the code's own reading */
	free(x);
	free(y);
}

int main(void)
{
	TEST_RUN(pushturn_angle_squares_up_against_exact_geometry);
	return TEST_EXIT();
}
