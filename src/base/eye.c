/* eye.c - the anatomy of Utak's eye: cell layout, gray levels, adjacency (paper 2.2, 3.4.1).
 * SHARED: pure geometry, no TABLE and no world model (see eye.h for the frame and
 * the cell order).
 *
 * ALGORITHM. The layout is built once, on first use, by walking each zone's grid of
 * cells in the documented order and keeping those outside the inner zone. The
 * adjacency lists come from testing every pair of cells as rectangles: adjacent
 * when one's right (top) side lies on the other's left (bottom) side and their
 * extents along that side overlap by a positive length. This is the definition of
 * paper 3.4.1 taken literally, so no special case for mixed sizes is needed.
 *
 * INVARIANTS (eye_validate): 64 + 48 + 48 cells; every square of the field belongs
 * to exactly one cell; adjacency is symmetric and irreflexive.
 * MEMORY: static tables, 160 cells, 160 x EYE_MAX_NEIGHBOURS ints, a 32 x 32 map.
 * COMPLEXITY: building, O(160^2) once; every query after, O(1). */
#include "utak/base/eye.h"

#include <assert.h>
#include <stdio.h>

static struct {
	bool built;
	EyeCell cell[RETINA_CELLS];
	int32_t cover[RETINA_FIELD * RETINA_FIELD]; /* picture row-major: row * 32 + col */
	int32_t neighbour[RETINA_CELLS][EYE_MAX_NEIGHBOURS];
	int32_t neighbour_count[RETINA_CELLS];
} eye;

/* eye_add_zone: the cells of side `size` tiling offsets -half..half-1, without
 * those inside -inner..inner-1, farthest row first, left to right. */
static int32_t eye_add_zone(int32_t n, int size, int half, int inner, EyeZone zone)
{
	for (int oy = half - size; oy >= -half; oy -= size)
		for (int ox = -half; ox < half; ox += size) {
			bool inside = ox >= -inner && ox < inner && oy >= -inner && oy < inner;
			if (inside)
				continue;
			eye.cell[n] = (EyeCell){(int8_t)ox, (int8_t)oy, (int8_t)size, (int8_t)zone};
			n++;
		}
	return n;
}

/* eye_touching(a, b): b's left side lies on a's right side, sharing positive length. */
static bool eye_touching(EyeCell a, EyeCell b)
{
	if (a.ox + a.size == b.ox) {
		int lo = a.oy > b.oy ? a.oy : b.oy;
		int hi = a.oy + a.size < b.oy + b.size ? a.oy + a.size : b.oy + b.size;
		if (hi > lo)
			return true;
	}
	if (a.oy + a.size == b.oy) {
		int lo = a.ox > b.ox ? a.ox : b.ox;
		int hi = a.ox + a.size < b.ox + b.size ? a.ox + a.size : b.ox + b.size;
		if (hi > lo)
			return true;
	}
	return false;
}

static void eye_build(void)
{
	if (eye.built)
		return;
	int32_t n = 0;
	n = eye_add_zone(n, 1, EYE_FOVEA_HALF, 0, EYE_FOVEA);
	n = eye_add_zone(n, 2, EYE_INTERMEDIATE_HALF, EYE_FOVEA_HALF, EYE_INTERMEDIATE);
	n = eye_add_zone(n, 4, EYE_HALF, EYE_INTERMEDIATE_HALF, EYE_PERIPHERAL);
	assert(n == RETINA_CELLS);
	for (int32_t k = 0; k < RETINA_FIELD * RETINA_FIELD; k++)
		eye.cover[k] = -1;
	for (int32_t i = 0; i < RETINA_CELLS; i++) {
		EyeCell c = eye.cell[i];
		for (int dy = 0; dy < c.size; dy++)
			for (int dx = 0; dx < c.size; dx++) {
				int32_t col = 0, row = 0;
				eye_picture_of(c.ox + dx, c.oy + dy, &col, &row);
				eye.cover[row * RETINA_FIELD + col] = i;
			}
	}
	for (int32_t i = 0; i < RETINA_CELLS; i++)
		for (int32_t j = 0; j < RETINA_CELLS; j++)
			if (eye_touching(eye.cell[i], eye.cell[j]) ||
			    eye_touching(eye.cell[j], eye.cell[i])) {
				assert(eye.neighbour_count[i] < EYE_MAX_NEIGHBOURS);
				eye.neighbour[i][eye.neighbour_count[i]++] = j;
			}
	eye.built = true;
}

