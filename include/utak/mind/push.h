/* push.h - pushing an object: where to hold it, where to take it, and seating it in a
 * corner (paper 2.2, 2.3 tasks (v)-(ix)). CONTROLLER SIDE: called by the action
 * cycle (controller.c) and the goals (goals.c). */
#ifndef UTAK_PUSH_H
#define UTAK_PUSH_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"
#include "utak/mind/goals.h"

/* push_mark_bumped(c, g): the squares bumped into are blocked on g (screen cells). */
void push_mark_bumped(const Controller *c, Grid *g);
/* push_bump(c, cmd): cmd made no headway: remember the squares it would have entered. */
void push_bump(Controller *c, const MotorCommand *cmd);
/* push_cspace_of(c, rx, ry, ox, oy, n, out): the configuration space of Utak on model
 * square (rx, ry) holding the n squares at offsets (ox, oy) from his. */
void push_cspace_of(const Controller *c, int32_t rx, int32_t ry, const int32_t *ox, const int32_t *oy, int32_t n,
		    Grid *out);
/* push_cspace_on(base, ox, oy, n, out): base (free where Utak and what he holds may
 * be) eroded by the footprint of his square and the n squares at (ox, oy). */
void push_cspace_on(const Grid *base, const int32_t *ox, const int32_t *oy, int32_t n, Grid *out);
/* push_space(c, out): the configuration space of Utak and what he holds. */
void push_space(Controller *c, Grid *out);
/* push_goal(c, g, dist, rm, start_room, here_room, ui, uj, goal): where the held
 * object should go, on its configuration space g. */
bool push_goal(const Controller *c, const Grid *g, const int32_t *dist, const RoomMap *rm, int32_t start_room,
	       int32_t here_room, int32_t ui, int32_t uj, Vec2 *goal);
/* push_grasp_side(c, k, dist, rm, start_room, goal): the cell beside node k to grasp
 * it from, for the push the task asks. */
bool push_grasp_side(const Controller *c, int32_t k, const int32_t *dist, const RoomMap *rm, int32_t start_room,
		     Vec2 *goal);
/* push_seat_command(c, cmd): the next push that seats the object in the corner, one
 * axis at a time; false when every axis is pressed home. */
bool push_seat_command(Controller *c, MotorCommand *cmd);
/* push_seat(c): after a seating push: on along this axis or on to the next. */
void push_seat(Controller *c);
/* push_seat_finish(c): both axes pressed: judge the corner before letting go. */
void push_seat_finish(Controller *c);
/* push_touch_blocked(c, dx, dy): touch feels the verge or a wall one step (dx, dy) away. */
bool push_touch_blocked(const Controller *c, int dx, int dy);
/* push_seat_begin(c): the push into a corner ends; seating begins (PHASE_SEAT,
 * the first axis, no pushes yet). */
void push_seat_begin(Controller *c);
/* push_seat_here(c): a push into a corner whose plan has stopped working (it goes
 * round in circles, or its pushes make no headway: a wall the eye places a square
 * off, or a gap the object crosses only flush against its wall) ends where it is
 * with seating (PHASE_SEAT, as at the goal): the walls, not the model, place the
 * object, and push_seat_finish judges the corner as ever. False, changing nothing,
 * for any other task or phase. */
bool push_seat_here(Controller *c);
/* push_in_circles(c): after a push: Utak has stood on this square too often since
 * he grasped; true when so: into a corner he then seats the object from where he
 * is (PHASE_SEAT), else the task fails. */
bool push_in_circles(Controller *c);

#endif
