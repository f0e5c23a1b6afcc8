/* worldmodel.c - Utak's world model: evidence, accommodation, disparity (paper 3.3,
 * 3.4.3, 3.5). CONTROLLER SIDE: it sees Impressions, the commands the
 * controller gave, and the eye's anatomy (eye.h); never the TABLE.
 *
 * ALGORITHM.
 * Evidence (paper 3.3's "degree of confidence based on evidence collected from a
 * series of retinal impressions"): each cell of an impression says how many of
 * its squares are occupied, within the rounding of eye_level. The squares of the
 * cell the model already knows at a finer resolution keep their values (they are
 * the "old parts seen at higher resolution" of paper 3.5, used the other way
 * round); the rest share what the cell's level leaves over. The confidence rules
 * are in worldmodel.h.
 * Prediction (paper 3.5): the model is projected through the same eye
 * (eye_cell, eye_level) with Utak on a given square. A cell is predicted only when
 * every square under it is known and definite, so that new parts coming into view
 * and coarse old knowledge never count as disagreement.
 * Disparity (paper 3.5, "trying the positions closest to the predicted position"):
 * the level differences over the cells the model predicts, with a small cost for
 * each cell it cannot (wm_score), are computed for the predicted square, every
 * square within WORLDMODEL_DISPARITY_RADIUS of it, and every square within one of
 * the commanded straight line (the controller is not told where a move halted).
 * The best, ties going to the nearest to the commanded line and then to the
 * prediction, wins if it beats the prediction by WORLDMODEL_DISPARITY_MARGIN, and
 * the prediction cannot explain every cell it predicts once each difference is
 * counted beyond what the resolution of the knowledge under it leaves open
 * (wm_tolerant_mismatch: a square known only from a 4 x 4 cell at level 0 or 7 may
 * be the one square of 16 that cell's rounding hides, once a cell).
 * Sliding along a straight wall changes nothing the eye sees, so along a wall
 * the belief can only be as good as these ties.
 * Motion's error (paper 3.5, uncertainty (2); worldmodel_motion_error): the
 * corrections no halt explains, over the lengths commanded, estimate its rate; and
 * for each axis the moves since an impression last placed Utak (a shift of one
 * square either way would have matched worse by the margin) say how far it may
 * have carried him unseen. The first impression, taken where he knew where he
 * stood, can place him again near his first square (worldmodel_recognise_first,
 * in firstlook.c).
 * The tree (paper 3.3, 3.4.3) is derived from the evidence after every impression:
 * modeltree.c.
 *
 * INVARIANTS: worldmodel_validate. MEMORY: the evidence in tiles allocated as they
 * are first seen (worldmodel.h: 12 bytes a square seen, 512 KiB of directory), and
 * the tree's arrays, owned by the WorldModel. COMPLEXITY: an impression costs
 * O(1024) squares to record, O(P x 1024) to search P candidate positions (P <= 49
 * + 18 x the length of the move within sight of the squares seen: wm_line_in_sight),
 * O(T) to count the seen window over T tiles, and O(A) to derive the tree, A the
 * seen area. */
#include "utak/mind/worldmodel.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/eye.h"
#include "utak/base/util.h"
#include "utak/mind/modeltree.h"
#include "worldmodel_work.h"

/* A coarse cell agreeing with the finer knowledge inside it raises that knowledge's
 * confidence by this share of what is missing. */
#define WM_AGREE_GROWTH 0.05
/* A halted move ends on the commanded line: ties go first to the candidate nearest
 * that line (this much per square), then to the one nearest the prediction. Both
 * are far below one foveal cell's disagreement (about 0.005). */
#define WM_LINE_COST 1e-3
/* Steps along the commanded line when listing candidate positions, squares. */
#define WM_PATH_STEP 0.5
/* How far beyond the rectangle of squares seen a point of the commanded line can
 * lie and still have a candidate that sees one of them: the eye reaches EYE_HALF
 * squares from Utak's square, a candidate lies within one square of the line, and
 * one more square covers the rounding of both (wm_line_in_sight). */
#define WM_SIGHT_MARGIN (EYE_HALF + 2)

/* Own-frame offsets of the touch squares, in Impression.touch order. */
const int8_t wm_touch_offset[TOUCH_CELLS][2] = {{0, 1},  {1, 1},   {1, 0},  {1, -1},
                                                       {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}};

/* ---- the evidence grid --------------------------------------------------------- */

/* wm_tile_of(x, y, &at): the index of the tile holding square (x, y), and in *at the
 * square's index within it; -1 beyond the reach. */
static int32_t wm_tile_of(int32_t x, int32_t y, int32_t *at)
{
	if (x < -WORLDMODEL_REACH || x >= WORLDMODEL_REACH || y < -WORLDMODEL_REACH || y >= WORLDMODEL_REACH)
		return -1;
	int32_t gx = x + WORLDMODEL_REACH, gy = y + WORLDMODEL_REACH;
	*at = (gy % WORLDMODEL_TILE) * WORLDMODEL_TILE + gx % WORLDMODEL_TILE;
	return (gy / WORLDMODEL_TILE) * WORLDMODEL_TILES + gx / WORLDMODEL_TILE;
}

/* wm_peek(m, x, y): the evidence of square (x, y), NULL where no tile holds it (never
 * seen, or beyond the reach). */
static const Evidence *wm_peek(const WorldModel *m, int32_t x, int32_t y)
{
	int32_t at, t = wm_tile_of(x, y, &at);
	return t < 0 || !m->tile[t] ? NULL : &m->tile[t][at];
}

/* wm_at(m, x, y): the evidence of square (x, y) to write, its tile allocated (all
 * unseen) if need be; NULL beyond the reach. */
