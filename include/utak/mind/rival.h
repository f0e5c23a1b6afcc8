/* rival.h - settling a doubt about ANOTHER object by going to it (issue 13 item 6:
 * "where his model cannot tell, he goes and looks"; paper 3.3: a shape read from
 * the squares an object covers is a hypothesis until confirmed). CONTROLLER SIDE:
 * it acts on the world model and the impressions only.
 *
 * WHY. "The square" is the object of that shape nearest the start
 * (doc/verdicts.md). Utak's claim on an object is in doubt when another object,
 * the RIVAL, may be the one the task means (objects_doubt, objects_rival):
 *   - one nearer the start never seen whole in the fovea, an unnamed crumb that
 *     may be a small square, or one read a square with a doubt of its own;
 *   - one as far or farther read a square too: if the object claimed is a polygon
 *     of more corners over a square's squares (no eye can tell), the rival is the
 *     square and the task means it.
 * Often Utak could tell: the rival was only seen from afar (a closer look names
 * it), or it is no square, which shape by motion shows (probe.h: pushed by a
 * fraction of a square, a polygon that is no square owns squares no square would).
 * A rival so shown to be no square (or named another shape by the fovea) can be
 * the task's object in no world that agrees with what Utak has seen, and the doubt
 * it raised is gone: the claim is judged again without it. A rival the probe does
 * not disprove stays a doubt (a probe can only disprove a square, never prove one):
 * nothing is claimed that was doubted without such a proof.
 *
 * WHEN. Where Utak would claim with a doubt that names a rival: "go square" beside
 * the object (controller.c, arrive), "go round square" where the loop closes
 * (below) and home from it, "push square" beside the object before he grasps it
 * (the object to push is chosen then). At most RIVAL_MAX rivals a task, each once (by ident and by place), and
 * only when the way there is known: a cell beside it (or in view of its unseen
 * squares) reachable on the current screen.
 *
 * HOW. Utak goes to the rival: first to look at the squares of it the fovea has not
 * seen (objects_unconfirmed_square), and at the floor round it not seen in the
 * fovea (the probe asks for it), each look from where the fovea holds the square
 * (fovealook.h: it reaches three squares north and east of him, four south and
 * west), then beside it (goals_beside), at most RIVAL_ARRIVALS goals, a look that
 * showed more of it than any before not counted (RIVAL_GAINS). A rival that
 * leaves the model on the way is not marked settled (rival_lost). Each arrival asks whether the rival is still open
 * (objects_rival_open): seen whole and named no square (nor an unnamed crumb), it
 * is settled. Touching it, seen whole, he probes it exactly as the claimed square
 * is probed (probe_begin: grasp, quarter-square pushes, looks, push back, release;
 * only where the probe can be made safely). A disproved rival is named nothing
 * from then on (probe_disproved, objects_read). Then he returns to his claim and
 * it is judged again from the start: "go square" and "push square" go back to the
 * very point beside the object he set off from (where he would have claimed, or
 * grasped: a push planned from elsewhere is another push), "go round square" goes
 * home (the whole trail counts for the winding, his measure and the judge's alike).
 * OWN FIRST. Beside the object he would claim (not home from a loop), Utak first
 * probes that object itself, once, where the probe can be made safely: a rival is
 * a doubt only while this one may be a square. Disproved, it is named nothing and
 * dropped (as a claimed square is, probe.h), and the task goes on to the next
 * object of the shape; may be a square, the rival is gone to as above, and "go
 * square"'s claim makes no second probe of it (rival_own_probed).
 * OWN FIRST ON A LOOP. "Go round square" walks round the object without touching
 * it, and home he is far from it: a rival seen whole that reads a square would
 * never be probed (the object gone round was not), and the doubt would stand. So
 * where the loop closes (its last point before home, or the closer looks after
 * it: rival_loop_closed, Utak beside the object still) and a doubt names a
 * rival, he probes the object gone round first: touching it, from there; else he
 * goes back beside it (RIVAL_OWN_GO: looks at its ring seen only coarsely, then
 * goals_beside; only when it is seen whole and nothing but floor may lie round it,
 * own_may_probe), at most RIVAL_MAX such trips a task. May be a square: on to the
 * rival as above, then home. Disproved: it is dropped, the loop round it counts
 * for nothing, and the task goes on (a loop round the next one of the shape).
 * Not from home (rival_begin there is rival8's: a rival seen whole is left): the
 * way back to the object and out again would cost the approach twice (random
 * g114, 290 cycles, ran out of the 300 so).
 * NARROW, AND PIECES SHOWN. The same OWN FIRST probe is made of the object Utak
 * would claim when no rival is named but its own squares may be those of a
 * polygon under 2 wide (objects_narrow: the probe may show it no square of sides
 * PROBE_MIN_SIDE or more, or at least 2 wide: probe.h), or when a probe in the
 * task has shown an object read a square to be none and this one was never
 * probed (objects_pieces_shown: "push square" makes no probe of its own, and
 * random g145 pushed a second piece to the corner, a false success, once the
 * first was disproved). Then arrive judges the claim again.
 * MERGED (objects.h): a rival that may hold a square merged in the model with a
 * neighbour is no square by sight, and a probe asks the wrong question (whether ONE
 * square owns the squares). Beside it, seen whole, Utak pulls it instead
 * (apart.h): come away whole, it is one object and the doubt is gone; else it
 * stands. The rival needs no probe of the object claimed first (it reads no
 * square, so it shows no pieces that read one), and before a push the object
 * claimed is not probed for it (the probe's error of motion would move the
 * square to be pushed, as for MERGED alone: perturbed slant-p3).
 * HALF A SQUARE. A rival's probe whose looks showed no change at all (probe.h:
 * no count other than before, at any place of the eye's grid the look allows)
 * settles nothing; a rival whose edges lie a quarter to three quarters into
 * their squares owns exactly the same squares pushed a quarter square either way
 * (perturbed clutter's 4 x 2 bricks). Touching it still, Utak probes it once more
 * with pushes of PROBE_HALF_STEP, which carry every such edge across a square's
 * edge (probe_begin_step); that probe is judged alone, as the first, and only an
 * INCONSISTENT verdict lifts the doubt (tests/unit/test_halfstep.c: such bricks
 * rejected every time, true squares never). 6 cycles more, only then.
 * COST: a probe's 6 cycles, the way there and back, and a probe's 6 cycles, only
 * where a rival doubt arises (going round, and the short way back beside the
 * object gone round). */
