/* apart.c - settling the MERGED doubt by motion: a grasp, two pulls straight back, a
 * look, and back again (paper 2.2, 3.4.2; issue 13 item 6). CONTROLLER SIDE. The
 * rule, and why it is sound, are in apart.h. */
#include "utak/mind/apart.h"

#include <math.h>
#include <stdlib.h>

#include "utak/base/eye.h"
#include "utak/mind/controller.h"
#include "utak/mind/goals.h"
#include "utak/mind/objects.h"
#include "utak/mind/tug.h"

/* in_set(sx, sy, n, x, y): (x, y) is one of the n squares. */
static bool in_set(const int32_t *sx, const int32_t *sy, int32_t n, int32_t x, int32_t y)
{
	for (int32_t i = 0; i < n; i++)
		if (sx[i] == x && sy[i] == y)
			return true;
	return false;
}

ApartVerdict apart_vacated_clear(const int32_t *sx, const int32_t *sy, int32_t n, int32_t tx, int32_t ty, int32_t ux,
				 int32_t uy, const Impression *imp, bool (*floor_at)(const void *ctx, int32_t x, int32_t y),
				 const void *ctx)
{
	ApartVerdict v = APART_ONE;
	int32_t vacated = 0;
	for (int32_t i = 0; i < n && v != APART_LEFT; i++) {
		if (in_set(sx, sy, n, sx[i] - tx, sy[i] - ty))
			continue; /* in S + t: one polygon drawn by t covers it still */
		if (sx[i] == ux && sy[i] == uy)
			continue; /* his own (pushing): no object but the one held may share it (motion.c), and the eye's cell there shows him */
		vacated++;
		int32_t cell = eye_cell_at(sx[i] - ux, sy[i] - uy);
		EyeCell e = cell >= 0 ? eye_cell(cell) : (EyeCell){0};
		if (cell < 0 || e.size > 2) {
			v = APART_UNSEEN; /* a 4 x 4 cell reads 0 over one square */
			continue;
		}
		/* The cell's squares one polygon drawn by t would leave occupied: those
		 * of S + t; the rest of S is left floor, and any other square must be
		 * believed floor (else what it holds could make up the count). */
		int32_t want = 0;
		bool known = true;
		for (int32_t dy = 0; dy < e.size; dy++)
			for (int32_t dx = 0; dx < e.size; dx++) {
				int32_t x = ux + e.ox + dx, y = uy + e.oy + dy;
				if (in_set(sx, sy, n, x - tx, y - ty))
					want++;
				else if (!in_set(sx, sy, n, x, y) && !floor_at(ctx, x, y))
					known = false;
			}

		if (!known)
			v = APART_UNSEEN;
		else if (imp->level[cell] != eye_level(want, e.size * e.size))
			v = APART_LEFT;
	}
	return vacated > 0 ? v : APART_UNSEEN;
}

const char *apart_verdict_text(ApartVerdict v)
{
	switch (v) {
	case APART_ONE:
		return "it came away whole, leaving floor behind: one object, the doubt is gone";
	case APART_LEFT:
		return "where one object drawn back would leave floor, the eye sees it occupied: part stayed "
		       "(or another object came): the doubt stands";
	case APART_UNSEEN:
		return "what it would leave behind was not seen closely enough (or nothing was held): the doubt stands";
	case APART_SHORT:
		return "a pull did not go its whole way (wedged, or the way blocked): the doubt stands";
	default:
		return "not pulled";
	}
}

/* in_view(c, j, x, y, mx, my): moved from model square (x, y) by TUG_STEP along
 * (mx, my), every square node j's motion leaves empty (S \ (S + t)) would lie in
 * a cell of 1 or 2 x 2 squares of the look after it (apart_vacated_clear asks no
 * less). */
