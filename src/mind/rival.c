/* rival.c - settling a doubt about another object by going to it: a closer look, and
 * shape by motion (issue 13 item 6; paper 3.3). CONTROLLER SIDE. The meaning, when
 * and how are in rival.h; the probe itself is probe.c's, unchanged. */
#include "utak/mind/rival.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/controller.h"
#include "utak/mind/goals.h"
#include "utak/mind/objects.h"
#include "utak/mind/probe.h"
#include "utak/mind/round.h"

/* node_centre(c, k): the centre of node k's rectangle, model frame: where an object
 * is remembered (a renumbered node is found again by it, within OBJECTS_SAME). */
static Vec2 node_centre(const Controller *c, int32_t k)
{
	const Box *r = &c->model.node[k].rect;
	return vec2((r->lo.x + r->hi.x) / 2, (r->lo.y + r->hi.y) / 2);
}

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
		double d = goals_distance(node_centre(c, k), c->rival.at);
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

/* rival_way(c, j, dist, goal): where to go next for rival node j: near the square of
 * it, or of the floor round it, the fovea has not seen nearest Utak, or, all seen,
 * beside it (where touch reaches it). */
static bool rival_way(const Controller *c, int32_t j, const int32_t *dist, Vec2 *goal)
{
	int32_t x, y;
	if (objects_unconfirmed_square(c, j, &x, &y) &&
	    goals_near(c, goals_centre(x, y), dist, goal))
		return true;
	if (c->rival.arrivals < RIVAL_ARRIVALS - 1 && ring_unseen(c, j, &x, &y) &&
	    goals_near(c, goals_centre(x, y), dist, goal) &&
	    goals_distance(*goal, c->model.utak) > CONTROLLER_ARRIVED)
		return true;
	return goals_beside(c, j, dist, goal);
}

/* rival_end(c, what): the rival settled or left (what says which, for the trace);
 * back to the claim. */
static void rival_end(Controller *c, const char *what)
{
	RivalRun *r = &c->rival;
	size_t n = strlen(r->note);
	snprintf(r->note + n, sizeof r->note - n, "; rival at (%.1f, %.1f): %s", r->at.x, r->at.y,
	         what);
	r->stage = RIVAL_IDLE;
	c->have_plan = false;
	if (r->home_after) /* "go round": the loop is walked; home, and judged there again */
		round_home(c, objects_find_target(c));
	else
		r->returning = true; /* back where he would have claimed (rival_goal) */
}

bool rival_own_probed(const Controller *c, int32_t k)
{
	const RivalRun *r = &c->rival;
	if (k < 0)
		return false;
	Vec2 at = node_centre(c, k);
	for (int i = 0; i < r->own_count; i++)
		if (r->own_ident[i] == (int32_t)c->model.node[k].ident ||
		    goals_distance(r->own_at[i], at) < OBJECTS_SAME)
			return true;
	return false;
}

