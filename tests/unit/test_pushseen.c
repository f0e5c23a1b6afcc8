/* test_pushseen.c - what a cell's gray level tells of the squares under it
 * (pushseen.h; paper 3.4.1: a cell's level is how much of it is occupied; 2.3
 * task (v), the claim of a pushed object's place; issue 13 item 6, an honest
 * belief).
 *
 * pushseen_counts gives the least and most occupied squares a cell of n squares
 * may hold at a level, and pushseen_forced whether that level leaves none of its
 * squares free to be floor. THE ORACLE is brute force over every occupancy of the
 * cell's squares (all 2^n subsets, n = 1, 4 and 16: the fovea's, the intermediate
 * zone's and the periphery's cells), each given the level of paper 3.4.1 worked
 * out again in floating point (7 k / n rounded, halves up), not by eye_level:
 * the counts are the least and most squares of the subsets at that level, and a
 * square is forced when every subset at that level holds it.
 *
 * pushseen_beyond tells a square that lies farther toward a corner than every held
 * square (pushseen_felt_object: an object touch felt there, beyond the pushed one).
 * THE ORACLE is the room's own geometry: the corner is the point of the room's
 * bounding box at that corner, and a square is nearer it than another when the L1
 * distance from its centre to that point is less, worked out in floating point
 * over every square of a box and random held sets, for all four corners. */
#include <math.h>
#include <stdint.h>

#include "test.h"
#include "utak/mind/pushseen.h"

/* level_of(k, n): paper 3.4.1's gray level of k of n squares occupied, 0..7. */
static int level_of(int32_t k, int32_t n)
{
	return (int)floor(7.0 * k / n + 0.5);
}

TEST_CASE(pushseen_counts_and_forced_match_brute_force)
{
	static const int32_t sizes[3] = {1, 4, 16};
	int forced_levels = 0;
	for (int z = 0; z < 3; z++) {
		int32_t n = sizes[z];
		for (int level = 0; level <= 7; level++) {
			int32_t lo = -1, hi = -1;
			bool all_hold_first = true, any = false;
			for (uint32_t mask = 0; mask < (1u << n); mask++) {
				int32_t k = 0;
				for (int32_t b = 0; b < n; b++)
					k += (mask >> b) & 1u;
				if (level_of(k, n) != level)
					continue;
				any = true;
				lo = lo < 0 || k < lo ? k : lo;
				hi = k > hi ? k : hi;
				all_hold_first &= (mask & 1u) != 0;
			}
			int32_t kmin = -7, kmax = -7;
			bool got = pushseen_counts(level, n, &kmin, &kmax);
			TEST_CHECK(got == any);
			if (any)
				TEST_CHECK(kmin == lo && kmax == hi);
			else
				TEST_CHECK(kmin == -7 && kmax == -7); /* untouched */
			bool forced = any && all_hold_first;
			TEST_CHECK(pushseen_forced(level, n) == forced);
			forced_levels += forced;
		}
	}
	/* Level 7 of a 1 x 1 or 2 x 2 cell, and nothing else: 15 of 16 squares of a
	 * peripheral cell are level 7 as well. */
	TEST_CHECK(forced_levels == 2);
	TEST_CHECK(pushseen_forced(7, 1) && pushseen_forced(7, 4) && !pushseen_forced(7, 16));
	TEST_CHECK(!pushseen_forced(5, 4)); /* 3 of 4: which one is floor, the level cannot say */
}

/* rnd(state): a small deterministic generator (xorshift32). */
static uint32_t rnd(uint32_t *state)
{
	uint32_t x = *state;
	x ^= x << 13;
	x ^= x >> 17;
	x ^= x << 5;
	return *state = x;
}

TEST_CASE(pushseen_beyond_matches_distance_to_the_corner_point)
{
	static const Corner corners[4] = {CORNER_NE, CORNER_NW, CORNER_SE, CORNER_SW};
	/* The room's squares: x in [X0, X1], y in [Y0, Y1]; its corner points. */
	enum { X0 = -9, X1 = 12, Y0 = -7, Y1 = 10 };
	const double px[4] = {X1 + 1, X0, X1 + 1, X0}, py[4] = {Y1 + 1, Y1 + 1, Y0, Y0};
	uint32_t state = 2463534242u;
	int beyond = 0, not_beyond = 0;
	for (int trial = 0; trial < 400; trial++) {
		int32_t hx[12], hy[12], n = 1 + (int32_t)(rnd(&state) % 12);
		/* A held set: a random walk of 4-neighbours, an object's squares. */
		hx[0] = X0 + (int32_t)(rnd(&state) % (X1 - X0 + 1));
		hy[0] = Y0 + (int32_t)(rnd(&state) % (Y1 - Y0 + 1));
		for (int32_t k = 1; k < n; k++) {
			uint32_t d = rnd(&state) % 4;
			hx[k] = hx[k - 1] + (d == 0) - (d == 1);
			hy[k] = hy[k - 1] + (d == 2) - (d == 3);
			/* Within the room: its corner point bounds every square of it. */
			hx[k] = hx[k] < X0 ? X0 : hx[k] > X1 ? X1 : hx[k];
			hy[k] = hy[k] < Y0 ? Y0 : hy[k] > Y1 ? Y1 : hy[k];
		}
		for (int c = 0; c < 4; c++)
			for (int32_t y = Y0; y <= Y1; y++)
				for (int32_t x = X0; x <= X1; x++) {
					double d =
					    fabs(px[c] - (x + 0.5)) + fabs(py[c] - (y + 0.5));
					bool want = true;
					for (int32_t k = 0; k < n; k++)
						want &= d < fabs(px[c] - (hx[k] + 0.5)) +
						                fabs(py[c] - (hy[k] + 0.5)) - 1e-9;
					TEST_CHECK(pushseen_beyond(corners[c], hx, hy, n, x, y) ==
					           want);
					beyond += want;
					not_beyond += !want;
				}
	}
	TEST_CHECK(beyond > 1000 && not_beyond > 1000);               /* both answers were tried */
	TEST_CHECK(!pushseen_beyond(CORNER_NE, NULL, NULL, 0, 0, 0)); /* nothing held */
}

int main(void)
{
	TEST_RUN(pushseen_counts_and_forced_match_brute_force);
	TEST_RUN(pushseen_beyond_matches_distance_to_the_corner_point);
	return TEST_EXIT();
}
