/* skelprune.c - the skeleton's pruning: spurs removed, then what that makes deletable
 * (paper 4.2; step 3 of skeleton.c's ALGORITHM, where the spur rule is; the thinning's
 * state is skelthin.h's Thinner). Private to the planner library. Its figures are in
 * skeleton.c's MEASURED. */
#include <assert.h>
#include <math.h>
#include <string.h>

#include "skelthin.h"
#include "utak/plan/skeleton.h"

/* thinner_degree(t, pi): the 4-neighbours of pi in the set. */
static inline int thinner_degree(const Thinner *t, int32_t pi)
{
	const uint8_t *st = t->state;
	return (st[pi + 1] & SKELETON_IN) + (st[pi - 1] & SKELETON_IN) +
	       (st[pi + t->pw] & SKELETON_IN) + (st[pi - t->pw] & SKELETON_IN);
}

/* thinner_mask4(st, pi, pw): pi's 4-neighbours in the set, bit k the k-th of east,
 * north (+pw), west and south: the ring's even neighbours in its order. */
static inline unsigned thinner_mask4(const uint8_t *st, int32_t pi, int32_t pw)
{
	return (unsigned)(st[pi + 1] & SKELETON_IN) | (unsigned)(st[pi + pw] & SKELETON_IN) << 1 |
	       (unsigned)(st[pi - 1] & SKELETON_IN) << 2 |
	       (unsigned)(st[pi - pw] & SKELETON_IN) << 3;
}

/* thinner_walk(t, end, remove, nremove, longest, pending): walks from the end point end
 * to a junction; when the branch is a spur (see the header comment), or may be one,
 * its cells are added to remove[0 .. nremove); returns the new count. The next cell is
 * the first 4-neighbour in the set, in the ring's order, other than the way back: found
 * by masks of the 4-neighbours, with no branch on the way the walk turns, and the next
 * cell's mask gives its degree and its way on. The cells are written after
 * remove[nremove - 1] as the walk goes, and kept when it finds a spur (a walk's cells
 * are no other walk's: a branch has one end point). longest: see thinner_prune. A
 * branch that reaches its junction within SKELETON_SPUR_FACTOR + SKELETON_SPUR_SLACK
 * cells is a spur whatever the junction (a free cell's clearance is at least 1); a
 * longer one needs the junction's dist2, and is listed in pending as three entries
 * (its first place in remove, its length, the junction) for thinner_prune to judge
 * after the scan, where the loads do not wait for one another: loaded here, that
 * dist2 was a cache miss the walk waited for (on the maze, whose branches from the
 * corners reach their junctions in 4 cells, the scan and walks took 0.94 ms at 1024
 * and 30 at 4096; now 0.91 and 25). pending has room: each listed branch has 3 cells
 * or more (thinner_prune asserts the constants allow no fewer), no cell is on two,
 * so its entries are no more than the cells. */
static inline int32_t thinner_walk(const Thinner *t, int32_t end, int32_t *remove, int32_t nremove,
                                   double longest, int32_t *pending, int32_t *npending)
{
	static const uint8_t first[16] = {0, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};
	static const uint8_t degree[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
	const uint8_t *st = t->state;
	const int32_t pw = t->pw;
	const int32_t step[4] = {1, pw, -1, -pw}; /* the 4-neighbours, as thinner_mask4 */
	int32_t cur = end, length = 1;
	unsigned m = thinner_mask4(st, cur, pw), back = 0;
	for (;;) {
		remove[nremove + length - 1] = cur;
		const unsigned j = first[m & ~back];
		const int32_t next = cur + step[j];
		const unsigned mn = thinner_mask4(st, next, pw);
		const int d = degree[mn];
		if (d >= 3) {
			if (length > SKELETON_SPUR_FACTOR + SKELETON_SPUR_SLACK) {
				int32_t *e = pending + 3 * (*npending)++;
				e[0] = nremove;
				e[1] = length;
				e[2] = next;
			}
			return nremove + length;
		}
		if (d <= 1)
			return nremove; /* the branch is all the component: no spur */
		back = 1u << ((j + 2) & 3);
		cur = next;
		m = mn;
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
int32_t thinner_prune(Thinner *t, int32_t *scratch, int32_t maxd)
{
	const double longest = SKELETON_SPUR_FACTOR * sqrt((double)maxd) + SKELETON_SPUR_SLACK;
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
			if ((st[pi] & SKELETON_IN) && thinner_degree(t, pi) == 1)
				nremove = thinner_walk(t, pi, remove, nremove, longest, scratch,
				                       &npending);
		}
	}
	/* the branches listed by the walks as pending: judged by their junctions' dist2,
	 * the loads independent of one another; the spurs' cells stay in remove, the
	 * others' are taken out (the list in scratch is in the order of remove) */
	for (int32_t k = 0; k < npending; k++) {
		int32_t *e = scratch + 3 * k;
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
	 * here retries its neighbours through the stack): marked in the bit plane recheck
	 * as each cell is removed, its rows in the cache (a cell removed later in the
	 * loop may be marked: it is not in the set when the plane is read), and on a large
	 * grid the rows of the cell THIN_AHEAD on fetched; then the plane is read in order
	 * and left zero (it was a list sorted by a radix sort: at 4096 a side, the maze's
	 * 0.9 million cells to test took 2.9 ms to sort) */
	uint64_t *const recheck = t->recheck;
	for (int32_t k = 0; k < nremove; k++) {
#if defined(__GNUC__)
		if (fetch && k + THIN_AHEAD < nremove) {
			__builtin_prefetch(st + remove[k + THIN_AHEAD] - t->pw, 1);
			__builtin_prefetch(st + remove[k + THIN_AHEAD] + t->pw, 1);
		}
#endif
		t->state[remove[k]] &= (uint8_t) ~(SKELETON_IN | SKELETON_KEPT);
		for (int i = 0; i < 8; i++) {
			const int32_t qi = remove[k] + t->off[i];
			if (t->state[qi] & SKELETON_IN)
				recheck[qi >> 6] |= (uint64_t)1 << (qi & 63);
		}
	}
	for (int32_t k = 0; k < t->ends_words; k++) {
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
