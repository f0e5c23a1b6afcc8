/* skeleton.c - the exact distance transform and the digital skeleton of free space
 * (paper 4.2; see skeleton.h for the digital topology and the units).
 *
 * ALGORITHM
 * 1. Distance transform: Meijster, Roerdink and Hesselink, "A general algorithm for
 *    computing distance transforms in linear time" (Mathematical Morphology and its
 *    Applications to Image and Signal Processing, 2000). Phase 1 finds, for every cell,
 *    the distance g to the nearest blocked cell in its column: one pass down the grid
 *    (the distance to the blocked cell above, 16 bits a cell), then one pass up that
 *    takes the distance below and the minimum and hands each row at once to phase 2:
 *    dist2(x) = min over the columns u of (x - u)^2 + g(u)^2. Phase 2 goes by blocks of
 *    32 cells. A block whose cells are all near a blocked cell (a bound b from g and
 *    from the row below, see edt_row) takes the minimum over the window |x - u| < b
 *    directly, one offset for the 32 cells at once in 16-bit lanes; the others, far
 *    from every blocked cell, take the lower envelope of the parabolas, as in
 *    Felzenszwalb and Huttenlocher ("Distance transforms of sampled functions", Theory
 *    of Computing 8, 2012) but with exact integer comparisons in place of divisions,
 *    over the columns in their reach. A blocked cell is one more column, with g = 0.
 *    The cells just outside the grid are blocked: phase 1 starts each column at
 *    distance 1 from the rows -1 and h, and phase 2 has a blocked column at -1 and w.
 *    The loops over a block have a fixed count, which compilers vectorise at -O2;
 *    on x86-64 Linux the row pass is also compiled for AVX2 and chosen at load time.
 * 2. Thinning: distance-ordered homotopic thinning (Pudney, "Distance-ordered homotopic
 *    thinning: a skeletonization algorithm for 3D digital images", CVIU 72(3), 1998),
 *    here in 2D with the (4, 8) topology. Free cells are visited in order of
 *    increasing dist2 (a counting sort: a bucket queue with all keys known in
 *    advance; ties by cell index, so the result is deterministic). A visited cell is
 *    deleted when it is simple (deleting it changes neither the 4-components of the
 *    set nor the 8-components of its complement: a 256-entry table over the 8
 *    neighbours, built from the definition of Bertrand's topological numbers
 *    T4 = 1 and T8bar = 1) and is not a ridge end (exactly one 4-neighbour in the set
 *    and no 8-neighbour in the set farther from the obstacles: the tip of a branch
 *    where the distance map peaks, as in a dead-end corridor or a niche; Pudney keeps
 *    the centres of maximal discs for the same purpose). A deletion can make an
 *    already visited neighbour deletable; such neighbours go on a stack and are tried
 *    again at once, so when the scan ends no cell of the set is deletable. Visiting in
 *    distance order peels the space like Blum's grassfire, so what is left lies on
 *    the ridge of the distance map, the medial axis.
 * 3. Pruning: a small bay in a wall can still leave a branch whose tip is a ridge end,
 *    a spur. Every branch from an end point to a junction cell (degree >= 3) is
 *    removed when it has at most SKELETON_SPUR_FACTOR * clearance(junction) +
 *    SKELETON_SPUR_SLACK cells (see skeleton.h); branches are judged all at once on
 *    the thinned set, one round, and a branch joining two end points (a component
 *    that is a simple arc) is never removed. Removing a branch that hangs off a
 *    junction changes no topology. Then step 2's deletion test runs again over the
 *    skeleton, because a junction that lost a branch may now be deletable.
 *
 * INVARIANTS (tested in tests/unit/test_skeleton.c against flood-fill oracles)
 *    skeleton cells are free; the skeleton has as many 4-components as the free
 *    space and, in each, as many loops (8-components of its complement not joined to
 *    the outside) as the space has holes; no skeleton cell is deletable by step 2.
 *
 * MEMORY  dist2 and on (5 bytes a cell), and the working space, kept in the Skeleton
 *    for the next grid of the same size: a padded state byte per cell, the visiting
 *    order and a stack (4 bytes a cell each; the stack holds the transform's 2 bytes a
 *    cell of column distances before the thinning uses it), and the counting-sort
 *    histogram (4 bytes per possible dist2 value: about (shorter side / 2)^2, a
 *    quarter of the cells). skeleton_edt alone keeps them in dist2's first half; the
 *    transform's other scratch is a few arrays of one row.
 *
 * COMPLEXITY  O(w h) but for the windows: the transform is one pass down the grid and
 *    one up, each row's envelope pushing each column at most once; a window block
 *    costs b offsets (b <= 181), each two loads, an addition and two minima for its
 *    32 cells; the sort is two passes;
 *    every cell is visited once plus once per deleted neighbour (at most 8; 1.1 visits
 *    a free cell on the benchmark grids); pruning walks each branch once.
 *
 * MEASURED  (issue 16; thread CPU time on this 2-core machine, shared, so +-15%;
 *    `make bench-compare` for the table against the peers). Everything after the
 *    transform (state, sort, visits, pruning, output) on the 1024 grids, before and
 *    after the rework of the thinning (the same skeleton cell for cell): 129, 146, 121
 *    and 118 million instructions on the maze, rooms, rects and Boston_0_1024 (123,
 *    139, 115 and 112 a cell; valgrind --tool=callgrind, exact) down to 58, 65, 53 and
 *    51 (56, 62, 51 and 49 a cell); in time, by phase (an instrumented copy, min of 7
 *    alternating runs), on the maze the state and the sort 1.7 -> 1.55 ms, the visits
 *    6.9 -> 2.4, listing and pruning 3.1 -> 0.9, the output 0.5 -> 0.15: about 12 ms
 *    to 5.1, and on rooms, rects and Boston 6.3-6.4 ms (visits 3.7-3.9, sort
 *    1.9-2.1). What did it: the visit's raster mask from two 4-byte loads gathered
 *    by one multiplication (the former byte loads spilled a byte that was read back
 *    as 4, a store-forwarding stall that was a third of the visits), the visits in a
 *    loop of their own (inlined, its index lived on the stack), SKELETON_KEPT so that
 *    "any neighbour to try again" is one test, the sort four cells a group with the
 *    blocked cells as bucket 0 (no branch; one link of the chain through start[] a
 *    group), the end points by a scan eight cells a word and walks by 4-neighbour
 *    masks, the recheck list by a radix sort. The visits are instruction-bound at 1024 (3-4 ns,
 *    about 35 instructions, a visit; at 256 a side, all in cache, 80% of that) and
 *    the sort takes 4-6 cycles a cell. 786 429 visits on the maze (993 796 on rooms),
 *    of which none found its cell interior (all 8 neighbours in the set): the
 *    distance order puts every cell on the front when its turn comes, so a border
 *    queue would save no visit. The medial axis from a feature transform was not
 *    tried: the visits now cost about a third of the transform, and the spur rule and
 *    topology are what the tests pin; a select instead of the kind's branch, a
 *    shortcut of the ridge test by the visited bits, a run-of-one-key path in the
 *    sort and prefetching at 1024 were tried and were slower or no faster. From 1024
 *    to 4096 a side the sort grows 14-16 times, the visits 18 (maze) to 43 times
 *    (rects: many distance levels, each a sweep of the 17 MB state) before the
 *    prefetch above 8 MB (thinner_visit_all), which takes 10-25% off at 4096.
 *    The transform (the same values throughout): from the former code's envelope over
 *    whole rows (one data-dependent branch mispredicted about every two cells) to the
 *    windows, valgrind counts (exact; bench driver, one transform) of 82.4, 82.7,
 *    82.3, 82.5 and 82.1 million instructions on the 1024 grids rooms, rects, maze,
 *    Boston_0_1024 and den520d fell to 18.7, 19.1, 12.4, 21.7 and 18.0 (11.8 to 20.7
 *    a cell). Each step, in thread CPU time against the code before it in one process
 *    (best of 5 to 15, on the loaded machine): the windows in 16-cell blocks with the
 *    SSE2 build, 1.7-2.6 times faster; an AVX2 clone with the window's copy taken
 *    into its loop (it had stalled on store forwarding), two offsets a turn and the
 *    bounds in a loop of their own, 1.2-1.5 more; phase 1 kept in dist2 instead of a
 *    grid-sized allocation, 1.4 at 4096 (a page fault every 4 KB before); 32-cell
 *    blocks, 1.2-1.4 (half the loop exits; the SSE2 build alone is 0.8-1.07 as fast
 *    with them); unsigned lanes taking bounds to 181, 1.04-1.1 at 4096. Tried and
 *    not kept: 64-cell blocks and four offsets a turn (slower: lanes kept in
 *    memory), a switch to the envelope at bounds 48 or 72 (1.1-1.4 slower: the
 *    envelope's mispredictions cost more than long windows), AVX2 for phase 1 too
 *    (no change), an AVX-512 clone (x86-64-v4: no change); a narrower window where
 *    the columns around have large g (a least g a block; 1.1-1.4 slower everywhere). Against OpenCV (cv2.distanceTransform,
 *    DIST_L2, DIST_MASK_PRECISE, one thread), `make bench-compare SIDE=1024`, one run,
 *    medians: rooms, rects, maze, Boston_0_1024, den520d at 1024 took 1.42, 1.39, 1.16,
 *    1.63 and 1.37 ms (3-5 read passes of the grid), OpenCV 14.9, 11.0, 11.4, 12.9 and
 *    9.7: 10.5, 7.9, 9.8, 7.9 and 7.1 times faster. At 4096 (medians of 5, utak timed
 *    before and after OpenCV's 7 in one session): 22.5-23.7, 23.6, 17.6-18.9, 47.3-52.0
 *    and 40.2-41.0 ms against 213, 215, 238, 198 and 180: 9.0-9.4, 9.1, 12.6-13.5,
 *    3.8-4.2 and 4.4-4.5 times. The scaled maps at 4096 miss the 5: their
 *    open spaces are 4 times as wide, so their windows 4 times as long (or past 181,
 *    the envelope): the windows' cost grows with the clearance, not only the cells. */
