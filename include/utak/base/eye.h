/* eye.h - the anatomy of Utak's eye: the 160 retinal cells and their layout (paper 2.2, 3.4.1).
 * SHARED: pure geometry, used by both sides of the wall. It knows nothing of the
 * TABLE (the simulator samples the TABLE through it, retina.c) nor of the world
 * model (the controller projects its model through it, worldmodel.c), so the
 * predicted impression and the actual one are made by the same eye.
 *
 * FRAME. Utak's own frame: x to his right, y ahead, one unit one TABLE square.
 * A square is named by its offset (ox, oy) from Utak's square, which is (0, 0); the
 * field is the 32 x 32 squares at offsets -16..15 on both axes. "Pixels are little
 * squares": offset (ox, oy) is the unit square [ox, ox+1] x [oy, oy+1] when Utak's
 * square is [0, 1] x [0, 1].
 *
 * CELLS (paper 2.2: 64 + 48 + 48). Fovea: the 64 squares at offsets -4..3, one
 * square a cell. Intermediate zone: the rest of -8..7, in 2 x 2 cells starting at
 * even offsets (48). Peripheral zone: the rest of -16..15, in 4 x 4 cells starting
 * at multiples of 4 (48). A cell is named by its lower-left square (ox, oy) and
 * its side.
 *
 * CELL ORDER (the order of Impression.level): the 64 foveal cells, then the 48
 * intermediate, then the 48 peripheral; within a zone, row by row from the row
 * farthest ahead to the nearest, each row from Utak's left to his right. So cell 0
 * is the fovea's far-left square (-4, 3) and cell 159 the near-right peripheral
 * cell (12, -16).
 *
 * ADJACENCY (paper 3.4.1). Two cells are edge-adjacent when their borders share a
 * piece of edge of positive length; cells meeting only at a corner (diagonal
 * neighbours) are not. A foveal cell may touch one 2 x 2 cell, a 2 x 2 cell up to
 * two foveal cells per side, and so on; at most EYE_MAX_NEIGHBOURS in all.
 *
 * PICTURE. The 32 x 32 picture of paper Figure 2: column c = ox + 16 (Utak's left
 * on the left), row r = 15 - oy (the row farthest ahead is row 0). */
#ifndef UTAK_EYE_H
#define UTAK_EYE_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/impression.h"

enum {
	EYE_HALF = RETINA_FIELD / 2, /* offsets run from -EYE_HALF to EYE_HALF - 1 */
	EYE_FOVEA_HALF = 4,          /* the fovea: offsets -4..3 */
	EYE_INTERMEDIATE_HALF = 8,   /* fovea and intermediate zone: offsets -8..7 */
	EYE_MAX_NEIGHBOURS =
	    12, /* a 4 x 4 cell next to 2 x 2 cells: 2 per side, at most 8; margin */
	EYE_MAX_LEVEL = RETINA_LEVELS - 1,
};

typedef enum EyeZone { EYE_FOVEA, EYE_INTERMEDIATE, EYE_PERIPHERAL } EyeZone;

/* One retinal cell: its lower-left square and its side, in Utak's frame. */
typedef struct EyeCell {
	int8_t ox, oy; /* offset of the lower-left square from Utak's square */
	int8_t size;   /* side in squares: 1, 2 or 4 */
	int8_t zone;   /* an EyeZone */
} EyeCell;

/* eye_cell(i): cell i, 0 <= i < RETINA_CELLS, in the order above. */
EyeCell eye_cell(int32_t i);

/* eye_level(occupied, total): the gray level of a cell of `total` squares of which
 * `occupied` are occupied: round(7 x occupied / total), halves rounding up. */
int eye_level(int32_t occupied, int32_t total);

/* eye_cell_at(ox, oy): the cell covering the square at offset (ox, oy), or -1
 * when the square is outside the field. */
int32_t eye_cell_at(int32_t ox, int32_t oy);

/* eye_picture_of(ox, oy, &col, &row): where offset (ox, oy) shows in the 32 x 32
 * picture; false (col, row untouched) outside the field. eye_offset_of inverts it. */
bool eye_picture_of(int32_t ox, int32_t oy, int32_t *col, int32_t *row);
void eye_offset_of(int32_t col, int32_t row, int32_t *ox, int32_t *oy);

/* eye_neighbours(i, &list): the cells edge-adjacent to cell i, in increasing
 * order; returns their number. The list is static and shared. */
int32_t eye_neighbours(int32_t i, const int32_t **list);
bool eye_adjacent(int32_t i, int32_t j);

/* eye_on_border(i): cell i touches the outer border of the field. */
bool eye_on_border(int32_t i);

/* eye_print_picture(level, f): the picture of paper Figure 2: 32 lines of exactly
 * 32 digits, each square showing the level of the cell covering it. */
void eye_print_picture(const uint8_t level[RETINA_CELLS], FILE *f);

/* eye_validate(why, size): the layout's invariants (160 cells, 64/48/48, every
 * square of the field covered exactly once, adjacency symmetric). */
bool eye_validate(char *why, size_t size);

#endif
