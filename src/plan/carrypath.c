/* carrypath.c - a carry's plan: from the lattice path to motor commands (paper 2.2:
 * push and turn; 5: rope-tightening; see carry.h, THE PLAN).
 *
 * ALGORITHM. The lattice path arrives as items (one-square pushes and turns where
 * Utak stands). (1) Fewest turns: repeatedly, a turn, a run of pushes and a turn
 * become one turn before the run or after it, when the whole plan replayed with the
 * search's own checks (carry.c) is still free and still ends in the goal; greedy,
 * so not always the least number. (2) Each run of pushes is string-pulled: from
 * each waypoint, the farthest cell of the run, before the first that fails, that
 * one straight push reaches with its whole swept area free (sweep_cover_push; the
 * TABLE's rule where the object is exact and the push is along an axis, within
 * SWEEP_EPS otherwise, since the simulator rounds the poses of a slanting push) and
 * Utak's point on free squares. The waypoints are lattice points, so every push is
 * a whole number of squares in each axis, as the controller's moves are.
 *
 * INVARIANT: the items always replay free and into the goal; the commands take each
 * checked pose to the next. COMPLEXITY: merging O(T^2 L R) for T turns and L items;
 * string pulling one sweep check per cell of a run, plus one per waypoint. */
#include <assert.h>
#include <math.h>
#include <stdlib.h>

#include "carry_work.h"
#include "utak/base/util.h"
#include "utak/plan/sweep.h"

static int32_t angle_mod(const CarryWork *k, int32_t a) { return ((a % k->angles) + k->angles) % k->angles; }

/* unwrapped_deg(k, a): degrees of angle index a, for any whole a (a full turn adds 360). */
static int32_t unwrapped_deg(const CarryWork *k, int32_t a)
{
	int32_t turns = a >= 0 ? a / k->angles : -((-a + k->angles - 1) / k->angles);
	return turns * 360 + k->deg[a - turns * k->angles];
}

/* replay(k, items, x0, y0): the lattice plan from (x0, y0) at angle 0 is still free
 * and ends in the goal, by the checks of the search, with the simulator's notion
 * of exactness: a turn keeps an exact pose exact only when it is whole quarters. */
static bool replay(CarryWork *k, const CarryItems *l, int32_t x0, int32_t y0)
{
	int32_t x = x0, y = y0, angle = 0, quarter = k->angles / CARRY_QUARTERS;
	bool exact = k->exact_start;
	for (int i = 0; i < l->count; i++) {
		const CarryItem *it = &l->item[i];
		if (it->turn != 0) {
			if (!carry_turn_run_free(k, angle, it->turn, x, y))
				return false;
			angle = angle_mod(k, angle + it->turn);
			exact = exact && it->turn % quarter == 0;
			continue;
		}
		if (!carry_body_free(k, exact ? carry_exact_layer(k, angle) : angle, it->x, it->y))
			return false;
		x = it->x;
		y = it->y;
	}
	return carry_goal_holds(k, exact ? carry_exact_layer(k, angle) : angle, x, y);
}

/* merge_turns(k, l, x0, y0): fewer turns (carry.h, THE PLAN): a turn, pushes and a
 * turn become one turn before the pushes or after them, where the plan stays free;
 * repeated until no pair merges. */
static void merge_turns(CarryWork *k, CarryItems *l, int32_t x0, int32_t y0)
{
	CarryItems trial = {0};
	bool changed = true;
	while (changed) {
		changed = false;
		for (int i = 0; i < l->count && !changed; i++) {
			if (l->item[i].turn == 0)
				continue;
			int j = i + 1;
			while (j < l->count && l->item[j].turn == 0)
				j++;
			if (j == l->count)
				break;
			for (int where = 0; where < 2 && !changed; where++) {
				/* where 0: the sum at i; 1: the sum at j. */
				trial.count = 0;
				int32_t sum = l->item[i].turn + l->item[j].turn;
				for (int m = 0; m < l->count; m++) {
					if ((m == i && where == 0) || (m == j && where == 1)) {
						if (sum != 0)
							carry_items_push(&trial, (CarryItem){.turn = sum});
					} else if (m != i && m != j) {
						carry_items_push(&trial, l->item[m]);
					}
				}
				if (replay(k, &trial, x0, y0)) {
					CarryItems t = *l;
					*l = trial;
					trial = t;
					changed = true;
				}
			}
		}
	}
	free(trial.item);
}

