/* rival.c - settling a doubt about another object by going to it: a closer look, and
 * shape by motion (issue 13 item 6; paper 3.3). CONTROLLER SIDE. The meaning, when
 * and how are in rival.h; the probe itself is probe.c's, unchanged. */
#include "utak/mind/rival.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/eye.h"
#include "utak/base/util.h"
#include "utak/mind/apart.h"
#include "utak/mind/controller.h"
#include "utak/mind/fovealook.h"
#include "utak/mind/goals.h"
#include "utak/mind/objects.h"
#include "utak/mind/probe.h"
#include "utak/mind/round.h"
#include "utak/mind/tug.h"

/* rival_node(c): the rival's node now, by ident or, renumbered, by place; -1 when
 * the model holds it no longer. */
static int32_t rival_node(const Controller *c)
{
	const WorldModel *m = &c->model;
	int32_t near = -1;
	double best = OBJECTS_SAME;
	for (int32_t k = 0; k < m->node_count; k++) {
		if (m->node[k].kind != NODE_OBJECT)
			continue;
		if ((int32_t)m->node[k].ident == c->rival.ident)
			return k;
		double d = goals_distance(objects_node_centre(c, k), c->rival.at);
		if (d < best) {
			best = d;
			near = k;
		}
	}
	return near;
}

/* ring_unseen(c, j, &x, &y): a square 8-adjacent to one of node j's, not its own and
 * not seen in the fovea, the nearest Utak: the probe is made only where every such
 * square is floor the fovea has seen (probe.h, WHEN), and a rival looked at from
 * one side may have its far corners' neighbours seen only coarsely. */
static bool ring_unseen(const Controller *c, int32_t j, int32_t *x, int32_t *y)
{
	const WorldModel *m = &c->model;
	const Box *r = &m->node[j].rect;
	double best = -1;
	for (int32_t sy = (int32_t)floor(r->lo.y) - 1; sy <= (int32_t)ceil(r->hi.y); sy++)
		for (int32_t sx = (int32_t)floor(r->lo.x) - 1; sx <= (int32_t)ceil(r->hi.x); sx++) {
			if (worldmodel_node_at(m, sx, sy) == j ||
			    worldmodel_evidence(m, sx, sy).res == WORLDMODEL_RES_FOVEA)
				continue;
			bool ring = false;
			for (int32_t dy = -1; dy <= 1 && !ring; dy++)
				for (int32_t dx = -1; dx <= 1 && !ring; dx++)
					ring = worldmodel_node_at(m, sx + dx, sy + dy) == j;
			double d = goals_distance(goals_centre(sx, sy), m->utak);
			if (ring && (best < 0 || d < best)) {
				best = d;
				*x = sx;
				*y = sy;
			}
		}
	return best >= 0;
}

/* own_may_probe(c, k): object node k, gone round, is one a probe could be made of
 * from beside it (probe.h, WHEN), as far as the model can tell from afar: seen
 * whole, of few enough squares, and no square 8-adjacent to it believed occupied
 * (a wall or another object there: no probe, so no trip); ring squares seen only
 * coarsely are looked at on the way (rival_way). */
static bool own_may_probe(Controller *c, int32_t k)
{
	const WorldModel *m = &c->model;
	ObjectReading o = objects_read(c, k);
	if (!o.confirmed || o.squares > PROBE_MAX_SQUARES)
		return false;
	const Box *r = &m->node[k].rect;
	for (int32_t sy = (int32_t)floor(r->lo.y) - 1; sy <= (int32_t)ceil(r->hi.y); sy++)
		for (int32_t sx = (int32_t)floor(r->lo.x) - 1; sx <= (int32_t)ceil(r->hi.x); sx++) {
			if (worldmodel_node_at(m, sx, sy) == k ||
			    worldmodel_belief(m, sx, sy) != BELIEF_OCCUPIED)
				continue;
			for (int32_t dy = -1; dy <= 1; dy++)
				for (int32_t dx = -1; dx <= 1; dx++)
					if (worldmodel_node_at(m, sx + dx, sy + dy) == k)
						return false;
		}
	return true;
}

