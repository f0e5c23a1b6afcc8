/* carry.c - carrying a held object in (x, y, theta): the lattice and its search
 * (paper 2.2, 3.6, 4.3, 5; see carry.h for the model, the guarantees and the use;
 * carrypath.c turns the path found into motor commands; carryproof.c proves a
 * carry impossible by the disc inside the object and says why none was found).
 *
 * ALGORITHM.
 *  1. Footprints (sweep.h), once per plan: for each of the N + 4 layers (N tolerant
 *     angles, 4 exact quarter turns) the body's cells and the object's own cells as
 *     row runs about Utak's cell; for each angle step k -> k + 1 the cells its turn
 *     sweeps. Each layer's slice of the configuration space is the grid eroded by
 *     one footprint (Lozano-Perez 1983; cspace.c), here evaluated lazily: one range
 *     test on per-row prefix sums of blocked cells per run, memoised per
 *     configuration; where the distance transform shows the reach about Utak clear,
 *     no test at all.
 *  2. The estimate: the cells within Chebyshev distance s of the goal region, s the
 *     largest, over the layers, of the least distance from Utak's cell to a cell of
 *     the object (a configuration with the object wholly in the region has Utak
 *     within s of it); then the breadth-first steps from those cells through free
 *     cells: a lower bound on the pushes still needed, consistent.
 *  3. The route (paper 4.3): the pathgraph's shortest path from Utak to the deepest
 *     cell of the goal region through skeleton edges wide enough for the disc
 *     inside the object; the corridor is the Utak cells near it.
 *  4. A* (Hart, Nilsson and Raphael 1968) in the corridor; if that fails, the disc
 *     inside the object may prove that nothing can pass (on cells twice as fine as
 *     the grid's: carryproof.c); else A* on the whole grid, exhaustive when there
 *     is no path. Lazy deletion of stale heap entries.
 *  5. The path, read back from the moves that reached each configuration, as items
 *     for carrypath.c; when none, the reason (carryproof.c, carry_explain).
 *
 * INVARIANTS. A configuration's id is (layer h + y) w + x. g[id] is 0 until the
 * search reaches id, then its best cost + 1; from[id] the move that reached it,
 * with CARRY_CLOSED once expanded (never reopened: the estimate is consistent). The
 * memo bits of known[] and turned[] are set only by the checks that define them.
 * Everything a plan touched is listed and reset, so the planner's arrays are clean
 * between plans without clearing them whole.
 *
 * MEMORY and COMPLEXITY: see carry.h. */
#include "utak/plan/carry.h"

#include "carry_work.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/plan/cspace.h"
#include "utak/plan/heap.h"
#include "utak/plan/path.h"
#include "utak/plan/pathgraph.h"
#include "utak/plan/skeleton.h"
#include "utak/plan/sweep.h"

/* Heap keys: f * 2^24 + (2^24 - 1 - g), so that of equal f the deeper state (larger
 * g) comes first; exact in a double while f < 2^29 (8 million squares of path). */
#define CARRY_KEY_SHIFT 16777216.0
#define CARRY_KEY_G_MAX 16777215

/* The moves, as from[] records them (the low 4 bits). */
enum {
	MOVE_NONE = 0,
	MOVE_EAST, MOVE_NORTH, MOVE_WEST, MOVE_SOUTH,
	MOVE_CCW, MOVE_CW,		/* one angle step, from a tolerant layer */
	MOVE_CCW_EXACT, MOVE_CW_EXACT,	/* one angle step, from an exact layer */
	MOVE_QUARTER_CCW, MOVE_QUARTER_CW, /* exact to exact */
	CARRY_CLOSED = 0x80,
	CARRY_MOVE_MASK = 0x0f,
};
static const int32_t move_dx[5] = {0, 1, 0, -1, 0}, move_dy[5] = {0, 0, 1, 0, -1};

/* known[] bits. */
enum { KNOWN_BODY = 1, BODY_FREE = 2, KNOWN_GOAL = 4, GOAL_HOLDS = 8 };
/* turned[] bits. */
enum { KNOWN_TURN = 1, TURN_FREE = 2 };

/* ---- parameters ------------------------------------------------------------------ */

CarryParams carry_params_default(void)
{
	return (CarryParams){.angles = CARRY_ANGLES_DEFAULT, .turn_weight = 1.0, .exact_start = true,
			     .use_route = true, .use_clearance = true, .use_disc = true};
}

/* ---- the shape ------------------------------------------------------------------- */

/* carry_narrowest(p): the least width of p's convex hull over all directions: for
 * a convex polygon it is attained with a hull edge flush on one side (Toussaint
 * 1983, rotating calipers), so it is the least, over the hull edges, of the
 * farthest vertex from the edge's line. Hull by Andrew's monotone chain. */
