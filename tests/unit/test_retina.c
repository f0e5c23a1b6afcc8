/* test_retina.c - the retina and touch (retina.h, SIMULATOR SIDE): the eye turns with Utak. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "utak/base/eye.h"
#include "utak/body/retina.h"

/* A 40 x 40 TABLE, Utak at (20.5, 20.5) facing `heading`, a one-square marker 6
 * squares ahead of him and a 2 x 2 block 2 squares to his right (touching nothing). */
static void make_world(const char *heading, World *w, Table *t)
{
	static const int ahead[4][2] = {{0, 1}, {1, 0}, {0, -1}, {-1, 0}}; /* N E S W */
	static const char *const names[4] = {"north", "east", "south", "west"};
	int h = 0;
	while (strcmp(names[h], heading) != 0)
		h++;
	int ax = ahead[h][0], ay = ahead[h][1];
	int rx = ay, ry = -ax; /* right is ahead turned clockwise */
	int mx = 20 + 6 * ax, my = 20 + 6 * ay;
	/* The block spans own x 2..3, y 0..1: TABLE corner squares. */
	int bx0 = 20 + 2 * rx, by0 = 20 + 2 * ry, bx1 = 20 + 3 * rx + ax, by1 = 20 + 3 * ry + ay;
	int lox = bx0 < bx1 ? bx0 : bx1, hix = bx0 < bx1 ? bx1 : bx0;
	int loy = by0 < by1 ? by0 : by1, hiy = by0 < by1 ? by1 : by0;
	char text[512];
	snprintf(text, sizeof text,
	         "table 40 40\nobject marker A %d %d %d %d %d %d %d %d\n"
	         "object block C %d %d %d %d %d %d %d %d\nutak 20.5 20.5 %s\n",
	         mx, my, mx + 1, my, mx + 1, my + 1, mx, my + 1, lox, loy, hix + 1, loy, hix + 1,
	         hiy + 1, lox, hiy + 1, heading);
	Diag d;
	TEST_CHECK(world_parse(w, "test", text, strlen(text), &d) == 0);
	TEST_CHECK(table_build(t, w, &d) == 0);
}

TEST_CASE(retina_four_headings)
{
	static const char *const headings[4] = {"north", "east", "south", "west"};
	Impression first;
	for (int h = 0; h < 4; h++) {
		World w;
		Table t;
		make_world(headings[h], &w, &t);
		Impression imp;
		retina_sense(&w, &t, &imp);
		/* The marker at own (0, 6) is one square of a 2 x 2 cell: level 2, at the top. */
		TEST_CHECK(imp.level[eye_cell_at(0, 6)] == eye_level(1, 4));
		TEST_CHECK(imp.level[eye_cell_at(0, -6)] == 0);
		TEST_CHECK(imp.level[eye_cell_at(-6, 0)] == 0 && imp.level[eye_cell_at(6, 0)] == 0);
		/* The block at own x 2..3, y 0..1: four foveal 7s on the right. */
		TEST_CHECK(imp.level[eye_cell_at(2, 0)] == 7 && imp.level[eye_cell_at(3, 1)] == 7);
		TEST_CHECK(imp.level[eye_cell_at(-2, 0)] == 0 &&
		           imp.level[eye_cell_at(-3, 1)] == 0);
		TEST_CHECK(imp.level[eye_cell_at(0, 0)] == 7); /* Utak himself */
		/* In the picture: the marker's cell at the top half, column of Utak. */
		char *pic = NULL;
		size_t len = 0;
		FILE *f = open_memstream(&pic, &len);
		eye_print_picture(imp.level, f);
		fclose(f);
		TEST_CHECK(len == 32 * 33);
		TEST_CHECK(pic[9 * 33 + 16] == '2' &&
		           pic[8 * 33 + 16] == '2');  /* rows 8-9: oy 7, 6 */
		TEST_CHECK(pic[21 * 33 + 16] == '0'); /* oy -6: behind */
		TEST_CHECK(pic[15 * 33 + 16] == '7' &&
		           pic[15 * 33 + 18] == '7'); /* Utak; block right */
		free(pic);
		/* The same world turned: the same impression, whatever the heading. */
		if (h == 0)
			first = imp;
		TEST_CHECK(memcmp(first.level, imp.level, sizeof imp.level) == 0);
		TEST_CHECK(memcmp(imp.touch, "........", 8) == 0);
		table_free(&t);
		world_free(&w);
	}
}

TEST_CASE(retina_off_table_is_verge_and_touch)
{
	const char *text = "table 10 10\nobject s A 2 1 3 1 3 2 2 2\nutak 1.5 1.5 north\n";
	World w;
	Table t;
	Diag d;
	TEST_CHECK(world_parse(&w, "test", text, strlen(text), &d) == 0);
	TEST_CHECK(table_build(&t, &w, &d) == 0);
	Impression imp;
	retina_sense(&w, &t, &imp);
	/* Near the corner: everything behind and to the left is verge or off the TABLE. */
	TEST_CHECK(imp.level[eye_cell_at(-16, -16)] == 7 && imp.level[eye_cell_at(-2, 0)] == 7);
	TEST_CHECK(imp.level[eye_cell_at(0, 1)] == 0);
	/* Touch: ahead '.', right 'A', behind 'B', left 'B'. */
	TEST_CHECK(imp.touch[0] == '.' && imp.touch[2] == 'A' && imp.touch[4] == 'B' &&
	           imp.touch[6] == 'B');
	table_free(&t);
	world_free(&w);
}

int main(void)
{
	TEST_RUN(retina_four_headings);
	TEST_RUN(retina_off_table_is_verge_and_touch);
	return TEST_EXIT();
}
