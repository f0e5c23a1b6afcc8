/* tug.c - telling an object from the wall it leans on by touch and motion (paper
 * 3.4.2, 2.2). CONTROLLER SIDE. The rule is in tug.h. */
#include "utak/mind/tug.h"

#include "utak/mind/goals.h"
#include "utak/mind/objects.h"

/* tug_way_free(c, dx, dy, n): the n squares from Utak's along (dx, dy) are believed
 * floor: he can walk back that far, drawing the object after him. */
static bool tug_way_free(const Controller *c, int dx, int dy, int n)
{
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	for (int t = 1; t <= n; t++)
		if (worldmodel_belief(&c->model, ux + t * dx, uy + t * dy) != BELIEF_FLOOR)
			return false;
	return true;
}

/* tug_applies(c): Utak travels looking for an object the model has not found,
 * for a task that lets him move it. Going round is not one: the loop is round the
 * object where it stood when the task began (the judge's measure, judge.c), and a
 * loop round the place he drew it to is not that, though the model, which sees the
 * object only where it is now, would count it. */
static bool tug_applies(Controller *c)
{
	TaskKind k = c->task.kind;
	if (c->phase != PHASE_TRAVEL || k == TASK_GO_CORNER || k == TASK_GO_NEXT_ROOM || k == TASK_GO_ROUND)
		return false;
	return goals_joined_seen(c) && objects_find_target(c) < 0;
}

/* tug_begin(c, cmd): a grasp, if touch shows an object's colour on a square of an
 * occupied set the model does not hold to be an object, beside Utak along an axis
 * (so that he can draw it straight back). */
static bool tug_begin(Controller *c, MotorCommand *cmd)
{
	const WorldModel *m = &c->model;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	for (int i = 0; i < TOUCH_CELLS; i += 2) { /* the four beside him, not diagonal */
		char colour = c->impression.touch[i];
		if (colour < 'A' || colour > 'Z' || colour == 'B')
			continue;
		int dx = goals_touch_offset[i][0], dy = goals_touch_offset[i][1];
		int32_t k = worldmodel_node_at(m, ux + dx, uy + dy);
		if (worldmodel_belief(m, ux + dx, uy + dy) != BELIEF_OCCUPIED ||
		    (k >= 0 && m->node[k].kind == NODE_OBJECT) || !tug_way_free(c, -dx, -dy, TUG_STEP) ||
		    objects_square_listed(c->tugged_x, c->tugged_y, c->tugged_squares, ux + dx, uy + dy) ||
		    !tug_applies(c))
			continue;
		objects_note_square(c->tugged_x, c->tugged_y, &c->tugged_squares, ux + dx, uy + dy);
		c->tug_dx = -dx;
		c->tug_dy = -dy;
		c->tug_pulled = 0;
		c->tug_stage = 1;
		c->tug_tries++;
		*cmd = (MotorCommand){.kind = MOTOR_GRASP};
		return true;
	}
	return false;
}

bool tug_decide(Controller *c, MotorCommand *cmd)
{
	if (c->tug_stage == 0)
		return c->tug_tries < TUG_TRIES && tug_begin(c, cmd);
	/* Pulling: the object is free when the model sees the square beside Utak,
	 * where he holds it, as part of an object of its own. */
	const WorldModel *m = &c->model;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	int32_t k = worldmodel_node_at(m, ux - c->tug_dx, uy - c->tug_dy);
	bool freed = k >= 0 && m->node[k].kind == NODE_OBJECT;
	/* A pull that left Utak where he was: the object does not come (it is
	 * wedged, or the way is blocked), and pulling again would not move it. */
	bool stuck = c->tug_stage == 2 && goals_distance(m->utak, c->tug_from) < TUG_STEP / 2.0;
	if (stuck && !freed) {
		c->tug_wedged++;
		c->tug_wedged_at = goals_centre(ux - c->tug_dx, uy - c->tug_dy);
	}
	if (!freed && !stuck && c->tug_pulled + TUG_STEP <= TUG_MOST && tug_way_free(c, c->tug_dx, c->tug_dy, TUG_STEP)) {
		*cmd = (MotorCommand){.kind = MOTOR_PUSH, .dx = TUG_STEP * c->tug_dx, .dy = TUG_STEP * c->tug_dy};
		c->tug_pulled += TUG_STEP;
		c->tug_stage = 2;
		c->tug_from = m->utak;
		return true;
	}
	*cmd = (MotorCommand){.kind = MOTOR_RELEASE};
	c->tug_stage = 0;
	c->have_plan = false;
	return true;
}
