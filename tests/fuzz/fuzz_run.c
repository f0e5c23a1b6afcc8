/* fuzz_run.c - fuzzes a whole run of the simulator: a world, then motor commands
 * (paper 2.1, 2.2: "objects never overlap and never leave the verge").
 *
 * INPUT: a world file, a NUL byte, then commands of 4 bytes each (at most
 * FUZZ_RUN_MAX_COMMANDS; no NUL means no commands):
 *   byte 0: the command, k % 5 (move, grasp, push, turn, release); when its top
 *           bit is set and Utak holds nothing, instead a move toward vertex 0 of
 *           object (byte 1 % objects), so that grasps and pushes happen often;
 *   byte 1, 2: dx, dy in Utak's frame, as signed bytes in quarter squares;
 *   byte 3: a turn, as a signed byte in units of 1.5 degrees.
 * After every command all of invariants.h must hold, or the harness aborts; at
 * the end the state written as a world file (utak -o) must read back to the
 * same TABLE.
 *
 * Worlds over FUZZ_RUN_MAX_SIDE squares a side are skipped: a turn's cost grows
 * with the square of the object's size, and the point here is the physics, not
 * the large-TABLE paths that fuzz_world covers. */
#include <string.h>

#include "fuzz.h"
#include "invariants.h"
#include "utak/body/motion.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

enum { FUZZ_RUN_MAX_SIDE = 128, FUZZ_RUN_MAX_COMMANDS = 32 };

/* toward(w, k): the displacement, in Utak's frame, to vertex 0 of object k. */
static Vec2 toward(const World *w, int32_t k)
{
	Vec2 dt = vec2_sub(w->objects[k].shape.v[0], w->utak);
	switch (w->heading) {
	case HEADING_NORTH:
		return dt;
	case HEADING_EAST:
		return vec2(-dt.y, dt.x);
	case HEADING_SOUTH:
		return vec2(-dt.x, -dt.y);
	case HEADING_WEST:
		return vec2(dt.y, -dt.x);
	}
	return dt;
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
	if (w.w > FUZZ_RUN_MAX_SIDE || w.h > FUZZ_RUN_MAX_SIDE || table_build(&t, &w, &d) != 0) {
		world_free(&w);
		return 0;
	}
	Polygon *orig = malloc(sizeof *orig * (size_t)(w.object_count + 1));
	Polygon *prev = malloc(sizeof *prev * (size_t)(w.object_count + 1));
	FUZZ_CHECK(orig && prev, "out of memory");
	for (int32_t k = 0; k < w.object_count; k++)
		orig[k] = w.objects[k].shape;
	char why[256];
	FUZZ_CHECK(inv_check(&w, &t, orig, orig, -1, why, sizeof why), "at load: %s", why);
	const uint8_t *c = nul ? nul + 1 : data + size, *end = data + size;
	for (int n = 0; c + 4 <= end && n < FUZZ_RUN_MAX_COMMANDS; n++, c += 4) {
		MotorCommand cmd = {.kind = (MotorKind)((c[0] & 0x7f) % 5),
				    .dx = (int8_t)c[1] / 4.0,
				    .dy = (int8_t)c[2] / 4.0,
				    .deg = (int8_t)c[3] * 1.5};
		if ((c[0] & 0x80) && w.held < 0 && w.object_count > 0) {
			Vec2 v = toward(&w, c[1] % w.object_count);
			cmd = (MotorCommand){.kind = MOTOR_MOVE, .dx = v.x, .dy = v.y};
		}
		for (int32_t k = 0; k < w.object_count; k++)
			prev[k] = w.objects[k].shape;
		int32_t held = w.held;
		MotorOutcome out;
		motion_execute(&w, &t, &cmd, &out);
		FUZZ_CHECK(inv_check(&w, &t, orig, prev, held, why, sizeof why), "after command %d: %s", n, why);
		FUZZ_CHECK(!(out.refused && out.halted), "refused and halted");
		FUZZ_CHECK(isfinite(out.done) && fabs(out.done) <= fabs(out.asked) + 1e-9, "done %g of %g",
			   out.done, out.asked);
	}
	char *text = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&text, &len);
	FUZZ_CHECK(f != NULL, "open_memstream");
	world_write(&w, f);
	fclose(f);
	World back;
	Table tb;
	FUZZ_CHECK(world_parse(&back, "written.w", text, len, &d) == 0, "written world: %s", d.msg);
	FUZZ_CHECK(table_build(&tb, &back, &d) == 0, "written world: %s\n%s", d.msg, text);
	FUZZ_CHECK(memcmp(tb.owner, t.owner, sizeof *t.owner * (size_t)t.w * (size_t)t.h) == 0,
		   "written world builds another TABLE");
	table_free(&tb);
	world_free(&back);
	free(text);
	free(orig);
	free(prev);
	table_free(&t);
	world_free(&w);
	return 0;
}
