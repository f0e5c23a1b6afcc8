/* gridpath.c - A* on the 8-connected grid (paper 4.1: "an application of the A*
 * algorithm of [8] using their function f = g + h").
 *
 * ALGORITHM: A* (P.E. Hart, N.J. Nilsson, B. Raphael, "A formal basis for the
 * heuristic determination of minimum cost paths", IEEE Trans. SSC 4(2), 1968) on
 * the graph of grid.h's cells, 8-connected, straight steps 1, diagonal steps sqrt 2,
 * a diagonal step only when both orthogonally adjacent cells are free. The
 * heuristic is the octile distance, which is the exact cost on an empty grid, so it
 * is consistent: a cell is final when it is first closed and is never reopened.
 * The open list uses lazy deletion: an improved cell is pushed again and stale
 * entries are skipped when popped (cheaper than decrease-key, whose position index
 * costs a random memory access per swap); plain A* pushes every offer to a cell not
 * closed and keeps no f per cell (LAZY OFFERS). Plain A* files its entries in five
 * first-in first-out queues, one for each growth of f a step can make above zero
 * (FIFO QUEUES), and orders by exact integer keys (EXACT KEYS); the jump search
 * (gridjump.c), whose growths are arbitrary, files them in buckets of f, a page of
 * them with an overflow beyond it, the current bucket a binary heap, and orders by
 * doubles (EXACT TIES). A neighbour whose f equals the f being expanded (the least
 * in the list) skips the queues or buckets through a
 * stack. Each free cell's legal steps are one byte of its node (made by the first
 * query from the 3 x 3 neighbourhood, by the table legal of gridpath_init), so an
 * expansion walks the set bits in order of d instead of testing eight neighbours
 * and two corners each.
 *
 * PERFORMANCE (issue 16; instructions by callgrind, exact, of one warm corner-to-
 * corner query at 1024 as skelbench picks the ends, gridpath_find inclusive;
 * first = the tree before issue 16's work, which kept the paged heap for both
 * searches; then the second round's, the third's, the fourth's, then this, the
 * fifth):
 *   plain A*    rooms 230 -> 145 -> 83 -> 35.4 -> 32.1 M, rects 149 -> 93 -> 54 ->
 *               20.8 -> 18.8, maze 333 -> 209 -> 151 -> 105.3 -> 96.1 (688 000
 *               cells expanded: 485 -> 304 -> 220 -> 153 -> 140 instructions a
 *               cell), Boston_0_1024 192 -> 119 -> 69 -> 28.7 -> 26.0, den520d (x2)
 *               51 -> 32 -> 19 -> 7.4 -> 6.7;
 *   jump points: gridjump.c, PERFORMANCE.
 * The steps of the second round, maze plain A*: the parent's neighbours skipped 337
 * -> 292 M; the ring for the paged heap 292 -> 232; locals instead of fields re-read
 * after byte stores and the sift inline 232 -> 225; the sorted current bucket 225
 * -> 209 (rooms 172 -> 145, and its time about halved: the heap's branches
 * mispredicted). The third: integer keys for the doubles (EXACT KEYS), f's growth
 * by a table of the cell's region about the goal instead of h from the octile
 * formula, one test for closed and not improved 209 -> 186; the ring's state in
 * locals and the step into the marks (no byte store that may alias them) 186 ->
 * 181; index types without sign extension 181 -> 177; ties in f left in order of
 * push, last first (TIES), instead of to the larger g 177 -> 162 (rooms 115 -> 96:
 * no sort moves equal keys); the region tables as byte offsets, the current
 * bucket's bit cleared when left, steps as byte offsets 162 -> 154; y by a
 * multiplication instead of carried in each entry 154 -> 149; nodes of 8 bytes, not
 * 16 (F RELATIVE) 149 -> 154, but the maze's query 1.15 times faster (34.0 -> 29.5
 * ms alternated, the caches flushed before each query as the benchmark's other jobs
 * do: at 32 bytes a node it had run 1.25 times slower than at 16, and 2 MB pages by
 * madvise gained under 5%); the current bucket told by its slot in a push 154 ->
 * 151. The fourth: the ring of 256 sorted buckets replaced by five first-in
 * first-out queues (FIFO QUEUES) 151 -> 143 (a push appends: 36 -> 23 instructions;
 * no sort; branch mispredictions in callgrind's model 2.2 -> 1.7 M a query); the
 * prefetches (PREFETCH) 143 -> 147, but the time down by a fifth at 1024 and a
 * third at 4096; no branch for the start's parent 147 -> 146; the steps skipped by
 * DIAGONAL FIRST, (b) of PARENT'S NEIGHBOURS, 146 -> 112, and by (c) 112 -> 105 (the
 * neighbours tried a cell 2.6 -> 1.0, mispredictions 1.7 -> 0.7 M). Time, best of
 * 9 alternated with the third round's code in one session (warm caches): rooms
 * 8.33 -> 3.32 ms (2.51 times faster), rects 4.95 -> 1.96 (2.52), maze 29.2 ->
 * 15.7 (1.86), Boston_0_1024 6.89 -> 2.73 (2.53), den520d 1.37 -> 0.62 (2.21);
 * maze at 4096, best of 3, 313-324 -> 160-175 ms. Without the prefetches it runs
 * 1.30-1.34 times slower at 1024, 1.35 at 4096 (211-216 against 158-160 ms).
 * Ratios to libtcod: see gridpath.h. Where the time went then, in the maze: about
 * 153 instructions a cell expanded (a pop about 40, a push about 23, the region and
 * the parent's steps about 30, one neighbour tried) and about 1.0 branch
 * misprediction (the queue of the least head, the loop's end). The search is bound
 * by the latency from a pop to the node it reads to the next pop, which branch
 * prediction lets the processor run ahead of: before the skips of (b) and (c),
 * with 2.5 mispredictions a cell, a version that chose by masks instead of
 * branches (the neighbours' tests, the queue of the least head) mispredicted a
 * fifth less but ran 1.1 to 1.3 times slower; so did a first pass for the mask of
 * taken neighbours, and buckets 4 or 16 times finer (153, 159 M).
 * The fifth round (issue 16, margin on the maze), by memory more than instructions:
 * WALK BACK, LAZY OFFERS (nodes of 4 bytes, no store at a push), ROOM and the push's
 * second prefetch (PREFETCH). Time, a driver timing gridpath_find on the bench
 * grids after writing 64 MB to flush the caches (thread CPU; the median of five
 * runs, each the median of 10 queries, alternating with the fourth round's code
 * in one session, load 8 on 2 cores; the ends as skelbench picks them): rooms 2.77
 * -> 2.21 ms, rects 1.61 -> 1.27, maze 18.1 -> 10.2 (1.78 times faster; 26 -> 15 ns
 * a cell expanded), Boston_0_1024 2.18 -> 1.70, den520d 0.52 -> 0.45; at 4096
 * (medians of 5 queries, three runs alternated) maze 161-172 -> 96-98 ms, rooms
 * 44-45 -> 35, rects 24.5-24.8 -> 19.4-19.9. The same paths, point for point, on
 * all of them. Where the maze's time goes now: the 256 maze (nodes 264 KB, in the
 * L2 cache) costs 9.8 ns a cell expanded, the 1024 about 15 (nodes 4 MB): a third
 * is memory; the rest the chain from a pop to its node to the next push and pop,
 * with about 1 branch misprediction a cell (callgrind's model: the loop's end,
 * the least head's queue). Tried and not kept this round, each no faster or slower
 * on the maze: the first legal step pushed without a branch (the stack's and the
 * queue's slot both written, one pointer advanced: 2-4% slower), the stack's top
 * kept in a register (the same), the code built for x86-64-v3 (2-3% faster: not
 * worth a clone), the walk back fetching 16 steps ahead too (1%).
 *
 * SCALING (issue 16's scaling round, `skelbench --scaling`, every side timed in each
 * round, medians of 7 and 9, three runs, loaded): corner to corner on rooms, rects
 * and the maze from 256 to 4096 a side, plain A* costs 9.4-10.8, 11.1-14.0 and
 * 15.0-18.6 ns a cell expanded at 256 and 11.4-12.1, 10.2-11.4 and 20.6-22.1 at
 * 4096 (rooms about 1.15 times, the maze 1.1-1.5: its nodes, 0.5 MB at 256, 134 MB
 * at 4096, leave the caches; the prefetches below hide most of it); the jump search
 * 240-340, 260-375 and 100-135 ns a jump point expanded at 256, 256-300, 258-320 and
 * 115-125 at 4096 (flat within the noise). A cell of the grid costs what its expansions do: the
 * cells a query expands are not proportional to the grid's (the 2048 maze's ends
 * are 807 097 cells apart by A*, the 1024's 687 929). Nothing was changed for it.
 *
 * PREFETCH: a cell pushed by step d is expanded later and then reads the line of
 * the cell one more step d beyond it, a new row or column that no hardware
 * prefetcher foresees when the search runs along a column; gridpath_prefetch asks
 * for it at the push, and for the node of a queue's next head at each pop. The
 * nodes were 8 MB at 1024 (past the 1 MB L2 cache here, and flushed by the
 * benchmark's other jobs) and 134 MB at 4096 (past every cache); 4 and 67 MB since
 * LAZY OFFERS. Further lines (the cells beside the one beyond, or two steps beyond)
 * gained nothing measurable then. Since LAZY OFFERS a push also asks for the line
 * GRIDPATH_PUSH_AHEAD = 4 steps beyond n: a run of growth 0 down a corridor goes by
 * the stack, each cell expanded right after its push, too soon for the line one
 * step on to arrive. Maze at 1024, caches flushed before each query (medians of 10,
 * three runs alternated): 10.5-10.7 -> 9.9-10.0 ms; 6 or 8 steps the same within the
 * noise, 2 steps half of it; the cells beside n, or the three lines about the
 * queue's next head, nothing measurable. (How much is memory: the 256 maze, 264 KB
 * of nodes, 9.8 ns a cell expanded, warm; 512, 1 MB, 13.7; 1024 15.4.)
 *
 * WALK BACK: the path is read back from the goal along each cell's from, a chain of
 * dependent loads, one node a step (45 298 steps on the 1024 maze, 303 414 at
 * 4096), each a miss past the caches. It is walked once, its steps kept in a byte
 * array (walk) from which the points are written (it was walked twice: 15% of the
 * maze's query at 1024, 26% at 4096 by perf), and each step asks for the node
 * GRIDPATH_WALK_AHEAD steps on as if the path ran straight on (a corridor), which
 * overlaps the misses: the 4096 maze's query 150 -> 120 ms (warm, best of 3), the
 * walk 26% -> 9% of it; 4 or 16 steps ahead were no better.
 *
 * PARENT'S NEIGHBOURS: an expansion of a cell c reached from its parent p (the
 * cell whose offer set c's cost, closed before c) need not try the steps of three
 * kinds, skip[from][moves of p] (gridpath_init), which leaves one step, or three,
 * to a cell entered straight along a corridor:
 *   (a) to p itself, or to a cell n one legal step from p: the path p, n costs
 *       |pn| < |pc| + |cn| (one step is shorter than two);
 *   (c) c entered diagonally (step e), to the cell n two straight steps s from p
 *       (s a component of e, the step c, n the other diagonal with that
 *       component), when the step s from p is legal (always, as c to n needs
 *       its corner p + s free): p, p + s, n costs 2 < 2 sqrt 2;
 *   (b) DIAGONAL FIRST: c entered straight (step s), to n = c + e for a diagonal
 *       e with component s, when the diagonal e from p is legal: the path p, m =
 *       p + e, n (m to n is the straight step s, n free as c to n is legal) costs
 *       sqrt 2 + 1, as much as p, c, n.
 * Why the search stays exact (every cell's cost final when it is closed, as plain
 * A* with consistent h): suppose a cell n is about to be closed with a cost above
 * its least, the first such. Take a shortest path to n, its first cell v not
 * closed at its least cost, and v's predecessor u on it, which is (and so is u's
 * parent p, closed before u). The offer u, v lies on a shortest path, so neither
 * (a) nor (c) skipped it: both skip only offers that a strictly shorter path
 * beats. If u made it, v is open at its least cost. If (b) skipped it, p, m, v is
 * a shortest path too (m = p + e costs at most p's least + sqrt 2); on the
 * shortest path through p, m and v, take the first cell not closed at its least:
 * either v again, now after m, whose offer to v (the straight s) was made since
 * no rule skips it ((b) skips diagonals only), so v is open at its least; or a
 * cell of lower least cost than v, and repeat (this ends: the least costs fall).
 * So some open cell x lies on a shortest path to n at its least cost, and f(x) <=
 * the least f(n) < f(n) (consistent h): x leaves the list before n, a
 * contradiction. The offers skipped would never have been taken or never have been
 * needed, so the lengths are those of plain A* (test_gridpath against Dijkstra and
 * the published Moving AI optima), and so are the cells expanded of f below the
 * optimum (those of f equal to it depend on the order of ties: the same counts on
 * the five 1024 maps and the 4096 maze); where shortest paths tie another may
 * come out. Maze at 1024: (a) alone 337
 * -> 292 M instructions (callgrind, gridpath_find, second round); (b) 146 -> 112 M,
 * (c) 112 -> 105 M (this round); in the maze the neighbours tried a cell fell from
 * 2.6 (38% unseen, 8% improved, 39% open and not improved, 14% closed) to 1.0, all
 * unseen (every free cell is offered once, by one parent); rooms 1.02, 98.5%
 * unseen.
 *
 * EXACT TIES (the jump search, gridjump.c): a cost is kept as two integers,
 * straight and diagonal step counts, and turned into a double by one fixed
 * expression. Since sqrt 2 is irrational, two costs are equal exactly when their
 * counts are, and then their doubles are bit-identical; so ties in f are true ties,
 * and they go to the larger g (the entry nearer the goal), which makes A* run
 * straight down a corridor of equal-f cells instead of flooding it.
 *
 * EXACT KEYS (plain A*): a cost a + b sqrt 2 (a straight steps, b diagonal) is the
 * integer a q + b p, with p / q = 1855077841 / 1311738121 a convergent of sqrt 2
 * (p^2 - 2 q^2 = -1, so |p - q sqrt 2| = 1 / (p + q sqrt 2) < 2.7e-10). Two
 * distinct costs differ by |da + db sqrt 2| >= 1 / (|da| + sqrt 2 |db|) (as |da^2 -
 * 2 db^2| >= 1), their keys by q times that less at most |db| 2.7e-10: so keys are
 * ordered as the costs while (|da| + sqrt 2 |db|) |db| < q (p + q sqrt 2) = 4.9e18,
 * which holds for step counts below 2^30; and equal keys mean equal counts (q
 * divides db p, gcd(p, q) = 1, |db| < q). f is such a key, u64 (below 2^63 for
 * such counts). Exact for any grid of fewer than 2^29 cells, with no double in the
 * search. A step's growth of f, step + h(next) - h(cell), depends only
 * on the signs of the cell's offset (rx, ry) from the goal and on |rx| - |ry|
 * clamped to [-2, 2] (a step changes each of |rx| and |ry| by one, so only offsets
 * within 2 of a diagonal can swap the longer axis): 45 regions, df[region][step]
 * (gridpath_init, which checks that claim on every offset within 5 of the goal), so
 * a neighbour's f is its cell's f plus one load; 0 sends it to the stack.
 *
 * F RELATIVE: an entry of the open list keeps only the low 32 bits of its f's key:
 * F, the f being expanded, is the least in the list and never decreases, and every
 * offer is at most 2 sqrt 2 above the F of its time, so every entry's f lies in [F,
 * F + 2 sqrt 2], 3.71e9 of key, under 2^32: its low 32 bits less F's, modulo 2^32,
 * give it exactly. (Until LAZY OFFERS a node kept these bits too, to compare an
 * offer to an open cell with its best.)
 *
 * LAZY OFFERS: a cell's node is 4 bytes, its legal steps, the step that closed it
 * and the round it was closed in, and nothing else: no f, no open mark. Every offer
 * to a cell not closed is pushed, the step that made it kept in the entry (the cell
 * index above 3 bits, below 2^29 cells: EXACT KEYS), and the first entry of a cell
 * to leave the list closes it and writes its from; the later ones are stale,
 * refused by the mark. This is the lazy deletion above with the comparison of an
 * offer against the open cell's best left to the list's order: a cell's entries
 * leave in order of f, its h fixed, so the first carries its least g (consistent
 * h). A push writes no node (it reads the neighbour's mark, to refuse a closed
 * one); an offer that the node's f would have refused becomes an entry more, rare
 * after PARENT'S NEIGHBOURS (none in the maze, where every free cell is offered
 * once; rects 142 581 -> 142 650 cells expanded, other ties). Nodes of 4 bytes, not
 * 8, halve the lines a query touches (16 cells to a line) and the stores: the maze's
 * query, its caches flushed before each query, 12.2-13.7 -> 9.4-9.8 ms at 1024
 * (medians of 10, three runs alternated), warm 108 -> 86 ms at 4096, for about the
 * same instructions (105.5 -> 107.9 M, callgrind). Where shortest paths tie,
 * another may come out than when an equal offer was refused.
 *
 * FIFO QUEUES: a step's growth of f (EXACT KEYS) is 0 or one of five values, 2 -
 * sqrt 2, 2 sqrt 2 - 2, sqrt 2, 2 and 2 sqrt 2 (gridpath_init finds them in df and
 * asserts that there are five). An entry pushed with growth w has the key F + w,
 * F the f being expanded; F never decreases (consistent h), so the keys pushed
 * into the queue of w never decrease either, and a first-in first-out queue per
 * growth is sorted by construction: the least entry of the list is the least of
 * the five heads (and the stack's, F itself, before them). A pop compares five
 * keys (hk, the heads' keys, kept per queue); a push appends. No bucket, no sort,
 * no bitmap of nonempty buckets. Their entries span at most 2 sqrt 2 (F RELATIVE),
 * so an entry keeps its key's low 32 bits and a head's key is F plus their
 * difference.
 *
 * TIES: entries of equal f leave in this order: the stack's, last pushed first (a
 * depth-first order among equals, which runs down a corridor of equal-f cells much
 * as a larger g first would, without comparing g); then the queue of the smaller
 * growth first (its entry was pushed from a larger F, later), and in a queue first
 * pushed first. Any order of equal f is optimal (consistent h, exact keys), so only
 * which of several shortest paths comes out may differ, and the count of cells
 * expanded by a few of those of the last f: the same lengths everywhere, and with
 * the queues, not the ring of sorted buckets (LIFO among equals) of the third
 * round: rooms 238 811 -> 237 769 cells, rects 142 903 -> 142 581, maze 687 929
 * (another path of the same length), Boston_0_1024 190 205 -> 190 559, den520d
 * 50 584 -> 50 682.
 *
 * ROOM: a push tests no capacity. Before an expansion, which pushes at most 8
 * entries, room (the least free slots of any queue and the stack, less 8 for each
 * expansion since it was counted) is at least 8, else each queue or stack with
 * fewer than GRIDPATH_ROOM free slots grows and room is counted again (about once in
 * 30 expansions). Maze at 1024: 107.9 -> 94.0 M instructions (callgrind), the time
 * the same within the noise (10.0-10.5 ms against 9.8-10.5, five runs alternated).
 * Not kept: the head's key of a push's queue set by a minimum, a store on every
 * push instead of a test (95.0 M, but 1.35 times slower: the pop's loads of the
 * heads' keys run ahead of a store whose queue is known late, and are replayed).
 *
 * INVARIANTS: node[c]'s round (bits 12-31) is this query's once c is closed, its
 * cost final, and then from (bits 8-11) is the step of a shortest path into it (8
 * for the start); with an earlier round c is not closed. Bits 0-7, its legal
 * steps, never change. Every entry's cell is free and was offered by a closed cell
 * by the entry's step. The border cells of the padded copy are never free.
 *
 * MEMORY: see gridpath.h. COMPLEXITY: plain A* O(n) for n cells expanded, n <=
 * free cells (a push or a pop is O(1), FIFO QUEUES; the queues' arrays grow by
 * doubling); the jump search: gridjump.c. Initialisation O(w h) once per grid,
 * and a query touches only what it expands (the round counter replaces clearing
 * the marks) and, for plain A*, its region tables, O(w + h). */
