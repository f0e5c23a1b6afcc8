/* objects.c - the objects of the world model named by shape: hypotheses and their
 * confirmation, and the task's object (paper 3.3, 2.3). CONTROLLER SIDE. The rules
 * are in objects.h. */
#include "utak/mind/objects.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "utak/base/eye.h"
#include "utak/base/util.h"
#include "utak/mind/apart.h"
#include "utak/mind/coarsewall.h"
#include "utak/mind/goals.h"
#include "utak/mind/joined.h"
#include "utak/mind/faint.h"
#include "utak/mind/probe.h"
#include "utak/mind/rival.h"
#include "utak/mind/shapefit.h"
#include "utak/mind/wallbump.h"

static const char *doubt_own(const ObjectReading *o);
static bool inexact(const ObjectReading *o);
static bool listed(const int32_t *list, int n, int32_t ident);
static bool in_gap(const ObjectReading *o);

/* Scale (shape.h) of each resolution: the side of its cells. */
static double objects_scale(int res)
{
	return res == WORLDMODEL_RES_FOVEA ? 1 : res == WORLDMODEL_RES_INTERMEDIATE ? 2 : 4;
}

bool objects_seen_exactly(const WorldModel *m, int32_t k, int32_t x, int32_t y)
{
	Evidence e = worldmodel_evidence(m, x, y);
	if (e.res == WORLDMODEL_RES_FOVEA)
		return true;
	if (e.res != WORLDMODEL_RES_INTERMEDIATE || (e.p < 1.0f && e.p > 0.0f))
		return false;
	/* Deep: every place from which the fovea would show (x, y) is k's. */
	for (int32_t oy = -EYE_FOVEA_HALF; oy < EYE_FOVEA_HALF; oy++)
		for (int32_t ox = -EYE_FOVEA_HALF; ox < EYE_FOVEA_HALF; ox++)
			if ((ox || oy) && worldmodel_node_at(m, x - ox, y - oy) != k)
				return false;
	return true;
}

ObjectReading objects_read(Controller *c, int32_t k)
{
	const WorldModel *m = &c->model;
	const ModelNode *n = &m->node[k];
	ObjectReading o = {SHAPE_NONE, false, 0, 0, 1, vec2(0, 0), false, 0, {0}, false, false, 0, false};
	int32_t x0 = (int32_t)floor(n->rect.lo.x), y0 = (int32_t)floor(n->rect.lo.y);
	int32_t x1 = (int32_t)ceil(n->rect.hi.x), y1 = (int32_t)ceil(n->rect.hi.y);
	int64_t cap = (int64_t)(x1 - x0) * (y1 - y0);
	if (n->kind != NODE_OBJECT || cap <= 0)
		return o;
	int32_t *xs = util_alloc((size_t)cap, sizeof *xs), *ys = util_alloc((size_t)cap, sizeof *ys);
	int coarsest = WORLDMODEL_RES_FOVEA;
	bool edge_seen = true; /* the floor round it seen in the fovea too */
	/* FNV-1a over the squares and their resolutions: the memo's key. */
	uint64_t key = 1469598103934665603u;
	for (int32_t y = y0; y < y1; y++)
		for (int32_t x = x0; x < x1; x++) {
			if (worldmodel_node_at(m, x, y) != k)
				continue;
			for (int d = 0; d < 4; d++) {
				static const int8_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
				int32_t nx = x + step[d][0], ny = y + step[d][1];
				edge_seen &= worldmodel_node_at(m, nx, ny) == k || objects_seen_exactly(m, k, nx, ny);
			}
			int res = worldmodel_evidence(m, x, y).res;
			coarsest = res < coarsest ? res : coarsest;
			o.foveal += objects_seen_exactly(m, k, x, y);
			o.centroid = vec2_add(o.centroid, vec2(x + 0.5, y + 0.5));
			xs[o.squares] = x;
			ys[o.squares++] = y;
			uint64_t v[3] = {(uint64_t)(uint32_t)x, (uint64_t)(uint32_t)y, (uint64_t)res};
			for (int i = 0; i < 3; i++) {
				key ^= v[i];
				key *= 1099511628211u;
			}
		}
	if (o.squares > 0)
		o.centroid = vec2_scale(o.centroid, 1.0 / o.squares);
	o.scale = objects_scale(coarsest);
	o.confirmed = o.squares > 0 && o.foveal == o.squares && edge_seen;
	int hit = -1;
	for (int i = 0; i < CONTROLLER_MEMOS && hit < 0; i++)
		if (c->memo[i].ident == n->ident && c->memo[i].key == key)
			hit = i;
	if (hit < 0) {
		hit = c->memo_next;
		c->memo_next = (c->memo_next + 1) % CONTROLLER_MEMOS;
		c->memo[hit].ident = n->ident;
		c->memo[hit].key = key;
		Shape named = shape_read(xs, ys, o.squares, o.scale, &c->memo[hit].reading);
		c->memo[hit].guessed = false;
		c->memo[hit].square_fits = -1;
		if (named == SHAPE_NONE && o.scale > 1 && !o.confirmed) {
			ShapeReading fine;
			if (shape_read(xs, ys, o.squares, 1, &fine) != SHAPE_NONE) {
				c->memo[hit].reading = fine;
				c->memo[hit].guessed = true;
			}
		}
	}
	/* ANOTHER NAME (objects.h): a brick seen whole whose squares a square's may
	 * be, by the probe's test with no push (asked once per reading, when first
	 * seen whole: the memo's key holds the squares, not the floor round them). */
	if (c->memo[hit].square_fits < 0 && o.confirmed && c->memo[hit].reading.shape == SHAPE_BRICK &&
	    c->task.shape == SHAPE_SQUARE)
		c->memo[hit].square_fits = probe_square_consistent(xs, ys, o.squares, NULL, 0, NULL, 0, false,
								   PROBE_BUDGET) != PROBE_INCONSISTENT;
	free(xs);
	free(ys);
	o.reading = c->memo[hit].reading;
	o.shape = o.reading.shape;
	o.guessed = c->memo[hit].guessed;
	o.square_fits = c->memo[hit].square_fits > 0;
	o.confidence = o.confirmed ? 1 : (o.squares ? (double)o.foveal / o.squares : 0) * (o.guessed ? 0.5 : 1);
	/* Once seen whole in the fovea, an object stays examined: a later look from
	 * afar overwrites its squares' evidence with coarser, and the looks closer at
	 * it before a task is claimed (goals.c) would otherwise begin again. */
	bool known = false;
	for (int i = 0; i < c->examined_count && !known; i++)
		known = c->examined[i] == (int32_t)n->ident;
	if (!known && o.squares > 0 && o.foveal == o.squares && c->examined_count < CONTROLLER_EXAMINED)
		c->examined[c->examined_count++] = (int32_t)n->ident, known = true;
	o.examined = known;
	o.shown_width = probe_width(c, (int32_t)n->ident, o.centroid);
	if (o.shape == SHAPE_SQUARE && (probe_disproved(c, (int32_t)n->ident, o.centroid) ||
					seam_parted(c, (int32_t)n->ident, objects_node_centre(c, k), n->squares))) {
		o.shape = SHAPE_NONE;
		o.disproved = true;
	}
	return o;
}

