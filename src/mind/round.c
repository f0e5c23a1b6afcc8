/* round.c - going round an object and returning (paper 2.3 task (iv)). CONTROLLER SIDE.
 *
 * The loop is four points, one outside each corner of the object's believed rectangle,
 * visited in turn, then the start: each leg is planned on the screen like any other
 * goal (paper 4.3: the path runs on the skeleton of the space round the object), so
 * only the points need care. A point laid out on a wall or another object (the object
 * stands beside a wall, or in clutter), or seen to be so later, moves to the reachable
 * square nearest it on the same side of the object (round_goal): the loop still winds
 * round the object wherever there is room to pass, whatever its shape.
 *
 * The loop's stops are a move apart and stand outside the rectangle's corners, so the
 * fovea (offsets -EYE_FOVEA_HALF..EYE_FOVEA_HALF-1 round Utak) can pass by parts of
 * an object that fill its rectangle unevenly (a square turned 45 degrees): the loop
 * winds round it, but it is not confirmed (objects.h), and walking the same loop
 * again would show nothing new. Then, as paper 3.3 has it, a hypothesis is confirmed
 * by seeing it closer: when the loop closes (or, failing that, home), Utak goes and
 * looks at the parts unseen (round_look), then home (round_home), and the loop
 * already walked is judged by its winding.
 *
 * Home under noisy motion (paper 3.5, uncertainty (2)): the disparity places Utak
 * against a model his own errors have shifted, and across open floor or along a
 * wall nothing places him at all. Near the start his first impression, taken where
 * he knew where he stood, corrects him (round_recognise_home); home, he claims the
 * task only when he may be no more than CONTROLLER_HOME_SD off on each axis
 * (round_home_doubt). Corrections that set him one way and back on the way (a
 * probe's quarter pushes, a leg past clutter) put his place in doubt until the look
 * home settles it: the model's disparity and the first impression, two
 * recognitions by features, agree on his believed square. The model's placing alone
 * does not make him home where the first impression, not placing him, fits what he
 * sees best a square or more off: the model near the start has drifted with him. */
#include "utak/mind/round.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "utak/base/eye.h"
#include "utak/mind/goals.h"
#include "utak/mind/objects.h"

/* round_lay_out(c, k): the points outside object node k's rectangle corners,
 * counter-clockwise from the one nearest Utak, then his starting point. */
void round_lay_out(Controller *c, int32_t k)
{
	const ModelNode *n = &c->model.node[k];
	double m = CONTROLLER_ROUND_MARGIN;
	Vec2 p[4] = {vec2(n->rect.lo.x - m, n->rect.lo.y - m), vec2(n->rect.hi.x + m, n->rect.lo.y - m),
		     vec2(n->rect.hi.x + m, n->rect.hi.y + m), vec2(n->rect.lo.x - m, n->rect.hi.y + m)};
	int first = 0;
	for (int i = 1; i < 4; i++)
		if (goals_distance(p[i], c->model.utak) < goals_distance(p[first], c->model.utak))
			first = i;
	for (int i = 0; i < 4; i++) {
		Vec2 q = p[(first + i) % 4];
		c->round[i] = goals_centre((int32_t)floor(q.x), (int32_t)floor(q.y));
	}
	/* Back to the first corner closes the loop round the object, then home. */
	c->round[4] = c->round[0];
	c->round[5] = c->start; /* "and return": to where the task began */
	c->round_count = 6;
	c->round_next = 0;
	c->round_ident = n->ident;
	c->round_rect = n->rect;
}

/* round_believed_turns(c, k): how many times the path Utak believes he took, closed back
 * to its start, winds round the centre of object node k: the judge's measure
 * (judge.c), taken on the world model. */
double round_believed_turns(const Controller *c, int32_t k)
{
	const Box *r = &c->model.node[k].rect;
	return geom_winding(c->trail.pts, c->trail.count, vec2((r->lo.x + r->hi.x) / 2, (r->lo.y + r->hi.y) / 2));
}

/* round_stale(c): the loop was laid out round what the model no longer believes is
 * the task's object, or round a rectangle that has since been seen to differ by more
 * than a square: a coarse first look can take a brick for a square. */
