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
 * costs a random memory access per swap). Since f never decreases during the
 * search, entries are filed in buckets of f (1/64 of a unit), and only the current
 * bucket is ordered. Plain A* keeps its buckets in a ring of 4 units (its open
 * entries never span more than 2 sqrt 2: "plain A*'s open list" below), the current one a sorted
 * array; the jump search, whose jumps are long, keeps a page of GRIDPATH_PAGE
 * buckets with an overflow beyond it (see GRIDPATH_PAGE), the current bucket a
 * binary heap. A neighbour whose f equals the f being expanded (the least in the
 * list) skips the buckets through a stack. Each free cell's legal steps are one
 * byte of its node (made by the first query from the 3 x 3 neighbourhood, by the
 * table legal of gridpath_init), so an expansion walks the set
 * bits in order of d instead of testing eight neighbours and two corners each.
 *
 * PERFORMANCE (issue 16; instructions by callgrind, exact, of one warm corner-to-
 * corner query at 1024 as skelbench picks the ends, gridpath_find inclusive;
 * before = the tree before this round of work, which kept the paged heap for
 * both searches):
 *   plain A*    rooms 230 -> 145 M, rects 149 -> 93, maze 333 -> 209 (688 000 cells
 *               expanded: 485 -> 304 instructions a cell), Boston_0_1024 192 -> 119,
 *               den520d (x2) 51 -> 32;
 *   jump points rooms 6.7 -> 6.1 -> 5.3 M, rects 5.6 -> 4.8 -> 3.1, maze 47.2 ->
 *               43.6 -> 50.0 (42 138 jump points expanded: 1 190 instructions
 *               each), Boston 11.3 -> 9.9 -> 7.2, den520d 3.3 -> 2.7 -> 1.4 (the
 *               second arrow: the second round, below).
 * The steps, maze plain A*: the parent's neighbours skipped 337 -> 292 M; the ring
 * for the paged heap 292 -> 232; locals instead of fields re-read after byte stores
 * and the sift inline 232 -> 225; the sorted current bucket 225 -> 209 (rooms 172
 * -> 145, and its time about halved: the heap's branches mispredicted). Times and
 * the ratios to libtcod: see gridpath.h. Where the time goes now (perf): the maze's
 * plain A* is bound by instructions (about 2 a cycle), spread over the bucket
 * work, the cost conversions and the neighbour loop.
 * The jump search's second round, for its time in the cache (perf, maze: 30% the
 * loads of the 16 MB node array at new jump points, 12% the walk back): thread CPU
 * ms, the best of 5 rounds alternating old and new in one session, maze / rooms:
 * records of its own instead of nodes (JUMP RECORDS) 7.5 -> 6.0 / -; the diagonal
 * runs' legal steps from rows, not a moves array, 5.5 -> 5.1 / -; rows and cols as
 * bits (CACHE; the moves array gone) 5.1 -> 5.6 with 53.6 M instructions, then 5.1
 * with the words' arithmetic unsigned (50.0 M; rooms 0.55 -> 0.31 over the two);
 * no divisions of an index back into x and y, 5.31 -> 5.08 / 0.31 -> 0.30. Where
 * its time goes now (perf, maze): the scans of the runs about 25%, the diagonal
 * runs' steps and the expansions' bookkeeping the rest, the open list about 10%;
 * instructions rose (the bit arithmetic), cache misses fell.

 * PARENT'S NEIGHBOURS: a cell c reached from its parent p need not try a step to p,
 * nor to any cell n one legal step from p: p was expanded, so n already holds a
 * cost at most g(p) + |pn| <= g(p) + |pc| + |cn| = g(c) + |cn| (one step is never
 * longer than two), and c's offer would be refused; likewise by induction when p
 * itself skipped n. So skip[from][moves of p] (gridpath_init) removes these steps
 * before the loop, which changes no push and no path: 3 of the 8 neighbours are
 * left to a cell entered straight along a corridor. Maze at 1024: 337 to 292
 * million instructions (callgrind, gridpath_find).
 *
 * EXACT TIES: a cost is kept as two integers, straight and diagonal step counts,
 * and turned into a double by one fixed expression. Since sqrt 2 is irrational,
 * two costs are equal exactly when their counts are, and then their doubles are
 * bit-identical; so ties in f are true ties, and they go to the larger g (the entry
 * nearer the goal), which makes A* run straight down a corridor of equal-f cells
 * instead of flooding it.
 *
 * INVARIANTS: node[c].mark == 2 round means c was reached this query and its step
 * counts hold its best known cost; 2 round + 1 means c is closed and its cost final;
 * any other value means unseen. The border cells of the padded copy are never free.
 *
 * MEMORY: see gridpath.h. COMPLEXITY: O(n log n) for n cells expanded, n <= free
 * cells, plus O(L) for a path of length L to skip the empty buckets (64 to a word
 * of nonempty bits), and for the jump search each overflow entry once per page it
 * waits through; initialisation O(w h) once per grid, and a query touches only
 * what it expands (the round counter replaces clearing the marks) and, for plain
 * A*, the ring's GRIDPATH_RING buckets. */
#include "utak/plan/gridpath.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

#define GRIDPATH_SQRT2 1.41421356237309504880
/* Buckets of the open list per unit of f. f runs from h(start) to the path length,
 * so a query uses (length - h(start)) x this many buckets, and each holds few
 * enough entries that its heap stays in cache. Of 1, 4, 16, 64 and 256 on the
 * 1024 x 1024 maps, 1 was slowest and 16 to 256 within the noise; 64 keeps the
 * current heap at 56 entries on average (8room_000 x2; 101 with 16). */
