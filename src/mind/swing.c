/* swing.c - the JOINED doubt settled by a quarter turn of the object held, which
 * does not move Utak (paper 2.2, 3.4.2; issue 13 item 6). CONTROLLER SIDE. The rule,
 * and why it is sound, are in swing.h. */
#include "utak/mind/swing.h"

#include <math.h>
#include <stdlib.h>

#include "utak/base/eye.h"
#include "utak/mind/controller.h"
#include "utak/mind/goals.h"
#include "utak/mind/objects.h"

static const double swing_pi = 3.14159265358979323846;

/* turned(x, y, sign, &tx, &ty): offset square (x, y) turned a quarter about the
 * centre of Utak's square, counter-clockwise for sign +1. */
static void turned(int32_t x, int32_t y, int sign, int32_t *tx, int32_t *ty)
{
	*tx = sign > 0 ? -y : y;
	*ty = sign > 0 ? x : -x;
}

/* in_s(sx, sy, n, x, y): (x, y) is one of S's offsets. */
static bool in_s(const int8_t *sx, const int8_t *sy, int32_t n, int32_t x, int32_t y)
{
	for (int32_t i = 0; i < n; i++)
		if (sx[i] == x && sy[i] == y)
			return true;
	return false;
}

/* in_g(sx, sy, n, sign, x, y): (x, y) lies in G, R(S) grown by a ring (swing.h). */
static bool in_g(const int8_t *sx, const int8_t *sy, int32_t n, int sign, int32_t x, int32_t y)
{
	for (int32_t i = 0; i < n; i++) {
		int32_t tx, ty;
		turned(sx[i], sy[i], sign, &tx, &ty);
		if (abs(tx - x) <= 1 && abs(ty - y) <= 1)
			return true;
	}
	return false;
}

ApartVerdict swing_vacated_clear(const int8_t *sx, const int8_t *sy, int32_t n, int sign, const Impression *imp,
				 bool (*floor_at)(const void *ctx, int32_t ox, int32_t oy), const void *ctx)
{
	ApartVerdict v = APART_ONE;
	int32_t vacated = 0;
	for (int32_t i = 0; i < n && v != APART_LEFT; i++) {
		if ((sx[i] == 0 && sy[i] == 0) || in_g(sx, sy, n, sign, sx[i], sy[i]))
			continue; /* his own square, or one the turned object may own */
		vacated++;
		int32_t cell = eye_cell_at(sx[i], sy[i]);
		EyeCell e = cell >= 0 ? eye_cell(cell) : (EyeCell){0};
		if (cell < 0 || e.size > 2) {
			v = APART_UNSEEN;
			continue;
		}
		/* Every square of the cell must be one the object left, or floor no
		 * turned square may reach: then the cell reads 0 unless a piece stayed. */
		bool known = true;
		for (int32_t dy = 0; dy < e.size && known; dy++)
			for (int32_t dx = 0; dx < e.size && known; dx++) {
				int32_t x = e.ox + dx, y = e.oy + dy;
				if ((x == 0 && y == 0) || in_g(sx, sy, n, sign, x, y))
					known = false;
				else if (!in_s(sx, sy, n, x, y) && !floor_at(ctx, x, y))
					known = false;
			}
		if (!known)
			v = APART_UNSEEN;
		else if (imp->level[cell] != 0)
			v = APART_LEFT;
	}
	return vacated > 0 ? v : APART_UNSEEN;
}

/* sure_floor(m, x, y): square (x, y) of the model is floor as far as the eye can
 * say: believed floor, seen in the fovea or in a 2 x 2 cell that read none
 * occupied (a gray level of 4 squares is their count, eye.h). */
static bool sure_floor(const WorldModel *m, int32_t x, int32_t y)
{
	Evidence e = worldmodel_evidence(m, x, y);
	return worldmodel_belief(m, x, y) == BELIEF_FLOOR &&
	       (e.res == WORLDMODEL_RES_FOVEA || (e.res == WORLDMODEL_RES_INTERMEDIATE && e.p <= 0.0f));
}

/* floor_before(ctx, ox, oy): at offset (ox, oy) from Utak's square, sure floor
 * before the turn (SwingRun.floor_before; the model after it has taken in the look
 * being judged). */
static bool floor_before(const void *ctx, int32_t ox, int32_t oy)
{
	const SwingRun *s = ctx;
	if (ox < -EYE_INTERMEDIATE_HALF || ox >= EYE_INTERMEDIATE_HALF || oy < -EYE_INTERMEDIATE_HALF ||
	    oy >= EYE_INTERMEDIATE_HALF)
		return false;
	return s->floor_before[(oy + EYE_INTERMEDIATE_HALF) * 16 + ox + EYE_INTERMEDIATE_HALF];
}

