/* world.h - the physical world of TABLETOP and its world file (paper 2.1). SIMULATOR SIDE.
 *
 * The Cartesian representation of everything on the tabletop: the TABLE's size,
 * the verge outline, the fixed walls, the movable objects and Utak's point and
 * heading. Coordinates in TABLE squares, x east, y north, origin at the TABLE's
 * south-west corner. The world file's grammar is in man/utak.5.
 *
 * Only the simulator and the final ground-truth check may include this header:
 * the controller knows the world through impressions only (impression.h). */
#ifndef UTAK_WORLD_H
#define UTAK_WORLD_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/base/diag.h"
#include "utak/base/geom.h"

/* Limits of the world file, each documented in man/utak.5. */
enum {
	WORLD_MAX_SIDE = 8192,		/* a TABLE side, in squares */
	WORLD_MAX_SQUARES = 1 << 25,	/* W x H: 32 Mi squares, 64 MiB of TABLE */
	WORLD_MAX_OBJECTS = 4096,	/* objects; also walls */
	WORLD_MAX_NAME = 31,		/* characters in an object's name */
	WORLD_MAX_LINE = 4096,		/* characters in one line */
	WORLD_MAX_BYTES = 16 << 20,	/* a whole world file */
};

/* Utak's heading: one of the TABLE's four directions, fixed for the whole run. */
typedef enum Heading { HEADING_NORTH, HEADING_EAST, HEADING_SOUTH, HEADING_WEST } Heading;

typedef struct WorldObject {
	char name[WORLD_MAX_NAME + 1];
	char colour;		/* 'A'..'Z', never 'B' */
	Polygon shape;		/* TABLE squares */
	int32_t line;		/* where the world file states it, for diagnostics */
} WorldObject;

typedef struct World {
	char file[256];		/* the file's name, for diagnostics */
	int32_t w, h;		/* TABLE size in squares */
	Polygon verge;		/* the verge outline (the default ring when not given) */
	bool verge_given;	/* a `verge` statement was read */
	Polygon *walls;		/* fixed polygons in the verge colour */
	int32_t wall_count;
	int32_t *wall_lines;
	WorldObject *objects;
	int32_t object_count;
	Vec2 utak;		/* Utak's point, TABLE squares */
	Heading heading;
	int32_t utak_line;
	int32_t held;		/* index of the object Utak holds, -1 none */
} World;

/* world_parse(w, name, text, len, d): reads a world file held in memory. On
 * failure fills d ("name:line:col: ...") and returns -1; w is then empty. Checks
 * syntax, limits and each polygon's shape; overlaps are table_build's to find. */
int world_parse(World *w, const char *name, const char *text, size_t len, Diag *d);
/* world_read(w, path, d): world_parse on a file's contents. world_read_stream(w,
 * name, f, d): on everything the open stream f holds (standard input, for "-"),
 * name standing for it in diagnostics. */
int world_read(World *w, const char *path, Diag *d);
int world_read_stream(World *w, const char *name, FILE *f, Diag *d);
void world_free(World *w);
/* world_write(w, f): the world as a world file that reads back to the same state. */
void world_write(const World *w, FILE *f);

/* world_own_to_table(h, v): a displacement in Utak's frame (x right, y ahead) as a
 * displacement on the TABLE. */
Vec2 world_own_to_table(Heading h, Vec2 v);
const char *world_heading_name(Heading h);
/* world_touch_square(w, k, &x, &y): the k-th square around Utak (0..7, in the
 * order of Impression.touch: ahead, ahead-right, right, ... ahead-left). */
void world_touch_square(const World *w, int k, int32_t *x, int32_t *y);

#endif