Evidence *wm_at(WorldModel *m, int32_t x, int32_t y)
{
	int32_t at, t = wm_tile_of(x, y, &at);
	if (t < 0)
		return NULL;
	if (!m->tile[t]) {
		m->tile[t] = util_alloc((size_t)WORLDMODEL_TILE * WORLDMODEL_TILE, sizeof *m->tile[t]);
		m->tile_list = util_grow(m->tile_list, &m->tile_cap, m->tile_count + 1, sizeof *m->tile_list);
		m->tile_list[m->tile_count++] = t;
	}
	return &m->tile[t][at];
}

Evidence worldmodel_evidence(const WorldModel *m, int32_t x, int32_t y)
{
	const Evidence *e = wm_peek(m, x, y);
	Evidence none = {0, 0, WORLDMODEL_UNSEEN, 0, 0};
	return e ? *e : none;
}

int32_t worldmodel_node_at(const WorldModel *m, int32_t x, int32_t y)
{
	x -= m->node_at_x0;
	y -= m->node_at_y0;
	if (!m->node_at || x < 0 || y < 0 || x >= m->node_at_w || y >= m->node_at_h)
		return -1;
	return m->node_at[(int64_t)y * m->node_at_w + x];
}

int32_t worldmodel_node_squares(const WorldModel *m, int32_t k, int32_t *xs, int32_t *ys, int32_t max)
{
	const Box *r = &m->node[k].rect;
	int32_t n = 0;
	for (int32_t y = (int32_t)floor(r->lo.y); y < (int32_t)ceil(r->hi.y); y++)
		for (int32_t x = (int32_t)floor(r->lo.x); x < (int32_t)ceil(r->hi.x); x++)
			if (worldmodel_node_at(m, x, y) == k) {
				if (n < max) {
					xs[n] = x;
					ys[n] = y;
				}
				n++;
			}
	return n;
}

void worldmodel_utak_square(const WorldModel *m, int32_t *x, int32_t *y)
{
	*x = (int32_t)floor(m->utak.x);
	*y = (int32_t)floor(m->utak.y);
}

Belief worldmodel_belief(const WorldModel *m, int32_t x, int32_t y)
{
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	if (x == ux && y == uy)
		return BELIEF_FLOOR;
	Evidence e = worldmodel_evidence(m, x, y);
	if (e.res == WORLDMODEL_UNSEEN)
		return BELIEF_UNKNOWN;
	return e.p >= 0.5f ? BELIEF_OCCUPIED : BELIEF_FLOOR;
}

void worldmodel_set_position(WorldModel *m, Vec2 p)
{
	m->utak = p;
}

static double wm_base(int res)
{
	static const double base[4] = {0, WORLDMODEL_CONF_PERIPHERAL, WORLDMODEL_CONF_INTERMEDIATE,
	                               WORLDMODEL_CONF_FOVEA};
	return base[res];
}

static int wm_res_of_zone(int zone)
{
	return zone == EYE_FOVEA          ? WORLDMODEL_RES_FOVEA
	       : zone == EYE_INTERMEDIATE ? WORLDMODEL_RES_INTERMEDIATE
	                                  : WORLDMODEL_RES_PERIPHERAL;
}

/* wm_level_count(level, n): how many of a cell's n squares a level says are
 * occupied: 0 for level 0 and n for level 7 (the reading of paper 3.4.2: a zero
 * cell is floorspace), else the mean of the counts that round to the level. */
static double wm_level_count(int level, int n)
{
	if (level == 0)
		return 0;
	if (level == EYE_MAX_LEVEL)
		return n;
	int sum = 0, k = 0;
	for (int o = 0; o <= n; o++)
		if (eye_level(o, n) == level) {
			sum += o;
			k++;
		}
	return k ? (double)sum / k : (double)level * n / EYE_MAX_LEVEL;
}

/* wm_update(e, q, res, faint, m): one observation of one square (the rules of
 * worldmodel.h); faint: the cell's level is not zero though q reads floor. */
static void wm_update(Evidence *e, double q, int res, bool faint, WorldModel *m)
{
	double weight = wm_base(res) * fabs(2 * q - 1);
	if (e->res < res) {
		if (e->res == WORLDMODEL_UNSEEN)
			m->report.new_squares++;
		else
			m->report.finer_squares++;
		e->p = (float)q;
		e->conf = (float)weight;
		e->res = (uint8_t)res;
		e->seen = 1;
	} else if ((q >= 0.5) == (e->p >= 0.5f)) {
		e->p = (float)((e->p * e->seen + q) / (e->seen + 1));
		e->conf = (float)(e->conf + (1 - e->conf) * weight * WORLDMODEL_CONF_GROWTH);
		if (e->seen < 255)
			e->seen++;
	} else if (faint && e->p >= 0.5f) {
		/* A cell that is not zero says something in it is occupied, not which
		 * squares: it cannot make floor of a square an earlier cell of the same
		 * resolution, aligned otherwise, read as occupied (paper 3.4.2: only a
		 * zero cell is floorspace). WHY: a thin wall under coarse cells that
		 * straddle it reads as floor in every cell, and the last look would
		 * erase it. A zero cell or a finer one settles the square. */
		e->conf = (float)(e->conf * WORLDMODEL_CONF_DECAY);
	} else {
		e->p = (float)q;
		e->conf = (float)(weight * WORLDMODEL_CONF_CONTRADICTED);
		e->seen = 1;
	}
}

