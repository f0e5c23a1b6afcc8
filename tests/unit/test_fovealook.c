/* test_fovealook.c - where to stand so that the fovea shows a square (fovealook.h;
 * paper 2.2, 3.3).
 *
 * THE ORACLE is the eye's own layout (eye.h: eye_cell_at names the cell that
 * covers an offset, eye_cell its zone), not fovealook.c's window of places: by
 * brute force over EVERY cell of the screen, the places Utak can reach (dist >= 0)
 * from which the square's offset lies in a foveal cell; of those the one whose
 * fovea (again by eye_cell_at) holds the most marked squares, then the nearest
 * by dist, then the first in the screen's order. fovealook_place must choose that
 * very cell, and say there is none exactly when there is none. Random screens
 * (sizes, origins, unreachable cells, ways, marked squares) from a fixed seed. */
#include <stdlib.h>

#include "first_look.h"
#include "test.h"
#include "utak/base/eye.h"
#include "utak/mind/fovealook.h"

/* Marked squares (the "still to be seen"), in a box of model squares. */
typedef struct Marks {
	int32_t x0, y0, w, h;
	const uint8_t *on;
} Marks;

static bool marked(const Marks *mk, int32_t x, int32_t y)
{
	int32_t i = x - mk->x0, j = y - mk->y0;
	return i >= 0 && j >= 0 && i < mk->w && j < mk->h && mk->on[j * mk->w + i];
}

/* in_fovea(px, py, x, y): Utak on square (px, py) sees square (x, y) in a foveal
 * cell (eye.h's layout). */
static bool in_fovea(int32_t px, int32_t py, int32_t x, int32_t y)
{
	int32_t cell = eye_cell_at(x - px, y - py);
	return cell >= 0 && eye_cell(cell).zone == EYE_FOVEA;
}

/* count(ctx, px, py): the marked squares the fovea holds from (px, py), by
 * eye_cell_at over the whole field. */
static int32_t count(void *ctx, int32_t px, int32_t py)
{
	const Marks *mk = ctx;
	int32_t n = 0;
	for (int32_t y = mk->y0; y < mk->y0 + mk->h; y++)
		for (int32_t x = mk->x0; x < mk->x0 + mk->w; x++)
			n += marked(mk, x, y) && in_fovea(px, py, x, y);
	return n;
}

TEST_CASE(the_place_is_the_brute_force_one)
{
	uint64_t seed = 0x9e3779b97f4a7c15u;
	int found = 0, none = 0;
	for (int trial = 0; trial < 400; trial++) {
		Screen s;
		s.w = 4 + (int32_t)(xorshift_uniform(&seed) * 30);
		s.h = 4 + (int32_t)(xorshift_uniform(&seed) * 30);
		s.x0 = (int32_t)(xorshift_uniform(&seed) * 40) - 20;
		s.y0 = (int32_t)(xorshift_uniform(&seed) * 40) - 20;
		int32_t *dist = malloc(sizeof *dist * (size_t)(s.w * s.h));
		double blocked = xorshift_uniform(&seed);
		for (int32_t at = 0; at < s.w * s.h; at++)
			dist[at] = xorshift_uniform(&seed) < blocked ? -1 : (int32_t)(xorshift_uniform(&seed) * 12);
		/* The square: anywhere on the screen or up to 6 beyond it. */
		int32_t x = s.x0 - 6 + (int32_t)(xorshift_uniform(&seed) * (s.w + 12));
		int32_t y = s.y0 - 6 + (int32_t)(xorshift_uniform(&seed) * (s.h + 12));
		uint8_t on[24 * 24];
		Marks mk = {x - 12, y - 12, 24, 24, on};
		double dense = xorshift_uniform(&seed) * 0.3;
		for (int i = 0; i < 24 * 24; i++)
			on[i] = xorshift_uniform(&seed) < dense;
		bool counted = trial % 4 != 0; /* a quarter with no count: nearest only */
		int32_t best = -1, best_n = 0, best_d = 0;
		for (int32_t at = 0; at < s.w * s.h; at++) {
			int32_t px = s.x0 + at % s.w, py = s.y0 + at / s.w;
			if (dist[at] < 0 || !in_fovea(px, py, x, y))
				continue;
			int32_t n = counted ? count(&mk, px, py) : 0;
			if (best < 0 || n > best_n || (n == best_n && dist[at] < best_d)) {
				best = at;
				best_n = n;
				best_d = dist[at];
			}
		}
		Vec2 goal = vec2(1e9, 1e9);
		bool ok = fovealook_place(&s, dist, x, y, counted ? count : NULL, &mk, &goal);
		TEST_CHECK(ok == (best >= 0));
		if (ok) {
			TEST_NEAR(goal.x, s.x0 + best % s.w + 0.5, 0);
			TEST_NEAR(goal.y, s.y0 + best / s.w + 0.5, 0);
			/* and from there the eye's fovea holds the square */
			TEST_CHECK(in_fovea((int32_t)(goal.x - 0.5), (int32_t)(goal.y - 0.5), x, y));
			found++;
		} else {
			TEST_NEAR(goal.x, 1e9, 0); /* untouched */
			none++;
		}
		free(dist);
	}
	/* Both outcomes were tried, many times. */
	TEST_CHECK(found > 100 && none > 20);
}

TEST_CASE(the_fovea_reaches_four_west_and_south_three_east_and_north)
{
	/* One row of reachable cells on a screen, the square in the middle: the
	 * places chosen with every other place blocked are exactly those at offsets
	 * -4..3 of it, the reach eye.h names (EYE_FOVEA_HALF). */
	Screen s = {0};
	s.x0 = -20;
	s.y0 = 0;
	s.w = 41;
	s.h = 1;
	int32_t dist[41];
	for (int32_t only = 0; only < 41; only++) {
		for (int32_t i = 0; i < 41; i++)
			dist[i] = i == only ? 0 : -1;
		Vec2 goal;
		bool ok = fovealook_place(&s, dist, 0, 0, NULL, NULL, &goal);
		int32_t px = s.x0 + only; /* Utak there sees square 0 at offset -px */
		TEST_CHECK(ok == (-px >= -EYE_FOVEA_HALF && -px < EYE_FOVEA_HALF));
		TEST_CHECK(ok == in_fovea(px, 0, 0, 0));
	}
}

int main(void)
{
	(void)first_look; /* first_look.h's; only its seeded draw is needed here */
	TEST_RUN(the_place_is_the_brute_force_one);
	TEST_RUN(the_fovea_reaches_four_west_and_south_three_east_and_north);
	return TEST_EXIT();
}
