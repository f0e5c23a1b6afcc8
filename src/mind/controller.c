/* controller.c - the robot-controller: initialization, plan and action cycle (paper 3.1).
 * CONTROLLER SIDE: it knows the world only through impressions and its own commands.
 *
 * The steps are the paper's:
 *   1-5  controller_start: default world model, first impression, regions and
 *        their interpretation, accommodation (worldmodel.c, regions.c);
 *   6    controller_set_task: the task, read in terms of the world model (an object
 *        named but not seen is looked for: Utak explores the frontiers of the
 *        unseen until he sees it or has seen everything);
 *   7    the plan: a goal on the screen, and a path to it (screen.c, planner.c);
 *   8-9  controller_decide: is the task complete? else the next leg of the plan;
 *   10   (the simulator carries it out; main.c);
 *   11   controller_perceive: accommodate the new impression;
 *   12   is the plan still viable (its goal unchanged, its path still free)?
 *   13   if not, plan again.
 *
 * THE PARTS. The goal of each task and of exploring is chosen in goals.c; going
 * round an object is laid out in round.c; pushing (where to hold an object, its
 * configuration space, seating it in a corner) is push.c; the checks a corner or
 * next-room claim rests on are roomclaim.c. This file keeps the cycle
 * itself: the phases (ControllerPhase), the plan and its viability, and what
 * arriving at a goal means in each phase (arrive). A new kind of task adds a goal
 * in goals.c and, if it needs one, a phase here.
 *
 * All coordinates are in the world model's $floor frame unless named screen. */
#include "utak/mind/controller.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/carrytask.h"
#include "utak/mind/goals.h"
#include "utak/mind/joined.h"
#include "utak/mind/objects.h"
#include "utak/mind/probe.h"
#include "utak/mind/push.h"
#include "utak/mind/rival.h"
#include "utak/mind/pushclear.h"
#include "utak/mind/pushturn.h"
#include "utak/mind/roomclaim.h"
#include "utak/mind/roomdoubt.h"
#include "utak/mind/hallsplit.h"
#include "utak/mind/round.h"
#include "utak/mind/shape.h"
#include "utak/mind/tug.h"
#include "utak/mind/wallbump.h"

/* build_space(c): the grid to plan on, from the current screen: its space, or
 * when pushing the configuration space. Utak's own square is free whatever the
 * model says of it: he stands there. */
static void build_space(Controller *c)
{
	if (c->phase == PHASE_PUSH) {
		push_space(c, &c->space);
	} else {
		grid_free(&c->space);
		grid_init(&c->space, c->screen.w, c->screen.h, GRID_BLOCKED);
		memcpy(c->space.cells, c->screen.free.cells, (size_t)c->screen.w * (size_t)c->screen.h);
		push_mark_bumped(c, &c->space);
	}
	int32_t i, j;
	if (goals_cell_of(&c->screen, c->model.utak, &i, &j))
		c->space.cells[j * c->space.w + i] = GRID_FREE;
}

/* make_plan(c, why): step 7 / 13: a goal and a route to it. False (with why) when
 * the task cannot be done from what Utak knows. */
static bool make_plan(Controller *c, char *why, size_t size)
{
	Vec2 extra[2] = {c->start, c->goal};
	screen_build(&c->screen, &c->model, extra, c->have_plan ? 2 : 1);
	build_space(c);
	GoalResult gr;
	goals_choose(c, &gr);
	if (!gr.found) {
		snprintf(why, size, "%s", gr.why);
		return false;
	}
	if (c->task.kind == TASK_GO_ROUND && c->round_count == 0 && !gr.exploring && c->phase == PHASE_TRAVEL) {
		/* Beside the object is where going round starts: lay out the loop now. */
		int32_t k = objects_find_target(c);
		/* A guess is looked at first; and what the eye takes for an object is
		 * felt first: a wall it did not see meet the verge looks the same. */
		if (k >= 0 && !objects_read(c, k).guessed && objects_felt(c, k)) {
			round_lay_out(c, k);
			goals_choose(c, &gr); /* the first point, moved off a wall if need be */
			if (!gr.found) {
				snprintf(why, size, "%s", gr.why);
				return false;
			}
		}
	}
	c->goal = gr.goal;
	c->exploring = gr.exploring;
	/* The goal may lie outside the screen built before it was known: only then
	 * build it again, around the goal too. */
	int32_t gi, gj;
	if (!goals_cell_of(&c->screen, c->goal, &gi, &gj)) {
		Vec2 both[2] = {c->start, c->goal};
		screen_build(&c->screen, &c->model, both, 2);
		build_space(c);
	}
	Vec2 from = screen_from_model(&c->screen, c->model.utak), to = screen_from_model(&c->screen, c->goal);
	c->plans_made++;
	c->plan_x0 = c->screen.x0;
	c->plan_y0 = c->screen.y0;
	if (!planner_plan(&c->planner, &c->space, from, to)) {
		snprintf(why, size, "no path to (%.1f, %.1f)", c->goal.x, c->goal.y);
		return false;
	}
	Path way;
	path_init(&way);
	planner_waypoints(&c->space, &c->planner.found, &way);
	path_clear(&c->route);
	for (int i = 0; i < way.count; i++)
		path_push(&c->route, screen_to_model(&c->screen, way.pts[i]));
	path_free(&way);
	c->route.pts[0] = c->model.utak;
	c->route.pts[c->route.count - 1] = c->goal;
	c->next = 1;
	c->have_plan = true;
	return true;
}

