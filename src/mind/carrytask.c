/* carrytask.c - the carrying tasks (vi)-(ix): look, survey, choose the grasp, carry
 * in (x, y, theta), release (paper 2.3, 3.6, 5). CONTROLLER SIDE: it knows the world
 * through the world model and the screen only (carrytask.h says what the steps
 * and the goal region are).
 *
 * ALGORITHM. The object's outline is traced from its squares on the screen
 * (carryoutline.h: the outer boundary of their 4-connected set, a rectilinear simple
 * polygon that contains the object). The grasp is chosen by
 * carry_grasp over the free squares beside the object, nearest Utak first; the
 * carry by carry_plan (carry.h: A* over (x, y, theta) on the screen, resolution
 * complete, the reason in words when no carry exists). While he holds it, the
 * outline moves with every command as the model believes Utak moved (a push) or
 * turns about his believed point (a turn), and each command's believed end is
 * compared with the plan's (steps 12-13).
 * MEMORY: a CarryTask of about 6 KB and its goal region (one byte a screen cell);
 * each plan's working space is carry.h's, freed when the plan is made.
 * COMPLEXITY: a plan costs carry.h's search; choosing the grasp up to
 * CARRYTASK_MAX_GRASPS of them; the goal region O(w h) plus carryroom.h's rooms and
 * bend. */
#include "utak/mind/carrytask.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "carryoutline.h"
#include "utak/base/util.h"
#include "utak/mind/carryframe.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/nextroom.h"
#include "utak/mind/objects.h"
#include "utak/mind/push.h"
#include "utak/mind/rooms.h"
#include "utak/mind/shape.h"
#include "utak/mind/wallbump.h"
#include "utak/plan/carry.h"
#include "utak/plan/pathgraph.h"
#include "utak/plan/skeleton.h"

/* Open floor for a re-grasp: every square within the object's reach plus this many
 * is free, so that Utak can walk round it to any side. */
#define CT_OPEN_MARGIN 2

bool carrytask_applies(const Task *t)
{
	return t->kind == TASK_PUSH_NEXT_ROOM || t->kind == TASK_PUSH_THROUGH_DOOR ||
	       t->kind == TASK_PUSH_AROUND_CORNER;
}

CarryTask *carrytask_new(void)
{
	CarryTask *ct = util_alloc(1, sizeof *ct);
	memset(ct, 0, sizeof *ct);
	return ct;
}

void carrytask_delete(CarryTask *ct)
{
	if (!ct)
		return;
	grid_free(&ct->region);
	free(ct);
}

/* ---- the grids ------------------------------------------------------------------ */

static void ct_free_span(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	Grid *g = ctx;
	for (int32_t x = x0; x <= x1; x++)
		g->cells[y * g->w + x] = GRID_FREE;
}

/* ct_carry_grid(c, k, held, out): the screen's space to carry on: the squares
 * bumped into blocked, the object's own squares (node k's, the held set's, and the
 * outline's, screen units) and Utak's free: they move with him. */
static void ct_carry_grid(const Controller *c, int32_t k, const Polygon *held, Grid *out)
{
	const Screen *s = &c->screen;
	grid_init(out, s->w, s->h, GRID_BLOCKED);
	memcpy(out->cells, s->free.cells, (size_t)s->w * (size_t)s->h);
	push_mark_bumped(c, out);
	for (int32_t at = 0; at < s->w * s->h; at++)
		if (s->label[at] >= 0 && (s->label[at] == k || c->model.node[s->label[at]].held))
			out->cells[at] = GRID_FREE;
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	if (c->model.holding)
		for (int32_t j = 0; j < c->model.held_count; j++) {
			int32_t i2 = ux + c->model.held_dx[j] - s->x0, j2 = uy + c->model.held_dy[j] - s->y0;
			if (i2 >= 0 && j2 >= 0 && i2 < s->w && j2 < s->h)
				out->cells[j2 * s->w + i2] = GRID_FREE;
		}
	if (held)
		geom_project(held, s->w, s->h, ct_free_span, out);
	int32_t i, j;
	if (goals_cell_of(s, c->model.utak, &i, &j))
		out->cells[j * s->w + i] = GRID_FREE;
}

/* ct_goal_grid(c, open, reach, out): the goal region on this screen: the fixed
 * region's squares the screen shows as floor (or as the object: it may already lie
 * there); with open, open floor of the object's present room instead (a re-grasp). */
static void ct_goal_grid(const Controller *c, const Grid *space, bool open, double reach, Grid *out)
{
	const CarryTask *ct = c->carry;
	const Screen *s = &c->screen;
	grid_init(out, s->w, s->h, GRID_BLOCKED);
	int32_t r = (int32_t)ceil(reach) + CT_OPEN_MARGIN;
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			int32_t at = j * s->w + i, l = s->label[at];
			if (space->cells[at] != GRID_FREE || l == SCREEN_UNKNOWN)
				continue;
			if (open) {
				bool clear = true;
				for (int32_t dy = -r; dy <= r && clear; dy++)
					for (int32_t dx = -r; dx <= r && clear; dx++)
						clear = grid_free_at(space, i + dx, j + dy) &&
							screen_label(s, i + dx, j + dy) != SCREEN_UNKNOWN;
				if (clear)
					out->cells[at] = GRID_FREE;
				continue;
			}
			int32_t x = s->x0 + i - ct->rx0, y = s->y0 + j - ct->ry0;
			if (grid_free_at(&ct->region, x, y))
				out->cells[at] = GRID_FREE;
		}
}