#include "utak/plan/gridpath.h"

#include <assert.h>
#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "gridpath_work.h"
#include "utak/base/util.h"

/* EXACT KEYS (see the header): a cost a + b sqrt 2 is kept as the integer
 * a GRIDPATH_KEY_ONE + b GRIDPATH_KEY_SQRT2, the two the Pell pair p^2 - 2 q^2 = -1
 * (p/q a convergent of sqrt 2). */
#define GRIDPATH_KEY_ONE UINT64_C(1311738121)
#define GRIDPATH_KEY_SQRT2 UINT64_C(1855077841)
/* GridPathNode.info: the legal steps in bits 0-7, from in 8-11, the round the cell
 * was closed in from 12 on (so any mark of this round exceeds any of an earlier
 * one). */
#define GRIDPATH_MOVES 0xffu
#define GRIDPATH_FROM_SHIFT 8
#define GRIDPATH_ROUND_SHIFT 12
/* An entry of the open list (LAZY OFFERS): its cell above GRIDPATH_ENTRY_SHIFT, the
 * step that offered it below (a cell index is below 2^29: EXACT KEYS). */
#define GRIDPATH_ENTRY_SHIFT 3
#define GRIDPATH_ENTRY_FROM 7u
/* How many steps ahead the walk back fetches (WALK BACK), and a push (PREFETCH). */
#define GRIDPATH_WALK_AHEAD 8
#define GRIDPATH_PUSH_AHEAD 4
/* The least room ROOM makes in each queue and the stack, when it looks. */
#define GRIDPATH_ROOM 256
/* A queue's first array (FIFO QUEUES), a power of two. */
#define GRIDPATH_QUEUE_FIRST 256
_Static_assert(GRIDPATH_KEY_SQRT2 *GRIDPATH_KEY_SQRT2 ==
                   2 * GRIDPATH_KEY_ONE * GRIDPATH_KEY_ONE - 1,
               "not a Pell pair");

