/* worldmodel.h - Utak's world model and its accommodation to impressions (paper 3.3, 3.4.3, 3.5).
 * CONTROLLER SIDE: built from Impressions and the MotorCommands the controller
 * gave, never from the TABLE or the world file.
 *
 * FRAME. Utak's own Cartesian frame at the first impression: x to his right, y
 * ahead, which is "north" for the tasks (paper 2.3; his heading never changes in
 * this simulation, utak(5)); one unit is one square; the origin is the
 * lower-left corner of the square he stood on at the first impression. Model
 * square (x, y) is [x, x+1] x [y, y+1]. Every coordinate below is in this frame,
 * the "$floor frame", unless said otherwise.
 *
 * TWO LAYERS.
 * 1. The evidence grid: for every square within WORLDMODEL_REACH of the origin on
 *    both axes, what the eye has said about it: an estimate p that it is
 *    occupied, the finest resolution it was seen at (fovea > intermediate >
 *    periphery; 0 = never seen, i.e. unknown), and a confidence. This is what
 *    every impression updates. It is stored in tiles of WORLDMODEL_TILE x
 *    WORLDMODEL_TILE squares, each allocated when a square of it is first seen,
 *    so that the model grows with what Utak has seen, up to the largest TABLE
 *    utak(5) allows, whatever square he starts on and whichever way he faces.
 *    MEMORY: sizeof(Evidence) = 12 bytes a square, in tiles of 48 KiB, for the
 *    tiles holding a square seen; and a directory of one pointer per tile of the
 *    whole reach, 512 KiB. A TABLE of 8192 x 4096 seen whole: about 400 MiB; a
 *    room of 100 x 100: a few tiles, well under 1 MiB.
 * 2. The tree of paper 3.3, derived from the grid after every impression: $org
 *    (Utak) -> $floor (the floorspace) -> one node per isolated object, and one
 *    NODE_UNCERTAIN per occupied set the rules cannot yet read. A node has
 *    its containing rectangle, its boundary as circular lists of straight segments
 *    (rings: outer boundaries counter-clockwise, holes clockwise), its relation
 *    to its parent (the offset of its frame's origin in the parent's frame: the
 *    lower-left corner of its rectangle) and a confidence. $floor's relation to
 *    $org is the floor origin seen from Utak, -utak: moving Utak changes that one
 *    relation. An object Utak holds hangs under $org instead of $floor, so
 *    pushing it moves it with him, again by one relation.
 *
 * BELIEF per square: unknown (never seen), occupied (p >= 1/2: a square under a
 * cell at least half occupied), or floor. A coarse cell with only a little in it
 * (a 4 x 4 cell at level 1 or 2) therefore reads as floor until it is seen finer
 * (unless an earlier cell of its resolution read the square occupied: below);
 * a planner that must not cut through thin things seen far away can look at
 * worldmodel_evidence (p, res, conf). Utak's own square is floor (he stands on
 * it). The first model's objects need not be the first impression's object
 * regions: a region joined to the verge by a faint cell may be an object here.
 *
 * CONFIDENCE RULES (all in [0, 1]):
 * - An observation of a square in a cell of resolution r with estimate q has
 *   weight base(r) x |2q - 1|: base is WORLDMODEL_CONF_FOVEA, _INTERMEDIATE,
 *   _PERIPHERAL; |2q - 1| is 1 for a cell wholly floor or wholly occupied and 0
 *   for half and half.
 * - Finer resolution replaces coarser: the square takes q and that weight.
 * - The same resolution, agreeing (same side of 1/2): p is averaged and the
 *   confidence grows, c += (1 - c) x weight x WORLDMODEL_CONF_GROWTH.
 * - The same resolution, contradicting: p = q and c = weight x
 *   WORLDMODEL_CONF_CONTRADICTED; except that a cell whose level is not zero
 *   never makes floor of a square believed occupied (it says something in it is
 *   occupied, not which squares: paper 3.4.2, only a zero cell is floorspace):
 *   the square stays occupied, its confidence times WORLDMODEL_CONF_DECAY. So a
 *   thin wall seen only by coarse cells that straddle it is not erased by the
 *   last look; a zero cell or a finer one settles the square.
 * - A coarser cell whose level disagrees with what the finer knowledge inside it
 *   predicts lowers those squares' confidence by WORLDMODEL_CONF_DECAY; a square
 *   whose confidence falls under WORLDMODEL_CONF_FORGET is re-estimated at the
 *   coarser resolution. A coarser cell that agrees raises them a little.
 * - A segment's confidence is the mean over its unit edges of the mean confidence
 *   of the squares on its two sides (an unknown square counts 0, so a frontier
 *   of the unseen has low confidence); a vertex's, the mean over the four squares
 *   meeting at it; a node's, the mean over its squares.
 *
 * ACCOMMODATION (paper 3.4.3, 3.5): see worldmodel_accommodate. */
