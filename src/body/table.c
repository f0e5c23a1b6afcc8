/* table.c - the TABLE, projection of the Cartesian representation onto the digital one
 * (paper 2.1). SIMULATOR SIDE.
 *
 * The projection itself is geom_project (geom.c); this file keeps the array of
 * owners, finds overlaps when a world is loaded, and draws the TABLE. */
#include "utak/body/table.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

void table_square_of(Vec2 p, int32_t *x, int32_t *y)
{
	*x = (int32_t)floor(p.x);
	*y = (int32_t)floor(p.y);
}

/* ---- span visitors ---------------------------------------------------------- */

typedef struct SpanCtx {
	Table *t;
	int16_t who;		/* the owner to stamp or clear */
} SpanCtx;

static void span_stamp(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	SpanCtx *c = ctx;
	int16_t *row = c->t->owner + (int64_t)y * c->t->w;
	for (int32_t x = x0; x <= x1; x++)
		row[x] = c->who;
}

static void span_clear(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	SpanCtx *c = ctx;
	int16_t *row = c->t->owner + (int64_t)y * c->t->w;
	for (int32_t x = x0; x <= x1; x++)
		if (row[x] == c->who)
			row[x] = TABLE_FLOOR;
}

typedef struct TestCtx {
	const Table *t;
	int16_t who;		/* the owner allowed */
	int16_t found;		/* the first conflicting owner, or TABLE_FLOOR */
	int32_t fx, fy;		/* ... and its square */
} TestCtx;

/* span_test: records the first square claimed by someone other than c->who. */
static void span_test(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	TestCtx *c = ctx;
	if (c->found != TABLE_FLOOR)
		return;
	const int16_t *row = c->t->owner + (int64_t)y * c->t->w;
	for (int32_t x = x0; x <= x1; x++)
		if (row[x] != TABLE_FLOOR && row[x] != c->who) {
			c->found = row[x];
			c->fx = x;
			c->fy = y;
			return;
		}
}

/* A polygon reaching past the TABLE's edge claims squares that do not exist: the
 * eye sees those as verge, so for collisions they are verge too. */
static bool polygon_leaves_table(const Table *t, const Polygon *p)
{
	Box b = geom_polygon_box(p);
	return b.lo.x < 0 || b.lo.y < 0 || b.hi.x > t->w || b.hi.y > t->h;
}

void table_clear_object(Table *t, const Polygon *p, int32_t k)
{
	SpanCtx c = {.t = t, .who = (int16_t)(k + 1)};
	geom_project(p, t->w, t->h, span_clear, &c);
}

void table_stamp_object(Table *t, const Polygon *p, int32_t k)
{
	SpanCtx c = {.t = t, .who = (int16_t)(k + 1)};
	geom_project(p, t->w, t->h, span_stamp, &c);
}

int32_t table_conflict(const Table *t, const Polygon *p, int32_t k, int32_t *x, int32_t *y)
{
	*x = *y = -1;
	if (polygon_leaves_table(t, p))
		return TABLE_VERGE;
	TestCtx c = {.t = t, .who = (int16_t)(k + 1), .found = TABLE_FLOOR};
	geom_project(p, t->w, t->h, span_test, &c);
	*x = c.fx;
	*y = c.fy;
	return c.found;
}

bool table_fits(const Table *t, const Polygon *p, int32_t k)
{
	int32_t x, y;
	return table_conflict(t, p, k, &x, &y) == TABLE_FLOOR;
}

bool table_point_inside(const Polygon *p, Vec2 q)
{
	if (!geom_point_in_polygon(p, q))
		return false;
	for (int32_t i = 0; i < p->count; i++)
		if (geom_point_segment_distance(q, p->v[i], p->v[(i + 1) % p->count]) <= TABLE_TOUCH)
			return false;
	return true;
}

/* ---- building --------------------------------------------------------------- */

