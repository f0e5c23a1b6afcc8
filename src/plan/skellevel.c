/* skellevel.c - the skeleton's lowest distance levels by bit planes, 64 cells a word:
 * the lowest thinned in subfields, the next three started a word at a time (paper 4.2;
 * skeleton.c calls it around its visits).
 *
 * WHY  The distance-ordered thinning (skeleton.c) visits the free cells one by one in
 *    order of dist2. Its first level, dist2 1 (the free cells with a blocked 4-neighbour
 *    or on the grid's edge), is most of the visits where the space is narrow: on the
 *    1024 maze (corridors 3 wide) 524 288 of its 786 429 visits. The order within a
 *    level is not fixed by the algorithm (the distance order alone is; skeleton.c
 *    took the cell index), so any order of the first level's deletions gives a
 *    distance-ordered thinning, provided each deletion is one the visit would make at
 *    that moment: a simple cell that is not a ridge end.
 *
 * ALGORITHM  The cells of the lowest level that are deletable are deleted by
 *    subfields, as in the parallel thinning of Golay and Preston (Preston and Duff,
 *    "Modern Cellular Automata", 1984; Hall, "Parallel connectivity-preserving thinning
 *    algorithms", 1996): the padded grid is cut into four subfields by the parities of
 *    x and y. No two cells of one subfield are 8-adjacent, so deleting one changes no
 *    other's neighbourhood, and the deletable cells of a subfield, all deleted at once,
 *    are the same as deleted one after another in any order: each sub-iteration is a
 *    sequence of the thinning's own deletions. The four subfields are taken in turn,
 *    SKELLEVEL_ROUNDS times. Only the level's cells where the space is at least 3
 *    wide across every wall they touch are candidates (the plane `peel`: for each
 *    4-neighbour not free, the two cells in line on the opposite side are free):
 *    in a passage 2 wide both cells are of level 1, and which of them stays is the
 *    tie-break's choice, left to the index order as before. A candidate is tested as
 *    skeleton.c's visit tests it:
 *    - simple: Yokoi's connectivity number for 4-connected sets,
 *      C4 = sum over k = 0, 2, 4, 6 of x_k (1 - x_{k+1} x_{k+2}) (x_i the ring of 8
 *      neighbours from east, counter-clockwise, indices mod 8), is 1; equivalent to
 *      Bertrand's T4 = 1 and T8bar = 1 on all 256 neighbourhoods (asserted against
 *      skeleton.c's table when it is built);
 *    - not a ridge end: it has other than one 4-neighbour in the set, or an
 *      8-neighbour in the set of larger dist2. During this pass the set's cells of
 *      dist2 above 1 are all there (nothing of a higher level is deleted yet), so the
 *      second is the plane `near`, fixed: some 8-neighbour is free and not of level 1.
 *    What is left of the level (cells not deletable when their subfield's turn came)
 *    is then visited by skeleton.c one by one in index order before the next level,
 *    as any cell of the level would be, so none deletable is left behind. No cell of
 *    a lower level exists (dist2 0 is blocked), so no earlier visited cell waits for a
 *    retry when one of these is deleted.
 *    The thinning as a whole thus stays Pudney's distance-ordered homotopic thinning;
 *    only the order within the first level changed (subfields first, then the rest by
 *    index, where it was all by index), and with it, where a corridor's medial axis
 *    falls between two cells of one level, which of them is kept.
 *
 * NEXT LEVELS  The levels dist2 2, 4 and 5 (the three values above 1 a squared
 *    distance takes) each get a plane, found from the free plane alone (a free cell not
 *    low is of level 2 when a diagonal neighbour is blocked, else 4 when a cell two
 *    away along a row or column is, else 5 when a cell a knight's move away is; the
 *    ring outside the grid is blocked, as in edt.c); skellevel_high lists the higher
 *    cells but those of a planed level, so that skelsort.c sorts fewer. A level is
 *    planed where it holds a cell a plane word or more (its word pass then costs less
 *    than listing, sorting and visiting its cells: on the 1024 maze, 3-wide corridors,
 *    levels 2 and 4 hold 45 734 and 255 247 cells, 5 holds 6 770 and is listed). When
 *    a planed level's turn comes (after every lower level's visits, as in the distance
 *    order), skellevel_next tests all its cells at once on the set as it is then (kept
 *    in step by skeleton.c: synced from the state where unplaned visits deleted cells,
 *    updated at each deletion while a planed level is visited): the cells deletable
 *    now (simple, not a ridge end; the cells of higher dist2, all still in the set,
 *    are the plane `above`) are listed for skeleton.c to visit one by one, in index
 *    order; the others are marked visited and kept in the state at once, and those of
 *    them that are ridge ends get their bit in skeleton.c's plane of ends. This is the
 *    same thinning, cell for cell, as visiting the level's cells one by one in index
 *    order: a cell not deletable when the level starts is still not deletable at its
 *    turn unless a neighbour was deleted first, and skeleton.c puts such a cell on a
 *    heap, to be visited at its turn (thinner_visit_level). On the 1024 maze every cell
 *    of level 4 is kept (a corridor's middle line) and every cell of level 2 deleted.
 *
 * MEMORY  four planes of (h + 2) (ceil((w + 2) / 64) + 2) words: half a byte a cell;
 *    four more for the next levels (their three and `above`).
 * COMPLEXITY  O(w h / 64) words a pass: the planes are two passes, each sub-iteration
 *    half the rows, the state a pass, the rest's list a pass.
 * MEASURED  (issue 16; skeleton.c's header has the whole) on the 1024 maze, 524 288
 *    cells of dist2 1: all deleted or left to the visits in 0.48 ms (planes, two
 *    rounds of subfields; 6.8 million instructions, callgrind), where their visits
 *    took about 1.6 ms; the 1024 rooms, rects and Boston_0_1024, whose lowest level
 *    is a thin rim, pay about 7 million instructions for 1-2 million fewer in the
 *    visits. The second round costs 0.4 million instructions on the maze (most words
 *    have no candidate left). The next levels on the 1024 maze (levels 2 and 4 planed, 5
 *    listed): their planes and `above` made with the lowest's, 2.5 million
 *    instructions more in skellevel_thin; skellevel_next 5.4 million (two levels,
 *    about 150 a word) in about 0.40 ms, the visits of level 2 0.21 and the listing
 *    and sort of level 5 0.18, where listing, sorting and visiting the 307 751 higher
 *    cells took about 1.5 ms (0.57, 0.32 and 0.65); the whole skeleton 49.9 -> 39.5
 *    million instructions (skeleton.c's MEASURED).
 *    Issue 16's maze round (skel11): skellevel_planes, the subfields and
 *    skellevel_next compiled for x86-64-v3 too (SKELLEVEL_CLONES, below: 0.45 -> 0.34
 *    ms and 0.30 -> 0.26 on the 1024 maze). With that round's changes to edt.c and
 *    skelprune.c (their MEASURED) and the thinning's tables built once (skeleton.c),
 *    the whole skeleton_compute, the same cell for cell (old and new code in one
 *    process: 500 random grids and the 19 bench grids from 256 to 4096), medians of
 *    41 calls alternating with the code before (9 at 4096), loaded: maze 256 0.159 ->
 *    0.107 ms, 512 0.680 -> 0.507, 1024 2.92 -> 2.26 (1.28 times), 2048 12.1 -> 9.7,
 *    4096 53.1 -> 42.1 (1.26 times); at 1024 rooms 6.30 -> 5.99, rects 6.93 -> 6.43,
 *    Boston_0_1024 7.15 -> 6.69, den520d 5.20 -> 4.84; at 4096 rooms 139 -> 128,
 *    rects 155 -> 149, Boston_0_1024 160 -> 149, den520d 103 -> 95. skelbench (best of
 *    3, two runs each): the maze's ns a cell 2.75, 2.4-2.5, 2.6-2.7, 2.9-3.0, 3.0-3.1
 *    at 256 .. 4096 before, 1.7, 1.7-1.85, 1.96-2.06, 2.22-2.25, 2.46-2.48 after (4096
 *    over 1024: 1.13-1.18 before, 1.19-1.26 after: 1024 gained more). make
 *    bench-compare SIDE=1024 (one run, loaded): the skeleton 5.88, 6.05, 2.20, 6.63 and
 *    4.65 ms on rooms, rects, maze, Boston_0_1024 and den520d, scikit-image's
 *    skeletonize 9.23, 13.4, 7.35, 19.5 and 19.9 times as long. Tried and not kept:
 *    writing a word's first four cells to visit with no loop test in skellevel_next
 *    (no faster), the planed level's cells told by its plane instead of dist2 in the
 *    re-tries (no faster). */
