/* skeleton.c - the digital skeleton of free space, from the exact distance transform
 * (paper 4.2; see skeleton.h for the digital topology and the units).
 *
 * ALGORITHM
 * 1. Distance transform: skeleton_edt, in edt.c (exact, squared Euclidean; see there).
 * 2. Thinning: distance-ordered homotopic thinning (Pudney, "Distance-ordered homotopic
 *    thinning: a skeletonization algorithm for 3D digital images", CVIU 72(3), 1998),
 *    here in 2D with the (4, 8) topology. Free cells are visited in order of
 *    increasing dist2 (a counting sort, skelsort.c: a bucket queue with all keys known in
 *    advance; ties by cell index, so the result is deterministic), except that the
 *    lowest level, dist2 1, is first thinned by bit planes in parallel subfields
 *    (skellevel.c: each of its deletions is one a visit would make, the order within
 *    the level being the algorithm's free choice), and its cells left are then
 *    visited in index order before the next level. The next three levels, dist2 2, 4
 *    and 5, are each started by bit planes where they are dense (skellevel.c's NEXT
 *    LEVELS): the level's cells not deletable when it starts are marked visited and
 *    kept at once, the others visited one by one, and a marked cell whose neighbour
 *    is deleted before its turn is visited at its turn (thinner_visit_level): the
 *    same thinning, cell for cell, as visiting the level in index order. A visited
 *    cell is
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
 *    Only the cells found ridge ends are marked (a bit plane): a cell of degree 1
 *    when the visits are over is simple, so it was last kept as a ridge end; the
 *    pruning takes its end points from the mark.
 * 3. Pruning (skelprune.c, on the Thinner of skelthin.h): a small bay in a wall can
 *    still leave a branch whose tip is a ridge end, a spur. Every branch from an end point to a
 * junction cell (degree >= 3) is removed when it has at most SKELETON_SPUR_FACTOR *
 * clearance(junction) + SKELETON_SPUR_SLACK cells (see skeleton.h); branches are judged all at once
 * on the thinned set, one round, and a branch joining two end points (a component that is a simple
 * arc) is never removed. Removing a branch that hangs off a junction changes no topology. Then step
 * 2's deletion test runs again over the skeleton, because a junction that lost a branch may now be
 * deletable.
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
 *    quarter of the cells), and the histogram's split tables (8.7 KB, on the stack);
 *    the lowest level's four bit planes (skellevel.c, half a byte a cell) and the
 *    ridge ends' plane (an eighth of a byte a cell); the next levels' four planes
 *    (half a byte a cell) and the pruning's plane of cells to test again (an eighth).
 *    The higher levels' list (two values a cell, when they are at most half the grid)
 *    is kept in the stack.
 *    The transform alone (skeleton_edt) keeps its column distances in dist2's first
 *    half; its other scratch is a few arrays of one row.
 *
 * COMPLEXITY  O(w h) after the transform (edt.c): the lowest level a few passes of
 *    w h / 64 words; the sort two passes (over the higher levels' list alone where
 *    they are at most half the grid);
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
 *    A fifth round, on the maze (the goal: 5 times scikit-image's skeletonize there,
 *    17.8 ms at 1024, so about 3.5 ms with the transform). By phase on the 1024 maze
 *    (an instrumented copy, best of 11, two rounds alternating with the code before):
 *    the transform with its histogram 2.47 ms -> 1.17 and 0.97 (the histogram made
 *    here, in split tables, from rows of dist2 read again, with the state), the
 *    sort 0.98 (unchanged), the visits 2.6 -> 2.45 (thinner_visits inlined by force),
 *    pruning 0.97 -> 0.88 (the junctions' clearances loaded after the scan), about
 *    7.1 -> 6.5 ms in all; on rooms, rects, Boston_0_1024 and den520d 0.3-0.6 ms less.
 *    Callgrind (skeleton_compute with its transform, 1024 grids): maze 78.8 -> 83.9
 *    million instructions, rooms 92.2 -> 94.2, rects 80.2 -> 82.9, Boston_0_1024
 *    80.6 -> 82.7, den520d 63.3 -> 68.3 (80, 90, 79, 79 and 65 a cell: the split
 *    tables take more instructions than the transform's one table, and less time);
 *    the visits alone 33.5 -> 29.3 million on the maze. skelbench --compare (caches
 *    cold after the other jobs; medians of 5 runs alternating with the code before):
 *    maze 7.98 -> 7.47 ms. make bench-compare SIDE=1024 (at 5b82d35, the machine
 *    loaded: the transform took 1.2-2.4 ms): the skeleton in 9.05, 8.55, 7.45, 9.87
 *    and 7.31 ms on rooms, rects, maze, Boston_0_1024 and den520d, scikit-image's
 *    skeletonize 7.77, 14.3, 2.39, 19.1 and 18.9 times as long (2.53 on the maze at
 *    48fe8a7, a quieter run): the maze's 5 is not met. What stands in the way there:
 *    the transform (1.0-1.2 ms), dist2 read twice more (histogram and sort, 0.3 ms
 *    each), the histogram's stores (one a cell), the sort's 3 cycles a cell (blocked
 *    cells included), and 786 429 visits at about 3 ns, each a chain of loads, a
 *    multiply, a table load and a branch: 3.5 ms leaves no room for the visits and
 *    the sort as they are. Tried and not kept: the ridge test at a visit decided by a
 *    bit in the order's entry (some neighbour has a larger dist2, exact at a cell's
 *    first visit) made during the sort, the visits 0.1 ms faster and the sort 1.7
 *    slower (the 3 x 3 maxima not vectorised at -O2); the levels holding a sixteenth
 *    of the cells or more (the maze's dist2 1 and 4: 93% of its free cells) visited by
 *    scans of a code byte a cell instead of sorted, the visits 2.45 -> 4.7 ms (the loop
 *    over a word's cells mispredicted at every word) and the codes' histogram
 *    0.75 -> 1.55; skipping the sort's groups of 4 blocked cells, 0.98 -> 1.2 ms on
 *    the maze (mispredicted); the histogram kept in the transform's row loop with the
 *    split tables (edt.c), no faster at 1024 and 2-4 ms faster at 4096 (left out:
 *    edt.c is the transform's); listing the cells to test again while removing the
 *    spurs, 2 ms slower at 4096; THIN_AHEAD 8, 32 or 64, no change above the noise;
 *    the visits by bits, 64 cells of a row and a level at a time (the neighbourhoods
 *    gathered from the state bytes by multiplications, the simple-point test by
 *    Yokoi's connectivity number on 64-bit words, the dependence on the west cell
 *    solved by composing each cell's function of it in six doubling steps, the ridge
 *    test only where the solved west cell makes it needed, and a cascade left to
 *    thinner_retry and the rest of the window to single visits): the same skeleton
 *    on the 30 grids, but the maze 6.5 -> 9.8 ms at 1024 (the gathering and the
 *    per-window setup cost more than the 20 to 30 visits of a window they replace).
 *    At 4096 the maze (instrumented, best of 3): the transform 18-20 ms, state and
 *    histogram 15, sort 16, visits 55-57, pruning 24 (scan and walks 14, the list to
 *    test again 5), about 130 ms against skeletonize's 295 (2.12 times at 48fe8a7).
 *    A sixth round, on the maze, by algorithm rather than by instruction: the lowest
 *    level (dist2 1: 524 288 of the 1024 maze's 786 429 free cells) thinned by bit
 *    planes in four parallel subfields (skellevel.c) instead of visited one by one;
 *    the higher levels listed from the planes with their dist2 and counted as they
 *    are listed, and sorted alone (the blocked cells and the lowest level neither
 *    counted nor sorted) when they are at most half the grid; the pruning's end
 *    points from a plane of the cells found ridge ends instead of a scan of the
 *    state. The order within the lowest level changed (the skeleton of the maze,
 *    rooms and den520d is the same cell for cell at 1024 and 4096; elsewhere cells
 *    move where the tie-break chose, with the same components and loops on all 30
 *    grids; see the commit). Callgrind, skeleton_compute with its transform, 1024
 *    grids: maze 83.9 -> 49.5 million instructions (80 -> 47 a cell), den520d 68.3
 *    -> 60.7, rooms 94.2 -> 99.2, rects 82.9 -> 87.1, Boston_0_1024 82.7 -> 87.4 (the
 *    planes cost about 7 million where the lowest level is a thin rim; Boston at 4096
 *    1691 -> 1771 million). By phase on the 1024 maze (an instrumented copy, best of
 *    21, the machine loaded): transform 0.96 ms, the lowest level's planes and
 *    subfields 0.48, state 0.08, the higher levels' list and histogram 0.57, sort
 *    0.32, visits 0.65 (308 000 visits, from 786 429), pruning 0.47 (its walks 0.27),
 *    output 0.08: 3.6 ms in all. skelbench --compare (medians of 5, alternating with
 *    the code before, loaded): maze 7.0-7.2 -> 4.4-4.5 ms at 1024, 135 -> 109 at 4096.
 *    make bench-compare SIDE=1024 in one run (two runs, both loaded): the skeleton
 *    4.61 and 5.21 ms on the maze against skeletonize's 17.9 and 18.6: 3.89 and 3.57
 *    (3.10 in the README's table at e47d589); rooms 8.97 and 8.62, rects 11.3 and
 *    12.9, Boston_0_1024 22.9 and 17.6, den520d 30.3 and 24.4. The maze's 5 is still
 *    unmet: it needs about 3.6 ms in skelbench's cold run, where the transform alone
 *    takes 1.0-1.1 (edt.c's, another job of issue 16) and the higher levels, a
 *    quarter million cells listed, counted, sorted and visited one by one, 1.5; at
 *    4096 the visits (26 ms) and the walks (10) wait on memory (the ridge test's
 *    dist2 loads and the ends walked after the visits, no longer while the scan has
 *    their rows in the cache). Not tried for want of time: the higher levels by
 *    planes too (cells not deletable at the start of their level can all be marked
 *    kept at once; a legitimate order within the level, but each level needs its
 *    plane), and prefetching dist2 for the ridge test at 4096. Tried and dropped:
 *    counting the listed cells by runs of one value instead of in split tables, 2
 *    million instructions fewer on the 1024 maze but the list 0.59 -> 0.80 ms (the
 *    run's branch mispredicted where keys alternate).
 *    A seventh round, on the maze (skel9): the levels 2, 4 and 5 from planes where
 *    dense (ALGORITHM, step 2; skellevel.c's NEXT LEVELS), the pruning's cells to
 *    test again in a bit plane read in order instead of a list and a radix sort, its
 *    state fetched ahead above 8 MB, and a listed cell of a made plane's level listed
 *    without a load of dist2. The skeleton is the same cell for cell (the five 1024
 *    grids, the three 4096 synthetic grids and 300 random grids, hashes of the old
 *    and new library; no golden output changed). Callgrind, one warm skeleton_compute
 *    with its transform, 1024 grids: maze 49.9 -> 39.5 million instructions (47.6 ->
 *    37.7 a cell), rooms 99.2 -> 99.7, rects 87.1 -> 87.4, Boston_0_1024 87.5 -> 87.7,
 *    den520d 61.0 -> 61.4 (the re-try's place test, and the next levels' planes
 *    where the lowest level is dense). By phase on the 1024 maze (an instrumented
 *    copy, best of 31, loaded): transform 1.01 ms, lowest level and next levels'
 *    planes 0.57, state 0.08, listing and sort (level 5 alone) 0.18, the planed
 *    levels' passes 0.40 and their visits 0.21 (level 2's 45 734 cells, all
 *    deletable; level 4's 255 247 all kept, none visited), pruning 0.48, output 0.08:
 *    3.1 ms. At 4096 (the same copy, loaded): transform 19, planes 9.6, listing and
 *    sort 7.1 -> 3.1 (no dist2 loads), the planed levels 6.7 and 4.0, pruning 19.5
 *    (scan and walks 6.0, removal and marking 5.2, the sort 2.9 now gone, the tests
 *    4.0). ns a cell on the maze (skelbench, best of 3, loaded, before the pruning's
 *    changes): 3.9 at 256, 3.8 at 512, 4.5 at 1024, 5.1 at 2048, 5.7 at 4096: linear
 *    up to 1024 (the state, 1 MB, in the core's L2), 1.3 times that at 4096 where
 *    dist2 (64 MB) and the state (17 MB) outgrow the 32 MB L3, the pruning and the
 *    planed levels' visits waiting on memory. Against scikit-image in one run (/tmp script, skeletonize's median
 *    of 3 against utak's medians of 5, the machine loaded, the code before beside it):
 *    maze 1024 4.66 -> 6.33 (skeletonize 22.8 ms, utak 4.88 -> 3.60), maze 4096 4.05
 *    -> 5.44 (394 ms, utak 97.4 -> 72.5); two runs of make bench-compare SIDE=1024
 *    (loaded): the maze 4.94 and 5.52 (skeleton 3.77 and 3.79 ms, skeletonize 18.6
 *    and 20.9), rooms 8.85 and 9.84, rects 9.89 and 12.5, Boston_0_1024 20.1 and
 *    27.6, den520d 18.2 and 24.8: the maze's 5 reached, with no margin on this
 *    shared machine. Not kept: planing level 5 too on the 1024 maze (its pass costs
 *    what its listing saves).
 *    An eighth round, on the maze (issue 16's maze round, skel11): maze 1024 2.92 ->
 *    2.26 ms (skeleton_compute, alternating with the code before), skeletonize / utak
 *    7.35 at 1024 (make bench-compare SIDE=1024) and 6.33 at 4096 (README's
 *    Benchmarks): the figures, by part, are in the MEASURED sections of skellevel.c
 *    (the planes and subfields, the whole skeleton_compute), edt.c (phase 1 for AVX2)
 *    and skelprune.c (the pruning's recheck marking).
 *    The scaling round (issue 16, "costs linear in cells from 256 to 4096";
 *    `skelbench --scaling`, which times every side in each round): skeleton_compute
 *    costs 4.6-5.1, 5.2-5.6 and 1.9-2.1 ns a cell on rooms, rects and the maze at 256,
 *    512 and 1024, then 5.6-5.8, 6.0 and 1.9-2.0 at 2048 and 6.5-6.8, 7.1-7.2 and
 *    2.2 at 4096 (1.3-1.4, 1.3 and 1.1 times its 256 figure), while one read pass
 *    over a 4-byte array the grid's size costs 0.14 ns a cell at every side (the
 *    prefetchers follow it) and a load of each of its lines in an order they cannot
 *    follow 0.05 at 256, 0.15 at 1024 and 0.67 at 4096. By function (perf, software
 *    clock; ns a cell at 1024 -> 4096): rooms: the visits (thinner_visit_all) 1.58 ->
 *    2.51, thinner_ridge_end 0.22 -> 1.12 (296 000 calls at 4096, about 60 ns each:
 *    its dist2 loads, which nothing before it has brought in), skelsort_rows 1.49 ->
 *    1.59, the transform 0.57 -> 0.56; rects: the visits 1.95 -> 3.14,
 *    thinner_ridge_end 0.10 -> 0.72, skelsort_rows 1.77 -> 2.24 (its scatter into a
 *    64 MB order). Instructions grow with the cells but for the visits' prefetches
 *    above THIN_PREFETCH_BYTES (callgrind, rooms, 89 -> 99 a cell); last-level
 *    misses (callgrind's simulated 32 MB, one call) 0.001 -> 0.27 a cell (the visits
 *    0.10, skelsort_rows 0.13): each distance level sweeps the whole grid, sparsely,
 *    and at 4096 the 17 MB state and the 64 MB dist2 stay in no cache. Tried and
 *    dropped (each switched at run time in one driver, alternating, medians of 9 to
 *    21 at 4096): dist2 prefetched for the cell THIN_AHEAD visits on, its line or its
 *    three rows (rooms 1.01 and 1.04, rects 1.16 and 1.28 times slower, the maze 1.01
 *    and 1.02: a ridge test follows 1.5% of the visits on rooms, so most of those
 *    lines are fetched for nothing); the same only where the raster of that cell,
 *    read from its rows prefetched earlier, is THIN_RIDGE (8 or 16 visits on, the rows
 *    16 or 32 on: rooms and rects 1.03-1.09 slower, the maze unchanged: the second
 *    raster a visit costs more than the misses it spares); the cell's own state row
 *    prefetched with the rows above and below (5-6% off rects in that driver, but
 *    0.97-1.03 on the five grids at 4096 against the former skeleton.c linked beside
 *    it under other names: the noise); 2 MB pages for every large allocation (glibc's
 *    glibc.malloc.hugetlb=1, which advises MADV_HUGEPAGE: 0-5%, not steady); the
 *    visits' prefetches from 2 MB of state, so at 2048 too (0.97-1.02 there). What
 *    would remove the growth changes the order of the visits within a level (by
 *    tiles rather than by index), and so the skeleton where the tie-break chose.
 *    The transform's own figures are in edt.c's header. */