#ifndef UTAK_WORLDMODEL_H
#define UTAK_WORLDMODEL_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "utak/base/geom.h"
#include "utak/impression.h"

enum {
	/* How far the model reaches from Utak's first square, on each axis: the largest
	 * TABLE side utak(5) allows, so that no square of any TABLE lies beyond it,
	 * whichever square Utak starts on. Squares -REACH..REACH-1. */
	WORLDMODEL_REACH = 8192,
	WORLDMODEL_SIDE = 2 * WORLDMODEL_REACH, /* squares along each axis of the reach */
	WORLDMODEL_TILE = 64,                   /* a tile of evidence: 64 x 64 squares */
	WORLDMODEL_TILES = WORLDMODEL_SIDE / WORLDMODEL_TILE, /* tiles along each axis */
	WORLDMODEL_DEFAULT_FLOOR = 32,   /* the default $floor: a square of the eye's field */
	WORLDMODEL_DISPARITY_RADIUS = 3, /* positions tried around the predicted one */
	WORLDMODEL_MIN_COMPARED = 24,    /* cells a position must be judged on to count */
	WORLDMODEL_HELD_MAX = 1024,      /* squares of a held object the model can carry */
	WORLDMODEL_WALLS = 64,           /* object nodes touch showed to be wall, kept */
};

/* Resolutions, finest last, so that a larger number is finer. */
enum {
	WORLDMODEL_UNSEEN = 0,
	WORLDMODEL_RES_PERIPHERAL = 1,
	WORLDMODEL_RES_INTERMEDIATE = 2,
	WORLDMODEL_RES_FOVEA = 3
};

#define WORLDMODEL_CONF_FOVEA 0.9
#define WORLDMODEL_CONF_INTERMEDIATE 0.6
#define WORLDMODEL_CONF_PERIPHERAL 0.3
#define WORLDMODEL_CONF_GROWTH 0.5
#define WORLDMODEL_CONF_CONTRADICTED 0.5
#define WORLDMODEL_CONF_DECAY 0.7
#define WORLDMODEL_CONF_FORGET 0.2
/* Disparity (paper 3.5): a position's measure is the sum of |predicted level -
 * actual level| / 7 over the cells the model can predict, plus a small cost for
 * each cell it cannot, over the 159 cells other than Utak's. The predicted
 * position stands unless another does better by WORLDMODEL_DISPARITY_MARGIN
 * (about a third of one foveal cell wrong) and the prediction cannot explain
 * every cell it predicts once each difference is taken beyond the slack of the
 * knowledge under it (a square known only from a 4 x 4 cell at level 0 or 7 may be
 * the one square of 16 that the cell's rounding hides: worldmodel.c,
 * wm_tolerant_mismatch, wm_explained). */
#define WORLDMODEL_DISPARITY_MARGIN 0.002

typedef enum Belief { BELIEF_UNKNOWN, BELIEF_FLOOR, BELIEF_OCCUPIED } Belief;

/* What the eye has said about one square. */
typedef struct Evidence {
	float p;      /* estimated probability that the square is occupied */
	float conf;   /* confidence in p, 0..1 */
	uint8_t res;  /* finest resolution seen at, WORLDMODEL_UNSEEN if never */
	uint8_t seen; /* observations at that resolution (saturates at 255) */
	uint8_t cell; /* seen at WORLDMODEL_RES_PERIPHERAL: its place (x + 4 y) in the
	                 4 x 4 cell last read it, so squares read by one cell are known */
} Evidence;

