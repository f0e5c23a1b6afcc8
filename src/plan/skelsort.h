/* skelsort.h - the skeleton's visiting order by distance (paper 4.2; skelsort.c).
 * Private to the planner library: only skeleton.c and skelsort.c include it. */
#ifndef UTAK_SKELSORT_H
#define UTAK_SKELSORT_H

#include <stdint.h>

#include "skellevel.h"

/* skelsort_listed(lv, dist2, start, order, maxd, nrest, high, upto): the higher levels'
 * cells (dist2 above 1) but those of the planed levels (SkelLevel.planed), listed from
 * lv's planes into high (two values a cell), sorted by dist2, ties by index, into
 * order after the lowest level's rest (nrest cells already there); returns their
 * number. upto[j]: the place in order where the cells of dist2 above planed level j's
 * value (skellevel_dist2) begin. start: maxd + 2 zeroed counters, left zeroed. */
int32_t skelsort_listed(const SkelLevel *lv, const int32_t *dist2, int32_t *start, int32_t *order,
                        int32_t maxd, int32_t nrest, int32_t *high, int32_t *upto);
/* skelsort_rows(dist2, w, h, pw, start, order, maxd): every cell of the w x h grid as
 * a padded index (rows pw wide, one blocked cell of padding), sorted by dist2, ties
 * by index, into order: the blocked cells first. start as above. */
void skelsort_rows(const int32_t *dist2, int32_t w, int32_t h, int32_t pw, int32_t *start,
                   int32_t *order, int32_t maxd);

#endif
