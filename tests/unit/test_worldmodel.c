/* test_worldmodel.c - the world model (worldmodel.h, CONTROLLER SIDE) judged against
 * the ground truth. This test is a helper that may see both sides of the wall: it
 * runs the simulator (world, table, motion, retina) to make impressions, hands the
 * model only those and the commands, and then compares the model with the TABLE. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test.h"
#include "utak/body/act.h"
#include "utak/base/eye.h"
#include "utak/body/motion.h"
#include "utak/body/retina.h"
#include "utak/mind/worldmodel.h"

/* Outlines are judged within one square (the tolerance), plus rounding. */
#define OUTLINE_TOLERANCE (1.0 + 1e-9)
#define SAMPLE_STEP 0.125

typedef struct Sim {
	World w;
	Table t;
	int32_t ux0, uy0; /* Utak's first square: the model's origin */
} Sim;

static void sim_load(Sim *s, const char *text)
{
	Diag d;
	TEST_CHECK(world_parse(&s->w, "test", text, strlen(text), &d) == 0);
	TEST_CHECK(table_build(&s->t, &s->w, &d) == 0);
	table_square_of(s->w.utak, &s->ux0, &s->uy0);
}

static void sim_free(Sim *s)
{
	table_free(&s->t);
	world_free(&s->w);
}

/* sim_start(s, m, text): the world of text, and Utak's model after his first
 * impression of it. */
static void sim_start(Sim *s, WorldModel *m, const char *text)
{
	sim_load(s, text);
	worldmodel_init(m);
	Impression imp;
	retina_sense(&s->w, &s->t, &imp);
	worldmodel_accommodate_first(m, &imp);
}

static void sim_end(Sim *s, WorldModel *m)
{
	worldmodel_free(m);
	sim_free(s);
}

static char *read_file(const char *path)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return NULL;
	static char buf[1 << 16];
	size_t n = fread(buf, 1, sizeof buf - 1, f);
	fclose(f);
	buf[n] = 0;
	return buf;
}

/* model_to_table(s, p): a point of the model's frame on the TABLE. */
static Vec2 model_to_table(const Sim *s, Vec2 p)
{
	Vec2 d = world_own_to_table(s->w.heading, vec2(p.x - 0.5, p.y - 0.5));
	return vec2(s->ux0 + 0.5 + d.x, s->uy0 + 0.5 + d.y);
}

/* belief_error(s, m): how far (squares, each axis) the centre of Utak's believed
 * square lies from the centre of the true one, on the TABLE. */
static Vec2 belief_error(const Sim *s, const WorldModel *m)
{
	int32_t bx, by, tx, ty;
	worldmodel_utak_square(m, &bx, &by);
	table_square_of(s->w.utak, &tx, &ty);
	Vec2 b = model_to_table(s, vec2(bx + 0.5, by + 0.5));
	return vec2(fabs(b.x - (tx + 0.5)), fabs(b.y - (ty + 0.5)));
}

static void sim_step(Sim *s, WorldModel *m, const char *script)
{
	MotorCommand *cmds;
	int n;
	Diag d;
	TEST_CHECK(act_parse(script, strlen(script), &cmds, &n, &d) == 0);
	for (int i = 0; i < n; i++) {
		MotorOutcome out;
		motion_execute(&s->w, &s->t, &cmds[i], &out);
		Impression imp;
		retina_sense(&s->w, &s->t, &imp);
		worldmodel_accommodate(m, &cmds[i], &imp);
		char why[160];
		TEST_CHECK(worldmodel_validate(m, why, sizeof why));
	}
	free(cmds);
}

static double point_segment(Vec2 p, Vec2 a, Vec2 b)
{
	Vec2 ab = vec2_sub(b, a);
	double len2 = vec2_dot(ab, ab), t = len2 > 0 ? vec2_dot(vec2_sub(p, a), ab) / len2 : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	Vec2 q = vec2_add(a, vec2_scale(ab, t));
	return hypot(p.x - q.x, p.y - q.y);
}

static double point_polygon(Vec2 p, const Polygon *poly)
{
	double best = INFINITY;
	for (int32_t i = 0; i < poly->count; i++) {
		double d = point_segment(p, poly->v[i], poly->v[(i + 1) % poly->count]);
		best = d < best ? d : best;
	}
	return best;
}

/* ring_polygon(s, m, r): a believed ring on the TABLE (rings are short: <= 64). */
static bool ring_polygon(const Sim *s, const WorldModel *m, const ModelRing *r, Polygon *out)
{
	if (r->count > GEOM_MAX_VERTICES)
		return false;
	out->count = r->count;
	for (int32_t j = 0; j < r->count; j++)
		out->v[j] = model_to_table(s, m->vertex[r->first + j].p);
	return true;
}

/* hausdorff(a, b): the larger of the two one-sided distances between outlines. */
static double one_sided(const Polygon *a, const Polygon *b)
{
	double worst = 0;
	for (int32_t i = 0; i < a->count; i++) {
		Vec2 p = a->v[i], q = a->v[(i + 1) % a->count];
		double len = hypot(q.x - p.x, q.y - p.y);
		for (double t = 0; t <= len; t += SAMPLE_STEP) {
			double d =
			    point_polygon(vec2_add(p, vec2_scale(vec2_sub(q, p), t / len)), b);
			worst = d > worst ? d : worst;
		}
	}
	return worst;
}

