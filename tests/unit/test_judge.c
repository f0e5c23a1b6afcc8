/* test_judge.c - the verdict's choice of the object a shape task is about (paper
 * 2.3; judge.h: "the nearest object of that shape"), against an oracle that knows
 * the objects from the numbers it wrote into the world file, not from the TABLE.
 *
 * Random worlds (seeded): a TABLE with a lattice of cells, in each an axis-aligned
 * square, a brick (twice as long as wide) or a right triangle of integer corners at a random place in its
 * cell; Utak at a random cell's corner, in the gap between objects, facing north.
 * The room is the whole TABLE within its one-square verge, so the sw-corner's best
 * score (-x - y over free squares) is that of square (1, 1), -2.
 *   'push square sw-corner', Utak where he began: the judge reports how far short
 *   of the corner the target is; the oracle's target is the square whose centre
 *   (x + a/2, y + a/2) is nearest Utak (the lower index among equally near ones),
 *   and its best square is its south-west one, (x, y): x + y - 2 short.
 *   'push lshape sw-corner': there is none.
 * issue 14 made the choice one pass of the TABLE (it was one per object); this
 * test holds the choice to what it was. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "utak/base/task.h"
#include "utak/body/judge.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

enum { JT_CELLS = 7, JT_CELL = 16, JT_SIDE = 8 + JT_CELLS * JT_CELL, JT_WORLDS = 24 };

typedef struct JtObject {
	int kind; /* 0 square, 1 brick, 2 triangle */
	int x, y, a;
} JtObject;

static const char *judge_of(const World *w, const Table *t, const char *task_text, char *why, size_t size)
{
	Task task;
	Diag d;
	if (task_parse(task_text, &task, &d))
		return NULL;
	Vec2 trail[1] = {w->utak};
	judge_task(w, w, t, &task, trail, 1, why, size);
	return why;
}

/* jt_build(name, text, len, w, t): the world of that text and its TABLE; the test
 * fails here if either is refused. */
static void jt_build(const char *name, const char *text, size_t len, World *w, Table *t)
{
	Diag d;
	TEST_CHECK(world_parse(w, name, text, len, &d) == 0);
	TEST_CHECK(table_build(t, w, &d) == 0);
}

TEST_CASE(judge_shape_target_is_the_nearest)
{
	srand(14);
	for (int n = 0; n < JT_WORLDS; n++) {
		JtObject obj[JT_CELLS * JT_CELLS];
		char text[16384];
		size_t len = 0;
		len += (size_t)snprintf(text + len, sizeof text - len, "table %d %d\n", JT_SIDE, JT_SIDE);
		int count = JT_CELLS * JT_CELLS;
		for (int k = 0; k < count; k++) {
			JtObject *o = &obj[k];
			o->kind = rand() % 3;
			o->a = o->kind == 1 ? 3 + rand() % 3 : 3 + rand() % 7;
			int b = o->kind == 1 ? 2 * o->a : o->a; /* a brick's aspect, 2, is no square's */
			o->x = 4 + JT_CELL * (k % JT_CELLS) + 2 + rand() % (JT_CELL - 3 - o->a);
			o->y = 4 + JT_CELL * (k / JT_CELLS) + 2 + rand() % (JT_CELL - 3 - b);
			int x = o->x, y = o->y;
			if (o->kind == 2)
				len += (size_t)snprintf(text + len, sizeof text - len, "object o%d C %d %d %d %d %d %d\n", k,
							x, y, x + o->a, y, x, y + o->a);
			else
				len += (size_t)snprintf(text + len, sizeof text - len,
							"object o%d C %d %d %d %d %d %d %d %d\n", k, x, y, x + o->a, y,
							x + o->a, y + b, x, y + b);
		}
		int ux = rand() % JT_CELLS, uy = rand() % JT_CELLS;
		double utak_x = 4 + JT_CELL * ux + 0.5, utak_y = 4 + JT_CELL * uy + 0.5;
		len += (size_t)snprintf(text + len, sizeof text - len, "utak %.1f %.1f north\n", utak_x, utak_y);
		TEST_CHECK(len < sizeof text);

		int best = -1;
		double best_d2 = 0;
		for (int k = 0; k < count; k++) {
			if (obj[k].kind != 0)
				continue;
			double dx = obj[k].x + obj[k].a / 2.0 - utak_x, dy = obj[k].y + obj[k].a / 2.0 - utak_y;
			double d2 = dx * dx + dy * dy;
			if (best < 0 || d2 < best_d2)
				best = k, best_d2 = d2;
		}

		World w;
		Table t;
		jt_build("judge.w", text, len, &w, &t);
		char why[256], want[256];
		TEST_CHECK(judge_of(&w, &t, "push square sw-corner", why, sizeof why) != NULL);
		if (best < 0)
			snprintf(want, sizeof want, "there is no square in this world");
		else
			snprintf(want, sizeof want, "the square %d short of the sw-corner (slack %d)",
				 obj[best].x + obj[best].y - 2, JUDGE_SLACK);
		if (strcmp(why, want) != 0)
			fprintf(stderr, "  world %d: judge '%s', oracle '%s'\n", n, why, want);
		TEST_CHECK(strcmp(why, want) == 0);
		TEST_CHECK(judge_of(&w, &t, "push lshape sw-corner", why, sizeof why) != NULL);
		TEST_CHECK(strcmp(why, "there is no lshape in this world") == 0);
		table_free(&t);
		world_free(&w);
	}
}