static double carry_narrowest(const Polygon *p)
{
	Vec2 pts[GEOM_MAX_VERTICES], hull[2 * GEOM_MAX_VERTICES];
	int32_t n = p->count;
	memcpy(pts, p->v, (size_t)n * sizeof *pts);
	for (int32_t i = 1; i < n; i++) /* insertion sort by (x, y) */
		for (int32_t j = i; j > 0 && (pts[j].x < pts[j - 1].x ||
					      (pts[j].x == pts[j - 1].x && pts[j].y < pts[j - 1].y)); j--) {
			Vec2 t = pts[j];
			pts[j] = pts[j - 1];
			pts[j - 1] = t;
		}
	int32_t m = 0;
	for (int32_t i = 0; i < n; i++) {
		while (m >= 2 && geom_orient(hull[m - 2], hull[m - 1], pts[i]) <= 0)
			m--;
		hull[m++] = pts[i];
	}
	for (int32_t i = n - 2, lower = m + 1; i >= 0; i--) {
		while (m >= lower && geom_orient(hull[m - 2], hull[m - 1], pts[i]) <= 0)
			m--;
		hull[m++] = pts[i];
	}
	m--; /* the last point repeats the first */
	double best = INFINITY;
	for (int32_t i = 0; i < m; i++) {
		Vec2 a = hull[i], b = hull[(i + 1) % m];
		double len = hypot(b.x - a.x, b.y - a.y), far = 0;
		if (len == 0)
			continue;
		for (int32_t j = 0; j < m; j++)
			far = fmax(far, fabs(geom_orient(a, b, hull[j])) / len);
		best = fmin(best, far);
	}
	return best;
}

/* CARRY_DISC_SAMPLES: the inscribed disc is sought at this many sample points
 * across the object's box (per axis): any disc inside the object serves the proof
 * below, a larger one proves more. */
#define CARRY_DISC_SAMPLES 64

/* carry_inscribed(p, &centre): a large disc inside p: the sample point inside p
 * farthest from its edges (a grid of samples over the box); its radius, 0 when no
 * sample falls inside. */
static double carry_inscribed(const Polygon *p, Vec2 *centre)
{
	Box b = geom_polygon_box(p);
	double best = 0, step = fmax(b.hi.x - b.lo.x, b.hi.y - b.lo.y) / CARRY_DISC_SAMPLES;
	*centre = p->v[0];
	for (double y = b.lo.y + step / 2; y < b.hi.y; y += step)
		for (double x = b.lo.x + step / 2; x < b.hi.x; x += step) {
			Vec2 q = vec2(x, y);
			if (!geom_point_in_polygon(p, q))
				continue;
			double d = INFINITY;
			for (int32_t i = 0; i < p->count; i++)
				d = fmin(d, geom_point_segment_distance(q, p->v[i], p->v[(i + 1) % p->count]));
			if (d > best) {
				best = d;
				*centre = q;
			}
		}
	return best;
}

/* ---- the grid's caches ------------------------------------------------------------ */

/* row_prefix(g, out): per row, how many cells before column x are not free:
 * out[y (w + 1) + x], for x = 0 .. w. */
static void row_prefix(const Grid *g, int32_t *out)
{
	for (int32_t y = 0; y < g->h; y++) {
		int32_t *row = out + (size_t)y * (size_t)(g->w + 1);
		const uint8_t *c = g->cells + (size_t)y * (size_t)g->w;
		row[0] = 0;
		for (int32_t x = 0; x < g->w; x++)
			row[x + 1] = row[x] + (c[x] != GRID_FREE);
	}
}

/* fits(prefix, w, h, fp, x, y): fp placed at cell (x, y) covers no counted cell and
 * stays inside the grid. */
static bool fits(const int32_t *prefix, int32_t w, int32_t h, const CSpaceFootprint *fp, int32_t x,
		 int32_t y)
{
	for (int i = 0; i < fp->count; i++) {
		const CSpaceRun *r = &fp->run[i];
		int32_t yy = y + r->dy, x0 = x + r->dx0, x1 = x + r->dx1;
		if (yy < 0 || yy >= h || x0 < 0 || x1 >= w)
			return false;
		const int32_t *row = prefix + (size_t)yy * (size_t)(w + 1);
		if (row[x1 + 1] != row[x0])
			return false;
	}
	return true;
}

void carry_init(CarryPlanner *cp, const Grid *grid, const CarryParams *params)
{
	cp->grid = grid;
	cp->params = params ? *params : carry_params_default();
	CarryWork *k = util_alloc(1, sizeof *k);
	cp->work = k;
	k->w = grid->w;
	k->h = grid->h;
	k->cells = (size_t)grid->w * (size_t)grid->h;
	k->grid_cells = grid->cells;
	k->blocked = util_alloc((size_t)(grid->w + 1) * (size_t)grid->h, sizeof *k->blocked);
	row_prefix(grid, k->blocked);
	k->dist2 = util_alloc(k->cells, sizeof *k->dist2);
	skeleton_edt(grid, k->dist2);
	skeleton_init(&k->skeleton);
	pathgraph_init(&k->graph);
	k->outside = util_alloc((size_t)(grid->w + 1) * (size_t)grid->h, sizeof *k->outside);
	k->steps = util_alloc(k->cells, sizeof *k->steps);
	k->allowed = util_alloc(k->cells, 1);
	for (int32_t l = 0; l < CARRY_LAYERS_MAX; l++) {
		cspace_footprint_init(&k->body[l]);
		cspace_footprint_init(&k->object[l]);
	}
	for (int32_t a = 0; a < CARRY_ANGLES_MAX; a++)
		cspace_footprint_init(&k->sweep[a]);
	heap_init(&k->heap);
}

