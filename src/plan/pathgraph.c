/* pathgraph.c - the pathgraph of a skeleton (paper 4.3, Figure 3): its build's steps (0)
 * and (1) (ranks, vertices, junction sets) and the incidence lists; steps (2) and (3),
 * the walk of the chains into edges, are pathwalk.c, the state both share
 * pathgraph_build.h. Finding paths on it is pathfind.c, checking and dumping it
 * pathcheck.c. See pathgraph.h for what the vertices, edges and paths are.
 *
 * ALGORITHM
 * Build, from the skeleton's bit plane (Skeleton.plane, 64 cells a word, made by
 *    skeleton_compute as it writes its output): the grid and the skeleton's bytes are
 *    not scanned, and every array the build writes is sized by the skeleton's cells,
 *    not the grid's. A
 *    skeleton cell's record (its cell_ref, pathgraph_cell_ref) is found by its rank,
 *    the skeleton cells before it in row-major order: a table holds the rank of each
 *    plane word's first bit, and a popcount of the word does the rest.
 *    (0) One pass over the plane's words, the empty ones skipped: the table of ranks,
 *    and the cells of degree other than 2, by bit arithmetic on the word and the four
 *    around it, each with its plane bit and rank. (1) Those cells are the vertex cells;
 *    4-adjacent junction cells are merged into a junction set by flood fill, placed at
 *    its cell of largest dist2, and a breadth-first tree inside the set (toward: a byte
 *    a skeleton cell, by rank, written on vertex cells alone) leads from any of its
 *    cells to that one. (2) From every vertex cell, every skeleton neighbour that is an
 *    unvisited chain cell (degree 2) starts a walk along the chain to the next vertex
 *    cell: that chain is an edge. The walk reads each cell's neighbours from the plane
 *    (three 16-bit loads) and a table, keeps the cell's rank (a step east or west is one
 *    rank on; north or south a popcount), takes a straight run east or west at once
 *    (its length from 64 bits of three rows) and measures the edge as it goes (length,
 *    clearance, the record's ref), so each chain cell is touched once. Two vertex
 *    cells of different vertices that touch are joined by an edge without chain cells.
 *    (3) Chain cells still unvisited lie on loops without a junction: the first of
 *    each in row-major order becomes a loop vertex and the loop an edge from it to
 *    itself. Vertices are numbered by their first cell in row-major order (loop
 *    vertices after the others), edges as found: the result depends on nothing else.
 *    A rebuild keeps every array.
 * Query: S' and D' by breadth-first search over free cells from S and D (4-connected,
 *    the topology of skeleton.h), testing each skeleton cell met with the line test
 *    and stopping once no nearer visible cell can be met (a cell in sight at distance e
 *    is at most sqrt(2) e + 1 steps away). Then A* (Hart, Nilsson and Raphael 1968, the
 *    paper's reference [8]) over the vertices plus S' and D', the edges holding S' or
 *    D' replaced by their pieces. k paths: Yen (1971), see pathgraph.h.
 *
 * INVARIANTS (pathgraph_validate): edge cells run from the cell of v0 to the cell of
 *    v1 along 4-adjacent skeleton cells; every skeleton cell is a vertex cell or an
 *    inner cell of exactly one edge; incident[] lists each edge under both its vertices
 *    (once for a loop).
 *
 * MEMORY  a record (4 bytes) and a junction-set parent direction (a byte, written
 *    on vertex cells alone) a skeleton cell, and the table of ranks (4 bytes a
 *    plane word: half a bit a grid cell); the edges' cells (4 + 4 bytes each);
 *    vertices and edges; and, for the
 *    queries, 12 bytes a grid cell of search scratch (a visit stamp, a parent and a
 *    queue entry: stamps spare clearing between queries).
 *
 * COMPLEXITY  build O(w h / 64) for the pass over the plane plus O(skeleton cells); a
 *    query O(cells searched for S' and D' + V log V + length of the edges holding S'
 *    and D' + cells of the path); k paths O(k L) such searches for routes of L arcs.
 *
 * MEASURED  on the bench-compare grids at 1024 x 1024 (issue 16), a rebuild on a grid of
 *    the same size. Instructions (callgrind --toggle-collect=pathgraph_build, exact;
 *    a driver building 3 times less one building once, over 2) before this file's
 *    masks, measuring walk and memset clearing, and after: rooms 5.76 -> 3.80 million
 *    (3.6 a grid cell), rects 6.62 -> 4.46 (4.3), maze 29.7 -> 23.0 (21.9; 255 000
 *    edge cells, 4.2 million of it the memset's loop), Boston_0_1024 4.48 -> 2.90
 *    (2.8), den520d 3.18 -> 1.97 (1.9); the same graph, array for array. Time,
 *    bench/skelbench --compare DIR --side 1024 (the pg column: median of 5 thread-CPU
 *    runs, the build just after the skeleton's, its caches cold), three runs each
 *    alternating with the former build, medians: rooms 1.37 -> 1.10 ms, rects 2.12
 *    -> 1.44, maze 7.2 -> 4.3, Boston_0_1024 1.05 -> 0.81, den520d 0.61 -> 0.55; one
 *    read pass over the grid 0.34 ms. The maze stays past issue 16's 2 ms: its walk
 *    is bound by memory (perf: the loads of dist2 and the stores to cell_ref, 4 MB
 *    each, in chain order, one new line a step down a corridor). At 4096 (skelbench
 *    --compare --side 4096, one run each, medians of 5): rooms 30.4 -> 23.8 ms, rects
 *    39.1 -> 29.6, maze 121 -> 88 (4.0 million skeleton cells: 22 ns each, 17 at
 *    1024), Boston_0_1024 8.7 -> 6.4, den520d 4.5 -> 3.8; 20-22 times the 1024 figure
 *    for 16 times the cells on the synthetic grids, the caches' share. Earlier, a corner
 *    to corner query 0.18-0.2 ms, 1.4 ms in the maze, whose path has 60 000 cells to
 *    write out; 116 (maze) to 600 (rooms) times fewer vertices expanded than a grid
 *    A* expands cells on the same query.
 *    Then the walk by a branch on the direction (builder_edge_from): instructions
 *    about equal (maze 23.0 -> 22.2 million, 21.2 a grid cell; rooms 3.80 -> 3.74,
 *    rects 4.46 -> 4.39, Boston_0_1024 2.90 -> 2.90, den520d 1.97 -> 1.95); the pg
 *    column at 1024, three runs alternating, medians: maze 4.20 -> 3.92 ms (15.7 ns
 *    a skeleton cell), rooms 1.01 -> 0.93, rects 1.40 -> 1.30, Boston_0_1024 0.79 ->
 *    0.86 (within the noise: load 5-6 on 2 cores), den520d 0.47 -> 0.45; at 4096,
 *    one run each: rooms 22.6 -> 18.7 ms, rects 28.2 -> 24.7, maze 82.9 -> 76.1
 *    (19.1 ns a skeleton cell), Boston_0_1024 6.0 -> 5.8, den520d 3.16 -> 3.09:
 *    19-20 times the 1024 figure on rooms and the maze for 16-17 times the skeleton
 *    cells, 7 times on Boston and den520d for 4.1-4.4 times (their grid, scanned
 *    whole, 16 times). Then straight on tested first in the walk and cell_edge
 *    filled four cells a store: maze 22.2 -> 20.8 million instructions (19.8 a grid
 *    cell, 81 an edge cell), rooms 3.74 -> 3.55, rects 4.39 -> 4.17,
 *    Boston_0_1024 2.90 -> 2.78, den520d 1.95 -> 1.89; in time within the noise. The
 *    maze stays past issue 16's 2 ms. Where its time goes (a copy timing each step,
 *    mean of 30 rebuilds, each after a skeleton_compute as in skelbench): the
 *    clearing 0.28 ms, step (1) 0.85, step (2) 2.5, of which the walk's loads of
 *    dist2 0.8 (the walk without them). Tried and not kept, the same graph each
 *    time, slower or no faster on the maze: the skeleton handing over a row-major
 *    list of its cells, step (1) and the clearing working from it (the last build's
 *    cells not in this one set back to -1 by merging the two lists, the cells taken
 *    told by a mask bit rather than cell_ref; one run each): maze 1024 +20%, rooms
 *    4096 -4%, Boston 4096 -5%, step (1) slower but on the maze at 4096 (rooms 4096
 *    4.8 -> 5.8 ms, Boston 2.2 -> 3.1: each cell's rows above and below a line of
 *    their own); masks in 8 x 8 tiles (one line each, so a walk up a corridor keeps
 *    its line) with a corner bit in place of the corner's dist2 load: step (2) no
 *    faster, step (1) 2.5 times slower (its scattered stores); a walk reading only
 *    the masks, then measuring the chain in a loop of its own: slower; prefetching 2
 *    or 4 cells ahead in the walk's direction: slower.
 *    Then the build from the skeleton's bit plane and records by rank (ALGORITHM above;
 *    issue 16's goal, 2 ms on every grid at 1024 and 4096, cannot be met by a build
 *    that reads the grid: one read pass over a 4096 grid's bytes costs 5.6 ms here).
 *    The same graph, array for array and cell_ref for cell_ref, on the ten bench grids
 *    (1024 and 4096), and against a brute-force build in the tests. Instructions of a
 *    rebuild (callgrind as above, 1024): rooms 3.55 -> 4.33 million (115 a skeleton
 *    cell), rects 4.17 -> 5.11 (114), maze 20.8 -> 24.8 (100), Boston_0_1024 2.78 ->
 *    3.05 (114), den520d 1.89 -> 1.59 (119): more instructions (the walk's neighbours
 *    from the plane, about 21 a step by bits and bytes, 13 by three 16-bit loads; a
 *    popcount a step north or south, 12 without the popcnt instruction, hence the
 *    target clone), far fewer lines: no grid-sized mask, cell_ref or clearing (the
 *    maze's rebuild, callgrind --cache-sim: first-level read misses 257 000 -> 202 000,
 *    write misses 249 000 -> 116 000). Time, a driver timing pathgraph_build alone
 *    after writing 64 MB to flush the caches (thread CPU, min of 7 builds, the median
 *    of 3 rounds alternating with the former build, the machine loaded, load 5-9 on 2
 *    cores): 1024 rooms 0.73 -> 0.62 ms, rects 1.17 -> 0.76, maze 3.45 -> 3.34,
 *    Boston_0_1024 0.61 -> 0.44, den520d 0.43 -> 0.22; 4096 rooms 19.1 -> 14.9, rects
 *    25.1 -> 20.4, maze 74.9 -> 59.0, Boston_0_1024 5.45 -> 2.86, den520d 2.69 -> 1.31;
 *    skelbench --compare in one session (the pg column, medians of 5, load 9 on 2
 *    cores): 1024 rooms 0.65 ms, rects 1.00, maze 3.06, Boston_0_1024 0.51, den520d
 *    0.32; 4096 13.9, 22.6, 62.0, 3.14, 1.73. What is left is 13-15 ns a skeleton cell
 *    on the maze (3.34 ms for 248 714 cells at 1024, 59.0 for 3 975 639 at 4096), 24-28
 *    on rooms, rects and Boston_0_1024 at 4096 (staircases, a turn a step): the walk's
 *    70-80 instructions a cell and its loads of dist2, a grid-sized array read in chain
 *    order (perf, Boston_0_1024 at 4096: 60% of the walk waits on the load of dist2 and
 *    the cut corner's). So 2 ms holds 80 000 to 140 000 skeleton cells: met on every
 *    1024 grid but the maze and on den520d at 4096 (55 134 cells); not on Boston_0_1024
 *    at 4096 (119 016), rooms and rects there (631 557, 725 098) or the maze (248 714,
 *    3 975 639). Tried and dropped: each skeleton cell's dist2 copied into its record
 *    in the first pass (so that the walk reads only skeleton-sized arrays): the copy,
 *    made in row-major order, waits on a page walk for each cell of a north-south run
 *    (rows 16 KB apart at 4096), and Boston_0_1024 at 4096 took 10.5 ms instead of 5.5;
 *    the corner's free test by the grid's byte instead of dist2 (a line of its own at
 *    every turn): the maze slower. Then a prefetch of dist2 8 rows on at each step
 *    north or south (PATHGRAPH_AHEAD; slower when the walk also read and wrote
 *    grid-sized masks and cell_ref, above, but now dist2 is the walk's one grid-sized
 *    array): the same driver, medians of 3 rounds alternating with the build without
 *    it, loaded machine: Boston_0_1024 at 4096 2.65 -> 2.41 ms, den520d 1.31 -> 1.23,
 *    rooms 14.7 -> 13.5, rects 20.2 -> 18.5, the maze at 1024 3.11 -> 2.89 (16 rows
 *    on: 2.56, 1.27, 14.2, 19.1, 3.22).
 *    Then toward by rank (a byte a skeleton cell, not the grid: its loads at each
 *    junction missed the caches after skeleton_compute, a quarter of step (1) on the
 *    maze), the walk's runs east and west at once, the vertex cells' plane bits and
 *    ranks carried from step (0) (no division, and a popcount only north or south),
 *    the root path of a one-cell vertex without a load, and steps (0) to (2) with the
 *    popcnt instruction. The same graph, array for array (a hash of every array and of
 *    pathgraph_cell_ref of every cell, the ten bench grids). skelbench --compare DIR
 *    MAP... (both sides), three sessions alternating with the build before, load 9-10
 *    on 2 cores, the medians of the sessions' pg medians: 1024 rooms 0.62 -> 0.51 ms,
 *    rects 0.91 -> 0.73, maze 2.92 -> 2.32, Boston_0_1024 0.48 -> 0.45, den520d 0.25
 *    -> 0.24; 4096 rooms 12.0 -> 10.4, rects 17.5 -> 14.2, maze 53.7 -> 49.3,
 *    Boston_0_1024 2.41 -> 2.20, den520d 1.24 -> 1.11. The maze at 1024 with --side
 *    1024, five sessions alternating, load 8: 2.31 -> 1.92 ms (2.52 -> 2.14 in five
 *    more). Its build with the caches warm (a driver building 31 times without the
 *    skeleton between, medians) 1.50 ms, 6.0 ns a skeleton cell; just after the
 *    skeleton on the loaded machine 1.9 to 2.4: issue 16's 2 ms is met on the maze only
 *    in the quieter sessions. Its time (perf, warm): the walk 58%, its steps north and
 *    south the most (each a new line of dist2), step (1) and the loop over the vertex
 *    cells 27%. Floors, the least ns a skeleton cell reached: maze 6.0 (1024, warm),
 *    11-12 (4096); rooms 16, rects 19 (4096: staircases, a turn a step); Boston_0_1024
 *    8 (4096, warm) to 18 (in the sessions). 2 ms needs 0.5 ns a cell on the maze at
 *    4096 (3 975 639 cells): less than the writing of its 12 bytes of output a cell
 *    (cells, cell_edge and the record, 48 MB) and a tenth of one read pass over that
 *    grid's bytes (5.6 ms): out of reach of any build that writes the graph. Rooms and
 *    rects at 4096 need 3.2 and 2.8 ns a cell (631 557, 725 098 cells), a fifth of the
 *    least reached there, about one mispredicted branch at the turn of each step:
 *    out of reach of this walk. Boston_0_1024 at 4096 needs 16.8 (119 016 cells):
 *    within 10% (2.11-2.23 ms in these sessions). Tried and dropped, the same graph,
 *    no faster alternating: each skeleton cell's dist2 gathered in rank order in step
 *    (0)'s pass (on the maze at 1024 the gather costs 0.22 ms; every dist2 load of the
 *    walk costs 0.19, measured by leaving them out), and so not asked of
 *    skeleton_compute's output loop either, whose gather would cost it as much (the
 *    skeleton was 2.4-3.0 ms on that maze then, at its goal against scikit-image with
 *    no margin; since skel11's round it is 2.26 ms, skeleton_compute alternating, and
 *    skeletonize / utak 7.35 at 1024 and 6.33 at 4096: README's Benchmarks); a run north or south a cell at a time; the corner's fourth cell free by
 *    the last cell's dist2 > 2 (no load); a prefetch extrapolated from the cell 8
 *    steps back, or 4 or 16 rows on; step (0)'s empty words told by a mask, without a
 *    branch; the walk made twice, without the loop's stop test for steps (2).
 *    Then the scaling round (issue 16, "costs linear in cells from 256 to 4096";
 *    `skelbench --scaling`): from 256 to 4096 the build cost 2.0-2.9 times as much a
 *    grid cell on rooms and rects, 1.7-1.9 on the maze, while its instructions grow
 *    with the cells (maze, 1024 to 4096: 16.1 times; callgrind's simulated 32 MB last
 *    level: no read misses at 1024, 0.3 a skeleton cell at 4096, most in the walk).
 *    perf, rooms at 4096: 47% of the walk on two loads of dist2, the cell's and the
 *    cut corner's.
 *    The rooms' diagonals are staircases: 8 rows on, the walk is 8 cells (32 bytes)
 *    east or west of the cell the single prefetch asked for. PATHGRAPH_AHEAD now asks
 *    for three lines 16 rows on, 16 cells either side too. The same graph, array for
 *    array (hashes of every array and cell_ref against the former pathgraph.c linked
 *    in one driver under other names: 1500 random grids, the bench grids); that
 *    driver, old and new alternating after a skeleton_compute, medians of 9 to 41
 *    (load 5-7): 4096 rooms 9.68 -> 8.15 ms, rects 13.06 -> 10.54, maze 42.2 -> 38.7,
 *    Boston_0_1024 2.04 -> 1.81, den520d 0.98 -> 0.97; 2048 1.06-1.26 times faster;
 *    1024 rooms 0.57 -> 0.41, rects 0.79 -> 0.57, maze 2.29 -> 2.07, Boston_0_1024
 *    0.48 -> 0.38, den520d 0.12 -> 0.12; 256 and 512 0.97-1.01. Also measured: 8 rows
 *    on, two lines (1.08-1.16 at 4096); 24 or 32 rows, 4 or 5 lines (rooms and rects
 *    1.27-1.36, Boston_0_1024 and den520d 0.91-1.00); 6 or 12 rows, two lines (less).
 *    Dropped: the edge measured after its walk in a loop of its own (edgerun_push,
 *    the same doubles, independent loads): old / new 1.05 at 4096 on rooms and rects,
 *    0.96 on the maze, 0.86-0.94 at 1024; the first 16 rows of a walk prefetched at
 *    its start: 0.99-1.02; 2 MB pages (glibc.malloc.hugetlb=1): within the noise.
 *    Then the file split (1011 lines): steps (2) and (3) to pathwalk.c, the state
 *    they share to pathgraph_build.h, no code changed (objdump: builder_edge_from,
 *    builder_edges and builder_vertices the same instructions but for assert's line
 *    numbers; builder_loops now inlined into pathgraph_build_edges, not
 *    pathgraph_build). make golden regenerates nothing; skelbench --scaling 5, old
 *    and new alternating twice in one session (load 7 on 2 cores), pg ns a cell,
 *    old / new: 4096 rooms 0.51 0.51 / 0.52 0.53, rects 0.71 0.72 / 0.70 0.70, maze
 *    2.52 2.62 / 2.49 2.62; 1024 rooms 0.41 0.39 / 0.38 0.42, rects 0.50 0.53 / 0.57
 *    0.57, maze 1.83 1.90 / 1.83 2.03: within the noise.
 *    Then VERTEX AHEAD (issue 16's fifth round of plain A*, 2026-11-27): perf put 7%
 *    of a driver's samples (skeleton_compute then pathgraph_build on the 1024 maze)
 *    in builder_vertex_at, 70% of them on the load of the vertex's dist2 in
 *    builder_add_vertex, a miss for each candidate (they lie far apart in row-major
 *    order); step (1)'s loop over the candidates now asks for the dist2 of the one 8
 *    on: 2.8% of the samples. pathgraph_build's thread CPU after each
 *    skeleton_compute, medians of 10 builds, six rounds alternating with the build
 *    before, load 12 on 2 cores: maze 1024 1.75-1.84 ms (median 1.80) -> 1.60-1.85
 *    (1.70); 4 on 1.73, 16 on 1.81 (three rounds). Three rounds: maze 4096 40.2-41.0 ->
 *    38.0-39.1, rooms 4096 8.4-8.8 -> 7.4-7.9, rooms 1024 0.34-0.42 -> 0.28-0.41,
 *    Boston_0_1024 0.23-0.33 -> 0.28-0.33 (within the noise). The same graph (a
 *    prefetch changes no value). Still: the walk (builder_edge_from) 58% of the
 *    build, and builder_root_path's read of the far vertex's set_size, a miss at
 *    the end of each walk (65% of that function).
 *    Then STREAMING (issue 16's seventh round, 2026-11-27): a build in raster order,
 *    measured and not kept. A prototype driver (not kept) made the chains in one pass
 *    over the plane in rank order, each chain cell joined to its earlier neighbours
 *    (west, the row before) by a union-find whose links carry an orientation and an
 *    offset (the cell's place in its fragment), the fragment's least dist2 and each
 *    cell's cut-corner flag taken as it went; a second pass in rank order found each
 *    cell's place and scattered cells[], cell_edge[] and the flags there; a third
 *    summed each fragment's length in order. That is the chains alone: no vertices,
 *    junction sets, root paths or edge order. pathgraph_build, the whole of it, and the
 *    prototype after each skeleton_compute, medians of 9 (1024) and 5 (4096), load
 *    1-2: 1024 rooms 0.23 against 0.95 ms, rects 0.43 / 1.88, maze 1.71 / 7.63; 4096
 *    rooms 7.8 / 35.3, rects 10.3 / 52.5, maze 38.4 / 127: 3.3 to 5.1 times slower, and
 *    no more linear (rooms 25 -> 56 ns a skeleton cell from 1024 to 4096, the build 6
 *    -> 12). Its passes at 4096: the union-find 25.4 (rooms), 36.2 (rects), 61
 *    (maze) ms, and 8.4 and 12.0 on rooms and rects with dist2 not loaded (so there
 *    the loads of dist2, in raster order but inside that branchy loop, cost 17 and 24
 *    ms, where skelbench --pgfloor's plain gather costs 3.5 and 4.2: FLOOR below); the
 *    placing pass 9.6, 17.8, 88 ms; the lengths 1.6, 3.0, 22. Finds took 2.1-2.35 hops
 *    a cell. The scatter itself is not the cost: writing 4 bytes a chain cell from
 *    rank order to its place in chain order alone took 0.04, 0.06, 0.29 ms at 1024 and
 *    0.7, 1.0, 5.0 at 4096 (load 13). Why not kept: cells[] is in chain order (edge
 *    after edge, each from v0 to v1: the graph must stay the same, array for array),
 *    so a raster build must rank each cell along its chain (list ranking), which the
 *    walk does by walking and the union-find by 2 finds and a handful of branches on
 *    the data at every cell (which neighbours came earlier, which end of a fragment, a
 *    merge), where the walk's branches go straight down a corridor; the union-find
 *    pass alone costs more than the whole build. A sparse build from a row-sorted list
 *    of the cells has the same ranking to do.
 *    FLOOR: skelbench --pgfloor (bench/skelbench.c) times what any build must read and
 *    write, alone, after each skeleton_compute (medians of 7, load 3-6): at 4096 the
 *    gather of every skeleton cell's dist2 in row-major order (an edge's clearance
 *    needs each) costs rooms 3.47 ms (631 557 cells on 311 159 lines of 64 bytes),
 *    rects 4.17 (725 098 cells, 365 225 lines), maze 3.87 (3 975 639 cells, 993 784
 *    lines: all 64 MB of dist2), and writing the graph (8 bytes an edge cell and the
 *    4-byte record, 7.7, 8.9 and 48.6 MB) 0.24, 0.36 and 1.35; the plane's read pass
 *    (2.2 MB) 0.08. So on these three grids issue 16's 2 ms at 4096 is below what
 *    reading their dist2 once costs streamed: out of reach of any build that reads
 *    each skeleton cell's dist2. The build stands at 2.1 (rooms: 8.1 ms against a
 *    floor of 3.8), 2.35 (rects, 10.8 / 4.6) and 7.5 times (maze, 39.7 / 5.3) that
 *    floor at 4096, 4.9 times on the maze at 1024 (1.72 / 0.35 ms), about 2 on rooms
 *    and rects there. On the sparse skeletons of Boston_0_1024 and den520d at 4096
 *    (a few cells a row) the gather waits on each line and the build, whose walk
 *    fetches dist2 16 rows ahead, beats it (2.01 against 2.05 ms, 1.03 against 1.37):
 *    no bound there (a gather that also asked for the cells 16 rows on: the same).
 *    Then ROOT BY TOWARD (pathwalk.c, builder_root_path): the root path reads toward[]
 *    at the vertex cell's rank, which the walk has in hand, in place of the vertex's
 *    set_size, a load that waited on the load of the far vertex's record (two misses
 *    in a row at the end of each walk; toward is 0 at a root, so a one-cell vertex
 *    still costs one load). The same graph: hashes of every array and of
 *    pathgraph_cell_ref of every skeleton cell on 1500 random grids (up to 300 x 300,
 *    random densities and blocks) and 15 bench grids (rooms, rects, maze,
 *    Boston_0_1024, den520d at 256, 1024 and 4096) against a71c967's library.
 *    pathgraph_build after each skeleton_compute, medians of 21 (1024) and 7 (4096),
 *    three sessions of 5, 5 and 7 rounds alternating with a71c967's, load 6-9, ms:
 *    maze 4096 40.9 -> 39.4, 42.9 -> 40.3, 39.1 -> 38.2 (2-6% less); rects 4096 11.39
 *    -> 11.40, 11.32 -> 10.93, 11.27 -> 11.04; rooms 4096 8.10 -> 8.15, 8.02 -> 7.96,
 *    7.88 -> 7.94; Boston_0_1024 4096 2.13 -> 2.13, 2.04 -> 1.97, 2.00 -> 2.03;
 *    den520d 4096 1.15 -> 1.13; maze 1024 1.80 -> 1.82, 1.65 -> 1.69, 1.69 -> 1.65;
 *    rooms, rects and Boston_0_1024 at 1024 within 10% either way (0.22 to 0.51 ms):
 *    a gain on the maze at 4096 alone, the rest within the noise. Tried and dropped:
 *    the record of the cell 16 rows on prefetched at each step north or south (the
 *    maze's records are 16 MB at 4096), its rank from that row's word's first rank:
 *    maze 4096 40.3 -> 39.6 past ROOT BY TOWARD, maze 1024 1.69 -> 1.73, rects 4096
 *    10.9 -> 11.5. */