int32_t objects_find_target(Controller *c)
{
	const WorldModel *m = &c->model;
	int32_t best = -1, chosen = -1, best_named = -1, best_sure = -1;
	double sure_d = INFINITY;
	bool chosen_doubtful = false;
	double best_d = INFINITY, named_d = INFINITY, chosen_d = INFINITY, chosen_near = OBJECTS_SAME;
	bool chosen_confirmed = false;
	for (int32_t k = 0; k < m->node_count; k++) {
		if (m->node[k].kind != NODE_OBJECT || objects_wall(c, k))
			continue;
		ObjectReading o = objects_read(c, k);
		double d = goals_distance(o.centroid, c->start);
		/* The one chosen before, by number or, when the model has renumbered it,
		 * by place: kept while the fovea has not shown it to be another shape. */
		double moved = goals_distance(o.centroid, c->target_at);
		bool same = c->target != 0 && (m->node[k].ident == c->target || moved < chosen_near);
		if (same && (o.shape == c->task.shape || !o.confirmed)) {
			chosen = k;
			chosen_d = d;
			chosen_confirmed = o.confirmed;
			chosen_doubtful = o.confirmed && doubt_own(&o);
			chosen_near = m->node[k].ident == c->target ? -1 : moved;
		}
		if (o.shape == c->task.shape && d < best_d) {
			best_d = d;
			best = k;
		}
		/* Sure: read the shape beyond doubt from squares all seen in the
		 * fovea, now or before (examined: a later look from afar may have
		 * coarsened them; going to it, Utak confirms it again before any
		 * claim, objects_touching_target). */
		if (o.shape == c->task.shape && (o.confirmed || (o.examined && !o.guessed)) && !doubt_own(&o) && d < sure_d) {
			sure_d = d;
			best_sure = k;
		}
		if (o.shape == c->task.shape && !o.guessed && d < named_d) {
			named_d = d;
			best_named = k;
		}
	}
	/* A guess (too coarse to name) does not take the place of a target the fovea
	 * has confirmed: a far object seen in the periphery can look like anything. */
	if (chosen_confirmed) {
		best = best_named;
		best_d = named_d;
	}
	if (chosen >= 0 && (best < 0 || chosen_d <= best_d + OBJECTS_SWITCH))
		best = chosen;
	/* One the fovea has shown to be of the shape beyond doubt goes before one it
	 * has shown to be doubtful (objects_doubt): the doubtful may be no such shape. */
	if (best_sure >= 0 && (best < 0 || (best == chosen ? chosen_doubtful : objects_doubtful(c, best))))
		best = best_sure;
	c->target = best >= 0 ? m->node[best].ident : 0;
	if (best >= 0)
		c->target_at = objects_read(c, best).centroid;
	return best;
}

static bool listed(const int32_t *list, int n, int32_t ident)
{
	for (int i = 0; i < n; i++)
		if (list[i] == ident)
			return true;
	return false;
}

