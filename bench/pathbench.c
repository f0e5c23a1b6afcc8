/* pathbench.c - the path-finding benchmark on Moving AI maps (paper 4.1 and 5: the
 * paper's planners compared on real maps).
 *
 *   pathbench [--sample N] [--vis-limit N] [--skel-paths K] FILE.map FILE.scen
 *	One line per scenario: index in the file, bucket, published optimum, grid A*
 *	length, any-angle (visibility-graph) length, the A* path rope-tightened, then
 *	the skeleton path and its tightened length; "-" where not computed, and
 *	" MISSED" / " ROPE-FAILED" at the end of a line that fails a check, and
 *	" SKEL-NO-PATH" / " SKEL-ROPE-REFUSED" / " SKEL>OPT+1" for the skeleton
 *	planner's shortfalls against the targets (not failures). Exit 1 when
 *	grid A* misses a published optimum (tolerance 1e-3 + 1e-5 x length) or the rope
 *	fails its checks (free, not longer than the A* path, not shorter than the
 *	any-angle optimum), 2 on a bad file or usage (one line on stderr).
 *   pathbench --table [--sample N] [--vis-limit N] [--skel-paths K] MAP SCEN [MAP SCEN ...]
 *	One row per scenario file, then a row over all scenarios run; same exit status.
 *	Columns (medians over the scenarios unless .mx = maximum):
 *	  size, cells (free), run (scenarios run), A*ok ("all" when every A* length
 *	  matched its optimum), A*.ms, A*.exp (cells expanded);
 *	  vis.V (convex corners), vis.build (ms, once per map; "-" when refused:
 *	  more corners than --vis-limit), vis.ms and vis.ex (query time, nodes
 *	  expanded), any/opt (any-angle length / published optimum);
 *	  rope.ms (tightening the A* path), rope/opt, rope/any, r/any.mx, r-opt.mx
 *	  (tightened length minus published optimum);
 *	  skel: dt.ms, sk.ms, pg.ms (distance transform, skeleton with its own
 *	  distance transform, pathgraph build: once per map, best of 3), q.ms, q.exp
 *	  (the pathgraph query from S's cell centre to D's: S', D', A* over the
 *	  vertices, the path), "A* / q" (A* cells expanded over pathgraph vertices expanded),
 *	  sk/opt, skr/opt, sk/any, skr/any (the skeleton path and its rope-tightened
 *	  form, skr, over the published and the any-angle optimum), skr/a.mx,
 *	  skr-o.mx (maxima: skr over any-angle, skr minus the grid optimum), >o+1
 *	  (scenarios where skr is longer than the grid optimum + 1, the bound)
 *	  and fail (no skeleton path, or rope_tighten refused it); each of these last
 *	  two is also a line on stderr, which does not change the exit status.
 *   pathbench --corner [--scale K] [--jump] MAP ...
 *	Grid A* (with --jump its jump-point search, gridpath.h) corner to corner (the free cell nearest the top-left corner to the one
 *	nearest the bottom-right), each map optionally enlarged K times (every cell
 *	becomes K x K cells), the figure the issue compares with libtcod: length,
 *	cells expanded, best wall-clock ms and best thread-CPU ms of 5 runs.
 *   pathbench --cspace MAP ...
 *	Configuration-space erosion (cspace.h) by three discs and an L-shaped object:
 *	free cells left and best ms of 3 runs.
 *
 * --sample N runs at most N scenarios of each file, evenly spaced (always the first),
 * so that `make bench` takes minutes. --skel-paths K (1 to 16, default 1) makes the
 * skeleton columns tighten the pathgraph's K best topologically distinct paths and
 * keep the shortest rope, instead of the planner's one best path. Times are milliseconds on one thread; every
 * other printed number is deterministic. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "utak/plan/cspace.h"
#include "utak/plan/grid.h"
#include "utak/plan/gridpath.h"
#include "utak/plan/movingai.h"
#include "utak/plan/path.h"
#include "utak/plan/pathgraph.h"
#include "utak/plan/rope.h"
#include "utak/plan/skeleton.h"
#include "utak/base/util.h"
#include "utak/plan/visibility.h"

#define PATHBENCH_NAME "pathbench"

/* One scenario's results; a negative length or time means "not computed". */
typedef struct BenchResult {
	double optimum;       /* published 8-connected optimum */
	double astar;         /* grid A* length */
	double anyangle;      /* visibility-graph (Euclidean) optimum */
	double rope;          /* the A* path, rope-tightened */
	double skeleton;      /* the skeleton planner's path (pathgraph, S' and D') */
	double skeleton_rope; /* the same, rope-tightened */
	double astar_ms, anyangle_ms, rope_ms, skeleton_ms;
	int64_t astar_expanded, anyangle_expanded, skeleton_expanded;
	int astar_ok; /* the A* length matches the optimum */
	int rope_ok;  /* the rope is free, keeps its ends, is not longer */
	/* The skeleton planner's outcome: it found a path where A* did, and rope_tighten
	 * accepted it (SKEL_OK), or which of the two failed. */
	enum { SKEL_OK, SKEL_NO_PATH, SKEL_ROPE_BAD_INPUT } skeleton_status;
	int skeleton_rope_ok; /* its rope is free and not longer than it (when made) */
	int skeleton_over; /* the tightened path is longer than the optimum + 1 square */
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
	/* The skeleton planner's per-map state (paper 4.2, 4.3) and the best of
	 * PATHBENCH_BUILD_REPEAT wall-clock times of each build step, in ms. The skeleton
	 * time includes its own distance transform (skeleton_compute runs one), as the
	 * issue's target "skeleton, distance transform included" counts it. */
	bool has_skeleton;
	Skeleton skeleton;
	Pathgraph pathgraph;
	double edt_ms, skeleton_ms, pathgraph_ms;
} BenchMap;

