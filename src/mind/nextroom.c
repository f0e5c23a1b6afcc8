/* nextroom.c - "in the next room" by the verdict's own rooms on Utak's model, and
 * what he must establish before claiming a room only that rule shows (paper 2.3
 * task (ii); issue 13: rooms and doors that are rooms and doors; the rules are in
 * nextroom.h). CONTROLLER SIDE: the screen, the world model and its room map.
 *
 * ALGORITHM. nextroom_beyond: carryroom_beyond on the space seen and on the fixed
 * space, ANDed. nextroom_unfelt: a watershed of the space seen, the start's room
 * (nearest cell in a room), the object nodes with a square in either room, the
 * nearest reachable cell beside one (goals_beside). nextroom_jambs: the same
 * watershed with clearances; round each door cell bordering the room, the faces
 * within its doorway not seen in the fovea, the nearest to Utak looked at from the
 * nearest reachable cell (goals_near). nextroom_felt: the space seen less every
 * object not felt, carryroom_beyond on it, the objects within a door cell's
 * doorway, the nearest reachable cell beside one.
 * COMPLEXITY: O(w h log(w h)) a watershed, O(D r^2) the doorways (D door cells, r
 * a doorway's reach). MEMORY: a screen's grid, rooms and clearances (12 bytes a
 * cell), freed before returning. */
#include "utak/mind/nextroom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/objects.h"
#include "utak/mind/roomdoubt.h"

/* nextroom_beyond: nextroom.h. */
void nextroom_beyond(const Controller *c, const Grid *g, const RoomMap *rm, int32_t si, int32_t sj, bool *ok)
{
	const Screen *s = &c->screen;
	int64_t cells = (int64_t)g->w * g->h;
	memset(ok, 0, (size_t)cells * sizeof *ok);
	if (rm->known.w != g->w || rm->known.h != g->h || s->fixed.w != g->w || s->fixed.h != g->h)
		return;
	bool *one = util_alloc((size_t)cells, sizeof *one);
	if (carryroom_beyond(&rm->known, si, sj, ok) > 0 && carryroom_beyond(&s->fixed, si, sj, one) > 0)
		for (int64_t k = 0; k < cells; k++)
			ok[k] = ok[k] && one[k];
	else
		memset(ok, 0, (size_t)cells * sizeof *ok);
	free(one);
}

/* nextroom_cell: nextroom.h. */
int32_t nextroom_cell(const Grid *g, const int32_t *dist, const bool *ok)
{
	int32_t at = -1;
	for (int64_t k = 0; k < (int64_t)g->w * g->h; k++) {
		int32_t i = (int32_t)(k % g->w), j = (int32_t)(k / g->w);
		bool all = dist[k] >= 0 && ok[k];
		for (int32_t dj = -1; dj <= 1 && all; dj++)
			for (int32_t di = -1; di <= 1 && all; di++)
				all = i + di >= 0 && j + dj >= 0 && i + di < g->w && j + dj < g->h &&
				      ok[(j + dj) * g->w + i + di];
		if (all && (at < 0 || dist[k] < dist[at]))
			at = (int32_t)k;
	}
	return at;
}

/* nextroom_unfelt: nextroom.h. */
bool nextroom_unfelt(const Controller *c, const Grid *g, const RoomMap *rm, int32_t si, int32_t sj, int32_t at,
		     const int32_t *dist, Vec2 *goal, int32_t *keep)
{
	const Screen *s = &c->screen;
	const WorldModel *m = &c->model;
	int64_t cells = (int64_t)g->w * g->h;
	int32_t *room = util_alloc((size_t)cells, sizeof *room);
	carryroom_watershed(&rm->known, room);
	int32_t start = -1;
	double near = INFINITY;
	for (int64_t k = 0; k < cells; k++) {
		double d = hypot((double)(k % g->w) - si, (double)(k / g->w) - sj);
		if (room[k] >= 0 && d < near)
			near = d, start = room[k];
	}
	bool *in = util_alloc((size_t)(m->node_count > 0 ? m->node_count : 1), sizeof *in);
	for (int32_t k = 0; k < m->node_count; k++)
		in[k] = false;
	for (int64_t k = 0; k < cells; k++) {
		int32_t l = s->label[k];
		if (l >= 0 && l < m->node_count && room[k] >= 0 && (room[k] == start || room[k] == room[at]))
			in[l] = m->node[l].kind == NODE_OBJECT && !m->node[l].held && !objects_felt(c, l);
	}
	bool left = false, found = false;
	int32_t best_d = INT32_MAX;
	for (int32_t k = 0; k < m->node_count; k++) {
		if (!in[k])
			continue;
		left = true;
		Vec2 p;
		int32_t pi, pj;
		if (goals_beside(c, k, dist, &p) && goals_cell_of(s, p, &pi, &pj) && dist[pj * g->w + pi] < best_d) {
			best_d = dist[pj * g->w + pi];
			*goal = p;
			found = true;
		}
	}
	if (left && !found)
		*keep = -1;
	free(in);
	free(room);
	return found;
}