#include "utak/plan/skeleton.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

/* ---------------------------------------------------------------- distance transform */

/* Phase 2 takes each row in blocks of EDT_BLOCK cells. For a cell x of the row, no
 * column u with (x - u)^2 >= b^2 can come strictly below a bound b^2 >= dist2(x), so
 * the minimum lies within |x - u| < b: a window. Two bounds are at hand, g(x) itself
 * and the row below's answer D': the nearest blocked cell of (x, y + 1) is at most
 * 1 farther from (x, y), so b = min(g(x), ceil(sqrt(D')) + 1). A block whose bound
 * (the larger over its cells) is at most EDT_WINDOW_BOUND is done by the window:
 * min over k < b of g(x - k)^2 + k^2 and g(x + k)^2 + k^2, one k for all the cells
 * of the block at once, in 16-bit lanes (EDT_BLOCK of them: plain C loops of a fixed
 * count, which GCC and Clang vectorise at -O2; 32 cells are two AVX2 vectors). Other
 * blocks, where some cell may be farther than EDT_WINDOW_BOUND from every blocked
 * cell (large open space), take the lower envelope (edt_envelope_push, _sweep) over
 * just the columns their window reaches. On the 1024 benchmark grids the bound of a
 * block is on average about 1 (maze) to 21 (Boston_0_1024); even at the largest
 * bound a window costs less time than the envelope, whose pops mispredict (a switch
 * at 48 or 72 was slower: see MEASURED above), so the bound is as large as the lanes
 * allow. */
#define EDT_BLOCK 32
#define EDT_WINDOW_BOUND 181
/* g^2 in unsigned 16-bit lanes, clipped at EDT_CLIP = EDT_WINDOW_BOUND^2: in a window
 * block every answer is at most EDT_CLIP, so a clipped term, still >= EDT_CLIP, cannot
 * come below the answer, nor wrongly reach it (the term that reaches it is then g^2 =
 * EDT_CLIP itself). The window's loop takes two offsets a turn, so k reaches
 * EDT_WINDOW_BOUND at most (one past a reach of EDT_WINDOW_BOUND - 1: a term of
 * the minimum all the same), and EDT_CLIP + EDT_WINDOW_BOUND^2 < 2^16: no lane
 * overflows. */
#define EDT_CLIP (EDT_WINDOW_BOUND * EDT_WINDOW_BOUND)
_Static_assert(EDT_CLIP + EDT_WINDOW_BOUND * EDT_WINDOW_BOUND <= UINT16_MAX,
               "the window's 16-bit lanes must not overflow");
/* The 16-bit squares are kept with this many zero columns on either side, so that a
 * window (k <= EDT_WINDOW_BOUND) never reads outside; a zero outside the grid stands
 * for a blocked column, which changes nothing beyond columns -1 and w (those are
 * nearer). */
#define EDT_PAD EDT_WINDOW_BOUND

/* The envelope (edt_envelope_push) keeps its first column at the bottom of its stack for
 * good (as in Felzenszwalb and Huttenlocher, where z[0] = -infinity): that entry's
 * differences make the drop test false, EDT_NEVER * (u - t) being below any
 * (F(u) - F(t)) (|F| < 2^31, columns less than 2^16 apart). Above the top lies a
 * parabola EDT_ABOVE + x^2, never lower than the last real column, which is at most
 * (SKELETON_MAX_SIDE + 1)^2 < EDT_ABOVE at any cell (and EDT_ABOVE + x^2 < 2^31). */
#define EDT_NEVER (-((int64_t)1 << 40))
#define EDT_ABOVE 0x40000000

/* The envelope's stack (see edt_envelope_push), w + 4 entries a field. */
typedef struct EdtStack {
	int32_t *u, *G, *L; /* column, its g^2, its distance from the entry below */
	int64_t *F, *D;     /* F = u^2 + G, and F less the entry below's F */
} EdtStack;

/* The lower envelope of the parabolas (x - u)^2 + g[u]^2 of the columns u pushed so
 * far (Meijster et al., Felzenszwalb and Huttenlocher; a blocked cell is one more
 * column, with g = 0). With F(u) = u^2 + g(u)^2 the parabola of column u at x is
 * F(u) - 2 u x + x^2, and two parabolas a < b cross at (F(b) - F(a)) / (2 (b - a)).
 * The envelope's columns are kept on a stack; the top t is dropped when the new
 * column u crosses it no later than t crosses the one below (cross multiplied in 64
 * bits: exact, and no division); each entry keeps its differences from the one below,
 * so the test is two multiplications of values already loaded. A sweep reads the
 * envelope: the entry lowest at x moves right as x does, and the next one is compared
 * by value (32 bits). One row's runs of blocks share one stream of columns, pushed
 * left to right, each column once: a run pushes the columns in its reach not pushed
 * yet, then sweeps its cells; columns pushed for an earlier run are valid candidates
 * too. A push that drops the entry the sweep stands on leaves that cell's place to
 * the new top (the dropped entry was lowest only right of where the new one is). */
typedef struct EdtCursor {
	int32_t top;  /* the stack's top entry, -1 when empty */
	int32_t k;    /* the entry lowest at the last cell swept */
	int32_t last; /* the last column pushed */
} EdtCursor;

/* edt_envelope_push(v, c, g, a, z): pushes the columns a..z not pushed yet (g is
 * read there; -1 <= a, z <= w, g[-1] = g[w] = 0: the blocked columns outside the
 * grid); a gap after the last column pushed starts the stack afresh. */
static void edt_envelope_push(const EdtStack *v, EdtCursor *c, const uint16_t *restrict g,
                              int32_t a, int32_t z)
{
	int32_t *restrict vu = v->u, *restrict vG = v->G, *restrict vL = v->L;
	int64_t *restrict vF = v->F, *restrict vD = v->D;
	int32_t top = c->top;
	if (top < 0 || a > c->last + 1) {
		top = 0;
		c->k = 0;
		vu[0] = a;
		vG[0] = g[a] * g[a];
		vF[0] = (int64_t)a * a + vG[0];
		vL[0] = 1;
		vD[0] = EDT_NEVER;
		c->last = a;
	}
	for (int32_t u = c->last + 1; u <= z; u++) {
		const int32_t gu = g[u];
		const int32_t Gu = gu * gu;
		const int64_t Fu = (int64_t)u * u + Gu;
		/* the top is nowhere strictly lowest: cross(top, u) <= cross(below, top) */
		while ((Fu - vF[top]) * vL[top] <= vD[top] * (u - vu[top]))
			top--;
		vD[top + 1] = Fu - vF[top];
		vL[top + 1] = u - vu[top];
		top++;
		vu[top] = u;
		vG[top] = Gu;
		vF[top] = Fu;
	}
	c->last = z > c->last ? z : c->last;
	c->top = top;
	c->k = c->k < top ? c->k : top;
	vu[top + 1] = 0;
	vG[top + 1] = EDT_ABOVE;
}