#include "skellevel.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

/* Rounds of the four subfields: the second round deletes what the first one's later
 * subfields made deletable (a corner a corridor turns), the rest is left to the
 * visits. */
#define SKELLEVEL_ROUNDS 2

/* The passes over the planes that cost most (skellevel_planes, the subfields,
 * skellevel_next) are also compiled for x86-64-v3 (AVX2, BMI, POPCNT) on x86-64 Linux,
 * chosen at load time as edt.c's row pass is: the row loops over words vectorise, and
 * the counts and lowest bits are one instruction each. On the 1024 maze (issue 16's
 * maze round, skel11) the planes and subfields took 0.45-0.47 ms -> 0.33-0.34 and
 * skellevel_next 0.30 -> 0.26 (an instrumented copy, means of 200 calls in runs
 * alternating with the code before); rooms, Boston_0_1024 and den520d 0.28-0.40 ->
 * 0.22-0.32; the 4096 maze 7.6 -> 5.9 and 5.2 -> 4.9. Not kept: x86-64-v4 (AVX-512)
 * too (skellevel_next 0.26 -> 0.31: a row of 17 words is short for 8-word vectors),
 * AVX2 alone (skellevel_next 0.28), and clones of skellevel_state, _high and _rest (no
 * faster; _rest 0.007 -> 0.013 ms).
 *
 * The x86-64-v3 clone is asked for only where target_clones handles it: GCC 12 on
 * (older GCC rejects "arch=x86-64-vN" there) and clang 18 on (older clang builds a
 * resolver that never picks it, and LLVM issue 55830 reports assertion failures);
 * elsewhere the clone is AVX2 alone, as edt.c's. ifunc, which target_clones needs,
 * is glibc's (musl has none), hence __GLIBC__ rather than __linux__. */