/* sweep_free(c, s, sign, ux, uy): every square S's squares pass over while turned
 * a quarter about the centre of Utak's square (points of each square's outline and
 * its centre, every SWING_SAMPLE_DEG degrees), grown by a ring (his point may be
 * anywhere in his square, and between samples a point moves under half a square at
 * SWING_REACH + 1), is S's, his own or sure floor, within the cells of 1 and 2 x 2. */
static bool sweep_free(const Controller *c, const SwingRun *s, int sign, int32_t ux, int32_t uy)
{
	static const double pt[9][2] = {{0, 0}, {0.5, 0}, {1, 0}, {0, 0.5}, {0.5, 0.5}, {1, 0.5}, {0, 1}, {0.5, 1}, {1, 1}};
	for (double deg = 0; deg <= 90 + 1e-9; deg += SWING_SAMPLE_DEG) {
		double a = sign * deg * swing_pi / 180, ca = cos(a), sa = sin(a);
		for (int32_t i = 0; i < s->n; i++)
			for (int p = 0; p < 9; p++) {
				/* about the centre (0.5, 0.5) of his square, offsets' frame */
				double px = s->sx[i] + pt[p][0] - 0.5, py = s->sy[i] + pt[p][1] - 0.5;
				double qx = ca * px - sa * py + 0.5, qy = sa * px + ca * py + 0.5;
				int32_t bx = (int32_t)floor(qx), by = (int32_t)floor(qy);
				for (int32_t dy = -1; dy <= 1; dy++)
					for (int32_t dx = -1; dx <= 1; dx++) {
						int32_t x = bx + dx, y = by + dy;
						if (x < -EYE_INTERMEDIATE_HALF || x >= EYE_INTERMEDIATE_HALF ||
						    y < -EYE_INTERMEDIATE_HALF || y >= EYE_INTERMEDIATE_HALF)
							return false;
						if ((x == 0 && y == 0) || in_s(s->sx, s->sy, s->n, x, y))
							continue;
						if (!sure_floor(&c->model, ux + x, uy + y))
							return false;
					}
			}
	}
	return true;
}

/* turnable(c, k, ux, uy, s): from model square (ux, uy), node k's squares (into
 * s->sx, s->sy as offsets) lie within SWING_REACH, and one way of turning (into
 * s->sign, counter-clockwise first) sweeps free (sweep_free). */
static bool turnable(const Controller *c, int32_t k, int32_t ux, int32_t uy, SwingRun *s)
{
	int32_t xs[SWING_MAX_SQUARES], ys[SWING_MAX_SQUARES];
	s->n = worldmodel_node_squares(&c->model, k, xs, ys, SWING_MAX_SQUARES);
	if (s->n > SWING_MAX_SQUARES || s->n != c->model.node[k].squares)
		return false;
	for (int32_t i = 0; i < s->n; i++) {
		if (abs(xs[i] - ux) > SWING_REACH || abs(ys[i] - uy) > SWING_REACH)
			return false;
		s->sx[i] = (int8_t)(xs[i] - ux);
		s->sy[i] = (int8_t)(ys[i] - uy);
	}
	for (int sign = 1; sign >= -1; sign -= 2)
		if (sweep_free(c, s, sign, ux, uy)) {
			s->sign = sign;
			return true;
		}
	return false;
}

bool swing_goal(const Controller *c, int32_t k, const int32_t *dist, Vec2 *goal)
{
	const Screen *sc = &c->screen;
	const WorldModel *m = &c->model;
	if (k < 0 || m->node[k].kind != NODE_OBJECT || m->node[k].squares > SWING_MAX_SQUARES)
		return false;
	SwingRun *trial = malloc(sizeof *trial);
	int32_t best = -1, best_d = INT32_MAX;
	for (int32_t at = 0; at < sc->w * sc->h; at++) {
		if (dist[at] < 0 || dist[at] >= best_d)
			continue;
		int32_t x = sc->x0 + at % sc->w, y = sc->y0 + at / sc->w;
		if (!sure_floor(m, x, y))
			continue;
		/* Touch there shows this object, and no other (the grasp takes the
		 * first object colour it feels): its squares among the eight, no
		 * other object's; wall reads B, which the grasp passes over. */
		bool beside = false, other = false;
		for (int32_t dy = -1; dy <= 1; dy++)
			for (int32_t dx = -1; dx <= 1; dx++) {
				int32_t n = worldmodel_node_at(m, x + dx, y + dy);
				if ((dx || dy) && n == k)
					beside = true;
				else if ((dx || dy) && n >= 0 && m->node[n].kind == NODE_OBJECT)
					other = true;
			}
		if (beside && !other && turnable(c, k, x, y, trial)) {
			best = at;
			best_d = dist[at];
		}
	}
	free(trial);
	if (best < 0)
		return false;
	*goal = goals_centre(sc->x0 + best % sc->w, sc->y0 + best / sc->w);
	return true;
}