#include "utak/plan/pathgraph.h"

#include <assert.h>
#include <stdlib.h>
#include <string.h>

#include "pathgraph_build.h"
#include "pathgraph_work.h"
#include "utak/base/util.h"
#include "utak/plan/heap.h"

/* ---------------------------------------------------------------- build */

void pathgraph_init(Pathgraph *pg)
{
	*pg = (Pathgraph){0};
}

static void pathgraph_free_scratch(struct PathgraphScratch *sc)
{
	if (!sc)
		return;
	free(sc->visit);
	free(sc->parent);
	free(sc->queue);
	free(sc->g);
	free(sc->pred_arc);
	free(sc->pred_node);
	free(sc->seen);
	free(sc->closed);
	free(sc->node_ban);
	free(sc->arc_ban);
	heap_free(&sc->heap);
	free(sc->walk_s.v);
	free(sc->walk_d.v);
	free(sc->cells.v);
	free(sc->toward);
	free(sc->built_vcells.v);
	free(sc->vstart.v);
	free(sc->cell_of);
	free(sc->cand.v);
	free(sc->rank_base);
	free(sc);
}

void pathgraph_free(Pathgraph *pg)
{
	free(pg->vertices);
	free(pg->edges);
	free(pg->cells);
	free(pg->incident_start);
	free(pg->incident);
	free(pg->cell_edge);
	pathgraph_free_scratch(pg->scratch);
	*pg = (Pathgraph){0};
}


