/* test_invariants.c - the simulator's invariants under random commands, the
 * regressions the fuzzers found, and the limits at their boundaries (paper 2.1:
 * objects never overlap and never leave the verge; issue 6).
 *
 * The property test drives 10,000 random command sequences on random worlds
 * (fixed seed: the same run every time) with walls, concave objects, a given
 * verge and every heading, and after every command checks tests/fuzz/invariants.h:
 * table_validate, the TABLE rebuilt from scratch square by square, shapes and
 * areas unchanged, only the held object moved, nothing outside the verge. */
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "../fuzz/invariants.h"
#include "test.h"
#include "world_fixture.h"
#include "utak/body/act.h"
#include "utak/body/motion.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

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

/* ---- limits at their boundaries (man utak.5 LIMITS, act.h) --------------------------- */

/* parses(text): world_parse accepts text; a failure's message is shown. */
static bool parses(const char *text)
{
	World w;
	Diag d;
	if (world_parse(&w, "limit.w", text, strlen(text), &d)) {
		fprintf(stderr, "  %s\n", d.msg);
		return false;
	}
	world_free(&w);
	return true;
}

TEST_CASE(limits_hold_at_the_boundary)
{
	/* One past each limit is a tests/bad case; here the limit itself loads. */
	static char text[8192];
	int n = snprintf(text, sizeof text, "table 100 100\nobject round A");
	for (int i = 0; i < GEOM_MAX_VERTICES; i++) {
		double a = 6.283185307179586 * i / GEOM_MAX_VERTICES;
		n += snprintf(text + n, sizeof text - (size_t)n, " %.3f %.3f", 50 + 20 * cos(a), 50 + 20 * sin(a));
	}
	snprintf(text + n, sizeof text - (size_t)n, "\nutak 5.5 5.5 north\n");
	TEST_CHECK(parses(text));
	TEST_CHECK(parses("table 20 20\nobject abcdefghijklmnopqrstuvwxyzabcde A 4 4 8 4 8 8\nutak 2.5 2.5 north\n"));
	n = snprintf(text, sizeof text, "table 20 20\n#");
	memset(text + n, 'x', WORLD_MAX_LINE - 1);
	snprintf(text + n + WORLD_MAX_LINE - 1, sizeof text - (size_t)n - WORLD_MAX_LINE + 1,
		 "\nutak 2.5 2.5 north\n");
	TEST_CHECK(parses(text));
	TEST_CHECK(parses("table 8192 4096\nutak 5.5 5.5 north\n"));
	TEST_CHECK(parses("table 4096 8192\nutak 5.5 5.5 north\n"));

	MotorCommand *cmds;
	int count;
	Diag d;
	TEST_CHECK(act_parse("move 1000000 -1000000; turn -1e6", 32, &cmds, &count, &d) == 0 && count == 2);
	free(cmds);
	/* act.h's 1 MiB script: too long for one command-line argument (128 KiB on
	 * Linux), so only act_parse can be given it. */
	char *big = malloc(ACT_MAX_BYTES + 1);
	memset(big, ';', ACT_MAX_BYTES + 1);
	TEST_CHECK(act_parse(big, ACT_MAX_BYTES, &cmds, &count, &d) == 0 && count == 0);
	free(cmds);
	TEST_CHECK(act_parse(big, ACT_MAX_BYTES + 1, &cmds, &count, &d) != 0 && cmds == NULL && count == 0);
	TEST_CHECK(strcmp(d.msg, "--act: script is over the limit of 1048576 bytes") == 0);
	free(big);
	/* An unknown command after good ones leaves no commands behind (fuzz_act). */
	TEST_CHECK(act_parse("move 1 1; jump 3", 16, &cmds, &count, &d) != 0 && cmds == NULL && count == 0);
}

/* ---- the property test ------------------------------------------------------------ */

/* A small linear congruential generator of our own, so that the sequence is the
 * same with every C library (rand() is not). */
static uint64_t rng_state;

static uint32_t rng_next(void)
{
	rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
	return (uint32_t)(rng_state >> 33);
}

