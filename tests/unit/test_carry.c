/* test_carry.c - carrying a held object in (x, y, theta) (carry.h, sweep.h; paper 2.2,
 * 3.6, 5).
 *
 * Two oracles. THE SIMULATOR: on fully known worlds (a World and its TABLE, built
 * with the body's own functions; a test may see both sides) the planner plans on a
 * grid made from the TABLE in Utak's frame, and its motor commands are carried out
 * by motion.c: no command may be refused or halt, the TABLE's invariant must hold
 * after each, and the object and Utak must be where the plan says, so every pose
 * the plan checked is one the simulator found free. BRUTE FORCE: on generated door
 * problems, a plain Dijkstra over the same lattice (the same angles, the same
 * exact and tolerant poses, the same sweeps), whose every configuration is tested
 * naively square by square (projection_oracle.h for the TABLE's rule, a
 * segment-to-segment distance for the tolerant one), must find a path exactly when
 * the planner does, and the planner without the route's pruning must find one of
 * the same cost. */
#include <stdlib.h>
#include <string.h>

#include "oracle.h"
#include "projection_oracle.h"
#include "test.h"
#include "world_fixture.h"
#include "utak/plan/carry.h"
#include "utak/plan/sweep.h"

/* ---- Utak's frame and the TABLE -------------------------------------------------- */

/* own_of_table(h, p): a TABLE point in Utak's frame (x right, y ahead), placed so
 * that the TABLE maps onto [0, W'] x [0, H'] (W' x H' = W x H, or H x W sideways). */
static Vec2 own_of_table(Heading hd, Vec2 p)
{
	double W = table.w, H = table.h;
	switch (hd) {
	case HEADING_NORTH:
		return p;
	case HEADING_EAST:
		return vec2(H - p.y, p.x);
	case HEADING_SOUTH:
		return vec2(W - p.x, H - p.y);
	case HEADING_WEST:
		return vec2(p.y, W - p.x);
	}
	return p;
}

static Vec2 table_of_own(Heading hd, Vec2 p)
{
	double W = table.w, H = table.h;
	switch (hd) {
	case HEADING_NORTH:
		return p;
	case HEADING_EAST:
		return vec2(p.y, H - p.x);
	case HEADING_SOUTH:
		return vec2(W - p.x, H - p.y);
	case HEADING_WEST:
		return vec2(W - p.y, p.x);
	}
	return p;
}

/* own_square(hd, i, j, &x, &y): the TABLE square of Utak-frame cell (i, j). */
static void own_square(Heading hd, int32_t i, int32_t j, int32_t *x, int32_t *y)
{
	Vec2 t = table_of_own(hd, vec2(i + 0.5, j + 0.5));
	*x = (int32_t)floor(t.x);
	*y = (int32_t)floor(t.y);
}

typedef bool GoalSquareFn(int32_t x, int32_t y); /* a TABLE square in the goal */

/* A problem on the loaded world: Utak holds (or is about to hold) object 0. */
typedef struct Scene {
	Grid grid, goal;
	CarryObject obj;
	Heading hd;
} Scene;

/* scene_grids(s, goal): the grid in Utak's frame from the TABLE (floor, object 0's
 * squares and Utak's square free) and the goal region. */
static void scene_grids(Scene *s, GoalSquareFn *goal)
{
	Heading hd = world.heading;
	s->hd = hd;
	bool sideways = hd == HEADING_EAST || hd == HEADING_WEST;
	int32_t w = sideways ? table.h : table.w, h = sideways ? table.w : table.h;
	grid_init(&s->grid, w, h, GRID_BLOCKED);
	grid_init(&s->goal, w, h, GRID_BLOCKED);
	int32_t ux, uy;
	table_square_of(world.utak, &ux, &uy);
	for (int32_t j = 0; j < h; j++)
		for (int32_t i = 0; i < w; i++) {
			int32_t x, y;
			own_square(hd, i, j, &x, &y);
			int32_t who = table_owner(&table, x, y);
			if (who == TABLE_FLOOR || who == 1 || (x == ux && y == uy))
				s->grid.cells[j * w + i] = GRID_FREE;
			if (goal(x, y))
				s->goal.cells[j * w + i] = GRID_FREE;
		}
	s->obj.shape = world.objects[0].shape;
	for (int32_t i = 0; i < s->obj.shape.count; i++)
		s->obj.shape.v[i] = own_of_table(hd, s->obj.shape.v[i]);
	s->obj.at = own_of_table(hd, world.utak);
	s->obj.name = "the object";
}

/* scene_make(s, goal): grasps object 0, then scene_grids. */
static void scene_make(Scene *s, GoalSquareFn *goal)
{
	TEST_CHECK(!act(MOTOR_GRASP, 0, 0).refused && world.held == 0);
	scene_grids(s, goal);
}

static void scene_free(Scene *s)
{
	grid_free(&s->grid);
	grid_free(&s->goal);
}

/* grasp_cells(s, at, cap): the centres of the free cells beside object 0 and beside
 * no other object, in Utak's frame; returns how many. */
static int grasp_cells(const Scene *s, Vec2 *at, int cap)
{
	int n = 0;
	for (int32_t j = 0; j < s->grid.h; j++)
		for (int32_t i = 0; i < s->grid.w; i++) {
			int32_t x, y;
			own_square(s->hd, i, j, &x, &y);
			if (table_owner(&table, x, y) != TABLE_FLOOR)
				continue;
			bool beside = false, other = false;
			for (int dy = -1; dy <= 1; dy++)
				for (int dx = -1; dx <= 1; dx++) {
					int32_t who = table_owner(&table, x + dx, y + dy);
					beside |= who == 1;
					other |= who > 1;
				}
			if (beside && !other && n < cap)
				at[n++] = vec2(i + 0.5, j + 0.5);
		}
	return n;
}

static double vertex_gap(const Polygon *a, const Polygon *b)
{
	double worst = 0;
	for (int32_t i = 0; i < a->count; i++)
		worst = fmax(worst, hypot(a->v[i].x - b->v[i].x, a->v[i].y - b->v[i].y));
	return worst;
}

/* meets(region): object 0's squares on the TABLE meet the region. */
static bool meets(GoalSquareFn *region)
{
	for (int32_t y = 0; y < table.h; y++)
		for (int32_t x = 0; x < table.w; x++)
			if (table_owner(&table, x, y) == 1 && region(x, y))
				return true;
	return false;
}

