/* tcodpath.c - the libtcod side of `make bench-compare` (issue 16): libtcod's A* on
 * the grid utak's gridpath searches (paper 4.1's grid planner, compared with a peer).
 *
 *   tcodpath GRID.pgm SX SY GX GY REPEAT
 *
 * Reads a binary PGM written by skelbench --compare (255 free, 0 blocked, first row
 * y = 0), and times REPEAT runs of TCOD_path_compute from (SX, SY) to (GX, GY),
 * thread CPU time, printing one line "tcod MEDIAN LO HI LENGTH STEPS" (ms; the length
 * of the path found, straight steps 1 and diagonal sqrt 2). libtcod's A* is given
 * this project's graph through its walk-cost callback: 8-connected, a diagonal step
 * only when both orthogonal cells are free (libtcod's own map rule would let a
 * diagonal cut a blocked corner), diagonal cost sqrt 2. Its heuristic is its own
 * (Euclidean). Built against Debian's libtcod-dev by the Makefile; not part of the
 * library, which stays libc + libm. */
#define _POSIX_C_SOURCE 200809L
#include <libtcod.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

typedef struct PeerGrid {
	int w, h;
	unsigned char *free; /* w * h, 1 when free */
} PeerGrid;

static double peer_now_ms(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return ts.tv_sec * 1e3 + ts.tv_nsec / 1e6;
}

static int peer_free(const PeerGrid *g, int x, int y)
{
	return x >= 0 && y >= 0 && x < g->w && y < g->h && g->free[(size_t)y * g->w + x];
}

/* The walk cost: 0 forbids the step (libtcod's convention), else 1 (the diagonal
 * factor is libtcod's diagonalCost). */
static float peer_cost(int xf, int yf, int xt, int yt, void *user)
{
	const PeerGrid *g = user;
	if (!peer_free(g, xt, yt))
		return 0.0f;
	if (xf != xt && yf != yt && (!peer_free(g, xt, yf) || !peer_free(g, xf, yt)))
		return 0.0f;
	return 1.0f;
}

static int peer_cmp(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
	if (argc != 7) {
		fprintf(stderr, "usage: tcodpath GRID.pgm SX SY GX GY REPEAT\n");
		return 2;
	}
	FILE *f = fopen(argv[1], "rb");
	PeerGrid g;
	int maxval;
	if (!f || fscanf(f, "P5 %d %d %d", &g.w, &g.h, &maxval) != 3 || fgetc(f) == EOF) {
		fprintf(stderr, "tcodpath: %s: not a binary PGM\n", argv[1]);
		return 2;
	}
	size_t n = (size_t)g.w * g.h;
	g.free = malloc(n);
	if (fread(g.free, 1, n, f) != n) {
		fprintf(stderr, "tcodpath: %s: short file\n", argv[1]);
		return 2;
	}
	fclose(f);
	for (size_t i = 0; i < n; i++)
		g.free[i] = g.free[i] != 0;
	int sx = atoi(argv[2]), sy = atoi(argv[3]), gx = atoi(argv[4]), gy = atoi(argv[5]);
	int repeat = atoi(argv[6]);
	if (repeat < 1 || repeat > 100)
		repeat = 3;
	double *t = malloc(sizeof *t * (size_t)repeat);
	TCOD_path_t path = TCOD_path_new_using_function(g.w, g.h, peer_cost, &g, (float)sqrt(2.0));
	double length = -1;
	int steps = 0;
	for (int r = 0; r < repeat; r++) {
		double t0 = peer_now_ms();
		bool found = TCOD_path_compute(path, sx, sy, gx, gy);
		t[r] = peer_now_ms() - t0;
		if (!found)
			continue;
		/* walked after the clock stops (TCOD_path_get is linear in the index) */
		length = 0;
		steps = TCOD_path_size(path);
		int px = sx, py = sy, x, y;
		while (TCOD_path_walk(path, &x, &y, false)) {
			length += (x != px && y != py) ? sqrt(2.0) : 1.0;
			px = x;
			py = y;
		}
	}
	qsort(t, (size_t)repeat, sizeof *t, peer_cmp);
	double median = repeat % 2 ? t[repeat / 2] : (t[repeat / 2 - 1] + t[repeat / 2]) / 2;
	printf("tcod %.3f %.3f %.3f %.4f %d\n", median, t[0], t[repeat - 1], length, steps);
	TCOD_path_delete(path);
	free(t);
	free(g.free);
	return 0;
}
