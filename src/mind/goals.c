/* goals.c - the goals of the tasks (paper 2.3, 3.1 step 7): corners, rooms, frontiers
 * of the unseen, the task's object. CONTROLLER SIDE.
 *
 * A corner is the reachable space of Utak's starting room extreme in that compass
 * direction (his frame: north is +y), judged as the judge judges it (judge.h) on
 * the world model. The next room is reached through a door of the room
 * segmentation (rooms.c): the goal is the other room's centre (nextroom.c,
 * nextroom_goal, asked from goals_choose). An object is named
 * by its shape (shape.c), the nearest of that shape if several; going to it means
 * standing beside it (it shows in touch). When the goal is not yet seen, Utak
 * explores: the nearest frontier of the unseen, or the nearest object seen only
 * coarsely. All coordinates are in the world model's $floor frame unless named
 * screen. */
#include "utak/mind/goals.h"
#include "utak/mind/carrytask.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/joined.h"
#include "utak/mind/seam.h"
#include "utak/mind/objects.h"
#include "utak/mind/push.h"
#include "utak/mind/pushclear.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/faint.h"
#include "utak/mind/hallsplit.h"
#include "utak/mind/nextroom.h"
#include "utak/mind/rival.h"
#include "utak/mind/roomdoubt.h"
#include "utak/mind/wallbump.h"
#include "utak/mind/round.h"
#include "utak/mind/shape.h"
#include "utak/mind/tug.h"

/* goals_reach(g, si, sj, dist): breadth-first steps over g's free cells, 4-connected
 * (the free space's topology, skeleton.h), from (si, sj); -1 where unreached. */
void goals_reach(const Grid *g, int32_t si, int32_t sj, int32_t *dist)
{
	int64_t n = (int64_t)g->w * g->h;
	for (int64_t k = 0; k < n; k++)
		dist[k] = -1;
	if (!grid_free_at(g, si, sj))
		return;
	int32_t *queue = util_alloc((size_t)n, sizeof *queue);
	int64_t head = 0, tail = 0;
	queue[tail++] = sj * g->w + si;
	dist[sj * g->w + si] = 0;
	while (head < tail) {
		int32_t k = queue[head++], x = k % g->w, y = k / g->w;
		static const int8_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
		for (int d = 0; d < 4; d++) {
			int32_t nx = x + step[d][0], ny = y + step[d][1];
			if (grid_free_at(g, nx, ny) && dist[ny * g->w + nx] < 0) {
				dist[ny * g->w + nx] = dist[k] + 1;
				queue[tail++] = ny * g->w + nx;
			}
		}
	}
	free(queue);
}

void goals_roommap_build(RoomMap *r, const Screen *s)
{
	grid_init(&r->known, s->w, s->h, GRID_BLOCKED);
	for (int32_t k = 0; k < s->w * s->h; k++)
		if (s->label[k] != SCREEN_UNKNOWN && s->fixed.cells[k] == GRID_FREE)
			r->known.cells[k] = GRID_FREE;
	goals_roommap_find(r);
}

void goals_roommap_find(RoomMap *r)
{
	skeleton_init(&r->skeleton);
	pathgraph_init(&r->pathgraph);
	rooms_init(&r->rooms);
	skeleton_compute(&r->skeleton, &r->known);
	pathgraph_build(&r->pathgraph, &r->skeleton, &r->known);
	rooms_find(&r->rooms, &r->pathgraph);
}

void goals_roommap_free(RoomMap *r)
{
	rooms_free(&r->rooms);
	pathgraph_free(&r->pathgraph);
	skeleton_free(&r->skeleton);
	grid_free(&r->known);
}

/* ---- corners ---------------------------------------------------------------------- */

/* corner_score: how far a cell lies in the task's compass direction (his frame). */
int64_t goals_corner_score(Corner k, int32_t x, int32_t y)
{
	int sx, sy;
	task_corner_signs(k, &sx, &sy);
	return (int64_t)sx * x + (int64_t)sy * y;
}

/* goals_room_corner_best(c, rm, room): the best corner score of any floor seen in the
 * room (INT64_MIN when none): the corner a subject is measured against, as the
 * judge measures it (judge.h). The room is rooms.c's room merged across every
 * narrowing the verdict does not count as a door, once both its sides are seen
 * whole (carryroom_merge_seen), as the judge's rooms are: a wall stub or a bay cuts
 * no room in two for a corner. */
int64_t goals_room_corner_best(const Controller *c, const RoomMap *rm, int32_t room)
{
	const Screen *s = &c->screen;
	int64_t best = INT64_MIN;
	CarryRooms cr;
	carryroom_merge_seen(rm, &c->screen, &cr);
	int32_t merged = room >= 0 && room < cr.count ? cr.merged[room] : -1;
	for (int32_t at = 0; at < s->w * s->h; at++)
		if (s->label[at] == SCREEN_SPACE && merged >= 0 && carryroom_at(&cr, rm, at % s->w, at / s->w) == merged) {
			int64_t v = goals_corner_score(c->task.corner, s->x0 + at % s->w, s->y0 + at / s->w);
			best = v > best ? v : best;
		}
	carryroom_free(&cr);
	return best;
}