#if defined(__GNUC__) && defined(__x86_64__) && defined(__GLIBC__) && \
	((!defined(__clang__) && __GNUC__ >= 12) || (defined(__clang__) && __clang_major__ >= 18))
#define SKELLEVEL_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#elif defined(__GNUC__) && defined(__x86_64__) && defined(__GLIBC__)
#define SKELLEVEL_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define SKELLEVEL_CLONES
#endif

void skellevel_init(SkelLevel *lv)
{
	*lv = (SkelLevel){0};
}

void skellevel_free(SkelLevel *lv)
{
	free(lv->set);
	free(lv->low);
	free(lv->near);
	free(lv->peel);
	free(lv->above);
	for (int j = 0; j < SKELLEVEL_PLANED; j++)
		free(lv->lev[j]);
	*lv = (SkelLevel){0};
}

/* skellevel_load8(p): the 8 bytes at p, byte i at bits 8 i whatever the machine's byte
 * order (compilers make it one load on a little-endian machine). */
static inline uint64_t skellevel_load8(const uint8_t *p)
{
	return (uint64_t)p[0] | (uint64_t)p[1] << 8 | (uint64_t)p[2] << 16 | (uint64_t)p[3] << 24 |
	       (uint64_t)p[4] << 32 | (uint64_t)p[5] << 40 | (uint64_t)p[6] << 48 |
	       (uint64_t)p[7] << 56;
}

#define SKELLEVEL_ONES 0x0101010101010101u

/* skellevel_free8(c): the 8 grid cells at c, bit i set when c[i] is free: a cell is
 * GRID_FREE (1) or GRID_BLOCKED (0), so its bit 0 says, and the 8 bits at 8 i times
 * 0x0102040810204080 fall on bit 56 + i with no carry (8 i + 7 j is unique for
 * i, j < 8). */
_Static_assert(GRID_FREE == 1 && GRID_BLOCKED == 0, "skellevel_free8 reads bit 0");
static inline uint64_t skellevel_free8(const uint8_t *c)
{
	return ((skellevel_load8(c) & SKELLEVEL_ONES) * 0x0102040810204080u) >> 56;
}

/* skellevel_row(lv, plane, r): the first word of padded row r. */
static inline uint64_t *skellevel_row(const SkelLevel *lv, uint64_t *plane, int32_t r)
{
	return plane + (size_t)r * (size_t)lv->stride + 1;
}

/* The word of the cells one column east (x + 1) and west (x - 1) of word k's cells, the
 * words beside it giving the end bits. */
static inline uint64_t skellevel_east(const uint64_t *row, int32_t k)
{
	return row[k] >> 1 | row[k + 1] << 63;
}
static inline uint64_t skellevel_west(const uint64_t *row, int32_t k)
{
	return row[k] << 1 | row[k - 1] >> 63;
}

