/* pathbench.c - the path-finding benchmark on Moving AI maps (paper 4.1 and 5: the
 * paper's planners compared on real maps).
 *
 *   pathbench [--sample N] [--vis-limit N] FILE.map FILE.scen
 *	One line per scenario: index in the file, bucket, published optimum, grid A*
 *	length, any-angle (visibility-graph) length, the A* path rope-tightened, then
 *	the skeleton path and its tightened length; "-" where not computed, and
 *	" MISSED" / " ROPE-FAILED" at the end of a line that fails a check. Exit 1 when
 *	grid A* misses a published optimum (tolerance 1e-3 + 1e-5 x length) or the rope
 *	fails its checks (free, not longer than the A* path, not shorter than the
 *	any-angle optimum), 2 on a bad file or usage (one line on stderr).
 *   pathbench --table [--sample N] [--vis-limit N] MAP SCEN [MAP SCEN ...]
 *	One row per scenario file, then a row over all scenarios run; same exit status.
 *	Columns (medians over the scenarios unless .mx = maximum):
 *	  size, cells (free), run (scenarios run), A*ok ("all" when every A* length
 *	  matched its optimum), A*.ms, A*.exp (cells expanded);
 *	  vis.V (convex corners), vis.build (ms, once per map; "-" when refused:
 *	  more corners than --vis-limit), vis.ms and vis.ex (query time, nodes
 *	  expanded), any/opt (any-angle length / published optimum);
 *	  rope.ms (tightening the A* path), rope/opt, rope/any, r/any.mx, r-opt.mx
 *	  (tightened length minus published optimum);
 *	  skel: dt.ms, sk.ms, pg.ms (distance transform, skeleton, pathgraph build),
 *	  q.ms, q.exp (pathgraph query), sk/any, skr/any (skeleton path and its
 *	  tightened form over the any-angle optimum), skr-opt (tightened minus the grid
 *	  optimum, max): "-" until the skeleton modules are wired in (SKELETON below).
 *   pathbench --corner [--scale K] MAP ...
 *	Grid A* corner to corner (the free cell nearest the top-left corner to the one
 *	nearest the bottom-right), each map optionally enlarged K times (every cell
 *	becomes K x K cells), the figure the issue compares with libtcod: length,
 *	cells expanded, best wall-clock ms and best thread-CPU ms of 5 runs.
 *   pathbench --cspace MAP ...
 *	Configuration-space erosion (cspace.h) by three discs and an L-shaped object:
 *	free cells left and best ms of 3 runs.
 *
 * --sample N runs at most N scenarios of each file, evenly spaced (always the first),
 * so that `make bench` takes minutes. Times are milliseconds on one thread; every
 * other printed number is deterministic. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "utak/cspace.h"
#include "utak/grid.h"
#include "utak/gridpath.h"
#include "utak/movingai.h"
#include "utak/path.h"
#include "utak/rope.h"
#include "utak/util.h"
#include "utak/visibility.h"

#define PATHBENCH_NAME "pathbench"

/* One scenario's results; a negative length or time means "not computed". */
typedef struct BenchResult {
	double optimum;       /* published 8-connected optimum */
	double astar;         /* grid A* length */
	double anyangle;      /* visibility-graph (Euclidean) optimum */
	double rope;          /* the A* path, rope-tightened */
	double skeleton;      /* SKELETON: the skeleton planner's path */
	double skeleton_rope; /* SKELETON: the same, rope-tightened */
	double astar_ms, anyangle_ms, rope_ms;
	int64_t astar_expanded, anyangle_expanded;
	int astar_ok; /* the A* length matches the optimum */
	int rope_ok;  /* the rope is free, keeps its ends, is not longer */
} BenchResult;

/* The per-map state every planner needs, built once per map. */
typedef struct BenchMap {
	const char *map_path, *scen_path;
	Grid grid;
	MovingAiScen scen;
	int64_t free_cells;
	GridPathSearch astar;
	int32_t corners;     /* convex corners: the visibility graph's vertices */
	bool has_visibility; /* built (corners <= the limit) */
	VisibilityGraph visibility;
	double visibility_build_ms;
	/* SKELETON: the distance transform, skeleton and pathgraph of the map, and the
	 * milliseconds each took to build, go here (built in bench_load, freed in
	 * bench_unload, printed by bench_print_row). */
} BenchMap;

