/* test_widthprobe.c - probe.h's WIDTH ONLY: for "go brick", "go round brick", "push
 * brick CORNER" (and the L-shape and triangle), an object whose squares standing
 * still leave its width under 2 is pushed a quarter square three ways and looked at,
 * and its width alone is judged (paper 3.3: a shape read from squares is a
 * hypothesis until confirmed; issue 13 item 6: where his model cannot tell, he goes
 * and looks).
 *
 * WHY IT MATTERS. A brick 3 squares wide owns 3 rows of squares, and so does a
 * sliver 1.01 wide lying along the middle row with thin edges in the other two:
 * the verdicts name no polygon under 2 wide a brick (judgeshape.h). Before WIDTH
 * ONLY the probe was made for the square alone, so every brick 3 wide was doubted
 * ("too narrow to name"), the paper's own room.w brick (9 x 3) among them.
 *
 * THE ORACLE is the simulator and the judge, on the true polygons (task_run.h):
 *   - BRICKS 3 WIDE ARE MEASURED: bricks 3 wide, 7 to 9 long, on whole rows (6
 *     of them: 3 rows owned, the narrow doubt standing still) and on a fractional
 *     row, "push brick ne-corner": the doubt of the narrow polygon never ends a
 *     run (the looks show them 2 wide or more; before WIDTH ONLY it ended 3 of
 *     the 6), at least half are claimed (5 of 9: the rest doubt the corner,
 *     roomclaim.h, not the brick), and none is claimed where the judge says not
 *     achieved;
 *   - SLIVERS ARE NEVER NAMED: bars 1.2 to 1.6 wide and 8 long (the judge names
 *     them nothing: under 2 wide), "go brick" and "push brick ne-corner": never
 *     a claim. */
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "world_fixture.h"
#include "task_run.h"
#include "utak/mind/controller.h"

/* bar(text, size, x, y, w, h): a world with one w x h object at (x, y), Utak west of it. */
static void bar(char *text, size_t size, double x, double y, double w, double h)
{
	snprintf(text, size,
		 "table 40 30\n"
		 "object b C %.2f %.2f %.2f %.2f %.2f %.2f %.2f %.2f\n"
		 "utak 5.5 12.5 north\n",
		 x, y, x + w, y, x + w, y + h, x, y + h);
}

TEST_CASE(bricks_3_wide_are_measured)
{
	int runs = 0, claimed = 0, narrow = 0;
	/* Whole rows (3 of them: the narrow doubt standing still) at whole and half
	 * columns, and a fractional row (4 rows: no doubt to begin with). */
	static const double off[3][2] = {{0, 0}, {0.5, 0}, {0.3, 0.3}};
	for (int len = 7; len <= 9; len++)
		for (int i = 0; i < 3; i++) {
			char text[256];
			bar(text, sizeof text, 14 + off[i][0], 10 + off[i][1], len, 3);
			Outcome o = run(text, "push brick ne-corner");
			runs++;
			if (o.believed && !o.achieved)
				fprintf(stderr, "  false success on\n%s", text);
			TEST_CHECK(!o.believed || o.achieved);
			claimed += o.believed;
			narrow += strstr(o.why, "too narrow to name") != NULL;
		}
	fprintf(stderr, "  bricks 3 wide: %d runs, %d claimed, %d ended on the narrow doubt\n", runs, claimed, narrow);
	TEST_CHECK(narrow == 0);
	TEST_CHECK(claimed * 2 >= runs);
}

TEST_CASE(slivers_are_never_named)
{
	int runs = 0;
	static const double wide[] = {1.2, 1.4, 1.6};
	for (int i = 0; i < 3; i++)
		for (int t = 0; t < 2; t++) {
			char text[256];
			bar(text, sizeof text, 14.4, 10.3, 8, wide[i]);
			const char *task = t ? "push brick ne-corner" : "go brick";
			Outcome o = run(text, task);
			runs++;
			if (o.believed)
				fprintf(stderr, "  claimed a sliver: %s on\n%s", task, text);
			TEST_CHECK(!o.believed);
		}
	fprintf(stderr, "  slivers: %d runs, none claimed\n", runs);
}

int main(void)
{
	(void)act; /* world_fixture.h's, not needed here */
	TEST_RUN(bricks_3_wide_are_measured);
	TEST_RUN(slivers_are_never_named);
	return TEST_EXIT();
}