#define GRIDPATH_BUCKETS_PER_UNIT 64
/* Buckets kept at once (a page, see gridpath.h): a path of length L would need
 * L x GRIDPATH_BUCKETS_PER_UNIT of them (3.2 million, 51 MB, corner to corner in a
 * 1024 x 1024 maze, whose path is 50 687 long), and walking the empty ones cost a
 * fifth of the jump search's time there. A page covers 64 units of f, more than
 * plain A*'s f grows in one step (at most 2 sqrt 2), so only long jumps overflow.
 * Empty buckets are skipped 64 at a time by the nonempty bits. */
#define GRIDPATH_PAGE 4096
#define GRIDPATH_WORDS (GRIDPATH_PAGE / 64)
/* Plain A*'s ring (GRIDPATH_RING buckets, gridpath.h): buckets per unit of f. Of
 * 64, 256 and 1024 (rings of 4 units), 64 ran the maze's query in the fewest
 * instructions (232, 236 and 242 million, callgrind), and it files entries as the
 * jump search's pages do. */
#define GRIDPATH_RING_PER_UNIT 64
#define GRIDPATH_RING_WORDS (GRIDPATH_RING / 64)
/* The ring must hold the open entries' span, 2 sqrt 2 units and a bucket each side,
 * and be a power of two of whole words. */
_Static_assert(GRIDPATH_RING >= 3 * GRIDPATH_RING_PER_UNIT + 2 && GRIDPATH_RING % 64 == 0 &&
                   (GRIDPATH_RING & (GRIDPATH_RING - 1)) == 0,
               "GRIDPATH_RING too small for GRIDPATH_RING_PER_UNIT, or not a power of two");
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

/* GRIDPATH_PREFETCH(p): asks for p's cache line ahead of use, where the compiler
 * can (a hint only: no effect on results). */
#if defined(__GNUC__)
#define GRIDPATH_PREFETCH(p) __builtin_prefetch(p)
#else
#define GRIDPATH_PREFETCH(p) ((void)(p))
#endif

/* The 8 steps: 0..3 straight (E, N, W, S), 4..7 diagonal (NE, NW, SW, SE); a
 * diagonal d = 4 + k lies between straight steps k and (k + 1) mod 4. "N" is +y. */
static const int8_t gridpath_dx[8] = {1, 0, -1, 0, 1, -1, -1, 1};
static const int8_t gridpath_dy[8] = {0, 1, 0, -1, 1, 1, -1, -1};

/* gridpath_dir_of[dy + 1][dx + 1]: the step index of (dx, dy) (-1 for (0, 0)). */
static const int8_t gridpath_dir_of[3][3] = {{6, 3, 7}, {2, -1, 0}, {5, 1, 4}};

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
			}
			s->skip[d][mp] = (uint8_t)skip;
		}
}

void gridpath_free(GridPathSearch *s)
{
	free(s->node);
	if (s->rows)
		free(s->rows - 1); /* the word before the lines, see gridpath_init */
	if (s->cols)
		free(s->cols - 1);
	if (s->bucket)
		for (int i = 0; i < GRIDPATH_PAGE; i++)
			free(s->bucket[i].e);
	free(s->bucket);
	if (s->ring)
		for (int i = 0; i < GRIDPATH_RING; i++)
			free(s->ring[i].e);
	free(s->ring);
	free(s->nonempty);
	free(s->overflow);
	free(s->stack);
	free(s->scratch);
	free(s->jump);
	free(s->jump_seen);
	free(s->jump_slot);
	*s = (GridPathSearch){0};
}

/* gridpath_before(a, b): a leaves the heap before b (smaller f; on equal f, larger g). */
static inline int gridpath_before(const GridPathOpen *a, const GridPathOpen *b)
{
	return a->f < b->f || (a->f == b->f && a->g > b->g);
}

/* gridpath_sift_down(h, n, i, e): puts e at position i of heap h[0..n) and sifts it
 * down to where it belongs. */
static inline void gridpath_sift_down(GridPathOpen *h, int n, int i, GridPathOpen e)
{
	for (;;) {
		int c = 2 * i + 1;
		if (c >= n)
			break;
		if (c + 1 < n && gridpath_before(&h[c + 1], &h[c]))
			c++;
		if (!gridpath_before(&h[c], &e))
			break;
		h[i] = h[c];
		i = c;
	}
	h[i] = e;
}

/* gridpath_bucket_of(s, f): the bucket number of f, never before the current one
 * (the heuristic is consistent, so f never decreases along a search: the clamp only
 * guards rounding). */