/* edt_envelope_sweep(v, c, x0, x1, out): out[x] for x0 <= x < x1, past the cells
 * swept before, from the envelope (every column within reach of them pushed). */
static void edt_envelope_sweep(const EdtStack *v, EdtCursor *c, int32_t x0, int32_t x1,
                               int32_t *restrict out)
{
	const int32_t *restrict vu = v->u, *restrict vG = v->G;
	int32_t k = c->k;
	for (int32_t x = x0; x < x1; x++) {
		int32_t d = x - vu[k], e = x - vu[k + 1];
		int32_t val = vG[k] + d * d, next = vG[k + 1] + e * e;
		while (next <= val) {
			k++;
			val = next;
			e = x - vu[k + 1];
			next = vG[k + 1] + e * e;
		}
		out[x] = val;
	}
	c->k = k;
}

/* edt_window_step(at, k, best): best[i] = min(best[i], at[i - k] + k^2, at[i + k] + k^2)
 * for the cells of a block. */
static inline void edt_window_step(const uint16_t *restrict at, int32_t k, uint16_t *restrict best)
{
	const uint16_t kk = (uint16_t)(k * k);
	const uint16_t *restrict left = at - k, *restrict right = at + k;
	for (int i = 0; i < EDT_BLOCK; i++) {
		uint16_t m = left[i] < right[i] ? left[i] : right[i];
		m = (uint16_t)(m + kk);
		best[i] = m < best[i] ? m : best[i];
	}
}

/* edt_window(sq, x0, reach, best): best[i] = min over |k| <= reach (or reach + 1: two
 * offsets a turn, half the loop's branches) of sq[x0 + i + k] + k^2 (sq: the row's
 * clipped squares, padded). */
static inline void edt_window(const uint16_t *restrict sq, int32_t x0, int32_t reach,
                              uint16_t *restrict best)
{
	const uint16_t *restrict at = sq + x0;
	/* k = 0 inside the loop rather than a copy before it: the copy, two 16-byte
	 * stores read back as one 32-byte vector under AVX2, stalled every block */
	for (int i = 0; i < EDT_BLOCK; i++)
		best[i] = UINT16_MAX;
	for (int32_t k = 0; k <= reach; k += 2) {
		edt_window_step(at, k, best);
		edt_window_step(at, k + 1, best);
	}
}

/* edt_ceil_sqrt(m): the least c with c^2 >= m (m >= 0; sqrt of a double is correctly
 * rounded, so its floor is exact below 2^52). */
static inline int32_t edt_ceil_sqrt(int32_t m)
{
	int32_t c = (int32_t)sqrt((double)m);
	return (int64_t)c * c < m ? c + 1 : c;
}

/* The scratch of phase 2, O(w). */
typedef struct EdtRow {
	uint16_t *g;    /* the row's column distances, g[-1] and g[w .. wb] 0 */
	uint16_t *sq;   /* min(g^2, EDT_CLIP), EDT_PAD zeros either side */
	uint16_t *dn;   /* per column: the distance to the blocked cell below */
	int32_t *bound; /* per block: the largest answer of the row done last */
	uint16_t *most; /* per block: the largest g */
	int32_t *reach; /* per block and one more: the bound b of the row being done */
	EdtStack v;
	int32_t w, blocks;
} EdtRow;

/* edt_columns_block(up, dn, g, sq): edt_columns on one block (the pointers at its
 * first column); returns its largest g. */
static inline uint16_t edt_columns_block(const unsigned char *restrict up_bytes,
                                         uint16_t *restrict dn, uint16_t *restrict g,
                                         uint16_t *restrict sq)
{
	uint16_t up[EDT_BLOCK];
	memcpy(up, up_bytes, sizeof up);
	for (int i = 0; i < EDT_BLOCK; i++) {
		const uint16_t d = up[i] ? (uint16_t)(dn[i] + 1) : 0;
		dn[i] = d;
		g[i] = d < up[i] ? d : up[i];
	}
	uint16_t m = 0;
	for (int i = 0; i < EDT_BLOCK; i++) {
		sq[i] = (uint16_t)(g[i] < EDT_WINDOW_BOUND ? g[i] * g[i] : EDT_CLIP);
		m = g[i] > m ? g[i] : m;
	}
	return m;
}

/* edt_down_block(cells, prev, row): phase 1 down the grid on one block: row = prev + 1
 * on a free cell, else 0. */
static inline void edt_down_block(const uint8_t *restrict cells,
                                  const unsigned char *restrict prev_bytes,
                                  unsigned char *restrict row_bytes)
{
	uint16_t prev[EDT_BLOCK], row[EDT_BLOCK];
	memcpy(prev, prev_bytes, sizeof prev);
	for (int i = 0; i < EDT_BLOCK; i++) {
		const uint16_t free_mask = (uint16_t)(0u - (cells[i] == GRID_FREE));
		row[i] = (uint16_t)((prev[i] + 1) & free_mask);
	}
	memcpy(row_bytes, row, sizeof row);
}

/* edt_columns(r, up): the end of phase 1 for one row (up: its distances to the
 * blocked cell above, 0 on a blocked cell): r->dn, the distance to the nearest
 * blocked cell below (row h blocked), and r->g = min(up, dn), the column distance,
 * with its clipped squares r->sq and each block's largest g. The loops over a block
 * have a fixed count, so that compilers vectorise them at -O2 (GCC 12's cheap cost
 * model takes only loops that need no scalar remainder). */
static void edt_columns(EdtRow *r, const unsigned char *restrict up)
{
	const int32_t w = r->w, full = w / EDT_BLOCK;
	uint16_t *restrict dn = r->dn, *restrict g = r->g, *restrict most = r->most;
	uint16_t *restrict sq = r->sq;
	for (int32_t blk = 0; blk < full; blk++) {
		const int32_t x0 = blk * EDT_BLOCK;
		most[blk] = edt_columns_block(up + 2 * x0, dn + x0, g + x0, sq + x0);
	}
	if (full * EDT_BLOCK < w) {
		uint16_t m = 0;
		for (int32_t x = full * EDT_BLOCK; x < w; x++) {
			uint16_t a;
			memcpy(&a, up + 2 * x, sizeof a);
			const uint16_t d = a ? (uint16_t)(dn[x] + 1) : 0;
			const uint16_t c = d < a ? d : a;
			dn[x] = d;
			g[x] = c;
			sq[x] = (uint16_t)(c < EDT_WINDOW_BOUND ? c * c : EDT_CLIP);
			m = c > m ? c : m;
		}
		most[full] = m;
	}
}

#if defined(__GNUC__) && defined(__x86_64__) && defined(__linux__)
#define EDT_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define EDT_CLONES
#endif

/* edt_row(r, up, out): one row: its column distances from up, its distances above
 * (edt_columns), then phase 2 into out (w values; up may lie in out's first half,
 * read before out is written, hence no restrict); r->bound is read as the row below's
 * and left as this row's. Returns the row's largest value. */
