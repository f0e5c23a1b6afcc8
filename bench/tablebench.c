/* tablebench.c - how long loading and projecting a large TABLE takes (paper 2.1).
 *
 * Builds, in memory, a world file of a 4096 x 4096 TABLE with 200 objects (random
 * star-shaped polygons of 3 to 24 vertices, 4 to 60 squares across, fixed seed,
 * placed where they do not overlap), then times world_parse + table_build. Figures
 * in ms; a benchmark, not a test.
 *
 *   tablebench [SIDE [OBJECTS]]   the square TABLE above
 *   tablebench limits             the largest TABLE utak(5) allows (8192 x 4096)
 *                                 with the most walls (4096 slanted triangles) */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "utak/body/motion.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

static double now_ms(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

int main(int argc, char **argv)
{
	bool limits = argc > 1 && strcmp(argv[1], "limits") == 0;
	int side = argc > 1 && !limits ? atoi(argv[1]) : 4096, objects = argc > 2 ? atoi(argv[2]) : 200;
	size_t cap = 1 << 20, n = 0;
	char *text = malloc(cap);
	if (limits) {
		n += (size_t)snprintf(text + n, cap - n, "table %d %d\n", WORLD_MAX_SIDE, WORLD_MAX_SIDE / 2);
		for (int i = 0; i < WORLD_MAX_OBJECTS; i++) {
			int x = 2 + (i % 64) * 127, y = 2 + (i / 64) * 63;
			n += (size_t)snprintf(text + n, cap - n, "wall %d %d %d %d %d %d\n", x, y, x + 120, y + 3, x + 5,
					      y + 55);
		}
		n += (size_t)snprintf(text + n, cap - n, "utak %d.5 %d.5 north\n", WORLD_MAX_SIDE - 2,
				      WORLD_MAX_SIDE / 2 - 2);
		side = WORLD_MAX_SIDE;
		objects = WORLD_MAX_OBJECTS;
	}
	if (!limits)
		n += (size_t)snprintf(text + n, cap - n, "table %d %d\n", side, side);
	srand(7);
	/* Objects on a coarse lattice of cells, one per cell, so they cannot overlap. */
	int per_row = (int)ceil(sqrt(objects)), cell = (side - 8) / per_row;
	for (int k = 0; k < objects && !limits; k++) {
		double cx = 4 + cell * (k % per_row + 0.5), cy = 4 + cell * (k / per_row + 0.5);
		double r = fmin(cell * 0.45, 4 + rand() % 28);
		int count = 3 + rand() % 22;
		n += (size_t)snprintf(text + n, cap - n, "object o%d %c", k, 'C' + k % 20);
		for (int i = 0; i < count; i++) {
			double a = 6.283185307179586 * (i + (rand() % 50) / 100.0) / count;
			double rr = r * (0.5 + (rand() % 50) / 100.0);
			n += (size_t)snprintf(text + n, cap - n, " %.2f %.2f", cx + rr * cos(a), cy + rr * sin(a));
		}
		n += (size_t)snprintf(text + n, cap - n, "\n");
	}
	if (!limits)
		n += (size_t)snprintf(text + n, cap - n, "utak 2.5 2.5 north\n");

	World w;
	Table t;
	Diag d;
	double t0 = now_ms();
	if (world_parse(&w, "bench.w", text, n, &d)) {
		fprintf(stderr, "tablebench: %s\n", d.msg);
		return 1;
	}
	double t1 = now_ms();
	if (table_build(&t, &w, &d)) {
		fprintf(stderr, "tablebench: %s\n", d.msg);
		return 1;
	}
	double t2 = now_ms();
	long long claimed = 0;
	for (long long i = 0; i < (long long)t.w * t.h; i++)
		claimed += limits ? t.owner[i] == TABLE_VERGE : t.owner[i] > 0;
	printf("TABLE %d x %d, %d %s (%lld %s squares): parse %.1f ms, project %.1f ms, load total %.1f ms\n", t.w,
	       t.h, objects, limits ? "walls" : "objects", claimed, limits ? "verge and wall" : "object", t1 - t0,
	       t2 - t1, t2 - t0);
	table_free(&t);
	world_free(&w);
	free(text);
	return 0;
}
