/* carryroom.c - the rooms and the L-shaped corridor by the verdicts' meaning, on
 * Utak's model (paper 2.3 tasks (vi)-(ix); the rule is in carryroom.h).
 * CONTROLLER SIDE: it reads a room map of the screen only.
 *
 * ALGORITHM. The rooms: the doors sorted by decreasing clearance, a union-find over
 * rooms.h's rooms (path halving; the root the least index, so a merged room's name
 * does not depend on the order of unions) with each set's peak clearance. The bend:
 * for each corner of the room's box, a summed-area table of the room's cells gives,
 * for every rectangle held in that corner, the cells that break the L in O(1): the
 * room's cells inside the rectangle plus the box's other cells outside the room.
 * MEMORY: 13 bytes a rooms.h room and door; the summed-area table, 4 bytes a cell
 * of the box.
 * COMPLEXITY: O(w h) a room map's clearance peaks, O(d log d) the doors, O(box) the
 * bend (each corner's rectangles are as many as the box's cells). */
#include "utak/mind/carryroom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

static int32_t cr_find(int32_t *parent, int32_t i)
{
	while (parent[i] != i) {
		parent[i] = parent[parent[i]];
		i = parent[i];
	}
	return i;
}

/* The doors' clearances, for the sort (decreasing; ties by index). */
static const double *cr_order_key;

static int cr_order_cmp(const void *pa, const void *pb)
{
	int32_t a = *(const int32_t *)pa, b = *(const int32_t *)pb;
	if (cr_order_key[a] != cr_order_key[b])
		return cr_order_key[a] > cr_order_key[b] ? -1 : 1;
	return (a > b) - (a < b);
}

static bool cr_wide(double peak, double c)
{
	return peak >= CARRYROOM_RATIO * c && peak >= c + CARRYROOM_MARGIN;
}

/* cr_merge(rm, open, each, out): carryroom_merge; with open (per rooms.h room: it
 * touches the unknown), a narrowing that fails the rule joins its two sides only
 * when neither side, as merged so far, is open (carryroom_merge_seen); with each
 * too, only when some side is neither wide nor open (carryroom_merge_maybe). */
static void cr_merge(const RoomMap *rm, bool *open, bool each, CarryRooms *out)
{
	const Rooms *r = &rm->rooms;
	int32_t n = r->room_count, nd = r->door_count;
	out->count = n;
	out->merged = util_alloc((size_t)(n > 0 ? n : 1), sizeof *out->merged);
	out->peak = util_alloc((size_t)(n > 0 ? n : 1), sizeof *out->peak);
	out->door = util_alloc((size_t)(nd > 0 ? nd : 1), sizeof *out->door);
	out->undecided = util_alloc((size_t)(nd > 0 ? nd : 1), sizeof *out->undecided);
	memset(out->undecided, 0, (size_t)(nd > 0 ? nd : 1) * sizeof *out->undecided);
	for (int32_t k = 0; k < n; k++) {
		out->merged[k] = k;
		out->peak[k] = 0;
	}
	for (int32_t at = 0; at < r->w * r->h; at++) {
		int32_t k = r->room[at];
		if (k >= 0 && k < n) {
			double c = sqrt((double)rm->skeleton.dist2[at]);
			out->peak[k] = c > out->peak[k] ? c : out->peak[k];
		}
	}
	double *key = util_alloc((size_t)(nd > 0 ? nd : 1), sizeof *key);
	int32_t *order = util_alloc((size_t)(nd > 0 ? nd : 1), sizeof *order);
	for (int32_t q = 0; q < nd; q++) {
		const RoomsDoor *d = &r->doors[q];
		key[q] = sqrt((double)rm->skeleton.dist2[d->y * r->w + d->x]);
		order[q] = q;
	}
	cr_order_key = key;
	qsort(order, (size_t)nd, sizeof *order, cr_order_cmp);
	for (int32_t p = 0; p < nd; p++) {
		int32_t q = order[p];
		const RoomsDoor *d = &r->doors[q];
		int32_t a = cr_find(out->merged, d->room_a), b = cr_find(out->merged, d->room_b);
		out->door[q] = a != b && cr_wide(out->peak[a], key[q]) && cr_wide(out->peak[b], key[q]);
		if (out->door[q] || a == b)
			continue;
		if (open && (each ? (open[a] || cr_wide(out->peak[a], key[q])) && (open[b] || cr_wide(out->peak[b], key[q]))
			       : open[a] || open[b])) {
			out->door[q] = out->undecided[q] = true; /* kept apart until both are seen whole */
			continue;
		}
		int32_t lo = a < b ? a : b, hi = a < b ? b : a;
		out->merged[hi] = lo;
		out->peak[lo] = fmax(out->peak[lo], out->peak[hi]);
		if (open)
			open[lo] = open[lo] || open[hi];
	}
	/* A door weighed before its rooms were merged with others may now join one
	 * room to itself: no door. */
	for (int32_t k = 0; k < n; k++)
		out->merged[k] = cr_find(out->merged, k);
	for (int32_t q = 0; q < nd; q++) {
		out->door[q] = out->door[q] && out->merged[r->doors[q].room_a] != out->merged[r->doors[q].room_b];
		out->undecided[q] = out->undecided[q] && out->door[q];
	}
	free(key);
	free(order);
}