/* The corner limit for the visibility graph (--vis-limit). */
static int32_t bench_vis_limit = VISIBILITY_MAX_VERTICES;

static double bench_now_ms(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

/* bench_cpu_ms: this thread's CPU time: unlike the wall clock, it does not count
 * the time the thread waits while another process has the core (the benchmark
 * machine is shared). */
static double bench_cpu_ms(void)
{
	struct timespec t;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
	return (double)t.tv_sec * 1e3 + (double)t.tv_nsec * 1e-6;
}

static void bench_die_usage(void)
{
	fprintf(stderr,
	        "usage: " PATHBENCH_NAME " [--sample N] [--vis-limit N] FILE.map FILE.scen\n"
	        "       " PATHBENCH_NAME
	        " --table [--sample N] [--vis-limit N] MAP SCEN [MAP SCEN ...]\n"
	        "       " PATHBENCH_NAME " --corner [--scale K] MAP [MAP ...]\n"
	        "       " PATHBENCH_NAME " --cspace MAP [MAP ...]\n");
	exit(2);
}

static int bench_cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* bench_median(v, n): the median of the n values (sorts v); NAN when n == 0. */
static double bench_median(double *v, int n)
{
	if (n == 0)
		return NAN;
	qsort(v, (size_t)n, sizeof *v, bench_cmp_double);
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* bench_load: reads a map (and its scenarios when scen_path is not NULL) and builds
 * the planners' per-map state (the visibility graph only when with_visibility); on
 * a bad file prints one line and exits 2. */
static void bench_load(BenchMap *bm, const char *map_path, const char *scen_path,
                       bool with_visibility)
{
	char err[MOVINGAI_ERROR_SIZE];
	*bm = (BenchMap){.map_path = map_path, .scen_path = scen_path};
	if (!movingai_read_map(map_path, &bm->grid, err)) {
		fprintf(stderr, PATHBENCH_NAME ": %s\n", err);
		exit(2);
	}
	if (scen_path && !movingai_read_scen(scen_path, &bm->grid, &bm->scen, err)) {
		fprintf(stderr, PATHBENCH_NAME ": %s\n", err);
		exit(2);
	}
	for (int64_t i = 0; i < (int64_t)bm->grid.w * bm->grid.h; i++)
		bm->free_cells += bm->grid.cells[i] == GRID_FREE;
	gridpath_init(&bm->astar, &bm->grid);
	bm->corners = visibility_count_corners(&bm->grid);
	if (with_visibility && bm->corners <= bench_vis_limit) {
		double t0 = bench_now_ms();
		bm->has_visibility = visibility_init(&bm->visibility, &bm->grid, bench_vis_limit) ==
		                     VISIBILITY_FOUND;
		bm->visibility_build_ms = bench_now_ms() - t0;
	}
	/* SKELETON: build the distance transform, skeleton and pathgraph here, timing
	 * each. */
}

static void bench_unload(BenchMap *bm)
{
	if (bm->has_visibility)
		visibility_free(&bm->visibility);
	gridpath_free(&bm->astar);
	movingai_scen_free(&bm->scen);
	grid_free(&bm->grid);
}

/* bench_selected(i, count, sample): scenario i is one of the `sample` evenly spaced
 * ones (all when sample <= 0 or sample >= count). */
static int bench_selected(int i, int count, int sample)
{
	if (sample <= 0 || sample >= count)
		return 1;
	/* The j-th pick is floor(j count / sample); i is picked when some j maps to it. */
	int64_t j = ((int64_t)i * sample + count - 1) / count;
	return j < sample && (j * count) / sample == i;
}

/* The slack allowed when comparing lengths computed along different polylines. */
#define PATHBENCH_LENGTH_EPS 1e-9

/* bench_run: solves problem i with every planner. */
static BenchResult bench_run(BenchMap *bm, int i, Path *path, Path *tight)
{
	const MovingAiProblem *pr = &bm->scen.problems[i];
	BenchResult r = {.optimum = pr->optimum,
	                 .anyangle = -1,
	                 .rope = -1,
	                 .skeleton = -1,
	                 .skeleton_rope = -1,
	                 .anyangle_ms = -1,
	                 .rope_ms = -1,
	                 .anyangle_expanded = -1,
	                 .rope_ok = 1};
	double t0 = bench_now_ms();
	GridPathStatus st =
	    gridpath_find(&bm->astar, pr->sx, pr->sy, pr->gx, pr->gy, path, &r.astar);
	r.astar_ms = bench_now_ms() - t0;
	r.astar_expanded = path->expanded;
	r.astar_ok =
	    st == GRIDPATH_FOUND && fabs(r.astar - r.optimum) <= movingai_tolerance(r.optimum);
	if (st == GRIDPATH_FOUND) {
		t0 = bench_now_ms();
		RopeStatus rs = rope_tighten(&bm->grid, path, tight);
		r.rope_ms = bench_now_ms() - t0;
		if (rs == ROPE_OK) {
			r.rope = path_length(tight);
			r.rope_ok = r.rope <= r.astar + PATHBENCH_LENGTH_EPS &&
			            visibility_path_free(&bm->grid, tight);
		} else
			r.rope_ok = 0;
	}
	if (bm->has_visibility) {
		Vec2 s = vec2(pr->sx + 0.5, pr->sy + 0.5), d = vec2(pr->gx + 0.5, pr->gy + 0.5);
		t0 = bench_now_ms();
		VisibilityStatus vs = visibility_find(&bm->visibility, s, d, tight, &r.anyangle);
		r.anyangle_ms = bench_now_ms() - t0;
		r.anyangle_expanded = tight->expanded;
		/* The any-angle optimum can be no longer than any other path. */
		if (vs == VISIBILITY_FOUND && r.rope >= 0 &&
		    r.anyangle > r.rope + PATHBENCH_LENGTH_EPS)
			r.rope_ok = 0;
	}
	/* SKELETON: the skeleton planner's query (S' and D', the pathgraph search, the
	 * skeleton path) into r.skeleton with its time and vertices expanded, then
	 * rope_tighten of that path into r.skeleton_rope (the targets: median
	 * r.skeleton_rope / r.anyangle <= 1.01, r.skeleton_rope <= r.optimum + 1); add
	 * their columns to the enum COL_... and to bench_table. */
	return r;
}

/* bench_report: a failed check, on stderr. Returns 1 when something failed. */
static int bench_report(const BenchMap *bm, int i, const BenchResult *r)
{
	int line = (int)bm->scen.problems[i].line;
	if (!r->astar_ok)
		fprintf(stderr, PATHBENCH_NAME ": %s:%d: grid A* length %.6f, published %.6f\n",
		        bm->scen_path, line, r->astar, r->optimum);
	if (!r->rope_ok)
		fprintf(stderr,
		        PATHBENCH_NAME ": %s:%d: rope-tightening failed its checks (A* %.6f, "
		                       "rope %.6f, any-angle %.6f)\n",
		        bm->scen_path, line, r->astar, r->rope, r->anyangle);
	return !r->astar_ok || !r->rope_ok;
}

/* bench_length: a length, or "-" when not computed, in a fixed-width column. */
static void bench_print_length(double v)
{
	if (v < 0)
		printf(" %12s", "-");
	else
		printf(" %12.4f", v);
}

#define PATHBENCH_LINE_HEADER                                                                      \
	"# index bucket      optimum        astar     anyangle   astar+rope     skeleton "         \
	"   skel+rope\n"

static int bench_lines(const char *map_path, const char *scen_path, int sample)
{
	BenchMap bm;
	bench_load(&bm, map_path, scen_path, true);
	Path path, tight;
	path_init(&path);
	path_init(&tight);
	printf("# map %s: %d x %d, %lld free cells, %d corners; %d scenarios\n", map_path,
	       (int)bm.grid.w, (int)bm.grid.h, (long long)bm.free_cells, (int)bm.corners,
	       bm.scen.count);
	if (!bm.has_visibility)
		printf("# anyangle: not computed, %d corners > --vis-limit %d\n", (int)bm.corners,
		       (int)bench_vis_limit);
	printf(PATHBENCH_LINE_HEADER);
	int failed = 0;
	for (int i = 0; i < bm.scen.count; i++) {
		if (!bench_selected(i, bm.scen.count, sample))
			continue;
		BenchResult r = bench_run(&bm, i, &path, &tight);
		printf("%7d %6d", i, (int)bm.scen.problems[i].bucket);
		bench_print_length(r.optimum);
		bench_print_length(r.astar);
		bench_print_length(r.anyangle);
		bench_print_length(r.rope);
		bench_print_length(r.skeleton);
		bench_print_length(r.skeleton_rope);
		printf("%s%s\n", r.astar_ok ? "" : "  MISSED", r.rope_ok ? "" : "  ROPE-FAILED");
		failed += bench_report(&bm, i, &r);
	}
	path_free(&path);
	path_free(&tight);
	bench_unload(&bm);
	return failed ? 1 : 0;
}

/* bench_print_value: a figure with the given decimals, or "-" (NAN). */
static void bench_print_value(int width, int decimals, double v)
{
	if (isnan(v))
		printf(" %*s", width, "-");
	else
		printf(" %*.*f", width, decimals, v);
}

/* The values collected per scenario, one column of numbers each. */
typedef struct BenchColumn {
	double *v;
	int n;
} BenchColumn;

static void bench_column_add(BenchColumn *c, double v)
{
	if (isnan(v))
		return;
	c->v = util_realloc(c->v, (size_t)c->n + 1, sizeof *c->v);
	c->v[c->n++] = v;
}

static double bench_column_max(const BenchColumn *c)
{
	double m = NAN;
	for (int i = 0; i < c->n; i++)
		if (isnan(m) || c->v[i] > m)
			m = c->v[i];
	return m;
}

static double bench_column_median(BenchColumn *c)
{
	return bench_median(c->v, c->n);
}

enum {
	COL_ASTAR_MS,       /* grid A* query time */
	COL_ASTAR_EXP,      /* cells A* expanded */
	COL_VIS_BUILD_MS,   /* visibility graph build, one value per map */
	COL_VIS_MS,         /* visibility query time */
	COL_VIS_EXP,        /* visibility nodes expanded */
	COL_ANY_OVER_OPT,   /* any-angle optimum / published 8-connected optimum */
	COL_ROPE_MS,        /* rope-tightening time */
	COL_ROPE_OVER_OPT,  /* rope-tightened A* / published optimum */
	COL_ROPE_OVER_ANY,  /* rope-tightened A* / any-angle optimum */
	COL_ROPE_MINUS_OPT, /* rope-tightened A* - published optimum (the issue's
	                       "never longer than the grid optimum + 1") */
	COL_COUNT
};

/* The table: one row per scenario file, every figure a median over the scenarios
 * run, except vis.V (the corners), vis.build (once per map) and the .max columns. */
static void bench_print_header(void)
{
	printf("%-32s %9s %8s %5s %4s %7s %7s | %6s %9s %7s %6s %7s | %7s %8s %8s %8s %8s"
	       " | skel: %5s %5s %5s %5s %5s %6s %7s %7s\n",
	       "map", "size", "cells", "run", "A*ok", "A*.ms", "A*.exp", "vis.V", "vis.build",
	       "vis.ms", "vis.ex", "any/opt", "rope.ms", "rope/opt", "rope/any", "r/any.mx",
	       "r-opt.mx", "dt.ms", "sk.ms", "pg.ms", "q.ms", "q.exp", "sk/any", "skr/any",
	       "skr-opt");
}

static void bench_print_row(const char *name, const char *size, int64_t cells, int run, int ok,
                            double corners, BenchColumn col[COL_COUNT])
{
	printf("%-32s %9s %8lld %5d %4s", name, size, (long long)cells, run,
	       ok == run ? "all" : "MISS");
	bench_print_value(7, 2, bench_column_median(&col[COL_ASTAR_MS]));
	bench_print_value(7, 0, bench_column_median(&col[COL_ASTAR_EXP]));
	printf(" |");
	bench_print_value(6, 0, corners);
	bench_print_value(9, 1, bench_column_median(&col[COL_VIS_BUILD_MS]));
	bench_print_value(7, 3, bench_column_median(&col[COL_VIS_MS]));
	bench_print_value(6, 0, bench_column_median(&col[COL_VIS_EXP]));
	bench_print_value(7, 4, bench_column_median(&col[COL_ANY_OVER_OPT]));
	printf(" |");
	bench_print_value(7, 3, bench_column_median(&col[COL_ROPE_MS]));
	bench_print_value(8, 4, bench_column_median(&col[COL_ROPE_OVER_OPT]));
	bench_print_value(8, 4, bench_column_median(&col[COL_ROPE_OVER_ANY]));
	bench_print_value(8, 4, bench_column_max(&col[COL_ROPE_OVER_ANY]));
	bench_print_value(8, 4, bench_column_max(&col[COL_ROPE_MINUS_OPT]));
	printf(" |      ");
	/* SKELETON: distance transform, skeleton and pathgraph build (ms, per map), query
	 * ms and vertices expanded, skeleton / any-angle, tightened skeleton / any-angle,
	 * tightened skeleton - grid optimum (max). */
	printf(" %5s %5s %5s %5s %5s %6s %7s %7s\n", "-", "-", "-", "-", "-", "-", "-", "-");
}

static const char *bench_basename(const char *path)
{
	const char *s = strrchr(path, '/');
	return s ? s + 1 : path;
}

static int bench_table(int argc, char **argv, int sample)
{
	if (argc < 2 || argc % 2 != 0)
		bench_die_usage();
	BenchColumn all[COL_COUNT] = {{0}};
	int all_run = 0, all_ok = 0, failed = 0;
	int64_t all_cells = 0;
	bench_print_header();
	Path path, tight;
	path_init(&path);
	path_init(&tight);
	for (int m = 0; m < argc; m += 2) {
		BenchMap bm;
		bench_load(&bm, argv[m], argv[m + 1], true);
		BenchColumn col[COL_COUNT] = {{0}};
		int run = 0, ok = 0;
		if (bm.has_visibility) {
			bench_column_add(&col[COL_VIS_BUILD_MS], bm.visibility_build_ms);
			bench_column_add(&all[COL_VIS_BUILD_MS], bm.visibility_build_ms);
		}
		for (int i = 0; i < bm.scen.count; i++) {
			if (!bench_selected(i, bm.scen.count, sample))
				continue;
			BenchResult r = bench_run(&bm, i, &path, &tight);
			run++;
			ok += r.astar_ok;
			failed += bench_report(&bm, i, &r);
			bool any = r.anyangle >= 0, rope = r.rope >= 0;
			double v[COL_COUNT] = {
			    [COL_ASTAR_MS] = r.astar_ms,
			    [COL_ASTAR_EXP] = (double)r.astar_expanded,
			    [COL_VIS_BUILD_MS] = NAN,
			    [COL_VIS_MS] = any ? r.anyangle_ms : NAN,
			    [COL_VIS_EXP] = any ? (double)r.anyangle_expanded : NAN,
			    [COL_ANY_OVER_OPT] =
			        any && r.optimum > 0 ? r.anyangle / r.optimum : NAN,
			    [COL_ROPE_MS] = rope ? r.rope_ms : NAN,
			    [COL_ROPE_OVER_OPT] = rope && r.optimum > 0 ? r.rope / r.optimum : NAN,
			    [COL_ROPE_OVER_ANY] =
			        rope && any && r.anyangle > 0 ? r.rope / r.anyangle : NAN,
			    [COL_ROPE_MINUS_OPT] = rope ? r.rope - r.optimum : NAN,
			};
			for (int c = 0; c < COL_COUNT; c++) {
				bench_column_add(&col[c], v[c]);
				bench_column_add(&all[c], v[c]);
			}
		}
		char size[32];
		snprintf(size, sizeof size, "%dx%d", (int)bm.grid.w, (int)bm.grid.h);
		/* The row is named after the scenario file (a map may have several). */
		char name[64];
		snprintf(name, sizeof name, "%s", bench_basename(argv[m + 1]));
		for (char *dot; (dot = strrchr(name, '.')) &&
		                (strcmp(dot, ".scen") == 0 || strcmp(dot, ".map") == 0);)
			*dot = '\0';
		bench_print_row(name, size, bm.free_cells, run, ok, (double)bm.corners, col);
		fflush(stdout);
		for (int c = 0; c < COL_COUNT; c++)
			free(col[c].v);
		all_run += run;
		all_ok += ok;
		all_cells += bm.free_cells;
		bench_unload(&bm);
	}
	bench_print_row("MEDIAN (all scenarios run)", "", all_cells, all_run, all_ok, NAN, all);
	for (int c = 0; c < COL_COUNT; c++)
		free(all[c].v);
	path_free(&path);
	path_free(&tight);
	printf("# any-angle columns only where the map has at most %d corners (--vis-limit)\n",
	       (int)bench_vis_limit);
	return failed ? 1 : 0;
}

/* bench_scale(g, k): every cell becomes k x k cells. */
static void bench_scale(Grid *g, int k)
{
	Grid big;
	grid_init(&big, g->w * k, g->h * k, GRID_BLOCKED);
	for (int32_t y = 0; y < big.h; y++)
		for (int32_t x = 0; x < big.w; x++)
			big.cells[(size_t)y * big.w + x] = g->cells[(size_t)(y / k) * g->w + x / k];
	grid_free(g);
	*g = big;
}

/* bench_nearest_free(g, cx, cy, &x, &y): the free cell nearest (cx, cy) in the
 * max-norm, scanning rings outward in a fixed order; false when none. */
static int bench_nearest_free(const Grid *g, int32_t cx, int32_t cy, int32_t *x, int32_t *y)
{
	int32_t rmax = g->w > g->h ? g->w : g->h;
	for (int32_t r = 0; r <= rmax; r++)
		for (int32_t dy = -r; dy <= r; dy++)
			for (int32_t dx = -r; dx <= r; dx++) {
				if (abs(dx) != r && abs(dy) != r)
					continue;
				if (grid_free_at(g, cx + dx, cy + dy)) {
					*x = cx + dx;
					*y = cy + dy;
					return 1;
				}
			}
	return 0;
}

/* The repetitions of a corner-to-corner query; the minimum is reported. */
#define PATHBENCH_CORNER_REPEAT 5

static int bench_corner(int argc, char **argv, int scale)
{
	printf("# grid A* corner to corner, best of %d runs: wall clock and thread CPU time\n",
	       PATHBENCH_CORNER_REPEAT);
	printf(
	    "map                         size       cells    length   expanded      ms  cpu.ms\n");
	Path path;
	path_init(&path);
	for (int m = 0; m < argc; m++) {
		BenchMap bm;
		bench_load(&bm, argv[m], NULL, false);
		if (scale > 1) {
			gridpath_free(&bm.astar);
			bench_scale(&bm.grid, scale);
			gridpath_init(&bm.astar, &bm.grid);
			bm.free_cells *= (int64_t)scale * scale;
		}
		int32_t sx, sy, gx, gy;
		char name[64], size[32];
		snprintf(name, sizeof name, "%s", bench_basename(argv[m]));
		char *dot = strrchr(name, '.');
		if (dot)
			*dot = '\0';
		if (scale > 1) {
			size_t n = strlen(name);
			snprintf(name + n, sizeof name - n, " x%d", scale);
		}
		snprintf(size, sizeof size, "%dx%d", (int)bm.grid.w, (int)bm.grid.h);
		double best = INFINITY, best_cpu = INFINITY, len = -1;
		if (bench_nearest_free(&bm.grid, 0, 0, &sx, &sy) &&
		    bench_nearest_free(&bm.grid, bm.grid.w - 1, bm.grid.h - 1, &gx, &gy))
			for (int rep = 0; rep < PATHBENCH_CORNER_REPEAT; rep++) {
				double t0 = bench_now_ms(), c0 = bench_cpu_ms();
				gridpath_find(&bm.astar, sx, sy, gx, gy, &path, &len);
				double t = bench_now_ms() - t0, c = bench_cpu_ms() - c0;
				best = t < best ? t : best;
				best_cpu = c < best_cpu ? c : best_cpu;
			}
		printf("%-26s %11s %10lld", name, size, (long long)bm.free_cells);
		if (len < 0)
			printf(" %9s %10s %7s %7s\n", "none", "-", "-", "-");
		else
			printf(" %9.2f %10lld %7.1f %7.1f\n", len, (long long)path.expanded, best,
			       best_cpu);
		fflush(stdout);
		bench_unload(&bm);
	}
	path_free(&path);
	return 0;
}

/* The shapes --cspace erodes by: clearance discs, and an L-shaped object 6 x 4
 * squares with a 3 x 2 notch (the paper's L-shaped object, section 5), its
 * reference point at its inner corner. */
static const double bench_disc_radius[] = {1.0, 2.5, 6.0};
static const Polygon bench_l_shape = {6, {{-2, -2}, {4, -2}, {4, 0}, {1, 0}, {1, 2}, {-2, 2}}};
#define PATHBENCH_CSPACE_REPEAT 3

static double bench_cspace_time(const Grid *g, const Polygon *shape, double radius, Grid *out)
{
	double best = INFINITY;
	for (int rep = 0; rep < PATHBENCH_CSPACE_REPEAT; rep++) {
		double t0 = bench_now_ms();
		if (shape)
			cspace_erode(g, shape, out);
		else
			cspace_erode_disc(g, radius, out);
		double t = bench_now_ms() - t0;
		best = t < best ? t : best;
	}
	return best;
}

static int64_t bench_count_free(const Grid *g)
{
	int64_t n = 0;
	for (int64_t i = 0; i < (int64_t)g->w * g->h; i++)
		n += g->cells[i] == GRID_FREE;
	return n;
}

/* bench_cspace: configuration-space erosion times (best of PATHBENCH_CSPACE_REPEAT)
 * and the free cells left, per map and shape. */
static int bench_cspace(int argc, char **argv)
{
	printf("# configuration-space erosion (cspace.h), best of %d runs; free cells left\n",
	       PATHBENCH_CSPACE_REPEAT);
	printf("%-26s %11s %10s", "map", "size", "cells");
	for (size_t k = 0; k < sizeof bench_disc_radius / sizeof bench_disc_radius[0]; k++)
		printf("   disc r=%-4.1f ms", bench_disc_radius[k]);
	printf("   L 6x4 (free)   ms\n");
	for (int m = 0; m < argc; m++) {
		BenchMap bm;
		bench_load(&bm, argv[m], NULL, false);
		Grid out;
		grid_init(&out, bm.grid.w, bm.grid.h, GRID_BLOCKED);
		char name[64], size[32];
		snprintf(name, sizeof name, "%s", bench_basename(argv[m]));
		char *dot = strrchr(name, '.');
		if (dot)
			*dot = '\0';
		snprintf(size, sizeof size, "%dx%d", (int)bm.grid.w, (int)bm.grid.h);
		printf("%-26s %11s %10lld", name, size, (long long)bm.free_cells);
		for (size_t k = 0; k < sizeof bench_disc_radius / sizeof bench_disc_radius[0];
		     k++) {
			double ms = bench_cspace_time(&bm.grid, NULL, bench_disc_radius[k], &out);
			printf(" %10lld %5.1f", (long long)bench_count_free(&out), ms);
		}
		double ms = bench_cspace_time(&bm.grid, &bench_l_shape, 0, &out);
		printf(" %13lld %5.1f\n", (long long)bench_count_free(&out), ms);
		fflush(stdout);
		grid_free(&out);
		bench_unload(&bm);
	}
	return 0;
}

int main(int argc, char **argv)
{
	int table = 0, corner = 0, cspace = 0, sample = 0, scale = 1, a = 1;
	for (; a < argc && strncmp(argv[a], "--", 2) == 0; a++) {
		if (strcmp(argv[a], "--table") == 0)
			table = 1;
		else if (strcmp(argv[a], "--corner") == 0)
			corner = 1;
		else if (strcmp(argv[a], "--cspace") == 0)
			cspace = 1;
		else if ((strcmp(argv[a], "--sample") == 0 || strcmp(argv[a], "--scale") == 0 ||
		          strcmp(argv[a], "--vis-limit") == 0) &&
		         a + 1 < argc) {
			char *end;
			long v = strtol(argv[a + 1], &end, 10);
			if (*end != '\0' || v < 1 || v > 1000000) {
				fprintf(stderr, PATHBENCH_NAME ": %s: bad number \"%s\"\n", argv[a],
				        argv[a + 1]);
				return 2;
			}
			if (strcmp(argv[a], "--sample") == 0)
				sample = (int)v;
			else if (strcmp(argv[a], "--scale") == 0)
				scale = (int)v;
			else
				bench_vis_limit = (int32_t)v;
			a++;
		} else
			bench_die_usage();
	}
	if (table + corner + cspace > 1)
		bench_die_usage();
	if (cspace)
		return argc - a >= 1 ? bench_cspace(argc - a, argv + a) : (bench_die_usage(), 2);
	if (scale > 16)
		bench_die_usage();
	if (corner)
		return argc - a >= 1 ? bench_corner(argc - a, argv + a, scale)
		                     : (bench_die_usage(), 2);
	if (table)
		return bench_table(argc - a, argv + a, sample);
	if (argc - a != 2)
		bench_die_usage();
	return bench_lines(argv[a], argv[a + 1], sample);
}
