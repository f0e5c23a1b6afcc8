/* objects.h - the objects of the world model named by shape: hypotheses and their
 * confirmation (paper 3.3, 2.3; the meaning in doc/verdicts.md). CONTROLLER
 * SIDE: the goals (goals.c) and the action cycle (controller.c) ask these.
 *
 * An object node's shape is read from its own squares (worldmodel_node_at) by
 * shape_read, at the scale of the coarsest cell any of them was seen in. Paper 3.3
 * gives every part of the model a "degree of confidence based on evidence
 * collected from a series of retinal impressions": here a shape read from squares
 * some of which were seen only in the outer zones is a HYPOTHESIS; it is CONFIRMED
 * when every square of the object has been seen exactly (objects_seen_exactly: in
 * the fovea, or, deep inside a big object where no place on the floor puts it in
 * the fovea, by 2 x 2 cells whose levels fix it), and then it is the
 * shape the object has (it may be another than the hypothesis, which is dropped).
 * A set too coarse to name at its scale (a 4 x 4 square seen in the periphery is
 * one or two blocks of 4) is still a hypothesis of low confidence: the shape its
 * squares would have if they had been seen in the fovea (GUESSED). A hypothesis of
 * the task's shape draws Utak closer, and the fovea then confirms or drops it.
 * Utak walks to a hypothesis to look at it; he claims to have reached an object
 * only when it is confirmed as the task's shape (objects_touching_target).
 *
 * THE TASK'S OBJECT ("the square") is, as for the judge, the object of the task's
 * shape nearest Utak's starting point (his point to the object's centroid), among
 * those Utak has named so (hypotheses too: he cannot know of others). The choice
 * is kept while it is not confirmed as another shape (a coarse look may show it
 * as none), until another object of the shape is seen nearer the start by more
 * than OBJECTS_SWITCH squares (so that a shape
 * read a square off from one place and right from the next does not draw Utak to
 * and fro).
 *
 * MEMORY: readings are kept in a small cache in the Controller, by object ident and
 * the squares read (shape_read costs milliseconds; the objects change little from
 * one impression to the next). */
#ifndef UTAK_OBJECTS_H
#define UTAK_OBJECTS_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "utak/mind/controller.h"
#include "utak/mind/shape.h"

/* Another object of the task's shape must lie this much nearer the start to take
 * the place of the one chosen (squares). */
#define OBJECTS_SWITCH 1.0
/* An object whose centroid lies this near the chosen one's is the chosen one, when
 * the model has given it another number (seen coarsely, an object can merge with
 * the unknown for an impression and come back; squares). */
#define OBJECTS_SAME 2.0

/* objects_same(ident, at, node_ident, node_at): an object remembered by its model
 * number and the centre of its rectangle is node's (number node_ident, centre
 * node_at): the same number, or, renumbered, centres within OBJECTS_SAME. The one
 * rule by which the probe, the rival's trips, the pulls and joined.h remember what
 * they have settled. */
static inline bool objects_same(int32_t ident, Vec2 at, int32_t node_ident, Vec2 node_at)
{
	return ident == node_ident || hypot(at.x - node_at.x, at.y - node_at.y) < OBJECTS_SAME;
}

/* objects_node_centre(c, k): the centre of node k's rectangle, model frame. */
Vec2 objects_node_centre(const Controller *c, int32_t k);

typedef struct ObjectReading {
	Shape shape;
	bool confirmed;   /* every square, and the floor round it, seen exactly */
	int32_t squares;  /* the object's squares */
	int32_t foveal;   /* how many of them were seen exactly (objects_seen_exactly) */
	double scale;     /* the side of the coarsest cell they were seen in: 1, 2 or 4 */
	Vec2 centroid;    /* of its squares, model frame */
	bool guessed;     /* the shape is a guess: the squares read as if seen in the fovea */
	double confidence; /* 1 confirmed; below, the share seen in the fovea, halved for a guess */
	ShapeReading reading;
	bool examined;     /* every square once seen in the fovea (now or before) */
	bool disproved;    /* read the square, but a probe showed it is none (probe.h):
			      its shape is then SHAPE_NONE */
	double shown_width; /* the least width a probe's looks showed (probe_width), 0
			       when none was probed */
	bool square_fits;   /* confirmed, named a brick, and some square of the probe's
			       hypothesis owns exactly its squares (objects.h, ANOTHER NAME) */
} ObjectReading;