/* The corner limit for the visibility graph (--vis-limit). */
static int32_t bench_vis_limit = VISIBILITY_MAX_VERTICES;

/* --skel-paths K: how many of the pathgraph's best paths the skeleton planner's
 * figures tighten (1, the default, is what the planner does); at most
 * PATHBENCH_MAX_SKEL_PATHS, as Yen's method costs a search per node of each path. */
#define PATHBENCH_MAX_SKEL_PATHS 16
static int bench_skel_paths = 1;

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
	        "usage: " PATHBENCH_NAME " [--sample N] [--vis-limit N] [--skel-paths K] FILE.map FILE.scen\n"
	        "       " PATHBENCH_NAME
	        " --table [--sample N] [--vis-limit N] [--skel-paths K] MAP SCEN [MAP SCEN ...]\n"
	        "       " PATHBENCH_NAME " --corner [--scale K] [--jump] MAP [MAP ...]\n"
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

/* The builds of the skeleton planner are repeated and the least time kept: each is a
 * few ms, done once per map, so one run would mostly measure the machine's noise
 * (it is shared). The later runs reuse the skeleton's working memory, as a planner
 * replanning on a screen of one size does. */
#define PATHBENCH_BUILD_REPEAT 3

/* bench_build_skeleton: the distance transform (timed alone, into a scratch array),
 * the skeleton and the pathgraph of bm's grid, each the best of
 * PATHBENCH_BUILD_REPEAT runs. */
static void bench_build_skeleton(BenchMap *bm)
{
	int32_t *dist2 = util_realloc(NULL, (size_t)bm->grid.w * (size_t)bm->grid.h, sizeof *dist2);
	skeleton_init(&bm->skeleton);
	pathgraph_init(&bm->pathgraph);
	bm->edt_ms = bm->skeleton_ms = bm->pathgraph_ms = INFINITY;
	for (int rep = 0; rep < PATHBENCH_BUILD_REPEAT; rep++) {
		double t0 = bench_now_ms();
		skeleton_edt(&bm->grid, dist2);
		double t1 = bench_now_ms();
		skeleton_compute(&bm->skeleton, &bm->grid);
		double t2 = bench_now_ms();
		pathgraph_build(&bm->pathgraph, &bm->skeleton, &bm->grid);
		double t3 = bench_now_ms();
		bm->edt_ms = fmin(bm->edt_ms, t1 - t0);
		bm->skeleton_ms = fmin(bm->skeleton_ms, t2 - t1);
		bm->pathgraph_ms = fmin(bm->pathgraph_ms, t3 - t2);
	}
	free(dist2);
	bm->has_skeleton = true;
}