bool round_stale(Controller *c)
{
	if (c->task.kind != TASK_GO_ROUND || c->round_count == 0)
		return false;
	int32_t k = objects_find_target(c);
	if (k < 0 || c->model.node[k].ident != c->round_ident)
		return true;
	Box r = c->model.node[k].rect, o = c->round_rect;
	return fabs(r.lo.x - o.lo.x) > 1 || fabs(r.lo.y - o.lo.y) > 1 || fabs(r.hi.x - o.hi.x) > 1 ||
	       fabs(r.hi.y - o.hi.y) > 1;
}

/* round_goal(c, dist, goal): the goal of the loop's next leg on the current screen
 * (dist: steps from Utak's cell, goals_reach). A corner point whose square is
 * reachable stands. Else the reachable square nearest it (ties to the nearer by
 * steps) on the same side of the object: in the same quadrant about the centre of
 * the rectangle the loop was laid out round, and outside that rectangle by half a
 * square, so that the legs between the points still pass round the object. The
 * start, if walled off, gives way to the reachable square nearest it. False when a
 * corner's quadrant has no reachable square: there is no way round. */
bool round_goal(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	const Screen *s = &c->screen;
	Vec2 p = c->round[c->round_next];
	int32_t i, j;
	if (goals_cell_of(s, p, &i, &j) && dist[j * s->w + i] >= 0) {
		*goal = p;
		return true;
	}
	if (c->round_next == c->round_count - 1)
		return goals_near(c, p, dist, goal);
	const Box *r = &c->round_rect;
	Vec2 m = vec2((r->lo.x + r->hi.x) / 2, (r->lo.y + r->hi.y) / 2);
	double sx = p.x < m.x ? -1 : 1, sy = p.y < m.y ? -1 : 1, best = INFINITY;
	for (int32_t at = 0; at < s->w * s->h; at++) {
		if (dist[at] < 0)
			continue;
		Vec2 q = goals_centre(s->x0 + at % s->w, s->y0 + at / s->w);
		bool quadrant = sx * (q.x - m.x) > 0 && sy * (q.y - m.y) > 0;
		bool outside = q.x < r->lo.x - 0.5 || q.x > r->hi.x + 0.5 || q.y < r->lo.y - 0.5 || q.y > r->hi.y + 0.5;
		double d = goals_distance(q, p) + 1e-3 * dist[at];
		if (quadrant && outside && d < best) {
			best = d;
			*goal = q;
		}
	}
	return best < INFINITY;
}

/* foveal(ox, oy): the fovea shows the square at offset (ox, oy) from Utak's. */
static bool foveal(int32_t ox, int32_t oy)
{
	int32_t cell = eye_cell_at(ox, oy);
	return (ox != 0 || oy != 0) && cell >= 0 && eye_cell(cell).zone == EYE_FOVEA;
}

/* round_look(c, k, dist, goal): the squares object node k's confirmation lacks
 * (objects.c: its squares, and the 4-neighbours of its squares, not seen in the
 * fovea) and not yet looked at (not in the fovea's reach of a place Utak went to
 * look from, c->visited: a look there showed it, or cannot); the reachable cell
 * fewest steps away from which the fovea covers one of them, ties to the cell
 * covering more. The model's frame is Utak's own (his heading never changes,
 * worldmodel.h), so the fovea covers the squares at eye.h's foveal offsets from
 * his square, other than his own. Each look is remembered on arrival
 * (controller.c), so the looks end. */
