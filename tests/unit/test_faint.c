/* test_faint.c - FAINT (faint.h; paper 3.4.2, only a zero cell is floorspace;
 * issue 13, an honest belief): a square of the judge's sizes seen only by the eye's
 * coarse cells never leaves the world model with nothing to say it is there.
 *
 * THE ORACLE is the simulator: a world of one square alone on the floor, at a
 * random size from 2.1 to 4.5, angle and phase, in the eye's coarse zones (clear of
 * the fovea), sensed by the retina (retina_sense, the TABLE's own squares), and
 * the model's first accommodation to that impression. Of the squares the TABLE
 * gives the object, at least one must be believed occupied on the screen, or be
 * marked by faint_marks (faint, in a set of its own). Before faint.h a square 3
 * wide over four cells of 4 left every square of them floor, and nothing asked
 * about them (tests/worlds/faint-nearer.w, a false success).
 *
 * And the LIMIT faint.h states, shown on the same simulator: a square exactly 2
 * wide on the corner four cells of 4 share leaves one occupied square in each,
 * every cell reads zero, and the model keeps no trace of it. This test is a
 * helper that sees both sides of the wall (as test_hallsplit.c). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "first_look.h"
#include "test.h"
#include "utak/base/eye.h"
#include "utak/base/geom.h"
#include "utak/body/retina.h"
#include "utak/body/table.h"
#include "utak/body/world.h"
#include "utak/mind/faint.h"
#include "utak/mind/screen.h"
#include "utak/mind/worldmodel.h"

static uint64_t rng = 0x2545f4914f6cdd1du;

static double uniform(void)
{
	return xorshift_uniform(&rng);
}

/* Utak stands on square (40, 40) facing north: his model's frame is the TABLE's,
 * moved by (40, 40) (the origin is the lower-left corner of his first square). */
enum { UX = 40, UY = 40 };

typedef struct Seen {
	int owned;    /* squares the TABLE gives the object */
	int occupied; /* of them, believed occupied on the screen */
	int faint;    /* of them, marked by faint_marks */
} Seen;

/* sense(text): the object's squares as the model holds them after the first
 * impression of the world text. */
static Seen sense(const char *text)
{
	World w;
	Table t;
	Seen out = {0};
	WorldModel m;
	Impression imp;
	first_look(text, &w, &t, &m, &imp);
	Screen s;
	screen_init(&s);
	screen_build(&s, &m, NULL, 0);
	uint8_t *mark = faint_marks(&m, &s, vec2(0, 0), INFINITY);
	for (int32_t y = 0; y < t.h; y++)
		for (int32_t x = 0; x < t.w; x++) {
			if (table_owner(&t, x, y) <= TABLE_VERGE)
				continue;
			out.owned++;
			int32_t i = x - UX - s.x0, j = y - UY - s.y0;
			if (i < 0 || j < 0 || i >= s.w || j >= s.h)
				continue;
			int32_t label = s.label[(int64_t)j * s.w + i];
			out.occupied += label >= 0 || label == SCREEN_VERGE;
			out.faint += mark[(int64_t)j * s.w + i];
		}
	free(mark);
	screen_free(&s);
	worldmodel_free(&m);
	table_free(&t);
	world_free(&w);
	return out;
}

TEST_CASE(no_square_of_the_judges_sizes_vanishes_in_coarse_cells)
{
	int only_faint = 0, trials = 400;
	for (int trial = 0; trial < trials; trial++) {
		double side = 2.1 + 2.4 * uniform(), deg = 90 * uniform(), r = side * sqrt(0.5);
		/* its centre in the coarse zones (offsets -16..15 from Utak's square),
		 * wholly clear of the fovea (-4..3) and inside the field */
		double cx, cy;
		do {
			cx = -15 + r + (30 - 2 * r) * uniform();
			cy = -15 + r + (30 - 2 * r) * uniform();
		} while (fabs(cx + 0.5) < 4.5 + r && fabs(cy + 0.5) < 4.5 + r);
		double c, sn, h = side / 2;
		geom_cos_sin(deg, &c, &sn);
		char text[400];
		int len = snprintf(text, sizeof text, "table 80 80\nobject sq A");
		for (int k = 0; k < 4; k++) {
			double px = (k == 1 || k == 2) ? h : -h, py = k >= 2 ? h : -h;
			len += snprintf(text + len, sizeof text - (size_t)len, " %.4f %.4f", UX + 0.5 + cx + c * px - sn * py,
					UY + 0.5 + cy + sn * px + c * py);
		}
		snprintf(text + len, sizeof text - (size_t)len, "\nutak %d.5 %d.5 north\n", UX, UY);
		Seen seen = sense(text);
		TEST_CHECK(seen.owned >= 4);
		if (seen.occupied == 0 && seen.faint == 0)
			fprintf(stderr, "  vanished: side %.2f, %.1f degrees, centre offset (%.2f, %.2f)\n", side, deg, cx, cy);
		TEST_CHECK(seen.occupied > 0 || seen.faint > 0);
		only_faint += seen.occupied == 0 && seen.faint > 0;
	}
	/* The case is not empty: some squares were held only faint. */
	printf("  squares held by no occupied square, only faint: %d of %d\n", only_faint, trials);
	TEST_CHECK(only_faint > 0);
}

TEST_CASE(a_square_two_wide_on_four_cells_corner_leaves_no_trace)
{
	/* The peripheral cells of 4 lie at offsets -16, -12, ..., 12 from Utak's
	 * square (eye.h), so the corner at offset (-12, -12) is shared by four of
	 * them; a square from (-13, -13) to (-11, -11) puts one square in each. */
	char text[200];
	snprintf(text, sizeof text, "table 80 80\nobject sq A %d %d %d %d %d %d %d %d\nutak %d.5 %d.5 north\n", UX - 13,
		 UY - 13, UX - 11, UY - 13, UX - 11, UY - 11, UX - 13, UY - 11, UX, UY);
	Seen seen = sense(text);
	TEST_CHECK(seen.owned == 4);
	TEST_CHECK(seen.occupied == 0 && seen.faint == 0);
}

int main(void)
{
	TEST_RUN(no_square_of_the_judges_sizes_vanishes_in_coarse_cells);
	TEST_RUN(a_square_two_wide_on_four_cells_corner_leaves_no_trace);
	return TEST_EXIT();
}