/* Lacking: the rival whose squares still to be seen a place's fovea counts. */
typedef struct Lacking {
	const Controller *c;
	int32_t j;
} Lacking;

/* lacking(ctx, px, py): how many squares of node j, or of the floor round it, not
 * yet seen in the fovea (objects_lacks) Utak's fovea holds from square (px, py). */
static int32_t lacking(void *ctx, int32_t px, int32_t py)
{
	const Lacking *l = ctx;
	int32_t n = 0;
	for (int32_t oy = -EYE_FOVEA_HALF; oy < EYE_FOVEA_HALF; oy++)
		for (int32_t ox = -EYE_FOVEA_HALF; ox < EYE_FOVEA_HALF; ox++)
			n += objects_lacks(l->c, l->j, px + ox, py + oy);
	return n;
}

/* look_at(c, j, x, y, dist, goal): where to look at square (x, y) of rival node j
 * or of the floor round it: where the fovea holds it (fovealook.h), else the place
 * nearest it (goals_near, as before: a square the fovea can be taken to from
 * nowhere reachable may yet be seen whole from near it by the deep rule,
 * objects_seen_exactly). */
static bool look_at(const Controller *c, int32_t j, int32_t x, int32_t y, const int32_t *dist, Vec2 *goal)
{
	Lacking l = {c, j};
	return fovealook_place(&c->screen, dist, x, y, lacking, &l, goal) ||
	       goals_near(c, goals_centre(x, y), dist, goal);
}

/* spent(r): the arrivals going to the rival that count against RIVAL_ARRIVALS. */
static int spent(const RivalRun *r)
{
	return r->arrivals - r->gained;
}

/* rival_way(c, j, dist, goal): where to go next for rival node j: where the fovea
 * shows the square of it, or of the floor round it, the fovea has not seen
 * nearest Utak (look_at), or, all seen, beside it (where touch reaches it). */
static bool rival_way(Controller *c, int32_t j, const int32_t *dist, Vec2 *goal)
{
	int32_t x, y;
	if (objects_unconfirmed_square(c, j, &x, &y) &&
	    look_at(c, j, x, y, dist, goal))
		return true;
	if (spent(&c->rival) < RIVAL_ARRIVALS - 1 && ring_unseen(c, j, &x, &y) &&
	    look_at(c, j, x, y, dist, goal) &&
	    goals_distance(*goal, c->model.utak) > CONTROLLER_ARRIVED)
		return true;
	/* MERGED: only where a pull can be made (apart.h): no look or touch beside
	 * it settles anything (tests/worlds/near-merged.w: 6 cycles to and fro). */
	if (objects_merged_rival(c, j))
		return apart_goal(c, j, dist, goal);
	return goals_beside(c, j, dist, goal);
}

/* rival_end(c, what): the rival settled or left (what says which, for the trace);
 * back to the claim. */
static void rival_end(Controller *c, const char *what)
{
	RivalRun *r = &c->rival;
	bool own = r->stage == RIVAL_OWN_GO;
	size_t n = strlen(r->note);
	snprintf(r->note + n, sizeof r->note - n, "; %s at (%.1f, %.1f): %s",
	         own ? "the object gone round" : "rival", r->at.x, r->at.y, what);
	r->stage = RIVAL_IDLE;
	c->have_plan = false;
	if (own) {
		/* No probe of the object gone round: no other trip to it would fare
		 * better. The rival as rival8 settles it without (rival_begin), or home. */
		r->own_trips = RIVAL_MAX;
		if (rival_begin(c, objects_find_target(c)))
			return;
	}
	if (r->home_after) /* "go round": the loop is walked; home, and judged there again */
		round_home(c, objects_find_target(c));
	else
		r->returning = true; /* back where he would have claimed (rival_goal) */
}

/* rival_lost(c): the rival gone to is no longer in the model (its squares joined to
 * another node's, or renumbered beyond OBJECTS_SAME of where it was): the trip
 * ends, but the rival is not marked settled, nor the trip counted against
 * RIVAL_MAX (at most RIVAL_MAX such trips a task, r->lost), so that where the
 * model holds it again it may be gone to again. WHY: a look on the
 * way may part and join nodes for a while; marked tried, the rival seen again in
 * the same place was left and the doubt stood on it unvisited (random g148, once
 * the look went where the fovea holds it, fovealook.h). */