/* Legs are given in parts of at most this many squares (carry_command_part), as the
 * action cycle gives them (controller.h's CONTROLLER_MAX_LEG); 0: whole. */
static double execute_most;

/* act_part(c): carries command c out, in parts when execute_most says so; the
 * outcome of the first part that was refused or halted, else of the last. */
static MotorOutcome act_part(const MotorCommand *c)
{
	MotorCommand leg = *c, part;
	for (;;) {
		bool last = execute_most <= 0 || carry_command_part(&leg, execute_most, &part);
		if (execute_most <= 0)
			part = leg;
		MotorOutcome out = part.kind == MOTOR_TURN ? act(MOTOR_TURN, part.deg, 0) : act(MOTOR_PUSH, part.dx, part.dy);
		if (last || out.refused || out.halted)
			return out;
	}
}

/* execute(s, plan, goal, door): carries the plan out in TABLETOP. Every command must
 * run to its end, and the world must then be in the plan's pose; at the end the
 * object must lie wholly in the goal (the TABLE's squares of it). Returns the
 * degrees turned while the object was in the doorway (door NULL: 0). */
static int32_t execute(const Scene *s, const CarryPlan *plan, GoalSquareFn *goal, GoalSquareFn *door)
{
	Polygon rel = s->obj.shape;
	for (int32_t i = 0; i < rel.count; i++)
		rel.v[i] = vec2_sub(s->obj.shape.v[i], s->obj.at);
	int32_t in_door = 0;
	for (int i = 0; i + 1 < plan->count; i++) {
		const MotorCommand *c = &plan->cmd[i];
		bool before = door && meets(door);
		MotorOutcome out = act_part(c);
		if (out.refused || out.halted) {
			MotorCommand shown = *c;
			fprintf(stderr, "  command %d of %d: ", i + 1, plan->count - 1);
			motion_print(&shown, &out, stderr);
			fputc('\n', stderr);
		}
		TEST_CHECK(!out.refused && !out.halted);
		if (c->kind == MOTOR_TURN && (before || (door && meets(door))))
			in_door += (int32_t)fabs(c->deg);
		const CarryPose *p = &plan->pose[i + 1];
		Polygon want = sweep_turned(&rel, p->at, p->deg);
		for (int32_t v = 0; v < want.count; v++)
			want.v[v] = table_of_own(s->hd, want.v[v]);
		TEST_CHECK(vertex_gap(&want, &world.objects[0].shape) < 1e-9);
		Vec2 u = table_of_own(s->hd, p->at);
		TEST_CHECK(hypot(u.x - world.utak.x, u.y - world.utak.y) < 1e-9);
	}
	for (int32_t y = 0; y < table.h; y++)
		for (int32_t x = 0; x < table.w; x++)
			if (table_owner(&table, x, y) == 1)
				TEST_CHECK(goal(x, y));
	return in_door;
}

/* What a carry did: its turning, all of it and in the doorway. */
typedef struct Carried {
	int32_t turned, in_door;
} Carried;

/* plan_and_carry(goal, params, door): plans on the loaded world (Utak beside object
 * 0) and carries the plan out in TABLETOP. */
static Carried plan_and_carry(GoalSquareFn *goal, const CarryParams *params, GoalSquareFn *door)
{
	Scene s;
	scene_make(&s, goal);
	CarryPlanner cp;
	carry_init(&cp, &s.grid, params);
	CarryResult r;
	carry_result_init(&r);
	CarryGoal goal_region = {.inside = &s.goal};
	CarryStatus st = carry_plan(&cp, &s.obj, &goal_region, &r);
	if (st != CARRY_FOUND)
		fprintf(stderr, "  %s\n", r.why);
	TEST_CHECK(st == CARRY_FOUND);
	Carried done = {r.plan.turned, execute(&s, &r.plan, goal, door)};
	carry_result_free(&r);
	carry_free(&cp);
	scene_free(&s);
	return done;
}

/* ---- the brute force ------------------------------------------------------------- */

/* The lattice of carry.h, written out plainly: configurations (x, y, layer), layers
 * 0 .. N - 1 tolerant at angle `layer`, N .. N + 3 exact at the quarter turns. */
typedef struct Brute {
	const Grid *grid, *goal;
	Polygon rel;
	Vec2 frac;
	int n;
	double reach;
	int deg[CARRY_ANGLES_MAX + 1];
	const Grid *door; /* the doorway's cells, for brute_cost's restriction; NULL: none */
	int span;	  /* the restriction: angles a window holds */
	bool tolerant;	  /* the start is tolerant (carry.h: exact_start false) */
} Brute;

static bool brute_blocked(const Brute *b, int x, int y) { return !grid_free_at(b->grid, x, y); }

/* point_segment2(q, a, b): the squared distance from q to the closed segment ab. */
static double point_segment2(Vec2 q, Vec2 a, Vec2 b)
{
	double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
	double t = len2 > 0 ? ((q.x - a.x) * dx + (q.y - a.y) * dy) / len2 : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	double ex = a.x + t * dx - q.x, ey = a.y + t * dy - q.y;
	return ex * ex + ey * ey;
}

/* segments_distance2(a, b, c, d): squared, between two closed segments. */
static double segments_distance2(Vec2 a, Vec2 b, Vec2 c, Vec2 d)
{
	if (geom_segments_meet(a, b, c, d))
		return 0;
	return fmin(fmin(point_segment2(a, c, d), point_segment2(b, c, d)),
		    fmin(point_segment2(c, a, b), point_segment2(d, a, b)));
}

/* near_square(p, x, y, r): the closed square (x, y) comes nearer than r to p. */
static bool near_square(const Polygon *p, int x, int y, double r)
{
	Box b = geom_polygon_box(p);
	if (b.lo.x >= x + 1 + r || b.hi.x <= x - r || b.lo.y >= y + 1 + r || b.hi.y <= y - r)
		return false;
	if (oracle(p, x, y))
		return true;
	Vec2 sq[4] = {vec2(x, y), vec2(x + 1, y), vec2(x + 1, y + 1), vec2(x, y + 1)};
	for (int k = 0; k < 4; k++)
		if (geom_point_in_polygon(p, sq[k]))
			return true;
	double least = INFINITY;
	for (int i = 0; i < p->count; i++) {
		Vec2 a = p->v[i], c = p->v[(i + 1) % p->count];
		if (a.x >= x && a.x <= x + 1 && a.y >= y && a.y <= y + 1)
			return true;
		for (int k = 0; k < 4; k++)
			least = fmin(least, segments_distance2(a, c, sq[k], sq[(k + 1) % 4]));
	}
	return least < r * r;
}

