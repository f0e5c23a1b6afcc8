/* pushclear.c - clearing the way into a corner: another movable object keeps the one
 * being pushed from the corner, and Utak moves it out of the way first (paper 2.2:
 * every object on the table can be grasped and pushed; 2.3 task (v)). CONTROLLER
 * SIDE. The stages and their bounds are in pushclear.h.
 *
 * WHY by the model and not by touch alone: touch tells a letter (an object) from B
 * (a wall) only for the squares round Utak, and seating presses the task's object
 * against the other one, not him. The model says where every object it has seen
 * lies; the configuration space with those squares freed says whether moving them
 * could let the held object in at all (a wall the eye placed wrongly, or a gap
 * too narrow between walls, is not cured by moving anything), and which one the
 * way meets first. */
#include "utak/mind/pushclear.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/objects.h"
#include "utak/mind/planner.h"
#include "utak/mind/push.h"

/* The four neighbours of a square, for the floods and the rings below. */
static const int8_t clear_step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};

/* free_apart(c, held, at): screen cell at counts as floor round a set drawn off what
 * it touches: believed floor, or a held square (held[] marks them) it will leave. */
static bool free_apart(const Screen *s, const uint8_t *held, int32_t i, int32_t j)
{
	if (i < 0 || j < 0 || i >= s->w || j >= s->h)
		return false;
	int32_t at = j * s->w + i;
	return s->label[at] == SCREEN_SPACE || held[at];
}

/* movable_sets(c, held, mov): marks in mov (screen cells) the squares of every object
 * Utak may move out of the way: a 4-connected set of occupied squares, held ones
 * left out, whose every neighbour is believed floor or held (an isolated object,
 * paper 3.4.2, once what he holds is taken away: pressed against it and a wall,
 * the model joins all three to the verge), other than one touch has felt to be
 * wall (objects_wall). */
static void movable_sets(Controller *c, const uint8_t *held, uint8_t *mov)
{
	const Screen *s = &c->screen;
	int32_t w = s->w, h = s->h;
	size_t cells = (size_t)w * (size_t)h;
	int32_t *queue = util_alloc(cells, sizeof *queue), *seen = util_alloc(cells, sizeof *seen);
	memset(mov, 0, cells);
	for (int32_t at0 = 0; at0 < w * h; at0++) {
		if (seen[at0] || s->free.cells[at0] == GRID_FREE || held[at0])
			continue;
		int32_t head = 0, tail = 0;
		bool isolated = true, wall = false;
		queue[tail++] = at0;
		seen[at0] = 1;
		while (head < tail) {
			int32_t at = queue[head++], i = at % w, j = at / w, l = s->label[at];
			wall |= l >= 0 && l < c->model.node_count && objects_wall(c, l);
			for (int d = 0; d < 4; d++) {
				int32_t ni = i + clear_step[d][0], nj = j + clear_step[d][1], n = nj * w + ni;
				if (ni >= 0 && nj >= 0 && ni < w && nj < h && s->free.cells[n] != GRID_FREE && !held[n]) {
					if (!seen[n]) {
						seen[n] = 1;
						queue[tail++] = n;
					}
				} else if (!free_apart(s, held, ni, nj)) {
					isolated = false;
				}
			}
		}
		if (isolated && !wall)
			for (int32_t q = 0; q < tail; q++)
				mov[queue[q]] = 1;
	}
	free(queue);
	free(seen);
}

/* back_off(c, held, bx, by): the shortest push, at most 3 squares along each axis,
 * away from the corner first, along which the held object's configuration space is
 * strictly free and after which its squares stand apart from everything else (each
 * neighbour believed floor): else the model cannot tell it from the object in the
 * way, or from the wall, once he lets go. Its length in squares (0: apart already),
 * -1 when there is none. */