bool round_look(const Controller *c, int32_t k, const int32_t *dist, Vec2 *goal)
{
	enum { MAX_LACK = 512 };
	const WorldModel *m = &c->model;
	const ModelNode *n = &m->node[k];
	const Screen *s = &c->screen;
	int32_t lx[MAX_LACK], ly[MAX_LACK];
	int lack = 0;
	for (int32_t j = (int32_t)floor(n->rect.lo.y) - 1; j <= (int32_t)ceil(n->rect.hi.y) && lack < MAX_LACK; j++)
		for (int32_t i = (int32_t)floor(n->rect.lo.x) - 1; i <= (int32_t)ceil(n->rect.hi.x) && lack < MAX_LACK; i++) {
			if (!objects_lacks(c, k, i, j))
				continue;
			bool looked = false;
			for (int v = 0; v < c->visited_count && !looked; v++)
				looked = foveal(i - (int32_t)floor(c->visited[v].x), j - (int32_t)floor(c->visited[v].y));
			if (!looked) {
				lx[lack] = i;
				ly[lack++] = j;
			}
		}
	int32_t best_steps = -1;
	int best_seen = 0;
	for (int32_t at = 0; at < s->w * s->h && lack > 0; at++) {
		if (dist[at] < 0 || (best_steps >= 0 && dist[at] > best_steps))
			continue;
		int32_t x = s->x0 + at % s->w, y = s->y0 + at / s->w;
		int seen = 0;
		for (int l = 0; l < lack; l++)
			seen += foveal(lx[l] - x, ly[l] - y);
		if (seen > 0 && (best_steps < 0 || dist[at] < best_steps || seen > best_seen)) {
			best_steps = dist[at];
			best_seen = seen;
			*goal = goals_centre(x, y);
		}
	}
	return best_steps >= 0;
}

/* round_home(c, k): the loop's last leg alone: back to the start. The rectangle is
 * node k's now, so that what the looks showed of it does not make the leg stale. */
void round_home(Controller *c, int32_t k)
{
	c->round_looking = false;
	c->round[0] = c->start;
	c->round_count = 1;
	c->round_next = 0;
	if (k >= 0) {
		c->round_ident = c->model.node[k].ident;
		c->round_rect = c->model.node[k].rect;
	}
}

/* round_unconfirmed(c): the task's object is known and not yet confirmed. */
bool round_unconfirmed(Controller *c)
{
	int32_t k = objects_find_target(c);
	return k >= 0 && !objects_read(c, k).confirmed;
}

/* round_home_leg(c): Utak is on the loop's leg home. */
static bool round_home_leg(const Controller *c)
{
	return c->task.kind == TASK_GO_ROUND && c->round_count > 0 && c->round_next == c->round_count - 1 &&
	       goals_distance(c->round[c->round_next], c->start) < CONTROLLER_ARRIVED;
}

/* round_recognise_home(c): paper 3.5's fallback, recognition by features. With a
 * noisy motion (uncertainty (2)) the disparity places Utak against a model his own
 * errors have shifted: across open floor, or along a wall, nothing corrects them,
 * and the belief drifts a square or two (the model with it). His first impression
 * was taken where he knew exactly where he stood: on the leg home, within
 * WORLDMODEL_DISPARITY_RADIUS of the start, the square where it best predicts what
 * he sees now is where he is (worldmodel_recognise_first), and the leg goes on from
 * there. In a world that does not move about him, exact motion leaves the belief
 * where it is. */
bool round_recognise_home(Controller *c)
{
	if (!round_home_leg(c) || c->round_homed >= CONTROLLER_HOME_FIXES)
		return false;
	int32_t x, y, sx = (int32_t)floor(c->start.x), sy = (int32_t)floor(c->start.y);
	worldmodel_utak_square(&c->model, &x, &y);
	if (abs(x - sx) > WORLDMODEL_DISPARITY_RADIUS || abs(y - sy) > WORLDMODEL_DISPARITY_RADIUS)
		return false;
	int32_t bx = x, by = y;
	bool placed[2];
	if (!worldmodel_recognise_first(&c->model, &c->impression, &bx, &by, placed) || (bx == x && by == y))
		return false;
	c->round_homed++;
	c->model.utak = vec2_add(c->model.utak, vec2(bx - x, by - y));
	return true;
}

/* Corrections this large (squares) along one axis that turn back ROUND_FIX_TURNS
 * times within the last CONTROLLER_FIXES impressions put the place along it in
 * doubt. */
#define ROUND_FIX_FLIP 0.5
#define ROUND_FIX_TURNS 2

