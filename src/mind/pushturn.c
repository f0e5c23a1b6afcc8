/* pushturn.c - squaring a slanted object up to the walls of the corner it is pushed
 * into (paper 2.2 the motor command turn: "the held object rotates about Utak's
 * point"; 2.3 task (v)). CONTROLLER SIDE: the world model and the task only. See
 * pushturn.h.
 *
 * WHY: seating (push.c) presses the object home with one-square pushes, and the
 * walls place it; but a push never turns it, and a square at 25 to 65 degrees,
 * pressed against both walls, stays 2 to 21 squares short of the corner by the
 * judge's measure (its squares' best score), with nothing in the way (random
 * worlds g55 g65 g85 g100 g110 g170 of the rates at 519ccd0). The turn that puts its
 * sides along the axes is read from the held squares by shape.h's rectangle at any
 * angle; it is made away from the walls, where the object's sweep round Utak's
 * point is clear on the model (a turn that meets something halts, and the
 * simulator says so: the model then re-finds the held squares as ever). Turned,
 * he keeps hold where the object still leads him toward both walls; else, or when
 * the disparity corrects his place on the push after, he lets go and fetches it
 * again (let_go). The claim is judged as ever (push_seat_finish). */
#include "utak/mind/pushturn.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "utak/base/geom.h"
#include "utak/mind/goals.h"
#include "utak/mind/shape.h"

/* Stages of a squaring up (Controller.turn_stage). */
enum { TURN_NONE, TURN_BACK, TURN_TURN, TURN_AGAIN, TURN_LETGO };

bool pushturn_angle(const int32_t *x, const int32_t *y, int32_t n, double *deg)
{
	ShapeReading r;
	Shape s = shape_read(x, y, n, 1.0, &r);
	/* A rectangle by name, or by how its squares fill their minimum-area
	 * rectangle (pressed into a corner, a slanted square's held set can lose a
	 * row to the wall and read as no shape: its sides' angle stands). */
	if (s != SHAPE_SQUARE && s != SHAPE_BRICK && !(s == SHAPE_NONE && r.rect_fill >= SHAPE_RECT_HULL))
		return false;
	double t = fmod(r.angle, 90.0); /* the long side's slant off the x axis, [0, 90) */
	if (t < 0)
		t += 90.0;
	double turn = t <= 45.0 ? -t : 90.0 - t;
	if (fabs(turn) < PUSHTURN_MIN_DEG)
		return false;
	*deg = round(turn); /* whole degrees, as the carries turn */
	return true;
}

/* blocked(c, x, y, ux, uy): model square (x, y) would stop Utak, standing on square
 * (ux, uy), or what he holds: believed occupied and not one of the held squares
 * (they move with him), or bumped into. */
static bool blocked(const Controller *c, int32_t x, int32_t y, int32_t ux, int32_t uy)
{
	const WorldModel *m = &c->model;
	for (int32_t k = 0; k < m->held_count; k++)
		if (ux + m->held_dx[k] == x && uy + m->held_dy[k] == y)
			return false;
	if (x == ux && y == uy)
		return false;
	for (int b = 0; b < c->bumped_count; b++)
		if (c->bumped_x[b] == x && c->bumped_y[b] == y)
			return true;
	return worldmodel_belief(m, x, y) == BELIEF_OCCUPIED;
}

/* footprint_free(c, x, y): Utak on square (x, y) and his held squares with him lie on
 * no square blocked on the model (the held squares as they are now do not count:
 * he moves them). */
static bool footprint_free(const Controller *c, int32_t x, int32_t y, int32_t ux, int32_t uy)
{
	const WorldModel *m = &c->model;
	if (blocked(c, x, y, ux, uy))
		return false;
	for (int32_t k = 0; k < m->held_count; k++)
		if (blocked(c, x + m->held_dx[k], y + m->held_dy[k], ux, uy))
			return false;
	return true;
}

/* sweep_clear(c, p, deg, ux, uy): the held squares, carried to point p (Utak's
 * point there), turned about p through deg degrees, meet no square blocked on the
 * model. Each held square is sampled at its centre, corners and sides' midpoints,
 * every PUSHTURN_SWEEP_STEP degrees: the object's outline lies within its held
 * squares, and a step of 1 degree moves no point of it more than 0.15 of a square. */