/* ct_mark_doorway(rm, d, region): the squares of door d's passage blocked in region:
 * from the run across it, along the way through, while both ends of the run meet
 * the wall's faces; and one square more each way. A slanted door: the squares
 * within its width of its cell. */
static void ct_mark_doorway(const RoomMap *rm, const RoomsDoor *d, Grid *region)
{
	const Grid *g = &rm->known;
	if (d->ay == d->by || d->ax == d->bx) {
		bool across_x = d->ay == d->by; /* the run lies along x: the way through is y */
		int32_t lo = across_x ? d->ax : d->ay, hi = across_x ? d->bx : d->by, at = across_x ? d->ay : d->ax;
		if (lo > hi) {
			int32_t t = lo;
			lo = hi;
			hi = t;
		}
		for (int way = -1; way <= 1; way += 2) {
			int32_t t = 0;
			for (;; t++) {
				int32_t row = at + way * t;
				bool wall_lo = across_x ? !grid_free_at(g, lo - 1, row) : !grid_free_at(g, row, lo - 1);
				bool wall_hi = across_x ? !grid_free_at(g, hi + 1, row) : !grid_free_at(g, row, hi + 1);
				if (t > 0 && !(wall_lo && wall_hi))
					break;
				if (t > region->w + region->h)
					break;
			}
			for (int32_t u = 0; u <= t; u++) /* the passage, and one square past it */
				for (int32_t v = lo - 1; v <= hi + 1; v++) {
					int32_t row = at + way * u, x = across_x ? v : row, y = across_x ? row : v;
					if (x >= 0 && y >= 0 && x < region->w && y < region->h)
						region->cells[y * region->w + x] = GRID_BLOCKED;
				}
		}
		return;
	}
	int32_t r = d->width + 1;
	for (int32_t y = d->y - r; y <= d->y + r; y++)
		for (int32_t x = d->x - r; x <= d->x + r; x++)
			if (x >= 0 && y >= 0 && x < region->w && y < region->h)
				region->cells[y * region->w + x] = GRID_BLOCKED;
}

/* ct_roommap_build(c, k, out): the rooms as goals_roommap_build finds them, except
 * that every object but node k (the one to carry) stands as fixed: the eye cannot
 * tell a wall from an object by its colour, and a wall whose joint with the verge
 * was seen only coarsely is modelled as an isolated object; a door between two such
 * walls must still be a door. The object carried is space, as are the squares
 * never seen (not fixed: they are blocked in the known grid, as in goals.c). */
static void ct_roommap_build(const Controller *c, int32_t k, bool objects_fixed, RoomMap *r)
{
	const Screen *s = &c->screen;
	grid_init(&r->known, s->w, s->h, GRID_BLOCKED);
	for (int32_t at = 0; at < s->w * s->h; at++) {
		int32_t l = s->label[at];
		bool wall_like = objects_fixed && l >= 0 && l != k && !c->model.node[l].held;
		if (l != SCREEN_UNKNOWN && s->fixed.cells[at] == GRID_FREE && !wall_like)
			r->known.cells[at] = GRID_FREE;
	}
	goals_roommap_find(r);
}

/* ct_box_has(b, x, y, grow): cell (x, y) lies in box b (x0, y0, x1, y1, inclusive)
 * grown by grow cells on every side. */
static bool ct_box_has(const int32_t b[4], int32_t x, int32_t y, int32_t grow)
{
	return x >= b[0] - grow && x <= b[2] + grow && y >= b[1] - grow && y <= b[3] + grow;
}

/* carrytask_door_sure: carrytask.h. */
bool carrytask_door_sure(const CarryRooms *cr, const RoomMap *rm, const RoomsDoor *d)
{
	double c = sqrt((double)rm->skeleton.dist2[d->y * rm->known.w + d->x]) + CARRYTASK_DOOR_SLACK;
	for (int side = 0; side < 2; side++) {
		double p = cr->peak[cr->merged[side ? d->room_b : d->room_a]];
		if (p < CARRYROOM_RATIO * c || p < c + CARRYROOM_MARGIN)
			return false;
	}
	return true;
}

/* ct_region_fix(c, rm): the goal region from this screen, fixed in the model's frame
 * (carrytask.h). Returns its squares. */