TEST_CASE(worldmodel_default_model)
{
	WorldModel m;
	worldmodel_init(&m);
	char why[160];
	TEST_CHECK(worldmodel_validate(&m, why, sizeof why));
	TEST_CHECK(m.node_count == 2 && m.node[1].ring_count == 1);
	TEST_NEAR(m.node[1].rect.hi.x - m.node[1].rect.lo.x, WORLDMODEL_DEFAULT_FLOOR, 0);
	TEST_NEAR((m.node[1].rect.hi.x + m.node[1].rect.lo.x) / 2, 0.5, 0); /* centred on Utak */
	TEST_CHECK(worldmodel_belief(&m, 3, 3) == BELIEF_UNKNOWN);
	worldmodel_free(&m);
}

/* Two worlds the same within Utak's 32 x 32 field, different outside it. */
TEST_CASE(worldmodel_same_field_same_model)
{
	const char *a = "table 40 30\nobject square A 6 20 10 20 10 24 6 24\n"
	                "object lshape D 8 4 11 4 11 8 17 8 17 11 8 11\nutak 20.5 12.5 north\n";
	const char *b =
	    "table 60 40\nobject square A 6 20 10 20 10 24 6 24\n"
	    "object lshape D 8 4 11 4 11 8 17 8 17 11 8 11\n"
	    "object far C 40 30 44 30 44 34 40 34\nobject high E 10 29 14 29 14 31 10 31\n"
	    "utak 20.5 12.5 north\n";
	Sim sa, sb;
	sim_load(&sa, a);
	sim_load(&sb, b);
	Impression ia, ib;
	retina_sense(&sa.w, &sa.t, &ia);
	retina_sense(&sb.w, &sb.t, &ib);
	TEST_CHECK(memcmp(&ia, &ib, sizeof ia) == 0);
	WorldModel ma, mb;
	worldmodel_init(&ma);
	worldmodel_init(&mb);
	worldmodel_accommodate_first(&ma, &ia);
	worldmodel_accommodate_first(&mb, &ib);
	char *da = NULL, *db = NULL;
	size_t la = 0, lb = 0;
	FILE *fa = open_memstream(&da, &la), *fb = open_memstream(&db, &lb);
	worldmodel_dump(&ma, fa);
	worldmodel_dump(&mb, fb);
	fclose(fa);
	fclose(fb);
	TEST_CHECK(la == lb && la > 0 && memcmp(da, db, la) == 0);
	free(da);
	free(db);
	worldmodel_free(&ma);
	worldmodel_free(&mb);
	sim_free(&sa);
	sim_free(&sb);
}

/* A walk round room.w that brings every object within the intermediate zone. */
static const char room_walk[] =
    "move -6 4; move -6 0; move 0 -3; move -5 0; move 0 -8; move 2 -3;"
    "move 8 0; move 6 4; move 0 8; move 8 2; move 8 0; move 0 8; move -8 0;"
    "move -15 0; move 0 -6";

TEST_CASE(worldmodel_room_walk_outlines)
{
	Sim s;
	const char *text = read_file("worlds/room.w");
	TEST_CHECK(text != NULL);
	WorldModel m;
	sim_start(&s, &m, text);
	sim_step(&s, &m, room_walk);
	/* Utak is where the model believes, to the square. */
	Vec2 err = belief_error(&s, &m);
	TEST_NEAR(err.x, 0, 0);
	TEST_NEAR(err.y, 0, 0);
	/* Every true object has a believed object whose outline is within one square
	 * of its own, both ways; every believed object is within one square of one. */
	int matched[WORLD_MAX_OBJECTS] = {0};
	for (int32_t id = 0; id < m.node_count; id++) {
		if (m.node[id].kind != NODE_OBJECT)
			continue;
		Polygon believed_outline;
		TEST_CHECK(m.node[id].ring_count >= 1 && !m.ring[m.node[id].first_ring].hole);
		TEST_CHECK(ring_polygon(&s, &m, &m.ring[m.node[id].first_ring], &believed_outline));
		int found = -1;
		for (int32_t k = 0; k < s.w.object_count && found < 0; k++) {
			const Polygon *truth = &s.w.objects[k].shape;
			if (one_sided(&believed_outline, truth) <= OUTLINE_TOLERANCE &&
			    one_sided(truth, &believed_outline) <= OUTLINE_TOLERANCE)
				found = (int)k;
		}
		if (found < 0)
			fprintf(stderr, "  believed %s matches no true object\n", m.node[id].name);
		TEST_CHECK(found >= 0);
		matched[found]++;
	}
	for (int32_t k = 0; k < s.w.object_count; k++) {
		if (matched[k] != 1)
			fprintf(stderr, "  true object %s matched %d times\n", s.w.objects[k].name,
			        matched[k]);
		TEST_CHECK(matched[k] == 1);
	}
	/* The floor's outline, where both its sides were seen in the fovea, lies within
	 * one square of the verge or an object. */
	const ModelNode *floor_node = &m.node[1];
	int32_t checked = 0;
	for (int32_t k = 0; k < floor_node->ring_count; k++) {
		const ModelRing *r = &m.ring[floor_node->first_ring + k];
		for (int32_t j = 0; j < r->count; j++) {
			Vec2 a = m.vertex[r->first + j].p,
			     b = m.vertex[r->first + (j + 1) % r->count].p;
			double len = hypot(b.x - a.x, b.y - a.y);
			for (double t = 0.5; t < len; t += 1) {
				Vec2 p = vec2_add(a, vec2_scale(vec2_sub(b, a), t / len));
				/* the squares on the two sides of this unit edge */
				Vec2 n = vec2((b.y - a.y) / len * 0.5, -(b.x - a.x) / len * 0.5);
				Vec2 in = vec2_sub(p, n), out = vec2_add(p, n);
				Evidence ei = worldmodel_evidence(&m, (int32_t)floor(in.x),
				                                  (int32_t)floor(in.y));
				Evidence eo = worldmodel_evidence(&m, (int32_t)floor(out.x),
				                                  (int32_t)floor(out.y));
				if (ei.res != WORLDMODEL_RES_FOVEA ||
				    eo.res != WORLDMODEL_RES_FOVEA)
					continue;
				Vec2 q = model_to_table(&s, p);
				double d = point_polygon(q, &s.w.verge);
				for (int32_t o = 0; o < s.w.object_count; o++) {
					double dobj = point_polygon(q, &s.w.objects[o].shape);
					d = dobj < d ? dobj : d;
				}
				if (d > OUTLINE_TOLERANCE)
					fprintf(stderr,
					        "  floor edge at model (%.1f, %.1f) is %.2f from "
					        "the truth\n",
					        p.x, p.y, d);
				TEST_CHECK(d <= OUTLINE_TOLERANCE);
				checked++;
			}
		}
	}
	TEST_CHECK(checked > 20);
	sim_end(&s, &m);
}