EDT_CLONES static int32_t edt_row(EdtRow *r, const unsigned char *up, int32_t *out)
{
	edt_columns(r, up);
	const int32_t w = r->w, blocks = r->blocks;
	const uint16_t *restrict g = r->g;
	const uint16_t *restrict sq = r->sq;
	int32_t *restrict bound = r->bound;
	int32_t largest = 0;
	int32_t run = -1, run_reach = 0; /* the first block of a run for the envelope */
	EdtCursor cursor = {.top = -1};
	/* the blocks' bounds first, in a loop of its own, where the square roots of
	 * successive blocks overlap (in the loop below each waited for a branch) */
	int32_t *restrict reach = r->reach;
	for (int32_t blk = 0; blk < blocks; blk++) {
		const int32_t c = edt_ceil_sqrt(bound[blk]) + 1;
		reach[blk] = r->most[blk] < c ? r->most[blk] : c;
	}
	reach[blocks] = EDT_WINDOW_BOUND + 1; /* past the end: ends a run */
	for (int32_t blk = 0; blk <= blocks; blk++) {
		const int32_t x0 = blk * EDT_BLOCK;
		const int32_t b = reach[blk];
		if (b > EDT_WINDOW_BOUND && blk < blocks) {
			run = run < 0 ? blk : run;
			run_reach = b - 1 > run_reach ? b - 1 : run_reach;
			continue;
		}
		if (run >= 0) {
			/* the blocks run .. blk - 1, by the envelope of the columns in reach */
			const int32_t r0 = run * EDT_BLOCK, r1 = x0 < w ? x0 : w;
			const int32_t a = r0 - run_reach > -1 ? r0 - run_reach : -1;
			const int32_t z = r1 - 1 + run_reach < w ? r1 - 1 + run_reach : w;
			edt_envelope_push(&r->v, &cursor, g, a, z);
			edt_envelope_sweep(&r->v, &cursor, r0, r1, out);
			for (int32_t k = run; k < blk; k++) {
				int32_t most = 0;
				const int32_t e = (k + 1) * EDT_BLOCK < w ? (k + 1) * EDT_BLOCK : w;
				for (int32_t x = k * EDT_BLOCK; x < e; x++)
					most = out[x] > most ? out[x] : most;
				bound[k] = most;
				largest = most > largest ? most : largest;
			}
			run = -1;
			run_reach = 0;
		}
		if (blk == blocks)
			break;
		uint16_t best[EDT_BLOCK];
		edt_window(sq, x0, b > 0 ? b - 1 : 0, best);
		uint16_t most = 0;
		for (int i = 0; i < EDT_BLOCK; i++)
			most = best[i] > most ? best[i] : most;
		bound[blk] = most;
		largest = most > largest ? most : largest;
		const int n = w - x0 < EDT_BLOCK ? w - x0 : EDT_BLOCK;
		if (n == EDT_BLOCK)
			for (int i = 0; i < EDT_BLOCK; i++)
				out[x0 + i] = best[i];
		else
			for (int i = 0; i < n; i++)
				out[x0 + i] = best[i];
	}
	return largest;
}

/* skeleton_edt_count(g, dist2, count, up): skeleton_edt, also counting the free cells
 * of each dist2 value d in count[d + 1] when count is not NULL (the counting sort's
 * histogram, gathered while the values are made rather than in a pass of its own).
 * up is scratch of 2 w h bytes, or NULL to use dist2's own memory (see below). */
static int32_t skeleton_edt_count(const Grid *gr, int32_t *dist2, int32_t *count, uint16_t *up)
{
	const int32_t w = gr->w, h = gr->h;
	assert(w >= 0 && h >= 0 && w <= SKELETON_MAX_SIDE && h <= SKELETON_MAX_SIDE);
	int32_t largest = 0;
	if (w == 0 || h == 0)
		return largest;
	/* Phase 1's distances to the blocked cell above, 2 bytes a cell, are kept either
	 * in up or in the first half of dist2: row k's at byte 2 w k, read (in row order
	 * from the bottom) before the output of row y, which covers rows 2 y and 2 y + 1,
	 * is written, and those are at or past y, so they have been read. No scratch the
	 * size of the grid, hence no page faults for it on every call (32 MB at 4096).
	 * They are stored and read through memcpy, so that no int32_t is accessed as a
	 * uint16_t (the compilers turn the copies into plain vector loads and stores). */
	unsigned char *above = up ? (unsigned char *)up : (unsigned char *)dist2;
	EdtRow r = {.w = w, .blocks = (w + EDT_BLOCK - 1) / EDT_BLOCK};
	const size_t wb = (size_t)r.blocks * EDT_BLOCK;
	uint16_t *gmem = util_alloc(wb + 2, sizeof *gmem);
	uint16_t *sqmem = util_alloc(wb + 2 * EDT_PAD, sizeof *sqmem);
	memset(gmem, 0, (wb + 2) * sizeof *gmem);
	memset(sqmem, 0, (wb + 2 * EDT_PAD) * sizeof *sqmem);
	r.g = gmem + 1;
	r.sq = sqmem + EDT_PAD;
	r.dn = util_alloc(wb, sizeof *r.dn);
	memset(r.dn, 0, wb * sizeof *r.dn); /* row h is blocked */
	r.bound = util_alloc((size_t)r.blocks, sizeof *r.bound);
	memset(r.bound, 0, (size_t)r.blocks * sizeof *r.bound);
	r.most = util_alloc((size_t)r.blocks, sizeof *r.most);
	r.reach = util_alloc((size_t)r.blocks + 1, sizeof *r.reach);
	const size_t n = (size_t)w + 4;
	r.v.u = util_alloc(n, sizeof *r.v.u);
	r.v.G = util_alloc(n, sizeof *r.v.G);
	r.v.L = util_alloc(n, sizeof *r.v.L);
	r.v.F = util_alloc(n, sizeof *r.v.F);
	r.v.D = util_alloc(n, sizeof *r.v.D);
	/* Phase 1 down the grid, row by row so that the loops run along memory: up is the
	 * distance along the column to the nearest blocked cell above (row -1 is
	 * blocked), 0 on a blocked cell. Blocks of a fixed count, as in edt_columns. */
	const int32_t w16 = w - w % EDT_BLOCK;
	for (int32_t y = 0; y < h; y++) {
		const uint8_t *restrict c = gr->cells + (size_t)y * w;
		unsigned char *restrict row = above + 2 * (size_t)y * w;
		const unsigned char *restrict prev =
		    y > 0 ? above + 2 * (size_t)(y - 1) * w : (const unsigned char *)r.dn;
		for (int32_t x0 = 0; x0 < w16; x0 += EDT_BLOCK)
			edt_down_block(c + x0, prev + 2 * x0, row + 2 * x0);
		for (int32_t x = w16; x < w; x++) {
			uint16_t a;
			memcpy(&a, prev + 2 * x, sizeof a);
			a = c[x] == GRID_FREE ? (uint16_t)(a + 1) : 0;
			memcpy(row + 2 * x, &a, sizeof a);
		}
	}
	/* Then up the grid, row by row: the column distances of a row (edt_columns), made
	 * and used at once by the row pass (no second pass over the grid). */
	for (int32_t y = h - 1; y >= 0; y--) {
		int32_t *out = dist2 + (size_t)y * w;
		const int32_t most = edt_row(&r, above + 2 * (size_t)y * w, out);
		largest = most > largest ? most : largest;
		if (count)
			for (int32_t x = 0; x < w; x++)
				count[out[x] + 1]++;
	}
	if (count)
		count[1] = 0; /* the blocked cells, counted at 0 */
	free(r.v.u);
	free(r.v.G);
	free(r.v.L);
	free(r.v.F);
	free(r.v.D);
	free(r.bound);
	free(r.most);
	free(r.reach);
	free(r.dn);
	free(gmem);
	free(sqmem);
	return largest;
}

int32_t skeleton_edt(const Grid *g, int32_t *dist2)
{
	return skeleton_edt_count(g, dist2, NULL, NULL);
}

/* skeleton_dist2_bound(w, h): no free cell is farther than this (squared) from the
 * nearest blocked cell, as the ring outside the grid is blocked: in the shorter axis
 * some border is at most (side + 1) / 2 away. */
static size_t skeleton_dist2_bound(int32_t w, int32_t h)
{
	size_t half = (size_t)((w < h ? w : h) + 2) / 2;
	return half * half;
}

/* ---------------------------------------------------------------- simple points */

/* The 8 neighbours in counter-clockwise order from east; even indices are the 4
 * edge neighbours. Bit i of a neighbourhood mask is neighbour i being in the set. */
static const int8_t SKELETON_DX[8] = {1, 1, 0, -1, -1, -1, 0, 1};
static const int8_t SKELETON_DY[8] = {0, 1, 1, 1, 0, -1, -1, -1};

/* skeleton_is_simple_mask(m): Bertrand's T4(p, X) = 1 and T8(p, complement) = 1 for
 * the neighbourhood m, straight from the definitions by a tiny union-find. In the ring
 * of 8 neighbours two cells are 4-adjacent exactly when consecutive; two background
 * cells are 8-adjacent when consecutive or when both are edge neighbours two apart. */