/* gridpath_prefetch(p): asks for p's cache line ahead of its use, where the
 * compiler can (a hint: no effect on results). */
static inline void gridpath_prefetch(const void *p)
{
#if defined(__GNUC__)
	__builtin_prefetch(p, 1);
#else
	(void)p;
#endif
}

/* gridpath_prefetch_near(p, k): gridpath_prefetch of p + k, which may lie outside
 * p's array (the address is made as an integer, not by pointer arithmetic). */
static inline void gridpath_prefetch_near(const uint32_t *p, ptrdiff_t k)
{
	gridpath_prefetch((const void *)((uintptr_t)p + (uintptr_t)(k * (ptrdiff_t)sizeof *p)));
}

/* gridpath_key_h(ax, ay): the key of the octile distance over (ax, ay) >= 0. */
static uint64_t gridpath_key_h(int32_t ax, int32_t ay)
{
	const uint64_t lo = (uint64_t)(ax < ay ? ax : ay), hi = (uint64_t)(ax < ay ? ay : ax);
	return (hi - lo) * GRIDPATH_KEY_ONE + lo * GRIDPATH_KEY_SQRT2;
}

/* gridpath_region(rx, ry): the region about the goal of a cell at (rx, ry) from it
 * (goal - cell), 0..44: the signs of rx and ry and |rx| - |ry| clamped to [-2, 2],
 * all that a step's change of the octile distance depends on (see EXACT KEYS). */