/* judge_cost_is_a_few_passes: on a 256 x 256 TABLE with 1024 objects, what a
 * shape task's verdict reads is within a few passes of the TABLE, as a corner
 * task's is (each pass counted as the TABLE's area, an object's shape as its
 * rectangle's). Before issue 14 it read the TABLE twice per object: 2048 passes. */
TEST_CASE(judge_cost_is_a_few_passes)
{
	enum { SIDE = 256, PER_ROW = 32, CELL = (SIDE - 8) / PER_ROW };
	static char text[PER_ROW * PER_ROW * 64 + 64];
	size_t len = (size_t)snprintf(text, sizeof text, "table %d %d\n", SIDE, SIDE);
	for (int k = 0; k < PER_ROW * PER_ROW; k++) {
		int x = 4 + CELL * (k % PER_ROW) + 1, y = 4 + CELL * (k / PER_ROW) + 1, a = 3 + k % 3;
		if (k % 2)
			len += (size_t)snprintf(text + len, sizeof text - len, "object o%d C %d %d %d %d %d %d\n", k, x, y,
						x + a, y, x, y + a);
		else
			len += (size_t)snprintf(text + len, sizeof text - len, "object o%d C %d %d %d %d %d %d %d %d\n", k,
						x, y, x + a, y, x + a, y + a, x, y + a);
	}
	len += (size_t)snprintf(text + len, sizeof text - len, "utak %d.5 %d.5 north\n", SIDE / 2, SIDE / 2);
	TEST_CHECK(len < sizeof text);
	World w;
	Table t;
	jt_build("cost.w", text, len, &w, &t);
	char why[256];
	const int64_t area = (int64_t)SIDE * SIDE;
	TEST_CHECK(judge_of(&w, &t, "go ne-corner", why, sizeof why) != NULL);
	int64_t corner = judge_squares_read();
	TEST_CHECK(corner >= area); /* the counter counts */
	static const char *const shape_tasks[] = {"push square sw-corner", "push triangle next-room", "go lshape"};
	for (int i = 0; i < 3; i++) {
		TEST_CHECK(judge_of(&w, &t, shape_tasks[i], why, sizeof why) != NULL);
		int64_t read = judge_squares_read();
		if (read > corner + 4 * area)
			fprintf(stderr, "  %s: %lld squares read, the corner task %lld\n", shape_tasks[i], (long long)read,
				(long long)corner);
		TEST_CHECK(read <= corner + 4 * area);
	}
	table_free(&t);
	world_free(&w);
}

/* A wall rectangle [x0, x1] x [y0, y1] as a world-file line. */
static size_t jt_wall(char *text, size_t len, size_t size, int x0, int y0, int x1, int y1)
{
	return (size_t)snprintf(text + len, size - len, "wall %d %d %d %d %d %d %d %d\n", x0, y0, x1, y0, x1, y1, x0,
				y1);
}

static int jt_applies(const World *w, const Table *t, const char *task)
{
	char why[256];
	TEST_CHECK(judge_of(w, t, task, why, sizeof why) != NULL);
	return strstr(why, "does not apply") == NULL;
}

/* judge.c "whether a task can be done at all", against worlds built so that the
 * answer is known by construction (seeded): a box of one-square walls in a 44 x 34
 * room, Utak outside it, a 3 x 3 square inside. Its south side is closed, or has a
 * gap of 1 or 2 squares, or a gap only at a corner where two walls touch
 * diagonally (the squeeze the judge allows him). Closed: going to, round or
 * pushing the square, and going to the next room (the box's inside is the only
 * other room) do not apply; any gap: they apply. The square touching the box's
 * wall can still be gone round (box and square stand free of the TABLE's edge);
 * touching a wall that runs to the verge it cannot (paper 3.4.2's pocket), and
 * touching one that stops short of the verge it can. */
