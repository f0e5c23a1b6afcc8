/* util.h - allocation that fails loudly, and size arithmetic that cannot overflow.
 *
 * Out of memory is not an input error a user can fix by editing a file: it ends
 * the program with one line on stderr and exit status 3. Every size is a size_t
 * checked for overflow before it reaches the allocator. */
#ifndef UTAK_UTIL_H
#define UTAK_UTIL_H

#include <stddef.h>

/* util_alloc(n, size): n * size bytes, zeroed; never NULL. */
void *util_alloc(size_t n, size_t size);
/* util_realloc(p, n, size): p resized to n * size bytes (new bytes are not zeroed). */
void *util_realloc(void *p, size_t n, size_t size);
/* util_grow(p, cap, need, size): makes an array of *cap elements hold at least need. */
void *util_grow(void *p, int *cap, int need, size_t size);

#endif
