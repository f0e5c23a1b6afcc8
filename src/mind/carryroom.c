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

void carryroom_merge(const RoomMap *rm, CarryRooms *out)
{
	const Rooms *r = &rm->rooms;
	int32_t n = r->room_count, nd = r->door_count;
	out->count = n;
	out->merged = util_alloc((size_t)(n > 0 ? n : 1), sizeof *out->merged);
	out->peak = util_alloc((size_t)(n > 0 ? n : 1), sizeof *out->peak);
	out->door = util_alloc((size_t)(nd > 0 ? nd : 1), sizeof *out->door);
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
		int32_t lo = a < b ? a : b, hi = a < b ? b : a;
		out->merged[hi] = lo;
		out->peak[lo] = fmax(out->peak[lo], out->peak[hi]);
	}
	/* A door weighed before its rooms were merged with others may now join one
	 * room to itself: no door. */
	for (int32_t k = 0; k < n; k++)
		out->merged[k] = cr_find(out->merged, k);
	for (int32_t q = 0; q < nd; q++)
		out->door[q] = out->door[q] && out->merged[r->doors[q].room_a] != out->merged[r->doors[q].room_b];
	free(key);
	free(order);
}

void carryroom_free(CarryRooms *cr)
{
	free(cr->merged);
	free(cr->door);
	free(cr->peak);
	*cr = (CarryRooms){0};
}

int32_t carryroom_at(const CarryRooms *cr, const RoomMap *rm, int32_t x, int32_t y)
{
	int32_t k = rooms_at(&rm->rooms, x, y);
	return k >= 0 && k < cr->count ? cr->merged[k] : -1;
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
	/* Trim the box: an edge line holding fewer than half the room's cells of the
	 * line inside it is a wall misplaced outwards by the eye, not the corridor's
	 * width (a leg 12 wide would read 13 on one stray square). */
	for (bool again = true; again;) {
		again = false;
		for (int side = 0; side < 4; side++) {
			bool vertical = side < 2; /* a column: x0 (side 0) or x1 (side 1) */
			int32_t edge = side == 0 ? x0 : side == 1 ? x1 : side == 2 ? y0 : y1;
			int32_t inner = side == 0 || side == 2 ? edge + 1 : edge - 1;
			if ((vertical ? x1 - x0 : y1 - y0) < 2)
				continue;
			int32_t ne = 0, ni = 0;
			for (int32_t t = vertical ? y0 : x0; t <= (vertical ? y1 : x1); t++) {
				ne += carryroom_at(cr, rm, vertical ? edge : t, vertical ? t : edge) == room;
				ni += carryroom_at(cr, rm, vertical ? inner : t, vertical ? t : inner) == room;
			}
			if (2 * ne >= ni)
				continue;
			*(side == 0 ? &x0 : side == 1 ? &x1 : side == 2 ? &y0 : &y1) = inner;
			again = true;
		}
	}
	int32_t bw = x1 - x0 + 1, bh = y1 - y0 + 1;
	/* in[(j) * (bw + 1) + i]: the room's cells in [x0, x0 + i) x [y0, y0 + j). */
	int32_t *in = util_alloc((size_t)(bw + 1) * (size_t)(bh + 1), sizeof *in);
	for (int32_t j = 0; j <= bh; j++)
		for (int32_t i = 0; i <= bw; i++) {
			int32_t v = 0;
			if (i > 0 && j > 0)
				v = (carryroom_at(cr, rm, x0 + i - 1, y0 + j - 1) == room) + in[(j - 1) * (bw + 1) + i] +
				    in[j * (bw + 1) + i - 1] - in[(j - 1) * (bw + 1) + i - 1];
			in[j * (bw + 1) + i] = v;
		}
	int32_t total = in[bh * (bw + 1) + bw], out_total = bw * bh - total;
	int32_t best = -1, best_c = 0, best_ex = 0, best_ey = 0;
	for (int c = 0; c < 4; c++) {
		bool east = c & 1, north = c & 2;
		/* The rectangle of ex columns and ey rows held in corner c. */
		for (int32_t ey = 1; ey < bh; ey++)
			for (int32_t ex = 1; ex < bw; ex++) {
				int32_t i0 = east ? bw - ex : 0, i1 = east ? bw : ex;
				int32_t j0 = north ? bh - ey : 0, j1 = north ? bh : ey;
				int32_t inside = in[j1 * (bw + 1) + i1] - in[j0 * (bw + 1) + i1] - in[j1 * (bw + 1) + i0] +
						 in[j0 * (bw + 1) + i0];
				int32_t wrong = inside + out_total - (ex * ey - inside);
				int32_t wa = bw - ex, wb = bh - ey; /* leg A's width (along x), leg B's (along y) */
				if (wa > CARRYROOM_LEG_WIDTH || wb > CARRYROOM_LEG_WIDTH || bh < CARRYROOM_LEG_LENGTH * wa ||
				    bw < CARRYROOM_LEG_LENGTH * wb)
					continue;
				if (best < 0 || wrong < best) {
					best = wrong, best_c = c, best_ex = ex, best_ey = ey;
				}
			}
	}
	free(in);
	if (best < 0 || best > CARRYROOM_BEND_SLACK * (bw + bh))
		return false;
	bool east = best_c & 1, north = best_c & 2;
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
