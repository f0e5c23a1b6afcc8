/* skellevel.h - the skeleton's lowest distance level thinned by bit planes (paper 4.2).
 * Private to the planner library: not installed under include/, and nothing outside
 * src/plan/skellevel.c and skeleton.c includes it. See skellevel.c for the algorithm
 * and why its deletions are some of the distance-ordered thinning's own. */
#ifndef UTAK_SKELLEVEL_H
#define UTAK_SKELLEVEL_H

#include <stdint.h>

#include "utak/plan/grid.h"

/* Bit planes over the grid padded by one blocked cell on every side (as the thinning's
 * state in skeleton.c): row r is the padded row r (0 .. h + 1), bit b of its word k the
 * padded column 64 k + b. Each row is `words` words with one zero word either side (so
 * that a shift by one column needs no bounds check): it starts at plane + r * stride + 1. */
typedef struct SkelLevel {
	int32_t w, h;   /* the grid's size, in cells */
	int32_t words;  /* words of a padded row of w + 2 cells */
	int32_t stride; /* words + 2 */
	uint64_t *set;  /* the cells in the thinning's set: the free cells, less the deleted */
	uint64_t *low;  /* the free cells of the lowest level, dist2 1 (a 4-neighbour blocked) */
	uint64_t *near; /* the cells with an 8-neighbour free and of dist2 above 1 */
	uint64_t *peel; /* the low cells the subfields may delete: free 2 cells beyond
	                 * them opposite each blocked 4-neighbour (skellevel.c) */
	int32_t nlow;   /* the free cells of dist2 1 */
	int32_t nhigh;  /* the free cells of dist2 above 1 */
} SkelLevel;

/* skellevel_lowest(m): the index of m's lowest set bit, m nonzero. */
static inline int skellevel_lowest(uint64_t m)
{
#if defined(__GNUC__)
	return __builtin_ctzll(m);
#else
	int i = 0;
	for (; !(m & 1); m >>= 1)
		i++;
	return i;
#endif
}

/* skellevel_init(lv): an empty SkelLevel; skellevel_free(lv) frees its planes. */
void skellevel_init(SkelLevel *lv);
void skellevel_free(SkelLevel *lv);

/* skellevel_thin(lv, g): the planes of g (memory kept for the next grid of the same
 * size) and the counts nlow and nhigh, then the deletions of the lowest level's cells
 * by subfields (skellevel.c). */
void skellevel_thin(SkelLevel *lv, const Grid *g);

/* skellevel_state(lv, state, in): the padded state of skeleton.c, (w + 2) (h + 2)
 * bytes: `in` for a cell in the set, 0 for any other. */
void skellevel_state(const SkelLevel *lv, uint8_t *state, uint8_t in);

/* skellevel_rest(lv, out): the padded indices ((w + 2) y + x of the padded grid) of
 * the lowest level's cells still in the set, in increasing order, into out; returns
 * their number. */
int32_t skellevel_rest(const SkelLevel *lv, int32_t *out);
/* skellevel_count_rest(lv): the number skellevel_rest would list. */
int32_t skellevel_count_rest(const SkelLevel *lv);

/* The histogram of skellevel_high: values below SKELLEVEL_SMALL counted in
 * SKELLEVEL_LANES tables by place in the list (a power of two), so that consecutive
 * cells of one value (a corridor's middle) do not each wait for the last one's store;
 * each table padded so that no two share their low 12 address bits (4K aliasing). */
#define SKELLEVEL_LANES 8
#define SKELLEVEL_SMALL 256
typedef int32_t SkelLevelCount[SKELLEVEL_LANES][SKELLEVEL_SMALL + 16];

/* skellevel_high(lv, dist2, out, small, big): the free cells of dist2 above 1, in
 * increasing order, as pairs in out: the padded index, then the cell's dist2 (dist2 is
 * the grid's, w h values); returns their number (out holds twice as many values). Each
 * is counted by its dist2 d: in small[lane][d] when d < SKELLEVEL_SMALL, else in
 * big[d + 1]. */
int32_t skellevel_high(const SkelLevel *lv, const int32_t *dist2, int32_t *out,
                       SkelLevelCount small, int32_t *big);

#endif
