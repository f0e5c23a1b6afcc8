/* judge.c - the ground-truth verdict on a task (paper 2.3). SIMULATOR SIDE: it reads
 * the real world, which the controller never does. The rules are in judge.h. */
#include "utak/body/judge.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/plan/pathgraph.h"
#include "utak/mind/rooms.h"
#include "utak/mind/shape.h"
#include "utak/plan/skeleton.h"
#include "utak/base/util.h"

/* Squares of a TABLE read by the current judge_task's own passes: its cost, which
 * judge_squares_read reports to tests and benchmarks. */
static int64_t judge_read;

int64_t judge_squares_read(void)
{
	return judge_read;
}

/* The fixed space and its rooms. The pathgraph borrows the grid and skeleton. */
typedef struct Fixed {
	Grid grid;
	Skeleton skeleton;
	Pathgraph pathgraph;
	Rooms rooms;
} Fixed;

static void fixed_build(Fixed *f, const Table *t)
{
	grid_init(&f->grid, t->w, t->h, GRID_FREE);
	judge_read += (int64_t)t->w * t->h;
	for (int64_t i = 0; i < (int64_t)t->w * t->h; i++)
		if (t->owner[i] == TABLE_VERGE)
			f->grid.cells[i] = GRID_BLOCKED;
	skeleton_init(&f->skeleton);
	pathgraph_init(&f->pathgraph);
	rooms_init(&f->rooms);
	skeleton_compute(&f->skeleton, &f->grid);
	pathgraph_build(&f->pathgraph, &f->skeleton, &f->grid);
	rooms_find(&f->rooms, &f->pathgraph);
}

static void fixed_free(Fixed *f)
{
	rooms_free(&f->rooms);
	pathgraph_free(&f->pathgraph);
	skeleton_free(&f->skeleton);
	grid_free(&f->grid);
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

/* object_shape(t, o, k): the shape of object k, whose squares are o; it reads only
 * o's containing rectangle. */
static Shape object_shape(const Table *t, const ObjectSquares *o, int32_t k)
{
	if (o->count == 0)
		return SHAPE_NONE;
	int32_t w = o->x1 - o->x0 + 1, h = o->y1 - o->y0 + 1;
	uint8_t *mask = util_alloc((size_t)w * (size_t)h, 1);
	judge_read += (int64_t)w * h;
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++)
			mask[y * w + x] = t->owner[(int64_t)(y + o->y0) * t->w + x + o->x0] == k + 1;
	Shape s = shape_classify(mask, w, h);
	free(mask);
	return s;
}

/* By distance from Utak, then by index: the order in which target looks. */
typedef struct Candidate {
	double d;
	int32_t k;
} Candidate;

static int candidate_cmp(const void *pa, const void *pb)
{
	const Candidate *a = pa, *b = pb;
	if (a->d != b->d)
		return a->d < b->d ? -1 : 1;
	return (a->k > b->k) - (a->k < b->k);
}

/* target(start, table0, shape): the object of that shape nearest Utak at the start
 * (the lowest index among equally near ones).
 * COMPLEXITY: one pass of the TABLE, a sort of the objects by distance, and the
 * shapes of the nearest ones only until one has the shape asked for (each reads its
 * containing rectangle). */
static int32_t target(const World *start, const Table *t0, Shape shape)
{
	int32_t n = start->object_count, best = -1;
	ObjectSquares *o = objects_squares(t0, n);
	Candidate *c = util_alloc((size_t)(n > 0 ? n : 1), sizeof *c);
	int32_t m = 0;
	for (int32_t k = 0; k < n; k++)
		if (o[k].count)
			c[m++] = (Candidate){hypot(o[k].cx - start->utak.x, o[k].cy - start->utak.y), k};
	qsort(c, (size_t)m, sizeof *c, candidate_cmp);
	for (int32_t i = 0; i < m && best < 0; i++)
		if (object_shape(t0, &o[c[i].k], c[i].k) == shape)
			best = c[i].k;
	free(c);
	free(o);
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
	Fixed f;
	fixed_build(&f, table);
	Heading h = start->heading;
	const char *shape = task_shape_name(task->shape);
	int32_t sx, sy, ex, ey;
	table_square_of(start->utak, &sx, &sy);
	table_square_of(end->utak, &ex, &ey);
	int32_t start_room = rooms_at(&f.rooms, sx, sy), end_room = rooms_at(&f.rooms, ex, ey);
	bool ok = false;
	int32_t k = task->shape == SHAPE_NONE ? -1 : target(start, &t0, task->shape);
	if (task->shape != SHAPE_NONE && k < 0) {
		snprintf(why, size, "there is no %s in this world", shape);
		goto done;
	}
	switch (task->kind) {
	case TASK_GO_CORNER:
	case TASK_PUSH_CORNER: {
		int64_t best = INT64_MIN;
		judge_read += (int64_t)table->w * table->h;
		for (int32_t y = 0; y < table->h; y++)
			for (int32_t x = 0; x < table->w; x++)
				if (rooms_at(&f.rooms, x, y) == start_room)
					best = fmax(best, score(h, task->corner, x, y));
		int64_t got = INT64_MIN;
		if (task->kind == TASK_GO_CORNER) {
			got = end_room == start_room ? score(h, task->corner, ex, ey) : INT64_MIN;
		} else {
			judge_read += (int64_t)table->w * table->h;
			for (int32_t y = 0; y < table->h; y++)
				for (int32_t x = 0; x < table->w; x++)
					if (table->owner[(int64_t)y * table->w + x] == k + 1 && rooms_at(&f.rooms, x, y) == start_room)
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
		ok = end_room >= 0 && end_room != start_room;
		snprintf(why, size, ok ? "Utak is in another room than he started in" : "Utak is still in the room he started in");
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
		ObjectSquares o = object_squares(&t0, start->object_count, k);
		double turns = n >= 3 ? geom_winding(trail, n, vec2(o.cx, o.cy)) : 0;
		double home = hypot(end->utak.x - start->utak.x, end->utak.y - start->utak.y);
		ok = fabs(turns) > 0.99 && home <= JUDGE_HOME;
		snprintf(why, size, "Utak's path winds %.2f times round the %s and ends %.2f from its start", fabs(turns),
			 shape, home);
		break;
	}
	case TASK_PUSH_NEXT_ROOM:
	case TASK_PUSH_THROUGH_DOOR: {
		ObjectSquares o0 = object_squares(&t0, start->object_count, k);
		int32_t from = rooms_at(&f.rooms, (int32_t)floor(o0.cx), (int32_t)floor(o0.cy)), room = -2;
		bool one_room = true;
		judge_read += (int64_t)table->w * table->h;
		for (int32_t y = 0; y < table->h; y++)
			for (int32_t x = 0; x < table->w; x++)
				if (table->owner[(int64_t)y * table->w + x] == k + 1) {
					int32_t r = rooms_at(&f.rooms, x, y);
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
		ObjectSquares o0 = object_squares(&t0, start->object_count, k), o1 = object_squares(table, start->object_count, k);
		ok = !pathgraph_segment_free(&f.grid, vec2(o0.cx, o0.cy), vec2(o1.cx, o1.cy));
		snprintf(why, size, ok ? "the %s is out of sight of where it was" : "the %s can still be seen from where it was",
			 shape);
		break;
	}
	}
done:
	fixed_free(&f);
	table_free(&t0);
	return ok;
}