bool objects_square_listed(const int32_t *xs, const int32_t *ys, int n, int32_t x, int32_t y)
{
	for (int i = 0; i < n; i++)
		if (xs[i] == x && ys[i] == y)
			return true;
	return false;
}

void objects_note_square(int32_t *xs, int32_t *ys, int *n, int32_t x, int32_t y)
{
	if (*n < CONTROLLER_FELT_SQUARES && !objects_square_listed(xs, ys, *n, x, y)) {
		xs[*n] = x;
		ys[(*n)++] = y;
	}
}

void objects_feel(Controller *c)
{
	wallbump_feel(c);
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	for (int i = 0; i < TOUCH_CELLS; i++) {
		char colour = c->impression.touch[i];
		int32_t x = ux + goals_touch_offset[i][0], y = uy + goals_touch_offset[i][1];
		int32_t k = worldmodel_node_at(&c->model, x, y);
		if (colour >= 'A' && colour <= 'Z' && colour != 'B' && (k < 0 || c->model.node[k].kind != NODE_OBJECT))
			objects_note_square(c->felt_x, c->felt_y, &c->felt_squares, x, y);
		if (k < 0 || c->model.node[k].kind != NODE_OBJECT || colour < 'A' || colour > 'Z')
			continue;
		int32_t ident = (int32_t)c->model.node[k].ident;
		if (colour == 'B' && !listed(c->model.wall_ident, c->model.wall_count, ident) &&
		    c->model.wall_count < WORLDMODEL_WALLS)
			c->model.wall_ident[c->model.wall_count++] = ident; /* the screen's verge */
		if (colour != 'B' && !listed(c->felt, c->felt_count, ident) && c->felt_count < CONTROLLER_EXAMINED)
			c->felt[c->felt_count++] = ident;
	}
}

bool objects_felt(const Controller *c, int32_t k)
{
	return listed(c->felt, c->felt_count, (int32_t)c->model.node[k].ident);
}

bool objects_wall(const Controller *c, int32_t k)
{
	int32_t ident = (int32_t)c->model.node[k].ident;
	return listed(c->model.wall_ident, c->model.wall_count, ident) && !listed(c->felt, c->felt_count, ident);
}

bool objects_touched_only(const Controller *c, int32_t k)
{
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	bool touched = false;
	for (int i = 0; i < TOUCH_CELLS; i++) {
		char colour = c->impression.touch[i];
		if (colour < 'A' || colour > 'Z' || colour == 'B')
			continue;
		if (worldmodel_node_at(&c->model, ux + goals_touch_offset[i][0], uy + goals_touch_offset[i][1]) != k)
			return false;
		touched = true;
	}
	return touched;
}

bool objects_touching(const Controller *c, int32_t k)
{
	int32_t ux, uy;
	worldmodel_utak_square(&c->model, &ux, &uy);
	for (int i = 0; i < TOUCH_CELLS; i++) {
		char colour = c->impression.touch[i];
		if (colour < 'A' || colour > 'Z' || colour == 'B')
			continue;
		if (k < 0)
			return true;
		if (worldmodel_node_at(&c->model, ux + goals_touch_offset[i][0], uy + goals_touch_offset[i][1]) == k)
			return true;
	}
	return false;
}

bool objects_touching_target(Controller *c)
{
	int32_t k = objects_find_target(c);
	if (k < 0 || !objects_touching(c, k))
		return false;
	ObjectReading o = objects_read(c, k);
	return o.confirmed && o.shape == c->task.shape;
}

/* inexact(o): o is read a square or a brick, and no rectangle the fit found covers
 * exactly its squares (objects.h, INEXACT). */
static bool inexact(const ObjectReading *o)
{
	return (o->shape == SHAPE_SQUARE || o->shape == SHAPE_BRICK) && o->reading.fit_error[FIT_RECT] > 0;
}

/* in_gap(o): o is read a square or a brick, its proportions between a square's and
 * a brick's (SHAPE_SQUARE_ASPECT to SHAPE_BRICK_ASPECT). */
static bool in_gap(const ObjectReading *o)
{
	return (o->shape == SHAPE_SQUARE && o->reading.aspect > SHAPE_SQUARE_ASPECT) ||
	       (o->shape == SHAPE_BRICK && o->reading.aspect < SHAPE_BRICK_ASPECT);
}

/* doubt_own(o, shape): objects_doubt's measures on one reading (NULL: none). */
/* narrow(o): o's squares may be those of a polygon under OBJECTS_NAMED_WIDTH, by
 * their spread standing still (shape.h, min_width) and by what a probe's looks
 * showed (probe_least_width): both bound the width of every polygon that agrees
 * with what was seen, and the larger holds. */
static bool narrow(const ObjectReading *o)
{
	return fmax(o->reading.min_width, o->shown_width) < OBJECTS_NAMED_WIDTH - 1e-9;
}

static const char *doubt_own(const ObjectReading *o)
{
	if (narrow(o))
		return "crumb";
	if (in_gap(o))
		return "gap";
	if (inexact(o))
		return "inexact";
	return NULL;
}