/* bench_load: reads a map (and its scenarios when scen_path is not NULL) and builds
 * the planners' per-map state (the visibility graph only when with_visibility, the
 * skeleton and pathgraph only when with_skeleton); on
 * a bad file prints one line and exits 2. */
static void bench_load(BenchMap *bm, const char *map_path, const char *scen_path,
                       bool with_visibility, bool with_skeleton)
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
	if (with_skeleton)
		bench_build_skeleton(bm);
}

static void bench_unload(BenchMap *bm)
{
	if (bm->has_visibility)
		visibility_free(&bm->visibility);
	if (bm->has_skeleton) {
		pathgraph_free(&bm->pathgraph);
		skeleton_free(&bm->skeleton);
	}
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

/* The paths one scenario needs, kept between scenarios so that their memory is. */
typedef struct BenchPaths {
	Path path, tight;              /* grid A*, then its rope; the any-angle path */
	Path skeleton, skeleton_tight; /* the skeleton planner's path and its rope */
	Path alt[PATHBENCH_MAX_SKEL_PATHS]; /* --skel-paths: the pathgraph's K best */
} BenchPaths;

static void bench_paths_init(BenchPaths *bp)
{
	path_init(&bp->path);
	path_init(&bp->tight);
	path_init(&bp->skeleton);
	path_init(&bp->skeleton_tight);
	for (int k = 0; k < PATHBENCH_MAX_SKEL_PATHS; k++)
		path_init(&bp->alt[k]);
}

static void bench_paths_free(BenchPaths *bp)
{
	path_free(&bp->path);
	path_free(&bp->tight);
	path_free(&bp->skeleton);
	path_free(&bp->skeleton_tight);
	for (int k = 0; k < PATHBENCH_MAX_SKEL_PATHS; k++)
		path_free(&bp->alt[k]);
}

static void bench_check_skeleton_rope(const BenchMap *bm, const BenchPaths *bp,
                                      BenchResult *r);

/* bench_run_skeleton_k: --skel-paths K > 1: the K best topologically distinct paths
 * of the pathgraph (pathgraph_find_paths), each rope-tightened, the shortest rope
 * kept (and the path it came from). Not what the planner does (it tightens its one
 * best path); a measure of how many of the bench's long ropes come from the pathgraph
 * choosing the wrong way round an obstacle. q.ms and q.exp count the K searches, not
 * the ropes. */
static void bench_run_skeleton_k(BenchMap *bm, Vec2 s, Vec2 d, BenchPaths *bp, BenchResult *r)
{
	double t0 = bench_now_ms();
	int n = pathgraph_find_paths(&bm->pathgraph, s, d, NULL, bench_skel_paths, bp->alt);
	r->skeleton_ms = bench_now_ms() - t0;
	if (n == 0) {
		r->skeleton_expanded = 0;
		r->skeleton_status = SKEL_NO_PATH;
		return;
	}
	r->skeleton_expanded = bp->alt[n - 1].expanded;
	int best = -1;
	for (int k = 0; k < n; k++) {
		/* A refused path is reported even when another path's rope is kept. */
		if (rope_tighten(&bm->grid, &bp->alt[k], &bp->skeleton_tight) != ROPE_OK) {
			r->skeleton_status = SKEL_ROPE_BAD_INPUT;
			continue;
		}
		double len = path_length(&bp->skeleton_tight);
		if (best < 0 || len < r->skeleton_rope) {
			best = k;
			r->skeleton_rope = len;
		}
	}
	if (best < 0)
		return;
	/* Tighten the kept one again, so that the checks see its rope and its path. */
	path_clear(&bp->skeleton);
	for (int i = 0; i < bp->alt[best].count; i++)
		path_push(&bp->skeleton, bp->alt[best].pts[i]);
	rope_tighten(&bm->grid, &bp->skeleton, &bp->skeleton_tight);
	r->skeleton = path_length(&bp->skeleton);
	bench_check_skeleton_rope(bm, bp, r);
}

/* bench_run_skeleton: the skeleton planner on problem pr: the pathgraph path from the
 * centre of S's cell to that of D's (through S' and D', paper 4.3), then the same
 * rope-tightened (paper 5). Only called when A* found a path, so a failure to find
 * one is the skeleton planner's. */
static void bench_run_skeleton(BenchMap *bm, const MovingAiProblem *pr, BenchPaths *bp,
                               BenchResult *r)
{
	Vec2 s = vec2(pr->sx + 0.5, pr->sy + 0.5), d = vec2(pr->gx + 0.5, pr->gy + 0.5);
	if (bench_skel_paths > 1) {
		bench_run_skeleton_k(bm, s, d, bp, r);
		return;
	}
	double t0 = bench_now_ms();
	bool found = pathgraph_find_path(&bm->pathgraph, s, d, NULL, &bp->skeleton);
	r->skeleton_ms = bench_now_ms() - t0;
	r->skeleton_expanded = bp->skeleton.expanded;
	if (!found) {
		r->skeleton_status = SKEL_NO_PATH;
		return;
	}
	r->skeleton = path_length(&bp->skeleton);
	if (rope_tighten(&bm->grid, &bp->skeleton, &bp->skeleton_tight) != ROPE_OK) {
		r->skeleton_status = SKEL_ROPE_BAD_INPUT;
		return;
	}
	r->skeleton_rope = path_length(&bp->skeleton_tight);
	bench_check_skeleton_rope(bm, bp, r);
}

/* bench_check_skeleton_rope: the checks on the rope in bp->skeleton_tight of the path
 * bp->skeleton, whose lengths are in r. */
static void bench_check_skeleton_rope(const BenchMap *bm, const BenchPaths *bp,
                                      BenchResult *r)
{
	/* The same checks as for the A* path's rope: free, not longer than its input. */
	r->skeleton_rope_ok = r->skeleton_rope <= r->skeleton + PATHBENCH_LENGTH_EPS &&
	                      visibility_path_free(&bm->grid, &bp->skeleton_tight);
	/* The target: never longer than the grid optimum (A*'s exact length,
	 * which matches the published one) plus one square. */
	r->skeleton_over = r->skeleton_rope > r->astar + 1 + PATHBENCH_LENGTH_EPS;
}

/* bench_run: solves problem i with every planner. */
static BenchResult bench_run(BenchMap *bm, int i, BenchPaths *bp)
{
	Path *path = &bp->path, *tight = &bp->tight;
	const MovingAiProblem *pr = &bm->scen.problems[i];
	BenchResult r = {.optimum = pr->optimum,
	                 .anyangle = -1,
	                 .rope = -1,
	                 .skeleton = -1,
	                 .skeleton_rope = -1,
	                 .anyangle_ms = -1,
	                 .rope_ms = -1,
	                 .anyangle_expanded = -1,
	                 .skeleton_ms = -1,
	                 .skeleton_expanded = -1,
	                 .rope_ok = 1,
	                 .skeleton_rope_ok = 1};
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
	if (bm->has_skeleton && st == GRIDPATH_FOUND) {
		bench_run_skeleton(bm, pr, bp, &r);
		/* ... and, like any path, the rope is no shorter than the any-angle optimum. */
		if (r.skeleton_rope >= 0 && r.anyangle >= 0 &&
		    r.anyangle > r.skeleton_rope + PATHBENCH_LENGTH_EPS)
			r.skeleton_rope_ok = 0;
	}
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
	if (!r->skeleton_rope_ok)
		fprintf(stderr,
		        PATHBENCH_NAME ": %s:%d: rope-tightening of the skeleton path failed its "
		                       "checks (skeleton %.6f, rope %.6f, any-angle %.6f)\n",
		        bm->scen_path, line, r->skeleton, r->skeleton_rope, r->anyangle);
	return !r->astar_ok || !r->rope_ok || !r->skeleton_rope_ok;
}

/* Two ropes whose lengths differ by less than this are taken to be in the same
 * homotopy class (one class has one shortest path; different classes, on these maps,
 * differ by far more than rounding). */
#define PATHBENCH_HOMOTOPY_EPS 1e-6

/* bench_report_skeleton: the skeleton planner's shortfalls against the issue's
 * targets, on stderr, one line each: not errors of the program (the exit status does
 * not change), but every one is printed and counted, never hidden. */
static void bench_report_skeleton(const BenchMap *bm, int i, const BenchResult *r)
{
	int line = (int)bm->scen.problems[i].line;
	if (r->skeleton_status == SKEL_NO_PATH)
		fprintf(stderr, PATHBENCH_NAME ": %s:%d: skeleton planner found no path (A* %.6f)\n",
		        bm->scen_path, line, r->astar);
	else if (r->skeleton_status == SKEL_ROPE_BAD_INPUT)
		fprintf(stderr,
		        PATHBENCH_NAME ": %s:%d: rope_tighten refused the skeleton path (not free "
		                       "by visibility_path_free; skeleton %.6f)\n",
		        bm->scen_path, line, r->skeleton);
	else if (r->skeleton_over)
		/* The A* path's rope is the shortest path of the optimum's homotopy class (or
		 * of one as short): a skeleton rope longer than it went round some obstacle
		 * on the other side, which no tightening can undo. */
		fprintf(stderr,
		        PATHBENCH_NAME ": %s:%d: tightened skeleton path %.6f > grid optimum "
		                       "%.6f + 1 (skeleton %.6f, A* rope %.6f, any-angle %.6f): %s\n",
		        bm->scen_path, line, r->skeleton_rope, r->astar, r->skeleton, r->rope,
		        r->anyangle,
		        r->rope >= 0 && r->skeleton_rope > r->rope + PATHBENCH_HOMOTOPY_EPS
		            ? "another homotopy class"
		            : "same length as the A* rope");
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
	bench_load(&bm, map_path, scen_path, true, true);
	BenchPaths bp;
	bench_paths_init(&bp);
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
		BenchResult r = bench_run(&bm, i, &bp);
		printf("%7d %6d", i, (int)bm.scen.problems[i].bucket);
		bench_print_length(r.optimum);
		bench_print_length(r.astar);
		bench_print_length(r.anyangle);
		bench_print_length(r.rope);
		bench_print_length(r.skeleton);
		bench_print_length(r.skeleton_rope);
		printf("%s%s%s%s\n", r.astar_ok ? "" : "  MISSED",
		       r.rope_ok && r.skeleton_rope_ok ? "" : "  ROPE-FAILED",
		       r.skeleton_status == SKEL_NO_PATH          ? "  SKEL-NO-PATH"
		       : r.skeleton_status == SKEL_ROPE_BAD_INPUT ? "  SKEL-ROPE-REFUSED"
		                                                  : "",
		       r.skeleton_over ? "  SKEL>OPT+1" : "");
		failed += bench_report(&bm, i, &r);
		bench_report_skeleton(&bm, i, &r);
	}
	bench_paths_free(&bp);
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
	COL_ASTAR_MS,        /* grid A* query time */
	COL_ASTAR_EXP,       /* cells A* expanded */
	COL_VIS_BUILD_MS,    /* visibility graph build, one value per map */
	COL_VIS_MS,          /* visibility query time */
	COL_VIS_EXP,         /* visibility nodes expanded */
	COL_ANY_OVER_OPT,    /* any-angle optimum / published 8-connected optimum */
	COL_ROPE_MS,         /* rope-tightening time */
	COL_ROPE_OVER_OPT,   /* rope-tightened A* / published optimum */
	COL_ROPE_OVER_ANY,   /* rope-tightened A* / any-angle optimum */
	COL_ROPE_MINUS_OPT,  /* rope-tightened A* - published optimum (the issue's
	                        "never longer than the grid optimum + 1") */
	COL_EDT_MS,          /* distance transform, one value per map */
	COL_SKEL_MS,         /* skeleton (its distance transform included), per map */
	COL_PG_MS,           /* pathgraph build, per map */
	COL_Q_MS,            /* pathgraph query (S', D', A* on the pathgraph, the path) */
	COL_Q_EXP,           /* pathgraph vertices the query expanded */
	COL_EXP_RATIO,       /* A* cells expanded / pathgraph vertices expanded */
	COL_SK_OVER_OPT,     /* skeleton path / published optimum */
	COL_SKR_OVER_OPT,    /* tightened skeleton path / published optimum */
	COL_SK_OVER_ANY,     /* skeleton path / any-angle optimum */
	COL_SKR_OVER_ANY,    /* tightened skeleton path / any-angle optimum */
	COL_SKR_MINUS_ASTAR, /* tightened skeleton path - grid optimum (target <= 1) */
	COL_COUNT
};