/* wm_observe(m, sx, sy, imp): records imp as seen with Utak on square (sx, sy). */
static void wm_observe(WorldModel *m, int32_t sx, int32_t sy, const Impression *imp)
{
	int32_t utak_cell = eye_cell_at(0, 0);
	for (int32_t i = 0; i < RETINA_CELLS; i++) {
		if (i == utak_cell)
			continue; /* Utak himself: says nothing of the floor under him */
		EyeCell c = eye_cell(i);
		int res = wm_res_of_zone(c.zone), n = c.size * c.size, level = imp->level[i];
		Evidence *sq[16];
		uint8_t place[16];
		int count = 0;
		bool all_known = true;
		int old_occupied = 0, finer = 0;
		for (int dy = 0; dy < c.size; dy++)
			for (int dx = 0; dx < c.size; dx++) {
				Evidence *e = wm_at(m, sx + c.ox + dx, sy + c.oy + dy);
				if (!e) {
					/* Outside the window: not recorded, but said in the dump.
					 */
					m->clipped = true;
					continue;
				}
				place[count] = (uint8_t)(dx + 4 * dy);
				sq[count++] = e;
				all_known &= e->res != WORLDMODEL_UNSEEN;
				old_occupied += e->p >= 0.5f;
				finer += e->res > res;
			}
		if (count < n)
			continue; /* a cell across the window's edge says nothing reliable */
		/* Finer knowledge inside a coarse cell: confirmed or put in doubt. */
		if (finer > 0 && all_known) {
			bool agree = eye_level(old_occupied, n) == level;
			for (int s = 0; s < count; s++) {
				Evidence *e = sq[s];
				if (e->res <= res)
					continue;
				if (agree) {
					e->conf =
					    (float)(e->conf + (1 - e->conf) * WM_AGREE_GROWTH);
				} else {
					e->conf = (float)(e->conf * WORLDMODEL_CONF_DECAY);
					if (e->conf < WORLDMODEL_CONF_FORGET)
						e->res = (uint8_t)res; /* re-estimated below */
				}
			}
		}
		double known_occupied = 0;
		int rest = 0;
		for (int s = 0; s < count; s++) {
			if (sq[s]->res > res)
				known_occupied += sq[s]->p >= 0.5f;
			else
				rest++;
		}
		if (rest == 0)
			continue;
		double q = (wm_level_count(level, n) - known_occupied) / rest;
		q = q < 0 ? 0 : q > 1 ? 1 : q;
		for (int s = 0; s < count; s++)
			if (sq[s]->res <= res) {
				wm_update(sq[s], q, res, level > 0, m);
				if (res == WORLDMODEL_RES_PERIPHERAL)
					sq[s]->cell = place[s];
			}
	}
}

/* ---- prediction and disparity ---------------------------------------------------- */

void worldmodel_predict(const WorldModel *m, int32_t x, int32_t y, Impression *pred,
                        bool known[RETINA_CELLS])
{
	int32_t utak_cell = eye_cell_at(0, 0);
	memset(pred->touch, '?', sizeof pred->touch);
	for (int32_t i = 0; i < RETINA_CELLS; i++) {
		EyeCell c = eye_cell(i);
		int occupied = 0;
		bool ok = i != utak_cell;
		for (int dy = 0; dy < c.size && ok; dy++)
			for (int dx = 0; dx < c.size && ok; dx++) {
				const Evidence *e = wm_peek(m, x + c.ox + dx, y + c.oy + dy);
				if (!e || e->res == WORLDMODEL_UNSEEN) {
					ok = false;
					break;
				}
				float p = e->p;
				if (p > WM_DEFINITE && p < 1 - WM_DEFINITE)
					ok = false;
				occupied += p >= 0.5f;
			}
		known[i] = ok;
		pred->level[i] = (uint8_t)(i == utak_cell ? EYE_MAX_LEVEL
		                           : ok           ? eye_level(occupied, c.size * c.size)
		                                          : 0);
	}
}

double worldmodel_mismatch(const WorldModel *m, int32_t x, int32_t y, const Impression *imp,
                           int32_t *compared)
{
	Impression pred;
	bool known[RETINA_CELLS];
	worldmodel_predict(m, x, y, &pred, known);
	double sum = 0;
	int32_t n = 0;
	for (int32_t i = 0; i < RETINA_CELLS; i++)
		if (known[i]) {
			sum += abs((int)pred.level[i] - (int)imp->level[i]) / (double)EYE_MAX_LEVEL;
			n++;
		}
	*compared = n;
	return n ? sum / n : 1.0;
}

/* wm_tolerant_mismatch(m, x, y, imp): the level differences of worldmodel_mismatch
 * summed over the cells it compares, less what the resolution of the model's
 * knowledge leaves open. WHY: a 4 x 4 cell at level 0 (or 7) allows one of its 16
 * squares the other way (eye_level rounds 1/16 to 0), and the model holds its
 * squares as definite floor (or occupied); a finer cell can meet that one square.
 * So each 4 x 4 cell the knowledge came from (Evidence.cell names its squares) may
 * excuse one square's difference, once, in one cell of the fovea or the
 * intermediate zone over it: the first cell, in retina order, whose difference that
 * lessens (a 2 x 2 cell across two or four of them, a square for each). A 2 x 2
 * cell at level 0 or 7 allows none (round(7/4) = 2), so intermediate knowledge
 * has no such slack, and a peripheral cell is compared as worldmodel_mismatch
 * compares it. Once per 4 x 4 cell: a shift of a wall or an
 * object's edge seen only coarsely still shows in every other cell along it. */