/* skellevel_one(a, b, c, d): the bits set in exactly one of the four words. */
static inline uint64_t skellevel_one(uint64_t a, uint64_t b, uint64_t c, uint64_t d)
{
	return (a | b | c | d) & ~((a & b) | (c & d) | ((a | b) & (c | d)));
}

/* skellevel_count(v): the bits set in v (a sum of bits by halves, no table). */
static inline int32_t skellevel_count(uint64_t v)
{
	v -= (v >> 1) & 0x5555555555555555u;
	v = (v & 0x3333333333333333u) + ((v >> 2) & 0x3333333333333333u);
	v = (v + (v >> 4)) & 0x0f0f0f0f0f0f0f0fu;
	return (int32_t)((v * SKELLEVEL_ONES) >> 56);
}

/* skellevel_planes(lv, g, max_high): set (the free cells), low and near, nlow and
 * nhigh (see SkelLevel) of g; the next levels' planes and `planed` when nhigh is at
 * most max_high. */
SKELLEVEL_CLONES static void skellevel_planes(SkelLevel *lv, const Grid *g, int32_t max_high)
{
	const int32_t w = g->w, h = g->h, words = lv->words;
	uint64_t *const set = lv->set, *const low = lv->low, *const near = lv->near;
	/* set is built by ORs, so cleared first; low, near and peel are written whole in
	 * rows 1 .. h, and their padding rows and guard words stay as allocated, zero */
	memset(set, 0, (size_t)lv->stride * (size_t)(h + 2) * sizeof *set);
	/* the set: grid cell x is padded column x + 1 */
	for (int32_t y = 0; y < h; y++) {
		const uint8_t *c = g->cells + (size_t)y * (size_t)w;
		uint64_t *row = skellevel_row(lv, set, y + 1);
		int32_t x = 0;
		for (; x + 64 <= w; x += 64) {
			uint64_t v = 0;
			for (int j = 0; j < 8; j++)
				v |= skellevel_free8(c + x + 8 * j) << (8 * j);
			row[x / 64] |= v << 1;
			row[x / 64 + 1] |= v >> 63;
		}
		for (; x < w; x++)
			if (c[x] == GRID_FREE)
				row[(x + 1) / 64] |= (uint64_t)1 << ((x + 1) % 64);
	}
	/* low: free with a 4-neighbour not free */
	int32_t nlow = 0, nhigh = 0;
	for (int32_t r = 1; r <= h; r++) {
		const uint64_t *s = skellevel_row(lv, set, r - 1), *c = skellevel_row(lv, set, r),
		               *n = skellevel_row(lv, set, r + 1);
		uint64_t *lo = skellevel_row(lv, low, r), *ab = skellevel_row(lv, lv->above, r);
		for (int32_t k = 0; k < words; k++) {
			const uint64_t l =
			    c[k] & ~(skellevel_east(c, k) & skellevel_west(c, k) & n[k] & s[k]);
			lo[k] = l;
			ab[k] = c[k] & ~l;
			nlow += skellevel_count(l);
			nhigh += skellevel_count(c[k] & ~l);
		}
	}
	/* near: the free cells of higher levels (set and not low) ORed over the rows
	 * above and below, then dilated by a column either way */
	/* the next levels' planes are made only where one of them may be planed (a cell a
	 * word or more, below): a level's cells lie along the boundary, as the lowest
	 * level's, and are not many more than those (not planed where they are fewer;
	 * the result is the same either way) */
	const bool levels = nhigh <= max_high && nlow >= h * words;
	int32_t nlev[SKELLEVEL_PLANED] = {0, 0, 0};
	for (int32_t r = 1; r <= h; r++) {
		const uint64_t *s = skellevel_row(lv, set, r - 1), *c = skellevel_row(lv, set, r),
		               *n = skellevel_row(lv, set, r + 1);
		const uint64_t *ls = skellevel_row(lv, low, r - 1), *lc = skellevel_row(lv, low, r),
		               *ln = skellevel_row(lv, low, r + 1);
		uint64_t *ne = skellevel_row(lv, near, r), *pe = skellevel_row(lv, lv->peel, r);
		/* rows two away: a missing one (outside the padding) stands in as the padding
		 * row, as it is read only where the row between is free */
		const uint64_t *s2 = skellevel_row(lv, set, r >= 2 ? r - 2 : 0),
		               *n2 = skellevel_row(lv, set, r + 2 <= h + 1 ? r + 2 : h + 1);
		uint64_t *l2 = skellevel_row(lv, lv->lev[0], r),
		         *l4 = skellevel_row(lv, lv->lev[1], r),
		         *l5 = skellevel_row(lv, lv->lev[2], r);
		for (int32_t k = 0; k < words; k++) {
			const uint64_t fe = skellevel_east(c, k), fw = skellevel_west(c, k);
			const uint64_t fee = c[k] >> 2 | c[k + 1] << 62, fww = c[k] << 2 | c[k - 1] >> 62;
			pe[k] = lc[k] & (fe | (fw & fww)) & (fw | (fe & fee)) & (n[k] | (s[k] & s2[k])) &
			        (s[k] | (n[k] & n2[k]));
			/* the next levels (NEXT LEVELS): all free at the offsets of dist2 2, of
			 * 4, of 5 (rows two away stand in as above: a cell they are read for
			 * wrongly is low) */
			if (!levels)
				continue;
			const uint64_t hi = c[k] & ~lc[k];
			const uint64_t at2 = skellevel_east(n, k) & skellevel_west(n, k) &
			                     skellevel_east(s, k) & skellevel_west(s, k);
			const uint64_t at4 = fee & fww & n2[k] & s2[k];
			const uint64_t nee = n[k] >> 2 | n[k + 1] << 62,
			               nww = n[k] << 2 | n[k - 1] >> 62,
			               see = s[k] >> 2 | s[k + 1] << 62,
			               sww = s[k] << 2 | s[k - 1] >> 62;
			const uint64_t at5 = nee & nww & see & sww & skellevel_east(n2, k) &
			                     skellevel_west(n2, k) & skellevel_east(s2, k) &
			                     skellevel_west(s2, k);
			l2[k] = hi & ~at2;
			l4[k] = hi & at2 & ~at4;
			l5[k] = hi & at2 & at4 & ~at5;
			nlev[0] += l2[k] ? skellevel_count(l2[k]) : 0;
			nlev[1] += l4[k] ? skellevel_count(l4[k]) : 0;
			nlev[2] += l5[k] ? skellevel_count(l5[k]) : 0;
		}
		uint64_t prev = 0, cur = (s[0] & ~ls[0]) | (c[0] & ~lc[0]) | (n[0] & ~ln[0]);
		for (int32_t k = 0; k < words; k++) {
			const uint64_t next = (s[k + 1] & ~ls[k + 1]) | (c[k + 1] & ~lc[k + 1]) |
			                      (n[k + 1] & ~ln[k + 1]); /* the guard word when k is last */
			ne[k] = cur | cur << 1 | prev >> 63 | cur >> 1 | next << 63;
			prev = cur;
			cur = next;
		}
	}
	lv->nlow = nlow;
	lv->nhigh = nhigh;
	/* a level is planed where it holds a cell a word or more: a level's planes cost
	 * a pass over the words (skellevel_next), listed it costs its cells */
	for (int j = 0; j < SKELLEVEL_PLANED; j++)
		lv->planed[j] = levels && nlev[j] > 0 && nlev[j] >= h * words;
}

