/* test_skeleton.c - the distance transform and the skeleton (skeleton.h, paper 4.2),
 * against brute-force oracles: an O(n^2) distance transform, and flood-fill counts of
 * components and holes under the (4, 8) topology of skeleton.h. */
#include <stdlib.h>
#include <string.h>

#include "oracle.h"
#include "test.h"
#include "utak/plan/skeleton.h"

/* brute_edt: the definition, with the ring of cells just outside the grid blocked. */
static int32_t brute_edt_at(const Grid *g, int x, int y)
{
	if (!grid_free_at(g, x, y))
		return 0;
	int32_t best = INT32_MAX;
	for (int by = -1; by <= g->h; by++)
		for (int bx = -1; bx <= g->w; bx++) {
			if (grid_free_at(g, bx, by))
				continue;
			int32_t d = (bx - x) * (bx - x) + (by - y) * (by - y);
			if (d < best)
				best = d;
		}
	return best;
}

static bool edt_matches_brute(const Grid *g)
{
	int32_t *d = malloc(sizeof(int32_t) * (size_t)(g->w * g->h + 1));
	int32_t largest = skeleton_edt(g, d), brute_largest = 0;
	bool ok = true;
	for (int y = 0; y < g->h && ok; y++)
		for (int x = 0; x < g->w && ok; x++) {
			int32_t b = brute_edt_at(g, x, y);
			ok = d[y * g->w + x] == b;
			brute_largest = b > brute_largest ? b : brute_largest;
		}
	free(d);
	return ok && largest == brute_largest;
}

TEST_CASE(edt_equals_brute_force_on_random_grids)
{
	oracle_seed = 1;
	for (int trial = 0; trial < 300; trial++) {
		Grid g;
		int w = 1 + oracle_rand_below(40), h = 1 + oracle_rand_below(40);
		int percent = trial % 3 == 0 ? 2 : oracle_rand_below(60);
		oracle_random_grid(&g, w, h, percent, trial % 2 ? 0 : 3);
		TEST_CHECK(edt_matches_brute(&g));
		grid_free(&g);
	}
}

TEST_CASE(edt_all_free_all_blocked_and_thin_grids)
{
	int sizes[][2] = {{1, 1}, {1, 30}, {30, 1}, {2, 2}, {37, 23}, {64, 64}};
	for (int k = 0; k < 6; k++)
		for (int fill = 0; fill <= 1; fill++) {
			Grid g;
			grid_init(&g, sizes[k][0], sizes[k][1], fill ? GRID_FREE : GRID_BLOCKED);
			TEST_CHECK(edt_matches_brute(&g));
			grid_free(&g);
		}
	/* by hand: a free 5x5 grid, the centre is 3 from the outside ring */
	Grid g;
	grid_init(&g, 5, 5, GRID_FREE);
	int32_t d[25];
	skeleton_edt(&g, d);
	TEST_CHECK(d[2 * 5 + 2] == 9 && d[0] == 1 && d[1 * 5 + 1] == 4);
	grid_free(&g);
}

/* edt_matches_sparse(g): as edt_matches_brute, for grids too large for it: the
 * oracle scans a list of the blocked cells of the grid that have a free 4-neighbour
 * (a blocked cell with none is never nearest: one of its 4-neighbours, blocked too,
 * is nearer to any free cell), and takes the ring outside the grid, a whole
 * rectangle, at its perpendicular distance. */