/* A believed position off by up to 3 squares, where the fovea or the intermediate
 * zone sees an edge, is corrected to within one square in two impressions. */
TEST_CASE(worldmodel_disparity_corrects_wrong_belief)
{
	const char *starts[] = {"utak 20.5 12.5 north", "utak 14.5 15.5 north",
	                        "utak 27.5 16.5 north"};
	Sim s;
	const char *room = read_file("worlds/room.w");
	TEST_CHECK(room != NULL);
	int trials = 0;
	for (int st = 0; st < 3; st++) {
		char text[1024];
		snprintf(text, sizeof text, "%.*s%s\n", (int)(strstr(room, "utak 20.5") - room),
		         room, starts[st]);
		for (int ey = -3; ey <= 3; ey++)
			for (int ex = -3; ex <= 3; ex++) {
				if (ex == 0 && ey == 0)
					continue;
				WorldModel m;
				sim_start(&s, &m, text);
				worldmodel_set_position(&m, vec2(0.5 + ex, 0.5 + ey));
				sim_step(&s, &m, "move 1 0; move 0 1");
				int32_t bx, by, tx, ty;
				worldmodel_utak_square(&m, &bx, &by);
				table_square_of(s.w.utak, &tx, &ty);
				int32_t dx = abs(bx - (tx - s.ux0)), dy = abs(by - (ty - s.uy0));
				if (dx > 1 || dy > 1)
					fprintf(
					    stderr,
					    "  start %d error (%d, %d): still off by (%d, %d)\n",
					    st, ex, ey, (int)dx, (int)dy);
				TEST_CHECK(dx <= 1 && dy <= 1);
				trials++;
				sim_end(&s, &m);
			}
	}
	TEST_CHECK(trials == 3 * 48);
}

/* The controller is not told where a move halted: the disparity search along the
 * commanded line finds it. From the start of room.w, "move 0 -12" halts against
 * the L-shaped object after about 6.5 squares. */
TEST_CASE(worldmodel_halted_move_found)
{
	Sim s;
	const char *text = read_file("worlds/room.w");
	TEST_CHECK(text != NULL);
	WorldModel m;
	sim_start(&s, &m, text);
	sim_step(&s, &m, "move 0 5; move -8 0; move 0 -12");
	TEST_CHECK(m.report.corrected);
	int32_t bx, by, tx, ty;
	worldmodel_utak_square(&m, &bx, &by);
	table_square_of(s.w.utak, &tx, &ty);
	TEST_CHECK(bx == tx - s.ux0 && by == ty - s.uy0);
	sim_end(&s, &m);
}

/* sight_bound(m): the most positions the disparity search may score after a move:
 * the 49 round the prediction, and 9 for every half square of the commanded line
 * within WM_SIGHT_MARGIN (EYE_HALF + 2) of the squares seen, whatever the command's
 * length: that stretch is at most the diagonal of the grown rectangle. */
static int32_t sight_bound(const WorldModel *m)
{
	double margin = 2.0 * (EYE_HALF + 2) + 1;
	double diagonal = hypot(m->seen_x1 - m->seen_x0 + margin, m->seen_y1 - m->seen_y0 + margin);
	return 49 + 9 * (int32_t)(2 * diagonal + 2);
}

/* Moves and pushes of a million squares into the verge a few squares away (issue
 * 14), against the same commands scaled down to 60 squares, which halt at the same
 * squares (the simulator says so): the same belief after each, and a search that
 * scored no more positions than the squares in sight allow (before, one per half
 * square of the command: 2.8 million for the diagonal move, some 20 s). */
TEST_CASE(worldmodel_long_moves_cost_what_is_in_sight)
{
	const char *text = read_file("worlds/room.w");
	TEST_CHECK(text != NULL);
	Sim s, short_s;
	WorldModel m, short_m;
	sim_start(&s, &m, text);
	sim_start(&short_s, &short_m, text);
	static const char *const steps[][2] = {
		{"move -10 9", "move -10 9"},       {"grasp", "grasp"},
		{"push 0 1000000", "push 0 60"},    {"push -1000000 0", "push -60 0"},
		{"release", "release"},             {"move 1000000 0", "move 60 0"},
		{"move -1000000 -1000000", "move -60 -60"}, {"move 0 1000000", "move 0 60"},
	};
	for (int k = 0; k < 8; k++) {
		sim_step(&s, &m, steps[k][0]);
		sim_step(&short_s, &short_m, steps[k][1]);
		int32_t tx, ty, short_tx, short_ty, bx, by, sx, sy;
		table_square_of(s.w.utak, &tx, &ty);
		table_square_of(short_s.w.utak, &short_tx, &short_ty);
		TEST_CHECK(tx == short_tx && ty == short_ty);
		worldmodel_utak_square(&m, &bx, &by);
		worldmodel_utak_square(&short_m, &sx, &sy);
		TEST_CHECK(bx == sx && by == sy && m.holding == short_m.holding);
		TEST_CHECK(m.report.candidates <= sight_bound(&m));
	}
	TEST_CHECK(m.report.corrected); /* the search did have to find him */
	sim_end(&short_s, &short_m);
	sim_end(&s, &m);
}

