/* test_motion.c - motion and collision (motion.h; paper 2.1, 2.2).
 *
 * Contact cases computed by hand, the exact quarter turn, and a property test:
 * 1,000 random command sequences on random worlds (fixed seed), checking the
 * TABLE's invariant after every command against the Cartesian shapes. */
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "world_fixture.h"
#include "utak/body/motion.h"
#include "utak/body/table.h"
#include "utak/body/world.h"


static double max_x(const Polygon *p)
{
	return geom_polygon_box(p).hi.x;
}

TEST_CASE(push_into_verge_halts_at_contact)
{
	/* The verge claims x >= 29 (default ring of a 30-wide TABLE). The square's
	 * right edge may reach x = 29 exactly and no farther. */
	load("table 30 20\nobject box A 10 8 14 8 14 12 10 12\nutak 9.5 10.5 north\n");
	TEST_CHECK(act(MOTOR_GRASP, 0, 0).refused == false);
	MotorOutcome out = act(MOTOR_PUSH, 20, 0);
	TEST_CHECK(out.halted && !out.refused);
	double right = max_x(&world.objects[0].shape);
	TEST_CHECK(right <= 29 && right > 29 - 0.5);
	TEST_NEAR(out.done, 15, 0.5);
	TEST_NEAR(world.utak.x - 9.5, right - 14, 1e-9); /* Utak moved with it, rigidly */
	unload();
}

TEST_CASE(push_into_object_halts_at_contact)
{
	load("table 40 20\nobject a A 10 8 14 8 14 12 10 12\nobject b C 20 9 24 9 24 11 20 11\n"
	     "utak 9.5 10.5 north\n");
	act(MOTOR_GRASP, 0, 0);
	MotorOutcome out = act(MOTOR_PUSH, 10, 0);
	TEST_CHECK(out.halted);
	TEST_CHECK(strstr(out.what, "'b'") != NULL);
	double gap = 20 - max_x(&world.objects[0].shape);
	TEST_CHECK(gap >= 0 && gap < 0.5);
	/* The other object did not move. */
	TEST_CHECK(world.objects[1].shape.v[0].x == 20 && world.objects[1].shape.v[0].y == 9);
	unload();
}

TEST_CASE(quarter_turn_is_exact)
{
	/* Utak at (10.5, 10.5) holds a bar to his east; a quarter turn puts it north. */
	load("table 30 30\nobject bar A 11 10 15 10 15 11 11 11\nutak 10.5 10.5 north\n");
	act(MOTOR_GRASP, 0, 0);
	MotorOutcome out = act(MOTOR_TURN, 90, 0);
	TEST_CHECK(!out.halted && !out.refused);
	TEST_NEAR(out.done, 90, 1e-12);
	const Polygon *p = &world.objects[0].shape;
	/* Rotation by +90 about (10.5, 10.5): (x, y) -> (10.5 - (y - 10.5), 10.5 + (x - 10.5)). */
	double want[4][2] = {{11, 11}, {11, 15}, {10, 15}, {10, 11}};
	for (int i = 0; i < 4; i++) {
		TEST_CHECK(p->v[i].x == want[i][0]);
		TEST_CHECK(p->v[i].y == want[i][1]);
	}
	unload();
}

TEST_CASE(turn_through_wall_is_halted)
{
	/* A wall just north of the bar's sweep: the bar, 6 long, cannot swing past it. */
	load("table 30 30\nwall 9 14 20 14 20 15 9 15\nobject bar A 11 10 17 10 17 11 11 11\n"
	     "utak 10.5 10.5 north\n");
	act(MOTOR_GRASP, 0, 0);
	MotorOutcome out = act(MOTOR_TURN, 90, 0);
	TEST_CHECK(out.halted);
	TEST_CHECK(out.done > 0 && out.done < 45);
	for (int i = 0; i < 4; i++)
		TEST_CHECK(world.objects[0].shape.v[i].y <= 14);
	unload();
}

TEST_CASE(refusals_change_nothing)
{
	load("table 30 30\nobject bar A 20 20 22 20 22 22 20 22\nutak 10.5 10.5 east\n");
	TEST_CHECK(act(MOTOR_GRASP, 0, 0).refused);
	TEST_CHECK(act(MOTOR_PUSH, 1, 0).refused);
	TEST_CHECK(act(MOTOR_TURN, 30, 0).refused);
	TEST_CHECK(act(MOTOR_RELEASE, 0, 0).refused);
	TEST_CHECK(world.utak.x == 10.5 && world.utak.y == 10.5 && world.held == -1);
	/* Facing east, "move 0 3" is three squares east; "move 2 0" two to his right: south. */
	act(MOTOR_MOVE, 0, 3);
	TEST_CHECK(world.utak.x == 13.5 && world.utak.y == 10.5);
	act(MOTOR_MOVE, 2, 0);
	TEST_CHECK(world.utak.x == 13.5 && world.utak.y == 8.5);
	unload();
}

TEST_CASE(move_into_object_halts)
{
	load("table 30 30\nobject box A 15 5 18 5 18 20 15 20\nutak 10.5 10.5 north\n");
	MotorOutcome out = act(MOTOR_MOVE, 10, 0);
	TEST_CHECK(out.halted);
	TEST_CHECK(world.utak.x < 15 && world.utak.x >= 14); /* his square is 14, next to the box */
	unload();
}

