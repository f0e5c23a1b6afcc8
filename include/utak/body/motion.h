/* motion.h - the motion and collision of shapes on the tabletop (paper 2.1, 2.2). SIMULATOR SIDE.
 *
 * Carries out Utak's five motor commands on the world and its TABLE, keeping the
 * TABLE's invariant (table.h) after every one: objects never overlap and never
 * leave the verge, whatever the sequence of commands. */
#ifndef UTAK_MOTION_H
#define UTAK_MOTION_H

#include <stdbool.h>
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

/* motion_execute(w, t, cmd, out): carries out one motor command. */
void motion_execute(World *w, Table *t, const MotorCommand *cmd, MotorOutcome *out);

/* motion_print(cmd, out, f): one line, e.g. "push 0.00 5.00: halted after 3.21 of
 * 5.00: blocked by the verge" (no newline). */
void motion_print(const MotorCommand *cmd, const MotorOutcome *out, FILE *f);

#endif