static double wm_tolerant_mismatch(const WorldModel *m, int32_t x, int32_t y, const Impression *imp)
{
	int32_t utak_cell = eye_cell_at(0, 0), used_x[RETINA_CELLS * 4], used_y[RETINA_CELLS * 4], used = 0;
	double sum = 0;
	for (int32_t i = 0; i < RETINA_CELLS; i++) {
		if (i == utak_cell)
			continue;
		EyeCell c = eye_cell(i);
		int res = wm_res_of_zone(c.zone), occupied = 0, n = c.size * c.size;
		bool ok = true;
		/* The 4 x 4 cells not yet spent that read a square of this cell as floor
		 * ([0]) or occupied ([1]), each once. */
		int32_t gx[2][4], gy[2][4];
		int ng[2] = {0, 0};
		for (int dy = 0; dy < c.size && ok; dy++)
			for (int dx = 0; dx < c.size && ok; dx++) {
				int32_t sx = x + c.ox + dx, sy = y + c.oy + dy;
				const Evidence *e = wm_peek(m, sx, sy);
				if (!e || e->res == WORLDMODEL_UNSEEN ||
				    (e->p > WM_DEFINITE && e->p < 1 - WM_DEFINITE)) {
					ok = false;
					break;
				}
				int occ = e->p >= 0.5f;
				occupied += occ;
				if (e->res != WORLDMODEL_RES_PERIPHERAL || res == WORLDMODEL_RES_PERIPHERAL)
					continue;
				int32_t cx = sx - e->cell % 4, cy = sy - e->cell / 4;
				bool spent = false;
				for (int32_t k = 0; k < used && !spent; k++)
					spent = used_x[k] == cx && used_y[k] == cy;
				for (int k = 0; k < ng[occ] && !spent; k++)
					spent = gx[occ][k] == cx && gy[occ][k] == cy;
				if (!spent) {
					gx[occ][ng[occ]] = cx;
					gy[occ][ng[occ]] = cy;
					ng[occ]++;
				}
			}
		if (!ok)
			continue; /* not predicted: as worldmodel_predict */
		int a = imp->level[i], pred = eye_level(occupied, n), d = abs(a - pred);
		/* Up to one square the other way for each of those 4 x 4 cells: floor
		 * squares read occupied when the cell shows more, else the reverse. */
		int way = a > pred ? 0 : 1, sign = way == 0 ? 1 : -1, best = 0;
		for (int k = 1; k <= ng[way]; k++) {
			int other = abs(a - eye_level(occupied + sign * k, n));
			if (other < d) {
				d = other;
				best = k;
			}
		}
		for (int k = 0; k < best; k++) {
			used_x[used] = gx[way][k];
			used_y[used] = gy[way][k];
			used++;
		}
		sum += d / (double)EYE_MAX_LEVEL;
	}
	return sum;
}

/* wm_score(m, x, y, imp, &compared): the disparity measure of a position: the
 * level differences summed over the cells the model can predict, and
 * WM_UNKNOWN_COST for every cell it cannot, over all cells but Utak's. Without
 * that cost a position that predicts little would look as good as one that
 * predicts much and gets it right. */
static double wm_score(const WorldModel *m, int32_t x, int32_t y, const Impression *imp,
                       int32_t *compared)
{
	double mm = worldmodel_mismatch(m, x, y, imp, compared);
	double cells = RETINA_CELLS - 1;
	return (mm * *compared + WM_UNKNOWN_COST * (cells - *compared)) / cells;
}

/* wm_place(m, x, y, held, under): puts the held object's squares down round Utak
 * on square (x, y), keeping in under what they cover (all but his own square). */
static void wm_place(WorldModel *m, int32_t x, int32_t y, const Evidence *held, Evidence *under)
{
	for (int32_t j = 0; j < m->held_count; j++) {
		if (m->held_dx[j] == 0 && m->held_dy[j] == 0)
			continue;
		Evidence *e = wm_at(m, x + m->held_dx[j], y + m->held_dy[j]);
		if (!e)
			continue;
		if (under)
			under[j] = *e;
		*e = held[j];
	}
}

/* wm_lift(m, x, y, under): puts back what wm_place(m, x, y, ...) covered. Squares
 * are restored in reverse order, so that one covered twice gets its first value. */
static void wm_lift(WorldModel *m, int32_t x, int32_t y, const Evidence *under)
{
	for (int32_t j = m->held_count - 1; j >= 0; j--) {
		if (m->held_dx[j] == 0 && m->held_dy[j] == 0)
			continue;
		Evidence *e = wm_at(m, x + m->held_dx[j], y + m->held_dy[j]);
		if (e)
			*e = under[j];
	}
}

/* wm_score_holding(m, x, y, held, under, imp, &compared): wm_score of Utak on (x, y)
 * pushing: the held object moves with him, so wherever he is, it is beside him. A
 * model that left it at the predicted place would have it vote for the prediction
 * even when the push was blocked. */
double wm_score_holding(WorldModel *m, int32_t x, int32_t y, const Evidence *held, Evidence *under,
                        const Impression *imp, int32_t *compared)
{
	wm_place(m, x, y, held, under);
	double score = wm_score(m, x, y, imp, compared);
	wm_lift(m, x, y, under);
	return score;
}

/* wm_explained(m, x, y, held, under, imp): Utak on (x, y) (with the held object
 * beside him, held not NULL) explains every cell the model predicts, once each
 * difference is counted beyond the slack of coarse knowledge (wm_tolerant_mismatch
 * is zero). */
static bool wm_explained(WorldModel *m, int32_t x, int32_t y, const Evidence *held, Evidence *under,
                         const Impression *imp)
{
	if (held)
		wm_place(m, x, y, held, under);
	bool explained = wm_tolerant_mismatch(m, x, y, imp) == 0;
	if (held)
		wm_lift(m, x, y, under);
	return explained;
}

/* wm_try(m, x, y, ...): scores candidate square (x, y) and keeps it when better. */
typedef struct WmSearch {
	WorldModel *m;
	const Impression *imp;
	const Evidence *held; /* pushing: the held object's squares, lifted, else NULL */
	Evidence *under;      /* pushing: room for what they cover */
	int32_t px, py; /* the predicted square */
	Vec2 from, to;  /* the commanded line: believed point before, predicted after */
	int32_t bx, by; /* the best so far */
	double best_key, best_score;
	int32_t tried;  /* candidates scored */
	/* Pushing: every candidate judged, with its key, its measure and how many
	 * held squares it puts on squares surely occupied (wm_held_on_solid), for
	 * wm_solid_tie. */
	struct WmCand {
		int32_t x, y, solid, believed, levels;
		double key, score;
	} *cand;
	int ncand, capcand;
} WmSearch;