/* builder_near_rank(b, cb, rk, d): the rank of the skeleton cell next to the skeleton
 * cell of plane bit cb and rank rk in direction d: one on or back east or west, else
 * counted. */
static inline int32_t builder_near_rank(const Builder *b, int32_t cb, int32_t rk, int d)
{
	if (d == 0)
		return rk + 1;
	if (d == 2)
		return rk - 1;
	return pathgraph_rank(b->plane, b->base, cb + (d == 1 ? b->row_bits : -b->row_bits));
}

/* The toward of a junction-set cell that the breadth-first tree has not reached yet. */
enum { PATHGRAPH_UNSEEN = 0xff };

/* builder_junction_set(b, seed, seed_cb, seed_rk): floods the junction set of seed (of
 * plane bit seed_cb and rank seed_rk) into a new vertex, placed at its cell of largest
 * dist2 (the first such in flood order), and records in toward[] (by rank) the
 * breadth-first tree from that cell. */
static void builder_junction_set(Builder *b, int32_t seed, int32_t seed_cb, int32_t seed_rk)
{
	Pathgraph *pg = b->pg;
	const int32_t step[4] = {1, pg->w, -1, -pg->w};
	const int32_t bstep[4] = {1, b->row_bits, -1, -b->row_bits};
	int32_t v = builder_add_vertex(b, seed, seed_rk, PATHGRAPH_JUNCTION);
	int first = b->vcells.count;
	intlist_push(&b->vcells, seed);
	for (int k = first; k < b->vcells.count; k++) {
		const int32_t c = b->vcells.v[k], cb = k == first ? seed_cb : builder_bit(b, c);
		const int32_t crk = k == first ? seed_rk : pathgraph_rank(b->plane, b->base, cb);
		const unsigned m = pathgraph_plane_mask(b->plane, cb, b->row_bits);
		for (int d = 0; d < 4; d++) {
			if (!(m >> PATHGRAPH_MASK_BIT[d] & 1))
				continue;
			const int32_t nb = c + step[d];
			const int32_t nr = builder_near_rank(b, cb, crk, d);
			if (b->cell[nr].ref == PATHGRAPH_REF_NONE &&
			    PATHGRAPH_POP4[pathgraph_plane_mask(b->plane, cb + bstep[d],
			                                        b->row_bits)] >= 3) {
				b->cell[nr].ref = v;
				b->toward[nr] = PATHGRAPH_UNSEEN;
				intlist_push(&b->vcells, nb);
			}
		}
	}
	int n = b->vcells.count - first;
	if (n > b->max_set)
		b->max_set = n;
	if (n == 1)
		return; /* the seed alone, its own root: as builder_add_vertex made it */
	int32_t root = seed;
	for (int k = first; k < b->vcells.count; k++)
		if (b->s->dist2[b->vcells.v[k]] > b->s->dist2[root])
			root = b->vcells.v[k];
	/* re-order the set's cells breadth-first from the root, recording parents */
	b->vcells.count = first;
	intlist_push(&b->vcells, root);
	b->toward[pathgraph_rank(b->plane, b->base, builder_bit(b, seed))] = PATHGRAPH_UNSEEN;
	b->toward[pathgraph_rank(b->plane, b->base, builder_bit(b, root))] = 0;
	for (int k = first; k < b->vcells.count; k++) {
		const int32_t c = b->vcells.v[k], cb = builder_bit(b, c);
		const unsigned m = pathgraph_plane_mask(b->plane, cb, b->row_bits);
		for (int d = 0; d < 4; d++) {
			if (!(m >> PATHGRAPH_MASK_BIT[d] & 1))
				continue;
			const int32_t nr = pathgraph_rank(b->plane, b->base, cb + bstep[d]);
			if (b->cell[nr].ref == v && b->toward[nr] == PATHGRAPH_UNSEEN) {
				b->toward[nr] = (uint8_t)(1 + (d + 2) % 4);
				intlist_push(&b->vcells, c + step[d]);
			}
		}
	}
	assert(b->vcells.count - first == n);
	pg->vertices[v].x = root % pg->w;
	pg->vertices[v].y = root / pg->w;
	pg->vertices[v].set_size = n;
	pg->vertices[v].dist2 = b->s->dist2[root];
}