/* ---- the property test -------------------------------------------------------- */

static double frand(double lo, double hi) { return lo + (hi - lo) * (rand() / (double)RAND_MAX); }

static int random_world(char *buf, size_t size)
{
	int w = 30 + rand() % 20, h = 30 + rand() % 20;
	int n = snprintf(buf, size, "table %d %d\n", w, h);
	int objects = 2 + rand() % 5;
	for (int k = 0; k < objects; k++) {
		double cx = frand(6, w - 6), cy = frand(6, h - 6);
		int count = 3 + rand() % 6;
		n += snprintf(buf + n, size - (size_t)n, "object o%d %c", k, "ACDEFG"[k % 6]);
		for (int i = 0; i < count; i++) {
			double a = 6.283185307179586 * (i + frand(0, 0.6)) / count;
			double r = frand(0.6, 4);
			n += snprintf(buf + n, size - (size_t)n, " %.3f %.3f", cx + r * cos(a), cy + r * sin(a));
		}
		n += snprintf(buf + n, size - (size_t)n, "\n");
	}
	n += snprintf(buf + n, size - (size_t)n, "utak %.3f %.3f %s\n", frand(2, w - 2), frand(2, h - 2),
		      (const char *[]){"north", "east", "south", "west"}[rand() % 4]);
	return n;
}

static double edge_length(const Polygon *p, int i)
{
	Vec2 a = p->v[i], b = p->v[(i + 1) % p->count];
	return hypot(b.x - a.x, b.y - a.y);
}

TEST_CASE(random_sequences_keep_the_invariant)
{
	srand(2024);
	int sequences = 0, commands = 0, moved = 0;
	char text[4096];
	while (sequences < 1000) {
		random_world(text, sizeof text);
		Diag d;
		if (world_parse(&world, "random.w", text, strlen(text), &d))
			continue; /* a random polygon that is not simple */
		if (table_build(&table, &world, &d)) {
			world_free(&world); /* overlapping objects, or Utak inside one */
			continue;
		}
		sequences++;
		World start = world;
		start.objects = malloc(sizeof *start.objects * (size_t)world.object_count);
		memcpy(start.objects, world.objects, sizeof *start.objects * (size_t)world.object_count);
		for (int step = 0; step < 12; step++) {
			MotorCommand c = {.kind = (MotorKind)(rand() % 5)};
			c.dx = frand(-6, 6);
			c.dy = frand(-6, 6);
			c.deg = frand(-180, 180);
			/* Walk toward the nearest object now and then, so that grasps succeed. */
			if (rand() % 3 == 0 && world.held < 0) {
				c.kind = MOTOR_MOVE;
				Vec2 to = world.objects[rand() % world.object_count].shape.v[0];
				Vec2 dt = vec2_sub(to, world.utak);
				/* TABLE displacement back into his frame (inverse rotation). */
				Vec2 own = world.heading == HEADING_NORTH ? dt
					   : world.heading == HEADING_EAST ? vec2(-dt.y, dt.x)
					   : world.heading == HEADING_SOUTH ? vec2(-dt.x, -dt.y)
									    : vec2(dt.y, -dt.x);
				c.dx = own.x;
				c.dy = own.y;
			}
			int held = world.held;
			static Polygon before[8];
			for (int k = 0; k < world.object_count; k++)
				before[k] = world.objects[k].shape;
			MotorOutcome out;
			motion_execute(&world, &table, &c, &out);
			commands++;
			char why[128];
			bool ok = table_validate(&table, &world, why, sizeof why);
			if (!ok)
				fprintf(stderr, "  sequence %d, command %d: %s\n", sequences, step, why);
			TEST_CHECK(ok);
			for (int k = 0; k < world.object_count; k++) {
				const Polygon *p = &world.objects[k].shape, *p0 = &start.objects[k].shape;
				TEST_NEAR(geom_polygon_area(p), geom_polygon_area(p0), 1e-9);
				for (int i = 0; i < p->count; i++)
					TEST_NEAR(edge_length(p, i), edge_length(p0, i), 1e-9);
				if (k != held) /* only the held object ever moves */
					TEST_CHECK(memcmp(p, &before[k], sizeof *p) == 0);
				Box b = geom_polygon_box(p);
				TEST_CHECK(b.lo.x >= 1 && b.lo.y >= 1 && b.hi.x <= world.w - 1 && b.hi.y <= world.h - 1);
			}
			if (held >= 0 && (c.kind == MOTOR_PUSH || c.kind == MOTOR_TURN) && out.done != 0)
				moved++;
		}
		free(start.objects);
		unload();
	}
	TEST_CHECK(commands == 12000);
	/* The test means something only if objects did move. */
	printf("  %d sequences, %d commands, %d pushes or turns that moved an object\n", sequences,
	       commands, moved);
	TEST_CHECK(moved > 300);
}

int main(void)
{
	TEST_RUN(push_into_verge_halts_at_contact);
	TEST_RUN(push_into_object_halts_at_contact);
	TEST_RUN(quarter_turn_is_exact);
	TEST_RUN(turn_through_wall_is_halted);
	TEST_RUN(refusals_change_nothing);
	TEST_RUN(move_into_object_halts);
	TEST_RUN(random_sequences_keep_the_invariant);
	return TEST_EXIT();
}
