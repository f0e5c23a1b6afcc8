/* controller.c - the robot-controller: initialization, plan and action cycle (paper 3.1).
 * CONTROLLER SIDE: it knows the world only through impressions and its own commands.
 *
 * The steps are the paper's:
 *   1-5  controller_start: default world model, first impression, regions and
 *        their interpretation, accommodation (worldmodel.c, regions.c);
 *   6    controller_set_task: the task, read in terms of the world model (an object
 *        named but not seen is looked for: Utak explores the frontiers of the
 *        unseen until he sees it or has seen everything);
 *   7    the plan: a goal on the screen, and a path to it (screen.c, planner.c);
 *   8-9  controller_decide: is the task complete? else the next leg of the plan;
 *   10   (the simulator carries it out; main.c);
 *   11   controller_perceive: accommodate the new impression;
 *   12   is the plan still viable (its goal unchanged, its path still free)?
 *   13   if not, plan again.
 *
 * GOALS. A corner is the reachable space of Utak's starting room extreme in that
 * compass direction (his frame: north is +y). The next room is reached through a
 * door of the room segmentation (rooms.c): the goal is the other room's centre.
 * An object is named by its shape (shape.c), the nearest of that shape if several;
 * going to it means standing beside it (it shows in touch). Going round it visits
 * four points outside the corners of its rectangle, counter-clockwise, and
 * returns. Pushing it means: go beside it, grasp, push it (Utak and object
 * rigidly, so any side will do) along a path planned in its configuration space
 * (cspace.c: the screen eroded by the held squares), release. Into a corner,
 * Utak first goes to look at the corner (surveying), and at the end seats the
 * object (PHASE_SEAT): one-square pushes along each axis until one makes no
 * headway, so that the walls, not the eye's estimate of them, place it.
 *
 * All coordinates are in the world model's $floor frame unless named screen. */
#include "utak/mind/controller.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/plan/cspace.h"
#include "utak/mind/rooms.h"
#include "utak/mind/shape.h"
#include "utak/base/util.h"

/* ---- small helpers ------------------------------------------------------------- */

static Vec2 centre_of(int32_t x, int32_t y) { return vec2(x + 0.5, y + 0.5); }

static double distance(Vec2 a, Vec2 b) { return hypot(a.x - b.x, a.y - b.y); }

static Vec2 m_utak(const Controller *c) { return c->model.utak; }

/* The touch squares in Utak's frame, in the order of Impression.touch. */
static const int8_t touch_offset[TOUCH_CELLS][2] = {{0, 1},  {1, 1},   {1, 0},	{1, -1},
						    {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}};

/* touching(c, k): touch shows an object's colour in a square of node k's rectangle
 * (any object when k < 0). */
static bool touching(const Controller *c, int32_t k)
{
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	for (int i = 0; i < TOUCH_CELLS; i++) {
		char colour = c->impression.touch[i];
		if (colour < 'A' || colour > 'Z' || colour == 'B')
			continue;
		if (k < 0)
			return true;
		const Box *r = &c->model.node[k].rect;
		double x = ux + touch_offset[i][0] + 0.5, y = uy + touch_offset[i][1] + 0.5;
		if (x > r->lo.x && x < r->hi.x && y > r->lo.y && y < r->hi.y)
			return true;
	}
	return false;
}

/* Screen cell of a model point; false when off the screen. */
static bool cell_of(const Screen *s, Vec2 p, int32_t *i, int32_t *j)
{
	*i = (int32_t)floor(p.x) - s->x0;
	*j = (int32_t)floor(p.y) - s->y0;
	return *i >= 0 && *j >= 0 && *i < s->w && *j < s->h;
}

/* reach(g, si, sj, dist): breadth-first steps over g's free cells, 4-connected
 * (the free space's topology, skeleton.h), from (si, sj); -1 where unreached. */
static void reach(const Grid *g, int32_t si, int32_t sj, int32_t *dist)
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

/* The rooms of the floor Utak has seen (objects counted as space: moving an
 * object does not change the rooms). Unknown squares are left out here, though the
 * planner goes through them: the optimistic unknown beyond a wall glimpsed through a
 * gap is one vast space, and it would make the seen room a corridor to it, with a
 * door in the middle. The pathgraph borrows the grid and the skeleton. */
typedef struct RoomMap {
	Grid known;
	Skeleton skeleton;
	Pathgraph pathgraph;
	Rooms rooms;
} RoomMap;

static void roommap_build(RoomMap *r, const Screen *s)
{
	grid_init(&r->known, s->w, s->h, GRID_BLOCKED);
	for (int32_t k = 0; k < s->w * s->h; k++)
		if (s->label[k] != SCREEN_UNKNOWN && s->fixed.cells[k] == GRID_FREE)
			r->known.cells[k] = GRID_FREE;
	skeleton_init(&r->skeleton);
	pathgraph_init(&r->pathgraph);
	rooms_init(&r->rooms);
	skeleton_compute(&r->skeleton, &r->known);
	pathgraph_build(&r->pathgraph, &r->skeleton, &r->known);
	rooms_find(&r->rooms, &r->pathgraph);
}

static void roommap_free(RoomMap *r)
{
	rooms_free(&r->rooms);
	pathgraph_free(&r->pathgraph);
	skeleton_free(&r->skeleton);
	grid_free(&r->known);
}

/* ---- objects by shape ------------------------------------------------------------- */

/* object_shape(m, k): the shape of object node k, from the squares believed occupied
 * within its containing rectangle. */
static Shape object_shape(const WorldModel *m, int32_t k)
{
	const ModelNode *n = &m->node[k];
	int32_t x0 = (int32_t)floor(n->rect.lo.x), y0 = (int32_t)floor(n->rect.lo.y);
	int32_t w = (int32_t)ceil(n->rect.hi.x) - x0, h = (int32_t)ceil(n->rect.hi.y) - y0;
	if (w <= 0 || h <= 0 || w > 256 || h > 256)
		return SHAPE_NONE;
	uint8_t *mask = util_alloc((size_t)w * (size_t)h, 1);
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++)
			mask[y * w + x] = worldmodel_belief(m, x0 + x, y0 + y) == BELIEF_OCCUPIED;
	Shape s = shape_classify(mask, w, h);
	free(mask);
	return s;
}

/* seen_at(m, k, res): every square object node k is believed to cover has been seen
 * at resolution res or finer. */
