/* gridpath.c - A* on the 8-connected grid (paper 4.1: "an application of the A*
 * algorithm of [8] using their function f = g + h").
 *
 * ALGORITHM: A* (P.E. Hart, N.J. Nilsson, B. Raphael, "A formal basis for the
 * heuristic determination of minimum cost paths", IEEE Trans. SSC 4(2), 1968) on
 * the graph of grid.h's cells, 8-connected, straight steps 1, diagonal steps sqrt 2,
 * a diagonal step only when both orthogonally adjacent cells are free. The
 * heuristic is the octile distance, which is the exact cost on an empty grid, so it
 * is consistent: a cell is final when it is first closed and is never reopened.
 * The open list is a binary heap with lazy deletion: an improved cell is pushed
 * again and stale entries are skipped when popped (cheaper than decrease-key, whose
 * position index costs a random memory access per swap).
 *
 * EXACT TIES: a cost is kept as two integers, straight and diagonal step counts,
 * and turned into a double by one fixed expression. Since sqrt 2 is irrational,
 * two costs are equal exactly when their counts are, and then their doubles are
 * bit-identical; so ties in f are true ties, and they go to the larger g (the entry
 * nearer the goal), which makes A* run straight down a corridor of equal-f cells
 * instead of flooding it.
 *
 * INVARIANTS: mark[c] == 2 round means c was reached this query and g_* hold its best
 * known cost; mark[c] == 2 round + 1 means c is closed and its cost final; any other
 * value means unseen. The border cells of the padded copy are never free.
 *
 * MEMORY: see gridpath.h. COMPLEXITY: O(n log n) for n cells expanded, n <= free
 * cells; initialisation O(w h) once per grid, and a query touches only what it
 * expands (the round counter replaces clearing). */
#include "utak/gridpath.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/util.h"

#define GRIDPATH_SQRT2 1.41421356237309504880

/* The 8 steps: 0..3 straight (E, N, W, S), 4..7 diagonal (NE, NW, SW, SE); a
 * diagonal d = 4 + k lies between straight steps k and (k + 1) mod 4. "N" is +y. */
static const int8_t gridpath_dx[8] = {1, 0, -1, 0, 1, -1, -1, 1};
static const int8_t gridpath_dy[8] = {0, 1, 0, -1, 1, 1, -1, -1};

double gridpath_octile(int32_t dx, int32_t dy)
{
	int32_t ax = abs(dx), ay = abs(dy);
	int32_t lo = ax < ay ? ax : ay, hi = ax < ay ? ay : ax;
	return (double)(hi - lo) + (double)lo * GRIDPATH_SQRT2;
}

/* The one expression that turns step counts into a length (see EXACT TIES). */
static inline double gridpath_cost(int32_t straight, int32_t diagonal)
{
	return (double)straight + (double)diagonal * GRIDPATH_SQRT2;
}

void gridpath_init(GridPathSearch *s, const Grid *grid)
{
	int32_t pw = grid->w + 2, ph = grid->h + 2;
	size_t n = (size_t)pw * (size_t)ph;
	*s = (GridPathSearch){0};
	s->w = grid->w;
	s->h = grid->h;
	s->pw = pw;
	s->free_cell = util_alloc(n, 1);
	s->mark = util_alloc(n, sizeof *s->mark);
	s->g_straight = util_alloc(n, sizeof *s->g_straight);
	s->g_diagonal = util_alloc(n, sizeof *s->g_diagonal);
	s->from = util_alloc(n, 1);
	for (int32_t y = 0; y < grid->h; y++)
		for (int32_t x = 0; x < grid->w; x++)
			s->free_cell[(size_t)(y + 1) * pw + (x + 1)] =
			    grid->cells[(size_t)y * grid->w + x] == GRID_FREE;
}

void gridpath_free(GridPathSearch *s)
{
	free(s->free_cell);
	free(s->mark);
	free(s->g_straight);
	free(s->g_diagonal);
	free(s->from);
	free(s->heap);
	*s = (GridPathSearch){0};
}

/* gridpath_before(a, b): a leaves the heap before b (smaller f; on equal f, larger g). */
static inline int gridpath_before(const GridPathOpen *a, const GridPathOpen *b)
{
	return a->f < b->f || (a->f == b->f && a->g > b->g);
}

static void gridpath_push(GridPathSearch *s, GridPathOpen e)
{
	s->heap = util_grow(s->heap, &s->heap_cap, s->heap_count + 1, sizeof *s->heap);
	int i = s->heap_count++;
	while (i > 0) {
		int parent = (i - 1) / 2;
		if (!gridpath_before(&e, &s->heap[parent]))
			break;
		s->heap[i] = s->heap[parent];
		i = parent;
	}
	s->heap[i] = e;
}