#ifndef UTAK_RIVAL_H
#define UTAK_RIVAL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/base/geom.h"
#include "utak/impression.h"
#include "utak/mind/probe.h"

/* Rivals settled a task, at most. Two left the third of perturbed clutter-p1's
 * and -p2's four bricks nearer the start unvisited (the doubt stood on it, at 88
 * and 89 cycles of 300); with four, each is gone to and probed (104 and 105
 * cycles). */
#define RIVAL_MAX 4
/* Goals reached going to one rival (looks at its unseen squares, then beside it),
 * at most: a rival whose squares stay unseen from where Utak can stand is left. */
#define RIVAL_ARRIVALS 4
/* Arrivals whose look showed more of the rival in the fovea than any before it,
 * not counted against RIVAL_ARRIVALS, at most: a rival wider than the fovea (8
 * squares) is seen whole only a part a look (random g188: a piece of 98 squares,
 * 85 of them seen in four looks, and the doubt stood). Each such look shows a
 * square more at least, so the trip ends. */
#define RIVAL_GAINS 6

typedef enum RivalStage {
	RIVAL_IDLE,
	RIVAL_GO,    /* going to the rival: to look at it, then beside it */
	RIVAL_PROBE, /* probing it (probe.h) */
	RIVAL_OWN,   /* probing the object Utak would claim first (OWN FIRST) */
	RIVAL_OWN_GO, /* "go round": going back beside the object gone round, to probe it */
	RIVAL_APART, /* pulling it, to see it come away whole (MERGED, apart.h) */
} RivalStage;

