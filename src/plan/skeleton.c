/* skeleton.c - the exact distance transform and the digital skeleton of free space
 * (paper 4.2; see skeleton.h for the digital topology and the units).
 *
 * ALGORITHM
 * 1. Distance transform: Meijster, Roerdink and Hesselink, "A general algorithm for
 *    computing distance transforms in linear time" (Mathematical Morphology and its
 *    Applications to Image and Signal Processing, 2000). Phase 1 scans every column
 *    for the distance g to the nearest blocked cell in that column; phase 2 takes, in
 *    every row, the lower envelope of the parabolas (x - u)^2 + g(u)^2, found as in
 *    Felzenszwalb and Huttenlocher ("Distance transforms of sampled functions", Theory
 *    of Computing 8, 2012) but with exact integer comparisons in place of divisions,
 *    and run separately on each run of free cells between two blocked ones (a blocked
 *    cell is nearer than anything beyond it). The cells just outside the grid are
 *    blocked: phase 1 starts each column at distance 1 from the rows -1 and h, and
 *    phase 2 has a blocked column at -1 and at w.
 * 2. Thinning: distance-ordered homotopic thinning (Pudney, "Distance-ordered homotopic
 *    thinning: a skeletonization algorithm for 3D digital images", CVIU 72(3), 1998),
 *    here in 2D with the (4, 8) topology. Free cells are visited in order of
 *    increasing dist2 (a counting sort: a bucket queue with all keys known in
 *    advance; ties by cell index, so the result is deterministic). A visited cell is
 *    deleted when it is simple (deleting it changes neither the 4-components of the
 *    set nor the 8-components of its complement: a 256-entry table over the 8
 *    neighbours, built from the definition of Bertrand's topological numbers
 *    T4 = 1 and T8bar = 1) and is not a ridge end (exactly one 4-neighbour in the set
 *    and no 8-neighbour in the set farther from the obstacles: the tip of a branch
 *    where the distance map peaks, as in a dead-end corridor or a niche; Pudney keeps
 *    the centres of maximal discs for the same purpose). A deletion can make an
 *    already visited neighbour deletable; such neighbours go on a stack and are tried
 *    again at once, so when the scan ends no cell of the set is deletable. Visiting in
 *    distance order peels the space like Blum's grassfire, so what is left lies on
 *    the ridge of the distance map, the medial axis.
 * 3. Pruning: a small bay in a wall can still leave a branch whose tip is a ridge end,
 *    a spur. Every branch from an end point to a junction cell (degree >= 3) is
 *    removed when it has at most SKELETON_SPUR_FACTOR * clearance(junction) +
 *    SKELETON_SPUR_SLACK cells (see skeleton.h); branches are judged all at once on
 *    the thinned set, one round, and a branch joining two end points (a component
 *    that is a simple arc) is never removed. Removing a branch that hangs off a
 *    junction changes no topology. Then step 2's deletion test runs again over the
 *    skeleton, because a junction that lost a branch may now be deletable.
 *
 * INVARIANTS (tested in tests/unit/test_skeleton.c against flood-fill oracles)
 *    skeleton cells are free; the skeleton has as many 4-components as the free
 *    space and, in each, as many loops (8-components of its complement not joined to
 *    the outside) as the space has holes; no skeleton cell is deletable by step 2.
 *
 * MEMORY  dist2 and on (5 bytes a cell), and the working space, kept in the Skeleton
 *    for the next grid of the same size: a padded state byte per cell, the visiting
 *    order and a stack (4 bytes a cell each), and the counting-sort histogram (4 bytes
 *    per possible dist2 value: about (shorter side / 2)^2, a quarter of the cells).
 *
 * COMPLEXITY  O(w h): the transform is two passes per axis; the sort is two passes;
 *    every cell is visited once plus once per deleted neighbour (at most 8; 1.1 visits
 *    a free cell on the benchmark grids); pruning walks each branch once.
 *
 * MEASURED  by bench/skelbench.c (CPU time, best of 3, on a 2-core Xeon shared with
 *    other jobs): on 1024 x 1024 rooms, random rectangles and a maze, the transform
 *    9-10 ms and the skeleton with it 28-29 ms; 27-31 ns a cell from 1024 to 4096 a
 *    side (39 on the rectangles at 4096, where the visits' jumps miss the cache). The
 *    thinning is bound by those jumps: a bit-set state and early loads did not help. */
