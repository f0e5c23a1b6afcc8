/* grid.h - a grid of free and blocked cells: what the planner works on.
 *
 * The screen of paper 3.6 reduced to what path-finding needs. Row-major, flat:
 * cell (x, y) is cells[y * w + x], x in [0, w), y in [0, h). Cell (x, y) is the unit
 * square [x, x+1) x [y, y+1), so its centre is (x + 0.5, y + 0.5); a point given
 * in grid units lies in cell (floor(px), floor(py)). The planner does not care
 * which way y grows: the screen has y north, Moving AI maps have y south. Outside
 * the grid counts as blocked. */
#ifndef UTAK_GRID_H
#define UTAK_GRID_H

#include <stdbool.h>
#include <stdint.h>

enum { GRID_BLOCKED = 0, GRID_FREE = 1 };

typedef struct Grid {
	int32_t w, h;	/* size in cells */
	uint8_t *cells; /* w * h cells, GRID_FREE or GRID_BLOCKED */
} Grid;

void grid_init(Grid *g, int32_t w, int32_t h, uint8_t fill);
void grid_free(Grid *g);

/* grid_free_at(g, x, y): the cell is inside the grid and free. */
static inline bool grid_free_at(const Grid *g, int32_t x, int32_t y)
{
	return x >= 0 && y >= 0 && x < g->w && y < g->h && g->cells[(int64_t)y * g->w + x] == GRID_FREE;
}

#endif