static bool seen_at(const WorldModel *m, int32_t k, int res)
{
	const ModelNode *n = &m->node[k];
	for (int32_t y = (int32_t)floor(n->rect.lo.y); y < (int32_t)ceil(n->rect.hi.y); y++)
		for (int32_t x = (int32_t)floor(n->rect.lo.x); x < (int32_t)ceil(n->rect.hi.x); x++)
			if (worldmodel_belief(m, x, y) == BELIEF_OCCUPIED &&
			    worldmodel_evidence(m, x, y).res < res)
				return false;
	return true;
}

/* find_target(c): the model node of the task's object: the one it chose before if
 * still there, else the object of the task's shape nearest where the task began
 * ("with several, the nearest": nearest Utak when he was given the task, so that
 * the choice does not wander as he walks); -1 when none is seen. */
static int32_t find_target(Controller *c)
{
	const WorldModel *m = &c->model;
	int32_t best = -1;
	double best_d = INFINITY;
	for (int32_t k = 0; k < m->node_count; k++) {
		const ModelNode *n = &m->node[k];
		if (n->kind != NODE_OBJECT)
			continue;
		/* An object is named by the shape it shows now: a coarse first look may
		 * have shown another. The one chosen before is kept, though, until the
		 * fovea has seen all of it and it shows another shape: else a shape read
		 * a square off from one place and right from the next draws Utak to and
		 * fro. */
		bool chosen = c->target != 0 && n->ident == c->target;
		if (object_shape(m, k) != c->task.shape && !(chosen && !seen_at(m, k, WORLDMODEL_RES_FOVEA)))
			continue;
		if (chosen)
			return k;
		Vec2 mid = vec2((n->rect.lo.x + n->rect.hi.x) / 2, (n->rect.lo.y + n->rect.hi.y) / 2);
		double d = distance(mid, c->start);
		if (d < best_d) {
			best_d = d;
			best = k;
		}
	}
	if (best >= 0)
		c->target = m->node[best].ident;
	return best;
}

/* ---- goals ------------------------------------------------------------------------ */

typedef struct GoalResult {
	bool found;
	bool exploring;
	Vec2 goal;		/* model frame */
	char why[160];		/* when not found */
} GoalResult;

/* corner_score: how far a cell lies in the task's compass direction (his frame). */
static int64_t corner_score(Corner k, int32_t x, int32_t y)
{
	int sx, sy;
	task_corner_signs(k, &sx, &sy);
	return (int64_t)sx * x + (int64_t)sy * y;
}

/* room_corner_best(c, rm, room): the best corner score of any floor seen in the
 * room (INT64_MIN when none): the corner a subject is measured against, as the
 * judge measures it (judge.h). */
static int64_t room_corner_best(const Controller *c, const RoomMap *rm, int32_t room)
{
	const Screen *s = &c->screen;
	int64_t best = INT64_MIN;
	for (int32_t at = 0; at < s->w * s->h; at++)
		if (s->label[at] == SCREEN_SPACE && rooms_at(&rm->rooms, at % s->w, at / s->w) == room) {
			int64_t v = corner_score(c->task.corner, s->x0 + at % s->w, s->y0 + at / s->w);
			best = v > best ? v : best;
		}
	return best;
}

/* frontier(c, g, dist): the nearest reachable known-floor cell beside an unknown one. */
static bool frontier(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int32_t best = -1, best_d = INT32_MAX;
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			int32_t k = j * s->w + i;
			if (dist[k] <= 0 || s->label[k] != SCREEN_SPACE || dist[k] >= best_d)
				continue;
			Vec2 here = centre_of(s->x0 + i, s->y0 + j);
			bool visited = false;
			for (int v = 0; v < c->visited_count && !visited; v++)
				visited = distance(here, c->visited[v]) < 1.0;
			if (visited)
				continue;
			if (screen_label(s, i + 1, j) == SCREEN_UNKNOWN || screen_label(s, i - 1, j) == SCREEN_UNKNOWN ||
			    screen_label(s, i, j + 1) == SCREEN_UNKNOWN || screen_label(s, i, j - 1) == SCREEN_UNKNOWN) {
				best = k;
				best_d = dist[k];
			}
		}
	if (best < 0)
		return false;
	*goal = centre_of(s->x0 + best % s->w, s->y0 + best / s->w);
	return true;
}

/* goal_corner(c, g, dist, room): the reachable cell of `room` extreme toward the
 * task's corner (any room when room < 0). */
static bool goal_corner(const Controller *c, const Grid *g, const int32_t *dist, const RoomMap *rm,
			int32_t room, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int64_t best_score = INT64_MIN;
	int32_t best = -1;
	for (int32_t j = 0; j < g->h; j++)
		for (int32_t i = 0; i < g->w; i++) {
			int32_t k = j * g->w + i;
			if (dist[k] < 0 || (room >= 0 && rooms_at(&rm->rooms, i, j) != room))
				continue;
			/* Only space seen to be floor: the unknown beyond a verge glimpsed in the
			 * periphery would draw Utak off after corners that are not there. */
			if (s->label[k] == SCREEN_UNKNOWN)
				continue;
			int64_t score = corner_score(c->task.corner, s->x0 + i, s->y0 + j);
			if (score > best_score) {
				best_score = score;
				best = k;
			}
		}
	if (best < 0)
		return false;
	*goal = centre_of(s->x0 + best % g->w, s->y0 + best / g->w);
	return true;
}

/* goal_beside(c, k, dist): the reachable free cell beside object node k (one of the
 * 8 around one of its squares: where touch reaches it) nearest Utak by steps. */
static bool goal_beside(const Controller *c, int32_t k, const int32_t *dist, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int32_t best = -1, best_d = INT32_MAX;
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			int32_t at = j * s->w + i;
			if (dist[at] < 0 || dist[at] >= best_d)
				continue;
			bool beside = false, visited = false;
			Vec2 here = centre_of(s->x0 + i, s->y0 + j);
			for (int v = 0; v < c->visited_count && !visited; v++)
				visited = distance(here, c->visited[v]) < 0.5;
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
	*goal = centre_of(s->x0 + best % s->w, s->y0 + best / s->w);
	return true;
}

/* goal_inspect(c, dist): beside the nearest object not yet seen whole in the fovea,
 * where a closer look may show its shape: part of looking for an object. */
static bool goal_inspect(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	const WorldModel *m = &c->model;
	double best_d = INFINITY;
	bool found = false;
	for (int32_t k = 0; k < m->node_count; k++) {
		const ModelNode *n = &m->node[k];
		if (n->kind != NODE_OBJECT)
			continue;
		Vec2 beside;
		if (seen_at(m, k, WORLDMODEL_RES_FOVEA) || !goal_beside(c, k, dist, &beside))
			continue;
		double d = distance(beside, m->utak);
		if (d < best_d) {
			best_d = d;
			*goal = beside;
			found = true;
		}
	}
	return found;
}

