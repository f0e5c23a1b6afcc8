/* heldobject.c - the object Utak holds, in his world model (paper 2.2: grasp, push
 * and turn move only the held object; paper 3.5: predicting the impression after a
 * push or turn). CONTROLLER SIDE, as worldmodel.c: impressions and commands only.
 *
 * The held object is a set of squares kept as offsets from Utak's square: found by
 * touch at the grasp (wm_find_held: the first object colour touch feels, and the
 * model's occupied squares flooded from it), kept to what the eye shows (wm_prune_held,
 * wm_refind_held, wm_regrow_held), put down after each push where the impression
 * fits it best (wm_register_held), and moved by a turn about Utak's point
 * (wm_vacate, wm_carry). worldmodel_accommodate (worldmodel.c) calls these; a push
 * itself is carried by its disparity search, with the set riding beside every
 * candidate (wm_score_holding). Split from worldmodel.c, which it shares
 * worldmodel_work.h with. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/eye.h"
#include "utak/base/geom.h"
#include "utak/base/util.h"
#include "worldmodel_work.h"

/* wm_find_held(m, imp): the squares of the object Utak touches (the first object
 * colour in imp's touch order), as offsets from his square; held_count stays 0
 * when the model cannot say which squares those are. */
void wm_find_held(WorldModel *m, const Impression *imp)
{
	m->held_count = 0;
	int k = 0;
	while (k < TOUCH_CELLS && (imp->touch[k] == '.' || imp->touch[k] == 'B'))
		k++;
	if (k == TOUCH_CELLS)
		return;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	int32_t seed_x = ux + wm_touch_offset[k][0], seed_y = uy + wm_touch_offset[k][1];
	if (worldmodel_belief(m, seed_x, seed_y) != BELIEF_OCCUPIED)
		return;
	/* A set joined to the verge or the unseen (not an object node of the last
	 * derivation) may be wall as well as object: the model cannot say which of
	 * its squares come along (tug.h draws such an object free). */
	int32_t node = worldmodel_node_at(m, seed_x, seed_y);
	if (node < 0 || m->node[node].kind != NODE_OBJECT)
		return;
	/* Flood fill, 4-connected, over occupied squares; the held offsets double as
	 * the stack and the visited list. */
	int32_t n = 0, next = 0;
	m->held_dx[n] = seed_x - ux;
	m->held_dy[n] = seed_y - uy;
	n++;
	while (next < n) {
		int32_t x = ux + m->held_dx[next], y = uy + m->held_dy[next];
		next++;
		static const int8_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
		for (int d = 0; d < 4; d++) {
			int32_t nx = x + step[d][0], ny = y + step[d][1];
			if (worldmodel_belief(m, nx, ny) != BELIEF_OCCUPIED)
				continue;
			bool seen = false;
			for (int32_t j = 0; j < n && !seen; j++)
				seen = m->held_dx[j] == nx - ux && m->held_dy[j] == ny - uy;
			if (seen)
				continue;
			if (n == WORLDMODEL_HELD_MAX) {
				m->held_count = 0; /* too big to be one object: part of the verge */
				return;
			}
			m->held_dx[n] = nx - ux;
			m->held_dy[n] = ny - uy;
			n++;
		}
	}
	m->held_count = n;
}

/* wm_prune_held(m): after a push, the held squares the eye now sees as floor: they
 * did not come along. A grasp takes one object (paper 2.2), and the model's held
 * set, found by flooding occupied squares, can take in another that touches it. */
void wm_prune_held(WorldModel *m)
{
	int32_t ux, uy, n = 0;
	worldmodel_utak_square(m, &ux, &uy);
	for (int32_t j = 0; j < m->held_count; j++)
		if (worldmodel_belief(m, ux + m->held_dx[j], uy + m->held_dy[j]) == BELIEF_OCCUPIED) {
			m->held_dx[n] = m->held_dx[j];
			m->held_dy[n++] = m->held_dy[j];
		}
	m->held_count = n;
}

