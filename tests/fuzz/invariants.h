/* invariants.h - the simulator's invariants, checked from outside the simulator
 * (paper 2.1: "objects never overlap and never leave the verge").
 *
 * Shared by the whole-run fuzz harness (fuzz_run.c) and the property test
 * (tests/unit/test_invariants.c). table_validate() is table.c checking itself;
 * this file checks again without table.c: it rebuilds the TABLE from the
 * Cartesian World with geom_project alone and compares owners square by square,
 * and it checks what the TABLE cannot see: shapes keep their edge lengths and
 * area, and only the held object moves.
 *
 * MEMORY: inv_rebuild uses a scratch array of w x h owners, allocated per call. */
#ifndef UTAK_TEST_INVARIANTS_H
#define UTAK_TEST_INVARIANTS_H

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/geom.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

/* Rounding in a rotation grows with the coordinates: a relative tolerance, loose
 * enough for many turns on a large TABLE, tight enough that any real change of
 * shape (a wrong vertex, a scaled polygon) shows. */
#define INV_REL_TOL 1e-9

typedef struct InvRebuild {
	int16_t *owner;		/* w x h, row-major, as Table.owner */
	int32_t w;
	int16_t who;		/* the owner being stamped */
	int16_t clash;		/* an owner found under it, or TABLE_FLOOR */
	int32_t cx, cy;		/* ... and where */
} InvRebuild;

static inline void inv_span_set(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	InvRebuild *r = ctx;
	for (int32_t x = x0; x <= x1; x++)
		r->owner[(int64_t)y * r->w + x] = r->who;
}

/* inv_span_claim: stamps an object's span, noting the first square already owned. */
static inline void inv_span_claim(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	InvRebuild *r = ctx;
	for (int32_t x = x0; x <= x1; x++) {
		int16_t *o = &r->owner[(int64_t)y * r->w + x];
		if (*o != TABLE_FLOOR && r->clash == TABLE_FLOOR) {
			r->clash = *o;
			r->cx = x;
			r->cy = y;
		}
		*o = r->who;
	}
}

/* inv_rebuild(w, owner, why, size): the TABLE of world w computed from scratch:
 * verge outside the outline, walls, then each object, which must find only floor
 * under it and must lie on the TABLE. False, with a reason, when it does not. */
static inline bool inv_rebuild(const World *w, int16_t *owner, char *why, size_t size)
{
	for (int64_t i = 0; i < (int64_t)w->w * w->h; i++)
		owner[i] = TABLE_FLOOR;
	InvRebuild r = {.owner = owner, .w = w->w, .who = TABLE_VERGE, .clash = TABLE_FLOOR};
	geom_project_outside(&w->verge, w->w, w->h, inv_span_set, &r);
	for (int32_t i = 0; i < w->wall_count; i++)
		geom_project(&w->walls[i], w->w, w->h, inv_span_set, &r);
	for (int32_t k = 0; k < w->object_count; k++) {
		const Polygon *p = &w->objects[k].shape;
		Box b = geom_polygon_box(p);
		if (b.lo.x < 0 || b.lo.y < 0 || b.hi.x > w->w || b.hi.y > w->h) {
			snprintf(why, size, "object '%s' reaches off the TABLE", w->objects[k].name);
			return false;
		}
		r.who = (int16_t)(k + 1);
		geom_project(p, w->w, w->h, inv_span_claim, &r);
		if (r.clash != TABLE_FLOOR) {
			snprintf(why, size, "object '%s' meets %s%s%s at square (%d, %d)", w->objects[k].name,
				 r.clash == TABLE_VERGE ? "the verge" : "object '",
				 r.clash == TABLE_VERGE ? "" : w->objects[r.clash - 1].name,
				 r.clash == TABLE_VERGE ? "" : "'", (int)r.cx, (int)r.cy);
			return false;
		}
	}
	return true;
}

static inline double inv_edge(const Polygon *p, int32_t i)
{
	Vec2 a = p->v[i], b = p->v[(i + 1) % p->count];
	return hypot(b.x - a.x, b.y - a.y);
}

static inline bool inv_near(double a, double b) { return fabs(a - b) <= INV_REL_TOL * (1 + fabs(a) + fabs(b)); }

/* inv_check(w, t, orig, prev, held, why, size): every invariant after one motor
 * command. orig: each object's shape when the world was loaded; prev: before the
 * command; held: the object held during it (-1 none), the only one that may move. */
static inline bool inv_check(const World *w, const Table *t, const Polygon *orig, const Polygon *prev,
		      int32_t held, char *why, size_t size)
{
	if (!table_validate(t, w, why, size))
		return false;
	if (t->w != w->w || t->h != w->h) {
		snprintf(why, size, "TABLE is %d x %d, world %d x %d", (int)t->w, (int)t->h, (int)w->w,
			 (int)w->h);
		return false;
	}
	int16_t *owner = malloc(sizeof *owner * (size_t)w->w * (size_t)w->h);
	if (!owner)
		abort();
	bool ok = inv_rebuild(w, owner, why, size);
	for (int64_t i = 0; ok && i < (int64_t)w->w * w->h; i++)
		if (owner[i] != t->owner[i]) {
			snprintf(why, size, "square (%d, %d) is %d in the TABLE, %d rebuilt from the world",
				 (int)(i % w->w), (int)(i / w->w), (int)t->owner[i], (int)owner[i]);
			ok = false;
		}
	free(owner);
	if (!ok)
		return false;
	if (!(w->utak.x >= 0 && w->utak.y >= 0 && w->utak.x < w->w && w->utak.y < w->h)) {
		snprintf(why, size, "Utak (%g, %g) is off the TABLE", w->utak.x, w->utak.y);
		return false;
	}
	for (int32_t k = 0; k < w->object_count; k++) {
		const Polygon *p = &w->objects[k].shape;
		const char *name = w->objects[k].name;
		if (p->count != orig[k].count) {
			snprintf(why, size, "object '%s' has %d vertices, had %d", name, (int)p->count,
				 (int)orig[k].count);
			return false;
		}
		if (k != held && memcmp(p, &prev[k], sizeof *p) != 0) {
			snprintf(why, size, "object '%s' moved, but Utak did not hold it", name);
			return false;
		}
		if (!inv_near(geom_polygon_area(p), geom_polygon_area(&orig[k]))) {
			snprintf(why, size, "object '%s' has area %.17g, had %.17g", name, geom_polygon_area(p),
				 geom_polygon_area(&orig[k]));
			return false;
		}
		for (int32_t i = 0; i < p->count; i++)
			if (!inv_near(inv_edge(p, i), inv_edge(&orig[k], i))) {
				snprintf(why, size, "object '%s' edge %d has length %.17g, had %.17g", name, (int)i,
					 inv_edge(p, i), inv_edge(&orig[k], i));
				return false;
			}
	}
	return true;
}

#endif