/* wm_compared_bare(m, x, y, imp): the cells a position is judged on by the model
 * as it stands (with the held object lifted, while pushing). */
static int32_t wm_compared_bare(const WorldModel *m, int32_t x, int32_t y, const Impression *imp)
{
	int32_t compared;
	worldmodel_mismatch(m, x, y, imp, &compared);
	return compared;
}

/* wm_levels(score, compared): the levels by which the cells compared disagree, in
 * all, from a wm_score of `compared` cells (its cost of the cells not compared
 * taken off). */
static int32_t wm_levels(double score, int32_t compared)
{
	double cells = RETINA_CELLS - 1;
	return (int32_t)lround((score * cells - WM_UNKNOWN_COST * (cells - compared)) * EYE_MAX_LEVEL);
}

static void wm_try(WmSearch *s, int32_t x, int32_t y)
{
	int32_t ux, uy;
	worldmodel_utak_square(s->m, &ux, &uy);
	Evidence e = worldmodel_evidence(s->m, x, y);
	if (!(x == ux && y == uy) && e.res != WORLDMODEL_UNSEEN && e.p >= 0.5f &&
	    e.conf >= WM_BLOCKED_CONF)
		return; /* Utak cannot stand inside what is surely an object */
	s->tried++;
	int32_t compared;
	double score = s->held ? wm_score_holding(s->m, x, y, s->held, s->under, s->imp, &compared)
	                       : wm_score(s->m, x, y, s->imp, &compared);
	if (compared < WORLDMODEL_MIN_COMPARED)
		return;
	/* Pushing, the held object rides beside every candidate and is compared at
	 * each: a position must also be judged on what stays put. WHY: a push of
	 * thousands of squares that halted at once otherwise had its prediction, far
	 * in the unseen, judged on the object alone and believed, and the model's
	 * window (and the cost of deriving the tree, O(its area)) ran away with it. */
	if (s->held && wm_compared_bare(s->m, x, y, s->imp) < WORLDMODEL_MIN_COMPARED)
		return;
	Vec2 c = vec2(x + 0.5, y + 0.5), ab = vec2_sub(s->to, s->from);
	double len2 = vec2_dot(ab, ab),
	       t = len2 > 0 ? vec2_dot(vec2_sub(c, s->from), ab) / len2 : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	Vec2 on_line = vec2_add(s->from, vec2_scale(ab, t));
	double key = score + WM_LINE_COST * hypot(c.x - on_line.x, c.y - on_line.y) +
	             WM_DISTANCE_COST * hypot(x - s->px, y - s->py);
	if (s->held) {
		s->cand = util_grow(s->cand, &s->capcand, s->ncand + 1, sizeof *s->cand);
		s->cand[s->ncand++] = (struct WmCand){x, y, wm_held_on_solid(s->m, x, y), wm_held_on_occupied(s->m, x, y),
		                                      wm_levels(score, compared), key, score};
	}
	if (key < s->best_key) {
		s->best_key = key;
		s->best_score = score;
		s->bx = x;
		s->by = y;
	}
}

/* wm_take(s, k): the search's position becomes candidate k; false (nothing taken)
 * when k < 0. The end of wm_solid_tie and wm_pressed. */
static bool wm_take(WmSearch *s, int32_t k)
{
	if (k < 0)
		return false;
	s->bx = s->cand[k].x;
	s->by = s->cand[k].y;
	s->best_score = s->cand[k].score;
	return true;
}

/* wm_solid_tie(s): pushing, the position found (s->bx, s->by, of measure
 * s->best_score) gives way to a candidate the impression cannot tell from it (its
 * measure at most WORLDMODEL_DISPARITY_MARGIN worse) that puts fewer held squares
 * on squares the model surely believes occupied (wm_held_on_solid): the fewest,
 * and of those the least key. True when it did. WHY: two things do not share a
 * square. An object pushed straight against a wall or the verge shows the eye the
 * same impression whether the push went on or halted: the object rides with Utak,
 * the wall beyond it is hidden by it or runs along the push, and what stays put
 * elsewhere may be far off, in coarse cells. The prediction then stood, and every
 * halted push read as a square gained: with --noise 0.05 Utak pushed a square
 * "into" the verge four times over and claimed a corner it was 2 short of
 * (tests/worlds/push-pier-noise.w, seed 2; a pier far off in the periphery his only mark
 * along the push). The object cannot have gone into a wall the eye has surely
 * seen; where the eye does tell (a margin's worth), it decides, so a wall the
 * model has a square off, or a square of the object left out of the held set
 * (still occupied before it), does not stop a push the impression shows made. */
static bool wm_solid_tie(WmSearch *s)
{
	int32_t have = wm_held_on_solid(s->m, s->bx, s->by), best = -1;
	for (int k = 0; k < s->ncand; k++) {
		const struct WmCand *c = &s->cand[k];
		if (c->solid >= have || c->score > s->best_score + WORLDMODEL_DISPARITY_MARGIN)
			continue;
		if (best < 0 || c->solid < s->cand[best].solid ||
		    (c->solid == s->cand[best].solid && c->key < s->cand[best].key))
			best = k;
	}
	return wm_take(s, best);
}

