/* carrytask.h - the carrying tasks: push an object into the next room, through the
 * door, around the corner (paper 2.3 tasks (vi)-(ix); 3.6 the plan as a list of
 * steps; 5 the L-shape in the doorway). CONTROLLER SIDE: the action cycle
 * (controller.c) and the goals (goals.c) hand these tasks over through the hooks
 * below; the motion of the held object is planned in (x, y, theta) by the planner
 * library's carry.h.
 *
 * THE STEPS, as the trace prints them ("plan: ..."):
 *   look      the object, and the place it is to go, are not yet both seen: explore
 *             the nearest frontier of the unseen (or what was seen only coarsely);
 *             when nothing is left, or the goals chosen keep coming back with
 *             nothing new seen (CARRYTASK_LOOK_IDLE), the task fails with why;
 *   survey    go to the door (the nearest square of the place beyond, for a corner)
 *             and look at it from close by, where the fovea places walls to the
 *             square; then the GOAL REGION (the squares the object must lie wholly
 *             in) is fixed in the model's frame and stays fixed while Utak pushes:
 *             the door once chosen stays chosen;
 *   go        to the grasp chosen for the whole carry (carry_grasp: every free
 *             square beside the object from which the carry exists, the cheapest);
 *   grasp;
 *   carry     the push legs and whole-degree turns of carry_plan, one command a
 *             cycle; after each the believed point is compared with the plan's, and
 *             on a disparity (or a halt) the carry is planned again from where Utak
 *             believes he is;
 *   release   when the believed object lies wholly in the goal region;
 *   regrasp   when no single grasp serves: carry the object to open floor of its
 *             room (where every side is free), let go, and choose a grasp again;
 *             so too when, holding it, no carry to the goal is left from his grasp
 *             (else he lets go where he is). An object let go that the model no
 *             longer tells from what it stands against (an L let go in a doorway)
 *             ends the task with that reason.
 * The object's start (whose room the goal is next to) is the task's object's
 * centre until it is first grasped: found elsewhere by more than
 * CARRYTASK_START_MOVED (another object read first as the task's), the place
 * beyond is looked for again.
 * An impossible carry (no grasp, not even after a re-grasp) ends the task with the
 * planner's reason in words.
 *
 * THE GOAL REGION (the judge's meaning, doc/verdicts.md and judgerooms.h, on Utak's model: carryroom.h):
 *   next room, through the door: the squares seen as floor in the rooms that share
 *     a door with the room of the object's centre, rooms and doors by the verdict's
 *     rule (a door only where the space widens to twice it and 2 squares more on
 *     both sides; rooms.h's other doors join their rooms) and still so with the
 *     door's clearance read a square more (a wall the eye placed a square off),
 *     less each door's doorway (the squares between the wall's two faces, and a
 *     square more on each side for what the eye misplaces), and only squares past
 *     a door line by the verdict's watershed on both readings of the model
 *     (nextroom.h's nextroom_beyond, as task (ii) claims);
 *   around the corner: the object's room must be an L-shaped corridor, seen whole
 *     (no square of it beside the unseen); the region is its other leg past the
 *     bend and a square more (either leg past the bend when it started in the
 *     bend). No such corridor, and nothing left to see: the task does not apply.
 *
 * FRAMES: points and polygons here are in the world model's $floor frame unless
 * named screen; the model's axes are Utak's, so a plan's pushes are motor commands
 * as they stand. */
#ifndef UTAK_CARRYTASK_H
#define UTAK_CARRYTASK_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/impression.h"
#include "utak/mind/carryroom.h"
#include "utak/mind/controller.h"
#include "utak/mind/goals.h"
#include "utak/plan/grid.h"

/* The longest carry plan kept, in commands; a longer one is followed this far and
 * planned again from there. */
#define CARRYTASK_MAX_COMMANDS 128
/* A believed point this far (squares) from the plan's after a command is a
 * disparity: the carry is planned again. */
#define CARRYTASK_DISPARITY 0.35
/* Carries planned after the first, before the task is given up as hopeless. */
#define CARRYTASK_MAX_REPLANS 12
/* Carries are planned first with quarter turns only, then at carry.h's default
 * resolution: a quarter turn keeps the held object's squares square, so the world
 * model (which turns the evidence of those squares with it) predicts the next
 * impression well; after a turn of 40 degrees it guesses, and may misplace Utak. */
#define CARRYTASK_COARSE_ANGLES 4
/* Grasps weighed by carry_grasp, the nearest to Utak first. */
#define CARRYTASK_MAX_GRASPS 40
/* Releases and re-grasps allowed in one task. */
#define CARRYTASK_MAX_REGRASPS 2
/* Looking for the place beyond stops when a goal among the last CARRYTASK_LOOK_RING
 * is chosen again, with no square seen since that was not seen before, more than
 * CARRYTASK_LOOK_IDLE times (the unseen that is left cannot be seen from anywhere he
 * can reach, and he walks between two places): the task then ends as when nothing
 * is left unseen. */
