/* util.h - allocation that fails loudly, and size arithmetic that cannot overflow.
 *
 * Out of memory is not an input error a user can fix by editing a file. Every
 * allocation of utak and of its planner library goes through util_alloc or
 * util_realloc, and every failure through ONE hook, the out-of-memory handler:
 * by default it writes one line on stderr, "utak: out of memory (N x SIZE bytes)",
 * and ends the program with exit status 3. A program that embeds the planner
 * library may install its own (util_set_out_of_memory): to log and exit its own
 * way, or to longjmp back to a point of its choosing. The handler must not
 * return; if it does, the program aborts, since no caller is written to go on
 * without the memory it asked for. (After a longjmp, whatever the interrupted call
 * had allocated is lost: the embedding program should treat the planner state it
 * was using as gone.)
 *
 * Every size is a size_t checked for overflow before it reaches the allocator: an
 * overflow is reported as a failure to allocate. */
#ifndef UTAK_UTIL_H
#define UTAK_UTIL_H

#include <stddef.h>
#include <stdio.h>

/* UtilOutOfMemory(n, size, context): called when n elements of size bytes could
 * not be had; must not return. */
typedef void UtilOutOfMemory(size_t n, size_t size, void *context);

/* util_set_out_of_memory(handler, context): installs handler (NULL restores the
 * default) and the context it is passed; not thread-safe, set it before planning. */
void util_set_out_of_memory(UtilOutOfMemory *handler, void *context);

/* util_alloc(n, size): n * size bytes, zeroed; never NULL. */
void *util_alloc(size_t n, size_t size);
/* util_realloc(p, n, size): p resized to n * size bytes (new bytes are not zeroed). */
void *util_realloc(void *p, size_t n, size_t size);
/* util_grow(p, cap, need, size): makes an array of *cap elements hold at least need. */
void *util_grow(void *p, int *cap, int need, size_t size);

/* util_read_stream(f, limit, &buf, &len): everything f holds, or its first limit + 1
 * bytes when it holds more (so that the caller can say it is over its limit
 * without reading the rest). *buf is NUL-terminated and the caller frees it.
 * Returns 0, or -1 with errno set when reading failed (*buf is then NULL). */
int util_read_stream(FILE *f, size_t limit, char **buf, size_t *len);

#endif