/* skellevel_subfield(lv, a, b): one sub-iteration: the low cells in the set of padded
 * column parity a and row parity b that are deletable (see the top of the file) are
 * deleted, all at once. Row r is updated in place: its cells' neighbours in rows r - 1
 * and r + 1 are of the other row parity, and in row r of the other column parity, so
 * none changes during the sub-iteration. The ring of neighbours x0 .. x7 runs from
 * east counter-clockwise, north being row r + 1 (skeleton.c's order). */
SKELLEVEL_CLONES static void skellevel_subfield(SkelLevel *lv, int a, int b)
{
	const uint64_t parity = a == 0 ? 0x5555555555555555u : 0xaaaaaaaaaaaaaaaau;
	const int32_t words = lv->words;
	for (int32_t r = 2 - b; r <= lv->h; r += 2) {
		uint64_t *c = skellevel_row(lv, lv->set, r);
		const uint64_t *n = skellevel_row(lv, lv->set, r + 1),
		               *s = skellevel_row(lv, lv->set, r - 1),
		               *pe = skellevel_row(lv, lv->peel, r),
		               *ne = skellevel_row(lv, lv->near, r);
		for (int32_t k = 0; k < words; k++) {
			const uint64_t cand = c[k] & pe[k] & parity;
			if (cand == 0)
				continue;
			const uint64_t x0 = skellevel_east(c, k), x1 = skellevel_east(n, k), x2 = n[k],
			               x3 = skellevel_west(n, k), x4 = skellevel_west(c, k),
			               x5 = skellevel_west(s, k), x6 = s[k], x7 = skellevel_east(s, k);
			const uint64_t simple = skellevel_one(x0 & ~(x1 & x2), x2 & ~(x3 & x4),
			                                      x4 & ~(x5 & x6), x6 & ~(x7 & x0));
			const uint64_t ridge = skellevel_one(x0, x2, x4, x6) & ~ne[k];
			c[k] &= ~(cand & simple & ~ridge);
		}
	}
}