static void rival_lost(Controller *c)
{
	RivalRun *r = &c->rival;
	if (r->stage == RIVAL_GO && r->count > 0 && r->lost < RIVAL_MAX) {
		r->lost++;
		r->count--; /* its slot free again: at most RIVAL_MAX such, a task */
	}
	rival_end(c, "no longer in the model");
}

/* rival_set_off(c, j, stage): going to object node j begun (stage RIVAL_GO, a
 * rival; RIVAL_OWN_GO, the object gone round), only when the way there is known
 * (on this cycle's screen and space); false, nothing begun, when it is not. */
static bool rival_set_off(Controller *c, int32_t j, RivalStage stage)
{
	RivalRun *r = &c->rival;
	const Grid *g = &c->space;
	if (g->w == 0 || c->screen.w != g->w || c->screen.h != g->h)
		return false;
	int32_t ui, uj;
	if (!goals_cell_of(&c->screen, c->model.utak, &ui, &uj))
		return false;
	int32_t *dist = util_alloc((size_t)g->w * (size_t)g->h, sizeof *dist);
	goals_reach(g, ui, uj, dist);
	Vec2 goal;
	int arrivals = r->arrivals, gained = r->gained;
	r->arrivals = r->gained = 0; /* rival_way's looks at the ring count from the start */
	bool way = rival_way(c, j, dist, &goal);
	r->arrivals = arrivals;
	r->gained = gained;
	free(dist);
	if (!way)
		return false;
	r->ident = (int32_t)c->model.node[j].ident;
	r->at = objects_node_centre(c, j);
	r->arrivals = r->gained = 0;
	r->foveal = objects_read(c, j).foveal;
	r->home_after = c->task.kind == TASK_GO_ROUND;
	r->back = c->model.utak;
	r->returning = false;
	r->stage = stage;
	r->merged = false; /* (begin sets it for a MERGED rival) */
	c->have_plan = false;
	return true;
}

bool rival_own_probed(const Controller *c, int32_t k)
{
	const RivalRun *r = &c->rival;
	if (k < 0)
		return false;
	Vec2 at = objects_node_centre(c, k);
	for (int i = 0; i < r->own_count; i++)
		if (objects_same(r->own_ident[i], r->own_at[i], (int32_t)c->model.node[k].ident, at))
			return true;
	return false;
}

/* own_doubt_told(c): the task's verdict line tells Utak's doubt of the object he
 * claims ("go square", "go round square", "push square CORNER"): only there is a
 * probe made for a doubt on the object's own squares (NARROW, PIECES SHOWN); the
 * carrying tasks push it on as before. */
static bool own_doubt_told(const Controller *c)
{
	return c->task.kind == TASK_GO_SHAPE || c->task.kind == TASK_GO_ROUND || c->task.kind == TASK_PUSH_CORNER;
}

/* begin(c, k, own_trip): rival_begin; with own_trip, Utak is where the loop round
 * node k closed, and may go back beside it to probe it first (a short way: from
 * home the way back and out again would cost a loop's approach twice). */