void carryroom_merge(const RoomMap *rm, CarryRooms *out)
{
	cr_merge(rm, NULL, false, out);
}

/* cr_open(rm, s): per rooms.h room of rm, whether a cell of it is 4-adjacent to a
 * square of s never seen (caller frees). */
static bool *cr_open(const RoomMap *rm, const Screen *s)
{
	const Rooms *r = &rm->rooms;
	int32_t n = r->room_count;
	bool *open = util_alloc((size_t)(n > 0 ? n : 1), sizeof *open);
	memset(open, 0, (size_t)(n > 0 ? n : 1) * sizeof *open);
	for (int32_t j = 0; j < r->h; j++)
		for (int32_t i = 0; i < r->w; i++) {
			int32_t k = r->room[j * r->w + i];
			if (k < 0 || k >= n || open[k])
				continue;
			for (int d = 0; d < 4 && !open[k]; d++) {
				int32_t x = i + (d == 0) - (d == 1), y = j + (d == 2) - (d == 3);
				open[k] = x >= 0 && y >= 0 && x < s->w && y < s->h && s->label[y * s->w + x] == SCREEN_UNKNOWN;
			}
		}
	return open;
}

void carryroom_merge_seen(const RoomMap *rm, const Screen *s, CarryRooms *out)
{
	bool *open = cr_open(rm, s);
	cr_merge(rm, open, false, out);
	free(open);
}

void carryroom_merge_maybe(const RoomMap *rm, const Screen *s, CarryRooms *out)
{
	bool *open = cr_open(rm, s);
	cr_merge(rm, open, true, out);
	free(open);
}

void carryroom_free(CarryRooms *cr)
{
	free(cr->merged);
	free(cr->door);
	free(cr->undecided);
	free(cr->peak);
	*cr = (CarryRooms){0};
}

int32_t carryroom_at(const CarryRooms *cr, const RoomMap *rm, int32_t x, int32_t y)
{
	int32_t k = rooms_at(&rm->rooms, x, y);
	return k >= 0 && k < cr->count ? cr->merged[k] : -1;
}

/* cr_leg_width(cr, rm, room, a0, a1, b0, b1, lo, hi, columns): the median, over the
 * lines from lo to hi outside [b0, b1] (rows when columns, else columns), of the
 * room's cells between a0 and a1 on the line; a1 - a0 + 1 when no line is left. */