static int32_t ct_region_fix(Controller *c, const RoomMap *rm)
{
	CarryTask *ct = c->carry;
	const Screen *s = &c->screen;
	grid_free(&ct->region);
	grid_init(&ct->region, s->w, s->h, GRID_BLOCKED);
	ct->rx0 = s->x0;
	ct->ry0 = s->y0;
	int32_t oi, oj, count = 0;
	if (!goals_cell_of(s, ct->object_start, &oi, &oj))
		return 0;
	CarryRooms cr;
	carryroom_merge(rm, &cr);
	int32_t room = carryroom_at(&cr, rm, oi, oj);
	if (room < 0) {
		carryroom_free(&cr);
		return 0;
	}
	if (c->task.kind == TASK_PUSH_AROUND_CORNER) {
		/* The other leg of the L-shaped corridor the object started in, past
		 * the bend and a square more (what the eye misplaces); from the bend,
		 * either leg past it. */
		/* Only a room seen whole is judged: a corridor seen in part (its far
		 * leg hidden, a wall not yet seen) may look like any shape. */
		bool whole = true;
		for (int32_t at = 0; at < s->w * s->h && whole; at++)
			if (carryroom_at(&cr, rm, at % s->w, at / s->w) == room)
				for (int q = 0; q < 4 && whole; q++)
					whole = screen_label(s, at % s->w + (q == 0) - (q == 1), at / s->w + (q == 2) - (q == 3)) !=
						SCREEN_UNKNOWN;
		CarryBend b;
		if (!whole || !carryroom_bend(&cr, rm, room, &b)) {
			carryroom_free(&cr);
			return 0;
		}
		int from = ct_box_has(b.bend, oi, oj, 0) ? -1 : ct_box_has(b.leg[0], oi, oj, 0) ? 0
								: ct_box_has(b.leg[1], oi, oj, 0) ? 1 : -1;
		for (int32_t j = 0; j < s->h; j++)
			for (int32_t i = 0; i < s->w; i++) {
				bool leg = from < 0 ? ct_box_has(b.leg[0], i, j, 0) || ct_box_has(b.leg[1], i, j, 0)
						    : ct_box_has(b.leg[1 - from], i, j, 0);
				if (s->label[j * s->w + i] == SCREEN_SPACE && carryroom_at(&cr, rm, i, j) == room && leg &&
				    !ct_box_has(b.bend, i, j, 1))
					ct->region.cells[j * s->w + i] = GRID_FREE;
			}
		snprintf(ct->corridor, sizeof ct->corridor,
			 "an L-shaped corridor, legs %d and %d wide, its bend (%d, %d) to (%d, %d)",
			 (int)(b.leg[0][2] - b.leg[0][0] + 1), (int)(b.leg[1][3] - b.leg[1][1] + 1),
			 (int)(s->x0 + b.bend[0]), (int)(s->y0 + b.bend[1]), (int)(s->x0 + b.bend[2]),
			 (int)(s->y0 + b.bend[3]));
	} else {
		/* The rooms that share a door with the object's, by the verdict's
		 * rule (carryroom.h) with the eye's slack (carrytask_door_sure), less every
		 * door's doorway. */
		bool *sure = util_alloc((size_t)(rm->rooms.door_count > 0 ? rm->rooms.door_count : 1), sizeof *sure);
		for (int32_t q = 0; q < rm->rooms.door_count; q++)
			sure[q] = cr.door[q] && carrytask_door_sure(&cr, rm, &rm->rooms.doors[q]);
		for (int32_t at = 0; at < s->w * s->h; at++) {
			if (s->label[at] != SCREEN_SPACE)
				continue;
			int32_t here = carryroom_at(&cr, rm, at % s->w, at / s->w);
			bool next = false;
			for (int32_t q = 0; q < rm->rooms.door_count && !next && here != room; q++) {
				const RoomsDoor *d = &rm->rooms.doors[q];
				int32_t a = cr.merged[d->room_a], bb = cr.merged[d->room_b];
				next = sure[q] && ((a == room && bb == here) || (bb == room && a == here));
			}
			if (next)
				ct->region.cells[at] = GRID_FREE;
		}
		free(sure);
		for (int32_t q = 0; q < rm->rooms.door_count; q++)
			if (cr.door[q])
				ct_mark_doorway(rm, &rm->rooms.doors[q], &ct->region);
		/* And only squares past a door line by the verdict's own watershed
		 * restated on both readings of the model (nextroom_beyond, as task
		 * (ii) claims): rooms.h's doors merged by the door rule may keep a
		 * narrowing the judge's watershed does not (three rooms in a row, each
		 * door 9 wide and the rooms 18 and 19: the judge sees one room, and
		 * the square pushed through "the door" was a false success). */
		bool *past = util_alloc((size_t)s->w * (size_t)s->h, sizeof *past);
		nextroom_beyond(c, &rm->known, rm, oi, oj, past);
		/* And in every frame the TABLE may have, and past every cell along a
		 * face a door square may move to (carryframe.h): the judge breaks ties
		 * of clearance by the TABLE's order of squares, not Utak's, and a door
		 * at a wall's end puts its doorway along the face into the far room. */
		bool *every = util_alloc((size_t)s->w * (size_t)s->h, sizeof *every);
		bool sized = rm->known.w == s->w && rm->known.h == s->h && s->fixed.w == s->w && s->fixed.h == s->h;
		if (!sized || carryframe_beyond(&rm->known, oi, oj, every) == 0)
			memset(past, 0, (size_t)s->w * (size_t)s->h * sizeof *past);
		for (int32_t at = 0; at < s->w * s->h; at++)
			past[at] = past[at] && every[at];
		if (!sized || carryframe_beyond(&s->fixed, oi, oj, every) == 0)
			memset(past, 0, (size_t)s->w * (size_t)s->h * sizeof *past);
		for (int32_t at = 0; at < s->w * s->h; at++)
			if (!past[at] || !every[at])
				ct->region.cells[at] = GRID_BLOCKED;
		free(every);
		free(past);
	}
	carryroom_free(&cr);
	for (int32_t at = 0; at < s->w * s->h; at++)
		count += ct->region.cells[at] == GRID_FREE;
	return count;
}

/* ct_region_grow(c): around a corner, the squares out of sight of where the object
 * was are a fact about the fixed walls and that point: what has been seen since the
 * region was fixed is added to it (nothing is taken away). */
