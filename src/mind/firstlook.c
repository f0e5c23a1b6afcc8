/* firstlook.c - the first impression places Utak again near his first square:
 * recognition by features, paper 3.5's fallback when the disparity is not enough
 * (issue 13, part 7: noisy motion). CONTROLLER SIDE: it sees the first Impression
 * the world model kept (WorldModel.first) and the eye's anatomy, never the TABLE.
 * Split from worldmodel.c (which it was part of) when that file passed 1,000 lines;
 * the measure is worldmodel.c's disparity with the first impression in place of the
 * model. COMPLEXITY: (2 WORLDMODEL_DISPARITY_RADIUS + 3)^2 positions, each projected
 * through the 160 cells. */
#include <math.h>
#include <stdlib.h>

#include "utak/base/eye.h"
#include "utak/mind/worldmodel.h"
#include "worldmodel_work.h"

/* wm_first_square(m, x, y): what the first impression showed of square (x, y): 1
 * occupied, 0 floor (a cell empty or full: a 4 x 4 cell's level 0 or 7 allows one
 * square the other way, the rounding worldmodel_predict accepts too), -1 unknown.
 * Utak's own first square is floor. */
static int wm_first_square(const WorldModel *m, int32_t x, int32_t y)
{
	if (x == 0 && y == 0)
		return 0;
	int32_t i = eye_cell_at(x, y);
	if (i < 0)
		return -1;
	int level = m->first.level[i];
	return level == 0 ? 0 : level == EYE_MAX_LEVEL ? 1 : -1;
}

/* wm_first_score(m, x, y, imp, &compared): wm_score with the first impression in
 * place of the model. */
static double wm_first_score(const WorldModel *m, int32_t x, int32_t y, const Impression *imp, int32_t *compared)
{
	int32_t utak_cell = eye_cell_at(0, 0), n = 0;
	double sum = 0;
	for (int32_t i = 0; i < RETINA_CELLS; i++) {
		if (i == utak_cell)
			continue;
		EyeCell c = eye_cell(i);
		int occupied = 0;
		bool ok = true;
		for (int dy = 0; dy < c.size && ok; dy++)
			for (int dx = 0; dx < c.size && ok; dx++) {
				int v = wm_first_square(m, x + c.ox + dx, y + c.oy + dy);
				ok = v >= 0;
				occupied += v == 1;
			}
		if (ok) {
			sum += abs(eye_level(occupied, c.size * c.size) - (int)imp->level[i]) / (double)EYE_MAX_LEVEL;
			n++;
		}
	}
	*compared = n;
	double cells = RETINA_CELLS - 1;
	return (sum + WM_UNKNOWN_COST * (cells - n)) / cells;
}

bool worldmodel_recognise_first(const WorldModel *m, const Impression *imp, int32_t *x, int32_t *y,
                                bool placed[2])
{
	enum { R = WORLDMODEL_DISPARITY_RADIUS, SIDE = 2 * R + 3 };
	/* Scores of the candidates and one square round them, INFINITY where none. */
	double score[SIDE][SIDE];
	int32_t bx = *x, by = *y;
	double best = INFINITY;
	for (int32_t j = 0; j < SIDE; j++)
		for (int32_t i = 0; i < SIDE; i++) {
			int32_t cx = *x + i - R - 1, cy = *y + j - R - 1, compared;
			double v = wm_first_score(m, cx, cy, imp, &compared);
			/* Not where the first impression showed something: he cannot stand there. */
			score[j][i] = compared >= WORLDMODEL_MIN_COMPARED && wm_first_square(m, cx, cy) != 1 ? v : INFINITY;
			bool inner = i >= 1 && i < SIDE - 1 && j >= 1 && j < SIDE - 1;
			/* Ties to the nearest to (*x, *y): a cost far below a cell's. */
			double key = score[j][i] + WM_DISTANCE_COST * hypot(cx - *x, cy - *y);
			if (inner && key < best) {
				best = key;
				bx = cx;
				by = cy;
			}
		}
	if (best == INFINITY)
		return false;
	/* As the disparity does: (*x, *y) stands unless another does better by the margin. */
	if (score[R + 1][R + 1] < INFINITY && score[by - *y + R + 1][bx - *x + R + 1] + WORLDMODEL_DISPARITY_MARGIN >=
	                                          score[R + 1][R + 1]) {
		bx = *x;
		by = *y;
	}
	/* Placed on an axis: every square tried off the best one along it matches worse
	 * by the margin (a square off on both axes would not do: a shift along one
	 * can mimic one along the other). */
	int32_t bi = bx - *x + R + 1, bj = by - *y + R + 1;
	double at = score[bj][bi] + WORLDMODEL_DISPARITY_MARGIN;
	placed[0] = placed[1] = true;
	for (int32_t j = 0; j < SIDE; j++)
		for (int32_t i = 0; i < SIDE; i++) {
			placed[0] &= i == bi || score[j][i] >= at;
			placed[1] &= j == bj || score[j][i] >= at;
		}
	*x = bx;
	*y = by;
	return true;
}