static bool skeleton_is_simple_mask(unsigned m)
{
	int parent[8];
	for (int i = 0; i < 8; i++)
		parent[i] = i;
	for (int i = 0; i < 8; i++) {
		int j = (i + 1) % 8, k = (i + 2) % 8;
		bool fi = (m >> i) & 1, fj = (m >> j) & 1, fk = (m >> k) & 1;
		int a, b;
		if (fi == fj) {
			for (a = i; parent[a] != a; a = parent[a])
				;
			for (b = j; parent[b] != b; b = parent[b])
				;
			parent[a] = b;
		}
		if (!fi && !fk && i % 2 == 0) {
			for (a = i; parent[a] != a; a = parent[a])
				;
			for (b = k; parent[b] != b; b = parent[b])
				;
			parent[a] = b;
		}
	}
	int t4 = 0, t8bar = 0;
	bool seen[8] = {false};
	for (int i = 0; i < 8; i++) {
		int r;
		for (r = i; parent[r] != r; r = parent[r])
			;
		bool fg = (m >> i) & 1;
		/* a foreground component counts for T4 only when it holds an edge neighbour */
		if (fg && i % 2 == 0 && !seen[r]) {
			seen[r] = true;
			t4++;
		}
		if (!fg && !seen[r]) {
			seen[r] = true;
			t8bar++;
		}
	}
	return t4 == 1 && t8bar == 1;
}

/* What one deletion test needs from the 8-neighbourhood mask (one table load). */
enum {
	THIN_KEEP = 0,   /* not simple: deleting would change the topology */
	THIN_DELETE = 1, /* simple, and not one edge neighbour: deletable */
	THIN_RIDGE = 2   /* simple with exactly one edge neighbour: a ridge end or not */
};

/* skeleton_build_kind_table(kind): THIN_* of every mask (see the Thinner). */
static void skeleton_build_kind_table(uint8_t kind[256])
{
	for (unsigned m = 0; m < 256; m++) {
		unsigned edge = (m & 1) + ((m >> 2) & 1) + ((m >> 4) & 1) + ((m >> 6) & 1);
		kind[m] = !skeleton_is_simple_mask(m) ? THIN_KEEP : edge == 1 ? THIN_RIDGE : THIN_DELETE;
	}
}

/* ---------------------------------------------------------------- thinning */

enum {
	SKELETON_IN = 1,      /* still in the set */
	SKELETON_KEPT = 2,    /* visited, and still in the set (kept, or not yet deleted
	                       * by a cascade): the cells a deletion tries again */
	SKELETON_STACKED = 4, /* on the re-try stack */
	SKELETON_RECHECK = 8  /* next to a pruned cell: to test again after pruning */
};

/* The thinning works on a copy of the grid padded by one background cell on every
 * side, so that a neighbourhood never needs a bounds check (and 3 bytes more at the
 * end, for the last row's 4-byte loads; see thinner_raster).
 *
 * A neighbourhood is read as its "raster mask" of THIN_RASTER bits: the rows below and
 * above as a 4-byte load each, gathered to 8 bits by one multiplication (thinner_rows;
 * the fourth cell of each, two east, is not a neighbour and the tables ignore it),
 * then the west and east cells' state, 2 bits each (only bit 0, SKELETON_IN, counts,
 * so the visits take the bytes as they are: SKELETON_IN and SKELETON_KEPT, below 4).
 * The middle row is read by bytes since the visit before this one usually stored the
 * west cell: a 4-byte load over a byte just stored waits for the store to reach the
 * cache (no store forwarding), and that stall was a third of the visits' time (perf
 * annotate). Which bit is which cell depends on the byte order, so the tables over
 * the mask are built by running thinner_raster itself on probes
 * (thinner_init_tables). */
#define THIN_RASTER 12

typedef struct Thinner {
	int32_t w, h, pw; /* grid size, padded width w + 2 */
	uint8_t *state;   /* (w + 2) * (h + 2) + 3 SKELETON_* bits */
	int32_t off[8];   /* padded index offsets of the 8 neighbours */
	int32_t *stack;   /* padded indices to try again */
	int32_t top;
	const int32_t *dist2;             /* w * h, unpadded */
	uint8_t kind[1u << THIN_RASTER];  /* THIN_* of each raster mask */
	uint8_t ring[1u << THIN_RASTER];  /* the neighbourhood mask (bit i: neighbour i) */
	int32_t doff[8];      /* unpadded index offsets of the 8 neighbours (in dist2) */
	uint64_t row_mul;     /* pi / pw as (pi * row_mul) >> row_shift (thinner_row) */
	unsigned row_shift;
} Thinner;

/* thinner_row(t, pi): pi / pw, the padded row, with no division (Granlund and
 * Montgomery, "Division by invariant integers using multiplication", PLDI 1994): with
 * l = ceil(log2 pw) and row_mul = ceil(2^(31 + l) / pw), the product's top bits are
 * the quotient for every pi < 2^31, and pi < (30002)^2 < 2^31; the product < 2^63. */
static inline int32_t thinner_row(const Thinner *t, int32_t pi)
{
	return (int32_t)(((uint64_t)pi * t->row_mul) >> t->row_shift);
}

/* thinner_unpadded(t, pi): the index in dist2 of the padded index pi: with pi =
 * (y + 1) pw + x + 1, that is y w + x = pi - pw - 1 - 2 y. */
static inline int32_t thinner_unpadded(const Thinner *t, int32_t pi)
{
	return pi - t->pw - 1 - 2 * (thinner_row(t, pi) - 1);
}

/* thinner_load4(p): the 4 bytes at p, in the machine's byte order. */
static inline uint32_t thinner_load4(const uint8_t *p)
{
	uint32_t v;
	memcpy(&v, p, sizeof v);
	return v;
}

/* THIN_ONES: a byte of 1 in each lane of a 64-bit word; THIN_LOW7: 0x7f in each. */
#define THIN_ONES 0x0101010101010101u
#define THIN_LOW7 0x7f7f7f7f7f7f7f7fu

/* thinner_rows(below, above): bit 0 of each byte of the two 4-byte loads, as 8 bits.
 * The bits sit at 8 i in a 64-bit word; times 0x0102040810204080 (the terms 2^(7 j + 7))
 * puts bit 8 i at 56 + i when i + j = 7, and no two of the 64 terms fall on one bit
 * (8 i + 7 j is unique for i, j < 8), so there is no carry. */
static inline unsigned thinner_rows(uint32_t below, uint32_t above)
{
	const uint64_t v = ((uint64_t)above << 32 | below) & THIN_ONES;
	return (unsigned)((v * 0x0102040810204080u) >> 56);
}

/* thinner_raster(st, pi, pw): the raster mask of pi's neighbours in the set (see the
 * Thinner). */
static inline unsigned thinner_raster(const uint8_t *st, int32_t pi, int32_t pw)
{
	return thinner_rows(thinner_load4(st + pi - pw - 1), thinner_load4(st + pi + pw - 1)) |
	       (unsigned)(st[pi - 1] & SKELETON_IN) << 8 | (unsigned)(st[pi + 1] & SKELETON_IN) << 10;
}

/* thinner_init_tables(t): the tables over the raster mask, found by reading probes
 * (one neighbour at a time set in a 3 x 3 patch), and thinner_row's constants. */
static void thinner_init_tables(Thinner *t)
{
	unsigned l = 0;
	while ((1u << l) < (unsigned)t->pw)
		l++;
	t->row_shift = 31 + l;
	t->row_mul = ((1ull << t->row_shift) + (uint64_t)t->pw - 1) / (uint64_t)t->pw;
	uint8_t kind8[256];
	skeleton_build_kind_table(kind8);
	uint8_t patch[3 * 5 + 4];
	unsigned bit_of[8];
	for (int i = 0; i < 8; i++) {
		memset(patch, 0, sizeof patch);
		patch[6 + SKELETON_DX[i] + 5 * SKELETON_DY[i]] = SKELETON_IN;
		bit_of[i] = thinner_raster(patch, 6, 5);
		assert(bit_of[i] != 0 && (bit_of[i] & (bit_of[i] - 1)) == 0);
	}
	for (unsigned r = 0; r < (1u << THIN_RASTER); r++) {
		unsigned m = 0;
		for (int i = 0; i < 8; i++)
			m |= (r & bit_of[i]) ? 1u << i : 0;
		t->ring[r] = (uint8_t)m;
		t->kind[r] = kind8[m];
	}
}

/* thinner_lowest_bit(m): the index of m's lowest set bit, m a nonzero byte. */
static inline int thinner_lowest_bit(unsigned m)
{
	static const int8_t lowest[16] = {-1, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};
	return (m & 15u) ? lowest[m & 15u] : 4 + lowest[(m >> 4) & 15u];
}