EyeCell eye_cell(int32_t i)
{
	assert(i >= 0 && i < RETINA_CELLS);
	eye_build();
	return eye.cell[i];
}

int eye_level(int32_t occupied, int32_t total)
{
	assert(total > 0 && occupied >= 0 && occupied <= total);
	/* round(7 o / t) with halves up = floor((14 o + t) / (2 t)), in integers. */
	return (int)((2 * EYE_MAX_LEVEL * occupied + total) / (2 * total));
}

bool eye_picture_of(int32_t ox, int32_t oy, int32_t *col, int32_t *row)
{
	if (ox < -EYE_HALF || ox >= EYE_HALF || oy < -EYE_HALF || oy >= EYE_HALF)
		return false;
	*col = ox + EYE_HALF;
	*row = EYE_HALF - 1 - oy;
	return true;
}

void eye_offset_of(int32_t col, int32_t row, int32_t *ox, int32_t *oy)
{
	*ox = col - EYE_HALF;
	*oy = EYE_HALF - 1 - row;
}

int32_t eye_cell_at(int32_t ox, int32_t oy)
{
	int32_t col, row;
	if (!eye_picture_of(ox, oy, &col, &row))
		return -1;
	eye_build();
	return eye.cover[row * RETINA_FIELD + col];
}

int32_t eye_neighbours(int32_t i, const int32_t **list)
{
	assert(i >= 0 && i < RETINA_CELLS);
	eye_build();
	*list = eye.neighbour[i];
	return eye.neighbour_count[i];
}

bool eye_adjacent(int32_t i, int32_t j)
{
	const int32_t *list;
	int32_t n = eye_neighbours(i, &list);
	for (int32_t k = 0; k < n; k++)
		if (list[k] == j)
			return true;
	return false;
}

bool eye_on_border(int32_t i)
{
	EyeCell c = eye_cell(i);
	return c.ox == -EYE_HALF || c.oy == -EYE_HALF || c.ox + c.size == EYE_HALF ||
	       c.oy + c.size == EYE_HALF;
}

void eye_print_picture(const uint8_t level[RETINA_CELLS], FILE *f)
{
	eye_build();
	for (int32_t row = 0; row < RETINA_FIELD; row++) {
		char line[RETINA_FIELD + 1];
		for (int32_t col = 0; col < RETINA_FIELD; col++)
			line[col] = (char)('0' + level[eye.cover[row * RETINA_FIELD + col]]);
		line[RETINA_FIELD] = '\n';
		fwrite(line, 1, sizeof line, f);
	}
}

bool eye_validate(char *why, size_t size)
{
	eye_build();
	int zone_count[3] = {0, 0, 0};
	for (int32_t i = 0; i < RETINA_CELLS; i++)
		zone_count[eye.cell[i].zone]++;
	if (zone_count[0] != RETINA_FOVEA || zone_count[1] != RETINA_INTERMEDIATE ||
	    zone_count[2] != RETINA_PERIPHERAL) {
		snprintf(why, size, "zones hold %d/%d/%d cells", zone_count[0], zone_count[1],
		         zone_count[2]);
		return false;
	}
	int32_t covered[RETINA_FIELD * RETINA_FIELD] = {0};
	for (int32_t i = 0; i < RETINA_CELLS; i++) {
		EyeCell c = eye.cell[i];
		for (int dy = 0; dy < c.size; dy++)
			for (int dx = 0; dx < c.size; dx++) {
				int32_t col, row;
				if (!eye_picture_of(c.ox + dx, c.oy + dy, &col, &row)) {
					snprintf(why, size, "cell %d leaves the field", (int)i);
					return false;
				}
				covered[row * RETINA_FIELD + col]++;
			}
		if (c.ox % c.size != 0 || c.oy % c.size != 0) {
			snprintf(why, size, "cell %d is not aligned to its size", (int)i);
			return false;
		}
	}
	for (int32_t k = 0; k < RETINA_FIELD * RETINA_FIELD; k++)
		if (covered[k] != 1) {
			snprintf(why, size, "picture square %d is covered %d times", (int)k,
			         (int)covered[k]);
			return false;
		}
	for (int32_t i = 0; i < RETINA_CELLS; i++)
		for (int32_t k = 0; k < eye.neighbour_count[i]; k++) {
			int32_t j = eye.neighbour[i][k];
			if (j == i || !eye_adjacent(j, i)) {
				snprintf(why, size, "adjacency of cells %d and %d", (int)i, (int)j);
				return false;
			}
		}
	return true;
}
