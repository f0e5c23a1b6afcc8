/* roomdoubt.c - whether the model can tell which room a point lies in, and where to
 * look when it cannot (paper 3.3, 3.4.2; the rule is in roomdoubt.h).
 * CONTROLLER SIDE: the world model's evidence and the screen.
 *
 * ALGORITHM. The doubtful squares: each square's evidence, then every square of an
 * object not felt whose doubtful square lies a coarse cell or less from the verge
 * along one of the 8 directions over doubtful squares. The screen's fixed space
 * less the doubtful squares makes a room map
 * (goals_roommap_build's steps on that grid), merged by the verdict's door rule
 * where both sides are seen whole (carryroom_merge_seen); the start's and p's merged rooms are compared; if they differ,
 * every doubtful square with a free 8-neighbour in each of the two rooms is a
 * candidate, and the one whose nearest reachable cell (goals_near) is nearest Utak,
 * not yet looked at, is looked at. roomdoubt_jambs: for each door of the start's
 * room toward a better corner, the coarse occupied squares facing floor near its
 * run. roomdoubt_frontier: the unseen squares beside the start's room, each marking
 * the cells within view of it, then the nearest such cell of the room by steps.
 * roomdoubt_felt: for each object node not yet felt, a room map with it taken for
 * wall; then all of them at once, cut by the watershed (nextroom_felt). roomdoubt_next: for each door of the merged map, its jambs (the verge
 * squares beyond its run's ends and, for a run much longer than twice its
 * clearance, the faces within a square of that clearance of its cell) each
 * flooded over squares seen in the fovea within ROOMDOUBT_VIEW, then the squares
 * within its clearance of its cell or beside its run's ends that face floor,
 * unseen or seen only coarsely (the coarse ones weighed as in roomdoubt_jambs);
 * the sides of each such door joined in the merged map. roomdoubt_hidden: a second room map of
 * the screen with the coarse squares near floor taken for floor, merged, and the
 * floor seen of the model's other rooms seen whole that it joins to the start's.
 * MEMORY: a grid and a room map of the screen, freed before returning.
 * COMPLEXITY: O(w h) for the map, O(w h) for the candidates, O(w h) for each
 * goals_near over at most the candidates kept (the nearest first). */
#include "utak/mind/roomdoubt.h"

#include <math.h>
#include <stdlib.h>

#include "utak/base/util.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/goals.h"
#include "utak/mind/nextroom.h"
#include "utak/mind/objects.h"

/* doubtful(m, x, y): the square is seen only coarsely and occupied, or floor beside
 * an occupied square (roomdoubt.h). */
static bool doubtful(const WorldModel *m, int32_t x, int32_t y)
{
	Evidence e = worldmodel_evidence(m, x, y);
	if (e.res == WORLDMODEL_UNSEEN || e.res >= WORLDMODEL_RES_FOVEA)
		return false;
	Belief b = worldmodel_belief(m, x, y);
	if (b == BELIEF_OCCUPIED)
		return true;
	if (b != BELIEF_FLOOR)
		return false;
	/* A cell of side k straddling a wall's face reads floor over up to k - 1
	 * squares of it beyond the face: 1 seen at 2 x 2, 3 seen at 4 x 4. */
	int reach = e.res == WORLDMODEL_RES_INTERMEDIATE ? 1 : 3;
	for (int dy = -reach; dy <= reach; dy++)
		for (int dx = -reach; dx <= reach; dx++)
			if ((dx || dy) && worldmodel_belief(m, x + dx, y + dy) == BELIEF_OCCUPIED)
				return true;
	return false;
}

/* pessimistic(c, si, sj, pi, pj, objects, rm): the room map of the screen's fixed
 * space less the doubtful squares (but for cells (si, sj) and (pi, pj)), with
 * `objects` the objects doubtful whole too (roomdoubt.h); returns the doubtful
 * squares (caller frees both). */
static bool *pessimistic(const Controller *c, int32_t si, int32_t sj, int32_t pi, int32_t pj, bool objects, RoomMap *rm)
{
	const Screen *s = &c->screen;
	grid_init(&rm->known, s->w, s->h, GRID_BLOCKED);
	int64_t n = (int64_t)s->w * s->h;
	bool *doubt = util_alloc((size_t)n, sizeof *doubt);
	const WorldModel *m = &c->model;
	for (int64_t k = 0; k < n; k++) {
		int32_t i = (int32_t)(k % s->w), j = (int32_t)(k / s->w);
		doubt[k] = (i != si || j != sj) && (i != pi || j != pj) && doubtful(m, s->x0 + i, s->y0 + j);
	}
	/* With `objects`: an object not felt, seen coarsely where it comes within a
	 * coarse cell of the verge (its doubtful square and the verge at most
	 * ROOMDOUBT_COARSE_CELL apart along a row, a column or a diagonal, every
	 * square between doubtful), may be a wall's end that a cell straddling the
	 * gap misread as floor (paper 3.4.2: an occupied set the eye has not seen
	 * meet the verge may be the verge): its squares seen in the fovea are
	 * doubtful too. */
	bool *part = util_alloc((size_t)(m->node_count > 0 ? m->node_count : 1), sizeof *part);
	for (int64_t k = 0; objects && k < n; k++) {
		int32_t i = (int32_t)(k % s->w), j = (int32_t)(k / s->w), l = s->label[k];
		if (!doubt[k] || l < 0 || l >= m->node_count || part[l] || m->node[l].kind != NODE_OBJECT ||
		    m->node[l].held || objects_felt(c, l))
			continue;
		for (int dd = 0; dd < 9 && !part[l]; dd++) {
			int32_t dx = dd % 3 - 1, dy = dd / 3 - 1;
			for (int32_t t = 1; t <= ROOMDOUBT_COARSE_CELL && (dx || dy); t++) {
				int32_t x = i + t * dx, y = j + t * dy, at = screen_label(s, x, y);
				if (at == SCREEN_VERGE) {
					part[l] = true;
					break;
				}
				if (at == l || !doubt[(int64_t)y * s->w + x])
					break;
			}
		}
	}
	for (int64_t k = 0; k < n; k++) {
		int32_t i = (int32_t)(k % s->w), j = (int32_t)(k / s->w), l = s->label[k];
		if (l >= 0 && l < m->node_count && part[l] && (i != si || j != sj) && (i != pi || j != pj))
			doubt[k] = true;
		if (s->label[k] != SCREEN_UNKNOWN && s->fixed.cells[k] == GRID_FREE && !doubt[k])
			rm->known.cells[k] = GRID_FREE;
	}
	free(part);
	goals_roommap_find(rm);
	return doubt;
}