/* route_viable(c): the rest of the route is still strictly free on the new space. */
static bool route_viable(const Controller *c)
{
	Vec2 prev = screen_from_model(&c->screen, c->model.utak);
	for (int i = c->next; i < c->route.count; i++) {
		Vec2 p = screen_from_model(&c->screen, c->route.pts[i]);
		if (!planner_segment_strict(&c->space, prev, p))
			return false;
		prev = p;
	}
	return true;
}

/* ---- the cycle -------------------------------------------------------------------- */

void controller_init(Controller *c, PlannerKind planner)
{
	memset(c, 0, sizeof *c);
	c->planner_kind = planner;
	planner_init(&c->planner, planner);
	screen_init(&c->screen);
	path_init(&c->route);
	path_init(&c->trail);
	worldmodel_init(&c->model); /* step 1: the default world model */
}

void controller_free(Controller *c)
{
	worldmodel_free(&c->model);
	screen_free(&c->screen);
	grid_free(&c->space);
	planner_free(&c->planner);
	path_free(&c->route);
	path_free(&c->trail);
	carrytask_delete(c->carry);
	c->carry = NULL;
}

void controller_set_task(Controller *c, const Task *t)
{
	c->task = *t;
	c->has_task = true;
	if (carrytask_applies(t) && !c->carry)
		c->carry = carrytask_new();
}

void controller_start(Controller *c, const Impression *first)
{
	c->impression = *first;		/* step 2 */
	regions_find(&c->regions, first); /* steps 3-4 */
	worldmodel_accommodate_first(&c->model, first); /* step 5 */
	c->seen_before = worldmodel_known_squares(&c->model);
	c->start = c->last_position = c->model.utak;
	path_push(&c->trail, c->model.utak);
	if (!c->has_task)
		return;
	c->phase = PHASE_TRAVEL; /* step 6: the task's object is looked for in the plan */
	/* Where a corner is, the eye tells only from close by: walls seen from afar
	 * are placed a square or two off, and a corner behind an obstacle not at all.
	 * Utak goes to look at it before he fetches what he is to push there. */
	c->surveying = c->task.kind == TASK_PUSH_CORNER;
	char why[160];
	if (!make_plan(c, why, sizeof why)) { /* step 7 */
		c->phase = PHASE_FAILED;
		snprintf(c->why, sizeof c->why, "%s", why);
	}
}

/* remember(c, p): a goal reached that is not to be chosen again. */
static void remember(Controller *c, Vec2 p)
{
	if (c->visited_count < CONTROLLER_MAX_VISITED)
		c->visited[c->visited_count++] = p;
}

/* shun(c, goal): a goal whose path is blocked, its own square now occupied on the
 * plan's space and never seen in the fovea, is not chosen again by goals_near.
 * WHY: the fringe of an object seen only in the 2 x 2 and 4 x 4 cells reads
 * otherwise from each square Utak stands on (the cells fall on other squares).
 * Looking at a hypothesis from the floor nearest a square of it he has not seen
 * in the fovea, two such cells, on two sides of the object, were each occupied
 * as seen from the way to the other: every path was blocked in turn and he went
 * to and fro between the two ways until the cycles ran out (random g258,
 * tests/worlds/look-fringe.w). */
static void shun(Controller *c, Vec2 goal)
{
	int32_t i, j;
	int32_t x = (int32_t)floor(goal.x), y = (int32_t)floor(goal.y);
	if (c->phase != PHASE_TRAVEL || /* pushing, the space is the configuration space */
	    !goals_cell_of(&c->screen, goal, &i, &j) || c->space.cells[j * c->space.w + i] == GRID_FREE ||
	    worldmodel_evidence(&c->model, x, y).res == WORLDMODEL_RES_FOVEA || c->shunned_count >= CONTROLLER_MAX_VISITED)
		return;
	c->shunned[c->shunned_count++] = goal;
}

/* round_trips(c, cmd, seen): after a move while travelling, whether Utak goes to and
 * fro: he stands on a square for the CONTROLLER_ROUND_TRIP_VISITS-th time within
 * his last CONTROLLER_ROUND_TRIP_WINDOW moves, none of which showed anything new
 * (seen: squares seen for the first time this cycle). WHY: the goal and the route
 * are chosen afresh from each place he stands (paper 3.1 steps 12-13), and where
 * the choice from one place leads to another from which it leads back (two
 * unseen squares of a hypothesis each the nearer from the way to the other, a
 * route free from one square and blocked from the next, an exploring goal and the
 * task's in turn), he walked to and fro until the cycles ran out, whatever their
 * number (random g238, tests/worlds/to-and-fro.w; g185 and g188 too). Going to and
 * fro shows him nothing new, so the goal is given up as one reached (remember):
 * goals_near and the frontier do not choose it again, and the next is planned.
 * Not while going round an object, whose loop comes back to its start by design. */