static inline unsigned gridpath_region(int32_t rx, int32_t ry)
{
	const int32_t ax = rx < 0 ? -rx : rx, ay = ry < 0 ? -ry : ry;
	int32_t dd = ax - ay;
	dd = dd < -2 ? -2 : dd > 2 ? 2 : dd;
	return (unsigned)(((rx > 0) - (rx < 0) + 1) * 15 + ((ry > 0) - (ry < 0) + 1) * 5 + dd + 2);
}

double gridpath_octile(int32_t dx, int32_t dy)
{
	int32_t ax = abs(dx), ay = abs(dy);
	int32_t lo = ax < ay ? ax : ay, hi = ax < ay ? ay : ax;
	return (double)(hi - lo) + (double)lo * GRIDPATH_SQRT2;
}

void gridpath_init(GridPathSearch *s, const Grid *grid)
{
	int32_t pw = grid->w + 2, ph = grid->h + 2;
	*s = (GridPathSearch){0};
	s->w = grid->w;
	s->h = grid->h;
	s->pw = pw;
	s->ph = ph;
	/* rows and cols: one bit a cell, a word before and after the lines so that a
	 * scan may read one word past either end of a line (see gridpath_scan) */
	s->row_words = (pw + 63) / 64;
	s->col_words = (ph + 63) / 64;
	const size_t row_total = (size_t)ph * (size_t)s->row_words + 2;
	const size_t col_total = (size_t)pw * (size_t)s->col_words + 2;
	s->rows = (uint64_t *)util_alloc(row_total, sizeof *s->rows) + 1;
	s->cols = (uint64_t *)util_alloc(col_total, sizeof *s->cols) + 1;
	memset(s->rows - 1, 0, row_total * sizeof *s->rows);
	memset(s->cols - 1, 0, col_total * sizeof *s->cols);
	for (int32_t y = 0; y < grid->h; y++)
		for (int32_t x = 0; x < grid->w; x++)
			if (grid->cells[(size_t)y * grid->w + x] == GRID_FREE) {
				uint64_t *row = s->rows + (size_t)(y + 1) * s->row_words;
				uint64_t *col = s->cols + (size_t)(x + 1) * s->col_words;
				row[(x + 1) / 64] |= (uint64_t)1 << ((x + 1) % 64);
				col[(y + 1) / 64] |= (uint64_t)1 << ((y + 1) % 64);
			}
	/* the legal steps of a cell from its 3 x 3 neighbourhood (see gridpath_moves) */
	for (unsigned nb = 0; nb < 512; nb++) {
		/* free(dx, dy): bit 3 (dy + 1) + dx + 1 of nb */
#define GRIDPATH_NB_FREE(dx, dy) (nb >> (3 * ((dy) + 1) + (dx) + 1) & 1u)
		unsigned m = 0;
		if (GRIDPATH_NB_FREE(0, 0)) {
			for (int d = 0; d < 4; d++)
				m |= GRIDPATH_NB_FREE(gridpath_dx[d], gridpath_dy[d]) << d;
			for (int k = 0; k < 4; k++) {
				const int d = 4 + k;
				if ((m >> k & 1) && (m >> ((k + 1) & 3) & 1) &&
				    GRIDPATH_NB_FREE(gridpath_dx[d], gridpath_dy[d]))
					m |= 1u << d;
			}
		}
#undef GRIDPATH_NB_FREE
		s->legal[nb] = (uint8_t)m;
	}
	/* the steps an expansion may skip (see PARENT'S NEIGHBOURS in gridpath_find) */
	for (int d = 0; d <= 8; d++)
		for (unsigned mp = 0; mp < 256; mp++) {
			unsigned skip = 0;
			for (int e = 0; d < 8 && e < 8; e++) {
				/* n = c + step e, seen from the parent p = c - step d */
				const int rx = gridpath_dx[e] + gridpath_dx[d];
				const int ry = gridpath_dy[e] + gridpath_dy[d];
				if (rx == 0 && ry == 0)
					skip |= 1u << e; /* n is p itself */
				else if (abs(rx) <= 1 && abs(ry) <= 1 &&
				         (mp >> gridpath_dir_of[ry + 1][rx + 1] & 1))
					skip |= 1u << e; /* one legal step from p */
				else if (d < 4 && e >= 4 &&
				         (gridpath_dx[d] ? gridpath_dx[e] == gridpath_dx[d]
				                         : gridpath_dy[e] == gridpath_dy[d]) &&
				         (mp >> e & 1))
					skip |= 1u << e; /* diagonal first: p, p + e, n */
				else if (d >= 4 && e >= 4 && (rx == 0 || ry == 0) &&
				         (mp >> gridpath_dir_of[ry / 2 + 1][rx / 2 + 1] & 1))
					skip |= 1u << e; /* p, p + s, n: 2 < 2 sqrt 2 */
			}
			s->skip[d][mp] = (uint8_t)skip;
		}
	/* y = c / pw as c div_mul >> div_shift, exact for every index c < pw ph: with
	 * div_mul = floor(2^k / pw) + 1 = (2^k + r) / pw, 0 < r <= pw, c div_mul / 2^k
	 * = c / pw + c r / (pw 2^k), whose second term is below 1 / pw when c pw < 2^k,
	 * so it never carries past the next integer; 2^k >= pw^2 ph makes it so, and c
	 * div_mul < ph 2^k + pw ph < 2 (pw ph)^2 + pw ph stays in 64 bits for fewer
	 * than 2^31 padded cells, as the int32_t index demands. */
	while (((uint64_t)1 << s->div_shift) < (uint64_t)pw * (uint64_t)pw * (uint64_t)ph)
		s->div_shift++;
	s->div_mul = ((uint64_t)1 << s->div_shift) / (uint64_t)pw + 1;
	/* df (EXACT KEYS) from every (rx, ry) in [-5, 5]^2, which meets each region
	 * more than once: the assert checks that a step's growth of f depends on the
	 * region alone. A growth is never negative (the octile distance is consistent). */
	bool seen[45] = {false};
	for (int32_t ry = -5; ry <= 5; ry++)
		for (int32_t rx = -5; rx <= 5; rx++) {
			const unsigned r = gridpath_region(rx, ry);
			const uint64_t h = gridpath_key_h(abs(rx), abs(ry));
			for (int d = 0; d < 8; d++) {
				const uint64_t step = d < 4 ? GRIDPATH_KEY_ONE : GRIDPATH_KEY_SQRT2;
				const uint64_t df = step +
				                    gridpath_key_h(abs(rx - gridpath_dx[d]),
				                                   abs(ry - gridpath_dy[d])) -
				                    h;
				assert(df <= 2 * GRIDPATH_KEY_SQRT2 &&
				       (!seen[r] || s->df[r][d] == df));
				s->df[r][d] = df;
			}
			seen[r] = true;
		}
	/* FIFO QUEUES: the growths above zero, each the index of its queue (their rank,
	 * smallest first) above its low 32 bits */
	uint64_t growth[GRIDPATH_QUEUES];
	int growths = 0;
	for (int r = 0; r < 45; r++)
		for (int d = 0; d < 8; d++) {
			int i = 0;
			while (i < growths && growth[i] != s->df[r][d])
				i++;
			if (i == growths && s->df[r][d] != 0) {
				assert(growths < GRIDPATH_QUEUES);
				growth[growths++] = s->df[r][d];
			}
		}
	assert(growths == GRIDPATH_QUEUES);
	for (int r = 0; r < 45; r++)
		for (int d = 0; d < 8; d++) {
			uint64_t rank = 0;
			for (int i = 0; i < growths; i++)
				rank += growth[i] < s->df[r][d];
			if (s->df[r][d] != 0)
				s->df[r][d] |= rank << 32;
		}
}