static int back_off(Controller *c, const uint8_t *held, int *bx, int *by)
{
	const Screen *s = &c->screen;
	const WorldModel *m = &c->model;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	int32_t ui = ux - s->x0, uj = uy - s->y0;
	/* On the screen's space, the held squares freed, not the squares bumped into:
	 * pressed against the object in the way, a halted push marked a whole side
	 * of the held object, and its own side too. */
	Grid base, cs = {0};
	grid_init(&base, s->w, s->h, GRID_BLOCKED);
	memcpy(base.cells, s->free.cells, (size_t)s->w * (size_t)s->h);
	for (int32_t at = 0; at < s->w * s->h; at++)
		if (held[at])
			base.cells[at] = GRID_FREE;
	push_cspace_on(&base, m->held_dx, m->held_dy, m->held_count, &cs);
	grid_free(&base);
	cs.cells[uj * cs.w + ui] = GRID_FREE;
	int sx, sy;
	task_corner_signs(c->task.corner, &sx, &sy);
	int best = -1, best_cost = INT32_MAX;
	for (int dy = -3; dy <= 3; dy++)
		for (int dx = -3; dx <= 3; dx++) {
			/* Fewest squares; of those, away from the corner before along it. */
			int cost = 4 * (abs(dx) + abs(dy)) + (sx * dx + sy * dy > 0 ? 2 : sx * dx + sy * dy == 0 ? 1 : 0);
			if (cost >= best_cost || !grid_free_at(&cs, ui + dx, uj + dy) ||
			    ((dx || dy) && !planner_segment_strict(&cs, vec2(ui + 0.5, uj + 0.5), vec2(ui + dx + 0.5, uj + dy + 0.5))))
				continue;
			bool ok = true;
			for (int32_t q = 0; q < m->held_count && ok; q++) {
				int32_t i = ui + m->held_dx[q] + dx, j = uj + m->held_dy[q] + dy;
				for (int e = 0; e < 4 && ok; e++) {
					int32_t ni = i + clear_step[e][0], nj = j + clear_step[e][1], ex = ni - ui - dx, ey = nj - uj - dy;
					bool own = ex == 0 && ey == 0;
					for (int32_t r = 0; r < m->held_count && !own; r++)
						own = m->held_dx[r] == ex && m->held_dy[r] == ey;
					ok = own || free_apart(s, held, ni, nj);
				}
			}
			if (ok) {
				best_cost = cost;
				best = abs(dx) + abs(dy);
				*bx = dx;
				*by = dy;
			}
		}
	grid_free(&cs);
	return best;
}

/* set_size(mov, w, h, at, seen): the squares of the 4-connected set of mov holding
 * screen cell at (seen: scratch, w * h, all zero on entry and on return). */
static int32_t set_size(const uint8_t *mov, int32_t w, int32_t h, int32_t at, uint8_t *seen, int32_t *queue)
{
	int32_t head = 0, tail = 0;
	queue[tail++] = at;
	seen[at] = 1;
	while (head < tail) {
		int32_t k = queue[head++], i = k % w, j = k / w;
		for (int d = 0; d < 4; d++) {
			int32_t ni = i + clear_step[d][0], nj = j + clear_step[d][1];
			if (ni >= 0 && nj >= 0 && ni < w && nj < h && mov[nj * w + ni] && !seen[nj * w + ni]) {
				seen[nj * w + ni] = 1;
				queue[tail++] = nj * w + ni;
			}
		}
	}
	for (int32_t q = 0; q < tail; q++)
		seen[queue[q]] = 0;
	return tail;
}

