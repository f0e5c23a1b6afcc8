/* retina.c - the retinal and tactile impression computed from the TABLE (paper 2.2). SIMULATOR
 * SIDE.
 *
 * ALGORITHM (paper 2.2): "superimpose the array of retinal fields on TABLE, centred
 * on Utak's digital representation, and compute the graylevels directly from the
 * TABLE array". For each cell, count the occupied TABLE squares under it and round
 * (eye_level). The eye is fixed to Utak's body: own offset (ox, oy) is the TABLE
 * square utak_square + world_own_to_table(heading, (ox, oy)); a quarter-turn
 * rotation of a square's centre offset about the centre of Utak's square, so
 * squares map to squares exactly.
 * COMPLEXITY: 1024 TABLE reads per impression. */
#include "utak/body/retina.h"

#include "utak/base/eye.h"

void retina_square(const World *w, int32_t ox, int32_t oy, int32_t *x, int32_t *y)
{
	int32_t ux, uy;
	table_square_of(w->utak, &ux, &uy);
	Vec2 d = world_own_to_table(w->heading, vec2(ox, oy));
	*x = ux + (int32_t)d.x;
	*y = uy + (int32_t)d.y;
}

bool retina_occupied(const World *w, const Table *t, int32_t x, int32_t y)
{
	int32_t ux, uy;
	table_square_of(w->utak, &ux, &uy);
	if (x == ux && y == uy)
		return true;
	return table_owner(t, x, y) != TABLE_FLOOR; /* off the TABLE: TABLE_VERGE */
}

void retina_sense(const World *w, const Table *t, Impression *imp)
{
	for (int32_t i = 0; i < RETINA_CELLS; i++) {
		EyeCell c = eye_cell(i);
		int32_t occupied = 0;
		for (int dy = 0; dy < c.size; dy++)
			for (int dx = 0; dx < c.size; dx++) {
				int32_t x, y;
				retina_square(w, c.ox + dx, c.oy + dy, &x, &y);
				occupied += retina_occupied(w, t, x, y);
			}
		imp->level[i] = (uint8_t)eye_level(occupied, c.size * c.size);
	}
	for (int k = 0; k < TOUCH_CELLS; k++) {
		int32_t x, y;
		world_touch_square(w, k, &x, &y);
		imp->touch[k] = table_colour(t, w, x, y);
	}
}

void retina_print_touch(const Impression *imp, FILE *f)
{
	const char *tc = imp->touch;
	/* Impression.touch order: ahead, ahead-right, right, behind-right, behind,
	 * behind-left, left, ahead-left. */
	fprintf(f, "%c%c%c\n%c@%c\n%c%c%c\n", tc[7], tc[0], tc[1], tc[6], tc[2], tc[5], tc[4],
	        tc[3]);
	fprintf(
	    f,
	    "order ahead,ahead-right,right,behind-right,behind,behind-left,left,ahead-left: %.8s\n",
	    tc);
}
