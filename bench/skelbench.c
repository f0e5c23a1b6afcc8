/* skelbench.c - times the distance transform, the skeleton, the pathgraph and a query
 * (paper 4.2, 4.3) on synthetic grids, to show the figures of issue 4 and linear growth.
 *
 *   make build/rel/bench/skelbench && build/rel/bench/skelbench [REPEATS [LARGEST [MAP...]]]
 *
 * LARGEST (default 4096) limits the synthetic grids' side; MAP are Moving AI .map files
 * to time as well (say LARGEST 0 for these alone).
 *
 * Grids, all from a fixed seed: "rooms" (a lattice of rooms 64 cells wide whose walls
 * have doors), "rects" (random rectangles covering about a quarter of the grid), "maze"
 * (a perfect maze by randomised depth-first search, corridors 3 cells wide), each at
 * 256, 512, 1024, 2048 and 4096 cells a side (linear costs show as even ns/c columns).
 * Each figure is the best of REPEATS runs (default 3): the least disturbed by the rest of the machine. The first run of a size also pays
 * for first touching its memory; the later runs reuse the skeleton's working memory,
 * as a planner that recomputes the skeleton of a screen of one size would. The query runs from near
 * one corner to near the opposite one and reports the pathgraph vertices it expanded.
 *
 *   skelbench --compare DIR [--side N] [MAP...]
 * The utak side of `make bench-compare` (bench/compare.py): writes the rooms, rects and
 * maze grids and each MAP (scaled by a whole factor and cut, bench_fit) at 1024 and
 * 4096 cells a side (at N alone with --side, for a reduced run) into DIR as NAME-SIDE.pgm (binary PGM, 255 free, 0 blocked, first
 * row y = 0) with NAME-SIDE.d2 (the distance transform: w h int32_t dist2 values,
 * native byte order, for compare.py to check OpenCV's against), and prints one line
 * per grid: "grid NAME W H ends SX SY GX GY len A* JPS exp A* JPS skcells N" and then,
 * for each job, its key and the median, least and most of SKELBENCH_COMPARE_REPEAT
 * runs (thread CPU ms): read (one pass reading the grid, the physical limit), edt,
 * skel (its distance transform included), pg (pathgraph_build), astar and jps
 * (gridpath_find between the ends by plain A* and by the jump-point search; the ends
 * as bench_ends picks them). Exit 2 when the two searches' lengths differ.
 * compare.py times the peers on the same files in the same run.
 *
 *   skelbench --scaling [REPEATS [LARGEST]]
 * Each job's ns a cell on the rooms, rects and maze grids at every side from 256 to
 * LARGEST (4096), medians of REPEATS rounds (7, at least 5) that time every side in
 * turn, beside the machine's floor at each size (read passes): see bench_scaling.
 *
 *   skelbench --pgfloor [REPEATS [MAP...]]
 * What any pathgraph build must read (the skeleton's bit plane, each skeleton cell's
 * dist2) and write (the graph's arrays), each timed alone, beside pathgraph_build, at
 * 1024 and 4096 on rooms, rects, maze and each MAP (issue 16's 2 ms): see
 * bench_pgfloor. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "utak/plan/grid.h"
#include "utak/plan/gridpath.h"
#include "utak/plan/path.h"
#include "utak/plan/pathgraph.h"
#include "utak/plan/skeleton.h"
/* The build's own loads of the skeleton's bit plane (--pgfloor reads it as the
 * build does). */
#include "../src/plan/pathgraph_build.h"

static uint64_t bench_seed = 2026;
static uint32_t bench_rand(void)
{
	bench_seed = bench_seed * 6364136223846793005ULL + 1442695040888963407ULL;
	return (uint32_t)(bench_seed >> 33);
}

/* bench_now_ms: this thread's CPU time (user and system), in ms. CPU time rather than
 * wall time, so that other work on the machine inflates the figures less. */
