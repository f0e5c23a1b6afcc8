/* pushslant.c - how far short of its corner a slanted rectangle must stay (paper 2.2,
 * 2.3 task (v)). CONTROLLER SIDE: the held squares and what was read at the grasp.
 * See pushslant.h for the bound and its proof. */
#include "utak/mind/pushslant.h"

#include <math.h>

#include "utak/mind/pushturn.h"
#include "utak/mind/shape.h"

static const double pushslant_pi = 3.14159265358979323846;

int64_t pushslant_bound(double w, double deg)
{
	double t = fmod(fabs(deg), 90.0);
	if (t > 45.0)
		t = 90.0 - t;
	double r = t * pushslant_pi / 180.0, v = w * sin(r) - tan(r) - 1.0;
	if (v < 0)
		return 0;
	return (int64_t)floor(v) + 1;
}

bool pushslant_short(const Controller *c, double *deg, double *w, int64_t *bound)
{
	const WorldModel *m = &c->model;
	double now;
	if (!m->holding || m->held_count == 0 || !c->turn_grasp_slant ||
	    !pushturn_angle(m->held_dx, m->held_dy, m->held_count, &now))
		return false;
	/* The same slant as at the grasp (a push never turns the object): else the
	 * reading is the held set's, pressed against something, not the object's. */
	double diff = fabs(now - c->turn_grasp_deg);
	if (fmin(diff, 90.0 - diff) > PUSHTURN_AGREE)
		return false;
	ShapeReading r;
	shape_read(m->held_dx, m->held_dy, m->held_count, 1.0, &r);
	double t = fmin(fabs(now), fabs(c->turn_grasp_deg));
	int64_t b = pushslant_bound(r.min_width, t);
	if (b <= CONTROLLER_CORNER_SLACK)
		return false;
	*deg = fabs(now);
	*w = r.min_width;
	*bound = b;
	return true;
}