bool goals_in_start_room(const Controller *c, const Vec2 *p, int32_t n)
{
	const Screen *s = &c->screen;
	int32_t si, sj;
	if (n <= 0 || !goals_cell_of(s, c->start, &si, &sj))
		return false;
	RoomMap rm;
	goals_roommap_build(&rm, s);
	CarryRooms cr;
	carryroom_merge_seen(&rm, s, &cr);
	int32_t start = carryroom_at(&cr, &rm, si, sj);
	bool in = false;
	for (int32_t k = 0; k < n && !in && start >= 0; k++) {
		int32_t i, j;
		in = goals_cell_of(s, p[k], &i, &j) && carryroom_at(&cr, &rm, i, j) == start;
	}
	carryroom_free(&cr);
	goals_roommap_free(&rm);
	return in;
}

/* goals_corner(c, g, dist, room): the reachable cell of `room` (merged by the
 * verdict's door rule, as in goals_room_corner_best) extreme toward the task's
 * corner (any room when room < 0). */
bool goals_corner(const Controller *c, const Grid *g, const int32_t *dist, const RoomMap *rm,
			int32_t room, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int64_t best_score = INT64_MIN;
	int32_t best = -1;
	CarryRooms cr;
	carryroom_merge_seen(rm, &c->screen, &cr);
	int32_t merged = room >= 0 && room < cr.count ? cr.merged[room] : -1;
	for (int32_t j = 0; j < g->h; j++)
		for (int32_t i = 0; i < g->w; i++) {
			int32_t k = j * g->w + i;
			if (dist[k] < 0 || (room >= 0 && carryroom_at(&cr, rm, i, j) != merged))
				continue;
			/* Only space seen to be floor: the unknown beyond a verge glimpsed in the
			 * periphery would draw Utak off after corners that are not there. */
			if (s->label[k] == SCREEN_UNKNOWN)
				continue;
			int64_t score = goals_corner_score(c->task.corner, s->x0 + i, s->y0 + j);
			if (score > best_score) {
				best_score = score;
				best = k;
			}
		}
	carryroom_free(&cr);
	if (best < 0)
		return false;
	*goal = goals_centre(s->x0 + best % g->w, s->y0 + best / g->w);
	return true;
}

/* goals_corner_shortfall(c): how far short of the corner of the starting room the task's
 * subject is, by what Utak has seen: Utak himself for "go", the held object for
 * "push". The same measure as the judge's (judge.h), taken on the world model:
 * the best score of any floor seen in the room, less the subject's best. */
int64_t goals_corner_shortfall(Controller *c)
{
	/* The screen of this cycle's impression: when going round in circles is
	 * noticed, step 12 has not yet built it. */
	Vec2 extra[2] = {c->start, c->goal};
	screen_build(&c->screen, &c->model, extra, 2);
	const Screen *s = &c->screen;
	RoomMap rm;
	goals_roommap_build(&rm, s);
	int32_t si, sj;
	goals_cell_of(s, c->start, &si, &sj);
	int32_t start_room = rooms_at(&rm.rooms, si, sj);
	int64_t best = goals_room_corner_best(c, &rm, start_room), got = goals_subject_score(c);
	goals_roommap_free(&rm);
	return best == INT64_MIN ? INT64_MAX : best - got; /* INT64_MAX: no floor seen in the room */
}

/* goals_subject_score(c): the best corner score of the task's subject on the model. */
int64_t goals_subject_score(const Controller *c)
{
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	/* Pushing, the object's squares; else, or when none are left in the held set
	 * (the eye saw them all as floor after a push), Utak's own, beside it. */
	if (c->task.kind == TASK_PUSH_CORNER && c->model.holding && c->model.held_count > 0)
		return goals_held_score(c, ux, uy);
	return goals_corner_score(c->task.corner, ux, uy);
}

int64_t goals_held_score(const Controller *c, int32_t x, int32_t y)
{
	int64_t best = INT64_MIN;
	for (int32_t k = 0; k < c->model.held_count; k++) {
		int64_t v = goals_corner_score(c->task.corner, x + c->model.held_dx[k], y + c->model.held_dy[k]);
		best = v > best ? v : best;
	}
	return best;
}

/* goals_corner_hidden(c): whether floor seen that beats the task's subject may be of
 * the start's room after all (roomdoubt_hidden); if so, the task fails with Utak's
 * doubt. For task (i) hallsplit_hidden_look has come first (controller.c): he has
 * looked from nearby at the coarse squares that may join that floor to his room,
 * while looks were left (HALL_LOOKS) and one could be made, and this is the doubt
 * that stands after them; for a push there is no look yet (he would have to let
 * go first). */