/* How many candidates ahead builder_vertices asks for a vertex's dist2 (VERTEX AHEAD,
 * MEASURED). */
#define PATHGRAPH_VERTEX_AHEAD 8

/* builder_vertex_at(b, i, cb, rk, d): the vertex whose first cell is i (plane bit cb,
 * rank rk), of degree d != 2. */
static void builder_vertex_at(Builder *b, int32_t i, int32_t cb, int32_t rk, int d)
{
	intlist_push(&b->vstart, b->vcells.count);
	if (d >= 3) {
		builder_junction_set(b, i, cb, rk);
	} else {
		builder_add_vertex(b, i, rk, d == 1 ? PATHGRAPH_END : PATHGRAPH_POINT);
		intlist_push(&b->vcells, i);
	}
}

/* builder_vertices(b): step (1). First, one pass over the skeleton's plane, 64 cells
 * a word, the empty words skipped: the rank of each word's first bit, each skeleton
 * cell's record in rank order (its ref, set later: a copy of its dist2 in the record
 * was tried and dropped, MEASURED), and the cells of
 * degree other than 2, found from the four words around by bit arithmetic. Then the
 * vertices, in row-major order of their first cell: a junction set's flood reaches
 * cells past the one it starts at, so it waits for every record. The grid itself is
 * not read. */