static Polygon brute_pose(const Brute *b, int x, int y, double deg)
{
	double c, s;
	geom_cos_sin(deg, &c, &s);
	Polygon p = b->rel;
	for (int i = 0; i < p.count; i++) {
		Vec2 d = b->rel.v[i];
		p.v[i] = vec2(x + b->frac.x + c * d.x - s * d.y, y + b->frac.y + s * d.x + c * d.y);
	}
	return p;
}

/* covers_only(b, p, r, region): every square p covers (r == 0: the TABLE's rule;
 * r > 0: within r) is free (region NULL) or in the region; only the others need
 * testing. */
static bool covers_only(const Brute *b, const Polygon *p, double r, const Grid *region)
{
	Box box = geom_polygon_box(p);
	for (int y = (int)floor(box.lo.y) - 1; y <= (int)floor(box.hi.y) + 1; y++)
		for (int x = (int)floor(box.lo.x) - 1; x <= (int)floor(box.hi.x) + 1; x++) {
			bool allowed = region ? grid_free_at(region, x, y) : !brute_blocked(b, x, y);
			if (!allowed && (r == 0 ? oracle(p, x, y) : near_square(p, x, y, r)))
				return false;
		}
	return true;
}

static int brute_angle(const Brute *b, int layer) { return layer < b->n ? layer : (layer - b->n) * b->n / 4; }

static bool brute_body(const Brute *b, int x, int y, int layer)
{
	Polygon p = brute_pose(b, x, y, b->deg[brute_angle(b, layer)]);
	return !brute_blocked(b, x, y) && covers_only(b, &p, layer < b->n ? SWEEP_EPS : 0, NULL);
}

static bool brute_goal(const Brute *b, int x, int y, int layer)
{
	Polygon p = brute_pose(b, x, y, b->deg[brute_angle(b, layer)]);
	return covers_only(b, &p, layer < b->n ? SWEEP_EPS : 0, b->goal);
}

/* brute_turn(b, x, y, k): the step from angle k to k + 1, by samples no vertex moves
 * more than a quarter square between, each within half that of every square it
 * covers, is free. */
static bool brute_turn(const Brute *b, int x, int y, int k)
{
	double d0 = b->deg[k], d1 = b->deg[k + 1];
	double travel = b->reach * (d1 - d0) * 3.14159265358979323846 / 180;
	int m = (int)fmax(1, ceil(travel / 0.25));
	for (int j = 0; j <= m; j++) {
		Polygon p = brute_pose(b, x, y, j == m ? d1 : d0 + (d1 - d0) * j / m);
		if (!covers_only(b, &p, travel / (2.0 * m) + SWEEP_EPS, NULL))
			return false;
	}
	return !brute_blocked(b, x, y);
}

static int64_t brute_turn_cost(const Brute *b, int k)
{
	double c = floor(CARRY_UNIT * b->reach * (b->deg[k + 1] - b->deg[k]) * 3.14159265358979323846 / 180 + 0.5);
	return c < 1 ? 1 : (int64_t)c;
}

/* A plain binary heap of (cost, configuration) for the brute force's Dijkstra. */
typedef struct BruteEntry {
	int64_t cost;
	size_t id;
} BruteEntry;

typedef struct BruteHeap {
	BruteEntry *e;
	size_t count, cap;
} BruteHeap;

static bool brute_less(BruteEntry a, BruteEntry b) { return a.cost < b.cost || (a.cost == b.cost && a.id < b.id); }