bool goals_corner_hidden(Controller *c)
{
	Vec2 at;
	if (!roomdoubt_hidden(c, goals_subject_score(c), &at))
		return false;
	c->phase = PHASE_FAILED;
	if (c->task.kind == TASK_GO_CORNER)
		snprintf(c->why, sizeof c->why,
			 "Utak cannot tell he is in the %s: floor that would beat it, at (%.1f, %.1f), may be of the room he started in, joined to it by squares seen only coarsely",
			 task_corner_name(c->task.corner), at.x, at.y);
	else
		snprintf(c->why, sizeof c->why,
			 "Utak cannot tell the %s is in the %s: floor that would beat it, at (%.1f, %.1f), may be of the room he started in, joined to it by squares seen only coarsely",
			 task_shape_name(c->task.shape), task_corner_name(c->task.corner), at.x, at.y);
	return true;
}

/* goals_corner_failed(c, short_by): the goal reached, and the corner still short_by
 * (corner_shortfall) away. */
void goals_corner_failed(Controller *c, int64_t short_by)
{
	c->phase = PHASE_FAILED;
	if (short_by == INT64_MAX)
		snprintf(c->why, sizeof c->why, "Utak can no longer place the room he started in");
	else if (c->task.kind == TASK_GO_CORNER)
		snprintf(c->why, sizeof c->why, "Utak can get no nearer the %s than %lld short",
			 task_corner_name(c->task.corner), (long long)short_by);
	else
		snprintf(c->why, sizeof c->why, "the %s can be pushed no nearer the %s than %lld short",
			 task_shape_name(c->task.shape), task_corner_name(c->task.corner), (long long)short_by);
}

/* ---- the other goals ------------------------------------------------------------ */

/* goals_frontier(c, g, dist): the nearest reachable known-floor cell beside an unknown one. */
bool goals_frontier(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	return goals_frontier_within(c, dist, c->start, INFINITY, goal);
}

/* unknown_beside(s, i, j, centre, radius): a 4-neighbour of screen cell (i, j) is
 * unknown, with its centre under radius from centre. */
static bool unknown_beside(const Screen *s, int32_t i, int32_t j, Vec2 centre, double radius)
{
	static const int8_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
	for (int d = 0; d < 4; d++) {
		int32_t a = i + step[d][0], b = j + step[d][1];
		if (screen_label(s, a, b) == SCREEN_UNKNOWN &&
		    (radius == INFINITY || goals_distance(goals_centre(s->x0 + a, s->y0 + b), centre) < radius))
			return true;
	}
	return false;
}

bool goals_unseen_within(const Controller *c, Vec2 centre, double radius)
{
	const Screen *s = &c->screen;
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++)
			if (s->label[j * s->w + i] == SCREEN_SPACE && unknown_beside(s, i, j, centre, radius))
				return true;
	return false;
}

bool goals_frontier_within(const Controller *c, const int32_t *dist, Vec2 centre, double radius, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int32_t best = -1, best_d = INT32_MAX;
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			int32_t k = j * s->w + i;
			if (dist[k] <= 0 || s->label[k] != SCREEN_SPACE || dist[k] >= best_d)
				continue;
			Vec2 here = goals_centre(s->x0 + i, s->y0 + j);
			bool visited = false;
			for (int v = 0; v < c->visited_count && !visited; v++)
				visited = goals_distance(here, c->visited[v]) < 1.0;
			if (visited)
				continue;
			if (unknown_beside(s, i, j, centre, radius)) {
				best = k;
				best_d = dist[k];
			}
		}
	if (best < 0)
		return false;
	*goal = goals_centre(s->x0 + best % s->w, s->y0 + best / s->w);
	return true;
}

/* goals_beside(c, k, dist): the reachable free cell beside object node k (one of the
 * 8 around one of its squares: where touch reaches it) nearest Utak by steps. */
bool goals_beside(const Controller *c, int32_t k, const int32_t *dist, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int32_t best = -1, best_d = INT32_MAX;
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			int32_t at = j * s->w + i;
			if (dist[at] < 0 || dist[at] >= best_d)
				continue;
			bool beside = false, visited = false;
			Vec2 here = goals_centre(s->x0 + i, s->y0 + j);
			for (int v = 0; v < c->visited_count && !visited; v++)
				visited = goals_distance(here, c->visited[v]) < 0.5;
			if (visited)
				continue;
			for (int dy = -1; dy <= 1 && !beside; dy++)
				for (int dx = -1; dx <= 1 && !beside; dx++)
					beside = screen_label(s, i + dx, j + dy) == k;
			if (beside) {
				best = at;
				best_d = dist[at];
			}
		}
	if (best < 0)
		return false;
	*goal = goals_centre(s->x0 + best % s->w, s->y0 + best / s->w);
	return true;
}

/* goals_near(c, p, dist, goal): the reachable free cell nearest point p (ties to
 * the nearer Utak by steps), not a goal already reached, nor one given up because
 * its square read occupied on the way (c->shunned) unless the fovea has seen it
 * since. */
