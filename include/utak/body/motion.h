/* motion.h - the motion and collision of shapes on the tabletop (paper 2.1, 2.2). SIMULATOR SIDE.
 *
 * Carries out Utak's five motor commands on the world and its TABLE, keeping the
 * TABLE's invariant (table.h) after every one: objects never overlap and never
 * leave the verge, whatever the sequence of commands. */
#ifndef UTAK_MOTION_H
#define UTAK_MOTION_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/impression.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

/* Motion advances in steps that move no point by more than half a square (so no
 * shape can jump over a square of another colour, every digital shape being at
 * least one square thick), re-projecting the moving shapes after each. */
#define MOTION_STEP 0.5
/* When a step is refused, the legal part of it is found by bisection to 1/2^12 of
 * a step, so a halted shape ends within a few thousandths of a square of where
 * its projection would first meet another colour. */
#define MOTION_BISECTIONS 12

typedef struct MotorOutcome {
	bool refused;		/* the command could not start; nothing changed */
	bool halted;		/* it started, and stopped short at the last legal pose */
	double asked, done;	/* squares (move, push) or degrees (turn) asked and achieved */
	char what[128];		/* why refused or halted, or what was grasped or released */
} MotorOutcome;

/* NOISY MOTION (paper 3.5, the second source of uncertainty: "the action is not as
 * predicted"). With noise, the simulator carries out a slightly different command
 * than the one given: a move or push of length L is displaced by an error whose x and
 * y parts (in the TABLE's frame) are independent Gaussians of standard deviation
 * sigma * L squares, and a turn of D degrees by a Gaussian angle error of standard
 * deviation sigma * |D| degrees. Grasp and release are exact. The error is drawn
 * before the command runs, so collision and halting act on the noisy motion, and the
 * outcome reports what was really done. The controller is not told: it finds the
 * error from its impressions, as it finds a halt.
 * The generator is seeded and deterministic (SplitMix64, Steele, Lea and Flood
 * 2014, "Fast splittable pseudorandom number generators"; Gaussians by the
 * Box-Muller transform), so a run with the same seed prints the same output on
 * every machine. */
typedef struct MotionNoise {
	double sigma;	/* squares of error per square moved; 0: exact motion */
	uint64_t state;	/* the generator's state: set by motion_noise_init */
} MotionNoise;

/* The largest sigma accepted: at 1, a leg's error is as long as the leg. */
#define MOTION_NOISE_MAX 1.0

/* motion_noise_init(n, sigma, seed): noise of sigma from a generator seeded with seed. */
void motion_noise_init(MotionNoise *n, double sigma, uint64_t seed);
/* motion_noise_gaussian(n): the next standard Gaussian of n's generator. */
double motion_noise_gaussian(MotionNoise *n);

/* motion_execute(w, t, cmd, out): carries out one motor command exactly. */
void motion_execute(World *w, Table *t, const MotorCommand *cmd, MotorOutcome *out);
/* motion_execute_noisy(w, t, cmd, noise, out): carries it out with noise (NULL or
 * sigma 0: exactly). out->asked is the command as given; out->done what the motion
 * achieved (for a move or push, the length travelled of the noisy displacement). */
void motion_execute_noisy(World *w, Table *t, const MotorCommand *cmd, MotionNoise *noise,
			  MotorOutcome *out);

/* motion_print(cmd, out, f): one line, e.g. "push 0.00 5.00: halted after 3.21 of
 * 5.00: blocked by the verge" (no newline). */
void motion_print(const MotorCommand *cmd, const MotorOutcome *out, FILE *f);

#endif