/* nextroom_jambs: nextroom.h. */
bool nextroom_jambs(const Controller *c, const Grid *g, const RoomMap *rm, int32_t at, const int32_t *dist,
		    Vec2 *goal, int32_t *keep)
{
	const Screen *s = &c->screen;
	const WorldModel *m = &c->model;
	int64_t cells = (int64_t)g->w * g->h;
	int32_t *room = util_alloc((size_t)cells, sizeof *room);
	float *clear = util_alloc((size_t)cells, sizeof *clear);
	carryroom_watershed_clear(&rm->known, room, clear);
	int32_t target = room[at];
	bool left = false, found = false;
	double best = INFINITY;
	for (int64_t q = 0; q < cells && target >= 0; q++) {
		if (rm->known.cells[q] != GRID_FREE || room[q] >= 0)
			continue;
		int32_t x0 = (int32_t)(q % g->w), y0 = (int32_t)(q / g->w);
		bool borders = false;
		for (int32_t y = y0 - 2; y <= y0 + 2 && !borders; y++)
			for (int32_t x = x0 - 2; x <= x0 + 2 && !borders; x++)
				borders = x >= 0 && y >= 0 && x < g->w && y < g->h && room[(int64_t)y * g->w + x] == target;
		if (!borders)
			continue;
		double reach = CARRYROOM_CHAMFER * clear[q] + CARRYROOM_DOORWAY_REACH;
		int32_t r = (int32_t)ceil(reach);
		for (int32_t y = y0 - r; y <= y0 + r; y++)
			for (int32_t x = x0 - r; x <= x0 + r; x++) {
				if (x < 0 || y < 0 || x >= g->w || y >= g->h || hypot(x - x0, y - y0) > reach ||
				    rm->known.cells[(int64_t)y * g->w + x] == GRID_FREE)
					continue;
				bool face = false;
				for (int u = 0; u < 4 && !face; u++) {
					int32_t fx = x + (u == 0) - (u == 1), fy = y + (u == 2) - (u == 3);
					face = fx >= 0 && fy >= 0 && fx < g->w && fy < g->h &&
					       rm->known.cells[(int64_t)fy * g->w + fx] == GRID_FREE;
				}
				if (!face)
					continue;
				Evidence e = worldmodel_evidence(m, s->x0 + x, s->y0 + y);
				if (e.res >= WORLDMODEL_RES_FOVEA)
					continue;
				left = true;
				Vec2 p, sq = goals_centre(s->x0 + x, s->y0 + y);
				double d = goals_distance(sq, m->utak);
				if (d < best && goals_near(c, sq, dist, &p) && goals_distance(p, sq) <= GOALS_LOOK) {
					best = d;
					*goal = p;
					found = true;
				}
			}
	}
	if (left && !found)
		*keep = -1;
	free(clear);
	free(room);
	return found;
}

