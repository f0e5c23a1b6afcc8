/* path.h - a plan's path: a polyline, the common result of every planner (paper 3.6, 4).
 *
 * The skeleton planner, grid A* and the visibility graph all return a Path, so
 * that they can be dumped, drawn, measured and compared the same way. Points are
 * in the units of the grid the planner worked on (see grid.h: cell (x, y) has
 * centre (x + 0.5, y + 0.5)). */
#ifndef UTAK_PATH_H
#define UTAK_PATH_H

#include <stdint.h>

#include "utak/base/geom.h"

typedef struct Path {
	int count, cap;		/* points used, points allocated */
	Vec2 *pts;		/* the polyline, start first */
	int64_t expanded;	/* search effort: cells or vertices expanded */
} Path;

void path_init(Path *p);
void path_free(Path *p);
void path_clear(Path *p);
void path_push(Path *p, Vec2 q);
/* path_length: the Euclidean length of the polyline. */
double path_length(const Path *p);

#endif