#define CARRYTASK_LOOK_IDLE 12
#define CARRYTASK_LOOK_RING 8
/* Before the object is first grasped, the task's object found this far (squares)
 * from where its start was taken is another object: its start is taken again and
 * the place beyond looked for again. */
#define CARRYTASK_START_MOVED 3.0
/* The plan's text for the trace. */
#define CARRYTASK_PLAN_TEXT 1536

typedef enum CarryStage {
	CARRY_STAGE_LOOK,	/* exploring for the object and the place beyond */
	CARRY_STAGE_SURVEY,	/* walking to look at the door or the corner */
	CARRY_STAGE_FETCH,	/* walking to the chosen grasp */
	CARRY_STAGE_HOLD,	/* holding: carrying, to the goal or to open floor */
} CarryStage;

typedef struct CarryTask {
	CarryStage stage;
	bool have_start;	/* the object's centre at first sight is known */
	Vec2 object_start;	/* model frame: the object's centre when first seen (the
				 * task's object's, until it is first grasped) */
	bool carried;		/* it has been grasped: its start stays */
	/* The goal region, fixed after the survey: region cell (i, j) is model square
	 * (rx0 + i, ry0 + j). */
	bool region_fixed;
	int32_t rx0, ry0;
	Grid region;
	Vec2 survey_at;		/* the survey's goal, model frame */
	bool have_survey;
	char survey_what[64];	/* "the door at (x, y)", "the corridor beyond" */
	char corridor[96];	/* around a corner: the L-shaped corridor the model shows */
	int32_t look_seen;	/* squares the model knew at the last look */
	int look_idle;		/* goals chosen again with nothing new seen */
	int look_cycle;		/* the cycle of the last look */
	Vec2 look_goal[CARRYTASK_LOOK_RING];	/* the last goals looked for */
	int look_count, look_next;	/* goals in the ring; where the next goes */
	Vec2 grasp_at;		/* the chosen grasp, model frame */
	bool have_grasp;
	bool to_open_floor;	/* the carry goes to open floor, for a re-grasp */
	int regrasps;
	/* Holding: the object's outline, model frame, moved with every command. */
	Polygon held;
	/* The carry: commands, and Utak's believed point expected after each. */
	MotorCommand cmd[CARRYTASK_MAX_COMMANDS];
	Vec2 expect[CARRYTASK_MAX_COMMANDS];
	int count, next;
	bool have_carry;
	Vec2 issued_from;	/* Utak's believed point when the last command was given */
	int replans;
	char plan[CARRYTASK_PLAN_TEXT];	/* the plan's text, for the next trace line */
	bool plan_new;
} CarryTask;

/* carrytask_door_sure(cr, rm, d): door d of rm (a door by the verdict's rule,
 * carryroom_merge's cr) stays one were a wall of it placed a square off by the eye:
 * both sides' peaks p satisfy the rule with the door's clearance c read
 * CARRYTASK_DOOR_SLACK more (p >= CARRYROOM_RATIO (c + s), p >= c + s +
 * CARRYROOM_MARGIN). Only such a door leads to the goal region. WHY: the judge
 * weighs the true walls; where a side widens to just twice the door (three rooms in
 * a row, doors 9 wide, rooms 18 and 19: one room to the judge), a door read a square
 * narrower, or a room a square wider, made it a door to Utak, and the square pushed
 * through it a false success (tests/worlds/rooms-in-a-row.w). test_carrytask.c: on
 * two-room worlds with a wall a square off, a door this keeps is a door to the judge. */
#define CARRYTASK_DOOR_SLACK 1.0
bool carrytask_door_sure(const CarryRooms *cr, const RoomMap *rm, const RoomsDoor *d);

/* carrytask_applies(t): the task is one of (vi)-(ix). */
bool carrytask_applies(const Task *t);
/* carrytask_new() / carrytask_delete(ct): a task's state (util_alloc). */
CarryTask *carrytask_new(void);
void carrytask_delete(CarryTask *ct);

/* carrytask_goal(c, dist, out): the goal while not holding: the frontier to
 * explore, the door to survey, or the grasp; out->found false (with why) when no
 * grasp can carry the object to the goal. False, leaving out alone, while the
 * object is not yet seen: the caller looks for it as for any object. */
bool carrytask_goal(Controller *c, const int32_t *dist, GoalResult *out);
/* carrytask_arrive(c): Utak has reached the goal of carrytask_goal; true when that
 * ends a survey (the caller does nothing more), false for the grasp. */
bool carrytask_arrive(Controller *c);
/* carrytask_decide(c, cmd): holding: the next command of the carry, or release. */
bool carrytask_decide(Controller *c, MotorCommand *cmd);
/* carrytask_perceive(c, cmd): holding, after cmd: move the believed object with it,
 * and check the plan (step 12). */
void carrytask_perceive(Controller *c, const MotorCommand *cmd);
/* carrytask_note(c, note, size): the plan's text when new, for the cycle's note;
 * returns the characters written. */
int carrytask_note(Controller *c, char *note, size_t size);

#endif
