/* regions.h - regions of a retinal impression and their interpretation (paper 3.4.1, 3.4.2).
 * CONTROLLER SIDE: works on an Impression alone.
 *
 * A region is a connected set of cells that are all zero or all non-zero, under
 * the edge adjacency of eye.h (diagonal neighbours are not connected).
 *
 * SURROUNDS, made precise on the retina: region A surrounds region B (B != A) when
 * B has no cell on the field's outer border and every chain of edge-adjacent cells
 * from a cell of B to a border cell passes through a cell of A. A region with a cell
 * on the border is surrounded by nobody.
 *
 * READINGS (paper 3.4.2):
 *   floor      every zero region (floorspace). When there are several, they are
 *              recorded as connected beyond view (Regions.floor_regions > 1).
 *   verge      a non-zero region that surrounds a zero region and is not itself
 *              surrounded by a zero region.
 *   object     a non-zero region surrounded by a zero region: an isolated object.
 *   utak       the non-zero region that is Utak's own foveal cell and nothing else.
 *   uncertain  a non-zero region neither rule decides: verge, or an object partly
 *              out of view, or an object touching the verge or Utak. */
#ifndef UTAK_REGIONS_H
#define UTAK_REGIONS_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/impression.h"

typedef enum RegionReading {
	REGION_FLOOR,
	REGION_VERGE,
	REGION_OBJECT,
	REGION_UTAK,
	REGION_UNCERTAIN,
} RegionReading;

typedef struct Region {
	bool nonzero; /* the cells' levels are all > 0 (else all 0) */
	RegionReading reading;
	int32_t cells;         /* number of cells */
	int32_t squares;       /* squares covered by its cells */
	int32_t first_cell;    /* its lowest-numbered cell: regions are numbered by it */
	bool on_border;        /* has a cell on the field's outer border */
	bool has_utak;         /* holds Utak's own cell, offset (0, 0) */
	int32_t surrounded_by; /* the zero region surrounding it, -1 none */
} Region;

typedef struct Regions {
	int32_t count;
	int32_t region_of[RETINA_CELLS]; /* cell -> region index */
	Region region[RETINA_CELLS];
	int32_t floor_regions; /* zero regions: > 1 means connected beyond view */
} Regions;

/* regions_find(r, imp): finds the regions of imp and reads them. Regions are
 * numbered in the order of their lowest cell (eye.h's cell order), so the result
 * is deterministic. */
void regions_find(Regions *r, const Impression *imp);

/* regions_surrounds(r, a, b): region a surrounds region b (definition above). */
bool regions_surrounds(const Regions *r, int32_t a, int32_t b);

const char *regions_reading_name(RegionReading reading);

/* regions_dump(r, f): a header line "regions N, floor regions F", then one line per
 * region:
 *   region ID zero|nonzero READING cells C squares S [border] [with-utak] [in ID]: CELL...
 * (border: it has a cell on the field's border; with-utak: it holds Utak's cell
 * but is more than it; in ID: the zero region surrounding it), then the 32 x 32
 * picture of region ids, in the layout of the retina picture, ids written as
 * letters a-z, A-Z, and '#' past 51. */
void regions_dump(const Regions *r, FILE *f);

#endif