void carry_free(CarryPlanner *cp)
{
	CarryWork *k = cp->work;
	if (!k)
		return;
	free(k->blocked);
	free(k->dist2);
	skeleton_free(&k->skeleton);
	pathgraph_free(&k->graph);
	free(k->outside);
	free(k->steps);
	free(k->allowed);
	for (int32_t l = 0; l < CARRY_LAYERS_MAX; l++) {
		cspace_footprint_free(&k->body[l]);
		cspace_footprint_free(&k->object[l]);
	}
	for (int32_t a = 0; a < CARRY_ANGLES_MAX; a++)
		cspace_footprint_free(&k->sweep[a]);
	free(k->g);
	free(k->from);
	free(k->known);
	free(k->turned);
	free(k->touched_search.id);
	free(k->touched_known.id);
	free(k->touched_turned.id);
	heap_free(&k->heap);
	free(k);
	cp->work = NULL;
}

void carry_result_init(CarryResult *r) { *r = (CarryResult){.way = -1}; }

void carry_result_free(CarryResult *r)
{
	free(r->plan.pose);
	free(r->plan.cmd);
	carry_result_init(r);
}

/* ---- the footprints --------------------------------------------------------------- */

/* footprints(k): the body, object and sweep footprints of the plan's object. */
static void footprints(CarryWork *k)
{
	SweepWindow win;
	sweep_window_init(&win, (int32_t)ceil(sweep_reach(&k->rel)) + 3);
	for (int32_t l = 0; l < k->layers; l++) {
		int32_t angle = carry_layer_angle(k, l);
		Polygon p = sweep_turned(&k->rel, k->frac, k->deg[angle]);
		sweep_window_clear(&win);
		sweep_cover_polygon(&p, carry_layer_exact(k, l) ? 0 : SWEEP_EPS, sweep_window_span, &win);
		sweep_window_runs(&win, &k->object[l]);
		sweep_window_span(&win, 0, 0, 0); /* Utak's square */
		sweep_window_runs(&win, &k->body[l]);
	}
	for (int32_t a = 0; a < k->angles; a++) {
		sweep_window_clear(&win);
		sweep_cover_turn(&k->rel, k->frac, k->deg[a], k->deg[a + 1], sweep_window_span, &win);
		sweep_window_span(&win, 0, 0, 0);
		sweep_window_runs(&win, &k->sweep[a]);
	}
	sweep_window_free(&win);
}

/* ---- the checks ------------------------------------------------------------------- */

static bool settled(const CarryWork *k, int32_t x, int32_t y)
{
	return k->params->use_clearance && k->dist2[(size_t)y * (size_t)k->w + (size_t)x] > k->settle_dist2;
}

/* carry_body_free(k, layer, x, y): the body fits at configuration (x, y, layer). */
bool carry_body_free(CarryWork *k, int32_t layer, int32_t x, int32_t y)
{
	size_t id = ((size_t)layer * (size_t)k->h + (size_t)y) * (size_t)k->w + (size_t)x;
	uint8_t bits = k->known[id];
	if (bits & KNOWN_BODY)
		return bits & BODY_FREE;
	bool ok;
	if (settled(k, x, y)) {
		ok = true;
		k->stats->settled++;
	} else {
		ok = fits(k->blocked, k->w, k->h, &k->body[layer], x, y);
		k->stats->checked++;
	}
	if (!bits)
		carry_ids_push(&k->touched_known, (int32_t)id);
	k->known[id] = (uint8_t)(bits | KNOWN_BODY | (ok ? BODY_FREE : 0));
	return ok;
}

/* turn_free(k, angle, x, y): the turn from angle to angle + 1 at cell (x, y) sweeps
 * only free cells. */
static bool turn_free(CarryWork *k, int32_t angle, int32_t x, int32_t y)
{
	size_t id = ((size_t)angle * (size_t)k->h + (size_t)y) * (size_t)k->w + (size_t)x;
	uint8_t bits = k->turned[id];
	if (bits & KNOWN_TURN)
		return bits & TURN_FREE;
	bool ok;
	if (settled(k, x, y)) {
		ok = true;
		k->stats->settled++;
	} else {
		ok = fits(k->blocked, k->w, k->h, &k->sweep[angle], x, y);
		k->stats->checked++;
	}
	carry_ids_push(&k->touched_turned, (int32_t)id);
	k->turned[id] = (uint8_t)(KNOWN_TURN | (ok ? TURN_FREE : 0));
	return ok;
}

/* carry_turn_run_free(k, angle, steps, x, y): a turn of steps angle steps (signed) from
 * angle, at (x, y). */
bool carry_turn_run_free(CarryWork *k, int32_t angle, int32_t steps, int32_t x, int32_t y)
{
	int32_t n = k->angles;
	for (int32_t i = 0; i < abs(steps); i++) {
		int32_t a = steps > 0 ? (angle + i) % n : ((angle - 1 - i) % n + n) % n;
		if (!turn_free(k, a, x, y))
			return false;
	}
	return true;
}

