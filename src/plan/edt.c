/* edt.c - the exact distance transform of a grid (paper 4.2: the clearance the
 * skeleton is the ridge of), squared Euclidean, in integers: skeleton_edt, and
 * skeleton_edt_scratch, the same with the caller's scratch (skeleton.c's).
 *
 * ALGORITHM
 *    Meijster, Roerdink and Hesselink, "A general algorithm for
 *    computing distance transforms in linear time" (Mathematical Morphology and its
 *    Applications to Image and Signal Processing, 2000). Phase 1 finds, for every cell,
 *    the distance g to the nearest blocked cell in its column: one pass down the grid
 *    (the distance to the blocked cell above, 16 bits a cell; on a large grid by
 *    bands of rows, each found again from the row kept above it when its turn comes,
 *    so that they stay in the cache: edt_bands), then one pass up that
 *    takes the distance below and the minimum and hands each row at once to phase 2:
 *    dist2(x) = min over the columns u of (x - u)^2 + g(u)^2. Phase 2 goes by blocks of
 *    32 cells. A block whose cells are all near a blocked cell (a bound b from g and
 *    from the row below, see edt_row) takes the minimum over the window |x - u| < b
 *    directly, one offset for the 32 cells at once in 16-bit lanes; the others, far
 *    from every blocked cell, take the lower envelope of the parabolas, as in
 *    Felzenszwalb and Huttenlocher ("Distance transforms of sampled functions", Theory
 *    of Computing 8, 2012) but with exact integer comparisons in place of divisions,
 *    over the columns in their reach but those whose g alone puts them above every
 *    answer there. A window longer than 96 goes by chunks of 16 offsets and skips
 *    a chunk's side whose columns' least g^2, plus the chunk's least k^2, cannot
 *    lower any cell of the block (wide open space, where the columns around have
 *    large g). A blocked cell is one more column, with g = 0.
 *    The cells just outside the grid are blocked: phase 1 starts each column at
 *    distance 1 from the rows -1 and h, and phase 2 has a blocked column at -1 and w.
 *    The loops over a block have a fixed count, which compilers vectorise at -O2;
 *    on x86-64 Linux the row pass is also compiled for AVX2 and chosen at load time.
 *
 * MEMORY  dist2 (4 bytes a cell); phase 1's column distances (2 bytes a cell) in the
 *    caller's scratch, or in dist2's own first half; a few arrays of one row. By
 *    bands (edt_bands: with the caller's scratch, or alone on grids of 2048 x 2048
 *    and up), about 256 KB of them at a time and one row a band, in the caller's
 *    scratch or about 1.5 MB of its own at 4096 a side.
 *
 * COMPLEXITY  O(w h) but for the windows: one pass down the grid and one up, each
 *    row's envelope pushing each column at most once; a window block costs b offsets
 *    (b <= 181), each two loads, an addition and two minima for its 32 cells; past
 *    96, a chunk of 16 offsets costs two least-of-48 checks and may be skipped.
 *
 * MEASURED  (issue 16; thread CPU time on this 2-core machine, shared, so +-15%;
 *    `make bench-compare` for the table against the peers)
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
 *    the columns around have large g (a least g a block; 1.1-1.4 slower everywhere).
 *    Against OpenCV (cv2.distanceTransform, DIST_L2, DIST_MASK_PRECISE, one thread),
 *    `make bench-compare SIDE=1024`, one run,
 *    medians: rooms, rects, maze, Boston_0_1024, den520d at 1024 took 1.42, 1.39, 1.16,
 *    1.63 and 1.37 ms (3-5 read passes of the grid), OpenCV 14.9, 11.0, 11.4, 12.9 and
 *    9.7: 10.5, 7.9, 9.8, 7.9 and 7.1 times faster. At 4096 (medians of 5, utak timed
 *    before and after OpenCV's 7 in one session): 22.5-23.7, 23.6, 17.6-18.9, 47.3-52.0
 *    and 40.2-41.0 ms against 213, 215, 238, 198 and 180: 9.0-9.4, 9.1, 12.6-13.5,
 *    3.8-4.2 and 4.4-4.5 times. The scaled maps at 4096 miss the 5: their
 *    open spaces are 4 times as wide, so their windows 4 times as long (or past 181,
 *    the envelope): the windows' cost grows with the clearance, not only the cells.
 *    A second push on those two (the same values, cell for cell, on the ten grids):
 *    the envelope without the columns whose g passes the largest bound of the row's
 *    envelope blocks (on Boston_0_1024 at 4096, 2.8 million pushes, 2.3 million of
 *    them popped, fell to 2.0 and 1.5), and windows longer than 96 by chunks with
 *    skipped sides (edt_window_far: at 4096, 57% of Boston_0_1024's chunk sides past
 *    the first and 75% of den520d's are skipped or cut by the end test). Valgrind counts at 4096: 683 and
 *    546 million instructions to 644 and 468 (38.4 and 27.9 a cell); at 1024, 0.4
 *    million more on every grid (12.8-22.1 million). Against the former code, best
 *    of 5 in one process: Boston_0_1024 and den520d at 4096 1.04-1.09 and 1.11-1.14
 *    times faster, the others 0.95-1.02 (noise). Against OpenCV (cvtime.py, one
 *    session, utak's medians of 9 before and after OpenCV's 7): at 1024, rooms,
 *    rects, maze, Boston_0_1024 and den520d took 1.14-1.18, 1.22-1.29, 0.74-0.80,
 *    1.36-1.44 and 1.10-1.15 ms, OpenCV 8.3, 9.4, 10.8, 11.5 and 8.1: 7.1-7.3,
 *    7.3-7.7, 13.5-14.6, 8.0-8.5 and 7.1-7.4 times (1.1-1.4 ns a cell); at 4096
 *    22.6-23.6, 23.5-25.1, 17.1-17.8, 44.1-45.4 and 33.6-34.8 ms against 194, 206,
 *    219, 193 and 173: 8.2-8.6, 8.2-8.8, 12.3-12.8, 4.3-4.4 and 5.0-5.2 times.
 *    Boston_0_1024 at 4096 still misses the 5 (about 39 ms would meet it): its
 *    windows of 16 to 181 take about half the time, the envelope a sixth, phase 1
 *    a sixth. Tried and not kept: the chunks for every window past 16 (2-19% slower
 *    at 1024: in edt_row their code kept the short windows' lanes in memory, which
 *    the function of its own avoids), switches at 32, 48, 64, 80 and 128 (no better),
 *    chunks of 8 or 32 (no better), the window's k^2 from a table (GCC then kept the
 *    lanes in memory, 2-10 times slower), the envelope also without each column no
 *    nearer than both neighbours (exact, no faster: its branch mispredicts as the
 *    pops did), one pop without a branch (slower: a longer dependency chain), the
 *    switch to the envelope at 96 or 128 (slower), phase 1's columns in signed lanes
 *    for SSE2 (1.7% fewer instructions, no faster).
 *    Phase 1 for AVX2 too (issue 16's maze round, skel11): edt_down and edt_columns
 *    compiled as the row pass is (edt_columns had been called from edt_row's AVX2
 *    clone as a plain SSE2 function, 10-11% of the 1024 maze's skeleton with its
 *    transform in perf), their 16-bit values loaded one by one through memcpy instead
 *    of copied into a local array (in the AVX2 clone the copy's 16-byte stores, read
 *    back as 32-byte vectors, stalled every block: with that copy the AVX2 edt_columns
 *    made the maze's skeleton 3-5% slower, not faster). The same values (old and new
 *    code in one process: 1500 random grids and the ten bench grids, dist2 compared).
 *    The transform's share of skeleton_compute (an instrumented copy, mean of 100
 *    calls, three runs alternating with the code before, loaded): at 1024 maze
 *    0.88-0.94 -> 0.64-0.69 ms, rooms 1.14-1.22 -> 0.97-1.00, rects 1.23-1.29 ->
 *    1.04-1.11, Boston_0_1024 1.39-1.46 -> 1.20-1.27, den520d 1.27-1.29 -> 1.02-1.13;
 *    at 4096 (8 calls, two runs) maze 19.7-20.0 -> 17.6-17.9, Boston_0_1024 41.9-42.3
 *    -> 39.3-41.0. Tried first: edt_columns inlined by force into edt_row (3-5% slower
 *    on the maze's skeleton: the copy's stall above).
 *    Phase 1 by bands (edt_bands, same round): at 4096 a side its column distances
 *    (32 MB) went to memory and back between the two passes; by bands of about 256 KB
 *    they stay in the cache, for a second read of the cells (16 MB). The same values
 *    (the harness above, also with bands of 1, 2, 5 rows and of 3000 bytes forced on
 *    every grid, 1500 random grids each; test_skeleton's
 *    edt_by_bands_equals_the_whole_grid). The transform inside skeleton_compute (the
 *    instrumented copy, 8 calls, two runs alternating with the code before): 4096
 *    maze 16.7-17.8 -> 13.4-15.2 ms, Boston_0_1024 41.4-43.7 -> 37.5-38.4; at 1024
 *    no change beyond the noise (0.59-0.78 -> 0.56-0.64 on the maze, four runs).
 *    skeleton_edt alone (medians of 7, alternating in one process) at 4096: maze
 *    13.1 -> 11.4, Boston_0_1024 33.3 -> 31.0, rooms 16.7 -> 14.5, rects 17.7 ->
 *    15.4, den520d 25.5 -> 23.6; at 1024 unchanged (not by bands: EDT_BANDS_ALONE).
 *    Bands of 64 KB, 128 KB and 512 KB: within the noise of 256 KB at 1024 and 4096
 *    (512 KB 5% better at 4096 on the maze; 256 KB kept for caches of 512 KB a
 *    core).
 *    Growth with the cells (the scaling round; `skelbench --scaling`, every side
 *    timed in each round, medians of 7 and 9, three runs, loaded): skeleton_edt costs
 *    0.74-0.90 ns a cell on rooms, 0.81-0.92 on rects and 0.54-0.68 on the maze at
 *    every side from 256 to 4096; 4096 over 256: 0.93-1.01, 0.98-1.02 and 1.02-1.13
 *    (the maze's bands from 2048 read the cells twice); 5.4-6.4 one-pass reads of a
 *    4-byte array the grid's size on rooms and rects, 3.7-4.6 on the maze, at every
 *    side. Linear: its rows and bands stay in the core's cache at every size, and it
 *    writes dist2 in order. Nothing was changed for it. */