/* wm_pressed(s): pushing, the position found (s->bx, s->by) gives way to a
 * candidate that puts fewer held squares on squares the model believes occupied
 * at all (wm_held_on_occupied: p >= 0.5, however unsure), and no more on squares
 * surely occupied (wm_solid_tie's measure, which has spoken), when the impression
 * shows that candidate better (fewer levels of disagreement, wm_levels, and a
 * lower measure) or, for a push of at most a square, when that candidate is the
 * square he pushed from and the impression is the last one unchanged. Of those,
 * the least key. True when it did.
 * WHY (paper 3.5): the prediction stands unless another position beats it by
 * WORLDMODEL_DISPARITY_MARGIN, the prior that a command does what it says. A push
 * that would carry the object into squares the model believes occupied has lost
 * that prior. Pressed against the verge, a slanted object's pushes halted, the
 * verge beside and beyond it seen only in coarse cells half on the object (conf
 * below WM_BLOCKED_CONF, which wm_solid_tie asks for), and the impression showed
 * the halt better by less than the margin: each read as a square gained, and Utak
 * claimed a corner the object was 2 short of (adversarial world h38,
 * tests/worlds/push-slant-verge.w: a false success). An impression left unchanged
 * by such a push is what a halt shows; one that went on would show what stopped
 * it nearer. Not "any" better measure: a candidate that compares fewer cells (the
 * prediction looks further into what is unseen) pays less for them, so it must
 * also disagree in fewer levels; and a push that carries the object into floor
 * the model is unsure of keeps its margin. */
static bool wm_pressed(WmSearch *s)
{
	int32_t have = wm_held_on_occupied(s->m, s->bx, s->by), solid = wm_held_on_solid(s->m, s->bx, s->by);
	int32_t best = -1, compared;
	double score = wm_score_holding(s->m, s->bx, s->by, s->held, s->under, s->imp, &compared);
	int32_t levels = wm_levels(score, compared);
	int32_t fx = (int32_t)floor(s->from.x), fy = (int32_t)floor(s->from.y);
	bool short_push = hypot(s->to.x - s->from.x, s->to.y - s->from.y) <= 1;
	for (int k = 0; k < s->ncand; k++) {
		const struct WmCand *c = &s->cand[k];
		if (c->believed >= have || c->solid > solid)
			continue;
		bool shown = c->levels < levels && c->score < score;
		if (!shown && short_push && c->x == fx && c->y == fy)
			shown = memcmp(s->imp->level, s->m->last.level, sizeof s->imp->level) == 0;
		if (shown && (best < 0 || c->key < s->cand[best].key))
			best = k;
	}
	return wm_take(s, best);
}

/* wm_line_in_sight(m, from, to, len, &t0, &t1): the stretch [t0, t1] of the
 * commanded line from `from` to `to` (t in squares from `from`, len its length)
 * along which a candidate can see a square the model had seen; false if none.
 *
 * WHY: a candidate whose field of view holds no square seen before compares no
 * cell, so wm_try rejects it (fewer than WORLDMODEL_MIN_COMPARED). Pushing, it
 * compares only the held object, which rides beside it wherever it is: such a
 * candidate scores as the prediction does (itself such a place whenever this
 * clips anything, the line being straight and the window convex) and loses to it
 * on distance. So the search is the same, and its cost follows what Utak can have
 * seen, not the command: "move -1000000 -1000000" into the verge a few squares
 * away tried 2.8 million positions, one projection through the eye each. (Where
 * the field leaves the evidence's reach, WORLDMODEL_REACH squares from the start, fewer held
 * squares are placed and the two may differ; the model is already clipped there.)
 * ALGORITHM: Liang-Barsky clipping against the seen rectangle grown by
 * WM_SIGHT_MARGIN. COMPLEXITY: O(1). */
static bool wm_line_in_sight(const WorldModel *m, Vec2 from, Vec2 to, double len, double *t0, double *t1)
{
	*t0 = 0;
	*t1 = len;
	if (m->seen_count == 0)
		return false;
	double lo[2] = {m->seen_x0 - WM_SIGHT_MARGIN, m->seen_y0 - WM_SIGHT_MARGIN};
	double hi[2] = {m->seen_x1 + 1 + WM_SIGHT_MARGIN, m->seen_y1 + 1 + WM_SIGHT_MARGIN};
	double p[2] = {from.x, from.y}, d[2] = {(to.x - from.x) / len, (to.y - from.y) / len};
	for (int a = 0; a < 2; a++) {
		if (d[a] == 0) {
			if (p[a] < lo[a] || p[a] > hi[a])
				return false;
			continue;
		}
		double ta = (lo[a] - p[a]) / d[a], tb = (hi[a] - p[a]) / d[a];
		*t0 = fmax(*t0, fmin(ta, tb));
		*t1 = fmin(*t1, fmax(ta, tb));
	}
	return *t0 <= *t1;
}

/* wm_placed(s, x, y, dx, dy, score): the impression places Utak against a shift
 * from believed square (x, y), of measure score, by (dx, dy): there he could not
 * stand, or the model would match it worse by WORLDMODEL_DISPARITY_MARGIN, or
 * could not judge it. */
static bool wm_placed(WmSearch *s, int32_t x, int32_t y, int32_t dx, int32_t dy, double score)
{
	Evidence e = worldmodel_evidence(s->m, x + dx, y + dy);
	if (e.res != WORLDMODEL_UNSEEN && e.p >= 0.5f && e.conf >= WM_BLOCKED_CONF)
		return true;
	int32_t compared;
	double other = s->held ? wm_score_holding(s->m, x + dx, y + dy, s->held, s->under, s->imp, &compared)
	                       : wm_score(s->m, x + dx, y + dy, s->imp, &compared);
	return compared < WORLDMODEL_MIN_COMPARED || other >= score + WORLDMODEL_DISPARITY_MARGIN;
}

