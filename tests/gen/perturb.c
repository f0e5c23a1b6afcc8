/* perturb.c - a world a little changed: every object shifted by up to two squares,
 * Utak's heading turned (issue 13, "Tests": a task that works on a world must not
 * depend on exactly where its objects lie or which way Utak faces).
 *
 *   perturb -n COUNT -o DIR SEED WORLD...
 *
 * For each WORLD, COUNT variants DIR/NAME-pK.w (K = 1..COUNT, NAME the world's
 * file name less .w). In variant K Utak faces his heading turned by K-1 quarter
 * turns (so four variants see all four headings) and each object, in file order,
 * is moved by (dx, dy), each uniform in [-2, 2] and rounded to 3 decimals, with
 * the world checked by the simulator's own reader and TABLE after each move; a
 * move that makes it invalid (an overlap, a wall, Utak inside) is drawn again, up
 * to PERTURB_TRIES times, and then the object stays where it was. Walls, the verge
 * and Utak's point never move. Deterministic: splitmix64 from SEED, the world's
 * index and K. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gen.h"

/* How far an object may be shifted, each way (squares), and how often a shift
 * is drawn again before the object is left in place. */
#define PERTURB_SHIFT 2.0
#define PERTURB_TRIES 20

/* world_text(w, seed, k, src, out): w as world-file text, coordinates to 3 decimals. */
static void world_text(const World *w, const char *src, int k, GenText *out)
{
	static const char *const headings[4] = {"north", "east", "south", "west"};
	out->len = 0;
	gen_printf(out, "# perturb: %s, variant %d\ntable %d %d\n", src, k, w->w, w->h);
	if (w->verge_given) {
		gen_printf(out, "verge");
		gen_points(out, &w->verge);
	}
	for (int32_t i = 0; i < w->wall_count; i++) {
		gen_printf(out, "wall");
		gen_points(out, &w->walls[i]);
	}
	for (int32_t i = 0; i < w->object_count; i++) {
		gen_printf(out, "object %s %c", w->objects[i].name, w->objects[i].colour);
		gen_points(out, &w->objects[i].shape);
	}
	gen_printf(out, "utak ");
	gen_number(out, w->utak.x);
	gen_printf(out, " ");
	gen_number(out, w->utak.y);
	gen_printf(out, " %s\n", headings[w->heading & 3]);
}

static int usage(void)
{
	fputs("usage: perturb -n COUNT -o DIR SEED WORLD...\n", stderr);
	return 2;
}

int main(int argc, char **argv)
{
	unsigned long long count = 0, seed = 0;
	const char *dir = NULL;
	int i = 1;
	for (; i + 1 < argc && argv[i][0] == '-'; i += 2) {
		char *end;
		errno = 0;
		if (strcmp(argv[i], "-n") == 0) {
			count = strtoull(argv[i + 1], &end, 10);
			if (errno || *end || count == 0)
				return usage();
		} else if (strcmp(argv[i], "-o") == 0) {
			dir = argv[i + 1];
		} else {
			return usage();
		}
	}
	if (!dir || !count || i + 1 >= argc)
		return usage();
	char *end;
	seed = strtoull(argv[i++], &end, 10);
	if (*end)
		return usage();
	GenText t = {0};
	for (int n = 0; i < argc; i++, n++) {
		World w;
		Diag d;
		if (world_read(&w, argv[i], &d)) {
			fprintf(stderr, "perturb: %s\n", d.msg);
			return 1;
		}
		const char *base = strrchr(argv[i], '/') ? strrchr(argv[i], '/') + 1 : argv[i];
		size_t len = strlen(base) > 2 && strcmp(base + strlen(base) - 2, ".w") == 0 ? strlen(base) - 2 : strlen(base);
		Heading h0 = w.heading;
		Polygon *home = util_alloc((size_t)w.object_count + 1, sizeof *home);
		for (int32_t o = 0; o < w.object_count; o++)
			home[o] = w.objects[o].shape;
		for (unsigned long long k = 1; k <= count; k++) {
			GenRng rng = {seed * 0x9E3779B97F4A7C15ull + (uint64_t)n * 0x100000001B3ull + k};
			w.heading = (Heading)((h0 + k - 1) & 3);
			for (int32_t o = 0; o < w.object_count; o++)
				w.objects[o].shape = home[o];
			for (int32_t o = 0; o < w.object_count; o++) {
				for (int tries = 0; tries < PERTURB_TRIES; tries++) {
					double dx = gen_round(gen_range(&rng, -PERTURB_SHIFT, PERTURB_SHIFT));
					double dy = gen_round(gen_range(&rng, -PERTURB_SHIFT, PERTURB_SHIFT));
					Polygon *p = &w.objects[o].shape;
					for (int32_t v = 0; v < p->count; v++)
						p->v[v] = vec2(gen_round(home[o].v[v].x + dx), gen_round(home[o].v[v].y + dy));
					world_text(&w, base, (int)k, &t);
					char why[DIAG_SIZE];
					if (gen_valid(t.s, t.len, why, sizeof why))
						break;
					*p = home[o];
				}
			}
			world_text(&w, base, (int)k, &t);
			char path[4096];
			snprintf(path, sizeof path, "%s/%.*s-p%llu.w", dir, (int)len, base, k);
			FILE *f = fopen(path, "w");
			if (!f || fwrite(t.s, 1, t.len, f) != t.len || fclose(f)) {
				fprintf(stderr, "perturb: cannot write %s\n", path);
				return 1;
			}
		}
		free(home);
		world_free(&w);
	}
	free(t.s);
	return 0;
}
