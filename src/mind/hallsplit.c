/* hallsplit.c - whether a blob the eye has seen only coarsely may be a wall that parts
 * the hall Utak started in, before he claims its corner, and settling it by touch
 * (paper 3.4.2; issue 13 items 3 and 6; the rule is in hallsplit.h). CONTROLLER
 * SIDE: the world model, its screen and what touch has felt.
 *
 * ALGORITHM. The rule (hs_unfelt_parts): for each object node not held and not
 * felt, seen in the fovea or not, the room map of the screen's fixed space seen,
 * that node taken for wall (goals_roommap_find), merged by the verdict's door rule
 * keeping every narrowing that may yet be a door (carryroom_merge_maybe); the node
 * parts the start from p when their merged rooms differ, or their rooms of the
 * verdict's watershed restated on the same space do. The first such node, by
 * index, is reported. (A node never seen in the fovea was asked first on the map
 * alone, until stub10 asked every unfelt node: that loop found nothing the second
 * does not, and went.)
 * Settling (task (i)): the SUSPECTS (hs_suspect) are taken for wall each alone and
 * all at once, on that map and on the verdict's watershed restated on the same
 * space (carryroom_watershed); the ones to settle are those that part the hall
 * alone, else those without which the whole set no longer parts it, else all;
 * the nearest by steps with a way to it (hs_way: beside it for touch, or a look)
 * is gone to, and its rectangle remembered. With none left that parts it, the
 * claim is still checked on the watershed (hs_beaten).
 * Looking (hs_unseen_look): where hs_beaten finds floor that beats the claim in
 * the start's watershed room, the way to it crossing the fewest squares not seen
 * in the fovea (hallsplit_fewest, a 0-1 breadth-first search); the first such
 * square along it from Utak that can be looked at is gone to. And before the
 * hidden-floor doubt (roomdoubt_hidden), a look at the coarse squares that may join
 * that floor to the start's room (hallsplit_hidden_look); both within HALL_LOOKS.
 * Before that look, CLOSED (hs_frontier_look): the watershed once more with every
 * square never seen taken for wall; where it clears the claim, a look at the
 * never-seen square beside the start's closed room nearest Utak by steps
 * (hallsplit_frontier: the cells sorted by their key), within HALL_LOOKS too;
 * then FACES, the same with the coarse faces of the verge taken for floor
 * (within HALL_FACE_LOOKS).
 * Faint squares (hs_faint_parts, FAINT in hallsplit.h): their 8-connected sets
 * (a depth-first labelling), each alone and all at once taken for wall as the
 * rule takes a node (hs_joint_parts_cells); a look at the nearest square of the
 * first that parts (hs_faint_look), within HALL_FAINT_LOOKS.
 * MEMORY: one room map of the screen at a time, freed before the next; the
 * watershed 17 bytes a screen cell while it works.
 * COMPLEXITY: the rule O(w h log(w h)) for each object node not felt; settling
 * O(S w h log(w h)) for S suspects, only on the arrivals of a task whose claim the
 * rule doubted; a look O(w h log(w h)) for the watershed and O(w h) for the search,
 * and O(w h) goals_near for each square of the way tried. */
#include "utak/mind/hallsplit.h"

#include <assert.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/controller.h"
#include "utak/mind/faint.h"
#include "utak/mind/goals.h"
#include "utak/mind/objects.h"
#include "utak/mind/roomdoubt.h"

bool hallsplit_parts(const Controller *c, Vec2 p, Vec2 *at)
{
	return hallsplit_parts_all(c, &p, 1, at);
}

/* hs_parted(cr, rm, s, a, p, n): whether room a (the start's, >= 0) is none of the
 * merged rooms of the n points p; a point on no room is not parted. */
static bool hs_parted(const CarryRooms *cr, const RoomMap *rm, const Screen *s, int32_t a, const Vec2 *p,
		      int32_t n)
{
	for (int32_t i = 0; i < n; i++) {
		int32_t pi, pj;
		if (!goals_cell_of(s, p[i], &pi, &pj))
			return false;
		int32_t b = carryroom_at(cr, rm, pi, pj);
		if (b < 0 || b == a)
			return false;
	}
	return n > 0;
}

/* hs_in_blob(c, x, y): model square (x, y) lies in the rectangle of a blob gone to. */
static bool hs_in_blob(const Controller *c, int32_t x, int32_t y)
{
	for (int b = 0; b < c->hall.blob_count; b++) {
		const Box *r = &c->hall.blob[b];
		if (x >= r->lo.x && x <= r->hi.x && y >= r->lo.y && y <= r->hi.y)
			return true;
	}
	return false;
}

static bool hs_suspect(const Controller *c, int32_t k);
static bool hs_joint_parts(const Controller *c, const bool *wall, int32_t si, int32_t sj, const Vec2 *p,
			   int32_t np);
static bool hs_joint_parts_cells(const Controller *c, const bool *wall, const int32_t *comp, int32_t k, int32_t si,
				 int32_t sj, const Vec2 *p, int32_t np);
static Vec2 hs_first(const Controller *c, int32_t k, Box *box);

/* hs_unfelt_parts(c, si, sj, p, np, at): whether an object node not held, not felt
 * and not felt as wall (hs_suspect), seen in the fovea or not, taken for wall alone
 * parts the start (screen cell si, sj) from every one of the np points p, on the
 * room map or on the verdict's watershed restated (hs_joint_parts); *at its first
 * square. WHY: the eye reads a free-standing stub seen in the fovea exactly as it
 * reads an object (hallsplit.h, THE RULE); only touch tells them apart. */
