/* judge.c - the ground-truth verdict on a task (paper 2.3). SIMULATOR SIDE: it reads
 * the real world, which the controller never does. The rules are in judge.h. */
#include "utak/body/judge.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/body/judgerooms.h"
#include "utak/body/judgeshape.h"
#include "utak/base/util.h"

/* Squares of a TABLE read by the current judge_task's own passes: its cost, which
 * judge_squares_read reports to tests and benchmarks. */
static int64_t judge_read;

int64_t judge_squares_read(void)
{
	return judge_read;
}

/* box_has(b, x, y): whether square (x, y) lies in box b (x0, y0, x1, y1). */
static bool box_has(const int32_t b[4], int32_t x, int32_t y)
{
	return x >= b[0] && x <= b[2] && y >= b[1] && y <= b[3];
}

/* own(h, x, y): a TABLE square's coordinates in Utak's frame (inverse of
 * world_own_to_table), for compass scores. */
static void own(Heading h, int32_t x, int32_t y, int64_t *ox, int64_t *oy)
{
	switch (h) {
	case HEADING_NORTH:
		*ox = x, *oy = y;
		break;
	case HEADING_EAST:
		*ox = -(int64_t)y, *oy = x;
		break;
	case HEADING_SOUTH:
		*ox = -(int64_t)x, *oy = -(int64_t)y;
		break;
	case HEADING_WEST:
		*ox = y, *oy = -(int64_t)x;
		break;
	}
}

static int64_t score(Heading h, Corner k, int32_t x, int32_t y)
{
	int64_t ox = 0, oy = 0;
	own(h, x, y, &ox, &oy);
	int sx, sy;
	task_corner_signs(k, &sx, &sy);
	return sx * ox + sy * oy;
}

/* Squares of object k on the table, as a mask of its containing rectangle. */
typedef struct ObjectSquares {
	int32_t x0, y0, x1, y1;
	int64_t count;
	double cx, cy;	/* centre of its squares */
} ObjectSquares;

/* objects_squares(t, n): the squares of each of the n objects, in ONE pass of the
 * TABLE (a pass per object made a shape task's verdict cost objects x squares:
 * 5.6 s for 4096 objects on 1024 x 1024, issue 14). The caller frees the array. */
static ObjectSquares *objects_squares(const Table *t, int32_t n)
{
	ObjectSquares *o = util_alloc((size_t)(n > 0 ? n : 1), sizeof *o);
	for (int32_t k = 0; k < n; k++)
		o[k] = (ObjectSquares){t->w, t->h, -1, -1, 0, 0, 0};
	judge_read += (int64_t)t->w * t->h;
	for (int32_t y = 0; y < t->h; y++)
		for (int32_t x = 0; x < t->w; x++) {
			int32_t k = t->owner[(int64_t)y * t->w + x] - 1;
			if (k < 0 || k >= n)
				continue;
			ObjectSquares *q = &o[k];
			q->x0 = x < q->x0 ? x : q->x0;
			q->y0 = y < q->y0 ? y : q->y0;
			q->x1 = x > q->x1 ? x : q->x1;
			q->y1 = y > q->y1 ? y : q->y1;
			q->count++;
			q->cx += x + 0.5;
			q->cy += y + 0.5;
		}
	for (int32_t k = 0; k < n; k++)
		if (o[k].count) {
			o[k].cx /= (double)o[k].count;
			o[k].cy /= (double)o[k].count;
		}
	return o;
}

/* object_squares(t, n, k): object k's squares alone (one pass). */
static ObjectSquares object_squares(const Table *t, int32_t n, int32_t k)
{
	ObjectSquares *all = objects_squares(t, n), o = all[k];
	free(all);
	return o;
}

/* WHETHER A TASK CAN BE DONE AT ALL. A task that no sequence of motor commands could
 * achieve in the true world does not apply (as with no such object, or one room):
 * its failure says why and is no failure of Utak's. The tests below claim
 * impossibility only where it is certain, so they err toward "applies": every object
 * counts as space (Utak may push it away), and Utak's squares connect 8-ways while
 * what blocks connects only 4-ways (a squeeze between two squares that touch at a
 * corner is allowed him). Walls and the verge alone make a task impossible. */

