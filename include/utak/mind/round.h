/* round.h - going round an object and returning (paper 2.3 task (iv)). CONTROLLER SIDE. */
#ifndef UTAK_ROUND_H
#define UTAK_ROUND_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"

/* round_lay_out(c, k): the points of a loop round object node k. */
void round_lay_out(Controller *c, int32_t k);
/* round_goal(c, dist, goal): the goal of the loop's next leg: its point, or where the
 * screen has a wall or object there, the reachable square nearest it on the same side
 * of the object (dist: steps from Utak). False when there is none: no way round. */
bool round_goal(const Controller *c, const int32_t *dist, Vec2 *goal);
/* round_look(c, k, dist, goal): where to stand next to see in the fovea a part of
 * object node k (or the floor round it) its confirmation lacks, after a loop home
 * round it; false when no such part is left that a look could show. */
bool round_look(const Controller *c, int32_t k, const int32_t *dist, Vec2 *goal);
/* round_home(c): the loop's last leg alone, back to the start, round node k. */
void round_home(Controller *c, int32_t k);
/* round_unconfirmed(c): the task's object is known and not yet confirmed. */
bool round_unconfirmed(Controller *c);
/* round_believed_turns(c, k): how often Utak's believed path winds round node k. */
double round_believed_turns(const Controller *c, int32_t k);
/* round_stale(c): the loop was laid out round what is no longer the task's object. */
bool round_stale(Controller *c);

/* round_recognise_home(c): on the leg home, near the start, Utak's position corrected
 * by what his first impression showed; true when it was (the belief moved). */
bool round_recognise_home(Controller *c);
/* round_home_doubt(c, why, size): home, by his belief, but motion has erred and
 * what he sees does not place him where he began: true, and why, when he doubts it.
 * Corrections that set him one way and back along an axis are settled by the look
 * home when both the model's disparity and his first impression place him on his
 * believed square along it. Where the first impression does not place him along an
 * axis and fits what he sees best on another square along it, he doubts it however
 * the model placed him. */
bool round_home_doubt(const Controller *c, char *why, size_t size);

#endif
