/* svg.h - a picture of a run, for people who would rather look than read.
 * SIMULATOR SIDE (it draws the real world), and an observer of the controller.
 *
 * One SVG document, north up, one TABLE square SVG_SCALE pixels: a title (the task
 * and the verdict); the TABLE at the end (floor, verge and walls, the objects in
 * colour with their names); what Utak came to believe, drawn once each: the outline
 * of every object in his world model (dashed) and the edge of the floor he believes
 * in (dotted); the skeleton of his last plan with its pathgraph's edges and vertices
 * (paper Figure 3); the path he took (the trail of his true positions, arrows giving
 * the direction, the start ringed) and, on top, the route he planned last; Utak where
 * he ended; and a legend. The view box holds everything drawn: the TABLE, and any
 * belief that strays past it. Colours are the Okabe-Ito set, told apart by colour-
 * blind readers, and each kind of line also has a dash pattern of its own, so the
 * picture reads in grey print.
 *
 * Element ids, for tests and style sheets: title, table, objects, model (one path per
 * believed object, class "object"), floor-edge, skeleton, pathgraph, trail, route,
 * start, utak, legend. */
#ifndef UTAK_SVG_H
#define UTAK_SVG_H

#include <stdio.h>

#include "utak/body/table.h"
#include "utak/body/world.h"
#include "utak/mind/controller.h"

#define SVG_SCALE 12

/* svg_draw(f, w, t, c, trail, n, title, verdict): the picture of a run that ended
 * with world w (TABLE t) and controller c; trail holds Utak's n >= 1 true positions,
 * the start first; title names the task, verdict is the verdict line. */
void svg_draw(FILE *f, const World *w, const Table *t, const Controller *c, const Vec2 *trail,
              int n, const char *title, const char *verdict);

#endif
