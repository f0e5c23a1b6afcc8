/* test_seam.c - seam.h's doubt: the object Utak would claim as "the square" may be
 * pieces pressed together, and pushes both ways settle it with nothing fixed in view
 * (paper 3.4.2: the eye cannot part objects that touch; paper 2.2; issue 13).
 *
 * THE ORACLE is the simulator and the judge (judge.h: its own code, on the TRUE
 * polygons; a test may see both sides). Whole runs of the action cycle, as main.c
 * drives them:
 *   - PIECES ARE NEVER CLAIMED: a square's outline made of two bricks (split at the
 *     middle, either way, or two squares off one side), four small squares, or an L
 *     and a small square in its notch, on open floor, with no square in the world
 *     (pieces meet only along the squares' edges: the world refuses two objects on
 *     one square, so two triangles along a diagonal cannot be pressed together):
 *     for "go square", "go round square" and "push square ne-corner" Utak never
 *     believes the task done (before seam.h 14 of 18 runs on the first two pairs
 *     from three starts were false successes), and in most he finds there is no square, so the
 *     property is not met by his never finishing.
 *   - A LONE SQUARE IS CLAIMED: one square on open floor, at 0, 20 and 35 degrees,
 *     pushed both ways, fits one object after every push: claimed and achieved.
 *   - THE TEST ITSELF (seam_look_fits) against the simulator's own motion and eye:
 *     a lone square grasped and pushed two squares each way fits every look; two
 *     bricks pressed together, one grasped, do not fit the look after the push that
 *     moves it (the pull away from the other).
 *   - UNDER NOISY MOTION NO CLAIM RESTS ON THE PUSHES: square-tight.w's square (a
 *     square of side 4 in a room with a door of 5) under noise 0.05, seeds 1-10,
 *     "go square" and "go round square": never a false success, and most achieved
 *     and claimed. Before seam_felt_after, seeds 7 ("go square": the probe's last
 *     push left him a square off it, touch no longer feeling it) was one; without
 *     the round's gate on erring motion, seeds 5 and 9 ("go round square": home by
 *     a reckoning the pushes had left 1.6 off). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "world_fixture.h"
#include "task_run.h"
#include "utak/body/motion.h"
#include "utak/body/retina.h"
#include "utak/mind/controller.h"
#include "utak/mind/seam.h"

TEST_CASE(pieces_are_never_claimed)
{
	static const char *const pieces[] = {
	    /* two bricks, split at the middle across */
	    "object b1 C 10 10 16 10 16 13 10 13\nobject b2 D 10 13 16 13 16 16 10 16\n",
	    /* ... along */
	    "object b1 C 10 10 13 10 13 16 10 16\nobject b2 C 13 10 16 10 16 16 13 16\n",
	    /* ... 2 off one side */
	    "object b1 C 10 10 16 10 16 12 10 12\nobject b2 D 10 12 16 12 16 16 10 16\n",
	    /* four small squares */
	    "object q1 C 10 10 13 10 13 13 10 13\nobject q2 C 13 10 16 10 16 13 13 13\n"
	    "object q3 C 10 13 13 13 13 16 10 16\nobject q4 C 13 13 16 13 16 16 13 16\n",
	    /* an L and a small square in its notch */
	    "object l1 C 10 10 16 10 16 13 13 13 13 16 10 16\nobject q1 D 13 13 16 13 16 16 13 16\n",
	};
	static const char *const starts[] = {"utak 25.5 20.5 west\n", "utak 12.5 4.5 north\n"};
	static const char *const tasks[] = {"go square", "go round square", "push square ne-corner"};
	int runs = 0, found = 0;
	for (size_t p = 0; p < sizeof pieces / sizeof *pieces; p++)
		for (size_t t = 0; t < sizeof tasks / sizeof *tasks; t++) {
				char text[512];
				snprintf(text, sizeof text, "table 40 30\n%s%s", pieces[p], starts[(p + t) % 2]);
				Outcome o = run(text, tasks[t]);
				runs++;
				if (o.believed && !o.achieved)
					fprintf(stderr, "  false success: %s on\n%s", tasks[t], text);
				TEST_CHECK(!o.believed || o.achieved);
				found += !o.believed && strstr(o.why, "no square seen") != NULL;
		}
	TEST_CHECK(runs == 15);
	TEST_CHECK(found >= runs / 2);
}

TEST_CASE(a_lone_square_is_claimed)
{
	static const char *const squares[] = {
	    "object sq C 10 10 16 10 16 16 10 16\n",
	    "object sq C 12 9 17.638 11.052 15.586 16.69 9.948 14.638\n",
	    "object sq C 13 9 17.096 11.868 14.228 15.964 10.132 13.096\n",
	};
	for (size_t i = 0; i < sizeof squares / sizeof *squares; i++) {
		char text[256];
		snprintf(text, sizeof text, "table 40 30\n%sutak 25.5 20.5 west\n", squares[i]);
		Outcome o = run(text, "go square");
		if (!(o.achieved && o.believed))
			fprintf(stderr, "  not claimed (%s): %s", o.why, text);
		TEST_CHECK(o.achieved && o.believed);
	}
}

