/* pushseen.c - what the eye establishes of a pushed object's place before Utak
 * claims it in a corner (paper 3.4.1 the gray levels, 3.5 the disparity of
 * predicted and actual impressions, 2.3 task (v)). CONTROLLER SIDE: the impression
 * and the world model only. See pushseen.h.
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
 * impression leaves no room to be floor. */
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