static void brute_heap_push(BruteHeap *hp, int64_t cost, size_t id)
{
	if (hp->count == hp->cap) {
		hp->cap = hp->cap ? 2 * hp->cap : 256;
		hp->e = realloc(hp->e, hp->cap * sizeof *hp->e);
	}
	size_t i = hp->count++;
	BruteEntry v = {cost, id};
	while (i > 0 && brute_less(v, hp->e[(i - 1) / 2])) {
		hp->e[i] = hp->e[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	hp->e[i] = v;
}

static BruteEntry brute_heap_pop(BruteHeap *hp)
{
	BruteEntry top = hp->e[0], last = hp->e[--hp->count];
	size_t i = 0;
	for (;;) {
		size_t c = 2 * i + 1;
		if (c >= hp->count)
			break;
		if (c + 1 < hp->count && brute_less(hp->e[c + 1], hp->e[c]))
			c++;
		if (!brute_less(hp->e[c], last))
			break;
		hp->e[i] = hp->e[c];
		i = c;
	}
	if (hp->count > 0)
		hp->e[i] = last;
	return top;
}

/* brute_meets(b, x, y, layer, region): the object's squares meet the region. */
static bool brute_meets(const Brute *b, int x, int y, int layer, const Grid *region)
{
	Polygon p = brute_pose(b, x, y, b->deg[brute_angle(b, layer)]);
	Box box = geom_polygon_box(&p);
	double r = layer < b->n ? SWEEP_EPS : 0;
	for (int yy = (int)floor(box.lo.y) - 1; yy <= (int)floor(box.hi.y) + 1; yy++)
		for (int xx = (int)floor(box.lo.x) - 1; xx <= (int)floor(box.hi.x) + 1; xx++)
			if (grid_free_at(region, xx, yy) && (r == 0 ? oracle(&p, xx, yy) : near_square(&p, xx, yy, r)))
				return true;
	return false;
}

/* brute_cost(b, obj, n): the least cost of a carry to the goal by Dijkstra over the
 * whole lattice at n angles, -1 when none. With b->door set, only paths on which
 * the object, each time it is in the doorway (its squares meeting b->door), keeps
 * within b->span neighbouring angles: the search's state then carries the window
 * (none outside the doorway; on entering, any window holding the angle). */
static int64_t brute_cost(Brute *b, const CarryObject *obj, int n)
{
	int w = b->grid->w, h = b->grid->h, layers = n + 4;
	b->n = n;
	b->rel = obj->shape;
	for (int i = 0; i < b->rel.count; i++)
		b->rel.v[i] = vec2_sub(obj->shape.v[i], obj->at);
	b->frac = vec2(obj->at.x - floor(obj->at.x), obj->at.y - floor(obj->at.y));
	b->reach = 0;
	for (int i = 0; i < b->rel.count; i++)
		b->reach = fmax(b->reach, hypot(b->rel.v[i].x, b->rel.v[i].y));
	for (int k = 0; k <= n; k++)
		b->deg[k] = (int)floor(k * 360.0 / n + 0.5);
	size_t configs = (size_t)layers * w * h, windows = b->door ? (size_t)n + 1 : 1, none = windows - 1;
	size_t total = configs * windows;
	int64_t *dist = malloc(total * sizeof *dist);
	uint8_t *done = calloc(total, 1), *body = calloc(configs, 1), *door = calloc(configs, 1);
	uint8_t *turn = calloc((size_t)n * w * h, 1);
	for (size_t i = 0; i < total; i++)
		dist[i] = INT64_MAX;
	BruteHeap open = {0};
	int64_t answer = -1;
	/* enter(cfg, from_window, cost): reach configuration cfg from a state with window
	 * from_window (none when outside the doorway). */
#define ENTER(cfg, from_window, cost)                                                                  \
	do {                                                                                           \
		size_t c_ = (cfg);                                                                     \
		int l_ = (int)(c_ / ((size_t)w * h)), cell_ = (int)(c_ % ((size_t)w * h));            \
		size_t wins_[CARRY_ANGLES_MAX];                                                        \
		int nw_ = 0;                                                                           \
		if (b->door && !door[c_])                                                              \
			door[c_] = brute_meets(b, cell_ % w, cell_ / w, l_, b->door) ? 1 : 2;         \
		if (!b->door || door[c_] == 2) {                                                       \
			wins_[nw_++] = none;                                                           \
		} else {                                                                               \
			size_t a_ = (size_t)brute_angle(b, l_);                                        \
			if ((from_window) == none) {                                                   \
				for (int k_ = 0; k_ < b->span; k_++)                                   \
					wins_[nw_++] = (a_ + (size_t)(n - k_)) % n;                    \
			} else if ((a_ + n - (from_window)) % n < (size_t)b->span) {                   \
				wins_[nw_++] = (from_window);                                          \
			}                                                                              \
		}                                                                                      \
		for (int i_ = 0; i_ < nw_; i_++) {                                                     \
			size_t s_ = c_ * windows + wins_[i_];                                          \
			if (!done[s_] && (cost) < dist[s_]) {                                          \
				dist[s_] = (cost);                                                     \
				brute_heap_push(&open, (cost), s_);                                    \
			}                                                                              \
		}                                                                                      \
	} while (0)
	int sx = (int)floor(obj->at.x), sy = (int)floor(obj->at.y);
	int start_layer = b->tolerant ? 0 : n;
	if (brute_body(b, sx, sy, start_layer))
		ENTER(((size_t)start_layer * h + sy) * w + sx, none, 0);
	while (open.count > 0) {
		size_t best = brute_heap_pop(&open).id;
		if (done[best])
			continue;
		done[best] = 1;
		size_t cfg = best / windows, window = best % windows;
		int layer = (int)(cfg / ((size_t)w * h)), cell = (int)(cfg % ((size_t)w * h));
		int x = cell % w, y = cell / w, a = brute_angle(b, layer);
		if (brute_goal(b, x, y, layer)) {
			answer = dist[best];
			break;
		}
		static const int dx[4] = {1, 0, -1, 0}, dy[4] = {0, 1, 0, -1};
		for (int m = 0; m < 4; m++) {
			int nx = x + dx[m], ny = y + dy[m];
			if (nx < 0 || ny < 0 || nx >= w || ny >= h)
				continue;
			size_t id = ((size_t)layer * h + ny) * w + nx;
			if (!body[id])
				body[id] = brute_body(b, nx, ny, layer) ? 1 : 2;
			if (body[id] == 1)
				ENTER(id, window, dist[best] + CARRY_UNIT);
		}
		/* turn_ok(k): the step k -> k + 1 here, memoised */
#define TURN_OK(k) (turn[((size_t)(k) * h + y) * w + x] ? turn[((size_t)(k) * h + y) * w + x] == 1 \
		    : (turn[((size_t)(k) * h + y) * w + x] = brute_turn(b, x, y, (k)) ? 1 : 2) == 1)
		int up = (a + 1) % n, down = (a + n - 1) % n;
		if (TURN_OK(a))
			ENTER(((size_t)up * h + y) * w + x, window, dist[best] + brute_turn_cost(b, a));
		if (TURN_OK(down))
			ENTER(((size_t)down * h + y) * w + x, window, dist[best] + brute_turn_cost(b, down));
		if (layer >= n) {
			int q = n / 4;
			bool ccw = true, cw = true;
			int64_t cu = 0, cd = 0;
			for (int i = 0; i < q; i++) {
				ccw = ccw && TURN_OK((a + i) % n);
				cw = cw && TURN_OK((a + n - 1 - i) % n);
				cu += brute_turn_cost(b, (a + i) % n);
				cd += brute_turn_cost(b, (a + n - 1 - i) % n);
			}
			/* Under the restriction a quarter turn (wider than any window
			 * used) may not start in the doorway nor pass through it. */
			for (int i = 1; b->door && i < q && (ccw || cw); i++) {
				ccw = ccw && !brute_meets(b, x, y, (a + i) % n, b->door);
				cw = cw && !brute_meets(b, x, y, (a + n - i) % n, b->door);
			}
			if (ccw && (!b->door || window == none))
				ENTER(((size_t)(n + (layer - n + 1) % 4) * h + y) * w + x, window, dist[best] + cu);
			if (cw && (!b->door || window == none))
				ENTER(((size_t)(n + (layer - n + 3) % 4) * h + y) * w + x, window, dist[best] + cd);
		}
#undef TURN_OK
	}
#undef ENTER
	free(open.e);
	free(dist);
	free(done);
	free(body);
	free(door);
	free(turn);
	return answer;
}

/* ---- worlds ------------------------------------------------------------------------ */

static bool east_of_21(int32_t x, int32_t y) { return (void)y, x >= 21; }

/* A 40 x 30 TABLE cut by a wall at x = 20..21 with a door from y = lo to hi. */
static void load_door(double lo, double hi, const char *object, const char *utak)
{
	char text[1024];
	snprintf(text, sizeof text,
		 "table 40 30\nwall 20 1 21 1 21 %g 20 %g\nwall 20 %g 21 %g 21 29 20 29\nobject held C %s\nutak %s\n", lo,
		 lo, hi, hi, object, utak);
	load(text);
}

TEST_CASE(square_into_the_next_room_every_heading)
{
	static const char *const headings[] = {"north", "east", "south", "west"};
	for (int h = 0; h < 4; h++) {
		char utak[64];
		snprintf(utak, sizeof utak, "9.5 12.5 %s", headings[h]);
		load_door(13, 17, "10 11 13 11 13 14 10 14", utak);
		plan_and_carry(east_of_21, NULL, NULL);
		unload();
	}
}

TEST_CASE(brick_must_turn_to_pass_the_door)
{
	/* A brick 2 x 6 standing north-south, a door 3 high: it passes only lying down. */
	load_door(13, 16, "10 10 12 10 12 16 10 16", "9.5 12.5 north");
	TEST_CHECK(plan_and_carry(east_of_21, NULL, NULL).turned >= 90);
	unload();
}

static bool east_of_17(int32_t x, int32_t y) { return (void)y, x >= 17; }
static bool l_doorway(int32_t x, int32_t y) { return x == 16 && y >= 9 && y < 12; }

/* The L-shape (arms 8 and 5 long, 1 thick) and a door 3 wide in a wall 1 thick,
 * Utak at (x, y). */
static void load_l_door(double x, double y)
{
	char text[512];
	snprintf(text, sizeof text,
		 "table 32 22\nwall 16 1 17 1 17 9 16 9\nwall 16 12 17 12 17 21 16 21\n"
		 "object ell C 5 6 13 6 13 7 6 7 6 11 5 11\nutak %g %g north\n",
		 x, y);
	load(text);
}

TEST_CASE(l_shape_turns_sixty_degrees_in_the_doorway)
{
	/* Choose the grasp (carry_grasp, 12 angles); the brute force agrees that the
	 * carry exists from it, and that it does not if the L, each time it is in the
	 * doorway, stays within 30 degrees; then carry it out in TABLETOP at 12 and at
	 * 72 angles and measure the turning done in the doorway. */
	load_l_door(2.5, 2.5);
	Scene s;
	scene_grids(&s, east_of_17);
	Vec2 at[64];
	int n = grasp_cells(&s, at, 64);
	CarryParams pr = carry_params_default();
	pr.angles = 12;
	CarryPlanner cp;
	carry_init(&cp, &s.grid, &pr);
	CarryGoal goal = {.inside = &s.goal};
	CarryGrasp each[64];
	CarryResult best;
	carry_result_init(&best);
	int chosen = carry_grasp(&cp, &s.obj.shape, at, n, &goal, each, &best);
	TEST_CHECK(chosen >= 0 && best.status == CARRY_FOUND && each[chosen].cost == best.plan.cost);
	for (int i = 0; i < n; i++)
		TEST_CHECK(each[i].status != CARRY_FOUND || each[i].cost >= each[chosen].cost);
	TEST_CHECK(best.narrowest > 3);
	CarryObject obj = {.shape = s.obj.shape, .at = at[chosen]};
	Grid door;
	grid_init(&door, s.grid.w, s.grid.h, GRID_BLOCKED);
	for (int y = 9; y < 12; y++)
		door.cells[y * door.w + 16] = GRID_FREE;
	Brute b = {.grid = &s.grid, .goal = &s.goal};
	TEST_CHECK(brute_cost(&b, &obj, 12) >= 0);
	b.door = &door;
	b.span = 2;
	TEST_CHECK(brute_cost(&b, &obj, 12) < 0);
	grid_free(&door);
	carry_result_free(&best);
	carry_free(&cp);
	scene_free(&s);
	unload();
	/* At 12 angles the brute force has shown the turn in the doorway necessary,
	 * and the simulator measures it; at 72 the finer lattice may enter at 15
	 * degrees and turn less there (carry.h says what the lattice guarantees). */
	for (int angles = 12; angles <= 72; angles += 60) {
		load_l_door(at[chosen].x, at[chosen].y);
		pr.angles = angles;
		Carried done = plan_and_carry(east_of_17, &pr, l_doorway);
		fprintf(stderr, "  %d angles: turned %d degrees, %d in the doorway\n", angles, done.turned, done.in_door);
		TEST_CHECK(done.turned >= 60 && (angles > 12 || done.in_door >= 60));
		unload();
	}
}

/* ---- generated door problems ------------------------------------------------------- */

/* door_shape(kind, x0, yc, out): an object of the kind (0 square, 1 brick, 2 L-shape,
 * 3 triangle) of random size, its west side at x0, about row yc. */
static void door_shape(int kind, double x0, double yc, Polygon *p)
{
	double y0 = yc - 1 - oracle_rand_below(2);
	if (kind == 0) {
		double s = 1 + oracle_rand_below(4);
		*p = (Polygon){4, {{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}}};
	} else if (kind == 1) {
		double a = 1 + oracle_rand_below(2), b = 3 + oracle_rand_below(4);
		if (oracle_rand_below(2)) {
			double t = a;
			a = b;
			b = t;
		}
		*p = (Polygon){4, {{x0, y0}, {x0 + a, y0}, {x0 + a, y0 + b}, {x0, y0 + b}}};
	} else if (kind == 2) {
		double A = 3 + oracle_rand_below(3), B = 3 + oracle_rand_below(3), t = 1 + oracle_rand_below(2);
		*p = (Polygon){6, {{x0, y0}, {x0 + A, y0}, {x0 + A, y0 + t}, {x0 + t, y0 + t}, {x0 + t, y0 + B}, {x0, y0 + B}}};
	} else {
		double a = 2 + oracle_rand_below(7) * 0.5, b = 2 + oracle_rand_below(7) * 0.5;
		*p = (Polygon){3, {{x0, y0}, {x0 + a, y0}, {x0, y0 + b}}};
	}
}

/* door_grid(g, goal, w, h, wall, lo, width): a walled grid cut by the column `wall`
 * with a door of `width` cells from row lo; the goal is everything east of it. */
static void door_grid(Grid *g, Grid *goal, int w, int h, int wall, int lo, int width)
{
	grid_init(g, w, h, GRID_FREE);
	grid_init(goal, w, h, GRID_BLOCKED);
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			bool ring = x == 0 || y == 0 || x == w - 1 || y == h - 1;
			if (ring || (x == wall && (y < lo || y >= lo + width)))
				g->cells[y * w + x] = GRID_BLOCKED;
			if (x > wall)
				goal->cells[y * w + x] = GRID_FREE;
		}
}

