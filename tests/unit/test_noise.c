/* test_noise.c - noisy motion (motion.h, "NOISY MOTION"; paper 3.5, the second source
 * of uncertainty). The simulator is the oracle: on an open table, the displacement it
 * really makes for many commanded moves, pushes and turns has the documented
 * distribution (mean 0, standard deviation sigma x length in each TABLE axis, sigma x
 * |degrees| for turns), the same seed gives the same motion, another seed another,
 * sigma 0 is exact, and the TABLE's invariant holds throughout. */
#include <math.h>

#include "world_fixture.h"

/* A large open table: no command below comes near the verge; the brick is within
 * Utak's touch, north of him, for the turns. */
static const char open_world[] =
    "table 400 400\n"
    "object brick A 200 201 206 201 206 203 200 203\n"
    "utak 200.5 200.5 north\n";
/* The same with the brick out of the way of the moves. */
static const char empty_world[] =
    "table 400 400\n"
    "object brick A 20 20 26 20 26 22 20 22\n"
    "utak 200.5 200.5 north\n";

/* noisy(kind, a, b, noise): one command with noise, the invariant checked. */
static MotorOutcome noisy(MotorKind kind, double a, double b, MotionNoise *noise)
{
	MotorCommand c = {.kind = kind, .dx = a, .dy = b, .deg = a};
	MotorOutcome out;
	motion_execute_noisy(&world, &table, &c, noise, &out);
	char why[256];
	bool ok = table_validate(&table, &world, why, sizeof why);
	if (!ok)
		fprintf(stderr, "  invariant: %s\n", why);
	TEST_CHECK(ok);
	return out;
}

/* Moves of 4 squares east, then back west, 400 of each: the errors' mean and
 * spread in x and y. With n = 800 draws the sample deviation is within 10% of
 * sigma L with overwhelming probability (its relative error is about 1/sqrt(2n),
 * 2.5%), and the mean within 4 standard errors of 0. */
TEST_CASE(noise_moves_have_the_stated_spread)
{
	const double sigma = 0.05, len = 4;
	const int n = 800;
	load(empty_world);
	MotionNoise noise;
	motion_noise_init(&noise, sigma, 7);
	double sx = 0, sy = 0, sxx = 0, syy = 0;
	for (int i = 0; i < n; i++) {
		Vec2 before = world.utak;
		double dir = i % 2 ? -1 : 1;
		MotorOutcome out = noisy(MOTOR_MOVE, dir * len, 0, &noise);
		TEST_CHECK(!out.refused && !out.halted);
		double ex = (world.utak.x - before.x) - dir * len, ey = world.utak.y - before.y;
		sx += ex, sy += ey, sxx += ex * ex, syy += ey * ey;
		/* The outcome reports what was really done. */
		TEST_NEAR(out.done, hypot(world.utak.x - before.x, world.utak.y - before.y), 1e-9);
		TEST_NEAR(out.asked, len, 1e-12);
		/* Walk back toward the start now and then, to stay in the open. */
		if (fabs(world.utak.y - 200.5) > 20 || fabs(world.utak.x - 200.5) > 20) {
			unload();
			load(empty_world);
		}
	}
	double want = sigma * len;
	TEST_CHECK(fabs(sx / n) < 4 * want / sqrt(n) && fabs(sy / n) < 4 * want / sqrt(n));
	TEST_NEAR(sqrt(sxx / n), want, 0.1 * want);
	TEST_NEAR(sqrt(syy / n), want, 0.1 * want);
	unload();
}

/* Turns of 30 degrees with the brick held: the angle error's spread, read from
 * where a vertex of the brick went. */
TEST_CASE(noise_turns_have_the_stated_spread)
{
	const double sigma = 0.05, deg = 30;
	const int n = 400;
	load(open_world);
	MotionNoise noise;
	motion_noise_init(&noise, sigma, 11);
	TEST_CHECK(!act(MOTOR_GRASP, 0, 0).refused);
	double s = 0, ss = 0;
	for (int i = 0; i < n; i++) {
		double dir = i % 2 ? -1 : 1;
		Vec2 u = world.utak, v0 = world.objects[0].shape.v[0];
		MotorOutcome out = noisy(MOTOR_TURN, dir * deg, 0, &noise);
		TEST_CHECK(!out.refused && !out.halted);
		Vec2 v1 = world.objects[0].shape.v[0];
		double turned = atan2(vec2_cross(vec2_sub(v0, u), vec2_sub(v1, u)), vec2_dot(vec2_sub(v0, u), vec2_sub(v1, u)));
		double e = turned * 180 / 3.14159265358979323846 - dir * deg;
		TEST_NEAR(out.done, dir * deg + e, 1e-6);
		s += e, ss += e * e;
	}
	double want = sigma * deg;
	TEST_CHECK(fabs(s / n) < 4 * want / sqrt(n));
	TEST_NEAR(sqrt(ss / n), want, 0.1 * want);
	unload();
}

/* The same seed, the same motion; another seed, another; sigma 0, exactly the
 * command. */
TEST_CASE(noise_is_seeded_and_exact_at_zero)
{
	Vec2 end[3];
	const uint64_t seeds[3] = {5, 5, 6};
	for (int k = 0; k < 3; k++) {
		load(open_world);
		MotionNoise noise;
		motion_noise_init(&noise, 0.1, seeds[k]);
		for (int i = 0; i < 20; i++)
			noisy(MOTOR_MOVE, i % 2 ? -3 : 3, -1, &noise);
		end[k] = world.utak;
		unload();
	}
	TEST_CHECK(end[0].x == end[1].x && end[0].y == end[1].y);
	TEST_CHECK(end[0].x != end[2].x || end[0].y != end[2].y);
	load(open_world);
	MotionNoise none;
	motion_noise_init(&none, 0, 5);
	noisy(MOTOR_MOVE, 3, -4, &none);
	TEST_CHECK(world.utak.x == 203.5 && world.utak.y == 196.5);
	unload();
}

int main(void)
{
	TEST_RUN(noise_moves_have_the_stated_spread);
	TEST_RUN(noise_turns_have_the_stated_spread);
	TEST_RUN(noise_is_seeded_and_exact_at_zero);
	return TEST_EXIT();
}