static bool round_trips(Controller *c, const MotorCommand *cmd, int32_t seen)
{
	if (cmd->kind != MOTOR_MOVE || c->phase != PHASE_TRAVEL || seen > 0 ||
	    (c->task.kind == TASK_GO_ROUND && c->round_count > 0)) {
		c->trip_count = 0;
		return false;
	}
	int32_t x, y;
	worldmodel_utak_square(&c->model, &x, &y);
	/* A move that left him on the square he stood on (a bump, a leg shorter than a
	 * square) is no trip: the stuck rule and the blocked route's re-plan deal with
	 * it, and counted here two bumps would give the goal up as reached. */
	if (c->trip_count > 0 && c->trip_x[c->trip_count - 1] == x && c->trip_y[c->trip_count - 1] == y)
		return false;
	int visits = 1;
	for (int k = 0; k < c->trip_count; k++)
		visits += c->trip_x[k] == x && c->trip_y[k] == y;
	if (c->trip_count == CONTROLLER_ROUND_TRIP_WINDOW) {
		memmove(c->trip_x, c->trip_x + 1, (CONTROLLER_ROUND_TRIP_WINDOW - 1) * sizeof *c->trip_x);
		memmove(c->trip_y, c->trip_y + 1, (CONTROLLER_ROUND_TRIP_WINDOW - 1) * sizeof *c->trip_y);
		c->trip_count--;
	}
	c->trip_x[c->trip_count] = x;
	c->trip_y[c->trip_count++] = y;
	if (visits < CONTROLLER_ROUND_TRIP_VISITS)
		return false;
	c->trip_count = 0;
	return true;
}

/* bump_trip(c, k): a corner of the wall that may be a square pressed against it,
 * nearer the start than node k, can still be reached and felt (wallbump.h): the
 * claim waits, and the next goal (goals.c) is beside it. */
static bool bump_trip(Controller *c, int32_t k)
{
	if (k < 0 || c->task.shape != SHAPE_SQUARE)
		return false;
	int32_t *dist = roomclaim_reach(c);
	Vec2 goal;
	bool go = wallbump_look(c, dist, c->start, goals_distance(objects_read(c, k).centroid, c->start), &goal);
	free(dist);
	return go;
}