/* goal_next_room(c, g, dist, rm, from_room, footprint_ok): the reachable cell nearest
 * the centre of a room next to from_room (through one of its doors). */
static bool goal_next_room(const Controller *c, const Grid *g, const int32_t *dist, const RoomMap *rm,
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
	*goal = centre_of(s->x0 + best % g->w, s->y0 + best / g->w);
	return true;
}

/* ---- the plan -------------------------------------------------------------------- */

/* mark_bumped(c, g): the squares bumped into are blocked on g (screen cells). */
static void mark_bumped(const Controller *c, Grid *g)
{
	for (int b = 0; b < c->bumped_count; b++) {
		int32_t i = c->bumped_x[b] - c->screen.x0, j = c->bumped_y[b] - c->screen.y0;
		if (i >= 0 && j >= 0 && i < g->w && j < g->h)
			g->cells[j * g->w + i] = GRID_BLOCKED;
	}
}

/* bump(c, cmd): a move or push made no headway: remember the squares its shapes
 * would have entered, one square on in the commanded direction. */
static void bump(Controller *c, const MotorCommand *cmd)
{
	double len = hypot(cmd->dx, cmd->dy);
	int32_t ux, uy, sx = (int32_t)lround(cmd->dx / len), sy = (int32_t)lround(cmd->dy / len);
	worldmodel_utak_square(&c->model, &ux, &uy);
	int32_t n = cmd->kind == MOTOR_PUSH && c->model.holding ? c->model.held_count : 0;
	for (int32_t k = -1; k < n; k++) {
		int32_t dx = k < 0 ? 0 : c->model.held_dx[k], dy = k < 0 ? 0 : c->model.held_dy[k];
		int32_t tx = dx + sx, ty = dy + sy;
		bool inside = tx == 0 && ty == 0;
		for (int32_t j = 0; j < n && !inside; j++)
			inside = c->model.held_dx[j] == tx && c->model.held_dy[j] == ty;
		if (!inside && c->bumped_count < CONTROLLER_MAX_BUMPED) {
			c->bumped_x[c->bumped_count] = ux + tx;
			c->bumped_y[c->bumped_count++] = uy + ty;
		}
	}
}

/* cspace_of(c, rx, ry, ox, oy, n, out): the configuration space of Utak on model
 * square (rx, ry) holding the n squares at offsets (ox, oy) from his: the screen's
 * space with those squares freed (they move with him) and the squares bumped into
 * blocked, eroded by the footprint of his square and theirs (cspace.c). */
static void cspace_of(const Controller *c, int32_t rx, int32_t ry, const int32_t *ox, const int32_t *oy, int32_t n,
		      Grid *out)
{
	const Screen *s = &c->screen;
	Grid base;
	grid_init(&base, s->w, s->h, GRID_BLOCKED);
	memcpy(base.cells, s->free.cells, (size_t)s->w * (size_t)s->h);
	int32_t *dx = util_alloc((size_t)n + 1, sizeof *dx), *dy = util_alloc((size_t)n + 1, sizeof *dy);
	dx[0] = dy[0] = 0;
	for (int32_t j = 0; j < n; j++) {
		dx[j + 1] = ox[j];
		dy[j + 1] = oy[j];
		int32_t i2 = rx + ox[j] - s->x0, j2 = ry + oy[j] - s->y0;
		if (i2 >= 0 && j2 >= 0 && i2 < s->w && j2 < s->h)
			base.cells[j2 * s->w + i2] = GRID_FREE;
	}
	mark_bumped(c, &base);
	/* The footprint as row runs: sort by (dy, dx) (insertion sort: n is a few
	 * dozen), then join neighbours in a row. */
	for (int32_t a = 1; a <= n; a++)
		for (int32_t b = a; b > 0 && (dy[b] < dy[b - 1] || (dy[b] == dy[b - 1] && dx[b] < dx[b - 1])); b--) {
			int32_t t = dx[b];
			dx[b] = dx[b - 1];
			dx[b - 1] = t;
			t = dy[b];
			dy[b] = dy[b - 1];
			dy[b - 1] = t;
		}
	CSpaceFootprint fp;
	cspace_footprint_init(&fp);
	for (int32_t a = 0; a <= n; a++) {
		if (a > 0 && dy[a] == dy[a - 1] && dx[a] <= fp.run[fp.count - 1].dx1 + 1) {
			if (dx[a] > fp.run[fp.count - 1].dx1)
				fp.run[fp.count - 1].dx1 = dx[a];
			continue;
		}
		fp.run = util_grow(fp.run, &fp.cap, fp.count + 1, sizeof *fp.run);
		fp.run[fp.count++] = (CSpaceRun){dy[a], dx[a], dx[a]};
	}
	grid_free(out);
	grid_init(out, s->w, s->h, GRID_BLOCKED);
	cspace_erode_footprint(&base, &fp, out);
	cspace_footprint_free(&fp);
	free(dx);
	free(dy);
	grid_free(&base);
}

/* space_for_push(c, out): the configuration space of Utak and what he holds. */
static void space_for_push(Controller *c, Grid *out)
{
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	cspace_of(c, ux, uy, c->model.held_dx, c->model.held_dy, c->model.held_count, out);
}

/* build_space(c): the grid to plan on, from the current screen: its space, or
 * when pushing the configuration space. Utak's own square is free whatever the
 * model says of it: he stands there. */
static void build_space(Controller *c)
{
	if (c->phase == PHASE_PUSH) {
		space_for_push(c, &c->space);
	} else {
		grid_free(&c->space);
		grid_init(&c->space, c->screen.w, c->screen.h, GRID_BLOCKED);
		memcpy(c->space.cells, c->screen.free.cells, (size_t)c->screen.w * (size_t)c->screen.h);
		mark_bumped(c, &c->space);
	}
	int32_t i, j;
	if (cell_of(&c->screen, c->model.utak, &i, &j))
		c->space.cells[j * c->space.w + i] = GRID_FREE;
}

/* push_goal(c, g, dist, rm, start_room, here_room, ui, uj, goal): where Utak
 * should take the object he holds (or would hold), on its configuration space g,
 * dist being the steps from his cell (ui, uj) on g: the corner of the starting
 * room, a cell near the centre of a room next to the one he is in, or the nearest
 * place out of sight of where the object was. */
