/* rooms.h - rooms and doors: the free space cut at the skeleton's narrow points (issue 4,
 * after paper 4.2: the skeleton carries the clearance that shows where a space narrows).
 *
 * So that a task can say "the next room", the free space is split into rooms at doors.
 *
 * THE DOOR RULE. Along every pathgraph edge (pathgraph.h) the clearance of the cells is
 * a profile. A door is a valley of that profile: a run of cells of equal clearance r,
 * holding at least one chain cell (not a vertex's), with higher clearance just before
 * and just after it (or the end of the edge), such that on EACH side, going away from
 * the run until the profile comes back down to r or below, the clearance rises to a
 * peak p with
 *     p >= ROOMS_DOOR_RATIO * r   and   p - r >= ROOMS_DOOR_RISE.
 * A side that reaches the end of the edge first goes on past the vertex, along the
 * skeleton through cells of clearance above r, for at most ROOMS_REACH_FACTOR * r +
 * ROOMS_REACH_SLACK steps: a door often opens straight onto a junction near the wall.
 * The door is the run's chain cell of least width (below), the one nearest the middle
 * of the run among equals: a run of equal clearance can follow a wall into the room
 * before it passes the gap. A narrowing into a space that is hardly
 * wider is no door; a long corridor of even width between two wide rooms is one door
 * (one valley); a door on a loop whose two sides turn out to be the same room (the
 * space goes round) is dropped.
 *
 * THE ROOMS. The skeleton without its door cells falls into 4-connected pieces: one
 * room each, numbered by their first cell in row-major order. Every free cell belongs
 * to the room whose skeleton it reaches first in a breadth-first search through free
 * cells (4-connected, skeleton.h) from all rooms' skeleton cells at once (sources in
 * row-major order, which settles ties): a geodesic Voronoi partition of the space by
 * the rooms' skeletons, so the border between two rooms runs through their door.
 *
 * A door's width is the number of free cells across it: the shorter of the runs of
 * free cells through the door cell along x and along y (exact for a door in an
 * axis-parallel wall; up to sqrt 2 too wide for a diagonal one). */
#ifndef UTAK_ROOMS_H
#define UTAK_ROOMS_H

#include <stdint.h>
#include <stdio.h>

#include "utak/plan/pathgraph.h"

/* A door is at least this much narrower than the space on either side... */
#define ROOMS_DOOR_RATIO 1.5
/* ...and the space widens by at least this much (cells of clearance): a digitisation
 * wobble of the clearance (1 to 1.41, say) is no door. */
#define ROOMS_DOOR_RISE 1.0
/* How far past the end of an edge a side's peak is looked for, in skeleton steps: a few
 * door widths, so that the room behind a door counts but not the whole building. */
#define ROOMS_REACH_FACTOR 4.0
#define ROOMS_REACH_SLACK 8.0

typedef struct RoomsRoom {
	int32_t x, y;     /* its centre: its skeleton cell of largest clearance, grid cells */
	int32_t cells;    /* free cells in it */
	double clearance; /* the clearance at its centre, cells */
} RoomsRoom;

typedef struct RoomsDoor {
	int32_t x, y;           /* the door's skeleton cell, grid cells */
	int32_t width;          /* free cells across the door */
	int32_t room_a, room_b; /* the rooms it joins, room_a < room_b */
	int32_t edge;           /* the pathgraph edge it lies on */
	int32_t ax, ay, bx, by; /* the run of free cells across it, from (ax, ay) to (bx, by) */
} RoomsDoor;

typedef struct Rooms {
	int32_t w, h;
	int32_t *room; /* w * h, row-major: the room of a free cell, -1 if blocked */
	int32_t room_count, door_count;
	RoomsRoom *rooms;
	RoomsDoor *doors; /* ordered by pathgraph edge, then along the edge */
} Rooms;

void rooms_init(Rooms *r);
void rooms_free(Rooms *r);
/* rooms_find(r, pg): the rooms and doors of pg's grid (see above), into r. */
void rooms_find(Rooms *r, const Pathgraph *pg);
/* rooms_at(r, x, y): the room of cell (x, y), -1 when blocked or outside. */
int32_t rooms_at(const Rooms *r, int32_t x, int32_t y);
/* rooms_doors_of(r, room, out, cap): the doors of a room (indices into r->doors, in
 * order), at most cap of them into out; returns how many there are. The rooms next to
 * room are the other rooms of these doors. */
int32_t rooms_doors_of(const Rooms *r, int32_t room, int32_t *out, int32_t cap);

/* rooms_dump(r, g, out): the rooms map, north (row h-1) on top: '#' blocked, '=' a
 * cell across a door, else the room's symbol: A-Z for rooms 0-25, a-z for 26-51,
 * 0-9 for 52-61, '?' beyond. Then:
 *   rooms: R rooms, D doors
 *   room ID X Y CELLS CLEARANCE
 *   door ID X Y WIDTH ROOM_A ROOM_B
 * with the clearance to 3 decimals. */
void rooms_dump(const Rooms *r, const Grid *g, FILE *out);

#endif
