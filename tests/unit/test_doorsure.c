/* test_doorsure.c - the judge's door rule restated with a slack for the corner claim
 * (doorsure.h; paper 2.3 task (i)).
 *
 * THE ORACLE is the judge (judgerooms.h: its own code, from the real TABLE; a test
 * may see both sides).
 *  - With no slack, carryroom_watershed_slack on the TABLE's own grid (verge blocked,
 *    floor and objects free) parts the squares exactly as the judge's rooms do, on
 *    halls with free-standing piers at random and on the two-room worlds of the
 *    grid (a wall across with a door).
 *  - The slack covers a face the eye places a square off: on every two-room world
 *    (a wall 1 to 3 thick across a 40 x 30 TABLE, a door 3 to 6 wide at three
 *    places) where the judge counts the door, the model misread with the wall one
 *    square thicker toward the far room (the far room a square narrower, its peak
 *    up to a square lower) still parts the start from the far room's squares with
 *    the slack, while without it some such worlds read one room: the false
 *    successes of the simplest worlds. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "oracle.h"
#include "test.h"
#include "room_worlds.h"
#include "world_fixture.h"
#include "utak/body/judgerooms.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/doorsure.h"

/* table_grid(g, thicken_from, thicken_to): the loaded TABLE's grid, verge blocked,
 * and the rows [thicken_from, thicken_to) blocked too where the column is blocked in
 * row thicken_from - 1 (a wall read thicker upward). */
static void table_grid(Grid *g, int32_t thicken_from, int32_t thicken_to)
{
	grid_init(g, table.w, table.h, GRID_BLOCKED);
	for (int32_t y = 0; y < table.h; y++)
		for (int32_t x = 0; x < table.w; x++)
			if (table_owner(&table, x, y) != TABLE_VERGE)
				g->cells[y * table.w + x] = GRID_FREE;
	for (int32_t y = thicken_from; y < thicken_to; y++)
		for (int32_t x = 1; x < table.w - 1; x++)
			if (g->cells[(y - 1) * table.w + x] == GRID_BLOCKED)
				g->cells[y * table.w + x] = GRID_BLOCKED;
}

/* agrees(jr, mine, cells): every square the judge puts in a room is in one of
 * mine, squares of one judge room in one of mine, of two in two. */
static bool agrees(const JudgeRooms *jr, const int32_t *mine, int64_t cells)
{
	int32_t *of = malloc((size_t)(jr->count + 1) * sizeof *of);
	for (int32_t r = 0; r < jr->count; r++)
		of[r] = -2;
	bool same = true;
	for (int64_t i = 0; i < cells && same; i++) {
		int32_t r = jr->room[i];
		if (r < 0)
			continue;
		same = mine[i] >= 0 && (of[r] == -2 || of[r] == mine[i]);
		of[r] = mine[i];
	}
	for (int32_t a = 0; a < jr->count && same; a++)
		for (int32_t b = a + 1; b < jr->count && same; b++)
			same = of[a] != of[b] || of[a] == -2;
	free(of);
	return same;
}

/* two_rooms(th, dw, x0): grid.sh's world: a 40 x 30 TABLE, a wall th thick across
 * at row 18 with a door dw wide from column x0. */
static void two_rooms(int th, int dw, int x0)
{
	char text[512];
	snprintf(text, sizeof text,
		 "table 40 30\nwall 1 18 %d 18 %d %d 1 %d\nwall %d 18 39 18 39 %d %d %d\nutak 15.5 7.5 north\n", x0,
		 x0, 18 + th, 18 + th, x0 + dw, 18 + th, x0 + dw, 18 + th);
	load(text);
}

TEST_CASE(no_slack_is_the_judge)
{
	oracle_seed = 26;
	int worlds = 0, parted = 0;
	for (int t = 0; t < 60 + 36; t++) {
		if (t < 60) {
			load_hall_with_piers(20, 4);
		} else {
			int k = t - 60;
			two_rooms(1 + k % 3, 3 + (k / 3) % 4, (int[]){5, 15, 29}[k / 12]);
		}
		JudgeRooms jr;
		judge_rooms_find(&jr, &table);
		Grid g;
		table_grid(&g, 0, 0);
		int64_t cells = (int64_t)table.w * table.h;
		int32_t *mine = malloc((size_t)cells * sizeof *mine);
		carryroom_watershed_slack(&g, 0, mine);
		bool same = agrees(&jr, mine, cells);
		if (!same) {
			fprintf(stderr, "  world %d:\n", t);
			world_write(&world, stderr);
		}
		TEST_CHECK(same);
		worlds++;
		parted += jr.count > 1;
		free(mine);
		grid_free(&g);
		judge_rooms_free(&jr);
		unload();
	}
	fprintf(stderr, "  %d worlds, %d parted into rooms by the judge\n", worlds, parted);
	TEST_CHECK(parted >= 20);
}

TEST_CASE(slack_covers_a_face_a_square_off)
{
	int doors = 0, lost_without = 0;
	for (int th = 1; th <= 3; th++)
		for (int dw = 3; dw <= 6; dw++)
			for (int p = 0; p < 3; p++) {
				two_rooms(th, dw, (int[]){5, 15, 29}[p]);
				JudgeRooms jr;
				judge_rooms_find(&jr, &table);
				/* The start (15, 7) and the far room's corner square (1, 28). */
				int32_t s = judge_rooms_at(&jr, 15, 7), far = judge_rooms_at(&jr, 1, 28);
				bool judge_door = s >= 0 && far >= 0 && s != far;
				judge_rooms_free(&jr);
				if (!judge_door) {
					unload();
					continue;
				}
				doors++;
				Grid g;
				table_grid(&g, 18 + th, 18 + th + 1); /* the wall read a square thicker */
				int32_t *mine = malloc((size_t)table.w * (size_t)table.h * sizeof *mine);
				carryroom_watershed_slack(&g, DOORSURE_SLACK, mine);
				int32_t ms = doorsure_start_room(&g, mine, 15, 7);
				TEST_CHECK(ms >= 0 && mine[28 * table.w + 1] != ms);
				carryroom_watershed_slack(&g, 0, mine);
				ms = doorsure_start_room(&g, mine, 15, 7);
				lost_without += mine[28 * table.w + 1] == ms;
				free(mine);
				grid_free(&g);
				unload();
			}
	fprintf(stderr, "  %d of 36 worlds with the judge's door; misread a square, %d read one room without the slack\n",
		doors, lost_without);
	TEST_CHECK(doors >= 20);
	TEST_CHECK(lost_without > 0); /* the slack is what keeps them apart */
}

int main(void)
{
	(void)act; /* the fixture's motor helper: not needed here */
	TEST_RUN(no_slack_is_the_judge);
	TEST_RUN(slack_covers_a_face_a_square_off);
	return TEST_EXIT();
}
