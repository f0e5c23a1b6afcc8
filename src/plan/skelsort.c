/* skelsort.c - the skeleton's visiting order: free cells sorted by their distance to
 * the obstacles, ties by index (paper 4.2; step 2 of skeleton.c's ALGORITHM, Pudney's
 * distance order). A counting sort, all keys known in advance (dist2 from edt.c), in
 * two forms: from the list of the higher levels' cells (skellevel.c), or over the whole
 * grid; skeleton.c picks by the share of the grid the higher levels hold. Both give
 * the same order. Private to the planner library (skelsort.h). The figures are in
 * skeleton.c's MEASURED. */
#include "skelsort.h"

#include <assert.h>
#include <string.h>

/* The histogram's split tables (skelsort_listed, skelsort_rows): values
 * below THIN_SMALL, in THIN_SPLIT tables by place (a power of two). */
#define THIN_SMALL 256 /* a power of two: a word of values below it ORs below it */
#define THIN_SPLIT 8

/* sort_place4(start, order, k0..k3, v0..v3): four values placed by the counting sort
 * at once, keys k0..k3 in that order (ties keep it): each key's slot is its bucket's
 * next plus how many of the group before it share the key, so the four loads of
 * start[] do not wait on one another's stores. */
static inline void sort_place4(int32_t *start, int32_t *order, int32_t k0, int32_t k1, int32_t k2,
                               int32_t k3, int32_t v0, int32_t v1, int32_t v2, int32_t v3)
{
	const int32_t p0 = start[k0];
	const int32_t p1 = start[k1] + (k1 == k0);
	const int32_t p2 = start[k2] + (k2 == k0) + (k2 == k1);
	const int32_t p3 = start[k3] + (k3 == k0) + (k3 == k1) + (k3 == k2);
	start[k0] = p0 + 1;
	start[k1] = p1 + 1;
	start[k2] = p2 + 1;
	start[k3] = p3 + 1;
	order[p0] = v0;
	order[p1] = v1;
	order[p2] = v2;
	order[p3] = v3;
}

/* skelsort_listed(lv, dist2, start, order, maxd, nrest, high): the higher
 * levels' cells (dist2 above SKELLEVEL_PLANED_MAX; those of 2, 4 and 5 go into lv's
 * planes, skellevel.c's NEXT LEVELS) listed in index order from the planes into high
 * (scratch of two values a listed cell: the padded index and the dist2) and counted by
 * dist2 as they are listed (skellevel_high; start[d + 1] the cells of value d), then
 * counting-sorted into order after the lowest level's rest (nrest cells): the distance
 * order, ties by index. The lowest level (two thirds of the free cells on the maze)
 * and the blocked cells are neither counted nor sorted. The sort takes four cells at a
 * time: each bucket's next
 * place is loaded for all four before any is stored, and a cell's place counts the
 * cells before it in the four with the same key; so the chain through start[], a
 * store forwarded to the next load, is one link a group rather than one a cell (it
 * was most of the sort's time). */
int32_t skelsort_listed(const SkelLevel *lv, const int32_t *dist2, int32_t *start, int32_t *order,
                        int32_t maxd, int32_t nrest, int32_t *high, int32_t *upto)
{
	SkelLevelCount small;
	memset(small, 0, sizeof small);
	const int32_t nlisted = skellevel_high(lv, dist2, high, small, start);
	assert(nlisted <= lv->nhigh);
	for (int32_t d = 2; d < SKELLEVEL_SMALL && d <= maxd; d++)
		for (int j = 0; j < SKELLEVEL_LANES; j++)
			start[d + 1] += small[j][d];
	start[2] = nrest;
	for (int32_t d = 2; d <= maxd; d++)
		start[d + 1] += start[d];
	/* where the cells above each planed level's value begin (the end of the list
	 * when no cell is) */
	for (int j = 0; j < SKELLEVEL_PLANED; j++)
		upto[j] =
		    skellevel_dist2[j] < maxd ? start[skellevel_dist2[j] + 1] : nrest + nlisted;
	int32_t k = 0;
	for (; k + 4 <= nlisted; k += 4) {
		const int32_t *e = high + 2 * k;
		sort_place4(start, order, e[1], e[3], e[5], e[7], e[0], e[2], e[4], e[6]);
	}
	for (; k < nlisted; k++)
		order[start[high[2 * k + 1]]++] = high[2 * k];
	memset(start, 0, ((size_t)maxd + 2) * sizeof *start);
	return nlisted;
}

/* skelsort_rows(t, start, order, maxd): every cell of the grid sorted by dist2
 * into order, ties by index, as padded indices: the blocked cells (dist2 0) first, so
 * that the loop needs no branch and no test, then the lowest level's, then the higher
 * levels' in the distance order. For a grid whose higher levels are most of its cells
 * (rooms, open maps), where listing them first (skelsort_listed) costs more than
 * it saves. The histogram over the rows of dist2 in split tables by column, and the
 * sort four cells a group, as skelsort_listed (see there). */
void skelsort_rows(const int32_t *dist2, int32_t w, int32_t h, int32_t pw, int32_t *start,
                   int32_t *order, int32_t maxd)
{
	int32_t small[THIN_SPLIT][THIN_SMALL + 16];
	memset(small, 0, sizeof small);
	for (int32_t y = 0; y < h; y++) {
		const int32_t *restrict d2 = dist2 + (size_t)y * w;
		int32_t x = 0;
		for (; x + THIN_SPLIT <= w; x += THIN_SPLIT) {
			int32_t any = 0;
			for (int j = 0; j < THIN_SPLIT; j++)
				any |= d2[x + j];
			if (any < THIN_SMALL)
				for (int j = 0; j < THIN_SPLIT; j++)
					small[j][d2[x + j]]++;
			else
				for (int j = 0; j < THIN_SPLIT; j++)
					start[d2[x + j] + 1]++;
		}
		for (; x < w; x++)
			start[d2[x] + 1]++;
	}
	for (int32_t d = 0; d < THIN_SMALL && d <= maxd; d++)
		for (int j = 0; j < THIN_SPLIT; j++)
			start[d + 1] += small[j][d];
	start[0] = 0;
	for (int32_t d = 0; d <= maxd; d++)
		start[d + 1] += start[d];
	for (int32_t y = 0; y < h; y++) {
		const int32_t *restrict d2 = dist2 + (size_t)y * w;
		const int32_t base = (y + 1) * pw + 1;
		int32_t x = 0;
		for (; x + 4 <= w; x += 4) {
			sort_place4(start, order, d2[x], d2[x + 1], d2[x + 2], d2[x + 3], base + x,
			            base + x + 1, base + x + 2, base + x + 3);
		}
		for (; x < w; x++)
			order[start[d2[x]]++] = base + x;
	}
	memset(start, 0, ((size_t)maxd + 2) * sizeof *start);
}