#include "edt_work.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/plan/skeleton.h"

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
/* A window block with a bound past EDT_FAR goes by chunks of EDT_CHUNK offsets, some
 * skipped (edt_window_far); shorter ones by edt_window, in one loop (chunks there
 * cost more than they save: a switch at 16, 32, 48, 64 was 2-19% slower on the 1024
 * maps; at 96 no map is slower by more than the noise, and den520d at 4096 is 1.15
 * times faster, Boston_0_1024 1.06). */
#define EDT_CHUNK 16
#ifndef EDT_FAR
#define EDT_FAR 96
#endif
/* The 16-bit squares are kept with this many zero columns on either side, so that a
 * window (k <= EDT_WINDOW_BOUND), and edt_window_far's least squares over a chunk
 * (EDT_CHUNK columns further), never read outside; a zero outside the grid stands
 * for a blocked column, which changes nothing beyond columns -1 and w (those are
 * nearer). */
#define EDT_PAD (EDT_WINDOW_BOUND + EDT_CHUNK)

/* The window's functions are inlined into edt_row, so that its AVX2 clone has them
 * in AVX2 too (GCC does not inline edt_window, grown by its chunks, on its own). */
#if defined(__GNUC__)
#define EDT_INLINE static inline __attribute__((always_inline))
#else
#define EDT_INLINE static inline
#endif
/* edt_window_far is kept out of line (GCC kept the short windows' lanes in memory
 * with it inlined); clang refuses noinline beside target_clones, and does not
 * inline a multiversioned function anyway. */
