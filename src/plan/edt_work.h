/* edt_work.h - the distance transform's entry for the skeleton (paper 4.2): edt.c
 * makes dist2 and, in the same passes, the histogram that skeleton.c's counting sort
 * needs. Private to the planner library: not installed under include/, and nothing
 * outside src/plan/edt.c and skeleton.c includes it. */
#ifndef UTAK_EDT_WORK_H
#define UTAK_EDT_WORK_H

#include <stdint.h>

#include "utak/plan/grid.h"

/* skeleton_edt_scratch(g, dist2, up): skeleton_edt (skeleton.h) with up as scratch of
 * 2 w h bytes, or NULL to use dist2's own memory. Returns the largest dist2. */
int32_t skeleton_edt_scratch(const Grid *gr, int32_t *dist2, uint16_t *up);

#endif
