/* pushslant.h - how far short of its corner a slanted rectangle must stay (paper 2.2
 * a push moves the held object rigidly, never turns it; 2.3 task (v)). CONTROLLER
 * SIDE: called by push.c's push_seat_finish when the object was not squared up.
 *
 * WHY. A rectangle held at a slant and seated against both walls of a corner
 * touches each wall with one vertex and leaves the corner's squares empty
 * (pushturn.h squares it up first, where the model shows room to turn it). Where it
 * could not be turned (no room for the sweep on a small table, or its try spent),
 * the claim rested on the held squares, and those, pressed against two walls, the
 * registration can slide a square into the wall (occupied either way to the eye:
 * heldobject.c wm_register_held): Utak claimed slanted squares 2 short of the
 * corner (adversarial worlds, a square 5 to 8 wide at 20 to 35 degrees on a
 * 24 x 18 table: 4 of 400 pushes).
 *
 * THE BOUND. Put the corner at the origin and the rectangle's side of length w
 * between the two vertices that touch the walls, at angle t to the wall (0 < t <=
 * 45 degrees, the other case its mirror): the vertices lie at (w sin t, 0) and
 * (0, w cos t), and every point of the rectangle has x + y >= w sin t. A square
 * (i, j) meets its interior only if its far corner passes the side between them:
 * (i + 1) / (w sin t) + (j + 1) / (w cos t) > 1, so i + j > w sin t - tan t - 1
 * (with j = 0 the least; i + j is how far the square lies from the corner's square
 * by the judge's score). A rectangle not pressed home lies farther still. So the
 * object is at least floor(w sin t - tan t - 1) + 1 short (0 when that is
 * negative), whatever its other side; seated, exactly that (test_pushslant.c:
 * every pose of 5874, against exact geometry). w is the least width the held
 * squares allow (shape.h min_width) and t the smaller of the slants read at the
 * grasp and now, as read: the reading errs both ways (a square 8 wide at 20
 * degrees read 30, one 7 wide at 30 read 21), and a tolerance taken off t left
 * the bound at 1 in every false success found; a reading over the truth can only
 * add a doubt where the object is in fact within the slack (cost measured in the
 * commit), never a false success. */
#ifndef UTAK_PUSHSLANT_H
#define UTAK_PUSHSLANT_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"

/* pushslant_bound(w, deg): the least shortfall (squares, by the corner score) of a
 * rectangle of width at least w seated in a corner at a slant of deg degrees
 * (taken into [0, 45]): the greatest integer below w sin t - tan t - 1 plus one,
 * or 0 when that is negative. */
int64_t pushslant_bound(double w, double deg);

/* pushslant_short(c, &deg, &w, &bound): the held object reads as a rectangle at a
 * slant that agrees with the one read at the grasp (pushturn.h), and the bound for
 * it exceeds CONTROLLER_CORNER_SLACK; deg, w and bound are then set. */
bool pushslant_short(const Controller *c, double *deg, double *w, int64_t *bound);

#endif