TEST_CASE(door_problems_agree_with_brute_force)
{
	/* Found exactly when the brute force finds a path; without the route's
	 * pruning at the same least cost, with it at no less. 8, 12 and 16 angles;
	 * one in five with a tolerant start. */
	oracle_seed = 2026;
	int found = 0, none = 0, by_disc = 0, in_corridor = 0;
	for (int t = 0; t < 80; t++) {
		int w = 17, h = 12, wall = 9, width = 1 + oracle_rand_below(5);
		Grid grid, goal;
		door_grid(&grid, &goal, w, h, wall, 1 + oracle_rand_below(h - 1 - width), width);
		CarryObject obj = {.at = vec2(2.5 + oracle_rand_below(2), 5.5 + oracle_rand_below(2))};
		door_shape(t % 4, floor(obj.at.x) + 1, obj.at.y, &obj.shape);
		int n = t % 3 == 0 ? 8 : t % 3 == 1 ? 12 : 16;
		Brute b = {.grid = &grid, .goal = &goal, .tolerant = t % 5 == 4};
		int64_t want = brute_cost(&b, &obj, n);
		CarryParams pr = carry_params_default();
		pr.angles = n;
		pr.exact_start = !b.tolerant;
		CarryGoal g = {.inside = &goal};
		CarryResult r;
		carry_result_init(&r);
		for (int route = 0; route < 2; route++) {
			pr.use_route = route;
			CarryPlanner cp;
			carry_init(&cp, &grid, &pr);
			CarryStatus st = carry_plan(&cp, &obj, &g, &r);
			carry_free(&cp);
			if ((st == CARRY_FOUND) != (want >= 0) || (st == CARRY_FOUND && !route && r.plan.cost != want))
				fprintf(stderr, "  problem %d route %d: status %d cost %lld, brute force %lld (%s)\n", t,
					route, st, (long long)r.plan.cost, (long long)want, r.why);
			TEST_CHECK((st == CARRY_FOUND) == (want >= 0));
			TEST_CHECK(st != CARRY_FOUND || (route ? r.plan.cost >= want : r.plan.cost == want));
			TEST_CHECK(st == CARRY_FOUND || r.why[0] != '\0');
			by_disc += r.stats.disc_proof;
			in_corridor += r.stats.found_in_corridor;
		}
		found += want >= 0;
		none += want < 0;
		carry_result_free(&r);
		grid_free(&grid);
		grid_free(&goal);
	}
	fprintf(stderr, "  door problems: %d with a path, %d without; %d searches ended in the corridor, %d by the disc\n",
		found, none, in_corridor, by_disc);
	TEST_CHECK(found >= 8 && none >= 8 && by_disc > 0 && in_corridor > 0);
}

