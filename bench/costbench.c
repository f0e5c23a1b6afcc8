/* costbench.c - whether the costs of a motor command and of a task's verdict
 * follow the work done (issue 14; paper 2.2 motion and perception, 2.3 the
 * verdict). A benchmark, not a test: it prints times and their ratios, measured
 * in one run on one world, so that the machine's speed cancels out.
 *
 * The world, built in memory: a SIDE x SIDE TABLE (default 1024) with OBJECTS
 * objects (default 4096, utak(5)'s limit) on a lattice of cells, one per cell:
 * squares, bricks and right triangles by turns, 3 to 9 squares across (fixed
 * seed); Utak at (2.5, 2.5) facing north, next to the verge's south-west corner.
 *
 * (1) A motor command and its perception (motion_execute, retina_sense,
 *     controller_perceive after controller_start, as utak --act runs them):
 *     'move -1000000 -1000000' against 'move -10 -10'. Both halt at the verge
 *     within two squares, so a cost that follows the distance actually travelled
 *     makes the ratio about 1; before issue 14 the world model walked the whole
 *     commanded line (about 20 s).
 * (2) judge_task with Utak where he began: 'push square sw-corner' (the nearest
 *     square found) and 'push lshape sw-corner' (there is none: every object's
 *     shape is looked at) against 'go ne-corner'. The corner task's verdict is a
 *     few passes of the TABLE (its rooms from the skeleton); before issue 14 the
 *     shape tasks added one pass of the TABLE per object (5.6 s at 4096 objects).
 *
 * Each figure is the median of REPS runs (default 5), in ms of wall time.
 *
 *   costbench [SIDE [OBJECTS [REPS]]] */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "utak/base/task.h"
#include "utak/body/judge.h"
#include "utak/body/motion.h"
#include "utak/body/retina.h"
#include "utak/body/table.h"
#include "utak/body/world.h"
#include "utak/mind/controller.h"

enum { COSTBENCH_MAX_REPS = 101 };

