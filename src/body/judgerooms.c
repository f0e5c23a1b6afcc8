/* judgerooms.c - the judge's rooms: a watershed of clearance with the door rule of
 * doc/verdicts.md (paper 2.3). SIMULATOR SIDE; the rule is in judgerooms.h.
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
#include <string.h>

#include "utak/base/util.h"

static const float judge_rooms_far = 1e30f;

/* across(t, x, y): the width across square (x, y): the shorter of its runs of
 * non-verge squares along x and along y (objects are space to the judge's rooms). */
static int32_t across(const Table *t, int32_t x, int32_t y)
{
	int32_t run[2];
	for (int a = 0; a < 2; a++) {
		int32_t dx = a == 0, dy = a == 1, n = 1;
		for (int s = -1; s <= 1; s += 2)
			for (int32_t k = 1;; k++) {
				int32_t u = x + s * k * dx, v = y + s * k * dy;
				if (u < 0 || v < 0 || u >= t->w || v >= t->h || t->owner[(int64_t)v * t->w + u] == TABLE_VERGE)
					break;
				n++;
			}
		run[a] = n;
	}
	return run[0] < run[1] ? run[0] : run[1];
}

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
	int32_t a = *(const int32_t *)pa, b = *(const int32_t *)pb;
	float ca = order_clearance[a], cb = order_clearance[b];
	if (ca != cb)
		return ca > cb ? -1 : 1;
	return (a > b) - (a < b);
}