/* ---- round a corner, and the impossible ---------------------------------------------- */

static bool north_of_7(int32_t x, int32_t y) { return (void)x, y >= 7; }

/* An L-shaped corridor 4 wide (east along y = 3..7, then north along x = 17..21)
 * and a brick 2 x 5 lying in the first leg, Utak at (x, y). */
static void load_corridor(double x, double y)
{
	char text[512];
	snprintf(text, sizeof text,
		 "table 30 30\nwall 1 1 29 1 29 3 1 3\nwall 1 7 17 7 17 29 1 29\nwall 21 3 29 3 29 29 21 29\n"
		 "object brick C 3 4 8 4 8 6 3 6\nutak %g %g north\n",
		 x, y);
	load(text);
}

TEST_CASE(brick_round_a_corridor_narrower_than_it_is_long)
{
	/* The brick must end wholly in the second leg, past the corner: it must turn
	 * there, and only a few grasps allow it; choose one, carry it out. */
	load_corridor(2.5, 3.5);
	Scene s;
	scene_grids(&s, north_of_7);
	Vec2 at[64];
	int n = grasp_cells(&s, at, 64), served = 0;
	CarryPlanner cp;
	carry_init(&cp, &s.grid, NULL);
	CarryGoal goal = {.inside = &s.goal};
	CarryGrasp each[64];
	int chosen = carry_grasp(&cp, &s.obj.shape, at, n, &goal, each, NULL);
	for (int i = 0; i < n; i++)
		served += each[i].status == CARRY_FOUND;
	fprintf(stderr, "  %d of %d grasps serve\n", served, n);
	TEST_CHECK(chosen >= 0 && served < n);
	carry_free(&cp);
	scene_free(&s);
	unload();
	load_corridor(at[chosen].x, at[chosen].y);
	Carried done = plan_and_carry(north_of_7, NULL, NULL);
	fprintf(stderr, "  turned %d degrees\n", done.turned);
	/* Lying along the first leg it is 5 across the second, which is 4 wide. */
	TEST_CHECK(done.turned >= 45);
	unload();
}