static bool edt_matches_sparse(const Grid *g)
{
	int32_t *d = malloc(sizeof(int32_t) * (size_t)(g->w * g->h + 1));
	int *bx = malloc(sizeof(int) * (size_t)(g->w * g->h + 1));
	int *by = malloc(sizeof(int) * (size_t)(g->w * g->h + 1));
	int nb = 0;
	for (int y = 0; y < g->h; y++)
		for (int x = 0; x < g->w; x++)
			if (!grid_free_at(g, x, y) &&
			    (grid_free_at(g, x - 1, y) || grid_free_at(g, x + 1, y) ||
			     grid_free_at(g, x, y - 1) || grid_free_at(g, x, y + 1))) {
				bx[nb] = x;
				by[nb++] = y;
			}
	int32_t largest = skeleton_edt(g, d), brute_largest = 0;
	bool ok = true;
	for (int y = 0; y < g->h && ok; y++)
		for (int x = 0; x < g->w && ok; x++) {
			int ring = x + 1;
			ring = y + 1 < ring ? y + 1 : ring;
			ring = g->w - x < ring ? g->w - x : ring;
			ring = g->h - y < ring ? g->h - y : ring;
			int32_t best = grid_free_at(g, x, y) ? ring * ring : 0;
			for (int k = 0; k < nb && best > 0; k++) {
				int32_t e = (bx[k] - x) * (bx[k] - x) + (by[k] - y) * (by[k] - y);
				best = e < best ? e : best;
			}
			ok = d[y * g->w + x] == best;
			brute_largest = best > brute_largest ? best : brute_largest;
		}
	free(d);
	free(bx);
	free(by);
	return ok && largest == brute_largest;
}

/* Open spaces wider than the transform's windows (skeleton.c: blocks of cells that may
 * be more than 181 from every blocked cell go by the lower envelope), next to narrow
 * places, on grids of widths that are and are not a multiple of its blocks of 32; and
 * a cell whose nearest blocked cell is far along its row: (100, 200) for the cells
 * about (290, 200) of a free 600 x 400 grid, nearer than the border. */
TEST_CASE(edt_equals_brute_force_on_wide_open_grids)
{
	oracle_seed = 7;
	int sizes[][3] = {
	    {700, 420, 3}, {391, 400, 12}, {333, 17, 40}, {5, 600, 40}, {600, 400, 0}};
	for (int k = 0; k < 5; k++) {
		Grid g;
		grid_init(&g, sizes[k][0], sizes[k][1], GRID_FREE);
		for (int i = 0; i < sizes[k][2]; i++) {
			int x0 = oracle_rand_below(g.w), y0 = oracle_rand_below(g.h);
			int rw = 1 + oracle_rand_below(12), rh = 1 + oracle_rand_below(12);
			for (int y = y0; y < y0 + rh && y < g.h; y++)
				for (int x = x0; x < x0 + rw && x < g.w; x++)
					g.cells[y * g.w + x] = GRID_BLOCKED;
		}
		if (sizes[k][2] == 0)
			g.cells[200 * g.w + 100] = GRID_BLOCKED;
		TEST_CHECK(edt_matches_sparse(&g));
		grid_free(&g);
	}
}

/* The skeleton's transform takes phase 1 by bands of rows on grids tall enough for
 * two bands and more (edt.c, edt_bands: about 256 KB of 16-bit column distances a
 * band, so 1872 rows of 70 cells), the transform alone over the whole grid at these
 * sizes: the two must agree cell for cell (a last band shorter than the others
 * included), and both with the definition on cells picked at random; the grids
 * from few blocked cells to many, the free runs down the columns up to the grid's
 * height. */
/* edt.c's choice, restated from its constants (EDT_BAND_BYTES 256 KB, EDT_BAND_MIN 8;
 * edt.c tells no caller which way it went): skeleton_compute's transform goes by
 * bands when bands + 2 x band <= h, band = max(8, 262144 / (2 w)) rows. The test
 * asserts its grids meet it, so that a change of those constants that left them on
 * the whole-grid path would show here. */
static bool edt_takes_bands(int w, int h)
{
	int band = 262144 / (2 * w);
	band = band > 8 ? band : 8;
	const int bands = (h + band - 1) / band;
	return bands + 2 * band <= h;
}