/* wm_refind_held(m, imp): after a turn, the held set found again from what the eye
 * now shows: wm_carry turned the squares' centres, which for a turn other than a
 * quarter turn only guesses which squares the object now covers. The guess stays
 * when the flood finds nothing (or too much: the object against a wall). */
void wm_refind_held(WorldModel *m, const Impression *imp)
{
	int32_t keep_dx[WORLDMODEL_HELD_MAX], keep_dy[WORLDMODEL_HELD_MAX]; /* 8 KB */
	int32_t keep = m->held_count;
	memcpy(keep_dx, m->held_dx, (size_t)keep * sizeof *keep_dx);
	memcpy(keep_dy, m->held_dy, (size_t)keep * sizeof *keep_dy);
	wm_find_held(m, imp);
	if (m->held_count == 0 || m->held_count > 2 * keep + 8) {
		m->held_count = keep;
		memcpy(m->held_dx, keep_dx, (size_t)keep * sizeof *keep_dx);
		memcpy(m->held_dy, keep_dy, (size_t)keep * sizeof *keep_dy);
	}
}

/* wm_box_held(m): the held set's box becomes the one it may regrow in. */
void wm_box_held(WorldModel *m)
{
	m->held_x0 = m->held_y0 = INT32_MAX;
	m->held_x1 = m->held_y1 = INT32_MIN;
	for (int32_t j = 0; j < m->held_count; j++) {
		m->held_x0 = m->held_dx[j] < m->held_x0 ? m->held_dx[j] : m->held_x0;
		m->held_y0 = m->held_dy[j] < m->held_y0 ? m->held_dy[j] : m->held_y0;
		m->held_x1 = m->held_dx[j] > m->held_x1 ? m->held_dx[j] : m->held_x1;
		m->held_y1 = m->held_dy[j] > m->held_y1 ? m->held_dy[j] : m->held_y1;
	}
}

/* The squares round the held set a push may add to it: its box (wm_box_held) and
 * one square beyond, as offsets from Utak's square, row-major. */
static int64_t wm_grow_area(const WorldModel *m, int32_t *w)
{
	*w = m->held_x1 - m->held_x0 + 3;
	return (int64_t)*w * (m->held_y1 - m->held_y0 + 3);
}

/* wm_floor_round_held(m): for each square of wm_grow_area, whether the model
 * believes it floor now (caller frees); NULL when Utak holds nothing. */
bool *wm_floor_round_held(const WorldModel *m)
{
	if (m->held_count == 0 || m->held_x0 > m->held_x1) /* no box: nothing to regrow */
		return NULL;
	int32_t w, ux, uy;
	int64_t n = wm_grow_area(m, &w);
	worldmodel_utak_square(m, &ux, &uy);
	bool *floor = util_alloc((size_t)n, sizeof *floor);
	for (int64_t k = 0; k < n; k++)
		floor[k] = worldmodel_belief(m, ux + m->held_x0 - 1 + (int32_t)(k % w),
		                             uy + m->held_y0 - 1 + (int32_t)(k / w)) == BELIEF_FLOOR;
	return floor;
}

/* wm_regrow_held(m, was_floor): after a push, the squares joined to the held set,
 * within its box and one square beyond, that the eye now sees occupied where the
 * model believed floor before this impression (was_floor: wm_floor_round_held
 * with the held set put down) join it, when the eye leaves no doubt (p definite:
 * a coarse cell over the object's edge smears it onto its neighbours).
 * WHY: pushed a fraction of a square off the grid (noisy motion, paper 3.5), an
 * object w squares wide covers w + 1 columns of the TABLE; the eye sees it there,
 * but a held set that only ever shrank (wm_prune_held) would leave those squares
 * behind at the next push, and the disparity search would then find the model
 * matched best where Utak had not moved (with --noise 0.05, most pushes into a
 * corner failed so). Only squares known as floor before may join: a wall the
 * object is pushed against was occupied, or not yet seen, and stays the wall's. */