static CarryPose pose_of(const CarryWork *k, int32_t layer, int32_t x, int32_t y)
{
	return (CarryPose){.at = vec2(x + k->frac.x, y + k->frac.y), .x = x, .y = y,
			   .deg = k->deg[carry_layer_angle(k, layer)], .exact = carry_layer_exact(k, layer)};
}

/* carry_goal_holds(k, layer, x, y): a free configuration is a goal. */
bool carry_goal_holds(CarryWork *k, int32_t layer, int32_t x, int32_t y)
{
	size_t id = ((size_t)layer * (size_t)k->h + (size_t)y) * (size_t)k->w + (size_t)x;
	uint8_t bits = k->known[id];
	if (bits & KNOWN_GOAL)
		return bits & GOAL_HOLDS;
	const CarryGoal *goal = k->goal;
	bool ok = fits(k->outside, k->w, k->h, &k->object[layer], x, y) &&
		  (!goal->utak_inside || grid_free_at(goal->inside, x, y));
	if (ok && goal->accept) {
		CarryPose pose = pose_of(k, layer, x, y);
		ok = goal->accept(goal->ctx, &pose);
	}
	if (!bits)
		carry_ids_push(&k->touched_known, (int32_t)id);
	k->known[id] = (uint8_t)(bits | KNOWN_GOAL | (ok ? GOAL_HOLDS : 0));
	return ok;
}

/* ---- the estimate ----------------------------------------------------------------- */

/* estimate(k): k->steps, the breadth-first steps through allowed free cells from
 * the cells within Chebyshev distance s of the goal region (see ALGORITHM). */
static void estimate(CarryWork *k)
{
	const Grid *g = k->goal->inside;
	int32_t w = k->w, h = k->h;
	int32_t s = 0;
	for (int32_t l = 0; l < k->layers; l++) {
		int32_t least = INT32_MAX;
		for (int i = 0; i < k->object[l].count; i++) {
			const CSpaceRun *r = &k->object[l].run[i];
			int32_t dx = r->dx0 > 0 ? r->dx0 : r->dx1 < 0 ? -r->dx1 : 0;
			int32_t d = abs(r->dy) > dx ? abs(r->dy) : dx;
			least = d < least ? d : least;
		}
		if (least != INT32_MAX && least > s)
			s = least;
	}
	/* Chebyshev distance to the region: two chamfer passes with unit weights on
	 * all eight neighbours are exact for it. */
	int32_t *cheb = k->steps;
	const int32_t far = INT32_MAX / 2;
	for (int32_t y = 0; y < h; y++)
		for (int32_t x = 0; x < w; x++) {
			int32_t v = grid_free_at(g, x, y) ? 0 : far;
			for (int32_t dy = -1; dy <= 0; dy++)
				for (int32_t dx = -1; dx <= 1; dx++) {
					if ((dy == 0 && dx >= 0) || x + dx < 0 || x + dx >= w || y + dy < 0)
						continue;
					int32_t u = cheb[(size_t)(y + dy) * w + (x + dx)] + 1;
					v = u < v ? u : v;
				}
			cheb[(size_t)y * w + x] = v;
		}
	for (int32_t y = h - 1; y >= 0; y--)
		for (int32_t x = w - 1; x >= 0; x--) {
			int32_t v = cheb[(size_t)y * w + x];
			for (int32_t dy = 0; dy <= 1; dy++)
				for (int32_t dx = -1; dx <= 1; dx++) {
					if ((dy == 0 && dx <= 0) || x + dx < 0 || x + dx >= w || y + dy >= h)
						continue;
					int32_t u = cheb[(size_t)(y + dy) * w + (x + dx)] + 1;
					v = u < v ? u : v;
				}
			cheb[(size_t)y * w + x] = v;
		}
	/* Breadth-first from the seeds, in place: steps[] is -1 until reached. */
	int32_t *queue = util_alloc(k->cells, sizeof *queue);
	size_t head = 0, tail = 0;
	for (size_t i = 0; i < k->cells; i++) {
		bool seed = cheb[i] <= s && k->allowed[i] && k->grid_cells[i] == GRID_FREE;
		if (seed)
			queue[tail++] = (int32_t)i;
		cheb[i] = seed ? 0 : -1;
	}
	while (head < tail) {
		int32_t i = queue[head++], x = i % w, y = i / w;
		for (int m = 1; m <= 4; m++) {
			int32_t nx = x + move_dx[m], ny = y + move_dy[m];
			if (nx < 0 || ny < 0 || nx >= w || ny >= h)
				continue;
			size_t j = (size_t)ny * w + nx;
			if (k->steps[j] >= 0 || !k->allowed[j] || k->grid_cells[j] != GRID_FREE)
				continue;
			k->steps[j] = k->steps[i] + 1;
			queue[tail++] = (int32_t)j;
		}
	}
	free(queue);
}

/* ---- the route ---------------------------------------------------------------------- */