/* nextroom_felt: nextroom.h. */
RoomDoubt nextroom_felt(const Controller *c, const int32_t *dist, int32_t si, int32_t sj, Vec2 *goal)
{
	const Screen *s = &c->screen;
	const WorldModel *m = &c->model;
	int64_t n = (int64_t)s->w * s->h;
	bool *blob = util_alloc((size_t)(m->node_count > 0 ? m->node_count : 1), sizeof *blob);
	for (int32_t k = 0; k < m->node_count; k++)
		blob[k] = m->node[k].kind == NODE_OBJECT && !m->node[k].held && !objects_felt(c, k);
	Grid g;
	grid_init(&g, s->w, s->h, GRID_BLOCKED);
	bool any = false;
	for (int64_t q = 0; q < n; q++) {
		int32_t l = s->label[q];
		bool b = l >= 0 && l < m->node_count && blob[l];
		any |= b;
		if (l != SCREEN_UNKNOWN && !b && s->fixed.cells[q] == GRID_FREE)
			g.cells[q] = GRID_FREE;
	}
	RoomDoubt verdict = ROOMDOUBT_NONE;
	bool *beyond = util_alloc((size_t)n, sizeof *beyond);
	if (any && carryroom_beyond(&g, si, sj, beyond) > 0) {
		int32_t *room = util_alloc((size_t)n, sizeof *room);
		float *clear = util_alloc((size_t)n, sizeof *clear);
		bool *near_door = util_alloc((size_t)(m->node_count > 0 ? m->node_count : 1), sizeof *near_door);
		for (int32_t k = 0; k < m->node_count; k++)
			near_door[k] = false;
		carryroom_watershed_clear(&g, room, clear);
		for (int64_t q = 0; q < n; q++) {
			if (g.cells[q] != GRID_FREE || room[q] >= 0)
				continue;
			int32_t x0 = (int32_t)(q % s->w), y0 = (int32_t)(q / s->w);
			double reach = CARRYROOM_CHAMFER * clear[q] + CARRYROOM_DOORWAY_REACH;
			int32_t r = (int32_t)ceil(reach);
			for (int32_t y = y0 - r; y <= y0 + r; y++)
				for (int32_t x = x0 - r; x <= x0 + r; x++) {
					int32_t l = screen_label(s, x, y);
					if (l >= 0 && l < m->node_count && blob[l] && hypot(x - x0, y - y0) <= reach)
						near_door[l] = true;
				}
		}
		int32_t best_d = INT32_MAX;
		for (int32_t k = 0; k < m->node_count; k++) {
			if (!near_door[k])
				continue;
			if (verdict == ROOMDOUBT_NONE)
				verdict = ROOMDOUBT_STUCK;
			Vec2 near;
			int32_t ni, nj;
			if (!goals_beside(c, k, dist, &near) || !goals_cell_of(s, near, &ni, &nj) ||
			    dist[nj * s->w + ni] >= best_d)
				continue;
			best_d = dist[nj * s->w + ni];
			*goal = near;
			verdict = ROOMDOUBT_LOOK;
		}
		free(near_door);
		free(clear);
		free(room);
	}
	free(beyond);
	grid_free(&g);
	free(blob);
	return verdict;
}

/* ---- the goal of task (ii) (moved from goals.c) ------------------------------- */

/* run_distance(d, i, j): the distance from cell (i, j) to the run across door d.
 * The judge's doorway is the free space within a door square's clearance and a
 * square of it (judgerooms.h), and its door squares lie all along the narrowing,
 * from face to face: near either end as near the middle. */
static double run_distance(const RoomsDoor *d, int32_t i, int32_t j)
{
	double dx = d->bx - d->ax, dy = d->by - d->ay, l2 = dx * dx + dy * dy;
	double t = l2 > 0 ? ((i - d->ax) * dx + (j - d->ay) * dy) / l2 : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	return hypot(i - (d->ax + t * dx), j - (d->ay + t * dy));
}

/* doorway_reach(rm, d, i, j): how far from the run across door d of rm cell (i, j)
 * may still be in its doorway: half its width and GOALS_DOORWAY; and where the
 * cell's clearance is no more than the door's (its chamfer's 8% and a square of the
 * eye's slack over), GOALS_DOORWAY_LOW more. The judge's doorway is the low
 * ground within a door square's clearance and a square of it, round EVERY door
 * square (judgerooms.h): its door squares run along the line where the two floods
 * meet, which need not be the straight run the model draws, and along a wall's or
 * the verge's face every square is low, so the doorway runs on along the face
 * (an open hall's edge: 13 squares and more). The judge's doorway holds no square
 * higher than its door square's clearance and 0.2 (JUDGE_DOORWAY_SLACK), so the
 * longer reach is only for cells no higher than that (with a square of slack),
 * and no door square is higher than the door's saddle. */
