/* util.c - allocation that fails loudly, and reading a whole stream (see util.h).
 * Not from the paper: plumbing. */
#include "utak/base/util.h"

#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void util_default_out_of_memory(size_t n, size_t size, void *context)
{
	(void)context;
	fprintf(stderr, "utak: out of memory (%zu x %zu bytes)\n", n, size);
	exit(3);
}

static UtilOutOfMemory *util_handler = util_default_out_of_memory;
static void *util_context;

void util_set_out_of_memory(UtilOutOfMemory *handler, void *context)
{
	util_handler = handler ? handler : util_default_out_of_memory;
	util_context = context;
}

static void util_out_of_memory(size_t n, size_t size)
{
	util_handler(n, size, util_context);
	/* A handler that returns leaves its caller with no memory to go on with. */
	abort();
}

void *util_alloc(size_t n, size_t size)
{
	if (n == 0 || size == 0)
		n = size = 1;
	if (n > SIZE_MAX / size)
		util_out_of_memory(n, size);
	void *p = calloc(n, size);
	if (!p)
		util_out_of_memory(n, size);
	return p;
}

void *util_realloc(void *p, size_t n, size_t size)
{
	if (n == 0 || size == 0)
		n = size = 1;
	if (n > SIZE_MAX / size)
		util_out_of_memory(n, size);
	void *q = realloc(p, n * size);
	if (!q)
		util_out_of_memory(n, size);
	return q;
}

void *util_grow(void *p, int *cap, int need, size_t size)
{
	if (need <= *cap)
		return p;
	int c = *cap > 0 ? *cap : 8;
	while (c < need) {
		if (c > INT32_MAX / 2)
			util_out_of_memory((size_t)need, size);
		c *= 2;
	}
	*cap = c;
	return util_realloc(p, (size_t)c, size);
}

int util_read_stream(FILE *f, size_t limit, char **buf, size_t *len)
{
	size_t cap = 1 << 16, n = 0;
	char *b = util_alloc(cap, 1);
	for (;;) {
		size_t want = cap - 1 - n; /* room for the NUL */
		if (want > limit + 1 - n)
			want = limit + 1 - n;
		size_t got = fread(b + n, 1, want, f);
		n += got;
		if (got == 0 || n > limit)
			break;
		if (n == cap - 1) {
			cap *= 2;
			b = util_realloc(b, cap, 1);
		}
	}
	if (ferror(f)) {
		int err = errno ? errno : EIO;
		free(b);
		*buf = NULL;
		*len = 0;
		errno = err;
		return -1;
	}
	b[n] = 0;
	*buf = b;
	*len = n;
	return 0;
}