/* corridor(k, grid, at, radius, reach, &narrowest): k->allowed := the Utak cells
 * within reach + CARRY_CORRIDOR_MARGIN of the skeleton route from at to the deepest
 * cell of the goal region (see ALGORITHM), a route on skeleton edges wide enough for
 * the disc of that radius inside the object; narrowest := the least clearance (cell
 * centre to blocked centre) of the cells it crosses on the skeleton (not on its way
 * from Utak to the skeleton and from it to the goal), if less. False, with allowed
 * untouched, when there is none. */
static bool corridor(CarryWork *k, const Grid *grid, Vec2 at, double radius, double reach, double *narrowest)
{
	if (!k->have_graph) {
		skeleton_compute(&k->skeleton, grid);
		pathgraph_build(&k->graph, &k->skeleton, grid);
		k->have_graph = true;
	}
	int32_t w = k->w;
	Grid scratch;
	grid_init(&scratch, k->w, k->h, GRID_BLOCKED);
	for (size_t i = 0; i < k->cells; i++)
		if (k->grid_cells[i] == GRID_FREE && k->goal->inside->cells[i] == GRID_FREE)
			scratch.cells[i] = GRID_FREE;
	int32_t *d2 = util_alloc(k->cells, sizeof *d2);
	skeleton_edt(&scratch, d2);
	size_t deepest = 0;
	for (size_t i = 1; i < k->cells; i++)
		if (d2[i] > d2[deepest])
			deepest = i;
	bool found = false;
	Path route;
	path_init(&route);
	if (d2[deepest] > 0) {
		/* The disc inside the object fits about no point of a cell whose centre is
		 * less than radius - 0.21 from a blocked centre (disc_cannot_pass says
		 * why): skip the skeleton edges with such cells. (The hull's narrowest
		 * width would be no bound: an L-shape passes doors narrower than it.) */
		double need = radius - (sqrt(2.0) / 2 - 0.5);
		PathgraphQuery q = {.min_clearance = need > 0 ? need : 0};
		Vec2 to = vec2((double)(deepest % (size_t)w) + 0.5, (double)(deepest / (size_t)w) + 0.5);
		found = pathgraph_find_path(&k->graph, at, to, &q, &route);
	}
	if (found) {
		/* The route's cells, by samples a quarter square apart; then each cell's
		 * distance to them. */
		memset(scratch.cells, GRID_FREE, k->cells);
		for (int i = 0; i + 1 < route.count; i++) {
			Vec2 a = route.pts[i], b = route.pts[i + 1];
			int32_t n = (int32_t)ceil(hypot(b.x - a.x, b.y - a.y) / 0.25) + 1;
			for (int32_t j = 0; j <= n; j++) {
				Vec2 p = vec2_add(a, vec2_scale(vec2_sub(b, a), (double)j / n));
				int32_t x = (int32_t)floor(p.x), y = (int32_t)floor(p.y);
				if (x >= 0 && y >= 0 && x < k->w && y < k->h) {
					scratch.cells[(size_t)y * w + x] = GRID_BLOCKED;
					if (i >= 1 && i + 2 < route.count) /* on the skeleton */
						*narrowest = fmin(*narrowest, sqrt((double)k->dist2[(size_t)y * w + x]));
				}
			}
		}
		skeleton_edt(&scratch, d2);
		double r = reach + CARRY_CORRIDOR_MARGIN;
		k->stats->corridor_cells = 0;
		for (size_t i = 0; i < k->cells; i++) {
			k->allowed[i] = (double)d2[i] <= r * r;
			k->stats->corridor_cells += k->allowed[i];
		}
	}
	path_free(&route);
	free(d2);
	grid_free(&scratch);
	return found;
}

/* ---- the disc ------------------------------------------------------------------------ */

/* A route whose narrowest place is less than this many squares wider (in clearance)
 * than the disc's radius is tight: the proof is tried before the corridor search. */
#define CARRY_DISC_TIGHT 1.0

/* ---- the search --------------------------------------------------------------------- */

static double key_of(int64_t g, int64_t f)
{
	return (double)f * CARRY_KEY_SHIFT + (double)(CARRY_KEY_G_MAX - (g < CARRY_KEY_G_MAX ? g : CARRY_KEY_G_MAX));
}

/* relax(k, id, g, move): reach configuration id at cost g by move. */
static void relax(CarryWork *k, int32_t id, int64_t g, int move)
{
	uint32_t old = k->g[id];
	if (old != 0 && ((k->from[id] & CARRY_CLOSED) || (int64_t)old - 1 <= g))
		return;
	if (old == 0)
		carry_ids_push(&k->touched_search, id);
	assert(g < UINT32_MAX - 1);
	k->g[id] = (uint32_t)(g + 1);
	k->from[id] = (uint8_t)move;
	int32_t cell = (int32_t)((size_t)id % k->cells);
	heap_push(&k->heap, key_of(g, g + (int64_t)CARRY_UNIT * k->steps[cell]), id);
}

/* search(k, start): A* from configuration start; the goal configuration reached, or
 * -1 when none is reachable. */
