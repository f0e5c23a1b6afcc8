/* test_worlds.c - every world in worlds/ loads, and its TABLE dump is the projection
 * rule applied square by square (paper 2.1; utak(5)), as computed by the
 * independent oracle of projection_oracle.h. Run from the repository's top. */
#include <dirent.h>
#include <stdlib.h>
#include <string.h>

#include "projection_oracle.h"
#include "test.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

/* expected(w, x, y): the character the dump must show at square (x, y). */
static char expected(const World *w, int x, int y)
{
	if (x == (int)floor(w->utak.x) && y == (int)floor(w->utak.y))
		return '@';
	if (oracle_outside(&w->verge, x, y))
		return 'B';
	for (int i = 0; i < w->wall_count; i++)
		if (oracle(&w->walls[i], x, y))
			return 'B';
	for (int k = 0; k < w->object_count; k++)
		if (oracle(&w->objects[k].shape, x, y))
			return w->objects[k].colour;
	return '.';
}

static int compare(const char *a, const char *b) { return strcmp(*(const char *const *)a, *(const char *const *)b); }

TEST_CASE(every_world_dumps_by_the_rule)
{
	DIR *dir = opendir("worlds");
	TEST_CHECK(dir != NULL);
	char *names[64];
	int n = 0;
	for (struct dirent *e; (e = readdir(dir)) && n < 64;) {
		size_t len = strlen(e->d_name);
		if (len > 2 && strcmp(e->d_name + len - 2, ".w") == 0)
			names[n++] = strdup(e->d_name);
	}
	closedir(dir);
	qsort(names, (size_t)n, sizeof names[0], (int (*)(const void *, const void *))compare);
	TEST_CHECK(n >= 8);
	for (int i = 0; i < n; i++) {
		char path[300];
		snprintf(path, sizeof path, "worlds/%s", names[i]);
		World w;
		Table t;
		Diag d;
		TEST_CHECK(world_read(&w, path, &d) == 0);
		TEST_CHECK(table_build(&t, &w, &d) == 0);
		char *text = NULL;
		size_t size = 0;
		FILE *f = open_memstream(&text, &size);
		table_dump(&t, &w, f);
		fclose(f);
		TEST_CHECK(size == (size_t)(w.w + 1) * (size_t)w.h);
		int bad = 0;
		for (int row = 0; row < w.h; row++) {
			const char *line = text + (size_t)row * (size_t)(w.w + 1);
			TEST_CHECK(line[w.w] == '\n');
			for (int x = 0; x < w.w; x++)
				if (line[x] != expected(&w, x, w.h - 1 - row)) {
					if (bad++ < 3)
						fprintf(stderr, "  %s: square (%d, %d) is '%c', the rule says '%c'\n",
							path, x, w.h - 1 - row, line[x], expected(&w, x, w.h - 1 - row));
				}
		}
		TEST_CHECK(bad == 0);
		free(text);
		table_free(&t);
		world_free(&w);
		free(names[i]);
	}
}

int main(void)
{
	TEST_RUN(every_world_dumps_by_the_rule);
	return TEST_EXIT();
}
