/* skelprune.c - the skeleton's pruning: spurs removed, then what that makes deletable
 * (paper 4.2; step 3 of skeleton.c's ALGORITHM, where the spur rule is; the thinning's
 * state is skelthin.h's Thinner). Private to the planner library. Its figures up to
 * issue 16's seventh round are in skeleton.c's MEASURED.
 *
 * MEASURED  (issue 16's maze round, skel11; an instrumented copy of skeleton_compute,
 *    mean of 200 calls, runs alternating with the code before on the loaded machine)
 *    On the 1024 maze the pruning walks 6524 ends, removes 13352 cells (17 376 marks
 *    of neighbours to test again) and tests 6683: 0.24 ms the scan and walks, 0.10-0.12
 *    the removal and marking, 0.14 the tests, a few ns a step, each a short chain of
 *    dependent loads or a mispredicted branch. The walks' steps without table loads
 *    (thinner_walk) and the marks by rows of three bits without a branch a neighbour
 *    (thinner_prune): 0.56-0.58 -> 0.50 ms at 1024, 12.0-12.3 -> 11.4-11.5 at 4096
 *    (8 calls); the same skeleton (1500 random grids and the ten bench grids, old and
 *    new code in one process). Then the removed cells out of the set before their
 *    neighbours are marked, in chunks (THIN_PRUNE_CHUNK): 20 035 bits to read in the
 *    plane of cells to test again down to 6683 or so, the tests 0.165 -> 0.066 ms;
 *    the pruning 0.43-0.52 -> 0.35-0.42 ms at 1024 (two sessions, loaded), 11.8-12.0
 *    -> 11.0-11.3 at 4096. Tried: prefetching the state ahead of the scan at 1024 as
 *    at 4096 (no change); all cells removed before any is marked (at 4096 the marks'
 *    rows were out of the cache again, no faster). What is left at 1024: the scan and
 *    walks, 0.21 ms, about 100 cycles a walk of a few steps, each step a chain of a
 *    lowest bit, a select and four loads.
 *    At 4096 a side (state 17 MB, dist2 64 MB), more of the rows fetched ahead: the
 *    removed cell's own row as well as those above and below it, the junctions' dist2
 *    of the pending branches THIN_AHEAD on, and the rows of the cells to test
 *    THIN_PRUNE_WORDS words on: the 4096 maze's pruning 12.6-12.9 -> 11.3-12.0 ms (8
 *    calls, two runs), its skeleton 43.9 -> 42.1 (medians of 9, alternating in one
 *    process); rects and Boston_0_1024 within the noise. */
#include <assert.h>
#include <math.h>
#include <string.h>

#include "skelthin.h"
#include "utak/plan/skeleton.h"

/* The pruning's recheck marking (thinner_prune's removal: a loaded word of state
 * masked with 0x010101, shifted by 7 and 14) takes byte k of the word to bit k only
 * where bytes are stored little-end first, as skeleton.c's gathers do. */
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "skelprune.c gathers bytes to bits as on a little-endian machine"
#endif

/* thinner_mask4(st, pi, pw): pi's 4-neighbours in the set, bit k the k-th of east,
 * north (+pw), west and south: the ring's even neighbours in its order. */
static inline unsigned thinner_mask4(const uint8_t *st, int32_t pi, int32_t pw)
{
	return (unsigned)(st[pi + 1] & SKELETON_IN) | (unsigned)(st[pi + pw] & SKELETON_IN) << 1 |
	       (unsigned)(st[pi - 1] & SKELETON_IN) << 2 |
	       (unsigned)(st[pi - pw] & SKELETON_IN) << 3;
}

/* thinner_walk(t, end, m, remove, nremove, longest, pending): walks from the end point
 * end (m: its one 4-neighbour in the set, as thinner_mask4) to a junction; when the
 * branch is a spur (see the header comment), or may be one, its cells are added to
 * remove[0 .. nremove); returns the new count. The next cell is the 4-neighbour in the
 * set other than the way back. A step is a chain of dependent operations (the next
 * cell's four loads wait for its index, which waits for the last cell's mask), and a
 * walk is a few steps, so the chain is kept short: the way on is the mask's lowest bit
 * and its offset two selects (no table loads: the tables of first bits, degrees and
 * offsets took about a third of the scan and walks, 0.24 ms on the 1024 maze), and the
 * next cell's neighbours but the way back, `rest`, say at once whether it is a
 * junction (two bits or more), an end (none) or a cell of the branch (one: the way on).
 * The cells are written after remove[nremove - 1] as the walk goes, and kept when it
 * finds a spur (a walk's cells are no other walk's: a branch has one end point).
 * longest: see thinner_prune. A branch that reaches its junction within
 * SKELETON_SPUR_FACTOR + SKELETON_SPUR_SLACK cells is a spur whatever the junction (a
 * free cell's clearance is at least 1); a longer one needs the junction's dist2, and is
 * listed in pending as three entries (its first place in remove, its length, the
 * junction) for thinner_prune to judge after the scan, where the loads do not wait for
 * one another: loaded here, that dist2 was a cache miss the walk waited for (on the
 * maze, whose branches from the corners reach their junctions in 4 cells, the scan and
 * walks took 0.94 ms at 1024 and 30 at 4096; then 0.91 and 25). pending has room: each
 * listed branch has 3 cells or more (thinner_prune asserts the constants allow no
 * fewer), no cell is on two, so its entries are no more than the cells. */