TEST_CASE(impossible_carry_says_why)
{
	/* An L-shaped object 5 wide at its narrowest (a 6 x 4 block with a 4 x 1
	 * step on it) and a door 4 wide: no carry at any angle, and the reason. */
	load_door(13, 17, "10 10 16 10 16 14 14 14 14 15 10 15", "9.5 12.5 north");
	Scene s;
	scene_make(&s, east_of_21);
	s.obj.name = "the L-shaped object";
	CarryPlanner cp;
	carry_init(&cp, &s.grid, NULL);
	CarryResult r;
	carry_result_init(&r);
	CarryGoal goal = {.inside = &s.goal};
	TEST_CHECK(carry_plan(&cp, &s.obj, &goal, &r) == CARRY_NO_PATH);
	fprintf(stderr, "  %s\n", r.why);
	TEST_CHECK(strcmp(r.why, "the L-shaped object is 5.0 wide at its narrowest, the way to the goal region 4.0 "
				 "at its narrowest") == 0);
	TEST_CHECK(r.way == 4);
	/* The disc inside it (more than 4 across) proves it before any search; the
	 * search without that proof, exhaustive, says the same. */
	TEST_CHECK(r.stats.disc_proof && r.stats.expanded == 0);
	CarryPlanner bare;
	CarryParams no_disc = carry_params_default();
	no_disc.use_disc = false;
	carry_init(&bare, &s.grid, &no_disc);
	TEST_CHECK(carry_plan(&bare, &s.obj, &goal, &r) == CARRY_NO_PATH && r.stats.expanded > 0 && !r.stats.disc_proof);
	carry_free(&bare);
	/* The same object and Utak moved to where the wall cuts it: said so at once. */
	CarryObject stuck = s.obj;
	for (int i = 0; i < stuck.shape.count; i++)
		stuck.shape.v[i] = vec2_add(stuck.shape.v[i], vec2(6, -3));
	stuck.at = vec2_add(stuck.at, vec2(6, -3));
	TEST_CHECK(carry_plan(&cp, &stuck, &goal, &r) == CARRY_NO_PATH && strstr(r.why, "does not fit where it stands"));
	/* A goal region with no room for it. */
	Grid tiny;
	grid_init(&tiny, s.grid.w, s.grid.h, GRID_BLOCKED);
	for (int y = 20; y < 23; y++)
		for (int x = 30; x < 33; x++)
			tiny.cells[y * tiny.w + x] = GRID_FREE;
	CarryGoal small = {.inside = &tiny};
	TEST_CHECK(carry_plan(&cp, &s.obj, &small, &r) == CARRY_NO_PATH && strstr(r.why, "has no room for"));
	grid_free(&tiny);
	carry_result_free(&r);
	carry_free(&cp);
	scene_free(&s);
	unload();
}

/* ---- the grasp ----------------------------------------------------------------------- */

TEST_CASE(grasp_choice_agrees_with_brute_force)
{
	/* Every cell beside a brick before a door one square wide: whether the
	 * carry exists from it, and the cheapest, as the brute force says. */
	Grid grid, goal;
	door_grid(&grid, &goal, 16, 11, 8, 4, 1);
	Polygon brick = {4, {{3, 4}, {6, 4}, {6, 5}, {3, 5}}};
	Vec2 at[16];
	int n = 0;
	for (int y = 3; y <= 5; y++)
		for (int x = 2; x <= 6; x++)
			if (!(y == 4 && x >= 3 && x < 6))
				at[n++] = vec2(x + 0.5, y + 0.5);
	CarryParams pr = carry_params_default();
	pr.angles = 8;
	pr.use_route = false;
	CarryPlanner cp;
	carry_init(&cp, &grid, &pr);
	CarryGoal g = {.inside = &goal};
	CarryGrasp each[16];
	CarryResult best;
	carry_result_init(&best);
	int chosen = carry_grasp(&cp, &brick, at, n, &g, each, &best);
	int64_t least = -1;
	int want = -1, found = 0;
	for (int i = 0; i < n; i++) {
		Brute b = {.grid = &grid, .goal = &goal};
		CarryObject obj = {.shape = brick, .at = at[i]};
		int64_t c = brute_cost(&b, &obj, 8);
		TEST_CHECK((each[i].status == CARRY_FOUND) == (c >= 0));
		TEST_CHECK(c < 0 || each[i].cost == c);
		if (c >= 0 && (least < 0 || c < least)) {
			least = c;
			want = i;
		}
		found += c >= 0;
	}
	fprintf(stderr, "  %d of %d grasps serve\n", found, n);
	TEST_CHECK(found > 0 && found < n);
	TEST_CHECK(chosen == want && best.status == CARRY_FOUND && best.plan.cost == least);
	carry_result_free(&best);
	carry_free(&cp);
	grid_free(&grid);
	grid_free(&goal);
}

/* ---- random worlds in TABLETOP --------------------------------------------------------- */

TEST_CASE(random_door_worlds_carried_out_in_tabletop)
{
	/* Random door widths, shapes (squares, bricks, L-shapes and triangles with
	 * half-square corners) and headings, at the default 72 angles: whatever is
	 * planned must be carried out without a halt. */
	static const char *const headings[] = {"north", "east", "south", "west"};
	oracle_seed = 77;
	int planned = 0;
	for (int t = 0; t < 64; t++) {
		/* The second half gives the legs in parts, as the action cycle does. */
		execute_most = t < 32 ? 0 : 4;
		Polygon p;
		double ux = 5.5 + oracle_rand_below(8), uy = 8.5 + oracle_rand_below(12);
		door_shape(t % 4, ux + 0.5, uy, &p);
		int width = 2 + oracle_rand_below(5), lo = 6 + oracle_rand_below(12);
		char object[512] = "", text[1024];
		for (int i = 0; i < p.count; i++)
			snprintf(object + strlen(object), sizeof object - strlen(object), "%g %g ", p.v[i].x, p.v[i].y);
		snprintf(text, sizeof text, "%g %g %s", ux, uy, headings[oracle_rand_below(4)]);
		load_door(lo, lo + width, object, text);
		Scene s;
		scene_make(&s, east_of_21);
		CarryPlanner cp;
		carry_init(&cp, &s.grid, NULL);
		CarryResult r;
		carry_result_init(&r);
		CarryGoal goal = {.inside = &s.goal};
		if (carry_plan(&cp, &s.obj, &goal, &r) == CARRY_FOUND) {
			execute(&s, &r.plan, east_of_21, NULL);
			planned++;
		} else {
			TEST_CHECK(r.status == CARRY_NO_PATH && r.why[0] != '\0');
		}
		carry_result_free(&r);
		carry_free(&cp);
		scene_free(&s);
		unload();
	}
	execute_most = 0;
	fprintf(stderr, "  %d of 64 carried out\n", planned);
	TEST_CHECK(planned >= 32);
}