static inline int64_t gridpath_bucket_of(const GridPathSearch *s, double f)
{
	double rel = (f - s->f_start) * GRIDPATH_BUCKETS_PER_UNIT;
	return rel < (double)s->bucket_now ? s->bucket_now : (int64_t)rel;
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

/* gridpath_file(s, e, b): e into bucket b of the page, unsorted (b is not current). */
static inline void gridpath_file(GridPathSearch *s, GridPathOpen e, int64_t b)
{
	int slot = (int)(b - s->page_base);
	GridPathBucket *k = &s->bucket[slot];
	k->e = gridpath_room(k->e, k->count, &k->cap);
	k->e[k->count++] = e;
	s->nonempty[slot / 64] |= (uint64_t)1 << (slot % 64);
}

/* gridpath_push: files e in its bucket; in the current one, by heap insertion; past
 * the page, in the overflow. */
static inline void gridpath_push(GridPathSearch *s, GridPathOpen e)
{
	int64_t b = gridpath_bucket_of(s, e.f);
	if (b >= s->page_base + GRIDPATH_PAGE) {
		s->overflow = gridpath_room(s->overflow, s->overflow_count, &s->overflow_cap);
		s->overflow[s->overflow_count++] = e;
		return;
	}
	if (b != s->bucket_now) {
		gridpath_file(s, e, b);
		return;
	}
	int slot = (int)(b - s->page_base);
	GridPathBucket *k = &s->bucket[slot];
	k->e = gridpath_room(k->e, k->count, &k->cap);
	s->nonempty[slot / 64] |= (uint64_t)1 << (slot % 64);
	int i = k->count++;
	while (i > 0) {
		int parent = (i - 1) / 2;
		if (!gridpath_before(&e, &k->e[parent]))
			break;
		k->e[i] = k->e[parent];
		i = parent;
	}
	k->e[i] = e;
}

/* gridpath_next_slot(s, slot): the first bucket of the page at or after slot that
 * holds entries, or GRIDPATH_PAGE. */
static int gridpath_next_slot(const GridPathSearch *s, int slot)
{
	for (int w = slot / 64; w < GRIDPATH_WORDS; w++) {
		uint64_t bits = s->nonempty[w];
		if (w == slot / 64)
			bits &= ~(uint64_t)0 << (slot % 64);
		if (bits == 0)
			continue;
		return w * 64 + gridpath_ctz64(bits);
	}
	return GRIDPATH_PAGE;
}

/* gridpath_pop: the first entry of the open list into *e; false when it is empty.
 * Moving to a new bucket turns it into a heap (Floyd's bottom-up build, O(n)); an
 * empty page is replaced by the one that starts at the overflow's least bucket. */
static bool gridpath_pop(GridPathSearch *s, GridPathOpen *e)
{
	int slot = (int)(s->bucket_now - s->page_base);
	int next = s->bucket[slot].count > 0 ? slot : gridpath_next_slot(s, slot);
	if (next == GRIDPATH_PAGE) {
		if (s->overflow_count == 0)
			return false;
		int64_t least = INT64_MAX;
		for (int i = 0; i < s->overflow_count; i++) {
			int64_t b = gridpath_bucket_of(s, s->overflow[i].f);
			least = b < least ? b : least;
		}
		s->page_base = s->bucket_now = least;
		int kept = 0;
		for (int i = 0; i < s->overflow_count; i++) {
			int64_t b = gridpath_bucket_of(s, s->overflow[i].f);
			if (b < s->page_base + GRIDPATH_PAGE)
				gridpath_file(s, s->overflow[i], b);
			else
				s->overflow[kept++] = s->overflow[i];
		}
		s->overflow_count = kept;
		slot = -1; /* bucket 0 is new: make it a heap below */
		next = gridpath_next_slot(s, 0);
	}
	GridPathBucket *k = &s->bucket[next];
	if (next != slot) {
		s->bucket_now = s->page_base + next;
		for (int i = k->count / 2 - 1; i >= 0; i--)
			gridpath_sift_down(k->e, k->count, i, k->e[i]);
	}
	*e = k->e[0];
	k->count--;
	if (k->count > 0)
		gridpath_sift_down(k->e, k->count, 0, k->e[k->count]);
	else
		s->nonempty[next / 64] &= ~((uint64_t)1 << (next % 64));
	return true;
}

/* ------------------------------------------------------- plain A*'s open list
 *
 * A ring of GRIDPATH_RING buckets of f, GRIDPATH_RING_PER_UNIT to a unit: plain
 * A* offers a neighbour at most 2 sqrt 2 above the f being expanded (a step of
 * cost c changes h by at most c), so the open entries span less than 3 units and a
 * ring of 4 units holds them all, with no overflow. Later buckets are unsorted
 * arrays; the current one, ring_now, is sorted (by gridpath_ring_sort when it
 * becomes current) from the entry to leave last to the one to leave first, so a
 * pop takes its last entry, and a push into it is an insertion from the end. In
 * the maze most buckets hold one to three entries: a sorted array beat the binary
 * heap kept before (see PERFORMANCE). */

/* gridpath_ring_sort(a, n, tmp): sorts a[0..n) so that a[n - 1] leaves first
 * (gridpath_before), stable: of entries that tie in f and g, the later in a leaves
 * first. Insertion for short arrays, else merging halves through tmp (n entries). */
static void gridpath_ring_sort(GridPathOpen *a, int n, GridPathOpen *tmp)
{
	if (n <= 16) {
		for (int i = 1; i < n; i++) {
			const GridPathOpen x = a[i];
			int j = i;
			for (; j > 0 && gridpath_before(&a[j - 1], &x); j--)
				a[j] = a[j - 1];
			a[j] = x;
		}
		return;
	}
	const int h = n / 2;
	gridpath_ring_sort(a, h, tmp);
	gridpath_ring_sort(a + h, n - h, tmp);
	int i = 0, j = h, k = 0;
	while (i < h && j < n) /* the one that leaves later first; on a tie, the left */
		tmp[k++] = gridpath_before(&a[i], &a[j]) ? a[j++] : a[i++];
	while (i < h)
		tmp[k++] = a[i++];
	while (j < n)
		tmp[k++] = a[j++];
	memcpy(a, tmp, (size_t)n * sizeof *a);
}

/* gridpath_ring_push(s, e): files e in the bucket of its f (never before ring_now:
 * f never decreases, the clamp only guards rounding). */
static inline void gridpath_ring_push(GridPathSearch *s, GridPathOpen e)
{
	const double rel = (e.f - s->f_start) * GRIDPATH_RING_PER_UNIT;
	const int64_t b = rel < (double)s->ring_now ? s->ring_now : (int64_t)rel;
	const unsigned slot = (unsigned)b & (GRIDPATH_RING - 1);
	GridPathBucket *k = &s->ring[slot];
	k->e = gridpath_room(k->e, k->count, &k->cap);
	s->ring_bits[slot / 64] |= (uint64_t)1 << (slot % 64);
	int i = k->count++;
	if (b == s->ring_now) /* the current bucket: sorted, leaving from the end */
		for (; i > 0 && gridpath_before(&k->e[i - 1], &e); i--)
			k->e[i] = k->e[i - 1];
	k->e[i] = e;
}

/* gridpath_ring_pop(s, e): the first entry into *e; false when the list is empty. */
static inline bool gridpath_ring_pop(GridPathSearch *s, GridPathOpen *e)
{
	unsigned slot = (unsigned)s->ring_now & (GRIDPATH_RING - 1);
	GridPathBucket *k = &s->ring[slot];
	if (k->count == 0) {
		/* the next nonempty bucket, cyclically after slot */
		unsigned next = GRIDPATH_RING;
		for (unsigned w = 0; w <= GRIDPATH_RING_WORDS; w++) {
			const unsigned word = (slot / 64 + w) % GRIDPATH_RING_WORDS;
			uint64_t bits = s->ring_bits[word];
			if (w == 0)
				bits &= ~(uint64_t)0 << (slot % 64);
			if (bits) {
				next = word * 64 + (unsigned)gridpath_ctz64(bits);
				break;
			}
		}
		if (next == GRIDPATH_RING)
			return false;
		s->ring_now += (next - slot) & (GRIDPATH_RING - 1);
		slot = next;
		k = &s->ring[slot];
		if (k->count == 2) { /* the usual case in the maze, inline */
			if (gridpath_before(&k->e[0], &k->e[1])) {
				const GridPathOpen t = k->e[0];
				k->e[0] = k->e[1];
				k->e[1] = t;
			}
		} else if (k->count > 2) {
			if (k->count > 16)
				s->scratch =
				    gridpath_room_for(s->scratch, k->count, &s->scratch_cap);
			gridpath_ring_sort(k->e, k->count, s->scratch);
		}
	}
	*e = k->e[--k->count];
	if (k->count == 0)
		s->ring_bits[slot / 64] &= ~((uint64_t)1 << (slot % 64));
	return true;
}

/* gridpath_ring_reset(s): an empty ring for a new query, bucket 0 current. */
static void gridpath_ring_reset(GridPathSearch *s)
{
	if (!s->ring) {
		s->ring = util_alloc(GRIDPATH_RING, sizeof *s->ring);
		memset(s->ring, 0, GRIDPATH_RING * sizeof *s->ring);
	}
	for (unsigned i = 0; i < GRIDPATH_RING; i++)
		s->ring[i].count = 0;
	memset(s->ring_bits, 0, sizeof s->ring_bits);
	s->ring_now = 0;
}

/* gridpath_open_reset(s): an empty open list for a new query. */
static void gridpath_open_reset(GridPathSearch *s)
{
	if (!s->bucket) {
		s->bucket = util_alloc(GRIDPATH_PAGE, sizeof *s->bucket);
		memset(s->bucket, 0, GRIDPATH_PAGE * sizeof *s->bucket);
		s->nonempty = util_alloc(GRIDPATH_WORDS, sizeof *s->nonempty);
		memset(s->nonempty, 0, GRIDPATH_WORDS * sizeof *s->nonempty);
	}
	for (int slot = gridpath_next_slot(s, 0); slot < GRIDPATH_PAGE;
	     slot = gridpath_next_slot(s, slot + 1))
		s->bucket[slot].count = 0;
	memset(s->nonempty, 0, GRIDPATH_WORDS * sizeof *s->nonempty);
	s->page_base = s->bucket_now = 0;
	s->overflow_count = 0;
}

/* gridpath_next_round: a fresh mark value; on wrap-around, clear the marks once. The
 * nodes are made by the first plain A* query (the jump search needs none), marked
 * unseen, with each cell's legal steps (gridpath_moves). */
static void gridpath_next_round(GridPathSearch *s)
{
	if (!s->node) {
		const size_t n = (size_t)s->pw * (size_t)s->ph;
		s->node = util_alloc(n, sizeof *s->node);
		memset(s->node, 0, n * sizeof *s->node);
		for (int32_t y = 1; y < s->ph - 1; y++)
			for (int32_t x = 1; x < s->pw - 1; x++)
				s->node[(size_t)y * s->pw + x].moves = gridpath_moves(s, x, y);
		s->round = 0;
	}
	if (s->round >= UINT32_MAX / 2 - 1) {
		size_t n = (size_t)s->pw * (size_t)(s->h + 2);
		for (size_t i = 0; i < n; i++)
			s->node[i].mark = 0;
		s->round = 0;
	}
	s->round++;
}

/* ---------------------------------------------------------------- jump points
 *
 * ALGORITHM: jump-point search (D. Harabor, A. Grastien, "Online graph pruning for
 * pathfinding on grid maps", AAAI 2011), the same A* over a pruned set of cells, in
 * the form that respects this grid's rule "a diagonal step only when both orthogonal
 * neighbours are free". Under that rule every shortest path can be taken as
 * straight runs and diagonal runs whose turns happen only at jump points:
 *   - a straight run (dx, 0) stops at a cell that has a "forced" neighbour: a free
 *     cell beside it, (x, y +- 1), whose cell behind, (x - dx, y +- 1), is blocked,
 *     so that no path through the previous cell reaches it as cheaply (the diagonal
 *     step that would have is forbidden by the rule); the same with x and y swapped;
 *   - a diagonal run (dx, dy) stops at a cell from which a straight run along dx or
 *     along dy reaches a jump point (it turns there);
 *   - any run stops at the goal, and ends (no jump point) at a blocked cell or, for
 *     a diagonal run, at a step the rule forbids.
 * Successors of a jump point reached by a straight run: straight on, the two
 * perpendicular straight runs and the two forward diagonals; by a diagonal run: the
 * diagonal and its two straight components; the start: all eight. The cost of a
 * jump is its step count (straight or diagonal), kept as counts as above, so the
 * lengths are the plain A*'s, exactly; checked against it and against every
 * published Moving AI optimum in tests/unit/test_gridpath.c.
 *
 * CACHE: a straight run reads three lines of bits: rows for runs along x, cols (the
 * grid transposed) for runs along y, so both scan memory in order, 64 cells a word,
 * instead of a node (16 bytes) or a row (pw bytes) per step. At a bit a cell both
 * copies of a 1024 x 1024 grid take 256 KB and stay in the L2 cache (as bytes, 2
 * MB, they did not: the rooms, rects, Boston and den520d queries ran 2 times
 * faster with bits, the maze's 1.1). Only jump points touch the jump state (JUMP
 * RECORDS below); node[] is plain A*'s alone.
 *
 * PATH: each jump point's record keeps the direction and length of the run that
 * reached it and the record of the jump point it started from, so the path is
 * rebuilt from the goal run by run without touching the cells between (on the 1024
 * maze they were 8% of the search's time, a cache miss each). */

/* A start has no run that reached it: all eight directions are its successors. */
#define GRIDPATH_FROM_START GRIDPATH_NO_PARENT

/* JUMP RECORDS: the jump search keeps what it knows of a jump point in a record of
 * its own, appended in order of first sight, not in the cell's node: the nodes are
 * 16 bytes a cell in one array (16 MB at 1024), and reading a new jump point's node
 * was a cache miss each, 30% of the maze's time, with another 12% for the walk back.
 * A cell's state is now one bit (seen this query, 128 KB at 1024, in cache), and the
 * record index is read from jump_slot only for a cell seen before (in the 1024 maze
 * 5 400 of 47 500 jump points found; the rest are new, and only written). The open
 * list's entries carry the record index in their cell field, so an expansion reads
 * its record, recently written, and the walk back follows parent indices through
 * the records, a few hundred KB. */
typedef struct GridPathJumpRecord {
	int32_t x, y;     /* padded coordinates of the jump point */
	int32_t straight; /* straight steps of the best known path to it */
	int32_t diagonal; /* diagonal steps of the best known path to it */
	int32_t parent;   /* record of the jump point its best run started from; -1: start */
	int32_t run;      /* steps of that run */
	uint8_t from;     /* direction (0..7) of that run; GRIDPATH_FROM_START at the start */
	uint8_t closed;   /* 1 once expanded: its cost is final */
} GridPathJumpRecord;

/* gridpath_jump_reset(s): the jump state for a new query: allocated on the first,
 * and the seen bits of the last query's records cleared (or all of them, when that
 * is fewer words than records). */
static void gridpath_jump_reset(GridPathSearch *s)
{
	const size_t n = (size_t)s->pw * (size_t)s->ph, words = (n + 63) / 64;
	if (!s->jump_seen) {
		s->jump_seen = util_alloc(words, sizeof *s->jump_seen);
		memset(s->jump_seen, 0, words * sizeof *s->jump_seen);
		s->jump_slot = util_alloc(n, sizeof *s->jump_slot);
	} else if ((size_t)s->jump_count >= words)
		memset(s->jump_seen, 0, words * sizeof *s->jump_seen);
	else
		for (int32_t i = 0; i < s->jump_count; i++) {
			const int32_t c = s->jump[i].y * s->pw + s->jump[i].x;
			s->jump_seen[c / 64] &= ~((uint64_t)1 << (c % 64));
		}
	s->jump_count = 0;
}

/* gridpath_jump_new(s, cell, x, y): a new record for cell (x, y), marked seen; its
 * index. */
static inline int32_t gridpath_jump_new(GridPathSearch *s, int32_t cell, int32_t x, int32_t y)
{
	if (s->jump_count == s->jump_cap)
		s->jump = util_grow(s->jump, &s->jump_cap, s->jump_count + 1, sizeof *s->jump);
	const int32_t r = s->jump_count++;
	s->jump_seen[cell / 64] |= (uint64_t)1 << (cell % 64);
	s->jump_slot[cell] = r;
	s->jump[r].x = x;
	s->jump[r].y = y;
	s->jump[r].closed = 0;
	return r;
}

/* gridpath_msb64(bits): the index of the highest set bit of bits != 0. */
static inline int gridpath_msb64(uint64_t bits)
{
#if defined(__GNUC__)
	return 63 - __builtin_clzll(bits);
#else
	int i = 63;
	while (!((bits >> i) & 1))
		i--;
	return i;
#endif
}

/* gridpath_scan(cur, a, b, i, dir, stop): the straight run from position i along the
 * line cur (bits, 1 free; with its two neighbouring lines a and b, all three padded
 * so the ends are blocked) in direction dir: the position of the jump point it
 * reaches (a free cell with a forced neighbour, or stop), or -1 (a blocked cell
 * first). Sixty-four cells at a time: the events of a word are its blocked cells,
 * its forced neighbours (a free cell of a or b whose cell behind, one step back
 * along dir, is blocked: the word shifted by one, with the bit carried in from the
 * word behind) and stop; the first is found by counting zero bits. The run always
 * ends, at the blocked end of the line at the latest. A word's carry may come from
 * the word before the line's first or after its last (the line before or after, or
 * the padding word of gridpath_init): it lands on an end cell, never scanned. */
static inline int32_t gridpath_scan(const uint64_t *cur, const uint64_t *a, const uint64_t *b,
                                    int32_t i, int32_t dir, int32_t stop)
{
	/* positions are never negative: unsigned, so / and % are shifts and masks */
	const uint32_t u = (uint32_t)i, goal = (uint32_t)stop;
	if (dir > 0) {
		const uint32_t p = u + 1, stop_word = stop > i ? goal / 64 : UINT32_MAX;
		uint64_t mask = ~(uint64_t)0 << (p % 64);
		for (uint32_t k = p / 64;; k++, mask = ~(uint64_t)0) {
			const uint64_t behind_a = a[k] << 1 | a[(int32_t)k - 1] >> 63;
			const uint64_t behind_b = b[k] << 1 | b[(int32_t)k - 1] >> 63;
			uint64_t ev = (~cur[k] | (a[k] & ~behind_a) | (b[k] & ~behind_b)) & mask;
			if (k == stop_word)
				ev |= (uint64_t)1 << (goal % 64);
			if (ev) {
				const int j = gridpath_ctz64(ev);
				return (cur[k] >> j & 1) ? (int32_t)(k * 64) + j : -1;
			}
		}
	}
	const uint32_t p = u - 1, stop_word = stop >= 0 && stop < i ? goal / 64 : UINT32_MAX;
	uint64_t mask = ~(uint64_t)0 >> (63 - p % 64);
	for (uint32_t k = p / 64;; k--, mask = ~(uint64_t)0) {
		const uint64_t behind_a = a[k] >> 1 | a[k + 1] << 63;
		const uint64_t behind_b = b[k] >> 1 | b[k + 1] << 63;
		uint64_t ev = (~cur[k] | (a[k] & ~behind_a) | (b[k] & ~behind_b)) & mask;
		if (k == stop_word)
			ev |= (uint64_t)1 << (goal % 64);
		if (ev) {
			const int j = gridpath_msb64(ev);
			return (cur[k] >> j & 1) ? (int32_t)(k * 64) + j : -1;
		}
	}
}

/* gridpath_run_x(s, x, y, dx, gx, gy): the straight run along x from padded (x, y):
 * the x of its jump point, or -1. gridpath_run_y: the same along y, the y. */
static inline int32_t gridpath_run_x(const GridPathSearch *s, int32_t x, int32_t y, int32_t dx,
                                     int32_t gx, int32_t gy)
{
	const int32_t lw = s->row_words;
	const uint64_t *row = s->rows + (size_t)y * lw;
	return gridpath_scan(row, row + lw, row - lw, x, dx, y == gy ? gx : -1);
}

static inline int32_t gridpath_run_y(const GridPathSearch *s, int32_t x, int32_t y, int32_t dy,
                                     int32_t gx, int32_t gy)
{
	const int32_t lw = s->col_words;
	const uint64_t *col = s->cols + (size_t)x * lw;
	return gridpath_scan(col, col + lw, col - lw, y, dy, x == gx ? gy : -1);
}

/* gridpath_jump(s, x, y, d, gx, gy): the run from padded (x, y) in direction d: the
 * number of steps to its jump point, or -1. (The caller steps to the point: no
 * index is divided back into coordinates, a division each.) */
static int32_t gridpath_jump(const GridPathSearch *s, int32_t x, int32_t y, int d, int32_t gx,
                             int32_t gy)
{
	const int32_t dx = gridpath_dx[d], dy = gridpath_dy[d];
	if (dy == 0) {
		int32_t jx = gridpath_run_x(s, x, y, dx, gx, gy);
		return jx < 0 ? -1 : abs(jx - x);
	}
	if (dx == 0) {
		int32_t jy = gridpath_run_y(s, x, y, dy, gx, gy);
		return jy < 0 ? -1 : abs(jy - y);
	}
	/* A diagonal step is legal when the cells ahead along x, along y and
	 * diagonally are free (no corner cutting), and a straight run whose first
	 * cell is blocked finds nothing, so it is not scanned (in the 1024 maze's
	 * corridors, 3 cells wide, most are not). Both are read in rows, whose words
	 * about (x, y) the straight run along x reads too: a byte array of legal
	 * steps read here before was one more line for each step, and 10% of the
	 * maze's time. */
	const int32_t up = dy * s->row_words;
	const uint64_t *row = s->rows + (size_t)y * s->row_words; /* row y */
	for (int32_t n = 1;; n++) {
		if (!(gridpath_bit(row, x + dx) & gridpath_bit(row + up, x) &
		      gridpath_bit(row + up, x + dx)))
			return -1;
		x += dx;
		y += dy;
		row += up;
		if ((x == gx && y == gy) ||
		    (gridpath_bit(row, x + dx) && gridpath_run_x(s, x, y, dx, gx, gy) >= 0) ||
		    (gridpath_bit(row + up, x) && gridpath_run_y(s, x, y, dy, gx, gy) >= 0))
			return n;
	}
}

/* gridpath_successor_dirs(from): the directions to run from a jump point reached by
 * a run in direction from (bit d for direction d). */
static unsigned gridpath_successor_dirs(int from)
{
	if (from == GRIDPATH_FROM_START)
		return 0xffu;
	int dx = gridpath_dx[from], dy = gridpath_dy[from];
	if (dx != 0 && dy != 0)
		return 1u << from | 1u << gridpath_dir_of[1][dx + 1] |
		       1u << gridpath_dir_of[dy + 1][1];
	if (dy == 0) /* along x: on, both sides, both forward diagonals */
		return 1u << from | 1u << 1 | 1u << 3 | 1u << gridpath_dir_of[2][dx + 1] |
		       1u << gridpath_dir_of[0][dx + 1];
	return 1u << from | 1u << 0 | 1u << 2 | 1u << gridpath_dir_of[dy + 1][2] |
	       1u << gridpath_dir_of[dy + 1][0];
}

/* gridpath_find_jump: gridpath_find for GRIDPATH_JUMP, with padded, checked ends. */
static GridPathStatus gridpath_find_jump(GridPathSearch *s, int32_t sx, int32_t sy, int32_t gx,
                                         int32_t gy, Path *path, double *length)
{
	const int32_t pw = s->pw;
	const int32_t start = sy * pw + sx;
	gridpath_jump_reset(s);
	gridpath_open_reset(s);
	{
		const int32_t r = gridpath_jump_new(s, start, sx, sy);
		GridPathJumpRecord *rs = &s->jump[r];
		rs->straight = rs->diagonal = rs->run = 0;
		rs->parent = -1;
		rs->from = GRIDPATH_FROM_START;
		int32_t ax = abs(gx - sx), ay = abs(gy - sy);
		int32_t lo = ax < ay ? ax : ay, hi = ax < ay ? ay : ax;
		s->f_start = gridpath_cost(hi - lo, lo);
		gridpath_push(s, (GridPathOpen){s->f_start, 0, r});
	}
	const uint64_t *seen = s->jump_seen;
	const int32_t *slot = s->jump_slot;
	int64_t expanded = 0;
	int32_t found = -1; /* the goal's record */
	GridPathOpen e;
	s->stack_count = 0;
	for (;;) {
		if (s->stack_count > 0)
			e = s->stack[--s->stack_count];
		else if (!gridpath_pop(s, &e))
			break;
		const int32_t r = e.cell; /* a record, see JUMP RECORDS */
		GridPathJumpRecord *rc = &s->jump[r];
		if (rc->closed)
			continue; /* stale, as in gridpath_find */
		rc->closed = 1;
		expanded++;
		/* locals: the records may move when they grow below */
		const int32_t cx = rc->x, cy = rc->y;
		if (cx == gx && cy == gy) {
			found = r;
			break;
		}
		const int32_t cs = rc->straight, cd = rc->diagonal;
		/* a run whose first step is illegal finds nothing: not tried (the legal
		 * steps from rows' words about c, which the runs read next) */
		unsigned dirs = gridpath_successor_dirs(rc->from) & gridpath_moves(s, cx, cy);
		/* All the runs first, then their jump points in order of d: the runs read
		 * only rows and cols, so the seen bits and slots of the jump points
		 * are fetched while the next runs scan. */
		int32_t found_steps[8];
		int found_d[8], runs = 0;
		for (; dirs; dirs &= dirs - 1) {
			const int d = gridpath_ctz64(dirs);
			const int32_t steps = gridpath_jump(s, cx, cy, d, gx, gy);
			if (steps < 0)
				continue;
			found_steps[runs] = steps;
			found_d[runs++] = d;
		}
		for (int k = 0; k < runs; k++) {
			const int32_t steps = found_steps[k];
			const int d = found_d[k];
			const int32_t nx = cx + gridpath_dx[d] * steps,
			              ny = cy + gridpath_dy[d] * steps;
			const int32_t n = ny * pw + nx;
			int32_t ns = cs + (d < 4 ? steps : 0);
			int32_t nd = cd + (d < 4 ? 0 : steps);
			double ng = gridpath_cost(ns, nd);
			int32_t rn;
			if (seen[n / 64] >> (n % 64) & 1) {
				rn = slot[n];
				const GridPathJumpRecord *old = &s->jump[rn];
				if (old->closed ||
				    !(ng < gridpath_cost(old->straight, old->diagonal)))
					continue;
			} else
				rn = gridpath_jump_new(s, n, nx, ny);
			GridPathJumpRecord *rr = &s->jump[rn];
			rr->straight = ns;
			rr->diagonal = nd;
			rr->parent = r;
			rr->run = steps;
			rr->from = (uint8_t)d;
			int32_t ax = abs(gx - nx), ay = abs(gy - ny);
			int32_t lo = ax < ay ? ax : ay, hi = ax < ay ? ay : ax;
			GridPathOpen ne = {gridpath_cost(ns + hi - lo, nd + lo), (float)ng, rn};
			if (ne.f == e.f) {
				s->stack = gridpath_room(s->stack, s->stack_count, &s->stack_cap);
				s->stack[s->stack_count++] = ne;
			} else
				gridpath_push(s, ne);
		}
	}
	path->expanded = expanded;
	if (found < 0)
		return GRIDPATH_NO_PATH;

	/* Walk back record by record (see PATH above), filling the path from its end. */
	const GridPathJumpRecord *jump = s->jump;
	const int32_t steps = jump[found].straight + jump[found].diagonal;
	path->pts = util_grow(path->pts, &path->cap, steps + 1, sizeof *path->pts);
	path->count = steps + 1; /* every point is written below */
	int32_t i = steps, x = gx, y = gy;
	path->pts[i] = vec2((double)(gx - 1) + 0.5, (double)(gy - 1) + 0.5);
	for (int32_t r = found; jump[r].parent >= 0; r = jump[r].parent) {
		const int d = jump[r].from;
		for (int32_t k = jump[r].run; k > 0; k--) {
			x -= gridpath_dx[d];
			y -= gridpath_dy[d];
			path->pts[--i] = vec2((double)(x - 1) + 0.5, (double)(y - 1) + 0.5);
		}
	}
	*length = gridpath_cost(jump[found].straight, jump[found].diagonal);
	return GRIDPATH_FOUND;
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

	int32_t offset[8];
	for (int d = 0; d < 8; d++)
		offset[d] = gridpath_dy[d] * pw + gridpath_dx[d];
	gridpath_next_round(s);
	const uint32_t open_mark = 2 * s->round, closed_mark = 2 * s->round + 1;
	GridPathNode *node = s->node;
	const int32_t goal_x = gx + 1, goal_y = gy + 1;

	gridpath_ring_reset(s);
	node[start].mark = open_mark;
	node[start].straight = node[start].diagonal = 0;
	node[start].from = GRIDPATH_NO_PARENT;
	{
		int32_t ax = abs(goal_x - (sx + 1)), ay = abs(goal_y - (sy + 1));
		int32_t lo = ax < ay ? ax : ay, hi = ax < ay ? ay : ax;
		s->f_start = gridpath_cost(hi - lo, lo);
		gridpath_ring_push(s, (GridPathOpen){s->f_start, 0, start});
	}
	int64_t expanded = 0;
	int found = 0;
	GridPathOpen e;
	GridPathOpen *stack = s->stack; /* s->stack, in locals (see below) */
	int stack_count = 0, stack_cap = s->stack_cap;
	for (;;) {
		if (stack_count > 0)
			e = stack[--stack_count];
		else if (!gridpath_ring_pop(s, &e))
			break;
		int32_t c = e.cell;
		/* Stale entries need no test of their own: a cell's entries leave the heap
		 * in order of f, h is fixed per cell, so the first to leave carries the
		 * best g, and it closes the cell; the later, stale ones meet the mark. */
		GridPathNode *nc = &node[c];
		if (nc->mark == closed_mark)
			continue;
		nc->mark = closed_mark;
		expanded++;
		if (c == goal) {
			found = 1;
			break;
		}
		/* the legal steps from one byte (gridpath_init), in order of d as before:
		 * the order of pushes decides ties, and so the path */
		unsigned m = nc->moves;
		if (nc->from != GRIDPATH_NO_PARENT)
			m &= ~(unsigned)s->skip[nc->from][node[c - offset[nc->from]].moves];
		/* locals: the stores of a byte below (from) may alias anything, so fields
		 * read through pointers would be read again after each */
		const int32_t cs = nc->straight, cd = nc->diagonal;
		const int32_t rx = goal_x - c % pw, ry = goal_y - c / pw; /* goal - c */
		for (; m; m &= m - 1) {
			const int d = gridpath_ctz64(m);
			const int32_t n = c + offset[d];
			GridPathNode *nn = &node[n];
			const uint32_t mark = nn->mark;
			if (mark == closed_mark)
				continue;
			const int32_t ns = cs + (d < 4), nd = cd + (d >= 4);
			const double ng = gridpath_cost(ns, nd);
			if (mark == open_mark && !(ng < gridpath_cost(nn->straight, nn->diagonal)))
				continue;
			nn->mark = open_mark;
			nn->straight = ns;
			nn->diagonal = nd;
			nn->from = (uint8_t)d;
			const int32_t ax = abs(rx - gridpath_dx[d]), ay = abs(ry - gridpath_dy[d]);
			const int32_t lo = ax < ay ? ax : ay, hi = ax < ay ? ay : ax;
			const GridPathOpen ne = {gridpath_cost(ns + hi - lo, nd + lo), (float)ng,
			                         n};
			if (ne.f == e.f) {
				/* As good as the best open entry: expand it next, no heap. */
				if (stack_count == stack_cap)
					stack = util_grow(stack, &stack_cap, stack_count + 1,
					                  sizeof *stack);
				stack[stack_count++] = ne;
			} else
				gridpath_ring_push(s, ne);
		}
	}
	s->stack = stack;
	s->stack_cap = stack_cap;
	path->expanded = expanded;
	if (!found)
		return GRIDPATH_NO_PATH;

	/* Walk back along from[], then reverse: the path runs start to goal. */
	int32_t steps = node[goal].straight + node[goal].diagonal;
	path->pts = util_grow(path->pts, &path->cap, steps + 1, sizeof *path->pts);
	path->count = steps + 1;                  /* every point is written below */
	int32_t c = goal, x = goal_x, y = goal_y; /* c = y pw + x: no division */
	for (int32_t i = steps; i >= 0; i--) {
		path->pts[i] = vec2((double)(x - 1) + 0.5, (double)(y - 1) + 0.5);
		if (i > 0) {
			const int d = node[c].from;
			c -= offset[d];
			x -= gridpath_dx[d];
			y -= gridpath_dy[d];
		}
	}
	*length = gridpath_cost(node[goal].straight, node[goal].diagonal);
	return GRIDPATH_FOUND;
}
