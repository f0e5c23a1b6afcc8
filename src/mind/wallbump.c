/* wallbump.c - a corner of the wall that may be an object pressed against it
 * (paper 3.4.2; the rules in wallbump.h). CONTROLLER SIDE.
 *
 * ALGORITHM. Every square of the model within reach of the bound (the start's
 * distance d plus the deepest centroid, WALLBUMP_MAX_SIDE) is tried as the corner
 * square of each of the four diagonal directions: O(area x 4). */
#include "utak/mind/wallbump.h"

#include <math.h>

#include "utak/mind/goals.h"
#include "utak/mind/objects.h"

/* exact(m, x, y, p): square (x, y) is known to be occupied (p 1) or floor (p 0)
 * as the fovea would know it: seen in the fovea, or in 2 x 2 cells whose levels
 * fixed it (objects_seen_exactly's reason: their five levels count the squares). */
static bool exact(const WorldModel *m, int32_t x, int32_t y, float p)
{
	Evidence e = worldmodel_evidence(m, x, y);
	if (e.res == WORLDMODEL_RES_FOVEA)
		return p > 0.5f ? worldmodel_belief(m, x, y) == BELIEF_OCCUPIED : worldmodel_belief(m, x, y) == BELIEF_FLOOR;
	return e.res == WORLDMODEL_RES_INTERMEDIATE && e.p == p;
}

/* wall(c, x, y): square (x, y) is known occupied (exact) and of no object node
 * (the verge's set, or one joined to it). */
static bool wall(const Controller *c, int32_t x, int32_t y)
{
	const WorldModel *m = &c->model;
	if (!exact(m, x, y, 1.0f))
		return false;
	int32_t k = worldmodel_node_at(m, x, y);
	return k < 0 || m->node[k].kind != NODE_OBJECT;
}

static bool floor_at(const Controller *c, int32_t x, int32_t y)
{
	return exact(&c->model, x, y, 0.0f);
}

/* held_at(c, x, y): square (x, y) is one of the held object's (Utak pushing it). */
static bool held_at(const Controller *c, int32_t x, int32_t y)
{
	const WorldModel *m = &c->model;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	for (int32_t k = 0; k < m->held_count && m->holding; k++)
		if (ux + m->held_dx[k] == x && uy + m->held_dy[k] == y)
			return true;
	return false;
}

/* corner_of(c, x, y, dx, dy, held_floor): (x, y) is a wall square with floor at x +
 * dx, at y + dy and on the diagonal between, and a face of 2 squares of wall each
 * way: (x - dx, y) with floor at y + dy, (x, y - dy) with floor at x + dx. With
 * held_floor the held object's squares are taken for floor (it moves, and was
 * floor's before it came: wallbump_in_corner). */
static bool corner_of(const Controller *c, int32_t x, int32_t y, int dx, int dy, bool held_floor)
{
	const int32_t wx[3] = {x, x - dx, x}, wy[3] = {y, y, y - dy};
	const int32_t fx[5] = {x + dx, x, x + dx, x - dx, x + dx}, fy[5] = {y, y + dy, y + dy, y + dy, y - dy};
	for (int i = 0; i < 3; i++)
		if (!wall(c, wx[i], wy[i]) || (held_floor && held_at(c, wx[i], wy[i])))
			return false;
	for (int i = 0; i < 5; i++)
		if (!floor_at(c, fx[i], fy[i]) && !(held_floor && held_at(c, fx[i], fy[i])))
			return false;
	return true;
}

static bool corner(const Controller *c, int32_t x, int32_t y, int dx, int dy)
{
	return corner_of(c, x, y, dx, dy, false);
}

static bool felt_wall(const Controller *c, int32_t x, int32_t y)
{
	return objects_square_listed(c->wall_felt_x, c->wall_felt_y, c->wall_felt_squares, x, y);
}

/* settled(c, x, y, dx, dy): touch felt B on the corner square or the next of
 * either face, and no letter on any of them. */
static bool settled(const Controller *c, int32_t x, int32_t y, int dx, int dy)
{
	const int32_t sx[3] = {x, x - dx, x}, sy[3] = {y, y, y - dy};
	bool b = false;
	for (int i = 0; i < 3; i++) {
		if (objects_square_listed(c->felt_x, c->felt_y, c->felt_squares, sx[i], sy[i]))
			return false;
		b |= felt_wall(c, sx[i], sy[i]);
	}
	return b;
}

/* nearest(from, x, y, dx, dy): the least distance from `from` to the centroid of a
 * square of side 2 to WALLBUMP_MAX_SIDE whose corner is the outer corner of (x, y)
 * and whose body lies away from the floor (-dx, -dy). */