static bool hs_unfelt_parts(const Controller *c, int32_t si, int32_t sj, const Vec2 *p, int32_t np, Vec2 *at)
{
	int32_t nn = c->model.node_count;
	bool *one = util_alloc((size_t)(nn > 0 ? nn : 1), sizeof *one);
	bool parted = false;
	for (int32_t k = 0; k < nn && !parted; k++) {
		if (objects_felt(c, k) || !hs_suspect(c, k))
			continue;
		one[k] = true;
		parted = hs_joint_parts(c, one, si, sj, p, np);
		one[k] = false;
		if (parted) {
			Box box;
			*at = hs_first(c, k, &box);
		}
	}
	free(one);
	return parted;
}

bool hallsplit_parts_all(const Controller *c, const Vec2 *p, int32_t np, Vec2 *at)
{
	int32_t si, sj;
	if (np <= 0 || !goals_cell_of(&c->screen, c->start, &si, &sj))
		return false;
	return hs_unfelt_parts(c, si, sj, p, np, at);
}

/* hs_coarse_square(c, k, sq): a square of node k on the screen not seen in the fovea,
 * the nearest Utak (*sq its centre); false when there is none. */
static bool hs_coarse_square(const Controller *c, int32_t k, Vec2 *sq)
{
	const Screen *s = &c->screen;
	double best = INFINITY;
	for (int64_t q = 0; q < (int64_t)s->w * s->h; q++) {
		if (s->label[q] != k)
			continue;
		int32_t x = s->x0 + (int32_t)(q % s->w), y = s->y0 + (int32_t)(q / s->w);
		double d = goals_distance(goals_centre(x, y), c->model.utak);
		if (worldmodel_evidence(&c->model, x, y).res < WORLDMODEL_RES_FOVEA && d < best) {
			best = d;
			*sq = goals_centre(x, y);
		}
	}
	return best < INFINITY;
}

/* hs_looked(c, k): node k, felt, has been looked at once already on a trip: what
 * the fovea could not show from nearby it will not show from there again. */
static bool hs_looked(const Controller *c, int32_t k)
{
	for (int i = 0; i < c->hall.looked_count; i++)
		if (c->hall.looked[i] == (int32_t)c->model.node[k].ident)
			return true;
	return false;
}

/* hs_suspect(c, k): while settling, node k may be a wall that the hall's parting
 * owes to: an object node not held, and not felt, or felt while a square of it in
 * a blob gone to is still seen only coarsely (the object felt may be read as one
 * with a stub beside it, which the fovea would part from it; once: hs_looked).
 * Seen in the fovea or not: the eye reads a free-standing pier in the fovea as an
 * object too. Touch has shown wall (objects_wall) is wall on the screen already. */
static bool hs_suspect(const Controller *c, int32_t k)
{
	const ModelNode *nd = &c->model.node[k];
	if (nd->kind != NODE_OBJECT || nd->held || objects_wall(c, k))
		return false;
	bool felt = objects_felt(c, k);
	Vec2 sq;
	if (felt && (hs_looked(c, k) || !hs_coarse_square(c, k, &sq)))
		return false;
	const Screen *s = &c->screen;
	for (int64_t q = 0; q < (int64_t)s->w * s->h; q++)
		if (s->label[q] == k && (!felt || hs_in_blob(c, s->x0 + (int32_t)(q % s->w), s->y0 + (int32_t)(q / s->w))))
			return true;
	return false; /* (off the screen: no part of the rooms judged) */
}

/* hs_joint_parts(c, wall, si, sj, p, np): whether, with every node k that wall[k]
 * marks taken for wall at once, the start (screen cell si, sj) and each of the np
 * points p lie in different merged rooms (the rule's map and merge, hallsplit.h),
 * or in different rooms of the verdict's watershed restated; false when np is 0.
 * The map and the watershed depend on the wall set alone: each is made once a call
 * (the watershed only when some point is not parted by the map), whatever np. */
static bool hs_joint_parts(const Controller *c, const bool *wall, int32_t si, int32_t sj, const Vec2 *p,
			   int32_t np)
{
	return hs_joint_parts_cells(c, wall, NULL, -1, si, sj, p, np);
}

/* hs_joint_parts_cells(c, wall, comp, k, si, sj, p, np): hs_joint_parts with, besides
 * the nodes wall marks, the screen cells comp marks k (or marks at all, k < 0) taken
 * for wall too (comp NULL: none). */
static bool hs_joint_parts_cells(const Controller *c, const bool *wall, const int32_t *comp, int32_t k, int32_t si,
				 int32_t sj, const Vec2 *p, int32_t np)
{
	const Screen *s = &c->screen;
	int64_t n = (int64_t)s->w * s->h;
	RoomMap rm;
	grid_init(&rm.known, s->w, s->h, GRID_BLOCKED);
	for (int64_t q = 0; q < n; q++) {
		int32_t l = s->label[q];
		if (l != SCREEN_UNKNOWN && !(l >= 0 && wall[l]) && s->fixed.cells[q] == GRID_FREE &&
		    !(comp && comp[q] >= 0 && (k < 0 || comp[q] == k)))
			rm.known.cells[q] = GRID_FREE;
	}
	goals_roommap_find(&rm);
	CarryRooms cr;
	carryroom_merge_maybe(&rm, s, &cr);
	int32_t a = carryroom_at(&cr, &rm, si, sj);
	int32_t *room = NULL; /* the watershed's rooms, made when first asked */
	bool parted = np > 0;
	for (int32_t i = 0; i < np && parted; i++) {
		parted = a >= 0 && hs_parted(&cr, &rm, s, a, &p[i], 1);
		/* ... or by the verdict's watershed restated on the same space, the
		 * unseen taken for floor: rooms.h finds no door across a diagonal
		 * narrowing between two offset piers (carryroom_watershed). */
		int32_t pi, pj;
		if (parted || !goals_cell_of(s, p[i], &pi, &pj))
			continue;
		if (!room) {
			Grid g;
			grid_init(&g, s->w, s->h, GRID_BLOCKED);
			for (int64_t q = 0; q < n; q++) {
				int32_t l = s->label[q];
				if (!(l >= 0 && wall[l]) && s->fixed.cells[q] == GRID_FREE &&
				    !(comp && comp[q] >= 0 && (k < 0 || comp[q] == k)))
					g.cells[q] = GRID_FREE;
			}
			room = util_alloc((size_t)(n > 0 ? n : 1), sizeof *room);
			carryroom_watershed(&g, room);
			grid_free(&g);
		}
		int32_t ra = room[(int64_t)sj * s->w + si], rb = room[(int64_t)pj * s->w + pi];
		parted = ra >= 0 && rb != ra;
	}
	free(room);
	carryroom_free(&cr);
	goals_roommap_free(&rm);
	return parted;
}