TEST_CASE(edt_by_bands_equals_the_whole_grid)
{
	oracle_seed = 11;
	/* the third at the least height that takes the bands for w = 67 (band 1956 rows,
	 * 3 bands: 3 + 3912 = 3915) */
	const int sizes[][4] = {{70, 4200, 3, 6}, {130, 2100, 0, 9}, {67, 3915, 20, 2}};
	TEST_CHECK(!edt_takes_bands(67, 3914));
	for (int k = 0; k < 3; k++) {
		TEST_CHECK(edt_takes_bands(sizes[k][0], sizes[k][1]));
		Grid g;
		oracle_random_grid(&g, sizes[k][0], sizes[k][1], sizes[k][2], sizes[k][3]);
		const size_t n = (size_t)g.w * (size_t)g.h;
		int32_t *d = malloc(sizeof(int32_t) * n);
		const int32_t largest = skeleton_edt(&g, d);
		Skeleton s;
		skeleton_init(&s);
		skeleton_compute(&s, &g);
		TEST_CHECK(memcmp(d, s.dist2, sizeof(int32_t) * n) == 0);
		int32_t most = 0;
		for (size_t i = 0; i < n; i++)
			most = s.dist2[i] > most ? s.dist2[i] : most;
		TEST_CHECK(most == largest);
		for (int t = 0; t < 60; t++) {
			const int x = oracle_rand_below(g.w), y = oracle_rand_below(g.h);
			TEST_CHECK(s.dist2[(size_t)y * g.w + x] == brute_edt_at(&g, x, y));
		}
		TEST_CHECK(skeleton_validate(&s, &g));
		skeleton_free(&s);
		free(d);
		grid_free(&g);
	}
}

/* skeleton_edt alone on a grid of 2048 x 2048 and up (2 bytes a cell of phase 1
 * reach EDT_BANDS_ALONE, 8 MB) goes by bands with scratch of its own (edt.c). Oracle:
 * the grid, 2064 a side, is 16 x 16 tiles of 129 cells, each a random 128 x 128 interior walled on its
 * east and north by a blocked line (outside the grid is blocked); no blocked cell
 * beyond a tile's walls is nearer a cell inside than the wall cell on its row or
 * column, so each interior's transform is that of the interior alone as a grid of
 * its own (128 x 128: the whole-grid path), a different path from the bands. The
 * bands (63 rows) cut the tiles at offsets that vary from tile row to tile row. */
TEST_CASE(edt_alone_by_bands_equals_its_tiles)
{
	oracle_seed = 12;
	enum { T = 129, N = 16, W = T * N };
	TEST_CHECK(2 * (size_t)W * W >= (size_t)8 << 20);
	Grid g;
	grid_init(&g, W, W, GRID_FREE);
	Grid tile[N * N];
	for (int t = 0; t < N * N; t++) {
		oracle_random_grid(&tile[t], T - 1, T - 1, t % 5 == 0 ? 0 : 4, t % 3);
		for (int y = 0; y < T; y++)
			for (int x = 0; x < T; x++) {
				const bool wall = x == T - 1 || y == T - 1;
				const size_t at = (size_t)((t / N) * T + y) * W + (size_t)((t % N) * T + x);
				g.cells[at] = wall ? GRID_BLOCKED : tile[t].cells[y * (T - 1) + x];
			}
	}
	int32_t *d = malloc(sizeof(int32_t) * (size_t)W * W);
	int32_t *e = malloc(sizeof(int32_t) * (T - 1) * (T - 1));
	const int32_t largest = skeleton_edt(&g, d);
	int32_t most = 0;
	bool same = true;
	for (int t = 0; t < N * N; t++) {
		const int32_t m = skeleton_edt(&tile[t], e);
		most = m > most ? m : most;
		for (int y = 0; y < T; y++)
			for (int x = 0; x < T; x++) {
				const int32_t want = x == T - 1 || y == T - 1 ? 0 : e[y * (T - 1) + x];
				same = same && d[(size_t)((t / N) * T + y) * W + (size_t)((t % N) * T + x)] == want;
			}
		grid_free(&tile[t]);
	}
	TEST_CHECK(same);
	TEST_CHECK(largest == most);
	for (int k = 0; k < 8; k++) {
		const int x = oracle_rand_below(W), y = oracle_rand_below(W);
		TEST_CHECK(d[(size_t)y * W + x] == brute_edt_at(&g, x, y));
	}
	free(e);
	free(d);
	grid_free(&g);
}

/* topology_matches(g, s): per free 4-component, exactly one skeleton 4-component,
 * and the same number of holes (each counted on that component alone). */
