/* gridpath_work.h - what gridpath.c (A* on the 8-connected grid, paper 4.1) and
 * gridjump.c (the same search over jump points) share: the steps, the one cost
 * expression, the grid's bit lines, the open list's order and growth. Private to
 * the planner library: not installed under include/, and nothing outside
 * src/plan/gridpath.c and gridjump.c includes it. */
#ifndef UTAK_GRIDPATH_WORK_H
#define UTAK_GRIDPATH_WORK_H

#include <stdint.h>

#include "utak/base/util.h"
#include "utak/plan/gridpath.h"

#define GRIDPATH_SQRT2 1.41421356237309504880
/* GridPathNode.from of a start: no step reached it. */
#define GRIDPATH_NO_PARENT 8

/* gridpath_ctz64(bits): the index of the lowest set bit of bits != 0 (one
 * instruction where the compiler has it; the loop cost a tenth of the maze's A*). */
static inline int gridpath_ctz64(uint64_t bits)
{
#if defined(__GNUC__)
	return __builtin_ctzll(bits);
#else
	int i = 0;
	while (!((bits >> i) & 1))
		i++;
	return i;
#endif
}

/* The 8 steps: 0..3 straight (E, N, W, S), 4..7 diagonal (NE, NW, SW, SE); a
 * diagonal d = 4 + k lies between straight steps k and (k + 1) mod 4. "N" is +y. */
static const int8_t gridpath_dx[8] = {1, 0, -1, 0, 1, -1, -1, 1};
static const int8_t gridpath_dy[8] = {0, 1, 0, -1, 1, 1, -1, -1};

/* gridpath_dir_of[dy + 1][dx + 1]: the step index of (dx, dy) (-1 for (0, 0)). */
static const int8_t gridpath_dir_of[3][3] = {{6, 3, 7}, {2, -1, 0}, {5, 1, 4}};

/* The one expression that turns step counts into a length (see EXACT TIES). */
static inline double gridpath_cost(int32_t straight, int32_t diagonal)
{
	return (double)straight + (double)diagonal * GRIDPATH_SQRT2;
}

/* gridpath_bit(line, i): bit i of a line of words (1: free). */
static inline unsigned gridpath_bit(const uint64_t *line, int32_t i)
{
	return (unsigned)(line[(uint32_t)i / 64] >> ((uint32_t)i % 64)) & 1u;
}

/* gridpath_is_free(s, x, y): padded cell (x, y) is free. */
static inline unsigned gridpath_is_free(const GridPathSearch *s, int32_t x, int32_t y)
{
	return gridpath_bit(s->rows + (size_t)y * s->row_words, x);
}

/* gridpath_window(line, x): bits x - 1, x, x + 1 of a line, as bits 0, 1, 2. */
static inline unsigned gridpath_window(const uint64_t *line, int32_t x)
{
	const uint32_t p = (uint32_t)x - 1, k = p / 64, o = p % 64;
	uint64_t bits = line[k] >> o;
	if (o > 61) /* the window runs into the next word */
		bits |= line[k + 1] << (64 - o);
	return (unsigned)bits & 7u;
}

/* gridpath_moves(s, x, y): the legal steps from padded cell (x, y), bit d for step
 * d (no corner cutting; 0 for a blocked cell), from its 3 x 3 neighbourhood in rows
 * (three words, near those the runs read) by the table s->legal. */
static inline unsigned gridpath_moves(const GridPathSearch *s, int32_t x, int32_t y)
{
	const int32_t lw = s->row_words;
	const uint64_t *row = s->rows + (size_t)y * lw;
	return s->legal[gridpath_window(row - lw, x) | gridpath_window(row, x) << 3 |
	                gridpath_window(row + lw, x) << 6];
}

/* gridpath_before(a, b): a leaves the heap before b (smaller f; on equal f, larger g). */
static inline int gridpath_before(const GridPathOpen *a, const GridPathOpen *b)
{
	return a->f < b->f || (a->f == b->f && a->g > b->g);
}

/* gridpath_room_for(p, need, cap): p with room for need entries. */
static inline GridPathOpen *gridpath_room_for(GridPathOpen *p, int need, int *cap)
{
	return need <= *cap ? p : util_grow(p, cap, need, sizeof *p);
}

/* gridpath_room(p, count, cap): p with room for one more entry. The test is inline,
 * the call only when full (a call per push was a tenth of the maze's A*). */
static inline GridPathOpen *gridpath_room(GridPathOpen *p, int count, int *cap)
{
	return count < *cap ? p : util_grow(p, cap, count + 1, sizeof *p);
}

/* gridpath_find_jump(s, sx, sy, gx, gy, path, length): gridpath_find for
 * GRIDPATH_JUMP (gridjump.c), with padded ends, both free and inside the grid. */
GridPathStatus gridpath_find_jump(GridPathSearch *s, int32_t sx, int32_t sy, int32_t gx, int32_t gy,
                                  Path *path, double *length);

/* gridpath_jump_free(s): frees the jump search's state (gridjump.c), for
 * gridpath_free. */
void gridpath_jump_free(GridPathSearch *s);

#endif