/* thinner_ridge_end(t, pi, m): pi, simple with one edge neighbour (neighbourhood
 * mask m), is a ridge end. A ridge end has exactly one 4-neighbour in the set and no
 * 8-neighbour in the set farther from the obstacles: it is the tip of a branch of the
 * medial axis (the distance map has a local maximum there along the branch). Without
 * the second condition every cell of the grassfire front that happens to lose its side
 * neighbours first would be kept as an end, and grow a spur; with it, a branch whose
 * distance rises from its tip (toward a convex corner of the space) burns back to its
 * junction, as Blum's branches into corners carry no choice of route. The padded row
 * comes by a multiplication and a shift (thinner_row), the neighbours as offsets. */
static bool thinner_ridge_end(const Thinner *t, int32_t pi, unsigned m)
{
	const int32_t *d2 = t->dist2 + thinner_unpadded(t, pi);
	const int32_t d = d2[0];
	for (; m != 0; m &= m - 1)
		if (d2[t->doff[thinner_lowest_bit(m)]] > d)
			return false;
	return true;
}

/* thinner_deletable(t, pi): pi is simple and not a ridge end. */
static inline bool thinner_deletable(const Thinner *t, int32_t pi)
{
	unsigned r = thinner_raster(t->state, pi, t->pw);
	uint8_t k = t->kind[r];
	return k == THIN_DELETE || (k == THIN_RIDGE && !thinner_ridge_end(t, pi, t->ring[r]));
}

/* thinner_push_again(t, pi): stacks pi's neighbours that are in the set and visited
 * (to be tried again now that pi is gone) and not stacked already. */
static inline void thinner_push_again(Thinner *t, int32_t pi)
{
	for (int i = 0; i < 8; i++) {
		int32_t qi = pi + t->off[i];
		uint8_t st = t->state[qi];
		if ((st & (SKELETON_KEPT | SKELETON_STACKED)) == SKELETON_KEPT) {
			t->state[qi] = st | SKELETON_STACKED;
			t->stack[t->top++] = qi;
		}
	}
}

/* thinner_delete_more(t, pi, top): deletes pi, then every visited cell that its
 * deletion (or a later one) makes deletable, with the re-try stack holding top cells
 * already. */
static void thinner_delete_more(Thinner *t, int32_t pi, int32_t top)
{
	t->state[pi] &= (uint8_t)~(SKELETON_IN | SKELETON_KEPT);
	t->top = top;
	for (;;) {
		thinner_push_again(t, pi);
		/* find the next stacked cell that is deletable now */
		for (;;) {
			if (t->top == 0)
				return;
			pi = t->stack[--t->top];
			t->state[pi] &= (uint8_t)~SKELETON_STACKED;
			if (thinner_deletable(t, pi))
				break;
		}
		t->state[pi] &= (uint8_t)~(SKELETON_IN | SKELETON_KEPT);
	}
}

/* thinner_delete_from(t, pi): deletes pi and whatever that makes deletable. */
static void thinner_delete_from(Thinner *t, int32_t pi) { thinner_delete_more(t, pi, 0); }

/* thinner_retry(t, pi): after pi's deletion in its visit, tries again its visited
 * neighbours in the set (none is stacked: the stack is empty between visits), and
 * deletes what that makes deletable (thinner_delete_more). */
static void thinner_retry(Thinner *t, int32_t pi)
{
	uint8_t *st = t->state;
	t->top = 0;
	thinner_push_again(t, pi);
	for (;;) {
		if (t->top == 0)
			return;
		int32_t qi = t->stack[--t->top];
		st[qi] &= (uint8_t)~SKELETON_STACKED;
		if (thinner_deletable(t, qi)) {
			/* a cascade; the stack as it is now is taken over */
			int32_t saved = t->top;
			thinner_delete_more(t, qi, saved);
			return;
		}
	}
}

/* The visits of a grid whose state outgrows THIN_PREFETCH_BYTES prefetch the rows
 * below and above the cell THIN_AHEAD visits on: each distance level sweeps the whole
 * grid, and at 4096 a side (17 MB of state) most of a sparse level's visits missed the
 * cache; there it took 10-25% off the visits of rooms and rects, at 1024 it added 10%
 * (the loads hit the cache anyway, the prefetch is instructions). */
#define THIN_AHEAD 16
#define THIN_PREFETCH_BYTES (8u << 20)

/* thinner_visits(t, order, nfree, prefetch), for thinner_visit_all(t, order, nfree): the
 * visits of the cells order[0 .. nfree) in
 * that order (the distance order): each is marked kept (SKELETON_KEPT) or, when
 * deletable, deleted (thinner_retry then tries its visited neighbours again). The same as thinner_deletable
 * and thinner_delete_from for each cell, with the neighbourhood read once for the
 * deletion test and for the test of a re-try: this runs for every free cell. The cell
 * itself needs no load: unvisited, it is in the set and on no stack. Whether any
 * neighbour is to be tried again (SKELETON_KEPT) is one test on the same loads (the
 * cells two east, in the 4-byte loads, may set it in vain: thinner_retry finds no
 * neighbour then), so the usual deletion, with none, costs no loop over the
 * neighbours and no mask. A branch on the kind, not a select: the
 * next visit usually reads this cell, and a select would chain each visit's loads to
 * the last one's table load (tried: 10% slower on the maze, where the branch goes
 * either way). Every visit is a real one: on the benchmark grids no free cell is
 * interior (all 8 neighbours in the set) when its turn comes, as the distance order
 * makes each cell part of the front then; so a border queue would save no visit, and
 * was not built. */
static inline void thinner_visits(Thinner *t, const int32_t *order, int32_t nfree, bool prefetch)
{
	uint8_t *const st = t->state;
	const int32_t pw = t->pw;
	const uint8_t *const kind = t->kind, *const ring = t->ring;
	for (int32_t k = 0; k < nfree; k++) {
		const int32_t pi = order[k];
#if defined(__GNUC__)
		if (prefetch && k + THIN_AHEAD < nfree) {
			__builtin_prefetch(st + order[k + THIN_AHEAD] - pw, 1);
			__builtin_prefetch(st + order[k + THIN_AHEAD] + pw, 1);
		}
#else
		(void)prefetch;
#endif
		const uint8_t *p = st + pi;
		const uint64_t rows = (uint64_t)thinner_load4(p + pw - 1) << 32 | thinner_load4(p - pw - 1);
		const unsigned we = p[-1] | (unsigned)p[1] << 2; /* west, east: 2 bits each */
		const unsigned r =
		    (unsigned)(((rows & THIN_ONES) * 0x0102040810204080u) >> 56) | we << 8;
		const uint8_t kd = kind[r];
		if (kd == THIN_KEEP || (kd == THIN_RIDGE && thinner_ridge_end(t, pi, ring[r]))) {
			st[pi] = SKELETON_IN | SKELETON_KEPT;
			continue;
		}
		st[pi] = 0;
		if (((rows & (THIN_ONES * SKELETON_KEPT)) | (we & (SKELETON_KEPT * 5u))) != 0)
			thinner_retry(t, pi);
	}
}

#if defined(__GNUC__)
/* a function of its own: inlined into skeleton_compute (GCC 12 -O2), it kept its
 * loop index and count on the stack, a chain of stores and loads through each visit */
__attribute__((noinline))
#endif
static void thinner_visit_all(Thinner *t, const int32_t *order, int32_t nfree)
{
	const size_t bytes = (size_t)t->pw * (size_t)(t->h + 2);
	if (bytes > THIN_PREFETCH_BYTES)
		thinner_visits(t, order, nfree, true);
	else
		thinner_visits(t, order, nfree, false);
}

/* ---------------------------------------------------------------- pruning */

/* thinner_degree(t, pi): the 4-neighbours of pi in the set. */
static inline int thinner_degree(const Thinner *t, int32_t pi)
{
	const uint8_t *st = t->state;
	return (st[pi + 1] & SKELETON_IN) + (st[pi - 1] & SKELETON_IN) + (st[pi + t->pw] & SKELETON_IN) +
	       (st[pi - t->pw] & SKELETON_IN);
}

/* thinner_mask4(st, pi, pw): pi's 4-neighbours in the set, bit k the k-th of east,
 * north (+pw), west and south: the ring's even neighbours in its order. */