static int32_t cr_leg_width(const CarryRooms *cr, const RoomMap *rm, int32_t room, int32_t a0, int32_t a1, int32_t b0,
			    int32_t b1, int32_t lo, int32_t hi, bool columns)
{
	int32_t n = 0, *count = util_alloc((size_t)(hi - lo + 1), sizeof *count);
	for (int32_t t = lo; t <= hi; t++) {
		if (t >= b0 && t <= b1)
			continue;
		int32_t k = 0;
		for (int32_t u = a0; u <= a1; u++)
			k += carryroom_at(cr, rm, columns ? u : t, columns ? t : u) == room;
		int32_t at = n++; /* insertion sort: the lines are few */
		for (; at > 0 && count[at - 1] > k; at--)
			count[at] = count[at - 1];
		count[at] = k;
	}
	int32_t w = n ? count[n / 2] : a1 - a0 + 1;
	free(count);
	return w;
}

bool carryroom_bend(const CarryRooms *cr, const RoomMap *rm, int32_t room, CarryBend *b)
{
	const Rooms *r = &rm->rooms;
	int32_t x0 = r->w, y0 = r->h, x1 = -1, y1 = -1;
	for (int32_t y = 0; y < r->h; y++)
		for (int32_t x = 0; x < r->w; x++)
			if (room >= 0 && carryroom_at(cr, rm, x, y) == room) {
				x0 = x < x0 ? x : x0, x1 = x > x1 ? x : x1;
				y0 = y < y0 ? y : y0, y1 = y > y1 ? y : y1;
			}
	if (x1 < 0)
		return false;
	/* The box may be trimmed: an edge line holding fewer than half the room's cells
	 * of the line inside it may be a wall misplaced outwards by the eye (a leg 12
	 * wide would read 13 on one stray square), or the end of a leg beside a
	 * rectangle one line thick. Up to CARRYROOM_TRIM such lines a side are tried;
	 * a trimmed room cell counts as a mismatch, so trimming wins only when it
	 * explains the room better. */
	int32_t tmax[4] = {0, 0, 0, 0}; /* west, east, south, north */
	for (int side = 0; side < 4; side++) {
		bool vertical = side < 2;
		int32_t step = side == 0 || side == 2 ? 1 : -1, edge = side == 0 ? x0 : side == 1 ? x1 : side == 2 ? y0 : y1;
		for (int32_t k = 0; k < CARRYROOM_TRIM; k++) {
			int32_t e = edge + k * step, i = e + step, ne = 0, ni = 0;
			if ((vertical ? x1 - x0 : y1 - y0) < 2 * CARRYROOM_TRIM + 2)
				break;
			for (int32_t t = vertical ? y0 : x0; t <= (vertical ? y1 : x1); t++) {
				ne += carryroom_at(cr, rm, vertical ? e : t, vertical ? t : e) == room;
				ni += carryroom_at(cr, rm, vertical ? i : t, vertical ? t : i) == room;
			}
			if (2 * ne >= ni)
				break;
			tmax[side] = k + 1;
		}
	}
	int32_t fw = x1 - x0 + 1, fh = y1 - y0 + 1;
	/* in[j * (fw + 1) + i]: the room's cells in [x0, x0 + i) x [y0, y0 + j). */
	int32_t *in = util_alloc((size_t)(fw + 1) * (size_t)(fh + 1), sizeof *in);
	for (int32_t j = 0; j <= fh; j++)
		for (int32_t i = 0; i <= fw; i++) {
			int32_t v = 0;
			if (i > 0 && j > 0)
				v = (carryroom_at(cr, rm, x0 + i - 1, y0 + j - 1) == room) + in[(j - 1) * (fw + 1) + i] +
				    in[j * (fw + 1) + i - 1] - in[(j - 1) * (fw + 1) + i - 1];
			in[j * (fw + 1) + i] = v;
		}
#define CR_IN(i0, j0, i1, j1) \
	(in[(j1) * (fw + 1) + (i1)] - in[(j0) * (fw + 1) + (i1)] - in[(j1) * (fw + 1) + (i0)] + in[(j0) * (fw + 1) + (i0)])
	int32_t room_total = in[fh * (fw + 1) + fw];
	int32_t best = -1, best_c = 0, best_ex = 0, best_ey = 0, bt[4] = {0, 0, 0, 0};
	for (int32_t tw = 0; tw <= tmax[0]; tw++)
		for (int32_t te = 0; te <= tmax[1]; te++)
			for (int32_t ts = 0; ts <= tmax[2]; ts++)
				for (int32_t tn = 0; tn <= tmax[3]; tn++) {
					/* The trimmed box [bi0, bi1) x [bj0, bj1), box indices. */
					int32_t bi0 = tw, bi1 = fw - te, bj0 = ts, bj1 = fh - tn, w = bi1 - bi0, h = bj1 - bj0;
					int32_t total = CR_IN(bi0, bj0, bi1, bj1), out_total = w * h - total;
					int32_t cut = room_total - total; /* room cells trimmed off */
					for (int c = 0; c < 4; c++) {
						bool east = c & 1, north = c & 2;
						/* The rectangle of ex columns and ey rows held in corner c. */
						for (int32_t ey = 1; ey < h; ey++)
							for (int32_t ex = 1; ex < w; ex++) {
								int32_t i0 = east ? bi1 - ex : bi0, j0 = north ? bj1 - ey : bj0;
								int32_t inside = CR_IN(i0, j0, i0 + ex, j0 + ey);
								int32_t wrong = inside + out_total - (ex * ey - inside) + cut;
								if (best < 0 || wrong < best) {
									best = wrong, best_c = c, best_ex = ex, best_ey = ey;
									bt[0] = tw, bt[1] = te, bt[2] = ts, bt[3] = tn;
								}
							}
					}
				}
#undef CR_IN
	free(in);
	x0 += bt[0], x1 -= bt[1], y0 += bt[2], y1 -= bt[3];
	int32_t bw = x1 - x0 + 1, bh = y1 - y0 + 1;
	/* The rectangle that fits best must make legs narrow and long enough. A leg's
	 * width is the median, over its lines beyond the bend, of the room's cells
	 * across it: on an exact room the box's (the judge's measure), and on the
	 * model not widened by one stray line of a misplaced wall. */
	bool east = best_c & 1, north = best_c & 2;
	int32_t wa = cr_leg_width(cr, rm, room, east ? x0 : x0 + best_ex, east ? x1 - best_ex : x1,
				  north ? y0 : y0 + best_ey, north ? y1 - best_ey : y1, y0, y1, true);
	int32_t wb = cr_leg_width(cr, rm, room, north ? y0 : y0 + best_ey, north ? y1 - best_ey : y1,
				  east ? x0 : x0 + best_ex, east ? x1 - best_ex : x1, x0, x1, false);
	if (best < 0 || best > CARRYROOM_BEND_SLACK * (bw + bh) || wa > CARRYROOM_LEG_WIDTH + CARRYROOM_EYE_SLACK ||
	    wb > CARRYROOM_LEG_WIDTH + CARRYROOM_EYE_SLACK || bh < CARRYROOM_LEG_LENGTH * (bw - best_ex) || bw < CARRYROOM_LEG_LENGTH * (bh - best_ey))
		return false;
	/* Leg A: the columns beside the missing rectangle, full height; leg B: the
	 * rows beside it, full width. */
	int32_t ax0 = east ? x0 : x0 + best_ex, ax1 = east ? x1 - best_ex : x1;
	int32_t by0 = north ? y0 : y0 + best_ey, by1 = north ? y1 - best_ey : y1;
	int32_t la[4] = {ax0, y0, ax1, y1}, lb[4] = {x0, by0, x1, by1}, bd[4] = {ax0, by0, ax1, by1};
	memcpy(b->leg[0], la, sizeof la);
	memcpy(b->leg[1], lb, sizeof lb);
	memcpy(b->bend, bd, sizeof bd);
	b->mismatch = best;
	return true;
}