/* objects_read(c, k): what object node k is, by shape (cached). */
ObjectReading objects_read(Controller *c, int32_t k);

/* objects_find_target(c): the model node of the task's object; -1 when no object
 * is named (as a hypothesis or confirmed) the task's shape. Sets c->target. */
int32_t objects_find_target(Controller *c);

/* objects_feel(c): after each impression, the object nodes in the touch cells
 * remembered by what touch felt there: a letter other than B, an object; B, wall
 * (paper 3.4.2: a set the eye takes for an object may be a wall it did not see
 * meet the verge). Utak goes round an object only once he has felt it
 * (objects_felt; controller.c); the world model keeps what touch found to be wall
 * (wall_ident: the screen counts it as verge). */
void objects_feel(Controller *c);
bool objects_felt(const Controller *c, int32_t k);
/* ... and the squares touch felt an object's colour on where the model holds no
 * object (an occupied set joined to the verge: paper 3.4.2's ambiguity, which
 * touch resolves there): c->felt_x, felt_y, kept for the whole task, so that
 * what touch showed in passing is not lost (goals_felt_tug goes back to draw the
 * object out, tug.h). objects_note_square adds a square to such a list once (a
 * full list stays as it is); objects_square_listed says whether it is there. */
void objects_note_square(int32_t *xs, int32_t *ys, int *n, int32_t x, int32_t y);
bool objects_square_listed(const int32_t *xs, const int32_t *ys, int n, int32_t x, int32_t y);

/* objects_wall(c, k): touch has felt node k as wall (B) and never as an object's
 * colour: a stretch of wall standing free, which the eye (gray levels only) takes
 * for an object. It is no candidate for the task's object and no object to doubt
 * or to look at again. A set of wall and object the model joins, felt only on its
 * wall side, is dropped with it: Utak then looks on, and can only fail honestly. */
bool objects_wall(const Controller *c, int32_t k);

/* objects_touching(c, k): touch shows an object's colour in a square of node k (any
 * object when k < 0). */
bool objects_touching(const Controller *c, int32_t k);

/* objects_touched_only(c, k): touch shows an object's colour, and every one it
 * shows lies on a square of node k: the grasp, which takes the first object colour
 * touch feels (paper 2.2), takes node k (probe.h, swing.h). */
bool objects_touched_only(const Controller *c, int32_t k);

/* objects_touching_target(c): Utak touches the task's object, confirmed as the
 * task's shape; a target confirmed as another shape is dropped (c->target = 0). */
bool objects_touching_target(Controller *c);