#include "utak/plan/skeleton.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

/* ---------------------------------------------------------------- distance transform */

/* Free runs of a row up to this long are solved by comparing every column with every
 * cell (at most 8 x 8 branch-free steps) instead of the envelope, whose stack
 * branches mispredict on short runs. */
#define SKELETON_SHORT_RUN 8

/* skeleton_edt_count(g, dist2, count): skeleton_edt, also counting the free cells of
 * each dist2 value d in count[d + 1] when count is not NULL (the counting sort's
 * histogram, gathered while the values are made rather than in a pass of its own). */
static int32_t skeleton_edt_count(const Grid *g, int32_t *dist2, int32_t *count)
{
	const int32_t w = g->w, h = g->h;
	assert(w >= 0 && h >= 0 && w <= SKELETON_MAX_SIDE && h <= SKELETON_MAX_SIDE);
	int32_t largest = 0;
	if (w == 0 || h == 0)
		return largest;
	/* Phase 1, row by row so that the inner loop runs along memory: dist2 holds g,
	 * the distance along the column to the nearest blocked cell (or to row -1 / h).
	 * The rows are restrict pointers into one array: they never overlap, and saying
	 * so frees the compiler from reloading after every store (and lets it vectorise
	 * where its options allow; -O2 with GCC 12 does not). */
	for (int32_t x = 0; x < w; x++)
		dist2[x] = g->cells[x] == GRID_FREE ? 1 : 0;
	for (int32_t y = 1; y < h; y++) {
		const uint8_t *restrict c = g->cells + (size_t)y * w;
		int32_t *restrict row = dist2 + (size_t)y * w;
		const int32_t *restrict prev = dist2 + (size_t)(y - 1) * w;
		for (int32_t x = 0; x < w; x++)
			row[x] = c[x] == GRID_FREE ? prev[x] + 1 : 0;
	}
	for (int32_t x = 0; x < w; x++) {
		int32_t *last = dist2 + (size_t)(h - 1) * w;
		if (last[x] > 1)
			last[x] = 1;
	}
	for (int32_t y = h - 2; y >= 0; y--) {
		int32_t *restrict row = dist2 + (size_t)y * w;
		const int32_t *restrict next = dist2 + (size_t)(y + 1) * w;
		for (int32_t x = 0; x < w; x++) {
			int32_t below = next[x] + 1;
			row[x] = below < row[x] ? below : row[x];
		}
	}
	/* Phase 2, one row at a time. A blocked cell at column b (or the outside at -1 and
	 * w) is the nearest obstacle column for every cell across it from the cells
	 * beyond, so the row falls into independent runs of free cells, each solved with
	 * the blocked columns at its two ends. Within a run, with F(u) = u^2 + g(u)^2, the
	 * parabola of column u at x is F(u) - 2 u x + x^2, and two parabolas a < b cross at
	 * (F(b) - F(a)) / (2 (b - a)). The lower envelope's columns are kept in the stack
	 * vu[0 .. top]; a column is dropped when the new one crosses its left neighbour no
	 * later than it does, compared by cross multiplication in 64 bits instead of
	 * Meijster's integer division: exact, and no division on the critical path. The
	 * stack holds each column with its F beside it (vu, vF), so the envelope's loads
	 * run along two arrays instead of through v into F. */
	const int32_t n = w + 2;
	int64_t *vF = util_alloc((size_t)n, sizeof *vF);
	int32_t *vu = util_alloc((size_t)n, sizeof *vu);
	for (int32_t y = 0; y < h; y++) {
		int32_t *row = dist2 + (size_t)y * w;
		int32_t x0 = 0;
		while (x0 < w) {
			if (row[x0] == 0) {
				x0++;
				continue;
			}
			int32_t x1 = x0;
			while (x1 + 1 < w && row[x1 + 1] != 0)
				x1++;
			if (x1 - x0 < 2) {
				/* one or two free cells: each touches a blocked end, at 1 */
				row[x0] = row[x1] = 1;
				largest = largest > 1 ? largest : 1;
				if (count)
					count[2] += x1 - x0 + 1;
				x0 = x1 + 1;
				continue;
			}
			if (x1 - x0 < SKELETON_SHORT_RUN) {
				/* a short run: every column against every cell, no branches (a
				 * vertical corridor's crossing of the row) */
				int32_t g2[SKELETON_SHORT_RUN], out[SKELETON_SHORT_RUN];
				const int32_t len = x1 - x0 + 1;
				for (int32_t i = 0; i < len; i++)
					g2[i] = row[x0 + i] * row[x0 + i];
				for (int32_t i = 0; i < len; i++) {
					int32_t best = (i + 1) * (i + 1); /* the blocked end at x0 - 1 */
					int32_t right = (len - i) * (len - i); /* and at x1 + 1 */
					best = right < best ? right : best;
					for (int32_t j = 0; j < len; j++) {
						int32_t c = (i - j) * (i - j) + g2[j];
						best = c < best ? c : best;
					}
					out[i] = best;
				}
				for (int32_t i = 0; i < len; i++) {
					row[x0 + i] = out[i];
					largest = out[i] > largest ? out[i] : largest;
					if (count)
						count[out[i] + 1]++;
				}
				x0 = x1 + 1;
				continue;
			}
			/* columns lo = x0 - 1 .. hi = x1 + 1, blocked at both ends */
			int32_t lo = x0 - 1, hi = x1 + 1;
			int32_t top = 0;
			vu[0] = lo;
			vF[0] = (int64_t)lo * lo;
			for (int32_t u = x0; u <= hi; u++) {
				int64_t Fu =
				    (int64_t)u * u + (u <= x1 ? (int64_t)row[u] * row[u] : 0);
				while (top > 0) {
					int32_t a = vu[top - 1], b = vu[top];
					int64_t Fa = vF[top - 1], Fb = vF[top];
					/* cross(b, u) <= cross(a, b): b is nowhere lowest */
					if ((Fu - Fb) * (b - a) > (Fb - Fa) * (u - b))
						break;
					top--;
				}
				top++;
				vu[top] = u;
				vF[top] = Fu;
			}
			int32_t k = 0;
			for (int32_t x = x0; x <= x1; x++) {
				/* the lowest parabola at x moves right as x does */
				while (k < top && vF[k + 1] - vF[k] <= 2 * (int64_t)x * (vu[k + 1] - vu[k]))
					k++;
				int32_t d = x - vu[k];
				row[x] = (int32_t)(vF[k] - (int64_t)vu[k] * vu[k]) + d * d;
				if (row[x] > largest)
					largest = row[x];
				if (count)
					count[row[x] + 1]++;
			}
			x0 = x1 + 1;
		}
	}
	free(vF);
	free(vu);
	return largest;
}