static void ct_region_grow(Controller *c)
{
	CarryTask *ct = c->carry;
	if (c->task.kind != TASK_PUSH_AROUND_CORNER || !ct->region_fixed)
		return;
	Grid old = ct->region;
	int32_t ox = ct->rx0, oy = ct->ry0;
	ct->region = (Grid){0};
	RoomMap rm;
	ct_roommap_build(c, -1, false, &rm);
	ct_region_fix(c, &rm);
	goals_roommap_free(&rm);
	/* The union, on a grid holding both. */
	int32_t x0 = ox < ct->rx0 ? ox : ct->rx0, y0 = oy < ct->ry0 ? oy : ct->ry0;
	int32_t x1 = ox + old.w > ct->rx0 + ct->region.w ? ox + old.w : ct->rx0 + ct->region.w;
	int32_t y1 = oy + old.h > ct->ry0 + ct->region.h ? oy + old.h : ct->ry0 + ct->region.h;
	Grid both;
	grid_init(&both, x1 - x0, y1 - y0, GRID_BLOCKED);
	for (int32_t y = y0; y < y1; y++)
		for (int32_t x = x0; x < x1; x++)
			if (grid_free_at(&old, x - ox, y - oy) || grid_free_at(&ct->region, x - ct->rx0, y - ct->ry0))
				both.cells[(y - y0) * both.w + (x - x0)] = GRID_FREE;
	grid_free(&old);
	grid_free(&ct->region);
	ct->region = both;
	ct->rx0 = x0;
	ct->ry0 = y0;
}

/* ct_survey_point(c, dist, rm): where to look from: the door of the object's room
 * nearest the object, whose far side has region; for a corner, the reachable
 * square of the region nearest Utak. */
static bool ct_survey_point(Controller *c, const int32_t *dist, const RoomMap *rm)
{
	CarryTask *ct = c->carry;
	const Screen *s = &c->screen;
	if (c->task.kind != TASK_PUSH_AROUND_CORNER) {
		int32_t oi, oj;
		goals_cell_of(s, ct->object_start, &oi, &oj);
		CarryRooms cr;
		carryroom_merge(rm, &cr);
		int32_t room = carryroom_at(&cr, rm, oi, oj);
		double best = INFINITY;
		for (int32_t q = 0; q < rm->rooms.door_count && room >= 0; q++) {
			const RoomsDoor *d = &rm->rooms.doors[q];
			if (!cr.door[q] || (cr.merged[d->room_a] != room && cr.merged[d->room_b] != room) ||
			    !carrytask_door_sure(&cr, rm, d))
				continue;
			double far = hypot(d->x - oi, d->y - oj);
			if (far < best && dist[d->y * s->w + d->x] >= 0) {
				best = far;
				ct->survey_at = goals_centre(s->x0 + d->x, s->y0 + d->y);
				snprintf(ct->survey_what, sizeof ct->survey_what, "the door at (%d, %d), %d wide",
					 (int)(s->x0 + d->x), (int)(s->y0 + d->y), (int)d->width);
			}
		}
		carryroom_free(&cr);
		return ct->have_survey = best < INFINITY;
	}
	int32_t best = -1;
	for (int32_t at = 0; at < s->w * s->h; at++) {
		int32_t x = s->x0 + at % s->w - ct->rx0, y = s->y0 + at / s->w - ct->ry0;
		if (dist[at] >= 0 && grid_free_at(&ct->region, x, y) && (best < 0 || dist[at] < dist[best]))
			best = at;
	}
	if (best < 0)
		return false;
	ct->survey_at = goals_centre(s->x0 + best % s->w, s->y0 + best / s->w);
	snprintf(ct->survey_what, sizeof ct->survey_what, "the corridor beyond the corner, at (%.1f, %.1f)",
		 ct->survey_at.x, ct->survey_at.y);
	return ct->have_survey = true;
}

/* ---- the plan's text ------------------------------------------------------------ */

static int ct_printf(char *buf, size_t size, int n, const char *fmt, ...) __attribute__((format(printf, 4, 5)));
static int ct_printf(char *buf, size_t size, int n, const char *fmt, ...)
{
	if (n < 0 || (size_t)n >= size)
		return n;
	va_list ap;
	va_start(ap, fmt);
	int k = vsnprintf(buf + n, size - (size_t)n, fmt, ap);
	va_end(ap);
	n += k;
	return (size_t)n >= size ? (int)size - 1 : n;
}

/* ct_side(grasp, shape): which side of the object the grasp is on, by compass. */
static const char *ct_side(Vec2 at, const Polygon *shape)
{
	Vec2 m = carryoutline_centroid(shape), d = vec2_sub(at, m);
	static const char *const names[8] = {"east", "north-east", "north", "north-west",
					     "west", "south-west", "south", "south-east"};
	double a = atan2(d.y, d.x) * 4 / 3.14159265358979323846;
	int k = (int)lround(a);
	return names[(k + 8) % 8];
}

/* ct_plan_text(c, plan, from_holding): the structured plan (paper 3.6), steps
 * numbered, for the trace. */
static void ct_plan_text(Controller *c, const CarryPlan *plan, bool holding)
{
	CarryTask *ct = c->carry;
	const char *shape = task_shape_name(c->task.shape);
	char *b = ct->plan;
	size_t z = sizeof ct->plan;
	int n = 0, step = 1;
	n = ct_printf(b, z, n, "\n  plan:");
	if (!holding) {
		n = ct_printf(b, z, n, "\n    %d. go to (%.1f, %.1f), beside the %s on its %s side", step++, ct->grasp_at.x,
			      ct->grasp_at.y, shape, ct_side(ct->grasp_at, &ct->held));
		n = ct_printf(b, z, n, "\n    %d. grasp", step++);
	}
	n = ct_printf(b, z, n, "\n    %d. carry%s:", step++, ct->to_open_floor ? " to open floor" : "");
	for (int i = 0; i + 1 < plan->count; i++) {
		const MotorCommand *m = &plan->cmd[i];
		if (m->kind == MOTOR_TURN)
			n = ct_printf(b, z, n, " turn %d;", (int)lround(m->deg));
		else
			n = ct_printf(b, z, n, " push %.2f %.2f;", m->dx, m->dy);
	}
	n = ct_printf(b, z, n, " (%d pushes, %.1f squares; %d turns, %d degrees)", (int)plan->pushes, plan->pushed,
		      (int)plan->turns, (int)plan->turned);
	n = ct_printf(b, z, n, "\n    %d. release", step++);
	if (ct->to_open_floor)
		n = ct_printf(b, z, n, "\n    %d. re-grasp on another side, and carry on", step++);
	ct->plan_new = true;
}