static bool topology_matches(const Grid *g, const Skeleton *s)
{
	int n = g->w * g->h;
	int *flab = malloc(sizeof(int) * (size_t)(n + 1));
	int *slab = malloc(sizeof(int) * (size_t)(n + 1));
	uint8_t *one = malloc((size_t)n + 1);
	int fc = oracle_label(g->cells, g->w, g->h, 4, flab);
	int sc = oracle_label(s->on, g->w, g->h, 4, slab);
	bool ok = fc == sc;
	/* each skeleton component lies in one free component, and no two share one */
	int *owner = malloc(sizeof(int) * (size_t)(fc + 1));
	for (int k = 0; k < fc; k++)
		owner[k] = -1;
	for (int i = 0; i < n && ok; i++) {
		if (slab[i] < 0)
			continue;
		int f = flab[i];
		ok = f >= 0 && (owner[f] < 0 || owner[f] == slab[i]);
		owner[f] = slab[i];
	}
	for (int k = 0; k < fc && ok; k++) {
		ok = owner[k] >= 0;
		for (int i = 0; i < n; i++)
			one[i] = flab[i] == k;
		int fh = oracle_holes(one, g->w, g->h);
		for (int i = 0; i < n; i++)
			one[i] = slab[i] == owner[k];
		int sh = oracle_holes(one, g->w, g->h);
		if (fh != sh)
			fprintf(stderr, "  component %d: %d holes in space, %d loops in skeleton\n",
			        k, fh, sh);
		ok = ok && fh == sh;
	}
	free(owner);
	free(one);
	free(flab);
	free(slab);
	return ok;
}

/* thin_by_definition(g, s): every skeleton cell that is not an end point changes the
 * numbers of components or holes when removed (it is not simple). */
static bool thin_by_definition(const Skeleton *s)
{
	int n = s->w * s->h;
	int *lab = malloc(sizeof(int) * (size_t)(n + 1));
	uint8_t *set = malloc((size_t)n + 1);
	memcpy(set, s->on, (size_t)n);
	int c0 = oracle_label(set, s->w, s->h, 4, lab), h0 = oracle_holes(set, s->w, s->h);
	bool ok = true;
	for (int i = 0; i < n && ok; i++) {
		if (!set[i] || skeleton_degree(s, i % s->w, i / s->w) == 1)
			continue;
		set[i] = 0;
		int c1 = oracle_label(set, s->w, s->h, 4, lab), h1 = oracle_holes(set, s->w, s->h);
		set[i] = 1;
		ok = c1 != c0 || h1 != h0;
		if (!ok)
			fprintf(stderr, "  cell (%d, %d) could go\n", i % s->w, i / s->w);
	}
	free(lab);
	free(set);
	return ok;
}

static void dump_on_failure(const Skeleton *s, const Grid *g, bool ok)
{
	if (!ok)
		skeleton_dump(s, g, stderr);
}

TEST_CASE(skeleton_topology_on_random_grids)
{
	oracle_seed = 7;
	for (int trial = 0; trial < 200; trial++) {
		Grid g;
		int w = 2 + oracle_rand_below(36), h = 2 + oracle_rand_below(36);
		oracle_random_grid(&g, w, h, oracle_rand_below(45), oracle_rand_below(6));
		Skeleton s;
		skeleton_init(&s);
		skeleton_compute(&s, &g);
		bool ok = skeleton_validate(&s, &g);
		dump_on_failure(&s, &g, ok);
		TEST_CHECK(ok);
		ok = topology_matches(&g, &s);
		dump_on_failure(&s, &g, ok);
		TEST_CHECK(ok);
		if (trial < 60) {
			ok = thin_by_definition(&s);
			dump_on_failure(&s, &g, ok);
			TEST_CHECK(ok);
		}
		skeleton_free(&s);
		grid_free(&g);
	}
}

/* The lowest level is thinned by bit planes of 64 cells a word (src/plan/skellevel.c),
 * the padded row being w + 2 cells: widths about one and two words, where a row's
 * last word is full, or holds one cell, or the next word begins. */