/* hs_first(c, k, box): the centre of node k's first square on the screen (by row),
 * and its rectangle of model squares. */
static Vec2 hs_first(const Controller *c, int32_t k, Box *box)
{
	const Screen *s = &c->screen;
	Vec2 first = {0, 0};
	int64_t count = 0;
	for (int64_t q = 0; q < (int64_t)s->w * s->h; q++) {
		if (s->label[q] != k)
			continue;
		int32_t x = s->x0 + (int32_t)(q % s->w), y = s->y0 + (int32_t)(q / s->w);
		if (count++ == 0) {
			*box = (Box){{x, y}, {x, y}};
			first = goals_centre(x, y);
		}
		box->lo.x = x < box->lo.x ? x : box->lo.x;
		box->lo.y = y < box->lo.y ? y : box->lo.y;
		box->hi.x = x > box->hi.x ? x : box->hi.x;
		box->hi.y = y > box->hi.y ? y : box->hi.y;
	}
	return first;
}

/* hs_way(c, k, dist, near): where to go to settle node k: felt (an object with a
 * square seen only coarsely), a look from the free square nearest that square, so
 * that a stub read as one with it is parted from it; else beside it, where touch
 * reaches it. */
static bool hs_way(const Controller *c, int32_t k, const int32_t *dist, Vec2 *near)
{
	Vec2 sq;
	if (objects_felt(c, k) && hs_coarse_square(c, k, &sq))
		return goals_near(c, sq, dist, near);
	return goals_beside(c, k, dist, near);
}

/* hs_beaten(c, p, beat): whether p is not in the start's
 * room by the verdict's watershed restated on the screen's fixed space
 * (carryroom_watershed: walls touch has shown are verge there, objects and the
 * unseen space; *out set), or floor seen in that room scores more than
 * CONTROLLER_CORNER_SLACK above p's square (*beat the best such). WHY: a wall
 * found by touch may make rooms.h cut the hall at a narrowing the verdict's ratio
 * counts no door, its far side not yet seen whole (random g256: a pier 4 x 6
 * across a hall 32 wide, felt B; Utak claimed the corner of its near side, 19
 * short); and a stub felt B may part the hall where rooms.h finds no door (made-up
 * variants of hall-stub.w: he claimed the far half's corner). */
static bool hs_beaten(const Controller *c, Vec2 p, Vec2 *beat, bool *out)
{
	const Screen *s = &c->screen;
	int32_t si, sj, px, py;
	if (!goals_cell_of(s, c->start, &si, &sj))
		return false;
	int64_t n = (int64_t)s->w * s->h;
	int32_t *room = util_alloc((size_t)n, sizeof *room);
	carryroom_watershed(&s->fixed, room);
	int32_t a = room[(int64_t)sj * s->w + si];
	px = (int32_t)floor(p.x), py = (int32_t)floor(p.y);
	int64_t got = goals_corner_score(c->task.corner, px, py), best = INT64_MIN;
	for (int64_t q = 0; q < n && a >= 0; q++)
		if (room[q] == a && s->label[q] == SCREEN_SPACE) {
			int32_t x = s->x0 + (int32_t)(q % s->w), y = s->y0 + (int32_t)(q / s->w);
			int64_t v = goals_corner_score(c->task.corner, x, y);
			if (v > best) {
				best = v;
				*beat = goals_centre(x, y);
			}
		}
	int32_t pi, pj;
	*out = !goals_cell_of(s, p, &pi, &pj) || room[(int64_t)pj * s->w + pi] != a;
	free(room);
	return *out || (best != INT64_MIN && best - got > CONTROLLER_CORNER_SLACK);
}