/* arrive(c): what reaching the goal means in the current phase. */
static void arrive(Controller *c)
{
	c->have_plan = false;
	if (rival_arrive(c))
		return; /* going to another object the claim is in doubt over (rival.h) */
	if (joined_arrive(c))
		return; /* where the object he would claim can be pulled from (joined.h) */
	if (seam_arrive(c))
		return; /* where the square he would claim can be pushed both ways from (seam.h) */
	if (c->exploring) {
		remember(c, c->goal); /* a frontier or an object to look at: look again from here */
		if (c->door_look_pending && goals_distance(c->goal, c->door_look_at) < 0.5)
			c->door_look_pending = false; /* doorlook.h's look taken */
		c->room_look = c->room_following = false;
		hallsplit_arrive(c); /* beside a blob: touch has felt it, or not (hallsplit.h) */
		return;
	}
	int64_t short_by;
	if (c->surveying) {
		c->surveying = false; /* the corner seen from close by: now the object */
		return;
	}
	if (c->carry && carrytask_arrive(c))
		return; /* the door or the corner seen from close by: now the object */
	if (pushclear_arrive(c))
		return; /* an object in the way of the corner: grasp it, or let it go */
	switch (c->task.kind) {
	case TASK_GO_NEXT_ROOM:
		if (roomclaim_next_leaning(c, true))
			c->room_look = true; /* the next goal: beside a door's jamb, to touch it (roomlean.h) */
		else if (!roomclaim_next_leaning(c, false))
			c->phase = PHASE_DONE; /* (roomclaim_next_leaning fails it, with his doubt) */
		return;
	case TASK_GO_CORNER:
		if ((short_by = goals_corner_shortfall(c)) > CONTROLLER_CORNER_SLACK)
			goals_corner_failed(c, short_by);
		else if (roomclaim_corner_look(c, roomdoubt_beyond))
			c->room_look = true; /* the next goal: a look past the undecided door */
		else if (roomclaim_corner_look(c, roomdoubt_jambs))
			c->room_look = true; /* the next goal: a look at the door's coarse side */
		else if (roomclaim_frontier(c))
			; /* the room seen in part: the next goal is a look at its unseen side */
		else if (roomclaim_corner_doubt(c) == ROOMDOUBT_LOOK)
			; /* not sure of the room: the next goal is a look at the wall between */
		else if (hallsplit_hidden_look(c))
			c->room_look = true; /* the next goal: a look at what may join a better floor */
		else if (roomclaim_corner_leaning(c, true))
			c->room_look = true; /* the next goal: beside a door's jamb nearby, to touch it (roomlean.h) */
		else if (!goals_corner_hidden(c) && !roomclaim_hall_split(c) && !roomclaim_felt_object(c) &&
			 !roomclaim_corner_leaning(c, false) && !roomclaim_door_doubt(c))
			c->phase = PHASE_DONE; /* (goals_corner_hidden, roomclaim_hall_split, roomclaim_felt_object, roomclaim_corner_leaning and roomclaim_door_doubt fail it, with his doubt; roomclaim_door_doubt may send him to look first) */
		return;
	case TASK_GO_SHAPE:
		if (objects_touching_target(c)) {
			char doubt[160];
			if (objects_misread(c, objects_find_target(c)) && goals_more_to_see(c)) {
				/* Beside one he would doubt, seen closely only now: the next
				 * goal is a look further for one beyond doubt (goals.c). */
			} else if (objects_doubt(c, objects_find_target(c), doubt, sizeof doubt)) {
				/* A doubt over another object: settle it first where he can
				 * (rival.h), then beside this one again. */
				if (!rival_begin(c, objects_find_target(c)) && !bump_trip(c, objects_find_target(c)) &&
				    !joined_begin(c, objects_find_target(c))) {
					c->phase = PHASE_FAILED; /* beside it, and no nearer being sure */
					snprintf(c->why, sizeof c->why, "Utak doubts he touches the %s: %s",
						 task_shape_name(c->task.shape), doubt);
				}
			} else if (seam_begin(c, objects_find_target(c))) { /* one or pieces? pushed both ways first (seam.h) */
			} else if (rival_own_probed(c, objects_find_target(c)) || !probe_begin(c, objects_find_target(c))) {
				c->phase = PHASE_DONE; /* else claimed, or dropped, by motion first */
			}
		} else
			remember(c, c->goal); /* touch says the object is not here after all */
		return;
	case TASK_GO_ROUND:
		if (round_stale(c)) {
			c->round_count = 0; /* round the wrong thing: find the object again */
		} else if (c->round_count == 0) {
			remember(c, c->goal); /* beside it, and not felt from here: another side */
		} else if (c->round_count > 1 && c->round_next + 1 == c->round_count - 1 && !c->round_looked &&
			   round_unconfirmed(c)) {
			/* The loop closed (its last point before home) round an object
			 * not yet seen whole: a look closer at what is unseen now, while
			 * beside it, then home (round.c). */
			c->round_looking = c->round_looked = true;
			c->round_count = 0;
		} else if (c->round_count > 1 && c->round_next + 1 == c->round_count - 1 && rival_loop_closed(c)) {
			/* The loop closed round an object a doubt over another names:
			 * settled from here, beside it, then home (rival.h). */
		} else if (c->round_count > 1 && c->round_next + 1 == c->round_count - 1 && joined_loop_closed(c)) {
			/* The loop closed round one object or two pressed together: pulled
			 * from here, beside it, then home (joined.h). */
		} else if (c->round_count > 1 && c->round_next + 1 == c->round_count - 1 && seam_loop_closed(c)) { /* (seam.h) */
		} else if (c->round_count > 0 && ++c->round_next == c->round_count) {
			/* Home. A loop begun round the wrong object and the one round the
			 * right one can cancel: then once more round it. */
			int32_t k = objects_find_target(c);
			bool confirmed = k >= 0 && objects_read(c, k).confirmed;
			char doubt[160];
			if (confirmed && fabs(round_believed_turns(c, k)) > CONTROLLER_ROUND_TURNS) {
				if (objects_doubtful(c, k) && c->round_loops == 0 && goals_more_to_see(c)) {
					/* Round one he would doubt: look further for one beyond doubt. */
					c->round_loops++;
					c->round_count = 0;
				} else if (objects_doubt(c, k, doubt, sizeof doubt) && rival_begin(c, k)) {
					/* a doubt over another object: settled first, then home again (rival.h) */
				} else if (objects_doubt(c, k, doubt, sizeof doubt) && bump_trip(c, k)) {
					/* a corner of the wall: felt first, then home again (wallbump.h) */
					c->round_count = 0;
					c->bump_home = true;
				} else if (objects_doubt(c, k, doubt, sizeof doubt) && joined_begin(c, k)) {
					/* one object or two pressed together: pulled first, then home again (joined.h) */
				} else if (objects_doubt(c, k, doubt, sizeof doubt)) {
					c->phase = PHASE_FAILED;
					snprintf(c->why, sizeof c->why, "Utak doubts he went round the %s: %s",
						 task_shape_name(c->task.shape), doubt);
				} else if (round_home_doubt(c, doubt, sizeof doubt)) {
					c->phase = PHASE_FAILED;
					snprintf(c->why, sizeof c->why, "Utak doubts he is back where he began: %s", doubt);
				} else if (seam_begin(c, k)) {
					/* one square or pieces pressed together: pushed both ways first, then home again (seam.h) */
				} else
					c->phase = PHASE_DONE;
			}
			else if (!confirmed && k >= 0 && !c->round_looked &&
				 fabs(round_believed_turns(c, k)) > CONTROLLER_ROUND_TURNS) {
				/* Round it, but not seen whole: the same loop again would show
				 * no more. A look closer at what is unseen (paper 3.3), then
				 * home, and the loop walked is judged (round.c). */
				c->round_looking = c->round_looked = true;
				c->round_count = 0;
			} else if (!confirmed && c->round_loops < CONTROLLER_ROUND_LOOPS) {
				/* Round a hypothesis, or an object no longer there: look again
				 * (objects.h), and go round what is found. */
				c->round_loops++;
				c->round_count = 0;
			} else if (!confirmed) {
				c->phase = PHASE_FAILED;
				snprintf(c->why, sizeof c->why, "%d loops, and no %s seen whole in the fovea to go round",
					 c->round_loops + 1, task_shape_name(c->task.shape));
			}
			else if (c->round_loops < CONTROLLER_ROUND_LOOPS) {
				c->round_loops++;
				round_lay_out(c, k);
			} else {
				c->phase = PHASE_FAILED;
				snprintf(c->why, sizeof c->why, "%d more loops round the %s, and still Utak's path does not wind round it",
					 c->round_loops, task_shape_name(c->task.shape));
			}
		}
		return;
	default:
		if (c->phase == PHASE_PUSH && c->task.kind == TASK_PUSH_CORNER)
			push_seat_begin(c);
		else if (c->phase == PHASE_PUSH)
			c->phase = PHASE_RELEASE;
		else if (objects_touching_target(c) && objects_misread(c, objects_find_target(c)) && goals_more_to_see(c)) {
			/* Beside one he would doubt: a look further first (goals.c). */
		} else if (objects_touching_target(c) && c->clear_tries == 0 && c->turn_tries == 0 &&
			   objects_doubt(c, objects_find_target(c), c->doubt, sizeof c->doubt) &&
			   (rival_begin(c, objects_find_target(c)) || bump_trip(c, objects_find_target(c)))) {
			/* A doubt over another object: settled before the object to push is
			 * chosen (rival.h), then back to its grasp side; or over a corner
			 * of the wall, felt first (wallbump.h, goals.c), then back. */
		} else if (objects_touching_target(c) && c->clear_tries == 0 && c->turn_tries == 0 &&
			   seam_begin(c, objects_find_target(c))) {
			/* The square to push, one or pieces? pushed both ways first (seam.h). */
		} else if (objects_touching_target(c)) {
			c->phase = PHASE_GRASP; /* what he doubts, he pushes still, and says so after */
			/* Fetched again after clearing the way (pushclear.h) or squaring it
			 * up (pushturn.h), the doubt is
			 * the one judged at the first grasp, with the object where it began:
			 * the task means the one nearest the start then, and he has moved it
			 * and the other since. */
			if (c->clear_tries == 0 && c->turn_tries == 0 &&
			    !objects_doubt(c, objects_find_target(c), c->doubt, sizeof c->doubt))
				c->doubt[0] = '\0';
		}
		else
			remember(c, c->goal);
	}
}