static bool push_goal(const Controller *c, const Grid *g, const int32_t *dist, const RoomMap *rm, int32_t start_room,
		      int32_t here_room, int32_t ui, int32_t uj, Vec2 *goal)
{
	const Screen *s = &c->screen;
	if (c->task.kind == TASK_PUSH_CORNER)
		return goal_corner(c, g, dist, rm, start_room, goal);
	if (c->task.kind == TASK_PUSH_NEXT_ROOM || c->task.kind == TASK_PUSH_THROUGH_DOOR)
		return goal_next_room(c, g, dist, rm, here_room, goal);
	int32_t best = -1;
	for (int32_t j = 0; j < g->h; j++)
		for (int32_t i = 0; i < g->w; i++) {
			int32_t k = j * g->w + i;
			if (dist[k] < 3 || (best >= 0 && dist[k] >= dist[best]))
				continue;
			if (!pathgraph_segment_free(&s->fixed, centre_of(ui, uj), centre_of(i, j)))
				best = k;
		}
	if (best >= 0)
		*goal = centre_of(s->x0 + best % g->w, s->y0 + best / g->w);
	return best >= 0;
}

/* grasp_side(c, k, dist, rm, start_room, goal): for a push task, the cell beside
 * object node k to grasp it from: the nearest (by steps, dist) from which Utak and
 * the object together, as one rigid footprint, can reach a push goal. A square
 * pushed into the north-east corner must be held from the south-west, a brick
 * pushed through a door from its end. False when no side works. */
static bool grasp_side(const Controller *c, int32_t k, const int32_t *dist, const RoomMap *rm, int32_t start_room,
		       Vec2 *goal)
{
	const Screen *s = &c->screen;
	const WorldModel *m = &c->model;
	const ModelNode *n = &m->node[k];
	int32_t x0 = (int32_t)floor(n->rect.lo.x), y0 = (int32_t)floor(n->rect.lo.y);
	int32_t x1 = (int32_t)ceil(n->rect.hi.x), y1 = (int32_t)ceil(n->rect.hi.y);
	int32_t cap = (x1 - x0) * (y1 - y0), count = 0;
	if (cap <= 0 || cap > WORLDMODEL_HELD_MAX)
		return false;
	int32_t *sx = util_alloc((size_t)cap, sizeof *sx), *sy = util_alloc((size_t)cap, sizeof *sy);
	int32_t *ox = util_alloc((size_t)cap, sizeof *ox), *oy = util_alloc((size_t)cap, sizeof *oy);
	for (int32_t y = y0; y < y1; y++)
		for (int32_t x = x0; x < x1; x++)
			if (worldmodel_belief(m, x, y) == BELIEF_OCCUPIED) {
				sx[count] = x;
				sy[count++] = y;
			}
	int32_t *cdist = util_alloc((size_t)s->w * (size_t)s->h, sizeof *cdist);
	bool found = false;
	Grid cs = {0};
	/* Candidates in order of steps from Utak: repeatedly the nearest untried. The
	 * first that works will do, except for a corner, where all are weighed. */
	bool corner = c->task.kind == TASK_PUSH_CORNER;
	int64_t best_score = INT64_MIN, room_best = corner ? room_corner_best(c, rm, start_room) : INT64_MIN;
	for (int32_t d = 0, tried = 0; (!found || corner) && tried < 64;) {
		int32_t best = -1;
		for (int32_t at = 0; at < s->w * s->h; at++) {
			if (dist[at] < d || (best >= 0 && dist[at] >= dist[best]))
				continue;
			int32_t i = at % s->w, j = at / s->w;
			bool beside = false;
			for (int dy = -1; dy <= 1 && !beside; dy++)
				for (int dx = -1; dx <= 1 && !beside; dx++)
					beside = (dx || dy) && screen_label(s, i + dx, j + dy) == k;
			if (beside)
				best = at;
		}
		if (best < 0)
			break;
		d = dist[best];
		/* Every candidate at this distance, in row order. */
		for (int32_t at = best; at < s->w * s->h && (!found || corner); at++) {
			if (dist[at] != d)
				continue;
			int32_t i = at % s->w, j = at / s->w, rx = s->x0 + i, ry = s->y0 + j;
			/* Beside it and no other object: a grasp takes the first object
			 * touch finds (paper 2.2), which must be this one. */
			bool beside = false, other = false;
			for (int dy = -1; dy <= 1; dy++)
				for (int dx = -1; dx <= 1; dx++) {
					int32_t l = screen_label(s, i + dx, j + dy);
					beside |= (dx || dy) && l == k;
					other |= (dx || dy) && l >= 0 && l != k;
				}
			beside &= !other;
			bool visited = false;
			for (int v = 0; v < c->visited_count && !visited; v++)
				visited = distance(centre_of(rx, ry), c->visited[v]) < 0.5;
			if (!beside || visited)
				continue;
			tried++;
			for (int32_t q = 0; q < count; q++) {
				ox[q] = sx[q] - rx;
				oy[q] = sy[q] - ry;
			}
			cspace_of(c, rx, ry, ox, oy, count, &cs);
			if (!grid_free_at(&cs, i, j))
				continue;
			reach(&cs, i, j, cdist);
			Vec2 to;
			if (!push_goal(c, &cs, cdist, rm, start_room, rooms_at(&rm->rooms, i, j), i, j, &to) ||
			    distance(to, centre_of(rx, ry)) <= CONTROLLER_ARRIVED)
				continue;
			if (!corner) {
				*goal = centre_of(rx, ry);
				found = true;
				continue;
			}
			/* Into a corner: how far toward it the object itself gets, Utak at
			 * `to` holding it from this side; the nearest side of the best. */
			int64_t reach_score = INT64_MIN;
			for (int32_t q = 0; q < count; q++) {
				int64_t v = corner_score(c->task.corner, (int32_t)floor(to.x) + ox[q], (int32_t)floor(to.y) + oy[q]);
				reach_score = v > reach_score ? v : reach_score;
			}
			if (reach_score > best_score) {
				best_score = reach_score;
				*goal = centre_of(rx, ry);
				found = true;
				/* Right into the room's own corner: no side can do better. (A
				 * side that leaves Utak between the object and a wall costs a
				 * square, and the judge's slack is all the eye's error.) */
				if (reach_score >= room_best - 1)
					corner = false;
			}
		}
		d++;
	}
	grid_free(&cs);
	free(cdist);
	free(sx);
	free(sy);
	free(ox);
	free(oy);
	return found;
}

/* choose_goal(c, out): the goal of the current phase on the current screen and
 * c->space (the screen's space, or the configuration space when pushing). */
