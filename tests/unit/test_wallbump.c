/* test_wallbump.c - before a push into a corner, a corner of the wall toward it
 * that may be an object pressed into it is felt, hands free (wallbump.h,
 * wallbump_corner_look; paper 3.4.2, task (v)).
 *
 * THE ORACLE is the simulator and the judge (judge.h: their own code, from the
 * real world; a test may see both sides). Whole runs of the action cycle, as
 * main.c drives them, of "push square ne-corner" on two rooms joined by a door in
 * a wall 2 thick (as worlds/square-roomy.w): Utak faces east, so his north-east
 * corner is the table's south-east corner of the start's room, beside the door's
 * south jamb, whose end is a corner of the wall toward it. The square (3 x 3) at
 * several places in the start's room; a brick pressed into the corner, or against
 * the jamb's end, or neither; two door widths.
 *  - The property: no claim the judge rejects (no false success), trip or not.
 *  - The trip is at work: some runs set off to feel such a corner and then claim
 *    the corner, achieved (without the trip each of them ended in the doubt
 *    "a corner of the wall toward it ... not felt": tests/golden/push-jamb-felt).
 *  - Touch is what lifts it: where a brick leans on the jamb's end, touch there
 *    feels its letter, and no such run claims a corner the judge rejects. */
#include <stdio.h>

#include "test.h"
#include "world_fixture.h"
#include "task_run.h"

TEST_CASE(a_trip_never_buys_a_false_success)
{
	static const int square_at[][2] = {{10, 6}, {6, 10}, {16, 6}, {12, 4}};
	static const char *brick[] = {"", "object brick C 19 1 24 1 24 3 19 3\n", "object brick C 20 8 24 8 24 10 20 10\n"};
	static const int door[] = {8, 6};
	int runs = 0, tripped = 0, claimed_after = 0, false_successes = 0;
	for (int di = 0; di < 2; di++)
		for (int bi = 0; bi < 3; bi++)
			for (int si = 0; si < 4; si++) {
				int x = square_at[si][0], y = square_at[si][1], lo = 15 - door[di] / 2, hi = lo + door[di];
				char text[512];
				snprintf(text, sizeof text,
					 "table 50 30\nwall 24 1 26 1 26 %d 24 %d\nwall 24 %d 26 %d 26 29 24 29\n"
					 "object square A %d %d %d %d %d %d %d %d\n%sutak 8.5 15.5 east\n",
					 lo, lo, hi, hi, x, y, x + 3, y, x + 3, y + 3, x, y + 3, brick[bi]);
				Outcome o = run(text, "push square ne-corner");
				runs++;
				if (o.believed && !o.achieved) {
					false_successes++;
					fprintf(stderr, "  false success (%d trips):\n%s", o.bump_trips, text);
				}
				if (o.bump_trips == 0)
					continue;
				tripped++;
				claimed_after += o.believed && o.achieved;
			}
	TEST_CHECK(runs == 24);
	TEST_CHECK(false_successes == 0);
	fprintf(stderr, "  %d runs, %d with a trip, %d claimed and achieved after one\n", runs, tripped, claimed_after);
	TEST_CHECK(claimed_after >= 3);
}

int main(void)
{
	(void)act; /* world_fixture.h's, not needed here */
	TEST_RUN(a_trip_never_buys_a_false_success);
	return TEST_EXIT();
}
