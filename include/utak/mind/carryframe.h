/* carryframe.h - for the carrying tasks (carrytask.c): "past the door line"
 * by the verdict's watershed restated on Utak's model in every frame the TABLE may
 * have (paper 2.3, tasks (vi), (vii), (ix); doc/verdicts.md "Rooms, doors,
 * doorways"). CONTROLLER SIDE.
 *
 * WHY. The judge floods the TABLE's squares by decreasing clearance, ties by the
 * square's index (judgerooms.h): the TABLE's rows, south to north, each west to
 * east. Where many squares share a clearance (a strip along a straight wall or the
 * verge) the door squares, and the doorways round them, fall where that order puts
 * them: a door at the end of a wall, against the verge, leaves door squares along
 * the verge past the wall's face, and how far they run depends on the order.
 * Utak's model is in his own frame (north the way he faced first), turned from the
 * TABLE's by a quarter turn he does not know; carryroom_beyond restates the rule
 * with ties by index in his frame, and on a model that may have seen the far room
 * only in part or a face a square off, which moves the door square too. So a cell
 * is claimed only where it holds in all four frames, and where no door cell of
 * that frame's watershed lies within CARRYFRAME_ALONG c + CARRYFRAME_ALONG_MORE
 * (c its clearance) unless the cell is clearer than c + CARRYFRAME_ALONG_SLACK:
 * the judge's doorway takes only cells within its door square's clearance and a
 * square, no clearer than it (judgerooms.h), and the door square may lie that far
 * along the face. Hand-written worlds with a door at a wall's end against the
 * verge (carry26, 64 runs): 23 false successes before, none after; the test
 * (test_carryframe.c) checks every cell claimed against the judge on the true
 * TABLE in every frame. */
#ifndef UTAK_CARRYFRAME_H
#define UTAK_CARRYFRAME_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/plan/grid.h"

#define CARRYFRAME_ALONG 3.0	  /* a door square moved along a face: reach, times its clearance */
#define CARRYFRAME_ALONG_MORE 3.0 /* and squares more */
#define CARRYFRAME_ALONG_SLACK 1.2 /* cells no clearer than the door's and this */

/* carryframe_beyond(g, si, sj, out): per cell of g (w h of them in out), whether
 * carryroom_beyond(g, si, sj) holds for it with g turned by each of the four
 * quarter turns (the cell and (si, sj) turned with it), and no door cell of that
 * turn's watershed has it along a face as above: beyond the door line of another
 * room than the start's in every frame. Returns how many cells are (0:
 * out all false, as when any turn finds none). COMPLEXITY: four times
 * carryroom_beyond's. MEMORY: a turned grid and its answer (2 bytes a cell) while
 * it works. */
int64_t carryframe_beyond(const Grid *g, int32_t si, int32_t sj, bool *out);

#endif