TEST_CASE(skeleton_topology_across_word_boundaries)
{
	static const int widths[] = {1, 2, 60, 61, 62, 63, 64, 65, 66, 125, 126, 127, 128, 130};
	oracle_seed = 11;
	for (size_t k = 0; k < sizeof widths / sizeof widths[0]; k++)
		for (int trial = 0; trial < 6; trial++) {
			Grid g;
			int w = widths[k], h = 1 + oracle_rand_below(14);
			oracle_random_grid(&g, w, h, trial * 8, trial % 2 ? 0 : 2);
			Skeleton s;
			skeleton_init(&s);
			skeleton_compute(&s, &g);
			bool ok = skeleton_validate(&s, &g) && topology_matches(&g, &s);
			dump_on_failure(&s, &g, ok);
			TEST_CHECK(ok);
			ok = thin_by_definition(&s);
			dump_on_failure(&s, &g, ok);
			TEST_CHECK(ok);
			skeleton_free(&s);
			grid_free(&g);
		}
}

/* count_blocks(s, &pinwheels): the 2x2 blocks all of skeleton, and among them the
 * pinwheels, whose four cells each have a skeleton edge neighbour outside the block. */
static int count_blocks(const Skeleton *s, int *pinwheels)
{
	int blocks = 0;
	*pinwheels = 0;
	for (int y = 0; y + 1 < s->h; y++)
		for (int x = 0; x + 1 < s->w; x++) {
			if (!(skeleton_on(s, x, y) && skeleton_on(s, x + 1, y) &&
			      skeleton_on(s, x, y + 1) && skeleton_on(s, x + 1, y + 1)))
				continue;
			blocks++;
			int arms = 0;
			for (int k = 0; k < 4; k++) {
				int cx = x + (k & 1), cy = y + (k >> 1);
				int ox = (k & 1) ? 1 : -1, oy = (k >> 1) ? 1 : -1;
				arms += skeleton_on(s, cx + ox, cy) || skeleton_on(s, cx, cy + oy);
			}
			*pinwheels += arms == 4;
		}
	return blocks;
}

/* One cell thick, precisely: no cell can go (thin_by_definition, above), and a 2x2
 * block of skeleton is always a pinwheel: four loops or branches meeting, as between
 * four one-cell obstacles, where the (4, 8) topology needs every cell. Among obstacles
 * that are rectangles a few cells apart there is no 2x2 block at all. */
TEST_CASE(skeleton_2x2_blocks_only_pinwheels)
{
	oracle_seed = 99;
	int blocks_in_clutter = 0;
	for (int trial = 0; trial < 200; trial++) {
		Grid g;
		bool clutter = trial % 2 == 0;
		oracle_random_grid(&g, 48, 40, clutter ? oracle_rand_below(30) : 0,
		                   1 + oracle_rand_below(8));
		Skeleton s;
		skeleton_init(&s);
		skeleton_compute(&s, &g);
		int pinwheels, blocks = count_blocks(&s, &pinwheels);
		bool ok = blocks == pinwheels && (clutter || blocks == 0);
		dump_on_failure(&s, &g, ok);
		TEST_CHECK(ok);
		blocks_in_clutter += blocks;
		skeleton_free(&s);
		grid_free(&g);
	}
	/* the clutter does make pinwheels, so the first check above was exercised */
	TEST_CHECK(blocks_in_clutter > 0);
}

TEST_CASE(skeleton_ring_has_one_loop_and_clearance)
{
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const rows[] = {
	    "...............",
	    "...............",
	    "...............",
	    "......###......",
	    "......###......",
	    "......###......",
	    "...............",
	    "...............",
	    "...............",
	};
	/* clang-format on */
	Grid g;
	oracle_grid_from(&g, rows, 9);
	Skeleton s;
	skeleton_init(&s);
	skeleton_compute(&s, &g);
	TEST_CHECK(skeleton_validate(&s, &g));
	TEST_CHECK(topology_matches(&g, &s));
	TEST_CHECK(oracle_holes(s.on, g.w, g.h) == 1);
	for (int y = 0; y < g.h; y++)
		for (int x = 0; x < g.w; x++)
			if (skeleton_on(&s, x, y))
				TEST_CHECK(skeleton_clearance(&s, x, y) >= 1.0);
	skeleton_free(&s);
	grid_free(&g);
}

