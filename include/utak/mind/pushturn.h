/* pushturn.h - squaring a slanted object up to the walls of the corner it is pushed
 * into (paper 2.2 the motor command turn, 2.3 task (v)). CONTROLLER SIDE: called by
 * push.c's seating.
 *
 * A push moves the held object rigidly, so a square lying at an angle, seated
 * against both walls of a corner, touches each with one vertex and leaves the
 * corner's own squares empty: 2 to 21 squares short on random worlds (slants of
 * 25 to 65 degrees). Seated short with what he holds reading at a slant, Utak
 * draws it back out of the corner until the turn's sweep round his point is clear
 * on his model, turns it (it rotates about his point) by the angle that puts its
 * sides along the axes, and pushes it into the corner again: holding on where,
 * turned, it still leads him toward both walls, else letting go and fetching it
 * again from the side best for the corner (push_grasp_side); so too when the
 * disparity corrects his place on a push after the turn. */
#ifndef UTAK_PUSHTURN_H
#define UTAK_PUSHTURN_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"

/* How many times a push into a corner squares its object up (each: back off, turn,
 * push again). */
#define PUSHTURN_TRIES 1
/* A held object is squared up only when its sides lie further than this (degrees)
 * from the axes: under it the eye's reading of the angle is mostly its staircase. */
#define PUSHTURN_MIN_DEG 10.0
/* The farthest Utak draws the object back out of the corner, squares along each axis. */
#define PUSHTURN_MAX_BACK 8
/* The turn's sweep is checked on the model every this many degrees. */
#define PUSHTURN_SWEEP_STEP 1.0
/* The slant read when seated short and the one read at the grasp agree within
 * this (degrees): the staircase's error of a small square (test_pushturn.c: 11). */
#define PUSHTURN_AGREE 12.0
/* Grasped again, the object's held squares' centre lies within this (squares) of
 * where it was let go: grasped from another side, the held set gains or loses a
 * row at most. */
#define PUSHTURN_SAME 2.0

/* pushturn_angle(x, y, n, deg): the turn (degrees, counter-clockwise, in [-45, 45])
 * that puts the sides of the rectangle read from the n squares (x, y) along the
 * axes; false when the set reads as no rectangle (square or brick) or it lies
 * within PUSHTURN_MIN_DEG of them already. */
bool pushturn_angle(const int32_t *x, const int32_t *y, int32_t n, double *deg);
/* pushturn_begin(c): seated short: whether Utak squares the held object up (a try
 * left, it reads slanted, and a place to turn it is found on his model); if so
 * the next commands are pushturn_command's. */
bool pushturn_begin(Controller *c);
/* pushturn_command(c, cmd): while squaring up: the next push back or the turn;
 * false when there is none (the push into the corner goes on, PHASE_PUSH). */
bool pushturn_command(Controller *c, MotorCommand *cmd);
/* pushturn_active(c): a squaring up is under way. */
bool pushturn_active(const Controller *c);
/* pushturn_watch(c): after a push into the corner that follows a turn he kept hold
 * through: when the disparity corrected Utak's place, he lets go (PHASE_RELEASE)
 * to fetch the object again; true if so. */
bool pushturn_watch(Controller *c);
/* pushturn_released(c): after a release: whether it was the squaring up's (if so
 * the task goes on: Utak fetches the object again, PHASE_TRAVEL). */
bool pushturn_released(Controller *c);
/* pushturn_grasped(c): after a grasp: the slant the held squares read at (a turn
 * is made only for one they read at when grasped, pushturn_begin); fetching the object turned square, what he
 * holds must lie where he let it go (its held squares' centre within
 * PUSHTURN_SAME): else the task fails, for it is another object. */
void pushturn_grasped(Controller *c);

#endif
