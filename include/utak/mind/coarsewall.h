/* coarsewall.h - wall seen only in coarse cells that juts out further than any
 * wall's face so seen can: where an object may be merged with it (paper 3.4.1,
 * 3.4.2; issue 13, an honest belief). CONTROLLER SIDE: faint.c and objects.c ask it
 * before Utak believes that no object of the task's shape lies nearer the start.
 *
 * WHY. Regions (paper 3.4.1) join every non-zero cell to its neighbours, and the
 * world model believes occupied every square of a coarse cell at least half full
 * (worldmodel.h). A square 3 to 5 wide lying 1 to 2.5 squares off the verge, seen
 * only in the eye's 4 x 4 cells, fills the cells over it and those over the gap
 * read at least half full too (they hold verge and object): the model has one
 * occupied set, the verge with a bump, and no object. Utak then claimed a farther
 * square in open floor as "the square", the nearest to his start (a false
 * success: 21 of 24 worlds of big14's joined.py).
 *
 * WHAT A WALL'S FACE EXPLAINS. A cell of 4 x 4 is believed whole occupied when at
 * least 8 of its 16 squares are (READING.md: 8 of 16 is level 4, 4/7 >= 1/2), so
 * where the face of a wall runs through a row of cells, the model's face lies at
 * most 2 squares out from the true one (a cell holding 2 of its 4 columns of wall
 * is believed whole), and a wall's face seen in 2 x 2 cells, at most 1. Where a
 * wall's face is straight over a stretch, its believed face is then a band 2
 * squares deep at most; a corner of two faces, the same on each. So a part of the
 * model's occupied set that juts from it as a neck (bounded by believed floor on
 * both flanks) for COARSEWALL_LEAST_HEIGHT rows or more, 3 > 2, is more than a
 * coarse reading of a face explains: something stands there, a wall's stub or an
 * object joined to the wall by the cells over the gap between them. The eye's
 * fovea (cells of one square) shows the gap if there is one; until it has looked,
 * such a bump nearer the start than a claimed square leaves the claim in doubt.
 *
 * BUMP (per square, on the screen, along each of the 4 axis directions D into the
 * wall, P across): the square is occupied and not an object's (SCREEN_VERGE); its
 * row along P is a NECK: occupied squares bounded on both flanks by believed floor,
 * at most COARSEWALL_MOST_WIDTH long; walking against D through necks Utak reaches
 * believed floor (the bump's front); walking along D through necks he reaches an
 * occupied square whose row is no neck (the wall it juts from); the necks from
 * front to wall number COARSEWALL_LEAST_HEIGHT to COARSEWALL_MOST_HEIGHT; and
 * the floor in front is no door: within COARSEWALL_DOOR squares on against D it
 * does not meet another neck of wall in line (JAMB: a wall 1 thick with a door
 * in it, read 2 wide by cells of 2 x 2, is two such pieces facing each other
 * across the door; random g158 looked at both as if objects stood there). MARKED:
 * a bump square read only in coarse cells (4 x 4 or 2 x 2) whose centre lies
 * within radius of the centre asked about and that is one of a 2 x 2 block of bump
 * squares (a square 2 wide or more owns such a block wherever it lies: objects.c,
 * hold_square_near), and the wall's first COARSEWALL_FACE_SLACK squares behind such
 * a square, where read only coarsely: the gap may be there, the object's squares
 * seen in the fovea and the wall's face only coarsely (joined.py's worlds, seeds 1
 * to 4, 96 runs: 19 false successes left without these squares, none with them).
 *
 * USED BY objects.c (a doubt on the claim, as faint floor is) and faint.c
 * (faint_look: a look from where the fovea covers a marked square, before Utak
 * goes to the claimed object; not asked with no object of the shape found, where
 * no claim rests on it).
 *
 * MEASURED (tests/unit/test_coarsewall.c, the simulator as oracle): straight faces
 * of wall at every phase, heading and thickness, 528 worlds: none marked; thin walls
 * with a door, 168: none; squares 3 to 5 wide 1 to 2.5 off a face, 400: 386 held
 * merged with the wall after the first impression, all marked.
 *
 * LIMITS. A bump taller than COARSEWALL_MOST_HEIGHT (a square off the end of a
 * long stub of wall: joined25's variants, stub2) or wider than COARSEWALL_MOST_WIDTH
 * is not marked; nor an object merged with the wall in a room's corner (no floor on
 * one flank), nor one in line with a wall across a door (JAMB), nor one merged
 * with a slanted wall, whose face the model holds as a staircase with no neck
 * along either axis (joined25's variants, slant19); nor a square whose
 * squares the model holds as the same band of wall a face alone gives (5 of the 400
 * above: only the cells' levels, which the model averages, could tell). An object
 * touching the wall square to square (no floor square between them on the TABLE)
 * shows no gap even to the fovea: the eye cannot part it (issue 13's pocket; touch
 * can). A stub of wall seen only coarsely is marked as an object would be: the eye
 * cannot tell them apart until the fovea has seen whether there is a gap. */
#ifndef UTAK_COARSEWALL_H
#define UTAK_COARSEWALL_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/mind/screen.h"
#include "utak/mind/worldmodel.h"

struct Controller;

/* The rows of neck a bump needs (more than the 2 squares a 4 x 4 cell's reading
 * can put a face out by), the most it may have (a square of the judge's sizes, up
 * to 6 wide at any angle, and a gap of up to 3 squares the 4 x 4 cells can hide)
 * and the widest neck (such a square's width at 45 degrees, and a cell's 2 squares
 * of overshoot each side). */
#define COARSEWALL_LEAST_HEIGHT 3
#define COARSEWALL_MOST_HEIGHT 12
#define COARSEWALL_MOST_WIDTH 12
/* How far out a face seen in 4 x 4 cells can stand (WHAT A WALL'S FACE EXPLAINS). */
#define COARSEWALL_FACE_SLACK 2
/* The widest door a JAMB's floor may be (coarsewall.c, bump_along). */
#define COARSEWALL_DOOR 12

/* coarsewall_marks(m, s, centre, radius, mark): sets mark[k] = 1 (a w x h array
 * over screen s, built from model m) where screen cell k is MARKED (above); radius
 * INFINITY: any distance. Leaves other marks as they are. COMPLEXITY: O(w h
 * (MOST_WIDTH + MOST_HEIGHT + DOOR)). */
void coarsewall_marks(const WorldModel *m, const Screen *s, Vec2 centre, double radius,
                      uint8_t *mark);
/* coarsewall_within(c, centre, radius): some square is marked. */
bool coarsewall_within(const struct Controller *c, Vec2 centre, double radius);

#endif
