/* path.c - a plan's path as a polyline (see path.h; paper 3.6). */
#include "utak/plan/path.h"

#include <math.h>
#include <stdlib.h>

#include "utak/base/util.h"

void path_init(Path *p) { *p = (Path){0}; }

void path_free(Path *p)
{
	free(p->pts);
	*p = (Path){0};
}

void path_clear(Path *p)
{
	p->count = 0;
	p->expanded = 0;
}

void path_push(Path *p, Vec2 q)
{
	p->pts = util_grow(p->pts, &p->cap, p->count + 1, sizeof *p->pts);
	p->pts[p->count++] = q;
}

double path_length(const Path *p)
{
	double len = 0;
	for (int i = 1; i < p->count; i++)
		len += hypot(p->pts[i].x - p->pts[i - 1].x, p->pts[i].y - p->pts[i - 1].y);
	return len;
}