void skellevel_thin(SkelLevel *lv, const Grid *g, int32_t max_high)
{
	if (!lv->set || lv->w != g->w || lv->h != g->h) {
		skellevel_free(lv);
		lv->w = g->w;
		lv->h = g->h;
		lv->words = (g->w + 2 + 63) / 64;
		lv->stride = lv->words + 2;
		const size_t n = (size_t)lv->stride * (size_t)(g->h + 2);
		lv->set = util_alloc(n, sizeof *lv->set);
		lv->low = util_alloc(n, sizeof *lv->low);
		lv->near = util_alloc(n, sizeof *lv->near);
		lv->peel = util_alloc(n, sizeof *lv->peel);
		lv->above = util_alloc(n, sizeof *lv->above);
		for (int j = 0; j < SKELLEVEL_PLANED; j++)
			lv->lev[j] = util_alloc(n, sizeof *lv->lev[j]);
	}
	skellevel_planes(lv, g, max_high);
	for (int round = 0; round < SKELLEVEL_ROUNDS; round++)
		for (int b = 0; b < 2; b++)
			for (int a = 0; a < 2; a++)
				skellevel_subfield(lv, a, b);
}

void skellevel_state(const SkelLevel *lv, uint8_t *state, uint8_t in)
{
	/* each byte of a word, 8 cells, to 8 state bytes by a table in memory order */
	uint64_t spread[256];
	for (unsigned v = 0; v < 256; v++) {
		uint8_t bytes[8];
		for (int i = 0; i < 8; i++)
			bytes[i] = (v >> i) & 1 ? in : 0;
		memcpy(&spread[v], bytes, sizeof bytes);
	}
	const int32_t pw = lv->w + 2;
	for (int32_t r = 0; r <= lv->h + 1; r++) {
		const uint64_t *row = skellevel_row(lv, lv->set, r);
		uint8_t *st = state + (size_t)r * (size_t)pw;
		int32_t x = 0;
		for (; x + 8 <= pw; x += 8)
			memcpy(st + x, &spread[(row[x / 64] >> (x % 64)) & 255u], 8);
		for (; x < pw; x++)
			st[x] = (row[x / 64] >> (x % 64)) & 1 ? in : 0;
	}
}

int32_t skellevel_rest(const SkelLevel *lv, int32_t *out)
{
	const int32_t pw = lv->w + 2;
	int32_t count = 0;
	for (int32_t r = 1; r <= lv->h; r++) {
		const uint64_t *c = skellevel_row(lv, lv->set, r), *lo = skellevel_row(lv, lv->low, r);
		for (int32_t k = 0; k < lv->words; k++)
			for (uint64_t m = c[k] & lo[k]; m != 0; m &= m - 1)
				out[count++] = r * pw + 64 * k + skellevel_lowest(m);
	}
	return count;
}

int32_t skellevel_count_rest(const SkelLevel *lv)
{
	int32_t count = 0;
	for (int32_t r = 1; r <= lv->h; r++) {
		const uint64_t *c = skellevel_row(lv, lv->set, r), *lo = skellevel_row(lv, lv->low, r);
		for (int32_t k = 0; k < lv->words; k++)
			count += skellevel_count(c[k] & lo[k]);
	}
	return count;
}

/* skellevel_list(lv, dist2, out, small, big, r, k, m, count, l2, l4, l5): the cells m
 * of padded row r, word k, listed and counted (skellevel_high); returns the new count.
 * l2, l4, l5: the cells of m known to be of dist2 2, 4, 5 (the levels' planes, made but
 * not planed; zero where none was made): their dist2 is not loaded (at 4096 a side
 * each load of a sparse level's cell missed the cache). */
