/* world_fixture.h - one world and its TABLE for simulator tests (paper 2.1, 2.2):
 * load a world from text, carry out a motor command with the TABLE's invariant
 * checked after it, unload. Shared by test_motion.c and test_invariants.c. */
#ifndef UTAK_TEST_WORLD_FIXTURE_H
#define UTAK_TEST_WORLD_FIXTURE_H

#include <string.h>

#include "test.h"
#include "utak/body/motion.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

static World world;
static Table table;

/* load(text): the world and its TABLE; the case fails if either is refused. */
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

/* act(kind, a, b): one command (a is dx, or the turn in degrees; b is dy); the
 * TABLE's invariant must hold after it. */
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

#endif
