/* carrybench.c - carrying a held object in (x, y, theta) (carry.h; paper 3.6, 5): the
 * planner's time and the configurations it expands on generated screens of 64 to 512
 * squares, with and without its pruning.
 *
 *   build/rel/bench/carrybench [--angles N] [--reps R] [--sizes LIST] [--write DIR]
 *
 * Problems, each at screens of 64, 128, 256 and 512 squares a side (LIST, e.g.
 * "64,128", chooses), from a fixed seed; objects and doors grow with the screen by
 * s = max(1, side / 128) so that the problem keeps its shape:
 *   door      two rooms, a door 3s wide; a brick s x 4s standing across it must turn
 *             to pass; the goal: wholly in the other room;
 *   ldoor     the L-shape of test_carry (arms 8s and 5s, s thick) through a door 3s
 *             wide, held in its inner corner: it must turn in the doorway;
 *   corridor  an L-shaped corridor 4s wide; a brick 2s x 5s round the corner,
 *             wholly into the other leg;
 *   clutter   one room with random blocks (about 15% of it); a square 3s across
 *             from the south-west into the north-east quarter;
 *   nodoor    the door problem with a square 4s across: impossible, and said why.
 * Each line: the problem, whether found, and by what ("corridor": the search in the
 * skeleton route's corridor; "grid": the search on the whole grid; "disc": no path,
 * proved by the object's inscribed disc before any search), the planner's time
 * (thread CPU ms, the best of R runs, default 3, set-up included), the configurations
 * expanded, footprints and sweeps checked against the grid and settled by clearance,
 * the plan (pushes, turns, and its length: squares pushed plus the far end's travel
 * in turns), then the times without each pruning in turn (the route's corridor, the
 * clearance of the reach, the disc's proof) and without any, the expansions without
 * any, and the ratios of time and expansions with none over with all (above 1, the
 * pruning saves; a proof without search counts as one expansion).
 *
 * --write DIR also writes each problem as DIR/NAME.carry for bench/carryompl.cpp
 * (OMPL on the same problems): "carry 1", "grid W H" and H rows of '.' free / '#'
 * blocked (row y = 0 first), "goal" and H rows ('.' in the goal region), "object N
 * X1 Y1 ... XN YN", "utak X Y", "angles N", "name NAME". */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "utak/plan/carry.h"

static uint64_t bench_seed = 2026;
static uint32_t bench_rand(void)
{
	bench_seed = bench_seed * 6364136223846793005ULL + 1442695040888963407ULL;
	return (uint32_t)(bench_seed >> 33);
}