static void choose_goal(Controller *c, GoalResult *out)
{
	*out = (GoalResult){0};
	const Screen *s = &c->screen;
	const Grid *g = &c->space;
	int32_t ui, uj;
	cell_of(s, c->model.utak, &ui, &uj);
	int32_t *dist = util_alloc((size_t)g->w * (size_t)g->h, sizeof *dist);
	reach(g, ui, uj, dist);
	RoomMap rm;
	roommap_build(&rm, s);
	int32_t si, sj;
	cell_of(s, c->start, &si, &sj);
	int32_t start_room = rooms_at(&rm.rooms, si, sj), here_room = rooms_at(&rm.rooms, ui, uj);
	const char *shape = task_shape_name(c->task.shape);
	bool pushing = c->phase == PHASE_PUSH;
	switch (c->surveying ? TASK_GO_CORNER : c->task.kind) {
	case TASK_GO_CORNER:
		out->found = goal_corner(c, g, dist, &rm, start_room, &out->goal);
		if (!out->found)
			snprintf(out->why, sizeof out->why, "no reachable space toward the %s",
				 task_corner_name(c->task.corner));
		break;
	case TASK_GO_NEXT_ROOM:
		if (start_room >= 0 && here_room >= 0 && here_room != start_room) {
			out->found = true; /* already through a door: here will do */
			out->goal = centre_of(s->x0 + ui, s->y0 + uj);
			break;
		}
		out->found = goal_next_room(c, g, dist, &rm, start_room, &out->goal);
		if (!out->found) {
			out->exploring = out->found = frontier(c, dist, &out->goal);
			if (!out->found)
				snprintf(out->why, sizeof out->why, "no door out of this room, and nothing left unseen");
		}
		break;
	default: /* an object's task (going round it first finds it) */
		if (c->task.kind == TASK_GO_ROUND && c->round_count > 0) {
			out->found = true;
			out->goal = c->round[c->round_next];
			break;
		}
		if (!pushing) {
			int32_t k = find_target(c);
			bool push_task = c->task.kind != TASK_GO_SHAPE && c->task.kind != TASK_GO_ROUND;
			if (k >= 0 && push_task && grasp_side(c, k, dist, &rm, start_room, &out->goal)) {
				out->found = true;
				break;
			}
			if (k >= 0 && goal_beside(c, k, dist, &out->goal)) {
				out->found = true;
				break;
			}
			/* Not seen, or not reachable: look further, at the nearer of the
			 * unseen and the objects seen only coarsely. */
			Vec2 unseen, coarse;
			bool have_unseen = frontier(c, dist, &unseen);
			bool have_coarse = k < 0 && goal_inspect(c, dist, &coarse);
			out->exploring = out->found = have_unseen || have_coarse;
			if (have_unseen && have_coarse)
				out->goal = distance(unseen, m_utak(c)) <= distance(coarse, m_utak(c)) ? unseen : coarse;
			else
				out->goal = have_unseen ? unseen : coarse;
			if (!out->found)
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
	roommap_free(&rm);
	free(dist);
}

/* round_points(c, k): the points outside object node k's rectangle corners,
 * counter-clockwise from the one nearest Utak, then his starting point. */
static void round_points(Controller *c, int32_t k)
{
	const ModelNode *n = &c->model.node[k];
	double m = CONTROLLER_ROUND_MARGIN;
	Vec2 p[4] = {vec2(n->rect.lo.x - m, n->rect.lo.y - m), vec2(n->rect.hi.x + m, n->rect.lo.y - m),
		     vec2(n->rect.hi.x + m, n->rect.hi.y + m), vec2(n->rect.lo.x - m, n->rect.hi.y + m)};
	int first = 0;
	for (int i = 1; i < 4; i++)
		if (distance(p[i], c->model.utak) < distance(p[first], c->model.utak))
			first = i;
	for (int i = 0; i < 4; i++) {
		Vec2 q = p[(first + i) % 4];
		c->round[i] = centre_of((int32_t)floor(q.x), (int32_t)floor(q.y));
	}
	/* Back to the first corner closes the loop round the object, then home. */
	c->round[4] = c->round[0];
	c->round[5] = c->start; /* "and return": to where the task began */
	c->round_count = 6;
	c->round_next = 0;
	c->round_ident = n->ident;
	c->round_rect = n->rect;
}

/* believed_turns(c, k): how many times the path Utak believes he took, closed back
 * to its start, winds round the centre of object node k: the judge's measure
 * (judge.c), taken on the world model. */
static double believed_turns(const Controller *c, int32_t k)
{
	const Box *r = &c->model.node[k].rect;
	return geom_winding(c->trail.pts, c->trail.count, vec2((r->lo.x + r->hi.x) / 2, (r->lo.y + r->hi.y) / 2));
}

/* round_stale(c): the loop was laid out round what the model no longer believes is
 * the task's object, or round a rectangle that has since been seen to differ by more
 * than a square: a coarse first look can take a brick for a square. */
static bool round_stale(Controller *c)
{
	if (c->task.kind != TASK_GO_ROUND || c->round_count == 0)
		return false;
	int32_t k = find_target(c);
	if (k < 0 || c->model.node[k].ident != c->round_ident)
		return true;
	Box r = c->model.node[k].rect, o = c->round_rect;
	return fabs(r.lo.x - o.lo.x) > 1 || fabs(r.lo.y - o.lo.y) > 1 || fabs(r.hi.x - o.hi.x) > 1 ||
	       fabs(r.hi.y - o.hi.y) > 1;
}

/* make_plan(c, why): step 7 / 13: a goal and a route to it. False (with why) when
 * the task cannot be done from what Utak knows. */
static bool make_plan(Controller *c, char *why, size_t size)
{
	Vec2 extra[2] = {c->start, c->goal};
	screen_build(&c->screen, &c->model, extra, c->have_plan ? 2 : 1);
	build_space(c);
	GoalResult gr;
	choose_goal(c, &gr);
	if (!gr.found) {
		snprintf(why, size, "%s", gr.why);
		return false;
	}
	if (c->task.kind == TASK_GO_ROUND && c->round_count == 0 && !gr.exploring && c->phase == PHASE_TRAVEL) {
		/* Beside the object is where going round starts: lay out the loop now. */
		int32_t k = find_target(c);
		if (k >= 0) {
			round_points(c, k);
			gr.goal = c->round[0];
		}
	}
	c->goal = gr.goal;
	c->exploring = gr.exploring;
	/* The goal may lie outside the screen built before it was known: only then
	 * build it again, around the goal too. */
	int32_t gi, gj;
	if (!cell_of(&c->screen, c->goal, &gi, &gj)) {
		Vec2 both[2] = {c->start, c->goal};
		screen_build(&c->screen, &c->model, both, 2);
		build_space(c);
	}
	Vec2 from = screen_from_model(&c->screen, c->model.utak), to = screen_from_model(&c->screen, c->goal);
	c->plans_made++;
	c->plan_x0 = c->screen.x0;
	c->plan_y0 = c->screen.y0;
	if (!planner_plan(&c->planner, &c->space, from, to)) {
		snprintf(why, size, "no path to (%.1f, %.1f)", c->goal.x, c->goal.y);
		return false;
	}
	Path way;
	path_init(&way);
	planner_waypoints(&c->space, &c->planner.found, &way);
	path_clear(&c->route);
	for (int i = 0; i < way.count; i++)
		path_push(&c->route, screen_to_model(&c->screen, way.pts[i]));
	path_free(&way);
	c->route.pts[0] = c->model.utak;
	c->route.pts[c->route.count - 1] = c->goal;
	c->next = 1;
	c->have_plan = true;
	return true;
}

/* route_viable(c): the rest of the route is still strictly free on the new space. */
static bool route_viable(const Controller *c)
{
	Vec2 prev = screen_from_model(&c->screen, c->model.utak);
	for (int i = c->next; i < c->route.count; i++) {
		Vec2 p = screen_from_model(&c->screen, c->route.pts[i]);
		if (!planner_segment_strict(&c->space, prev, p))
			return false;
		prev = p;
	}
	return true;
}

/* ---- the cycle -------------------------------------------------------------------- */

void controller_init(Controller *c, PlannerKind planner)
{
	memset(c, 0, sizeof *c);
	c->planner_kind = planner;
	planner_init(&c->planner, planner);
	screen_init(&c->screen);
	path_init(&c->route);
	path_init(&c->trail);
	worldmodel_init(&c->model); /* step 1: the default world model */
}

void controller_free(Controller *c)
{
	worldmodel_free(&c->model);
	screen_free(&c->screen);
	grid_free(&c->space);
	planner_free(&c->planner);
	path_free(&c->route);
	path_free(&c->trail);
}

void controller_set_task(Controller *c, const Task *t)
{
	c->task = *t;
	c->has_task = true;
}

void controller_start(Controller *c, const Impression *first)
{
	c->impression = *first;		/* step 2 */
	regions_find(&c->regions, first); /* steps 3-4 */
	worldmodel_accommodate_first(&c->model, first); /* step 5 */
	c->seen_before = worldmodel_known_squares(&c->model);
	c->start = c->last_position = c->model.utak;
	path_push(&c->trail, c->model.utak);
	if (!c->has_task)
		return;
	c->phase = PHASE_TRAVEL; /* step 6: the task's object is looked for in the plan */
	/* Where a corner is, the eye tells only from close by: walls seen from afar
	 * are placed a square or two off, and a corner behind an obstacle not at all.
	 * Utak goes to look at it before he fetches what he is to push there. */
	c->surveying = c->task.kind == TASK_PUSH_CORNER;
	char why[160];
	if (!make_plan(c, why, sizeof why)) { /* step 7 */
		c->phase = PHASE_FAILED;
		snprintf(c->why, sizeof c->why, "%s", why);
	}
}

/* remember(c, p): a goal reached that is not to be chosen again. */
static void remember(Controller *c, Vec2 p)
{
	if (c->visited_count < CONTROLLER_MAX_VISITED)
		c->visited[c->visited_count++] = p;
}

/* corner_shortfall(c): how far short of the corner of the starting room the task's
 * subject is, by what Utak has seen: Utak himself for "go", the held object for
 * "push". The same measure as the judge's (judge.h), taken on the world model:
 * the best score of any floor seen in the room, less the subject's best. */
static int64_t corner_shortfall(Controller *c)
{
	/* The screen of this cycle's impression: when going round in circles is
	 * noticed, step 12 has not yet built it. */
	Vec2 extra[2] = {c->start, c->goal};
	screen_build(&c->screen, &c->model, extra, 2);
	const Screen *s = &c->screen;
	RoomMap rm;
	roommap_build(&rm, s);
	int32_t si, sj;
	cell_of(s, c->start, &si, &sj);
	int32_t start_room = rooms_at(&rm.rooms, si, sj);
	int64_t best = room_corner_best(c, &rm, start_room), got = INT64_MIN;
	roommap_free(&rm);
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	/* Pushing, the object's squares; else, or when none are left in the held set
	 * (the eye saw them all as floor after a push), Utak's own, beside it. */
	int32_t n = c->task.kind == TASK_PUSH_CORNER && c->model.holding ? c->model.held_count : 0;
	if (n == 0)
		got = corner_score(c->task.corner, ux, uy);
	for (int32_t k = 0; k < n; k++) {
		int64_t v = corner_score(c->task.corner, ux + c->model.held_dx[k], uy + c->model.held_dy[k]);
		got = v > got ? v : got;
	}
	return best == INT64_MIN ? INT64_MAX : best - got; /* INT64_MAX: no floor seen in the room */
}

/* corner_failed(c, short_by): the goal reached, and the corner still short_by
 * (corner_shortfall) away. */
static void corner_failed(Controller *c, int64_t short_by)
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

/* touching_target(c): touch finds the task's object, and from beside it, where
 * the fovea sees it best, it still shows the task's shape (a target kept through a
 * coarse look, find_target, is dropped here if it does not). */
static bool touching_target(Controller *c)
{
	int32_t k = find_target(c);
	if (k < 0 || !touching(c, k))
		return false;
	if (object_shape(&c->model, k) == c->task.shape)
		return true;
	c->target = 0;
	return false;
}

/* arrive(c): what reaching the goal means in the current phase. */
static void arrive(Controller *c)
{
	c->have_plan = false;
	if (c->exploring) {
		remember(c, c->goal); /* a frontier or an object to look at: look again from here */
		return;
	}
	int64_t short_by;
	if (c->surveying) {
		c->surveying = false; /* the corner seen from close by: now the object */
		return;
	}
	switch (c->task.kind) {
	case TASK_GO_NEXT_ROOM:
		c->phase = PHASE_DONE;
		return;
	case TASK_GO_CORNER:
		if ((short_by = corner_shortfall(c)) > CONTROLLER_CORNER_SLACK)
			corner_failed(c, short_by);
		else
			c->phase = PHASE_DONE;
		return;
	case TASK_GO_SHAPE:
		if (touching_target(c))
			c->phase = PHASE_DONE;
		else
			remember(c, c->goal); /* touch says the object is not here after all */
		return;
	case TASK_GO_ROUND:
		if (round_stale(c)) {
			c->round_count = 0; /* round the wrong thing: find the object again */
		} else if (c->round_count > 0 && ++c->round_next == c->round_count) {
			/* Home. A loop begun round the wrong object and the one round the
			 * right one can cancel: then once more round it. */
			int32_t k = find_target(c);
			if (k < 0 || fabs(believed_turns(c, k)) > CONTROLLER_ROUND_TURNS)
				c->phase = PHASE_DONE;
			else if (c->round_loops < CONTROLLER_ROUND_LOOPS) {
				c->round_loops++;
				round_points(c, k);
			} else {
				c->phase = PHASE_FAILED;
				snprintf(c->why, sizeof c->why, "%d more loops round the %s, and still Utak's path does not wind round it",
					 c->round_loops, task_shape_name(c->task.shape));
			}
		}
		return;
	default:
		if (c->phase == PHASE_PUSH && c->task.kind == TASK_PUSH_CORNER) {
			c->phase = PHASE_SEAT;
			c->seat_axis = c->seat_pushes = 0;
		} else if (c->phase == PHASE_PUSH)
			c->phase = PHASE_RELEASE;
		else if (touching_target(c))
			c->phase = PHASE_GRASP;
		else
			remember(c, c->goal);
	}
}

/* seat(c): after a push that seats the object: on along this axis, or, when it
 * made no headway (pressed against a wall) or enough pushes were made, the next
 * axis (controller_decide judges the corner after the last). */
static void seat(Controller *c)
{
	if (distance(c->model.utak, c->seat_from) >= 0.5 && c->seat_pushes < CONTROLLER_SEAT_PUSHES)
		return;
	c->seat_pushes = 0;
	c->seat_axis++;
}

/* seat_finish(c): both axes pressed: the corner as Utak now sees it, and what he
 * holds, judged before he lets go. */
static void seat_finish(Controller *c)
{
	int64_t short_by = corner_shortfall(c);
	if (shape_of_squares(c->model.held_dx, c->model.held_dy, c->model.held_count) != c->task.shape) {
		/* What came along is not what the task named: another object touching
		 * it was grasped, or the model lost part of it. */
		c->phase = PHASE_FAILED;
		snprintf(c->why, sizeof c->why, "what Utak pushed into the %s is not the %s",
			 task_corner_name(c->task.corner), task_shape_name(c->task.shape));
	} else if (short_by > CONTROLLER_CORNER_SLACK)
		corner_failed(c, short_by);
	else
		c->phase = PHASE_RELEASE;
}

/* touch_blocked(c, dx, dy): touch feels the verge or a wall in the square beside
 * Utak one step (dx, dy) away. */
static bool touch_blocked(const Controller *c, int dx, int dy)
{
	for (int i = 0; i < TOUCH_CELLS; i++)
		if (touch_offset[i][0] == dx && touch_offset[i][1] == dy)
			return c->impression.touch[i] == 'B';
	return false;
}

bool controller_decide(Controller *c, MotorCommand *cmd)
{
	*cmd = (MotorCommand){0};
	if (!c->has_task)
		return false;
	c->cycle++;
	/* Step 8 and 9, a few times over if arriving changes the phase. */
	for (int round = 0; round < 4; round++) {
		switch (c->phase) {
		case PHASE_DONE:
		case PHASE_FAILED:
			return false;
		case PHASE_GRASP:
			cmd->kind = MOTOR_GRASP;
			c->phase = PHASE_PUSH;
			c->have_plan = false;
			return true;
		case PHASE_RELEASE:
			cmd->kind = MOTOR_RELEASE;
			c->phase = PHASE_DONE;
			return true;
		case PHASE_SEAT: {
			/* An axis along which touch feels the verge or a wall against
			 * Utak himself is pressed home already: he cannot go that way. */
			int sx, sy, dx = 0, dy = 0;
			task_corner_signs(c->task.corner, &sx, &sy);
			while (c->seat_axis < 2) {
				dx = c->seat_axis == 0 ? sx : 0;
				dy = c->seat_axis == 1 ? sy : 0;
				if (!touch_blocked(c, dx, dy))
					break;
				c->seat_axis++;
				c->seat_pushes = 0;
			}
			if (c->seat_axis == 2) {
				seat_finish(c);
				continue;
			}
			*cmd = (MotorCommand){.kind = MOTOR_PUSH, .dx = dx, .dy = dy};
			c->seat_from = c->model.utak;
			c->seat_pushes++;
			return true;
		}
		case PHASE_TRAVEL:
		case PHASE_PUSH:
			break;
		}
		char why[160];
		if (!c->have_plan && !make_plan(c, why, sizeof why)) {
			c->phase = PHASE_FAILED;
			snprintf(c->why, sizeof c->why, "%s", why);
			return false;
		}
		if (distance(c->model.utak, c->goal) <= CONTROLLER_ARRIVED) {
			arrive(c);
			continue;
		}
		while (c->next < c->route.count - 1 && distance(c->model.utak, c->route.pts[c->next]) <= CONTROLLER_ARRIVED)
			c->next++;
		Vec2 d = vec2_sub(c->route.pts[c->next], c->model.utak);
		double len = hypot(d.x, d.y);
		if (len > CONTROLLER_MAX_LEG) {
			/* A shorter leg ends on a square's centre, like every waypoint, so
			 * that moves are whole squares: shapes then keep their digital form
			 * as they move, and the eye's next impression is predictable. */
			Vec2 to = vec2_add(c->model.utak, vec2_scale(d, CONTROLLER_MAX_LEG / len));
			Vec2 snapped = centre_of((int32_t)floor(to.x), (int32_t)floor(to.y));
			if (distance(snapped, c->model.utak) > CONTROLLER_ARRIVED)
				d = vec2_sub(snapped, c->model.utak);
			else
				d = vec2_scale(d, CONTROLLER_MAX_LEG / len);
		}
		cmd->kind = c->phase == PHASE_PUSH ? MOTOR_PUSH : MOTOR_MOVE;
		cmd->dx = d.x;
		cmd->dy = d.y;
		return true;
	}
	/* Arrived again and again without a command to give: the goals keep landing
	 * where Utak already is. */
	c->phase = PHASE_FAILED;
	snprintf(c->why, sizeof c->why, "no progress: every goal found is where Utak already stands");
	return false;
}

/* going_in_circles(c): after a push, true when Utak has now stood on his square
 * CONTROLLER_CIRCLES times since he grasped: a plan that keeps failing the same way
 * (a wall the eye places a square off) goes round and round. It ends the push with
 * an honest failure: the world model that led him round cannot be trusted to say the
 * object is where it should be. */
static bool going_in_circles(Controller *c)
{
	int32_t ux, uy, visits = 1;
	worldmodel_utak_square(&c->model, &ux, &uy);
	for (int i = 0; i < c->pushed_count; i++)
		visits += c->pushed_x[i] == ux && c->pushed_y[i] == uy;
	if (c->pushed_count < CONTROLLER_MAX_PUSHES) {
		c->pushed_x[c->pushed_count] = ux;
		c->pushed_y[c->pushed_count++] = uy;
	}
	if (visits < CONTROLLER_CIRCLES)
		return false;
	int64_t short_by = c->task.kind == TASK_PUSH_CORNER ? corner_shortfall(c) : INT64_MAX;
	c->phase = PHASE_FAILED;
	if (short_by == INT64_MAX || short_by <= 0)
		snprintf(c->why, sizeof c->why, "pushing the %s round in circles at (%.1f, %.1f)",
			 task_shape_name(c->task.shape), c->model.utak.x, c->model.utak.y);
	else
		snprintf(c->why, sizeof c->why, "pushing the %s round in circles, %lld short of the %s",
			 task_shape_name(c->task.shape), (long long)short_by, task_corner_name(c->task.corner));
	return true;
}

void controller_perceive(Controller *c, const MotorCommand *cmd, const Impression *imp)
{
	c->impression = *imp;
	regions_find(&c->regions, imp);		 /* step 11 */
	worldmodel_accommodate(&c->model, cmd, imp);
	path_push(&c->trail, c->model.utak);
	int32_t seen = worldmodel_known_squares(&c->model);
	int n = snprintf(c->note, sizeof c->note, "model: %+d squares seen", (int)(seen - c->seen_before));
	c->seen_before = seen;
	if (c->model.report.corrected)
		n += snprintf(c->note + n, sizeof c->note - (size_t)n, ", position corrected to (%.1f, %.1f)",
			      c->model.utak.x, c->model.utak.y);
	if (!c->has_task || c->phase == PHASE_DONE || c->phase == PHASE_FAILED)
		return;
	/* No progress: the same believed point after a move or push, cycle after cycle. */
	if ((cmd->kind == MOTOR_MOVE || cmd->kind == MOTOR_PUSH) && hypot(cmd->dx, cmd->dy) > 0 &&
	    distance(c->model.utak, c->last_position) < 0.5 * hypot(cmd->dx, cmd->dy))
		bump(c, cmd);
	if ((cmd->kind == MOTOR_MOVE || cmd->kind == MOTOR_PUSH) && distance(c->model.utak, c->last_position) < 0.05) {
		if (++c->stuck >= CONTROLLER_STUCK_CYCLES) {
			c->phase = PHASE_FAILED;
			snprintf(c->why, sizeof c->why, "stuck at (%.1f, %.1f): every way on is blocked", c->model.utak.x,
				 c->model.utak.y);
			return;
		}
	} else {
		c->stuck = 0;
	}
	c->last_position = c->model.utak;
	if (cmd->kind == MOTOR_PUSH && c->phase == PHASE_PUSH && going_in_circles(c))
		return;
	if (c->phase == PHASE_SEAT) {
		seat(c);
		return;
	}
	if (c->phase != PHASE_TRAVEL && c->phase != PHASE_PUSH)
		return;
	if (!c->have_plan)
		return; /* the next decision plans */
	/* Step 12: is the plan still viable? */
	const char *reason = NULL;
	Vec2 old_goal = c->goal;
	Vec2 extra[2] = {c->start, c->goal};
	screen_build(&c->screen, &c->model, extra, 2);
	build_space(c);
	GoalResult gr;
	if (c->model.report.corrected)
		reason = "Utak is not where he expected";
	else if (round_stale(c)) {
		reason = "the object to go round is not what it seemed";
		c->round_count = 0;
	} else if (!route_viable(c))
		reason = "the path is blocked";
	else if (c->task.kind != TASK_GO_ROUND) {
		choose_goal(c, &gr);
		if (!gr.found || distance(gr.goal, old_goal) > CONTROLLER_ARRIVED || gr.exploring != c->exploring)
			reason = "the goal has moved";
	}
	if (!reason) {
		snprintf(c->note + n, sizeof c->note - (size_t)n, "; plan viable");
		return;
	}
	char why[160];
	c->replans++;
	c->have_plan = false;
	if (!make_plan(c, why, sizeof why)) { /* step 13 */
		c->phase = PHASE_FAILED;
		snprintf(c->why, sizeof c->why, "%s", why);
		snprintf(c->note + n, sizeof c->note - (size_t)n, "; re-plan: %s; no plan", reason);
		return;
	}
	snprintf(c->note + n, sizeof c->note - (size_t)n, "; re-plan: %s; goal (%.1f, %.1f)%s, path %.2f", reason,
		 c->goal.x, c->goal.y, c->exploring ? " (exploring)" : "", c->planner.found_length);
}

/* ---- dumps ------------------------------------------------------------------------ */

void controller_dump_screen(Controller *c, FILE *f)
{
	if (c->screen.w == 0) {
		Vec2 extra = c->start;
		screen_build(&c->screen, &c->model, &extra, 1);
	}
	screen_dump(&c->screen, &c->model, f);
}

void controller_dump_skeleton(Controller *c, FILE *f)
{
	if (!c->planner.have_graph) {
		fputs("skeleton: no plan made on the skeleton\n", f);
		return;
	}
	skeleton_dump(&c->planner.skeleton, &c->planner.grid, f);
}

void controller_dump_pathgraph(Controller *c, FILE *f)
{
	if (!c->planner.have_graph) {
		fputs("pathgraph: no plan made on the skeleton\n", f);
		return;
	}
	pathgraph_dump(&c->planner.pathgraph, f);
}

void controller_dump_rooms(Controller *c, FILE *f)
{
	if (c->screen.w == 0) {
		Vec2 extra = c->start;
		screen_build(&c->screen, &c->model, &extra, 1);
	}
	RoomMap rm;
	roommap_build(&rm, &c->screen);
	rooms_dump(&rm.rooms, &rm.known, f);
	roommap_free(&rm);
}

void controller_dump_path(Controller *c, FILE *f)
{
	planner_dump_path(&c->planner, f);
	if (c->route.count > 0) {
		fprintf(f, "route (model frame), %d waypoints:\n", c->route.count);
		for (int i = 0; i < c->route.count; i++)
			fprintf(f, "  %.2f %.2f%s\n", c->route.pts[i].x, c->route.pts[i].y, i == c->next ? " <- next" : "");
	}
}