int carrytask_note(Controller *c, char *note, size_t size)
{
	CarryTask *ct = c->carry;
	if (!ct || !ct->plan_new || size == 0)
		return 0;
	ct->plan_new = false;
	int k = snprintf(note, size, "%s", ct->plan);
	return (size_t)k >= size ? (int)size - 1 : k;
}

/* ct_name_reason(c, why, out, size): carry_grasp's reason, which names no object
 * ("the object is ..."), with the task's object named. */
static void ct_name_reason(const Controller *c, const char *why, char *out, size_t size)
{
	static const char anon[] = "the object";
	bool unnamed = strncmp(why, anon, sizeof anon - 1) == 0;
	const char *part[3] = {unnamed ? "the " : "", unnamed ? task_shape_name(c->task.shape) : "",
			       unnamed ? why + sizeof anon - 1 : why};
	size_t n = 0;
	for (int p = 0; p < 3; p++)
		for (const char *q = part[p]; *q && n + 1 < size; q++)
			out[n++] = *q;
	out[n] = '\0';
}

/* ---- choosing the grasp -------------------------------------------------------- */

/* ct_choose_grasp(c, k, dist, out): carry_grasp over the free squares beside node
 * k, nearest Utak first; failing that, a grasp that takes it to open floor for a
 * re-grasp. out->found false with the reason when none serves. */
static void ct_choose_grasp(Controller *c, int32_t k, const int32_t *dist, GoalResult *out)
{
	CarryTask *ct = c->carry;
	const Screen *s = &c->screen;
	Polygon shape;
	if (!carryoutline_object(c, k, &shape)) {
		snprintf(out->why, sizeof out->why, "the %s's outline cannot be traced", task_shape_name(c->task.shape));
		return;
	}
	Grid space, goal;
	ct_carry_grid(c, k, &shape, &space);
	/* Candidates: free squares Utak can reach, beside the object and no other
	 * (a grasp takes the first object touch finds, paper 2.2), nearest first. */
	Vec2 at[CARRYTASK_MAX_GRASPS];
	int n = 0;
	int32_t *order = util_alloc((size_t)s->w * (size_t)s->h, sizeof *order);
	int32_t count = 0;
	for (int32_t a = 0; a < s->w * s->h; a++) {
		if (dist[a] < 0 || space.cells[a] != GRID_FREE || s->label[a] >= 0)
			continue;
		int32_t i = a % s->w, j = a / s->w;
		bool beside = false, other = false;
		for (int dy = -1; dy <= 1; dy++)
			for (int dx = -1; dx <= 1; dx++) {
				int32_t l = screen_label(s, i + dx, j + dy);
				beside |= (dx || dy) && l == k;
				other |= (dx || dy) && l >= 0 && l != k;
			}
		if (beside && !other)
			order[count++] = a;
	}
	for (int32_t p = 1; p < count; p++) /* insertion sort by steps, then index */
		for (int32_t q = p; q > 0 && dist[order[q]] < dist[order[q - 1]]; q--) {
			int32_t t = order[q];
			order[q] = order[q - 1];
			order[q - 1] = t;
		}
	for (int32_t p = 0; p < count && n < CARRYTASK_MAX_GRASPS; p++)
		at[n++] = vec2(order[p] % s->w + 0.5, order[p] / s->w + 0.5);
	free(order);
	if (n == 0) {
		snprintf(out->why, sizeof out->why, "no free square beside the %s can be reached",
			 task_shape_name(c->task.shape));
		grid_free(&space);
		return;
	}
	CarryGrasp each[CARRYTASK_MAX_GRASPS];
	CarryResult best;
	carry_result_init(&best);
	int chosen = -1;
	for (int pass = 0; pass < 2 && chosen < 0; pass++) {
		CarryParams params = carry_params_default();
		params.angles = pass == 0 ? CARRYTASK_COARSE_ANGLES : CARRY_ANGLES_DEFAULT;
		CarryPlanner cp;
		carry_init(&cp, &space, &params);
		for (int open = 0; open <= 1 && chosen < 0; open++) {
			if (open && ct->regrasps >= CARRYTASK_MAX_REGRASPS)
				break;
			double reach = 0; /* the farthest point from a grasp: about its diameter */
			for (int32_t v = 0; v < shape.count; v++)
				for (int32_t u = 0; u < v; u++)
					reach = fmax(reach, hypot(shape.v[v].x - shape.v[u].x, shape.v[v].y - shape.v[u].y));
			ct_goal_grid(c, &space, open, reach, &goal);
			CarryGoal cg = {&goal, false, NULL, NULL};
			chosen = carry_grasp(&cp, &shape, at, n, &cg, each, &best);
			grid_free(&goal);
			if (chosen >= 0)
				ct->to_open_floor = open;
			else if (!open)
				ct_name_reason(c, each[0].why, out->why, sizeof out->why);
		}
		carry_free(&cp);
	}
	if (chosen >= 0) {
		ct->grasp_at = screen_to_model(s, at[chosen]);
		ct->have_grasp = true;
		ct->held = carryoutline_moved(&shape, vec2(s->x0, s->y0));
		out->found = true;
		out->goal = ct->grasp_at;
		ct_plan_text(c, &best.plan, false);
	}
	carry_result_free(&best);
	grid_free(&space);
}

