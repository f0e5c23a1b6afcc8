/* test_rooms.c - rooms and doors (rooms.h) on small hand-made grids, and their
 * invariants on random ones against a flood-fill oracle. */
#include <stdlib.h>
#include <string.h>

#include "oracle.h"
#include "test.h"
#include "utak/mind/rooms.h"

typedef struct World {
	Grid g;
	Skeleton s;
	Pathgraph pg;
	Rooms r;
} World;

static void world_make(World *w, const char *const *rows, int h)
{
	oracle_grid_from(&w->g, rows, h);
	skeleton_init(&w->s);
	pathgraph_init(&w->pg);
	rooms_init(&w->r);
	skeleton_compute(&w->s, &w->g);
	pathgraph_build(&w->pg, &w->s, &w->g);
	rooms_find(&w->r, &w->pg);
}

static void world_free(World *w)
{
	rooms_free(&w->r);
	pathgraph_free(&w->pg);
	skeleton_free(&w->s);
	grid_free(&w->g);
}

/* rooms_consistent(r, g): every free cell has a room, blocked cells none, each room's
 * cells are one 4-component (flood fill), doors join different rooms. */
static bool rooms_consistent(const Rooms *r, const Grid *g)
{
	int n = g->w * g->h;
	uint8_t *one = malloc((size_t)n + 1);
	int *lab = malloc(sizeof(int) * (size_t)(n + 1));
	bool ok = true;
	for (int i = 0; i < n && ok; i++)
		ok = (r->room[i] >= 0) == (g->cells[i] == GRID_FREE) && r->room[i] < r->room_count;
	for (int k = 0; k < r->room_count && ok; k++) {
		for (int i = 0; i < n; i++)
			one[i] = r->room[i] == k;
		ok = oracle_label(one, g->w, g->h, 4, lab) == 1;
	}
	for (int k = 0; k < r->door_count && ok; k++)
		ok = r->doors[k].room_a != r->doors[k].room_b && r->doors[k].room_a >= 0 &&
		     r->doors[k].room_b < r->room_count;
	free(one);
	free(lab);
	return ok;
}

TEST_CASE(two_rooms_one_door)
{
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const rows[] = {
	    "..........#..........",
	    "..........#..........",
	    "..........#..........",
	    "..........#..........",
	    ".....................",
	    ".....................",
	    "..........#..........",
	    "..........#..........",
	    "..........#..........",
	    "..........#..........",
	};
	/* clang-format on */
	World w;
	world_make(&w, rows, 10);
	if (w.r.room_count != 2 || w.r.door_count != 1)
		rooms_dump(&w.r, &w.g, stderr);
	TEST_CHECK(w.r.room_count == 2);
	TEST_CHECK(w.r.door_count == 1);
	TEST_CHECK(rooms_consistent(&w.r, &w.g));
	const RoomsDoor *d = &w.r.doors[0];
	TEST_CHECK(d->x == 10 && (d->y == 4 || d->y == 5));
	TEST_CHECK(d->width == 2);
	/* the left side is one room, the right side the other */
	TEST_CHECK(rooms_at(&w.r, 2, 2) != rooms_at(&w.r, 18, 7));
	TEST_CHECK(rooms_at(&w.r, 2, 2) == rooms_at(&w.r, 5, 8));
	int32_t doors[4];
	TEST_CHECK(rooms_doors_of(&w.r, rooms_at(&w.r, 2, 2), doors, 4) == 1 && doors[0] == 0);
	world_free(&w);
}

TEST_CASE(one_open_room_no_door)
{
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const rows[] = {
	    "..............",
	    "..............",
	    "..............",
	    "..............",
	    "..............",
	    "..............",
	    "..............",
	};
	/* clang-format on */
	World w;
	world_make(&w, rows, 7);
	TEST_CHECK(w.r.room_count == 1);
	TEST_CHECK(w.r.door_count == 0);
	TEST_CHECK(rooms_consistent(&w.r, &w.g));
	TEST_CHECK(w.r.rooms[0].cells == 14 * 7);
	world_free(&w);
}

TEST_CASE(three_rooms_in_a_row)
{
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const rows[] = {
	    "#########################",
	    "#.......#.......#.......#",
	    "#.......#.......#.......#",
	    "#.......#.......#.......#",
	    "#...............#.......#",
	    "#.......#...............#",
	    "#.......#.......#.......#",
	    "#.......#.......#.......#",
	    "#.......#.......#.......#",
	    "#########################",
	};
	/* clang-format on */
	World w;
	world_make(&w, rows, 10);
	if (w.r.room_count != 3 || w.r.door_count != 2)
		rooms_dump(&w.r, &w.g, stderr);
	TEST_CHECK(w.r.room_count == 3);
	TEST_CHECK(w.r.door_count == 2);
	TEST_CHECK(rooms_consistent(&w.r, &w.g));
	/* the middle room has two doors, the end rooms one */
	int32_t doors[4];
	TEST_CHECK(rooms_doors_of(&w.r, rooms_at(&w.r, 12, 4), doors, 4) == 2);
	TEST_CHECK(rooms_doors_of(&w.r, rooms_at(&w.r, 3, 4), doors, 4) == 1);
	world_free(&w);
}

TEST_CASE(rooms_consistent_on_random_grids)
{
	oracle_seed = 5;
	for (int trial = 0; trial < 100; trial++) {
		World w;
		oracle_random_grid(&w.g, 4 + oracle_rand_below(40), 4 + oracle_rand_below(40),
		                   oracle_rand_below(30), oracle_rand_below(8));
		skeleton_init(&w.s);
		pathgraph_init(&w.pg);
		rooms_init(&w.r);
		skeleton_compute(&w.s, &w.g);
		pathgraph_build(&w.pg, &w.s, &w.g);
		rooms_find(&w.r, &w.pg);
		bool ok = rooms_consistent(&w.r, &w.g);
		if (!ok)
			rooms_dump(&w.r, &w.g, stderr);
		TEST_CHECK(ok);
		world_free(&w);
	}
}

TEST_CASE(rooms_dump_by_hand)
{
	/* the rows are a picture of the grid, north on top */
	/* clang-format off */
	static const char *const rows[] = {
	    "#######",
	    "#..#..#",
	    "#.....#",
	    "#..#..#",
	    "#######",
	};
	/* clang-format on */
	World w;
	world_make(&w, rows, 5);
	char *text = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&text, &len);
	rooms_dump(&w.r, &w.g, f);
	fclose(f);
	/* the gap at (3, 2) is narrower (clearance 1) than the rooms either side, but
	 * they are hardly wider (clearance sqrt 2 < 1.5): no door, one room */
	const char *want = "#######\n"
	                   "#AA#AA#\n"
	                   "#AAAAA#\n"
	                   "#AA#AA#\n"
	                   "#######\n"
	                   "rooms: 1 rooms, 0 doors\n"
	                   "room 0 2 2 13 1.414\n";
	if (strcmp(text, want) != 0)
		fprintf(stderr, "%s", text);
	TEST_CHECK(strcmp(text, want) == 0);
	free(text);
	world_free(&w);
}

int main(void)
{
	TEST_RUN(two_rooms_one_door);
	TEST_RUN(one_open_room_no_door);
	TEST_RUN(three_rooms_in_a_row);
	TEST_RUN(rooms_consistent_on_random_grids);
	TEST_RUN(rooms_dump_by_hand);
	return TEST_EXIT();
}