static double nearest(Vec2 from, int32_t x, int32_t y, int dx, int dy)
{
	Vec2 p = vec2(x + (dx > 0), y + (dy > 0));
	double best = INFINITY;
	for (int a = 2; a <= WALLBUMP_MAX_SIDE; a++) {
		Vec2 q = vec2(p.x - dx * 0.5 * a, p.y - dy * 0.5 * a);
		best = fmin(best, goals_distance(q, from));
	}
	return best;
}

/* tried(c, x, y): a corner square touch has reached (felt, whatever it showed). */
static bool tried(const Controller *c, int32_t x, int32_t y)
{
	return objects_square_listed(c->bump_tried_x, c->bump_tried_y, c->bump_tried, x, y);
}

/* open_corner(c, from, d, x, y, &e): (x, y) is a corner of some direction, not
 * settled by touch, whose square's centroid could lie nearer `from` than d (the
 * least such distance in e). */
static bool open_corner(const Controller *c, Vec2 from, double d, int32_t x, int32_t y, double *e)
{
	bool open = false;
	*e = INFINITY;
	for (int dir = 0; dir < 4; dir++) {
		int dx = dir & 1 ? 1 : -1, dy = dir & 2 ? 1 : -1;
		if (!corner(c, x, y, dx, dy) || settled(c, x, y, dx, dy))
			continue;
		double n = nearest(from, x, y, dx, dy);
		if (n < d) {
			open = true;
			*e = fmin(*e, n);
		}
	}
	return open;
}

bool wallbump_within(const Controller *c, Vec2 from, double d, Vec2 *at, bool *object)
{
	if (!isfinite(d))
		return false;
	int32_t r = (int32_t)ceil(d) + WALLBUMP_MAX_SIDE + 1;
	int32_t fx = (int32_t)floor(from.x), fy = (int32_t)floor(from.y);
	double best = INFINITY, e;
	for (int32_t y = fy - r; y <= fy + r; y++)
		for (int32_t x = fx - r; x <= fx + r; x++)
			if (open_corner(c, from, d, x, y, &e) && e < best) {
				best = e;
				*at = goals_centre(x, y);
				*object = objects_square_listed(c->felt_x, c->felt_y, c->felt_squares, x, y) ||
					  objects_square_listed(c->felt_x, c->felt_y, c->felt_squares, x - 1, y) ||
					  objects_square_listed(c->felt_x, c->felt_y, c->felt_squares, x + 1, y) ||
					  objects_square_listed(c->felt_x, c->felt_y, c->felt_squares, x, y - 1) ||
					  objects_square_listed(c->felt_x, c->felt_y, c->felt_squares, x, y + 1);
			}
	return best < INFINITY;
}

bool wallbump_look(const Controller *c, const int32_t *dist, Vec2 from, double d, Vec2 *goal)
{
	if (!isfinite(d) || c->bump_trips >= WALLBUMP_TRIPS)
		return false;
	const Screen *s = &c->screen;
	int32_t r = (int32_t)ceil(d) + WALLBUMP_MAX_SIDE + 1;
	int32_t fx = (int32_t)floor(from.x), fy = (int32_t)floor(from.y);
	int32_t best = -1;
	double e;
	for (int32_t y = fy - r; y <= fy + r; y++)
		for (int32_t x = fx - r; x <= fx + r; x++) {
			if (tried(c, x, y) || !open_corner(c, from, d, x, y, &e))
				continue;
			/* The floor square beside it fewest steps away: touch there reaches it. */
			for (int32_t j = y - 1; j <= y + 1; j++)
				for (int32_t i = x - 1; i <= x + 1; i++) {
					int32_t si, sj;
					if (!floor_at(c, i, j) || !goals_cell_of(s, goals_centre(i, j), &si, &sj))
						continue;
					int32_t steps = dist[sj * s->w + si];
					if (steps >= 0 && (best < 0 || steps < best)) {
						best = steps;
						*goal = goals_centre(i, j);
					}
				}
		}
	return best >= 0;
}

void wallbump_going(Controller *c, Vec2 goal)
{
	if (c->bump_trips == 0 || goals_distance(goal, c->bump_goal) > 0.5)
		c->bump_trips++;
	c->bump_goal = goal;
}

bool wallbump_set_off(Controller *c, const int32_t *dist, double d, GoalResult *out)
{
	if (!wallbump_look(c, dist, c->start, d, &out->goal))
		return false;
	wallbump_going(c, out->goal);
	out->exploring = out->found = true;
	return true;
}