/* NODE_UNCERTAIN: an occupied set that touches the unseen, so that neither rule of
 * paper 3.4.2 decides it: the verge, or an object not yet seen whole. It has a
 * rectangle, squares and confidence but no rings: its sides facing the floor are
 * already $floor's boundary (segments "beyond occupied"). */
typedef enum NodeKind { NODE_ORG, NODE_FLOOR, NODE_OBJECT, NODE_UNCERTAIN } NodeKind;

/* One corner of a boundary, and the straight segment from it to the next. */
typedef struct ModelVertex {
	Vec2 p;         /* $floor frame */
	float conf;     /* of the vertex */
	float seg_conf; /* of the segment to the next vertex */
	uint8_t beyond; /* a Belief: what lies outside the segment (occupied or unknown) */
} ModelVertex;

/* A closed boundary: vertices first..first+count-1, circular. */
typedef struct ModelRing {
	int32_t first, count;
	bool hole; /* clockwise: a hole in the node's shape */
} ModelRing;

typedef struct ModelNode {
	NodeKind kind;
	char name[24]; /* "$org", "$floor", "object<ident>" */
	int32_t ident; /* an object's number, kept from impression to impression
	                  while its squares overlap; 0 for $org and $floor */
	int32_t parent, first_son, next_sibling; /* -1 none */
	Vec2 relation; /* origin of this node's frame in its parent's frame */
	Box rect;      /* containing rectangle, $floor frame */
	int32_t first_ring, ring_count;
	int32_t squares; /* squares believed part of the shape */
	float conf;
	bool held; /* an object Utak holds */
} ModelNode;

/* What the last accommodation did, for the trace and the dump. */
typedef struct Accommodation {
	Vec2 predicted;        /* where the command should have put Utak */
	Vec2 believed;         /* where he is now believed to be */
	double mismatch;       /* disparity measure at the predicted position */
	double best_mismatch;  /* ... at the believed position */
	int32_t compared;      /* cells compared at the predicted position */
	bool corrected;        /* the disparity search moved the belief */
	int32_t new_squares;   /* squares seen for the first time */
	int32_t finer_squares; /* squares seen at a finer resolution than before */
	int32_t candidates;    /* positions the disparity search scored (its cost) */
} Accommodation;

typedef struct WorldModel {
	/* WORLDMODEL_TILES^2 tiles, row-major, NULL where nothing has been seen; tile
	 * (tx, ty) holds squares x = tx * TILE - REACH + i, y = ty * TILE - REACH + j
	 * at [j * TILE + i]. */
	Evidence **tile;
	int32_t *tile_list; /* the tiles allocated, in the order they were */
	int32_t tile_count, tile_cap;
	Vec2 utak;           /* believed position of Utak's point, $floor frame */
	int32_t impressions; /* impressions accommodated */
	Impression last;     /* the last impression (its touch names a held object) */
	Accommodation report;
	int32_t next_ident; /* the last object number given */
	bool clipped;       /* some impression reached past WORLDMODEL_REACH */
	/* The held object: its squares as offsets from Utak's square. */
	bool holding;
	int32_t held_count;
	int32_t held_dx[WORLDMODEL_HELD_MAX], held_dy[WORLDMODEL_HELD_MAX];
	/* The box of the held offsets when the object was taken (or last turned): the
	 * set may regrow within it, and one square beyond (wm_regrow_held). */
	int32_t held_x0, held_y0, held_x1, held_y1;
	/* Set by the controller: after a push, put the held squares down where the
	 * impression shows the object lagged or led Utak's square (wm_register_held).
	 * Off while a carry (tasks (vi)-(ix), carrytask.h) follows the object as its
	 * own polygon, which the squares' shift would part from the model's squares. */
	bool register_held;
	/* Idents of object nodes touch has shown to be wall (colour B, paper 3.4.2: an
	 * occupied set apart from the verge may be a free-standing stretch of wall):
	 * the screen counts their squares as verge (screen.c), rooms with them. */
	int32_t wall_ident[WORLDMODEL_WALLS];
	int32_t wall_count;
	/* The derived tree (paper 3.3): arrays linked by index. */
	ModelNode *node;
	int32_t node_count, node_cap;
	ModelRing *ring;
	int32_t ring_count, ring_cap;
	ModelVertex *vertex;
	int32_t vertex_count, vertex_cap;
	/* Which node holds each occupied square of the derivation's window (x0, y0,
	 * w, h; row-major, -1 none): an object's own squares, which its rectangle
	 * alone cannot tell from a neighbour's. */
	int32_t *node_at;
	int32_t node_at_x0, node_at_y0, node_at_w, node_at_h;
	/* The squares ever seen: how many, and their containing rectangle (x0..x1,
	 * y0..y1, inclusive; meaningless when seen_count is 0). Kept by every change
	 * to the grid, so that no reader has to scan the whole evidence window. */
	int32_t seen_count, seen_x0, seen_y0, seen_x1, seen_y1;
	/* Motion's error as the disparity shows it (paper 3.5, uncertainty (2)): the
	 * squared corrections no halted move explains (across the commanded line, or
	 * past its end), and the squared lengths of all the moves and pushes
	 * commanded (worldmodel_motion_error). */
	double drift_sq, drift_len_sq;
	/* The squared lengths moved since the last impression that placed Utak on x,
	 * on y: one whose disparity measure a shift of one square along the axis,
	 * either way, would have made worse by WORLDMODEL_DISPARITY_MARGIN. */
	double unplaced[2];
	/* The first impression, taken where Utak's position is known exactly: his
	 * first square, (0, 0) (worldmodel_recognise_first). */
	Impression first;
} WorldModel;