static bool sweep_clear(const Controller *c, Vec2 p, double deg, int32_t ux, int32_t uy)
{
	const WorldModel *m = &c->model;
	int32_t px = (int32_t)floor(p.x), py = (int32_t)floor(p.y);
	int steps = (int)ceil(fabs(deg) / PUSHTURN_SWEEP_STEP);
	for (int t = 1; t <= steps; t++) {
		double cs, sn;
		geom_cos_sin(deg * t / steps, &cs, &sn);
		for (int32_t k = 0; k < m->held_count; k++)
			for (int q = 0; q < 9; q++) {
				double x = px + m->held_dx[k] + 0.5 * (q % 3) - p.x;
				double y = py + m->held_dy[k] + 0.5 * (q / 3) - p.y;
				/* a point on a square's edge is taken a hair inside it */
				x += q % 3 == 0 ? 1e-6 : q % 3 == 2 ? -1e-6 : 0;
				y += q / 3 == 0 ? 1e-6 : q / 3 == 2 ? -1e-6 : 0;
				double rx = p.x + cs * x - sn * y, ry = p.y + sn * x + cs * y;
				int32_t sx = (int32_t)floor(rx), sy = (int32_t)floor(ry);
				bool held = sx == px && sy == py;
				for (int32_t j = 0; j < m->held_count && !held; j++)
					held = px + m->held_dx[j] == sx && py + m->held_dy[j] == sy;
				if (!held && blocked(c, sx, sy, ux, uy))
					return false;
			}
	}
	return true;
}

/* held_centre(c, at): the centre of the held squares (model frame); false when none. */
static bool held_centre(const Controller *c, Vec2 *at)
{
	const WorldModel *m = &c->model;
	if (m->held_count <= 0)
		return false;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	double sx = 0, sy = 0;
	for (int32_t k = 0; k < m->held_count; k++) {
		sx += ux + m->held_dx[k] + 0.5;
		sy += uy + m->held_dy[k] + 0.5;
	}
	*at = vec2(sx / m->held_count, sy / m->held_count);
	return true;
}

bool pushturn_active(const Controller *c)
{
	return c->turn_stage != TURN_NONE;
}

/* leads(c, deg, ahead): turned through deg about Utak's point, the held object
 * still leads him toward the corner along both axes: on each, its foremost
 * square's centre lies at least `ahead` squares beyond his point. WHY: the turn
 * swings the object round him, up to 45 degrees of its bearing from him, and can
 * put him between it and a wall, where seating presses him, not it, home (random world g85: squared up,
 * 2 short still, Utak against the wall beside the square): then he lets go and
 * fetches it again. */
static bool leads(const Controller *c, double deg, double ahead)
{
	const WorldModel *m = &c->model;
	int sx, sy;
	task_corner_signs(c->task.corner, &sx, &sy);
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	double cs, sn, ax = -INFINITY, ay = -INFINITY;
	geom_cos_sin(deg, &cs, &sn);
	for (int32_t k = 0; k < m->held_count; k++) {
		double x = ux + m->held_dx[k] + 0.5 - m->utak.x, y = uy + m->held_dy[k] + 0.5 - m->utak.y;
		ax = fmax(ax, sx * (cs * x - sn * y));
		ay = fmax(ay, sy * (sn * x + cs * y));
	}
	return ax >= ahead && ay >= ahead;
}

/* back_off(c, deg, d, dir): the fewest squares d (at most PUSHTURN_MAX_BACK) Utak
 * must draw the object back out of the corner, diagonally or along one axis (dir
 * into *dirs), along a way clear on the model, for the turn through deg to sweep
 * only squares clear on it; false when none. */
static bool back_off(const Controller *c, double deg, int *best_d, int best_dir[2])
{
	const WorldModel *m = &c->model;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	int sx, sy;
	task_corner_signs(c->task.corner, &sx, &sy);
	const int dirs[3][2] = {{-sx, -sy}, {-sx, 0}, {0, -sy}};
	*best_d = -1;
	for (int a = 0; a < 3; a++)
		for (int d = 0; d <= PUSHTURN_MAX_BACK && (*best_d < 0 || d < *best_d); d++) {
			int32_t x = ux + d * dirs[a][0], y = uy + d * dirs[a][1];
			if (d > 0 && !footprint_free(c, x, y, ux, uy))
				break;
			if (sweep_clear(c, vec2(m->utak.x + d * dirs[a][0], m->utak.y + d * dirs[a][1]), deg, ux, uy)) {
				*best_d = d;
				best_dir[0] = dirs[a][0];
				best_dir[1] = dirs[a][1];
			}
		}
	return *best_d >= 0;
}