int32_t hallsplit_fewest(int32_t w, int32_t h, const bool *pass, const bool *costly, int64_t u, int64_t b,
			 int64_t *from)
{
	int64_t n = (int64_t)w * h;
	if (u < 0 || b < 0 || u >= n || b >= n || !pass[u] || !pass[b])
		return -1;
	/* 0-1 breadth-first search: the queue of cost L, and the next's (L + 1). A
	 * cell's cost of entry (costly[r]) is its own, whichever neighbour it is
	 * entered from, and the levels are taken in order, every cell of cost below L
	 * done before any of cost L: so the first cost a cell gets, from a neighbour
	 * of the lowest level, is final, and each cell is queued once, into one of
	 * the two queues: n entries each suffice (20 bytes a cell with cost). */
	int32_t *cost = util_alloc((size_t)n, sizeof *cost);
	int64_t *cur = util_alloc((size_t)n, sizeof *cur), *next = util_alloc((size_t)n, sizeof *next);
	for (int64_t q = 0; q < n; q++)
		cost[q] = INT32_MAX;
	int64_t nc = 0, nn = 0;
	cost[u] = 0;
	from[u] = -1;
	cur[nc++] = u;
	for (int32_t level = 0; nc > 0 && cost[b] == INT32_MAX; level++) {
		for (int64_t k = 0; k < nc; k++) {
			int64_t q = cur[k];
			/* No cell is bettered once queued (above): a check would never fire. */
			assert(cost[q] == level);
			int32_t i = (int32_t)(q % w), j = (int32_t)(q / w);
			static const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
			for (int d = 0; d < 4; d++) {
				int32_t x = i + di[d], y = j + dj[d];
				if (x < 0 || y < 0 || x >= w || y >= h)
					continue;
				int64_t r = (int64_t)y * w + x;
				if (!pass[r])
					continue;
				int32_t c = level + costly[r];
				if (c >= cost[r])
					continue;
				cost[r] = c;
				from[r] = q;
				if (c == level)
					cur[nc++] = r;
				else
					next[nn++] = r;
			}
		}
		int64_t *t = cur;
		cur = next;
		next = t;
		nc = nn;
		nn = 0;
	}
	int32_t got = cost[b] == INT32_MAX ? -1 : cost[b];
	free(next);
	free(cur);
	free(cost);
	return got;
}

/* hs_settled(c, q): screen cell q has been seen in the fovea: a square never seen,
 * or seen only by the 2 x 2 and 4 x 4 cells (which read a wall one square thick
 * as floor), may yet be wall. */
static bool hs_settled(const Controller *c, int64_t q)
{
	const Screen *s = &c->screen;
	return worldmodel_evidence(&c->model, s->x0 + (int32_t)(q % s->w), s->y0 + (int32_t)(q / s->w)).res >=
	       WORLDMODEL_RES_FOVEA;
}

/* hs_looked_at(c, here): a goal Utak has reached lies within GOALS_LOOK + 1 of here
 * (roomdoubt.c's looks): he has looked at it from close by once already. */
static bool hs_looked_at(const Controller *c, Vec2 here)
{
	for (int v = 0; v < c->visited_count; v++)
		if (goals_distance(here, c->visited[v]) <= GOALS_LOOK + 1)
			return true;
	return false;
}

/* hs_begin_look(c, goal, p, count, fmt, ...): a look-trip begun: Utak goes to goal
 * to look (c->hall set: going, look, the claim p it is for), *count (the budget it
 * spends: HALL_LOOKS or HALL_FAINT_LOOKS) one more, the plan dropped, and the why
 * (fmt) added to the task's note. Shared by hs_unseen_look and hs_faint_look. */
static void hs_begin_look(Controller *c, Vec2 goal, Vec2 p, int *count, const char *fmt, ...)
{
	HallRun *h = &c->hall;
	h->going = h->look = true;
	h->at = goal;
	h->claim = p;
	(*count)++;
	c->have_plan = false;
	size_t len = strlen(h->note);
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(h->note + len, sizeof h->note - len, fmt, ap);
	va_end(ap);
}

/* hs_unseen_look(c, p, beat): LOOKING (hallsplit.h): floor at beat beats Utak's claim
 * at p in the start's watershed room; if the way to it within that room that
 * crosses the fewest squares never seen crosses any, a look at the first of them
 * from Utak not yet looked at is begun (true; c->hall set). WHY the fewest: a way
 * over floor seen alone means the rooms join on what the eye has shown, and no
 * look can undo that; the unseen squares of the cheapest way are the ones that
 * decide it. */
static bool hs_unseen_look(Controller *c, Vec2 p, Vec2 beat)
{
	const Screen *s = &c->screen;
	HallRun *h = &c->hall;
	int32_t si, sj, ui, uj, bi, bj;
	if (h->looks >= HALL_LOOKS || !goals_cell_of(s, c->start, &si, &sj) ||
	    !goals_cell_of(s, c->model.utak, &ui, &uj) || !goals_cell_of(s, beat, &bi, &bj))
		return false;
	int64_t n = (int64_t)s->w * s->h;
	int32_t *room = util_alloc((size_t)n, sizeof *room);
	carryroom_watershed(&s->fixed, room);
	int32_t a = room[(int64_t)sj * s->w + si];
	int64_t u = (int64_t)uj * s->w + ui, b = (int64_t)bj * s->w + bi;
	bool begun = false;
	if (a >= 0 && room[u] == a && room[b] == a) {
		bool *pass = util_alloc((size_t)n, sizeof *pass), *costly = util_alloc((size_t)n, sizeof *costly);
		for (int64_t q = 0; q < n; q++) {
			pass[q] = room[q] == a;
			costly[q] = !hs_settled(c, q);
		}
		int64_t *from = util_alloc((size_t)n, sizeof *from);
		int32_t fewest = hallsplit_fewest(s->w, s->h, pass, costly, u, b, from);
		free(costly);
		free(pass);
		if (fewest > 0) {
			/* The way from the beating floor back to Utak; the square not
			 * seen in the fovea nearest Utak along it that can still be looked
			 * at (a reachable cell within GOALS_LOOK of it, no goal reached
			 * within GOALS_LOOK + 1: roomdoubt.c's looks). */
			int32_t *dist = util_alloc((size_t)n, sizeof *dist);
			goals_reach(&s->free, ui, uj, dist);
			bool found = false;
			Vec2 goal = {0, 0}, sq = {0, 0};
			for (int64_t q = b; q >= 0; q = from[q]) {
				if (hs_settled(c, q))
					continue;
				Vec2 here = goals_centre(s->x0 + (int32_t)(q % s->w), s->y0 + (int32_t)(q / s->w)), near;
				if (hs_looked_at(c, here) || !goals_near(c, here, dist, &near) ||
				    goals_distance(near, here) > GOALS_LOOK || goals_distance(near, c->model.utak) < 0.5)
					continue;
				/* the last kept is the nearest Utak along the path */
				found = true;
				goal = near;
				sq = here;
			}
			free(dist);
			if (found) {
				begun = true;
				hs_begin_look(c, goal, p, &h->looks,
					 "; floor at (%.1f, %.1f) that would beat the corner joins his room only through squares not seen in the fovea: going to look at (%.1f, %.1f) (hallsplit.h)",
					 beat.x, beat.y, sq.x, sq.y);
			}
		}
		free(from);
	}
	free(room);
	return begun;
}