/* wm_drift(m, s, cmd, corrected): after a move or push, the evidence of motion's
 * error (worldmodel_motion_error): the correction's part no halt explains (a halt
 * ends the move short on its line: so the part across the line, and the part past
 * its end), and the squared length commanded. */
static void wm_drift(WorldModel *m, WmSearch *s, const MotorCommand *cmd, bool corrected)
{
	if (cmd->kind != MOTOR_MOVE && cmd->kind != MOTOR_PUSH)
		return;
	double len = hypot(cmd->dx, cmd->dy);
	if (len <= 0 || (cmd->kind == MOTOR_PUSH && !m->holding))
		return;
	double cx = corrected ? s->bx - s->px : 0, cy = corrected ? s->by - s->py : 0;
	double along = (cx * cmd->dx + cy * cmd->dy) / len, across = (cx * cmd->dy - cy * cmd->dx) / len;
	m->drift_sq += across * across + (along > 0 ? along * along : 0);
	m->drift_len_sq += len * len;
	int32_t x = corrected ? s->bx : s->px, y = corrected ? s->by : s->py, compared;
	double score = s->held ? wm_score_holding(m, x, y, s->held, s->under, s->imp, &compared)
	                       : wm_score(m, x, y, s->imp, &compared);
	for (int a = 0; a < 2; a++) {
		m->unplaced[a] += len * len;
		if (wm_placed(s, x, y, a == 0, a == 1, score) && wm_placed(s, x, y, -(a == 0), -(a == 1), score))
			m->unplaced[a] = 0;
	}
}

double worldmodel_motion_error(const WorldModel *m)
{
	return m->drift_len_sq > 0 ? sqrt(m->drift_sq / m->drift_len_sq) : 0;
}

/* wm_seen_window(m): counts the squares seen and their rectangle (WorldModel's seen_
 * fields): one scan of the tiles allocated, after every change to the evidence. */
static void wm_seen_window(WorldModel *m)
{
	int32_t n = 0, x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;
	for (int32_t t = 0; t < m->tile_count; t++) {
		const Evidence *tile = m->tile[m->tile_list[t]];
		int32_t tx = m->tile_list[t] % WORLDMODEL_TILES, ty = m->tile_list[t] / WORLDMODEL_TILES;
		for (int32_t at = 0; at < WORLDMODEL_TILE * WORLDMODEL_TILE; at++) {
			if (tile[at].res == WORLDMODEL_UNSEEN)
				continue;
			int32_t x = tx * WORLDMODEL_TILE - WORLDMODEL_REACH + at % WORLDMODEL_TILE;
			int32_t y = ty * WORLDMODEL_TILE - WORLDMODEL_REACH + at / WORLDMODEL_TILE;
			x0 = x < x0 ? x : x0;
			y0 = y < y0 ? y : y0;
			x1 = x > x1 ? x : x1;
			y1 = y > y1 ? y : y1;
			n++;
		}
	}
	m->seen_count = n;
	m->seen_x0 = x0;
	m->seen_y0 = y0;
	m->seen_x1 = x1;
	m->seen_y1 = y1;
}

int32_t worldmodel_known_squares(const WorldModel *m)
{
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	/* Utak's own square is floor whether seen or not (worldmodel_belief). */
	return m->seen_count + (worldmodel_evidence(m, ux, uy).res == WORLDMODEL_UNSEEN);
}

/* ---- accommodation ---------------------------------------------------------------- */

void worldmodel_init(WorldModel *m)
{
	memset(m, 0, sizeof *m);
	m->tile = util_alloc((size_t)WORLDMODEL_TILES * WORLDMODEL_TILES, sizeof *m->tile);
	m->utak = vec2(0.5, 0.5);
	m->report.predicted = m->report.believed = m->utak;
	m->report.mismatch = m->report.best_mismatch = -1;
	wm_seen_window(m);
	modeltree_derive(m);
}

void worldmodel_free(WorldModel *m)
{
	for (int32_t t = 0; t < m->tile_count; t++)
		free(m->tile[m->tile_list[t]]);
	free(m->tile);
	free(m->tile_list);
	free(m->node);
	free(m->node_at);
	free(m->ring);
	free(m->vertex);
	memset(m, 0, sizeof *m);
}

void worldmodel_accommodate_first(WorldModel *m, const Impression *imp)
{
	memset(&m->report, 0, sizeof m->report);
	m->report.predicted = m->report.believed = m->utak;
	m->report.mismatch = m->report.best_mismatch = -1;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	wm_observe(m, ux, uy, imp);
	m->last = m->first = *imp;
	m->impressions = 1;
	wm_seen_window(m);
	modeltree_derive(m);
}

