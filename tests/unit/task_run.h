/* task_run.h - a task run whole by the action cycle on a world from text, and the
 * judge's verdict on it beside Utak's belief (paper 2.2's perceive-plan-act cycle,
 * as main.c's run_task runs it, without output): for the controller's tests that
 * take the simulator and the judge as their oracle. Shared by test_joined.c,
 * test_roomlean.c, test_roundhome.c, test_thinwall.c, test_doorlook.c and test_wallbump.c. Include after world_fixture.h (load, unload, world, table). */
#ifndef UTAK_TEST_TASK_RUN_H
#define UTAK_TEST_TASK_RUN_H

#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "utak/body/judge.h"
#include "utak/body/motion.h"
#include "utak/body/retina.h"
#include "utak/mind/controller.h"

/* A run's outcome: the judge's verdict, Utak's belief, and his reason; the
 * corrections of his place the last CONTROLLER_FIXES impressions made (oldest
 * first), and the corner looks he set off on (doorlook.h: how many, and whether
 * the last was left unreached), and the trips to corners of the wall he set off on
 * to feel (wallbump.h), which a test may read to see what the run put him through. */
typedef struct Outcome {
	bool achieved, believed;
	char why[320];
	Vec2 fix[CONTROLLER_FIXES];
	int door_looks;
	bool door_look_pending;
	int bump_trips;
} Outcome;

/* run_noisy(text, task_text, sigma, seed): the task on the world, by the action
 * cycle, at most 300 cycles, the simulator's motion noisy by sigma with that seed
 * (main.c's run_task with --noise sigma --seed seed, without output). */
static inline Outcome run_noisy(const char *text, const char *task_text, double sigma, uint64_t seed)
{
	Outcome o = {0};
	load(text);
	Task task;
	Diag d;
	TEST_CHECK(task_parse(task_text, &task, &d) == 0);
	World start = world;
	start.objects = calloc((size_t)world.object_count + 1, sizeof *start.objects);
	if (world.object_count > 0)
		memcpy(start.objects, world.objects, sizeof *start.objects * (size_t)world.object_count);
	Controller *ctl = calloc(1, sizeof *ctl);
	controller_init(ctl, PLANNER_SKELETON);
	controller_set_task(ctl, &task);
	MotionNoise noise;
	motion_noise_init(&noise, sigma, seed);
	Impression sensed;
	retina_sense(&world, &table, &sensed);
	controller_start(ctl, &sensed);
	Vec2 *trail = malloc(sizeof *trail * 302);
	int32_t n = 0;
	trail[n++] = world.utak;
	MotorCommand cmd;
	for (int cycle = 0; cycle < 300 && controller_decide(ctl, &cmd); cycle++) {
		MotorOutcome mo;
		motion_execute_noisy(&world, &table, &cmd, &noise, &mo);
		trail[n++] = world.utak;
		retina_sense(&world, &table, &sensed);
		controller_perceive(ctl, &cmd, &sensed);
	}
	char why[256];
	o.achieved = judge_task(&start, &world, &table, &task, trail, n, why, sizeof why);
	o.believed = ctl->phase == PHASE_DONE;
	snprintf(o.why, sizeof o.why, "%s", ctl->why);
	for (int i = 0; i < CONTROLLER_FIXES; i++)
		o.fix[i] = ctl->fix[(ctl->fix_next + i) % CONTROLLER_FIXES];
	o.door_looks = ctl->door_looks;
	o.door_look_pending = ctl->door_look_pending;
	o.bump_trips = ctl->bump_trips;
	controller_free(ctl);
	free(ctl);
	free(trail);
	free(start.objects);
	unload();
	return o;
}

/* run(text, task_text): the same with exact motion. */
static inline Outcome run(const char *text, const char *task_text)
{
	return run_noisy(text, task_text, 0, 1);
}

#endif