/* worldmodel_init(m): the default world model (paper 3.4.3): Utak at the centre of
 * his first square, a square $floor of WORLDMODEL_DEFAULT_FLOOR around him, no
 * objects, nothing seen. worldmodel_free releases it. */
void worldmodel_init(WorldModel *m);
void worldmodel_free(WorldModel *m);

/* worldmodel_accommodate_first(m, imp): accommodates the default model to the
 * first impression (paper 3.4.3): records the evidence, fixes $floor's rectangle
 * and shape, and makes a node for every isolated object. */
void worldmodel_accommodate_first(WorldModel *m, const Impression *imp);

/* worldmodel_accommodate(m, cmd, imp): accommodates to the impression received
 * after the controller gave cmd (paper 3.5): builds the predicted model (Utak,
 * and for a push or turn the held object, moved as cmd says), projects it through
 * the eye into a predicted impression, compares. Differences in cells the model
 * has not seen, or seen only coarser, are explained by updating the model;
 * differences where the model is sure are a disparity: the positions within
 * WORLDMODEL_DISPARITY_RADIUS of the predicted one, and along the commanded
 * straight line (a move may have halted), are tried, and the best match becomes
 * Utak's believed position. After a push every position is tried with the held
 * object beside it (it moves with Utak, halted or not), and of those the eye cannot
 * tell from the best (within WORLDMODEL_DISPARITY_MARGIN) the one that puts the
 * fewest held squares on squares surely occupied wins (two things do not share a
 * square); and a position that puts fewer on squares believed occupied at all wins
 * where the impression shows it better, or where a push of a square left the
 * impression unchanged (a wall seen only coarsely: worldmodel.c, wm_pressed); it is
 * put down beside the
 * position found (with m->register_held, shifted by a square on either axis where
 * the impression shows it lagged or led his square: it rides with his point, not
 * his square, and a push halted a fraction of a square on, or gone astray, can
 * carry his point over a square's edge while its squares stay), and its squares
 * then seen as floor
 * leave the held set. Then the
 * evidence is recorded there and the tree derived again. The result is in
 * m->report. */
void worldmodel_accommodate(WorldModel *m, const MotorCommand *cmd, const Impression *imp);

/* worldmodel_motion_error(m): how far motion errs, in squares per square moved on
 * each axis, as the disparity has shown it (paper 3.5, uncertainty (2)): the root
 * of the squared corrections no halt explains over the squared lengths commanded
 * (a Gaussian error per move adds sigma^2 L^2 of variance on each axis). 0 while
 * there have been none: motion looks exact. Utak is never told the error. */
double worldmodel_motion_error(const WorldModel *m);