/* objects_doubt(c, k, why, size): whether the judge could name object node k, seen
 * whole in the fovea as the task's shape, otherwise (why says how). The eye knows
 * an object by the squares it covers, and the same squares are covered by objects
 * of other names: Utak claims a task on an object only when they are not.
 *   A CRUMB: a set of squares that a polygon under OBJECTS_NAMED_WIDTH may
 *   cover, which has no shape name (doc/verdicts.md): the reading's min_width
 *   (shape.h) under it. The bound is exact for polygons of any form: a 3 x 3
 *   block (min_width 1) is a crumb, a 4 x 4 block (2) is not. It replaced a
 *   count (at most OBJECTS_CRUMB squares), which doubted every 4 x 4 square
 *   that happened to cover 14 squares or fewer and no 15-square set, whatever
 *   its spread. A probe's looks bound the width too, for any polygon, and
 *   often higher (probe_least_width, ObjectReading.shown_width): the larger
 *   bound holds, and the doubt names both ("from 1.00; moved, at least 1.27").
 *   Utak probes the object in this doubt before he gives up (rival.h, NARROW).
 *   PIECES SHOWN: a probe this task showed an object read a square to be none,
 *   and this one was never probed: it may be such a piece (rival.h).
 *   NEARER THE START: the task's object is the one of its shape nearest the
 *   start; another object nearer may be it when its squares were never all seen
 *   in the fovea at once (EXAMINED; the floor round them need not be), or is of
 *   the shape, in doubt or not (a sure one nearer by less than OBJECTS_SWITCH
 *   does not take the chosen one's place: objects_find_target), or is a crumb left unnamed that spans 3
 *   squares or more each way (a square two wide or more, unless its sides lie on
 *   the grid's lines, does) and has OBJECTS_CRUMB_LEAST squares or more (such a
 *   square covers no fewer). A crumb named another shape is taken at its name,
 *   but for ANOTHER NAME: a nearer one seen whole read a brick that spans 3
 *   squares or more each way, whose squares some square of the probe's
 *   hypothesis owns exactly (probe_square_consistent with no push, asked once
 *   per reading: ObjectReading.square_fits), may be the task's square; the fit
 *   reads a true square of 2.3 to 2.5 turned 15 to 45 degrees 1.36 to 1.53 times
 *   as long as wide (its squares are a rectangle's of those proportions too),
 *   a brick, and Utak passed it by for a square farther on, a false success in
 *   38 of 160 poses of 2.2 to 2.6 squares (tests/worlds/near-turned-square.w).
 *   One read a brick but not seen whole (the floor round it not all seen in the
 *   fovea) was never asked so, and may own squares where that floor was seen
 *   only in cells of 4 or never (a cell of 4 x 4 over one occupied square reads
 *   0): it may be the square unless its squares' extent could not grow to a
 *   square's (within one square each way) on the sides where such floor lies
 *   (may_grow_square; tests/worlds/near-tie-brick.w: a square 2.6 wide turned
 *   0.3 radians, its far side seen coarsely, read a brick, and the farther
 *   square pushed to the corner: a false success).
 *   A probe that shows it no square settles it (rival.h); for "the brick", one read a square
 *   longer than SHAPE_SQUARE_ASPECT (in the gap) may be the brick the same way,
 *   and no probe settles that (the probe's hypothesis is a square).
 *   AS NEAR: the judge measures the distance to an object's area centroid, Utak
 *   to the centroid of its squares, which may lie half a cell's diagonal from
 *   it (cells of the coarsest resolution it was seen in: centroid_slack); so an
 *   object not seen whole, a crumb or one of ANOTHER NAME counts as nearer when
 *   its centroid is within the two slacks beyond the claimed one's too (one
 *   seen whole read the shape there is ANOTHER OF THE SHAPE's doubt already).
 *   Tests/worlds/near-tie.w: a square 2.6 wide seen from afar, read a brick
 *   0.5 farther than the square he chose, was 0.3 nearer: he pushed the farther
 *   square to the corner and believed it done.
 *   THE NEARER UNSEEN: where floor the model knows borders unseen squares nearer
 *   the start than the object's centroid (goals_unseen_within), an object of
 *   the shape may lie there; goals.c looks at such space before going to the
 *   object, and what cannot be reached or seen stays a doubt.
 *   THE GAP: a square is at most SHAPE_SQUARE_ASPECT long for its width, a brick at
 *   least SHAPE_BRICK_ASPECT; read between the two (shape.h names it the nearer),
 *   the object may be neither.
 *   INEXACT: read a square or a brick, but the best rectangle the fit found
 *   differs from the squares on some (ShapeReading.fit_error): the squares a
 *   rectangle covers, seen in the fovea, are fitted exactly (measured: 5000 of
 *   5000 rectangles of aspect up to 1.2, sides 2.5 to 8, at random angles and
 *   offsets; 2992 of 3000 of aspect up to 3), and a polygon of more corners
 *   often leaves a square in or out that no rectangle does (worldgen's pieces).
 *   OTHER FRAME: the fit finds one rectangle of the many that may cover the
 *   same squares; read again with the squares turned a quarter or mirrored, it
 *   may find another, exact too, of other proportions (a 22-square set read 1.02
 *   one way and 1.26 another): then the object may be neither a square nor a
 *   brick. Asked only of the object claimed (8 readings). True squares of sides
 *   3 to 7 at random angles and offsets are doubted so about 4% of the time
 *   (measured, 23 of 571; mostly the small ones), rightly: their squares are a
 *   rectangle's of other proportions too.
 *   ANOTHER OF THE SHAPE: another object, as far from the start as this one or
 *   farther, is read the task's shape too (confirmed, a hypothesis, or a guess
 *   from squares too coarse to name). Asked last, of the object claimed. No eye
 *   can tell a square from a polygon of more corners whose cut corners fall
 *   within the squares the square covers (below), and worldgen's pieces do so
 *   at their size (a brute force over every angle: 6 of the 7 pieces Utak took
 *   for the square in 300 random worlds cover exactly a square's squares):
 *   with no other object of the shape seen, the claim is wrong only where a
 *   square lies beyond what he has seen; with one, the world in which this one
 *   is such a polygon and that one the square agrees with all he has seen, and
 *   the task means that one (tests/worlds/piece-square.w). Measured on the 180
 *   random square, round and push runs of tests/rates.sh (172 apply): false
 *   successes 9 -> 5 (the 4 now honest failures: a piece claimed while the
 *   true square, another piece or a coarse guess read a square farther on);
 *   the 95 achieved stay achieved, 17 more of them doubted (45 -> 62), in 15
 *   a piece or a brick read a square farther on: the same sight as a false
 *   success's, the other way round. Perturbed worlds/ (300 runs): 2 more
 *   doubted (two squares); no golden run changes. Counting guesses or not
 *   changes little (without them: false 9 -> 7, doubted 45 -> 53).
 *   MERGED: a square within one square of another object owns squares beside
 *   that object's (no square is owned by two: utak(5)), and the model holds
 *   the two as one object, seen whole, that reads no shape, or an L (a square
 *   beside a bar), which the rules above pass by: he claimed a farther square
 *   (near13b's adversarial worlds: 14 false successes of 332 runs;
 *   tests/worlds/near-merged.w, near-merged-l.w). So an object of the model
 *   nearer the start, seen whole or not, not read the square, of
 *   OBJECTS_CRUMB_LEAST squares or more (fewer are no square's off the grid's
 *   lines, above), is a doubt where (1) its squares hold a 2 x 2 block whose
 *   shared corner lies under sqrt(0.5) beyond the claimed one's distance plus
 *   its centroid_slack (a square 2 wide or more owns the 4 squares round the grid
 *   point nearest its centroid, which lies within sqrt(0.5) of it: the judge's
 *   square's centroid can lie no nearer; checked against squares at every angle,
 *   test_nearer.c), and (2) they are no convex polygon's: some square centred
 *   strictly inside the hull of their centres is not one of them (a convex
 *   polygon owns every such square, test_nearer.c; one object with a notch, or
 *   two with a cleft between). Not doubted: a brick a rectangle fits exactly
 *   (a square end to end with a bar may read so, and so may a square and a
 *   neighbour whose squares together are a convex polygon's: the doubt would
 *   fall on every brick and convex piece nearer the start, which cells alone
 *   never tell from such a pair). No look settles it: a look shows the squares
 *   he has, and a probe asks whether ONE square owns them all (a pair is
 *   disproved as one). Motion does: the object, seen whole, is the doubt's
 *   rival (objects_merged_rival), and Utak pulls it (apart.h, from rival.h):
 *   come away whole, it is one object, not convex, so no square, and the doubt
 *   on it is gone (apart_one); else it stands. The doubt is asked last (the
 *   doubts before it name rivals and probes that may settle the claim), and
 *   it asks for the OWN FIRST probe of the object claimed (rival.h): shown no
 *   square, that one is dropped and the task goes on. Cost, random square
 *   tasks of tests/rates.sh (182 runs): 9 achieved runs doubted (50 -> 41 achieved
 *   without a doubt), none failed. Without (2), and with L-shapes and triangles
 *   an L or a triangle fits exactly left out too: 15 doubted, and 3 of the 14 left
 *   false (j11, j15: an L fits a square beside a slanted bar exactly).
 * What it cannot tell, and no eye can at this scale: a polygon of more corners
 * whose cut corners fall within the squares of a rectangle's (a hexagon with
 * corners cut by under a square reads as the rectangle). */