static int32_t search(CarryWork *k, int32_t start)
{
	int32_t n = k->angles, quarter = n / CARRY_QUARTERS;
	heap_clear(&k->heap);
	k->stats->searches++;
	relax(k, start, 0, MOVE_NONE);
	while (k->heap.count > 0) {
		int32_t id = heap_pop(&k->heap);
		if (k->from[id] & CARRY_CLOSED)
			continue;
		k->from[id] |= CARRY_CLOSED;
		k->stats->expanded++;
		int32_t layer = (int32_t)((size_t)id / k->cells), cell = (int32_t)((size_t)id % k->cells);
		int32_t x = cell % k->w, y = cell / k->w;
		if (carry_goal_holds(k, layer, x, y))
			return id;
		int64_t g = (int64_t)k->g[id] - 1;
		size_t base = (size_t)layer * k->cells;
		for (int m = MOVE_EAST; m <= MOVE_SOUTH; m++) {
			int32_t nx = x + move_dx[m], ny = y + move_dy[m];
			if (nx < 0 || ny < 0 || nx >= k->w || ny >= k->h)
				continue;
			size_t c = (size_t)ny * k->w + nx;
			if (!k->allowed[c] || k->steps[c] < 0 || !carry_body_free(k, layer, nx, ny))
				continue;
			relax(k, (int32_t)(base + c), g + CARRY_UNIT, m);
		}
		int32_t angle = carry_layer_angle(k, layer);
		bool exact = carry_layer_exact(k, layer);
		int32_t ccw = (angle + 1) % n, cw = (angle + n - 1) % n;
		if (turn_free(k, angle, x, y))
			relax(k, (int32_t)((size_t)ccw * k->cells + cell), g + k->turn_cost[angle],
			      exact ? MOVE_CCW_EXACT : MOVE_CCW);
		if (turn_free(k, cw, x, y))
			relax(k, (int32_t)((size_t)cw * k->cells + cell), g + k->turn_cost[cw],
			      exact ? MOVE_CW_EXACT : MOVE_CW);
		if (!exact)
			continue;
		int64_t up = 0, down = 0;
		for (int32_t i = 0; i < quarter; i++) {
			up += k->turn_cost[(angle + i) % n];
			down += k->turn_cost[(angle + n - 1 - i) % n];
		}
		if (carry_turn_run_free(k, angle, quarter, x, y))
			relax(k, (int32_t)((size_t)carry_exact_layer(k, (angle + quarter) % n) * k->cells + cell), g + up,
			      MOVE_QUARTER_CCW);
		if (carry_turn_run_free(k, angle, -quarter, x, y))
			relax(k, (int32_t)((size_t)carry_exact_layer(k, (angle + n - quarter) % n) * k->cells + cell),
			      g + down, MOVE_QUARTER_CW);
	}
	return -1;
}

/* predecessor(k, id, &turn): the configuration from which move from[id] reached id;
 * turn receives the move's signed angle steps (0 for a push). */
static int32_t predecessor(const CarryWork *k, int32_t id, int32_t *turn)
{
	int32_t n = k->angles, quarter = n / CARRY_QUARTERS;
	int32_t layer = (int32_t)((size_t)id / k->cells), cell = (int32_t)((size_t)id % k->cells);
	int32_t angle = carry_layer_angle(k, layer), move = k->from[id] & CARRY_MOVE_MASK, prev;
	*turn = 0;
	switch (move) {
	case MOVE_EAST:
	case MOVE_NORTH:
	case MOVE_WEST:
	case MOVE_SOUTH:
		return id - move_dx[move] - move_dy[move] * k->w;
	case MOVE_CCW:
	case MOVE_CCW_EXACT:
		*turn = 1;
		prev = (angle + n - 1) % n;
		break;
	case MOVE_CW:
	case MOVE_CW_EXACT:
		*turn = -1;
		prev = (angle + 1) % n;
		break;
	case MOVE_QUARTER_CCW:
		*turn = quarter;
		prev = (angle + n - quarter) % n;
		break;
	case MOVE_QUARTER_CW:
		*turn = -quarter;
		prev = (angle + quarter) % n;
		break;
	default:
		assert(!"no predecessor of the start");
		return -1;
	}
	bool from_exact = move == MOVE_CCW_EXACT || move == MOVE_CW_EXACT || move == MOVE_QUARTER_CCW ||
			  move == MOVE_QUARTER_CW;
	int32_t prev_layer = from_exact ? carry_exact_layer(k, prev) : prev;
	return (int32_t)((size_t)prev_layer * k->cells + (size_t)cell);
}

static void reset_search(CarryWork *k)
{
	for (int i = 0; i < k->touched_search.count; i++) {
		k->g[k->touched_search.id[i]] = 0;
		k->from[k->touched_search.id[i]] = 0;
	}
	k->touched_search.count = 0;
}

static void reset_checks(CarryWork *k)
{
	for (int i = 0; i < k->touched_known.count; i++)
		k->known[k->touched_known.id[i]] = 0;
	for (int i = 0; i < k->touched_turned.count; i++)
		k->turned[k->touched_turned.id[i]] = 0;
	k->touched_known.count = k->touched_turned.count = 0;
}

/* ---- the plan ------------------------------------------------------------------------ */

void carry_items_push(CarryItems *l, CarryItem it)
{
	l->item = util_grow(l->item, &l->cap, l->count + 1, sizeof *l->item);
	l->item[l->count++] = it;
}