bool objects_misread(Controller *c, int32_t k)
{
	ObjectReading o = objects_read(c, k);
	/* doubt_own's measures but the crumb's (a crumb may yet be a small square). */
	return o.confirmed && (in_gap(&o) || inexact(&o));
}

bool objects_narrow(Controller *c, int32_t k)
{
	ObjectReading o = objects_read(c, k);
	return o.confirmed && narrow(&o);
}

bool objects_doubtful(Controller *c, int32_t k)
{
	ObjectReading o = objects_read(c, k);
	return o.confirmed && doubt_own(&o);
}

/* other_frame(c, k, &aspect): node k's squares, read again in each of the 8 frames
 * a quarter turn and a mirror make of the model's, fit exactly (no square off) a
 * rectangle whose proportions are not the task's shape's: the fits start from the
 * hull's measures and find one rectangle of many that cover the same squares, and
 * which one depends on how the squares are turned (objects.h, OTHER FRAME). */
static bool other_frame(const Controller *c, int32_t k, double *aspect)
{
	const ModelNode *n = &c->model.node[k];
	int32_t x0 = (int32_t)floor(n->rect.lo.x), y0 = (int32_t)floor(n->rect.lo.y);
	int32_t x1 = (int32_t)ceil(n->rect.hi.x), y1 = (int32_t)ceil(n->rect.hi.y);
	int64_t cap = (int64_t)(x1 - x0) * (y1 - y0);
	if (cap <= 0 || (c->task.shape != SHAPE_SQUARE && c->task.shape != SHAPE_BRICK))
		return false;
	int32_t *xs = util_alloc((size_t)cap, sizeof *xs), *ys = util_alloc((size_t)cap, sizeof *ys), count = 0;
	int32_t *tx = util_alloc((size_t)cap, sizeof *tx), *ty = util_alloc((size_t)cap, sizeof *ty);
	for (int32_t y = y0; y < y1; y++)
		for (int32_t x = x0; x < x1; x++)
			if (worldmodel_node_at(&c->model, x, y) == k) {
				xs[count] = x - x0;
				ys[count++] = y - y0;
			}
	bool other = false;
	for (int f = 1; f < 8 && !other; f++) { /* frame 0 is the model's own, read already */
		for (int32_t i = 0; i < count; i++) {
			int32_t a = f & 4 ? ys[i] : xs[i], b = f & 4 ? xs[i] : ys[i];
			tx[i] = f & 1 ? -a : a;
			ty[i] = f & 2 ? -b : b;
		}
		ShapeReading r;
		shape_read(tx, ty, count, 1, &r);
		bool exact = r.fit_error[FIT_RECT] == 0 && r.width >= SHAPE_MIN_SIDE;
		if (exact && (c->task.shape == SHAPE_SQUARE ? r.aspect > SHAPE_SQUARE_ASPECT : r.aspect < SHAPE_BRICK_ASPECT)) {
			other = true;
			*aspect = r.aspect;
		}
	}
	free(xs);
	free(ys);
	free(tx);
	free(ty);
	return other;
}

/* another_of_shape(c, k, &at): the node of another object of the model than node k
 * (not felt to be wall), as far from the start or farther, read the task's shape
 * (confirmed, a hypothesis or a guess, as objects_find_target counts them), -1
 * when there is none; at is its centroid (objects.h, ANOTHER OF THE SHAPE).
 * Nearer ones are the loop above doubt_of's. */
static int32_t another_of_shape(Controller *c, int32_t k, Vec2 *at)
{
	double d = goals_distance(objects_read(c, k).centroid, c->start);
	for (int32_t j = 0; j < c->model.node_count; j++) {
		if (j == k || c->model.node[j].kind != NODE_OBJECT || objects_wall(c, j))
			continue;
		ObjectReading q = objects_read(c, j);
		if (q.shape == c->task.shape && goals_distance(q.centroid, c->start) >= d) {
			*at = q.centroid;
			return j;
		}
	}
	return -1;
}

/* unnamed_crumb(c, j, q): node j (read q) is left unnamed but may be a small square
 * (objects.h, NEARER THE START): 8 to 14 squares spanning 3 or more each way, and
 * no probe has shown that no square owns them (probe.h: the probe's hypothesis is
 * every rectangle of a square's proportions, sides from PROBE_MIN_SIDE, at any angle). */
static bool unnamed_crumb(const Controller *c, int32_t j, const ObjectReading *q)
{
	const Box *r = &c->model.node[j].rect;
	return q->shape == SHAPE_NONE && !q->disproved && q->squares >= OBJECTS_CRUMB_LEAST && q->squares <= OBJECTS_CRUMB &&
	       r->hi.x - r->lo.x >= 3 && r->hi.y - r->lo.y >= 3 &&
	       !probe_disproved(c, (int32_t)c->model.node[j].ident, q->centroid);
}

/* centroid_slack(q): how far the centroid of an object's squares, as the model
 * holds them (q read from them), may lie from its true area centroid, by which the
 * judge measures "nearest the start" (objects.h, AS NEAR): its squares are those
 * it covers at the coarsest cell they were seen in (q->scale: 1, 2 or 4 squares),
 * so each edge of the set may lie up to a cell beyond the outline, and a convex
 * object's set is off centre by at most half a cell each way: half the cell's
 * diagonal. */
