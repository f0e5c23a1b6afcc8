/* wallbump.h - a corner of the wall that may be an object pressed against it (paper
 * 3.4.2: an occupied set joined to the verge is ambiguous; issue 13 items 2 and 6).
 * CONTROLLER SIDE: the world model and touch only.
 *
 * WHY. The eye reads an object that leans on a wall as part of the wall: on
 * hand-written worlds, a square pressed into a corner of the table or against its
 * edge, nearer the start than another square in open floor, was never told apart,
 * and Utak claimed the farther one ("go square", "go round square", "push square":
 * 9 of the 14 false successes left on 60 such worlds, 420 runs). An object pressed
 * against a wall stands out of its face: where a square stands, the wall's boundary
 * turns round a CORNER that sticks out into the floor (an occupied square with
 * floor on two sides and on the diagonal between), with a face of at least 2
 * squares on each side (a square's side is 2 or more: the judge names nothing
 * narrower). A wall's own ends and piers make such corners too, and only touch
 * tells which (B, the verge's colour, or an object's letter).
 *
 * THE DOUBT (objects_doubt). The claim on "the square" (the object of the shape
 * nearest the start, doc/verdicts.md) is in doubt while such a corner, seen in the
 * fovea, lies where a square of side 2 to WALLBUMP_MAX_SIDE with that corner, its
 * body in the wall, would have its centroid nearer the start than the claimed
 * one's, and touch has not felt B on it (the corner square or the next square of
 * either face: wallbump_feel). A letter felt there names an object: the doubt
 * stands.
 *
 * THE TRIP (goals.c). Before he goes to the square, as he looks at the unseen
 * nearer the start first, Utak goes beside each such corner, nearest first, and
 * touch settles it; at most WALLBUMP_TRIPS a task. Corners seen only in coarse cells are faint.h's and objects.h's: their
 * squares are not exact. */
#ifndef UTAK_WALLBUMP_H
#define UTAK_WALLBUMP_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"
#include "utak/mind/goals.h"

/* The largest square side tried behind a corner (squares): its centroid is then
 * this deep in the wall, half of it each way. */
#define WALLBUMP_MAX_SIDE 12
/* Trips to corners a task, at most (each a few cycles; a corner the eye shows
 * and then does not may be set off for again, and this ends it). */
#define WALLBUMP_TRIPS 8
/* Steps to the place a corner toward the task's corner is felt from, at most, before
 * a push (wallbump_corner_look): the way there and back must leave cycles for the
 * push itself. */
#define WALLBUMP_CORNER_REACH 60

/* wallbump_within(c, from, d, at, object): a corner of the wall not felt B whose
 * square could have its centroid nearer `from` than d; its centre in *at, and in
 * *object whether touch felt a letter there (an object leans on the wall). */
bool wallbump_within(const Controller *c, Vec2 from, double d, Vec2 *at, bool *object);

/* wallbump_look(c, dist, from, d, goal): the reachable floor square (dist: steps
 * on the screen, -1 unreached) beside a corner that wallbump_within would name,
 * not yet within touch's reach, fewest steps away: there touch settles it. At most
 * WALLBUMP_TRIPS places a task are set off for (wallbump_going). */
bool wallbump_look(const Controller *c, const int32_t *dist, Vec2 from, double d, Vec2 *goal);

/* wallbump_in_corner(c, best, at): a corner of the wall not felt B whose square,
 * its body away from the floor, lies toward the task's corner (the corner of an
 * object pressed into it) within 2 WALLBUMP_MAX_SIDE of the room's best score
 * `best`, beside floor of the start's room; its centre in *at. WHY: the judge
 * counts an object's squares as the room's (judge.h), and an object pressed into
 * the corner reads as the wall: a square pushed against it stops short of the
 * judge's corner, and Utak, behind the square, cannot feel what it presses on
 * (push.c, push_seat_finish: a doubt). */
bool wallbump_in_corner(const Controller *c, int64_t best, Vec2 *at);

/* wallbump_corner_look(c, dist, best, goal): the reachable floor square (dist:
 * steps on the screen, -1 unreached, at most WALLBUMP_CORNER_REACH) beside a corner
 * that wallbump_in_corner would name against the room's best score `best`, not yet
 * within touch's reach, fewest steps away; false when none, or the task's trips
 * (WALLBUMP_TRIPS) are spent. WHY: pushing, Utak is behind the object and cannot
 * feel what it presses on, so that doubt stood at the corner (push.c,
 * push_seat_finish) wherever the eye showed such a corner; before he grasps, his
 * hands are free and touch settles it (B felt lifts it, a letter leaves it). The
 * rule that decides is wallbump_in_corner's, unchanged: the trip only adds what
 * touch felt. */
bool wallbump_corner_look(const Controller *c, const int32_t *dist, int64_t best, Vec2 *goal);

/* wallbump_corner_set_off(c, dist, best, out): for "push ... into the corner", not
 * holding: wallbump_corner_look, and, if there is a place, the goal set for it (out
 * found and exploring) and counted (wallbump_going). */
bool wallbump_corner_set_off(Controller *c, const int32_t *dist, int64_t best, GoalResult *out);

/* wallbump_going(c, goal): goals.c sets off for a place wallbump_look chose; a
 * place other than the last counts one trip of WALLBUMP_TRIPS. */
void wallbump_going(Controller *c, Vec2 goal);

/* wallbump_set_off(c, dist, d, out): wallbump_look from the start for a square
 * nearer it than d, and, if there is a place, the goal set for it (out found and
 * exploring) and counted (wallbump_going). */
bool wallbump_set_off(Controller *c, const int32_t *dist, double d, GoalResult *out);

/* wallbump_feel(c): after an impression: the squares round Utak touch shows B
 * that are squares of such a corner (the corner or the next of a face) are
 * remembered as wall (c->wall_felt_x, y). */
void wallbump_feel(Controller *c);

#endif
