/* motion.c - the motion and collision of Utak and the objects (paper 2.1, 2.2). SIMULATOR SIDE.
 *
 * ALGORITHM. TABLETOP's approximate collision (paper 2.1): a motion is cut into
 * steps of at most MOTION_STEP squares of travel for any point of the moving
 * shapes; at each step the shapes are re-projected onto the TABLE from their
 * Cartesian representation, and a step whose projection meets a square of
 * another colour is refused. The command then halts at the last legal pose,
 * refined by bisection inside the refused step. Poses are always computed from
 * the pose at the start of the command (start + fraction x motion), never by
 * adding steps, so no rounding drifts in.
 *
 * What collides: the moving object's squares may be floor or its own; Utak's
 * square may be floor, or the held object's (he is a point outside the polygon,
 * but the two digital shapes can share a square), or his current square when an
 * object he let go of shares it, so long as his point does not enter that object.
 *
 * INVARIANT kept: table_validate(). COMPLEXITY: per step, O(squares of the
 * moving shape) to clear, test and stamp it. */
#include "utak/body/motion.h"

#include <math.h>
#include <string.h>

/* A pose of the moving set, as a fraction f in [0, 1] of the whole command. */
typedef struct Motion {
	World *w;
	Table *t;
	MotorKind kind;
	Vec2 utak0;		/* Utak's point at the start */
	Polygon shape0;		/* the held object at the start (push, turn) */
	Vec2 delta;		/* move, push: TABLE displacement */
	double deg;		/* turn */
	int32_t blocker;	/* who refused the last illegal pose */
} Motion;

static Polygon motion_shape_at(const Motion *m, double f)
{
	Polygon p = m->shape0;
	if (m->kind == MOTOR_PUSH) {
		for (int32_t i = 0; i < p.count; i++)
			p.v[i] = vec2_add(p.v[i], vec2_scale(m->delta, f));
	} else if (m->kind == MOTOR_TURN) {
		double c, s;
		geom_cos_sin(m->deg * f, &c, &s);
		for (int32_t i = 0; i < p.count; i++)
			p.v[i] = geom_rotate(p.v[i], m->utak0, c, s);
	}
	return p;
}

static Vec2 motion_utak_at(const Motion *m, double f)
{
	if (m->kind == MOTOR_TURN)
		return m->utak0;
	return vec2_add(m->utak0, vec2_scale(m->delta, f));
}

/* enters_polygon(p, a, b): Utak's step from a to b ends inside p or crosses one
 * of its edges. Needed only where his square is shared with an object (he let go
 * of it beside him): there the TABLE cannot tell whether his point stays out. */
static bool enters_polygon(const Polygon *p, Vec2 a, Vec2 b)
{
	if (table_point_inside(p, b))
		return true;
	for (int32_t i = 0; i < p->count; i++) {
		Vec2 c = p->v[i], d = p->v[(i + 1) % p->count];
		/* The edge he stands on (table.h, TABLE_TOUCH): leaving it is no crossing. */
		if (geom_point_segment_distance(a, c, d) <= TABLE_TOUCH)
			continue;
		double o1 = geom_orient(a, b, c), o2 = geom_orient(a, b, d);
		double o3 = geom_orient(c, d, a), o4 = geom_orient(c, d, b);
		if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
			return true;
	}
	return false;
}

/* motion_try(m, f): moves the world to pose f if that pose is legal. The held
 * object is lifted off the TABLE, tested at the new pose and put down at the new
 * or the old one. */
static bool motion_try(Motion *m, double f)
{
	World *w = m->w;
	Table *t = m->t;
	int32_t held = w->held;
	Vec2 u = motion_utak_at(m, f);
	Polygon p;
	if (held >= 0) {
		p = motion_shape_at(m, f);
		table_clear_object(t, &w->objects[held].shape, held);
		int32_t x, y;
		int32_t who = table_conflict(t, &p, held, &x, &y);
		if (who != TABLE_FLOOR) {
			table_stamp_object(t, &w->objects[held].shape, held);
			m->blocker = who;
			return false;
		}
	}
	int32_t ux, uy, cx, cy;
	table_square_of(u, &ux, &uy);
	table_square_of(w->utak, &cx, &cy);
	int32_t who = table_owner(t, ux, uy);
	bool utak_ok = who == TABLE_FLOOR ||
		       (ux == cx && uy == cy && who > 0 && !enters_polygon(&w->objects[who - 1].shape, w->utak, u));
	if (!utak_ok && held >= 0) {
		/* His square may be one the held object's new projection claims. */
		table_stamp_object(t, &p, held);
		utak_ok = table_owner(t, ux, uy) == held + 1;
		table_clear_object(t, &p, held);
	}
	if (!utak_ok) {
		if (held >= 0)
			table_stamp_object(t, &w->objects[held].shape, held);
		m->blocker = who;
		return false;
	}
	if (held >= 0) {
		table_stamp_object(t, &p, held);
		w->objects[held].shape = p;
	}
	w->utak = u;
	return true;
}