void gridpath_free(GridPathSearch *s)
{
	free(s->node);
	if (s->rows)
		free(s->rows - 1); /* the word before the lines, see gridpath_init */
	if (s->cols)
		free(s->cols - 1);
	for (int i = 0; i < GRIDPATH_QUEUES; i++)
		free(s->queue[i].e);
	free(s->stack);
	free(s->at_stack);
	free(s->walk);
	free(s->region_x);
	free(s->region_y);
	free(s->region_d);
	gridpath_jump_free(s);
	*s = (GridPathSearch){0};
}

/* ------------------------------------------------------- plain A*'s open list
 *
 * FIFO QUEUES (see the header): a queue per growth of f above zero, in the order
 * of the growths, smallest first; the stack takes the growths of zero. */

/* gridpath_queue_grown(q): q with an array twice as long, its entries moved
 * to the front in order. By value, so that no queue's address escapes
 * gridpath_find (a store into a node could then alias it). */
static GridPathQueue gridpath_queue_grown(GridPathQueue q)
{
	/* A query pushes fewer than 8 entries a cell, under 2^32 for fewer than 2^29
	 * cells (GRIDPATH_MAX_CELLS): a queue never holds 2^32, and at 2^31 the mask
	 * below wraps to UINT32_MAX, a 2^32-entry array. */
	const uint32_t cap = q.mask + 1, count = q.tail - q.head;
	GridPathQueueEntry *e = util_alloc((size_t)cap * 2, sizeof *e);
	for (uint32_t i = 0; i < count; i++)
		e[i] = q.e[(q.head + i) & q.mask];
	free(q.e);
	return (GridPathQueue){e, 0, count, 2 * cap - 1};
}