/* The most squares a rectangle under two squares wide and at most 1.2 times as
 * long covers (measured: 1.99 x 2.39 at every 5 degrees and eighth-square
 * offsets, 14; a 1.99 square covers at most 12): an unnamed set nearer the start
 * no larger may be a square (objects_doubt). */
#define OBJECTS_CRUMB 14
/* The fewest squares a square two wide or more covers when they span 3 squares
 * each way (off the grid's lines): measured, every quarter degree and hundredth
 * of a square of offset, 8 (a 2 x 2 square turned 37 degrees); a larger square
 * holds a concentric 2 x 2 one and covers its squares too. An unnamed set nearer
 * the start of fewer squares (clutter.w's 7-square triangle) is no such square
 * (tests/unit/test_shape.c checks the count against geom_project). */
#define OBJECTS_CRUMB_LEAST 8
/* The least width the verdicts give a name (doc/verdicts.md: a polygon narrower
 * is unnamed). A set of squares that a polygon narrower than this may cover is a
 * crumb to objects_doubt (shape.h, min_width: a bound on the width of every
 * polygon covering the set, from how far its centres spread in each direction). */
#define OBJECTS_NAMED_WIDTH 2.0
bool objects_doubt(Controller *c, int32_t k, char *why, size_t size);
/* objects_rival(c, k): the node of the other object that objects_doubt's doubt on
 * node k names (one NEARER THE START, or ANOTHER OF THE SHAPE), -1 when there is
 * no doubt or it names no other object. Utak goes and settles such a rival before
 * he claims (rival.h). objects_rival_open(c, j): node j may still be the task's
 * object by its own sight: never seen whole in the fovea, or read the task's
 * shape, or an unnamed crumb that may be a small square, or of ANOTHER NAME (a
 * crumb or brick a probe has shown no square owns is none: probe.h). */