#include "utak/plan/skeleton.h"

#include "edt_work.h"
#include "skellevel.h"
#include "skelsort.h"
#include "skelthin.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

/* The thinning's row loads and the output's plane bytes gather 8 state bytes into 8
 * bits by one multiply, which takes byte k of a loaded word to bit k only where
 * bytes are stored little-end first (pathgraph_work.h reads the plane so too). */
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ != __ORDER_LITTLE_ENDIAN__
#error "skeleton.c gathers bytes to bits as on a little-endian machine"
#endif

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

/* skeleton_yokoi(m): Yokoi's connectivity number of the neighbourhood m for a
 * 4-connected set, the sum over the edge neighbours k of x_k (1 - x_{k+1} x_{k+2});
 * it is 1 exactly for the simple points (skellevel.c's test on bit planes relies on it,
 * asserted here over all 256 masks). */
static unsigned skeleton_yokoi(unsigned m)
{
	unsigned c = 0;
	for (unsigned k = 0; k < 8; k += 2)
		c += ((m >> k) & 1) & ~((m >> ((k + 1) % 8)) & (m >> ((k + 2) % 8)) & 1);
	return c;
}

/* skeleton_build_kind_table(kind): THIN_* of every mask (see the Thinner). */
static void skeleton_build_kind_table(uint8_t kind[256])
{
	for (unsigned m = 0; m < 256; m++) {
		assert(skeleton_is_simple_mask(m) == (skeleton_yokoi(m) == 1));
		unsigned edge = (m & 1) + ((m >> 2) & 1) + ((m >> 4) & 1) + ((m >> 6) & 1);
		kind[m] = !skeleton_is_simple_mask(m) ? THIN_KEEP : edge == 1 ? THIN_RIDGE : THIN_DELETE;
	}
}