bool goals_near(const Controller *c, Vec2 p, const int32_t *dist, Vec2 *goal)
{
	const Screen *s = &c->screen;
	double best = INFINITY;
	for (int32_t at = 0; at < s->w * s->h; at++) {
		if (dist[at] < 0)
			continue;
		Vec2 here = goals_centre(s->x0 + at % s->w, s->y0 + at / s->w);
		bool visited = false;
		for (int v = 0; v < c->visited_count && !visited; v++)
			visited = goals_distance(here, c->visited[v]) < 0.5;
		for (int v = 0; v < c->shunned_count && !visited; v++)
			visited = goals_distance(here, c->shunned[v]) < 0.5 &&
				  worldmodel_evidence(&c->model, s->x0 + at % s->w, s->y0 + at / s->w).res != WORLDMODEL_RES_FOVEA;
		double d = goals_distance(here, p) + 1e-3 * dist[at];
		if (!visited && d < best) {
			best = d;
			*goal = here;
		}
	}
	return best < INFINITY;
}

bool goals_worth_looking(Controller *c, Vec2 p)
{
	const WorldModel *m = &c->model;
	int32_t x = (int32_t)floor(p.x), y = (int32_t)floor(p.y);
	if (worldmodel_belief(m, x, y) == BELIEF_OCCUPIED)
		return false;
	for (int32_t dy = -GOALS_LOOK; dy <= GOALS_LOOK; dy++)
		for (int32_t dx = -GOALS_LOOK; dx <= GOALS_LOOK; dx++) {
			if (worldmodel_belief(m, x + dx, y + dy) == BELIEF_UNKNOWN)
				return true;
			int32_t k = worldmodel_node_at(m, x + dx, y + dy);
			if (k >= 0 && m->node[k].kind == NODE_OBJECT && !objects_read(c, k).confirmed)
				return true;
		}
	return false;
}

/* goals_inspect(c, dist): beside the nearest object not yet seen whole in the fovea,
 * where a closer look may show its shape: part of looking for an object. */
bool goals_inspect(Controller *c, const int32_t *dist, Vec2 *goal)
{
	const WorldModel *m = &c->model;
	double best_d = INFINITY;
	bool found = false;
	for (int32_t k = 0; k < m->node_count; k++) {
		const ModelNode *n = &m->node[k];
		if (n->kind != NODE_OBJECT || objects_wall(c, k))
			continue;
		Vec2 beside;
		if (objects_read(c, k).confirmed || !goals_beside(c, k, dist, &beside))
			continue;
		double d = goals_distance(beside, m->utak);
		if (d < best_d) {
			best_d = d;
			*goal = beside;
			found = true;
		}
	}
	return found;
}

/* goals_inspect_joined(c, dist, goal): near the nearest square of an occupied set
 * joined to the verge (an uncertain node, paper 3.4.2) that the fovea has not yet
 * seen and that borders floor: seen coarsely, an object near a wall merges with it
 * (a block of 4 squares takes in the floor between them), and only a finer look
 * tells them apart. The last resort of a search: every wall seen coarsely is such a
 * set. */
static bool goals_joined_unseen(const Controller *c, Vec2 *square);
static bool goals_inspect_joined(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	Vec2 best;
	return goals_joined_unseen(c, &best) && goals_near(c, best, dist, goal);
}

bool goals_joined_seen(const Controller *c)
{
	Vec2 square;
	return !goals_joined_unseen(c, &square);
}

/* goals_joined_unseen(c, square): the centre of the nearest square that
 * goals_inspect_joined looks at; false when there is none. */
static bool goals_joined_unseen(const Controller *c, Vec2 *square)
{
	const WorldModel *m = &c->model;
	const Screen *s = &c->screen;
	static const int8_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
	double best_d = INFINITY;
	Vec2 best = vec2(0, 0);
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			int32_t x = s->x0 + i, y = s->y0 + j, k = worldmodel_node_at(m, x, y);
			if (k < 0 || m->node[k].kind != NODE_UNCERTAIN ||
			    worldmodel_evidence(m, x, y).res == WORLDMODEL_RES_FOVEA)
				continue;
			bool edge = false;
			for (int d = 0; d < 4 && !edge; d++)
				edge = worldmodel_belief(m, x + step[d][0], y + step[d][1]) == BELIEF_FLOOR;
			/* ... not looked at already from a goal reached beside it */
			bool looked = false;
			for (int v = 0; v < c->visited_count && !looked; v++)
				looked = goals_distance(goals_centre(x, y), c->visited[v]) <= GOALS_LOOK + 1;
			double dd = goals_distance(goals_centre(x, y), m->utak);
			if (edge && !looked && dd < best_d) {
				best_d = dd;
				best = goals_centre(x, y);
			}
		}
	*square = best;
	return best_d < INFINITY;
}

/* goals_probe_joined(c, dist, goal): the nearest reachable floor cell, not yet
 * reached, at a corner of an occupied set joined to the verge (occupied on two
 * sides at right angles, or only diagonally): where an object against a wall would
 * make one, and from where touch reaches it (tug.h). The search's very last
 * resort, after the eye has seen every such set in the fovea. */