bool swing_begin(Controller *c, int32_t k)
{
	SwingRun *s = &c->swing;
	const WorldModel *m = &c->model;
	if (s->stage != SWING_IDLE || k < 0 || m->node[k].kind != NODE_OBJECT || m->node[k].squares > SWING_MAX_SQUARES)
		return false;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	/* The grasp takes the first object colour touch shows: it must be this one's. */
	if (!objects_touched_only(c, k) || !turnable(c, k, ux, uy, s))
		return false;
	for (int32_t oy = -EYE_INTERMEDIATE_HALF; oy < EYE_INTERMEDIATE_HALF; oy++)
		for (int32_t ox = -EYE_INTERMEDIATE_HALF; ox < EYE_INTERMEDIATE_HALF; ox++)
			s->floor_before[(oy + EYE_INTERMEDIATE_HALF) * 16 + ox + EYE_INTERMEDIATE_HALF] =
			    sure_floor(m, ux + ox, uy + oy);
	s->ident = m->node[k].ident;
	s->at = objects_node_centre(c, k);
	s->squares = m->node[k].squares;
	s->verdict = APART_UNTRIED;
	s->stage = SWING_GRASP;
	return true;
}

bool swing_decide(Controller *c, MotorCommand *cmd)
{
	SwingRun *s = &c->swing;
	switch (s->stage) {
	case SWING_IDLE:
		return false;
	case SWING_GRASP:
		*cmd = (MotorCommand){.kind = MOTOR_GRASP};
		s->stage = SWING_TURN;
		return true;
	case SWING_TURN:
		if (!c->model.holding) {
			s->verdict = APART_UNSEEN; /* nothing held: nothing to turn */
			*cmd = (MotorCommand){.kind = MOTOR_RELEASE};
			s->stage = SWING_IDLE;
			return true;
		}
		*cmd = (MotorCommand){.kind = MOTOR_TURN, .deg = 90.0 * s->sign};
		s->stage = SWING_BACK;
		return true;
	case SWING_BACK:
		if (s->verdict != APART_ONE) {
			/* A piece stayed, or the turn halted (against a piece, most likely:
			 * the sweep was free): how far it went he cannot tell, and a turn
			 * back by a quarter would swing what he holds past where it was. */
			*cmd = (MotorCommand){.kind = MOTOR_RELEASE};
			s->stage = SWING_IDLE;
			return true;
		}
		*cmd = (MotorCommand){.kind = MOTOR_TURN, .deg = -90.0 * s->sign};
		s->stage = SWING_RELEASE;
		return true;
	case SWING_RELEASE:
		*cmd = (MotorCommand){.kind = MOTOR_RELEASE};
		s->stage = SWING_IDLE;
		if (s->verdict == APART_ONE && s->kept < SWING_KEPT) {
			s->one_ident[s->kept] = s->ident;
			s->one_at[s->kept] = s->at;
			s->one_squares[s->kept++] = s->squares;
		}
		return true;
	}
	return false;
}

void swing_perceive(Controller *c, const MotorCommand *cmd)
{
	SwingRun *s = &c->swing;
	if (cmd->kind != MOTOR_TURN || s->stage != SWING_BACK)
		return; /* only the look after the quarter turn is judged */
	s->verdict = swing_vacated_clear(s->sx, s->sy, s->n, s->sign, &c->impression, floor_before, s);
}

bool swing_one(const Controller *c, int32_t j)
{
	const SwingRun *s = &c->swing;
	if (j < 0)
		return false;
	const ModelNode *n = &c->model.node[j];
	for (int i = 0; i < s->kept; i++)
		if (objects_same(s->one_ident[i], s->one_at[i], n->ident, objects_node_centre(c, j)) &&
		    s->one_squares[i] == n->squares)
			return true;
	return false;
}

const char *swing_verdict_text(ApartVerdict v)
{
	switch (v) {
	case APART_ONE:
		return "it came round whole, leaving floor where it was: one object, the doubt is gone";
	case APART_LEFT:
		return "where it was, the eye sees it occupied still: a piece stayed, or the turn halted: the doubt stands";
	case APART_UNSEEN:
		return "where it was was not seen closely enough after the turn (or nothing was held): the doubt stands";
	default:
		return "not turned";
	}
}