/* The counts of a row: scenarios run, A* matches, and the skeleton planner's
 * shortfalls (each also printed on stderr by bench_report_skeleton). */
typedef struct BenchCounts {
	int run, ok;
	int over;      /* tightened skeleton path longer than the grid optimum + 1 */
	int skel_fail; /* no skeleton path, or rope_tighten refused it */
} BenchCounts;

/* The table: one row per scenario file, every figure a median over the scenarios
 * run, except vis.V (the corners), the build times (once per map; in the last row,
 * the median over the maps) and the .mx columns (maxima). */
static void bench_print_header(void)
{
	printf("%-32s %9s %8s %5s %4s %7s %7s | %6s %9s %7s %6s %7s | %7s %8s %8s %8s %8s"
	       " | skel: %6s %6s %6s %6s %6s %7s | %7s %7s %7s %7s %8s %8s %5s %4s\n",
	       "map", "size", "cells", "run", "A*ok", "A*.ms", "A*.exp", "vis.V", "vis.build",
	       "vis.ms", "vis.ex", "any/opt", "rope.ms", "rope/opt", "rope/any", "r/any.mx",
	       "r-opt.mx", "dt.ms", "sk.ms", "pg.ms", "q.ms", "q.exp", "A*/q", "sk/opt",
	       "skr/opt", "sk/any", "skr/any", "skr/a.mx", "skr-o.mx", ">o+1", "fail");
}

