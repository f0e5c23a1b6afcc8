/* test_eye.c - the eye's anatomy (eye.h): rounding, layout, adjacency, the picture. */
#include "test.h"
#include "utak/base/eye.h"

TEST_CASE(eye_level_rounds_halves_up)
{
	TEST_CHECK(eye_level(1, 16) == 0);
	TEST_CHECK(eye_level(15, 16) == 7);
	TEST_CHECK(eye_level(2, 4) == 4); /* 3.5 rounds up */
	TEST_CHECK(eye_level(0, 1) == 0 && eye_level(1, 1) == 7);
	TEST_CHECK(eye_level(1, 4) == 2 && eye_level(3, 4) == 5);
	TEST_CHECK(eye_level(8, 16) == 4 && eye_level(2, 16) == 1 && eye_level(16, 16) == 7);
	/* Brute-force oracle: round(7 o / t) with halves up, in doubles. */
	for (int t = 1; t <= 16; t *= 4)
		for (int o = 0; o <= t; o++)
			TEST_CHECK(eye_level(o, t) == (int)floor(7.0 * o / t + 0.5));
}

TEST_CASE(eye_layout_counts_and_cover)
{
	char why[128];
	TEST_CHECK(eye_validate(why, sizeof why));
	int zone[3] = {0, 0, 0};
	for (int i = 0; i < RETINA_CELLS; i++) {
		EyeCell c = eye_cell(i);
		zone[c.zone]++;
		TEST_CHECK(c.size == (c.zone == EYE_FOVEA          ? 1
		                      : c.zone == EYE_INTERMEDIATE ? 2
		                                                   : 4));
	}
	TEST_CHECK(zone[0] == 64 && zone[1] == 48 && zone[2] == 48);
	/* Every square of the 32 x 32 field is covered exactly once, by a cell that holds it. */
	for (int oy = -16; oy < 16; oy++)
		for (int ox = -16; ox < 16; ox++) {
			int n = 0;
			for (int i = 0; i < RETINA_CELLS; i++) {
				EyeCell c = eye_cell(i);
				n += ox >= c.ox && ox < c.ox + c.size && oy >= c.oy &&
				     oy < c.oy + c.size;
			}
			TEST_CHECK(n == 1);
			EyeCell c = eye_cell(eye_cell_at(ox, oy));
			TEST_CHECK(ox >= c.ox && ox < c.ox + c.size && oy >= c.oy &&
			           oy < c.oy + c.size);
		}
	TEST_CHECK(eye_cell_at(16, 0) == -1 && eye_cell_at(0, -17) == -1);
}

TEST_CASE(eye_cell_order_documented)
{
	EyeCell c = eye_cell(0);
	TEST_CHECK(c.ox == -4 && c.oy == 3 && c.size == 1);
	c = eye_cell(63);
	TEST_CHECK(c.ox == 3 && c.oy == -4 && c.size == 1);
	c = eye_cell(64);
	TEST_CHECK(c.ox == -8 && c.oy == 6 && c.size == 2);
	c = eye_cell(112);
	TEST_CHECK(c.ox == -16 && c.oy == 12 && c.size == 4);
	c = eye_cell(159);
	TEST_CHECK(c.ox == 12 && c.oy == -16 && c.size == 4);
	TEST_CHECK(eye_cell(eye_cell_at(0, 0)).zone == EYE_FOVEA);
	/* Offsets of the zones' inner and outer bounds. */
	TEST_CHECK(eye_cell(eye_cell_at(3, 3)).size == 1 && eye_cell(eye_cell_at(4, 3)).size == 2);
	TEST_CHECK(eye_cell(eye_cell_at(-5, 0)).ox == -6 && eye_cell(eye_cell_at(7, 7)).size == 2);
	TEST_CHECK(eye_cell(eye_cell_at(8, 0)).size == 4 &&
	           eye_cell(eye_cell_at(-9, -9)).oy == -12);
}

TEST_CASE(eye_adjacency_mixed_sizes)
{
	/* A foveal cell and the 2 x 2 cell beside it: full and partial shared edge. */
	TEST_CHECK(eye_adjacent(eye_cell_at(3, 0), eye_cell_at(4, 0)));
	TEST_CHECK(eye_adjacent(eye_cell_at(3, 1), eye_cell_at(4, 0)));
	TEST_CHECK(eye_adjacent(eye_cell_at(0, 3), eye_cell_at(0, 4)));
	/* A 2 x 2 cell and a 4 x 4 cell. */
	TEST_CHECK(eye_adjacent(eye_cell_at(6, 0), eye_cell_at(8, 0)));
	TEST_CHECK(eye_adjacent(eye_cell_at(6, 2), eye_cell_at(8, 0)));
	TEST_CHECK(eye_adjacent(eye_cell_at(-8, -8), eye_cell_at(-8, -12)));
	/* Diagonal neighbours are not adjacent. */
	TEST_CHECK(!eye_adjacent(eye_cell_at(3, 3), eye_cell_at(4, 4)));
	TEST_CHECK(!eye_adjacent(eye_cell_at(6, 6), eye_cell_at(8, 8)));
	TEST_CHECK(!eye_adjacent(eye_cell_at(-5, -5), eye_cell_at(-4, -4)));
	TEST_CHECK(!eye_adjacent(eye_cell_at(0, 0), eye_cell_at(1, 1)));
	TEST_CHECK(eye_adjacent(eye_cell_at(0, 0), eye_cell_at(1, 0)));
	/* Symmetry, and the oracle: adjacency by squares that share an edge. */
	for (int i = 0; i < RETINA_CELLS; i++)
		for (int j = 0; j < RETINA_CELLS; j++) {
			bool oracle = false;
			for (int oy = -16; oy < 16 && !oracle; oy++)
				for (int ox = -16; ox < 16 && !oracle; ox++)
					if (eye_cell_at(ox, oy) == i && i != j)
						oracle = eye_cell_at(ox + 1, oy) == j ||
						         eye_cell_at(ox - 1, oy) == j ||
						         eye_cell_at(ox, oy + 1) == j ||
						         eye_cell_at(ox, oy - 1) == j;
			TEST_CHECK(eye_adjacent(i, j) == oracle);
		}
}

TEST_CASE(eye_picture_frame)
{
	int32_t col, row, ox, oy;
	TEST_CHECK(eye_picture_of(0, 0, &col, &row) && col == 16 && row == 15);
	TEST_CHECK(eye_picture_of(-16, 15, &col, &row) && col == 0 && row == 0);
	eye_offset_of(31, 31, &ox, &oy);
	TEST_CHECK(ox == 15 && oy == -16);
	TEST_CHECK(eye_on_border(eye_cell_at(-16, 0)) && !eye_on_border(eye_cell_at(-12, 0)));
}

int main(void)
{
	TEST_RUN(eye_level_rounds_halves_up);
	TEST_RUN(eye_layout_counts_and_cover);
	TEST_RUN(eye_cell_order_documented);
	TEST_RUN(eye_adjacency_mixed_sizes);
	TEST_RUN(eye_picture_frame);
	return TEST_EXIT();
}