static inline int32_t skellevel_list(const SkelLevel *lv, const int32_t *dist2, int32_t *out,
                                     SkelLevelCount small, int32_t *big, int32_t r, int32_t k,
                                     uint64_t m, int32_t count, uint64_t l2, uint64_t l4,
                                     uint64_t l5)
{
	const int32_t w = lv->w, pw = w + 2;
	/* padded column x of row r is the grid's cell x - 1 of row r - 1 */
	const int32_t *d2 = dist2 + (size_t)(r - 1) * (size_t)w - 1;
	for (; m != 0; m &= m - 1) {
		const uint64_t bit = m & (0 - m);
		const int32_t x = 64 * k + skellevel_lowest(m);
		int32_t d;
		if (bit & (l2 | l4 | l5)) {
			d = bit & l2 ? 2 : bit & l4 ? 4 : 5;
		} else {
			d = d2[x];
			/* the planes are dist2's levels */
			assert(d > SKELLEVEL_PLANED_MAX || d == 3 || (l2 | l4 | l5) == 0);
		}
		out[2 * count] = r * pw + x;
		out[2 * count + 1] = d;
		if (d < SKELLEVEL_SMALL)
			small[count & (SKELLEVEL_LANES - 1)][d]++;
		else
			big[d + 1]++;
		count++;
	}
	return count;
}

int32_t skellevel_high(const SkelLevel *lv, const int32_t *dist2, int32_t *out,
                       SkelLevelCount small, int32_t *big)
{
	/* the higher cells are never deleted here: they are the set's cells not low; those
	 * of the planed levels are not listed (two loops, so that a grid with none planed
	 * pays nothing for them; where one is, every level's plane was made) */
	const bool any = lv->planed[0] || lv->planed[1] || lv->planed[2];
	int32_t count = 0;
	for (int32_t r = 1; r <= lv->h; r++) {
		const uint64_t *c = skellevel_row(lv, lv->set, r), *lo = skellevel_row(lv, lv->low, r);
		if (!any) {
			for (int32_t k = 0; k < lv->words; k++)
				count = skellevel_list(lv, dist2, out, small, big, r, k,
				                       c[k] & ~lo[k], count, 0, 0, 0);
			continue;
		}
		const uint64_t *l2 = skellevel_row(lv, lv->lev[0], r),
		               *l4 = skellevel_row(lv, lv->lev[1], r),
		               *l5 = skellevel_row(lv, lv->lev[2], r);
		const uint64_t m2 = lv->planed[0] ? ~(uint64_t)0 : 0,
		               m4 = lv->planed[1] ? ~(uint64_t)0 : 0,
		               m5 = lv->planed[2] ? ~(uint64_t)0 : 0;
		for (int32_t k = 0; k < lv->words; k++) {
			const uint64_t planed = (l2[k] & m2) | (l4[k] & m4) | (l5[k] & m5);
			count = skellevel_list(lv, dist2, out, small, big, r, k,
			                       c[k] & ~(lo[k] | planed), count, l2[k] & ~m2,
			                       l4[k] & ~m4, l5[k] & ~m5);
		}
	}
	return count;
}

/* skellevel_spread(spread, v): spread[b] has byte i equal to v where bit i of b is set,
 * 0 elsewhere (in memory order: byte i is the cell at the word's bit 8 k + i). */
static void skellevel_spread(uint64_t spread[256], uint8_t v)
{
	for (unsigned b = 0; b < 256; b++) {
		uint8_t bytes[8];
		for (int i = 0; i < 8; i++)
			bytes[i] = (b >> i) & 1 ? v : 0;
		memcpy(&spread[b], bytes, sizeof bytes);
	}
}

void skellevel_sync(SkelLevel *lv, const uint8_t *state)
{
	const int32_t pw = lv->w + 2;
	/* the padding rows and columns are blocked and stay so */
	for (int32_t r = 1; r <= lv->h; r++) {
		const uint8_t *st = state + (size_t)r * (size_t)pw;
		uint64_t *row = skellevel_row(lv, lv->set, r);
		int32_t k = 0;
		for (; 64 * k + 64 <= pw; k++) {
			uint64_t v = 0;
			for (int j = 0; j < 8; j++)
				v |= skellevel_free8(st + 64 * k + 8 * j) << (8 * j);
			row[k] = v;
		}
		for (; k < lv->words; k++) {
			uint64_t v = 0;
			for (int32_t x = 64 * k; x < pw && x < 64 * k + 64; x++)
				v |= (uint64_t)(st[x] & 1) << (x - 64 * k);
			row[k] = v;
		}
	}
}

/* skellevel_next_words: skellevel_next, in a static function of its own so that only
 * it is multiversioned (Clang 14 names the dispatcher of an external function with
 * target_clones apart from the callers' references in other files, which then do not
 * link). */
