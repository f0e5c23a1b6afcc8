/* carryoutline.h - private to the carrying tasks (carrytask.c): the object's
 * outline from its squares on the screen, and two polygon sums (paper 3.6, 5).
 * CONTROLLER SIDE. */
#ifndef UTAK_MIND_CARRYOUTLINE_H
#define UTAK_MIND_CARRYOUTLINE_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/mind/controller.h"

/* carryoutline_object(c, k, out): object node k's outline from its squares on the
 * screen, in screen units: the outer boundary of their 4-connected set, counter-
 * clockwise, its vertices where it turns; the convex hull of the squares' corners
 * when that has more than GEOM_MAX_VERTICES. False when neither can be made. */
bool carryoutline_object(const Controller *c, int32_t k, Polygon *out);

/* carryoutline_moved(p, by): p moved by the vector by. */
Polygon carryoutline_moved(const Polygon *p, Vec2 by);

/* carryoutline_centroid(p): p's centroid (the area's); its first vertex when it
 * has no area. */
Vec2 carryoutline_centroid(const Polygon *p);

#endif