TEST_CASE(judge_impossible_tasks_do_not_apply)
{
	srand(13);
	for (int n = 0; n < 40; n++) {
		char text[4096];
		size_t len = (size_t)snprintf(text, sizeof text, "table 44 34\n");
		int bx0 = 14 + rand() % 6, by0 = 8 + rand() % 4, bw = 12 + rand() % 6, bh = 10 + rand() % 6;
		int bx1 = bx0 + bw, by1 = by0 + bh, gap = rand() % 4; /* 0 closed, 1-2 squares, 3 diagonal */
		int gx = bx0 + 3 + rand() % (bw - 8);
		len += jt_wall(text, len, sizeof text, bx0, by1 - 1, bx1, by1);	     /* north */
		len += jt_wall(text, len, sizeof text, bx0, by0 + 1, bx0 + 1, by1 - 1); /* west */
		len += jt_wall(text, len, sizeof text, bx1 - 1, by0 - 1, bx1, by1 - 1); /* east, a square low */
		if (gap == 0) {
			len += jt_wall(text, len, sizeof text, bx0, by0, bx1 - 1, by0 + 1);
		} else if (gap < 3) {
			len += jt_wall(text, len, sizeof text, bx0, by0, gx, by0 + 1);
			len += jt_wall(text, len, sizeof text, gx + gap, by0, bx1 - 1, by0 + 1);
		} else { /* the south wall's east part a row lower: its square (gx, by0 - 1) meets
			  * the west part's (gx - 1, by0) at a corner only */
			len += jt_wall(text, len, sizeof text, bx0, by0, gx, by0 + 1);
			len += jt_wall(text, len, sizeof text, gx, by0 - 1, bx1 - 1, by0);
		}
		int touch = rand() % 2; /* the square touches the west wall */
		int sx = touch ? bx0 + 1 : bx0 + 3 + rand() % (bw - 8), sy = by0 + 3 + rand() % (bh - 7);
		len += (size_t)snprintf(text + len, sizeof text - len, "object s A %d %d %d %d %d %d %d %d\n", sx, sy,
					sx + 3, sy, sx + 3, sy + 3, sx, sy + 3);
		len += (size_t)snprintf(text + len, sizeof text - len, "utak 4.5 4.5 north\n");
		TEST_CHECK(len < sizeof text);
		World w;
		Table t;
		jt_build("box.w", text, len, &w, &t);
		int open = gap != 0;
		static const char *const tasks[] = {"go square", "go round square", "push square ne-corner"};
		for (int i = 0; i < 3; i++) {
			if (jt_applies(&w, &t, tasks[i]) != open)
				fprintf(stderr, "  world %d (gap %d): '%s' %s\n%s", n, gap, tasks[i],
					open ? "does not apply" : "applies", text);
			TEST_CHECK(jt_applies(&w, &t, tasks[i]) == open);
		}
		if (!open)
			TEST_CHECK(!jt_applies(&w, &t, "go next-room"));
		table_free(&t);
		world_free(&w);
	}
	/* A pier of wall down from the north verge, or stopping 2 to 4 squares short of
	 * it, and the square against its east face. */
	for (int n = 0; n < 20; n++) {
		char text[1024];
		int px = 10 + rand() % 20, py = 8 + rand() % 12, reaches = n % 2, top = reaches ? 34 : 31 - rand() % 3;
		int sy = py + rand() % (top - py - 3);
		size_t len = (size_t)snprintf(text, sizeof text, "table 44 34\n");
		len += jt_wall(text, len, sizeof text, px, py, px + 2, top);
		len += (size_t)snprintf(text + len, sizeof text - len,
					"object s A %d %d %d %d %d %d %d %d\nutak 4.5 4.5 north\n", px + 2, sy, px + 5,
					sy, px + 5, sy + 3, px + 2, sy + 3);
		TEST_CHECK(len < sizeof text);
		World w;
		Table t;
		jt_build("pier.w", text, len, &w, &t);
		TEST_CHECK(jt_applies(&w, &t, "go square"));
		if (jt_applies(&w, &t, "go round square") != !reaches)
			fprintf(stderr, "  pier %d: going round %s\n%s", n, reaches ? "applies" : "does not apply", text);
		TEST_CHECK(jt_applies(&w, &t, "go round square") == !reaches);
		table_free(&t);
		world_free(&w);
	}
}

int main(void)
{
	TEST_RUN(judge_shape_target_is_the_nearest);
	TEST_RUN(judge_cost_is_a_few_passes);
	TEST_RUN(judge_impossible_tasks_do_not_apply);
	return TEST_EXIT();
}