int32_t skeleton_edt(const Grid *g, int32_t *dist2) { return skeleton_edt_count(g, dist2, NULL); }

/* skeleton_dist2_bound(w, h): no free cell is farther than this (squared) from the
 * nearest blocked cell, as the ring outside the grid is blocked: in the shorter axis
 * some border is at most (side + 1) / 2 away. */
static size_t skeleton_dist2_bound(int32_t w, int32_t h)
{
	size_t half = (size_t)((w < h ? w : h) + 2) / 2;
	return half * half;
}

/* ---------------------------------------------------------------- simple points */

/* The 8 neighbours in counter-clockwise order from east; even indices are the 4
 * edge neighbours. Bit i of a neighbourhood mask is neighbour i being in the set. */
static const int8_t SKELETON_DX[8] = {1, 1, 0, -1, -1, -1, 0, 1};
static const int8_t SKELETON_DY[8] = {0, 1, 1, 1, 0, -1, -1, -1};

/* skeleton_is_simple_mask(m): Bertrand's T4(p, X) = 1 and T8(p, complement) = 1 for
 * the neighbourhood m, straight from the definitions by a tiny union-find. In the ring
 * of 8 neighbours two cells are 4-adjacent exactly when consecutive; two background
 * cells are 8-adjacent when consecutive or when both are edge neighbours two apart. */