void worldmodel_accommodate(WorldModel *m, const MotorCommand *cmd, const Impression *imp)
{
	Accommodation *rep = &m->report;
	memset(rep, 0, sizeof *rep);
	Vec2 from = m->utak, to = m->utak;
	Evidence *held = NULL, *under = NULL; /* a push: the object, lifted */
	/* The predicted model (paper 3.5): what the command should have done. */
	switch (cmd->kind) {
	case MOTOR_MOVE:
		to = vec2_add(from, vec2(cmd->dx, cmd->dy));
		break;
	case MOTOR_PUSH:
		/* Without a held object the simulator refuses a push (paper 2.2). With
		 * one, it is lifted from where it was and put down below, where Utak
		 * is found to be. */
		if (m->holding)
			to = vec2_add(from, vec2(cmd->dx, cmd->dy));
		if (m->holding && m->held_count > 0) {
			held = util_alloc((size_t)m->held_count, sizeof *held);
			under = util_alloc((size_t)m->held_count, sizeof *under);
			wm_vacate(m, from, held);
		}
		break;
	case MOTOR_TURN:
		if (m->holding) {
			wm_carry(m, from, to, cmd->deg);
			wm_box_held(m);
		}
		break;
	case MOTOR_GRASP:
		/* Granted when touch showed an object (the simulator's rule, paper 2.2). */
		wm_find_held(m, &m->last);
		wm_box_held(m);
		/* Holding whenever touch showed an object's colour; its squares may be
		 * unknown (held_count 0: it leans on a wall), and then the model moves
		 * Utak alone and the eye finds the object where it went. */
		m->holding = false;
		for (int k = 0; k < TOUCH_CELLS; k++)
			m->holding |= m->last.touch[k] >= 'A' && m->last.touch[k] <= 'Z' && m->last.touch[k] != 'B';
		break;
	case MOTOR_RELEASE:
		m->holding = false;
		m->held_count = 0;
		break;
	}
	m->utak = to;
	rep->predicted = to;
	int32_t px, py;
	worldmodel_utak_square(m, &px, &py);
	rep->mismatch = held ? wm_score_holding(m, px, py, held, under, imp, &rep->compared)
	                     : wm_score(m, px, py, imp, &rep->compared);

	/* Disparity: the positions near the prediction and along the commanded line. */
	WmSearch s = {m, imp, held, under, px, py, from, to, px, py, INFINITY, rep->mismatch, 0, NULL, 0, 0};
	/* The prediction counts as judged by the same rule as every candidate (wm_try). */
	bool judged = rep->compared >= WORLDMODEL_MIN_COMPARED &&
	              (!held || wm_compared_bare(m, px, py, imp) >= WORLDMODEL_MIN_COMPARED);
	if (judged)
		s.best_key = rep->mismatch;
	int32_t r = WORLDMODEL_DISPARITY_RADIUS;
	for (int32_t dy = r; dy >= -r; dy--)
		for (int32_t dx = -r; dx <= r; dx++)
			wm_try(&s, px + dx, py + dy);
	/* Only the stretch of the line within sight of the seen squares; its t are
	 * the multiples of WM_PATH_STEP they always were (exact in binary). */
	double len = hypot(to.x - from.x, to.y - from.y), t0, t1;
	bool in_sight = len > 0 && wm_line_in_sight(m, from, to, len, &t0, &t1);
	for (double t = in_sight ? WM_PATH_STEP * ceil(t0 / WM_PATH_STEP) : len; t < len && t <= t1;
	     t += WM_PATH_STEP) {
		Vec2 q = vec2_add(from, vec2_scale(vec2_sub(to, from), t / len));
		int32_t qx = (int32_t)floor(q.x), qy = (int32_t)floor(q.y);
		for (int32_t dy = 1; dy >= -1; dy--)
			for (int32_t dx = -1; dx <= 1; dx++)
				wm_try(&s, qx + dx, qy + dy);
	}
	rep->best_mismatch = s.best_score;
	rep->candidates = s.tried;
	/* A correction needs a difference the prediction cannot explain: none when,
	 * counted beyond the slack of coarse knowledge, every cell it predicts agrees
	 * (wm_explained). WHY: after a long move the fovea lands on squares seen only
	 * in 4 x 4 cells, one of which may hold a square of an object a zero cell did
	 * not show; that one foveal cell (a whole cell's difference, five times the
	 * margin) moved the belief 2.24 squares off a move nothing stopped, to a
	 * square where the object fell on squares the model cannot predict, and Utak
	 * closed his loop round the square on the wrong square and claimed it
	 * (tests/worlds/coarse-zero-slack.w). A difference within that resolution is
	 * no evidence of where he is. Only a veto: a difference beyond it leaves the
	 * search's choice as it was (a margin of evidence for the best, however
	 * small the rest: with --noise a 2 x 2 cell with two squares over one zero
	 * 4 x 4 cell was the only sign of a leg 1.75 squares long, worlds/west.w
	 * seed 10, and the estimate of motion's error needs it). */
	/* A turn moves the object held about Utak's point, never Utak (paper 2.2):
	 * no look after one can place him elsewhere. Where the held object did not
	 * turn as predicted (a turn halted against a piece not held, swing.h), the
	 * search found the difference a better fit two squares off. */
	if ((s.bx != px || s.by != py) && cmd->kind != MOTOR_TURN &&
	    (!judged ||
	     (s.best_score + WORLDMODEL_DISPARITY_MARGIN < rep->mismatch && !wm_explained(m, px, py, held, under, imp)))) {
		rep->corrected = true;
	} else {
		s.bx = px;
		s.by = py;
		s.best_score = rep->best_mismatch = rep->mismatch;
	}
	/* Both, in this order (wm_pressed weighs the position wm_solid_tie leaves): `|`
	 * would leave the order of the two calls unspecified. */
	bool tied = held && wm_solid_tie(&s);
	bool pressed = held && wm_pressed(&s);
	if (tied || pressed) {
		rep->corrected = s.bx != px || s.by != py;
		rep->best_mismatch = s.best_score;
	}
	free(s.cand);
	if (rep->corrected)
		m->utak = vec2_add(m->utak, vec2(s.bx - px, s.by - py));
	rep->believed = m->utak;
	wm_drift(m, &s, cmd, rep->corrected);

	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	if (held) {
		if (m->register_held)
			wm_register_held(m, ux, uy, held, under, imp);
		wm_place(m, ux, uy, held, NULL);
	}
	free(held);
	free(under);
	bool *was_floor = held ? wm_floor_round_held(m) : NULL;
	wm_observe(m, ux, uy, imp);
	if (held) {
		wm_prune_held(m);
		wm_regrow_held(m, was_floor);
	}
	free(was_floor);
	if (cmd->kind == MOTOR_TURN && m->holding) {
		wm_refind_held(m, imp);
		wm_box_held(m);
	}
	m->last = *imp;
	m->impressions++;
	wm_seen_window(m);
	modeltree_derive(m);
}
