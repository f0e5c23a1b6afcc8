/* gridjump.c - A* over jump points on the 8-connected grid: the search of gridpath.c
 * (paper 4.1, the paper's second alternative), pruned to the cells where a shortest
 * path may turn, for the same lengths (GRIDPATH_JUMP, gridpath.h). gridpath.c keeps
 * the grid's copies, plain A* and the public entry; this file the jump search and
 * its open list, a paged bucket queue. What both share: gridpath_work.h.
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
 * jump is its step count (straight or diagonal), kept as counts (gridpath.c, EXACT
 * TIES), so the lengths are the plain A*'s, exactly; checked against it and against
 * every published Moving AI optimum in tests/unit/test_gridpath.c.
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
 * maze they were 8% of the search's time, a cache miss each).
 *
 * OPEN LIST: the entries of gridpath.h's GridPathOpen, filed in buckets of f
 * (GRIDPATH_BUCKETS_PER_UNIT to a unit) of which a page is kept, the current
 * bucket a binary heap (see GRIDPATH_PAGE); ties in f go to the larger g, and a
 * jump point whose f equals the f being expanded skips the buckets through the
 * stack, as in plain A*. See gridpath.c for the costs' exactness (EXACT TIES).
 *
 * PERFORMANCE (issue 16; instructions by callgrind, exact, of one warm corner-to-
 * corner query at 1024 as skelbench picks the ends, gridpath_find inclusive;
 * before = the tree before issue 16's work, -> the first round, -> the second):
 *   rooms 6.7 -> 6.1 -> 5.3 M, rects 5.6 -> 4.8 -> 3.1, maze 47.2 -> 43.6 -> 50.0
 *   (42 138 jump points expanded: 1 190 instructions each), Boston_0_1024 11.3 ->
 *   9.9 -> 7.2, den520d 3.3 -> 2.7 -> 1.4.
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
 * Times and the ratios to libtcod: gridpath.h.
 *
 * MEMORY: gridpath.h. COMPLEXITY: O(n log n) for n jump points expanded, plus the
 * runs' scans (64 cells a word), the empty buckets skipped (64 a word) and each
 * overflow entry once per page it waits through. */
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "gridpath_work.h"
#include "utak/base/util.h"
#include "utak/plan/gridpath.h"

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

/* gridpath_jump_free: see gridpath_work.h. */
void gridpath_jump_free(GridPathSearch *s)
{
	if (s->bucket)
		for (int i = 0; i < GRIDPATH_PAGE; i++)
			free(s->bucket[i].e);
	free(s->bucket);
	free(s->nonempty);
	free(s->overflow);
	free(s->jump);
	free(s->jump_seen);
	free(s->jump_slot);
}

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
GridPathStatus gridpath_find_jump(GridPathSearch *s, int32_t sx, int32_t sy, int32_t gx, int32_t gy,
                                  Path *path, double *length)
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
