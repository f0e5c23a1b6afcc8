/* gen.h - what the test-world tools share (issue 13): a seeded random number
 * generator, world text built line by line, and the reader's own verdict on it.
 *
 * The tools are test helpers: they may see both sides of the wall (they write
 * world files and check them with the simulator's reader and TABLE). Everything
 * is deterministic: the same seed gives the same bytes on every machine (no libc
 * rand, numbers printed with fixed precision). */
#ifndef UTAK_TEST_GEN_H
#define UTAK_TEST_GEN_H

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/geom.h"
#include "utak/base/util.h"
#include "utak/body/table.h"
#include "utak/body/world.h"

/* ---- the random number generator: splitmix64 (Steele, Lea and Flood, "Fast
 * splittable pseudorandom number generators", OOPSLA 2014), 64 bits of state. */
typedef struct GenRng {
	uint64_t state;
} GenRng;

static inline uint64_t gen_next(GenRng *r)
{
	uint64_t z = (r->state += 0x9E3779B97F4A7C15ull);
	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
	return z ^ (z >> 31);
}

/* gen_unit: uniform in [0, 1), 53 bits. */
static inline double gen_unit(GenRng *r)
{
	return (double)(gen_next(r) >> 11) * (1.0 / 9007199254740992.0);
}

/* gen_range(lo, hi): uniform real in [lo, hi). */
static inline double gen_range(GenRng *r, double lo, double hi)
{
	return lo + (hi - lo) * gen_unit(r);
}

/* gen_int(lo, hi): uniform whole number in [lo, hi] (hi >= lo). */
static inline int32_t gen_int(GenRng *r, int32_t lo, int32_t hi)
{
	return lo + (int32_t)(gen_next(r) % (uint64_t)(hi - lo + 1));
}

static inline int gen_chance(GenRng *r, double p)
{
	return gen_unit(r) < p;
}

#define GEN_PI 3.14159265358979323846

/* ---- world text --------------------------------------------------------------- */

typedef struct GenText {
	char *s;
	size_t len, cap;
} GenText;

static inline void gen_printf(GenText *t, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 2, 3)))
#endif
	;

static inline void gen_printf(GenText *t, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	int n = vsnprintf(NULL, 0, fmt, ap);
	va_end(ap);
	if (t->len + (size_t)n + 1 > t->cap) {
		t->cap = (t->len + (size_t)n + 1) * 2;
		t->s = util_realloc(t->s, t->cap, 1);
	}
	va_start(ap, fmt);
	vsnprintf(t->s + t->len, (size_t)n + 1, fmt, ap);
	va_end(ap);
	t->len += (size_t)n;
}

/* gen_round(v): v to GEN_DECIMALS decimals, the precision the tools print, so that
 * what a tool checks is exactly what the file says. */
#define GEN_DECIMALS 3
static inline double gen_round(double v)
{
	return round(v * 1000.0) / 1000.0;
}

/* gen_number(t, v): v (already gen_round'ed) with at most three decimals and no
 * trailing zeros: "12", "12.5", "12.125". */
static inline void gen_number(GenText *t, double v)
{
	char buf[48];
	snprintf(buf, sizeof buf, "%.3f", v);
	char *end = buf + strlen(buf);
	while (end[-1] == '0')
		*--end = 0;
	if (end[-1] == '.')
		*--end = 0;
	if (strcmp(buf, "-0") == 0)
		strcpy(buf, "0");
	gen_printf(t, "%s", buf);
}

static inline void gen_points(GenText *t, const Polygon *p)
{
	for (int32_t i = 0; i < p->count; i++) {
		gen_printf(t, " ");
		gen_number(t, p->v[i].x);
		gen_printf(t, " ");
		gen_number(t, p->v[i].y);
	}
	gen_printf(t, "\n");
}

/* gen_valid(text, len, why, size): the simulator's reader and TABLE accept the
 * world (the judge of validity is the program itself, not the tool's own checks). */
static inline int gen_valid(const char *text, size_t len, char *why, size_t size)
{
	World w;
	Table t;
	Diag d;
	if (world_parse(&w, "gen.w", text, len, &d)) {
		snprintf(why, size, "%s", d.msg);
		return 0;
	}
	int ok = table_build(&t, &w, &d) == 0;
	if (ok)
		table_free(&t);
	else
		snprintf(why, size, "%s", d.msg);
	world_free(&w);
	return ok;
}

#endif
