/* joined.c - the JOINED doubt on the object Utak would claim for a shape other than
 * the square, settled by a pull (paper 3.4.2, 2.2; issue 13 item 6). CONTROLLER
 * SIDE. The rule, and why it is sound, are in joined.h. */
#include "utak/mind/joined.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "utak/base/util.h"

#include "utak/mind/apart.h"
#include "utak/mind/controller.h"
#include "utak/mind/goals.h"
#include "utak/mind/objects.h"
#include "utak/mind/round.h"
#include "utak/mind/swing.h"

bool joined_open(Controller *c, int32_t k)
{
	if ((c->task.kind != TASK_GO_SHAPE && c->task.kind != TASK_GO_ROUND) || c->task.shape == SHAPE_SQUARE || k < 0 ||
	    c->model.node[k].kind != NODE_OBJECT)
		return false;
	ObjectReading o = objects_read(c, k);
	return o.confirmed && o.shape == c->task.shape && !apart_one(c, k) && !swing_one(c, k);
}

bool joined_tried(const Controller *c, int32_t k)
{
	const JoinedRun *j = &c->joined;
	if (k < 0)
		return false;
	Vec2 at = objects_node_centre(c, k);
	for (int i = 0; i < j->tried; i++)
		if (objects_same(j->tried_ident[i], j->tried_at[i], (int32_t)c->model.node[k].ident, at))
			return true;
	return false;
}

bool joined_begin(Controller *c, int32_t k)
{
	JoinedRun *j = &c->joined;
	if (j->pulling || j->swinging || j->going || j->tried >= JOINED_TRIED || !joined_open(c, k) ||
	    joined_tried(c, k))
		return false;
	j->tried_ident[j->tried] = (int32_t)c->model.node[k].ident;
	j->tried_at[j->tried++] = objects_node_centre(c, k);
	if (objects_touching(c, k) && apart_begin(c, k)) {
		j->pulling = true;
		c->have_plan = false;
		return true;
	}
	if (objects_touching(c, k) && swing_begin(c, k)) { /* no pull from here: a turn (swing.h) */
		j->swinging = true;
		c->have_plan = false;
		return true;
	}
	/* Not from here: to the nearest square a pull can be made from, if the way
	 * there is known (apart_goal), once. */
	const Grid *g = &c->space;
	int32_t ui, uj;
	if (g->w == 0 || c->screen.w != g->w || c->screen.h != g->h || !goals_cell_of(&c->screen, c->model.utak, &ui, &uj))
		return false;
	int32_t *dist = util_alloc((size_t)g->w * (size_t)g->h, sizeof *dist);
	goals_reach(g, ui, uj, dist);
	/* Where it can be turned first: a turn needs nothing fixed in view (swing.h),
	 * a pull does (apart.h); else where it can be pulled. */
	j->going = swing_goal(c, k, dist, &j->goal) || apart_goal(c, k, dist, &j->goal);
	free(dist);
	if (j->going) {
		j->ident = (int32_t)c->model.node[k].ident;
		c->have_plan = false;
	}
	return j->going;
}

bool joined_loop_closed(Controller *c)
{
	int32_t k = objects_find_target(c);
	return c->task.kind == TASK_GO_ROUND && k >= 0 && fabs(round_believed_turns(c, k)) > CONTROLLER_ROUND_TURNS &&
	       joined_begin(c, k);
}

bool joined_goal(Controller *c, GoalResult *out)
{
	if (!c->joined.going)
		return false;
	out->goal = c->joined.goal;
	out->found = out->exploring = true;
	return true;
}

bool joined_arrive(Controller *c)
{
	JoinedRun *j = &c->joined;
	if (!j->going)
		return false;
	j->going = false;
	c->have_plan = false;
	int32_t k = objects_find_target(c);
	bool here = k >= 0 && (int32_t)c->model.node[k].ident == j->ident && joined_open(c, k) && objects_touching(c, k);
	if (here && apart_begin(c, k))
		j->pulling = true;
	else if (here && swing_begin(c, k))
		j->swinging = true;
	else if (c->task.kind == TASK_GO_ROUND)
		round_home(c, k); /* no pull from here either: home, the doubt standing */
	return true; /* else beside it again, the claim is judged with the doubt standing */
}

bool joined_decide(Controller *c, MotorCommand *cmd)
{
	JoinedRun *j = &c->joined;
	if (j->swinging) {
		if (swing_decide(c, cmd))
			return true;
		j->swinging = false;
	} else if (j->pulling) {
		if (apart_decide(c, cmd))
			return true;
		j->pulling = false;
		/* Neither one object nor a piece left (the look could not place him, or
		 * was too coarse): a quarter turn, which does not move him (swing.h). */
		int32_t k = objects_find_target(c);
		if ((c->apart.verdict == APART_SHORT || c->apart.verdict == APART_UNSEEN) && joined_open(c, k) &&
		    objects_touching(c, k) && swing_begin(c, k) && swing_decide(c, cmd)) {
			j->swinging = true;
			return true;
		}
	} else
		return false;
	c->have_plan = false; /* beside it still: the claim is judged again (arrive) */
	if (c->task.kind == TASK_GO_ROUND)
		round_home(c, objects_find_target(c)); /* the loop walked: home, and judged there */
	return false;
}

bool joined_perceive(Controller *c, const MotorCommand *cmd, char *note, size_t size)
{
	if (c->joined.swinging) {
		swing_perceive(c, cmd);
		static const char *const did[] = {"moved", "grasped", "pushed", "turned", "released"};
		int i = cmd->kind == MOTOR_GRASP ? 1 : cmd->kind == MOTOR_RELEASE ? 4 : cmd->kind == MOTOR_TURN ? 3 : 0;
		bool back = cmd->kind == MOTOR_TURN && c->swing.stage == SWING_RELEASE;
		snprintf(note, size, "; joined: %s the %s he would claim%s, to see it come round whole (swing.h)%s%s",
			 did[i], task_shape_name(c->task.shape), back ? " back" : cmd->kind == MOTOR_TURN ? " a quarter" : "",
			 cmd->kind == MOTOR_RELEASE ? ": " : "",
			 cmd->kind == MOTOR_RELEASE ? swing_verdict_text(c->swing.verdict) : "");
		return true;
	}
	if (!c->joined.pulling)
		return false;
	static const char *const what[] = {"moved", "grasped", "pulled", "pushed", "turned", "released"};
	int i = cmd->kind == MOTOR_GRASP ? 1 : cmd->kind == MOTOR_RELEASE ? 5 : cmd->kind == MOTOR_PUSH ? 2 : 0;
	if (cmd->kind == MOTOR_PUSH && c->apart.stage == APART_BACK)
		i = 3; /* the push back where it was */
	snprintf(note, size, "; joined: %s the %s he would claim, to see it come away whole (joined.h)%s%s", what[i],
		 task_shape_name(c->task.shape), cmd->kind == MOTOR_RELEASE ? ": " : "",
		 cmd->kind == MOTOR_RELEASE ? apart_verdict_text(c->apart.verdict) : "");
	return true;
}