/* hs_faint(c, q): screen cell q is faint (faint.h, faint_cell): space on the model
 * read only by the 2 x 2 or 4 x 4 cells, and by one that was not zero (worldmodel.c: a cell not zero says
 * something in it is occupied, not which squares; a wall one square thick across
 * a coarse cell leaves all its squares below half occupied, so floor, faint). */
static bool hs_faint(const Controller *c, int64_t q)
{
	return faint_cell(&c->model, &c->screen, q);
}

/* hs_faint_parts(c, p, np, at): FAINT (hallsplit.h): whether some 8-connected set
 * of faint squares (hs_faint), taken for wall alone, or all of them at once, parts
 * the start from every one of the np points p as a node taken for wall would (on
 * the room map merged keeping every narrowing that may be a door, or on the
 * verdict's watershed restated: hs_joint_parts_cells); *at, the square of the
 * first such set nearest Utak and not looked at from a goal reached (else the
 * nearest). COMPLEXITY: O(w h) the labelling, and a room map and a watershed for
 * each set, O(F w h log(w h)) for F sets. */
static bool hs_faint_parts(const Controller *c, const Vec2 *p, int32_t np, Vec2 *at)
{
	const Screen *s = &c->screen;
	int32_t si, sj;
	if (np <= 0 || !goals_cell_of(s, c->start, &si, &sj))
		return false;
	int64_t n = (int64_t)s->w * s->h;
	int32_t *comp = util_alloc((size_t)n, sizeof *comp), ncomp = 0;
	int64_t *stack = util_alloc((size_t)n, sizeof *stack);
	for (int64_t q = 0; q < n; q++)
		comp[q] = -1;
	for (int64_t q = 0; q < n; q++) {
		if (comp[q] >= 0 || !hs_faint(c, q))
			continue;
		int64_t top = 0;
		comp[q] = ncomp;
		stack[top++] = q;
		while (top > 0) {
			int64_t r = stack[--top];
			int32_t i = (int32_t)(r % s->w), j = (int32_t)(r / s->w);
			for (int dj = -1; dj <= 1; dj++)
				for (int di = -1; di <= 1; di++) {
					int32_t x = i + di, y = j + dj;
					if (x < 0 || y < 0 || x >= s->w || y >= s->h)
						continue;
					int64_t t = (int64_t)y * s->w + x;
					if (comp[t] < 0 && hs_faint(c, t)) {
						comp[t] = ncomp;
						stack[top++] = t;
					}
				}
		}
		ncomp++;
	}
	free(stack);
	bool parted = false;
	int32_t which = -1;
	int32_t nn = c->model.node_count;
	bool *none = util_alloc((size_t)(nn > 0 ? nn : 1), sizeof *none);
	/* k == ncomp: all of them at once (the door rule is not monotone). */
	for (int32_t k = 0; k <= ncomp && ncomp > 0 && !parted; k++) {
		parted = hs_joint_parts_cells(c, none, comp, k == ncomp ? -1 : k, si, sj, p, np);
		which = k;
	}
	free(none);
	if (parted) {
		double best = INFINITY;
		for (int64_t q = 0; q < n; q++)
			if (comp[q] >= 0 && which >= 0 && (which == ncomp || comp[q] == which)) {
				Vec2 here = goals_centre(s->x0 + (int32_t)(q % s->w), s->y0 + (int32_t)(q / s->w));
				/* the nearest Utak not yet looked at from a goal reached, else the nearest */
				double d = goals_distance(here, c->model.utak) + (hs_looked_at(c, here) ? 1e6 : 0);
				if (d < best) {
					best = d;
					*at = here;
				}
			}
	}
	free(comp);
	return parted;
}

/* hs_faint_look(c, p, sq): FAINT (hallsplit.h): the faint squares at sq part the
 * start from Utak's claim at p; a look from the reachable free cell nearest sq
 * (within GOALS_LOOK of it, no goal reached within GOALS_LOOK + 1) is begun, at
 * most HALL_FAINT_LOOKS a task (true; c->hall set). The fovea reads a square one
 * wall thick as it is: the squares it sees are faint no more. */
static bool hs_faint_look(Controller *c, Vec2 p, Vec2 sq)
{
	const Screen *s = &c->screen;
	HallRun *h = &c->hall;
	int32_t ui, uj;
	if (h->faint_looks >= HALL_FAINT_LOOKS || !goals_cell_of(s, c->model.utak, &ui, &uj))
		return false;
	if (hs_looked_at(c, sq))
		return false;
	int32_t *dist = util_alloc((size_t)s->w * (size_t)s->h, sizeof *dist);
	goals_reach(&s->free, ui, uj, dist);
	Vec2 near;
	bool ok = goals_near(c, sq, dist, &near) && goals_distance(near, sq) <= GOALS_LOOK &&
		  goals_distance(near, c->model.utak) >= 0.5;
	free(dist);
	if (!ok)
		return false;
	hs_begin_look(c, near, p, &h->faint_looks,
		 "; squares seen only coarsely, not empty, at (%.1f, %.1f) may be a wall that parts the room: going to look (hallsplit.h)",
		 sq.x, sq.y);
	return true;
}

