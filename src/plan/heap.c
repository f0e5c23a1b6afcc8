/* heap.c - the binary min-heap of heap.h (Williams 1964, "Algorithm 232:
 * Heapsort"): sift up on push, sift down from the root on pop; keys and ids in
 * parallel arrays. */
#include "utak/plan/heap.h"

#include <stdlib.h>

#include "utak/base/util.h"

void heap_free(Heap *h)
{
	free(h->key);
	free(h->id);
	*h = (Heap){0};
}

void heap_push(Heap *h, double key, int32_t id)
{
	if (h->count == h->cap) {
		int cap = h->cap;
		h->key = util_grow(h->key, &cap, h->count + 1, sizeof *h->key);
		h->id = util_grow(h->id, &h->cap, h->count + 1, sizeof *h->id);
	}
	int i = h->count++;
	while (i > 0 && key < h->key[(i - 1) / 2]) {
		h->key[i] = h->key[(i - 1) / 2];
		h->id[i] = h->id[(i - 1) / 2];
		i = (i - 1) / 2;
	}
	h->key[i] = key;
	h->id[i] = id;
}

int32_t heap_pop(Heap *h)
{
	int32_t top = h->id[0];
	int n = --h->count;
	double last_key = h->key[n];
	int32_t last_id = h->id[n];
	int i = 0;
	for (;;) {
		int c = 2 * i + 1;
		if (c >= n)
			break;
		if (c + 1 < n && h->key[c + 1] < h->key[c])
			c++;
		if (!(h->key[c] < last_key))
			break;
		h->key[i] = h->key[c];
		h->id[i] = h->id[c];
		i = c;
	}
	if (n > 0) {
		h->key[i] = last_key;
		h->id[i] = last_id;
	}
	return top;
}