/* Grasp, push and turn: the held object hangs under $org and moves with Utak; its
 * believed outline follows the true one. */
TEST_CASE(worldmodel_held_object_follows)
{
	Sim s;
	const char *text = read_file("worlds/room.w");
	TEST_CHECK(text != NULL);
	WorldModel m;
	sim_start(&s, &m, text);
	const char *steps[] = {"move -10 9", "grasp",   "push 0 -3",
	                       "push 4 0",   "turn 90", "release"};
	int32_t ident = -1;
	for (int k = 0; k < 6; k++) {
		sim_step(&s, &m, steps[k]);
		if (k == 0)
			continue;
		/* The node of the square: the object nearest Utak. */
		int32_t held = -1;
		for (int32_t id = 0; id < m.node_count; id++)
			if (m.node[id].kind == NODE_OBJECT && m.node[id].squares == 16)
				held = id;
		TEST_CHECK(held >= 0);
		TEST_CHECK(m.node[held].held == (k < 5) && m.node[held].parent == (k < 5 ? 0 : 1));
		if (ident < 0)
			ident = m.node[held].ident;
		TEST_CHECK(m.node[held].ident == ident);
		Polygon believed;
		TEST_CHECK(ring_polygon(&s, &m, &m.ring[m.node[held].first_ring], &believed));
		TEST_CHECK(one_sided(&believed, &s.w.objects[0].shape) <= OUTLINE_TOLERANCE);
		TEST_CHECK(one_sided(&s.w.objects[0].shape, &believed) <= OUTLINE_TOLERANCE);
		TEST_CHECK(!m.report.corrected);
	}
	sim_end(&s, &m);
}

/* Pushing the square into a wall one square at a time: the pushes go on after it
 * meets the wall and make no headway. After each, Utak's believed square is the
 * true one (the simulator's), halted or not: the held object moves with him in
 * every position the disparity search tries, so it cannot vote for the predicted
 * one. */
TEST_CASE(worldmodel_push_halted_at_wall)
{
	Sim s;
	const char *text = read_file("worlds/room.w");
	TEST_CHECK(text != NULL);
	WorldModel m;
	sim_start(&s, &m, text);
	sim_step(&s, &m, "move -10 9; grasp");
	TEST_CHECK(m.holding && m.held_count == 16);
	int halted = 0;
	for (int k = 0; k < 12; k++) {
		int32_t tx0, ty0;
		table_square_of(s.w.utak, &tx0, &ty0);
		sim_step(&s, &m, "push 0 1");
		int32_t tx, ty;
		table_square_of(s.w.utak, &tx, &ty);
		halted += tx == tx0 && ty == ty0;
		Vec2 err = belief_error(&s, &m);
		TEST_CHECK(err.x < 0.5 && err.y < 0.5);
	}
	TEST_CHECK(halted >= 2); /* the test reaches the wall */
	TEST_CHECK(m.held_count == 16);
	sim_end(&s, &m);
}

/* Pushing the square east with noisy motion (paper 3.5; utak --noise 0.05): each
 * push leaves it a fraction of a square off the grid, where it covers a fifth
 * column of the TABLE. The controller is not told the error. Over ten seeds of
 * five pushes each, his believed square must on average lie within a square of
 * the true one (the simulator is the oracle). Before the held set could regrow
 * (wm_regrow_held) the squares of that fifth column stayed behind at each push,
 * and the disparity search believed Utak had not moved: the mean error was 2.8
 * squares, growing to 10 by the fifth push; with it 0.6, mostly the first push
 * (the held set not yet grown) and the last (the square meets the brick). */
TEST_CASE(worldmodel_noisy_pushes_keep_track)
{
	const char *text = read_file("worlds/room.w");
	TEST_CHECK(text != NULL);
	double sum = 0;
	int pushes = 0;
	for (uint64_t seed = 1; seed <= 10; seed++) {
		Sim s;
		WorldModel m;
		sim_start(&s, &m, text);
		sim_step(&s, &m, "move -10 9; grasp");
		TEST_CHECK(m.holding);
		MotionNoise noise;
		motion_noise_init(&noise, 0.05, seed);
		MotorCommand push = {.kind = MOTOR_PUSH, .dx = 3, .dy = 0};
		for (int k = 0; k < 5; k++) {
			MotorOutcome out;
			motion_execute_noisy(&s.w, &s.t, &push, &noise, &out);
			Impression imp;
			retina_sense(&s.w, &s.t, &imp);
			worldmodel_accommodate(&m, &push, &imp);
			Vec2 err = belief_error(&s, &m);
			sum += fmax(err.x, err.y);
			pushes++;
		}
		sim_end(&s, &m);
	}
	printf("  noisy pushes: the belief %.2f squares from the true square on average\n", sum / pushes);
	TEST_CHECK(sum / pushes <= 1.0);
}

/* A long move that halts against a wall seen only in the periphery. The only
 * evidence of the wall is one 4 x 4 cell of the first impression at level 4: two
 * of its four rows occupied, which two it cannot say. Halting one square before
 * the wall at any of three places fits that evidence equally, so the belief can
 * be two squares out; within that it must be. (Where the fovea or intermediate
 * zone has seen the wall, worldmodel_halted_move_found asks for the square.) */
TEST_CASE(worldmodel_halted_at_coarse_wall)
{
	Sim s;
	const char *text = read_file("worlds/tworooms.w");
	TEST_CHECK(text != NULL);
	WorldModel m;
	sim_start(&s, &m, text);
	sim_step(&s, &m, "move 0 25");
	Vec2 err = belief_error(&s, &m);
	TEST_CHECK(err.x <= 2 && err.y <= 2);
	sim_end(&s, &m);
}