static double centroid_slack(const ObjectReading *q)
{
	return q->scale * sqrt(0.5);
}

/* side_growth(c, j, side): how many squares node j may own beyond those the model
 * gives it on that side (0 west, 1 east, 2 south, 3 north), by how finely the squares
 * next to its own that way were seen (objects.h, ANOTHER NAME): none where each was
 * seen in the fovea or in cells of 2 (a cell of 2 x 2 over one occupied square reads
 * level 2 of 7, eye_level: never floor); unbounded where some was seen only in cells
 * of 4 (one occupied square of 16 reads level 0, floor: a turned square's corner
 * spread one square a cell hides up to 5 rows, tests/unit/test_nearer.c) or never. */
static double side_growth(const Controller *c, int32_t j, int side)
{
	static const int8_t step[4][2] = {{-1, 0}, {1, 0}, {0, -1}, {0, 1}};
	const WorldModel *m = &c->model;
	const Box *r = &m->node[j].rect;
	for (int32_t y = (int32_t)floor(r->lo.y); y < (int32_t)ceil(r->hi.y); y++)
		for (int32_t x = (int32_t)floor(r->lo.x); x < (int32_t)ceil(r->hi.x); x++) {
			int32_t nx = x + step[side][0], ny = y + step[side][1];
			if (worldmodel_node_at(m, x, y) != j || worldmodel_node_at(m, nx, ny) == j)
				continue;
			int res = worldmodel_evidence(m, nx, ny).res;
			if (res == WORLDMODEL_UNSEEN || res == WORLDMODEL_RES_PERIPHERAL)
				return INFINITY;
		}
	return 0;
}

/* may_grow_square(c, j): node j, not seen whole (the floor round it not all seen in
 * the fovea), may own squares beyond those the model gives it where that floor was
 * seen only coarsely (side_growth), and so be a square though its squares read a
 * brick (objects.h, ANOTHER NAME). A square at any angle spans as many squares each
 * way, give or take one (its box is square; a side of E covers E to E + 1 squares,
 * started anywhere); so a set spanning w x h squares can be a square's only if,
 * grown where it may, each way can come within one of the other. */
static bool may_grow_square(const Controller *c, int32_t j)
{
	const Box *r = &c->model.node[j].rect;
	double w = r->hi.x - r->lo.x, h = r->hi.y - r->lo.y;
	double gw = side_growth(c, j, 0) + side_growth(c, j, 1), gh = side_growth(c, j, 2) + side_growth(c, j, 3);
	return w + gw >= h - 1 && h + gh >= w - 1;
}

/* another_name(c, j, q): node j (read q), nearer the start, may be the task's object
 * though named the other of square and brick (objects.h, ANOTHER NAME): for "the
 * square", a brick seen whole spanning 3 squares or more each way whose squares a
 * square of the probe's hypothesis owns exactly, standing still (square_fits; one
 * not seen whole now, the floor round it seen only coarsely, was never asked: it
 * may be such a brick, and a look settles it, rival.h),
 * and no probe has shown no square owns them; for "the brick", a square read in
 * the gap (no probe settles that). */
static bool another_name(const Controller *c, int32_t j, const ObjectReading *q)
{
	const Box *r = &c->model.node[j].rect;
	if (c->task.shape == SHAPE_SQUARE)
		return q->shape == SHAPE_BRICK && (q->square_fits || (!q->confirmed && may_grow_square(c, j))) &&
		       r->hi.x - r->lo.x >= 3 && r->hi.y - r->lo.y >= 3 &&
		       !probe_disproved(c, (int32_t)c->model.node[j].ident, q->centroid);
	return c->task.shape == SHAPE_BRICK && q->shape == SHAPE_SQUARE && in_gap(q);
}

bool objects_rival_open(Controller *c, int32_t j)
{
	ObjectReading q = objects_read(c, j);
	return !q.examined || q.shape == c->task.shape || unnamed_crumb(c, j, &q) || another_name(c, j, &q) ||
	       objects_merged_rival(c, j);
}

/* pieces_shown(c, k): a probe in this task has shown an object Utak read the task's
 * shape (a square: the probe's hypothesis) to be none, and node k has not been
 * probed (rival.h, OWN FIRST): this world holds pieces the eye takes for squares,
 * and k may be one (random g145: a piece disproved, the next piece read a square
 * was pushed to the corner unprobed, a false success). */
static bool pieces_shown(const Controller *c, int32_t k)
{
	return c->task.shape == SHAPE_SQUARE && c->probe.disproved_count > 0 && !rival_own_probed(c, k) &&
	       !probe_disproved(c, (int32_t)c->model.node[k].ident, vec2(INFINITY, INFINITY));
}

bool objects_pieces_shown(Controller *c, int32_t k)
{
	return objects_read(c, k).confirmed && pieces_shown(c, k);
}