static bool begin(Controller *c, int32_t k, bool own_trip)
{
	RivalRun *r = &c->rival;
	if (k < 0 || r->stage != RIVAL_IDLE)
		return false;
	int32_t j = objects_rival(c, k);
	bool rival = j >= 0 && objects_rival_open(c, j);
	/* NARROW: its own squares may be a polygon's under 2 wide; a probe tells
	 * more (probe.h): no square, or wide enough. MERGED (objects.h): an object
	 * nearer may hold a square merged with its neighbour, which a pull of it
	 * settles (apart.h, below), and a probe that shows this one no square drops the claim on it, and the
	 * task goes on to the next object of the shape (random g123, g208: without
	 * it "go square" gave up on a piece it had dropped before). Not before a
	 * push: the probe's error of motion moved the square, and the push planned
	 * again from there was blocked 13 short (perturbed slant-p3, achieved
	 * before); the doubt stands on the square pushed. */
	bool merged = c->task.kind != TASK_PUSH_CORNER && objects_merged(c, k);
	if (!rival && !(own_doubt_told(c) && (objects_narrow(c, k) || objects_pieces_shown(c, k) || merged)))
		return false;
	/* OWN FIRST: beside the object he would claim, that one first, whatever the
	 * rival (going round, only from where the loop closed: own_trip). Going
	 * round, a rival never seen whole is not looked at first either: a look
	 * that shows it reading a square leaves the doubt, for the object gone
	 * round was not probed (random g134, in a version that looked first: the
	 * piece gone round was never disproved; probed first, it is, and the
	 * square beside it is gone round instead). */
	bool merged_rival = rival && objects_merged_rival(c, j);
	bool own = (c->task.kind != TASK_GO_ROUND || own_trip) && !(merged_rival && c->task.kind == TASK_PUSH_CORNER);
	if (own && !rival_own_probed(c, k) && r->own_count < PROBE_RUNS && objects_touching(c, k) &&
	    probe_begin_object(c, k)) {
		r->own_ident[r->own_count] = (int32_t)c->model.node[k].ident;
		r->own_at[r->own_count++] = objects_node_centre(c, k);
		r->stage = RIVAL_OWN;
		r->own_alone = !rival;
		c->have_plan = false;
		return true;
	}
	/* OWN FIRST ON A LOOP: "go round square" walks round the object without
	 * touching it, so he goes back beside it to probe it first (where a probe
	 * may be made, and the way is known), then to the rival, then home. */
	if (own && own_trip && !rival_own_probed(c, k) && r->own_count < PROBE_RUNS &&
	    r->own_trips < RIVAL_MAX && own_may_probe(c, k) && rival_set_off(c, k, RIVAL_OWN_GO)) {
		r->own_trips++;
		r->own_alone = !rival;
		size_t n = strlen(r->note);
		snprintf(r->note + n, sizeof r->note - n,
		         "; back to the %s gone round, at (%.1f, %.1f), to probe it %s "
		         "(rival.h)",
		         task_shape_name(c->task.shape), r->at.x, r->at.y,
		         rival ? "before a rival" : "for a doubt on its own squares");
		return true;
	}
	if (!rival || r->count >= RIVAL_MAX)
		return false;
	/* A rival seen whole that still reads a square (or a crumb that may be one)
	 * shows that this world holds pieces the eye takes for squares: then the
	 * one he would claim may be such a piece too, and a rival disproved would
	 * leave the claim on that alone. So he probes a rival only once the object
	 * claimed has been probed and may be a square (OWN FIRST); else the doubt
	 * stands as it is. */
	if (objects_read(c, j).examined && !rival_own_probed(c, k) && !merged_rival)
		return false;
	/* MERGED going round: pulled from where the loop closed, never from home
	 * (NOT FROM HOME above: the way there and back, under noise, leaves him
	 * believing himself home where he is not; worlds/square-behind.w, noise
	 * seed 6, a version that went: 3.17 off, a false success). */
	if (merged_rival && c->task.kind == TASK_GO_ROUND && c->round_count > 0 && c->round_next >= c->round_count)
		return false;
	Vec2 at = objects_node_centre(c, j);
	for (int i = 0; i < r->count; i++)
		if (objects_same(r->tried_ident[i], r->tried_at[i], (int32_t)c->model.node[j].ident, at))
			return false; /* settled once already: what it left stands */
	if (!rival_set_off(c, j, RIVAL_GO))
		return false;
	r->merged = merged_rival;
	r->tried_ident[r->count] = r->ident;
	r->tried_at[r->count++] = at;
	size_t n = strlen(r->note);
	snprintf(r->note + n, sizeof r->note - n,
	         "; rival at (%.1f, %.1f): going to settle it (rival.h)", at.x, at.y);
	c->have_plan = false;
	return true;
}

bool rival_begin(Controller *c, int32_t k)
{
	return begin(c, k, false);
}

