/* test_doorlook.c - a look at the squares that can settle doorsure's doubt of a
 * corner, before the doubt (doorlook.h; paper 2.3 task (i), 3.4).
 *
 * THE ORACLE is the simulator and the judge (judge.h, judgerooms.h: their own code,
 * from the real world; a test may see both sides). Whole runs of the action cycle
 * (the body senses and moves, the controller decides, as main.c drives them) on the
 * simplest two-room worlds: a 40 x 30 TABLE cut by a wall 1 or 2 thick across at
 * row 18, a door 4 to 6 wide at two places, Utak at (15.5, 7.5) facing north or
 * west, "go nw-corner" and "go sw-corner".
 *  - The property: every run in which Utak set off on a look of doorlook.h and then
 *    claimed the corner is achieved by the judge (a look never buys a false
 *    success). Runs without a look are doorsure's as before (its own test and
 *    tests/doors.test.sh hold them).
 *  - The look is at work: some runs claim, achieved, after a look (without it each
 *    of them ended in doorsure's doubt), and every claim after a look was made
 *    with each look set off on reached (doorlook.h, SAFETY). */
#include <stdio.h>

#include "test.h"
#include "world_fixture.h"
#include "task_run.h"

TEST_CASE(a_look_never_buys_a_false_success)
{
	static const char *heading[] = {"north", "west"}, *corner[] = {"go nw-corner", "go sw-corner"};
	static const int door_x[] = {5, 15};
	int runs = 0, looked = 0, claimed_after = 0;
	for (int th = 1; th <= 2; th++)
		for (int dw = 4; dw <= 6; dw++)
			for (int xi = 0; xi < 2; xi++)
				for (int hi = 0; hi < 2; hi++)
					for (int ci = 0; ci < 2; ci++) {
						int x0 = door_x[xi];
						char text[512];
						snprintf(text, sizeof text,
							 "table 40 30\nwall 1 18 %d 18 %d %d 1 %d\nwall %d 18 39 18 39 %d %d %d\n"
							 "utak 15.5 7.5 %s\n",
							 x0, x0, 18 + th, 18 + th, x0 + dw, 18 + th, x0 + dw, 18 + th, heading[hi]);
						Outcome o = run(text, corner[ci]);
						runs++;
						if (o.door_looks == 0)
							continue;
						looked++;
						if (!o.believed)
							continue;
						if (!o.achieved)
							fprintf(stderr, "  false success after a look: %s on\n%s", corner[ci], text);
						TEST_CHECK(o.achieved);
						TEST_CHECK(!o.door_look_pending);
						claimed_after += o.achieved;
					}
	TEST_CHECK(runs == 48);
	fprintf(stderr, "  %d runs, %d with a look, %d claimed and achieved after one\n", runs, looked, claimed_after);
	TEST_CHECK(claimed_after >= 4);
}

int main(void)
{
	(void)act; /* world_fixture.h's, not needed here */
	TEST_RUN(a_look_never_buys_a_false_success);
	return TEST_EXIT();
}
