/* gridpath.h - A* on the 8-connected grid: the paper's second alternative (paper 4.1).
 *
 * The screen becomes a graph: every free cell is a vertex, joined to its 4 edge
 * neighbours at cost 1 and to its 4 diagonal neighbours at cost sqrt 2. A diagonal
 * step is allowed only when BOTH orthogonally adjacent cells are free (no cutting
 * past an occupied corner: the Moving AI convention, see
 * movingai.com and tests/data/README.md). The search is A* (Hart, Nilsson and Raphael
 * 1968), the paper's reference [8], with the exact octile heuristic.
 *
 * Usage:
 *	GridPathSearch s;
 *	gridpath_init(&s, &grid);            // copies the grid; O(w h)
 *	double len;
 *	Path path; path_init(&path);
 *	if (gridpath_find(&s, sx, sy, gx, gy, &path, &len) == GRIDPATH_FOUND) ...
 *	path_free(&path); gridpath_free(&s);
 * One GridPathSearch serves any number of queries on the same grid; it must not be
 * shared between threads. The Path holds the cell centres (x + 0.5, y + 0.5) from
 * start to goal, one per step, and path.expanded the number of cells expanded.
 *
 * JUMP POINTS: with s.method = GRIDPATH_JUMP after gridpath_init, the same query
 * runs as a jump-point search (gridjump.c): the same length, path.expanded then
 * counts the jump points expanded.
 *
 * MEMORY: per cell of the grid with a one-cell border, 2 bits (the grid's copies
 * rows and cols; 64 cells to a word, so up to 63 bits more a line), and from the
 * first query of either method, 4 bytes more for plain A* (the node) and 4 and a
 * bit for the jump search (a record index and a seen bit); plus the open list (for
 * plain A* five queues of 8-byte entries, each a power of two of at least 256
 * entries and at most twice the most it held at once, 4 bytes per entry of its
 * stack and a byte per step of its last path; for the jump search 16 bytes per
 * pushed entry; at most 8 pushes per cell, far fewer in practice), for plain A* 18 bytes per column and per row (its region
 * tables), and for the jump search 28 bytes per jump point seen, all kept
 * between queries.
 *
 * PERFORMANCE (issue 16; `make bench-compare SIDE=1024`, one run on this shared
 * 2-core machine, one thread, thread CPU time, medians of 5 (utak) and 3 (libtcod);
 * corner to corner, the ends as skelbench picks them). Plain A* at 1024 after its
 * fourth round (five first-in first-out queues, prefetches, the steps its parent
 * makes needless skipped; gridpath.c): rooms 3.46 ms, rects 2.07, maze 16.70
 * (688 000 cells expanded), Boston_0_1024 2.84, den520d 0.81; libtcod's A* over
 * these 138, 164, 5.63, 114 and 75.8 times (after the third round 51.2, 61.1,
 * 2.95, 37.1, 33.2; the second 25.9, 32.2, 2.13, 21.3, 17.2; before issue 16's
 * work 12.9, 11.3, 1.34, 10.6, 8.9). The jump search in the same run: 0.55, 0.40,
 * 6.94, 0.76 and 0.15 ms, libtcod over it 878, 852, 13.6, 429 and 414 times. At
 * 4096 (skelbench --compare --side 4096, medians of 5, and libtcod's tcodpath on
 * the maze right after it, median of 3, 990 ms; on rooms and rects from an earlier
 * run on the same grids, 29 126 and 18 250 ms): plain A* rooms 68.1 ms, rects 35.0,
 * maze 167 (the third round: 197, 100, 305), libtcod over it 428, 521 and 5.93
 * times (148, 182, 3.3); the jump search 19.9, 15.0 and 75.3 ms. The 5
 * times libtcod for plain A* is met on every map at 1024 and on the three run at
 * 4096 (the maze 5.63 and 5.93, at about 153 instructions a cell expanded, see
 * gridpath.c); the Moving AI maps at 4096 were not run this round.
 * After the fifth round (gridpath.c: WALK BACK, LAZY OFFERS, ROOM, PREFETCH), two
 * runs of bench/compare.py --side 1024 each beside one of the fourth round's code
 * (skelbench built with it), alternating, on 2026-11-27 at load 10-14 on 2 cores:
 * plain A* rooms 2.23-2.26 ms, rects 1.29-1.34, maze 10.33-10.44 (19.25-19.49 with
 * the fourth round's), Boston_0_1024 1.76-1.77, den520d 0.45-0.52; libtcod over it
 * 104-112, 139-145, 7.18-7.53 (3.98-4.05), 98-107 and 80-97 times. At 4096
 * (skelbench --compare --side 4096, two runs each alternating, medians of 5; then
 * libtcod's tcodpath on the same grids, medians of 3): the maze 92.7-99.1 ms
 * against 162.8-167.5, libtcod (770 ms) over it 7.77-8.30 (4.60-4.73); see README,
 * Benchmarks, for the other grids.
 * Instructions a query (callgrind): gridpath.c and gridjump.c, PERFORMANCE. */