static double doorway_reach(const RoomMap *rm, const RoomsDoor *d, int32_t i, int32_t j)
{
	int32_t w = rm->rooms.w;
	double c = sqrt((double)rm->skeleton.dist2[d->y * w + d->x]);
	double here = sqrt((double)rm->skeleton.dist2[j * w + i]);
	double reach = d->width / 2.0 + GOALS_DOORWAY;
	return here <= GOALS_DOORWAY_CHAMFER * c + GOALS_DOORWAY_SLACK ? reach + GOALS_DOORWAY_LOW : reach;
}

/* in_doorway(rm, i, j): cell (i, j) within doorway_reach of the run across a door,
 * for any door of rm. */
static bool in_doorway(const RoomMap *rm, int32_t i, int32_t j)
{
	for (int32_t d = 0; d < rm->rooms.door_count; d++)
		if (run_distance(&rm->rooms.doors[d], i, j) <= doorway_reach(rm, &rm->rooms.doors[d], i, j))
			return true;
	return false;
}

/* nextroom_goal: nextroom.h. THE NEXT ROOM, as the judge counts rooms (judge.h, judgerooms.h): a door is a
 * narrowing between two spaces that each widen well beyond it. rooms.c cuts the
 * space at gentler narrowings (ROOMS_DOOR_RATIO), which suits the planner; its rooms
 * are merged by the verdict's rule restated on the model (carryroom.h, the same
 * code the carrying tasks use), so a bay or a wall stub is no next room. "In the
 * next room" means in another merged room (carryroom_merge: a side seen in part,
 * still narrow, counts as the same room; so does a door whose width the eye has not
 * settled, roomdoubt_next) and past the door line: farther from the run across each
 * such door than half its width and GOALS_DOORWAY squares (the judge counts the
 * doorway, the passage between the faces of the narrowing, in no room). The goal
 * is the centre of the room beyond a door; an unsettled door's sides are looked at
 * first (kept until reached), and with nothing left to look at it is gone through,
 * exploring, once; a door kept only because a side of it is seen in part
 * (carryroom_merge_seen, undecided) is a place to look from, once, not to claim.
 * Every cell claimed (here, or a goal reached) must lie beyond a door line by the
 * verdict's own watershed too (nextroom_beyond): rooms.h's doors, merged, may lie
 * at another narrowing than the judge's (random g197: another row of piers). Where
 * rooms.h's doors give nothing to go to and nothing is left to see, the goal is
 * the nearest cell beyond a door line by the watershed alone, once the objects
 * in its room and the start's have been touched (nextroom_unfelt) and the faces
 * in its doors' doorways seen in the fovea (nextroom_jambs): random g257, g292.
 * Returns whether out's goal is such a look at an unsettled door's side. */