#if defined(__GNUC__) && !defined(__clang__)
#define EDT_NOINLINE __attribute__((noinline))
#else
#define EDT_NOINLINE
#endif
/* On x86-64 with glibc (target_clones needs its ifunc; musl has none) the row pass is
 * also compiled for AVX2, chosen at load time. */
#if defined(__GNUC__) && defined(__x86_64__) && defined(__GLIBC__)
#define EDT_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define EDT_CLONES
#endif

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

/* edt_envelope_push(v, c, g, a, z, far): pushes the columns a..z not pushed yet (g is
 * read there; -1 <= a, z <= w, g[-1] = g[w] = 0: the blocked columns outside the
 * grid) but those with g > far; a gap after the last column pushed starts the stack
 * afresh. Every cell the envelope answers has dist2 <= far^2 (far is the largest bound
 * b of the row's envelope blocks), so a column with g > far, its parabola above g^2 >
 * far^2 everywhere, is never strictly lowest: leaving it out changes no value, and
 * saves its push and, in wide open space where most such columns would be pushed only
 * to be popped, the pops' mispredicted branches. */
static void edt_envelope_push(const EdtStack *v, EdtCursor *c, const uint16_t *restrict g,
                              int32_t a, int32_t z, int32_t far)
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
		if (gu > far)
			continue;
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
EDT_INLINE void edt_window_step(const uint16_t *restrict at, int32_t k, uint16_t *restrict best)
{
	const uint16_t kk = (uint16_t)(k * k);
	const uint16_t *restrict left = at - k, *restrict right = at + k;
	for (int i = 0; i < EDT_BLOCK; i++) {
		uint16_t m = left[i] < right[i] ? left[i] : right[i];
		m = (uint16_t)(m + kk);
		best[i] = m < best[i] ? m : best[i];
	}
}