/* look_at(c, dist, sq, best, goal): whether doubtful square sq is to be looked at
 * from nearer Utak than *best: not looked at already (no goal reached within
 * GOALS_LOOK + 1), and a reachable cell within GOALS_LOOK of it; *best and *goal
 * updated if so. */
static bool look_at(const Controller *c, const int32_t *dist, Vec2 sq, double *best, Vec2 *goal)
{
	Vec2 near;
	if (goals_distance(sq, c->model.utak) - GOALS_LOOK >= *best)
		return false;
	for (int v = 0; v < c->visited_count; v++)
		if (goals_distance(sq, c->visited[v]) <= GOALS_LOOK + 1)
			return false;
	if (!goals_near(c, sq, dist, &near) || goals_distance(near, sq) > GOALS_LOOK)
		return false;
	double d = goals_distance(near, c->model.utak);
	if (d >= *best)
		return false;
	*best = d;
	*goal = near;
	return true;
}

RoomDoubt roomdoubt_check(const Controller *c, const int32_t *dist, Vec2 p, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int32_t si, sj, pi, pj;
	if (!goals_cell_of(s, c->start, &si, &sj) || !goals_cell_of(s, p, &pi, &pj))
		return ROOMDOUBT_NONE;
	RoomMap rm;
	bool *doubt = pessimistic(c, si, sj, pi, pj, true, &rm);
	int64_t n = (int64_t)s->w * s->h;
	CarryRooms cr;
	carryroom_merge_seen(&rm, s, &cr);
	int32_t a = carryroom_at(&cr, &rm, si, sj), b = carryroom_at(&cr, &rm, pi, pj);
	RoomDoubt verdict = ROOMDOUBT_NONE;
	if (a != b && a >= 0 && b >= 0) {
		/* The doubtful squares between the two rooms: look at the one nearest
		 * Utak that no goal reached has looked at already. */
		verdict = ROOMDOUBT_STUCK;
		double best = INFINITY;
		for (int64_t k = 0; k < n; k++) {
			if (!doubt[k])
				continue;
			int32_t i = (int32_t)(k % s->w), j = (int32_t)(k / s->w);
			bool by_a = false, by_b = false;
			for (int dy = -1; dy <= 1; dy++)
				for (int dx = -1; dx <= 1; dx++) {
					int32_t r = carryroom_at(&cr, &rm, i + dx, j + dy);
					by_a |= r == a;
					by_b |= r == b;
				}
			if (by_a && by_b && look_at(c, dist, goals_centre(s->x0 + i, s->y0 + j), &best, goal))
				verdict = ROOMDOUBT_LOOK;
		}
	}
	carryroom_free(&cr);
	goals_roommap_free(&rm);
	free(doubt);
	return verdict;
}

RoomDoubt roomdoubt_door(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	const Screen *s = &c->screen;
	int32_t si, sj, ui, uj;
	if (!goals_cell_of(s, c->start, &si, &sj) || !goals_cell_of(s, c->model.utak, &ui, &uj))
		return ROOMDOUBT_NONE;
	RoomMap rm;
	bool *doubt = pessimistic(c, si, sj, ui, uj, false, &rm);
	int64_t n = (int64_t)s->w * s->h;
	int32_t a = rooms_at(&rm.rooms, si, sj), nr = rm.rooms.room_count;
	/* The rooms a narrowing joins to the start's on this map (rooms.h's gentler
	 * rule: a look costs a few cycles, a door missed the task). */
	bool *next = util_alloc((size_t)(nr > 0 ? nr : 1), sizeof *next);
	bool any = false;
	for (int32_t r = 0; r < nr; r++)
		next[r] = false;
	for (int32_t q = 0; a >= 0 && q < rm.rooms.door_count; q++) {
		int32_t ra = rm.rooms.doors[q].room_a, rb = rm.rooms.doors[q].room_b;
		if (ra == a || rb == a)
			next[ra == a ? rb : ra] = any = true;
	}
	RoomDoubt verdict = ROOMDOUBT_NONE;
	if (any) {
		/* The doubtful squares that part them: each 8-connected set of doubtful
		 * squares beside both the start's room and a next one (a wall seen
		 * coarsely is thicker than one square), looked at from the start's side,
		 * nearest Utak first. */
		int32_t *set = util_alloc((size_t)n, sizeof *set), *queue = util_alloc((size_t)n, sizeof *queue);
		for (int64_t k = 0; k < n; k++)
			set[k] = -1;
		verdict = ROOMDOUBT_STUCK;
		double best = INFINITY;
		for (int64_t k0 = 0; k0 < n; k0++) {
			if (!doubt[k0] || set[k0] >= 0)
				continue;
			int64_t head = 0, tail = 0;
			bool by_a = false, by_b = false;
			queue[tail++] = (int32_t)k0;
			set[k0] = (int32_t)k0;
			while (head < tail) {
				int32_t k = queue[head++], i = k % s->w, j = k / s->w;
				for (int dy = -1; dy <= 1; dy++)
					for (int dx = -1; dx <= 1; dx++) {
						int32_t x = i + dx, y = j + dy;
						if (x < 0 || y < 0 || x >= s->w || y >= s->h)
							continue;
						int32_t at = y * s->w + x, r = rooms_at(&rm.rooms, x, y);
						by_a |= r == a;
						by_b |= r >= 0 && r != a && next[r];
						if (doubt[at] && set[at] < 0) {
							set[at] = (int32_t)k0;
							queue[tail++] = at;
						}
					}
			}
			for (int64_t h = 0; by_a && by_b && h < tail; h++) {
				int32_t k = queue[h], i = k % s->w, j = k / s->w;
				bool beside_a = false;
				for (int dy = -1; dy <= 1; dy++)
					for (int dx = -1; dx <= 1; dx++)
						beside_a |= rooms_at(&rm.rooms, i + dx, j + dy) == a;
				if (beside_a && look_at(c, dist, goals_centre(s->x0 + i, s->y0 + j), &best, goal))
					verdict = ROOMDOUBT_LOOK;
			}
		}
		free(set);
		free(queue);
	}
	free(next);
	goals_roommap_free(&rm);
	free(doubt);
	return verdict;
}

/* StartRooms: the rooms of this cycle's screen (goals_roommap_build), merged by the
 * verdict's door rule where both sides are seen whole (carryroom_merge_seen), and
 * the start's cell: what roomdoubt_beyond, _jambs and _frontier begin with. */