/* A thin wall seen only by peripheral cells is not erased by a look whose cells
 * straddle it (worldmodel.h, the confidence rules; paper 3.4.2: only a zero cell
 * is floorspace). A wall two squares thick lies 8 and 9 squares ahead, in one row
 * of 4 x 4 cells; Utak steps back one square at a time until it lies 11 and 12
 * ahead, across two rows of cells, each a quarter full, whose level alone reads
 * every square of them as floor. Every square of the wall's middle, seen only
 * peripherally, must still be believed occupied, by the TABLE. */
TEST_CASE(worldmodel_coarse_thin_wall_kept)
{
	Sim s;
	WorldModel m;
	sim_start(&s, &m, "table 60 60\nwall 10 28 50 28 50 30 10 30\nutak 30.5 20.5 north\n");
	for (int i = 0; i < 3; i++)
		sim_step(&s, &m, "move 0 -1");
	Vec2 err = belief_error(&s, &m);
	TEST_CHECK(err.x == 0 && err.y == 0);
	int wall = 0, kept = 0;
	for (int32_t y = 0; y < s.t.h; y++)
		for (int32_t x = 20; x <= 40; x++) {
			if (table_owner(&s.t, x, y) != TABLE_VERGE)
				continue;
			Evidence e = worldmodel_evidence(&m, x - s.ux0, y - s.uy0);
			if (e.res == WORLDMODEL_UNSEEN)
				continue; /* the table's own verge, out of sight */
			TEST_CHECK(e.res == WORLDMODEL_RES_PERIPHERAL);
			wall++;
			kept += worldmodel_belief(&m, x - s.ux0, y - s.uy0) == BELIEF_OCCUPIED;
		}
	TEST_CHECK(wall == 2 * 21);
	TEST_CHECK(kept == wall);
	sim_end(&s, &m);
}

/* A property over random walks (a fixed little generator, so the same walks on
 * every machine): moves of up to 8 squares each way, many of them halting against
 * objects and walls, in every world of this test. After every move the believed
 * square is never more than one square from the true one, and exactly right most
 * of the time (along a straight wall the eye cannot tell where it is). */
TEST_CASE(worldmodel_random_walks_stay_close)
{
	static const char *const worlds[] = {"worlds/room.w", "worlds/tworooms.w",
	                                     "worlds/nearcorner.w"};
	int steps = 0, exact = 0;
	for (int wi = 0; wi < 3; wi++)
		for (uint32_t seed = 1; seed <= 8; seed++) {
			Sim s;
			const char *text = read_file(worlds[wi]);
			TEST_CHECK(text != NULL);
			WorldModel m;
			sim_start(&s, &m, text);
			uint32_t state = seed * 2654435761u;
			for (int i = 0; i < 20; i++) {
				char cmd[64];
				state = state * 1664525u + 1013904223u;
				int dx = (int)((state >> 16) % 17) - 8;
				state = state * 1664525u + 1013904223u;
				int dy = (int)((state >> 16) % 17) - 8;
				snprintf(cmd, sizeof cmd, "move %d %d", dx, dy);
				sim_step(&s, &m, cmd);
				Vec2 err = belief_error(&s, &m);
				double ex = err.x, ey = err.y;
				if (ex > 1 || ey > 1)
					fprintf(stderr,
					        "  %s seed %u move %d: off by (%.0f, %.0f)\n",
					        worlds[wi], (unsigned)seed, i, ex, ey);
				TEST_CHECK(ex <= 1 && ey <= 1);
				exact += ex == 0 && ey == 0;
				steps++;
			}
			sim_end(&s, &m);
		}
	printf("  random walks: %d of %d moves end with the belief on the true square\n", exact,
	       steps);
	TEST_CHECK(exact * 10 >= steps * 8);
}

/* The first impression places Utak again near his first square (paper 3.5's
 * fallback, recognition by features; worldmodel_recognise_first), however wrong his
 * belief has become. In four worlds Utak steps to each square within two of his
 * first (exact motion, so the simulator's square is the truth), and his belief is
 * then pushed off by every shift of up to two squares: on every axis the first
 * impression says it places him, the square it returns is the true one, and with the
 * belief right it keeps it. Over all, it finds the true square on both axes at least
 * 40% of the time (1200 of 2500 when written: open floor far from everything, and
 * west.w's long room, place him on one axis or neither). */
TEST_CASE(worldmodel_first_impression_places_utak)
{
	static const char *const worlds[] = {"worlds/room.w", "worlds/tworooms.w", "worlds/west.w",
	                                     "worlds/nearcorner.w"};
	int tries = 0, found = 0;
	for (int wi = 0; wi < 4; wi++)
		for (int ty = -2; ty <= 2; ty++)
			for (int tx = -2; tx <= 2; tx++) {
				Sim s;
				const char *text = read_file(worlds[wi]);
				TEST_CHECK(text != NULL);
				WorldModel m;
				sim_start(&s, &m, text);
				char cmd[64];
				snprintf(cmd, sizeof cmd, "move %d %d", tx, ty);
				sim_step(&s, &m, cmd);
				Vec2 err = belief_error(&s, &m);
				if (err.x != 0 || err.y != 0) { /* halted: not the square asked for */
					sim_end(&s, &m);
					continue;
				}
				Impression imp;
				retina_sense(&s.w, &s.t, &imp);
				for (int sy = -2; sy <= 2; sy++)
					for (int sx = -2; sx <= 2; sx++) {
						int32_t x = tx + sx, y = ty + sy;
						bool placed[2] = {false, false};
						if (!worldmodel_recognise_first(&m, &imp, &x, &y, placed))
							continue;
						if ((placed[0] && x != tx) || (placed[1] && y != ty))
							fprintf(stderr, "  %s at (%d, %d), believed (%d, %d): placed at (%d, %d)\n",
							        worlds[wi], tx, ty, tx + sx, ty + sy, (int)x, (int)y);
						if (placed[0])
							TEST_CHECK(x == tx);
						if (placed[1])
							TEST_CHECK(y == ty);
						if (sx == 0 && sy == 0)
							TEST_CHECK(x == tx && y == ty);
						found += x == tx && y == ty && placed[0] && placed[1];
						tries++;
					}
				sim_end(&s, &m);
			}
	printf("  first impression: %d of %d shifted beliefs placed back on the true square\n", found, tries);
	TEST_CHECK(tries > 0 && found * 5 >= tries * 2);
}