/* ---- the hooks --------------------------------------------------------------------- */

bool carrytask_goal(Controller *c, const int32_t *dist, GoalResult *out)
{
	CarryTask *ct = c->carry;
	int32_t k = objects_find_target(c);
	if (k < 0 && ct->carried) {
		/* Let go (a carry that could not go on), the object is no longer
		 * told from what it stands against (an L let go in a doorway reads as
		 * one with the wall): no grasp can be chosen. Said so, rather than
		 * looking for another object of the shape until the cycles run out. */
		Vec2 at = carryoutline_centroid(&ct->held);
		snprintf(out->why, sizeof out->why,
			 "the %s, let go at (%.1f, %.1f), is no longer told from what it stands against: no grasp "
			 "can be chosen",
			 task_shape_name(c->task.shape), at.x, at.y);
		out->found = false;
		return true;
	}
	if (k < 0)
		return false;
	const ModelNode *node = &c->model.node[k];
	Vec2 centre = vec2((node->rect.lo.x + node->rect.hi.x) / 2, (node->rect.lo.y + node->rect.hi.y) / 2);
	if (ct->have_start && !ct->carried && goals_distance(centre, ct->object_start) > CARRYTASK_START_MOVED) {
		/* Not yet carried, the task's object is another than the one the
		 * place beyond was chosen for (a square far off read as a brick, the
		 * brick found later in the other room): that place was the next room
		 * of the wrong room, and pushing the brick there (where it already
		 * was) a false success. Look and survey again from its room. */
		snprintf(ct->plan, sizeof ct->plan, "\n  plan: look again: the %s is at (%.1f, %.1f), not (%.1f, %.1f)",
			 task_shape_name(c->task.shape), centre.x, centre.y, ct->object_start.x, ct->object_start.y);
		ct->plan_new = true;
		ct->have_start = ct->region_fixed = ct->have_survey = ct->have_grasp = false;
		ct->stage = CARRY_STAGE_LOOK;
	}
	if (!ct->have_start) {
		ct->object_start = centre;
		ct->have_start = true;
	}
	int32_t ux, uy;
	if (ct->stage == CARRY_STAGE_FETCH && objects_unconfirmed_square(c, k, &ux, &uy) &&
	    goals_near(c, goals_centre(ux, uy), dist, &out->goal)) {
		/* The object is grasped only when the fovea has seen all of it (as for
		 * any task's object, objects.h): look closer first. */
		out->found = true;
		return true;
	}
	if (ct->stage == CARRY_STAGE_FETCH && c->task.shape == SHAPE_SQUARE &&
	    wallbump_set_off(c, dist, goals_distance(centre, c->start), out)) {
		/* A corner of the wall nearer the start may be a square pressed against
		 * it, the task's square then (the nearest to the start, objects.h):
		 * arriving beside this one, Utak doubts it and sets off to feel that
		 * corner (controller.c, bump_trip), as any push does (goals.c, whose
		 * goal this one is: the carry's goals come first). Without it the grasp
		 * was chosen again where he stood, and the run ended "no progress". */
		return true;
	}
	if (ct->stage == CARRY_STAGE_FETCH && ct->have_grasp) {
		out->found = true;
		out->goal = ct->grasp_at;
		return true;
	}
	int32_t si, sj;
	if (ct->stage == CARRY_STAGE_SURVEY && ct->have_survey &&
	    !(goals_cell_of(&c->screen, ct->survey_at, &si, &sj) && dist[sj * c->screen.w + si] >= 0))
		ct->stage = CARRY_STAGE_LOOK; /* the door was no door: look again */
	if (ct->stage == CARRY_STAGE_FETCH && ct->have_grasp &&
	    !(goals_cell_of(&c->screen, ct->grasp_at, &si, &sj) && dist[sj * c->screen.w + si] >= 0))
		ct->have_grasp = false; /* no way there after all: choose again */
	if (ct->stage == CARRY_STAGE_SURVEY && ct->have_survey) {
		out->found = true;
		out->goal = ct->survey_at;
		return true;
	}
	if (ct->stage == CARRY_STAGE_LOOK) {
		/* The place beyond: seen yet? Then fix it, and go and look at it from
		 * close by (where it may be fixed again, better). */
		bool seen = false;
		for (int fixed = 0; fixed <= 0 && !seen; fixed++) {
			RoomMap own;
			ct_roommap_build(c, k, fixed, &own);
			seen = ct_region_fix(c, &own) > 0 && ct_survey_point(c, dist, &own);
			goals_roommap_free(&own);
		}
		if (seen) {
			ct->region_fixed = true;
			ct->stage = CARRY_STAGE_SURVEY;
			out->found = true;
			out->goal = ct->survey_at;
			/* (after a note not yet printed: "look again") */
			int at = ct->plan_new ? (int)strlen(ct->plan) : 0;
			ct_printf(ct->plan, sizeof ct->plan, at, "\n  plan: survey %s%s%s", ct->survey_what,
				 c->task.kind == TASK_PUSH_AROUND_CORNER ? ", in " : "",
				 c->task.kind == TASK_PUSH_AROUND_CORNER ? ct->corridor : "");
			ct->plan_new = true;
			return true;
		}
		/* Not yet: look further, at the unseen, or else at what was seen only
		 * coarsely: a wall seen from afar may seem an object standing free.
		 * Going back to a place looked from before, with nothing new seen
		 * since, CARRYTASK_LOOK_IDLE times (a frontier no place in reach
		 * shows, visited in turn) is as if nothing were left unseen. */
		int32_t known = worldmodel_known_squares(&c->model);
		if (known > ct->look_seen)
			ct->look_idle = 0;
		ct->look_seen = known;
		out->exploring = out->found = ct->look_idle <= CARRYTASK_LOOK_IDLE &&
					      (goals_frontier(c, dist, &out->goal) || goals_inspect(c, dist, &out->goal));
		if (out->found && c->cycle != ct->look_cycle) {
			/* A goal looked for before, with nothing new seen since: idle. */
			bool again = false;
			for (int q = 0; q < CARRYTASK_LOOK_RING && !again; q++)
				again = q < ct->look_count && goals_distance(ct->look_goal[q], out->goal) < 0.5;
			ct->look_idle += again; /* (it was set to 0 above when something new was seen) */
			ct->look_goal[ct->look_next++ % CARRYTASK_LOOK_RING] = out->goal;
			ct->look_count = ct->look_count < CARRYTASK_LOOK_RING ? ct->look_count + 1 : CARRYTASK_LOOK_RING;
			ct->look_cycle = c->cycle;
		}
		if (!out->found)
			snprintf(out->why, sizeof out->why, "%s, and %s",
				 c->task.kind == TASK_PUSH_AROUND_CORNER
					 ? "the task does not apply: the object's room is no L-shaped corridor"
					 : "no door out of the object's room",
				 ct->look_idle > CARRYTASK_LOOK_IDLE ? "looking further has shown nothing new"
								     : c->task.kind == TASK_PUSH_AROUND_CORNER ? "nothing is left unseen"
														: "nothing left unseen");
		return true;
	}
	/* FETCH without a grasp: choose it for the whole carry. */
	ct_choose_grasp(c, k, dist, out);
	return true;
}

