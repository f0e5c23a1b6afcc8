/* skeleton.h - the distance transform and the digital skeleton of free space (paper 4.2).
 *
 * The skeleton (Blum's medial axis, paper 4.2) of the free cells of a Grid: a set of
 * free cells one cell thick, running along the middle of the space, with the same
 * topology as the space, each cell carrying its clearance. The pathgraph (pathgraph.h,
 * paper 4.3) is built on it.
 *
 * DIGITAL TOPOLOGY (shared with the grid planner's rule "a diagonal step only when both
 * orthogonal neighbours are free"): free space is 4-connected, obstacles (and the
 * outside of the grid) are 8-connected. Two free cells that touch only at a corner are
 * NOT connected, so free space never leaks through the shared corner of two
 * diagonally touching blocked cells. The skeleton is thinned under the same (4, 8)
 * pair: it is a 4-connected set, its complement 8-connected. Hence:
 *   - each 4-component of free space holds exactly one 4-component of skeleton;
 *   - each 8-component of blocked cells not joined to the outside (an obstacle
 *     inside a region, i.e. a hole of the space) is ringed by exactly one loop;
 *   - "one cell thick": no skeleton cell can be removed without changing that
 *     topology or cutting off a branch end (every cell is non-simple or an end
 *     point), and in particular no 2x2 block is all skeleton, unless it is a
 *     "pinwheel" whose four cells each carry a branch of their own (see skeleton.c).
 * A skeleton path is a chain of 4-adjacent cells; the pathgraph measures and draws it
 * with a diagonal step (length sqrt 2) across every staircase corner whose both
 * orthogonal cells are free, so its lengths follow the grid planner's convention.
 *
 * Distances are between cell centres, in cells: dist2 of a free cell is the squared
 * Euclidean distance from its centre to the centre of the nearest blocked cell, where
 * the cells just outside the grid count as blocked; dist2 of a blocked cell is 0. The
 * clearance of a cell is sqrt(dist2): the open disc of radius clearance - sqrt(2)/2
 * about the cell centre meets no blocked square, and the closed disc of radius
 * clearance - 1/2 meets one. */
#ifndef UTAK_SKELETON_H
#define UTAK_SKELETON_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/plan/grid.h"

/* Largest grid side the distance transform accepts: its integer arithmetic holds
 * 2 * (SKELETON_MAX_SIDE + 2)^2 in an int32_t. */
#define SKELETON_MAX_SIDE 30000

/* Spur pruning (skeleton.c, "Pruning"): a branch from an end point to a junction is
 * a digitisation spur, and removed, when it has at most
 * SKELETON_SPUR_FACTOR * clearance(junction) + SKELETON_SPUR_SLACK cells. A real
 * branch (a dead-end corridor, a niche) reaches beyond the junction's clearance disc;
 * a spur into a small bay of a wall does not. */
#define SKELETON_SPUR_FACTOR 1.5
#define SKELETON_SPUR_SLACK 2.0

typedef struct Skeleton {
	int32_t w, h;   /* size in cells, as the grid it was computed on */
	int32_t *dist2; /* w * h, row-major: squared distance to the nearest blocked centre */
	uint8_t *on;    /* w * h, row-major: 1 for a skeleton cell, else 0 */
	int32_t count;  /* number of skeleton cells */
	int32_t pruned; /* number of cells removed as spurs (for the bench and tests) */
	uint8_t *plane; /* the skeleton again as bits, for the pathgraph (pathgraph.c), or NULL:
	                 * cell (x, y) is bit skeleton_plane_bit(w, x, y), bit b being bit
	                 * b & 7 of byte b >> 3; the bits outside the grid (a zero row below
	                 * and above it, a zero word before each row and zero bits after it
	                 * up to the next row) are 0 */
	struct SkeletonWork *work; /* working space, kept for the next grid of this size */
} Skeleton;

/* skeleton_edt(g, dist2): the exact Euclidean distance transform of g into the
 * caller's array of g->w * g->h int32_t (see dist2 above). Linear time. Returns the
 * largest value (0 for a grid with no free cell). */
int32_t skeleton_edt(const Grid *g, int32_t *dist2);

void skeleton_init(Skeleton *s);
void skeleton_free(Skeleton *s);
/* skeleton_compute(s, g): the distance transform and the pruned skeleton of g's free
 * cells, into s. Linear time in the cells. The memory of an earlier skeleton of a grid
 * of the same size is reused, any other is freed. */
void skeleton_compute(Skeleton *s, const Grid *g);

/* skeleton_plane_words(w): 64-bit words a row of Skeleton.plane takes: one zero word,
 * then w bits, zero bits up to the next word and one more zero word (so that a load of
 * a few bytes about any cell stays in its row). The plane has h + 2 such rows. */
static inline int32_t skeleton_plane_words(int32_t w)
{
	return (w + 63) / 64 + 2;
}
/* skeleton_plane_bit(w, x, y): the bit of Skeleton.plane that holds cell (x, y); x and
 * y may be -1, w or h, an outside cell, whose bit is 0. */
static inline int64_t skeleton_plane_bit(int32_t w, int32_t x, int32_t y)
{
	return ((int64_t)(y + 1) * skeleton_plane_words(w) + 1) * 64 + x;
}

/* skeleton_on(s, x, y): (x, y) is inside the grid and a skeleton cell. */
static inline bool skeleton_on(const Skeleton *s, int32_t x, int32_t y)
{
	return x >= 0 && y >= 0 && x < s->w && y < s->h && s->on[(int64_t)y * s->w + x];
}
/* skeleton_degree(s, x, y): how many of the 4 edge neighbours are skeleton cells:
 * <= 1 an end point, 2 a chain cell, >= 3 a junction cell. */
int skeleton_degree(const Skeleton *s, int32_t x, int32_t y);
/* skeleton_clearance(s, x, y): sqrt(dist2) of the cell, in cells. */
double skeleton_clearance(const Skeleton *s, int32_t x, int32_t y);

/* skeleton_validate(s, g): the local invariants, in one pass: skeleton cells are free,
 * count is right, dist2 is 0 exactly on blocked cells, no 2x2 block is all skeleton
 * unless a pinwheel. The global ones (components, loops) are for the unit tests and
 * their flood-fill oracle. Returns false on the first failure. */
bool skeleton_validate(const Skeleton *s, const Grid *g);

/* skeleton_dump(s, g, out): the grid drawn with the skeleton, north (row h-1) on top,
 * one character per cell:
 *   '#' blocked   '.' free   'o' skeleton chain cell (degree 2)
 *   '+' junction cell (degree >= 3)   '*' end point (degree <= 1)
 * then one line "skeleton: N cells, J junction cells, E end points, P pruned". */
void skeleton_dump(const Skeleton *s, const Grid *g, FILE *out);

#endif