static bool skeleton_is_simple_mask(unsigned m)
{
	int parent[8];
	for (int i = 0; i < 8; i++)
		parent[i] = i;
	for (int i = 0; i < 8; i++) {
		int j = (i + 1) % 8, k = (i + 2) % 8;
		bool fi = (m >> i) & 1, fj = (m >> j) & 1, fk = (m >> k) & 1;
		int a, b;
		if (fi == fj) {
			for (a = i; parent[a] != a; a = parent[a])
				;
			for (b = j; parent[b] != b; b = parent[b])
				;
			parent[a] = b;
		}
		if (!fi && !fk && i % 2 == 0) {
			for (a = i; parent[a] != a; a = parent[a])
				;
			for (b = k; parent[b] != b; b = parent[b])
				;
			parent[a] = b;
		}
	}
	int t4 = 0, t8bar = 0;
	bool seen[8] = {false};
	for (int i = 0; i < 8; i++) {
		int r;
		for (r = i; parent[r] != r; r = parent[r])
			;
		bool fg = (m >> i) & 1;
		/* a foreground component counts for T4 only when it holds an edge neighbour */
		if (fg && i % 2 == 0 && !seen[r]) {
			seen[r] = true;
			t4++;
		}
		if (!fg && !seen[r]) {
			seen[r] = true;
			t8bar++;
		}
	}
	return t4 == 1 && t8bar == 1;
}

/* What one deletion test needs from the 8-neighbourhood mask (one table load). */
enum {
	THIN_KEEP = 0,   /* not simple: deleting would change the topology */
	THIN_DELETE = 1, /* simple, and not one edge neighbour: deletable */
	THIN_RIDGE = 2   /* simple with exactly one edge neighbour: a ridge end or not */
};

/* skeleton_build_kind_table(kind): THIN_* of every mask (see the Thinner). */
static void skeleton_build_kind_table(uint8_t kind[256])
{
	for (unsigned m = 0; m < 256; m++) {
		unsigned edge = (m & 1) + ((m >> 2) & 1) + ((m >> 4) & 1) + ((m >> 6) & 1);
		kind[m] = !skeleton_is_simple_mask(m) ? THIN_KEEP : edge == 1 ? THIN_RIDGE : THIN_DELETE;
	}
}

/* ---------------------------------------------------------------- thinning */

enum {
	SKELETON_IN = 1,      /* still in the set */
	SKELETON_VISITED = 2, /* reached in the distance order */
	SKELETON_STACKED = 4, /* on the re-try stack */
	SKELETON_RECHECK = 8  /* next to a pruned cell: to test again after pruning */
};

/* The thinning works on a copy of the grid padded by one background cell on every
 * side, so that a neighbourhood never needs a bounds check. */
typedef struct Thinner {
	int32_t w, h, pw; /* grid size, padded width w + 2 */
	uint8_t *state;   /* (w + 2) * (h + 2) SKELETON_* bits */
	int32_t off[8];   /* padded index offsets of the 8 neighbours */
	int32_t *stack;   /* padded indices to try again */
	int32_t top;
	const int32_t *dist2; /* w * h, unpadded */
	uint8_t kind[256];    /* THIN_* of each neighbourhood mask */
} Thinner;

/* thinner_mask_of(st, pi, pw): the neighbourhood mask, written out: the offsets are
 * known shapes, so the eight loads issue together (a loop over t->off did not). */
static inline unsigned thinner_mask_of(const uint8_t *st, int32_t pi, int32_t pw)
{
	return (unsigned)(st[pi + 1] & SKELETON_IN) | (unsigned)(st[pi + 1 + pw] & SKELETON_IN) << 1 |
	       (unsigned)(st[pi + pw] & SKELETON_IN) << 2 |
	       (unsigned)(st[pi - 1 + pw] & SKELETON_IN) << 3 | (unsigned)(st[pi - 1] & SKELETON_IN) << 4 |
	       (unsigned)(st[pi - 1 - pw] & SKELETON_IN) << 5 |
	       (unsigned)(st[pi - pw] & SKELETON_IN) << 6 | (unsigned)(st[pi + 1 - pw] & SKELETON_IN) << 7;
}