bool carrytask_arrive(Controller *c)
{
	CarryTask *ct = c->carry;
	if (ct->stage == CARRY_STAGE_SURVEY) {
		/* Seen from close by: fix the goal region now, and fetch the object. */
		RoomMap rm;
		int32_t k = objects_find_target(c);
		ct_roommap_build(c, k, false, &rm);
		CarryTask keep = *ct; /* the region fixed before, should this one be empty */
		grid_init(&keep.region, ct->region.w, ct->region.h, GRID_BLOCKED);
		memcpy(keep.region.cells, ct->region.cells, (size_t)ct->region.w * (size_t)ct->region.h);
		if (ct_region_fix(c, &rm) > 0) {
			grid_free(&keep.region);
		} else {
			grid_free(&ct->region);
			ct->region = keep.region;
			ct->rx0 = keep.rx0;
			ct->ry0 = keep.ry0;
		}
		goals_roommap_free(&rm);
		ct->stage = CARRY_STAGE_FETCH;
		ct->have_survey = false;
		return true;
	}
	if (ct->stage == CARRY_STAGE_FETCH)
		ct->have_grasp = false; /* grasped, or chosen again if touch finds it not there */
	return false;
}

/* ct_fail(c, why): the task cannot be done. */
static bool ct_fail(Controller *c, const char *why)
{
	c->phase = PHASE_FAILED;
	snprintf(c->why, sizeof c->why, "%s", why);
	return false;
}

/* ct_plan_carry(c): the carry from where Utak believes he and the object are. */
static CarryStatus ct_plan_carry(Controller *c, bool *inside, char *why, size_t size)
{
	CarryTask *ct = c->carry;
	Vec2 extra = c->start;
	screen_build(&c->screen, &c->model, &extra, 1);
	ct_region_grow(c);
	const Screen *s = &c->screen;
	Polygon shape = carryoutline_moved(&ct->held, vec2(-s->x0, -s->y0));
	Grid space, goal;
	ct_carry_grid(c, -1, &shape, &space);
	Vec2 at = screen_from_model(s, c->model.utak);
	double reach = 0;
	for (int32_t v = 0; v < shape.count; v++)
		reach = fmax(reach, hypot(shape.v[v].x - at.x, shape.v[v].y - at.y));
	ct_goal_grid(c, &space, ct->to_open_floor, reach, &goal);
	char name[32];
	snprintf(name, sizeof name, "the %s", task_shape_name(c->task.shape));
	CarryObject obj = {shape, at, name};
	*inside = carry_pose_inside(&obj, &goal, at, 0);
	CarryStatus st = CARRY_FOUND;
	for (int pass = 0; pass < 2 && !*inside && (pass == 0 || st != CARRY_FOUND); pass++) {
		CarryParams params = carry_params_default();
		params.angles = pass == 0 ? CARRYTASK_COARSE_ANGLES : CARRY_ANGLES_DEFAULT;
		CarryPlanner cp;
		carry_init(&cp, &space, &params);
		CarryResult r;
		carry_result_init(&r);
		CarryGoal cg = {&goal, false, NULL, NULL};
		st = carry_plan(&cp, &obj, &cg, &r);
		if (st == CARRY_FOUND) {
			ct->count = 0;
			for (int i = 0; i + 1 < r.plan.count && ct->count < CARRYTASK_MAX_COMMANDS; i++) {
				ct->cmd[ct->count] = r.plan.cmd[i];
				ct->expect[ct->count++] = screen_to_model(s, r.plan.pose[i + 1].at);
			}
			ct->next = 0;
			ct->have_carry = true;
			ct_plan_text(c, &r.plan, true);
		} else {
			snprintf(why, size, "%s", r.why);
		}
		carry_result_free(&r);
		carry_free(&cp);
	}
	grid_free(&space);
	grid_free(&goal);
	return st;
}

