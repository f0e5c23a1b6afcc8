/* skellevel.h - the skeleton's lowest distance levels by bit planes (paper 4.2).
 * Private to the planner library: not installed under include/, and nothing outside
 * src/plan/skellevel.c and skeleton.c includes it. See skellevel.c for the algorithm
 * and why its deletions are some of the distance-ordered thinning's own. */
#ifndef UTAK_SKELLEVEL_H
#define UTAK_SKELLEVEL_H

#include <stdbool.h>
#include <stddef.h>
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
	uint64_t *above; /* the free cells of dist2 above the planed levels done so far
	                  * (skellevel_next), all in the set until their turn */
	int32_t nlow;   /* the free cells of dist2 1 */
	int32_t nhigh;  /* the free cells of dist2 above 1 */
	/* the next levels, SKELLEVEL_PLANED of them (dist2 2, 4 and 5), as planes made by
	 * skellevel_thin; a planed level's cells are not listed (skellevel.c, NEXT
	 * LEVELS) */
	uint64_t *lev[3];
	bool planed[3]; /* the level is visited from its plane (else listed and sorted) */
} SkelLevel;

/* The levels after the lowest that may be planed (lev) rather than listed by
 * skellevel_high: the next three values a squared distance takes, 2, 4 and 5
 * (skellevel_dist2); a cell of dist2 above SKELLEVEL_PLANED_MAX is always listed. */
#define SKELLEVEL_PLANED 3
#define SKELLEVEL_PLANED_MAX 5
static const int32_t skellevel_dist2[SKELLEVEL_PLANED] = {2, 4, 5};

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

/* skellevel_thin(lv, g, max_high): the planes of g (memory kept for the next grid of
 * the same size) and the counts nlow and nhigh, then the deletions of the lowest
 * level's cells by subfields (skellevel.c); the next levels' planes, and which of them
 * are planed, when nhigh is at most max_high (else none is planed). */
void skellevel_thin(SkelLevel *lv, const Grid *g, int32_t max_high);

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

/* skellevel_high(lv, dist2, out, small, big): the free cells of dist2 above 1 but those
 * of the planed levels, in increasing order, as pairs in out: the padded index, then
 * the cell's dist2 (dist2 is the grid's, w h values); returns their number (out holds
 * twice as many values). Each is counted by its dist2 d: in small[lane][d] when
 * d < SKELLEVEL_SMALL, else in big[d + 1]. */
int32_t skellevel_high(const SkelLevel *lv, const int32_t *dist2, int32_t *out,
                       SkelLevelCount small, int32_t *big);

/* skellevel_sync(lv, state): lv's set made again from the padded state (a cell is in
 * the set when bit 0 of its state byte is set), after visits that deleted cells. */
void skellevel_sync(SkelLevel *lv, const uint8_t *state);

/* skellevel_delete(lv, r, x): the cell of padded row r and column x taken out of lv's
 * set (a deletion while the planed levels are visited, kept in step with the state). */
static inline void skellevel_delete(SkelLevel *lv, int32_t r, int32_t x)
{
	lv->set[(size_t)r * (size_t)lv->stride + 1 + (size_t)(x >> 6)] &=
	    ~((uint64_t)1 << (x & 63));
}

/* skellevel_next(lv, j, state, mark, ends, out): the start of planed level j (dist2 2, 4
 * or 5 for j = 0, 1, 2), on the set as it is then (kept in step with the state): the
 * level's cells in the set that are deletable now (simple, and not a ridge end) as
 * padded indices in increasing order into out (returns their number); each of its
 * other cells in the set gets the state bits `mark` ORed in (skeleton.c: visited and
 * kept), and those of them that are ridge ends (simple, one 4-neighbour in the set and
 * no 8-neighbour of larger dist2) get their bit set in ends (bit pi of the padded index
 * pi). */
int32_t skellevel_next(const SkelLevel *lv, int j, uint8_t *state, uint8_t mark, uint64_t *ends,
                       int32_t *out);

#endif