/* reach(t, sx, sy): the squares Utak could ever stand on from square (sx, sy): the
 * non-verge squares 8-connected to it, as a mask of w * h bytes the caller frees.
 * COMPLEXITY: O(w h), one pass to clear and one breadth-first search. */
static uint8_t *reach(const Table *t, int32_t sx, int32_t sy)
{
	int64_t n = (int64_t)t->w * t->h;
	uint8_t *seen = util_alloc((size_t)n, 1);
	int32_t *queue = util_alloc((size_t)n, sizeof *queue);
	int64_t head = 0, tail = 0;
	judge_read += n;
	if (table_owner(t, sx, sy) != TABLE_VERGE) {
		seen[(int64_t)sy * t->w + sx] = 1;
		queue[tail++] = sy * t->w + sx;
	}
	while (head < tail) {
		int32_t i = queue[head++], x = i % t->w, y = i / t->w;
		for (int32_t dy = -1; dy <= 1; dy++)
			for (int32_t dx = -1; dx <= 1; dx++) {
				int32_t u = x + dx, v = y + dy;
				if (table_owner(t, u, v) == TABLE_VERGE || seen[(int64_t)v * t->w + u])
					continue;
				seen[(int64_t)v * t->w + u] = 1;
				queue[tail++] = v * t->w + u;
			}
	}
	free(queue);
	return seen;
}

/* object_reached(t, seen, k): whether Utak can reach object k at all: a square of
 * it lies in reach's mask (objects are space to reach, so a square of k is reached
 * exactly when a square beside it is). */
static bool object_reached(const Table *t, const uint8_t *seen, int32_t k)
{
	judge_read += (int64_t)t->w * t->h;
	for (int64_t i = 0; i < (int64_t)t->w * t->h; i++)
		if (t->owner[i] == k + 1 && seen[i])
			return true;
	return false;
}

/* island(t, k): whether object k, with the walls that touch it, stands free of the
 * TABLE's edge: the squares of k and of the verge 4-connected to them include no
 * square of the TABLE's border (beyond which all is verge). If they reach it, no
 * path of free squares can wind round k (it would have to cross them), so going
 * round it is impossible. COMPLEXITY: O(w h). */
