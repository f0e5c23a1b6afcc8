/* pushseen.c - what the eye and touch establish of a pushed object's place before
 * Utak claims it in a corner (paper 3.4.1 the gray levels, 3.5 the disparity of
 * predicted and actual impressions, 3.4.2 touch, 2.3 task (v)). CONTROLLER SIDE:
 * the impression, touch and the world model only. See pushseen.h.
 *
 * WHY: the held object's squares are offsets from Utak's square, carried by his own
 * motion and put down where the impression fits them best (heldobject.c). Under
 * noisy motion (--noise, paper 3.5) that fit is not exact: the object rides with
 * his point, it may be turned (a slanted square fills a corner square only in
 * part), and the squares nearest the corner lie 4 to 6 squares from him, in the
 * eye's 2 x 2 cells. Utak claimed squares pushed 2 short of the corner (slack 1)
 * on the strength of a held square in a cell whose level said only 2 or 3 of its 4
 * squares were occupied (adversarial worlds with a pier near the corner, --noise
 * 0.05: tests/worlds/push-pier-noise.w seed 2 and 4 more of 600 runs), and once with 4 held
 * squares in a cell showing 1. The claim now rests only on held squares the last
 * impression leaves no room to be floor.
 *
 * And what touch established (pushseen_felt_object, paper 3.4.2: an occupied set
 * joined to the verge is ambiguous, and only touch's colour tells an object
 * leaning on the wall from the wall): no object felt beyond the held one toward
 * the corner. */
#include "utak/mind/pushseen.h"

#include <stdlib.h>

#include "utak/base/eye.h"
#include "utak/base/util.h"
#include "utak/mind/goals.h"

bool pushseen_counts(int level, int32_t n, int32_t *kmin, int32_t *kmax)
{
	int32_t lo = -1, hi = -1;
	for (int32_t k = 0; k <= n; k++)
		if (eye_level(k, n) == level) {
			lo = lo < 0 ? k : lo;
			hi = k;
		}
	if (lo < 0)
		return false;
	*kmin = lo;
	*kmax = hi;
	return true;
}

bool pushseen_forced(int level, int32_t n)
{
	int32_t kmin, kmax;
	return pushseen_counts(level, n, &kmin, &kmax) && kmin == n;
}

bool pushseen_check(const Controller *c, int64_t short_by, Vec2 *at)
{
	const WorldModel *m = &c->model;
	if (!m->holding || m->held_count == 0 || short_by == INT64_MAX)
		return false;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	/* The best corner score of the held squares the impression establishes,
	 * against the best floor seen in the start's room (got + short_by) or, when
	 * the held set reaches beyond it, the held set's own best (got): those of
	 * its squares the eye has not shown may be floor (pushseen.h). */
	int64_t got = goals_subject_score(c), best = got + (short_by > 0 ? short_by : 0), est = INT64_MIN;
	for (int32_t k = 0; k < m->held_count; k++) {
		int32_t dx = m->held_dx[k], dy = m->held_dy[k], i = eye_cell_at(dx, dy);
		int64_t v = goals_corner_score(c->task.corner, ux + dx, uy + dy);
		if (v == got)
			*at = goals_centre(ux + dx, uy + dy);
		if (i < 0)
			continue;
		EyeCell e = eye_cell(i);
		if (v > est && pushseen_forced(c->impression.level[i], e.size * e.size))
			est = v;
	}
	return est == INT64_MIN || best - est > CONTROLLER_CORNER_SLACK;
}

bool pushseen_beyond(Corner k, const int32_t *hx, const int32_t *hy, int32_t nh, int32_t x,
                     int32_t y)
{
	if (nh <= 0)
		return false;
	int64_t v = goals_corner_score(k, x, y);
	for (int32_t i = 0; i < nh; i++)
		if (goals_corner_score(k, hx[i], hy[i]) >= v)
			return false;
	return true;
}

/* held_here(m, ux, uy, x, y): square (x, y) is one of the held object's. */
static bool held_here(const WorldModel *m, int32_t ux, int32_t uy, int32_t x, int32_t y)
{
	for (int32_t k = 0; k < m->held_count; k++)
		if (ux + m->held_dx[k] == x && uy + m->held_dy[k] == y)
			return true;
	return false;
}

bool pushseen_felt_object(const Controller *c, Vec2 *at)
{
	const WorldModel *m = &c->model;
	if (!m->holding || m->held_count == 0)
		return false;
	int32_t ux, uy, n = m->held_count;
	worldmodel_utak_square(m, &ux, &uy);
	int32_t *hx = util_alloc((size_t)n, sizeof *hx), *hy = util_alloc((size_t)n, sizeof *hy);
	for (int32_t k = 0; k < n; k++) {
		hx[k] = ux + m->held_dx[k];
		hy[k] = uy + m->held_dy[k];
	}
	bool found = false;
	int64_t best = INT64_MIN;
	for (int f = 0; f < c->felt_squares; f++) {
		int32_t x = c->felt_x[f], y = c->felt_y[f];
		int64_t v = goals_corner_score(c->task.corner, x, y);
		/* Still occupied to the model (the squares a pushed object was felt on
		 * before it moved are floor or held now), and nearer the corner than
		 * the whole held object. */
		if (v <= best || worldmodel_belief(m, x, y) != BELIEF_OCCUPIED ||
		    held_here(m, ux, uy, x, y) || !pushseen_beyond(c->task.corner, hx, hy, n, x, y))
			continue;
		/* Of the start's room: beside the held object (which held_room_split
		 * has placed in it), or beside floor of that room. */
		static const int nb[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
		Vec2 p[4];
		int32_t np = 0;
		bool room = false;
		for (int i = 0; i < 4 && !room; i++) {
			int32_t qx = x + nb[i][0], qy = y + nb[i][1];
			room = held_here(m, ux, uy, qx, qy);
			if (worldmodel_belief(m, qx, qy) == BELIEF_FLOOR)
				p[np++] = goals_centre(qx, qy);
		}
		if (room || goals_in_start_room(c, p, np)) {
			found = true;
			best = v;
			*at = goals_centre(x, y);
		}
	}
	free(hx);
	free(hy);
	return found;
}