static void blocker_name(const World *w, int32_t who, char *buf, size_t size)
{
	if (who == TABLE_VERGE)
		snprintf(buf, size, "blocked by the verge");
	else if (who > 0)
		snprintf(buf, size, "blocked by '%s'", w->objects[who - 1].name);
	else
		snprintf(buf, size, "blocked");
}

/* motion_run(m, steps, out): steps through f = 1/steps, 2/steps, ... 1. */
static void motion_run(Motion *m, int64_t steps, MotorOutcome *out)
{
	double f = 0;
	for (int64_t k = 1; k <= steps; k++) {
		double next = (double)k / (double)steps;
		if (motion_try(m, next)) {
			f = next;
			continue;
		}
		int32_t blocker = m->blocker;
		double lo = f, hi = next;
		for (int i = 0; i < MOTION_BISECTIONS; i++) {
			double mid = (lo + hi) / 2;
			if (motion_try(m, mid))
				lo = mid;
			else
				hi = mid;
		}
		f = lo;
		out->halted = true;
		blocker_name(m->w, blocker, out->what, sizeof out->what);
		break;
	}
	out->done = out->asked * f;
}

/* ---- noise (motion.h, "NOISY MOTION") ---------------------------------------------- */

void motion_noise_init(MotionNoise *n, double sigma, uint64_t seed)
{
	n->sigma = sigma;
	n->state = seed;
}

/* splitmix64(state): the next 64 random bits (Steele, Lea and Flood 2014). */
static uint64_t splitmix64(uint64_t *state)
{
	uint64_t z = (*state += 0x9E3779B97F4A7C15u);
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
	return z ^ (z >> 31);
}

double motion_noise_gaussian(MotionNoise *n)
{
	/* Box-Muller with u1 in (0, 1]: 53 random bits, never 0, so the log is finite.
	 * One of the pair is used: the other would need state between calls. */
	double u1 = ((double)(splitmix64(&n->state) >> 11) + 1.0) / 9007199254740992.0;
	double u2 = (double)(splitmix64(&n->state) >> 11) / 9007199254740992.0;
	return sqrt(-2.0 * log(u1)) * cos(2.0 * 3.14159265358979323846 * u2);
}

static bool motion_noisy(const MotionNoise *n) { return n && n->sigma > 0; }

/* ---- the commands ------------------------------------------------------------------- */

static void motion_translate(World *w, Table *t, const MotorCommand *cmd, MotionNoise *noise,
			     MotorOutcome *out)
{
	Vec2 own = vec2(cmd->dx, cmd->dy);
	double len = hypot(own.x, own.y);
	out->asked = len;
	if (cmd->kind == MOTOR_MOVE && w->held >= 0) {
		out->refused = true;
		snprintf(out->what, sizeof out->what, "holding '%s' (push it, or release it first)",
			 w->objects[w->held].name);
		return;
	}
	if (cmd->kind == MOTOR_PUSH && w->held < 0) {
		out->refused = true;
		snprintf(out->what, sizeof out->what, "not holding anything (grasp first)");
		return;
	}
	Motion m = {.w = w, .t = t, .kind = cmd->kind, .utak0 = w->utak,
		    .delta = world_own_to_table(w->heading, own)};
	if (motion_noisy(noise) && len > 0) {
		double ex = motion_noise_gaussian(noise), ey = motion_noise_gaussian(noise);
		m.delta = vec2_add(m.delta, vec2_scale(vec2(ex, ey), noise->sigma * len));
		len = hypot(m.delta.x, m.delta.y);
	}
	if (w->held >= 0)
		m.shape0 = w->objects[w->held].shape;
	double asked = out->asked;
	out->asked = len;
	motion_run(&m, (int64_t)fmax(1, ceil(len / MOTION_STEP)), out);
	out->asked = asked;
}

