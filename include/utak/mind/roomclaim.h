/* roomclaim.h - the checks a room claim rests on (paper 3.4.2; tasks (i) and (ii),
 * issue 13 item 3): is Utak's point in the room he started in, for a corner of it,
 * or in another, for "go next-room"? CONTROLLER SIDE: the model, this cycle's screen
 * (goals_corner_shortfall built it) and touch only.
 *
 * controller.c's arrive asks them in turn at the claim point. Those that return
 * true with a look set the next goal (c->room_look_at, c->room_look); those that
 * return true otherwise have failed the task with his doubt in c->why. */
#ifndef UTAK_ROOMCLAIM_H
#define UTAK_ROOMCLAIM_H

#include <stdbool.h>
#include <stdint.h>

#include "utak/mind/controller.h"
#include "utak/mind/roomdoubt.h"

/* roomclaim_reach(c): breadth-first steps from Utak's cell over this cycle's screen
 * (goals_reach), for roomdoubt.h's checks; the caller frees. */
int32_t *roomclaim_reach(const Controller *c);

/* roomclaim_corner_doubt(c): whether the model can tell that Utak's point is in the
 * room he started in (roomdoubt_check). */
RoomDoubt roomclaim_corner_doubt(Controller *c);

/* roomclaim_corner_look(c, check): whether check (roomdoubt_beyond, roomdoubt_jambs)
 * sends him to look toward a better corner; if so c->room_look_at is where from. */
bool roomclaim_corner_look(Controller *c, RoomDoubt (*check)(const Controller *, const int32_t *, Vec2 *));

/* roomclaim_frontier(c): whether the start's room runs into the unseen as a passage
 * (roomdoubt_frontier). */
bool roomclaim_frontier(Controller *c);

/* roomclaim_hall_split(c): a blob seen only coarsely that may be a wall parting the
 * start's room from his point (hallsplit.h): true while he goes to touch it, or when
 * touch cannot settle it and the task has failed with his doubt. */
bool roomclaim_hall_split(Controller *c);

/* roomclaim_door_doubt(c): a door the judge may count on some reading the eye leaves
 * open (doorsure.h): true when the next goal is a look (doorlook.h) or the task has
 * failed with his doubt. Asked last: a look only ever replaces a doubt. */
bool roomclaim_door_doubt(Controller *c);

/* roomclaim_felt_object(c): touch feels an object's letter beside him, nearer the
 * task's corner, that the eye reads as wall: the task fails with his doubt. */
bool roomclaim_felt_object(Controller *c);

/* roomclaim_corner_leaning(c, look), roomclaim_next_leaning(c, look): a door the
 * corner's (the next room's) claim rests on whose jamb may be an object (roomlean.h):
 * with look, true when a jamb is to be touched first; without, true when touch felt
 * an object on one and the task has failed with his doubt. */
bool roomclaim_corner_leaning(Controller *c, bool look);
bool roomclaim_next_leaning(Controller *c, bool look);

#endif