static int32_t find(int32_t *parent, int32_t i)
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
	int32_t n = w * h;
	r->w = w, r->h = h, r->count = 0, r->doors = 0;
	r->room = util_alloc((size_t)n, sizeof *r->room);
	r->clearance = util_alloc((size_t)n, sizeof *r->clearance);
	clearance(r, t);
	/* Indices fit 32 bits: utak(5) allows at most 8192 x 4096 squares. */
	int32_t *order = util_alloc((size_t)n, sizeof *order), m = 0;
	int32_t *parent = util_alloc((size_t)n, sizeof *parent);
	float *peak = util_alloc((size_t)n, sizeof *peak);
	uint8_t *state = util_alloc((size_t)n, 1);	/* 0 unflooded, 1 in a region, 2 door */
	for (int32_t i = 0; i < n; i++) {
		state[i] = 0;
		parent[i] = i;
		if (t->owner[i] != TABLE_VERGE)
			order[m++] = i;
	}
	order_clearance = r->clearance;
	qsort(order, (size_t)m, sizeof *order, order_cmp);
	int32_t *doors = util_alloc((size_t)(m > 0 ? m : 1), sizeof *doors);
	for (int32_t j = 0; j < m; j++) {
		int32_t i = order[j], x = i % w, y = i / w, roots[4];
		float c = r->clearance[i];
		int nr = 0;
		int32_t nb[4] = {x > 0 ? i - 1 : -1, x < w - 1 ? i + 1 : -1, y > 0 ? i - w : -1, y < h - 1 ? i + w : -1};
		for (int k = 0; k < 4; k++) {
			if (nb[k] < 0 || state[nb[k]] != 1)
				continue;
			int32_t q = find(parent, nb[k]);
			bool seen = false;
			for (int u = 0; u < nr; u++)
				seen |= roots[u] == q;
			if (!seen)
				roots[nr++] = q;
		}
		/* The widest region first: the others join it unless both are wide. */
		for (int u = 1; u < nr; u++)
			if (peak[roots[u]] > peak[roots[0]]) {
				int32_t s = roots[0];
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
	/* Number the regions in order of their first square (deterministic); the flood
	 * order's array, no longer needed, holds the labels. */
	int32_t *label = order;
	for (int32_t i = 0; i < n; i++)
		label[i] = -1;
	for (int32_t i = 0; i < n; i++) {
		r->room[i] = JUDGE_ROOM_NONE;
		if (state[i] != 1)
			continue;
		int32_t q = find(parent, i);
		if (label[q] < 0)
			label[q] = r->count++;
		r->room[i] = (int32_t)label[q];
	}
	/* The doorways: free squares near each door square belong to no room. */
	for (int32_t d = 0; d < r->doors; d++) {
		int32_t i = doors[d];
		int32_t dx0 = (int32_t)(i % w), dy0 = (int32_t)(i / w);
		double reach = r->clearance[i] + JUDGE_DOORWAY_REACH;
		int32_t R = (int32_t)ceil(reach), width = across(t, dx0, dy0);
		for (int32_t y = dy0 - R; y <= dy0 + R; y++)
			for (int32_t x = dx0 - R; x <= dx0 + R; x++)
				if (x >= 0 && y >= 0 && x < w && y < h && hypot(x - dx0, y - dy0) <= reach &&
				    r->clearance[(int64_t)y * w + x] <= r->clearance[i] + JUDGE_DOORWAY_SLACK &&
				    t->owner[(int64_t)y * w + x] != TABLE_VERGE &&
				    across(t, x, y) <= width + JUDGE_DOORWAY_WIDEN)
					r->room[(int64_t)y * w + x] = JUDGE_ROOM_NONE;
	}
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

/* in(r, room, x, y, box): square (x, y) of the box counts as the room's (the
 * doorway squares inside the box count too: they are free space of the corridor). */
static bool in_room(const JudgeRooms *r, int32_t room, int32_t x, int32_t y)
{
	int32_t q = judge_rooms_at(r, x, y);
	return q == room || (q == JUDGE_ROOM_NONE && r->clearance[(int64_t)y * r->w + x] > 0);
}

bool judge_rooms_bend(const JudgeRooms *r, int32_t room, JudgeBend *b)
{
	int32_t x0 = r->w, y0 = r->h, x1 = -1, y1 = -1;
	for (int32_t y = 0; y < r->h; y++)
		for (int32_t x = 0; x < r->w; x++)
			if (judge_rooms_at(r, x, y) == room) {
				x0 = x < x0 ? x : x0, x1 = x > x1 ? x : x1;
				y0 = y < y0 ? y : y0, y1 = y > y1 ? y : y1;
			}
	if (x1 < 0)
		return false;
	/* The four corners: (cx, cy) the box's corner, (dx, dy) inwards. */
	for (int c = 0; c < 4; c++) {
		int32_t cx = c & 1 ? x1 : x0, cy = c & 2 ? y1 : y0, dx = c & 1 ? -1 : 1, dy = c & 2 ? -1 : 1;
		if (in_room(r, room, cx, cy))
			continue;
		/* The missing rectangle's extent from this corner along each axis. */
		int32_t ex = 0, ey = 0;
		while (cx + dx * ex >= x0 && cx + dx * ex <= x1 && !in_room(r, room, cx + dx * ex, cy))
			ex++;
		while (cy + dy * ey >= y0 && cy + dy * ey <= y1 && !in_room(r, room, cx, cy + dy * ey))
			ey++;
		/* Exactly that rectangle is missing from the box. */
		bool exact = true;
		for (int32_t y = y0; y <= y1 && exact; y++)
			for (int32_t x = x0; x <= x1 && exact; x++) {
				bool out = (x - cx) * dx < ex && (x - cx) * dx >= 0 && (y - cy) * dy < ey && (y - cy) * dy >= 0;
				exact = out != in_room(r, room, x, y);
			}
		if (!exact)
			continue;
		int32_t bw = x1 - x0 + 1, bh = y1 - y0 + 1;
		int32_t wa = bw - ex, wb = bh - ey;	/* leg A's width (along x), leg B's (along y) */
		if (wa < 1 || wb < 1 || wa > JUDGE_LEG_WIDTH || wb > JUDGE_LEG_WIDTH ||
		    bh < JUDGE_LEG_LENGTH * wa || bw < JUDGE_LEG_LENGTH * wb)
			continue;
		/* Leg A: the columns beside the missing rectangle, full height. */
		int32_t ax0 = dx > 0 ? x0 + ex : x0, ax1 = dx > 0 ? x1 : x1 - ex;
		int32_t by0 = dy > 0 ? y0 + ey : y0, by1 = dy > 0 ? y1 : y1 - ey;
		int32_t la[4] = {ax0, y0, ax1, y1}, lb[4] = {x0, by0, x1, by1}, bd[4] = {ax0, by0, ax1, by1};
		memcpy(b->leg[0], la, sizeof la);
		memcpy(b->leg[1], lb, sizeof lb);
		memcpy(b->bend, bd, sizeof bd);
		return true;
	}
	return false;
}
