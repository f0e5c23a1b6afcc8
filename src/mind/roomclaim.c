/* roomclaim.c - the checks a room claim rests on: that Utak's point is in the room
 * he started in, for a corner of it, or in another room, for "go next-room" (paper
 * 3.4.2: a region joined to the verge is ambiguous; tasks (i) and (ii), issue 13
 * item 3). CONTROLLER SIDE: it reads the model, this cycle's screen and touch only.
 *
 * Each check answers at the claim point, asked in turn by controller.c's arrive:
 * first those that send Utak to look or touch (roomdoubt.h, roomlean.h), then those
 * that fail the task with his doubt (hallsplit.h, touch beside him, doorsure.h with
 * doorlook.h's look first). WHY a module of its own: they are one concept, the
 * corner's and next room's soundness, and kept controller.c, the cycle itself, under
 * its size. */
#include "utak/mind/roomclaim.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"
#include "utak/mind/doorlook.h"
#include "utak/mind/doorsure.h"
#include "utak/mind/goals.h"
#include "utak/mind/hallsplit.h"
#include "utak/mind/roomdoubt.h"
#include "utak/mind/roomlean.h"

/* roomclaim_reach(c): breadth-first steps from Utak's cell over this cycle's screen
 * (goals_reach), for roomdoubt.h's checks; the caller frees. */
int32_t *roomclaim_reach(const Controller *c)
{
	int32_t ui, uj;
	goals_cell_of(&c->screen, c->model.utak, &ui, &uj);
	int32_t *dist = util_alloc((size_t)c->screen.w * (size_t)c->screen.h, sizeof *dist);
	goals_reach(&c->screen.free, ui, uj, dist);
	return dist;
}

/* roomclaim_corner_doubt(c): whether the model can tell that Utak's point is in the room
 * he started in (roomdoubt.h), on this cycle's screen (goals_corner_shortfall built
 * it). */
RoomDoubt roomclaim_corner_doubt(Controller *c)
{
	int32_t *dist = roomclaim_reach(c);
	Vec2 look;
	RoomDoubt d = roomdoubt_check(c, dist, c->model.utak, &look);
	free(dist);
	return d;
}

/* roomclaim_corner_look(c, check): whether the start's room may be other than the model
 * shows toward a better corner, by roomdoubt.h's check (roomdoubt_beyond: past a
 * door seen in part; roomdoubt_jambs: a door whose width is set by squares seen
 * coarsely); if so, c->room_look_at is where
 * to look from. */
bool roomclaim_corner_look(Controller *c, RoomDoubt (*check)(const Controller *, const int32_t *, Vec2 *))
{
	int32_t *dist = roomclaim_reach(c);
	bool look = check(c, dist, &c->room_look_at) == ROOMDOUBT_LOOK;
	free(dist);
	return look;
}

/* roomclaim_frontier(c): whether the start's room runs into the unseen as a passage
 * (roomdoubt_frontier); goals_choose then looks along it before the corner again. */
bool roomclaim_frontier(Controller *c)
{
	int32_t *dist = roomclaim_reach(c);
	Vec2 look;
	bool seen_in_part = roomdoubt_frontier(c, dist, c->model.utak, c->room_follow ? &c->room_follow_at : NULL,
					       &look) == ROOMDOUBT_LOOK;
	free(dist);
	return seen_in_part;
}

/* roomclaim_hall_split(c): whether a blob seen only coarsely may be a wall that parts
 * the start's room from Utak's point (hallsplit.h); if so he goes to touch it
 * (hallsplit_settle), or, when touch cannot settle it, the task fails with his
 * doubt. */
bool roomclaim_hall_split(Controller *c)
{
	Vec2 at;
	HallVerdict v = hallsplit_settle(c, c->model.utak, &at);
	if (v != HALL_DOUBT)
		return v == HALL_GOING; /* going: the next goal is beside the blob, to touch it */
	c->phase = PHASE_FAILED;
	snprintf(c->why, sizeof c->why, "Utak cannot tell he is in the %s: %s", task_corner_name(c->task.corner),
		 c->hall.why);
	return true;
}

/* roomclaim_door_doubt(c): whether a door the judge may count lies between the start
 * and Utak's point, or the start's room may hold a better corner, on some reading
 * the eye leaves open (doorsure.h); if so the next goal is a look at the squares
 * seen only coarsely that can tell (doorlook.h: c->room_look), or, with none left,
 * the task fails with his doubt. Asked last, where the claim would be made: a look
 * only ever replaces a doubt, and back at the corner every check is asked again. */