bool rival_goal(Controller *c, const int32_t *dist, GoalResult *out)
{
	int32_t i, j0;
	if (c->rival.returning) {
		/* Back to where he set off from beside the object he would claim, while
		 * it can be reached; arriving there, the claim is judged again. */
		if (c->space.w == c->screen.w && c->space.h == c->screen.h &&
		    goals_cell_of(&c->screen, c->rival.back, &i, &j0) &&
		    dist[j0 * c->screen.w + i] >= 0) {
			out->goal = c->rival.back;
			out->found = out->exploring = true;
			return true;
		}
		c->rival.returning = false;
	}
	if (c->rival.stage != RIVAL_GO && c->rival.stage != RIVAL_OWN_GO)
		return false;
	int32_t j = rival_node(c);
	if (j < 0) {
		rival_lost(c);
		return c->rival.stage == RIVAL_GO && rival_goal(c, dist, out);
	}
	if (!rival_way(c, j, dist, &out->goal)) {
		rival_end(c, "no way to it: the doubt stands");
		return c->rival.stage == RIVAL_GO && rival_goal(c, dist, out);
	}
	/* A goal where he stands, and where he arrived on the way already: the eye
	 * and touch have shown from here all they will (else the arrivals would
	 * follow one another without a command between). */
	if (c->rival.arrivals > 0 && goals_distance(out->goal, c->model.utak) <= CONTROLLER_ARRIVED &&
	    goals_distance(c->rival.arrived_at, c->model.utak) <= CONTROLLER_ARRIVED) {
		rival_end(c, "nothing more to see or touch from here: the doubt stands");
		/* (after the object gone round, a rival may be gone to: its first goal) */
		return c->rival.stage == RIVAL_GO && rival_goal(c, dist, out);
	}
	out->found = out->exploring = true;
	return true;
}

bool rival_arrive(Controller *c)
{
	RivalRun *r = &c->rival;
	if (r->returning) {
		/* Back: the task's own arrival judges the claim again. */
		r->returning = false;
		c->exploring = false;
		return false;
	}
	if (r->stage != RIVAL_GO && r->stage != RIVAL_OWN_GO)
		return false;
	c->have_plan = false;
	r->arrivals++;
	r->arrived_at = c->model.utak;
	int32_t j = rival_node(c);
	if (j < 0) {
		rival_lost(c);
		return true;
	}
	if (r->stage == RIVAL_OWN_GO) {
		/* Back beside the object gone round: probed now if it can be (OWN
		 * FIRST ON A LOOP), else on to the next goal, or given up. */
		if (j != objects_find_target(c))
			rival_end(c, "no longer the task's object");
		else if (objects_touching(c, j) && probe_begin_object(c, j)) {
			r->own_ident[r->own_count] = (int32_t)c->model.node[j].ident;
			r->own_at[r->own_count++] = objects_node_centre(c, j);
			r->stage = RIVAL_OWN;
		} else if (r->arrivals >= RIVAL_ARRIVALS)
			rival_end(c, "no probe can be made safely from where Utak can stand");
		return true;
	}
	/* A look that showed more of it than any before is not counted (RIVAL_GAINS). */
	int32_t foveal = objects_read(c, j).foveal;
	if (foveal > r->foveal && r->gained < RIVAL_GAINS)
		r->gained++;
	r->foveal = foveal > r->foveal ? foveal : r->foveal;
	if (j == objects_find_target(c)) {
		rival_end(c, "seen closer, it is the task's object now");
		return true;
	}
	if (objects_merged_rival(c, j) || r->merged) {
		/* MERGED: pulled, if it can be from here (apart.h); never probed (a
		 * probe disproves a pair as one square, and the doubt would go:
		 * near13b's k10, push, a false success in a version that probed). */
		if (objects_merged_rival(c, j) && apart_begin(c, j)) {
			r->stage = RIVAL_APART;
			size_t n = strlen(r->note);
			snprintf(r->note + n, sizeof r->note - n,
			         "; rival at (%.1f, %.1f): to pull it %d straight back twice and look (apart.h)", r->at.x,
			         r->at.y, TUG_STEP);
		} else if (spent(r) >= RIVAL_ARRIVALS || !objects_merged_rival(c, j))
			rival_end(c, "no pull can be made from where Utak can stand: the doubt stands");
		return true;
	}
	if (!objects_rival_open(c, j)) {
		rival_end(c, "seen whole in the fovea, no square: the doubt is gone");
		return true;
	}
	ObjectReading q = objects_read(c, j);
	if (q.examined && !rival_own_probed(c, objects_find_target(c))) {
		rival_end(c, "seen whole, it may be a square, and the object claimed was not "
		             "probed: the doubt stands");
		return true;
	}
	if (q.confirmed && objects_touching(c, j)) {
		/* Not from here: from beside it elsewhere, maybe (rival_goal: goals_beside,
		 * and where that is here, nothing more is to be had). A look taken
		 * where the fovea holds it (fovealook.h) may leave him touching it
		 * where no probe can be made: tests/worlds/rival-piece.w, going
		 * round, probed from the side goals_beside chooses. */
		if (probe_begin_object(c, j))
			r->stage = RIVAL_PROBE;
		else if (spent(r) >= RIVAL_ARRIVALS)
			rival_end(c, "no probe can be made safely here: the doubt stands");
		return true;
	}
	if (spent(r) >= RIVAL_ARRIVALS)
		rival_end(c, "not seen whole from where Utak can stand: the doubt stands");
	return true;
}

