/* test_hallsplit.c - the search behind a corner's look at the unseen (hallsplit.h,
 * LOOKING; paper 3.3 and 3.4.2: where the model cannot tell, Utak goes and looks;
 * issue 13 item 6).
 *
 * hallsplit_fewest finds, over the passable cells of a grid, the way from one cell
 * to another that enters the fewest costly cells (squares not seen in the fovea):
 * zero means the two join over what the eye has settled, and no look can part
 * them. THE ORACLE is brute force: every cell's least cost relaxed over its four
 * neighbours until nothing changes (Bellman-Ford, no queue, no levels), on random
 * grids of every density; and the way the search hands back is walked cell by cell
 * (each step to a 4-neighbour, each cell passable, its costly cells counted) and
 * must cost what it says. */
#include <stdint.h>
#include <stdlib.h>

#include "test.h"
#include "utak/mind/hallsplit.h"

static uint64_t rng = 0x9e3779b97f4a7c15u;

static uint32_t next(void)
{
	rng ^= rng << 13;
	rng ^= rng >> 7;
	rng ^= rng << 17;
	return (uint32_t)(rng >> 11);
}

/* brute(w, h, pass, costly, u, b): the least costly cells entered from u to b by
 * relaxing every cell against its neighbours until nothing changes; -1 if none. */
static int32_t brute(int32_t w, int32_t h, const bool *pass, const bool *costly, int64_t u, int64_t b)
{
	int64_t n = (int64_t)w * h;
	if (!pass[u] || !pass[b])
		return -1;
	int32_t *cost = malloc((size_t)n * sizeof *cost);
	for (int64_t q = 0; q < n; q++)
		cost[q] = INT32_MAX;
	cost[u] = 0;
	for (bool changed = true; changed;) {
		changed = false;
		for (int64_t q = 0; q < n; q++) {
			if (!pass[q] || q == u)
				continue;
			int32_t i = (int32_t)(q % w), j = (int32_t)(q / w);
			int64_t nb[4] = {i > 0 ? q - 1 : -1, i < w - 1 ? q + 1 : -1, j > 0 ? q - w : -1, j < h - 1 ? q + w : -1};
			for (int d = 0; d < 4; d++)
				if (nb[d] >= 0 && cost[nb[d]] != INT32_MAX && cost[nb[d]] + costly[q] < cost[q]) {
					cost[q] = cost[nb[d]] + costly[q];
					changed = true;
				}
		}
	}
	int32_t got = cost[b] == INT32_MAX ? -1 : cost[b];
	free(cost);
	return got;
}

TEST_CASE(fewest_costly_cells_agrees_with_brute_force)
{
	int joined = 0, free_ways = 0, costly_ways = 0;
	for (int t = 0; t < 400; t++) {
		int32_t w = 1 + (int32_t)(next() % 24), h = 1 + (int32_t)(next() % 24);
		int64_t n = (int64_t)w * h;
		uint32_t wall = next() % 60, dear = next() % 100; /* percent */
		bool *pass = malloc((size_t)n * sizeof *pass), *costly = malloc((size_t)n * sizeof *costly);
		int64_t *from = malloc((size_t)n * sizeof *from);
		for (int64_t q = 0; q < n; q++) {
			pass[q] = next() % 100 >= wall;
			costly[q] = next() % 100 < dear;
		}
		int64_t u = (int64_t)(next() % (uint32_t)n), b = (int64_t)(next() % (uint32_t)n);
		int32_t want = brute(w, h, pass, costly, u, b);
		int32_t got = hallsplit_fewest(w, h, pass, costly, u, b, from);
		TEST_CHECK(got == want);
		if (got >= 0) {
			/* the way back: adjacent passable cells from b to u, costing got */
			int32_t walked = 0, steps = 0;
			bool ok = true;
			for (int64_t q = b; q != u && ok && steps <= n; q = from[q], steps++) {
				int64_t p = from[q];
				ok = p >= 0 && p < n && pass[p] &&
				     ((p / w == q / w && (p - q == 1 || q - p == 1)) || p - q == w || q - p == w);
				walked += costly[q];
			}
			TEST_CHECK(ok && steps <= n);
			TEST_CHECK(walked == got);
			joined++;
			free_ways += got == 0;
			costly_ways += got > 0;
		}
		free(from);
		free(costly);
		free(pass);
	}
	/* the cases the search must tell apart all occur */
	TEST_CHECK(joined > 100 && free_ways > 20 && costly_ways > 20);
}

TEST_CASE(fewest_refuses_what_is_not_passable)
{
	bool pass[6] = {true, false, true, true, true, true}, costly[6] = {false, false, true, false, false, false};
	int64_t from[6];
	/* 3 x 2: the top row's middle blocked; the way from 0 to 2 goes round below */
	TEST_CHECK(hallsplit_fewest(3, 2, pass, costly, 0, 2, from) == 1);
	TEST_CHECK(hallsplit_fewest(3, 2, pass, costly, 0, 1, from) == -1);
	TEST_CHECK(hallsplit_fewest(3, 2, pass, costly, 0, 0, from) == 0);
	pass[3] = pass[4] = false;
	TEST_CHECK(hallsplit_fewest(3, 2, pass, costly, 0, 2, from) == -1);
}

int main(void)
{
	TEST_RUN(fewest_costly_cells_agrees_with_brute_force);
	TEST_RUN(fewest_refuses_what_is_not_passable);
	return TEST_EXIT();
}