static void motion_turn_exact(World *w, Table *t, const MotorCommand *cmd, MotorOutcome *out)
{
	out->asked = cmd->deg;
	if (w->held < 0) {
		out->refused = true;
		snprintf(out->what, sizeof out->what, "not holding anything (grasp first)");
		return;
	}
	Motion m = {.w = w, .t = t, .kind = MOTOR_TURN, .utak0 = w->utak, .deg = cmd->deg,
		    .shape0 = w->objects[w->held].shape};
	/* No vertex may travel more than MOTION_STEP in one step: the farthest one
	 * sets the angle. (Edges, being straight, travel no farther than their ends.) */
	double r = 0;
	for (int32_t i = 0; i < m.shape0.count; i++)
		r = fmax(r, hypot(m.shape0.v[i].x - m.utak0.x, m.shape0.v[i].y - m.utak0.y));
	double step_deg = r > 0 ? (MOTION_STEP / r) * (180.0 / 3.14159265358979323846) : 360;
	/* A turn past a full circle sweeps no pose the first circle did not, and only
	 * the held object moves: when the first circle is free, so is the rest, and
	 * only its last part, deg mod 360, need be swept. (Sweeping it all made
	 * "turn 1000000" of a long object take most of an hour.) */
	double skipped = 0;
	if (fabs(cmd->deg) > 360) {
		m.deg = cmd->deg > 0 ? 360 : -360;
		out->asked = m.deg;
		motion_run(&m, (int64_t)ceil(360 / step_deg), out);
		out->asked = cmd->deg;
		if (out->halted)
			return;
		m.shape0 = w->objects[w->held].shape;
		m.deg = fmod(cmd->deg, 360);
		skipped = cmd->deg - m.deg;
	}
	out->asked = m.deg;
	motion_run(&m, (int64_t)fmax(1, ceil(fabs(m.deg) / step_deg)), out);
	out->asked = cmd->deg;
	out->done += skipped;
}

static void motion_turn(World *w, Table *t, const MotorCommand *cmd, MotionNoise *noise,
			MotorOutcome *out)
{
	MotorCommand noisy = *cmd;
	if (motion_noisy(noise) && w->held >= 0)
		noisy.deg += motion_noise_gaussian(noise) * noise->sigma * fabs(cmd->deg);
	motion_turn_exact(w, t, &noisy, out);
	out->asked = cmd->deg;
}

static void motion_grasp(World *w, const Table *t, MotorOutcome *out)
{
	if (w->held >= 0) {
		out->refused = true;
		snprintf(out->what, sizeof out->what, "already holding '%s'", w->objects[w->held].name);
		return;
	}
	/* His own square first (after a release he may share one), then the eight
	 * around him in the tactile order. */
	int32_t x, y;
	table_square_of(w->utak, &x, &y);
	int32_t who = table_owner(t, x, y);
	for (int k = 0; k < 8 && who <= 0; k++) {
		world_touch_square(w, k, &x, &y);
		who = table_owner(t, x, y);
	}
	if (who <= 0) {
		out->refused = true;
		snprintf(out->what, sizeof out->what, "no object within touch");
		return;
	}
	w->held = who - 1;
	snprintf(out->what, sizeof out->what, "holding '%s' (%c)", w->objects[w->held].name,
		 w->objects[w->held].colour);
}

void motion_execute(World *w, Table *t, const MotorCommand *cmd, MotorOutcome *out)
{
	motion_execute_noisy(w, t, cmd, NULL, out);
}

void motion_execute_noisy(World *w, Table *t, const MotorCommand *cmd, MotionNoise *noise,
			  MotorOutcome *out)
{
	memset(out, 0, sizeof *out);
	switch (cmd->kind) {
	case MOTOR_MOVE:
	case MOTOR_PUSH:
		motion_translate(w, t, cmd, noise, out);
		break;
	case MOTOR_TURN:
		motion_turn(w, t, cmd, noise, out);
		break;
	case MOTOR_GRASP:
		motion_grasp(w, t, out);
		break;
	case MOTOR_RELEASE:
		if (w->held < 0) {
			out->refused = true;
			snprintf(out->what, sizeof out->what, "not holding anything");
		} else {
			snprintf(out->what, sizeof out->what, "released '%s'", w->objects[w->held].name);
			w->held = -1;
		}
		break;
	}
}

/* shown(v): v as printed with %.2f, without a "-0.00". */
static double shown(double v) { return fabs(v) < 0.005 ? 0.0 : v; }

void motion_print(const MotorCommand *cmd, const MotorOutcome *out, FILE *f)
{
	static const char *const names[] = {"move", "grasp", "push", "turn", "release"};
	fputs(names[cmd->kind], f);
	if (cmd->kind == MOTOR_MOVE || cmd->kind == MOTOR_PUSH)
		fprintf(f, " %.2f %.2f", shown(cmd->dx), shown(cmd->dy));
	else if (cmd->kind == MOTOR_TURN)
		fprintf(f, " %.2f", shown(cmd->deg));
	if (out->refused) {
		fprintf(f, ": refused: %s", out->what);
		return;
	}
	const char *verb = cmd->kind == MOTOR_MOVE ? "moved" : cmd->kind == MOTOR_PUSH ? "pushed" : "turned";
	switch (cmd->kind) {
	case MOTOR_MOVE:
	case MOTOR_PUSH:
	case MOTOR_TURN:
		if (out->halted)
			fprintf(f, ": halted after %.2f of %.2f: %s", shown(out->done), shown(out->asked),
				out->what);
		else
			fprintf(f, ": %s %.2f", verb, shown(out->done));
		break;
	default:
		fprintf(f, ": %s", out->what);
	}
}
