/* thinwall.h - an object that may be a stretch of a thin wall whose rest the coarse
 * cells read as faint floor (paper 3.4.2, 2.2; issue 13, "a wall seen must not
 * vanish"). CONTROLLER SIDE: the screen and the world model's evidence only;
 * doorsure.c asks it on its readings that take faint floor for wall.
 *
 * WHY. A wall 1 thick seen from afar lies in the eye's 4 x 4 cells as 4 of their
 * 16 squares, level 2: the world model spreads that over the cell as floor below
 * half occupied (faint.h, FAINT). The stretch of it the fovea or the 2 x 2 cells
 * have seen (Utak walked past it) is occupied, but with its two ends joined to the
 * TABLE's edge or another wall only by faint floor it is an occupied set apart from
 * the verge: an OBJECT to the model, and the screen counts objects as space to the
 * rooms (screen.h, fixed). doorsure.h's reading "faint floor taken for wall"
 * closed the faint ends but left that stretch open, so a door in the wall was a
 * gap of the stretch's length plus the door, no door, and the rooms one: on
 * tests/gen/tworooms.py's two-room grid (a wall 1 thick across a 40 x 30 TABLE, the
 * door 3 or 4 wide) Utak walked through the door into the next room's corner and
 * claimed it (37 false successes of 4320 runs at main 742d775, the trace of
 * h10-t1-d3-x15-s0-east "go nw-corner": the stretch beside the door object2, its
 * ends faint at p 0.2 to 0.35 from the peripheral cells).
 *
 * THE RULE. A set of faint screen cells (8-connected) that touches the verge (or
 * the screen's edge) and an object at most THINWALL_MOST_THICK deep on the mean
 * (its squares over its rectangle's longer side) JOINS that object to the wall; an object joined
 * so, or joined by such a set to an object already joined, may be wall. Its cells
 * are returned in `block`; the faint cells of the joining sets in `look` (a look
 * in the fovea settles them: occupied, the stretch is the verge's; zero, it stands
 * apart). The object Utak holds is never joined (touch shows it an object). */
#ifndef UTAK_THINWALL_H
#define UTAK_THINWALL_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/screen.h"
#include "utak/mind/worldmodel.h"

/* The most squares deep an object may be on the mean, its squares over its
 * rectangle's longer side, to be a stretch of thin wall (thinwall.c, thin_bar). */
#define THINWALL_MOST_THICK 3.0

/* thinwall_marks(m, s, unseen, block, look): block and look (w x h arrays over
 * screen s, built from model m, zeroed by the caller; look may be NULL) set to 1 as
 * THE RULE says, a set touching the unseen joining too when unseen (the wall may run
 * on where the eye has not been); returns the number of objects joined. COMPLEXITY: O(w h) a pass,
 * a pass for each object joined in a chain (at most the objects on the screen, plus one). */
int32_t thinwall_marks(const WorldModel *m, const Screen *s, bool unseen, uint8_t *block,
                       uint8_t *look);

#endif
