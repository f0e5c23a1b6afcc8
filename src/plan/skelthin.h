/* skelthin.h - the skeleton's thinning state, shared by its visits (skeleton.c) and its
 * pruning (skelprune.c) (paper 4.2). Private to the planner library: only skeleton.c
 * and skelprune.c include it. The algorithm is in skeleton.c's header. */
#ifndef UTAK_SKELTHIN_H
#define UTAK_SKELTHIN_H

#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "skellevel.h"

/* What one deletion test needs from the 8-neighbourhood mask (one table load). */
enum {
	THIN_KEEP = 0,   /* not simple: deleting would change the topology */
	THIN_DELETE = 1, /* simple, and not one edge neighbour: deletable */
	THIN_RIDGE = 2   /* simple with exactly one edge neighbour: a ridge end or not */
};

enum {
	SKELETON_IN = 1,      /* still in the set */
	SKELETON_KEPT = 2,    /* visited, and still in the set (kept, or not yet deleted
	                       * by a cascade): the cells a deletion tries again */
	SKELETON_STACKED = 4, /* on the re-try stack */
	SKELETON_QUEUED = 8   /* a planed level's cell marked kept before its turn, on the
	                       * heap of such cells to visit at their turn
	                       * (thinner_visit_level) */
};

/* The thinning works on a copy of the grid padded by one background cell on every
 * side, so that a neighbourhood never needs a bounds check (and 3 bytes more at the
 * end, for the last row's 4-byte loads; see thinner_raster).
 *
 * A neighbourhood is read as its "raster mask" of THIN_RASTER bits: the rows below and
 * above as a 4-byte load each, gathered to 8 bits by one multiplication (thinner_rows;
 * the fourth cell of each, two east, is not a neighbour and the tables ignore it),
 * then the west and east cells' state, 2 bits each (only bit 0, SKELETON_IN, counts,
 * so the visits take the bytes as they are: SKELETON_IN and SKELETON_KEPT, below 4).
 * The middle row is read by bytes since the visit before this one usually stored the
 * west cell: a 4-byte load over a byte just stored waits for the store to reach the
 * cache (no store forwarding), and that stall was a third of the visits' time (perf
 * annotate). Which bit is which cell depends on the byte order, so the tables over
 * the mask are built by running thinner_raster itself on probes
 * (thinner_init_tables). */
#define THIN_RASTER 12

typedef struct Thinner {
	int32_t w, h, pw; /* grid size, padded width w + 2 */
	uint8_t *state;   /* (w + 2) * (h + 2) + 3 SKELETON_* bits */
	int32_t off[8];   /* padded index offsets of the 8 neighbours */
	int32_t *stack;   /* padded indices to try again */
	int32_t top;
	uint64_t *ends; /* bit pi: pi was found a ridge end (thinner_ridge_end), at least
	                 * once: the only cells that can be end points when the visits
	                 * are over (thinner_prune) */
	int32_t ends_words;
	uint64_t *recheck;    /* ends_words + 1 words, zero but in thinner_prune: the cells
	                       * to test again after the spurs are removed (the word past
	                       * the state's cells stays zero: thinner_prune) */
	const int32_t *dist2; /* w * h, unpadded */
	const uint8_t *kind; /* 1 << THIN_RASTER: THIN_* of each raster mask */
	const uint8_t *ring; /* 1 << THIN_RASTER: the neighbourhood mask (bit i: neighbour
	                      * i); both built once for a Skeleton's working space
	                      * (skeleton.c), not at every call */
	int32_t doff[8];                 /* unpadded index offsets of the 8 neighbours (in dist2) */
	uint64_t row_mul;                /* pi / pw as (pi * row_mul) >> row_shift (thinner_row) */
	unsigned row_shift;
	int32_t pos;   /* the cell a planed level's visit is at (thinner_visit_level);
	                * INT32_MAX at any other time */
	int32_t level; /* that level's dist2 */
	int32_t *heap; /* its cells marked kept early, to visit at their turn: a
	                * binary min-heap */
	int32_t nheap;
	SkelLevel *track; /* while the planed levels are visited: the planes whose set
	                   * each deletion updates (skellevel_next reads it) */
} Thinner;

/* thinner_row(t, pi): pi / pw, the padded row, with no division (Granlund and
 * Montgomery, "Division by invariant integers using multiplication", PLDI 1994): with
 * l = ceil(log2 pw) and row_mul = ceil(2^(31 + l) / pw), the product's top bits are
 * the quotient for every pi < 2^31, and pi < (30002)^2 < 2^31; the product < 2^63. */
static inline int32_t thinner_row(const Thinner *t, int32_t pi)
{
	return (int32_t)(((uint64_t)pi * t->row_mul) >> t->row_shift);
}

/* thinner_unpadded(t, pi): the index in dist2 of the padded index pi: with pi =
 * (y + 1) pw + x + 1, that is y w + x = pi - pw - 1 - 2 y. */