/* ---------------------------------------------------------------- thinning */

/* thinner_divisor(d, mul, shift): the constants of thinner_row for the divisor d. */
static void thinner_divisor(int32_t d, uint64_t *mul, unsigned *shift)
{
	unsigned l = 0;
	while ((1u << l) < (unsigned)d)
		l++;
	*shift = 31 + l;
	*mul = ((1ull << *shift) + (uint64_t)d - 1) / (uint64_t)d;
}

/* thinner_init_tables(kind, ring): the tables over the raster mask (Thinner.kind and
 * .ring, 1 << THIN_RASTER bytes each), found by reading probes (one neighbour at a
 * time set in a 3 x 3 patch). Built once with a Skeleton's working space: built at
 * every call, they took 0.04 ms of the 1024 maze's 2.4 (the union-find of 256 masks
 * and the 4096 entries). */
static void thinner_init_tables(uint8_t *kind, uint8_t *ring)
{
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
		ring[r] = (uint8_t)m;
		kind[r] = kind8[m];
	}
}

/* thinner_heap_push(t, pi), thinner_heap_pop(t): Thinner.heap (a binary min-heap of
 * padded indices). */
static void thinner_heap_push(Thinner *t, int32_t pi)
{
	int32_t i = t->nheap++;
	while (i > 0 && t->heap[(i - 1) / 2] > pi) {
		t->heap[i] = t->heap[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	t->heap[i] = pi;
}
static int32_t thinner_heap_pop(Thinner *t)
{
	const int32_t top = t->heap[0], last = t->heap[--t->nheap];
	int32_t i = 0;
	for (;;) {
		int32_t c = 2 * i + 1;
		if (c >= t->nheap)
			break;
		if (c + 1 < t->nheap && t->heap[c + 1] < t->heap[c])
			c++;
		if (t->heap[c] >= last)
			break;
		t->heap[i] = t->heap[c];
		i = c;
	}
	t->heap[i] = last;
	return top;
}

/* thinner_push_again(t, pi): stacks pi's neighbours that are in the set and visited
 * (to be tried again now that pi is gone) and not stacked already. While a planed
 * level is visited (thinner_visit_level), a neighbour marked kept that is of that level
 * and past the visit's place was marked so before its turn, and is not visited yet: it
 * goes on the heap instead, to be visited at its turn, as its neighbourhood is no
 * longer what it was when it was found not deletable. */
static inline void thinner_push_again(Thinner *t, int32_t pi)
{
	for (int i = 0; i < 8; i++) {
		int32_t qi = pi + t->off[i];
		uint8_t st = t->state[qi];
		if ((st & (SKELETON_KEPT | SKELETON_STACKED)) == SKELETON_KEPT) {
			if (qi > t->pos && t->dist2[thinner_unpadded(t, qi)] == t->level) {
				if (!(st & SKELETON_QUEUED)) {
					t->state[qi] = st | SKELETON_QUEUED;
					thinner_heap_push(t, qi);
				}
				continue;
			}
			t->state[qi] = st | SKELETON_STACKED;
			t->stack[t->top++] = qi;
		}
	}
}

/* thinner_untrack(t, pi): pi, just deleted, out of the tracked set (Thinner.track). */
static inline void thinner_untrack(Thinner *t, int32_t pi)
{
	if (t->track) {
		const int32_t r = thinner_row(t, pi);
		skellevel_delete(t->track, r, pi - r * t->pw);
	}
}

/* thinner_delete_more(t, pi, top): deletes pi, then every visited cell that its
 * deletion (or a later one) makes deletable, with the re-try stack holding top cells
 * already. */
static void thinner_delete_more(Thinner *t, int32_t pi, int32_t top)
{
	t->state[pi] &= (uint8_t)~(SKELETON_IN | SKELETON_KEPT);
	thinner_untrack(t, pi);
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
		thinner_untrack(t, pi);
	}
}

/* thinner_delete_from(t, pi): deletes pi and whatever that makes deletable. */
void thinner_delete_from(Thinner *t, int32_t pi)
{
	thinner_delete_more(t, pi, 0);
}

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
#if defined(__GNUC__)
/* inlined by force into thinner_visit_all's two calls, so that each is a loop of its
 * own: GCC 12 kept one function testing prefetch on every visit, and, short of
 * registers, reloaded pw's offsets and the table from the stack (29.3 million
 * instructions in the visits on the 1024 maze, from 33.5; 0.4-0.8 ms less on every
 * 1024 grid, alternating runs in one session) */
__attribute__((always_inline))
#endif
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

/* thinner_visit_level(t, list, n, level): the visits of a planed level, dist2 level
 * (skellevel.c's NEXT LEVELS), the same as visits of all its cells in index order.
 * When the level starts, skellevel_next has marked its cells not deletable then as
 * visited and kept (SKELETON_KEPT), and listed the others in list[0 .. n), in index
 * order. A cell so marked, visited at its turn, would be kept, unless a neighbour was
 * deleted since the level started: the deletion puts it on the heap
 * (thinner_push_again), to be visited at its turn, merged with the list; one before
 * the visit's place is one visited and kept, and a deletion next to it tries it again,
 * as any. */
static void thinner_visit_level(Thinner *t, const int32_t *list, int32_t n, int32_t level)
{
	int32_t i = 0;
	t->nheap = 0;
	t->level = level;
	for (;;) {
		int32_t pi;
		if (t->nheap > 0 && (i == n || t->heap[0] < list[i]))
			pi = thinner_heap_pop(t);
		else if (i < n)
			pi = list[i++];
		else
			break;
		t->pos = pi;
		/* as thinner_visits, but the bytes may hold SKELETON_QUEUED: masked */
		const uint8_t *p = t->state + pi;
		const uint64_t rows =
		    (uint64_t)thinner_load4(p + t->pw - 1) << 32 | thinner_load4(p - t->pw - 1);
		const unsigned r = (unsigned)((((rows & THIN_ONES) * 0x0102040810204080u) >> 56) |
		                              (unsigned)(p[-1] & SKELETON_IN) << 8 |
		                              (unsigned)(p[1] & SKELETON_IN) << 10);
		const uint8_t kd = t->kind[r];
		if (kd == THIN_KEEP || (kd == THIN_RIDGE && thinner_ridge_end(t, pi, t->ring[r]))) {
			t->state[pi] = SKELETON_IN | SKELETON_KEPT;
			continue;
		}
		t->state[pi] = 0;
		thinner_untrack(t, pi);
		if (((rows & (THIN_ONES * SKELETON_KEPT)) | ((p[-1] | p[1]) & SKELETON_KEPT)) != 0)
			thinner_retry(t, pi);
	}
	t->pos = INT32_MAX;
	t->level = 0;
}

/* ---------------------------------------------------------------- the skeleton */

/* The higher levels are sorted from a list of their cells when they are at most this
 * share of the grid's cells (skelsort_listed), else with the whole grid
 * (skelsort_rows); at most a half, as the list, two values a cell, is kept in
 * the stack, one value a cell of the grid. */
#define SKELETON_LISTED 0.5

/* The working space of skeleton_compute, kept between calls so that computing the
 * skeleton of a grid of the same size again touches no new memory. */
struct SkeletonWork {
	size_t cells;   /* the grid size it was made for, w * h */
	uint8_t *state; /* (w + 2) * (h + 2) */
	int32_t *stack; /* w * h */
	uint64_t *ends; /* ceil((w + 2) (h + 2) / 64): the Thinner's */
	uint64_t *recheck; /* one word more, all zero between calls: the Thinner's */
	int32_t *order; /* w * h */
	int32_t *start; /* start_cap */
	size_t start_cap;
	SkelLevel level; /* the lowest level's bit planes (skellevel.c) */
	uint8_t kind[1u << THIN_RASTER], ring[1u << THIN_RASTER]; /* the Thinner's tables */
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
	free(wk->ends);
	free(wk->recheck);
	free(wk->order);
	free(wk->start);
	skellevel_free(&wk->level);
	free(wk);
}

void skeleton_free(Skeleton *s)
{
	free(s->dist2);
	free(s->on);
	free(s->plane);
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
		s->plane = util_alloc((size_t)(h + 2) * (size_t)skeleton_plane_words(w), 8);
		s->work = util_alloc(1, sizeof *s->work);
		s->work->cells = n;
		s->work->state = util_alloc(pn + 3, 1); /* + 3: thinner_raster's last load */
		s->work->stack = util_alloc(n, sizeof *s->work->stack);
		s->work->ends = util_alloc((pn + 63) / 64, sizeof *s->work->ends);
		s->work->recheck = util_alloc((pn + 63) / 64 + 1, sizeof *s->work->recheck);
		s->work->order = util_alloc(n, sizeof *s->work->order);
		thinner_init_tables(s->work->kind, s->work->ring);
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
	const int32_t maxd = skeleton_edt_scratch(g, s->dist2, (uint16_t *)(void *)wk->stack);
	assert((size_t)maxd + 2 <= wk->start_cap);

	Thinner t = {.w = w, .h = h, .pw = w + 2, .dist2 = s->dist2, .pos = INT32_MAX};
	t.state = wk->state;
	t.stack = wk->stack;
	t.ends = wk->ends;
	t.recheck = wk->recheck;
	t.ends_words = (int32_t)((pn + 63) / 64);
	memset(t.ends, 0, (size_t)t.ends_words * sizeof *t.ends);
	for (int i = 0; i < 8; i++) {
		t.off[i] = SKELETON_DX[i] + SKELETON_DY[i] * t.pw;
		t.doff[i] = SKELETON_DX[i] + SKELETON_DY[i] * w;
	}
	thinner_divisor(t.pw, &t.row_mul, &t.row_shift);
	t.kind = wk->kind;
	t.ring = wk->ring;

	/* The lowest level, dist2 1, by bit planes (skellevel.c); the padded state made
	 * from the planes' set. Then the visiting order: what is left of the lowest level,
	 * in index order, then the higher levels' cells sorted by dist2, ties by index; by
	 * a list of the higher cells where they are at most SKELETON_LISTED of the grid,
	 * else by a sort of the whole grid (the same order either way). */
	SkelLevel *lv = &wk->level;
	skellevel_thin(lv, g, (int32_t)(SKELETON_LISTED * (double)n));
	skellevel_state(lv, t.state, SKELETON_IN);
	memset(t.state + pn, 0, 3);
	int32_t nrest;
	if ((double)lv->nhigh <= SKELETON_LISTED * (double)n) {
		/* the rest of the lowest level; then each of the levels 2, 4 and 5, from its
		 * plane where it is planed (the set synced with the state first when visits
		 * since the planes were made may have deleted cells; the planed visits keep
		 * it in step), else from the list; then the listed higher levels
		 * (skellevel.c's NEXT LEVELS). A planed level's list of cells and its heap
		 * in order past the listed cells: they are at most that level's cells */
		nrest = skellevel_rest(lv, order);
		int32_t upto[SKELLEVEL_PLANED];
		const int32_t nlisted =
		    skelsort_listed(lv, s->dist2, start, order, maxd, nrest, wk->stack, upto);
		int32_t *scratch = order + nrest + nlisted;
		int32_t done = nrest;
		bool synced = nrest == 0; /* else the set is as the state was made from it */
		thinner_visit_all(&t, order, nrest);
		for (int j = 0; j < SKELLEVEL_PLANED; j++) {
			if (!lv->planed[j]) {
				thinner_visit_all(&t, order + done, upto[j] - done);
				synced = synced && upto[j] == done;
				done = upto[j];
				continue;
			}
			if (!synced)
				skellevel_sync(lv, t.state);
			synced = true;
			t.track = lv;
			const int32_t nd =
			    skellevel_next(lv, j, t.state, SKELETON_KEPT, t.ends, scratch);
			t.heap = scratch + nd;
			thinner_visit_level(&t, scratch, nd, skellevel_dist2[j]);
			t.track = NULL;
		}
		thinner_visit_all(&t, order + done, nrest + nlisted - done);
	} else {
		skelsort_rows(s->dist2, w, h, t.pw, start, order, maxd);
		const int32_t nblocked = (int32_t)n - lv->nlow - lv->nhigh;
		nrest = skellevel_count_rest(lv);
		int32_t *visit = order + nblocked + lv->nlow - nrest;
		skellevel_rest(lv, visit);
		thinner_visit_all(&t, visit, nrest + lv->nhigh);
	}
	s->pruned = thinner_prune(&t, order, maxd);

	/* the output, 8 cells at a time: bit 0 of each state byte, and their count; and
	 * the same 8 cells as the 8 bits of one byte of the plane (x is a multiple of 8,
	 * and each row's bits start on a word) */
	int32_t count = 0;
	const uint64_t ones = 0x0101010101010101u;
	for (int32_t y = 0; y < h; y++) {
		const uint8_t *st = t.state + (size_t)(y + 1) * t.pw + 1;
		uint8_t *on = s->on + (size_t)y * w;
		uint8_t *bits = s->plane + skeleton_plane_bit(w, 0, y) / 8;
		int32_t x = 0;
		for (; x + 8 <= w; x += 8) {
			uint64_t v;
			memcpy(&v, st + x, sizeof v);
			v &= ones * SKELETON_IN;
			memcpy(on + x, &v, sizeof v);
			count += (int32_t)((v * ones) >> 56);
			/* byte k (0 or 1) to bit k: each product term lands on its own bit */
			bits[x / 8] = (uint8_t)((v * 0x0102040810204080u) >> 56);
		}
		unsigned last = 0;
		for (int32_t k = 0; x < w; x++, k++) {
			on[x] = st[x] & SKELETON_IN;
			count += on[x];
			last |= (unsigned)on[x] << k;
		}
		if (w % 8)
			bits[w / 8] = (uint8_t)last;
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