/* swept_confident(c, from, to): every square Utak's body (a unit square about his
 * point) passes over on the straight move from `from` to `to`, other than the one he
 * stands on, is believed floor with the confidence CONTROLLER_LEG_CONF and nothing
 * seen in it (p at most CONTROLLER_LEG_P), is free on the plan's space (not bumped
 * into) and not under an object of the model. */
static bool swept_confident(const Controller *c, Vec2 from, Vec2 to)
{
	int32_t ux = (int32_t)floor(from.x), uy = (int32_t)floor(from.y);
	double len = goals_distance(from, to);
	int steps = (int)ceil(len / 0.25) + 1;
	/* Squares merely touched at an edge are not entered; CONTROLLER_LEG_MARGIN more
	 * on every side are close to the move. */
	const double half = 0.5 - 1e-6 + CONTROLLER_LEG_MARGIN;
	for (int s = 0; s <= steps; s++) {
		Vec2 p = vec2_add(from, vec2_scale(vec2_sub(to, from), (double)s / steps));
		for (int32_t y = (int32_t)floor(p.y - half); y <= (int32_t)floor(p.y + half); y++)
			for (int32_t x = (int32_t)floor(p.x - half); x <= (int32_t)floor(p.x + half); x++) {
				if (x == ux && y == uy)
					continue;
				Evidence e = worldmodel_evidence(&c->model, x, y);
				int32_t i, j;
				if (e.res == WORLDMODEL_UNSEEN || e.p > CONTROLLER_LEG_P || e.conf < CONTROLLER_LEG_CONF ||
				    worldmodel_node_at(&c->model, x, y) >= 0 || !goals_cell_of(&c->screen, vec2(x + 0.5, y + 0.5), &i, &j) ||
				    c->space.cells[j * c->space.w + i] != GRID_FREE)
					return false;
			}
	}
	return true;
}

/* confident_reach(c, d, len): how far along the leg d (of length len) toward the
 * next waypoint Utak may walk in one move (paper 3.1 step 9: "the degrees of
 * confidence associated with those parts of the world model close to the planned
 * actions"): the whole leg when it is at most CONTROLLER_LONG_LEG and swept over
 * confidently free floor; else the longest whole number of squares up to
 * CONTROLLER_LONG_LEG, ending on a square's centre, that is; 0 when not even
 * CONTROLLER_MAX_LEG + 1 is (the short leg of old then stands). */
static double confident_reach(const Controller *c, Vec2 d, double len)
{
	if (len <= CONTROLLER_MAX_LEG)
		return 0;
	if (len <= CONTROLLER_LONG_LEG && swept_confident(c, c->model.utak, vec2_add(c->model.utak, d)))
		return len;
	for (double r = floor(fmin(len, CONTROLLER_LONG_LEG)); r > CONTROLLER_MAX_LEG; r -= 1) {
		Vec2 to = goals_centre((int32_t)floor(c->model.utak.x + d.x * r / len),
				       (int32_t)floor(c->model.utak.y + d.y * r / len));
		if (goals_distance(to, c->model.utak) > CONTROLLER_MAX_LEG && swept_confident(c, c->model.utak, to))
			return r;
	}
	return 0;
}