static bool island(const Table *t, int32_t k)
{
	int64_t n = (int64_t)t->w * t->h;
	uint8_t *seen = util_alloc((size_t)n, 1);
	int32_t *queue = util_alloc((size_t)n, sizeof *queue);
	int64_t head = 0, tail = 0;
	judge_read += 2 * n;
	for (int64_t i = 0; i < n; i++)
		if (t->owner[i] == k + 1) {
			seen[i] = 1;
			queue[tail++] = (int32_t)i;
		}
	bool free_standing = true;
	static const int32_t step[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
	while (head < tail && free_standing) {
		int32_t i = queue[head++], x = i % t->w, y = i / t->w;
		if (x == 0 || y == 0 || x == t->w - 1 || y == t->h - 1) {
			free_standing = false;
			break;
		}
		for (int d = 0; d < 4; d++) {
			int32_t u = x + step[d][0], v = y + step[d][1], who = table_owner(t, u, v);
			if ((who != TABLE_VERGE && who != k + 1) || seen[(int64_t)v * t->w + u])
				continue;
			seen[(int64_t)v * t->w + u] = 1;
			queue[tail++] = v * t->w + u;
		}
	}
	free(queue);
	free(seen);
	return free_standing;
}

/* other_room_reached(f, seen, room): whether Utak can reach a square of a room other than
 * room (the rooms count objects as space, as reach does). */
static bool other_room_reached(const JudgeRooms *f, const uint8_t *seen, int32_t room)
{
	judge_read += (int64_t)f->w * f->h;
	for (int64_t i = 0; i < (int64_t)f->w * f->h; i++)
		if (seen[i] && f->room[i] >= 0 && f->room[i] != room)
			return true;
	return false;
}

/* target(start, shape): the object of that shape nearest Utak at the start, by the
 * distance from his point to the object's area centroid, named by judgeshape.h's
 * rule on its true polygon; ties to the earlier object in the world file.
 * COMPLEXITY: O(objects x vertices^2); no TABLE read. */
static int32_t target(const World *start, Shape shape)
{
	int32_t best = -1;
	double best_d = INFINITY;
	for (int32_t k = 0; k < start->object_count; k++) {
		const Polygon *p = &start->objects[k].shape;
		if (judge_shape_name(p) != shape)
			continue;
		Vec2 c = judge_shape_centroid(p);
		double d = hypot(c.x - start->utak.x, c.y - start->utak.y);
		if (d < best_d)
			best = k, best_d = d;
	}
	return best;
}

bool judge_task(const World *start, const World *end, const Table *table, const Task *task, const Vec2 *trail,
		int n, char *why, size_t size)
{
	judge_read = 0;
	Table t0;
	Diag d;
	if (table_build(&t0, start, &d)) {
		snprintf(why, size, "cannot rebuild the starting TABLE: %s", d.msg);
		return false;
	}
	JudgeRooms f;
	judge_rooms_find(&f, table);
	judge_read += (int64_t)table->w * table->h;
	Heading h = start->heading;
	const char *shape = task_shape_name(task->shape);
	int32_t sx, sy, ex, ey;
	table_square_of(start->utak, &sx, &sy);
	table_square_of(end->utak, &ex, &ey);
	int32_t start_room = judge_rooms_nearest(&f, sx, sy), end_room = judge_rooms_at(&f, ex, ey);
	bool ok = false;
	int32_t k = task->shape == SHAPE_NONE ? -1 : target(start, task->shape);
	if (task->shape != SHAPE_NONE && k < 0) {
		snprintf(why, size, "there is no %s in this world", shape);
		goto done;
	}
	uint8_t *seen = reach(table, sx, sy);
	if (k >= 0 && !object_reached(table, seen, k)) {
		snprintf(why, size, "the task does not apply: the %s cannot be reached (walls close it off from Utak's "
			 "start)", shape);
		free(seen);
		goto done;
	}
	switch (task->kind) {
	case TASK_GO_CORNER:
	case TASK_PUSH_CORNER: {
		int64_t best = INT64_MIN;
		judge_read += (int64_t)table->w * table->h;
		for (int32_t y = 0; y < table->h; y++)
			for (int32_t x = 0; x < table->w; x++)
				if (judge_rooms_at(&f, x, y) == start_room)
					best = fmax(best, score(h, task->corner, x, y));
		int64_t got = INT64_MIN;
		if (task->kind == TASK_GO_CORNER) {
			got = end_room == start_room ? score(h, task->corner, ex, ey) : INT64_MIN;
		} else {
			judge_read += (int64_t)table->w * table->h;
			for (int32_t y = 0; y < table->h; y++)
				for (int32_t x = 0; x < table->w; x++)
					if (table->owner[(int64_t)y * table->w + x] == k + 1 && judge_rooms_at(&f, x, y) == start_room)
						got = fmax(got, score(h, task->corner, x, y));
		}
		ok = got != INT64_MIN && got >= best - JUDGE_SLACK;
		if (got == INT64_MIN)
			snprintf(why, size, "%s%s is not in the room Utak started in",
				 task->kind == TASK_GO_CORNER ? "Utak" : "the ", task->kind == TASK_GO_CORNER ? "" : shape);
		else
			snprintf(why, size, "%s %s %lld short of the %s (slack %d)",
				 task->kind == TASK_GO_CORNER ? "Utak" : "the", task->kind == TASK_GO_CORNER ? "is" : shape,
				 (long long)(best - got), task_corner_name(task->corner), JUDGE_SLACK);
		break;
	}
	case TASK_GO_NEXT_ROOM:
		if (f.count < 2) {
			snprintf(why, size, "the task does not apply: there is no next room (one room)");
			break;
		}
		if (!other_room_reached(&f, seen, start_room)) {
			snprintf(why, size, "the task does not apply: no other room can be reached (walls close Utak's "
				 "room)");
			break;
		}
		ok = end_room >= 0 && end_room != start_room;
		snprintf(why, size, "%s", ok ? "Utak is in another room than he started in"
			 : end_room == JUDGE_ROOM_NONE ? "Utak stands in a doorway, not wholly in the next room"
			 : "Utak is still in the room he started in");
		break;
	case TASK_GO_SHAPE:
		for (int i = 0; i < 8 && !ok; i++) {
			int32_t x, y;
			world_touch_square(end, i, &x, &y);
			ok = table_owner(table, x, y) == k + 1;
		}
		snprintf(why, size, ok ? "Utak touches the %s" : "Utak does not touch the %s", shape);
		break;
	case TASK_GO_ROUND: {
		if (!island(table, k)) {
			snprintf(why, size, "the task does not apply: the %s and the walls it touches reach the TABLE's "
				 "edge, so no path can go round it", shape);
			break;
		}
		Vec2 c = judge_shape_centroid(&start->objects[k].shape);
		double turns = n >= 3 ? geom_winding(trail, n, c) : 0;
		double home = hypot(end->utak.x - start->utak.x, end->utak.y - start->utak.y);
		ok = fabs(turns) > 0.99 && home <= JUDGE_HOME;
		snprintf(why, size, "Utak's path winds %.2f times round the %s and ends %.2f from its start", fabs(turns),
			 shape, home);
		break;
	}
	case TASK_PUSH_NEXT_ROOM:
	case TASK_PUSH_THROUGH_DOOR: {
		ObjectSquares o0 = object_squares(&t0, start->object_count, k);
		int32_t from = judge_rooms_nearest(&f, (int32_t)floor(o0.cx), (int32_t)floor(o0.cy)), room = -2;
		bool one_room = true;
		judge_read += (int64_t)table->w * table->h;
		for (int32_t y = 0; y < table->h; y++)
			for (int32_t x = 0; x < table->w; x++)
				if (table->owner[(int64_t)y * table->w + x] == k + 1) {
					int32_t r = judge_rooms_at(&f, x, y);
					if (room == -2)
						room = r;
					else if (r != room)
						one_room = false;
				}
		ok = one_room && room >= 0 && room != from;
		snprintf(why, size, ok ? "the %s is wholly in another room" : "the %s is not wholly in another room", shape);
		break;
	}
	case TASK_PUSH_AROUND_CORNER: {
		Vec2 c0 = judge_shape_centroid(&start->objects[k].shape);
		int32_t cx, cy;
		table_square_of(c0, &cx, &cy);
		JudgeBend b;
		if (!judge_rooms_bend(&f, judge_rooms_nearest(&f, cx, cy), &b)) {
			snprintf(why, size, "the task does not apply: there is no corner to push round here (the %s did not "
				 "start in an L-shaped corridor)", shape);
			break;
		}
		/* The leg it started in (-1: in the bend), and the other. */
		int from = box_has(b.bend, cx, cy) ? -1 : box_has(b.leg[0], cx, cy) ? 0 : 1;
		bool past = true, any = false;
		judge_read += (int64_t)table->w * table->h;
		for (int32_t y = 0; y < table->h; y++)
			for (int32_t x = 0; x < table->w; x++)
				if (table->owner[(int64_t)y * table->w + x] == k + 1) {
					any = true;
					bool leg = from < 0 ? box_has(b.leg[0], x, y) || box_has(b.leg[1], x, y)
							    : box_has(b.leg[1 - from], x, y);
					past = past && leg && !box_has(b.bend, x, y);
				}
		ok = any && past;
		snprintf(why, size, ok ? "the %s is wholly in the other leg of the corridor, past the bend"
				       : "the %s is not wholly in the other leg of the corridor, past the bend", shape);
		break;
	}
	}
	free(seen);
done:
	judge_rooms_free(&f);
	table_free(&t0);
	return ok;
}
