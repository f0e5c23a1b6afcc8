/* pathgraph_build.h - the pathgraph build's working state (Builder) and its bit
 * helpers, shared by the build's two files, paper 4.3 (Figure 3's graph): pathgraph.c
 * (steps (0) and (1): the pass over the skeleton's bit plane, the ranks, the vertices
 * and junction sets; then the incidence lists) and pathwalk.c (steps (2) and (3): the
 * walk of the skeleton's chains into edges, and the loops without a junction). The
 * algorithm and its measured figures are in pathgraph.c's header. Private to those two
 * files: not installed under include/. */
#ifndef UTAK_PATHGRAPH_BUILD_H
#define UTAK_PATHGRAPH_BUILD_H

#include <stdbool.h>
#include <stdint.h>

#include "pathgraph_work.h"
#include "utak/base/util.h"

/* cell_ref of a cell that is not (yet) a skeleton cell of the graph. While building,
 * a chain cell walked in step (2) holds ref_base + k, k its place in cells[]: its final
 * value once the vertices are counted (see Builder.ref_base). */
enum { PATHGRAPH_REF_NONE = -1 };

typedef struct Builder {
	Pathgraph *pg;
	const Skeleton *s;
	struct PathgraphScratch *sc; /* the capacities of pg's arrays, kept between builds */
	uint8_t *toward; /* by rank: a vertex cell's 1 + direction to its set's root (0 there) */
	const uint8_t *plane; /* the skeleton's bits (Skeleton.plane) */
	int32_t row_bits;     /* bits a row of the plane: the step north there */
	const int32_t *base;  /* the rank of each plane word's first bit */
	PathgraphCell *cell;  /* the skeleton cells' records, by rank */
	IntList vcells;       /* cells of every vertex, vertex after vertex */
	IntList vstart;       /* vertex v's cells: vcells[vstart[v] .. vstart[v + 1]) */
	int32_t count;        /* edge cells so far, in pg->cells and pg->cell_edge */
	int32_t max_set;      /* the largest vertex (cells): a bound on a walk to its root */
	int32_t chain_left;   /* skeleton cells not yet in a vertex or an edge: a bound */
	int32_t ref_base;     /* vertices found by step (1): chain cells' cell_ref base */
} Builder;

/* pathgraph_load16(p): the 16 bits at p, in the plane's order. */
static inline unsigned pathgraph_load16(const uint8_t *p)
{
	return (unsigned)p[0] | (unsigned)p[1] << 8;
}

/* pathgraph_ctz64(v): the index of the lowest bit set in v != 0. */
static inline int pathgraph_ctz64(uint64_t v)
{
#if defined(__GNUC__)
	return __builtin_ctzll(v);
#else
	int k = 0;
	while (!(v & 1)) {
		v >>= 1;
		k++;
	}
	return k;
#endif
}

/* pathgraph_clz64(v): 63 less the index of the highest bit set in v != 0. */
static inline int pathgraph_clz64(uint64_t v)
{
#if defined(__GNUC__)
	return __builtin_clzll(v);
#else
	int k = 0;
	while (!(v >> 63)) {
		v <<= 1;
		k++;
	}
	return k;
#endif
}

/* pathgraph_plane_mask(plane, cb, row_bits): the skeleton 4-neighbours of the cell of
 * plane bit cb, as bits west 0, north 1, east 2, south 3: the west, own and east bits
 * of the cell's row and of the rows north and south (row_bits away, a multiple of 64:
 * the same shift) by three 16-bit loads. The plane's zero border spares every test of
 * the grid's edges. */
static inline unsigned pathgraph_plane_mask(const uint8_t *plane, int32_t cb, int32_t row_bits)
{
	const uint8_t *p = plane + ((cb - 1) >> 3);
	const unsigned sh = (unsigned)(cb - 1) & 7;
	const size_t rowb = (size_t)row_bits / 8;
	return (pathgraph_load16(p) >> sh & 5) | (pathgraph_load16(p + rowb) >> sh & 2) |
	       (pathgraph_load16(p - rowb) >> sh & 2) << 2;
}

/* The bit of direction d (east north west south) in a pathgraph_plane_mask, and the
 * number of bits set in a mask: a cell's skeleton degree. */
static const uint8_t PATHGRAPH_MASK_BIT[4] = {2, 1, 0, 3};
static const uint8_t PATHGRAPH_POP4[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};

/* On x86-64 with glibc (target_clones needs its ifunc; musl has none) the build's
 * steps (builder_vertices, builder_edges and the walk, builder_edge_from) are also
 * compiled with the popcnt instruction, chosen at load
 * time: a rank (pathgraph_rank: a vertex cell's, its neighbours' north and south, or a
 * step north or south in the walk) counts bits, twelve instructions without it.
 * PATHGRAPH_POPCOUNT is for those functions alone (elsewhere, GCC's builtin is a call
 * on the default target). */
#if defined(__GNUC__) && defined(__x86_64__) && defined(__GLIBC__)
#define PATHGRAPH_CLONES __attribute__((target_clones("popcnt", "default")))
#define PATHGRAPH_POPCOUNT(x) ((int32_t)__builtin_popcountll(x))
#else
#define PATHGRAPH_CLONES
#define PATHGRAPH_POPCOUNT(x) pathgraph_pop64(x)
#endif

/* builder_rank(b, cb): pathgraph_rank by PATHGRAPH_POPCOUNT (see there). */
static inline int32_t builder_rank(const Builder *b, int32_t cb)
{
	const uint64_t word = pathgraph_load64(b->plane + 8 * (size_t)(cb >> 6));
	return b->base[cb >> 6] + PATHGRAPH_POPCOUNT(word & ((UINT64_C(1) << (cb & 63)) - 1));
}

/* builder_bit(b, i): the plane bit of grid cell i (a division: for vertex cells, not
 * for every step of a walk, which carries its bit along). */
static inline int32_t builder_bit(const Builder *b, int32_t i)
{
	const int32_t w = b->pg->w, y = i / w;
	return (int32_t)skeleton_plane_bit(w, i - y * w, y);
}

/* builder_cell(b, cb): the record of the skeleton cell of plane bit cb. */
static inline PathgraphCell *builder_cell(const Builder *b, int32_t cb)
{
	return &b->cell[pathgraph_rank(b->plane, b->base, cb)];
}
/* builder_add_vertex(b, cell, rk, kind): a vertex of one cell, cell of rank rk. */
static inline int32_t builder_add_vertex(Builder *b, int32_t cell, int32_t rk, PathgraphKind kind)
{
	Pathgraph *pg = b->pg;
	pg->vertices =
	    util_grow(pg->vertices, &b->sc->vertex_cap, pg->vertex_count + 1, sizeof *pg->vertices);
	int32_t v = pg->vertex_count++;
	pg->vertices[v] = (PathgraphVertex){cell % pg->w, cell / pg->w, kind, 1, b->s->dist2[cell]};
	b->cell[rk].ref = v;
	b->toward[rk] = 0;
	return v;
}

/* pathgraph_build_edges(b): steps (2) and (3) of the build (pathwalk.c), after step
 * (1) has made the vertices, b->chain_left and b->ref_base are set: every edge, the
 * chain cells' refs, and the loop vertices. */
void pathgraph_build_edges(Builder *b);

#endif /* UTAK_PATHGRAPH_BUILD_H */