/* ---- the verdict's rooms as a watershed (carryroom_watershed) ------------------- */

static const float *ws_key;

/* ws_cmp: decreasing clearance, ties by increasing index. */
static int ws_cmp(const void *pa, const void *pb)
{
	int32_t a = *(const int32_t *)pa, b = *(const int32_t *)pb;
	if (ws_key[a] != ws_key[b])
		return ws_key[a] > ws_key[b] ? -1 : 1;
	return (a > b) - (a < b);
}

/* ws_flood(g, slack, room, clear): carryroom_watershed_slack, and with clear (w h
 * of them) each cell's clearance (0 blocked) kept for the caller. */
static void ws_flood(const Grid *g, double slack, int32_t *room, float *clear)
{
	int32_t w = g->w, h = g->h;
	int64_t n = (int64_t)w * h;
	float *cl = util_alloc((size_t)(n > 0 ? n : 1), sizeof *cl);
	const float d1 = 1.0f, d2 = 1.41421356f;
	/* Clearance: two chamfer passes; off the grid is wall, a square away from
	 * the border cells. */
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++) {
			int64_t i = (int64_t)y * w + x;
			cl[i] = g->cells[i] != GRID_FREE ? 0 : (x == 0 || y == 0 || x == w - 1 || y == h - 1) ? d1 : 1e30f;
		}
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++) {
			float *c = &cl[(int64_t)y * w + x];
			if (x > 0 && c[-1] + d1 < *c) *c = c[-1] + d1;
			if (y > 0 && c[-w] + d1 < *c) *c = c[-w] + d1;
			if (x > 0 && y > 0 && c[-w - 1] + d2 < *c) *c = c[-w - 1] + d2;
			if (x < w - 1 && y > 0 && c[-w + 1] + d2 < *c) *c = c[-w + 1] + d2;
		}
	for (int32_t y = h - 1; y >= 0; y--)
		for (int32_t x = w - 1; x >= 0; x--) {
			float *c = &cl[(int64_t)y * w + x];
			if (x < w - 1 && c[1] + d1 < *c) *c = c[1] + d1;
			if (y < h - 1 && c[w] + d1 < *c) *c = c[w] + d1;
			if (x < w - 1 && y < h - 1 && c[w + 1] + d2 < *c) *c = c[w + 1] + d2;
			if (x > 0 && y < h - 1 && c[w - 1] + d2 < *c) *c = c[w - 1] + d2;
		}
	int32_t *order = util_alloc((size_t)(n > 0 ? n : 1), sizeof *order);
	int32_t *parent = util_alloc((size_t)(n > 0 ? n : 1), sizeof *parent);
	float *peak = util_alloc((size_t)(n > 0 ? n : 1), sizeof *peak);
	uint8_t *state = util_alloc((size_t)(n > 0 ? n : 1), 1); /* 0 not flooded, 1 in a region, 2 door */
	int32_t m = 0;
	for (int32_t i = 0; i < n; i++) {
		parent[i] = i;
		state[i] = 0;
		if (g->cells[i] == GRID_FREE)
			order[m++] = i;
	}
	ws_key = cl;
	qsort(order, (size_t)m, sizeof *order, ws_cmp);
	for (int32_t k = 0; k < m; k++) {
		int32_t i = order[k], x = i % w, y = i / w, roots[4], nr = 0;
		float c = cl[i];
		int32_t nb[4] = {x > 0 ? i - 1 : -1, x < w - 1 ? i + 1 : -1, y > 0 ? i - w : -1, y < h - 1 ? i + w : -1};
		for (int u = 0; u < 4; u++) {
			if (nb[u] < 0 || state[nb[u]] != 1)
				continue;
			int32_t q = cr_find(parent, nb[u]);
			bool dup = false;
			for (int v = 0; v < nr; v++)
				dup |= roots[v] == q;
			if (!dup)
				roots[nr++] = q;
		}
		for (int u = 1; u < nr; u++) /* the widest first */
			if (peak[roots[u]] > peak[roots[0]]) {
				int32_t t = roots[0];
				roots[0] = roots[u];
				roots[u] = t;
			}
		int wide = 0;
		for (int u = 0; u < nr; u++)
			wide += cr_wide(peak[roots[u]] + slack, c);
		if (wide >= 2) {
			state[i] = 2;
			for (int u = 1; u < nr; u++)
				if (!cr_wide(peak[roots[u]] + slack, c))
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
	for (int32_t i = 0; i < n; i++)
		room[i] = state[i] == 1 ? cr_find(parent, i) : -1;
	if (clear)
		memcpy(clear, cl, (size_t)n * sizeof *clear);
	free(state);
	free(peak);
	free(parent);
	free(order);
	free(cl);
}

void carryroom_watershed(const Grid *g, int32_t *room)
{
	ws_flood(g, 0, room, NULL);
}

void carryroom_watershed_clear(const Grid *g, int32_t *room, float *clear)
{
	ws_flood(g, 0, room, clear);
}

void carryroom_watershed_slack(const Grid *g, double slack, int32_t *room)
{
	ws_flood(g, slack, room, NULL);
}

/* ---- beyond the door line (carryroom_beyond) ------------------------------------ */

int64_t carryroom_beyond(const Grid *g, int32_t si, int32_t sj, bool *out)
{
	int32_t w = g->w, h = g->h;
	int64_t n = (int64_t)w * h, got = 0;
	int32_t *room = util_alloc((size_t)(n > 0 ? n : 1), sizeof *room);
	float *cl = util_alloc((size_t)(n > 0 ? n : 1), sizeof *cl);
	ws_flood(g, 0, room, cl);
	/* The start's rooms: the room of the nearest cell in one (the judge's
	 * judge_rooms_nearest: a start in a doorway counts in the nearest room), and,
	 * when the start lies within a door cell's doorway (as the judge's), every
	 * room within 2 of that door cell: the judge's doorway is not the model's,
	 * and its nearest room may be either side. Marked in `mark` (by region root). */
	uint8_t *mark = util_alloc((size_t)(n > 0 ? n : 1), 1);
	memset(mark, 0, (size_t)(n > 0 ? n : 1));
	bool any = false;
	double best = INFINITY;
	int32_t start = -1;
	for (int64_t i = 0; i < n; i++) {
		double d = hypot((double)(i % w) - si, (double)(i / w) - sj);
		if (room[i] >= 0 && d < best)
			best = d, start = room[i];
	}
	if (start >= 0)
		mark[start] = any = true;
	for (int64_t i = 0; i < n; i++) {
		if (g->cells[i] != GRID_FREE || room[i] >= 0)
			continue;
		int32_t x0 = (int32_t)(i % w), y0 = (int32_t)(i / w);
		if (hypot(x0 - si, y0 - sj) > CARRYROOM_CHAMFER * cl[i] + CARRYROOM_DOORWAY_REACH)
			continue;
		for (int32_t y = y0 - 2; y <= y0 + 2; y++)
			for (int32_t x = x0 - 2; x <= x0 + 2; x++)
				if (x >= 0 && y >= 0 && x < w && y < h && room[(int64_t)y * w + x] >= 0)
					mark[room[(int64_t)y * w + x]] = 1;
	}
	for (int64_t i = 0; i < n; i++) {
		out[i] = any && room[i] >= 0 && !mark[room[i]];
		got += out[i];
	}
	free(mark);
	/* Every door cell's doorway, widened: within its clearance (read up to
	 * CARRYROOM_CHAMFER over by the chamfer), the judge's reach and the margin. */
	for (int64_t i = 0; i < n && got > 0; i++) {
		if (g->cells[i] != GRID_FREE || room[i] >= 0)
			continue;
		int32_t x0 = (int32_t)(i % w), y0 = (int32_t)(i / w);
		double reach = CARRYROOM_CHAMFER * cl[i] + CARRYROOM_DOORWAY_REACH + CARRYROOM_DOORWAY_MARGIN;
		int32_t R = (int32_t)ceil(reach);
		for (int32_t y = y0 - R; y <= y0 + R; y++)
			for (int32_t x = x0 - R; x <= x0 + R; x++)
				if (x >= 0 && y >= 0 && x < w && y < h && out[(int64_t)y * w + x] &&
				    hypot(x - x0, y - y0) <= reach) {
					out[(int64_t)y * w + x] = false;
					got--;
				}
	}
	free(cl);
	free(room);
	return got;
}