static bool in_view(const Controller *c, int32_t j, int32_t x, int32_t y, int mx, int my)
{
	const WorldModel *m = &c->model;
	const Box *r = &m->node[j].rect;
	int32_t tx = TUG_STEP * mx, ty = TUG_STEP * my, ux = x + tx, uy = y + ty;
	for (int32_t sy = (int32_t)floor(r->lo.y); sy < (int32_t)ceil(r->hi.y); sy++)
		for (int32_t sx = (int32_t)floor(r->lo.x); sx < (int32_t)ceil(r->hi.x); sx++) {
			if (worldmodel_node_at(m, sx, sy) != j || worldmodel_node_at(m, sx - tx, sy - ty) == j)
				continue;
			int32_t cell = eye_cell_at(sx - ux, sy - uy);
			if (cell < 0 || eye_cell(cell).size > 2)
				return false;
		}
	return true;
}

/* anchored(c, j, x, y, mx, my): moved from model square (x, y) by TUG_STEP along
 * (mx, my), the look's cells of 1 and 2 x 2 would cover at least APART_ANCHORS
 * squares believed occupied that are not node j's: something that stays put, by
 * which the look can place him (the disparity, paper 3.5). Where there is nothing
 * (j alone on open floor), the held set rides with him in every place the search
 * tries, a pull halted against a hidden neighbour looks like a whole one, and
 * pushed back by what he believes he drew he would leave himself and the object
 * where he does not believe them (tests/worlds: the adversarial set of apart.h,
 * "go round square" ended 2 squares from home, believed home). */
static bool anchored(const Controller *c, int32_t j, int32_t x, int32_t y, int mx, int my)
{
	const WorldModel *m = &c->model;
	int32_t ux = x + TUG_STEP * mx, uy = y + TUG_STEP * my, n = 0;
	for (int32_t oy = -EYE_INTERMEDIATE_HALF; oy < EYE_INTERMEDIATE_HALF; oy++)
		for (int32_t ox = -EYE_INTERMEDIATE_HALF; ox < EYE_INTERMEDIATE_HALF; ox++)
			if (worldmodel_belief(m, ux + ox, uy + oy) == BELIEF_OCCUPIED &&
			    worldmodel_node_at(m, ux + ox, uy + oy) != j)
				n++;
	return n >= APART_ANCHORS;
}

/* way_free(c, j, x, y, mx, my): Utak's way from model square (x, y), APART_WAY
 * squares along (mx, my), and node j's squares moved as far, land only on j's own
 * squares or believed floor (a way blocked makes the motion fall short: no harm,
 * but nothing settled). */
static bool way_free(const Controller *c, int32_t j, int32_t x, int32_t y, int mx, int my)
{
	const WorldModel *m = &c->model;
	for (int t = 1; t <= APART_WAY; t++)
		if (worldmodel_node_at(m, x + t * mx, y + t * my) != j &&
		    worldmodel_belief(m, x + t * mx, y + t * my) != BELIEF_FLOOR)
			return false;
	const Box *r = &m->node[j].rect;
	for (int32_t sy = (int32_t)floor(r->lo.y); sy < (int32_t)ceil(r->hi.y); sy++)
		for (int32_t sx = (int32_t)floor(r->lo.x); sx < (int32_t)ceil(r->hi.x); sx++) {
			if (worldmodel_node_at(m, sx, sy) != j)
				continue;
			for (int t = 1; t <= APART_WAY; t++) {
				int32_t qx = sx + t * mx, qy = sy + t * my;
				if (worldmodel_node_at(m, qx, qy) != j && worldmodel_belief(m, qx, qy) != BELIEF_FLOOR)
					return false;
			}
		}
	return true;
}

/* move_from(c, j, x, y, &mx, &my): Utak on model square (x, y) could move node j:
 * the first square the model believes occupied among the eight round (x, y), in
 * touch's order (the simulator grasps the first object touch feels, motion.c), is
 * one of j's beside it along an axis, e from him; and drawn back (-e) or pushed on
 * (e), the first of the two that way_free and in_view allow, is (mx, my): a pull
 * leaves empty the squares farthest from him, a push the nearest, and the look
 * must show them closely. */
