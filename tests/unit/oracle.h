/* oracle.h - brute-force oracles shared by the skeleton, pathgraph and rooms tests.
 *
 * Deliberately naive code, written apart from src/: random grids from a fixed-seed
 * generator, flood-fill labelling of a set of cells under 4- or 8-adjacency on a grid
 * padded by one ring of cells (the outside of the grid), and counts of components and
 * holes that define the digital topology of skeleton.h independently of its tables. */
#ifndef UTAK_ORACLE_H
#define UTAK_ORACLE_H

#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "utak/plan/grid.h"

/* oracle_rand: a 64-bit LCG (Knuth's MMIX constants), deterministic on every platform. */
static uint64_t oracle_seed = 12345;
static inline uint32_t oracle_rand(void)
{
	oracle_seed = oracle_seed * 6364136223846793005ULL + 1442695040888963407ULL;
	return (uint32_t)(oracle_seed >> 33);
}
static inline int oracle_rand_below(int n)
{
	return (int)(oracle_rand() % (uint32_t)n);
}

/* oracle_random_grid(g, w, h, percent): each cell blocked with the given probability;
 * with rects > 0, that many random rectangles are blocked on top. */
static inline void oracle_random_grid(Grid *g, int w, int h, int percent, int rects)
{
	grid_init(g, w, h, GRID_FREE);
	for (int i = 0; i < w * h; i++)
		if (oracle_rand_below(100) < percent)
			g->cells[i] = GRID_BLOCKED;
	for (int r = 0; r < rects; r++) {
		int x0 = oracle_rand_below(w), y0 = oracle_rand_below(h);
		int rw = 1 + oracle_rand_below(w / 3 + 1), rh = 1 + oracle_rand_below(h / 3 + 1);
		for (int y = y0; y < y0 + rh && y < h; y++)
			for (int x = x0; x < x0 + rw && x < w; x++)
				g->cells[y * w + x] = GRID_BLOCKED;
	}
}

/* oracle_grid_from(g, rows, h): a grid from strings, row 0 of the strings on top
 * (north), so rows[h - 1 - y] is grid row y; '#' blocked, anything else free. */
static inline void oracle_grid_from(Grid *g, const char *const *rows, int h)
{
	int w = (int)strlen(rows[0]);
	grid_init(g, w, h, GRID_FREE);
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++)
			g->cells[y * w + x] = rows[h - 1 - y][x] == '#' ? GRID_BLOCKED : GRID_FREE;
}

/* oracle_label(in, w, h, conn, label): labels the cells with in[i] != 0 of a w x h
 * array by flood fill, conn 4 or 8; label[i] = component number from 0, or -1.
 * Returns the number of components. */
static inline int oracle_label(const uint8_t *in, int w, int h, int conn, int *label)
{
	int *stack = malloc(sizeof(int) * (size_t)(w * h + 1));
	int count = 0;
	for (int i = 0; i < w * h; i++)
		label[i] = -1;
	for (int i = 0; i < w * h; i++) {
		if (!in[i] || label[i] >= 0)
			continue;
		int top = 0;
		stack[top++] = i;
		label[i] = count;
		while (top > 0) {
			int c = stack[--top], cx = c % w, cy = c / w;
			for (int dy = -1; dy <= 1; dy++)
				for (int dx = -1; dx <= 1; dx++) {
					if ((dx == 0 && dy == 0) ||
					    (conn == 4 && dx != 0 && dy != 0))
						continue;
					int nx = cx + dx, ny = cy + dy;
					if (nx < 0 || ny < 0 || nx >= w || ny >= h)
						continue;
					int nb = ny * w + nx;
					if (in[nb] && label[nb] < 0) {
						label[nb] = count;
						stack[top++] = nb;
					}
				}
		}
		count++;
	}
	free(stack);
	return count;
}

/* oracle_holes(set, w, h): the number of holes of a 4-connected set of cells: the
 * 8-components of its complement, with the outside of the grid joined to the
 * complement, minus the one that holds the outside. */
static inline int oracle_holes(const uint8_t *set, int w, int h)
{
	int pw = w + 2, ph = h + 2;
	uint8_t *comp = calloc((size_t)(pw * ph), 1);
	int *label = malloc(sizeof(int) * (size_t)(pw * ph));
	for (int y = 0; y < ph; y++)
		for (int x = 0; x < pw; x++) {
			bool inside = x > 0 && y > 0 && x <= w && y <= h;
			comp[y * pw + x] = !(inside && set[(y - 1) * w + (x - 1)]);
		}
	int n = oracle_label(comp, pw, ph, 8, label);
	free(comp);
	free(label);
	return n - 1;
}

#endif
