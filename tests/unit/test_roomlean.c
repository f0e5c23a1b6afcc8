/* test_roomlean.c - a door a claim rests on whose jamb may be an object leaning on the
 * wall (roomlean.h; paper 3.4.2, 2.3 tasks (i) and (ii)).
 *
 * THE ORACLE is the simulator and the judge (judge.h, judgerooms.h: their own code,
 * from the real world; a test may see both sides). Whole runs of the action cycle
 * (the body senses and moves, the controller decides, as main.c drives them) on
 * generated worlds: a wall across the TABLE with a gap, and a square flush against
 * the verge on Utak's side, narrowing the space so that Utak's model (which reads it
 * as verge) keeps a door there that the judge (which counts objects as space) does
 * not. The property: Utak never believes a task done that the judge says is not (no
 * false success). The worlds are ones where the rule is at work: Utak ends
 * doubting by roomlean's rule (touch felt the square's letter at a jamb) in most of
 * them, so the property is not met by the rule never firing, and without the rule
 * it fails (each "go ne-corner" there was a false success).
 * And the converse: a true door (both rooms wide by the judge's rule, its jambs
 * wall) is still one: "go next-room" and "go ne-corner" are claimed and achieved
 * after the jambs are touched. */
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "world_fixture.h"
#include "task_run.h"
#include "utak/mind/controller.h"

/* lean_world(text, size, gap, brick_x, ux): a 30 x 20 TABLE, a wall 1 thick across at
 * row 9 with a gap `gap` wide in its middle, a 6 x 6 square flush against the south
 * verge at column brick_x whose top leaves a passage 2 wide under the wall, and Utak
 * at column ux east of it, in the pocket (tests/worlds/lean-pocket.w's kind). */
static void lean_world(char *text, size_t size, int gap, int brick_x, int ux)
{
	int gx = (30 - gap) / 2;
	snprintf(text, size,
		 "table 30 20\nwall 1 9 %d 9 %d 10 1 10\nwall %d 9 29 9 29 10 %d 10\nobject sq A %d 1 %d 1 %d 7 %d 7\n"
		 "utak %d.5 4.5 north\n",
		 gx, gx, gx + gap, gx + gap, brick_x, brick_x + 6, brick_x + 6, brick_x, ux);
}

TEST_CASE(no_false_success_where_a_brick_leans_on_the_wall)
{
	/* Gaps 5 to 7: the judge finds one room (the strip above does not widen
	 * enough beyond the gap), Utak's model a pocket behind a door 2 wide over
	 * the square. Before roomlean.h every one of these runs of "go ne-corner"
	 * was a false success (the pocket's corner, 10 short), and "go next-room"
	 * too where he went past the square. The square's top is within
	 * ROOMLEAN_REACH of the pocket's corner: he touches it and doubts. (Started
	 * farther east, or with the square a square west, the square's top is not
	 * the jamb his model's door ends on, or no door is on his model at all, and
	 * some runs still claim: README, Reliability.) */
	static const char *tasks[] = {"go ne-corner", "go next-room"};
	int doubted = 0, runs = 0;
	for (int gap = 5; gap <= 7; gap++)
		for (int t = 0; t < 2; t++) {
			char text[512];
			lean_world(text, sizeof text, gap, 18, 25);
			Outcome o = run(text, tasks[t]);
			runs++;
			if (o.believed && !o.achieved)
				fprintf(stderr, "  false success: %s on\n%s", tasks[t], text);
			TEST_CHECK(!o.believed || o.achieved);
			doubted += strstr(o.why, "touch felt an object's colour on its jamb") != NULL;
		}
	TEST_CHECK(runs == 6);
	TEST_CHECK(doubted >= 3);
}

TEST_CASE(a_true_door_is_still_a_door)
{
	/* Two rooms, each far wider than the door 4 wide between them: the judge
	 * keeps it, and so must Utak once touch has felt B on its jambs. */
	const char *text = "table 40 20\nwall 19 1 21 1 21 8 19 8\nwall 19 12 21 12 21 19 19 19\nutak 5.5 5.5 north\n";
	Outcome next = run(text, "go next-room");
	TEST_CHECK(next.achieved && next.believed);
	Outcome corner = run(text, "go ne-corner");
	TEST_CHECK(corner.achieved && corner.believed);
}

int main(void)
{
	(void)act; /* world_fixture.h's, not needed here */
	TEST_RUN(no_false_success_where_a_brick_leans_on_the_wall);
	TEST_RUN(a_true_door_is_still_a_door);
	return TEST_EXIT();
}