static inline unsigned thinner_mask4(const uint8_t *st, int32_t pi, int32_t pw)
{
	return (unsigned)(st[pi + 1] & SKELETON_IN) | (unsigned)(st[pi + pw] & SKELETON_IN) << 1 |
	       (unsigned)(st[pi - 1] & SKELETON_IN) << 2 | (unsigned)(st[pi - pw] & SKELETON_IN) << 3;
}

/* thinner_sort(a, n, tmp): sorts the padded indices a[0 .. n) (below 2^31) in
 * increasing order, with tmp as long as a: a radix sort, three passes of 11 bits (the
 * maze's 6 700 cells to test again after pruning took glibc's qsort a quarter of the
 * pruning's time); a short list by insertion. */
static void thinner_sort(int32_t *a, int32_t n, int32_t *tmp)
{
	if (n < 64) {
		for (int32_t i = 1; i < n; i++) {
			int32_t v = a[i], j = i;
			for (; j > 0 && a[j - 1] > v; j--)
				a[j] = a[j - 1];
			a[j] = v;
		}
		return;
	}
	int32_t count[3][2049];
	memset(count, 0, sizeof count);
	for (int32_t i = 0; i < n; i++)
		for (int d = 0; d < 3; d++)
			count[d][((uint32_t)a[i] >> (11 * d) & 2047u) + 1]++;
	int32_t *from = a, *to = tmp;
	for (int d = 0; d < 3; d++) {
		for (int b = 0; b < 2048; b++)
			count[d][b + 1] += count[d][b];
		for (int32_t i = 0; i < n; i++)
			to[count[d][(uint32_t)from[i] >> (11 * d) & 2047u]++] = from[i];
		int32_t *swap = from;
		from = to;
		to = swap;
	}
	/* three passes: the sorted list is in tmp */
	memcpy(a, from, (size_t)n * sizeof *a);
}

/* thinner_load8(p): the 8 bytes at p, in the machine's byte order. */
static inline uint64_t thinner_load8(const uint8_t *p)
{
	uint64_t v;
	memcpy(&v, p, sizeof v);
	return v;
}

/* thinner_walk(t, end, remove, nremove, longest): walks from the end point end to a
 * junction; when the branch is a spur (see the header comment), its cells are added
 * to remove[0 .. nremove); returns the new count. The next cell is the first
 * 4-neighbour in the set, in the ring's order, other than the way back: found by masks
 * of the 4-neighbours, with no branch on the way the walk turns, and the next cell's
 * mask gives its degree and its way on. The cells are written after remove[nremove - 1]
 * as the walk goes, and kept when it finds a spur (a walk's cells are no other walk's:
 * a branch has one end point). longest: see thinner_prune. */
static inline int32_t thinner_walk(const Thinner *t, int32_t end, int32_t *remove, int32_t nremove,
                                   double longest)
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
			double r = sqrt((double)t->dist2[thinner_unpadded(t, next)]);
			return length > SKELETON_SPUR_FACTOR * r + SKELETON_SPUR_SLACK ? nremove
			                                                               : nremove + length;
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
 * scratch is an array as long as the grid. Spurs are found on the set as thinned,
 * then removed. The end points are found by a scan of the set in raster order, eight
 * cells a word: each lane holds a cell's bit 0, the sum of four neighbours' lanes its
 * degree (at most 4: no carry), and a lane of degree ^ 1 is zero exactly where
 * ((lane & 0x7f) + 0x7f) | lane has no top bit; most words hold no end and cost no
 * branch of their own. Each end is walked when the scan finds it, while its rows are
 * in the cache (walked after the whole scan, they were not, and the walks on the maze
 * cost as much as the scan). maxd is the largest dist2: no junction is farther from the
 * obstacles, so a branch longer than SKELETON_SPUR_FACTOR * sqrt(maxd) +
 * SKELETON_SPUR_SLACK cells is no spur whatever its junction, and its walk stops there
 * (the same test, monotone in the clearance; on the 1024 maze, whose dead ends are
 * long corridors, it saves most of the walking). */
static int32_t thinner_prune(Thinner *t, int32_t *scratch, int32_t maxd)
{
	const double longest = SKELETON_SPUR_FACTOR * sqrt((double)maxd) + SKELETON_SPUR_SLACK;
	/* cells to remove are collected in the stack array, as long as the grid */
	int32_t nremove = 0;
	int32_t *remove = t->stack;
	const uint8_t *st = t->state;
	const int32_t w = t->w, pw = t->pw;
	for (int32_t y = 0; y < t->h; y++) {
		const int32_t row = (y + 1) * pw + 1;
		int32_t x = 0;
		for (; x + 8 <= w; x += 8) {
			const uint8_t *p = st + row + x;
			const uint64_t in = thinner_load8(p) & THIN_ONES;
			if (in == 0)
				continue; /* most words of a sparse skeleton: rooms, rects */
			const uint64_t deg = (thinner_load8(p - 1) & THIN_ONES) +
			                     (thinner_load8(p + 1) & THIN_ONES) +
			                     (thinner_load8(p - pw) & THIN_ONES) +
			                     (thinner_load8(p + pw) & THIN_ONES);
			const uint64_t e = deg ^ THIN_ONES;
			const uint64_t one = ~(((e & THIN_LOW7) + THIN_LOW7) | e) & (in << 7);
			if (one == 0)
				continue;
			for (int32_t j = 0; j < 8; j++)
				if ((p[j] & SKELETON_IN) && thinner_degree(t, row + x + j) == 1)
					nremove = thinner_walk(t, row + x + j, remove, nremove, longest);
		}
		for (; x < w; x++)
			if ((st[row + x] & SKELETON_IN) && thinner_degree(t, row + x) == 1)
				nremove = thinner_walk(t, row + x, remove, nremove, longest);
	}
	for (int32_t k = 0; k < nremove; k++)
		t->state[remove[k]] &= (uint8_t)~(SKELETON_IN | SKELETON_KEPT);
	/* only a cell next to a removed one has a new neighbourhood (every other was
	 * left not deletable by the thinning), so only those are tested again: listed in
	 * scratch and sorted, so that they are tested in raster order as
	 * a test of every cell in raster order would (and equals: a deletion here
	 * retries its neighbours through the stack) */
	int32_t nrecheck = 0;
	for (int32_t k = 0; k < nremove; k++)
		for (int i = 0; i < 8; i++) {
			int32_t qi = remove[k] + t->off[i];
			if ((t->state[qi] & (SKELETON_IN | SKELETON_RECHECK)) == SKELETON_IN) {
				t->state[qi] |= SKELETON_RECHECK;
				scratch[nrecheck++] = qi;
			}
		}
	thinner_sort(scratch, nrecheck, remove); /* remove is no longer needed */
	for (int32_t k = 0; k < nrecheck; k++) {
		int32_t pi = scratch[k];
		t->state[pi] &= (uint8_t)~SKELETON_RECHECK;
		if ((t->state[pi] & SKELETON_IN) && thinner_deletable(t, pi))
			thinner_delete_from(t, pi);
	}
	return nremove;
}

/* ---------------------------------------------------------------- the skeleton */

/* The working space of skeleton_compute, kept between calls so that computing the
 * skeleton of a grid of the same size again touches no new memory. */
struct SkeletonWork {
	size_t cells;   /* the grid size it was made for, w * h */
	uint8_t *state; /* (w + 2) * (h + 2) */
	int32_t *stack; /* w * h */
	int32_t *order; /* w * h */
	int32_t *start; /* start_cap */
	size_t start_cap;
};

void skeleton_init(Skeleton *s)
{
	*s = (Skeleton){0};
}

static void skeleton_free_work(struct SkeletonWork *wk)
{
	if (!wk)
		return;
	free(wk->state);
	free(wk->stack);
	free(wk->order);
	free(wk->start);
	free(wk);
}

void skeleton_free(Skeleton *s)
{
	free(s->dist2);
	free(s->on);
	skeleton_free_work(s->work);
	*s = (Skeleton){0};
}