/* Motion's error as the disparity shows it (worldmodel_motion_error): the
 * controller is not told sigma. With exact motion there is none to see, halts or no
 * halts; with --noise 0.05 over walks of moves of 4 to 8 squares in room.w, the
 * estimate is above 0 and within a factor of 4 of the simulator's sigma (the
 * corrections are whole squares, so short moves overstate it). */
TEST_CASE(worldmodel_motion_error_estimated)
{
	const char *text = read_file("worlds/room.w");
	TEST_CHECK(text != NULL);
	static const int moves[][2] = {{0, 6}, {-8, 0}, {0, -8}, {8, 0}, {5, 5}, {-4, -6}, {6, -4}, {-7, 3}};
	for (int noisy = 0; noisy < 2; noisy++) {
		double sum = 0;
		for (uint64_t seed = 1; seed <= 6; seed++) {
			Sim s;
			WorldModel m;
			sim_start(&s, &m, text);
			MotionNoise noise;
			motion_noise_init(&noise, noisy ? 0.05 : 0, seed);
			for (int round = 0; round < 3; round++)
				for (int k = 0; k < 8; k++) {
					MotorCommand mv = {.kind = MOTOR_MOVE, .dx = moves[k][0], .dy = moves[k][1]};
					MotorOutcome out;
					motion_execute_noisy(&s.w, &s.t, &mv, &noise, &out);
					Impression imp;
					retina_sense(&s.w, &s.t, &imp);
					worldmodel_accommodate(&m, &mv, &imp);
				}
			double e = worldmodel_motion_error(&m);
			if (!noisy)
				TEST_CHECK(e == 0);
			sum += e;
			sim_end(&s, &m);
		}
		if (noisy) {
			printf("  motion error: estimated %.3f squares a square, sigma 0.05\n", sum / 6);
			TEST_CHECK(sum / 6 > 0.05 / 4 && sum / 6 < 0.05 * 4);
		}
	}
}

/* A halted push into the verge is found (worldmodel.c, wm_solid_tie). The square
 * is pushed north, one square a push, until it meets the table's north verge, then
 * pushed on: the pushes halt at once. The object rides with Utak and hides the
 * verge beyond it, and what stays put (the verge beside it, a pier off to the
 * east) is seen mostly in coarse cells, so the impression alone barely tells a
 * halted push from a square gained (the case of tests/worlds/push-pier-noise.w,
 * from /tmp/p11/adv/a14.w). The
 * oracle is the simulator: over the pushes it halts (exact, and --noise 0.05 over
 * 8 seeds), the believed square must never step on (a halted push read as a
 * square gained: the object believed a square deeper into the verge than the eye
 * has surely seen it can be, and a corner claimed short of it). Measured: 63
 * pushes halted, none read as gained; with wm_solid_tie switched off, 31 were. */
TEST_CASE(worldmodel_push_into_verge_halts)
{
	const char *text = "table 43 27\nwall 35 19 37 19 37 23 35 23\n"
	                   "object square A 18 9 22 9 22 13 18 13\nutak 20.5 8.5 north\n";
	int halted = 0, gained = 0;
	for (uint64_t seed = 0; seed <= 8; seed++) {
		Sim s;
		WorldModel m;
		sim_start(&s, &m, text);
		sim_step(&s, &m, "grasp");
		TEST_CHECK(m.holding && m.held_count >= 16);
		MotionNoise noise;
		motion_noise_init(&noise, seed ? 0.05 : 0, seed);
		MotorCommand push = {.kind = MOTOR_PUSH, .dx = 0, .dy = 1};
		for (int k = 0; k < 20; k++) {
			int32_t tx0, ty0, tx, ty, bx0, by0, bx, by;
			table_square_of(s.w.utak, &tx0, &ty0);
			worldmodel_utak_square(&m, &bx0, &by0);
			MotorOutcome out;
			motion_execute_noisy(&s.w, &s.t, &push, &noise, &out);
			Impression imp;
			retina_sense(&s.w, &s.t, &imp);
			worldmodel_accommodate(&m, &push, &imp);
			table_square_of(s.w.utak, &tx, &ty);
			worldmodel_utak_square(&m, &bx, &by);
			if (tx == tx0 && ty == ty0) {
				halted++;
				gained += by > by0;
			}
		}
		sim_end(&s, &m);
	}
	printf("  pushes into the verge: %d halted, %d of them believed a square gained\n", halted, gained);
	TEST_CHECK(halted >= 9 * 4); /* every run reaches the verge and pushes on */
	TEST_CHECK(gained == 0);
}