typedef struct StartRooms {
	RoomMap rm;
	CarryRooms cr;
	int32_t si, sj; /* the start's cell of the screen */
} StartRooms;

/* start_rooms_build(c, r): r for c's screen; false (nothing built) when the start
 * lies off the screen. */
static bool start_rooms_build(const Controller *c, StartRooms *r)
{
	if (!goals_cell_of(&c->screen, c->start, &r->si, &r->sj))
		return false;
	goals_roommap_build(&r->rm, &c->screen);
	carryroom_merge_seen(&r->rm, &c->screen, &r->cr);
	return true;
}

static void start_rooms_free(StartRooms *r)
{
	carryroom_free(&r->cr);
	goals_roommap_free(&r->rm);
}

RoomDoubt roomdoubt_beyond(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	const Screen *s = &c->screen;
	StartRooms sr;
	if (!start_rooms_build(c, &sr))
		return ROOMDOUBT_NONE;
	int32_t si = sr.si, sj = sr.sj;
	/* a0 the start's room of rooms.c, a its merged room: the doors' sides are
	 * compared merged, as carryroom_merge_seen names them (the least index of a
	 * merged set, which a0 need not be) */
	int32_t a0 = rooms_at(&sr.rm.rooms, si, sj), a = a0 >= 0 ? sr.cr.merged[a0] : -1;
	RoomDoubt verdict = ROOMDOUBT_NONE;
	int64_t here = a0 >= 0 ? goals_room_corner_best(c, &sr.rm, a0) : INT64_MAX;
	double best = INFINITY;
	for (int32_t q = 0; a >= 0 && q < sr.rm.rooms.door_count; q++) {
		const RoomsDoor *d = &sr.rm.rooms.doors[q];
		int32_t ra = sr.cr.merged[d->room_a], rb = sr.cr.merged[d->room_b];
		if (!sr.cr.undecided[q] || (ra != a && rb != a))
			continue;
		int32_t other = ra == a ? rb : ra;
		/* Only a side that may hold a better corner: a cell of it, or a square
		 * never seen beside it, scores above the best of the start's room. */
		bool better = false;
		for (int32_t k = 0; k < s->w * s->h && !better; k++) {
			if (carryroom_at(&sr.cr, &sr.rm, k % s->w, k / s->w) != other)
				continue;
			for (int dd = 0; dd < 5 && !better; dd++) {
				int32_t x = k % s->w + (dd == 1) - (dd == 2), y = k / s->w + (dd == 3) - (dd == 4);
				if (x < 0 || y < 0 || x >= s->w || y >= s->h)
					continue;
				int32_t at = y * s->w + x;
				if (dd > 0 && s->label[at] != SCREEN_UNKNOWN)
					continue;
				better = goals_corner_score(c->task.corner, s->x0 + x, s->y0 + y) > here;
			}
		}
		if (!better)
			continue;
		const RoomsRoom *r = &sr.rm.rooms.rooms[ra == a ? d->room_b : d->room_a];
		Vec2 centre = goals_centre(s->x0 + r->x, s->y0 + r->y), near;
		if (!goals_near(c, centre, dist, &near))
			continue;
		bool looked = false;
		for (int v = 0; v < c->visited_count && !looked; v++)
			looked = goals_distance(near, c->visited[v]) <= GOALS_LOOK + 1;
		double dd = goals_distance(near, c->model.utak);
		if (!looked && dd < best) {
			best = dd;
			*goal = near;
			verdict = ROOMDOUBT_LOOK;
		}
	}
	start_rooms_free(&sr);
	return verdict;
}

/* seg_dist2(px, py, ax, ay, bx, by): the squared distance from (px, py) to the
 * segment (ax, ay)-(bx, by). */
static double seg_dist2(double px, double py, double ax, double ay, double bx, double by)
{
	double dx = bx - ax, dy = by - ay, l2 = dx * dx + dy * dy;
	double t = l2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / l2 : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	double ex = px - (ax + t * dx), ey = py - (ay + t * dy);
	return ex * ex + ey * ey;
}

/* door_box(s, d, ...): the screen's squares within reach of door d's run across it,
 * reach being half its width and a coarse cell (the squares that may set its width:
 * roomdoubt_jambs and roomdoubt_next), as the box [i0, i1] x [j0, j1] clipped to the
 * screen; returns reach. */
static double door_box(const Screen *s, const RoomsDoor *d, int32_t *i0, int32_t *i1, int32_t *j0, int32_t *j1)
{
	double reach = d->width / 2.0 + ROOMDOUBT_COARSE_CELL;
	int32_t r = (int32_t)ceil(reach);
	*i0 = (d->ax < d->bx ? d->ax : d->bx) - r, *i1 = (d->ax > d->bx ? d->ax : d->bx) + r;
	*j0 = (d->ay < d->by ? d->ay : d->by) - r, *j1 = (d->ay > d->by ? d->ay : d->by) + r;
	*i0 = *i0 < 0 ? 0 : *i0, *j0 = *j0 < 0 ? 0 : *j0;
	*i1 = *i1 >= s->w ? s->w - 1 : *i1, *j1 = *j1 >= s->h ? s->h - 1 : *j1;
	return reach;
}
/* jamb_wide(peak, c): the verdict's door rule (carryroom.h) for one side. */
static bool jamb_wide(double peak, double c)
{
	return peak >= CARRYROOM_RATIO * c && peak >= c + CARRYROOM_MARGIN;
}