static inline unsigned thinner_mask(const Thinner *t, int32_t pi)
{
	return thinner_mask_of(t->state, pi, t->pw);
}

/* thinner_ridge_end(t, pi, m): pi, simple with one edge neighbour (mask m), is a
 * ridge end. A ridge end has exactly one 4-neighbour in the set and no 8-neighbour in
 * the set farther from the obstacles: it is the tip of a branch of the medial axis
 * (the distance map has a local maximum there along the branch). Without the second
 * condition every cell of the grassfire front that happens to lose its side
 * neighbours first would be kept as an end, and grow a spur; with it, a branch whose
 * distance rises from its tip (toward a convex corner of the space) burns back to its
 * junction, as Blum's branches into corners carry no choice of route. One division
 * finds the unpadded index; the neighbours are offsets from it. */
static bool thinner_ridge_end(const Thinner *t, int32_t pi, unsigned m)
{
	const int32_t w = t->w;
	const int32_t *d2 = t->dist2 + (size_t)(pi / t->pw - 1) * w + (pi % t->pw - 1);
	const int32_t d = d2[0];
	const int32_t off[8] = {1, 1 + w, w, w - 1, -1, -1 - w, -w, 1 - w};
	for (int i = 0; i < 8; i++)
		if (((m >> i) & 1) && d2[off[i]] > d)
			return false;
	return true;
}

/* thinner_deletable(t, pi): pi is simple and not a ridge end. */
static inline bool thinner_deletable(const Thinner *t, int32_t pi)
{
	unsigned m = thinner_mask(t, pi);
	uint8_t k = t->kind[m];
	return k == THIN_DELETE || (k == THIN_RIDGE && !thinner_ridge_end(t, pi, m));
}

/* thinner_delete_more(t, pi, top): deletes pi, then every visited cell that its
 * deletion (or a later one) makes deletable, with the re-try stack holding top cells
 * already. */
static void thinner_delete_more(Thinner *t, int32_t pi, int32_t top)
{
	t->state[pi] &= (uint8_t)~SKELETON_IN;
	t->top = top;
	for (;;) {
		for (int i = 0; i < 8; i++) {
			int32_t qi = pi + t->off[i];
			uint8_t st = t->state[qi];
			if ((st & (SKELETON_IN | SKELETON_VISITED | SKELETON_STACKED)) ==
			    (SKELETON_IN | SKELETON_VISITED)) {
				t->state[qi] = st | SKELETON_STACKED;
				t->stack[t->top++] = qi;
			}
		}
		/* find the next stacked cell that is deletable now */
		for (;;) {
			if (t->top == 0)
				return;
			pi = t->stack[--t->top];
			t->state[pi] &= (uint8_t)~SKELETON_STACKED;
			if (thinner_deletable(t, pi))
				break;
		}
		t->state[pi] &= (uint8_t)~SKELETON_IN;
	}
}

/* thinner_delete_from(t, pi): deletes pi and whatever that makes deletable. */
static void thinner_delete_from(Thinner *t, int32_t pi) { thinner_delete_more(t, pi, 0); }

/* thinner_visit(t, pi): the visit of pi in the distance order: marks it visited and,
 * when deletable, deletes it (thinner_delete_from). The same as those two calls, with
 * the 8 neighbours loaded once for the deletion test and for the re-try stack: this
 * runs for every free cell. The neighbours to try again, visited and in the set, come
 * as a second mask from the same loads (none is stacked: the stack is empty between
 * visits), so the usual deletion, with none, costs no loop over the neighbours.
 * Every visit is a real one: on the benchmark grids no free cell is interior (all 8
 * neighbours in the set) when its turn comes, as the distance order makes each cell
 * part of the front then; so a border queue would save no visit, and was not built. */