bool round_home_doubt(const Controller *c, char *why, size_t size)
{
	double e = worldmodel_motion_error(&c->model);
	if (e <= 0)
		return false; /* motion has looked exact: the belief is as good as the model */
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	int32_t x = ux, y = uy;
	bool placed[2] = {false, false};
	bool judged = worldmodel_recognise_first(&c->model, &c->impression, &x, &y, placed);
	/* What he sees now, set against his first impression (taken where he knew
	 * where he stood): on an axis where it places him on his believed square, he
	 * is there (recognition by features, paper 3.5's fallback). Where it places him
	 * on another, it does not count: something it showed may have moved since (a
	 * square probed beside the start, worlds/square-behind.w under noise, seeds 2,
	 * 5 and 8: it placed him a square off on both axes, and he was home in each),
	 * and the moves since the model last placed him say how far off he may be. */
	bool home[2];
	for (int a = 0; a < 2; a++)
		home[a] = judged && placed[a] && (a ? y == uy : x == ux);
	double sd[2];
	for (int a = 0; a < 2; a++)
		sd[a] = home[a] ? 0 : e * sqrt(c->model.unplaced[a]);
	/* Corrected one way and back again, again and again, along an axis in the last
	 * moves: the impressions fit two places there, and whichever he stands at
	 * places him (worlds/west.w under noise, seed 1: each move home set him a
	 * square one way, the next a square the other, and he claimed home 2 squares
	 * off). Two such turns in a row, at least: he may be off by their spread,
	 * unless he has looked, home, and two recognitions agree on his square along
	 * that axis: the model's disparity on this impression placed him there
	 * (unplaced 0) and so does his first impression (home). Then the turns were
	 * earlier, and settled since (worlds/nearcorner.w, seed 2: a probe's quarter
	 * pushes, each set a square one way and the next back; home, both place him). */
	bool flip[2] = {false, false};
	for (int b = 0; b < 2; b++) {
		int turns = 0;
		double prev = 0, lo = 0, hi = 0;
		for (int i = 0; i < CONTROLLER_FIXES; i++) {
			Vec2 f = c->fix[(c->fix_next + i) % CONTROLLER_FIXES];
			double v = b ? f.y : f.x;
			if (fabs(v) < ROUND_FIX_FLIP)
				continue;
			turns += prev * v < 0;
			prev = v;
			lo = fmin(lo, v);
			hi = fmax(hi, v);
		}
		bool settled = home[b] && c->model.unplaced[b] == 0;
		if (turns >= ROUND_FIX_TURNS && hi - lo > sd[b] && !settled) {
			sd[b] = hi - lo;
			flip[b] = true;
		}
	}
	/* The model's disparity placed him (unplaced 0), but the model is his own: its
	 * squares seen since motion erred lie where his drifted belief put them, and a
	 * match against them can place him a square or two off as well as home (open
	 * floor, a long wall: a shift of a square predicts nearly the same impression).
	 * His first impression was taken where he knew where he stood: where it does
	 * not place him on an axis and yet fits what he sees better on another square
	 * along it, nothing that really places him says he is home there
	 * (worlds/hidden.w seed 12, worlds/square-roomy.w seed 25, worlds/west.w seeds
	 * 16 and 98 under noise: the model placed him home, the first impression
	 * best a square or two off, and he was 1.5 to 3.7 squares from the start). */
	for (int b = 0; b < 2; b++) {
		int32_t off = b ? y - uy : x - ux;
		if (judged && !placed[b] && off != 0 && !flip[b]) {
			snprintf(why, size,
				 "the model places him home, but his first impression fits what he sees best %d %s "
				 "and does not place him: nothing places him %s",
				 abs(off), b ? (off > 0 ? "ahead" : "behind") : (off > 0 ? "right" : "left"),
				 b ? "ahead or behind" : "left or right");
			return true;
		}
	}
	int a = sd[1] > sd[0];
	if (sd[a] <= CONTROLLER_HOME_SD)
		return false;
	if (flip[a])
		snprintf(why, size, "what he saw set him one way and back again %s in his last moves: he may be %.1f off",
			 a ? "ahead and behind" : "left and right", sd[a]);
	else
		snprintf(why, size,
			 "motion errs by about %.2f squares a square, and nothing seen since his last moves places him %s: "
			 "he may be %.1f off",
			 e, a ? "ahead or behind" : "left or right", sd[a]);
	return true;
}