bool pushclear_begin(Controller *c, int64_t short_by)
{
	const WorldModel *m = &c->model;
	const Screen *s = &c->screen;
	if (c->clear_tries >= CONTROLLER_CLEAR_TRIES || !m->holding || m->held_count == 0 || short_by == INT64_MAX ||
	    c->task.kind != TASK_PUSH_CORNER)
		return false;
	int32_t ux, uy, w = s->w, h = s->h;
	worldmodel_utak_square(m, &ux, &uy);
	int32_t ui = ux - s->x0, uj = uy - s->y0;
	if (ui < 0 || uj < 0 || ui >= w || uj >= h)
		return false;
	size_t cells = (size_t)w * (size_t)h;
	/* The space with every movable object's squares freed, the held ones too. */
	uint8_t *mov = util_alloc(cells, 1);
	Grid base;
	grid_init(&base, w, h, GRID_BLOCKED);
	memcpy(base.cells, s->free.cells, cells);
	/* Only floor seen: the way must be one the model vouches for. */
	for (size_t at = 0; at < cells; at++)
		if (s->label[at] == SCREEN_UNKNOWN)
			base.cells[at] = GRID_BLOCKED;
	uint8_t *held = util_alloc(cells, 1);
	for (int32_t q = 0; q < m->held_count; q++) {
		int32_t i = ui + m->held_dx[q], j = uj + m->held_dy[q];
		if (i >= 0 && j >= 0 && i < w && j < h)
			held[j * w + i] = 1;
	}
	held[uj * w + ui] = 1; /* his own square, which he leaves with it */
	movable_sets(c, held, mov);
	for (size_t at = 0; at < cells; at++)
		if (mov[at] || held[at])
			base.cells[at] = GRID_FREE;
	/* Squares bumped into are left out: most were bumped into where the held
	 * object met the one in the way (a push halted marks a whole side of it), and
	 * the walls place it in the end (seating). */
	Grid cs = {0};
	push_cspace_on(&base, m->held_dx, m->held_dy, m->held_count, &cs);
	cs.cells[uj * w + ui] = GRID_FREE; /* he stands there */
	int32_t *dist = util_alloc(cells, sizeof *dist);
	goals_reach(&cs, ui, uj, dist);
	/* The cell that takes the held object farthest toward the corner, the nearest
	 * of those; worth clearing for only when it gains more than the slack (the
	 * eye may place a wall a square off: the corner itself need not be reached
	 * on the model, seating presses the object home against the real walls). */
	int64_t now = goals_held_score(c, ux, uy), far = now;
	int32_t target = -1;
	for (size_t at = 0; at < cells; at++) {
		if (dist[at] < 0)
			continue;
		int64_t r = goals_held_score(c, s->x0 + (int32_t)(at % (size_t)w), s->y0 + (int32_t)(at / (size_t)w));
		if (r > far || (r == far && target >= 0 && dist[at] < dist[target])) {
			far = r;
			target = (int32_t)at;
		}
	}
	if (far <= now + CONTROLLER_CORNER_SLACK)
		target = -1;
	/* The way back from it, fewest steps: the squares the held object and Utak
	 * sweep along it, and the first movable object it meets (from Utak). */
	uint8_t *keep = util_alloc(cells, 1), *scratch = util_alloc(cells, 1);
	int32_t *queue = util_alloc(cells, sizeof *queue);
	int32_t blocker = -1;
	for (int32_t at = target; at >= 0;) {
		int32_t i = at % w, j = at / w;
		for (int32_t q = -1; q < m->held_count; q++) {
			int32_t x = i + (q < 0 ? 0 : m->held_dx[q]), y = j + (q < 0 ? 0 : m->held_dy[q]);
			if (x < 0 || y < 0 || x >= w || y >= h)
				continue;
			keep[y * w + x] = 1;
			/* A set of a few squares is no object to grasp: a square the eye
			 * saw part of an object's edge cover, apart from the rest. */
			if (mov[y * w + x] && set_size(mov, w, h, y * w + x, scratch, queue) >= PUSHCLEAR_LEAST)
				blocker = y * w + x;
		}
		if (dist[at] == 0)
			break;
		int32_t prev = -1;
		for (int d = 0; d < 4 && prev < 0; d++) {
			int32_t ni = i + clear_step[d][0], nj = j + clear_step[d][1];
			if (ni >= 0 && nj >= 0 && ni < w && nj < h && dist[nj * w + ni] == dist[at] - 1)
				prev = nj * w + ni;
		}
		at = prev;
	}
	int bx = 0, by = 0;
	bool begun = blocker >= 0 && back_off(c, held, &bx, &by) >= 0;
	if (begun) {
		/* The object in the way: its set (mov is 4-connected sets), by the centre
		 * of its box, which the model's node will have once it stands apart. */
		int32_t head = 0, tail = 0;
		int32_t x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;
		queue[tail++] = blocker;
		mov[blocker] = 2;
		while (head < tail) {
			int32_t at = queue[head++], i = at % w, j = at / w;
			x0 = i < x0 ? i : x0;
			y0 = j < y0 ? j : y0;
			x1 = i > x1 ? i : x1;
			y1 = j > y1 ? j : y1;
			for (int d = 0; d < 4; d++) {
				int32_t ni = i + clear_step[d][0], nj = j + clear_step[d][1];
				if (ni >= 0 && nj >= 0 && ni < w && nj < h && mov[nj * w + ni] == 1) {
					mov[nj * w + ni] = 2;
					queue[tail++] = nj * w + ni;
				}
			}
		}
		c->clear_ident = 0;
		c->clear_at = vec2(s->x0 + (x0 + x1 + 1) / 2.0, s->y0 + (y0 + y1 + 1) / 2.0);
		c->clear_back_x = bx;
		c->clear_back_y = by;
		c->clear_noted = false;
		c->clear_keep_count = 0;
		for (size_t at = 0; at < cells && c->clear_keep_count < CONTROLLER_CLEAR_KEEP; at++)
			if (keep[at]) {
				c->clear_keep_x[c->clear_keep_count] = s->x0 + (int32_t)(at % (size_t)w);
				c->clear_keep_y[c->clear_keep_count++] = s->y0 + (int32_t)(at / (size_t)w);
			}
		/* The squares bumped into beside it, or on the way, were its: they go
		 * with it. */
		int kept = 0;
		for (int b = 0; b < c->bumped_count; b++) {
			int32_t i = c->bumped_x[b] - s->x0, j = c->bumped_y[b] - s->y0;
			bool near = false;
			for (int32_t dj = -1; dj <= 1 && !near; dj++)
				for (int32_t di = -1; di <= 1 && !near; di++)
					near = i + di >= 0 && j + dj >= 0 && i + di < w && j + dj < h &&
					       mov[(j + dj) * w + i + di] == 2;
			if (!near && !(i >= 0 && j >= 0 && i < w && j < h && keep[j * w + i])) {
				c->bumped_x[kept] = c->bumped_x[b];
				c->bumped_y[kept++] = c->bumped_y[b];
			}
		}
		c->bumped_count = kept;
		c->clear_stage = PUSHCLEAR_RELEASE;
		c->clear_tries++;
		c->phase = PHASE_RELEASE;
	}
	free(keep);
	free(scratch);
	free(queue);
	free(dist);
	free(mov);
	free(held);
	grid_free(&cs);
	grid_free(&base);
	return begun;
}

