/* fovealook.h - where to stand so that the fovea shows a square (paper 2.2: the
 * fovea is the eye's finest zone; paper 3.3: "where his model cannot tell, he
 * goes and looks", issue 13 item 6). CONTROLLER SIDE: it reads the screen Utak
 * plans on and the way there, nothing else.
 *
 * WHY. A square of an object, or of the floor round it, seen only in the eye's
 * coarser cells is confirmed only by the fovea: the 8 x 8 squares at offsets
 * -4..3 from Utak's own (eye.h), and his heading never changes, so it reaches
 * four squares west and south of him but three east and north. The place nearest
 * the square (goals_near) may leave it just outside: random g100 stood beside a
 * piece 7 wide, the square 4 rows north of him, inside the piece, and the look
 * there showed nothing more ("nothing more to see or touch from here": a doubt
 * that a rival nearer the start may be the square stood, rival.h); from its north
 * side the fovea holds it. And a place that holds only that square leaves the
 * next one just outside: random g298 crept along a piece a square a look.
 *
 * WHAT. fovealook_place chooses, among the screen's cells Utak can reach, one
 * whose fovea holds the square: the one whose fovea holds the most of the squares
 * still to be seen (a count the caller gives, e.g. objects_lacks for a rival),
 * then the nearest by the way there (dist), then the first in the screen's order
 * (deterministic). Only the 64 places whose fovea holds the square are weighed.
 * COST: 64 places, each counting over its 64 squares. */
#ifndef UTAK_FOVEALOOK_H
#define UTAK_FOVEALOOK_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/mind/screen.h"

/* fovealook_count: how many squares still to be seen Utak's fovea holds when he
 * stands on model square (px, py) (ctx: the caller's). */
typedef int32_t (*FovealookCount)(void *ctx, int32_t px, int32_t py);

/* fovealook_place(s, dist, x, y, count, ctx, &goal): the centre of the screen
 * cell (model frame) chosen above for model square (x, y); dist is s's cells'
 * way from Utak (-1 unreachable; goals_reach); count may be NULL (all count 0).
 * False, goal untouched, when no reachable cell's fovea holds the square. */
bool fovealook_place(const Screen *s, const int32_t *dist, int32_t x, int32_t y, FovealookCount count, void *ctx,
		     Vec2 *goal);

#endif