bool roomclaim_door_doubt(Controller *c)
{
	int64_t n = (int64_t)c->screen.w * c->screen.h;
	uint8_t *mark = util_alloc((size_t)(n > 0 ? n : 1), 1);
	memset(mark, 0, (size_t)(n > 0 ? n : 1));
	DoorSure d = doorsure_corner_marks(c, c->model.utak, mark);
	int32_t *dist = roomclaim_reach(c);
	bool look = false;
	if (c->door_look_pending) {
		/* A look set off on and given up (another check's look took the
		 * goal, or the map moved it out of reach): what changed the readings
		 * since is not the look, and no claim rests on it (doorlook.h,
		 * SAFETY). It is set off on again, while it can be reached. */
		int32_t li, lj;
		look = c->door_look_retries < DOORLOOK_RETRIES && goals_cell_of(&c->screen, c->door_look_at, &li, &lj) &&
		       dist[(int64_t)lj * c->screen.w + li] >= 0;
		if (look) {
			c->door_look_retries++;
			c->room_look_at = c->door_look_at;
		}
		d = DOORSURE_DOUBT;
	} else if (d == DOORSURE_DOUBT)
		look = doorlook_choose(c, dist, mark, &c->room_look_at);
	free(dist);
	free(mark);
	if (d == DOORSURE_SURE)
		return false;
	if (look) {
		c->room_look = true; /* the next goal: the look (goals.c keeps it until reached) */
		c->door_look_at = c->room_look_at;
		c->door_look_pending = true;
		return true;
	}
	c->phase = PHASE_FAILED;
	snprintf(c->why, sizeof c->why,
		 "Utak cannot tell he is in the %s: a door the judge may count, by a square or a wall seen only from afar, may part him from the room he started in",
		 task_corner_name(c->task.corner));
	return true;
}

/* roomclaim_felt_object(c): touch feels an object (a letter, not the verge's B) on a
 * square beside Utak that lies farther toward the task's corner than his own; if
 * so the task fails with his doubt. WHY: the judge counts an object's squares as
 * squares of the room (a corner is measured against floor or object, judge.h),
 * and an object pressed into the corner reads, to the eye, as part of the wall it
 * leans on (paper 3.4.2): the model's best floor is then short of the judge's
 * corner, and without this Utak claimed it (a brick in the north-east corner,
 * "go ne-corner": 5 short, believed achieved). Touch is the sense that tells an
 * object from the wall; how far such an object reaches into the corner the eye
 * cannot say, so any square of it beyond his own puts the corner in doubt. */
bool roomclaim_felt_object(Controller *c)
{
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	int64_t here = goals_corner_score(c->task.corner, ux, uy);
	for (int i = 0; i < TOUCH_CELLS; i++) {
		char colour = c->impression.touch[i];
		int32_t x = ux + goals_touch_offset[i][0], y = uy + goals_touch_offset[i][1];
		if (colour < 'A' || colour > 'Z' || colour == 'B' || goals_corner_score(c->task.corner, x, y) <= here)
			continue;
		c->phase = PHASE_FAILED;
		snprintf(c->why, sizeof c->why,
			 "Utak cannot tell he is in the %s: touch feels an object (%c) beside him at (%.1f, %.1f), nearer the corner, that the eye reads as wall: its squares, the room's for the corner, may reach farther into it",
			 task_corner_name(c->task.corner), colour, x + 0.5, y + 0.5);
		return true;
	}
	return false;
}

/* lean_settle(c, r, at, from, look, claim): what roomlean.h's answer r means for a
 * claim: with look, true when a jamb nearby is to be touched first (c->room_look_at
 * beside it, at from); without, true when touch felt an object on one (at), and then
 * the task fails with his doubt, claim naming what he cannot tell. */
static bool lean_settle(Controller *c, RoomLean r, Vec2 at, Vec2 from, bool look, const char *claim)
{
	if (look) {
		if (r == ROOMLEAN_LOOK)
			c->room_look_at = from;
		return r == ROOMLEAN_LOOK;
	}
	if (r != ROOMLEAN_DOUBT)
		return false;
	c->phase = PHASE_FAILED;
	snprintf(c->why, sizeof c->why,
		 "Utak cannot tell %s may be no door: touch felt an object's colour on its jamb at (%.1f, %.1f), and objects are space to rooms",
		 claim, at.x, at.y);
	return true;
}

/* roomclaim_corner_leaning(c, look): a door the corner's claim rests on whose jamb may be an
 * object (roomlean.h; lean_settle). */
bool roomclaim_corner_leaning(Controller *c, bool look)
{
	Vec2 at, from;
	char claim[160];
	int32_t *dist = look ? roomclaim_reach(c) : NULL;
	RoomLean r = roomlean_corner(c, goals_subject_score(c), dist, &at, &from);
	free(dist);
	snprintf(claim, sizeof claim, "he is in the %s: the door that parts his room from floor that would beat the corner",
		 task_corner_name(c->task.corner));
	return lean_settle(c, r, at, from, look, claim);
}

/* roomclaim_next_leaning(c, look): as roomclaim_corner_leaning, for "go next-room" at Utak's place
 * (roomlean_next). */
bool roomclaim_next_leaning(Controller *c, bool look)
{
	Vec2 at, from;
	int32_t *dist = look ? roomclaim_reach(c) : NULL;
	RoomLean r = roomlean_next(c, dist, &at, &from);
	free(dist);
	return lean_settle(c, r, at, from, look,
			   "he is in another room: the door that parts him from the room he started in");
}