int pushclear_note(Controller *c, char *buf, size_t size)
{
	if (c->clear_noted || (c->clear_stage != PUSHCLEAR_RELEASE && c->clear_stage != PUSHCLEAR_FETCH) || size == 0)
		return 0;
	c->clear_noted = true;
	int n = snprintf(buf, size, "; an object in the way of the %s, about (%.1f, %.1f): moving it out of the way (%d of %d)",
			 task_corner_name(c->task.corner), c->clear_at.x, c->clear_at.y, c->clear_tries,
			 CONTROLLER_CLEAR_TRIES);
	return n < 0 ? 0 : n >= (int)size ? (int)size - 1 : n;
}

bool pushclear_released(Controller *c)
{
	switch (c->clear_stage) {
	case PUSHCLEAR_RELEASE:
		c->clear_stage = PUSHCLEAR_FETCH;
		break;
	case PUSHCLEAR_MOVE:
	case PUSHCLEAR_FETCH:
		c->clear_stage = PUSHCLEAR_NONE; /* out of the way: the task's object again */
		break;
	default:
		return false;
	}
	c->have_plan = false;
	c->pushed_count = 0; /* the next push's circles are its own */
	c->stuck = 0;
	return true;
}

int32_t pushclear_node(Controller *c)
{
	const WorldModel *m = &c->model;
	int32_t best = -1;
	double best_d = 3; /* renumbered by the model: the one whose box's centre is nearest */
	for (int32_t k = 0; k < m->node_count; k++) {
		if (m->node[k].kind != NODE_OBJECT)
			continue;
		if (m->node[k].ident == c->clear_ident) {
			best = k;
			break;
		}
		Vec2 at = vec2((m->node[k].rect.lo.x + m->node[k].rect.hi.x) / 2, (m->node[k].rect.lo.y + m->node[k].rect.hi.y) / 2);
		double d = goals_distance(at, c->clear_at);
		if (d < best_d) {
			best_d = d;
			best = k;
		}
	}
	if (best >= 0) {
		const ModelNode *n = &m->node[best];
		c->clear_ident = n->ident;
		c->clear_at = vec2((n->rect.lo.x + n->rect.hi.x) / 2, (n->rect.lo.y + n->rect.hi.y) / 2);
	}
	return best;
}