static bool move_from(const Controller *c, int32_t j, int32_t x, int32_t y, int *mx, int *my)
{
	const WorldModel *m = &c->model;
	for (int i = 0; i < TOUCH_CELLS; i++) {
		int ox = goals_touch_offset[i][0], oy = goals_touch_offset[i][1];
		if (worldmodel_belief(m, x + ox, y + oy) != BELIEF_OCCUPIED)
			continue;
		if (i % 2 != 0 || worldmodel_node_at(m, x + ox, y + oy) != j)
			return false;
		for (int sign = -1; sign <= 1; sign += 2)
			if (way_free(c, j, x, y, sign * ox, sign * oy) && in_view(c, j, x, y, sign * ox, sign * oy) &&
			    anchored(c, j, x, y, sign * ox, sign * oy)) {
				*mx = sign * ox;
				*my = sign * oy;
				return true;
			}
		return false;
	}
	return false;
}

bool apart_goal(const Controller *c, int32_t j, const int32_t *dist, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int32_t best = -1, best_d = INT32_MAX;
	int mx, my;
	for (int32_t at = 0; at < s->w * s->h; at++)
		if (dist[at] >= 0 && dist[at] < best_d && move_from(c, j, s->x0 + at % s->w, s->y0 + at / s->w, &mx, &my)) {
			best = at;
			best_d = dist[at];
		}
	if (best < 0)
		return false;
	*goal = goals_centre(s->x0 + best % s->w, s->y0 + best / s->w);
	return true;
}

bool apart_begin(Controller *c, int32_t j)
{
	ApartRun *a = &c->apart;
	const WorldModel *m = &c->model;
	if (a->stage != APART_IDLE || j < 0 || m->node[j].kind != NODE_OBJECT || m->node[j].squares > APART_MAX_SQUARES)
		return false;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	/* The simulator grasps the first object touch feels, in its order: that one
	 * must be a square of node j, beside Utak along an axis, and the model's
	 * first occupied square the same (move_from). */
	int i = 0;
	while (i < TOUCH_CELLS && (c->impression.touch[i] < 'A' || c->impression.touch[i] > 'Z' ||
				   c->impression.touch[i] == 'B'))
		i++;
	if (i == TOUCH_CELLS || i % 2 != 0)
		return false;
	int ex = goals_touch_offset[i][0], ey = goals_touch_offset[i][1], mx, my;
	if (worldmodel_node_at(m, ux + ex, uy + ey) != j || !move_from(c, j, ux, uy, &mx, &my) ||
	    abs(mx) != abs(ex) || abs(my) != abs(ey))
		return false;
	a->n = worldmodel_node_squares(m, j, a->sx, a->sy, APART_MAX_SQUARES);
	a->n = a->n < APART_MAX_SQUARES ? a->n : APART_MAX_SQUARES;
	a->ident = m->node[j].ident;
	a->dx = mx;
	a->dy = my;
	a->drawn = 0;
	a->clear = false;
	a->verdict = APART_UNTRIED;
	a->stage = APART_GRASPED;
	a->grasp_due = true;
	a->at = objects_node_centre(c, j);
	a->squares = m->node[j].squares;
	return true;
}

/* believed_floor(m, x, y): the model believes square (x, y) floor. */
static bool believed_floor(const void *m, int32_t x, int32_t y)
{
	return worldmodel_belief((const WorldModel *)m, x, y) == BELIEF_FLOOR;
}

/* pull(c, cmd): a motion of TUG_STEP along the run's line (a pull or a push). */
static void pull(Controller *c, MotorCommand *cmd)
{
	*cmd = (MotorCommand){.kind = MOTOR_PUSH, .dx = TUG_STEP * c->apart.dx, .dy = TUG_STEP * c->apart.dy};
	c->apart.from = c->model.utak;
}

/* went(c): how far the last pull drew Utak along its line; *whole when within
 * APART_SLACK of the step, and no farther across it. */