bool carrytask_decide(Controller *c, MotorCommand *cmd)
{
	CarryTask *ct = c->carry;
	ct->stage = CARRY_STAGE_HOLD;
	ct->carried = true;
	for (int attempt = 0; attempt < 2; attempt++) {
		if (!ct->have_carry || ct->next >= ct->count) {
			if (ct->have_carry)
				ct->replans++; /* followed to its end, and not there */
			if (ct->replans > CARRYTASK_MAX_REPLANS)
				return ct_fail(c, "the carry was planned again and again, and the object is not there yet");
			bool inside = false;
			char why[CARRY_WHY];
			ct->have_carry = false;
			CarryStatus st = ct_plan_carry(c, &inside, why, sizeof why);
			if (st != CARRY_FOUND && !ct->to_open_floor && ct->regrasps < CARRYTASK_MAX_REGRASPS) {
				/* No carry to the goal from this grasp any more: first to
				 * open floor with it, and let go there. WHY: let go where it
				 * stands, the object may be half through a doorway (an L
				 * turned in it, tests/worlds/door-thin-l.w), where no grasp
				 * serves and the model reads it as one with the wall. */
				ct->to_open_floor = true;
				char why_open[CARRY_WHY];
				if (ct_plan_carry(c, &inside, why_open, sizeof why_open) == CARRY_FOUND) {
					st = CARRY_FOUND;
					static const char head[] = "\n  plan:";
					char steps[CARRYTASK_PLAN_TEXT];
					snprintf(steps, sizeof steps, "%s",
						 inside ? " let go here, on open floor, and grasp again" : ct->plan + sizeof head - 1);
					int n = ct_printf(ct->plan, sizeof ct->plan, 0, "%s no carry from this grasp (%s):", head, why);
					ct_printf(ct->plan, sizeof ct->plan, n, "%s", steps);
					ct->plan_new = true;
				} else {
					ct->to_open_floor = false;
				}
			}
			if (st != CARRY_FOUND) {
				if (ct->regrasps >= CARRYTASK_MAX_REGRASPS)
					return ct_fail(c, why);
				/* No carry from this grasp any more (what was seen or bumped
				 * into since says so): let go, and choose a grasp again. */
				ct->regrasps++;
				ct->to_open_floor = false;
				ct->stage = CARRY_STAGE_FETCH;
				ct->have_grasp = false;
				c->phase = PHASE_TRAVEL;
				c->have_plan = false;
				snprintf(ct->plan, sizeof ct->plan, "\n  plan: release and grasp again: %s", why);
				ct->plan_new = true;
				*cmd = (MotorCommand){.kind = MOTOR_RELEASE};
				return true;
			}
			if (inside) {
				*cmd = (MotorCommand){.kind = MOTOR_RELEASE};
				if (ct->to_open_floor) {
					/* On open floor: let go, and choose a grasp again. */
					ct->to_open_floor = false;
					ct->regrasps++;
					ct->stage = CARRY_STAGE_FETCH;
					ct->have_grasp = false;
					c->phase = PHASE_TRAVEL;
					c->have_plan = false;
				} else {
					c->phase = PHASE_DONE;
				}
				return true;
			}
			continue;
		}
		break;
	}
	if (!ct->have_carry || ct->next >= ct->count)
		return ct_fail(c, "the carry plan is empty");
	MotorCommand *next = &ct->cmd[ct->next];
	*cmd = *next;
	ct->issued_from = c->model.utak;
	/* A long leg in parts (carry.h says why they are whole 64ths). */
	if (!carry_command_part(next, CONTROLLER_MAX_LEG, cmd))
		return true;
	ct->next++;
	return true;
}

void carrytask_perceive(Controller *c, const MotorCommand *cmd)
{
	CarryTask *ct = c->carry;
	if (cmd->kind == MOTOR_PUSH) {
		ct->held = carryoutline_moved(&ct->held, vec2_sub(c->model.utak, ct->issued_from));
	} else if (cmd->kind == MOTOR_TURN) {
		/* Turned about the point he turned at; then moved with him by whatever
		 * the model corrected his position by: the object is held rigidly. */
		double cs, sn;
		geom_cos_sin(cmd->deg, &cs, &sn);
		Vec2 by = vec2_sub(c->model.utak, ct->issued_from);
		for (int32_t i = 0; i < ct->held.count; i++)
			ct->held.v[i] = vec2_add(geom_rotate(ct->held.v[i], ct->issued_from, cs, sn), by);
	}
	if (!ct->have_carry)
		return;
	Vec2 expected = ct->next > 0 && (cmd->kind == MOTOR_TURN || ct->next <= ct->count)
				? vec2_add(ct->issued_from, cmd->kind == MOTOR_PUSH ? vec2(cmd->dx, cmd->dy) : vec2(0, 0))
				: c->model.utak;
	if (goals_distance(c->model.utak, expected) > CARRYTASK_DISPARITY) {
		ct->have_carry = false; /* step 13: plan the carry again from here */
		ct->replans++;
		snprintf(ct->plan, sizeof ct->plan, "; re-plan the carry: Utak is at (%.1f, %.1f), not (%.1f, %.1f)",
			 c->model.utak.x, c->model.utak.y, expected.x, expected.y);
		ct->plan_new = true;
	}
}