static bool goals_probe_joined(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	const WorldModel *m = &c->model;
	const Screen *s = &c->screen;
	double best_d = INFINITY;
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			int32_t x = s->x0 + i, y = s->y0 + j;
			if (dist[j * s->w + i] < 0 || worldmodel_belief(m, x, y) != BELIEF_FLOOR)
				continue;
			bool occ[TOUCH_CELLS], joined = false;
			int sides = 0;
			for (int t = 0; t < TOUCH_CELLS; t++) {
				int32_t nx = x + goals_touch_offset[t][0], ny = y + goals_touch_offset[t][1];
				int32_t k = worldmodel_node_at(m, nx, ny);
				occ[t] = worldmodel_belief(m, nx, ny) == BELIEF_OCCUPIED;
				joined |= t % 2 == 0 && k >= 0 && m->node[k].kind == NODE_UNCERTAIN;
				sides += t % 2 == 0 && occ[t];
			}
			/* touch order: N NE E SE S SW W NW; sides at right angles are
			 * neighbours in it two apart */
			bool corner = false;
			for (int t = 0; t < TOUCH_CELLS; t += 2)
				corner |= occ[t] && occ[(t + 2) % TOUCH_CELLS];
			for (int t = 1; t < TOUCH_CELLS && sides == 0; t += 2)
				corner |= occ[t];
			if (!joined && sides == 0) {
				for (int t = 1; t < TOUCH_CELLS; t += 2) {
					int32_t k = worldmodel_node_at(m, x + goals_touch_offset[t][0],
								     y + goals_touch_offset[t][1]);
					joined |= occ[t] && k >= 0 && m->node[k].kind == NODE_UNCERTAIN;
				}
			}
			if (!joined || !corner)
				continue;
			/* Utak stands on the corner itself: touch feels all eight squares
			 * round him, both faces and the square between them, so what it
			 * shows does not depend on which way he faces or came; where it
			 * shows an object, goals_felt_tug then chooses where to draw it
			 * back from. */
			int32_t at = j * s->w + i;
			Vec2 here = goals_centre(x, y);
			bool visited = false;
			for (int v = 0; v < c->visited_count && !visited; v++)
				visited = goals_distance(here, c->visited[v]) < 0.5;
			double d = goals_distance(here, m->utak) + 1e-3 * dist[at];
			if (!visited && d < best_d) {
				best_d = d;
				*goal = here;
			}
		}
	return best_d < INFINITY;
}

/* goals_felt_tug(c, dist, goal): the nearest reachable floor cell, not yet reached,
 * beside a square touch felt an object's colour on where the model holds no object
 * (objects_feel), from which Utak can draw that object straight back TUG_STEP
 * squares over floor, and not yet tugged at (tug.h): touch has shown an object
 * against a wall there, and drawing it out is the way to see it. */
static bool goals_felt_tug(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	const WorldModel *m = &c->model;
	const Screen *s = &c->screen;
	static const int8_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
	double best_d = INFINITY;
	if (c->task.kind == TASK_GO_ROUND || c->tug_tries >= TUG_TRIES)
		return false; /* no tug is made (tug.h) */
	for (int f = 0; f < c->felt_squares; f++) {
		int32_t fx = c->felt_x[f], fy = c->felt_y[f], k = worldmodel_node_at(m, fx, fy);
		if (worldmodel_belief(m, fx, fy) != BELIEF_OCCUPIED || (k >= 0 && m->node[k].kind == NODE_OBJECT) ||
		    objects_square_listed(c->tugged_x, c->tugged_y, c->tugged_squares, fx, fy))
			continue;
		for (int d = 0; d < 4; d++) {
			int32_t x = fx + step[d][0], y = fy + step[d][1], i = x - s->x0, j = y - s->y0;
			if (i < 0 || j < 0 || i >= s->w || j >= s->h || dist[j * s->w + i] < 0)
				continue;
			bool way = true; /* the cell and TUG_STEP more straight back: floor */
			for (int t = 0; t <= TUG_STEP && way; t++)
				way = worldmodel_belief(m, x + t * step[d][0], y + t * step[d][1]) == BELIEF_FLOOR;
			Vec2 here = goals_centre(x, y);
			bool visited = false;
			for (int v = 0; v < c->visited_count && !visited; v++)
				visited = goals_distance(here, c->visited[v]) < 0.5;
			double dd = goals_distance(here, m->utak) + 1e-3 * dist[j * s->w + i];
			if (way && !visited && dd < best_d) {
				best_d = dd;
				*goal = here;
			}
		}
	}
	return best_d < INFINITY;
}

/* goals_next_room(c, g, dist, rm, from_room, footprint_ok): the reachable cell nearest
 * the centre of a room next to from_room (through one of its doors). */