PATHGRAPH_CLONES static void builder_vertices(Builder *b, IntList *cand)
{
	Pathgraph *pg = b->pg;
	const int32_t w = pg->w, h = pg->h, words = skeleton_plane_words(w);
	const int32_t last = 1 + (w - 1) / 64; /* the last word of a row holding cells */
	int32_t *base = b->sc->rank_base;
	PathgraphCell *cell = b->cell;
	int32_t rank = 0;
	cand->count = 0;
	for (int32_t y = 0; y < h; y++) {
		const size_t wi = (size_t)(y + 1) * (size_t)words;
		const uint8_t *row = b->plane + wi * 8;
		const uint8_t *above = row + (size_t)words * 8, *below = row - (size_t)words * 8;
		for (int32_t j = 1; j <= last; j++) {
			base[wi + (size_t)j] = rank;
			const uint64_t here = pathgraph_load64(row + 8 * j);
			if (here == 0)
				continue;
			rank += PATHGRAPH_POPCOUNT(here);
			const uint64_t e = here >> 1 | pathgraph_load64(row + 8 * (j + 1)) << 63,
			               wst = here << 1 | pathgraph_load64(row + 8 * (j - 1)) >> 63,
			               nth = pathgraph_load64(above + 8 * j),
			               sth = pathgraph_load64(below + 8 * j);
			/* degree exactly 2: e + wst = s1 + 2 c1, nth + sth = s2 + 2 c2 */
			const uint64_t s1 = e ^ wst, c1 = e & wst, s2 = nth ^ sth, c2 = nth & sth;
			const uint64_t two = (s1 & s2 & ~(c1 | c2)) | (~(s1 | s2) & (c1 ^ c2));
			/* each as its cell, plane bit and rank */
			for (uint64_t t = here & ~two; t; t &= t - 1) {
				const int z = pathgraph_ctz64(t);
				intlist_push(cand, y * w + (j - 1) * 64 + z);
				intlist_push(cand, (int32_t)(wi + (size_t)j) * 64 + z);
				intlist_push(cand, rank - PATHGRAPH_POPCOUNT(here >> z));
			}
		}
	}
	assert(rank == b->s->count);
	memset(cell, 0xff, (size_t)rank * sizeof *cell); /* all PATHGRAPH_REF_NONE */
	for (int k = 0; k < cand->count; k += 3) {
		const int32_t i = cand->v[k], cb = cand->v[k + 1], rk = cand->v[k + 2];
#if defined(__GNUC__)
		/* VERTEX AHEAD (MEASURED): the dist2 that the vertex of the candidate
		 * PATHGRAPH_VERTEX_AHEAD on will read (a hint: no effect on the graph) */
		if (k + 3 * PATHGRAPH_VERTEX_AHEAD < cand->count)
			__builtin_prefetch(b->s->dist2 + cand->v[k + 3 * PATHGRAPH_VERTEX_AHEAD]);
#endif
		if (b->cell[rk].ref == PATHGRAPH_REF_NONE)
			builder_vertex_at(
			    b, i, cb, rk,
			    PATHGRAPH_POP4[pathgraph_plane_mask(b->plane, cb, b->row_bits)]);
	}
	intlist_push(&b->vstart, b->vcells.count);
}

