/* probe_work.h - what probe.c (the square's test by branch and bound, and the
 * probe in the action cycle) and probewidth.c (the least width the looks show)
 * share. Private to the probe: not installed under include/, and nothing but
 * those two files includes it. */
#ifndef UTAK_PROBE_WORK_H
#define UTAK_PROBE_WORK_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/probe.h"

/* A quarter turn, radians: a rectangle turned by it is one with its sides swapped. */
#define PROBE_QUARTER 1.57079632679489661923

/* The most places of the eye's grid tried: (PROBE_LOOKS + 1) pieces an axis. */
#define PROBE_SHIFTS ((PROBE_LOOKS + 1) * (PROBE_LOOKS + 1))

/* probe_grid_places(looks, nlooks, unplaced, place): the places of Utak's point in
 * his square that the looks tell apart, each with the places of the eye's grid
 * it allows at each look (bit (sy + 1) * 3 + sx + 1, as ProbeLook.shifts); their
 * number. Not unplaced: one, the grid where it was at every look. */
int probe_grid_places(const ProbeLook *looks, int32_t nlooks, bool unplaced, uint16_t place[][PROBE_LOOKS]);

#endif