/* The table's squares: floor before the grasp (the test's floor_at). */
static bool table_floor(const void *ctx, int32_t x, int32_t y)
{
	const uint8_t *before = ctx;
	return x >= 0 && y >= 0 && x < 40 && y < 30 && before[y * 40 + x];
}

/* pushed_fits(text, sx, sy, n, dx, dy): on the world, Utak grasps what he touches and
 * pushes (dx, dy); does the look after fit one object of the squares S? S and the
 * floor before are the simulator's own (the TABLE), the look its retina. */
static bool pushed_fits(const char *text, const int32_t *sx, const int32_t *sy, int32_t n, double dx, double dy)
{
	load(text);
	uint8_t *before = calloc(40 * 30, 1);
	for (int32_t y = 0; y < 30; y++)
		for (int32_t x = 0; x < 40; x++)
			before[y * 40 + x] = table_colour(&table, &world, x, y) == '.';
	int32_t ox = (int32_t)floor(world.utak.x), oy = (int32_t)floor(world.utak.y);
	before[oy * 40 + ox] = 1; /* his own square: floor, as the model believes it */
	act(MOTOR_GRASP, 0, 0);
	act(MOTOR_PUSH, dx, dy);
	Impression imp;
	retina_sense(&world, &table, &imp);
	int32_t ux = (int32_t)floor(world.utak.x), uy = (int32_t)floor(world.utak.y);
	bool fits = seam_look_fits(sx, sy, n, ux - ox, uy - oy, ux, uy, &imp, table_floor, before);
	free(before);
	unload();
	return fits;
}

TEST_CASE(the_look_against_the_simulator)
{
	int32_t sx[36], sy[36], n = 0;
	for (int32_t y = 10; y < 16; y++)
		for (int32_t x = 10; x < 16; x++) {
			sx[n] = x;
			sy[n++] = y;
		}
	/* Utak below the block, touching it; heading north (his frame is the table's). */
	const char *lone = "table 40 30\nobject sq C 10 10 16 10 16 16 10 16\nutak 12.5 9.5 north\n";
	const char *pair = "table 40 30\nobject b1 C 10 10 16 10 16 13 10 13\nobject b2 D 10 13 16 13 16 16 10 16\n"
			   "utak 12.5 9.5 north\n";
	static const double way[4][2] = {{0, -2}, {0, 2}, {2, 0}, {-2, 0}};
	for (int w = 0; w < 4; w++)
		TEST_CHECK(pushed_fits(lone, sx, sy, n, way[w][0], way[w][1]));
	/* The pair: pulled down, b1 comes away and b2 stays: no one object. Pushed up,
	 * b1 halts against b2: nothing shows (the other way tells). Across, b1 slides
	 * along b2 and leaves it: no one object. */
	TEST_CHECK(!pushed_fits(pair, sx, sy, n, 0, -2));
	TEST_CHECK(pushed_fits(pair, sx, sy, n, 0, 2));
	TEST_CHECK(!pushed_fits(pair, sx, sy, n, 2, 0));
	TEST_CHECK(!pushed_fits(pair, sx, sy, n, -2, 0));
}

TEST_CASE(no_claim_rests_on_noisy_pushes)
{
	const char *text = "table 44 36\nwall 20 1 22 1 22 14 20 14\nwall 20 19 22 19 22 35 20 35\n"
			   "object square A 30 10 34 10 34 14 30 14\nutak 36.5 20.5 west\n";
	static const char *const tasks[] = {"go square", "go round square"};
	int runs = 0, claimed = 0;
	for (size_t t = 0; t < sizeof tasks / sizeof *tasks; t++)
		for (uint64_t seed = 1; seed <= 10; seed++) {
			Outcome o = run_noisy(text, tasks[t], 0.05, seed);
			runs++;
			if (o.believed && !o.achieved)
				fprintf(stderr, "  false success: %s, noise 0.05, seed %d: %s\n", tasks[t], (int)seed,
					o.why);
			TEST_CHECK(!o.believed || o.achieved);
			claimed += o.believed && o.achieved;
		}
	TEST_CHECK(runs == 20);
	TEST_CHECK(claimed >= 14);
}

int main(void)
{
	TEST_RUN(pieces_are_never_claimed);
	TEST_RUN(a_lone_square_is_claimed);
	TEST_RUN(the_look_against_the_simulator);
	TEST_RUN(no_claim_rests_on_noisy_pushes);
	return TEST_EXIT();
}