/* A sink for sweep covers that checks each span against the grid. */
typedef struct CarrySink {
	const CarryWork *k;
	bool free;
} CarrySink;

static void carry_sink_span(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	CarrySink *s = ctx;
	const CarryWork *k = s->k;
	if (!s->free)
		return;
	if (y < 0 || y >= k->h || x0 < 0 || x1 >= k->w) {
		s->free = false;
		return;
	}
	const int32_t *row = k->blocked + (size_t)y * (size_t)(k->w + 1);
	if (row[x1 + 1] != row[x0])
		s->free = false;
}

/* leg_free(k, angle, exact, x0, y0, x1, y1): one straight push from lattice cell
 * (x0, y0) to (x1, y1) at angle sweeps only free cells (carry.h, THE PLAN). */
static bool leg_free(CarryWork *k, int32_t angle, bool exact, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
	Vec2 a = vec2(x0 + k->frac.x, y0 + k->frac.y), d = vec2(x1 - x0, y1 - y0);
	Polygon p = sweep_turned(&k->rel, a, k->deg[angle]);
	bool axis = x0 == x1 || y0 == y1;
	CarrySink sink = {k, true};
	k->stats->checked++;
	sweep_cover_push(&p, d, exact && axis ? 0 : SWEEP_EPS, carry_sink_span, &sink);
	if (y0 == y1) /* his point stays in one row or column of squares */
		carry_sink_span(&sink, y0, x0 < x1 ? x0 : x1, x0 < x1 ? x1 : x0);
	else if (x0 == x1)
		for (int32_t y = y0 < y1 ? y0 : y1; y <= (y0 < y1 ? y1 : y0); y++)
			carry_sink_span(&sink, y, x0, x0);
	else
		sweep_cover_segment(a, vec2_add(a, d), SWEEP_EPS, carry_sink_span, &sink);
	return sink.free;
}

static void plan_push(CarryPlan *plan, CarryPose pose, MotorCommand cmd)
{
	int cap = plan->cap;
	plan->pose = util_grow(plan->pose, &cap, plan->count + 1, sizeof *plan->pose);
	plan->cmd = util_grow(plan->cmd, &plan->cap, plan->count + 1, sizeof *plan->cmd);
	if (plan->count > 0)
		plan->cmd[plan->count - 1] = cmd;
	plan->pose[plan->count++] = pose;
}

/* emit(k, l, x0, y0, plan): the commands and poses of the lattice plan, pushes
 * string-pulled. */
static void emit(CarryWork *k, const CarryItems *l, int32_t x0, int32_t y0, CarryPlan *plan)
{
	int32_t x = x0, y = y0, angle = 0, quarter = k->angles / CARRY_QUARTERS;
	bool exact = k->exact_start;
	plan->count = 0;
	plan_push(plan, (CarryPose){vec2(x + k->frac.x, y + k->frac.y), x, y, 0, exact}, (MotorCommand){0});
	for (int i = 0; i < l->count;) {
		const CarryItem *it = &l->item[i];
		if (it->turn != 0) {
			int32_t deg = unwrapped_deg(k, angle + it->turn) - unwrapped_deg(k, angle);
			angle = angle_mod(k, angle + it->turn);
			exact = exact && it->turn % quarter == 0;
			plan_push(plan, (CarryPose){vec2(x + k->frac.x, y + k->frac.y), x, y, k->deg[angle], exact},
				  (MotorCommand){.kind = MOTOR_TURN, .deg = deg});
			plan->turns++;
			plan->turned += abs(deg);
			i++;
			continue;
		}
		int j = i;
		while (j < l->count && l->item[j].turn == 0)
			j++;
		/* Cells i .. j - 1 of the run, after (x, y): from each waypoint the farthest
		 * cell before the first that one leg cannot reach, then on from there. */
		int at = i - 1; /* i - 1 stands for (x, y) */
		while (at < j - 1) {
			int32_t ax = at < i ? x : l->item[at].x, ay = at < i ? y : l->item[at].y;
			int best = at + 1;
			for (int m = at + 2; m < j; m++) {
				if (!leg_free(k, angle, exact, ax, ay, l->item[m].x, l->item[m].y))
					break;
				best = m;
			}
			int32_t bx = l->item[best].x, by = l->item[best].y;
			plan_push(plan, (CarryPose){vec2(bx + k->frac.x, by + k->frac.y), bx, by, k->deg[angle], exact},
				  (MotorCommand){.kind = MOTOR_PUSH, .dx = bx - ax, .dy = by - ay});
			plan->pushes++;
			plan->pushed += hypot(bx - ax, by - ay);
			at = best;
		}
		x = l->item[j - 1].x;
		y = l->item[j - 1].y;
		i = j;
	}
}

