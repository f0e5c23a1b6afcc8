/* test_judgeworld.c - the judge's own shape names and rooms (issue 13; paper 2.3)
 * against hand-built worlds whose answers are known by construction: each shape
 * turned through every 5 degrees (with collinear and near-duplicate vertices
 * added), a wall with a doorway, a large room with piers, an L-shaped corridor. */
#include <math.h>
#include <stdio.h>

#include "test.h"
#include "world_fixture.h"
#include "utak/body/judgerooms.h"
#include "utak/body/judgeshape.h"

static const double pi = 3.14159265358979323846;

/* turned(pts, n, deg, extra): pts turned by deg about the origin and moved to
 * (50, 50), with a collinear midpoint and a near-duplicate inserted on the first
 * side when extra. */
static Polygon turned(const Vec2 *pts, int n, double deg, bool extra)
{
	Polygon p = {0};
	double c = cos(deg * pi / 180), s = sin(deg * pi / 180);
	for (int i = 0; i < n; i++) {
		Vec2 v = pts[i];
		p.v[p.count++] = vec2(50 + c * v.x - s * v.y, 50 + s * v.x + c * v.y);
		if (extra && i == 0) {
			Vec2 w = pts[1], m = vec2((v.x + w.x) / 2, (v.y + w.y) / 2);
			p.v[p.count++] = vec2(50 + c * m.x - s * m.y, 50 + s * m.x + c * m.y);
			p.v[p.count] = p.v[p.count - 1];
			p.v[p.count].x += 0.01;
			p.count++;
		}
	}
	return p;
}

TEST_CASE(judge_shapes_at_every_5_degrees)
{
	for (double size = 1; size <= 8; size *= 2) {
		double z = size;
		Vec2 square[] = {{0, 0}, {z, 0}, {z, z}, {0, z}};
		Vec2 brick[] = {{0, 0}, {2 * z, 0}, {2 * z, z}, {0, z}};
		Vec2 between[] = {{0, 0}, {1.35 * z, 0}, {1.35 * z, z}, {0, z}};
		Vec2 lshape[] = {{0, 0}, {2 * z, 0}, {2 * z, z}, {z, z}, {z, 3 * z}, {0, 3 * z}};
		Vec2 triangle[] = {{0, 0}, {z, 0}, {0.3 * z, z}};
		Vec2 rhombus[] = {{0, 0}, {z, 0}, {1.5 * z, z}, {0.5 * z, z}};
		Vec2 tee[] = {{0, 0}, {3 * z, 0}, {3 * z, z}, {2 * z, z}, {2 * z, 2 * z}, {z, 2 * z}, {z, z}, {0, z}};
		/* Each figure's least width, by hand: the square's, brick's and
		 * between's z; the L's 2z (its short leg's length); the triangle's the
		 * altitude on its longest side, z^2 / (z sqrt(0.49 + 1)). Narrower than
		 * JUDGE_SHAPE_MIN_WIDTH, a figure is unnamed. */
		bool wide = z >= JUDGE_SHAPE_MIN_WIDTH, l_wide = 2 * z >= JUDGE_SHAPE_MIN_WIDTH;
		bool t_wide = z / sqrt(1.49) >= JUDGE_SHAPE_MIN_WIDTH;
		for (int deg = 0; deg < 360; deg += 5)
			for (int extra = 0; extra < 2; extra++) {
				Polygon p;
				p = turned(square, 4, deg, extra);
				TEST_CHECK(judge_shape_name(&p) == (wide ? SHAPE_SQUARE : SHAPE_NONE));
				p = turned(brick, 4, deg, extra);
				TEST_CHECK(judge_shape_name(&p) == (wide ? SHAPE_BRICK : SHAPE_NONE));
				p = turned(between, 4, deg, extra);
				TEST_CHECK(judge_shape_name(&p) == SHAPE_NONE);
				p = turned(lshape, 6, deg, extra);
				TEST_CHECK(judge_shape_name(&p) == (l_wide ? SHAPE_LSHAPE : SHAPE_NONE));
				p = turned(triangle, 3, deg, extra);
				TEST_CHECK(judge_shape_name(&p) == (t_wide ? SHAPE_TRIANGLE : SHAPE_NONE));
				p = turned(rhombus, 4, deg, extra);
				TEST_CHECK(judge_shape_name(&p) == SHAPE_NONE);
				p = turned(tee, 8, deg, extra);
				TEST_CHECK(judge_shape_name(&p) == SHAPE_NONE);
			}
	}
}

TEST_CASE(judge_shapes_too_small_to_name)
{
	/* A crumb 1.9 squares wide covers a 3 x 3 block of the TABLE, as a 3 x 3
	 * square does: unnamed. From 2 squares wide, named, at every angle. */
	for (int deg = 0; deg < 360; deg += 5) {
		Vec2 crumb[] = {{0, 0}, {1.9, 0}, {1.9, 1.9}, {0, 1.9}};
		Vec2 least[] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
		Vec2 thin[] = {{0, 0}, {6, 0}, {6, 1.5}, {0, 1.5}};
		Polygon p = turned(crumb, 4, deg, 0);
		TEST_CHECK(judge_shape_name(&p) == SHAPE_NONE);
		p = turned(least, 4, deg, 0);
		TEST_CHECK(judge_shape_name(&p) == SHAPE_SQUARE);
		p = turned(thin, 4, deg, 0);
		TEST_CHECK(judge_shape_name(&p) == SHAPE_NONE);
	}
}