int32_t objects_rival(Controller *c, int32_t k);
bool objects_rival_open(Controller *c, int32_t j);
/* objects_doubtful(c, k): node k is seen whole and doubtful by its own measures
 * (a crumb, in the gap, or inexact): one of the shape beyond doubt goes before it as the
 * task's object (objects_find_target), and after a loop round it Utak looks once
 * more for one (controller.c). */
bool objects_doubtful(Controller *c, int32_t k);
/* objects_narrow(c, k): node k is seen whole and its squares may be those of a
 * polygon under OBJECTS_NAMED_WIDTH (a crumb, objects_doubt), by their spread
 * and by what a probe of it showed: a probe may tell more (rival.h, NARROW). */
bool objects_narrow(Controller *c, int32_t k);
/* objects_pieces_shown(c, k): node k is seen whole, a probe this task showed an
 * object read a square to be none, and k was not probed: a doubt a probe of k
 * settles (objects_doubt, rival.h). */
bool objects_pieces_shown(Controller *c, int32_t k);
/* objects_merged(c, k): node k, confirmed, is doubted for an object nearer the
 * start that may hold a square merged with its neighbour (MERGED, objects_doubt). */
bool objects_merged(Controller *c, int32_t k);
/* objects_merged_rival(c, j): node j, seen whole, is one MERGED doubts (for a claim
 * as far as any), and no pull has shown it one object (apart.h): the rival a
 * pull settles (rival.h). */
bool objects_merged_rival(Controller *c, int32_t j);
/* objects_misread(c, k): node k is seen whole and its own reading puts its name in
 * doubt (in the gap, or inexact), not only its width (a crumb read squarely the
 * task's shape, most often a small one of it). Before going to such a one Utak
 * looks further, while anything is left to see, for one beyond doubt (goals.c,
 * controller.c): a brick 3 x 2 off the grid's lines covers a 4 x 3 block, read
 * 1.33 long for its width, and is the commonest such (perturbed clutter.w). */
bool objects_misread(Controller *c, int32_t k);

/* objects_seen_exactly(m, k, x, y): the model knows square (x, y) of node k (or
 * round it) exactly: seen in the fovea; or, where no place but k's own squares
 * would put it in the fovea (every square of the 8 x 8 block of places the fovea
 * shows it from is k's), seen at best in 2 x 2 cells that each fixed it (p exactly
 * 1 or 0). WHY: the fovea reaches 4 squares to one side of Utak and 3 to the other
 * (eye.h), so the middle of an object 8 or more squares across both ways is never
 * in it from the floor, and by the fovea alone such an object is never seen whole
 * (a 10 x 10 square: "go square" ran out of cycles, "go round square" ended in
 * doubt). A 2 x 2 cell's five levels (0, 2, 4, 5, 7 for 0 to 4 squares:
 * READING.md) tell how many of its squares are occupied, so a cell at 7 (or 0),
 * or one whose other squares are known, fixes each square as the fovea would. A
 * 4 x 4 cell's level does not (15 of 16 reads 7), so it never counts: the middle
 * of an object 16 or more across both ways stays unconfirmed. Elsewhere the
 * fovea's look is kept: it is where the looks closer that settle a claim's other
 * doubts are made. */
bool objects_seen_exactly(const WorldModel *m, int32_t k, int32_t x, int32_t y);
/* objects_lacks(c, k, x, y): square (x, y) is one that node k's confirmation lacks:
 * not seen exactly (objects_seen_exactly), and a square of k or a 4-neighbour of one. */
bool objects_lacks(const Controller *c, int32_t k, int32_t x, int32_t y);

/* objects_unconfirmed_square(c, k, &x, &y): a square of node k not yet seen in the
 * fovea, the nearest Utak; false when there is none. */
bool objects_unconfirmed_square(const Controller *c, int32_t k, int32_t *x, int32_t *y);

#endif
