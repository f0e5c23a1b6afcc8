/* judgerooms.c - the judge's rooms: a watershed of clearance with the door rule of
 * spec-verdicts.md (paper 2.3). SIMULATOR SIDE; the rule is in judgerooms.h.
 *
 * ALGORITHM: two-pass 8-neighbour chamfer distance (Rosenfeld and Pfaltz,
 * "Distance functions on digital pictures", 1968, with weights 1 and sqrt 2);
 * squares sorted by decreasing clearance; union-find (Tarjan 1975, path halving,
 * union by peak) with each region's peak clearance; the door test at each square
 * that touches two or more regions.
 * INVARIANTS: a region's peak is the largest clearance among its squares; a door
 * square is in no region; two regions both of peak >= the rule's bound at a square
 * never merge at it. */
#include "utak/body/judgerooms.h"

#include <math.h>
#include <stdlib.h>

#include "utak/base/util.h"

static const float judge_rooms_far = 1e30f;

static void clearance(JudgeRooms *r, const Table *t)
{
	int32_t w = t->w, h = t->h;
	const float d1 = 1.0f, d2 = 1.41421356f;
	for (int64_t i = 0; i < (int64_t)w * h; i++)
		r->clearance[i] = t->owner[i] == TABLE_VERGE ? 0 : judge_rooms_far;
	/* Off the TABLE is verge: the border squares are at most 1 from it. */
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++)
			if ((x == 0 || y == 0 || x == w - 1 || y == h - 1) && r->clearance[(int64_t)y * w + x] > d1)
				r->clearance[(int64_t)y * w + x] = d1;
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++) {
			float *c = &r->clearance[(int64_t)y * w + x];
			if (x > 0 && c[-1] + d1 < *c) *c = c[-1] + d1;
			if (y > 0 && c[-w] + d1 < *c) *c = c[-w] + d1;
			if (x > 0 && y > 0 && c[-w - 1] + d2 < *c) *c = c[-w - 1] + d2;
			if (x < w - 1 && y > 0 && c[-w + 1] + d2 < *c) *c = c[-w + 1] + d2;
		}
	for (int32_t y = h - 1; y >= 0; y--)
		for (int32_t x = w - 1; x >= 0; x--) {
			float *c = &r->clearance[(int64_t)y * w + x];
			if (x < w - 1 && c[1] + d1 < *c) *c = c[1] + d1;
			if (y < h - 1 && c[w] + d1 < *c) *c = c[w] + d1;
			if (x < w - 1 && y < h - 1 && c[w + 1] + d2 < *c) *c = c[w + 1] + d2;
			if (x > 0 && y < h - 1 && c[w - 1] + d2 < *c) *c = c[w - 1] + d2;
		}
}

/* The flood order: by decreasing clearance, ties by index (deterministic). */
static const float *order_clearance;

static int order_cmp(const void *pa, const void *pb)
{
	int64_t a = *(const int64_t *)pa, b = *(const int64_t *)pb;
	float ca = order_clearance[a], cb = order_clearance[b];
	if (ca != cb)
		return ca > cb ? -1 : 1;
	return (a > b) - (a < b);
}

static int64_t find(int64_t *parent, int64_t i)
{
	while (parent[i] != i) {
		parent[i] = parent[parent[i]];
		i = parent[i];
	}
	return i;
}

static bool wide(float peak, float c)
{
	return peak >= JUDGE_ROOM_RATIO * c && peak >= c + JUDGE_ROOM_MARGIN;
}