void skeleton_compute(Skeleton *s, const Grid *g)
{
	const int32_t w = g->w, h = g->h;
	const size_t n = (size_t)w * (size_t)h;
	const size_t pn = (size_t)(w + 2) * (size_t)(h + 2);
	if (!s->dist2 || s->w != w || s->h != h) {
		skeleton_free(s);
		s->dist2 = util_alloc(n, sizeof *s->dist2);
		s->on = util_alloc(n, 1);
		s->work = util_alloc(1, sizeof *s->work);
		s->work->cells = n;
		s->work->state = util_alloc(pn + 3, 1); /* + 3: thinner_raster's last load */
		s->work->stack = util_alloc(n, sizeof *s->work->stack);
		s->work->order = util_alloc(n, sizeof *s->work->order);
	}
	s->w = w;
	s->h = h;
	s->count = s->pruned = 0;
	if (n == 0)
		return;
	struct SkeletonWork *wk = s->work;
	/* the histogram is all zero between calls: set up zeroed, cleared after use */
	if (!wk->start) {
		wk->start_cap = skeleton_dist2_bound(w, h) + 2;
		wk->start = util_alloc(wk->start_cap, sizeof *wk->start);
	}
	int32_t *start = wk->start, *order = wk->order;
	/* the stack is scratch until the thinning: the transform's column distances
	 * (2 bytes a cell of its 4; malloc'd memory takes the type it is written as) */
	const int32_t maxd = skeleton_edt_count(g, s->dist2, start, (uint16_t *)(void *)wk->stack);
	assert((size_t)maxd + 2 <= wk->start_cap);

	Thinner t = {.w = w, .h = h, .pw = w + 2, .dist2 = s->dist2};
	t.state = wk->state;
	t.stack = wk->stack;
	for (int i = 0; i < 8; i++) {
		t.off[i] = SKELETON_DX[i] + SKELETON_DY[i] * t.pw;
		t.doff[i] = SKELETON_DX[i] + SKELETON_DY[i] * w;
	}
	thinner_init_tables(&t);

	/* the padded state: the free cells in the set, the ring around the grid not */
	memset(t.state, 0, (size_t)t.pw);
	memset(t.state + (size_t)(h + 1) * t.pw, 0, (size_t)t.pw + 3);
	for (int32_t y = 0; y < h; y++) {
		const uint8_t *restrict c = g->cells + (size_t)y * w;
		uint8_t *restrict st = t.state + (size_t)(y + 1) * t.pw;
		st[0] = st[w + 1] = 0;
		int32_t x = 0;
		/* 8 cells at a time: a lane of c ^ GRID_FREE is zero exactly where
		 * ((lane & 0x7f) + 0x7f) | lane has no top bit */
		for (; x + 8 <= w; x += 8) {
			const uint64_t e = thinner_load8(c + x) ^ (THIN_ONES * GRID_FREE);
			const uint64_t v = ((~(((e & THIN_LOW7) + THIN_LOW7) | e) >> 7) & THIN_ONES) * SKELETON_IN;
			memcpy(st + x + 1, &v, sizeof v);
		}
		for (; x < w; x++)
			st[x + 1] = c[x] == GRID_FREE ? SKELETON_IN : 0;
	}
	/* counting sort of the cells by dist2, ties by index (the histogram of the free
	 * cells came with the distance transform): the blocked cells, dist2 0, come first,
	 * so that the loop needs no branch and no test, and the free ones follow in the
	 * distance order. Four cells at a time: each bucket's next place is loaded for all
	 * four before any is stored, and a cell's place counts the cells before it in the
	 * four with the same key; so the chain through start[], a store forwarded to the
	 * next load, is one link a group rather than one a cell (it was most of the
	 * sort's time). */
	int32_t nfree = 0;
	for (int32_t d = 1; d <= maxd; d++)
		nfree += start[d + 1];
	const int32_t nblocked = (int32_t)n - nfree;
	start[1] = nblocked;
	for (int32_t d = 0; d <= maxd; d++)
		start[d + 1] += start[d];
	for (int32_t y = 0; y < h; y++) {
		const int32_t *restrict d2 = s->dist2 + (size_t)y * w;
		const int32_t base = (y + 1) * t.pw + 1;
		int32_t x = 0;
		for (; x + 4 <= w; x += 4) {
			const int32_t k0 = d2[x], k1 = d2[x + 1], k2 = d2[x + 2], k3 = d2[x + 3];
			const int32_t p0 = start[k0];
			const int32_t p1 = start[k1] + (k1 == k0);
			const int32_t p2 = start[k2] + (k2 == k0) + (k2 == k1);
			const int32_t p3 = start[k3] + (k3 == k0) + (k3 == k1) + (k3 == k2);
			start[k0] = p0 + 1;
			start[k1] = p1 + 1;
			start[k2] = p2 + 1;
			start[k3] = p3 + 1;
			order[p0] = base + x;
			order[p1] = base + x + 1;
			order[p2] = base + x + 2;
			order[p3] = base + x + 3;
		}
		for (; x < w; x++)
			order[start[d2[x]]++] = base + x;
	}
	memset(start, 0, ((size_t)maxd + 2) * sizeof *start);

	thinner_visit_all(&t, order + nblocked, nfree);
	s->pruned = thinner_prune(&t, order, maxd);

	/* the output, 8 cells at a time: bit 0 of each state byte, and their count */
	int32_t count = 0;
	const uint64_t ones = 0x0101010101010101u;
	for (int32_t y = 0; y < h; y++) {
		const uint8_t *st = t.state + (size_t)(y + 1) * t.pw + 1;
		uint8_t *on = s->on + (size_t)y * w;
		int32_t x = 0;
		for (; x + 8 <= w; x += 8) {
			uint64_t v;
			memcpy(&v, st + x, sizeof v);
			v &= ones * SKELETON_IN;
			memcpy(on + x, &v, sizeof v);
			count += (int32_t)((v * ones) >> 56);
		}
		for (; x < w; x++) {
			on[x] = st[x] & SKELETON_IN;
			count += on[x];
		}
	}
	s->count = count;
}

int skeleton_degree(const Skeleton *s, int32_t x, int32_t y)
{
	return skeleton_on(s, x + 1, y) + skeleton_on(s, x - 1, y) + skeleton_on(s, x, y + 1) +
	       skeleton_on(s, x, y - 1);
}

double skeleton_clearance(const Skeleton *s, int32_t x, int32_t y)
{
	return sqrt((double)s->dist2[(size_t)y * s->w + x]);
}

/* skeleton_is_pinwheel(s, x, y): the 2x2 block with lower-left cell (x, y) is all
 * skeleton and each of its cells has a skeleton edge neighbour outside the block: the
 * one 2x2 block thinning cannot remove, since each cell is then a branch's root. */
static bool skeleton_is_pinwheel(const Skeleton *s, int32_t x, int32_t y)
{
	return (skeleton_on(s, x - 1, y) || skeleton_on(s, x, y - 1)) &&
	       (skeleton_on(s, x + 2, y) || skeleton_on(s, x + 1, y - 1)) &&
	       (skeleton_on(s, x - 1, y + 1) || skeleton_on(s, x, y + 2)) &&
	       (skeleton_on(s, x + 2, y + 1) || skeleton_on(s, x + 1, y + 2));
}

bool skeleton_validate(const Skeleton *s, const Grid *g)
{
	if (s->w != g->w || s->h != g->h)
		return false;
	int32_t count = 0;
	for (int32_t y = 0; y < s->h; y++)
		for (int32_t x = 0; x < s->w; x++) {
			size_t i = (size_t)y * s->w + x;
			bool free_cell = g->cells[i] == GRID_FREE;
			if ((s->dist2[i] == 0) == free_cell)
				return false;
			if (s->on[i] && !free_cell)
				return false;
			count += s->on[i] != 0;
			if (skeleton_on(s, x, y) && skeleton_on(s, x + 1, y) &&
			    skeleton_on(s, x, y + 1) && skeleton_on(s, x + 1, y + 1) &&
			    !skeleton_is_pinwheel(s, x, y))
				return false;
		}
	return count == s->count;
}

void skeleton_dump(const Skeleton *s, const Grid *g, FILE *out)
{
	int32_t junctions = 0, ends = 0;
	for (int32_t y = s->h - 1; y >= 0; y--) {
		for (int32_t x = 0; x < s->w; x++) {
			char c = grid_free_at(g, x, y) ? '.' : '#';
			if (skeleton_on(s, x, y)) {
				int d = skeleton_degree(s, x, y);
				c = d >= 3 ? '+' : d <= 1 ? '*' : 'o';
				junctions += d >= 3;
				ends += d <= 1;
			}
			fputc(c, out);
		}
		fputc('\n', out);
	}
	fprintf(out, "skeleton: %d cells, %d junction cells, %d end points, %d pruned\n",
	        (int)s->count, (int)junctions, (int)ends, (int)s->pruned);
}