/* extract(k, start, goal_id, plan): the lattice path, merged and emitted. */
static void extract(CarryWork *k, int32_t start, int32_t goal_id, CarryPlan *plan)
{
	CarryItems rev = {0}, l = {0};
	for (int32_t id = goal_id; id != start;) {
		int32_t turn, cell = (int32_t)((size_t)id % k->cells);
		int32_t prev = predecessor(k, id, &turn);
		carry_items_push(&rev, (CarryItem){turn, cell % k->w, cell / k->w});
		id = prev;
	}
	for (int i = rev.count - 1; i >= 0; i--) {
		CarryItem it = rev.item[i];
		if (it.turn != 0 && l.count > 0 && l.item[l.count - 1].turn != 0)
			l.item[l.count - 1].turn += it.turn;
		else
			carry_items_push(&l, it);
		if (l.item[l.count - 1].turn == 0 && it.turn != 0)
			l.count--; /* a turn and its undoing */
	}
	int32_t sx = (int32_t)((size_t)start % k->cells) % k->w, sy = (int32_t)((size_t)start % k->cells) / k->w;
	plan->cost = (int64_t)k->g[goal_id] - 1;
	carry_path_commands(k, &l, sx, sy, plan);
	free(rev.item);
	free(l.item);
}

/* ---- the calls ---------------------------------------------------------------------- */

/* check_problem(cp, obj, goal, why, size): a malformed problem, said in why. */
static bool check_problem(const CarryPlanner *cp, const CarryObject *obj, const CarryGoal *goal, char *why,
			  size_t size)
{
	const Grid *g = cp->grid;
	int32_t n = cp->params.angles;
	if (n < CARRY_QUARTERS || n > CARRY_ANGLES_MAX || n % CARRY_QUARTERS != 0)
		snprintf(why, size, "angles must be a multiple of 4 from 4 to %d, not %d", CARRY_ANGLES_MAX, n);
	else if (!(cp->params.turn_weight >= 0 && cp->params.turn_weight < 1e6))
		snprintf(why, size, "turn weight must be from 0 to 1e6");
	else if (g->w <= 0 || g->h <= 0 || g->w > SKELETON_MAX_SIDE || g->h > SKELETON_MAX_SIDE)
		snprintf(why, size, "the grid must be 1 to %d cells a side", SKELETON_MAX_SIDE);
	else if ((int64_t)(n + CARRY_QUARTERS) * g->w * g->h > INT32_MAX)
		snprintf(why, size, "the grid is too large for %d angles", n);
	else if (!goal || !goal->inside || goal->inside->w != g->w || goal->inside->h != g->h)
		snprintf(why, size, "the goal region must be a grid of the grid's size");
	else if (obj->shape.count < 3 || obj->shape.count > GEOM_MAX_VERTICES || !geom_polygon_is_simple(&obj->shape))
		snprintf(why, size, "the object must be a simple polygon");
	else if (!(obj->at.x >= 0 && obj->at.y >= 0 && obj->at.x < g->w && obj->at.y < g->h))
		snprintf(why, size, "Utak's point must lie on the grid");
	else if (geom_point_in_polygon(&obj->shape, obj->at))
		snprintf(why, size, "Utak's point lies inside the object");
	else
		return true;
	return false;
}

/* prepare(k, cp, obj, goal, out): the plan's object and goal into k. */
static void prepare(CarryWork *k, const CarryPlanner *cp, const CarryObject *obj, const CarryGoal *goal,
		    CarryResult *out)
{
	const CarryParams *pr = &cp->params;
	k->params = pr;
	k->stats = &out->stats;
	k->goal = goal;
	k->exact_start = pr->exact_start;
	int32_t n = pr->angles;
	if (k->g && k->allocated_angles != n) {
		/* cp->params.angles changed since the last plan: arrays of a new size. */
		free(k->g);
		free(k->from);
		free(k->known);
		free(k->turned);
		k->g = NULL;
	}
	if (!k->g) {
		k->allocated_angles = n;
		size_t configs = (size_t)(n + CARRY_QUARTERS) * k->cells;
		k->g = util_alloc(configs, sizeof *k->g);
		k->from = util_alloc(configs, 1);
		k->known = util_alloc(configs, 1);
		k->turned = util_alloc((size_t)n * k->cells, 1);
	}
	k->angles = n;
	k->layers = n + (pr->exact_start ? CARRY_QUARTERS : 0);
	for (int32_t a = 0; a <= n; a++)
		k->deg[a] = (int32_t)floor(a * 360.0 / n + 0.5);
	k->rel = obj->shape;
	for (int32_t i = 0; i < k->rel.count; i++)
		k->rel.v[i] = vec2_sub(obj->shape.v[i], obj->at);
	k->frac = vec2(obj->at.x - floor(obj->at.x), obj->at.y - floor(obj->at.y));
	out->reach = sweep_reach(&k->rel);
	out->narrowest = carry_narrowest(&obj->shape);
	for (int32_t a = 0; a < n; a++) {
		double travel = out->reach * (k->deg[a + 1] - k->deg[a]) * (CARRY_PI / 180.0);
		double cost = floor(CARRY_UNIT * travel * pr->turn_weight + 0.5);
		k->turn_cost[a] = cost < 1 ? 1 : (int32_t)cost;
	}
	/* Everything within this of his cell's centre is free when the distance
	 * transform says so (skeleton.h: the open disc of radius clearance - sqrt 2 / 2
	 * meets no blocked square): his point's offset, the reach, and the sweeps'
	 * thickening. */
	double r = out->reach + hypot(k->frac.x - 0.5, k->frac.y - 0.5) + SWEEP_TRAVEL / 2 + 2 * SWEEP_EPS +
		   sqrt(2.0) / 2;
	k->settle_dist2 = r * r < INT32_MAX ? (int32_t)floor(r * r) : INT32_MAX;
	footprints(k);
	row_prefix(goal->inside, k->outside);
}