void wm_regrow_held(WorldModel *m, const bool *was_floor)
{
	if (m->held_count == 0 || !was_floor)
		return;
	int32_t w, ux, uy;
	wm_grow_area(m, &w);
	worldmodel_utak_square(m, &ux, &uy);
	for (int32_t next = 0; next < m->held_count; next++) {
		static const int8_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
		for (int d = 0; d < 4; d++) {
			int32_t dx = m->held_dx[next] + step[d][0], dy = m->held_dy[next] + step[d][1];
			if ((dx == 0 && dy == 0) || dx < m->held_x0 - 1 || dx > m->held_x1 + 1 ||
			    dy < m->held_y0 - 1 || dy > m->held_y1 + 1 ||
			    !was_floor[(int64_t)(dy - m->held_y0 + 1) * w + (dx - m->held_x0 + 1)] ||
			    worldmodel_evidence(m, ux + dx, uy + dy).p < 1 - WM_DEFINITE)
				continue;
			bool seen = false;
			for (int32_t j = 0; j < m->held_count && !seen; j++)
				seen = m->held_dx[j] == dx && m->held_dy[j] == dy;
			if (seen || m->held_count == WORLDMODEL_HELD_MAX)
				continue;
			m->held_dx[m->held_count] = dx;
			m->held_dy[m->held_count++] = dy;
		}
	}
}

/* held_on(m, x, y, least): how many held squares, Utak on square (x, y), lie on
 * squares the model, the object lifted (wm_vacate), believes occupied by something
 * else (seen, p >= 0.5) with a confidence of at least `least`. */
static int32_t held_on(const WorldModel *m, int32_t x, int32_t y, float least)
{
	int32_t n = 0;
	for (int32_t j = 0; j < m->held_count; j++) {
		Evidence e = worldmodel_evidence(m, x + m->held_dx[j], y + m->held_dy[j]);
		n += e.res != WORLDMODEL_UNSEEN && e.p >= 0.5f && e.conf >= least;
	}
	return n;
}

/* wm_held_on_solid(m, x, y): held_on's squares the model surely believes occupied
 * (conf >= WM_BLOCKED_CONF). */
int32_t wm_held_on_solid(const WorldModel *m, int32_t x, int32_t y)
{
	return held_on(m, x, y, WM_BLOCKED_CONF);
}

/* wm_held_on_occupied(m, x, y): held_on's squares the model believes occupied at
 * all, however unsure. */
int32_t wm_held_on_occupied(const WorldModel *m, int32_t x, int32_t y)
{
	return held_on(m, x, y, 0);
}

/* wm_register_held(m, x, y, held, under, imp): after a push, Utak found on square
 * (x, y): the held set shifted by the square (-1, 0 or 1 on each axis) that makes
 * the impression fit best, when that fits better than the set unshifted by
 * WORLDMODEL_DISPARITY_MARGIN: the disparity of paper 3.5, here of the object's
 * place beside Utak. WHY: the held offsets are from Utak's square, but the object
 * rides with his point, which lies anywhere in that square: a push that halts a
 * fraction of a square on (pressed against a wall) or goes astray (noisy motion)
 * can carry his point over a square's edge while the object's squares stay, or the
 * other way round. Unshifted, the set then takes in a row of the wall the object
 * is pressed against (and the object reads a square nearer the corner than it is:
 * a false success), or a row of floor beyond it that a coarse cell half on the
 * object cannot clear (paper 3.4.2). The box the set may regrow in shifts with it.
 * A shift that would put more held squares than the unshifted set does on squares
 * the model, the object lifted, surely believes occupied (the verge, a wall,
 * another object) is not tried: two things do not share a square. (Not "any":
 * under noisy motion the set may hold a column of the wall already, or miss one
 * of the object's squares, which the model then still has occupied, and a shift
 * along that wall must stay open.) WHY: an object pushed a fraction of a square off
 * the grid covers a row more than it does pressed flush against a wall; after the
 * push that presses it home (halted at once), its trailing row is floor and the
 * set's extra row fits the impression as well inside the wall, occupied either
 * way; shifted into the wall, the set read a square nearer the corner than the
 * object is (in a corner it cannot fill, a bay too small for it or one cut off
 * diagonally, a false success). Left in place, its trailing row, seen floor, is pruned
 * (wm_prune_held).
 * COMPLEXITY: 9 predictions of the impression, O(held squares + 160) each. */
