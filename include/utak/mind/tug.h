/* tug.h - telling an object from the wall it leans on by touch and motion (paper
 * 3.4.2, 2.2; issue 13). CONTROLLER SIDE: the action cycle (controller.c) asks it
 * first, while Utak looks for the task's object.
 *
 * An occupied set joined to the verge may be verge, or an object against a wall:
 * the eye cannot tell them apart, for both show the same gray levels. Touch can:
 * it names an object's colour, a letter other than B, where the verge and the
 * walls show B. And motion can: grasped and drawn back, an object leaves the wall
 * and is seen whole, on its own. So when Utak, looking for the task's object and
 * not having found it, touches an object's colour on a square the model holds to
 * be part of such a set, he grasps it and pulls it straight back, TUG_STEP squares
 * at a time, until the model sees the squares beside him as an object of their
 * own (or TUG_MOST squares, or the way back is not floor), and lets go. A pull
 * that leaves Utak where he was ends the tug at once: the object is wedged (a
 * square that fills its pocket exactly cannot come out when the pull goes the
 * least astray, paper 3.5's noisy motion), and pulling again would not move it;
 * the square grasped is not tugged at again, and the search's failure says where
 * the object stuck (c->tug_wedged). Then the object is named like any other
 * (objects.h), and the task goes on.
 *
 * Where to touch: goals.c sends Utak, as a last resort of the search, to the
 * corners of such sets (goals_probe_joined), standing on the corner itself: an
 * object against a wall makes corners in it, and there touch feels both faces and
 * the square between them. Every square of such a set touch has felt an object's
 * colour on, then or in passing, is remembered (objects_feel, c->felt_x), and
 * before any more corners are probed Utak goes to the nearest floor square beside
 * one from which he can draw it straight back (goals_felt_tug): what touch showed
 * does not depend on the way he faced or came. */
#ifndef UTAK_TUG_H
#define UTAK_TUG_H

#include <stdbool.h>

#include "utak/impression.h"
#include "utak/mind/controller.h"

/* Squares pulled per push, and at most in all. */
#define TUG_STEP 2
#define TUG_MOST 10
/* Tugs in one task at most: each is a try at an object the eye could not see. */
#define TUG_TRIES 4

/* tug_decide(c, cmd): the next command of a tug, begun here if touch shows the way
 * (see above); false when no tug is under way. */
bool tug_decide(Controller *c, MotorCommand *cmd);

#endif