static double now_ms(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static double median(double *v, int n)
{
	qsort(v, (size_t)n, sizeof *v, cmp_double);
	return v[n / 2];
}

/* world_text(side, objects, &len): the benchmark's world file (see the top). */
static char *world_text(int side, int objects, size_t *len)
{
	size_t cap = (size_t)objects * 96 + 256, n = 0;
	char *text = malloc(cap);
	if (!text)
		exit(1);
	n += (size_t)snprintf(text + n, cap - n, "table %d %d\n", side, side);
	int per_row = 1;
	while (per_row * per_row < objects)
		per_row++;
	int cell = (side - 8) / per_row;
	if (cell < 7) {
		fprintf(stderr, "costbench: %d objects do not fit a %d x %d TABLE\n", objects, side, side);
		exit(2);
	}
	srand(14);
	for (int k = 0; k < objects; k++) {
		int x = 4 + cell * (k % per_row) + 2, y = 4 + cell * (k / per_row) + 2;
		int a = 3 + rand() % 7, b = k % 3 == 1 ? a / 2 + 1 : a;
		if (a > cell - 4)
			a = b = cell - 4;
		n += (size_t)snprintf(text + n, cap - n, "object o%d %c", k, 'C' + k % 20);
		if (k % 3 == 2)
			n += (size_t)snprintf(text + n, cap - n, " %d %d %d %d %d %d\n", x, y, x + a, y, x, y + a);
		else
			n += (size_t)snprintf(text + n, cap - n, " %d %d %d %d %d %d %d %d\n", x, y, x + a, y, x + a,
					      y + b, x, y + b);
	}
	n += (size_t)snprintf(text + n, cap - n, "utak 2.5 2.5 north\n");
	*len = n;
	return text;
}

static void load(const char *text, size_t len, World *w, Table *t)
{
	Diag d;
	if (world_parse(w, "costbench.w", text, len, &d) || table_build(t, w, &d)) {
		fprintf(stderr, "costbench: %s\n", d.msg);
		exit(1);
	}
}

/* time_move(text, len, dx, dy, &travelled): one 'move dx dy' and its perception,
 * on the world afresh; the distance Utak actually went. */
static double time_move(const char *text, size_t len, double dx, double dy, double *travelled)
{
	World w;
	Table t;
	load(text, len, &w, &t);
	Controller *c = malloc(sizeof *c);
	if (!c)
		exit(1);
	controller_init(c, PLANNER_SKELETON);
	Impression imp;
	retina_sense(&w, &t, &imp);
	controller_start(c, &imp);
	Vec2 from = w.utak;
	MotorCommand cmd = {.kind = MOTOR_MOVE, .dx = dx, .dy = dy};
	MotorOutcome out;
	double t0 = now_ms();
	motion_execute(&w, &t, &cmd, &out);
	retina_sense(&w, &t, &imp);
	controller_perceive(c, &cmd, &imp);
	double ms = now_ms() - t0;
	*travelled = hypot(w.utak.x - from.x, w.utak.y - from.y);
	controller_free(c);
	free(c);
	table_free(&t);
	world_free(&w);
	return ms;
}

/* time_judge(w, t, text): judge_task of the task, Utak where he began. */
static double time_judge(const World *w, const Table *t, const char *task_text, char *why, size_t size)
{
	Task task;
	Diag d;
	if (task_parse(task_text, &task, &d)) {
		fprintf(stderr, "costbench: %s\n", d.msg);
		exit(1);
	}
	Vec2 trail[1] = {w->utak};
	double t0 = now_ms();
	judge_task(w, w, t, &task, trail, 1, why, size);
	return now_ms() - t0;
}

int main(int argc, char **argv)
{
	int side = argc > 1 ? atoi(argv[1]) : 1024, objects = argc > 2 ? atoi(argv[2]) : 4096;
	int reps = argc > 3 ? atoi(argv[3]) : 5;
	if (side < 64 || side > WORLD_MAX_SIDE || objects < 1 || objects > WORLD_MAX_OBJECTS || reps < 1 ||
	    reps > COSTBENCH_MAX_REPS) {
		fprintf(stderr, "usage: costbench [SIDE (64..%d) [OBJECTS (1..%d) [REPS (1..%d)]]]\n", WORLD_MAX_SIDE,
			WORLD_MAX_OBJECTS, COSTBENCH_MAX_REPS);
		return 2;
	}
	size_t len;
	char *text = world_text(side, objects, &len);
	printf("costbench: TABLE %d x %d, %d objects, Utak at (2.5, 2.5); medians of %d runs, ms\n", side, side,
	       objects, reps);

	double far[COSTBENCH_MAX_REPS], near[COSTBENCH_MAX_REPS], far_went = 0, near_went = 0;
	for (int r = 0; r < reps; r++) {
		far[r] = time_move(text, len, -1e6, -1e6, &far_went);
		near[r] = time_move(text, len, -10, -10, &near_went);
	}
	double mf = median(far, reps), mn = median(near, reps);
	printf("  move -1000000 -1000000 (went %.2f squares) + perception: %8.2f\n", far_went, mf);
	printf("  move -10 -10           (went %.2f squares) + perception: %8.2f\n", near_went, mn);
	printf("  ratio long / short move: %.2f\n", mf / mn);

	World w;
	Table t;
	load(text, len, &w, &t);
	static const char *const tasks[] = {"go ne-corner", "push square sw-corner", "push lshape sw-corner"};
	double ms[3][COSTBENCH_MAX_REPS], med[3];
	int64_t read[3];
	char why[3][256];
	for (int r = 0; r < reps; r++)
		for (int i = 0; i < 3; i++) {
			ms[i][r] = time_judge(&w, &t, tasks[i], why[i], sizeof why[i]);
			read[i] = judge_squares_read();
		}
	for (int i = 0; i < 3; i++) {
		med[i] = median(ms[i], reps);
		printf("  verdict of %-22s %8.2f   %.1f passes of the TABLE (%s)\n", tasks[i], med[i],
		       (double)read[i] / ((double)t.w * t.h), why[i]);
	}
	printf("  ratio shape / corner verdict: %.2f (square found), %.2f (no lshape: every shape looked at)\n",
	       med[1] / med[0], med[2] / med[0]);
	table_free(&t);
	world_free(&w);
	free(text);
	return 0;
}