static void thinner_visit(Thinner *t, int32_t pi)
{
	uint8_t *st = t->state;
	const int32_t pw = t->pw;
	const unsigned n[8] = {st[pi + 1],  st[pi + 1 + pw],  st[pi + pw],  st[pi - 1 + pw],
	                       st[pi - 1], st[pi - 1 - pw], st[pi - pw], st[pi + 1 - pw]};
	unsigned m = 0, again = 0;
	for (int i = 0; i < 8; i++) {
		m |= (n[i] & SKELETON_IN) << i;
		again |= ((n[i] >> 1) & n[i] & 1u) << i; /* SKELETON_IN and SKELETON_VISITED */
	}
	st[pi] = (uint8_t)(st[pi] | SKELETON_VISITED);
	const uint8_t k = t->kind[m];
	if (k == THIN_KEEP || (k == THIN_RIDGE && thinner_ridge_end(t, pi, m)))
		return;
	st[pi] &= (uint8_t)~SKELETON_IN;
	if (again == 0)
		return;
	t->top = 0;
	for (int i = 0; i < 8; i++)
		if ((again >> i) & 1) {
			int32_t qi = pi + t->off[i];
			st[qi] = (uint8_t)(st[qi] | SKELETON_STACKED);
			t->stack[t->top++] = qi;
		}
	for (;;) {
		if (t->top == 0)
			return;
		int32_t qi = t->stack[--t->top];
		st[qi] &= (uint8_t)~SKELETON_STACKED;
		if (thinner_deletable(t, qi)) {
			/* rare: a cascade; the stack as it is now is taken over */
			int32_t saved = t->top;
			thinner_delete_more(t, qi, saved);
			return;
		}
	}
}

/* ---------------------------------------------------------------- pruning */

/* thinner_degree(t, pi): the 4-neighbours of pi in the set. */
static int thinner_degree(const Thinner *t, int32_t pi)
{
	return (t->state[pi + t->off[0]] & SKELETON_IN) + (t->state[pi + t->off[2]] & SKELETON_IN) +
	       (t->state[pi + t->off[4]] & SKELETON_IN) + (t->state[pi + t->off[6]] & SKELETON_IN);
}

/* thinner_prune(t, dist2): removes the spurs (see the header comment); returns the
 * number of cells removed. Spurs are found on the set as thinned, then removed. */
static int32_t thinner_prune(Thinner *t, const int32_t *dist2, int32_t *order, int32_t nset)
{
	/* order[0 .. nset) lists the padded indices of the set; cells to remove are
	 * collected at the end of the stack array, which is as long as the grid. */
	int32_t nremove = 0;
	int32_t *remove = t->stack;
	for (int32_t k = 0; k < nset; k++) {
		int32_t end = order[k];
		if (thinner_degree(t, end) != 1)
			continue;
		int32_t prev = -1, cur = end, length = 1;
		bool to_junction = false;
		for (;;) {
			int32_t next = -1;
			for (int i = 0; i < 8; i += 2) {
				int32_t qi = cur + t->off[i];
				if (qi != prev && (t->state[qi] & SKELETON_IN)) {
					next = qi;
					break;
				}
			}
			int d = thinner_degree(t, next);
			if (d >= 3) {
				to_junction = true;
				int32_t jx = next % t->pw - 1, jy = next / t->pw - 1;
				double r = sqrt((double)dist2[(size_t)jy * t->w + jx]);
				if (length > SKELETON_SPUR_FACTOR * r + SKELETON_SPUR_SLACK)
					to_junction = false;
				break;
			}
			if (d <= 1)
				break;
			prev = cur;
			cur = next;
			length++;
		}
		if (!to_junction)
			continue;
		/* walk it again, recording the cells */
		prev = -1;
		cur = end;
		for (;;) {
			remove[nremove++] = cur;
			int32_t next = -1;
			for (int i = 0; i < 8; i += 2) {
				int32_t qi = cur + t->off[i];
				if (qi != prev && (t->state[qi] & SKELETON_IN)) {
					next = qi;
					break;
				}
			}
			if (thinner_degree(t, next) >= 3)
				break;
			prev = cur;
			cur = next;
		}
	}
	for (int32_t k = 0; k < nremove; k++)
		t->state[remove[k]] &= (uint8_t)~SKELETON_IN;
	/* only a cell next to a removed one has a new neighbourhood (every other was
	 * left not deletable by the thinning), so only those are tested again */
	for (int32_t k = 0; k < nremove; k++)
		for (int i = 0; i < 8; i++) {
			uint8_t *q = &t->state[remove[k] + t->off[i]];
			if (*q & SKELETON_IN)
				*q |= SKELETON_RECHECK;
		}
	return nremove;
}