/* hf_cmp: frontier cells by their key (steps), then index. */
typedef struct HfCell {
	int32_t key;
	int64_t q;
} HfCell;

static int hf_cmp(const void *pa, const void *pb)
{
	const HfCell *a = pa, *b = pb;
	if (a->key != b->key)
		return a->key < b->key ? -1 : 1;
	return (a->q > b->q) - (a->q < b->q);
}

int64_t hallsplit_frontier(int32_t w, int32_t h, const bool *unknown, const int32_t *room, int32_t a,
			   const int32_t *dist, int64_t *out)
{
	int64_t n = (int64_t)w * h, m = 0;
	HfCell *cell = util_alloc((size_t)(n > 0 ? n : 1), sizeof *cell);
	static const int di[4] = {1, -1, 0, 0}, dj[4] = {0, 0, 1, -1};
	for (int64_t q = 0; q < n; q++) {
		if (!unknown[q])
			continue;
		int32_t i = (int32_t)(q % w), j = (int32_t)(q / w), key = INT32_MAX;
		for (int k = 0; k < 4; k++) {
			int32_t x = i + di[k], y = j + dj[k];
			if (x < 0 || y < 0 || x >= w || y >= h)
				continue;
			int64_t r = (int64_t)y * w + x;
			if (room[r] == a && dist[r] >= 0 && dist[r] < key)
				key = dist[r];
		}
		if (key != INT32_MAX)
			cell[m++] = (HfCell){key, q};
	}
	qsort(cell, (size_t)m, sizeof *cell, hf_cmp);
	for (int64_t k = 0; k < m; k++)
		out[k] = cell[k].q;
	free(cell);
	return m;
}

/* hs_frontier_look(c, p, faces): CLOSED (hallsplit.h): hs_beaten doubts the claim at p,
 * but on the verdict's watershed restated with every square never seen taken for
 * wall, p is in the start's room and no floor seen in it beats p by more than the
 * slack: the doubt owes to the unseen. Then a look at the never-seen square that
 * borders that closed room nearest Utak (by steps to the room's square beside
 * it), not looked at from a goal reached, from a reachable cell within GOALS_LOOK
 * of it, is begun (true; c->hall set; HALL_LOOKS). WHY: the open watershed joins
 * the start's room to floor beyond a door through a wall never seen (random g241:
 * the start room's far wall unseen, 16 squares of it; the door east is then no
 * door by the verdict's ratio); the fewest-unseen way to the beating floor runs
 * through the door, over floor seen, and its looks went to the far floor itself,
 * never to the wall that decides. A look only adds what the eye saw: the claim is
 * still made by hs_beaten alone. With faces, FACES: not the unseen but every
 * verge square not seen in the fovea with floor seen beside it (a coarse face)
 * is what the watershed is restated without (taken for floor), and what is
 * looked at (random g291: an object by the start room's wall read as wall made
 * the room too narrow for its door to be one). */
static bool hs_frontier_look(Controller *c, Vec2 p, bool faces)
{
	const Screen *s = &c->screen;
	HallRun *h = &c->hall;
	int32_t si, sj, ui, uj, pi, pj;
	int *budget = faces ? &h->face_looks : &h->looks;
	if (*budget >= (faces ? HALL_FACE_LOOKS : HALL_LOOKS) || !goals_cell_of(s, c->start, &si, &sj) ||
	    !goals_cell_of(s, c->model.utak, &ui, &uj) || !goals_cell_of(s, p, &pi, &pj))
		return false;
	int64_t n = (int64_t)s->w * s->h;
	Grid closed = {s->w, s->h, util_alloc((size_t)n, 1)};
	bool *unknown = util_alloc((size_t)n, sizeof *unknown);
	for (int64_t q = 0; q < n; q++) {
		closed.cells[q] = s->fixed.cells[q];
		if (!faces) {
			unknown[q] = s->label[q] == SCREEN_UNKNOWN;
			if (unknown[q])
				closed.cells[q] = GRID_BLOCKED;
			continue;
		}
		/* FACES: a verge square not seen in the fovea with floor seen beside it */
		int32_t i = (int32_t)(q % s->w), j = (int32_t)(q / s->w);
		unknown[q] = s->label[q] == SCREEN_VERGE && !hs_settled(c, q) &&
			     (screen_label(s, i - 1, j) == SCREEN_SPACE || screen_label(s, i + 1, j) == SCREEN_SPACE ||
			      screen_label(s, i, j - 1) == SCREEN_SPACE || screen_label(s, i, j + 1) == SCREEN_SPACE);
	}
	for (int64_t q = 0; q < n && faces; q++)
		if (unknown[q])
			closed.cells[q] = GRID_FREE;
	int32_t *room = util_alloc((size_t)n, sizeof *room);
	carryroom_watershed(&closed, room);
	free(closed.cells);
	int32_t a = room[(int64_t)sj * s->w + si];
	bool clear = a >= 0 && room[(int64_t)pj * s->w + pi] == a;
	int64_t got = goals_corner_score(c->task.corner, (int32_t)floor(p.x), (int32_t)floor(p.y));
	for (int64_t q = 0; q < n && clear; q++)
		if (room[q] == a && s->label[q] == SCREEN_SPACE &&
		    goals_corner_score(c->task.corner, s->x0 + (int32_t)(q % s->w), s->y0 + (int32_t)(q / s->w)) - got >
			    CONTROLLER_CORNER_SLACK)
			clear = false;
	if (!clear) {
		free(unknown);
		free(room);
		return false;
	}
	/* The never-seen squares beside the closed room, by the steps to their
	 * neighbour in it; tried nearest first until one can be looked at. */
	int32_t *dist = util_alloc((size_t)n, sizeof *dist);
	goals_reach(&s->free, ui, uj, dist);
	if (faces) /* the faces' own squares are beside the room when on it */
		for (int64_t q = 0; q < n; q++)
			if (unknown[q] && room[q] == a)
				room[q] = -2;
	int64_t *cand = util_alloc((size_t)n, sizeof *cand);
	int64_t nc = hallsplit_frontier(s->w, s->h, unknown, room, a, dist, cand);
	free(unknown);
	free(room);
	bool begun = false;
	for (int64_t k = 0; k < nc && !begun; k++) {
		int64_t q = cand[k];
		Vec2 here = goals_centre(s->x0 + (int32_t)(q % s->w), s->y0 + (int32_t)(q / s->w)), near;
		if (hs_looked_at(c, here) || !goals_near(c, here, dist, &near) || goals_distance(near, here) > GOALS_LOOK ||
		    goals_distance(near, c->model.utak) < 0.5)
			continue;
		begun = true;
		hs_begin_look(c, near, p, budget,
			 faces ? "; a wall of the room he started in, seen only coarsely at (%.1f, %.1f), may lie farther back, and the room be no part of floor that would beat the corner: going to look (hallsplit.h)"
			       : "; the room he started in may run on into squares never seen, at (%.1f, %.1f), that join it to floor that would beat the corner: going to look (hallsplit.h)",
			 here.x, here.y);
	}
	free(cand);
	free(dist);
	return begun;
}

