/* grid.c - a grid of free and blocked cells (see grid.h): the planner's screen (paper 3.6). */
#include "utak/plan/grid.h"

#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

void grid_init(Grid *g, int32_t w, int32_t h, uint8_t fill)
{
	g->w = w;
	g->h = h;
	g->cells = util_alloc((size_t)w * (size_t)h, 1);
	memset(g->cells, fill, (size_t)w * (size_t)h);
}

void grid_free(Grid *g)
{
	free(g->cells);
	g->cells = NULL;
	g->w = g->h = 0;
}