/* gridpath_next_round: a fresh round; on wrap-around, clear the marks once. The
 * nodes are made by the first plain A* query (the jump search needs none), marked
 * unseen, with each cell's legal steps (gridpath_moves), and the region tables. */
static void gridpath_next_round(GridPathSearch *s)
{
	if (!s->node) {
		const size_t n = (size_t)s->pw * (size_t)s->ph;
		s->node = util_alloc(n, sizeof *s->node);
		memset(s->node, 0, n * sizeof *s->node);
		for (int32_t y = 1; y < s->ph - 1; y++)
			for (int32_t x = 1; x < s->pw - 1; x++)
				s->node[(size_t)y * s->pw + x] = gridpath_moves(s, x, y);
		s->region_x = util_alloc((size_t)s->pw, sizeof *s->region_x);
		s->region_y = util_alloc((size_t)s->ph, sizeof *s->region_y);
		s->region_d = util_alloc((size_t)s->pw + (size_t)s->ph + 1, sizeof *s->region_d);
		for (int32_t i = 0; i <= s->pw + s->ph; i++) {
			const int32_t dd = i - s->ph;
			s->region_d[i] = (uint16_t)(64 * ((dd < -2 ? -2 : dd > 2 ? 2 : dd) + 2));
		}
		s->round = 0;
	}
	if (s->round >= (UINT32_MAX >> GRIDPATH_ROUND_SHIFT) - 1) {
		size_t n = (size_t)s->pw * (size_t)s->ph;
		for (size_t i = 0; i < n; i++)
			s->node[i] &= GRIDPATH_MOVES;
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
	if (!gridpath_is_free(s, sx + 1, sy + 1) || !gridpath_is_free(s, gx + 1, gy + 1))
		return GRIDPATH_BAD_ENDPOINT;

	if (s->method == GRIDPATH_JUMP)
		return gridpath_find_jump(s, sx + 1, sy + 1, gx + 1, gy + 1, path, length);
	if ((int64_t)s->pw * s->ph >= GRIDPATH_MAX_CELLS)
		return GRIDPATH_TOO_LARGE; /* the keys' proof holds below it: EXACT KEYS */

	/* a step's offset in cells */
	ptrdiff_t offset[8];
	for (int d = 0; d < 8; d++)
		offset[d] = (ptrdiff_t)gridpath_dy[d] * pw + gridpath_dx[d];
	gridpath_next_round(s);
	/* the round's mark in info (see GridPathNode): a cell is closed when its info
	 * is at least it */
	const uint32_t closed_mark = s->round << GRIDPATH_ROUND_SHIFT;
	uint32_t *const node = s->node;
	const int32_t goal_x = gx + 1, goal_y = gy + 1;
	int64_t *const region_x = s->region_x, *const region_y = s->region_y;
	const uint16_t *const region_d = s->region_d + s->ph;
	const char *const df_rows = (const char *)s->df;
	const uint64_t div_mul = s->div_mul;
	const unsigned div_shift = s->div_shift;
	/* region_x[x] = |goal x - x| 4096 + 64 15 (its sign + 1), region_y[y] = |goal y
	 * - y| 4096 + 64 5 (its sign + 1): with region_d's, the byte offset of the
	 * cell's row of df (gridpath_region) */
	for (int32_t x = 0; x < pw; x++) {
		const int64_t r = goal_x - x;
		region_x[x] = (r < 0 ? -r : r) * 4096 + 64 * 15 * ((r > 0) - (r < 0) + 1);
	}
	for (int32_t y = 0; y < s->ph; y++) {
		const int64_t r = goal_y - y;
		region_y[y] = (r < 0 ? -r : r) * 4096 + 64 * 5 * ((r > 0) - (r < 0) + 1);
	}

	/* the queues and their heads' keys in locals (no store into a node aliases
	 * them); hk[i] = UINT64_MAX when queue i is empty */
	GridPathQueue q[GRIDPATH_QUEUES];
	uint64_t hk[GRIDPATH_QUEUES];
	for (int i = 0; i < GRIDPATH_QUEUES; i++) {
		if (!s->queue[i].e) {
			s->queue[i].e = util_alloc(GRIDPATH_QUEUE_FIRST, sizeof *s->queue[i].e);
			s->queue[i].mask = GRIDPATH_QUEUE_FIRST - 1;
		}
		q[i] = (GridPathQueue){s->queue[i].e, 0, 0, s->queue[i].mask};
		hk[i] = UINT64_MAX;
	}
	/* the stack in locals, as the queues; sp its top */
	uint32_t *stack = s->at_stack, *sp = stack;
	int stack_cap = s->at_stack_cap;
	/* The start is closed first, its from GRIDPATH_NO_PARENT, all its legal steps
	 * tried; every later cell comes out of an entry (LAZY OFFERS). f is the key of
	 * f of the cell expanded. */
	uint64_t f = gridpath_key_h(abs(goal_x - (sx + 1)), abs(goal_y - (sy + 1)));
	uint32_t c = (uint32_t)start, cinfo = node[start];
	unsigned m = cinfo & GRIDPATH_MOVES;
	node[start] = m | closed_mark | GRIDPATH_NO_PARENT << GRIDPATH_FROM_SHIFT;
	int64_t expanded = 1;
	int found = start == goal;
	/* ROOM: every queue and the stack have room for room more entries */
	int32_t room = 0;
	while (!found) {
		if (room < 8) { /* an expansion pushes at most 8 entries */
			room = INT32_MAX;
			for (int i = 0; i < GRIDPATH_QUEUES; i++) {
				if (q[i].mask + 1 - (q[i].tail - q[i].head) < GRIDPATH_ROOM)
					q[i] = gridpath_queue_grown(q[i]);
				const uint32_t free_slots = q[i].mask + 1 - (q[i].tail - q[i].head);
				room = free_slots < (uint32_t)room ? (int32_t)free_slots : room;
			}
			const int count = (int)(sp - stack);
			if (stack_cap - count < GRIDPATH_ROOM) {
				stack = util_grow(stack, &stack_cap, count + GRIDPATH_ROOM, sizeof *stack);
				sp = stack + count;
			}
			room = stack_cap - count < room ? stack_cap - count : room;
		}
		room -= 8;
		const uint32_t f_low = (uint32_t)f;
		/* the row of df of the cell's region (gridpath_region), by tables */
		const ptrdiff_t y = (ptrdiff_t)((uint64_t)c * div_mul >> div_shift);
		const int64_t rx = region_x[(ptrdiff_t)c - y * pw], ry = region_y[y];
		const uint64_t *df = (const uint64_t *)(df_rows + (rx & 4095) + (ry & 4095) +
		                                        region_d[(rx >> 12) - (ry >> 12)]);
		/* the legal steps not skipped, in order of d: the order of pushes decides
		 * ties, and so the path */
		for (; m; m &= m - 1) {
			const unsigned d = (unsigned)gridpath_ctz64(m);
			const uint32_t n = c + (uint32_t)offset[d];
			/* a closed cell's cost is final; any other is offered (LAZY OFFERS) */
			if (node[n] >= closed_mark)
				continue;
			/* PREFETCH: the line of the cell beyond n, which n's expansion reads,
			 * and the one GRIDPATH_PUSH_AHEAD steps on */
			gridpath_prefetch(node + n + offset[d]);
			gridpath_prefetch_near(node + n, GRIDPATH_PUSH_AHEAD * offset[d]);
			const uint64_t grow = df[d];
			const uint32_t dfd = (uint32_t)grow, e = n << GRIDPATH_ENTRY_SHIFT | d;
			if (dfd == 0) {
				/* As good as the best open entry: expand it next, no queue. */
				*sp++ = e;
			} else {
				/* its growth's queue, whose keys never decrease (FIFO QUEUES) */
				const unsigned i = (unsigned)(grow >> 32);
				GridPathQueue *const qi = &q[i];
				/* its head's key: this one's if the queue is empty (hk[i] =
				 * UINT64_MAX), else no more than it */
				if (qi->tail == qi->head)
					hk[i] = f + dfd;
				qi->e[qi->tail++ & qi->mask] = (GridPathQueueEntry){f_low + dfd, e};
			}
		}
		/* the next entry whose cell is not closed: a cell's entries leave the list in
		 * order of f, h is fixed per cell, so the first to leave carries the best g
		 * and closes it; the later, stale ones meet the mark */
		uint32_t e;
		for (;;) {
			if (sp != stack) { /* f is that of the cell that pushed it */
				e = *--sp;
			} else {
				/* the queue whose head has the least f; on a tie the first (the
				 * smaller growth: its entry was pushed from a larger f, later) */
				_Static_assert(GRIDPATH_QUEUES == 5, "the tree below picks of five");
				const uint64_t k0 = hk[0], k1 = hk[1], k2 = hk[2], k3 = hk[3],
				               k4 = hk[4];
				const bool l01 = k1 < k0, l23 = k3 < k2;
				const uint64_t m01 = l01 ? k1 : k0, m23 = l23 ? k3 : k2;
				const unsigned b01 = l01, b23 = 2 + (unsigned)l23;
				const bool l03 = m23 < m01;
				const uint64_t m03 = l03 ? m23 : m01;
				const unsigned b03 = l03 ? b23 : b01;
				const bool l04 = k4 < m03;
				const uint64_t best = l04 ? k4 : m03;
				const unsigned b = l04 ? 4 : b03;
				if (best == UINT64_MAX)
					goto done;
				f = best;
				GridPathQueue *const qb = &q[b];
				e = qb->e[qb->head++ & qb->mask].offer;
				/* the next head's key lies in [f, f + 2^32) (F RELATIVE) */
				const GridPathQueueEntry next = qb->e[qb->head & qb->mask];
				hk[b] = qb->head == qb->tail
				            ? UINT64_MAX
				            : f + (uint32_t)(next.key - (uint32_t)f);
				/* PREFETCH: the node of the queue's next head (a stale or free
				 * slot's cell is a cell of the grid too) */
				gridpath_prefetch(node + (next.offer >> GRIDPATH_ENTRY_SHIFT));
			}
			c = e >> GRIDPATH_ENTRY_SHIFT;
			cinfo = node[c];
			if (cinfo < closed_mark)
				break;
		}
		/* close c, its from the entry's step */
		const unsigned from = e & GRIDPATH_ENTRY_FROM;
		node[c] = (cinfo & GRIDPATH_MOVES) | closed_mark | from << GRIDPATH_FROM_SHIFT;
		expanded++;
		found = c == (uint32_t)goal;
		/* PARENT'S NEIGHBOURS: the steps the parent's offers make needless */
		m = cinfo & GRIDPATH_MOVES &
		    ~(unsigned)s->skip[from][node[c - (uint32_t)offset[from]] & GRIDPATH_MOVES];
	}
done:
	for (int i = 0; i < GRIDPATH_QUEUES; i++)
		s->queue[i] = q[i];
	s->at_stack = stack;
	s->at_stack_cap = stack_cap;
	path->expanded = expanded;
	if (!found)
		return GRIDPATH_NO_PATH;

	/* Walk back once along the marks' from, keeping each step in walk, then write
	 * the points from walk (WALK BACK): the path runs start to goal. */
	int32_t straight = 0, steps = 0;
	uint8_t *walk = s->walk;
	int walk_cap = s->walk_cap;
	c = (uint32_t)goal;
	for (int d; (d = (int)(node[c] >> GRIDPATH_FROM_SHIFT & 15)) != GRIDPATH_NO_PARENT;) {
		if (steps == walk_cap)
			walk = util_grow(walk, &walk_cap, steps + 1, sizeof *walk);
		walk[steps++] = (uint8_t)d;
		straight += d < 4;
		c -= (uint32_t)offset[d];
		/* WALK BACK: the node GRIDPATH_WALK_AHEAD steps on if the path runs
		 * straight on (a hint: no effect on results) */
		gridpath_prefetch_near(node + c, -GRIDPATH_WALK_AHEAD * offset[d]);
	}
	s->walk = walk;
	s->walk_cap = walk_cap;
	const int32_t diagonal = steps - straight;
	path->pts = util_grow(path->pts, &path->cap, steps + 1, sizeof *path->pts);
	path->count = steps + 1; /* every point is written below */
	int32_t x = goal_x, y = goal_y;
	for (int32_t i = steps; i >= 0; i--) {
		path->pts[i] = vec2((double)(x - 1) + 0.5, (double)(y - 1) + 0.5);
		if (i > 0) {
			const int d = walk[steps - i];
			x -= gridpath_dx[d];
			y -= gridpath_dy[d];
		}
	}
	*length = gridpath_cost(straight, diagonal);
	return GRIDPATH_FOUND;
}