#ifndef UTAK_GRIDPATH_H
#define UTAK_GRIDPATH_H

#include <stdint.h>

#include "utak/plan/grid.h"
#include "utak/plan/path.h"

/* How gridpath_find searches; both return a shortest path of the same length (the
 * cells may differ where several paths are shortest). */
typedef enum GridPathMethod {
	GRIDPATH_ASTAR = 0, /* A* over every cell (the default) */
	GRIDPATH_JUMP,      /* A* over jump points (Harabor and Grastien 2011), see gridjump.c */
} GridPathMethod;

typedef enum GridPathStatus {
	GRIDPATH_FOUND = 0,    /* a shortest path was found */
	GRIDPATH_NO_PATH,      /* start and goal are free but not connected */
	GRIDPATH_BAD_ENDPOINT, /* start or goal is outside the grid or blocked */
	GRIDPATH_TOO_LARGE,    /* plain A* on a grid of GRIDPATH_MAX_CELLS or more (padded):
	                          past what its exact integer costs cover (gridpath.c) */
} GridPathStatus;

/* Plain A*'s integer costs order paths exactly on a grid, padded by a ring of
 * cells, of fewer cells than this (gridpath.c, EXACT KEYS); the jump search has no
 * such bound. utak's own grids stay far below it (8192 x 4096 at most). */
#define GRIDPATH_MAX_CELLS ((int64_t)1 << 29)

/* One entry of the open list: a cell and its priority. Public only so that the
 * search state below can be allocated by the caller; treat it as opaque. */
typedef struct GridPathOpen {
	double f;     /* g + h: the priority, smallest first */
	float g;      /* cost so far: ties in f go to the larger g (a float keeps the
	                 entry at 16 bytes; it only orders ties, so rounding is harmless) */
	int32_t cell; /* index into the padded grid */
} GridPathOpen;

/* Plain A*'s open list (gridpath.c, FIFO QUEUES): one first-in first-out queue for
 * each growth of f a step can make above zero, of which the octile distance has
 * five (2 - sqrt 2, 2 sqrt 2 - 2, sqrt 2, 2, 2 sqrt 2). */
#define GRIDPATH_QUEUES 5

/* One bucket of the open list (opaque, see below). */
typedef struct GridPathBucket {
	GridPathOpen *e;
	int count, cap;
} GridPathBucket;

/* One entry of a queue of plain A* (gridpath.c): the low 32 bits of its f's key,
 * and the offer: the cell above 3 bits, the step that offered it in them
 * (gridpath.c, LAZY OFFERS). */
typedef struct GridPathQueueEntry {
	uint32_t key;
	uint32_t offer;
} GridPathQueueEntry;

/* One queue of plain A* (opaque): a circular array of mask + 1 entries, a power of
 * two; head and tail count the entries taken and put, modulo 2^32. */
typedef struct GridPathQueue {
	GridPathQueueEntry *e; /* NULL before the first query */
	uint32_t head, tail, mask;
} GridPathQueue;

/* The search state for one grid. Cells are indexed in a copy of the grid with a
 * blocked border one cell wide (width w + 2), so neighbours need no bounds tests. */