RoomDoubt roomdoubt_jambs(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	const Screen *s = &c->screen;
	StartRooms sr;
	if (!start_rooms_build(c, &sr))
		return ROOMDOUBT_NONE;
	int32_t si = sr.si, sj = sr.sj;
	int32_t a0 = rooms_at(&sr.rm.rooms, si, sj), a = a0 >= 0 ? sr.cr.merged[a0] : -1;
	RoomDoubt verdict = ROOMDOUBT_NONE;
	int64_t here = a0 >= 0 ? goals_room_corner_best(c, &sr.rm, a0) : INT64_MAX;
	double best = INFINITY;
	for (int32_t q = 0; a >= 0 && q < sr.rm.rooms.door_count; q++) {
		const RoomsDoor *d = &sr.rm.rooms.doors[q];
		int32_t ra = sr.cr.merged[d->room_a], rb = sr.cr.merged[d->room_b];
		/* Doors the verdict's rule keeps on the model, out of the start's room,
		 * undecided ones too: a look past one (roomdoubt_beyond) may leave it
		 * undecided, its width still the coarse squares'. */
		if (ra == rb || (ra != a && rb != a))
			continue;
		int32_t other = ra == a ? rb : ra;
		bool better = false;
		for (int32_t k = 0; k < s->w * s->h && !better; k++)
			better = carryroom_at(&sr.cr, &sr.rm, k % s->w, k / s->w) == other &&
				 goals_corner_score(c->task.corner, s->x0 + k % s->w, s->y0 + k / s->w) > here;
		if (!better)
			continue;
		/* The squares that set the door's width: occupied, seen only coarsely,
		 * facing floor, within half its width and a coarse cell of the run
		 * across it. The coarse faces on each side may lie up to a cell less a
		 * square back (roomdoubt.h), and the door's clearance grow by half of
		 * each: if the start's room would still widen well beyond it by the
		 * verdict's rule, they cannot matter. */
		int32_t i0, i1, j0, j1, coarsest[2] = {WORLDMODEL_RES_FOVEA, WORLDMODEL_RES_FOVEA};
		double reach = door_box(s, d, &i0, &i1, &j0, &j1);
		for (int pass = 0; pass < 2; pass++) {
			if (pass == 1) {
				if (coarsest[0] == WORLDMODEL_RES_FOVEA && coarsest[1] == WORLDMODEL_RES_FOVEA)
					break; /* no square seen coarsely sets its width */
				double c1 = sqrt((double)sr.rm.skeleton.dist2[d->y * s->w + d->x]);
				for (int end = 0; end < 2; end++)
					c1 += coarsest[end] == WORLDMODEL_RES_PERIPHERAL     ? (ROOMDOUBT_COARSE_CELL - 1) / 2.0
					      : coarsest[end] == WORLDMODEL_RES_INTERMEDIATE ? 0.5
											     : 0;
				if (jamb_wide(sr.cr.peak[a], c1))
					break;
				if (verdict == ROOMDOUBT_NONE)
					verdict = ROOMDOUBT_STUCK;
			}
			for (int32_t j = j0; j <= j1; j++)
				for (int32_t i = i0; i <= i1; i++) {
					int32_t x = s->x0 + i, y = s->y0 + j;
					Evidence e = worldmodel_evidence(&c->model, x, y);
					if (e.res == WORLDMODEL_UNSEEN || e.res >= WORLDMODEL_RES_FOVEA ||
					    worldmodel_belief(&c->model, x, y) != BELIEF_OCCUPIED ||
					    seg_dist2(i, j, d->ax, d->ay, d->bx, d->by) > reach * reach)
						continue;
					bool faces = false;
					for (int dd = 1; dd < 5 && !faces; dd++) {
						int32_t u = i + (dd == 1) - (dd == 2), v = j + (dd == 3) - (dd == 4);
						faces = u >= 0 && v >= 0 && u < s->w && v < s->h &&
							worldmodel_belief(&c->model, s->x0 + u, s->y0 + v) == BELIEF_FLOOR;
					}
					if (!faces)
						continue;
					/* Each end of the run has its own side: the nearer one. */
					int end = (i - d->ax) * (i - d->ax) + (j - d->ay) * (j - d->ay) >
						  (i - d->bx) * (i - d->bx) + (j - d->by) * (j - d->by);
					if (pass == 0)
						coarsest[end] = e.res < coarsest[end] ? e.res : coarsest[end];
					else if (look_at(c, dist, goals_centre(x, y), &best, goal))
						verdict = ROOMDOUBT_LOOK;
				}
		}
	}
	start_rooms_free(&sr);
	return verdict;
}

/* across(g, x, y): the width across cell (x, y) between the walls seen on g (the
 * screen's fixed space: objects and the unseen count as space): the shorter of its
 * runs of free cells along x and along y; a run that leaves the screen has no wall
 * seen at that end and is unbounded (INT32_MAX). */
static int32_t across(const Grid *g, int32_t x, int32_t y)
{
	int32_t run[2];
	for (int axis = 0; axis < 2; axis++) {
		int32_t dx = axis == 0, dy = axis == 1, n = 1;
		bool open = false;
		for (int side = -1; side <= 1 && !open; side += 2)
			for (int32_t k = 1;; k++) {
				int32_t u = x + side * k * dx, v = y + side * k * dy;
				if (u < 0 || v < 0 || u >= g->w || v >= g->h) {
					open = true;
					break;
				}
				if (!grid_free_at(g, u, v))
					break;
				n++;
			}
		run[axis] = open ? INT32_MAX : n;
	}
	return run[0] < run[1] ? run[0] : run[1];
}

RoomDoubt roomdoubt_frontier(const Controller *c, const int32_t *dist, Vec2 toward, const Vec2 *follow, Vec2 *goal)
{
	const Screen *s = &c->screen;
	StartRooms sr;
	/* The room as for the corner (goals_room_corner_best). */
	if (!start_rooms_build(c, &sr))
		return ROOMDOUBT_NONE;
	int32_t si = sr.si, sj = sr.sj;
	int32_t a = carryroom_at(&sr.cr, &sr.rm, si, sj);
	int64_t n = (int64_t)s->w * s->h;
	const int32_t v = ROOMDOUBT_VIEW;
	/* cover: the cells from which one impression shows an unseen square beside
	 * the room that no visited point has had within view (not Utak's own point:
	 * the goal would flip as he comes near and he would never reach it). */
	bool *cover = util_alloc((size_t)n, sizeof *cover);
	for (int64_t k = 0; k < n; k++)
		cover[k] = false;
	RoomDoubt verdict = ROOMDOUBT_NONE;
	bool open = false; /* the room meets the unseen wide too: an open room seen in part */
	for (int64_t k = 0; a >= 0 && k < n; k++) {
		if (s->label[k] != SCREEN_UNKNOWN)
			continue;
		int32_t i = (int32_t)(k % s->w), j = (int32_t)(k / s->w);
		Vec2 q = goals_centre(s->x0 + i, s->y0 + j);
		bool beside = false, followed = follow && goals_distance(q, *follow) <= ROOMDOUBT_FOLLOW;
		for (int dd = 1; dd < 5 && !beside; dd++) {
			int32_t x = i + (dd == 1) - (dd == 2), y = j + (dd == 3) - (dd == 4);
			if (carryroom_at(&sr.cr, &sr.rm, x, y) != a)
				continue;
			if (followed || across(&s->fixed, x, y) <= ROOMDOUBT_PASSAGE)
				beside = true;
			else
				open = true;
		}
		if (!beside)
			continue;
		if (verdict == ROOMDOUBT_NONE)
			verdict = ROOMDOUBT_STUCK;
		bool seen_from = false;
		for (int p = 0; p < c->visited_count && !seen_from; p++)
			seen_from = goals_distance(q, c->visited[p]) <= v;
		if (seen_from)
			continue; /* out of the eye's reach from anywhere near: not again */
		for (int32_t y = j - v; y <= j + v; y++)
			for (int32_t x = i - v; x <= i + v; x++)
				if (x >= 0 && y >= 0 && x < s->w && y < s->h &&
				    (x - i) * (x - i) + (y - j) * (y - j) <= v * v)
					cover[(int64_t)y * s->w + x] = true;
	}
	if (open && !follow)
		verdict = ROOMDOUBT_NONE;
	/* The look nearest Utak and farthest from `toward`: the room is swept away
	 * from the corner first, so the looks near it fall on the way back. */
	double best = INFINITY;
	for (int64_t k = 0; verdict != ROOMDOUBT_NONE && k < n; k++) {
		int32_t i = (int32_t)(k % s->w), j = (int32_t)(k / s->w);
		if (!cover[k] || dist[k] < 0 || s->label[k] != SCREEN_SPACE || carryroom_at(&sr.cr, &sr.rm, i, j) != a)
			continue;
		Vec2 p = goals_centre(s->x0 + i, s->y0 + j);
		double cost = dist[k] - goals_distance(p, toward);
		if (cost >= best)
			continue;
		best = cost;
		*goal = p;
		verdict = ROOMDOUBT_LOOK;
	}
	free(cover);
	start_rooms_free(&sr);
	return verdict;
}

