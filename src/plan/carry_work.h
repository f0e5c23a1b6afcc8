/* carry_work.h - the working state of carry.c, shared with carrypath.c and
 * carryproof.c: the planner's caches, the lattice's layers and the checks the plan
 * is made with (see carry.c for the invariants). Private to the carry module:
 * not installed under include/, and nothing outside src/plan/carry*.c includes it. */
#ifndef UTAK_CARRY_WORK_H
#define UTAK_CARRY_WORK_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/plan/carry.h"
#include "utak/plan/cspace.h"
#include "utak/plan/heap.h"
#include "utak/plan/pathgraph.h"
#include "utak/base/util.h"
#include "utak/plan/skeleton.h"

#define CARRY_PI 3.14159265358979323846
/* The exact layers: the quarter turns 0, 90, 180, 270 degrees. */
#define CARRY_QUARTERS 4
#define CARRY_LAYERS_MAX (CARRY_ANGLES_MAX + CARRY_QUARTERS)

/* A growable list of ids. */
typedef struct CarryIds {
	int32_t *id;
	int count, cap;
} CarryIds;

static inline void carry_ids_push(CarryIds *l, int32_t id)
{
	l->id = util_grow(l->id, &l->cap, l->count + 1, sizeof *l->id);
	l->id[l->count++] = id;
}

typedef struct CarryWork {
	int32_t w, h;
	size_t cells;			/* w h */
	const uint8_t *grid_cells;	/* the grid's own */
	/* The grid's caches. */
	int32_t *blocked;		/* (w + 1) h: per row, blocked cells before column x */
	int32_t *dist2;			/* w h: skeleton_edt of the grid */
	Skeleton skeleton;
	Pathgraph graph;
	bool have_graph;
	/* The plan's object. */
	int32_t angles, layers;
	int32_t deg[CARRY_ANGLES_MAX + 1];	/* deg[N] = 360 */
	int32_t turn_cost[CARRY_ANGLES_MAX];	/* step k -> k + 1 */
	CSpaceFootprint body[CARRY_LAYERS_MAX];
	CSpaceFootprint object[CARRY_LAYERS_MAX];
	CSpaceFootprint sweep[CARRY_ANGLES_MAX];
	Polygon rel;			/* the object about Utak's point */
	Vec2 frac;			/* Utak's point inside his cell */
	int32_t settle_dist2;		/* dist2 above which everything is free */
	bool exact_start;
	/* The plan's goal. */
	const CarryGoal *goal;
	int32_t *outside;		/* (w + 1) h: per row, cells not in the goal before x */
	int32_t *steps;			/* w h: the estimate's steps, -1 unreachable */
	uint8_t *allowed;		/* w h: Utak cells the search may use */
	/* Per configuration, for allocated_angles + 4 layers (allocated at the first
	 * plan, zeroed, and kept clean between plans by the touched lists). */
	int32_t allocated_angles;
	uint32_t *g;
	uint8_t *from;
	uint8_t *known;
	uint8_t *turned;		/* per (angle, cell) */
	CarryIds touched_search, touched_known, touched_turned;
	Heap heap;
	CarryStats *stats;
	const CarryParams *params;
} CarryWork;

/* Layers 0 .. angles - 1 are tolerant at angle `layer`; angles .. angles + 3 exact at
 * the quarter turns. */
static inline int32_t carry_layer_angle(const CarryWork *k, int32_t layer)
{
	return layer < k->angles ? layer : (layer - k->angles) * (k->angles / CARRY_QUARTERS);
}

static inline bool carry_layer_exact(const CarryWork *k, int32_t layer) { return layer >= k->angles; }

/* carry_exact_layer(k, angle): the exact layer of a quarter-turn angle. */
static inline int32_t carry_exact_layer(const CarryWork *k, int32_t angle)
{
	return k->angles + angle / (k->angles / CARRY_QUARTERS);
}

/* An item of the lattice plan: a turn of `turn` angle steps (signed) where Utak
 * stands, or (turn == 0) a push of one square to cell (x, y). */
typedef struct CarryItem {
	int32_t turn;
	int32_t x, y;
} CarryItem;

typedef struct CarryItems {
	CarryItem *item;
	int count, cap;
} CarryItems;

void carry_items_push(CarryItems *l, CarryItem it);

/* The checks of carry.c, memoised per configuration. */
bool carry_body_free(CarryWork *k, int32_t layer, int32_t x, int32_t y);
bool carry_turn_run_free(CarryWork *k, int32_t angle, int32_t steps, int32_t x, int32_t y);
bool carry_goal_holds(CarryWork *k, int32_t layer, int32_t x, int32_t y);

/* carry_path_commands(k, items, x0, y0, plan) (carrypath.c): the lattice path
 * from cell (x0, y0) at angle 0, as items, into plan's poses and commands. */
void carry_path_commands(CarryWork *k, CarryItems *items, int32_t x0, int32_t y0, CarryPlan *plan);

/* carry_disc_cannot_pass(k, centre, radius) (carryproof.c): true when the disc of
 * that radius at centre, inside the object, provably cannot reach any place wholly
 * inside the goal region, so neither can the object (carry.h, PRUNING). */
bool carry_disc_cannot_pass(CarryWork *k, Vec2 centre, double radius);

/* carry_explain(k, start_layer, sx, sy, name, out) (carryproof.c): why no plan
 * exists, into out->why (and out->way), once the whole-grid search found none. */
void carry_explain(CarryWork *k, int32_t start_layer, int32_t sx, int32_t sy, const char *name,
		   CarryResult *out);

#endif