static void bench_print_row(const char *name, const char *size, int64_t cells,
                            const BenchCounts *n, double corners, BenchColumn col[COL_COUNT])
{
	printf("%-32s %9s %8lld %5d %4s", name, size, (long long)cells, n->run,
	       n->ok == n->run ? "all" : "MISS");
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
	bench_print_value(6, 2, bench_column_median(&col[COL_EDT_MS]));
	bench_print_value(6, 2, bench_column_median(&col[COL_SKEL_MS]));
	bench_print_value(6, 2, bench_column_median(&col[COL_PG_MS]));
	bench_print_value(6, 3, bench_column_median(&col[COL_Q_MS]));
	bench_print_value(6, 0, bench_column_median(&col[COL_Q_EXP]));
	bench_print_value(7, 1, bench_column_median(&col[COL_EXP_RATIO]));
	printf(" |");
	bench_print_value(7, 4, bench_column_median(&col[COL_SK_OVER_OPT]));
	bench_print_value(7, 4, bench_column_median(&col[COL_SKR_OVER_OPT]));
	bench_print_value(7, 4, bench_column_median(&col[COL_SK_OVER_ANY]));
	bench_print_value(7, 4, bench_column_median(&col[COL_SKR_OVER_ANY]));
	bench_print_value(8, 4, bench_column_max(&col[COL_SKR_OVER_ANY]));
	bench_print_value(8, 3, bench_column_max(&col[COL_SKR_MINUS_ASTAR]));
	printf(" %5d %4d\n", n->over, n->skel_fail);
}