static inline int32_t thinner_walk(const Thinner *t, int32_t end, unsigned m, int32_t *remove,
                                   int32_t nremove, int32_t longest, int32_t *pending,
                                   int32_t *npending)
{
	const uint8_t *st = t->state;
	const int32_t pw = t->pw;
	int32_t cur = end, length = 1;
	for (;;) {
		remove[nremove + length - 1] = cur;
		/* the way on, j (m has one bit): east 0, north 1, west 2, south 3 */
		const unsigned j = (unsigned)skellevel_lowest(m);
		const int32_t along = (j & 1) ? pw : 1;
		const int32_t next = cur + ((j & 2) ? -along : along);
		const unsigned rest = thinner_mask4(st, next, pw) & ~(1u << ((j + 2) & 3));
		if ((rest & (rest - 1)) != 0) {
			/* next is a junction: its degree is 3 or 4 */
			if (length > SKELETON_SPUR_FACTOR + SKELETON_SPUR_SLACK) {
				int32_t *e = pending + 3 * (*npending)++;
				e[0] = nremove;
				e[1] = length;
				e[2] = next;
			}
			return nremove + length;
		}
		if (rest == 0)
			return nremove; /* the branch is all the component: no spur */
		cur = next;
		m = rest;
		length++;
		if (length > longest)
			return nremove; /* no spur */
	}
}

/* thinner_prune(t, scratch, maxd): removes the spurs (see the header comment), then
 * deletes what that makes deletable; returns the number of cells removed as spurs.
 * scratch is an array as long as the grid (the walks' pending branches). Spurs are
 * found on the set as thinned, then removed. The end points are those of the plane of
 * ridge ends (Thinner.ends) still in the set with one 4-neighbour, found in raster
 * order. Each end is walked when the scan finds it, while its rows are
 * in the cache (walked after the whole scan, they were not, and the walks on the maze
 * cost as much as the scan). maxd is the largest dist2: no junction is farther from the
 * obstacles, so a branch longer than SKELETON_SPUR_FACTOR * sqrt(maxd) +
 * SKELETON_SPUR_SLACK cells is no spur whatever its junction, and its walk stops there
 * (the same test, monotone in the clearance; on the 1024 maze, whose dead ends are
 * long corridors, it saves most of the walking). */
/* The spurs' cells removed and their neighbours marked this many at a time (see
 * thinner_prune). */
#define THIN_PRUNE_CHUNK 256
/* words of the plane of cells to test again whose state rows are fetched ahead, on
 * a large grid (see thinner_prune) */
#define THIN_PRUNE_WORDS 8