static double went(const Controller *c, bool *whole)
{
	const ApartRun *a = &c->apart;
	double along = (c->model.utak.x - a->from.x) * a->dx + (c->model.utak.y - a->from.y) * a->dy;
	Vec2 want = vec2(a->from.x + TUG_STEP * a->dx, a->from.y + TUG_STEP * a->dy);
	/* ... and this look placed him on the line's axis (worldmodel.h, unplaced:
	 * a shift of a square either way would match it worse), so that a halt
	 * would have shown. */
	*whole = goals_distance(c->model.utak, want) <= APART_SLACK && c->model.unplaced[a->dx != 0 ? 0 : 1] == 0;
	return along;
}

/* back(c, cmd): the object pushed back by what he believes he drew, or, drawn
 * nowhere, let go. */
static void back(Controller *c, MotorCommand *cmd)
{
	ApartRun *a = &c->apart;
	if (a->drawn > APART_SLACK) {
		*cmd = (MotorCommand){.kind = MOTOR_PUSH, .dx = -a->drawn * a->dx, .dy = -a->drawn * a->dy};
		a->stage = APART_BACK;
	} else {
		*cmd = (MotorCommand){.kind = MOTOR_RELEASE};
		a->stage = APART_IDLE;
	}
}

bool apart_decide(Controller *c, MotorCommand *cmd)
{
	ApartRun *a = &c->apart;
	bool whole;
	switch (a->stage) {
	case APART_IDLE:
		return false;
	case APART_GRASPED:
		if (a->grasp_due) {
			a->grasp_due = false;
			*cmd = (MotorCommand){.kind = MOTOR_GRASP};
			return true;
		}
		if (!c->model.holding) {
			a->verdict = APART_UNSEEN; /* nothing held: nothing to draw */
			*cmd = (MotorCommand){.kind = MOTOR_RELEASE};
			a->stage = APART_IDLE;
			return true;
		}
		pull(c, cmd);
		a->stage = APART_PULLED;
		return true;
	case APART_PULLED: {
		a->drawn += went(c, &whole);
		if (!whole) {
			a->verdict = APART_SHORT;
			back(c, cmd);
			return true;
		}
		int32_t ux, uy;
		worldmodel_utak_square(&c->model, &ux, &uy);
		a->verdict = apart_vacated_clear(a->sx, a->sy, a->n, TUG_STEP * a->dx, TUG_STEP * a->dy, ux, uy,
						 &c->impression, believed_floor, &c->model);
		if (a->verdict != APART_ONE) {
			back(c, cmd);
			return true;
		}
		pull(c, cmd);
		a->stage = APART_PULLED2;
		return true;
	}
	case APART_PULLED2:
		a->drawn += went(c, &whole);
		if (!whole)
			a->verdict = APART_SHORT; /* the first pull may have been halted against a part */
		back(c, cmd);
		return true;
	case APART_BACK:
		*cmd = (MotorCommand){.kind = MOTOR_RELEASE};
		a->stage = APART_IDLE;
		if (a->verdict == APART_ONE && a->kept < APART_KEPT &&
		    apart_set_make(&a->one_set[a->kept], a->sx, a->sy, a->n)) {
			a->one_ident[a->kept] = a->ident;
			a->one_squares[a->kept] = a->squares;
			a->one_at[a->kept++] = a->at;
		}
		return true;
	}
	return false;
}

bool apart_redo(Controller *c)
{
	ApartRun *a = &c->apart;
	if (a->stage != APART_IDLE || (a->verdict != APART_LEFT && a->verdict != APART_SHORT) ||
	    a->redone >= APART_REDO || worldmodel_motion_error(&c->model) <= 0)
		return false;
	a->redone++;
	a->verdict = APART_UNTRIED;
	return true;
}