static const char *bench_basename(const char *path)
{
	const char *s = strrchr(path, '/');
	return s ? s + 1 : path;
}

/* bench_ratio(a, b): a / b, or NAN when either is not computed (negative) or b is 0. */
static double bench_ratio(double a, double b)
{
	return a >= 0 && b > 0 ? a / b : NAN;
}

/* bench_columns: one scenario's values, NAN where not computed. */
static void bench_columns(const BenchResult *r, double v[COL_COUNT])
{
	bool any = r->anyangle >= 0, rope = r->rope >= 0, skel = r->skeleton_ms >= 0;
	for (int c = 0; c < COL_COUNT; c++)
		v[c] = NAN;
	v[COL_ASTAR_MS] = r->astar_ms;
	v[COL_ASTAR_EXP] = (double)r->astar_expanded;
	v[COL_VIS_MS] = any ? r->anyangle_ms : NAN;
	v[COL_VIS_EXP] = any ? (double)r->anyangle_expanded : NAN;
	v[COL_ANY_OVER_OPT] = bench_ratio(r->anyangle, r->optimum);
	v[COL_ROPE_MS] = rope ? r->rope_ms : NAN;
	v[COL_ROPE_OVER_OPT] = bench_ratio(r->rope, r->optimum);
	v[COL_ROPE_OVER_ANY] = any ? bench_ratio(r->rope, r->anyangle) : NAN;
	v[COL_ROPE_MINUS_OPT] = rope ? r->rope - r->optimum : NAN;
	v[COL_Q_MS] = skel ? r->skeleton_ms : NAN;
	v[COL_Q_EXP] = skel ? (double)r->skeleton_expanded : NAN;
	/* A query that expands no vertex (S' and D' on one edge) has no finite ratio. */
	v[COL_EXP_RATIO] =
	    skel && r->skeleton_expanded > 0
	        ? (double)r->astar_expanded / (double)r->skeleton_expanded
	        : NAN;
	v[COL_SK_OVER_OPT] = bench_ratio(r->skeleton, r->optimum);
	v[COL_SKR_OVER_OPT] = bench_ratio(r->skeleton_rope, r->optimum);
	v[COL_SK_OVER_ANY] = any ? bench_ratio(r->skeleton, r->anyangle) : NAN;
	v[COL_SKR_OVER_ANY] = any ? bench_ratio(r->skeleton_rope, r->anyangle) : NAN;
	v[COL_SKR_MINUS_ASTAR] = r->skeleton_rope >= 0 ? r->skeleton_rope - r->astar : NAN;
}