TEST_CASE(square_through_a_door_just_as_wide_in_parts)
{
	/* A square exactly as wide as the door, far from it and off its line, so that
	 * the carry has a long slanting leg, given in parts of at most 4 squares as the
	 * action cycle gives them: the parts must add up to the leg exactly, or the
	 * square ends a rounding error past a grid line, meets a row of squares more
	 * and halts in the door (tworooms.w, before carry_command_part). */
	static const char *const headings[] = {"north", "east", "south", "west"};
	oracle_seed = 12;
	int planned = 0, slanting = 0;
	for (int t = 0; t < 48; t++) {
		int size = 2 + oracle_rand_below(4), lo = 4 + oracle_rand_below(20 - size);
		double x0 = 3 + oracle_rand_below(6), y0 = 2 + oracle_rand_below(24 - size);
		char object[256], utak[64];
		snprintf(object, sizeof object, "%g %g %g %g %g %g %g %g", x0, y0, x0 + size, y0, x0 + size, y0 + size, x0,
			 y0 + size);
		snprintf(utak, sizeof utak, "%g %g %s", x0 - 0.5, y0 + 0.5, headings[t % 4]);
		load_door(lo, lo + size, object, utak);
		Scene sc;
		scene_make(&sc, east_of_21);
		CarryPlanner cp;
		carry_init(&cp, &sc.grid, NULL);
		CarryResult r;
		carry_result_init(&r);
		CarryGoal goal = {.inside = &sc.goal};
		if (carry_plan(&cp, &sc.obj, &goal, &r) == CARRY_FOUND) {
			for (int i = 0; i + 1 < r.plan.count; i++) {
				const MotorCommand *c = &r.plan.cmd[i];
				slanting += c->kind == MOTOR_PUSH && c->dx != 0 && c->dy != 0 && hypot(c->dx, c->dy) > 4;
			}
			execute_most = 4;
			execute(&sc, &r.plan, east_of_21, NULL);
			execute_most = 0;
			planned++;
		}
		carry_result_free(&r);
		carry_free(&cp);
		scene_free(&sc);
		unload();
	}
	fprintf(stderr, "  %d of 48 carried out, %d slanting legs cut in parts\n", planned, slanting);
	TEST_CHECK(planned >= 40 && slanting >= 20);
}

/* ---- poses off the lattice ----------------------------------------------------------- */

TEST_CASE(poses_off_the_lattice_against_the_projection_oracle)
{
	/* carry_pose_free and carry_pose_inside at random poses (any point, any
	 * angle), square by square against projection_oracle.h. */
	oracle_seed = 99;
	Grid grid, goal;
	door_grid(&grid, &goal, 30, 20, 15, 8, 4);
	CarryPlanner cp;
	carry_init(&cp, &grid, NULL);
	int free_count = 0, inside_count = 0;
	for (int t = 0; t < 400; t++) {
		CarryObject obj = {.at = vec2(4.5, 9.5)};
		door_shape(t % 4, 5, 9.5, &obj.shape);
		Vec2 at = vec2(1 + oracle_rand_below(2800) / 100.0, 1 + oracle_rand_below(1800) / 100.0);
		double deg = t % 3 == 0 ? 90 * oracle_rand_below(4) : oracle_rand_below(36000) / 100.0;
		Polygon rel = obj.shape;
		for (int i = 0; i < rel.count; i++)
			rel.v[i] = vec2_sub(obj.shape.v[i], obj.at);
		Polygon p = sweep_turned(&rel, at, deg);
		bool want_free = grid_free_at(&grid, (int)floor(at.x), (int)floor(at.y)), want_inside = true;
		for (int y = -2; y < grid.h + 2; y++)
			for (int x = -2; x < grid.w + 2; x++)
				if (oracle(&p, x, y)) {
					want_free &= grid_free_at(&grid, x, y);
					want_inside &= grid_free_at(&goal, x, y);
				}
		TEST_CHECK(carry_pose_free(&cp, &obj, at, deg) == want_free);
		TEST_CHECK(carry_pose_inside(&obj, &goal, at, deg) == want_inside);
		free_count += want_free;
		inside_count += want_inside;
	}
	TEST_CHECK(free_count > 50 && inside_count > 50);
	carry_free(&cp);
	grid_free(&grid);
	grid_free(&goal);
}

TEST_CASE(same_problem_same_plan)
{
	/* A planner reused after other problems gives the plan a fresh one gives,
	 * command for command: nothing of one plan leaks into the next, and ties
	 * are broken the same way every time. */
	Grid grid, goal;
	door_grid(&grid, &goal, 30, 20, 15, 8, 3);
	CarryObject a = {.shape = {4, {{5, 7}, {6, 7}, {6, 12}, {5, 12}}}, .at = vec2(4.5, 9.5)};
	CarryObject b = {.shape = {3, {{5, 3}, {9, 3}, {5, 6}}}, .at = vec2(4.5, 3.5)};
	CarryGoal g = {.inside = &goal};
	CarryPlanner fresh, reused;
	carry_init(&fresh, &grid, NULL);
	carry_init(&reused, &grid, NULL);
	CarryResult r1, r2, other;
	carry_result_init(&r1);
	carry_result_init(&r2);
	carry_result_init(&other);
	TEST_CHECK(carry_plan(&fresh, &a, &g, &r1) == CARRY_FOUND);
	carry_plan(&reused, &b, &g, &other);
	carry_plan(&reused, &a, &g, &other);
	carry_plan(&reused, &b, &g, &other);
	TEST_CHECK(carry_plan(&reused, &a, &g, &r2) == CARRY_FOUND);
	TEST_CHECK(r1.plan.count == r2.plan.count && r1.plan.cost == r2.plan.cost);
	for (int i = 0; i + 1 < r1.plan.count; i++)
		TEST_CHECK(r1.plan.cmd[i].kind == r2.plan.cmd[i].kind && r1.plan.cmd[i].dx == r2.plan.cmd[i].dx &&
			   r1.plan.cmd[i].dy == r2.plan.cmd[i].dy && r1.plan.cmd[i].deg == r2.plan.cmd[i].deg);
	TEST_CHECK(r1.stats.expanded == r2.stats.expanded && r1.stats.checked == r2.stats.checked);
	carry_result_free(&r1);
	carry_result_free(&r2);
	carry_result_free(&other);
	carry_free(&fresh);
	carry_free(&reused);
	grid_free(&grid);
	grid_free(&goal);
}

int main(void)
{
	TEST_RUN(square_into_the_next_room_every_heading);
	TEST_RUN(brick_must_turn_to_pass_the_door);
	TEST_RUN(door_problems_agree_with_brute_force);
	TEST_RUN(l_shape_turns_sixty_degrees_in_the_doorway);
	TEST_RUN(brick_round_a_corridor_narrower_than_it_is_long);
	TEST_RUN(impossible_carry_says_why);
	TEST_RUN(grasp_choice_agrees_with_brute_force);
	TEST_RUN(random_door_worlds_carried_out_in_tabletop);
	TEST_RUN(square_through_a_door_just_as_wide_in_parts);
	TEST_RUN(poses_off_the_lattice_against_the_projection_oracle);
	TEST_RUN(same_problem_same_plan);
	return TEST_EXIT();
}