bool goals_next_room(const Controller *c, const Grid *g, const int32_t *dist, const RoomMap *rm,
			   int32_t from_room, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int32_t doors[64], n = rooms_doors_of(&rm->rooms, from_room, doors, 64);
	double best_d = INFINITY;
	int32_t best = -1;
	for (int32_t d = 0; d < n && d < 64; d++) {
		const RoomsDoor *door = &rm->rooms.doors[doors[d]];
		int32_t other = door->room_a == from_room ? door->room_b : door->room_a;
		const RoomsRoom *room = &rm->rooms.rooms[other];
		for (int32_t j = 0; j < g->h; j++)
			for (int32_t i = 0; i < g->w; i++) {
				int32_t k = j * g->w + i;
				if (dist[k] < 0 || rooms_at(&rm->rooms, i, j) != other)
					continue;
				double dd = hypot(i - room->x, j - room->y) + 1e-3 * dist[k];
				if (dd < best_d) {
					best_d = dd;
					best = k;
				}
			}
	}
	if (best < 0)
		return false;
	*goal = goals_centre(s->x0 + best % g->w, s->y0 + best / g->w);
	return true;
}

static bool unexamined(Controller *c, int32_t k, bool nearer, const int32_t *dist, Vec2 *goal);

bool goals_more_to_see(Controller *c)
{
	const Grid *g = &c->space;
	if (g->w == 0 || c->screen.w != g->w || c->screen.h != g->h)
		return false;
	int32_t ui, uj;
	goals_cell_of(&c->screen, c->model.utak, &ui, &uj);
	int32_t *dist = util_alloc((size_t)g->w * (size_t)g->h, sizeof *dist);
	goals_reach(g, ui, uj, dist);
	Vec2 p;
	int32_t k = objects_find_target(c);
	bool more = goals_frontier(c, dist, &p) || (k >= 0 && unexamined(c, k, false, dist, &p));
	free(dist);
	return more;
}

/* unexamined(c, k, nearer, dist, goal): the reachable cell nearest a square not yet
 * seen in the fovea of an object never seen whole (objects.h, examined) other than
 * node k, nearer the start than k (centroid to start) when `nearer`, the nearest
 * Utak of those; false when there is none. Each such square is looked at once: not
 * when a goal reached lies within GOALS_LOOK + 1 of it (an object walled in shows
 * no more from a second look, and the looks would take every cycle). */
static bool unexamined(Controller *c, int32_t k, bool nearer, const int32_t *dist, Vec2 *goal)
{
	double d = nearer ? goals_distance(objects_read(c, k).centroid, c->start) : INFINITY, best = INFINITY;
	for (int32_t j = 0; j < c->model.node_count; j++) {
		if (j == k || c->model.node[j].kind != NODE_OBJECT || objects_wall(c, j))
			continue;
		ObjectReading q = objects_read(c, j);
		int32_t x, y;
		Vec2 near;
		if (q.examined || goals_distance(q.centroid, c->start) >= d || !objects_unconfirmed_square(c, j, &x, &y) ||
		    !goals_near(c, goals_centre(x, y), dist, &near) || goals_distance(near, goals_centre(x, y)) > GOALS_LOOK)
			continue;
		bool looked = false;
		for (int v = 0; v < c->visited_count && !looked; v++)
			looked = goals_distance(goals_centre(x, y), c->visited[v]) <= GOALS_LOOK + 1;
		if (looked)
			continue;
		double dd = goals_distance(near, c->model.utak);
		if (dd < best) {
			best = dd;
			*goal = near;
		}
	}
	return best < INFINITY;
}

/* ---- the goal of the current phase ---------------------------------------------- */

/* goals_choose(c, out): the goal of the current phase on the current screen and
 * c->space (the screen's space, or the configuration space when pushing). */