typedef struct GridPathSearch {
	int32_t w, h;       /* size of the grid searched, in cells */
	int32_t pw;         /* padded width: w + 2 */
	/* Plain A*'s state of each of the (w + 2) (h + 2) cells, NULL before its first
	 * query: the legal steps from the cell (bits 0-7: bit d for step d of
	 * gridpath.c, no corner cutting; 0 for blocked and border cells), the step that
	 * reached it (8-11; 8 for the start), the round it was closed in (12-31); 4
	 * bytes a cell, so that a cache line holds 16 (gridpath.c, LAZY OFFERS). */
	uint32_t *node;
	uint32_t round;     /* plain A*'s query counter; marks of other rounds mean "unseen" */
	/* The jump search's open list: buckets of f, GRIDPATH_BUCKETS_PER_UNIT per unit of length
	 * from the start's f; the current bucket is a binary heap, later ones are unsorted. Only a
	 * page of GRIDPATH_PAGE buckets, from bucket page_base on, is kept; entries past it wait
	 * unsorted in overflow until the page is empty. */
	GridPathBucket *bucket; /* GRIDPATH_PAGE buckets, or NULL before the first query */
	uint64_t *nonempty;     /* GRIDPATH_PAGE bits: bucket i holds entries */
	int64_t page_base;      /* the bucket number of bucket[0] */
	int64_t bucket_now;     /* the current bucket; no entry lies in an earlier one */
	double f_start;         /* f of the start cell: the origin of bucket numbers */
	GridPathOpen *overflow; /* entries of buckets >= page_base + GRIDPATH_PAGE */
	int overflow_count, overflow_cap;
	/* Entries whose f equals that of the cell being expanded, the least in the open
	 * list: they may be expanded next in any order, so they skip the heap. */
	GridPathOpen *stack;
	int stack_count, stack_cap;
	/* Plain A*'s open list: its queues (gridpath.c, FIFO QUEUES), and the stack of
	 * cells whose f equals the one being expanded. */
	GridPathQueue queue[GRIDPATH_QUEUES];
	uint32_t *at_stack; /* offers, as GridPathQueueEntry.offer */
	int at_stack_cap;
	/* plain A*'s path, walked back once from the goal: the step into each cell */
	uint8_t *walk;
	int walk_cap;
	/* y = c / pw for a padded index c as c div_mul >> div_shift (gridpath_init) */
	uint64_t div_mul;
	unsigned div_shift;
	/* df[r][d]: the growth of f's key by step d from a cell in region r about the
	 * goal in the low 32 bits, the index of its queue above them (gridpath_init, see
	 * gridpath.c, EXACT KEYS and FIFO QUEUES). */
	uint64_t df[45][8];
	/* The row of df of a cell's region about the goal (gridpath.c) from its x and
	 * y, as byte offsets: region_x[x] = |goal x - x| 4096 + 64 15 (sign + 1),
	 * region_y[y] the same with 64 5 (sign + 1), both set by each query, and
	 * region_d[|dx| - |dy| + ph] = 64 (that clamped to [-2, 2] + 2). */
	int64_t *region_x, *region_y;
	uint16_t *region_d;
	/* GRIDPATH_ASTAR after gridpath_init; set it to GRIDPATH_JUMP for a jump-point
	 * search. The jump search scans the grid along rows and columns, so the free
	 * cells are kept twice, row-major (rows) and column-major (cols), both padded
	 * like node. */
	GridPathMethod method;
	int32_t ph; /* padded height: h + 2 */
	/* rows: one bit a cell (1: free), row by row, row_words words a row (bit x % 64
	 * of word x / 64 for padded x); cols: the same transposed, col_words words a
	 * column. 128 KB each at 1024 x 1024, so the runs' scans stay in cache. */
	uint64_t *rows, *cols;
	int32_t row_words, col_words;
	/* legal[n]: the legal steps of a cell (GridPathNode.info's bits 0-7) whose 3 x 3
	 * neighbourhood is n: bit 3 (dy + 1) + dx + 1 for (x + dx, y + dy) free. */
	uint8_t legal[512];
	/* The jump search's own state (gridjump.c, JUMP RECORDS), allocated by its first
	 * query: a record per jump point seen, in order of first sight, and per cell a
	 * seen bit and the index of its record (valid only where the bit is set). */
	struct GridPathJumpRecord *jump; /* the records of this query */
	int32_t jump_count, jump_cap;
	uint64_t *jump_seen; /* pw * ph bits; clear between queries */
	int32_t *jump_slot;  /* pw * ph: record index of each seen cell */
	/* skip[d][m]: the steps an expansion of a cell reached by step d need not try,
	 * when its parent's legal steps are m (see gridpath.c); d = 8 for a start. */
	uint8_t skip[9][256];
} GridPathSearch;

/* gridpath_init(s, grid): prepares a search on a copy of grid (w, h >= 1). */
void gridpath_init(GridPathSearch *s, const Grid *grid);
void gridpath_free(GridPathSearch *s);

/* gridpath_find(s, sx, sy, gx, gy, path, length): a shortest 8-connected path from
 * cell (sx, sy) to cell (gx, gy). On GRIDPATH_FOUND, path holds the cell centres
 * and *length the exact length (straight + diagonal sqrt 2, computed from step
 * counts, not by summing). On other results path is empty and *length is -1.
 * path->expanded counts the cells expanded (closed) in every case: every cell the
 * search closed, or for GRIDPATH_JUMP every jump point. */
GridPathStatus gridpath_find(GridPathSearch *s, int32_t sx, int32_t sy, int32_t gx, int32_t gy,
                             Path *path, double *length);

/* gridpath_octile(dx, dy): the octile distance, the exact 8-connected length on an
 * empty grid: max - min straight steps plus min diagonal steps. */
double gridpath_octile(int32_t dx, int32_t dy);

#endif