/* worldmodel_recognise_first(m, imp, &x, &y, placed): where, within
 * WORLDMODEL_DISPARITY_RADIUS of square (*x, *y), the first impression best
 * predicts imp (paper 3.5's fallback, recognition by features: the first
 * impression was taken where Utak's position is known exactly, so it places him
 * however far his belief has drifted since, while he is near enough to his first
 * square to see what it showed, and nothing seen has moved). It predicts a cell
 * where every square under it lay in a cell of the first impression that was
 * empty or full; (*x, *y) stands unless another does better by
 * WORLDMODEL_DISPARITY_MARGIN. On return (*x, *y) is the best square, and
 * placed[0], placed[1] say whether every square tried (one beyond the radius too)
 * with another x, another y, matched worse by the margin (or could not be judged):
 * the first impression places him on that axis. False, (*x, *y) and
 * placed untouched, when no candidate can be judged on WORLDMODEL_MIN_COMPARED
 * cells. */
bool worldmodel_recognise_first(const WorldModel *m, const Impression *imp, int32_t *x, int32_t *y,
                                bool placed[2]);

/* worldmodel_predict(m, x, y, pred, known): the impression the model predicts with
 * Utak on square (x, y); known[i] false where cell i's squares are not all known
 * and definite (then pred->level[i] is 0). Touch is not predicted ('?'). */
void worldmodel_predict(const WorldModel *m, int32_t x, int32_t y, Impression *pred,
                        bool known[RETINA_CELLS]);

/* worldmodel_mismatch(m, x, y, imp, &compared): mean |predicted - actual| / 7 over
 * the cells known to the model with Utak on (x, y); 1 when none are. */
double worldmodel_mismatch(const WorldModel *m, int32_t x, int32_t y, const Impression *imp,
                           int32_t *compared);

/* worldmodel_belief(m, x, y): what the model believes of square (x, y). */
Belief worldmodel_belief(const WorldModel *m, int32_t x, int32_t y);
/* worldmodel_known_squares(m): the squares whose belief is not unknown (those seen,
 * and Utak's own). */
int32_t worldmodel_known_squares(const WorldModel *m);
/* worldmodel_evidence(m, x, y): the square's evidence (all zero where never seen,
 * and beyond the reach). */
Evidence worldmodel_evidence(const WorldModel *m, int32_t x, int32_t y);

/* worldmodel_node_at(m, x, y): the node (index into m->node) whose squares hold
 * square (x, y): an object or an uncertain set; -1 for floor, unknown, or Utak. */
int32_t worldmodel_node_at(const WorldModel *m, int32_t x, int32_t y);

/* worldmodel_node_squares(m, k, xs, ys, max): node k's squares, row by row from its
 * rectangle's lower left, at most max of them into (xs, ys); how many it has (more
 * than max when they did not all fit). */
int32_t worldmodel_node_squares(const WorldModel *m, int32_t k, int32_t *xs, int32_t *ys, int32_t max);

/* worldmodel_utak_square(m, &x, &y): the square holding Utak's believed point. */
void worldmodel_utak_square(const WorldModel *m, int32_t *x, int32_t *y);
/* worldmodel_set_position(m, p): overrides the belief (tests give a wrong one). */
void worldmodel_set_position(WorldModel *m, Vec2 p);

/* worldmodel_dump(m, f): the report of the last accommodation, the tree (nodes,
 * relations, rectangles, rings with vertices and segment confidences, at 2
 * decimals), then the belief map of the seen window, the row farthest north
 * first: '.' floor, '#' occupied, '?' unknown, '@' Utak. */
void worldmodel_dump(const WorldModel *m, FILE *f);

/* worldmodel_validate(m, why, size): the tree's invariants: $org the root with one
 * son $floor; parents and sons agree; rings closed with >= 4 axis-aligned segments
 * and inside their node's rectangle. */
bool worldmodel_validate(const WorldModel *m, char *why, size_t size);
/* worldmodel_ring_outlines_object(m, r): ring r is a hole of $floor whose corners
 * are those of a ring of an object (the object's outline seen from the floor): for
 * readers that draw each outline once. */
bool worldmodel_ring_outlines_object(const WorldModel *m, int32_t r);

#endif