void goals_choose(Controller *c, GoalResult *out)
{
	*out = (GoalResult){0};
	const Screen *s = &c->screen;
	const Grid *g = &c->space;
	int32_t ui, uj;
	goals_cell_of(s, c->model.utak, &ui, &uj);
	int32_t *dist = util_alloc((size_t)g->w * (size_t)g->h, sizeof *dist);
	goals_reach(g, ui, uj, dist);
	RoomMap rm;
	goals_roommap_build(&rm, s);
	int32_t si, sj;
	goals_cell_of(s, c->start, &si, &sj);
	int32_t start_room = rooms_at(&rm.rooms, si, sj), here_room = rooms_at(&rm.rooms, ui, uj);
	const char *shape = task_shape_name(c->task.shape);
	bool pushing = c->phase == PHASE_PUSH;
	int32_t ri, rj;
	switch (c->surveying ? TASK_GO_CORNER : c->task.kind) {
	case TASK_GO_CORNER:
		if (!c->surveying && hallsplit_goal(c, dist, out))
			break; /* beside a blob that may part the hall, to touch it (hallsplit.h) */
		out->found = goals_corner(c, g, dist, &rm, start_room, &out->goal);
		/* A corner only of a room the model can tell is the start's: else a look
		 * first at the wall between, at fine resolution (roomdoubt.h). */
		int32_t li, lj;
		/* Where the start's room runs into the unseen as a passage, a look
		 * from the nearest cell in view of it, swept from the far side toward
		 * the corner, and the passage followed (roomdoubt.h). */
		Vec2 look;
		if (out->found && !c->surveying &&
		    roomdoubt_frontier(c, dist, out->goal, c->room_follow ? &c->room_follow_at : NULL, &look) ==
			ROOMDOUBT_LOOK) {
			c->room_follow = c->room_following = true;
			c->room_follow_at = out->goal = look;
			out->exploring = true;
			break;
		}
		/* A look given up before it was reached (the room map, built on a
		 * screen that moves with him, may draw the room's edge a cell apart
		 * from one cycle to the next) counts as taken: else he would go to
		 * and fro between it and the corner. */
		if (c->room_following && c->visited_count < CONTROLLER_MAX_VISITED)
			c->visited[c->visited_count++] = c->room_follow_at;
		c->room_following = false;
		if (c->room_look && goals_cell_of(s, c->room_look_at, &li, &lj) && dist[lj * g->w + li] >= 0) {
			out->goal = c->room_look_at; /* kept: the map may flip as he moves */
			out->exploring = out->found = true;
		} else if (out->found && !c->surveying &&
			   roomdoubt_check(c, dist, out->goal, &c->room_look_at) == ROOMDOUBT_LOOK) {
			out->goal = c->room_look_at;
			out->exploring = c->room_look = true;
		} else
			c->room_look = false;
		if (!out->found)
			snprintf(out->why, sizeof out->why, "no reachable space toward the %s",
				 task_corner_name(c->task.corner));
		break;
	case TASK_GO_NEXT_ROOM:
		/* A look at a door's unsettled side is kept until reached: the door
		 * reads settled or not as the eye sees its sides from nearer or
		 * farther, and he would go to and fro (roomdoubt_next). */
		if (c->room_look && goals_cell_of(s, c->room_look_at, &ri, &rj) && dist[rj * g->w + ri] >= 0) {
			out->goal = c->room_look_at;
			out->exploring = out->found = true;
			break;
		}
		c->room_look = nextroom_goal(c, g, dist, &rm, si, sj, ui, uj, out);
		if (c->room_look)
			c->room_look_at = out->goal;
		if (!out->found) {
			out->exploring = out->found = goals_frontier(c, dist, &out->goal);
		}
		/* No door: before saying so, a touch of any object that would part the
		 * room in two were it wall (roomdoubt_felt), and a look at any wall
		 * seen only coarsely that may (roomdoubt_door). */
		if (!out->found && roomdoubt_felt(c, dist, &out->goal) == ROOMDOUBT_LOOK)
			out->exploring = out->found = true;
		if (!out->found && roomdoubt_door(c, dist, &out->goal) == ROOMDOUBT_LOOK)
			out->exploring = out->found = true;
		if (!out->found)
			snprintf(out->why, sizeof out->why, "no door out of this room, and nothing left unseen");
		break;
	default: /* an object's task (going round it first finds it) */
		if (!pushing && rival_goal(c, dist, out))
			break; /* another object the claim is in doubt over: settled first (rival.h) */
		if (!pushing && joined_goal(c, out))
			break; /* where the object he would claim can be pulled from (joined.h) */
		if (!pushing && seam_goal(c, out))
			break; /* where the square he would claim can be pushed both ways from (seam.h) */
		if (c->task.kind == TASK_GO_ROUND && c->bump_home) {
			/* Home from a loop, a corner of the wall in doubt: felt first,
			 * then home (wallbump.h); the whole trail counts. */
			int32_t k = objects_find_target(c);
			double nearer = k >= 0 ? goals_distance(objects_read(c, k).centroid, c->start) : 0;
			if (k >= 0 && wallbump_set_off(c, dist, nearer, out))
				break;
			c->bump_home = false;
			round_home(c, k);
		}
		if (c->task.kind == TASK_GO_ROUND && c->round_looking) {
			/* Home from a loop round an object not seen whole: a closer look
			 * at each part unseen, then the start again (round.c). */
			int32_t k = objects_find_target(c);
			if (k >= 0 && round_look(c, k, dist, &out->goal)) {
				out->exploring = out->found = true;
				break;
			}
			/* Seen closer, beside it still: a doubt over another object is
			 * settled from here (rival.h), then home. */
			if (rival_loop_closed(c)) {
				c->round_looking = false;
				if (rival_probing(c)) {
					/* touching it: probed from where he stands, the
					 * arrival's next command (controller.c) */
					out->goal = c->model.utak;
					out->exploring = out->found = true;
					break;
				}
				if (rival_goal(c, dist, out))
					break;
			}
			round_home(c, k);
		}
		if (c->task.kind == TASK_GO_ROUND && c->round_count > 0) {
			out->found = round_goal(c, dist, &out->goal);
			if (!out->found)
				snprintf(out->why, sizeof out->why, "no way round the %s: walls or objects close every way past one side of it",
					 shape);
			break;
		}
		if (pushclear_goal(c, dist, &rm, start_room, out))
			break; /* an object in the way of the corner: move it (pushclear.h) */
		if (!pushing && c->carry && carrytask_goal(c, dist, out))
			break; /* tasks (vi)-(ix): look, survey, grasp for the whole carry */
		if (!pushing) {
			int32_t k = objects_find_target(c), ux, uy;
			bool push_task = c->task.kind != TASK_GO_SHAPE && c->task.kind != TASK_GO_ROUND;
			/* Another object nearer the start, not yet seen whole, may be the
			 * task's (objects_doubt): a closer look at it first. */
			if (k >= 0 && unexamined(c, k, true, dist, &out->goal)) {
				out->exploring = out->found = true;
				break;
			}
			/* The task's object is the nearest of its shape to the start: where
			 * the model has unseen space nearer the start than k's centroid,
			 * a nearer one may lie, and Utak looks there before going to k
			 * (objects.h, THE NEARER UNSEEN). */
			double nearer = k >= 0 ? goals_distance(objects_read(c, k).centroid, c->start) : 0;
			if (k >= 0 && (goals_frontier_within(c, dist, c->start, nearer, &out->goal) ||
				       faint_look(c, dist, c->start, nearer, &out->goal))) {
				out->exploring = out->found = true;
				break;
			}
			/* A corner of the wall nearer the start may be a square pressed
			 * against it: touch settles it first (wallbump.h). */
			if (k >= 0 && c->task.shape == SHAPE_SQUARE && wallbump_set_off(c, dist, nearer, out))
				break;
			/* A target the fovea has shown misread (objects_misread: read
			 * between a square and a brick, or fitted by no rectangle exactly)
			 * may be no object of the task's shape: while anything reachable
			 * is unseen, or an object not seen whole is left, Utak looks there
			 * first for one beyond doubt (which objects_find_target then
			 * prefers); only when nothing is left does he go to the doubtful
			 * one, and says what he doubts. */
			if (k >= 0 && objects_misread(c, k) &&
			    (unexamined(c, k, false, dist, &out->goal) || goals_frontier(c, dist, &out->goal))) {
				out->exploring = out->found = true;
				break;
			}
			/* A hypothesis is looked at closer first: beside the part of it the
			 * fovea has not yet seen. */
			if (k >= 0 && objects_unconfirmed_square(c, k, &ux, &uy) &&
			    goals_near(c, goals_centre(ux, uy), dist, &out->goal)) {
				out->found = true;
				break;
			}
			/* Pushing, behind the object, he cannot feel what it presses on: a
			 * corner of the wall toward the task's corner that may be an object
			 * pressed into it is felt first, hands free (wallbump.h). */
			if (k >= 0 && push_task &&
			    wallbump_corner_set_off(c, dist, goals_room_corner_best(c, &rm, start_room), out))
				break;
			if (k >= 0 && push_task && push_grasp_side(c, k, dist, &rm, start_room, &out->goal)) {
				out->found = true;
				break;
			}
			if (k >= 0 && goals_beside(c, k, dist, &out->goal)) {
				out->found = true;
				break;
			}
			/* Not seen, or not reachable: look further: first at the objects
			 * seen only coarsely (each may be the one, too small or too coarse
			 * to name yet: paper 3.3's hypotheses of low confidence), unless
			 * the unseen is much nearer (GOALS_COARSE_FIRST). */
			Vec2 unseen = vec2(0, 0), coarse = vec2(0, 0);
			bool have_unseen = goals_frontier(c, dist, &unseen);
			bool have_coarse = k < 0 && goals_inspect(c, dist, &coarse);
			if (!have_unseen && !have_coarse && k < 0)
				have_coarse = faint_look(c, dist, c->start, INFINITY, &coarse) ||
					      goals_inspect_joined(c, dist, &coarse) || goals_felt_tug(c, dist, &coarse) ||
					      goals_probe_joined(c, dist, &coarse);
			out->exploring = out->found = have_unseen || have_coarse;
			if (have_unseen && have_coarse)
				out->goal = GOALS_COARSE_FIRST * goals_distance(unseen, c->model.utak) <= goals_distance(coarse, c->model.utak) ? unseen : coarse;
			else
				out->goal = have_unseen ? unseen : coarse;
			if (!out->found && k < 0 && c->tug_wedged > 0)
				/* Touch showed an object against a wall, and it would not come
				 * away: the eye cannot tell its squares from the wall's. */
				snprintf(out->why, sizeof out->why,
					 "no %s seen; touch felt an object against the wall at (%.1f, %.1f) that would not "
					 "come away when drawn back: it may be the %s",
					 shape, c->tug_wedged_at.x, c->tug_wedged_at.y, shape);
			else if (!out->found)
				snprintf(out->why, sizeof out->why,
					 k >= 0 ? "cannot reach the %s: no free square beside it can be reached"
						: "no %s seen, and nothing left unseen or seen only coarsely",
					 shape);
			break;
		}
		/* Pushing: where the held object should go. */
		out->found = push_goal(c, g, dist, &rm, start_room, here_room, ui, uj, &out->goal);
		if (!out->found)
			snprintf(out->why, sizeof out->why,
				 c->task.kind == TASK_PUSH_CORNER ? "the %s cannot be moved toward the corner"
				 : c->task.kind == TASK_PUSH_AROUND_CORNER
				     ? "no corner the %s can be pushed around"
				     : "the %s does not fit through any door of this room without turning",
				 shape);
	}
	goals_roommap_free(&rm);
	free(dist);
}