/* halfstep_again(c): the rival's probe just ended, pushes of a quarter square
 * showed no change at all (its edges lie a quarter to three quarters into their
 * squares, probe.h PROBE_HALF_STEP): a second probe of it begun with pushes of
 * half a square, which carry every edge across a square's edge; false when none
 * was (a change was seen, it was the second, or none can be made here). */
static bool halfstep_again(Controller *c)
{
	const ProbeRun *p = &c->probe;
	if (p->changed || p->step >= PROBE_HALF_STEP)
		return false;
	int32_t j = rival_node(c);
	if (j < 0 || !objects_touching(c, j) || !probe_begin_step(c, j, PROBE_HALF_STEP))
		return false;
	size_t n = strlen(c->rival.note);
	snprintf(c->rival.note + n, sizeof c->rival.note - n,
	         "; rival at (%.1f, %.1f): the quarter-square pushes showed no change, "
	         "probed again by half a square (rival.h)", c->rival.at.x, c->rival.at.y);
	return true;
}

bool rival_probing(const Controller *c)
{
	return c->rival.stage == RIVAL_PROBE || c->rival.stage == RIVAL_OWN || c->rival.stage == RIVAL_APART;
}

bool rival_decide(Controller *c, MotorCommand *cmd)
{
	if (c->rival.stage == RIVAL_APART) {
		if (apart_decide(c, cmd))
			return true;
		c->have_plan = false;
		ApartVerdict v = c->apart.verdict;
		if (apart_redo(c)) { /* noise spoilt the look: to a place to pull it again (apart.h) */
			size_t n = strlen(c->rival.note);
			snprintf(c->rival.note + n, sizeof c->rival.note - n,
			         "; rival at (%.1f, %.1f): %s; under noise, to pull it again", c->rival.at.x,
			         c->rival.at.y, apart_verdict_text(v));
			c->rival.stage = RIVAL_GO;
			c->rival.arrivals = c->rival.gained = 0;
			return false;
		}
		rival_end(c, apart_verdict_text(v));
		return false;
	}
	if (!rival_probing(c) || c->probe.stage != PROBE_FINISH)
		return probe_decide(c, cmd);
	if (c->rival.stage == RIVAL_OWN) {
		/* The object he would claim, probed first: disproved, it is dropped
		 * (probe_decide: the task goes on without it); else the claim waits
		 * on the rival (arrive asks again). Not claimed here either way. */
		ProbeVerdict verdict = probe_end(c);
		if (verdict == PROBE_INCONSISTENT)
			c->target = 0; /* not the square: the task goes on without it */
		c->have_plan = false;
		c->rival.stage = RIVAL_IDLE;
		if (verdict == PROBE_INCONSISTENT)
			c->rival.own_count--; /* no claim on it is left to spare a probe of */
		size_t n = strlen(c->rival.note);
		snprintf(c->rival.note + n, sizeof c->rival.note - n,
		         c->rival.own_alone ? "; probed, for a doubt on its own squares: %s" : "; probed first, before a rival: %s",
		         verdict == PROBE_INCONSISTENT ? "it is no square, dropped"
		         : c->probe.width_only         ? "its width measured"
		                                       : "it may be a square");
		if (c->task.kind == TASK_GO_ROUND) {
			/* The loop was walked round it. No square: the loop counts for
			 * nothing, and the task goes on (a loop round the next one of
			 * the shape). May be one: on to the rival, or home. */
			int32_t k = objects_find_target(c);
			if (verdict == PROBE_INCONSISTENT) {
				c->round_count = 0;
				c->round_looked = c->round_looking = false;
			} else if (!rival_begin(c, k))
				round_home(c, k);
		}
		return false;
	}
	/* The object probed is the rival: what the probe records (a disproved
	 * object) is kept, and the task's object and phase are left as they are. */
	ProbeVerdict verdict = probe_end(c);
	if (verdict != PROBE_INCONSISTENT && halfstep_again(c))
		return false; /* HALF A SQUARE: a second probe begun */
	if (verdict == PROBE_INCONSISTENT)
		c->have_plan = false;
	rival_end(c, verdict == PROBE_INCONSISTENT
	                 ? "probed, its squares fit no square: it is no square, the doubt is gone"
	                 : "probed, its squares may be a square's: the doubt stands");
	return false;
}