/* bench_map_columns: the values built once per map (a single value each). */
static void bench_map_columns(const BenchMap *bm, double v[COL_COUNT])
{
	for (int c = 0; c < COL_COUNT; c++)
		v[c] = NAN;
	if (bm->has_visibility)
		v[COL_VIS_BUILD_MS] = bm->visibility_build_ms;
	if (bm->has_skeleton) {
		v[COL_EDT_MS] = bm->edt_ms;
		v[COL_SKEL_MS] = bm->skeleton_ms;
		v[COL_PG_MS] = bm->pathgraph_ms;
	}
}

static void bench_columns_add(BenchColumn *col, BenchColumn *all, const double v[COL_COUNT])
{
	for (int c = 0; c < COL_COUNT; c++) {
		bench_column_add(&col[c], v[c]);
		bench_column_add(&all[c], v[c]);
	}
}

static void bench_counts_add(BenchCounts *n, const BenchResult *r)
{
	n->run++;
	n->ok += r->astar_ok;
	n->over += r->skeleton_over;
	n->skel_fail += r->skeleton_ms >= 0 && r->skeleton_status != SKEL_OK;
}

static int bench_table(int argc, char **argv, int sample)
{
	if (argc < 2 || argc % 2 != 0)
		bench_die_usage();
	BenchColumn all[COL_COUNT] = {{0}};
	BenchCounts all_n = {0};
	int failed = 0;
	int64_t all_cells = 0;
	bench_print_header();
	BenchPaths bp;
	bench_paths_init(&bp);
	for (int m = 0; m < argc; m += 2) {
		BenchMap bm;
		bench_load(&bm, argv[m], argv[m + 1], true, true);
		BenchColumn col[COL_COUNT] = {{0}};
		BenchCounts n = {0};
		double v[COL_COUNT];
		bench_map_columns(&bm, v);
		bench_columns_add(col, all, v);
		for (int i = 0; i < bm.scen.count; i++) {
			if (!bench_selected(i, bm.scen.count, sample))
				continue;
			BenchResult r = bench_run(&bm, i, &bp);
			failed += bench_report(&bm, i, &r);
			bench_report_skeleton(&bm, i, &r);
			bench_counts_add(&n, &r);
			bench_counts_add(&all_n, &r);
			bench_columns(&r, v);
			bench_columns_add(col, all, v);
		}
		char size[32];
		snprintf(size, sizeof size, "%dx%d", (int)bm.grid.w, (int)bm.grid.h);
		/* The row is named after the scenario file (a map may have several). */
		char name[64];
		snprintf(name, sizeof name, "%s", bench_basename(argv[m + 1]));
		for (char *dot; (dot = strrchr(name, '.')) &&
		                (strcmp(dot, ".scen") == 0 || strcmp(dot, ".map") == 0);)
			*dot = '\0';
		fflush(stderr);
		bench_print_row(name, size, bm.free_cells, &n, (double)bm.corners, col);
		fflush(stdout);
		for (int c = 0; c < COL_COUNT; c++)
			free(col[c].v);
		all_cells += bm.free_cells;
		bench_unload(&bm);
	}
	bench_print_row("MEDIAN (all scenarios run)", "", all_cells, &all_n, NAN, all);
	for (int c = 0; c < COL_COUNT; c++)
		free(all[c].v);
	bench_paths_free(&bp);
	printf("# any-angle columns only where the map has at most %d corners (--vis-limit)\n",
	       (int)bench_vis_limit);
	printf("# skel: dt.ms, sk.ms (distance transform included), pg.ms: best of %d builds "
	       "per map; q.ms, q.exp: the pathgraph query;\n"
	       "#   A*/q: A* cells expanded / pathgraph vertices expanded, per scenario; "
	       "skr = the skeleton path rope-tightened;\n"
	       "#   skr-o.mx: the largest skr minus the grid optimum; >o+1: scenarios where "
	       "skr > grid optimum + 1; fail: no path or rope refused (stderr)\n",
	       PATHBENCH_BUILD_REPEAT);
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

static int bench_corner(int argc, char **argv, int scale, bool jump)
{
	printf("# grid A* corner to corner, best of %d runs: wall clock and thread CPU time\n",
	       PATHBENCH_CORNER_REPEAT);
	printf(
	    "map                         size       cells    length   expanded      ms  cpu.ms\n");
	Path path;
	path_init(&path);
	for (int m = 0; m < argc; m++) {
		BenchMap bm;
		bench_load(&bm, argv[m], NULL, false, false);
		if (scale > 1) {
			gridpath_free(&bm.astar);
			bench_scale(&bm.grid, scale);
			gridpath_init(&bm.astar, &bm.grid);
			bm.free_cells *= (int64_t)scale * scale;
		}
		if (jump)
			bm.astar.method = GRIDPATH_JUMP;
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
		bench_load(&bm, argv[m], NULL, false, false);
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
	bool jump = false;
	for (; a < argc && strncmp(argv[a], "--", 2) == 0; a++) {
		if (strcmp(argv[a], "--table") == 0)
			table = 1;
		else if (strcmp(argv[a], "--corner") == 0)
			corner = 1;
		else if (strcmp(argv[a], "--cspace") == 0)
			cspace = 1;
		else if (strcmp(argv[a], "--jump") == 0)
			jump = true;
		else if ((strcmp(argv[a], "--sample") == 0 || strcmp(argv[a], "--scale") == 0 ||
		          strcmp(argv[a], "--vis-limit") == 0 ||
		          strcmp(argv[a], "--skel-paths") == 0) &&
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
			else if (strcmp(argv[a], "--skel-paths") == 0) {
				if (v > PATHBENCH_MAX_SKEL_PATHS)
					bench_die_usage();
				bench_skel_paths = (int)v;
			}
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
		return argc - a >= 1 ? bench_corner(argc - a, argv + a, scale, jump)
		                     : (bench_die_usage(), 2);
	if (table)
		return bench_table(argc - a, argv + a, sample);
	if (argc - a != 2)
		bench_die_usage();
	return bench_lines(argv[a], argv[a + 1], sample);
}
