/* heap.h - a binary min-heap of (key, id) pairs: the open list of the pathgraph's
 * and the visibility graph's A* (issue 4). SHARED: no side's types.
 *
 * Keys are compared with <; of equal keys the one that reaches the top first is
 * not specified, but it is always the same for the same pushes and pops, so the
 * searches built on it are deterministic. Stale entries are the caller's affair
 * (both searches skip a node popped again with a worse key: cheaper than
 * decrease-key). Memory: grows as needed, kept between searches by heap_clear. */
#ifndef UTAK_HEAP_H
#define UTAK_HEAP_H

#include <stdint.h>

typedef struct Heap {
	double *key;
	int32_t *id;
	int count, cap;
} Heap;

static inline void heap_init(Heap *h) { *h = (Heap){0}; }
static inline void heap_clear(Heap *h) { h->count = 0; }
void heap_free(Heap *h);
void heap_push(Heap *h, double key, int32_t id);
/* heap_pop(h): removes and returns the id of a least key (h->count > 0). */
int32_t heap_pop(Heap *h);

#endif
