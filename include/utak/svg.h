/* svg.h - a picture of a run, for people who would rather look than read.
 * SIMULATOR SIDE (it draws the real world), and an observer of the controller.
 *
 * One SVG document: the TABLE (floor, verge, objects in colour), what Utak came to
 * believe (the world model's outlines, dashed), the skeleton and pathgraph of his
 * last plan, the route he planned, and the path he took (the trail of his true
 * positions). One TABLE square is SVG_SCALE pixels; north is up. */
#ifndef UTAK_SVG_H
#define UTAK_SVG_H

#include <stdio.h>

#include "utak/mind/controller.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

#define SVG_SCALE 12

void svg_draw(FILE *f, const World *w, const Table *t, const Controller *c, const Vec2 *trail, int n);

#endif