static int rng_int(int n) { return (int)(rng_next() % (uint32_t)n); }
static double rng_real(double lo, double hi) { return lo + (hi - lo) * (rng_next() / 2147483648.0); }

/* put(buf, size, &n, fmt, ...): appends to a world file being written. */
static void put(char *buf, size_t size, int *n, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	*n += vsnprintf(buf + *n, size - (size_t)*n, fmt, ap);
	va_end(ap);
}

/* put_shape: one of three kinds, about (cx, cy): a random star-shaped polygon
 * (concave when its radii differ), an L or a U (concave), turned by a random angle. */
static void put_shape(char *buf, size_t size, int *n, double cx, double cy)
{
	static const double ell[6][2] = {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 4}, {0, 4}};
	static const double u[8][2] = {{0, 0}, {4, 0}, {4, 3}, {3, 3}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
	int kind = rng_int(4);
	double a = rng_real(0, 6.283185307179586), c = cos(a), s = sin(a);
	if (kind <= 1) {
		int count = 3 + rng_int(8);
		for (int i = 0; i < count; i++) {
			double t = 6.283185307179586 * (i + rng_real(0, 0.6)) / count, r = rng_real(0.7, 3.5);
			put(buf, size, n, " %.3f %.3f", cx + r * cos(t), cy + r * sin(t));
		}
		return;
	}
	const double(*v)[2] = kind == 2 ? ell : u;
	int count = kind == 2 ? 6 : 8;
	double scale = rng_real(0.8, 1.6);
	for (int i = 0; i < count; i++) {
		double x = (v[i][0] - 1.5) * scale, y = (v[i][1] - 1.5) * scale;
		put(buf, size, n, " %.3f %.3f", cx + c * x - s * y, cy + s * x + c * y);
	}
}

/* random_world: a TABLE of 24..40 squares a side; a third of the time a given
 * verge with a notch (concave); up to two walls, one slanted; two to five objects;
 * Utak anywhere, facing anywhere. Many such worlds overlap: the caller retries. */
static void random_world(char *buf, size_t size)
{
	int w = 24 + rng_int(17), h = 24 + rng_int(17), n = 0;
	put(buf, size, &n, "table %d %d\n", w, h);
	if (rng_int(3) == 0)
		put(buf, size, &n, "verge 1 1 %d 1 %d %d %d %d %d %d 1 %d\n", w - 1, w - 1, h - 1, w / 2, h - 1,
		    w / 2, h - 6, h - 6);
	for (int k = rng_int(3); k > 0; k--) {
		double x = rng_real(3, w - 8), y = rng_real(3, h - 8), l = rng_real(2, 6), t = rng_real(0.5, 1.5);
		if (rng_int(2))
			put(buf, size, &n, "wall %.3f %.3f %.3f %.3f %.3f %.3f %.3f %.3f\n", x, y, x + l, y, x + l,
			    y + t, x, y + t);
		else
			put(buf, size, &n, "wall %.3f %.3f %.3f %.3f %.3f %.3f %.3f %.3f\n", x, y, x + l, y + l / 2,
			    x + l - t, y + l / 2 + t, x - t, y + t);
	}
	for (int k = 0, objects = 2 + rng_int(4); k < objects; k++) {
		put(buf, size, &n, "object o%d %c", k, "ACDEFG"[k % 6]);
		put_shape(buf, size, &n, rng_real(6, w - 6), rng_real(6, h - 6));
		put(buf, size, &n, "\n");
	}
	put(buf, size, &n, "utak %.3f %.3f %s\n", rng_real(2, w - 2), rng_real(2, h - 2),
	    (const char *[]){"north", "east", "south", "west"}[rng_int(4)]);
}

/* own_frame(w, v): a TABLE displacement in Utak's frame (world_own_to_table inverted). */
static Vec2 own_frame(const World *w, Vec2 v)
{
	switch (w->heading) {
	case HEADING_EAST:
		return vec2(-v.y, v.x);
	case HEADING_SOUTH:
		return vec2(-v.x, -v.y);
	case HEADING_WEST:
		return vec2(v.y, -v.x);
	default:
		return v;
	}
}

