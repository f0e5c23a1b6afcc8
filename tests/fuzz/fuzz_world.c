/* fuzz_world.c - fuzzes the world-file reader and the TABLE's construction (paper 2.1;
 * man utak.5).
 *
 * Any bytes: world_parse either fails with one clear diagnostic or gives a world
 * whose TABLE either fails to build (overlaps, Utak misplaced: again one clear
 * diagnostic) or builds and passes table_validate. A world that loads is written
 * with world_write and read back: the copy must load to the same TABLE, square
 * for square (the promise of `utak -o`). */
#include <string.h>

#include "fuzz.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

/* Building a TABLE costs time in proportion to its area: above this many squares
 * (a 2048 x 2048 TABLE) the harness checks the reading only, so that the fuzzer
 * spends its time on the reader's many paths rather than on clearing memory. */
enum { FUZZ_WORLD_MAX_SQUARES = 1 << 22 };

static void check_round_trip(const World *w, const Table *t)
{
	char *text = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&text, &len);
	FUZZ_CHECK(f != NULL, "open_memstream");
	world_write(w, f);
	fclose(f);
	World back;
	Table tb;
	Diag d;
	FUZZ_CHECK(world_parse(&back, w->file, text, len, &d) == 0, "written world does not read back: %s\n%s",
		   d.msg, text);
	FUZZ_CHECK(table_build(&tb, &back, &d) == 0, "written world does not build: %s", d.msg);
	FUZZ_CHECK(memcmp(tb.owner, t->owner, sizeof *t->owner * (size_t)t->w * (size_t)t->h) == 0,
		   "written world builds another TABLE");
	FUZZ_CHECK(back.object_count == w->object_count && back.wall_count == w->wall_count &&
			   back.utak.x == w->utak.x && back.utak.y == w->utak.y && back.heading == w->heading,
		   "written world differs");
	for (int32_t k = 0; k < w->object_count; k++)
		FUZZ_CHECK(memcmp(&back.objects[k].shape, &w->objects[k].shape, sizeof w->objects[k].shape) == 0,
			   "object %d reads back with other points", (int)k);
	table_free(&tb);
	world_free(&back);
	free(text);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	World w;
	Diag d;
	if (world_parse(&w, "fuzz.w", (const char *)data, size, &d) != 0) {
		FUZZ_CHECK(fuzz_diag_ok(d.msg, "fuzz.w"), "bad diagnostic '%s'", d.msg);
		FUZZ_CHECK(w.objects == NULL && w.walls == NULL, "failed parse kept memory");
		return 0;
	}
	FUZZ_CHECK(w.w >= 3 && w.h >= 3 && w.w <= WORLD_MAX_SIDE && w.h <= WORLD_MAX_SIDE &&
			   (int64_t)w.w * w.h <= WORLD_MAX_SQUARES,
		   "TABLE %d x %d passed the limits", (int)w.w, (int)w.h);
	FUZZ_CHECK(w.object_count <= WORLD_MAX_OBJECTS && w.wall_count <= WORLD_MAX_OBJECTS, "too many shapes");
	if ((int64_t)w.w * w.h <= FUZZ_WORLD_MAX_SQUARES) {
		Table t;
		if (table_build(&t, &w, &d) != 0) {
			FUZZ_CHECK(fuzz_diag_ok(d.msg, "fuzz.w"), "bad diagnostic '%s'", d.msg);
		} else {
			char why[256];
			FUZZ_CHECK(table_validate(&t, &w, why, sizeof why), "%s", why);
			check_round_trip(&w, &t);
			table_free(&t);
		}
	}
	world_free(&w);
	return 0;
}