static inline int32_t thinner_unpadded(const Thinner *t, int32_t pi)
{
	return pi - t->pw - 1 - 2 * (thinner_row(t, pi) - 1);
}

/* thinner_load4(p): the 4 bytes at p, in the machine's byte order. */
static inline uint32_t thinner_load4(const uint8_t *p)
{
	uint32_t v;
	memcpy(&v, p, sizeof v);
	return v;
}

/* THIN_ONES: a byte of 1 in each lane of a 64-bit word; THIN_LOW7: 0x7f in each. */
#define THIN_ONES 0x0101010101010101u
#define THIN_LOW7 0x7f7f7f7f7f7f7f7fu

/* thinner_rows(below, above): bit 0 of each byte of the two 4-byte loads, as 8 bits.
 * The bits sit at 8 i in a 64-bit word; times 0x0102040810204080 (the terms 2^(7 j + 7))
 * puts bit 8 i at 56 + i when i + j = 7, and no two of the 64 terms fall on one bit
 * (8 i + 7 j is unique for i, j < 8), so there is no carry. */
static inline unsigned thinner_rows(uint32_t below, uint32_t above)
{
	const uint64_t v = ((uint64_t)above << 32 | below) & THIN_ONES;
	return (unsigned)((v * 0x0102040810204080u) >> 56);
}

/* thinner_raster(st, pi, pw): the raster mask of pi's neighbours in the set (see the
 * Thinner). */
static inline unsigned thinner_raster(const uint8_t *st, int32_t pi, int32_t pw)
{
	return thinner_rows(thinner_load4(st + pi - pw - 1), thinner_load4(st + pi + pw - 1)) |
	       (unsigned)(st[pi - 1] & SKELETON_IN) << 8 |
	       (unsigned)(st[pi + 1] & SKELETON_IN) << 10;
}

/* thinner_lowest_bit(m): the index of m's lowest set bit, m a nonzero byte. */
static inline int thinner_lowest_bit(unsigned m)
{
	static const int8_t lowest[16] = {-1, 0, 1, 0, 2, 0, 1, 0, 3, 0, 1, 0, 2, 0, 1, 0};
	return (m & 15u) ? lowest[m & 15u] : 4 + lowest[(m >> 4) & 15u];
}

/* thinner_ridge_end(t, pi, m): pi, simple with one edge neighbour (neighbourhood
 * mask m), is a ridge end. A ridge end has exactly one 4-neighbour in the set and no
 * 8-neighbour in the set farther from the obstacles: it is the tip of a branch of the
 * medial axis (the distance map has a local maximum there along the branch). Without
 * the second condition every cell of the grassfire front that happens to lose its side
 * neighbours first would be kept as an end, and grow a spur; with it, a branch whose
 * distance rises from its tip (toward a convex corner of the space) burns back to its
 * junction, as Blum's branches into corners carry no choice of route. The padded row
 * comes by a multiplication and a shift (thinner_row), the neighbours as offsets. */
static bool thinner_ridge_end(const Thinner *t, int32_t pi, unsigned m)
{
	const int32_t *d2 = t->dist2 + thinner_unpadded(t, pi);
	const int32_t d = d2[0];
	for (; m != 0; m &= m - 1)
		if (d2[t->doff[thinner_lowest_bit(m)]] > d)
			return false;
	t->ends[pi >> 6] |= (uint64_t)1 << (pi & 63); /* see Thinner.ends */
	return true;
}

/* thinner_deletable(t, pi): pi is simple and not a ridge end. */
static inline bool thinner_deletable(const Thinner *t, int32_t pi)
{
	unsigned r = thinner_raster(t->state, pi, t->pw);
	uint8_t k = t->kind[r];
	return k == THIN_DELETE || (k == THIN_RIDGE && !thinner_ridge_end(t, pi, t->ring[r]));
}

/* The visits of a grid whose state outgrows THIN_PREFETCH_BYTES prefetch the rows
 * below and above the cell THIN_AHEAD visits on: each distance level sweeps the whole
 * grid, and at 4096 a side (17 MB of state) most of a sparse level's visits missed the
 * cache; there it took 10-25% off the visits of rooms and rects, at 1024 it added 10%
 * (the loads hit the cache anyway, the prefetch is instructions). */
#define THIN_AHEAD 16
#define THIN_PREFETCH_BYTES (8u << 20)
/* rows ahead of the pruning's scan of ends (thinner_prune): past the longest walk on
 * grids of small clearance (SKELETON_SPUR_FACTOR * sqrt(5) + SKELETON_SPUR_SLACK) */
#define THIN_PRUNE_ROWS 6

/* thinner_delete_from(t, pi): deletes pi and whatever that makes deletable
 * (skeleton.c). */
void thinner_delete_from(Thinner *t, int32_t pi);

/* thinner_prune(t, scratch, maxd): removes the spurs, then deletes what that makes
 * deletable; returns the number of cells removed as spurs (skelprune.c). */
int32_t thinner_prune(Thinner *t, int32_t *scratch, int32_t maxd);

#endif