/* edt_window_side(src, k, best): best[i] = min(best[i], src[i] + k^2), one side of
 * edt_window_step (src = at - k or at + k). */
EDT_INLINE void edt_window_side(const uint16_t *restrict src, int32_t k,
                                uint16_t *restrict best)
{
	const uint16_t kk = (uint16_t)(k * k);
	for (int i = 0; i < EDT_BLOCK; i++) {
		const uint16_t m = (uint16_t)(src[i] + kk);
		best[i] = m < best[i] ? m : best[i];
	}
}

/* edt_least(p): the least of p[0 .. EDT_BLOCK + EDT_CHUNK - 1]. */
EDT_INLINE int32_t edt_least(const uint16_t *restrict p)
{
	uint16_t m = UINT16_MAX;
	for (int i = 0; i < EDT_BLOCK + EDT_CHUNK; i++)
		m = p[i] < m ? p[i] : m;
	return m;
}

/* edt_block_out(best, out, n): out[i] = best[i] for i < n (n <= EDT_BLOCK); returns
 * the largest best[i]. */
EDT_INLINE int32_t edt_block_out(const uint16_t *restrict best, int32_t *restrict out, int n)
{
	uint16_t most = 0;
	for (int i = 0; i < EDT_BLOCK; i++)
		most = best[i] > most ? best[i] : most;
	if (n == EDT_BLOCK)
		for (int i = 0; i < EDT_BLOCK; i++)
			out[i] = best[i];
	else
		for (int i = 0; i < n; i++)
			out[i] = best[i];
	return most;
}

/* edt_window_far(sq, x0, reach, out, n): edt_window for a reach of EDT_CHUNK or
 * more, its answers written to out[0 .. n - 1] (edt_block_out).
 * The offsets go by chunks of EDT_CHUNK; before each chunk past the first, a side
 * (left or right) whose columns' least square plus the chunk's least k^2 is no lower
 * than the largest best so far cannot lower any cell, and is skipped (in wide open
 * space, where the columns around have large g, most are); the window ends once k^2
 * alone is that high. A function of its own, not inlined: in edt_row its code slowed
 * the short windows' loop (2-18% on the 1024 maps, where it hardly runs). */