RoomDoubt roomdoubt_felt(const Controller *c, const int32_t *dist, Vec2 *goal)
{
	const Screen *s = &c->screen;
	const WorldModel *m = &c->model;
	int32_t si, sj;
	if (!goals_cell_of(s, c->start, &si, &sj))
		return ROOMDOUBT_NONE;
	int64_t n = (int64_t)s->w * s->h;
	RoomDoubt verdict = ROOMDOUBT_NONE;
	int32_t best_d = INT32_MAX;
	for (int32_t k = 0; k < m->node_count; k++) {
		if (m->node[k].kind != NODE_OBJECT || m->node[k].held || objects_felt(c, k))
			continue;
		/* The room map with k taken for wall: does the start's room, merged by
		 * the verdict's rule, then have a door to another? */
		RoomMap rm;
		grid_init(&rm.known, s->w, s->h, GRID_BLOCKED);
		bool any = false;
		for (int64_t q = 0; q < n; q++) {
			any |= s->label[q] == k;
			if (s->label[q] != SCREEN_UNKNOWN && s->label[q] != k && s->fixed.cells[q] == GRID_FREE)
				rm.known.cells[q] = GRID_FREE;
		}
		if (!any) {
			grid_free(&rm.known);
			continue;
		}
		goals_roommap_find(&rm);
		CarryRooms cr;
		carryroom_merge(&rm, &cr);
		int32_t a = carryroom_at(&cr, &rm, si, sj);
		bool parts = false;
		for (int32_t q = 0; a >= 0 && q < rm.rooms.door_count && !parts; q++) {
			int32_t ra = cr.merged[rm.rooms.doors[q].room_a], rb = cr.merged[rm.rooms.doors[q].room_b];
			parts = ra != rb && (ra == a || rb == a);
		}
		carryroom_free(&cr);
		goals_roommap_free(&rm);
		if (!parts)
			continue;
		if (verdict == ROOMDOUBT_NONE)
			verdict = ROOMDOUBT_STUCK;
		Vec2 near;
		if (!goals_beside(c, k, dist, &near))
			continue;
		int32_t ni, nj;
		if (!goals_cell_of(s, near, &ni, &nj) || dist[nj * s->w + ni] >= best_d)
			continue;
		best_d = dist[nj * s->w + ni];
		*goal = near;
		verdict = ROOMDOUBT_LOOK;
	}
	if (verdict == ROOMDOUBT_NONE)
		verdict = nextroom_felt(c, dist, si, sj, goal);
	return verdict;
}

/* A JAMB to weigh (jamb_loose): a verge square seen in the fovea that sets a door's
 * width, the way the run across would go on through it were it space (a unit
 * vector), and the free square beside it where touch shows its colour. */
typedef struct Jamb {
	int32_t i, j;
	double ux, uy;
	int32_t ei, ej;
} Jamb;

/* jamb_faces(c, rm, d, c0, out, n): append to out (n of them; room for (2 r + 1)^2
 * more, r = ceil(c0 + 1)) the verge squares seen in the fovea with a free
 * 4-neighbour on rm within c0 + 1 of door d's cell: the faces that set its
 * clearance (the skeleton's cell is equidistant from both sides within a square).
 * The run across a door is a row or a column; where the narrowing lies across a
 * diagonal (a blob off a pier), the run's ends are not its sides, and these are.
 * Each with the direction from the door's cell to it (the way the run would go on
 * through it) and its free 8-neighbour nearest the door's cell (where touch shows
 * it). COMPLEXITY: O((c0 + 1)^2). */
static void jamb_faces(const Controller *c, const RoomMap *rm, const RoomsDoor *d, double c0, Jamb *out, int *n)
{
	const Screen *s = &c->screen;
	int32_t r = (int32_t)ceil(c0 + 1);
	for (int32_t j = d->y - r; j <= d->y + r; j++)
		for (int32_t i = d->x - r; i <= d->x + r; i++) {
			double dx = i - d->x, dy = j - d->y, dd = hypot(dx, dy);
			if (dd > c0 + 1 || dd <= 0 || screen_label(s, i, j) != SCREEN_VERGE ||
			    worldmodel_evidence(&c->model, s->x0 + i, s->y0 + j).res < WORLDMODEL_RES_FOVEA)
				continue;
			bool face = false;
			for (int k = 0; k < 4 && !face; k++) {
				int32_t x = i + (k == 0) - (k == 1), y = j + (k == 2) - (k == 3);
				face = grid_free_at(&rm->known, x, y);
			}
			double near = INFINITY;
			int32_t ei = -1, ej = -1;
			for (int k = 0; k < 9 && face; k++) {
				int32_t x = i + k % 3 - 1, y = j + k / 3 - 1;
				double e = hypot(x - d->x, y - d->y);
				if (grid_free_at(&rm->known, x, y) && e < near) {
					near = e;
					ei = x, ej = y;
				}
			}
			if (!face)
				continue;
			out[(*n)++] = (Jamb){i, j, dx / dd, dy / dd, ei, ej};
		}
}

