/* judge.h - the ground truth: was the task achieved in the real world? (paper 2.3)
 * SIMULATOR SIDE.
 *
 * The controller believes it has done its task; the judge looks at the world
 * itself (the World and its TABLE, which the controller never sees) and says
 * whether it has. Its verdict is the program's: exit status 0 or 1.
 *
 * It uses only base/ and body/ (tests/wall.test.sh has no exception for it): the
 * shared meaning is doc/verdicts.md's, the code its own. Objects are named
 * by judgeshape.h's rule on their TRUE polygons (exact geometry, orientation
 * free); the task's object is the object of that shape nearest Utak's starting
 * point by area centroid (ties to the earlier in the world file). Rooms, doors
 * and doorways are judgerooms.h's (verge and walls only; objects count as space;
 * a doorway belongs to no room); Utak's starting room, if he starts in a doorway,
 * is the room of the nearest square that has one. Compass directions are in
 * Utak's frame at the start (his north is the way he faced). The rules, per task:
 *   go CORNER       Utak's square is in his starting room and at most JUDGE_SLACK
 *                   short of the room's free square farthest in that direction
 *                   (score x + y, signs by the corner, in his frame);
 *   go next-room    his square is in a room (not a doorway) other than his
 *                   starting room; with one room only, the task does not apply;
 *   go SHAPE        the task's object fills one of the 8 squares around him;
 *   go round SHAPE  his path winds once round the task's object (winding number
 *                   about its centroid over 0.99 in absolute value) and ends within
 *                   JUDGE_HOME of where it began;
 *   push SHAPE CORNER   the object lies in the starting room and has a square at
 *                   most JUDGE_SLACK short of the room's farthest free square;
 *   push SHAPE next-room / through-door   every square of the object lies in one
 *                   room, none in a doorway, other than the room of its centroid
 *                   at the start;
 *   push SHAPE around-corner   the object started (area centroid) in an L-shaped
 *                   corridor (judgerooms.h: two legs and their bend) and every
 *                   square of it now lies in the other leg, none in the bend (from
 *                   the bend itself: in either leg, past the bend); if it did not
 *                   start in such a corridor the task does not apply and the
 *                   verdict says so.
 * A task no sequence of commands could achieve in the true world does not apply
 * either, and the verdict says why (judge.c, "whether a task can be done at
 * all"): the task's object lies where Utak cannot reach it, walls and the verge
 * closing it off from his start (every object counted as space, since he may push
 * it away; his squares 8-connected); go next-room with no other room so reached;
 * go round an object that, with the walls it touches (4-connected), reaches the
 * TABLE's edge, so that no loop can wind round it. Each test errs toward
 * "applies": it calls a task impossible only where it is certain. */
#ifndef UTAK_JUDGE_H
#define UTAK_JUDGE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/body/table.h"
#include "utak/base/task.h"
#include "utak/body/world.h"

/* How far short of a corner counts as in it, in units of the corner score (one
 * diagonal step = 2): the corner square itself or a neighbour along the walls. */
#define JUDGE_SLACK 1
/* How close to his start Utak must end after going round (squares). */
#define JUDGE_HOME 1.5

/* judge_task(start, end, table, task, trail, n, why, size): the verdict. start is
 * the world as it began, end and table as it ended, trail the n points Utak
 * stood at (the first at the start; he went straight from each to the next).
 * why says what was or was not achieved. */
bool judge_task(const World *start, const World *end, const Table *table, const Task *task, const Vec2 *trail,
		int n, char *why, size_t size);

/* judge_squares_read(): how many squares of a TABLE the last judge_task read in its
 * own passes (rebuilding the starting TABLE and the rooms' skeleton aside): its
 * cost, a few passes of the TABLE whatever the task (issue 14: a shape task's
 * verdict once read the TABLE twice per object). For tests and benchmarks; one
 * count for the whole program, so not thread-safe. */
int64_t judge_squares_read(void);

#endif