bool nextroom_goal(const Controller *c, const Grid *g, const int32_t *dist, const RoomMap *rm, int32_t si, int32_t sj,
		   int32_t ui, int32_t uj, GoalResult *out)
{
	const Screen *s = &c->screen;
	int32_t start_room = rooms_at(&rm->rooms, si, sj), here_room = rooms_at(&rm->rooms, ui, uj);
	if (start_room < 0)
		return false;
	CarryRooms sure, seen, plain;
	carryroom_merge(rm, &sure);
	carryroom_merge(rm, &plain);
	carryroom_merge_seen(rm, s, &seen);
	/* A door whose width the eye has not settled is none to claim by: its sides
	 * are one room to `sure` (roomdoubt_next), and Utak looks at them first.
	 * When nothing is left to look at, he still heads through it as through a
	 * door (`plain`), exploring, once. */
	Vec2 look;
	bool jamb = roomdoubt_next(c, rm, &sure, start_room, dist, &look) == ROOMDOUBT_LOOK;
	int32_t sp = sure.merged[start_room], ss = seen.merged[start_room], pp = plain.merged[start_room];
	int64_t cells = (int64_t)g->w * g->h;
	bool *ok = util_alloc((size_t)cells, sizeof *ok);
	nextroom_beyond(c, g, rm, si, sj, ok);
	bool past = here_room >= 0 && sure.merged[here_room] != sp && ok[uj * g->w + ui];

	double best_d[3] = {INFINITY, INFINITY, INFINITY};
	int32_t best[3] = {-1, -1, -1};
	for (int32_t d = 0; d < rm->rooms.door_count; d++) {
		const RoomsDoor *door = &rm->rooms.doors[d];
		int32_t pa = sure.merged[door->room_a], pb = sure.merged[door->room_b];
		int32_t qa = plain.merged[door->room_a], qb = plain.merged[door->room_b];
		int32_t ga = seen.merged[door->room_a], gb = seen.merged[door->room_b];
		bool is_sure = pa != pb && (pa == sp || pb == sp), is_seen = ga != gb && (ga == ss || gb == ss);
		bool is_plain = qa != qb && (qa == pp || qb == pp);
		if (!is_sure && !is_seen && !is_plain)
			continue; /* inside a room, or not a door of the starting room */
		if (run_distance(door, ui, uj) <= doorway_reach(rm, door, ui, uj))
			past = false;
		if (!is_seen)
			continue;
		const RoomsRoom *room = &rm->rooms.rooms[ga == ss ? door->room_b : door->room_a];
		int32_t other = ga == ss ? gb : ga, kind = is_sure ? 0 : is_plain ? 2 : 1;
		if (kind >= 1) { /* a look beyond an undecided or unsettled door: once */
			/* Beyond an unsettled door, standing near its room's centre counts
			 * too: the centre moves with the map as he comes near. */
			Vec2 centre = goals_centre(s->x0 + room->x, s->y0 + room->y);
			bool looked = kind == 2 && goals_distance(centre, c->model.utak) <= GOALS_LOOK + 1;
			for (int v = 0; v < c->visited_count && !looked; v++)
				looked = goals_distance(centre, c->visited[v]) <= GOALS_LOOK + 1;
			if (looked)
				continue;
		}
		for (int32_t k = 0; k < g->w * g->h; k++) {
			int32_t i = k % g->w, j = k / g->w, r = rooms_at(&rm->rooms, i, j);
			if (dist[k] < 0 || r < 0 || seen.merged[r] != other)
				continue;
			/* A goal he would claim on reaching: a cell of another room than
			 * the start's by `sure`, and not in a doorway (as for `past`). */
			if (kind == 0 && (sure.merged[r] == sp || in_doorway(rm, i, j) || !ok[k]))
				continue;
			double dd = hypot(i - room->x, j - room->y) + 1e-3 * dist[k];
			if (dd < best_d[kind]) {
				best_d[kind] = dd;
				best[kind] = k;
			}
		}
	}
	carryroom_free(&sure);
	carryroom_free(&plain);
	carryroom_free(&seen);
	/* No such goal through rooms.h's doors: the nearest cell beyond a door line
	 * by the watershed alone (nextroom_cell). */
	int32_t ws = best[0] < 0 && !past ? nextroom_cell(g, dist, ok) : -1;
	free(ok);
	bool touch = false;
	Vec2 feel;
	/* Only when nothing is left to see (goals_frontier, as goals_choose tries
	 * next): the rule's own doubts come first. */
	if (ws >= 0 && (best[0] >= 0 || best[1] >= 0 || best[2] >= 0 || jamb || goals_frontier(c, dist, &feel)))
		ws = -1;
	if (ws >= 0)
		touch = nextroom_unfelt(c, g, rm, si, sj, ws, dist, &feel, &ws) ||
			nextroom_jambs(c, g, rm, ws, dist, &feel, &ws);
	int32_t pick = best[0] >= 0 ? best[0] : best[2] >= 0 ? best[2] : best[1];
	if (past) { /* already through a door and past its doorway: here will do */
		out->found = true;
		out->goal = goals_centre(s->x0 + ui, s->y0 + uj);
	} else if (best[0] < 0 && jamb) {
		out->found = out->exploring = true;
		out->goal = look;
		return true;
	} else if (pick < 0 && touch) {
		out->found = out->exploring = true;
		out->goal = feel;
	} else if (pick < 0 && ws >= 0) {
		out->found = true;
		out->goal = goals_centre(s->x0 + ws % g->w, s->y0 + ws / g->w);
	} else if (pick >= 0) {
		out->found = true;
		out->exploring = best[0] < 0;
		out->goal = goals_centre(s->x0 + pick % g->w, s->y0 + pick / g->w);
	}
	return false;
}
