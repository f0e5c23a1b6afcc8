/* screen.h - the screen: Utak's map-in-the-head (paper 3.2, 3.6). CONTROLLER SIDE.
 *
 * "A spatial problem is to be solved by projecting all or part of the world model
 * onto a screen, then solving the problem there and translating the solution back
 * into the Cartesian coordinate system" (3.2). A window of the world model's
 * squares that holds Utak, his destination and everything he has seen is
 * projected onto a grid of cells, one cell a square; each cell is marked space,
 * unknown, or with the object over it.
 *
 * FRAMES. Screen cell (i, j) is model square (x0 + i, y0 + j); a point p in the
 * model ($floor) frame is p - (x0, y0) in screen units (grid.h conventions).
 *
 * UNKNOWN POLICY: optimistic. A square never seen is marked SCREEN_UNKNOWN and
 * planned through as space; when it comes into view and proves occupied, the plan
 * fails its viability check and is made again (paper 3.1, steps 12-13). So Utak
 * can plan before he has seen everything, and explores as he goes. */
#ifndef UTAK_SCREEN_H
#define UTAK_SCREEN_H

#include <stdint.h>
#include <stdio.h>

#include "utak/base/geom.h"
#include "utak/plan/grid.h"
#include "utak/mind/worldmodel.h"

/* Cells of margin around what has been seen: room to plan past the last seen
 * edge into the unknown, so exploration has somewhere to go. */
#define SCREEN_MARGIN 4

enum {
	SCREEN_SPACE = -1,	/* believed floor */
	SCREEN_UNKNOWN = -2,	/* never seen: space, by the optimistic policy */
	SCREEN_VERGE = -3,	/* occupied, not part of an isolated object: verge or wall */
	/* 0.. : occupied by the world model's node of that index (an object) */
};

typedef struct Screen {
	int32_t x0, y0;		/* model square of cell (0, 0) */
	int32_t w, h;		/* cells */
	int32_t *label;		/* w * h: SCREEN_SPACE, _UNKNOWN, _VERGE or a node index */
	Grid free;		/* GRID_FREE for space and unknown, else GRID_BLOCKED */
	Grid fixed;		/* the same with objects counted as space: the rooms */
} Screen;

void screen_init(Screen *s);
void screen_free(Screen *s);
/* screen_build(s, m, extra, n): projects the world model through a window that holds
 * every square seen, Utak's believed square, and the n model points extra[] (the
 * destination), with SCREEN_MARGIN cells around. */
void screen_build(Screen *s, const WorldModel *m, const Vec2 *extra, int n);

static inline Vec2 screen_from_model(const Screen *s, Vec2 p) { return vec2(p.x - s->x0, p.y - s->y0); }
static inline Vec2 screen_to_model(const Screen *s, Vec2 p) { return vec2(p.x + s->x0, p.y + s->y0); }
/* screen_label(s, i, j): the label of cell (i, j); SCREEN_VERGE outside. */
int32_t screen_label(const Screen *s, int32_t i, int32_t j);

/* screen_dump(s, f): a header line, then h lines of w characters, north on top:
 * '.' space, '?' unknown, '#' verge or wall, a letter for an object (object1 'a',
 * object2 'b', ..., cycling after 'z'), '@' Utak. */
void screen_dump(const Screen *s, const WorldModel *m, FILE *f);

#endif