bool pushturn_begin(Controller *c)
{
	const WorldModel *m = &c->model;
	if (c->turn_tries >= PUSHTURN_TRIES || !m->holding || m->held_count == 0 || c->clear_stage != 0 ||
	    c->task.kind != TASK_PUSH_CORNER)
		return false;
	double small;
	if (!pushturn_angle(m->held_dx, m->held_dy, m->held_count, &small))
		return false;
	/* A push only carries the object, never turns it: the slant read now must be
	 * the one read when he grasped it, within PUSHTURN_AGREE. WHY: pressed
	 * against another object the held set gains or loses squares and can read at
	 * a slant it does not have (tests/worlds/push-blocked-tilted.w: a square on
	 * the grid, pressed under a tilted triangle, read 24 degrees off, was turned,
	 * and lost). */
	double diff = fabs(small - c->turn_grasp_deg);
	if (!c->turn_grasp_slant || fmin(diff, 90.0 - diff) > PUSHTURN_AGREE)
		return false;
	/* Only the smaller way round (at most 45 degrees): the eye finds the held
	 * squares again after a turn by the disparity (worldmodel.c), and after
	 * turns of 48 and 51 degrees it put Utak a square or two off and seating
	 * stopped short (adversarial squares at 35 and 40 degrees). */
	int d, dir[2];
	if (back_off(c, small, &d, dir)) {
		c->turn_tries++;
		c->turn_stage = d > 0 ? TURN_BACK : TURN_TURN;
		c->turn_back_x = d * dir[0];
		c->turn_back_y = d * dir[1];
		c->turn_deg = small;
		/* Turned, it leads him toward both walls, or lies at most half a
		 * square behind his point (its front then within a square of the wall
		 * he meets, the judge's slack: random g170, 1 short): he keeps hold. */
		c->turn_keep = leads(c, small, -0.5);
		c->turn_from = m->utak;
		c->turn_first = true;
		return true;
	}
	return false;
}

/* let_go(c): the squaring up ends in letting go of the object, to fetch it again
 * from the side push_grasp_side finds best now (PHASE_RELEASE, then
 * pushturn_released). WHY: the turn swings the object round Utak and may leave
 * him between it and a wall (random g85: squared up, still 2 short, he against
 * the wall beside it); and the model carries the held squares through a turn only
 * by rotating their digital form: after 42 degrees it set him a square off at the
 * next push (the disparity corrected his place on a push that went as commanded)
 * and he claimed a square 2 short (adversarial a50, a false success). Let go of,
 * the object is seen afresh, and grasped anew its held squares are what the eye
 * finds then (wm_find_held). */
static void let_go(Controller *c)
{
	c->turn_stage = TURN_LETGO;
	c->turn_watch = false;
	c->phase = PHASE_RELEASE;
	held_centre(c, &c->turn_at);
}

bool pushturn_command(Controller *c, MotorCommand *cmd)
{
	if (c->turn_stage == TURN_BACK) {
		/* A push back that made no headway ends the backing: the turn is tried
		 * where he is (it halts if it meets something). */
		bool headway = c->turn_first || goals_distance(c->model.utak, c->turn_from) >= 0.5;
		if (headway && (c->turn_back_x || c->turn_back_y)) {
			int stepx = abs(c->turn_back_x) < 3 ? c->turn_back_x : (c->turn_back_x > 0 ? 3 : -3);
			int stepy = abs(c->turn_back_y) < 3 ? c->turn_back_y : (c->turn_back_y > 0 ? 3 : -3);
			c->turn_back_x -= stepx;
			c->turn_back_y -= stepy;
			c->turn_from = c->model.utak;
			c->turn_first = false;
			*cmd = (MotorCommand){.kind = MOTOR_PUSH, .dx = stepx, .dy = stepy};
			return true;
		}
		c->turn_stage = TURN_TURN;
	}
	if (c->turn_stage == TURN_TURN) {
		c->turn_stage = TURN_AGAIN;
		*cmd = (MotorCommand){.kind = MOTOR_TURN, .deg = c->turn_deg};
		return true;
	}
	if (c->turn_keep) {
		/* Turned, still holding: the push into the corner planned anew on the
		 * held squares the eye now finds, its circles its own, watched
		 * (pushturn_watch). */
		c->turn_stage = TURN_NONE;
		c->turn_watch = true;
		c->phase = PHASE_PUSH;
		c->have_plan = false;
		c->pushed_count = 0;
		return false;
	}
	let_go(c);
	return false;
}

bool pushturn_watch(Controller *c)
{
	if (!c->turn_watch || c->phase != PHASE_PUSH || !c->model.report.corrected)
		return false;
	let_go(c);
	return true;
}

bool pushturn_released(Controller *c)
{
	if (c->turn_stage != TURN_LETGO)
		return false;
	c->turn_stage = TURN_NONE;
	c->turn_fetch = true;
	c->have_plan = false;
	c->pushed_count = 0; /* the next push's circles are its own */
	c->stuck = 0;
	return true;
}

void pushturn_grasped(Controller *c)
{
	const WorldModel *m = &c->model;
	c->turn_grasp_slant = m->holding && pushturn_angle(m->held_dx, m->held_dy, m->held_count, &c->turn_grasp_deg);
	if (!c->turn_fetch)
		return;
	c->turn_fetch = false;
	Vec2 at;
	if (c->model.holding && held_centre(c, &at) && goals_distance(at, c->turn_at) <= PUSHTURN_SAME)
		return;
	c->phase = PHASE_FAILED;
	snprintf(c->why, sizeof c->why,
		 "what Utak grasped again is not the %s he turned square to the walls (its squares' centre %.1f from where he let it go)",
		 task_shape_name(c->task.shape), c->model.holding && held_centre(c, &at) ? goals_distance(at, c->turn_at) : -1.0);
}