/* snap_on_route(c, to): the centre of a square near the point to, where a short leg
 * of travel toward the next waypoint ends. The centre of to's own square, unless
 * that is the square Utak set off from on his last move and the waypoint is not in
 * a strictly free straight line from it; then the nearest of the other centres
 * round to from which it is (and which Utak reaches in one straight line), if any.
 * WHY: the centre of to's own square may lie off the leg, beside a corner the leg
 * passes, and from there the rest of the route is not strictly free (route_viable):
 * the plan made again from there goes back to where he came from, whose next short
 * leg snaps to the same square again, and Utak walks to and fro for ever (a square
 * in a pocket of the wall, looked at from below a pier's corner). Only then is the
 * rule changed: everywhere else the legs stay as they were. */
static Vec2 snap_on_route(const Controller *c, Vec2 to)
{
	Vec2 own = goals_centre((int32_t)floor(to.x), (int32_t)floor(to.y));
	Vec2 next = screen_from_model(&c->screen, c->route.pts[c->next]);
	const Path *t = &c->trail;
	if (t->count < 2 || goals_distance(own, t->pts[t->count - 2]) > 0.5 ||
	    planner_segment_strict(&c->space, screen_from_model(&c->screen, own), next))
		return own;
	Vec2 here = screen_from_model(&c->screen, c->model.utak);
	Vec2 best = own;
	double best_d = INFINITY;
	for (int k = 0; k < 4; k++) {
		Vec2 q = goals_centre((int32_t)floor(to.x + (k & 1 ? 0.5 : -0.5)),
				      (int32_t)floor(to.y + (k & 2 ? 0.5 : -0.5)));
		Vec2 s = screen_from_model(&c->screen, q);
		double dq = goals_distance(q, to);
		if (goals_distance(q, own) > 0.5 && dq < best_d && goals_distance(q, c->model.utak) > CONTROLLER_ARRIVED &&
		    planner_segment_strict(&c->space, here, s) && planner_segment_strict(&c->space, s, next)) {
			best_d = dq;
			best = q;
		}
	}
	return best;
}

bool controller_decide(Controller *c, MotorCommand *cmd)
{
	*cmd = (MotorCommand){0};
	if (!c->has_task)
		return false;
	c->cycle++;
	/* A square about to be claimed, or a rival, confirmed by motion first (probe.h,
	 * rival.h). */
	if (rival_decide(c, cmd))
		return true;
	/* The object he would claim pulled first, to see it one (joined.h). */
	if (joined_decide(c, cmd))
		return true;
	if (seam_decide(c, cmd)) /* the square he would claim pushed both ways, to see it one (seam.h) */
		return true;
	/* An object not yet told from the wall it leans on: touch and motion. */
	if (tug_decide(c, cmd))
		return true;
	/* Step 8 and 9, a few times over if arriving changes the phase. */
	for (int round = 0; round < 4; round++) {
		if (rival_decide(c, cmd)) /* begun on arriving (arrive) */
			return true;
		if (joined_decide(c, cmd)) /* begun on arriving (arrive) */
			return true;
		if (seam_decide(c, cmd)) /* begun on arriving (arrive) */
			return true;
		switch (c->phase) {
		case PHASE_DONE:
		case PHASE_FAILED:
			return false;
		case PHASE_GRASP:
			cmd->kind = MOTOR_GRASP;
			c->phase = PHASE_PUSH;
			c->have_plan = false;
			return true;
		case PHASE_RELEASE:
			if (pushclear_back_off(c, cmd))
				return true; /* first drawn off what it is pressed against */
			cmd->kind = MOTOR_RELEASE;
			/* Letting go to move an object out of the way, or having moved it,
			 * the task goes on (pushclear.h). */
			c->phase = pushclear_released(c) || pushturn_released(c) ? PHASE_TRAVEL : PHASE_DONE;
			return true;
		case PHASE_SEAT:
			if (push_seat_command(c, cmd))
				return true;
			push_seat_finish(c);
			continue;
		case PHASE_TRAVEL:
		case PHASE_PUSH:
			break;
		}
		if (c->phase == PHASE_PUSH && c->carry)
			return carrytask_decide(c, cmd); /* tasks (vi)-(ix): the carry's next command */
		char why[160];
		if (!c->have_plan && !make_plan(c, why, sizeof why)) {
			c->phase = PHASE_FAILED;
			snprintf(c->why, sizeof c->why, "%s", why);
			return false;
		}
		if (goals_distance(c->model.utak, c->goal) <= CONTROLLER_ARRIVED) {
			arrive(c);
			continue;
		}
		while (c->next < c->route.count - 1 && goals_distance(c->model.utak, c->route.pts[c->next]) <= CONTROLLER_ARRIVED)
			c->next++;
		Vec2 d = vec2_sub(c->route.pts[c->next], c->model.utak);
		double len = hypot(d.x, d.y);
		double reach = c->phase == PHASE_TRAVEL ? confident_reach(c, d, len) : 0;
		if (reach >= len) {
			/* The whole way to the waypoint is confidently free. */
		} else if (reach > CONTROLLER_MAX_LEG) {
			d = vec2_sub(goals_centre((int32_t)floor(c->model.utak.x + d.x * reach / len),
						  (int32_t)floor(c->model.utak.y + d.y * reach / len)),
				     c->model.utak);
		} else if (len > CONTROLLER_MAX_LEG) {
			/* A shorter leg ends on a square's centre, like every waypoint, so
			 * that moves are whole squares: shapes then keep their digital form
			 * as they move, and the eye's next impression is predictable. */
			Vec2 to = vec2_add(c->model.utak, vec2_scale(d, CONTROLLER_MAX_LEG / len));
			Vec2 snapped = c->phase == PHASE_TRAVEL ? snap_on_route(c, to)
							      : goals_centre((int32_t)floor(to.x), (int32_t)floor(to.y));
			if (goals_distance(snapped, c->model.utak) > CONTROLLER_ARRIVED)
				d = vec2_sub(snapped, c->model.utak);
			else
				d = vec2_scale(d, CONTROLLER_MAX_LEG / len);
		}
		cmd->kind = c->phase == PHASE_PUSH ? MOTOR_PUSH : MOTOR_MOVE;
		cmd->dx = d.x;
		cmd->dy = d.y;
		return true;
	}
	/* Arrived again and again without a command to give: the goals keep landing
	 * where Utak already is. */
	c->phase = PHASE_FAILED;
	snprintf(c->why, sizeof c->why, "no progress: every goal found is where Utak already stands");
	return false;
}

