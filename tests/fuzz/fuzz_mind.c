/* fuzz_mind.c - fuzzes a whole run of the robot: a world, a task, and the action
 * cycle of paper 3.1 (perception, the world model, planning, acting), so that a
 * strange but valid world cannot crash the controller.
 *
 * INPUT: a world file, a NUL byte, then a task (short form or sentence). Worlds
 * the reader refuses, or over FUZZ_MIND_MAX_SIDE a side, end the run (the reader
 * has its own harness). At most FUZZ_MIND_CYCLES cycles run; after each the
 * simulator's invariants must hold; at the end the judge must give a verdict.
 * Worlds without objects run too (their seeds are in the corpus: one once stopped
 * the harness itself, on memcpy from NULL). */
#include <string.h>

#include "fuzz.h"
#include "invariants.h"
#include "utak/mind/controller.h"
#include "utak/body/judge.h"
#include "utak/body/motion.h"
#include "utak/body/retina.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

enum { FUZZ_MIND_MAX_SIDE = 64, FUZZ_MIND_CYCLES = 12 };

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	const uint8_t *nul = memchr(data, 0, size);
	size_t wlen = nul ? (size_t)(nul - data) : size;
	char task_text[256] = "go ne-corner";
	if (nul) {
		size_t n = size - wlen - 1 < sizeof task_text - 1 ? size - wlen - 1 : sizeof task_text - 1;
		memcpy(task_text, nul + 1, n);
		task_text[n] = 0;
	}
	World w, start;
	Table t;
	Diag d;
	Task task;
	if (task_parse(task_text, &task, &d) != 0)
		return 0;
	if (world_parse(&w, "fuzz.w", (const char *)data, wlen, &d) != 0)
		return 0;
	if (w.w > FUZZ_MIND_MAX_SIDE || w.h > FUZZ_MIND_MAX_SIDE || table_build(&t, &w, &d) != 0) {
		world_free(&w);
		return 0;
	}
	start = w;
	start.objects = malloc(sizeof *start.objects * ((size_t)w.object_count + 1));
	FUZZ_CHECK(start.objects != NULL, "out of memory");
	/* A world without objects has no array at all: memcpy must not see NULL. */
	if (w.object_count > 0)
		memcpy(start.objects, w.objects, sizeof *start.objects * (size_t)w.object_count);
	Controller *c = malloc(sizeof *c);
	controller_init(c, PLANNER_SKELETON);
	controller_set_task(c, &task);
	Impression imp;
	retina_sense(&w, &t, &imp);
	controller_start(c, &imp);
	Vec2 trail[FUZZ_MIND_CYCLES + 1];
	int n = 0;
	trail[n++] = w.utak;
	MotorCommand cmd;
	for (int cycle = 0; cycle < FUZZ_MIND_CYCLES && controller_decide(c, &cmd); cycle++) {
		MotorOutcome out;
		motion_execute(&w, &t, &cmd, &out);
		trail[n++] = w.utak;
		char why[256];
		FUZZ_CHECK(table_validate(&t, &w, why, sizeof why), "cycle %d: %s", cycle, why);
		retina_sense(&w, &t, &imp);
		controller_perceive(c, &cmd, &imp);
	}
	char why[256];
	judge_task(&start, &w, &t, &task, trail, n, why, sizeof why);
	FUZZ_CHECK(why[0] != 0, "the judge gave no reason");
	controller_free(c);
	free(c);
	free(start.objects);
	table_free(&t);
	world_free(&w);
	return 0;
}