SKELLEVEL_CLONES static int32_t skellevel_next_words(const SkelLevel *lv, int j, uint8_t *state,
                                                     uint8_t mark, uint64_t *ends,
                                                     int32_t *out)
{
	uint64_t spread[256];
	skellevel_spread(spread, mark);
	const int32_t pw = lv->w + 2, words = lv->words;
	/* this level's cells out of `above` first, and those of the levels before it
	 * (again, or for the first time where a level was listed, not planed) */
	for (int32_t r = 1; r <= lv->h; r++) {
		uint64_t *a = skellevel_row(lv, lv->above, r);
		for (int i = 0; i <= j; i++) {
			const uint64_t *l = skellevel_row(lv, lv->lev[i], r);
			for (int32_t k = 0; k < words; k++)
				a[k] &= ~l[k];
		}
	}
	int32_t count = 0;
	for (int32_t r = 1; r <= lv->h; r++) {
		const uint64_t *c = skellevel_row(lv, lv->set, r),
		               *lj = skellevel_row(lv, lv->lev[j], r);
		const uint64_t *n = skellevel_row(lv, lv->set, r + 1),
		               *s = skellevel_row(lv, lv->set, r - 1);
		/* the cells above the level (in the set: none is deleted before its turn),
		 * ORed over rows r - 1 .. r + 1: word k - 1 (prev), k (cur) and k + 1 (next;
		 * the guard word past the last) */
		const uint64_t *as = skellevel_row(lv, lv->above, r - 1),
		               *ac = skellevel_row(lv, lv->above, r),
		               *an = skellevel_row(lv, lv->above, r + 1);
		uint64_t prev = 0, cur = as[0] | ac[0] | an[0];
		for (int32_t k = 0; k < words; k++) {
			const uint64_t next = as[k + 1] | ac[k + 1] | an[k + 1];
			const uint64_t cand = c[k] & lj[k];
			if (cand != 0) {
				const uint64_t near =
				    cur | cur << 1 | prev >> 63 | cur >> 1 | next << 63;
				const uint64_t x0 = skellevel_east(c, k), x1 = skellevel_east(n, k),
				               x2 = n[k], x3 = skellevel_west(n, k),
				               x4 = skellevel_west(c, k), x5 = skellevel_west(s, k),
				               x6 = s[k], x7 = skellevel_east(s, k);
				const uint64_t simple =
				    skellevel_one(x0 & ~(x1 & x2), x2 & ~(x3 & x4), x4 & ~(x5 & x6),
				                  x6 & ~(x7 & x0));
				const uint64_t ridge =
				    simple & skellevel_one(x0, x2, x4, x6) & ~near;
				const uint64_t del = cand & simple & ~ridge, keep = cand & ~del;
				const int32_t pi0 = r * pw + 64 * k;
				for (uint64_t m = del; m != 0; m &= m - 1)
					out[count++] = pi0 + skellevel_lowest(m);
				/* 8 cells a step, every step in the row: most words have cells
				 * kept in most bytes, and a branch a byte mispredicted (a state
				 * byte past the row gets 0 ORed in: the next row's, or the
				 * padding's, within the state as w >= 3 where a cell is planed) */
				uint8_t *st = state + pi0;
				if (keep != 0 && 64 * k + 64 <= pw)
					for (int b = 0; b < 8; b++) {
						uint64_t v;
						memcpy(&v, st + 8 * b, sizeof v);
						v |= spread[(keep >> (8 * b)) & 255u];
						memcpy(st + 8 * b, &v, sizeof v);
					}
				else if (keep != 0)
					for (int b = 0; b < 8 && 64 * k + 8 * b < pw; b++) {
						uint64_t v;
						memcpy(&v, st + 8 * b, sizeof v);
						v |= spread[(keep >> (8 * b)) & 255u];
						memcpy(st + 8 * b, &v, sizeof v);
					}
				const uint64_t e = cand & ridge;
				if (e != 0) {
					const int sh = pi0 & 63;
					ends[pi0 >> 6] |= e << sh;
					if (sh != 0 && (e >> (64 - sh)) != 0)
						ends[(pi0 >> 6) + 1] |= e >> (64 - sh);
				}
			}
			prev = cur;
			cur = next;
		}
	}
	return count;
}

int32_t skellevel_next(const SkelLevel *lv, int j, uint8_t *state, uint8_t mark, uint64_t *ends,
                       int32_t *out)
{
	return skellevel_next_words(lv, j, state, mark, ends, out);
}