int32_t thinner_prune(Thinner *t, int32_t *scratch, int32_t maxd)
{
	const double longest_real = SKELETON_SPUR_FACTOR * sqrt((double)maxd) + SKELETON_SPUR_SLACK;
	/* a length (a whole number) is above longest_real exactly when it is above its
	 * floor; the length test of the walks is then on integers */
	const int32_t longest = (int32_t)floor(longest_real);
	assert(SKELETON_SPUR_FACTOR + SKELETON_SPUR_SLACK >= 2.0); /* thinner_walk's pending */
	/* cells to remove are collected in the stack array, as long as the grid */
	int32_t nremove = 0, npending = 0;
	int32_t *remove = t->stack;
	const uint8_t *st = t->state;
	/* on a grid whose state outgrows THIN_PREFETCH_BYTES, the state THIN_PRUNE_ROWS
	 * rows on is fetched as the scan goes, a line (64 cells) for each word of ends:
	 * a walk from an end reaches rows not yet touched, and at 4096 a side most of its
	 * steps missed the cache (the pruning of the maze took 19.5 ms of 70) */
	const size_t pn = (size_t)t->pw * (size_t)(t->h + 2);
	const size_t ahead = (size_t)THIN_PRUNE_ROWS * (size_t)t->pw;
	const bool fetch = pn > THIN_PREFETCH_BYTES;
	for (int32_t k = 0; k < t->ends_words; k++) {
#if defined(__GNUC__)
		if (fetch && 64 * (size_t)k + ahead < pn)
			__builtin_prefetch(st + 64 * (size_t)k + ahead);
#endif
		for (uint64_t m = t->ends[k]; m != 0; m &= m - 1) {
			const int32_t pi = 64 * k + skellevel_lowest(m);
			const unsigned m4 = thinner_mask4(st, pi, t->pw);
			if ((st[pi] & SKELETON_IN) && m4 != 0 && (m4 & (m4 - 1)) == 0)
				nremove = thinner_walk(t, pi, m4, remove, nremove, longest, scratch,
				                       &npending);
		}
	}
	/* the branches listed by the walks as pending: judged by their junctions' dist2,
	 * the loads independent of one another; the spurs' cells stay in remove, the
	 * others' are taken out (the list in scratch is in the order of remove) */
	for (int32_t k = 0; k < npending; k++) {
		int32_t *e = scratch + 3 * k;
#if defined(__GNUC__)
		if (fetch && k + THIN_AHEAD < npending)
			__builtin_prefetch(t->dist2 + thinner_unpadded(t, e[3 * THIN_AHEAD + 2]));
#endif
		const double r = sqrt((double)t->dist2[thinner_unpadded(t, e[2])]);
		e[2] = e[1] > SKELETON_SPUR_FACTOR * r + SKELETON_SPUR_SLACK; /* no spur */
	}
	int32_t kept = 0, from = 0;
	for (int32_t k = 0; k < npending; k++) {
		const int32_t *e = scratch + 3 * k;
		if (!e[2])
			continue;
		memmove(remove + kept, remove + from, (size_t)(e[0] - from) * sizeof *remove);
		kept += e[0] - from;
		from = e[0] + e[1];
	}
	memmove(remove + kept, remove + from, (size_t)(nremove - from) * sizeof *remove);
	nremove = kept + (nremove - from);
	/* only a cell next to a removed one has a new neighbourhood (every other was
	 * left not deletable by the thinning), so only those are tested again, in raster
	 * order, as a test of every cell in raster order would (and equals: a deletion
	 * here retries its neighbours through the stack): the spurs' cells removed, then
	 * their neighbours still in the set marked in the bit plane recheck, their rows in
	 * the cache after the walk (on a large grid the rows of the cell THIN_AHEAD on
	 * fetched), then the plane read in order and left zero (it was a list sorted by a
	 * radix sort: at 4096 a side, the maze's 0.9 million cells to test took 2.9 ms to
	 * sort). The cells are removed THIN_PRUNE_CHUNK at a time before any of them is
	 * marked: so no 4-byte load of a row overlaps a byte just stored (a store not
	 * forwarded, which the load waits for), and hardly any removed cell is marked (a
	 * cell of a later chunk may be, and is not in the set when the plane is read;
	 * marked, as when each cell was removed as its marks were made, removed cells
	 * were two thirds of the bits read, each a branch on the cell's state,
	 * mispredicted a third of the time); the chunk's rows are still in the cache. The three cells of each row from
	 * pi - 1 to pi + 1 come as three bits, ORed in at the first one's place, with no
	 * branch on each neighbour (one a cell in three was mispredicted). The second
	 * word's share is the bits past the first word, shifted in two steps as a shift by
	 * 64 is not defined; it lands in the word past the state's cells only with bits of
	 * the state's three zero bytes past its end */
	uint64_t *const recheck = t->recheck;
	for (int32_t k0 = 0; k0 < nremove; k0 += THIN_PRUNE_CHUNK) {
		const int32_t k1 = nremove - k0 < THIN_PRUNE_CHUNK ? nremove : k0 + THIN_PRUNE_CHUNK;
		for (int32_t k = k0; k < k1; k++) {
#if defined(__GNUC__)
			if (fetch && k + THIN_AHEAD < nremove) {
				__builtin_prefetch(st + remove[k + THIN_AHEAD] - t->pw, 1);
				__builtin_prefetch(st + remove[k + THIN_AHEAD], 1);
				__builtin_prefetch(st + remove[k + THIN_AHEAD] + t->pw, 1);
			}
#endif
			t->state[remove[k]] &= (uint8_t) ~(SKELETON_IN | SKELETON_KEPT);
		}
		for (int32_t k = k0; k < k1; k++) {
			const int32_t pi = remove[k];
			for (int32_t b = pi - t->pw - 1; b <= pi + t->pw - 1; b += t->pw) {
				const uint32_t v = thinner_load4(st + b) & 0x010101u;
				const uint64_t bits = (v | v >> 7 | v >> 14) & 7u;
				recheck[b >> 6] |= bits << (b & 63);
				recheck[(b >> 6) + 1] |= (bits >> 1) >> (63 - (b & 63));
			}
		}
	}
	for (int32_t k = 0; k < t->ends_words; k++) {
#if defined(__GNUC__)
		/* on a large grid, the rows of the cells to test THIN_PRUNE_WORDS words on */
		if (fetch && k + THIN_PRUNE_WORDS < t->ends_words &&
		    recheck[k + THIN_PRUNE_WORDS] != 0) {
			const uint8_t *at = st + 64 * (size_t)(k + THIN_PRUNE_WORDS);
			__builtin_prefetch(at - t->pw);
			__builtin_prefetch(at);
			__builtin_prefetch(at + t->pw);
		}
#endif
		uint64_t m = recheck[k];
		if (m == 0)
			continue;
		recheck[k] = 0;
		for (; m != 0; m &= m - 1) {
			const int32_t pi = 64 * k + skellevel_lowest(m);
			if ((t->state[pi] & SKELETON_IN) && thinner_deletable(t, pi))
				thinner_delete_from(t, pi);
		}
	}
	return nremove;
}