/* A slanted square pushed north into the verge, one square a push, the held set
 * registered as for the corner push (m.register_held): after every push, is
 * Utak's believed square the true one (the simulator is the oracle)? A push
 * that halts once the square meets the verge shows the eye nearly what a push
 * that went on would: the object rides with him, and the verge beyond a slanted
 * object is seen mostly in coarse cells half on the object, never surely enough
 * for wm_solid_tie. Read as squares gained, such pushes made Utak claim a corner
 * the object was 2 short of (adversarial world h38, tests/worlds/push-slant-verge.w).
 * Sides 4 to 7, turned 0 to 40 degrees in steps of 5, offsets of a third of a
 * square, 14 pushes each (108 runs, 1512 pushes): before wm_pressed (worldmodel.c),
 * 163 pushes left the belief ahead of the truth (the worst way to be wrong: the
 * object reads nearer the corner than it is), 50 runs ended so, and 344 pushes in
 * all left it off the true square; after, 98, 29 and 291, all of it from the
 * rule for a push of a square that leaves the impression unchanged (without it,
 * 163, 50 and 344 again; h38's halts are found by the other). What is left: a push
 * that halts a fraction of a square on without crossing his square's edge moves
 * only the object in the impression, at every candidate alike, and the verge
 * beyond it is still unsure: the prediction stands (README, Reliability). */
TEST_CASE(worldmodel_slanted_push_into_verge)
{
	int runs = 0, pushed = 0, ahead = 0, misloc = 0, end_ahead = 0;
	for (int side = 4; side <= 7; side++)
		for (int deg = 0; deg <= 40; deg += 5)
			for (int off = 0; off < 3; off++) {
				double a = deg * 3.14159265358979323846 / 180, c = cos(a), sn = sin(a);
				/* The square's lowest corner just north of Utak's square. */
				double h = side / 2.0, cx = 20.5 + off / 3.0, cy = 12.2 + h * (c + sn);
				char text[512];
				int len = snprintf(text, sizeof text, "table 41 %d\nobject square A", 14 + 2 * side + 6);
				for (int k = 0; k < 4; k++) {
					double px = (k == 0 || k == 3) ? -h : h, py = k < 2 ? -h : h;
					len += snprintf(text + len, sizeof text - (size_t)len, " %.4f %.4f",
					                cx + px * c - py * sn, cy + px * sn + py * c);
				}
				snprintf(text + len, sizeof text - (size_t)len, "\nutak 20.5 10.5 north\n");
				Sim s;
				WorldModel m;
				sim_start(&s, &m, text);
				sim_step(&s, &m, "move 0 1; grasp");
				if (!m.holding || m.held_count == 0) {
					sim_end(&s, &m);
					continue;
				}
				runs++;
				m.register_held = true;
				int dy = 0;
				for (int k = 0; k < 14; k++) {
					sim_step(&s, &m, "push 0 1");
					pushed++;
					/* Utak faces north: the model's axes are the TABLE's. */
					int32_t bx, by, tx, ty;
					worldmodel_utak_square(&m, &bx, &by);
					table_square_of(s.w.utak, &tx, &ty);
					dy = by - (ty - s.uy0);
					misloc += bx != tx - s.ux0 || dy != 0;
					ahead += dy > 0;
				}
				end_ahead += dy > 0;
				sim_end(&s, &m);
			}
	printf("  slanted squares pushed into the verge: %d runs, %d pushes, %d left the belief off the true "
	       "square, %d ahead of it; %d runs ended ahead\n",
	       runs, pushed, misloc, ahead, end_ahead);
	TEST_CHECK(runs >= 100); /* nearly every square is grasped */
	TEST_CHECK(ahead <= 110); /* 163 before */
	TEST_CHECK(end_ahead <= 32); /* 50 before */
}

/* The premise of the disparity's slack (worldmodel.c, wm_tolerant_mismatch), by
 * brute force over eye_level: a 4 x 4 cell at level 0 may hold one occupied square
 * and no more, at level 7 one floor square and no more; a 2 x 2 or a single square
 * at level 0 or 7 holds none the other way. */
TEST_CASE(worldmodel_slack_of_coarse_levels)
{
	for (int side = 1; side <= 4; side *= 2) {
		int n = side * side, zero = 0, full = 0;
		for (int o = 0; o <= n; o++) {
			zero += eye_level(o, n) == 0;
			full += eye_level(o, n) == EYE_MAX_LEVEL;
		}
		TEST_CHECK(zero == (side == 4 ? 2 : 1) && full == (side == 4 ? 2 : 1));
	}
}

/* lcg(state): the next of a fixed little generator (the same worlds on every machine). */
static uint32_t lcg(uint32_t *state)
{
	*state = *state * 1664525u + 1013904223u;
	return *state >> 8;
}

/* open_floor(seed, text, size): an open-floor world of the kind nobody tuned the
 * model for: a TABLE 60 to 100 square, Utak at its middle facing any way, 2 to 4
 * squares of side 2 to 5 at any angle, 5 to 20 squares from him and clear of him
 * and of each other. */