bool rival_begin(Controller *c, int32_t k)
{
	RivalRun *r = &c->rival;
	if (k < 0 || r->stage != RIVAL_IDLE)
		return false;
	int32_t j = objects_rival(c, k);
	if (j < 0 || !objects_rival_open(c, j))
		return false;
	/* OWN FIRST: beside the object he would claim, that one first. */
	if (!rival_own_probed(c, k) && r->own_count < PROBE_RUNS && objects_touching(c, k) &&
	    probe_begin_object(c, k)) {
		r->own_ident[r->own_count] = (int32_t)c->model.node[k].ident;
		r->own_at[r->own_count++] = node_centre(c, k);
		r->stage = RIVAL_OWN;
		c->have_plan = false;
		return true;
	}
	if (r->count >= RIVAL_MAX)
		return false;
	/* A rival seen whole that still reads a square (or a crumb that may be one)
	 * shows that this world holds pieces the eye takes for squares: then the
	 * one he would claim may be such a piece too, and a rival disproved would
	 * leave the claim on that alone. So he probes a rival only once the object
	 * claimed has been probed and may be a square (OWN FIRST); else the doubt
	 * stands as it is. */
	if (objects_read(c, j).examined && !rival_own_probed(c, k))
		return false;
	Vec2 at = node_centre(c, j);
	for (int i = 0; i < r->count; i++)
		if (r->tried_ident[i] == (int32_t)c->model.node[j].ident ||
		    goals_distance(r->tried_at[i], at) < OBJECTS_SAME)
			return false; /* settled once already: what it left stands */
	/* Only when the way there is known (on this cycle's screen and space). */
	const Grid *g = &c->space;
	if (g->w == 0 || c->screen.w != g->w || c->screen.h != g->h)
		return false;
	int32_t ui, uj;
	if (!goals_cell_of(&c->screen, c->model.utak, &ui, &uj))
		return false;
	int32_t *dist = util_alloc((size_t)g->w * (size_t)g->h, sizeof *dist);
	goals_reach(g, ui, uj, dist);
	Vec2 goal;
	bool way = rival_way(c, j, dist, &goal);
	free(dist);
	if (!way)
		return false;
	r->ident = (int32_t)c->model.node[j].ident;
	r->at = at;
	r->tried_ident[r->count] = r->ident;
	r->tried_at[r->count++] = at;
	r->arrivals = 0;
	r->home_after = c->task.kind == TASK_GO_ROUND;
	r->back = c->model.utak;
	r->returning = false;
	r->stage = RIVAL_GO;
	size_t n = strlen(r->note);
	snprintf(r->note + n, sizeof r->note - n,
	         "; rival at (%.1f, %.1f): going to settle it (rival.h)", at.x, at.y);
	c->have_plan = false;
	return true;
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
	if (c->rival.stage != RIVAL_GO)
		return false;
	int32_t j = rival_node(c);
	if (j < 0) {
		rival_end(c, "no longer in the model");
		return false;
	}
	if (!rival_way(c, j, dist, &out->goal)) {
		rival_end(c, "no way to it: the doubt stands");
		return false;
	}
	/* A goal where he stands, and where he arrived on the way already: the eye
	 * and touch have shown from here all they will (else the arrivals would
	 * follow one another without a command between). */
	if (c->rival.arrivals > 0 && goals_distance(out->goal, c->model.utak) <= CONTROLLER_ARRIVED &&
	    goals_distance(c->rival.arrived_at, c->model.utak) <= CONTROLLER_ARRIVED) {
		rival_end(c, "nothing more to see or touch from here: the doubt stands");
		return false;
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
	if (r->stage != RIVAL_GO)
		return false;
	c->have_plan = false;
	r->arrivals++;
	r->arrived_at = c->model.utak;
	int32_t j = rival_node(c);
	if (j < 0) {
		rival_end(c, "no longer in the model");
		return true;
	}
	if (j == objects_find_target(c)) {
		rival_end(c, "seen closer, it is the task's object now");
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
		if (probe_begin_object(c, j))
			r->stage = RIVAL_PROBE;
		else
			rival_end(c, "no probe can be made safely here: the doubt stands");
		return true;
	}
	if (r->arrivals >= RIVAL_ARRIVALS)
		rival_end(c, "not seen whole from where Utak can stand: the doubt stands");
	return true;
}

bool rival_probing(const Controller *c)
{
	return c->rival.stage == RIVAL_PROBE || c->rival.stage == RIVAL_OWN;
}

bool rival_decide(Controller *c, MotorCommand *cmd)
{
	if (!rival_probing(c) || c->probe.stage != PROBE_FINISH)
		return probe_decide(c, cmd);
	if (c->rival.stage == RIVAL_OWN) {
		/* The object he would claim, probed first: disproved, it is dropped
		 * (probe_decide: the task goes on without it); else the claim waits
		 * on the rival (arrive asks again). Not claimed here either way. */
		ControllerPhase phase = c->phase;
		ProbeVerdict verdict = c->probe.verdict;
		probe_decide(c, cmd);
		c->phase = phase;
		c->have_plan = false;
		c->rival.stage = RIVAL_IDLE;
		if (verdict == PROBE_INCONSISTENT)
			c->rival.own_count--; /* no claim on it is left to spare a probe of */
		size_t n = strlen(c->rival.note);
		snprintf(c->rival.note + n, sizeof c->rival.note - n,
		         "; probed first, before a rival: %s",
		         verdict == PROBE_INCONSISTENT ? "it is no square, dropped"
		                                       : "it may be a square");
		return false;
	}
	/* The probe's end (probe_decide) claims the task's object or drops it; here
	 * the object probed is the rival: what it records (a disproved object) is
	 * kept, and the task's object and phase are left as they were. */
	int32_t target = c->target;
	Vec2 target_at = c->target_at;
	ControllerPhase phase = c->phase;
	ProbeVerdict verdict = c->probe.verdict;
	probe_decide(c, cmd);
	c->target = target;
	c->target_at = target_at;
	c->phase = phase;
	rival_end(c, verdict == PROBE_INCONSISTENT
	                 ? "probed, its squares fit no square: it is no square, the doubt is gone"
	                 : "probed, its squares may be a square's: the doubt stands");
	return false;
}

bool rival_perceive(Controller *c, const MotorCommand *cmd, char *note, size_t size)
{
	if (!probe_perceive(c, cmd, note, size))
		return false;
	if (c->rival.stage == RIVAL_OWN && cmd->kind == MOTOR_RELEASE) {
		snprintf(note, size, "; probe: released the object he would claim; its squares %s",
		         c->probe.verdict == PROBE_INCONSISTENT
		             ? "fit no square: it is not the square"
		             : "may be a square's: the claim waits on the rival");
		return true;
	}
	if (c->rival.stage != RIVAL_PROBE)
		return true; /* the object he would claim: probe.c's own notes */
	if (cmd->kind == MOTOR_GRASP)
		snprintf(note, size,
		         "; probe: grasped the rival at (%.1f, %.1f), to push it %d way%s by a "
		         "quarter square and back (rival.h)",
		         c->rival.at.x, c->rival.at.y, c->probe.corners,
		         c->probe.corners > 1 ? "s" : "");
	else if (cmd->kind == MOTOR_RELEASE)
		snprintf(note, size, "; probe: released the rival; its squares %s",
		         c->probe.verdict == PROBE_INCONSISTENT ? "fit no square"
		                                                : "may be a square's");
	return true;
}