static GridPathOpen gridpath_pop(GridPathSearch *s)
{
	GridPathOpen top = s->heap[0];
	GridPathOpen last = s->heap[--s->heap_count];
	int n = s->heap_count, i = 0;
	for (;;) {
		int c = 2 * i + 1;
		if (c >= n)
			break;
		if (c + 1 < n && gridpath_before(&s->heap[c + 1], &s->heap[c]))
			c++;
		if (!gridpath_before(&s->heap[c], &last))
			break;
		s->heap[i] = s->heap[c];
		i = c;
	}
	if (n > 0)
		s->heap[i] = last;
	return top;
}

/* gridpath_next_round: a fresh mark value; on wrap-around, clear the marks once. */
static void gridpath_next_round(GridPathSearch *s)
{
	if (s->round >= UINT32_MAX / 2 - 1) {
		memset(s->mark, 0, (size_t)s->pw * (size_t)(s->h + 2) * sizeof *s->mark);
		s->round = 0;
	}
	s->round++;
}

GridPathStatus gridpath_find(GridPathSearch *s, int32_t sx, int32_t sy, int32_t gx, int32_t gy,
			     Path *path, double *length)
{
	path_clear(path);
	*length = -1;
	if (sx < 0 || sy < 0 || gx < 0 || gy < 0 || sx >= s->w || gx >= s->w || sy >= s->h ||
	    gy >= s->h)
		return GRIDPATH_BAD_ENDPOINT;
	const int32_t pw = s->pw;
	const int32_t start = (sy + 1) * pw + (sx + 1), goal = (gy + 1) * pw + (gx + 1);
	if (!s->free_cell[start] || !s->free_cell[goal])
		return GRIDPATH_BAD_ENDPOINT;

	int32_t offset[8];
	for (int d = 0; d < 8; d++)
		offset[d] = gridpath_dy[d] * pw + gridpath_dx[d];
	gridpath_next_round(s);
	const uint32_t open_mark = 2 * s->round, closed_mark = 2 * s->round + 1;
	const uint8_t *free_cell = s->free_cell;
	uint32_t *mark = s->mark;
	int32_t *gs = s->g_straight, *gd = s->g_diagonal;
	const int32_t goal_x = gx + 1, goal_y = gy + 1;

	s->heap_count = 0;
	mark[start] = open_mark;
	gs[start] = gd[start] = 0;
	{
		int32_t ax = abs(goal_x - (sx + 1)), ay = abs(goal_y - (sy + 1));
		int32_t lo = ax < ay ? ax : ay, hi = ax < ay ? ay : ax;
		gridpath_push(s, (GridPathOpen){gridpath_cost(hi - lo, lo), 0, start});
	}
	int64_t expanded = 0;
	int found = 0;
	while (s->heap_count > 0) {
		GridPathOpen e = gridpath_pop(s);
		int32_t c = e.cell;
		if (mark[c] == closed_mark)
			continue;
		/* A stale entry of an open cell: its cost has since improved. */
		if (e.g != gridpath_cost(gs[c], gd[c]))
			continue;
		mark[c] = closed_mark;
		expanded++;
		if (c == goal) {
			found = 1;
			break;
		}
		int32_t cx = c % pw, cy = c / pw;
		uint8_t straight_free[4];
		for (int d = 0; d < 8; d++) {
			int32_t n = c + offset[d];
			int32_t ns = gs[c], nd = gd[c];
			if (d < 4) {
				straight_free[d] = free_cell[n];
				if (!straight_free[d])
					continue;
				ns++;
			} else {
				/* The no-corner-cutting rule: both orthogonal neighbours free. */
				if (!free_cell[n] || !straight_free[d - 4] || !straight_free[(d - 3) & 3])
					continue;
				nd++;
			}
			if (mark[n] == closed_mark)
				continue;
			double ng = gridpath_cost(ns, nd);
			if (mark[n] == open_mark && !(ng < gridpath_cost(gs[n], gd[n])))
				continue;
			mark[n] = open_mark;
			gs[n] = ns;
			gd[n] = nd;
			s->from[n] = (uint8_t)d;
			int32_t ax = abs(goal_x - (cx + gridpath_dx[d]));
			int32_t ay = abs(goal_y - (cy + gridpath_dy[d]));
			int32_t lo = ax < ay ? ax : ay, hi = ax < ay ? ay : ax;
			gridpath_push(s, (GridPathOpen){gridpath_cost(ns + hi - lo, nd + lo), ng, n});
		}
	}
	path->expanded = expanded;
	if (!found)
		return GRIDPATH_NO_PATH;

	/* Walk back along from[], then reverse: the path runs start to goal. */
	int32_t steps = gs[goal] + gd[goal];
	for (int32_t i = 0; i <= steps; i++)
		path_push(path, vec2(0, 0));
	int32_t c = goal;
	for (int32_t i = steps; i >= 0; i--) {
		path->pts[i] = vec2((double)(c % pw - 1) + 0.5, (double)(c / pw - 1) + 0.5);
		if (i > 0)
			c -= offset[s->from[c]];
	}
	*length = gridpath_cost(gs[goal], gd[goal]);
	return GRIDPATH_FOUND;
}