/* ---------------------------------------------------------------- the skeleton */

/* The working space of skeleton_compute, kept between calls so that computing the
 * skeleton of a grid of the same size again touches no new memory. */
struct SkeletonWork {
	size_t cells;   /* the grid size it was made for, w * h */
	uint8_t *state; /* (w + 2) * (h + 2) */
	int32_t *stack; /* w * h */
	int32_t *order; /* w * h */
	int32_t *start; /* start_cap */
	size_t start_cap;
};

void skeleton_init(Skeleton *s)
{
	*s = (Skeleton){0};
}

static void skeleton_free_work(struct SkeletonWork *wk)
{
	if (!wk)
		return;
	free(wk->state);
	free(wk->stack);
	free(wk->order);
	free(wk->start);
	free(wk);
}

void skeleton_free(Skeleton *s)
{
	free(s->dist2);
	free(s->on);
	skeleton_free_work(s->work);
	*s = (Skeleton){0};
}

void skeleton_compute(Skeleton *s, const Grid *g)
{
	const int32_t w = g->w, h = g->h;
	const size_t n = (size_t)w * (size_t)h;
	const size_t pn = (size_t)(w + 2) * (size_t)(h + 2);
	if (!s->dist2 || s->w != w || s->h != h) {
		skeleton_free(s);
		s->dist2 = util_alloc(n, sizeof *s->dist2);
		s->on = util_alloc(n, 1);
		s->work = util_alloc(1, sizeof *s->work);
		s->work->cells = n;
		s->work->state = util_alloc(pn, 1);
		s->work->stack = util_alloc(n, sizeof *s->work->stack);
		s->work->order = util_alloc(n, sizeof *s->work->order);
	}
	s->w = w;
	s->h = h;
	s->count = s->pruned = 0;
	if (n == 0)
		return;
	struct SkeletonWork *wk = s->work;
	/* the histogram is all zero between calls: set up zeroed, cleared after use */
	if (!wk->start) {
		wk->start_cap = skeleton_dist2_bound(w, h) + 2;
		wk->start = util_alloc(wk->start_cap, sizeof *wk->start);
	}
	int32_t *start = wk->start, *order = wk->order;
	const int32_t maxd = skeleton_edt_count(g, s->dist2, start);
	assert((size_t)maxd + 2 <= wk->start_cap);

	Thinner t = {.w = w, .h = h, .pw = w + 2, .dist2 = s->dist2};
	t.state = wk->state;
	memset(t.state, 0, pn);
	t.stack = wk->stack;
	for (int i = 0; i < 8; i++)
		t.off[i] = SKELETON_DX[i] + SKELETON_DY[i] * t.pw;
	skeleton_build_kind_table(t.kind);

	/* counting sort of the free cells by dist2, ties by index (the histogram came
	 * with the distance transform) */
	for (int32_t d = 0; d <= maxd; d++)
		start[d + 1] += start[d];
	const int32_t nfree = start[maxd + 1];
	for (int32_t y = 0; y < h; y++) {
		const uint8_t *c = g->cells + (size_t)y * w;
		const int32_t *d2 = s->dist2 + (size_t)y * w;
		uint8_t *st = t.state + (size_t)(y + 1) * t.pw + 1;
		for (int32_t x = 0; x < w; x++) {
			if (c[x] != GRID_FREE)
				continue;
			st[x] = SKELETON_IN;
			order[start[d2[x]]++] = (y + 1) * t.pw + x + 1;
		}
	}
	memset(start, 0, ((size_t)maxd + 2) * sizeof *start);

	for (int32_t k = 0; k < nfree; k++)
		thinner_visit(&t, order[k]);

	/* the cells left, for pruning, in row-major order (a scan along memory) */
	int32_t nset = 0;
	for (int32_t y = 0; y < h; y++) {
		int32_t row = (y + 1) * t.pw + 1;
		for (int32_t x = 0; x < w; x++)
			if (t.state[row + x] & SKELETON_IN)
				order[nset++] = row + x;
	}
	s->pruned = thinner_prune(&t, s->dist2, order, nset);
	if (s->pruned > 0) {
		/* a junction that lost a branch may be deletable now: the cells marked by
		 * thinner_prune, in the same raster order as a test of every cell (which
		 * it equals: a deletion here retries its neighbours through the stack) */
		for (int32_t k = 0; k < nset; k++) {
			int32_t pi = order[k];
			if (!(t.state[pi] & SKELETON_RECHECK))
				continue;
			t.state[pi] &= (uint8_t)~SKELETON_RECHECK;
			if ((t.state[pi] & SKELETON_IN) && thinner_deletable(&t, pi))
				thinner_delete_from(&t, pi);
		}
	}

	int32_t count = 0; /* a local, so that the loop need not store it every cell */
	for (int32_t y = 0; y < h; y++) {
		const uint8_t *st = t.state + (size_t)(y + 1) * t.pw + 1;
		uint8_t *on = s->on + (size_t)y * w;
		for (int32_t x = 0; x < w; x++) {
			on[x] = st[x] & SKELETON_IN;
			count += on[x];
		}
	}
	s->count = count;
}