bool pushclear_goal(Controller *c, const int32_t *dist, const RoomMap *rm, int32_t start_room, GoalResult *out)
{
	if (c->clear_stage == PUSHCLEAR_MOVE && c->phase == PHASE_PUSH) {
		const Grid *g = &c->space;
		/* No place: let go where it is (arrived at once). */
		if (!pushclear_place(c, g, dist, c->model.held_dx, c->model.held_dy, c->model.held_count, &out->goal))
			out->goal = c->model.utak;
		out->found = true;
		return true;
	}
	if (c->clear_stage != PUSHCLEAR_FETCH || c->phase != PHASE_TRAVEL)
		return false;
	int32_t k = pushclear_node(c);
	if (k >= 0 && push_grasp_side(c, k, dist, rm, start_room, &out->goal)) {
		out->found = true;
		return true;
	}
	c->clear_stage = PUSHCLEAR_NONE; /* no side to push it from: given up */
	return false;
}

bool pushclear_place(const Controller *c, const Grid *g, const int32_t *dist, const int32_t *ox, const int32_t *oy,
		     int32_t n, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int32_t w = g->w, h = g->h;
	/* The way kept free, and a square round it (the eye's error). */
	uint8_t *keep = util_alloc((size_t)w * (size_t)h, 1);
	for (int k = 0; k < c->clear_keep_count; k++)
		for (int32_t dj = -1; dj <= 1; dj++)
			for (int32_t di = -1; di <= 1; di++) {
				int32_t i = c->clear_keep_x[k] - s->x0 + di, j = c->clear_keep_y[k] - s->y0 + dj;
				if (i >= 0 && j >= 0 && i < w && j < h)
					keep[j * w + i] = 1;
			}
	int32_t best = -1;
	for (int32_t at = 0; at < w * h; at++) {
		if (dist[at] < 0 || (best >= 0 && dist[at] >= dist[best]))
			continue;
		int32_t i = at % w, j = at / w;
		bool clear = true;
		for (int32_t q = 0; q < n && clear; q++) {
			int32_t x = i + ox[q], y = j + oy[q];
			clear = !(x >= 0 && y >= 0 && x < w && y < h && keep[y * w + x]);
		}
		if (clear)
			best = at;
	}
	free(keep);
	if (best < 0)
		return false;
	*goal = goals_centre(s->x0 + best % w, s->y0 + best / w);
	return true;
}

bool pushclear_arrive(Controller *c)
{
	if (c->clear_stage == PUSHCLEAR_MOVE && c->phase == PHASE_PUSH) {
		c->phase = PHASE_RELEASE; /* out of the way: let go */
		return true;
	}
	if (c->clear_stage != PUSHCLEAR_FETCH || c->phase != PHASE_TRAVEL)
		return false;
	int32_t k = pushclear_node(c);
	if (k >= 0 && objects_touching(c, k)) {
		c->phase = PHASE_GRASP;
		c->clear_stage = PUSHCLEAR_MOVE;
		c->pushed_count = 0;
	} else {
		c->clear_stage = PUSHCLEAR_NONE; /* touch does not find it here: given up */
	}
	return true;
}

bool pushclear_stop(Controller *c)
{
	if (c->clear_stage != PUSHCLEAR_MOVE || c->phase != PHASE_PUSH)
		return false;
	c->phase = PHASE_RELEASE;
	return true;
}

bool pushclear_back_off(Controller *c, MotorCommand *cmd)
{
	if (c->clear_stage != PUSHCLEAR_RELEASE || (c->clear_back_x == 0 && c->clear_back_y == 0))
		return false;
	*cmd = (MotorCommand){.kind = MOTOR_PUSH, .dx = c->clear_back_x, .dy = c->clear_back_y};
	c->clear_back_x = c->clear_back_y = 0;
	return true;
}
