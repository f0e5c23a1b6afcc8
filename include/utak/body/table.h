/* table.h - the TABLE: the digital representation of the tabletop (paper 2.1). SIMULATOR SIDE.
 *
 * A W x H array with one entry per square, flat and row-major (square (x, y) is
 * owner[y * w + x], y = 0 the south row). Each entry says who claims the square:
 * TABLE_FLOOR, TABLE_VERGE (the verge and the walls, colour B) or object k as
 * k + 1. Utak is not stored: he is a point, and his square is the one that holds
 * it (utak(5), THE DIGITAL REPRESENTATION).
 *
 * INVARIANT (table_validate): every object's squares are exactly its projection;
 * no square is claimed twice; no object square is outside the verge. */
#ifndef UTAK_TABLE_H
#define UTAK_TABLE_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/base/diag.h"
#include "utak/body/world.h"

enum { TABLE_FLOOR = -1, TABLE_VERGE = 0 };

typedef struct Table {
	int32_t w, h;
	int16_t *owner; /* w * h squares: TABLE_FLOOR, TABLE_VERGE, or object index + 1 */
} Table;

/* table_build(t, w, d): projects the verge, walls and objects of w. Fails (-1,
 * with d naming the world file's line) when objects overlap each other or the
 * verge, or when Utak's square is claimed. */
int table_build(Table *t, const World *w, Diag *d);
void table_free(Table *t);

/* table_owner(t, x, y): who claims square (x, y); squares off the TABLE are verge. */
static inline int32_t table_owner(const Table *t, int32_t x, int32_t y)
{
	if (x < 0 || y < 0 || x >= t->w || y >= t->h)
		return TABLE_VERGE;
	return t->owner[(int64_t)y * t->w + x];
}

/* table_square_of(p): the square holding point p (a point on a grid line belongs
 * to the square north or east of it). */
void table_square_of(Vec2 p, int32_t *x, int32_t *y);

/* table_colour(t, w, x, y): '.', 'B' or the object's colour letter. */
char table_colour(const Table *t, const World *w, int32_t x, int32_t y);

/* table_clear_object / table_stamp_object: remove object k's squares, or claim the
 * squares of polygon p for it. table_fits(t, p, k): every square of p is floor or
 * already object k's. */
void table_clear_object(Table *t, const Polygon *p, int32_t k);
void table_stamp_object(Table *t, const Polygon *p, int32_t k);
bool table_fits(const Table *t, const Polygon *p, int32_t k);
/* table_conflict(t, p, k, &x, &y): the first square (in row order) of p's
 * projection claimed by someone other than object k, and who claims it; TABLE_FLOOR
 * when none. Parts of p off the TABLE conflict with the verge. */
int32_t table_conflict(const Table *t, const Polygon *p, int32_t k, int32_t *x, int32_t *y);

/* Utak's point is inside an object only when it is inside by more than TABLE_TOUCH
 * squares. He often stands exactly on an object's edge (a move halts there); a
 * turn rotates the held object about his point, which keeps him on the edge in
 * exact arithmetic, but rounding may carry the edge past him by ~1e-15. Without
 * this tolerance that made him "inside": stuck for good, and his -o world
 * unreadable. Far below anything a world file or a motion can mean. */
#define TABLE_TOUCH 1e-9
/* table_point_inside(p, q): q is inside p and farther than TABLE_TOUCH from its edges. */
bool table_point_inside(const Polygon *p, Vec2 q);

/* table_dump(t, w, f): H lines of exactly W characters, north row first: '.'
 * floor, the colour letter of an object, 'B' verge, '@' Utak. */
void table_dump(const Table *t, const World *w, FILE *f);

/* table_validate(t, w, why, size): the invariant above, Utak's square not verge
 * and his point inside no object; false with a reason when it fails. */
bool table_validate(const Table *t, const World *w, char *why, size_t size);

#endif