void pathgraph_build(Pathgraph *pg, const Skeleton *s, const Grid *g)
{
	/* keep the query scratch and the arrays of the last build */
	if (!pg->scratch)
		pg->scratch = util_alloc(1, sizeof *pg->scratch);
	struct PathgraphScratch *sc = pg->scratch;
	const size_t words = (size_t)(s->h + 2) * (size_t)skeleton_plane_words(s->w);
	if (sc->rank_words != words || !sc->rank_base) {
		free(sc->rank_base);
		sc->rank_base = util_alloc(words, sizeof *sc->rank_base);
		sc->rank_words = words;
	}
	sc->cell_of = util_grow(sc->cell_of, &sc->cell_cap, s->count + 1, sizeof *sc->cell_of);
	sc->toward = util_grow(sc->toward, &sc->toward_cap, s->count + 1, 1);
	pg->w = s->w;
	pg->h = s->h;
	pg->grid = g;
	pg->skeleton = s;
	pg->vertex_count = pg->edge_count = pg->cell_count = 0;
	assert(s->plane); /* made by skeleton_compute */
	Builder b = {.pg = pg,
	             .s = s,
	             .sc = sc,
	             .toward = sc->toward,
	             .plane = s->plane,
	             .row_bits = 64 * skeleton_plane_words(s->w),
	             .base = sc->rank_base,
	             .cell = sc->cell_of,
	             .max_set = 1};
	b.vcells = sc->built_vcells; /* its memory, reused */
	b.vcells.count = 0;
	b.vstart = sc->vstart;
	b.vstart.count = 0;

	builder_vertices(&b, &sc->cand);
	b.chain_left = s->count - b.vcells.count;
	b.ref_base = pg->vertex_count;
	pathgraph_build_edges(&b); /* pathwalk.c */
	pg->cell_count = b.count;

	/* incidence lists */
	const int32_t nv = pg->vertex_count, ne = pg->edge_count;
	pg->incident_start = util_grow(pg->incident_start, &sc->incident_start_cap, nv + 1,
	                               sizeof *pg->incident_start);
	pg->incident = util_grow(pg->incident, &sc->incident_cap, 2 * ne + 1, sizeof *pg->incident);
	int32_t *start = pg->incident_start;
	memset(start, 0, ((size_t)nv + 1) * sizeof *start);
	for (int32_t e = 0; e < ne; e++) {
		start[pg->edges[e].v0 + 1]++;
		if (pg->edges[e].v1 != pg->edges[e].v0)
			start[pg->edges[e].v1 + 1]++;
	}
	for (int32_t v = 0; v < nv; v++)
		start[v + 1] += start[v];
	/* fill by the start entries, which move up to the next vertex's; then back */
	for (int32_t e = 0; e < ne; e++) {
		int32_t a = pg->edges[e].v0, c = pg->edges[e].v1;
		pg->incident[start[a]++] = e;
		if (c != a)
			pg->incident[start[c]++] = e;
	}
	for (int32_t v = nv; v > 0; v--)
		start[v] = start[v - 1];
	start[0] = 0;
	sc->built_vcells = b.vcells;
	sc->vstart = b.vstart;
}

int32_t pathgraph_cell_ref(const Pathgraph *pg, int32_t i)
{
	if (!pg->scratch || !pg->skeleton)
		return PATHGRAPH_REF_NONE;
	const int32_t y = i / pg->w, cb = (int32_t)skeleton_plane_bit(pg->w, i - y * pg->w, y);
	const uint8_t *plane = pg->skeleton->plane;
	if (!(plane[cb >> 3] >> (cb & 7) & 1))
		return PATHGRAPH_REF_NONE;
	return pg->scratch->cell_of[pathgraph_rank(plane, pg->scratch->rank_base, cb)].ref;
}