/* jamb_loose(c, rm, d, c0, peak_a, peak_b, dist, best, goal, look): whether a jamb of
 * door d (the verge cell beyond an end of its run across, or a face that sets its
 * clearance, jamb_faces; c0 its clearance, peak_a and peak_b its sides' peaks) may
 * be an object (roomdoubt.h): a blob of wall seen in the fovea that the model joins
 * to the rest of the wall only through squares seen coarsely, near it (within
 * ROOMDOUBT_VIEW of the jamb cell, where it does not reach farther), without which
 * (the run going on through it) a side would no longer widen well beyond the door,
 * and touch has not shown its colour; or touch felt an object's colour on it. Not
 * yet touched (no point of Utak's trail beside it), the free square beside it is,
 * when dist is given, the candidate goal (*look set when taken): there touch
 * shows B or a letter. The blob's marks are cleared over the box a flood can
 * reach, not the whole screen. */
static bool jamb_loose(const Controller *c, const RoomMap *rm, const RoomsDoor *d, double c0, double peak_a,
		       double peak_b, const int32_t *dist, double *best, Vec2 *goal, bool *look)
{
	const Screen *s = &c->screen;
	int32_t ux = (d->bx > d->ax) - (d->bx < d->ax), uy = (d->by > d->ay) - (d->by < d->ay);
	if (!ux && !uy)
		return false;
	int32_t rf = (int32_t)ceil(c0 + 1);
	Jamb *jambs = util_alloc((size_t)(2 * rf + 1) * (size_t)(2 * rf + 1) + 2, sizeof *jambs);
	int count = 0;
	/* The run's two ends. Both walk the blob from a to b, as before jamb_faces
	 * came: at the first end that walks back toward the door, so the blob
	 * counts one square there. Walking away from the door at that end, as the
	 * rule means, was tried (with other changes): Utak touched piers of doors
	 * his eye had settled (random g87: 4 -> 39 cycles), and one new false
	 * success came (g112, in a doorway). Left as it was: a doubt. */
	jambs[count++] = (Jamb){d->ax - ux, d->ay - uy, ux, uy, d->ax, d->ay};
	jambs[count++] = (Jamb){d->bx + ux, d->by + uy, ux, uy, d->bx, d->by};
	/* A run much longer than twice the clearance does not lie across the
	 * narrowing (a diagonal one, or one whose run slips through a door beside
	 * it): its ends are not the sides that set the width, and the faces are. */
	if (d->width > 2 * c0 + 2)
		jamb_faces(c, rm, d, c0, jambs, &count);
	int64_t n = (int64_t)s->w * s->h;
	const int32_t r = ROOMDOUBT_VIEW;
	bool loose = false;
	int8_t *mark = util_alloc((size_t)n, sizeof *mark); /* 1 blob, 2 joint */
	int32_t *queue = util_alloc((size_t)n, sizeof *queue);
	for (int q = 0; q < count; q++) {
		int32_t ji = jambs[q].i, jj = jambs[q].j, ei = jambs[q].ei, ej = jambs[q].ej;
		if (ji < 0 || jj < 0 || ji >= s->w || jj >= s->h || screen_label(s, ji, jj) != SCREEN_VERGE ||
		    worldmodel_evidence(&c->model, s->x0 + ji, s->y0 + jj).res < WORLDMODEL_RES_FOVEA)
			continue;
		Vec2 jc = goals_centre(s->x0 + ji, s->y0 + jj);
		bool touched = false;
		for (int v = 0; v < c->trail.count && !touched; v++)
			touched = goals_distance(jc, c->trail.pts[v]) <= 1.5;
		if (touched) {
			/* Touch has shown it: an object's colour, or B. */
			if (objects_square_listed(c->felt_x, c->felt_y, c->felt_squares, s->x0 + ji, s->y0 + jj))
				loose = true;
			continue;
		}
		int64_t head = 0, tail = 0;
		bool reaches = false, joint = false;
		mark[(int64_t)jj * s->w + ji] = 1;
		queue[tail++] = jj * s->w + ji;
		while (head < tail && !reaches) {
			int32_t k = queue[head++], i = k % s->w, j = k / s->w;
			for (int dd = 0; dd < 9 && !reaches; dd++) {
				int32_t x = i + dd % 3 - 1, y = j + dd / 3 - 1;
				if (x < 0 || y < 0 || x >= s->w || y >= s->h) {
					reaches = true; /* the wall runs off the screen */
					break;
				}
				int32_t at = y * s->w + x;
				if (mark[at] || s->label[at] != SCREEN_VERGE)
					continue;
				if ((x - ji) * (x - ji) + (y - jj) * (y - jj) > r * r) {
					reaches = true; /* longer than an object near the door */
					break;
				}
				if (worldmodel_evidence(&c->model, s->x0 + x, s->y0 + y).res >= WORLDMODEL_RES_FOVEA) {
					mark[at] = 1;
					queue[tail++] = at;
				} else {
					mark[at] = 2;
					joint = true;
				}
			}
		}
		/* Were the blob space, the run across would go on through it: the
		 * door's clearance half its extent that way more. If both sides
		 * still widen well beyond that, the door stands whatever it is. */
		int32_t ext = 0;
		for (;; ext++) {
			int32_t x = ji + (int32_t)lround(ext * jambs[q].ux), y = jj + (int32_t)lround(ext * jambs[q].uy);
			if (x < 0 || y < 0 || x >= s->w || y >= s->h || mark[(int64_t)y * s->w + x] != 1)
				break;
		}
		/* The flood keeps within r of the jamb: clear that box for the next. */
		for (int32_t y = jj - r - 1; y <= jj + r + 1; y++)
			for (int32_t x = ji - r - 1; x <= ji + r + 1; x++)
				if (x >= 0 && y >= 0 && x < s->w && y < s->h)
					mark[(int64_t)y * s->w + x] = 0;
		if (reaches || !joint)
			continue;
		if (jamb_wide(peak_a, c0 + ext / 2.0) && jamb_wide(peak_b, c0 + ext / 2.0))
			continue;
		loose = true;
		if (!dist || ei < 0 || dist[ej * s->w + ei] < 0)
			continue;
		Vec2 e = goals_centre(s->x0 + ei, s->y0 + ej);
		double de = goals_distance(e, c->model.utak);
		if (de < *best) {
			*best = de;
			*goal = e;
			*look = true;
		}
	}
	free(mark);
	free(queue);
	free(jambs);
	return loose;
}