EDT_CLONES EDT_NOINLINE static int32_t edt_window_far(const uint16_t *restrict sq,
                                                      int32_t x0, int32_t reach,
                                                      int32_t *restrict out, int n)
{
	const uint16_t *restrict at = sq + x0;
	uint16_t lane[EDT_BLOCK];
	for (int i = 0; i < EDT_BLOCK; i++)
		lane[i] = UINT16_MAX;
	for (int32_t k = 0; k < EDT_CHUNK; k += 2) {
		edt_window_step(at, k, lane);
		edt_window_step(at, k + 1, lane);
	}
	for (int32_t k0 = EDT_CHUNK; k0 <= reach; k0 += EDT_CHUNK) {
		uint16_t most = 0;
		for (int i = 0; i < EDT_BLOCK; i++)
			most = lane[i] > most ? lane[i] : most;
		const int32_t kk = k0 * k0;
		if (kk >= most)
			break;
		/* the chunk's offsets k0 .. k0 + EDT_CHUNK - 1 reach the columns
		 * x0 - k0 - EDT_CHUNK + 1 .. x0 - k0 + EDT_BLOCK - 1 on the left, and
		 * x0 + k0 .. x0 + k0 + EDT_BLOCK + EDT_CHUNK - 2 on the right */
		const int left = kk + edt_least(at - k0 - EDT_CHUNK) < most;
		const int right = kk + edt_least(at + k0) < most;
		const int32_t end = reach < k0 + EDT_CHUNK - 1 ? reach : k0 + EDT_CHUNK - 1;
		if (left && right)
			for (int32_t k = k0; k <= end; k += 2) {
				edt_window_step(at, k, lane);
				edt_window_step(at, k + 1, lane);
			}
		else if (left)
			for (int32_t k = k0; k <= end; k += 2) {
				edt_window_side(at - k, k, lane);
				edt_window_side(at - k - 1, k + 1, lane);
			}
		else if (right)
			for (int32_t k = k0; k <= end; k += 2) {
				edt_window_side(at + k, k, lane);
				edt_window_side(at + k + 1, k + 1, lane);
			}
	}
	return edt_block_out(lane, out, n);
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
	for (int i = 0; i < EDT_BLOCK; i++) {
		uint16_t up;
		memcpy(&up, up_bytes + 2 * i, sizeof up);
		const uint16_t d = up ? (uint16_t)(dn[i] + 1) : 0;
		dn[i] = d;
		g[i] = d < up ? d : up;
	}
	uint16_t m = 0;
	for (int i = 0; i < EDT_BLOCK; i++) {
		sq[i] = (uint16_t)(g[i] < EDT_WINDOW_BOUND ? g[i] * g[i] : EDT_CLIP);
		m = g[i] > m ? g[i] : m;
	}
	return m;
}

/* edt_down(cells, prev, row, w): phase 1 down the grid on one row: row = prev + 1 on
 * a free cell, else 0. Compiled for AVX2 too, as the row pass; the values are loaded
 * and stored one by one through memcpy (vector loads and stores once compiled), not
 * copied through a local array: under AVX2 that array's two 16-byte halves, stored
 * and then read back as one 32-byte vector, stalled every block (no store
 * forwarding). */
EDT_CLONES EDT_NOINLINE static void edt_down(const uint8_t *restrict cells,
                                             const unsigned char *restrict prev,
                                             unsigned char *restrict row, int32_t w)
{
	const int32_t w32 = w - w % EDT_BLOCK;
	for (int32_t x0 = 0; x0 < w32; x0 += EDT_BLOCK)
		for (int i = 0; i < EDT_BLOCK; i++) {
			uint16_t a;
			memcpy(&a, prev + 2 * (x0 + i), sizeof a);
			const uint16_t free_mask = (uint16_t)(0u - (cells[x0 + i] == GRID_FREE));
			a = (uint16_t)((a + 1) & free_mask);
			memcpy(row + 2 * (x0 + i), &a, sizeof a);
		}
	for (int32_t x = w32; x < w; x++) {
		uint16_t a;
		memcpy(&a, prev + 2 * x, sizeof a);
		a = cells[x] == GRID_FREE ? (uint16_t)(a + 1) : 0;
		memcpy(row + 2 * x, &a, sizeof a);
	}
}