/* ---- poses off the lattice ------------------------------------------------------- */

bool carry_pose_free(const CarryPlanner *cp, const CarryObject *obj, Vec2 at, double deg)
{
	const CarryWork *k = cp->work;
	Polygon rel = obj->shape;
	for (int32_t i = 0; i < rel.count; i++)
		rel.v[i] = vec2_sub(obj->shape.v[i], obj->at);
	Polygon p = sweep_turned(&rel, at, deg);
	CarrySink sink = {k, true};
	sweep_cover_polygon(&p, 0, carry_sink_span, &sink);
	return sink.free && grid_free_at(cp->grid, (int32_t)floor(at.x), (int32_t)floor(at.y));
}

/* A sink that checks each span lies in a region. */
typedef struct CarryRegionSink {
	const Grid *region;
	bool inside;
} CarryRegionSink;

static void carry_region_span(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	CarryRegionSink *s = ctx;
	for (int32_t x = x0; x <= x1 && s->inside; x++)
		s->inside = grid_free_at(s->region, x, y);
}

bool carry_pose_inside(const CarryObject *obj, const Grid *region, Vec2 at, double deg)
{
	Polygon rel = obj->shape;
	for (int32_t i = 0; i < rel.count; i++)
		rel.v[i] = vec2_sub(obj->shape.v[i], obj->at);
	Polygon p = sweep_turned(&rel, at, deg);
	CarryRegionSink sink = {region, true};
	sweep_cover_polygon(&p, 0, carry_region_span, &sink);
	return sink.inside;
}

bool carry_command_part(MotorCommand *leg, double most, MotorCommand *part)
{
	*part = *leg;
	double len = hypot(leg->dx, leg->dy);
	if (leg->kind != MOTOR_PUSH || len <= most)
		return true;
	double f = most / len;
	part->dx = round(leg->dx * f * CARRY_PART_GRAIN) / CARRY_PART_GRAIN;
	part->dy = round(leg->dy * f * CARRY_PART_GRAIN) / CARRY_PART_GRAIN;
	leg->dx -= part->dx;
	leg->dy -= part->dy;
	return false;
}

void carry_plan_print(const CarryPlan *plan, FILE *f)
{
	for (int i = 0; i + 1 < plan->count; i++) {
		const MotorCommand *c = &plan->cmd[i];
		if (c->kind == MOTOR_TURN)
			fprintf(f, "turn %d\n", (int)c->deg);
		else
			fprintf(f, "push %d %d\n", (int)c->dx, (int)c->dy);
	}
	fprintf(f, "carry: %d pushes (%.2f squares), %d turns (%d degrees)\n", plan->pushes, plan->pushed,
		plan->turns, plan->turned);
}

void carry_path_commands(CarryWork *k, CarryItems *items, int32_t x0, int32_t y0, CarryPlan *plan)
{
	bool still = replay(k, items, x0, y0);
	assert(still);
	(void)still;
	merge_turns(k, items, x0, y0);
	emit(k, items, x0, y0, plan);
}
