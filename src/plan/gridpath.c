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
 * entries never span more than 2 sqrt 2: "plain A*'s open list" below), the
 * current one a sorted array; the jump search (gridjump.c), whose jumps are long,
 * keeps a page of buckets with an overflow beyond it, the current bucket a binary
 * heap. A neighbour whose f equals the f being expanded (the least in the
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
 *   jump points: gridjump.c, PERFORMANCE.
 * The steps, maze plain A*: the parent's neighbours skipped 337 -> 292 M; the ring
 * for the paged heap 292 -> 232; locals instead of fields re-read after byte stores
 * and the sift inline 232 -> 225; the sorted current bucket 225 -> 209 (rooms 172
 * -> 145, and its time about halved: the heap's branches mispredicted). Times and
 * the ratios to libtcod: see gridpath.h. Where the time goes now (perf): the maze's
 * plain A* is bound by instructions (about 2 a cycle), spread over the bucket
 * work, the cost conversions and the neighbour loop.
 *
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
 * of nonempty bits); initialisation O(w h) once per grid, and a query touches only
 * what it expands (the round counter replaces clearing the marks) and, for plain
 * A*, the ring's GRIDPATH_RING buckets. */
#include "utak/plan/gridpath.h"

#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "gridpath_work.h"
#include "utak/base/util.h"

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
	if (s->ring)
		for (int i = 0; i < GRIDPATH_RING; i++)
			free(s->ring[i].e);
	free(s->ring);
	free(s->stack);
	free(s->scratch);
	gridpath_jump_free(s);
	*s = (GridPathSearch){0};
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