static void perceive(Controller *c, const MotorCommand *cmd, const Impression *imp);

void controller_perceive(Controller *c, const MotorCommand *cmd, const Impression *imp)
{
	perceive(c, cmd, imp);
	if (c->carry) { /* the carry's plan, when one was made this cycle, after the note */
		size_t n = strlen(c->note);
		carrytask_note(c, c->note + n, sizeof c->note - n);
	}
}

/* perceive(c, cmd, imp): steps 11-13, the note saying what they did. */
static void perceive(Controller *c, const MotorCommand *cmd, const Impression *imp)
{
	c->impression = *imp;
	regions_find(&c->regions, imp);		 /* step 11 */
	/* Only the corner push judges the object by its held squares (push_seat_finish). */
	c->model.register_held = c->has_task && c->task.kind == TASK_PUSH_CORNER && !rival_probing(c);
	worldmodel_accommodate(&c->model, cmd, imp);
	if (cmd->kind == MOTOR_GRASP) {
		c->grasp_shape = shape_of_squares(c->model.held_dx, c->model.held_dy, c->model.held_count);
		pushturn_grasped(c); /* fetched again after squaring it up: the same object? */
	}
	if (round_recognise_home(c))
		c->model.report.corrected = true; /* placed by the first impression: re-plan */
	c->fix[c->fix_next] = c->model.report.corrected ? vec2_sub(c->model.utak, c->model.report.predicted) : vec2(0, 0);
	c->fix_next = (c->fix_next + 1) % CONTROLLER_FIXES;
	path_push(&c->trail, c->model.utak);
	objects_feel(c);
	int32_t seen = worldmodel_known_squares(&c->model);
	int n = snprintf(c->note, sizeof c->note, "model: %+d squares seen", (int)(seen - c->seen_before));
	bool to_and_fro = c->has_task && round_trips(c, cmd, seen - c->seen_before);
	c->seen_before = seen;
	if (c->model.report.corrected)
		n += snprintf(c->note + n, sizeof c->note - (size_t)n, ", position corrected to (%.1f, %.1f)",
			      c->model.utak.x, c->model.utak.y);
	if (!c->has_task || c->phase == PHASE_DONE || c->phase == PHASE_FAILED)
		return;
	n += pushclear_note(c, c->note + n, sizeof c->note - (size_t)n); /* a clearing begun: why */
	if (c->hall.note[0]) { /* a blob gone to, to touch it (hallsplit.h) */
		n += snprintf(c->note + n, sizeof c->note - (size_t)n, "%s", c->hall.note);
		c->hall.note[0] = '\0';
	}
	if (c->rival.note[0]) { /* a rival gone to, or settled (rival.h) */
		n += snprintf(c->note + n, sizeof c->note - (size_t)n, "%s", c->rival.note);
		c->rival.note[0] = '\0';
	}
	if (seam_note(c, c->note + n, sizeof c->note - (size_t)n)) {
		c->last_position = c->model.utak; /* its pushes are short by design */
		c->stuck = 0;
		return;
	}
	if (joined_perceive(c, cmd, c->note + n, sizeof c->note - (size_t)n)) {
		c->last_position = c->model.utak; /* its pulls are short by design */
		c->stuck = 0;
		return;
	}
	if (rival_perceive(c, cmd, c->note + n, sizeof c->note - (size_t)n)) {
		c->last_position = c->model.utak; /* its pushes are short by design */
		c->stuck = 0;
		return;
	}
	if (c->tug_stage) {
		snprintf(c->note + n, sizeof c->note - (size_t)n, "; tugging what touch shows is an object");
		c->have_plan = false;
		return;
	}
	/* No progress: the same believed point after a move or push, cycle after cycle. */
	if ((cmd->kind == MOTOR_MOVE || cmd->kind == MOTOR_PUSH) && hypot(cmd->dx, cmd->dy) > 0 &&
	    goals_distance(c->model.utak, c->last_position) < 0.5 * hypot(cmd->dx, cmd->dy))
		push_bump(c, cmd);
	if ((cmd->kind == MOTOR_MOVE || cmd->kind == MOTOR_PUSH) && goals_distance(c->model.utak, c->last_position) < 0.05) {
		/* Seating, pushes that make no headway are expected and bounded (push_seat). */
		if (++c->stuck >= CONTROLLER_STUCK_CYCLES && c->phase != PHASE_SEAT) {
			if (push_seat_here(c))
				return; /* into a corner: the walls place it (push.c) */
			c->phase = PHASE_FAILED;
			snprintf(c->why, sizeof c->why, "stuck at (%.1f, %.1f): every way on is blocked", c->model.utak.x,
				 c->model.utak.y);
			return;
		}
	} else {
		c->stuck = 0;
	}
	c->last_position = c->model.utak;
	if (c->carry && c->phase == PHASE_PUSH) {
		carrytask_perceive(c, cmd); /* its own plan, checked its own way */
		return;
	}
	if (cmd->kind == MOTOR_PUSH && c->phase == PHASE_PUSH && push_in_circles(c))
		return;
	if (c->phase == PHASE_SEAT) {
		push_seat(c);
		return;
	}
	if (c->phase != PHASE_TRAVEL && c->phase != PHASE_PUSH)
		return;
	if (!c->have_plan)
		return; /* the next decision plans */
	/* Step 12: is the plan still viable? */
	const char *reason = NULL;
	Vec2 old_goal = c->goal;
	Vec2 extra[2] = {c->start, c->goal};
	screen_build(&c->screen, &c->model, extra, 2);
	build_space(c);
	GoalResult gr;
	if (c->model.report.corrected)
		reason = "Utak is not where he expected";
	else if (to_and_fro) {
		reason = "Utak goes to and fro, seeing nothing new: the goal given up";
		remember(c, old_goal);
	} else if (round_stale(c)) {
		reason = "the object to go round is not what it seemed";
		c->round_count = 0;
	} else if (!route_viable(c)) {
		reason = "the path is blocked";
		shun(c, old_goal);
	}
	else if (c->task.kind != TASK_GO_ROUND) {
		goals_choose(c, &gr);
		/* Exploring, one place to look from is as good as another: the one
		 * chosen stands while there is still something to see from it (else
		 * two of them, each nearer from the other, draw Utak to and fro). */
		bool keep = c->exploring && gr.found && gr.exploring && goals_worth_looking(c, old_goal);
		if (!keep && (!gr.found || goals_distance(gr.goal, old_goal) > CONTROLLER_ARRIVED ||
			      gr.exploring != c->exploring))
			reason = "the goal has moved";
	}
	if (!reason) {
		snprintf(c->note + n, sizeof c->note - (size_t)n, "; plan viable");
		return;
	}
	char why[160];
	c->replans++;
	c->have_plan = false;
	if (!make_plan(c, why, sizeof why)) { /* step 13 */
		c->phase = PHASE_FAILED;
		snprintf(c->why, sizeof c->why, "%s", why);
		snprintf(c->note + n, sizeof c->note - (size_t)n, "; re-plan: %s; no plan", reason);
		return;
	}
	snprintf(c->note + n, sizeof c->note - (size_t)n, "; re-plan: %s; goal (%.1f, %.1f)%s, path %.2f", reason,
		 c->goal.x, c->goal.y, c->exploring ? " (exploring)" : "", c->planner.found_length);
}