void wallbump_feel(Controller *c)
{
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	for (int i = 0; i < TOUCH_CELLS; i++) {
		int32_t x = ux + goals_touch_offset[i][0], y = uy + goals_touch_offset[i][1];
		/* A corner square within touch's reach is tried, whatever it showed: a
		 * trip to it is not made again (a letter leaves the doubt standing). B on
		 * a square of some corner (the corner itself or the next of a face) is
		 * wall felt. */
		bool any = false, part = false;
		for (int dir = 0; dir < 4; dir++) {
			int dx = dir & 1 ? 1 : -1, dy = dir & 2 ? 1 : -1;
			bool here = corner(c, x, y, dx, dy);
			any |= here;
			part |= here || corner(c, x + dx, y, dx, dy) || corner(c, x, y + dy, dx, dy);
		}
		if (part && c->impression.touch[i] == 'B' && wall(c, x, y))
			objects_note_square(c->wall_felt_x, c->wall_felt_y, &c->wall_felt_squares, x, y);
		if (any)
			objects_note_square(c->bump_tried_x, c->bump_tried_y, &c->bump_tried, x, y);
	}
}

/* corner_sign(c, sx, sy): the task's corner's direction, the sign of each axis in
 * its score. */
static void corner_sign(const Controller *c, int *sx, int *sy)
{
	*sx = goals_corner_score(c->task.corner, 1, 0) > goals_corner_score(c->task.corner, 0, 0) ? 1 : -1;
	*sy = goals_corner_score(c->task.corner, 0, 1) > goals_corner_score(c->task.corner, 0, 0) ? 1 : -1;
}

/* toward_corner(c, x, y, best, sx, sy): (x, y) is a corner of the wall, its body
 * (away from the floor) toward the task's corner, not settled by touch, within 2
 * WALLBUMP_MAX_SIDE of the room's best score `best`, beside floor of the start's
 * room: wallbump_in_corner's doubt. The held object's squares count as floor. */
static bool toward_corner(const Controller *c, int32_t x, int32_t y, int64_t best, int sx, int sy)
{
	return corner_of(c, x, y, -sx, -sy, true) && !settled(c, x, y, -sx, -sy) &&
	       goals_corner_score(c->task.corner, x, y) >= best - 2 * WALLBUMP_MAX_SIDE &&
	       goals_in_start_room(c, &(Vec2){x - sx + 0.5, y - sy + 0.5}, 1);
}

bool wallbump_in_corner(const Controller *c, int64_t best, Vec2 *at)
{
	const WorldModel *m = &c->model;
	if (m->seen_count == 0 || best == INT64_MIN)
		return false;
	int sx, sy;
	corner_sign(c, &sx, &sy);
	for (int32_t y = m->seen_y0; y <= m->seen_y1; y++)
		for (int32_t x = m->seen_x0; x <= m->seen_x1; x++)
			if (toward_corner(c, x, y, best, sx, sy)) {
				*at = goals_centre(x, y);
				return true;
			}
	return false;
}

bool wallbump_corner_look(const Controller *c, const int32_t *dist, int64_t best, Vec2 *goal)
{
	const WorldModel *m = &c->model;
	const Screen *s = &c->screen;
	if (m->seen_count == 0 || best == INT64_MIN || c->bump_trips >= WALLBUMP_TRIPS)
		return false;
	int sx, sy;
	corner_sign(c, &sx, &sy);
	int32_t fewest = -1;
	for (int32_t y = m->seen_y0; y <= m->seen_y1; y++)
		for (int32_t x = m->seen_x0; x <= m->seen_x1; x++) {
			if (tried(c, x, y) || !toward_corner(c, x, y, best, sx, sy))
				continue;
			/* The floor square beside it fewest steps away: touch there
			 * reaches the corner and the next square of each face. */
			for (int32_t j = y - 1; j <= y + 1; j++)
				for (int32_t i = x - 1; i <= x + 1; i++) {
					int32_t si, sj;
					if (!floor_at(c, i, j) || !goals_cell_of(s, goals_centre(i, j), &si, &sj))
						continue;
					int32_t steps = dist[(int64_t)sj * s->w + si];
					if (steps >= 0 && steps <= WALLBUMP_CORNER_REACH && (fewest < 0 || steps < fewest)) {
						fewest = steps;
						*goal = goals_centre(i, j);
					}
				}
		}
	return fewest >= 0;
}

bool wallbump_corner_set_off(Controller *c, const int32_t *dist, int64_t best, GoalResult *out)
{
	if (c->task.kind != TASK_PUSH_CORNER || c->model.holding || !wallbump_corner_look(c, dist, best, &out->goal))
		return false;
	wallbump_going(c, out->goal);
	out->exploring = out->found = true;
	return true;
}