TEST_CASE(judge_centroid_is_the_area_centroid)
{
	/* An L of a 2 x 1 and a 1 x 2 block: area 3 (2 + 1 beyond the overlap). */
	Polygon p = {6, {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
	Vec2 c = judge_shape_centroid(&p);
	/* Blocks [0,2]x[0,1] (area 2, centre (1, .5)) and [0,1]x[1,2] (area 1, (.5, 1.5)). */
	TEST_NEAR(c.x, (2 * 1 + 0.5) / 3, 1e-12);
	TEST_NEAR(c.y, (2 * 0.5 + 1.5) / 3, 1e-12);
}

TEST_CASE(judge_rooms_a_doorway)
{
	/* Two 19 x 18 rooms, a wall 2 thick at x 19..21, a door 4 wide at y 8..12. */
	load("table 40 20\n"
	     "wall 19 1 21 1 21 8 19 8\n"
	     "wall 19 12 21 12 21 19 19 19\n"
	     "utak 5.5 10.5 north\n");
	JudgeRooms r;
	judge_rooms_find(&r, &table);
	TEST_CHECK(r.count == 2);
	int32_t west = judge_rooms_at(&r, 5, 10), east = judge_rooms_at(&r, 34, 10);
	TEST_CHECK(west >= 0 && east >= 0 && west != east);
	/* The passage between the wall's faces belongs to no room. */
	for (int32_t x = 19; x <= 20; x++)
		for (int32_t y = 8; y <= 11; y++)
			TEST_CHECK(judge_rooms_at(&r, x, y) == JUDGE_ROOM_NONE);
	/* Three squares past either face, on the door's axis: in a room. */
	TEST_CHECK(judge_rooms_at(&r, 16, 10) == west);
	TEST_CHECK(judge_rooms_at(&r, 24, 10) == east);
	/* Far corners are in their rooms; the doorway's nearest room is one of them. */
	TEST_CHECK(judge_rooms_at(&r, 1, 1) == west && judge_rooms_at(&r, 38, 18) == east);
	int32_t n = judge_rooms_nearest(&r, 19, 10);
	TEST_CHECK(n == west || n == east);
	judge_rooms_free(&r);
	unload();
}

TEST_CASE(judge_rooms_a_big_room_with_piers_is_one)
{
	load("table 160 120\n"
	     "wall 40 40 44 40 44 44 40 44\n"
	     "wall 80 40 84 40 84 44 80 44\n"
	     "wall 40 80 44 80 44 84 40 84\n"
	     "wall 80 80 84 80 84 84 80 84\n"
	     "wall 120 1 122 1 122 20 120 20\n"
	     "utak 10.5 10.5 north\n");
	JudgeRooms r;
	judge_rooms_find(&r, &table);
	TEST_CHECK(r.count == 1);
	TEST_CHECK(r.doors == 0);
	JudgeBend b;
	TEST_CHECK(!judge_rooms_bend(&r, 0, &b));	/* a room, not a corridor */
	TEST_CHECK(judge_rooms_at(&r, 1, 1) == 0 && judge_rooms_at(&r, 158, 118) == 0 && judge_rooms_at(&r, 123, 1) == 0 && judge_rooms_at(&r, 119, 1) == 0);
	judge_rooms_free(&r);
	unload();
}

TEST_CASE(judge_rooms_an_l_corridor_is_one_room_with_a_bend)
{
	/* A corridor 4 wide: along the south, then up the east side. Constant
	 * width: no narrowing, so one room and no door. */
	load("table 30 30\n"
	     "wall 1 5 25 5 25 29 1 29\n"
	     "utak 3.5 2.5 north\n");
	JudgeRooms r;
	judge_rooms_find(&r, &table);
	TEST_CHECK(r.count == 1);
	TEST_CHECK(r.doors == 0);
	TEST_CHECK(judge_rooms_at(&r, 2, 2) == 0 && judge_rooms_at(&r, 27, 27) == 0);
	/* Its legs and bend, known by construction: the south leg y 1..4, the east
	 * leg x 25..28 (the border squares are verge), the bend their overlap. */
	JudgeBend b;
	TEST_CHECK(judge_rooms_bend(&r, 0, &b));
	int32_t east[4] = {25, 1, 28, 28}, south[4] = {1, 1, 28, 4}, bend[4] = {25, 1, 28, 4};
	for (int i = 0; i < 4; i++) {
		TEST_CHECK(b.leg[0][i] == east[i]);
		TEST_CHECK(b.leg[1][i] == south[i]);
		TEST_CHECK(b.bend[i] == bend[i]);
	}
	judge_rooms_free(&r);
	unload();
}

TEST_CASE(judge_rooms_a_corridor_between_rooms)
{
	/* Two 14-wide rooms joined by a corridor 2 wide: two rooms. */
	load("table 40 16\n"
	     "wall 15 1 25 1 25 7 15 7\n"
	     "wall 15 9 25 9 25 15 15 15\n"
	     "utak 5.5 8.5 north\n");
	JudgeRooms r;
	judge_rooms_find(&r, &table);
	TEST_CHECK(r.count == 2);
	TEST_CHECK(judge_rooms_at(&r, 5, 8) != judge_rooms_at(&r, 34, 8));
	TEST_CHECK(judge_rooms_at(&r, 5, 8) >= 0 && judge_rooms_at(&r, 34, 8) >= 0);
	judge_rooms_free(&r);
	unload();
}

int main(void)
{
	(void)act;	/* the fixture's motor helper: not needed here */
	TEST_RUN(judge_shapes_at_every_5_degrees);
	TEST_RUN(judge_shapes_too_small_to_name);
	TEST_RUN(judge_centroid_is_the_area_centroid);
	TEST_RUN(judge_rooms_a_doorway);
	TEST_RUN(judge_rooms_a_big_room_with_piers_is_one);
	TEST_RUN(judge_rooms_an_l_corridor_is_one_room_with_a_bend);
	TEST_RUN(judge_rooms_a_corridor_between_rooms);
	return TEST_EXIT();
}
