/* joined.h - the JOINED doubt on the object Utak would claim for "go brick", "go
 * lshape", "go triangle": it may be two objects (or an object and a stretch of
 * wall) pressed together, which the eye cannot part, and a pull settles it (paper
 * 3.4.2: two objects that touch make one set of occupied squares; paper 2.2: a grasp
 * and a push move only the object held; issue 13 item 6: "where his model cannot
 * tell, he goes and looks"). CONTROLLER SIDE: it acts on the world model and the
 * impressions only.
 *
 * WHY. Two squares of 5 side by side cover exactly a 10 x 5 brick's squares; a 9 x
 * 3 brick and a 3 x 6 one against its end, an L's; a brick against a free-standing
 * block of wall, an L's too. No look tells them from one polygon. Before, on 44 such
 * hand-written worlds (not in the tree), "go brick" and "go lshape" claimed
 * the pair in 6 of 44 "go" runs, a false success each (the judge: "there is no
 * brick in this world").
 * HOW. Beside the object he would claim ("go round": where the loop closes, or from
 * home, then home again), every other doubt settled (objects.h), and
 * the object read the task's shape (not the square: its probe, probe.h, asks
 * whether ONE square owns the squares, and its own runs stay as they were), Utak
 * pulls it once as apart.h pulls a MERGED rival: grasp, two pulls of TUG_STEP
 * straight back, a look after each, back, release. Come away whole (APART_ONE,
 * apart_one), it is one polygon and the claim stands on the shape the fovea read.
 * Otherwise (part stayed, a pull halted, or the look too coarse), or where no pull
 * can be made from where he stands (apart_begin: an object touched along an axis,
 * the way behind believed floor), the doubt stands and the task ends with it:
 * never a claim on a pair. Asked once per object (by ident and by the centre of its
 * rectangle, within OBJECTS_SAME).
 * WHY SOUND. apart.h: a pull passes only when every square the polygon drawn
 * leaves empty reads floor; a pair leaves the part that stayed there.
 * COST: five cycles beside the object, once per claim on a non-square shape. */
#ifndef UTAK_JOINED_H
#define UTAK_JOINED_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/impression.h"

/* Objects whose pull was begun, remembered in a task. */
#define JOINED_TRIED 4

typedef struct JoinedRun {
	bool pulling;    /* a pull of the object he would claim under way (apart.h) */
	bool swinging;   /* ... or a quarter turn of it (swing.h) */
	bool going;      /* ... or going where it can be pulled from: */
	Vec2 goal;       /* ... that square's centre, model frame ... */
	int32_t ident;   /* ... and the node to pull (model ident) */
	int tried;       /* pulls begun this task */
	int32_t tried_ident[JOINED_TRIED];
	Vec2 tried_at[JOINED_TRIED];
} JoinedRun;

struct Controller;

/* joined_open(c, k): "go SHAPE" for a shape other than the square, node k seen whole
 * and read that shape, and no pull has shown it one object (apart_one). */
bool joined_open(struct Controller *c, int32_t k);

/* joined_tried(c, k): a pull of node k was begun this task. */
bool joined_tried(const struct Controller *c, int32_t k);

/* joined_begin(c, k): joined_open and not tried: the pull begun (its grasp the next
 * command) when it can be made from where Utak stands, else the way begun to the
 * nearest square it can be made from (apart_goal), when the way is known; false,
 * nothing begun, when neither. */
bool joined_begin(struct Controller *c, int32_t k);

/* joined_loop_closed(c): "go round": where the loop closed (its last point before
 * home), round the task's object, joined_begin on it: pulled from there, beside it,
 * then home (as rival.h's OWN FIRST ON A LOOP: from home, the way back to it and
 * out again looks at the world anew, and raised other doubts). */
bool joined_loop_closed(struct Controller *c);

/* joined_goal(c, out): while going to pull it, the goal (goals.c). */
struct GoalResult;
bool joined_goal(struct Controller *c, struct GoalResult *out);

/* joined_arrive(c): arrived where the pull can be made: begun if it can be from
 * there (else the claim is judged with the doubt standing); false when Utak was not
 * going there. */
bool joined_arrive(struct Controller *c);

/* joined_decide(c, cmd): the next command while the pull is under way; false when
 * there is none (the claim is then judged again where he stands). */
bool joined_decide(struct Controller *c, MotorCommand *cmd);

/* joined_perceive(c, cmd, note, size): the trace's note on a command of the pull;
 * false when none was under way. */
bool joined_perceive(struct Controller *c, const MotorCommand *cmd, char *note, size_t size);

#endif