bool rival_perceive(Controller *c, const MotorCommand *cmd, char *note, size_t size)
{
	if (c->rival.stage == RIVAL_APART) {
		static const char *const what[] = {"moved", "grasped", "pulled", "pushed", "turned", "released"};
		int i = cmd->kind == MOTOR_GRASP ? 1 : cmd->kind == MOTOR_RELEASE ? 5 : cmd->kind == MOTOR_PUSH ? 2 : 0;
		snprintf(note, size, "; apart: %s the rival at (%.1f, %.1f)%s", what[i], c->rival.at.x, c->rival.at.y,
		         cmd->kind == MOTOR_PUSH && c->apart.stage == APART_BACK ? " back" : "");
		return true;
	}
	if (!probe_perceive(c, cmd, note, size))
		return false;
	if (c->rival.stage == RIVAL_OWN && cmd->kind == MOTOR_RELEASE) {
		snprintf(note, size, "; probe: released the object he would claim; its squares %s",
		         c->probe.verdict == PROBE_INCONSISTENT ? "fit no square: it is not the square"
		         : c->probe.width_only                  ? "were measured: the claim is judged again"
		         : c->rival.own_alone                   ? "may be a square's: the claim is judged again"
		                                                : "may be a square's: the claim waits on the rival");
		probe_width_note(&c->probe, note, size);
		return true;
	}
	if (c->rival.stage != RIVAL_PROBE)
		return true; /* the object he would claim: probe.c's own notes */
	if (cmd->kind == MOTOR_GRASP)
		snprintf(note, size,
		         "; probe: grasped the rival at (%.1f, %.1f), to push it %d way%s by a "
		         "%s square and back (rival.h)",
		         c->rival.at.x, c->rival.at.y, c->probe.corners,
		         c->probe.corners > 1 ? "s" : "", c->probe.step >= PROBE_HALF_STEP ? "half" : "quarter");
	else if (cmd->kind == MOTOR_RELEASE) {
		snprintf(note, size, "; probe: released the rival; its squares %s",
		         c->probe.verdict == PROBE_INCONSISTENT ? "fit no square"
		                                                : "may be a square's");
		probe_width_note(&c->probe, note, size);
	}
	return true;
}

bool rival_loop_closed(Controller *c)
{
	int32_t k = objects_find_target(c);
	char why[160];
	return c->task.kind == TASK_GO_ROUND && k >= 0 && objects_read(c, k).confirmed &&
	       fabs(round_believed_turns(c, k)) > CONTROLLER_ROUND_TURNS &&
	       objects_doubt(c, k, why, sizeof why) && begin(c, k, true);
}