bool hallsplit_faint_parts_all(const Controller *c, const Vec2 *p, int32_t np, Vec2 *at)
{
	return hs_faint_parts(c, p, np, at);
}

/* hs_settle(c, p, at): hallsplit_settle without the verdict's check (hs_beaten);
 * also asked on reaching a trip's goal (hallsplit_arrive). */
static HallVerdict hs_settle(Controller *c, Vec2 p, Vec2 *at)
{
	const Screen *s = &c->screen;
	HallRun *h = &c->hall;
	int32_t si, sj, ui, uj;
	if (!goals_cell_of(s, c->start, &si, &sj) || !goals_cell_of(s, c->model.utak, &ui, &uj))
		return HALL_CLEAR;
	/* Not yet settling: the rule itself (a blob seen only coarsely), as for the
	 * doubt; where it finds none, nothing changes. */
	if (h->trips == 0 && !hallsplit_parts(c, p, at))
		return HALL_CLEAR;
	/* Settling: every suspect taken for wall at once (a pier and a stub may part
	 * the hall only together); those without which it is no longer parted are
	 * the ones to settle, the nearest first (all of them, when no one alone
	 * undoes the parting). */
	int32_t nn = c->model.node_count;
	bool *wall = util_alloc((size_t)(nn > 0 ? nn : 1), sizeof *wall);
	int32_t suspects = 0;
	for (int32_t k = 0; k < nn; k++)
		suspects += wall[k] = hs_suspect(c, k);
	if (suspects == 0) {
		free(wall);
		return HALL_CLEAR;
	}
	/* The rule's measure is not monotone (a wall more may narrow a side so that
	 * a narrowing is no door): each suspect alone is asked too. Those that part
	 * it alone are the ones to settle; else those without which the whole set
	 * no longer parts it; else all. */
	bool *one = util_alloc((size_t)nn, sizeof *one), *key = util_alloc((size_t)nn, sizeof *key);
	bool *alone = util_alloc((size_t)nn, sizeof *alone);
	int32_t ones = 0, keys = 0;
	for (int32_t k = 0; k < nn; k++) {
		if (!wall[k])
			continue;
		one[k] = true;
		ones += alone[k] = hs_joint_parts(c, one, si, sj, &p, 1);
		one[k] = false;
	}
	bool joint = hs_joint_parts(c, wall, si, sj, &p, 1);
	if (ones == 0 && !joint) {
		free(alone);
		free(key);
		free(one);
		free(wall);
		return HALL_CLEAR;
	}
	for (int32_t k = 0; k < nn && ones == 0; k++) {
		if (!wall[k])
			continue;
		wall[k] = false;
		keys += key[k] = !hs_joint_parts(c, wall, si, sj, &p, 1);
		wall[k] = true;
	}
	for (int32_t k = 0; k < nn; k++)
		key[k] = ones > 0 ? alone[k] : keys > 0 ? key[k] : wall[k];
	free(alone);
	free(one);
	int32_t *dist = util_alloc((size_t)s->w * (size_t)s->h, sizeof *dist);
	goals_reach(&c->screen.free, ui, uj, dist);
	int32_t best = -1, best_d = INT32_MAX;
	Vec2 best_near = {0, 0};
	bool named = h->trips == 0; /* at first, the doubt's words are the rule's (hallsplit_parts) */
	for (int32_t k = 0; k < nn; k++) {
		Vec2 near;
		int32_t ni, nj;
		if (!key[k])
			continue;
		if (!named) { /* else the first to settle's */
			Box box;
			*at = hs_first(c, k, &box);
			named = true;
		}
		if (h->trips >= HALL_TRIPS || !hs_way(c, k, dist, &near) || !goals_cell_of(s, near, &ni, &nj) ||
		    dist[nj * s->w + ni] >= best_d)
			continue;
		best = k;
		best_d = dist[nj * s->w + ni];
		best_near = near;
	}
	free(dist);
	free(key);
	free(wall);
	if (best < 0)
		return HALL_DOUBT;
	Box box;
	*at = hs_first(c, best, &box);
	if (objects_felt(c, best) && h->looked_count < HALL_TRIPS) /* a look (hs_way) */
		h->looked[h->looked_count++] = (int32_t)c->model.node[best].ident;
	h->going = true;
	h->look = false;
	h->at = best_near;
	h->claim = p;
	h->trips++;
	h->blob[h->blob_count < HALL_BLOBS ? h->blob_count++ : HALL_BLOBS - 1] = box;
	c->have_plan = false;
	size_t n = strlen(h->note);
	snprintf(h->note + n, sizeof h->note - n,
		 "; an object not felt at (%.1f, %.1f) may be a wall that parts the room: going to settle it (hallsplit.h)",
		 at->x, at->y);
	return HALL_GOING;
}