typedef struct RivalRun {
	RivalStage stage;
	int32_t ident;   /* the rival (model ident) */
	Vec2 at;         /* ... the centre of its rectangle when chosen, model frame */
	int arrivals;    /* goals reached going to it */
	Vec2 arrived_at; /* ... the last of them */
	int gained;      /* ... of them, those that showed more of it in the fovea (RIVAL_GAINS) */
	int32_t foveal;  /* its squares seen in the fovea, the most at any arrival */
	bool home_after; /* "go round": home again when it is settled */
	bool merged;     /* set off to as MERGED's rival: only a pull settles it (apart.h),
			    never a probe (a pair is disproved as one square) */
	Vec2 back;       /* where he stood beside the object he would claim ... */
	bool returning;  /* ... and he is going back there (the others) */
	int count;       /* rivals begun this task */
	int lost;        /* ... and trips to one that left the model, not counted (rival_lost) */
	int32_t tried_ident[RIVAL_MAX];
	Vec2 tried_at[RIVAL_MAX];
	char note[400]; /* what settling did since the last impression, for the trace */
	/* Objects Utak would claim that he probed first (OWN FIRST), and found
	 * may be squares: the claim's probe is not made again. */
	int32_t own_ident[PROBE_RUNS];
	Vec2 own_at[PROBE_RUNS];
	int own_count;
	bool own_alone; /* the probe under way (OWN FIRST) is for a doubt that names no rival */
	/* "go round": trips back to the object gone round begun this task (OWN
	 * FIRST ON A LOOP), at most RIVAL_MAX. */
	int own_trips;
} RivalRun;

struct Controller;
struct GoalResult;
/* rival_begin(c, k): the doubt on node k (the object Utak would claim) names a rival
 * that may be settled (WHEN): going to it begun; false when none is (the doubt
 * stands as it is). */
bool rival_begin(struct Controller *c, int32_t k);
/* rival_goal(c, dist, out): while going to a rival, the goal (a look at it, or
 * beside it; exploring, so that arriving is the rival's: rival_arrive); false when
 * no rival is being gone to. */
bool rival_goal(struct Controller *c, const int32_t *dist, struct GoalResult *out);
/* rival_arrive(c): a goal reached while going to a rival: settled by sight, a probe
 * begun, or on to the next goal; false when no rival is being gone to. */
bool rival_arrive(struct Controller *c);
/* rival_decide(c, cmd): probe_decide, but a probe of a rival ends without claiming
 * or dropping the task's object: the rival is disproved or not, and Utak returns
 * to his claim. */
bool rival_decide(struct Controller *c, MotorCommand *cmd);
/* rival_perceive(c, cmd, note, size): probe_perceive, the note saying a rival was
 * probed. */
bool rival_perceive(struct Controller *c, const MotorCommand *cmd, char *note, size_t size);
/* rival_probing(c): a probe of a rival, or of the object claimed (OWN FIRST), or a
 * pull of a rival (MERGED), is under way. */
bool rival_probing(const struct Controller *c);
/* rival_own_probed(c, k): node k, the object Utak would claim, was probed first
 * (OWN FIRST) and may be a square: its claim needs no second probe. */
bool rival_own_probed(const struct Controller *c, int32_t k);
/* rival_loop_closed(c): "go round square", the loop just closed round the task's
 * object (its last point before home), seen whole, and a doubt names a rival:
 * settling begun from there, beside the object (OWN FIRST ON A LOOP), then home;
 * false when nothing was begun (home as before). */
bool rival_loop_closed(struct Controller *c);

#endif
