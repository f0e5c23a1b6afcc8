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
 * must cost what it says.
 *
 * FAINT's premise (hallsplit.h): a free-standing wall stub seen only by the 2 x 2
 * and 4 x 4 cells is read as floor where it fills under half a cell, but its
 * squares keep an occupancy above 0 ("faint") wherever the cell's level is not
 * zero; only a 4 x 4 cell holding a single occupied square reads zero. THE ORACLE
 * is the simulator's TABLE: for random stubs 1 to 3 thick and 2 to 16 long in the
 * eye's coarse zones, after Utak's first impression (facing north, so that his
 * frame is the TABLE's), every stub square the model reads as floor must be faint
 * exactly when its cell holds more occupied squares, by the TABLE, than round to
 * level 0, and a coarse square read as floor with no occupancy at all must lie in
 * a cell of at most one occupied square. This test is a helper that sees both sides
 * of the wall (as test_worldmodel.c).
 *
 * CLOSED (hallsplit.h): the never-seen cells beside the start's closed room, in
 * the order Utak tries to look at them, against brute force pushed from the
 * room's side (frontier_agrees_with_brute_force). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "first_look.h"
#include "test.h"
#include "utak/base/eye.h"
#include "utak/body/retina.h"
#include "utak/body/table.h"
#include "utak/body/world.h"
#include "utak/mind/hallsplit.h"
#include "utak/mind/worldmodel.h"

static uint64_t rng = 0x9e3779b97f4a7c15u;

static uint32_t next(void)
{
	return (uint32_t)(xorshift64(&rng) >> 11);
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

/* CLOSED's choice of where to look (hallsplit_frontier): THE ORACLE pushes from
 * the room's side instead of pulling from the unseen's: each reachable cell of the
 * room marks its four neighbours that are never seen with its steps (the least
 * kept), and the marked cells are picked out smallest (steps, index) first by a
 * plain scan; the sequence must be the function's, cell for cell, on random grids
 * of rooms, unseen cells and unreachable ones. */
TEST_CASE(frontier_agrees_with_brute_force)
{
	int64_t seen = 0;
	for (int t = 0; t < 300; t++) {
		int32_t w = 1 + (int32_t)(next() % 20), h = 1 + (int32_t)(next() % 20);
		int64_t n = (int64_t)w * h;
		bool *unknown = malloc((size_t)n * sizeof *unknown);
		int32_t *room = malloc((size_t)n * sizeof *room), *dist = malloc((size_t)n * sizeof *dist);
		int32_t *key = malloc((size_t)n * sizeof *key);
		int64_t *got = malloc((size_t)n * sizeof *got), *want = malloc((size_t)n * sizeof *want);
		uint32_t dark = next() % 70;
		for (int64_t q = 0; q < n; q++) {
			unknown[q] = next() % 100 < dark;
			room[q] = unknown[q] ? -1 : (int32_t)(next() % 4) - 1; /* -1 a door or wall, rooms 0..2 */
			dist[q] = next() % 5 == 0 ? -1 : (int32_t)(next() % 30);
			key[q] = INT32_MAX;
		}
		int32_t a = (int32_t)(next() % 3);
		for (int64_t r = 0; r < n; r++) {
			if (room[r] != a || dist[r] < 0)
				continue;
			int64_t nb[4] = {r % w > 0 ? r - 1 : -1, r % w < w - 1 ? r + 1 : -1, r >= w ? r - w : -1,
					 r + w < n ? r + w : -1};
			for (int k = 0; k < 4; k++)
				if (nb[k] >= 0 && unknown[nb[k]] && dist[r] < key[nb[k]])
					key[nb[k]] = dist[r];
		}
		int64_t m = 0;
		for (;;) {
			int64_t pick = -1;
			for (int64_t q = 0; q < n; q++)
				if (key[q] != INT32_MAX && (pick < 0 || key[q] < key[pick]))
					pick = q; /* the first of the least: the lowest index */
			if (pick < 0)
				break;
			want[m++] = pick;
			key[pick] = INT32_MAX;
		}
		int64_t k = hallsplit_frontier(w, h, unknown, room, a, dist, got);
		TEST_CHECK(k == m);
		for (int64_t i = 0; i < m && i < k; i++)
			TEST_CHECK(got[i] == want[i]);
		seen += m;
		free(want);
		free(got);
		free(key);
		free(dist);
		free(room);
		free(unknown);
	}
	TEST_CHECK(seen > 1000); /* grids with a frontier occur, not only empty ones */
}

TEST_CASE(faint_squares_cover_every_thin_stub_read_as_floor)
{
	int32_t floor_read = 0, faint = 0;
	for (int trial = 0; trial < 200; trial++) {
		/* Utak at (40.5, 40.5) facing north; a stub horizontal or vertical,
		 * 1 to 3 thick, 2 to 16 long, within the eye's field (offsets -16..15)
		 * and clear of the fovea and of Utak (offsets -5..4). */
		int32_t th = 1 + (int32_t)(next() % 3), len = 2 + (int32_t)(next() % 15);
		bool vertical = next() % 2;
		int32_t ox, oy, wx = vertical ? th : len, wy = vertical ? len : th;
		do {
			ox = -16 + (int32_t)(next() % (uint32_t)(32 - wx + 1));
			oy = -16 + (int32_t)(next() % (uint32_t)(32 - wy + 1));
		} while (ox < 5 && ox + wx > -5 && oy < 5 && oy + wy > -5);
		int32_t x0 = 40 + ox, y0 = 40 + oy, x1 = x0 + wx, y1 = y0 + wy;
		char text[256];
		snprintf(text, sizeof text, "table 80 80\nwall %d %d %d %d %d %d %d %d\nutak 40.5 40.5 north\n", x0, y0,
			 x1, y0, x1, y1, x0, y1);
		World w;
		Table t;
		WorldModel m;
		Impression imp;
		first_look(text, &w, &t, &m, &imp);
		for (int32_t i = 0; i < RETINA_CELLS; i++) {
			EyeCell c = eye_cell(i);
			if (c.zone == EYE_FOVEA)
				continue;
			int32_t occupied = 0, n = c.size * c.size;
			for (int32_t dy = 0; dy < c.size; dy++)
				for (int32_t dx = 0; dx < c.size; dx++)
					occupied += table_owner(&t, 40 + c.ox + dx, 40 + c.oy + dy) == TABLE_VERGE;
			for (int32_t dy = 0; dy < c.size; dy++)
				for (int32_t dx = 0; dx < c.size; dx++) {
					Evidence e = worldmodel_evidence(&m, c.ox + dx, c.oy + dy);
					TEST_CHECK(e.res == (c.zone == EYE_INTERMEDIATE ? WORLDMODEL_RES_INTERMEDIATE
											: WORLDMODEL_RES_PERIPHERAL));
					if (e.p >= 0.5f)
						continue;
					/* read as floor: faint exactly when the cell's level is not zero */
					TEST_CHECK((e.p > 0) == (eye_level(occupied, n) > 0));
					TEST_CHECK(e.p > 0 || occupied <= 1);
					if (table_owner(&t, 40 + c.ox + dx, 40 + c.oy + dy) == TABLE_VERGE) {
						floor_read++;
						faint += e.p > 0;
					}
				}
		}
		worldmodel_free(&m);
		table_free(&t);
		world_free(&w);
	}
	/* The case is not empty: thin stubs were read as floor, nearly all faint. */
	printf("  stub squares read as floor: %d, faint: %d\n", floor_read, faint);
	TEST_CHECK(floor_read > 100);
	TEST_CHECK(faint * 10 >= floor_read * 9);
}

int main(void)
{
	TEST_RUN(fewest_costly_cells_agrees_with_brute_force);
	TEST_RUN(fewest_refuses_what_is_not_passable);
	TEST_RUN(frontier_agrees_with_brute_force);
	TEST_RUN(faint_squares_cover_every_thin_stub_read_as_floor);
	return TEST_EXIT();
}