static double bench_now_ms(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static void bench_fill(Grid *g, int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint8_t v)
{
	for (int32_t y = y0 < 0 ? 0 : y0; y < y1 && y < g->h; y++)
		for (int32_t x = x0 < 0 ? 0 : x0; x < x1 && x < g->w; x++)
			g->cells[(size_t)y * g->w + x] = v;
}

/* rooms 64 wide, walls 2 thick, one door 6 wide in every wall segment */
static void bench_rooms(Grid *g, int32_t side)
{
	const int32_t room = 64, wall = 2, door = 6;
	grid_init(g, side, side, GRID_FREE);
	for (int32_t k = room; k < side; k += room) {
		bench_fill(g, k, 0, k + wall, side, GRID_BLOCKED);
		bench_fill(g, 0, k, side, k + wall, GRID_BLOCKED);
	}
	for (int32_t a = 0; a < side; a += room)
		for (int32_t k = room; k < side; k += room) {
			int32_t d = a + wall + 4 +
			            (int32_t)(bench_rand() % (uint32_t)(room - wall - door - 8));
			bench_fill(g, k, d, k + wall, d + door, GRID_FREE);
			d = a + wall + 4 +
			    (int32_t)(bench_rand() % (uint32_t)(room - wall - door - 8));
			bench_fill(g, d, k, d + door, k + wall, GRID_FREE);
		}
}

/* random rectangles 4..40 cells a side until about a quarter is blocked */
static void bench_rects(Grid *g, int32_t side)
{
	grid_init(g, side, side, GRID_FREE);
	int64_t want = (int64_t)side * side / 4, blocked = 0;
	while (blocked < want) {
		int32_t w = 4 + (int32_t)(bench_rand() % 37), h = 4 + (int32_t)(bench_rand() % 37);
		int32_t x = (int32_t)(bench_rand() % (uint32_t)side),
		        y = (int32_t)(bench_rand() % (uint32_t)side);
		bench_fill(g, x, y, x + w, y + h, GRID_BLOCKED);
		blocked += (int64_t)w * h;
	}
}

/* a perfect maze on a lattice of 4-cell pitch: corridors 3 wide, walls 1 thick */
static void bench_maze(Grid *g, int32_t side)
{
	const int32_t pitch = 4;
	int32_t n = side / pitch;
	grid_init(g, side, side, GRID_BLOCKED);
	uint8_t *seen = calloc((size_t)n * n, 1);
	int32_t *stack = malloc(sizeof(int32_t) * (size_t)n * n);
	int32_t top = 0;
	stack[top++] = 0;
	seen[0] = 1;
	bench_fill(g, 1, 1, pitch, pitch, GRID_FREE);
	while (top > 0) {
		int32_t c = stack[top - 1], cx = c % n, cy = c / n;
		int32_t options[4], count = 0;
		static const int32_t dx[4] = {1, -1, 0, 0}, dy[4] = {0, 0, 1, -1};
		for (int k = 0; k < 4; k++) {
			int32_t nx = cx + dx[k], ny = cy + dy[k];
			if (nx >= 0 && ny >= 0 && nx < n && ny < n && !seen[ny * n + nx])
				options[count++] = k;
		}
		if (count == 0) {
			top--;
			continue;
		}
		int k = options[bench_rand() % (uint32_t)count];
		int32_t nx = cx + dx[k], ny = cy + dy[k];
		seen[ny * n + nx] = 1;
		stack[top++] = ny * n + nx;
		int32_t x0 = (cx < nx ? cx : nx) * pitch + 1, y0 = (cy < ny ? cy : ny) * pitch + 1;
		bench_fill(g, x0, y0, x0 + (dx[k] ? 2 * pitch - 1 : pitch - 1),
		           y0 + (dy[k] ? 2 * pitch - 1 : pitch - 1), GRID_FREE);
	}
	free(seen);
	free(stack);
}

/* bench_ends(g, &from, &to): the query's ends: the free cell nearest the corner (2, 2),
 * and the cell of its 4-connected free component nearest the opposite corner. */
static void bench_ends(const Grid *g, Vec2 *from, Vec2 *to)
{
	const size_t n = (size_t)g->w * g->h;
	int64_t start = -1;
	double best = HUGE_VAL;
	for (size_t i = 0; i < n; i++) {
		double dx = (double)(i % g->w) - 2, dy = (double)(i / g->w) - 2;
		if (g->cells[i] == GRID_FREE && dx * dx + dy * dy < best) {
			best = dx * dx + dy * dy;
			start = (int64_t)i;
		}
	}
	*from = *to = vec2(0.5, 0.5);
	if (start < 0)
		return;
	int32_t *queue = malloc(sizeof *queue * n);
	uint8_t *seen = calloc(n, 1);
	int64_t head = 0, tail = 0, goal = start;
	queue[tail++] = (int32_t)start;
	seen[start] = 1;
	best = HUGE_VAL;
	while (head < tail) {
		int32_t c = queue[head++], x = c % g->w, y = c / g->w;
		double dx = x - (g->w - 3.0), dy = y - (g->h - 3.0);
		if (dx * dx + dy * dy < best) {
			best = dx * dx + dy * dy;
			goal = c;
		}
		static const int DX[4] = {1, 0, -1, 0}, DY[4] = {0, 1, 0, -1};
		for (int k = 0; k < 4; k++) {
			int32_t nx = x + DX[k], ny = y + DY[k];
			if (grid_free_at(g, nx, ny) && !seen[(size_t)ny * g->w + nx]) {
				seen[(size_t)ny * g->w + nx] = 1;
				queue[tail++] = ny * g->w + nx;
			}
		}
	}
	free(queue);
	free(seen);
	*from = vec2(start % g->w + 0.5, start / g->w + 0.5);
	*to = vec2(goal % g->w + 0.5, goal / g->w + 0.5);
}

/* A reference grid A*, here only to count the cells it expands on the same problem as
 * the pathgraph query (issue 4 asks for >= 100 times fewer): 8-connected, a diagonal
 * step only when both orthogonal cells are free, octile estimate, ties to the larger g.
 * The program's own grid planner lives elsewhere; this one is not timed. */
typedef struct BenchHeap {
	double *key;
	int32_t *cell;
	int64_t count, cap;
} BenchHeap;

static void bench_heap_push(BenchHeap *hp, double key, int32_t cell)
{
	if (hp->count == hp->cap) {
		hp->cap = hp->cap ? 2 * hp->cap : 1024;
		hp->key = realloc(hp->key, sizeof *hp->key * (size_t)hp->cap);
		hp->cell = realloc(hp->cell, sizeof *hp->cell * (size_t)hp->cap);
	}
	int64_t i = hp->count++;
	while (i > 0 && hp->key[(i - 1) / 2] > key) {
		hp->key[i] = hp->key[(i - 1) / 2];
		hp->cell[i] = hp->cell[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	hp->key[i] = key;
	hp->cell[i] = cell;
}

static int32_t bench_heap_pop(BenchHeap *hp)
{
	int32_t top = hp->cell[0];
	double key = hp->key[--hp->count];
	int32_t cell = hp->cell[hp->count];
	int64_t i = 0;
	for (;;) {
		int64_t c = 2 * i + 1;
		if (c >= hp->count)
			break;
		if (c + 1 < hp->count && hp->key[c + 1] < hp->key[c])
			c++;
		if (key <= hp->key[c])
			break;
		hp->key[i] = hp->key[c];
		hp->cell[i] = hp->cell[c];
		i = c;
	}
	if (hp->count > 0) {
		hp->key[i] = key;
		hp->cell[i] = cell;
	}
	return top;
}

static double bench_octile(int32_t ax, int32_t ay, int32_t bx, int32_t by)
{
	double dx = abs(ax - bx), dy = abs(ay - by);
	return dx > dy ? dx + (sqrt(2.0) - 1) * dy : dy + (sqrt(2.0) - 1) * dx;
}

/* bench_grid_astar(g, from, to, &length): cells expanded; the length of the path. */
static int64_t bench_grid_astar(const Grid *g, Vec2 from, Vec2 to, double *length)
{
	const int32_t w = g->w, h = g->h;
	int32_t sx = (int32_t)from.x, sy = (int32_t)from.y, tx = (int32_t)to.x, ty = (int32_t)to.y;
	double *gs = malloc(sizeof *gs * (size_t)w * h);
	uint8_t *closed = calloc((size_t)w * h, 1);
	for (int64_t i = 0; i < (int64_t)w * h; i++)
		gs[i] = HUGE_VAL;
	BenchHeap hp = {0};
	int64_t expanded = 0;
	gs[sy * w + sx] = 0;
	/* key = f, less a tiny share of g so that ties go to the deeper cell */
	bench_heap_push(&hp, bench_octile(sx, sy, tx, ty), sy * w + sx);
	*length = -1;
	while (hp.count > 0) {
		int32_t c = bench_heap_pop(&hp), cx = c % w, cy = c / w;
		if (closed[c])
			continue;
		closed[c] = 1;
		expanded++;
		if (cx == tx && cy == ty) {
			*length = gs[c];
			break;
		}
		for (int dy = -1; dy <= 1; dy++)
			for (int dx = -1; dx <= 1; dx++) {
				if (dx == 0 && dy == 0)
					continue;
				int32_t nx = cx + dx, ny = cy + dy;
				if (!grid_free_at(g, nx, ny))
					continue;
				if (dx && dy &&
				    !(grid_free_at(g, cx + dx, cy) && grid_free_at(g, cx, cy + dy)))
					continue;
				double ng = gs[c] + (dx && dy ? sqrt(2.0) : 1.0);
				int32_t nb = ny * w + nx;
				if (ng < gs[nb]) {
					gs[nb] = ng;
					bench_heap_push(
					    &hp, ng + bench_octile(nx, ny, tx, ty) - 1e-9 * ng, nb);
				}
			}
	}
	free(gs);
	free(closed);
	free(hp.key);
	free(hp.cell);
	return expanded;
}

static void bench_one(const char *name, Grid g, int repeats)
{
	const int32_t side = g.w > g.h ? g.w : g.h;
	double cells = (double)g.w * g.h;
	double t_edt = 1e30, t_skel = 1e30, t_graph = 1e30, t_query = 1e30;
	int32_t *d2 = malloc(sizeof(int32_t) * (size_t)cells);
	Skeleton s;
	Pathgraph pg;
	Path path;
	skeleton_init(&s);
	pathgraph_init(&pg);
	path_init(&path);
	Vec2 from, to;
	bench_ends(&g, &from, &to);
	int64_t expanded = 0;
	for (int r = 0; r < repeats; r++) {
		double t0 = bench_now_ms();
		skeleton_edt(&g, d2);
		double t1 = bench_now_ms();
		skeleton_compute(&s, &g);
		double t2 = bench_now_ms();
		pathgraph_build(&pg, &s, &g);
		double t3 = bench_now_ms();
		PathgraphQuery q = pathgraph_query_default();
		pathgraph_find_path(&pg, from, to, &q, &path);
		double t4 = bench_now_ms();
		expanded = path.expanded;
		t_edt = fmin(t_edt, t1 - t0);
		t_skel = fmin(t_skel, t2 - t1);
		t_graph = fmin(t_graph, t3 - t2);
		t_query = fmin(t_query, t4 - t3);
	}
	printf("%-6s %5d %9.0f | %7.2f %5.2f | %7.2f %5.2f | %6.2f %5.2f | %6.3f %6lld %7.1f | %7d "
	       "%6d %6d\n",
	       name, (int)side, cells, t_edt, t_edt * 1e6 / cells, t_skel, t_skel * 1e6 / cells,
	       t_graph, t_graph * 1e6 / cells, t_query, (long long)expanded, path_length(&path),
	       (int)s.count, (int)pg.vertex_count, (int)pg.edge_count);
	double grid_length;
	int64_t grid_expanded = bench_grid_astar(&g, from, to, &grid_length);
	printf("%-6s %5d   grid A* expands %lld cells (length %.1f): %.0f times the pathgraph's "
	       "%lld\n",
	       name, (int)side, (long long)grid_expanded, grid_length,
	       expanded ? (double)grid_expanded / expanded : 0.0, (long long)expanded);
	path_free(&path);
	pathgraph_free(&pg);
	skeleton_free(&s);
	free(d2);
	grid_free(&g);
}

/* bench_load_map(path, g): a Moving AI .map file (movingai.h):
 * '.', 'G' and 'S' free, anything else blocked; the file's rows in order as y. */
static bool bench_load_map(const char *path, Grid *g)
{
	FILE *f = fopen(path, "r");
	if (!f)
		return false;
	char line[1 << 16];
	int w = -1, h = -1;
	while (fgets(line, sizeof line, f)) {
		if (sscanf(line, "height %d", &h) == 1 || sscanf(line, "width %d", &w) == 1)
			continue;
		if (strncmp(line, "map", 3) == 0)
			break;
	}
	if (w <= 0 || h <= 0 || w > SKELETON_MAX_SIDE || h > SKELETON_MAX_SIDE) {
		fclose(f);
		return false;
	}
	grid_init(g, w, h, GRID_BLOCKED);
	for (int y = 0; y < h && fgets(line, sizeof line, f); y++)
		for (int x = 0; x < w && line[x] && line[x] != '\n' && line[x] != '\r'; x++)
			if (line[x] == '.' || line[x] == 'G' || line[x] == 'S')
				g->cells[(size_t)y * w + x] = GRID_FREE;
	fclose(f);
	return true;
}

/* Runs per figure in --compare mode (at least 3): each figure is their median, with
 * the least and the most beside it. */
#define SKELBENCH_COMPARE_REPEAT 5

/* A figure of --compare: the median of the runs and their spread. */
typedef struct BenchFigure {
	double median, lo, hi;
} BenchFigure;

static int bench_cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static BenchFigure bench_figure(double *t, int n)
{
	qsort(t, (size_t)n, sizeof *t, bench_cmp_double);
	return (BenchFigure){n % 2 ? t[n / 2] : (t[n / 2 - 1] + t[n / 2]) / 2, t[0], t[n - 1]};
}

static void bench_print_figure(const char *key, BenchFigure f)
{
	printf(" %s %.3f %.3f %.3f", key, f.median, f.lo, f.hi);
}

/* bench_read_pass(g): one pass reading every byte of the grid, the least any job
 * on it must do: the physical limit printed beside each job. The sum is returned so
 * that the compiler keeps the loop. */
static uint64_t bench_read_pass(const Grid *g)
{
	const size_t n = (size_t)g->w * g->h;
	uint64_t sum = 0;
	for (size_t i = 0; i < n; i++)
		sum += g->cells[i];
	return sum;
}

/* bench_write_compare(dir, name, g): the grid as DIR/NAME-SIDE.pgm, its distance
 * transform as DIR/NAME-SIDE.d2, and its line of figures (see --compare above). False
 * when a file cannot be written. */
static bool bench_write_compare(const char *dir, const char *name, const Grid *g)
{
	const size_t n = (size_t)g->w * g->h;
	char path[4096];
	snprintf(path, sizeof path, "%s/%s-%d.pgm", dir, name, (int)g->w);
	FILE *f = fopen(path, "wb");
	if (!f)
		return false;
	fprintf(f, "P5\n%d %d\n255\n", (int)g->w, (int)g->h);
	for (size_t i = 0; i < n; i++)
		fputc(g->cells[i] == GRID_FREE ? 255 : 0, f);
	if (fclose(f) != 0)
		return false;
	int32_t *d2 = malloc(sizeof *d2 * n);
	Skeleton s;
	Pathgraph pg;
	GridPathSearch astar, jump;
	Path path_a, path_j;
	skeleton_init(&s);
	pathgraph_init(&pg);
	path_init(&path_a);
	path_init(&path_j);
	gridpath_init(&astar, g);
	gridpath_init(&jump, g);
	jump.method = GRIDPATH_JUMP;
	Vec2 from, to;
	bench_ends(g, &from, &to);
	const int32_t sx = (int32_t)from.x, sy = (int32_t)from.y, gx = (int32_t)to.x,
	              gy = (int32_t)to.y;
	enum { READ, EDT, SKEL, GRAPH, ASTAR, JUMP, JOBS };
	static const char *const keys[JOBS] = {"read", "edt", "skel", "pg", "astar", "jps"};
	double t[JOBS][SKELBENCH_COMPARE_REPEAT];
	double len_a = -1, len_j = -1;
	volatile uint64_t sink = 0;
	for (int r = 0; r < SKELBENCH_COMPARE_REPEAT; r++) {
		double t0 = bench_now_ms();
		sink += bench_read_pass(g);
		double t1 = bench_now_ms();
		skeleton_edt(g, d2);
		double t2 = bench_now_ms();
		skeleton_compute(&s, g);
		double t3 = bench_now_ms();
		pathgraph_build(&pg, &s, g);
		double t4 = bench_now_ms();
		gridpath_find(&astar, sx, sy, gx, gy, &path_a, &len_a);
		double t5 = bench_now_ms();
		gridpath_find(&jump, sx, sy, gx, gy, &path_j, &len_j);
		double t6 = bench_now_ms();
		t[READ][r] = t1 - t0;
		t[EDT][r] = t2 - t1;
		t[SKEL][r] = t3 - t2;
		t[GRAPH][r] = t4 - t3;
		t[ASTAR][r] = t5 - t4;
		t[JUMP][r] = t6 - t5;
	}
	(void)sink;
	snprintf(path, sizeof path, "%s/%s-%d.d2", dir, name, (int)g->w);
	f = fopen(path, "wb");
	bool ok = f && fwrite(d2, sizeof *d2, n, f) == n;
	ok = f && fclose(f) == 0 && ok;
	printf("grid %s %d %d ends %d %d %d %d len %.4f %.4f exp %lld %lld skcells %d", name,
	       (int)g->w, (int)g->h, (int)sx, (int)sy, (int)gx, (int)gy, len_a, len_j,
	       (long long)path_a.expanded, (long long)path_j.expanded, (int)s.count);
	for (int j = 0; j < JOBS; j++)
		bench_print_figure(keys[j], bench_figure(t[j], SKELBENCH_COMPARE_REPEAT));
	printf("\n");
	fflush(stdout);
	gridpath_free(&astar);
	gridpath_free(&jump);
	path_free(&path_a);
	path_free(&path_j);
	pathgraph_free(&pg);
	skeleton_free(&s);
	free(d2);
	return ok && len_a == len_j;
}

/* bench_fit(g, side): g scaled by the least whole factor that makes it at least side
 * cells each way (each cell becoming k x k), then cut to side x side: a Moving AI
 * map at the comparison's sizes. */
static void bench_fit(Grid *g, int32_t side)
{
	int32_t big = g->w > g->h ? g->w : g->h;
	int32_t small = g->w < g->h ? g->w : g->h;
	int32_t k = (side + small - 1) / small;
	(void)big;
	Grid out;
	grid_init(&out, side, side, GRID_BLOCKED);
	for (int32_t y = 0; y < side; y++)
		for (int32_t x = 0; x < side; x++) {
			int32_t ox = x / k, oy = y / k;
			if (ox < g->w && oy < g->h)
				out.cells[(size_t)y * side + x] = g->cells[(size_t)oy * g->w + ox];
		}
	grid_free(g);
	*g = out;
}

/* bench_compare(dir, maps, count): --compare (see the top of the file); the sides
 * 1024 and 4096, or only `only` when it is positive (--side). */
static int bench_compare(const char *dir, char **maps, int count, int32_t only)
{
	static const char *const names[] = {"rooms", "rects", "maze"};
	void (*const make[])(Grid *, int32_t) = {bench_rooms, bench_rects, bench_maze};
	int32_t sides[] = {1024, 4096};
	int nsides = 2;
	if (only > 0) {
		sides[0] = only;
		nsides = 1;
	}
	for (int z = 0; z < nsides; z++) {
		for (int k = 0; k < 3; k++) {
			Grid g;
			bench_seed = 2026;
			make[k](&g, sides[z]);
			bool ok = bench_write_compare(dir, names[k], &g);
			grid_free(&g);
			if (!ok) {
				fprintf(stderr, "skelbench: %s: cannot write the files of %s\n", dir,
				        names[k]);
				return 2;
			}
		}
		for (int k = 0; k < count; k++) {
			Grid g;
			if (!bench_load_map(maps[k], &g)) {
				fprintf(stderr, "skelbench: %s: not a readable .map file\n", maps[k]);
				return 2;
			}
			bench_fit(&g, sides[z]);
			/* The name without directory and ".map". */
			char name[256];
			const char *base = strrchr(maps[k], '/');
			snprintf(name, sizeof name, "%s", base ? base + 1 : maps[k]);
			char *dot = strrchr(name, '.');
			if (dot && strcmp(dot, ".map") == 0)
				*dot = '\0';
			bool ok = bench_write_compare(dir, name, &g);
			grid_free(&g);
			if (!ok) {
				fprintf(stderr, "skelbench: %s: cannot write the files of %s\n", dir,
				        name);
				return 2;
			}
		}
	}
	return 0;
}

/* ---------------------------------------------------------------- --scaling */

/* skelbench --scaling [REPEATS [LARGEST]] (issue 16, "costs linear in cells from 256
 * to 4096"): for each of the rooms, rects and maze grids, all sides from 256 to
 * LARGEST (default 4096) are built at once, each with its own skeleton, pathgraph and
 * searches, and every round (REPEATS of them, at least 5, default 7) times every job
 * on every side in turn (the sides in alternate directions from round to round), so
 * that the load of this shared machine falls on all sides alike (after one round
 * not timed, which first touches the working memory). Printed per side:
 * the median ns a cell of each job (thread CPU time over w h), and beside them the
 * floor of the machine at that size: one read pass over the grid's bytes (read8: 1
 * byte a cell, 16 MB at 4096) and over a 4-byte array of the grid's size (read32, as
 * dist2: 64 MB at 4096), each summing 8 bytes a load, and one load of every line of
 * that 4-byte array down its columns (down32: bench_read_down, the floor of an
 * access order the prefetchers cannot follow). Then, per job, its ns a cell at each
 * side over that at 256 (growth), and its time in read32 and in down32 passes ("x
 * r32", "x d32": linear in cells, within the machine's floor, means one of these
 * columns is even from 256 to 4096). A* and jump points also in ns per cell
 * expanded (their expansions are not proportional to the cells).
 * Jobs: edt (skeleton_edt), skel (skeleton_compute, its transform included), pg
 * (pathgraph_build), astar and jps (gridpath_find between bench_ends' ends). */
#define SKELBENCH_SCALING_SIDES 5

typedef struct BenchSide {
	Grid g;
	int32_t *d2;
	uint32_t *wide; /* the 4-byte read pass's array, the grid's size */
	Skeleton s;
	Pathgraph pg;
	GridPathSearch astar, jump;
	Path pa, pj;
	int32_t sx, sy, gx, gy;
} BenchSide;

enum { SC_READ8, SC_READ32, SC_DOWN32, SC_EDT, SC_SKEL, SC_PG, SC_ASTAR, SC_JPS, SC_JOBS };

/* bench_read_down(a, w, h): one pass reading one 4-byte value of every 64-byte line
 * of a (w x h, w a multiple of 16), down the columns: no two loads in a row share a
 * line, a page (at 1024 a side and up) or a stride the hardware prefetchers follow
 * across pages: the floor of a job that reads a grid-sized array in an order of its
 * own (a walk along a chain, a level's cells across the grid), as read32 is of one
 * that streams. */
static uint64_t bench_read_down(const uint32_t *a, int32_t w, int32_t h)
{
	uint64_t sum = 0;
	for (int32_t x = 0; x < w; x += 16)
		for (int32_t y = 0; y < h; y++)
			sum += a[(size_t)y * w + x];
	return sum;
}

/* bench_read_words(p, bytes): one pass reading bytes (a multiple of 8) 8 at a time. */
static uint64_t bench_read_words(const void *p, size_t bytes)
{
	const unsigned char *b = p;
	uint64_t sum = 0;
	for (size_t i = 0; i + 8 <= bytes; i += 8) {
		uint64_t v;
		memcpy(&v, b + i, 8);
		sum += v;
	}
	return sum;
}

static int bench_scaling(int repeats, int32_t largest)
{
	static const char *const names[] = {"rooms", "rects", "maze"};
	void (*const make[])(Grid *, int32_t) = {bench_rooms, bench_rects, bench_maze};
	static const int32_t all[SKELBENCH_SCALING_SIDES] = {256, 512, 1024, 2048, 4096};
	static const char *const keys[SC_JOBS] = {"read8", "read32", "down32", "edt",
	                                          "skel",  "pg",     "astar",  "jps"};
	int nsides = 0;
	while (nsides < SKELBENCH_SCALING_SIDES && all[nsides] <= largest)
		nsides++;
	printf("# --scaling: ns a cell (thread CPU / w h), medians of %d rounds, every side "
	       "timed in each round; read8/read32: one read pass over 1 and 4 bytes a cell, "
	       "down32: a load of each line of the 4-byte array down its columns; growth: "
	       "over 256; x r32, x d32: edt skel pg astar jps in read32 and down32 passes\n",
	       repeats);
	double *t = malloc(sizeof *t * (size_t)repeats * SC_JOBS * SKELBENCH_SCALING_SIDES);
	for (int k = 0; k < 3; k++) {
		BenchSide side[SKELBENCH_SCALING_SIDES];
		int64_t exp_a[SKELBENCH_SCALING_SIDES], exp_j[SKELBENCH_SCALING_SIDES];
		for (int z = 0; z < nsides; z++) {
			BenchSide *b = &side[z];
			bench_seed = 2026;
			make[k](&b->g, all[z]);
			const size_t n = (size_t)all[z] * all[z];
			b->d2 = malloc(sizeof *b->d2 * n);
			b->wide = malloc(sizeof *b->wide * n);
			for (size_t i = 0; i < n; i++)
				b->wide[i] = (uint32_t)i;
			skeleton_init(&b->s);
			pathgraph_init(&b->pg);
			gridpath_init(&b->astar, &b->g);
			gridpath_init(&b->jump, &b->g);
			b->jump.method = GRIDPATH_JUMP;
			path_init(&b->pa);
			path_init(&b->pj);
			Vec2 from, to;
			bench_ends(&b->g, &from, &to);
			b->sx = (int32_t)from.x;
			b->sy = (int32_t)from.y;
			b->gx = (int32_t)to.x;
			b->gy = (int32_t)to.y;
		}
		volatile uint64_t sink = 0;
		/* round -1 warms up: first touches of the working memory are not timed */
		for (int r = -1; r < repeats; r++)
			for (int q = 0; q < nsides; q++) {
				const int z = r % 2 ? nsides - 1 - q : q;
				BenchSide *b = &side[z];
				const size_t n = (size_t)b->g.w * b->g.h;
				double len;
				double c[SC_JOBS + 1];
				c[0] = bench_now_ms();
				sink += bench_read_words(b->g.cells, n);
				c[1] = bench_now_ms();
				sink += bench_read_words(b->wide, 4 * n);
				c[2] = bench_now_ms();
				sink += bench_read_down(b->wide, b->g.w, b->g.h);
				c[3] = bench_now_ms();
				skeleton_edt(&b->g, b->d2);
				c[4] = bench_now_ms();
				skeleton_compute(&b->s, &b->g);
				c[5] = bench_now_ms();
				pathgraph_build(&b->pg, &b->s, &b->g);
				c[6] = bench_now_ms();
				gridpath_find(&b->astar, b->sx, b->sy, b->gx, b->gy, &b->pa, &len);
				c[7] = bench_now_ms();
				gridpath_find(&b->jump, b->sx, b->sy, b->gx, b->gy, &b->pj, &len);
				c[8] = bench_now_ms();
				for (int j = 0; j < SC_JOBS && r >= 0; j++)
					t[((size_t)z * SC_JOBS + j) * repeats + r] =
					    (c[j + 1] - c[j]) * 1e6 / (double)n;
				exp_a[z] = b->pa.expanded;
				exp_j[z] = b->pj.expanded;
			}
		(void)sink;
		double med[SKELBENCH_SCALING_SIDES][SC_JOBS];
		printf("%-6s %5s |", names[k], "side");
		for (int j = 0; j < SC_JOBS; j++)
			printf(" %6s", keys[j]);
		printf(" | %9s %9s | %8s %8s\n", "A* exp", "jps exp", "A* ns/e", "jps ns/e");
		for (int z = 0; z < nsides; z++) {
			printf("%-6s %5d |", names[k], (int)all[z]);
			for (int j = 0; j < SC_JOBS; j++) {
				BenchFigure f =
				    bench_figure(&t[((size_t)z * SC_JOBS + j) * repeats], repeats);
				med[z][j] = f.median;
				printf(" %6.2f", f.median);
			}
			const double n = (double)all[z] * all[z];
			printf(" | %9lld %9lld | %8.1f %8.1f\n", (long long)exp_a[z],
			       (long long)exp_j[z],
			       exp_a[z] ? med[z][SC_ASTAR] * n / (double)exp_a[z] : 0.0,
			       exp_j[z] ? med[z][SC_JPS] * n / (double)exp_j[z] : 0.0);
		}
		/* growth: each side's ns a cell over 256's; then in read32 passes */
		for (int z = 0; z < nsides; z++) {
			printf("%-6s %5d growth", names[k], (int)all[z]);
			for (int j = 0; j < SC_JOBS; j++)
				printf(" %s %.2f", keys[j], med[z][j] / med[0][j]);
			printf(" | x r32");
			for (int j = SC_EDT; j < SC_JOBS; j++)
				printf(" %.1f", med[z][j] / med[z][SC_READ32]);
			printf(" | x d32");
			for (int j = SC_EDT; j < SC_JOBS; j++)
				printf(" %.2f", med[z][j] / med[z][SC_DOWN32]);
			printf("\n");
		}
		fflush(stdout);
		for (int z = 0; z < nsides; z++) {
			BenchSide *b = &side[z];
			path_free(&b->pa);
			path_free(&b->pj);
			gridpath_free(&b->astar);
			gridpath_free(&b->jump);
			pathgraph_free(&b->pg);
			skeleton_free(&b->s);
			free(b->d2);
			free(b->wide);
			grid_free(&b->g);
		}
	}
	free(t);
	return 0;
}

/* ---------------------------------------------------------------- --pgfloor */

/* skelbench --pgfloor [REPEATS [MAP...]] (issue 16, "pathgraph build <= 2 ms
 * everywhere"): what any build of the pathgraph must read and write, timed on its own,
 * beside pathgraph_build, on the rooms, rects and maze grids and each MAP (bench_fit)
 * at 1024 and 4096 cells a side. The build must read the skeleton (its bit plane,
 * Skeleton.plane: an eighth of a byte a cell) and the dist2 of every skeleton cell (an
 * edge's clearance is the least dist2 of its cells, a vertex's its cell's), and write
 * the graph: cells and cell_edge (4 + 4 bytes an edge cell) and a 4-byte record a
 * skeleton cell (the cell_ref by rank). Timed after each skeleton_compute, as the
 * build is (its caches as the build finds them), medians of REPEATS (default 7, at
 * least 3), thread CPU ms: plane, one read pass over the plane's words; gather, each
 * skeleton cell's dist2 loaded in row-major order (ascending addresses, the order of
 * a build that streams the rows) and its least kept; write, a memset of the graph's
 * bytes; floor, their sum; pg, pathgraph_build; and the lines of 64 bytes of dist2
 * that hold a skeleton cell (each a line fetched from memory once the grid outgrows
 * the caches). The build also reads dist2 at turns (the cut corner's fourth cell),
 * and has its vertices, their junction sets and the incidence lists besides. Where
 * the skeleton is dense (rooms, rects, the maze) the floor is what reading and
 * writing that much costs streamed; where it is sparse (a few cells a row, as on the
 * Moving AI maps scaled to 4096) the gather waits on a line at a time and the build's
 * walk, which fetches dist2 16 rows ahead, can beat it: there the floor is no bound
 * (measured: pathgraph.c's MEASURED, FLOOR). */
static int bench_pgfloor(int repeats, char **maps, int count)
{
	static const char *const names[] = {"rooms", "rects", "maze"};
	void (*const make[])(Grid *, int32_t) = {bench_rooms, bench_rects, bench_maze};
	static const int32_t sides[] = {1024, 4096};
	printf("# --pgfloor: thread CPU ms, medians of %d, each after a skeleton_compute: "
	       "plane (read pass), gather (each skeleton cell's dist2, row-major), write "
	       "(the graph's 8 bytes an edge cell and 4 a skeleton cell), floor (their sum), "
	       "pg (pathgraph_build)\n",
	       repeats);
	printf("%-14s %5s %9s %9s %8s %8s %8s | %7s %7s %7s %7s %7s %6s\n", "grid", "side",
	       "skel", "edgecell", "lines", "plane MB", "out MB", "plane", "gather", "write",
	       "floor", "pg", "pg/fl");
	double *t = malloc(sizeof *t * (size_t)repeats * 4);
	for (int z = 0; z < 2; z++)
		for (int k = 0; k < 3 + count; k++) {
			Grid g;
			char name[256];
			if (k < 3) {
				bench_seed = 2026;
				make[k](&g, sides[z]);
				snprintf(name, sizeof name, "%s", names[k]);
			} else {
				if (!bench_load_map(maps[k - 3], &g)) {
					fprintf(stderr, "skelbench: %s: not a readable .map file\n",
					        maps[k - 3]);
					free(t);
					return 2;
				}
				bench_fit(&g, sides[z]);
				const char *base = strrchr(maps[k - 3], '/');
				snprintf(name, sizeof name, "%s", base ? base + 1 : maps[k - 3]);
				char *dot = strrchr(name, '.');
				if (dot && strcmp(dot, ".map") == 0)
					*dot = '\0';
			}
			Skeleton s;
			Pathgraph pg;
			skeleton_init(&s);
			pathgraph_init(&pg);
			skeleton_compute(&s, &g);
			pathgraph_build(&pg, &s, &g);
			const int32_t w = s.w, h = s.h, words = skeleton_plane_words(w);
			const size_t plane_bytes = (size_t)(h + 2) * (size_t)words * 8;
			int64_t lines = 0;
			for (int32_t y = 0; y < h; y++) {
				uintptr_t last = 0;
				for (int32_t x = 0; x < w; x++) {
					const int64_t cb = skeleton_plane_bit(w, x, y);
					if (!(s.plane[cb >> 3] >> (cb & 7) & 1))
						continue;
					const uintptr_t line = (uintptr_t)(s.dist2 + (size_t)y * w + x) >> 6;
					lines += line != last;
					last = line;
				}
			}
			const size_t out_bytes = (size_t)pg.cell_count * 8 + (size_t)s.count * 4;
			unsigned char *out = malloc(out_bytes + 1);
			volatile uint64_t sink = 0;
			for (int r = -1; r < repeats; r++) { /* round -1: first touches */
				double c[4];
				skeleton_compute(&s, &g);
				c[0] = bench_now_ms();
				sink += bench_read_words(s.plane, plane_bytes);
				c[1] = bench_now_ms();
				int32_t least = INT32_MAX;
				for (int32_t y = 0; y < h; y++) {
					const unsigned char *row = s.plane + (size_t)(y + 1) * words * 8;
					const int32_t *d = s.dist2 + (size_t)y * w;
					/* the plane's word j >= 1 holds cells 64 (j - 1) on */
					for (int32_t j = 1; (j - 1) * 64 < w; j++)
						for (uint64_t here = pathgraph_load64(row + 8 * j); here;
						     here &= here - 1) {
							const int32_t v = d[(j - 1) * 64 + pathgraph_ctz64(here)];
							least = v < least ? v : least;
						}
				}
				c[2] = bench_now_ms();
				memset(out, r & 0xff, out_bytes);
				c[3] = bench_now_ms();
				for (int j = 0; j < 3 && r >= 0; j++)
					t[(size_t)j * repeats + r] = c[j + 1] - c[j];
				skeleton_compute(&s, &g); /* the build as it comes after the skeleton */
				const double p0 = bench_now_ms();
				pathgraph_build(&pg, &s, &g);
				if (r >= 0)
					t[(size_t)3 * repeats + r] = bench_now_ms() - p0;
				sink += (uint64_t)least + out[out_bytes / 2];
			}
			(void)sink;
			double med[4];
			for (int j = 0; j < 4; j++)
				med[j] = bench_figure(&t[(size_t)j * repeats], repeats).median;
			const double floor_ms = med[0] + med[1] + med[2];
			printf("%-14s %5d %9d %9d %8lld %8.2f %8.2f | %7.3f %7.3f %7.3f %7.3f %7.3f "
			       "%6.2f\n",
			       name, (int)sides[z], (int)s.count, (int)pg.cell_count,
			       (long long)lines, plane_bytes / 1e6, out_bytes / 1e6, med[0], med[1],
			       med[2], floor_ms, med[3], med[3] / floor_ms);
			fflush(stdout);
			free(out);
			pathgraph_free(&pg);
			skeleton_free(&s);
			grid_free(&g);
		}
	free(t);
	return 0;
}

int main(int argc, char **argv)
{
	if (argc > 1 && strcmp(argv[1], "--scaling") == 0) {
		int repeats = argc > 2 ? atoi(argv[2]) : 7;
		int32_t largest = argc > 3 ? atoi(argv[3]) : 4096;
		return bench_scaling(repeats < 5 ? 5 : repeats, largest);
	}
	if (argc > 1 && strcmp(argv[1], "--pgfloor") == 0) {
		int repeats = argc > 2 ? atoi(argv[2]) : 7;
		return bench_pgfloor(repeats < 3 ? 3 : repeats, argv + 3, argc > 3 ? argc - 3 : 0);
	}
	if (argc > 2 && strcmp(argv[1], "--compare") == 0) {
		if (argc > 4 && strcmp(argv[3], "--side") == 0) {
			int32_t side = atoi(argv[4]);
			if (side < 16 || side > 16384) {
				fprintf(stderr, "skelbench: --side: 16 to 16384 cells\n");
				return 2;
			}
			return bench_compare(argv[2], argv + 5, argc - 5, side);
		}
		return bench_compare(argv[2], argv + 3, argc - 3, 0);
	}
	int repeats = argc > 1 ? atoi(argv[1]) : 3;
	int32_t largest = argc > 2 ? atoi(argv[2]) : 4096;
	if (repeats < 1)
		repeats = 1;
	printf("# best of %d; skeleton includes its own distance transform\n", repeats);
	printf("%-6s %5s %9s | %7s %5s | %7s %5s | %6s %5s | %6s %6s %7s | %7s %6s %6s\n", "grid",
	       "side", "cells", "edt ms", "ns/c", "skel ms", "ns/c", "pg ms", "ns/c", "q ms",
	       "expand", "length", "skcells", "verts", "edges");
	static const int32_t sides[] = {256, 512, 1024, 2048, 4096};
	for (int k = 0; k < 5 && sides[k] <= largest; k++) {
		Grid g;
		bench_seed = 2026;
		bench_rooms(&g, sides[k]);
		bench_one("rooms", g, repeats);
		bench_seed = 2026;
		bench_rects(&g, sides[k]);
		bench_one("rects", g, repeats);
		bench_seed = 2026;
		bench_maze(&g, sides[k]);
		bench_one("maze", g, repeats);
	}
	for (int k = 3; k < argc; k++) {
		Grid g;
		if (!bench_load_map(argv[k], &g)) {
			fprintf(stderr, "skelbench: %s: not a readable .map file\n", argv[k]);
			return 2;
		}
		const char *base = strrchr(argv[k], '/');
		bench_one(base ? base + 1 : argv[k], g, repeats);
	}
	return 0;
}