CarryStatus carry_plan(CarryPlanner *cp, const CarryObject *obj, const CarryGoal *goal, CarryResult *out)
{
	CarryWork *k = cp->work;
	CarryPlan plan = out->plan;
	carry_result_init(out);
	out->plan = (CarryPlan){.pose = plan.pose, .cmd = plan.cmd, .cap = plan.cap};
	if (!check_problem(cp, obj, goal, out->why, sizeof out->why))
		return out->status = CARRY_BAD_INPUT;
	const char *name = obj->name ? obj->name : "the object";
	prepare(k, cp, obj, goal, out);
	int32_t sx = (int32_t)floor(obj->at.x), sy = (int32_t)floor(obj->at.y);
	int32_t start_layer = k->exact_start ? carry_exact_layer(k, 0) : 0;
	int32_t start = (int32_t)((size_t)start_layer * k->cells + (size_t)sy * k->w + sx);
	int32_t found = -1;
	out->status = CARRY_NO_PATH;
	if (!carry_body_free(k, start_layer, sx, sy)) {
		snprintf(out->why, sizeof out->why, "%s does not fit where it stands: a square it or Utak covers is not free",
			 name);
		goto done;
	}
	Vec2 centre;
	out->disc = carry_inscribed(&obj->shape, &centre);
	/* Where the route squeezes past a place hardly wider than the disc inside the
	 * object, the disc's proof comes first: it is cheaper than a corridor search
	 * that may find nothing. */
	double narrowest = INFINITY;
	bool routed = cp->params.use_route && corridor(k, cp->grid, obj->at, out->disc, out->reach, &narrowest);
	bool tight = narrowest < out->disc + CARRY_DISC_TIGHT;
	if (routed && tight && cp->params.use_disc && carry_disc_cannot_pass(k, centre, out->disc))
		goto disc_proof;
	if (routed) {
		out->stats.routed = true;
		estimate(k);
		if (k->steps[(size_t)sy * k->w + sx] >= 0)
			found = search(k, start);
		out->stats.found_in_corridor = found >= 0;
		if (found < 0)
			reset_search(k);
	}
	/* Before the whole grid is searched, the disc may prove it in vain. */
	if (found < 0 && cp->params.use_disc && !(routed && tight) && carry_disc_cannot_pass(k, centre, out->disc)) {
	disc_proof:
		out->stats.disc_proof = true;
		memset(k->allowed, 1, k->cells);
		estimate(k);
		carry_explain(k, start_layer, sx, sy, name, out);
		goto done;
	}
	if (found < 0) {
		memset(k->allowed, 1, k->cells);
		estimate(k);
		if (k->steps[(size_t)sy * k->w + sx] < 0) {
			bool any = false;
			for (size_t c = 0; c < k->cells && !any; c++)
				any = goal->inside->cells[c] == GRID_FREE;
			snprintf(out->why, sizeof out->why,
				 any ? "no free way leads from %s to the goal region" : "the goal region is empty", name);
			goto done;
		}
		found = search(k, start);
	}
	if (found >= 0) {
		extract(k, start, found, &out->plan);
		out->status = CARRY_FOUND;
	} else {
		carry_explain(k, start_layer, sx, sy, name, out);
	}
done:
	reset_search(k);
	reset_checks(k);
	return out->status;
}

int carry_grasp(CarryPlanner *cp, const Polygon *shape, const Vec2 *at, int n, const CarryGoal *goal,
		CarryGrasp *each, CarryResult *best)
{
	CarryResult cur, keep;
	carry_result_init(&cur);
	carry_result_init(&keep);
	int chosen = -1;
	for (int i = 0; i < n; i++) {
		CarryObject obj = {.shape = *shape, .at = at[i]};
		CarryStatus st = carry_plan(cp, &obj, goal, &cur);
		each[i] = (CarryGrasp){.status = st, .cost = st == CARRY_FOUND ? cur.plan.cost : INT64_MAX,
				       .turns = st == CARRY_FOUND ? cur.plan.turns : 0};
		snprintf(each[i].why, sizeof each[i].why, "%s", cur.why);
		if (st == CARRY_FOUND && (chosen < 0 || cur.plan.cost < keep.plan.cost)) {
			CarryResult t = keep;
			keep = cur;
			cur = t;
			chosen = i;
		}
	}
	carry_result_free(&cur);
	if (best) {
		carry_result_free(best);
		*best = keep;
	} else {
		carry_result_free(&keep);
	}
	return chosen;
}