/* MAY HOLD A SQUARE (objects.h): the distance from the start of the nearest place a
 * square the judge would name (2 wide or more, OBJECTS_NAMED_WIDTH) may have its
 * centroid while it owns only squares of node j, INFINITY when it can own none.
 * Such a square holds the disc of radius 1 round its centroid; the grid point
 * nearest the centroid lies within sqrt(0.5) < 1 of it, inside that disc, so the
 * square owns the 4 squares round that point (their open interiors meet its own):
 * a 2 x 2 block of j's squares whose shared corner is within sqrt(0.5) of the
 * centroid. So the centroid lies no nearer the start than that corner less
 * sqrt(0.5), the least over j's 2 x 2 blocks. A bound only: that a block is there
 * shows no square is (tests/unit/test_nearer.c checks the bound against squares
 * at every angle and offset). */
static double hold_square_near(const Controller *c, int32_t j)
{
	const WorldModel *m = &c->model;
	const Box *r = &m->node[j].rect;
	double best = INFINITY;
	for (int32_t y = (int32_t)floor(r->lo.y); y + 1 < (int32_t)ceil(r->hi.y); y++)
		for (int32_t x = (int32_t)floor(r->lo.x); x + 1 < (int32_t)ceil(r->hi.x); x++)
			if (worldmodel_node_at(m, x, y) == j && worldmodel_node_at(m, x + 1, y) == j &&
			    worldmodel_node_at(m, x, y + 1) == j && worldmodel_node_at(m, x + 1, y + 1) == j)
				best = fmin(best, goals_distance(vec2(x + 1, y + 1), c->start) - sqrt(0.5));
	return best;
}

/* cross(o, a, b): the z of (a - o) x (b - o), on squares' coordinates. */
static int64_t cross(int32_t ox, int32_t oy, int32_t ax, int32_t ay, int32_t bx, int32_t by)
{
	return (int64_t)(ax - ox) * (by - oy) - (int64_t)(ay - oy) * (bx - ox);
}

/* notched(c, j): some square whose centre lies strictly inside the convex hull of
 * the centres of node j's squares is not one of them; then no single convex
 * polygon owns exactly j's squares (objects.h, MERGED: a convex polygon P's
 * squares' centres lie in P grown by the unit square, so their hull does, and a
 * square centred strictly inside meets P's interior). */
static bool notched(const Controller *c, int32_t j)
{
	const WorldModel *m = &c->model;
	const Box *r = &m->node[j].rect;
	int32_t x0 = (int32_t)floor(r->lo.x), y0 = (int32_t)floor(r->lo.y);
	int32_t x1 = (int32_t)ceil(r->hi.x), y1 = (int32_t)ceil(r->hi.y);
	int64_t cap = (int64_t)(x1 - x0) * (y1 - y0);
	if (cap <= 0)
		return false;
	/* Andrew's monotone chain over the squares in x-then-y order: the leftmost
	 * and rightmost square of each row are enough (the rest lie between). */
	int32_t *hx = util_alloc((size_t)(4 * (y1 - y0) + 2), sizeof *hx), *hy = util_alloc((size_t)(4 * (y1 - y0) + 2), sizeof *hy);
	int32_t *px = util_alloc((size_t)(2 * (y1 - y0)), sizeof *px), *py = util_alloc((size_t)(2 * (y1 - y0)), sizeof *py);
	int n = 0;
	for (int32_t y = y0; y < y1; y++) {
		int32_t lo = INT32_MAX, hi = INT32_MIN;
		for (int32_t x = x0; x < x1; x++)
			if (worldmodel_node_at(m, x, y) == j) {
				lo = x < lo ? x : lo;
				hi = x > hi ? x : hi;
			}
		if (lo == INT32_MAX)
			continue;
		px[n] = lo, py[n++] = y;
		if (hi != lo)
			px[n] = hi, py[n++] = y;
	}
	/* sort by (x, y): insertion, n is a few dozen */
	for (int a = 1; a < n; a++)
		for (int b = a; b > 0 && (px[b - 1] > px[b] || (px[b - 1] == px[b] && py[b - 1] > py[b])); b--) {
			int32_t tx = px[b], ty = py[b];
			px[b] = px[b - 1], py[b] = py[b - 1];
			px[b - 1] = tx, py[b - 1] = ty;
		}
	int h = 0;
	for (int pass = 0; pass < 2; pass++) {
		int start = h;
		for (int a = 0; a < n; a++) {
			int i = pass ? n - 1 - a : a;
			while (h >= start + 2 && cross(hx[h - 2], hy[h - 2], hx[h - 1], hy[h - 1], px[i], py[i]) <= 0)
				h--;
			hx[h] = px[i], hy[h++] = py[i];
		}
		h--; /* the last point of each chain is the first of the other */
	}
	bool notch = false;
	for (int32_t y = y0; y < y1 && !notch && h >= 3; y++)
		for (int32_t x = x0; x < x1 && !notch; x++) {
			if (worldmodel_node_at(m, x, y) == j)
				continue;
			bool inside = true; /* the hull runs counter-clockwise */
			for (int e = 0; e < h && inside; e++)
				inside = cross(hx[e], hy[e], hx[(e + 1) % h], hy[(e + 1) % h], x, y) > 0;
			notch = inside;
		}
	free(hx);
	free(hy);
	free(px);
	free(py);
	return notch;
}