/* bench_now_ms: this thread's CPU time, in ms (skelbench.c says why CPU time). */
static double bench_now_ms(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

typedef struct Problem {
	char name[64];
	Grid grid, goal;
	CarryObject obj;
} Problem;

static void fill(Grid *g, int32_t x0, int32_t y0, int32_t x1, int32_t y1, uint8_t v)
{
	for (int32_t y = y0 < 0 ? 0 : y0; y < y1 && y < g->h; y++)
		for (int32_t x = x0 < 0 ? 0 : x0; x < x1 && x < g->w; x++)
			g->cells[(size_t)y * g->w + x] = v;
}

/* frame(p, side): a side x side grid with a blocked ring, and an empty goal. */
static void frame(Problem *p, int32_t side)
{
	grid_init(&p->grid, side, side, GRID_FREE);
	grid_init(&p->goal, side, side, GRID_BLOCKED);
	fill(&p->grid, 0, 0, side, 1, GRID_BLOCKED);
	fill(&p->grid, 0, side - 1, side, side, GRID_BLOCKED);
	fill(&p->grid, 0, 0, 1, side, GRID_BLOCKED);
	fill(&p->grid, side - 1, 0, side, side, GRID_BLOCKED);
}

static Polygon rect(double x0, double y0, double x1, double y1)
{
	return (Polygon){4, {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

/* two_rooms(p, side, s, door_lo): a wall s thick at x = side / 2 with a door 3s wide
 * from row door_lo; the goal is the east room. */
static void two_rooms(Problem *p, int32_t side, int32_t s, int32_t door_lo)
{
	frame(p, side);
	int32_t wall = side / 2;
	fill(&p->grid, wall, 0, wall + s, door_lo, GRID_BLOCKED);
	fill(&p->grid, wall, door_lo + 3 * s, wall + s, side, GRID_BLOCKED);
	fill(&p->goal, wall + s, 0, side, side, GRID_FREE);
}

static void make_problem(Problem *p, const char *kind, int32_t side)
{
	/* Each problem its own seed: the same problem whichever sizes are run. */
	bench_seed = 2026;
	for (const char *c = kind; *c; c++)
		bench_seed = bench_seed * 31 + (uint64_t)*c;
	bench_seed = bench_seed * 31 + (uint64_t)side;
	int32_t s = side / 128 > 1 ? side / 128 : 1;
	snprintf(p->name, sizeof p->name, "%s-%d", kind, side);
	double mid = side / 2;
	if (strcmp(kind, "door") == 0 || strcmp(kind, "nodoor") == 0) {
		int32_t lo = (int32_t)(side / 4 + bench_rand() % (uint32_t)(side / 2));
		two_rooms(p, side, s, lo);
		double x0 = side / 8 + 1, y0 = mid - 2 * s;
		bool fat = strcmp(kind, "nodoor") == 0;
		p->obj.shape = fat ? rect(x0, y0, x0 + 4 * s, y0 + 4 * s) : rect(x0, y0, x0 + s, y0 + 4 * s);
		p->obj.at = vec2(x0 - 0.5, y0 + 0.5);
		p->obj.name = fat ? "the square" : "the brick";
	} else if (strcmp(kind, "ldoor") == 0) {
		frame(p, side);
		int32_t wall = side / 2, lo = (int32_t)mid;
		fill(&p->grid, wall, 0, wall + s, lo, GRID_BLOCKED);
		fill(&p->grid, wall, lo + 3 * s, wall + s, side, GRID_BLOCKED);
		fill(&p->goal, wall + s, 0, side, side, GRID_FREE);
		double x0 = wall - 11 * s, y0 = mid - 3 * s, t = s;
		p->obj.shape = (Polygon){6, {{x0, y0}, {x0 + 8 * s, y0}, {x0 + 8 * s, y0 + t}, {x0 + t, y0 + t},
					     {x0 + t, y0 + 5 * s}, {x0, y0 + 5 * s}}};
		p->obj.at = vec2(x0 + s + 0.5, y0 + s + 0.5);
		p->obj.name = "the L-shaped object";
	} else if (strcmp(kind, "corridor") == 0) {
		frame(p, side);
		int32_t w = 4 * s, y0 = side / 8, x1 = side / 2;
		/* Blocked everywhere but the two legs. */
		fill(&p->grid, 1, 1, side - 1, y0, GRID_BLOCKED);
		fill(&p->grid, 1, y0 + w, x1, side - 1, GRID_BLOCKED);
		fill(&p->grid, x1 + w, y0, side - 1, side - 1, GRID_BLOCKED);
		fill(&p->goal, x1, y0 + w, x1 + w, side - 1, GRID_FREE);
		double bx = 2 + s, by = y0 + s;
		p->obj.shape = rect(bx, by, bx + 5 * s, by + 2 * s);
		p->obj.at = vec2(bx + floor(1.5 * s) + 0.5, by + 2 * s + 0.5);
		p->obj.name = "the brick";
	} else { /* clutter */
		frame(p, side);
		double x0 = side / 16 + 1, y0 = side / 16 + 1;
		p->obj.shape = rect(x0, y0, x0 + 3 * s, y0 + 3 * s);
		p->obj.at = vec2(x0 - 0.5, y0 + 0.5);
		p->obj.name = "the square";
		/* Blocks of 2s to 8s squares, not over the object, Utak or the goal's corner. */
		int32_t area = 0;
		while (area < side * side * 15 / 100) {
			int32_t bw = (int32_t)(2 * s + bench_rand() % (uint32_t)(6 * s + 1));
			int32_t bh = (int32_t)(2 * s + bench_rand() % (uint32_t)(6 * s + 1));
			int32_t bx = (int32_t)(bench_rand() % (uint32_t)side), by = (int32_t)(bench_rand() % (uint32_t)side);
			bool near_start = bx < x0 + 3 * s + 4 * s && by < y0 + 3 * s + 4 * s;
			bool near_goal = bx + bw > side - side / 8 && by + bh > side - side / 8;
			if (near_start || near_goal)
				continue;
			fill(&p->grid, bx, by, bx + bw, by + bh, GRID_BLOCKED);
			area += bw * bh;
		}
		fill(&p->goal, side / 2, side / 2, side, side, GRID_FREE);
	}
}

static void write_problem(const Problem *p, const char *dir, int32_t angles)
{
	char path[512];
	snprintf(path, sizeof path, "%s/%s.carry", dir, p->name);
	FILE *f = fopen(path, "w");
	if (!f) {
		perror(path);
		exit(2);
	}
	fprintf(f, "carry 1\ngrid %d %d\n", p->grid.w, p->grid.h);
	for (int32_t y = 0; y < p->grid.h; y++) {
		for (int32_t x = 0; x < p->grid.w; x++)
			fputc(p->grid.cells[(size_t)y * p->grid.w + x] == GRID_FREE ? '.' : '#', f);
		fputc('\n', f);
	}
	fprintf(f, "goal\n");
	for (int32_t y = 0; y < p->goal.h; y++) {
		for (int32_t x = 0; x < p->goal.w; x++)
			fputc(p->goal.cells[(size_t)y * p->goal.w + x] == GRID_FREE ? '.' : '#', f);
		fputc('\n', f);
	}
	fprintf(f, "object %d", p->obj.shape.count);
	for (int32_t i = 0; i < p->obj.shape.count; i++)
		fprintf(f, " %.17g %.17g", p->obj.shape.v[i].x, p->obj.shape.v[i].y);
	fprintf(f, "\nutak %.17g %.17g\nangles %d\nname %s\n", p->obj.at.x, p->obj.at.y, angles, p->name);
	fclose(f);
}

/* run(p, params, reps, out, ms): plans reps times on a fresh planner each (its
 * set-up, the distance transform, included); the best time. */
static void run(const Problem *p, const CarryParams *params, int reps, CarryResult *out, double *ms)
{
	*ms = INFINITY;
	for (int r = 0; r < reps; r++) {
		double t0 = bench_now_ms();
		CarryPlanner cp;
		carry_init(&cp, &p->grid, params);
		CarryGoal goal = {.inside = &p->goal};
		carry_plan(&cp, &p->obj, &goal, out);
		carry_free(&cp);
		double t = bench_now_ms() - t0;
		*ms = t < *ms ? t : *ms;
	}
}

int main(int argc, char **argv)
{
	int32_t angles = CARRY_ANGLES_DEFAULT, reps = 3;
	const char *dir = NULL, *sizes = "64,128,256,512";
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "--angles") == 0 && i + 1 < argc)
			angles = atoi(argv[++i]);
		else if (strcmp(argv[i], "--reps") == 0 && i + 1 < argc)
			reps = atoi(argv[++i]);
		else if (strcmp(argv[i], "--write") == 0 && i + 1 < argc)
			dir = argv[++i];
		else if (strcmp(argv[i], "--sizes") == 0 && i + 1 < argc)
			sizes = argv[++i];
		else {
			fprintf(stderr, "usage: carrybench [--angles N] [--reps R] [--sizes LIST] [--write DIR]\n");
			return 2;
		}
	}
	static const char *const kinds[] = {"door", "ldoor", "corridor", "clutter", "nodoor"};
	printf("carrybench: %d angles, best of %d runs, thread CPU ms (set-up included)\n", angles, reps);
	printf("%-14s %5s %8s %8s %9s %9s %9s %6s %5s %8s | %8s %8s %8s %8s %9s | %6s %6s\n", "problem", "found",
	       "by", "ms", "expanded", "checked", "settled", "pushes", "turns", "length", "-route", "-reach",
	       "-disc", "none", "exp-none", "x time", "x exp");
	char list[256];
	snprintf(list, sizeof list, "%s", sizes);
	for (char *tok = strtok(list, ","); tok; tok = strtok(NULL, ",")) {
		int32_t side = atoi(tok);
		if (side < 32 || side > 4096) {
			fprintf(stderr, "carrybench: a size must be 32 to 4096, not %s\n", tok);
			return 2;
		}
		for (size_t k = 0; k < sizeof kinds / sizeof *kinds; k++) {
			Problem p = {0};
			make_problem(&p, kinds[k], side);
			if (dir)
				write_problem(&p, dir, angles);
			/* all pruning; then without the route, the clearance, the disc; none */
			CarryParams pr[5];
			CarryResult res[5];
			double ms[5];
			for (int v = 0; v < 5; v++) {
				pr[v] = carry_params_default();
				pr[v].angles = angles;
				pr[v].use_route = v != 1 && v != 4;
				pr[v].use_clearance = v != 2 && v != 4;
				pr[v].use_disc = v != 3 && v != 4;
				carry_result_init(&res[v]);
				run(&p, &pr[v], reps, &res[v], &ms[v]);
			}
			const CarryResult *a = &res[0], *b = &res[4];
			const char *by = a->stats.disc_proof ? "disc" : a->stats.found_in_corridor ? "corridor" : "grid";
			double length = a->plan.pushed + a->plan.turned * (3.14159265358979323846 / 180) * a->reach;
			printf("%-14s %5s %8s %8.1f %9lld %9lld %9lld %6d %5d %8.1f | %8.1f %8.1f %8.1f %8.1f %9lld | %6.2f "
			       "%6.1f\n",
			       p.name, a->status == CARRY_FOUND ? "yes" : "no", by, ms[0], (long long)a->stats.expanded,
			       (long long)a->stats.checked, (long long)a->stats.settled, a->plan.pushes, a->plan.turns,
			       length, ms[1], ms[2], ms[3], ms[4], (long long)b->stats.expanded, ms[4] / ms[0],
			       (double)b->stats.expanded / (double)(a->stats.expanded > 0 ? a->stats.expanded : 1));
			if (a->status != CARRY_FOUND)
				printf("  %s: %s\n", p.name, a->why);
			for (int v = 1; v < 5; v++)
				if ((res[v].status == CARRY_FOUND) != (a->status == CARRY_FOUND)) {
					printf("carrybench: %s: the searches with and without pruning disagree\n", p.name);
					return 1;
				}
			for (int v = 0; v < 5; v++)
				carry_result_free(&res[v]);
			grid_free(&p.grid);
			grid_free(&p.goal);
		}
	}
	return 0;
}