int skeleton_degree(const Skeleton *s, int32_t x, int32_t y)
{
	return skeleton_on(s, x + 1, y) + skeleton_on(s, x - 1, y) + skeleton_on(s, x, y + 1) +
	       skeleton_on(s, x, y - 1);
}

double skeleton_clearance(const Skeleton *s, int32_t x, int32_t y)
{
	return sqrt((double)s->dist2[(size_t)y * s->w + x]);
}

/* skeleton_is_pinwheel(s, x, y): the 2x2 block with lower-left cell (x, y) is all
 * skeleton and each of its cells has a skeleton edge neighbour outside the block: the
 * one 2x2 block thinning cannot remove, since each cell is then a branch's root. */
static bool skeleton_is_pinwheel(const Skeleton *s, int32_t x, int32_t y)
{
	return (skeleton_on(s, x - 1, y) || skeleton_on(s, x, y - 1)) &&
	       (skeleton_on(s, x + 2, y) || skeleton_on(s, x + 1, y - 1)) &&
	       (skeleton_on(s, x - 1, y + 1) || skeleton_on(s, x, y + 2)) &&
	       (skeleton_on(s, x + 2, y + 1) || skeleton_on(s, x + 1, y + 2));
}

bool skeleton_validate(const Skeleton *s, const Grid *g)
{
	if (s->w != g->w || s->h != g->h)
		return false;
	int32_t count = 0;
	for (int32_t y = 0; y < s->h; y++)
		for (int32_t x = 0; x < s->w; x++) {
			size_t i = (size_t)y * s->w + x;
			bool free_cell = g->cells[i] == GRID_FREE;
			if ((s->dist2[i] == 0) == free_cell)
				return false;
			if (s->on[i] && !free_cell)
				return false;
			count += s->on[i] != 0;
			if (skeleton_on(s, x, y) && skeleton_on(s, x + 1, y) &&
			    skeleton_on(s, x, y + 1) && skeleton_on(s, x + 1, y + 1) &&
			    !skeleton_is_pinwheel(s, x, y))
				return false;
		}
	return count == s->count;
}

void skeleton_dump(const Skeleton *s, const Grid *g, FILE *out)
{
	int32_t junctions = 0, ends = 0;
	for (int32_t y = s->h - 1; y >= 0; y--) {
		for (int32_t x = 0; x < s->w; x++) {
			char c = grid_free_at(g, x, y) ? '.' : '#';
			if (skeleton_on(s, x, y)) {
				int d = skeleton_degree(s, x, y);
				c = d >= 3 ? '+' : d <= 1 ? '*' : 'o';
				junctions += d >= 3;
				ends += d <= 1;
			}
			fputc(c, out);
		}
		fputc('\n', out);
	}
	fprintf(out, "skeleton: %d cells, %d junction cells, %d end points, %d pruned\n",
	        (int)s->count, (int)junctions, (int)ends, (int)s->pruned);
}
