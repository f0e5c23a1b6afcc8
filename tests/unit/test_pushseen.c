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
 * square is forced when every subset at that level holds it. */
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

int main(void)
{
	TEST_RUN(pushseen_counts_and_forced_match_brute_force);
	return TEST_EXIT();
}