/* merged(c, j, q, d): node j (read q), seen whole and named neither the task's
 * square nor a brick a rectangle fits exactly, may hold the square the task means
 * merged with a neighbour (objects.h, MERGED): its squares hold a 2 x 2 block
 * where a square 2 wide may lie with its centroid under d from the start. */
static bool merged(const Controller *c, int32_t j, const ObjectReading *q, double d)
{
	if (c->task.shape != SHAPE_SQUARE || q->shape == SHAPE_SQUARE || q->squares < OBJECTS_CRUMB_LEAST)
		return false;
	if (q->shape == SHAPE_BRICK && q->reading.fit_error[FIT_RECT] == 0)
		return false;
	return hold_square_near(c, j) < d && notched(c, j);
}

/* merged_near(c, k, d): the node of an object other than node k (not felt to be
 * wall, nor shown one object by a pull: apart.h) that merged() holds may hold the
 * square under d from the start, -1 when there is none. */
static int32_t merged_near(Controller *c, int32_t k, double d)
{
	for (int32_t j = 0; j < c->model.node_count; j++) {
		if (j == k || c->model.node[j].kind != NODE_OBJECT || objects_wall(c, j) || apart_no_square(c, j))
			continue;
		ObjectReading q = objects_read(c, j);
		if (merged(c, j, &q, d))
			return j;
	}
	return -1;
}

bool objects_merged_rival(Controller *c, int32_t j)
{
	if (j < 0 || c->model.node[j].kind != NODE_OBJECT || objects_wall(c, j) || apart_no_square(c, j))
		return false;
	ObjectReading q = objects_read(c, j);
	return q.examined && merged(c, j, &q, INFINITY);
}

bool objects_merged(Controller *c, int32_t k)
{
	ObjectReading o = objects_read(c, k);
	return o.confirmed && c->task.shape == SHAPE_SQUARE &&
	       merged_near(c, k, goals_distance(o.centroid, c->start) + centroid_slack(&o)) >= 0;
}

/* doubt_of(c, k, why, size, &rival): objects_doubt, and the node of the other
 * object the doubt names (-1 when it names none). */