/* random_command: with free hands, half the time a move toward a vertex of an
 * object and a quarter of the time a grasp (so that grasps succeed); holding,
 * mostly pushes and turns. Displacements up to 6 squares, turns up to half a
 * turn, a quarter of the turns exact multiples of 90 degrees. Every kind of
 * command, refused ones included, comes up. */
static MotorCommand random_command(const World *w)
{
	MotorCommand c = {.kind = (MotorKind)rng_int(5)};
	c.dx = rng_real(-6, 6);
	c.dy = rng_real(-6, 6);
	c.deg = rng_int(4) == 0 ? 90.0 * (rng_int(5) - 2) : rng_real(-180, 180);
	int r = rng_int(8);
	if (w->held < 0 && r < 4) {
		const Polygon *p = &w->objects[rng_int(w->object_count)].shape;
		Vec2 v = own_frame(w, vec2_sub(p->v[rng_int(p->count)], w->utak));
		c = (MotorCommand){.kind = MOTOR_MOVE, .dx = v.x, .dy = v.y};
	} else if (w->held < 0 && r < 6) {
		c.kind = MOTOR_GRASP;
	} else if (w->held >= 0 && r < 6) {
		c.kind = r < 3 ? MOTOR_PUSH : MOTOR_TURN;
	}
	return c;
}

enum { PROPERTY_SEQUENCES = 10000, PROPERTY_COMMANDS = 8 };

TEST_CASE(ten_thousand_sequences_keep_every_invariant)
{
	rng_state = 2026;
	int sequences = 0, commands = 0, tries = 0, moved = 0, turned = 0, halted = 0;
	char text[8192], why[256];
	Polygon orig[8], prev[8];
	while (sequences < PROPERTY_SEQUENCES) {
		tries++;
		random_world(text, sizeof text);
		Diag d;
		if (world_parse(&world, "random.w", text, strlen(text), &d))
			continue; /* a random star that is not simple */
		if (table_build(&table, &world, &d)) {
			world_free(&world); /* overlaps, or Utak inside something */
			continue;
		}
		sequences++;
		for (int32_t k = 0; k < world.object_count; k++)
			orig[k] = world.objects[k].shape;
		bool ok = inv_check(&world, &table, orig, orig, -1, why, sizeof why);
		for (int step = 0; ok && step < PROPERTY_COMMANDS; step++) {
			MotorCommand c = random_command(&world);
			for (int32_t k = 0; k < world.object_count; k++)
				prev[k] = world.objects[k].shape;
			int32_t held = world.held;
			MotorOutcome out;
			motion_execute(&world, &table, &c, &out);
			commands++;
			ok = inv_check(&world, &table, orig, prev, held, why, sizeof why);
			if (!ok)
				fprintf(stderr, "  sequence %d, command %d (kind %d): %s\n%s", sequences, step,
					(int)c.kind, why, text);
			if (held >= 0 && (c.kind == MOTOR_PUSH || c.kind == MOTOR_TURN) && out.done != 0) {
				moved++;
				turned += c.kind == MOTOR_TURN;
			}
			halted += out.halted && held >= 0;
		}
		TEST_CHECK(ok);
		unload();
	}
	printf("  %d sequences (%d worlds tried), %d commands; %d pushes or turns moved an object, %d of them "
	       "turns; %d halted against something\n",
	       sequences, tries, commands, moved, turned, halted);
	TEST_CHECK(commands == PROPERTY_SEQUENCES * PROPERTY_COMMANDS);
	/* The test means something only if objects did move, turn and collide. */
	TEST_CHECK(moved > PROPERTY_SEQUENCES / 2 && turned > PROPERTY_SEQUENCES / 10 &&
		   halted > PROPERTY_SEQUENCES / 10);
}

int main(void)
{
	TEST_RUN(released_beside_utak_reads_back);
	TEST_RUN(turn_about_a_point_on_the_edge);
	TEST_RUN(a_million_degrees_is_quick);
	TEST_RUN(limits_hold_at_the_boundary);
	TEST_RUN(ten_thousand_sequences_keep_every_invariant);
	return TEST_EXIT();
}