void judge_rooms_find(JudgeRooms *r, const Table *t)
{
	int32_t w = t->w, h = t->h;
	int64_t n = (int64_t)w * h;
	r->w = w, r->h = h, r->count = 0, r->doors = 0;
	r->room = util_alloc((size_t)n, sizeof *r->room);
	r->clearance = util_alloc((size_t)n, sizeof *r->clearance);
	clearance(r, t);
	int64_t *order = util_alloc((size_t)n, sizeof *order), m = 0;
	int64_t *parent = util_alloc((size_t)n, sizeof *parent);
	float *peak = util_alloc((size_t)n, sizeof *peak);
	uint8_t *state = util_alloc((size_t)n, 1);	/* 0 unflooded, 1 in a region, 2 door */
	for (int64_t i = 0; i < n; i++) {
		state[i] = 0;
		parent[i] = i;
		if (t->owner[i] != TABLE_VERGE)
			order[m++] = i;
	}
	order_clearance = r->clearance;
	qsort(order, (size_t)m, sizeof *order, order_cmp);
	int64_t *doors = util_alloc((size_t)(m > 0 ? m : 1), sizeof *doors);
	for (int64_t j = 0; j < m; j++) {
		int64_t i = order[j], x = i % w, y = i / w, roots[4];
		float c = r->clearance[i];
		int nr = 0;
		int64_t nb[4] = {x > 0 ? i - 1 : -1, x < w - 1 ? i + 1 : -1, y > 0 ? i - w : -1, y < h - 1 ? i + w : -1};
		for (int k = 0; k < 4; k++) {
			if (nb[k] < 0 || state[nb[k]] != 1)
				continue;
			int64_t q = find(parent, nb[k]);
			bool seen = false;
			for (int u = 0; u < nr; u++)
				seen |= roots[u] == q;
			if (!seen)
				roots[nr++] = q;
		}
		/* The widest region first: the others join it unless both are wide. */
		for (int u = 1; u < nr; u++)
			if (peak[roots[u]] > peak[roots[0]]) {
				int64_t s = roots[0];
				roots[0] = roots[u], roots[u] = s;
			}
		int wide_count = 0;
		for (int u = 0; u < nr; u++)
			wide_count += wide(peak[roots[u]], c);
		if (wide_count >= 2) {
			state[i] = 2;
			doors[r->doors++] = i;
			for (int u = 1; u < nr; u++)
				if (!wide(peak[roots[u]], c))
					parent[roots[u]] = roots[0];
			continue;
		}
		state[i] = 1;
		if (nr == 0) {
			peak[i] = c;
			continue;
		}
		parent[i] = roots[0];
		for (int u = 1; u < nr; u++)
			parent[roots[u]] = roots[0];
	}
	/* Number the regions in order of their first square (deterministic). */
	int64_t *label = util_alloc((size_t)n, sizeof *label);
	for (int64_t i = 0; i < n; i++)
		label[i] = -1;
	for (int64_t i = 0; i < n; i++) {
		r->room[i] = JUDGE_ROOM_NONE;
		if (state[i] != 1)
			continue;
		int64_t q = find(parent, i);
		if (label[q] < 0)
			label[q] = r->count++;
		r->room[i] = (int32_t)label[q];
	}
	/* The doorways: free squares near each door square belong to no room. */
	for (int32_t d = 0; d < r->doors; d++) {
		int64_t i = doors[d];
		int32_t dx0 = (int32_t)(i % w), dy0 = (int32_t)(i / w);
		double reach = r->clearance[i] + JUDGE_DOORWAY_REACH;
		int32_t R = (int32_t)ceil(reach);
		for (int32_t y = dy0 - R; y <= dy0 + R; y++)
			for (int32_t x = dx0 - R; x <= dx0 + R; x++)
				if (x >= 0 && y >= 0 && x < w && y < h && hypot(x - dx0, y - dy0) <= reach &&
				    r->clearance[(int64_t)y * w + x] <= r->clearance[i] + JUDGE_DOORWAY_SLACK)
					r->room[(int64_t)y * w + x] = JUDGE_ROOM_NONE;
	}
	free(label);
	free(doors);
	free(state);
	free(peak);
	free(parent);
	free(order);
}

void judge_rooms_free(JudgeRooms *r)
{
	free(r->room);
	free(r->clearance);
	r->room = NULL;
	r->clearance = NULL;
}

int32_t judge_rooms_at(const JudgeRooms *r, int32_t x, int32_t y)
{
	if (x < 0 || y < 0 || x >= r->w || y >= r->h)
		return JUDGE_ROOM_NONE;
	return r->room[(int64_t)y * r->w + x];
}

int32_t judge_rooms_nearest(const JudgeRooms *r, int32_t x, int32_t y)
{
	int32_t got = judge_rooms_at(r, x, y);
	for (int32_t R = 1; got == JUDGE_ROOM_NONE && R < r->w + r->h; R++) {
		double best = INFINITY;
		for (int32_t yy = y - R; yy <= y + R; yy++)
			for (int32_t xx = x - R; xx <= x + R; xx++) {
				int32_t q = judge_rooms_at(r, xx, yy);
				double d = hypot(xx - x, yy - y);
				if (q != JUDGE_ROOM_NONE && d < best)
					best = d, got = q;
			}
	}
	return got;
}