TEST_CASE(skeleton_of_diagonal_pinch_is_two_components)
{
	/* two rooms that touch only at the corner of two diagonally touching blocked
	 * cells: not connected (skeleton.h), so two skeleton components */
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const rows[] = {
	    "....#....",
	    "....#....",
	    "....#....",
	    "#####....",
	    ".....####",
	    "....#....",
	    "....#....",
	};
	/* clang-format on */
	Grid g;
	oracle_grid_from(&g, rows, 7);
	Skeleton s;
	skeleton_init(&s);
	skeleton_compute(&s, &g);
	int lab[63];
	TEST_CHECK(oracle_label(s.on, g.w, g.h, 4, lab) == oracle_label(g.cells, g.w, g.h, 4, lab));
	TEST_CHECK(topology_matches(&g, &s));
	skeleton_free(&s);
	grid_free(&g);
}

TEST_CASE(skeleton_of_corridor_is_its_middle)
{
	/* a corridor 3 wide, closed at both ends: the skeleton is its middle row but for
	 * the end cells, whose distance (1, to the end walls) rises inward */
	Grid g;
	grid_init(&g, 12, 3, GRID_FREE);
	Skeleton s;
	skeleton_init(&s);
	skeleton_compute(&s, &g);
	TEST_CHECK(s.count == 10);
	for (int x = 1; x < 11; x++)
		TEST_CHECK(skeleton_on(&s, x, 1));
	skeleton_free(&s);
	grid_free(&g);
}

TEST_CASE(skeleton_all_blocked_and_empty)
{
	Grid g;
	grid_init(&g, 6, 4, GRID_BLOCKED);
	Skeleton s;
	skeleton_init(&s);
	skeleton_compute(&s, &g);
	TEST_CHECK(s.count == 0 && skeleton_validate(&s, &g));
	grid_free(&g);
	grid_init(&g, 1, 1, GRID_FREE);
	skeleton_compute(&s, &g);
	TEST_CHECK(s.count == 1 && skeleton_validate(&s, &g));
	skeleton_free(&s);
	grid_free(&g);
}

/* dump_to_string(s, g): skeleton_dump into a string (caller frees). */
static char *dump_to_string(const Skeleton *s, const Grid *g)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);
	skeleton_dump(s, g, f);
	fclose(f);
	return buf;
}

TEST_CASE(skeleton_dump_of_a_corridor_by_hand)
{
	Grid g;
	grid_init(&g, 12, 3, GRID_FREE);
	g.cells[2 * 12 + 5] = GRID_BLOCKED; /* a blocked cell in the top row */
	Skeleton s;
	skeleton_init(&s);
	skeleton_compute(&s, &g);
	char *text = dump_to_string(&s, &g);
	const char *want = ".....#......\n"
	                   ".*oooooooo*.\n"
	                   "............\n"
	                   "skeleton: 10 cells, 0 junction cells, 2 end points, 0 pruned\n";
	if (strcmp(text, want) != 0)
		fprintf(stderr, "%s", text);
	TEST_CHECK(strcmp(text, want) == 0);
	free(text);
	skeleton_free(&s);
	grid_free(&g);
}

int main(void)
{
	TEST_RUN(edt_equals_brute_force_on_random_grids);
	TEST_RUN(edt_all_free_all_blocked_and_thin_grids);
	TEST_RUN(edt_equals_brute_force_on_wide_open_grids);
	TEST_RUN(edt_by_bands_equals_the_whole_grid);
	TEST_RUN(edt_alone_by_bands_equals_its_tiles);
	TEST_RUN(skeleton_topology_on_random_grids);
	TEST_RUN(skeleton_topology_across_word_boundaries);
	TEST_RUN(skeleton_2x2_blocks_only_pinwheels);
	TEST_RUN(skeleton_ring_has_one_loop_and_clearance);
	TEST_RUN(skeleton_of_diagonal_pinch_is_two_components);
	TEST_RUN(skeleton_of_corridor_is_its_middle);
	TEST_RUN(skeleton_all_blocked_and_empty);
	TEST_RUN(skeleton_dump_of_a_corridor_by_hand);
	return TEST_EXIT();
}