/* edt_columns(r, up): the end of phase 1 for one row (up: its distances to the
 * blocked cell above, 0 on a blocked cell): r->dn, the distance to the nearest
 * blocked cell below (row h blocked), and r->g = min(up, dn), the column distance,
 * with its clipped squares r->sq and each block's largest g. The loops over a block
 * have a fixed count, so that compilers vectorise them at -O2 (GCC 12's cheap cost
 * model takes only loops that need no scalar remainder). */
EDT_CLONES EDT_NOINLINE static void edt_columns(EdtRow *r, const unsigned char *restrict up)
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
	int32_t far = 0; /* the largest bound of the blocks left to the envelope */
	for (int32_t blk = 0; blk < blocks; blk++) {
		const int32_t c = edt_ceil_sqrt(bound[blk]) + 1;
		const int32_t b = r->most[blk] < c ? r->most[blk] : c;
		reach[blk] = b;
		far = b > EDT_WINDOW_BOUND && b > far ? b : far;
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
			edt_envelope_push(&r->v, &cursor, g, a, z, far);
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
		const int n = w - x0 < EDT_BLOCK ? w - x0 : EDT_BLOCK;
		int32_t most;
		if (b > EDT_FAR) {
			most = edt_window_far(sq, x0, b - 1, out + x0, n);
		} else {
			uint16_t best[EDT_BLOCK];
			edt_window(sq, x0, b > 0 ? b - 1 : 0, best);
			most = edt_block_out(best, out + x0, n);
		}
		bound[blk] = most;
		largest = most > largest ? most : largest;
	}
	return largest;
}

/* Phase 1 by bands of rows, each about EDT_BAND_BYTES of column distances (2 bytes
 * a cell), at least EDT_BAND_MIN rows: see edt_bands. */
#ifndef EDT_BAND_BYTES
#define EDT_BAND_BYTES (256 * 1024)
#endif
#ifndef EDT_BAND_MIN
#define EDT_BAND_MIN 8
#endif

/* skeleton_edt (no caller's scratch) goes by bands, with scratch of its own, when
 * phase 1's distances would take this many bytes or more (a grid of 2048 x 2048 and
 * up); on a smaller grid they stay in dist2's first half, with no allocation. */
#ifndef EDT_BANDS_ALONE
#define EDT_BANDS_ALONE (8u << 20)
#endif

/* edt_band_rows(w): the rows of a band, for rows of w cells. */
static int32_t edt_band_rows(int32_t w)
{
	const int32_t rows = EDT_BAND_BYTES / (2 * (w > 0 ? w : 1));
	return rows > EDT_BAND_MIN ? rows : EDT_BAND_MIN;
}

/* edt_bands(gr, r, band, bands, scratch, dist2): both phases by bands of `band` rows
 * (bands of them, the last one shorter), so that the column distances of phase 1
 * stay in the cache until the row pass reads them instead of going to memory and
 * back (2 bytes a cell each way, besides dist2's 4 written: at 4096 a side 32 MB,
 * where the caches hold 1 MB a core and 32 MB in all). First down the grid with two
 * rows of distances, keeping each band's last row; then, from the top band's up to
 * the first, each band's distances again from the row kept above it (rows of zeros,
 * a blocked row, above the first band), down the band, and the row pass up it (the
 * distance below and the row below's bounds carried from band to band, as from row
 * to row). The same values as phase 1 over the whole grid: each row's distances are
 * the same numbers, found once more. The cells are read twice, 1 byte a cell. scratch
 * holds (bands + 2 band) rows of 2 w bytes (the kept rows, then the band's, the
 * first two of which serve the first pass); returns the largest dist2. */
