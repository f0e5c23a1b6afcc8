/* pushseen.h - what the eye and touch establish of a pushed object's place before
 * Utak claims it in a corner (paper 3.4.1: a cell's gray level is how many of its
 * squares are occupied; 3.5: the held object's place is inferred from his own
 * motion, and the impression is the only check on it; 3.4.2: touch tells an object
 * from the wall; 2.3 task (v)). CONTROLLER SIDE: called by push.c's push_seat_finish.
 *
 * A cell of the retina over s x s squares has the level round(7 k / s^2) of the k of
 * them occupied: for a fovea cell (1 x 1) and an intermediate one (2 x 2) every k
 * has its own level, for a peripheral one (4 x 4) two k may share one. A square of
 * the held set is ESTABLISHED when the last impression leaves no way for it to be
 * floor: every count the level allows fills its whole cell. */
#ifndef UTAK_PUSHSEEN_H
#define UTAK_PUSHSEEN_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"

/* pushseen_counts(level, n, &kmin, &kmax): the least and most occupied squares of n
 * (1, 4 or 16) a cell at this gray level may hold (eye_level(k, n) == level); false,
 * and nothing set, when no count gives that level. */
bool pushseen_counts(int level, int32_t n, int32_t *kmin, int32_t *kmax);

/* pushseen_forced(level, n): every square of a cell of n squares at this level is
 * occupied, by every count the level allows (a 1 x 1 or 2 x 2 cell at level 7; a
 * 4 x 4 cell never: level 7 is 15 of 16 as well). WHY not fewer, with the cell's
 * squares the model knows floor set aside: that knowledge may be older than the
 * object's arrival, and a finer look is not overwritten by a coarser one. */
bool pushseen_forced(int level, int32_t n);

/* pushseen_check(c, short_by, at): after seating, whether the last impression
 * fails to establish that the held object reaches within CONTROLLER_CORNER_SLACK of
 * the corner (short_by: goals_corner_shortfall, by all the held squares): true
 * when the held squares it establishes (pushseen_forced) fall short by more than
 * the slack of the best floor seen in the start's room or of the held square the
 * model has farthest toward the corner, or it establishes none. WHY the second:
 * after a turn the held set is a guess (heldobject.c wm_refind_held), and a
 * square of it the eye has not shown may be floor that beats the object; a square
 * 8 wide turned 45 degrees, squared up and pushed into a corner, kept two columns
 * the eye saw only in 4 x 4 cells, the best floor the model knew lay behind them,
 * and Utak claimed it 2 short (tests/worlds/turned-square-push.w). The cost: the
 * far squares of an object 10 wide, seen from behind it, lie in 4 x 4 cells,
 * which establish nothing (a 4 x 4 cell at level 7 leaves one square floor, and
 * counting the second best held square of such a cell gave the false success
 * back: the cell's other occupied squares were the wall's), so such a push is
 * doubted (tests/golden/big-square-push);
 * at is then set to the held square the model has nearest the corner. Holding
 * nothing (the subject is Utak's own square) it is false. */
bool pushseen_check(const Controller *c, int64_t short_by, Vec2 *at);

/* pushseen_beyond(k, hx, hy, nh, x, y): square (x, y) lies farther toward corner k
 * than every one of the nh squares (hx, hy), by the judge's measure of a corner
 * (its score, goals_corner_score: x + y with the corner's signs, which orders
 * squares as the L1 distance to the room's corner point does, reversed). False
 * with nh 0. */
bool pushseen_beyond(Corner k, const int32_t *hx, const int32_t *hy, int32_t nh, int32_t x,
                     int32_t y);

/* pushseen_felt_object(c, at): after seating, whether touch has felt an object's
 * letter (not the verge's B) on a square the model holds occupied and takes for
 * wall (c->felt_x, y: objects_feel), not one of the held squares, that lies
 * farther toward the task's corner than the whole held object (pushseen_beyond)
 * and borders the held object or floor of the start's room; *at is then the
 * centre of the one nearest the corner. WHY: the judge counts an object's squares
 * as the room's (judge.h), and an object pressed into the corner reads, to the
 * eye, as the wall it leans on (paper 3.4.2): the square pushed against it stops
 * short of the judge's corner while the model's best floor is beside it. Touch
 * is the sense that tells an object from the wall, and surveying the corner
 * before the push (controller.c) brings him beside such an object; how far it
 * reaches into the corner the eye cannot say, so any square of it beyond the held
 * object puts the claim in doubt (as roomclaim_felt_object does for task (i)).
 * Hand-written worlds: a triangle, a brick and a square pressed into the corner
 * (set 2 h107 and h111, set 3 h231), 5, 3 and 7 short, were claimed. */
bool pushseen_felt_object(const Controller *c, Vec2 *at);

#endif