static bool doubt_of(Controller *c, int32_t k, char *why, size_t size, int32_t *rival)
{
	ObjectReading o = objects_read(c, k);
	const char *shape = task_shape_name(c->task.shape);
	double aspect = 0;
	Vec2 other;
	bool felt = false;
	*rival = -1;
	/* Another of the shape nearer the start, not sure or not yet seen whole,
	 * may be the one the task means (objects.h, NEARER THE START, AS NEAR). */
	double d = goals_distance(o.centroid, c->start);
	for (int32_t j = 0; j < c->model.node_count; j++) {
		if (j == k || c->model.node[j].kind != NODE_OBJECT || objects_wall(c, j))
			continue;
		ObjectReading q = objects_read(c, j);
		double dj = goals_distance(q.centroid, c->start);
		if (dj >= d + centroid_slack(&q) + centroid_slack(&o))
			continue;
		/* Of the shape, doubted or not: objects_find_target keeps the one
		 * chosen before until another is OBJECTS_SWITCH nearer (so that the
		 * goal does not flicker), so a square seen whole beyond doubt may lie
		 * nearer by less and the claim be on the farther (tests/worlds/
		 * near-tie.w: a false success, the judge's square the other). One
		 * read the shape as far or farther is ANOTHER OF THE SHAPE's, below. */
		bool as_near = dj >= d;
		if (!q.examined || unnamed_crumb(c, j, &q) || (q.shape == c->task.shape && !as_near) ||
		    another_name(c, j, &q)) {
			if (as_near)
				snprintf(why, size, "what may be another %s lies as near the start, at (%.1f, %.1f) (%.1f from it, the %s %.1f: within what the squares seen tell)",
					 shape, q.centroid.x, q.centroid.y, dj, shape, d);
			else
				snprintf(why, size, "what may be another %s lies nearer the start, at (%.1f, %.1f)", shape,
					 q.centroid.x, q.centroid.y);
			*rival = j;
			return true;
		}
	}
	if (goals_unseen_within(c, c->start, d))
		snprintf(why, size, "space nearer the start than the %s is unseen, where another may lie", shape);
	else if (faint_within(c, c->start, d))
		snprintf(why, size, "floor nearer the start than the %s was read only by coarse cells that were not empty, where another may lie (faint.h)", shape);
	else if (coarsewall_within(c, c->start, d))
		snprintf(why, size, "wall nearer the start than the %s, seen only in coarse cells, juts out further than a face so seen can, where another may be merged with it (coarsewall.h)", shape);
	else if (c->task.shape == SHAPE_SQUARE && wallbump_within(c, c->start, d, &other, &felt))
		snprintf(why, size, "a corner of the wall at (%.1f, %.1f), %s, may be one of another %s pressed against the wall, nearer the start (wallbump.h)",
			 other.x, other.y, felt ? "where touch felt an object" : "not felt", shape);
	else if (narrow(&o) && o.shown_width > 0)
		snprintf(why, size, "the %s's %d squares may be those of a polygon under %.0f wide (from %.2f; moved, at least %.2f), too narrow to name",
			 shape, (int)o.squares, OBJECTS_NAMED_WIDTH, o.reading.min_width, o.shown_width);
	else if (narrow(&o))
		snprintf(why, size, "the %s's %d squares may be those of a polygon under %.0f wide (from %.2f), too narrow to name",
			 shape, (int)o.squares, OBJECTS_NAMED_WIDTH, o.reading.min_width);
	else if (o.shape == SHAPE_SQUARE && o.reading.aspect > SHAPE_SQUARE_ASPECT)
		snprintf(why, size, "the %s reads %.2f times as long as wide, over a square's %.1f", shape,
			 o.reading.aspect, SHAPE_SQUARE_ASPECT);
	else if (o.shape == SHAPE_BRICK && o.reading.aspect < SHAPE_BRICK_ASPECT)
		snprintf(why, size, "the %s reads %.2f times as long as wide, under a brick's %.1f", shape,
			 o.reading.aspect, SHAPE_BRICK_ASPECT);
	else if (inexact(&o))
		snprintf(why, size, "no rectangle covers the %s's %d squares exactly (the best %d off): it may have more corners",
			 shape, (int)o.squares, (int)o.reading.fit_error[FIT_RECT]);
	else if (o.confirmed && o.shape == c->task.shape && other_frame(c, k, &aspect))
		snprintf(why, size, "a rectangle %.2f times as long as wide covers the %s's %d squares exactly too", aspect,
			 shape, (int)o.squares);
	else if (pieces_shown(c, k))
		snprintf(why, size, "a probe showed an object here that read a %s to be none: this one, not probed, may be such a piece too",
			 shape);
	else if ((*rival = another_of_shape(c, k, &other)) >= 0)
		snprintf(why, size, "another object, at (%.1f, %.1f), reads a %s too: this one may be a polygon of more corners over the same squares, and that one the %s",
			 other.x, other.y, shape, shape);
	else if ((*rival = merged_near(c, k, d + centroid_slack(&o))) >= 0) {
		ObjectReading q = objects_read(c, *rival);
		snprintf(why, size, "an object nearer the start, at (%.1f, %.1f), %d squares read %s%s, may hold a %s merged in the model with a neighbour",
			 q.centroid.x, q.centroid.y, (int)q.squares, q.shape == SHAPE_NONE ? "no shape" : q.shape == SHAPE_LSHAPE ? "an " : "a ",
			 q.shape == SHAPE_NONE ? "" : task_shape_name(q.shape), shape);
		/* The rival, seen whole: a pull settles it (rival.h, apart.h); not seen
		 * whole, nothing does (a trip to look would be NEARER THE START's). */
		if (!objects_merged_rival(c, *rival))
			*rival = -1;
	} else if (joined_open(c, k))
		snprintf(why, size, "the %s may be two objects pressed together (paper 3.4.2): no pull showed it come away whole (joined.h)",
			 shape);
	else
		return false;
	return true;
}

bool objects_doubt(Controller *c, int32_t k, char *why, size_t size)
{
	int32_t rival;
	if (c->task.shape == SHAPE_SQUARE && seam_nearer(c, k, why, size))
		return true; /* pieces nearer the start, one of which may be the square (seam.h) */
	return doubt_of(c, k, why, size, &rival);
}

int32_t objects_rival(Controller *c, int32_t k)
{
	char why[200];
	int32_t rival;
	return doubt_of(c, k, why, sizeof why, &rival) ? rival : -1;
}

Vec2 objects_node_centre(const Controller *c, int32_t k)
{
	const Box *r = &c->model.node[k].rect;
	return vec2((r->lo.x + r->hi.x) / 2, (r->lo.y + r->hi.y) / 2);
}

bool objects_lacks(const Controller *c, int32_t k, int32_t x, int32_t y)
{
	const WorldModel *m = &c->model;
	if (objects_seen_exactly(m, k, x, y))
		return false;
	bool part = worldmodel_node_at(m, x, y) == k;
	for (int d = 0; d < 4 && !part; d++) {
		static const int8_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
		part = worldmodel_node_at(m, x + step[d][0], y + step[d][1]) == k;
	}
	return part;
}

bool objects_unconfirmed_square(const Controller *c, int32_t k, int32_t *x, int32_t *y)
{
	const WorldModel *m = &c->model;
	const ModelNode *n = &m->node[k];
	double best = INFINITY;
	/* The object's squares and the floor round them (one square beyond its
	 * rectangle): any not yet seen in the fovea. */
	for (int32_t j = (int32_t)floor(n->rect.lo.y) - 1; j <= (int32_t)ceil(n->rect.hi.y); j++)
		for (int32_t i = (int32_t)floor(n->rect.lo.x) - 1; i <= (int32_t)ceil(n->rect.hi.x); i++) {
			if (!objects_lacks(c, k, i, j))
				continue;
			double d = goals_distance(goals_centre(i, j), m->utak);
			if (d < best) {
				best = d;
				*x = i;
				*y = j;
			}
		}
	return best < INFINITY;
}