bool hallsplit_goal(Controller *c, const int32_t *dist, GoalResult *out)
{
	HallRun *h = &c->hall;
	int32_t i, j;
	if (!h->going)
		return false;
	if (c->space.w != c->screen.w || c->space.h != c->screen.h) {
		h->going = false;
		return false;
	}
	if (h->look && (!goals_cell_of(&c->screen, h->at, &i, &j) || dist[j * c->screen.w + i] < 0)) {
		h->going = false; /* a look whose cell is no longer reachable: the corner judged again */
		return false;
	}
	if (!goals_cell_of(&c->screen, h->at, &i, &j) || dist[j * c->screen.w + i] < 0) {
		/* The square beside it, seen closer, is no longer free or reachable:
		 * another way to what is in the blob's rectangle, if any (else the
		 * corner judged again says what is left). */
		const Screen *s = &c->screen;
		const Box *b = &h->blob[h->blob_count - 1];
		int32_t k = -1;
		for (int64_t q = 0; q < (int64_t)s->w * s->h && k < 0; q++) {
			int32_t l = s->label[q], x = s->x0 + (int32_t)(q % s->w), y = s->y0 + (int32_t)(q / s->w);
			if (l >= 0 && x >= b->lo.x && x <= b->hi.x && y >= b->lo.y && y <= b->hi.y && hs_suspect(c, l))
				k = l;
		}
		if (k < 0 || !hs_way(c, k, dist, &h->at)) {
			h->going = false;
			return false;
		}
	}
	out->goal = h->at;
	out->found = out->exploring = true;
	return true;
}

void hallsplit_arrive(Controller *c)
{
	/* Still unsettled (touch felt nothing here: the blob was seen coarsely, a
	 * square or two off), the next trip sets off from here, not from the
	 * corner. */
	Vec2 at;
	if (c->hall.going) {
		c->hall.going = c->hall.look = false;
		hs_settle(c, c->hall.claim, &at);
	}
}

HallVerdict hallsplit_settle(Controller *c, Vec2 p, Vec2 *at)
{
	HallRun *h = &c->hall;
	HallVerdict v = hs_settle(c, p, at);
	if (v == HALL_DOUBT)
		snprintf(h->why, sizeof h->why, "an object touch has not settled, at (%.1f, %.1f), may be a wall that parts the room he started in",
			 at->x, at->y);
	bool out = false;
	if (v == HALL_CLEAR && hs_faint_parts(c, &p, 1, at)) {
		if (hs_faint_look(c, p, *at))
			return HALL_GOING; /* a look at the faint squares (FAINT) */
		snprintf(h->why, sizeof h->why,
			 "squares seen only coarsely, not empty, at (%.1f, %.1f), may hold a wall that parts the room he started in",
			 at->x, at->y);
		return HALL_DOUBT;
	}
	if (v == HALL_CLEAR && hs_beaten(c, p, at, &out)) {
		if (!out && (hs_frontier_look(c, p, false) || hs_frontier_look(c, p, true) || hs_unseen_look(c, p, *at)))
			return HALL_GOING; /* a look at the unseen that joins the two (LOOKING) */
		v = HALL_DOUBT;
		if (out)
			snprintf(h->why, sizeof h->why,
				 "by the verdict's rule, with the walls touch found, he is not in the room he started in");
		else
			snprintf(h->why, sizeof h->why,
				 "floor that would beat it, at (%.1f, %.1f), is of the room he started in by the verdict's rule, with the walls touch found",
				 at->x, at->y);
	}
	return v;
}

bool hallsplit_hidden_look(Controller *c)
{
	HallRun *h = &c->hall;
	int32_t ui, uj;
	if (h->looks >= HALL_LOOKS || !goals_cell_of(&c->screen, c->model.utak, &ui, &uj))
		return false;
	int32_t *dist = util_alloc((size_t)c->screen.w * (size_t)c->screen.h, sizeof *dist);
	goals_reach(&c->screen.free, ui, uj, dist);
	bool look = roomdoubt_hidden_look(c, dist, goals_subject_score(c), &c->room_look_at);
	free(dist);
	if (look) {
		h->looks++;
		size_t n = strlen(h->note);
		snprintf(h->note + n, sizeof h->note - n,
			 "; floor that would beat the corner may join his room by squares seen only coarsely: going to look from (%.1f, %.1f) (roomdoubt.h)",
			 c->room_look_at.x, c->room_look_at.y);
	}
	return look;
}