static int32_t edt_bands(const Grid *gr, EdtRow *r, int32_t band, int32_t bands,
                         unsigned char *scratch, int32_t *dist2)
{
	const int32_t w = gr->w, h = gr->h;
	const size_t row_bytes = 2 * (size_t)w;
	unsigned char *kept = scratch, *buf = scratch + (size_t)bands * row_bytes;
	/* rows of zeros, a blocked row above the grid: buf's last row, cleared here for
	 * the first pass and again after it (which uses buf's first two rows; the bands'
	 * pass uses band rows at most) */
	unsigned char *zero = buf + (size_t)(2 * band - 1) * row_bytes;
	memset(zero, 0, row_bytes);
	const unsigned char *prev = zero;
	for (int32_t b = 0; b < bands; b++) {
		const int32_t y1 = (b + 1) * band < h ? (b + 1) * band : h;
		for (int32_t y = b * band; y < y1; y++) {
			unsigned char *row = buf + (size_t)(y & 1) * row_bytes;
			edt_down(gr->cells + (size_t)y * w, prev, row, w);
			prev = row;
		}
		memcpy(kept + (size_t)b * row_bytes, prev, row_bytes);
		prev = kept + (size_t)b * row_bytes;
	}
	memset(zero, 0, row_bytes);
	int32_t largest = 0;
	for (int32_t b = bands - 1; b >= 0; b--) {
		const int32_t y0 = b * band, y1 = (b + 1) * band < h ? (b + 1) * band : h;
		prev = b > 0 ? kept + (size_t)(b - 1) * row_bytes : zero;
		for (int32_t y = y0; y < y1; y++) {
			unsigned char *row = buf + (size_t)(y - y0) * row_bytes;
			edt_down(gr->cells + (size_t)y * w, prev, row, w);
			prev = row;
		}
		for (int32_t y = y1 - 1; y >= y0; y--) {
			const int32_t most =
			    edt_row(r, buf + (size_t)(y - y0) * row_bytes, dist2 + (size_t)y * w);
			largest = most > largest ? most : largest;
		}
	}
	return largest;
}

/* skeleton_edt_scratch(g, dist2, up): skeleton_edt with up as scratch of 2 w h bytes,
 * or NULL to use dist2's own memory (see below). It once also counted each dist2
 * value for the thinning's sort; counting here stalled on its own stores (skeleton.c,
 * the histogram), so skeleton.c counts on rows read again. */
int32_t skeleton_edt_scratch(const Grid *gr, int32_t *dist2, uint16_t *up)
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
	 * blocked), 0 on a blocked cell. Blocks of a fixed count, as in edt_columns. With
	 * the caller's scratch, by bands (edt_bands); else over the whole grid, then up
	 * it. */
	const int32_t band = edt_band_rows(w);
	const int32_t bands = (h + band - 1) / band;
	const size_t band_bytes = ((size_t)bands + 2 * (size_t)band) * 2 * (size_t)w;
	if (up && (int64_t)bands + 2 * band <= h) {
		largest = edt_bands(gr, &r, band, bands, above, dist2);
	} else if (!up && 2 * (size_t)w * (size_t)h >= EDT_BANDS_ALONE) {
		/* the transform alone on a large grid: the bands' own scratch (about 1.5 MB
		 * at 4096 a side) costs less than the traffic it saves */
		unsigned char *scratch = util_alloc(band_bytes, 1);
		largest = edt_bands(gr, &r, band, bands, scratch, dist2);
		free(scratch);
	} else {
		for (int32_t y = 0; y < h; y++)
			edt_down(gr->cells + (size_t)y * w,
			         y > 0 ? above + 2 * (size_t)(y - 1) * w
			               : (const unsigned char *)r.dn,
			         above + 2 * (size_t)y * w, w);
		/* Then up the grid, row by row: the column distances of a row
		 * (edt_columns), made and used at once by the row pass (no second pass
		 * over the grid). */
		for (int32_t y = h - 1; y >= 0; y--) {
			int32_t *out = dist2 + (size_t)y * w;
			const int32_t most = edt_row(&r, above + 2 * (size_t)y * w, out);
			largest = most > largest ? most : largest;
		}
	}
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
	return skeleton_edt_scratch(g, dist2, NULL);
}