/* unsettled(c, rm, cr, q, dist, best, goal, look): whether door q of rm, a door of
 * cr, may owe its narrowness to squares the eye has not settled (roomdoubt_next);
 * each such square, when dist is given, a candidate for look_at (*look set when one
 * is taken). */
static bool unsettled(const Controller *c, const RoomMap *rm, const CarryRooms *cr, int32_t q, const int32_t *dist,
		      double *best, Vec2 *goal, bool *look)
{
	const Screen *s = &c->screen;
	const RoomsDoor *d = &rm->rooms.doors[q];
	int32_t i0, i1, j0, j1, coarsest[2] = {WORLDMODEL_RES_FOVEA, WORLDMODEL_RES_FOVEA};
	double reach = door_box(s, d, &i0, &i1, &j0, &j1);
	bool unseen = false, coarse = false;
	double c0 = sqrt((double)rm->skeleton.dist2[d->y * s->w + d->x]), near2 = (c0 + 1.5) * (c0 + 1.5);
	if (jamb_loose(c, rm, d, c0, cr->peak[cr->merged[d->room_a]], cr->peak[cr->merged[d->room_b]], dist, best, goal,
		       look))
		return true;
	for (int pass = 0; pass < 2; pass++) {
		if (pass == 1) {
			/* The unseen may be floor as far as it goes: the door's width is
			 * not known. Squares seen coarsely may lie a cell less a square
			 * back, the clearance half of that more on each side: if both
			 * sides would still widen well beyond it, they cannot matter. */
			if (!unseen && !coarse)
				return false;
			if (!unseen) {
				double c1 = c0;
				for (int end = 0; end < 2; end++)
					c1 += coarsest[end] == WORLDMODEL_RES_PERIPHERAL     ? (ROOMDOUBT_COARSE_CELL - 1) / 2.0
					      : coarsest[end] == WORLDMODEL_RES_INTERMEDIATE ? 0.5
											     : 0;
				if (jamb_wide(cr->peak[cr->merged[d->room_a]], c1) && jamb_wide(cr->peak[cr->merged[d->room_b]], c1))
					return false;
			}
			if (!dist)
				return true;
		}
		for (int32_t j = j0; j <= j1; j++)
			for (int32_t i = i0; i <= i1; i++) {
				int32_t x = s->x0 + i, y = s->y0 + j;
				if (seg_dist2(i, j, d->ax, d->ay, d->bx, d->by) > reach * reach)
					continue;
				/* Only squares that set the door's clearance matter: within it
				 * (and the diagonal's half square) of the door's cell, or beside
				 * an end of the run across it. A face farther along the wall
				 * leaves the width as it is. */
				bool hidden = s->label[j * s->w + i] == SCREEN_UNKNOWN;
				if ((i - d->x) * (i - d->x) + (j - d->y) * (j - d->y) > near2 &&
				    (i - d->ax) * (i - d->ax) + (j - d->ay) * (j - d->ay) > 2 &&
				    (i - d->bx) * (i - d->bx) + (j - d->by) * (j - d->by) > 2)
					continue;
				Evidence e = worldmodel_evidence(&c->model, x, y);
				if (!hidden && (e.res >= WORLDMODEL_RES_FOVEA || worldmodel_belief(&c->model, x, y) != BELIEF_OCCUPIED))
					continue;
				bool faces = false;
				for (int dd = 1; dd < 5 && !faces; dd++) {
					int32_t u = i + (dd == 1) - (dd == 2), v = j + (dd == 3) - (dd == 4);
					faces = u >= 0 && v >= 0 && u < s->w && v < s->h && s->label[v * s->w + u] == SCREEN_SPACE;
				}
				if (!faces)
					continue;
				/* A square Utak has stood near has been seen in the fovea (or
				 * cannot be seen from there); a coarse one reads coarse again
				 * only as the model forgets it, seen from afar (worldmodel.h,
				 * WORLDMODEL_CONF_FORGET). Neither is looked at again. */
				bool looked = false;
				for (int v = 0; v < c->trail.count && !looked; v++)
					looked = goals_distance(goals_centre(x, y), c->trail.pts[v]) <= GOALS_LOOK + 1;
				if (pass == 1) {
					if (!looked && look_at(c, dist, goals_centre(x, y), best, goal))
						*look = true;
					continue;
				}
				if (hidden) {
					unseen = true;
					continue;
				}
				if (looked)
					continue;
				coarse = true;
				int end = (i - d->ax) * (i - d->ax) + (j - d->ay) * (j - d->ay) >
					  (i - d->bx) * (i - d->bx) + (j - d->by) * (j - d->by);
				coarsest[end] = e.res < coarsest[end] ? e.res : coarsest[end];
			}
	}
	return true;
}

RoomDoubt roomdoubt_next(const Controller *c, const RoomMap *rm, CarryRooms *cr, int32_t room, const int32_t *dist,
			 Vec2 *goal)
{
	const Rooms *r = &rm->rooms;
	int32_t nd = r->door_count;
	bool *join = util_alloc((size_t)(nd > 0 ? nd : 1), sizeof *join), look = false;
	RoomDoubt verdict = ROOMDOUBT_NONE;
	double best = INFINITY;
	for (int32_t q = 0; q < nd; q++) {
		int32_t a = cr->merged[r->doors[q].room_a], b = cr->merged[r->doors[q].room_b];
		bool mine = room >= 0 && (a == cr->merged[room] || b == cr->merged[room]);
		join[q] = a != b && unsettled(c, rm, cr, q, mine ? dist : NULL, &best, goal, &look);
		if (join[q] && mine && verdict == ROOMDOUBT_NONE)
			verdict = ROOMDOUBT_STUCK;
	}
	/* Join the two sides of each: the least name stands for both. */
	for (int32_t q = 0; q < nd; q++) {
		if (!join[q])
			continue;
		int32_t a = cr->merged[r->doors[q].room_a], b = cr->merged[r->doors[q].room_b];
		int32_t lo = a < b ? a : b, hi = a < b ? b : a;
		if (lo == hi)
			continue;
		for (int32_t k = 0; k < cr->count; k++)
			if (cr->merged[k] == hi)
				cr->merged[k] = lo;
		cr->peak[lo] = fmax(cr->peak[lo], cr->peak[hi]);
	}
	for (int32_t q = 0; q < nd; q++) {
		cr->door[q] = cr->door[q] && cr->merged[r->doors[q].room_a] != cr->merged[r->doors[q].room_b];
		cr->undecided[q] = cr->undecided[q] && cr->door[q];
	}
	free(join);
	return look ? ROOMDOUBT_LOOK : verdict;
}