int table_build(Table *t, const World *w, Diag *d)
{
	t->w = w->w;
	t->h = w->h;
	t->owner = util_alloc((size_t)w->w * (size_t)w->h, sizeof *t->owner);
	for (int64_t i = 0; i < (int64_t)w->w * w->h; i++)
		t->owner[i] = TABLE_FLOOR;
	SpanCtx c = {.t = t, .who = TABLE_VERGE};
	geom_project_outside(&w->verge, t->w, t->h, span_stamp, &c);
	for (int32_t i = 0; i < w->wall_count; i++)
		geom_project(&w->walls[i], t->w, t->h, span_stamp, &c);
	for (int32_t k = 0; k < w->object_count; k++) {
		const WorldObject *o = &w->objects[k];
		TestCtx test = {.t = t, .who = (int16_t)(k + 1), .found = TABLE_FLOOR};
		geom_project(&o->shape, t->w, t->h, span_test, &test);
		if (test.found == TABLE_VERGE) {
			diag_set(d, w->file, o->line, 1,
				 "object '%s' overlaps the verge or a wall at square (%d, %d)", o->name,
				 (int)test.fx, (int)test.fy);
			table_free(t);
			return -1;
		}
		if (test.found != TABLE_FLOOR) {
			const WorldObject *other = &w->objects[test.found - 1];
			diag_set(d, w->file, o->line, 1,
				 "object '%s' overlaps object '%s' (line %d) at square (%d, %d)", o->name,
				 other->name, (int)other->line, (int)test.fx, (int)test.fy);
			table_free(t);
			return -1;
		}
		table_stamp_object(t, &o->shape, k);
	}
	int32_t ux, uy;
	table_square_of(w->utak, &ux, &uy);
	int32_t who = table_owner(t, ux, uy);
	/* He may share his square with an object his point is outside of: one he
	 * pushed or turned and let go beside him (motion.c), which -o writes. */
	if (who > 0 && !table_point_inside(&w->objects[who - 1].shape, w->utak))
		who = TABLE_FLOOR;
	if (who != TABLE_FLOOR) {
		diag_set(d, w->file, w->utak_line, 1, "Utak's square (%d, %d) is %s", (int)ux, (int)uy,
			 who == TABLE_VERGE ? "in the verge or a wall" : "inside an object");
		if (who > 0) {
			size_t n = strlen(d->msg);
			snprintf(d->msg + n, sizeof d->msg - n, " ('%s')", w->objects[who - 1].name);
		}
		table_free(t);
		return -1;
	}
	return 0;
}

void table_free(Table *t)
{
	free(t->owner);
	t->owner = NULL;
}

char table_colour(const Table *t, const World *w, int32_t x, int32_t y)
{
	int32_t who = table_owner(t, x, y);
	if (who == TABLE_FLOOR)
		return '.';
	if (who == TABLE_VERGE)
		return 'B';
	return w->objects[who - 1].colour;
}

void table_dump(const Table *t, const World *w, FILE *f)
{
	int32_t ux, uy;
	table_square_of(w->utak, &ux, &uy);
	char *line = util_alloc((size_t)t->w + 2, 1);
	for (int32_t y = t->h - 1; y >= 0; y--) {
		for (int32_t x = 0; x < t->w; x++)
			line[x] = (x == ux && y == uy) ? '@' : table_colour(t, w, x, y);
		line[t->w] = '\n';
		fwrite(line, 1, (size_t)t->w + 1, f);
	}
	free(line);
}

/* ---- the invariant ------------------------------------------------------------ */

typedef struct CountCtx {
	const Table *t;
	int16_t who;
	int64_t mine, other;	/* squares of the projection owned by who / by anyone else */
} CountCtx;

static void span_count(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	CountCtx *c = ctx;
	const int16_t *row = c->t->owner + (int64_t)y * c->t->w;
	for (int32_t x = x0; x <= x1; x++) {
		if (row[x] == c->who)
			c->mine++;
		else
			c->other++;
	}
}

bool table_validate(const Table *t, const World *w, char *why, size_t size)
{
	/* Each object owns exactly its projection: every projected square is its own,
	 * and it owns no square outside the projection (counts agree). */
	int64_t *owned = util_alloc((size_t)w->object_count + 1, sizeof *owned);
	for (int64_t i = 0; i < (int64_t)t->w * t->h; i++)
		if (t->owner[i] > 0)
			owned[t->owner[i]]++;
	bool ok = true;
	for (int32_t k = 0; k < w->object_count && ok; k++) {
		const Polygon *p = &w->objects[k].shape;
		CountCtx c = {.t = t, .who = (int16_t)(k + 1)};
		geom_project(p, t->w, t->h, span_count, &c);
		if (polygon_leaves_table(t, p)) {
			snprintf(why, size, "object '%s' reaches off the TABLE", w->objects[k].name);
			ok = false;
		} else if (c.other != 0) {
			snprintf(why, size, "object '%s': %lld of its squares are claimed by another",
				 w->objects[k].name, (long long)c.other);
			ok = false;
		} else if (c.mine != owned[k + 1]) {
			snprintf(why, size, "object '%s' owns %lld squares, its projection has %lld",
				 w->objects[k].name, (long long)owned[k + 1], (long long)c.mine);
			ok = false;
		}
	}
	free(owned);
	if (!ok)
		return false;
	int32_t ux, uy;
	table_square_of(w->utak, &ux, &uy);
	if (table_owner(t, ux, uy) == TABLE_VERGE) {
		snprintf(why, size, "Utak's square (%d, %d) is verge", (int)ux, (int)uy);
		return false;
	}
	/* His square may share an object's squares only while he touches it (he
	 * pushed it, then let go): his point itself is never inside an object. */
	for (int32_t k = 0; k < w->object_count; k++)
		if (table_point_inside(&w->objects[k].shape, w->utak)) {
			snprintf(why, size, "Utak's point is inside object '%s'", w->objects[k].name);
			return false;
		}
	return true;
}
