/* first_look.h - a world from text and the world model its first impression gives
 * (paper 3.3-3.4: what Utak believes before he moves), and a seeded uniform draw,
 * for the controller's tests that take the simulator as their oracle. Shared by
 * test_coarsewall.c, test_faint.c and test_hallsplit.c. */
#ifndef UTAK_TEST_FIRST_LOOK_H
#define UTAK_TEST_FIRST_LOOK_H

#include <stdint.h>
#include <string.h>

#include "test.h"
#include "utak/body/retina.h"
#include "utak/body/table.h"
#include "utak/body/world.h"
#include "utak/mind/worldmodel.h"

/* xorshift64(s): Marsaglia's xorshift (13, 7, 17), the next state of *s. */
static inline uint64_t xorshift64(uint64_t *s)
{
	*s ^= *s << 13;
	*s ^= *s >> 7;
	*s ^= *s << 17;
	return *s;
}

/* xorshift_uniform(s): a draw in [0, 1) with 53 bits from *s's next state. */
static inline double xorshift_uniform(uint64_t *s)
{
	return (double)(xorshift64(s) >> 11) / 9007199254740992.0;
}

/* first_look(text, w, t, m, imp): the world and its TABLE (the case fails if either
 * is refused), the impression Utak senses there and the model it gives him; the
 * caller frees m, t and w. */
static void first_look(const char *text, World *w, Table *t, WorldModel *m, Impression *imp)
{
	Diag d;
	TEST_CHECK(world_parse(w, "test", text, strlen(text), &d) == 0);
	TEST_CHECK(table_build(t, w, &d) == 0);
	worldmodel_init(m);
	retina_sense(w, t, imp);
	worldmodel_accommodate_first(m, imp);
}

#endif