/* hidden_floor(m, x, y): the square is occupied on the model but seen only coarsely,
 * and within a cell less a square of floor seen (1 square at 2 x 2, 3 at 4 x 4): a
 * coarse cell straddling a wall's face reads occupied over the floor it shares, so
 * the square may be floor (roomdoubt_hidden). */
static bool hidden_floor(const WorldModel *m, int32_t x, int32_t y)
{
	Evidence e = worldmodel_evidence(m, x, y);
	if (e.res == WORLDMODEL_UNSEEN || e.res >= WORLDMODEL_RES_FOVEA || worldmodel_belief(m, x, y) != BELIEF_OCCUPIED)
		return false;
	int reach = e.res == WORLDMODEL_RES_INTERMEDIATE ? 1 : ROOMDOUBT_COARSE_CELL - 1;
	for (int dy = -reach; dy <= reach; dy++)
		for (int dx = -reach; dx <= reach; dx++)
			if ((dx || dy) && worldmodel_belief(m, x + dx, y + dy) == BELIEF_FLOOR)
				return true;
	return false;
}

bool roomdoubt_maybe_floor(const WorldModel *m, int32_t x, int32_t y)
{
	return hidden_floor(m, x, y);
}

/* hidden(c, got, at, dist, goal): roomdoubt_hidden; with dist, also a look (*goal,
 * true in *look) at the square that may be floor under a coarse cell, beside the
 * start's room or the room of the floor that beats, nearest Utak and not looked at
 * already (look_at): the squares that join the two on the optimistic map. */
static bool hidden(const Controller *c, int64_t got, Vec2 *at, const int32_t *dist, Vec2 *goal, bool *look)
{
	const Screen *s = &c->screen;
	StartRooms sr;
	if (!start_rooms_build(c, &sr))
		return false;
	int32_t w = s->w, h = s->h, a = carryroom_at(&sr.cr, &sr.rm, sr.si, sr.sj);
	int64_t n = (int64_t)w * h;
	/* The OPTIMISTIC map: the fixed space seen, and every square that may be floor
	 * under a coarse cell, taken for floor. */
	bool *maybe = util_alloc((size_t)n, sizeof *maybe);
	RoomMap rm;
	grid_init(&rm.known, w, h, GRID_BLOCKED);
	for (int64_t k = 0; k < n; k++) {
		int32_t i = (int32_t)(k % w), j = (int32_t)(k / w);
		bool seen = s->label[k] != SCREEN_UNKNOWN;
		maybe[k] = seen && s->fixed.cells[k] != GRID_FREE && hidden_floor(&c->model, s->x0 + i, s->y0 + j);
		if (seen && (s->fixed.cells[k] == GRID_FREE || maybe[k]))
			rm.known.cells[k] = GRID_FREE;
	}
	goals_roommap_find(&rm);
	CarryRooms cr;
	carryroom_merge(&rm, &cr);
	int32_t b = carryroom_at(&cr, &rm, sr.si, sr.sj);
	/* The model's rooms (merged) that are seen whole: no cell of one beside a
	 * square never seen. A room seen in part is roomdoubt_beyond's and
	 * roomdoubt_frontier's: the eye has not yet shown it a pocket. */
	bool *open = util_alloc((size_t)(sr.cr.count > 0 ? sr.cr.count : 1), sizeof *open);
	for (int64_t k = 0; k < n; k++) {
		int32_t i = (int32_t)(k % w), j = (int32_t)(k / w), r = carryroom_at(&sr.cr, &sr.rm, i, j);
		for (int d = 0; d < 4 && r >= 0 && r < sr.cr.count && !open[r]; d++) {
			int32_t x = i + (d == 0) - (d == 1), y = j + (d == 2) - (d == 3);
			open[r] = x < 0 || y < 0 || x >= w || y >= h || s->label[y * w + x] == SCREEN_UNKNOWN;
		}
	}
	int64_t best = INT64_MIN;
	int32_t beat = -1; /* the model's room of the floor that beats */
	for (int64_t k = 0; a >= 0 && b >= 0 && k < n; k++) {
		int32_t i = (int32_t)(k % w), j = (int32_t)(k / w);
		int32_t r = carryroom_at(&sr.cr, &sr.rm, i, j);
		if (s->label[k] != SCREEN_SPACE || maybe[k] || carryroom_at(&cr, &rm, i, j) != b || r == a || r < 0 ||
		    r >= sr.cr.count || open[r])
			continue;
		int64_t score = goals_corner_score(c->task.corner, s->x0 + i, s->y0 + j);
		if (score > got + CONTROLLER_CORNER_SLACK && score > best) {
			best = score;
			beat = r;
			*at = goals_centre(s->x0 + i, s->y0 + j);
		}
	}
	double near = INFINITY;
	for (int64_t k = 0; dist && best > INT64_MIN && k < n; k++) {
		int32_t i = (int32_t)(k % w), j = (int32_t)(k / w);
		if (!maybe[k] || carryroom_at(&cr, &rm, i, j) != b)
			continue;
		bool beside = false;
		for (int dy = -1; dy <= 1 && !beside; dy++)
			for (int dx = -1; dx <= 1 && !beside; dx++) {
				int32_t r = carryroom_at(&sr.cr, &sr.rm, i + dx, j + dy);
				beside = r >= 0 && (r == a || r == beat);
			}
		if (beside && look_at(c, dist, goals_centre(s->x0 + i, s->y0 + j), &near, goal))
			*look = true;
	}
	carryroom_free(&cr);
	goals_roommap_free(&rm);
	start_rooms_free(&sr);
	free(maybe);
	free(open);
	return best > INT64_MIN;
}

bool roomdoubt_hidden(const Controller *c, int64_t got, Vec2 *at)
{
	bool look = false;
	return hidden(c, got, at, NULL, NULL, &look);
}

bool roomdoubt_hidden_look(const Controller *c, const int32_t *dist, int64_t got, Vec2 *goal)
{
	Vec2 at;
	bool look = false;
	return hidden(c, got, &at, dist, goal, &look) && look;
}