void wm_register_held(WorldModel *m, int32_t x, int32_t y, const Evidence *held, Evidence *under,
                      const Impression *imp)
{
	int32_t compared;
	double best = wm_score_holding(m, x, y, held, under, imp, &compared);
	int32_t bx = 0, by = 0, solid = wm_held_on_solid(m, x, y);
	for (int32_t sy = -1; sy <= 1; sy++)
		for (int32_t sx = -1; sx <= 1; sx++) {
			if ((sx == 0 && sy == 0) || wm_held_on_solid(m, x + sx, y + sy) > solid)
				continue;
			for (int32_t j = 0; j < m->held_count; j++) {
				m->held_dx[j] += sx;
				m->held_dy[j] += sy;
			}
			double v = wm_score_holding(m, x, y, held, under, imp, &compared);
			for (int32_t j = 0; j < m->held_count; j++) {
				m->held_dx[j] -= sx;
				m->held_dy[j] -= sy;
			}
			if (compared >= WORLDMODEL_MIN_COMPARED && v + WORLDMODEL_DISPARITY_MARGIN < best) {
				best = v;
				bx = sx;
				by = sy;
			}
		}
	for (int32_t j = 0; j < m->held_count; j++) {
		m->held_dx[j] += bx;
		m->held_dy[j] += by;
	}
	m->held_x0 += bx;
	m->held_x1 += bx;
	m->held_y0 += by;
	m->held_y1 += by;
}

/* wm_vacate(m, from, saved): the held object's squares, Utak on `from`, leave their
 * places (predicted floor); their evidence goes to saved. */
void wm_vacate(WorldModel *m, Vec2 from, Evidence *saved)
{
	int32_t fx = (int32_t)floor(from.x), fy = (int32_t)floor(from.y);
	for (int32_t j = 0; j < m->held_count; j++) {
		Evidence *e = wm_at(m, fx + m->held_dx[j], fy + m->held_dy[j]);
		saved[j] = e ? *e : (Evidence){1, 0, WORLDMODEL_RES_PERIPHERAL, 1, 0};
		if (e) {
			e->p = 0;
			e->conf = (float)(e->conf * WORLDMODEL_CONF_CONTRADICTED);
		}
	}
}

/* wm_carry(m, from, to, deg): the predicted model of a turn: the held object's
 * squares leave their places (predicted floor) and are put down where the turn
 * takes their centres, the object turning by deg about Utak's point. (A push is
 * carried by the disparity search itself: worldmodel_accommodate.) */
void wm_carry(WorldModel *m, Vec2 from, Vec2 to, double deg)
{
	Evidence saved[WORLDMODEL_HELD_MAX]; /* 12 KB */
	int32_t fx = (int32_t)floor(from.x), fy = (int32_t)floor(from.y);
	double c, s;
	geom_cos_sin(deg, &c, &s);
	wm_vacate(m, from, saved);
	int32_t tx = (int32_t)floor(to.x), ty = (int32_t)floor(to.y), n = 0;
	for (int32_t j = 0; j < m->held_count; j++) {
		Vec2 centre = vec2(fx + m->held_dx[j] + 0.5, fy + m->held_dy[j] + 0.5);
		Vec2 moved = vec2_add(geom_rotate(centre, from, c, s), vec2_sub(to, from));
		int32_t nx = (int32_t)floor(moved.x), ny = (int32_t)floor(moved.y);
		Evidence *e = nx == tx && ny == ty ? NULL : wm_at(m, nx, ny);
		if (e)
			*e = saved[j];
		/* The held set turns with it (two squares landing on one are one). */
		bool again = false;
		for (int32_t i = 0; i < n && !again; i++)
			again = m->held_dx[i] == nx - tx && m->held_dy[i] == ny - ty;
		if (!again) {
			m->held_dx[n] = nx - tx;
			m->held_dy[n++] = ny - ty;
		}
	}
	m->held_count = n;
}