bool apart_set_make(ApartSet *set, const int32_t *sx, const int32_t *sy, int32_t n)
{
	if (n <= 0)
		return false;
	int32_t x0 = sx[0], y0 = sy[0], x1 = sx[0], y1 = sy[0];
	for (int32_t i = 1; i < n; i++) {
		x0 = sx[i] < x0 ? sx[i] : x0;
		y0 = sy[i] < y0 ? sy[i] : y0;
		x1 = sx[i] > x1 ? sx[i] : x1;
		y1 = sy[i] > y1 ? sy[i] : y1;
	}
	if ((int64_t)x1 - x0 >= APART_BOX || (int64_t)y1 - y0 >= APART_BOX)
		return false;
	*set = (ApartSet){.x0 = x0, .y0 = y0, .n = n};
	for (int32_t i = 0; i < n; i++)
		set->row[sy[i] - y0] |= (uint64_t)1 << (sx[i] - x0);
	return true;
}

bool apart_set_holds(const ApartSet *set, int32_t x, int32_t y)
{
	int64_t bx = (int64_t)x - set->x0, by = (int64_t)y - set->y0;
	return bx >= 0 && by >= 0 && bx < APART_BOX && by < APART_BOX && ((set->row[by] >> bx) & 1);
}

/* beside_set(set, x, y): (x, y) is one of the set's or one of the eight round one. */
static bool beside_set(const ApartSet *set, int32_t x, int32_t y)
{
	for (int32_t dy = -1; dy <= 1; dy++)
		for (int32_t dx = -1; dx <= 1; dx++)
			if (apart_set_holds(set, x + dx, y + dy))
				return true;
	return false;
}

bool apart_still_one(const ApartSet *set, const int32_t *nx, const int32_t *ny, int32_t n)
{
	for (int32_t i = 0; i < n; i++)
		if (!beside_set(set, nx[i], ny[i]))
			return false;
	/* A 2 x 2 block of squares not the set's, with (nx[i], ny[i]) its lower left. */
	for (int32_t i = 0; i < n; i++) {
		if (apart_set_holds(set, nx[i], ny[i]))
			continue;
		int found = 0;
		for (int32_t k = 0; k < n; k++)
			if (!apart_set_holds(set, nx[k], ny[k]) && nx[k] - nx[i] >= 0 && nx[k] - nx[i] <= 1 &&
			    ny[k] - ny[i] >= 0 && ny[k] - ny[i] <= 1 && (nx[k] != nx[i] || ny[k] != ny[i]))
				found++;
		if (found == 3)
			return false;
	}
	return true;
}

bool apart_one(const Controller *c, int32_t j)
{
	const ApartRun *a = &c->apart;
	if (j < 0)
		return false;
	const ModelNode *n = &c->model.node[j];
	for (int i = 0; i < a->kept; i++)
		if (objects_same(a->one_ident[i], a->one_at[i], n->ident, objects_node_centre(c, j)) &&
		    a->one_squares[i] == n->squares)
			return true;
	return false;
}

bool apart_no_square(const Controller *c, int32_t j)
{
	const ApartRun *a = &c->apart;
	if (j < 0 || a->kept == 0)
		return false;
	const WorldModel *m = &c->model;
	const ModelNode *node = &m->node[j];
	Vec2 at = objects_node_centre(c, j);
	for (int i = 0; i < a->kept; i++) {
		if (!objects_same(a->one_ident[i], a->one_at[i], node->ident, at))
			continue;
		/* The node's squares, no more than the set's and a ring round it
		 * could hold (else it is not the set). */
		int32_t nx[APART_MAX_SQUARES], ny[APART_MAX_SQUARES], n = 0;
		bool fits = true;
		const Box *r = &node->rect;
		for (int32_t y = (int32_t)floor(r->lo.y); fits && y < (int32_t)ceil(r->hi.y); y++)
			for (int32_t x = (int32_t)floor(r->lo.x); fits && x < (int32_t)ceil(r->hi.x); x++)
				if (worldmodel_node_at(m, x, y) == j) {
					if (n == APART_MAX_SQUARES || !beside_set(&a->one_set[i], x, y))
						fits = false;
					else {
						nx[n] = x;
						ny[n++] = y;
					}
				}
		if (fits && apart_still_one(&a->one_set[i], nx, ny, n))
			return true;
	}
	return false;
}
