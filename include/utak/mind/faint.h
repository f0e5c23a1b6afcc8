/* faint.h - floor the coarse cells read, but not as empty (paper 3.4.2; issue 13).
 * CONTROLLER SIDE: goals.c and objects.c ask it before Utak believes that no object
 * of the task's shape lies nearer the start, or that none is on the TABLE at all.
 *
 * FAINT: the eye's coarse cells give the share of a block that is occupied, not
 * which squares (READING.md: a cell of 2 x 2 or 4 x 4 squares, its level the
 * nearest of 0..7 to the share). A square of the judge's sizes can spread over
 * several such cells so that each holds less than half of its own squares: a
 * square 3 wide over four cells of 4 holds 1, 2, 2 and 4 of their 16 squares,
 * levels 0, 1, 1 and 2; the world model (worldmodel.c) then believes every
 * square of all four cells floor, below half occupied, and the square is gone
 * from the model. Only a zero cell is floorspace (paper 3.4.2): a square the
 * model believes floor, read only by such cells and by at least one that was not
 * zero, is faint, and may be part of an object. Seen in the fovea (squares of
 * one) it is settled. tests/worlds/faint-nearer.w: the judge's square, 3 wide,
 * seen only faint from the start while a square 4 wide, farther, read clear;
 * Utak went to the farther one and believed it the nearest (a false success).
 * So: faint floor nearer the start than the object he would claim is a doubt
 * (objects.c, as unseen space is), and goals.c sends him first to stand within
 * the fovea's reach of it; and before he says no object of the task's shape is
 * seen, he looks at faint floor anywhere (tests/worlds/faint-alone.w: a lone
 * square 3 wide was never seen). Faint floor along walls and other objects is
 * left out (faint.c, faint_marks: the share a coarse cell holds of their edge).
 * Measured (tests/unit/test_faint.c, the simulator as oracle): of 400 squares 2.1
 * to 4.5 wide at random angles and phases in the coarse zones, 57 leave no square
 * believed occupied after the first impression, and every one leaves faint floor.
 *
 * LIMIT: a cell of 4 x 4 holding one occupied square of its 16 reads zero
 * (READING.md), so four zero cells of 4 can hide a square exactly 2 wide that
 * lies on the corner they share, squarely; no faint square marks it. The
 * judge's least width is 2 (judgeshape.h), so such a square is the judge's;
 * the rule below does not see it (test_faint.c shows it; README, Reliability);
 * nor a square hidden faint within a coarse cell's reach of a wall or another
 * object (faint.c). */
#ifndef UTAK_FAINT_H
#define UTAK_FAINT_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/mind/screen.h"
#include "utak/mind/worldmodel.h"

struct Controller;

/* How far from where Utak stands the fovea reaches every way, whatever his
 * heading: its squares are those at offsets -4..3 (eye.h, EYE_FOVEA_HALF). */
#define FAINT_FOVEA_REACH 3

/* faint_cell(m, s, k): screen cell k (of s, built from m) is faint: believed floor,
 * read only in cells of 2 x 2 or 4 x 4 squares, and its estimate not zero, which
 * a cell that was not zero left. hallsplit.h's FAINT asks the same. */
bool faint_cell(const WorldModel *m, const Screen *s, int64_t k);
/* faint_marks(m, s, centre, radius): a w x h array over screen s (built from model
 * m), 1 where the cell is faint (FAINT), its centre lies under radius from centre
 * (INFINITY: any), and its 8-connected set of faint cells touches no cell s holds
 * occupied (verge, wall or object: faint.c says why); the caller frees. */
uint8_t *faint_marks(const WorldModel *m, const Screen *s, Vec2 centre, double radius);
/* faint_within(c, centre, radius): some faint square's centre lies under radius
 * from centre. */
bool faint_within(const struct Controller *c, Vec2 centre, double radius);
/* faint_look(c, dist, centre, radius, goal): the reachable cell (dist: steps from
 * Utak on the screen, goals_reach) nearest him, not yet visited, from which the
 * fovea shows a faint square whose centre lies under radius from centre (INFINITY:
 * any); false if none. COMPLEXITY: O(w h) on the screen. */
bool faint_look(const struct Controller *c, const int32_t *dist, Vec2 centre, double radius, Vec2 *goal);

#endif
