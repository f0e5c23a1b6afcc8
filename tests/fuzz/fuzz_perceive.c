/* fuzz_perceive.c - fuzzes an --act run as utak makes it: a world, motor commands
 * of any magnitude up to the script limit, and after each the mind perceiving the
 * impression that follows (paper 3.1 steps 10-11: the world model accommodating,
 * its disparity search, the regions), so that no world and no command, however
 * long, can crash the mind or make its cost run away (issue 14: a move of a
 * million squares cost the disparity search 20 s; libFuzzer's -timeout catches
 * such a thing again).
 *
 * INPUT: a world file, a NUL byte, then commands of 4 bytes each (at most
 * FUZZ_PERCEIVE_MAX_COMMANDS; no NUL means no commands):
 *   byte 0: the command, (k & 7) % 5 (move, grasp, push, turn, release); its five
 *           top bits, k >> 3, choose the scale (below);
 *   byte 1, 2: dx, dy in Utak's frame, signed bytes, times the scale;
 *   byte 3: a turn, a signed byte, times the scale.
 * The scale is 2^((k >> 3) - 6) squares (or degrees), so from 1/64 to 2^25 a
 * unit, the product clamped to ACT_MAX_MAGNITUDE (10^6) as the script reader
 * would insist. Worlds with no objects run too (one once broke the harness
 * itself: memcpy from NULL). After every command the world model must pass
 * worldmodel_validate and the TABLE table_validate; Utak's believed position
 * must be finite. Worlds over FUZZ_PERCEIVE_MAX_SIDE a side are skipped: the
 * whole-TABLE paths are fuzz_world's. */
#include <math.h>
#include <string.h>

#include "fuzz.h"
#include "utak/body/act.h"
#include "utak/body/motion.h"
#include "utak/body/retina.h"
#include "utak/body/table.h"
#include "utak/body/world.h"
#include "utak/mind/controller.h"

enum { FUZZ_PERCEIVE_MAX_SIDE = 128, FUZZ_PERCEIVE_MAX_COMMANDS = 16 };

/* magnitude(byte, scale): a signed byte times the scale, within the script limit. */
static double magnitude(uint8_t byte, double scale)
{
	double v = (int8_t)byte * scale;
	return v > ACT_MAX_MAGNITUDE ? ACT_MAX_MAGNITUDE : v < -ACT_MAX_MAGNITUDE ? -ACT_MAX_MAGNITUDE : v;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const uint8_t *nul = memchr(data, 0, size);
	size_t wlen = nul ? (size_t)(nul - data) : size;
	World w;
	Table t;
	Diag d;
	if (world_parse(&w, "fuzz.w", (const char *)data, wlen, &d) != 0)
		return 0;
	if (w.w > FUZZ_PERCEIVE_MAX_SIDE || w.h > FUZZ_PERCEIVE_MAX_SIDE || table_build(&t, &w, &d) != 0) {
		world_free(&w);
		return 0;
	}
	Controller *c = malloc(sizeof *c);
	FUZZ_CHECK(c != NULL, "out of memory");
	controller_init(c, PLANNER_SKELETON);
	Impression imp;
	retina_sense(&w, &t, &imp);
	controller_start(c, &imp);
	const uint8_t *p = nul ? nul + 1 : data + size, *end = data + size;
	char why[256];
	for (int n = 0; p + 4 <= end && n < FUZZ_PERCEIVE_MAX_COMMANDS; n++, p += 4) {
		double scale = ldexp(1.0, (p[0] >> 3) - 6);
		MotorCommand cmd = {.kind = (MotorKind)((p[0] & 7) % 5),
				    .dx = magnitude(p[1], scale),
				    .dy = magnitude(p[2], scale),
				    .deg = magnitude(p[3], scale)};
		MotorOutcome out;
		motion_execute(&w, &t, &cmd, &out);
		FUZZ_CHECK(table_validate(&t, &w, why, sizeof why), "command %d: %s", n, why);
		retina_sense(&w, &t, &imp);
		controller_perceive(c, &cmd, &imp);
		FUZZ_CHECK(worldmodel_validate(&c->model, why, sizeof why), "command %d: %s", n, why);
		FUZZ_CHECK(isfinite(c->model.utak.x) && isfinite(c->model.utak.y), "command %d: belief", n);
	}
	controller_free(c);
	free(c);
	table_free(&t);
	world_free(&w);
	return 0;
}