/* ---- dumps ------------------------------------------------------------------------ */

void controller_dump_screen(Controller *c, FILE *f)
{
	if (c->screen.w == 0) {
		Vec2 extra = c->start;
		screen_build(&c->screen, &c->model, &extra, 1);
	}
	screen_dump(&c->screen, &c->model, f);
}

void controller_dump_skeleton(Controller *c, FILE *f)
{
	if (!c->planner.have_graph) {
		fputs("skeleton: no plan made on the skeleton\n", f);
		return;
	}
	skeleton_dump(&c->planner.skeleton, &c->planner.grid, f);
}

void controller_dump_pathgraph(Controller *c, FILE *f)
{
	if (!c->planner.have_graph) {
		fputs("pathgraph: no plan made on the skeleton\n", f);
		return;
	}
	pathgraph_dump(&c->planner.pathgraph, f);
}

void controller_dump_rooms(Controller *c, FILE *f)
{
	if (c->screen.w == 0) {
		Vec2 extra = c->start;
		screen_build(&c->screen, &c->model, &extra, 1);
	}
	RoomMap rm;
	goals_roommap_build(&rm, &c->screen);
	rooms_dump(&rm.rooms, &rm.known, f);
	goals_roommap_free(&rm);
}

void controller_dump_path(Controller *c, FILE *f)
{
	planner_dump_path(&c->planner, f);
	if (c->route.count > 0) {
		fprintf(f, "route (model frame), %d waypoints:\n", c->route.count);
		for (int i = 0; i < c->route.count; i++)
			fprintf(f, "  %.2f %.2f%s\n", c->route.pts[i].x, c->route.pts[i].y, i == c->next ? " <- next" : "");
	}
}