static void open_floor(uint32_t seed, char *text, size_t size)
{
	uint32_t st = seed * 2654435761u;
	static const char *const heading[] = {"north", "east", "south", "west"};
	int side = 60 + 20 * (int)(lcg(&st) % 3), k = 2 + (int)(lcg(&st) % 3), n = 0;
	double ux = side / 2 + 0.5, uy = side / 2 + 0.5, cx[4], cy[4], cs[4];
	size_t at = (size_t)snprintf(text, size, "table %d %d\n", side, side);
	while (n < k) {
		double a = (lcg(&st) % 3600) * (4 * atan(1.0)) / 1800, r = 5 + (lcg(&st) % 1500) / 100.0,
		       sd = 2 + (lcg(&st) % 300) / 100.0, turn = (lcg(&st) % 900) * (4 * atan(1.0)) / 1800;
		double x = ux + r * cos(a), y = uy + r * sin(a);
		bool ok = x > 5 && y > 5 && x < side - 6 && y < side - 6 && hypot(x - ux, y - uy) > sd / 1.4 + 2;
		for (int j = 0; j < n && ok; j++)
			ok = hypot(x - cx[j], y - cy[j]) > (sd + cs[j]) / 1.4 + 2;
		if (!ok)
			continue;
		cx[n] = x, cy[n] = y, cs[n] = sd;
		at += (size_t)snprintf(text + at, size - at, "object o%d %c", n, "ACDE"[n]);
		static const double corner[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
		for (int c = 0; c < 4; c++) {
			double px = corner[c][0] * sd / 2, py = corner[c][1] * sd / 2;
			at += (size_t)snprintf(text + at, size - at, " %.3f %.3f", x + cos(turn) * px - sin(turn) * py,
			                       y + sin(turn) * px + cos(turn) * py);
		}
		at += (size_t)snprintf(text + at, size - at, "\n");
		n++;
	}
	snprintf(text + at, size - at, "utak %.1f %.1f %s\n", ux, uy, heading[lcg(&st) % 4]);
}

/* Exact motion on open floor: a move nothing stopped, from the true square, leaves
 * the belief on the true square (the simulator's, the oracle): the disparity never
 * "corrects" it off. Long legs of up to 12 squares each way (the controller's
 * longest, CONTROLLER_LONG_LEG) carry the fovea onto squares seen only in 4 x 4
 * cells, where a zero cell may hide one square of a slanted square: in
 * tests/worlds/coarse-zero-slack.w that one foveal cell once moved Utak's belief
 * 2.24 squares off a move nothing stopped (tests/golden/coarse-zero-slack.out). That
 * world and 40 generated ones, 12 moves each. A move that halts against an object
 * (one halting more than two squares short) must still be found: the belief moves
 * off the prediction. */
TEST_CASE(worldmodel_exact_moves_never_misplaced)
{
	int free_moves = 0, wrong = 0, halts = 0, halts_exact = 0, halts_short = 0, halts_found = 0,
	    corrected = 0;
	for (uint32_t seed = 0; seed <= 40; seed++) {
		char text[1024];
		if (seed == 0) {
			const char *w = read_file("tests/worlds/coarse-zero-slack.w");
			TEST_CHECK(w != NULL && strlen(w) < sizeof text);
			snprintf(text, sizeof text, "%.1000s", w ? w : "");
		} else {
			open_floor(seed, text, sizeof text);
		}
		Sim s;
		WorldModel m;
		sim_start(&s, &m, text);
		uint32_t st = seed * 40503u + 7;
		for (int i = 0; i < 12; i++) {
			MotorCommand cmd = {.kind = MOTOR_MOVE};
			if (seed == 0 && i == 0)
				cmd.dx = 12; /* the leg that was misplaced */
			else
				cmd.dx = (int)(lcg(&st) % 25) - 12, cmd.dy = (int)(lcg(&st) % 25) - 12;
			Vec2 before = belief_error(&s, &m);
			MotorOutcome out;
			motion_execute(&s.w, &s.t, &cmd, &out);
			Impression imp;
			retina_sense(&s.w, &s.t, &imp);
			worldmodel_accommodate(&m, &cmd, &imp);
			Vec2 err = belief_error(&s, &m);
			corrected += m.report.corrected;
			if (out.halted) {
				/* Found: a halt well short of the prediction moves the belief
				 * (along a straight wall or the verge the eye cannot tell
				 * exactly where he stopped, so not always onto the true square). */
				halts++;
				halts_exact += err.x == 0 && err.y == 0;
				if (before.x == 0 && before.y == 0 && out.done < out.asked - 2) {
					halts_short++;
					halts_found += m.report.corrected;
				}
			} else if (before.x == 0 && before.y == 0) {
				free_moves++;
				if (err.x > 0 || err.y > 0) {
					fprintf(stderr, "  seed %u move %d (%.0f, %.0f): misplaced by (%.0f, %.0f)\n",
					        (unsigned)seed, i, cmd.dx, cmd.dy, err.x, err.y);
					wrong++;
				}
			}
		}
		sim_end(&s, &m);
	}
	printf("  open floor, exact motion: %d moves free from the true square, %d misplaced; %d halted, "
	       "%d of them on the true square after; of the %d halted over 2 short from it, %d found; "
	       "%d corrections in all\n",
	       free_moves, wrong, halts, halts_exact, halts_short, halts_found, corrected);
	TEST_CHECK(wrong == 0);
	TEST_CHECK(halts_found * 10 >= halts_short * 9);
}

int main(void)
{
	TEST_RUN(worldmodel_default_model);
	TEST_RUN(worldmodel_first_impression_places_utak);
	TEST_RUN(worldmodel_motion_error_estimated);
	TEST_RUN(worldmodel_same_field_same_model);
	TEST_RUN(worldmodel_room_walk_outlines);
	TEST_RUN(worldmodel_disparity_corrects_wrong_belief);
	TEST_RUN(worldmodel_halted_move_found);
	TEST_RUN(worldmodel_long_moves_cost_what_is_in_sight);
	TEST_RUN(worldmodel_held_object_follows);
	TEST_RUN(worldmodel_push_halted_at_wall);
	TEST_RUN(worldmodel_noisy_pushes_keep_track);
	TEST_RUN(worldmodel_push_into_verge_halts);
	TEST_RUN(worldmodel_slanted_push_into_verge);
	TEST_RUN(worldmodel_halted_at_coarse_wall);
	TEST_RUN(worldmodel_coarse_thin_wall_kept);
	TEST_RUN(worldmodel_random_walks_stay_close);
	TEST_RUN(worldmodel_slack_of_coarse_levels);
	TEST_RUN(worldmodel_exact_moves_never_misplaced);
	return TEST_EXIT();
}
