/* worldmodel.c - Utak's world model: evidence, accommodation, disparity, the tree
 * (paper 3.3, 3.4.3, 3.5). CONTROLLER SIDE: it sees Impressions, the commands the
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
 * prediction, wins if it beats the prediction by WORLDMODEL_DISPARITY_MARGIN.
 * Sliding along a straight wall changes nothing the eye sees, so along a wall
 * the belief can only be as good as these ties.
 * The tree (paper 3.3, 3.4.3): after every impression, $floor is the set of floor
 * squares and each object a 4-connected set of occupied squares all of whose
 * neighbours are floor (the isolated objects of paper 3.4.2; sets touching the
 * unknown may be verge or objects partly seen, and stay part of $floor's
 * boundary, with the segments there marked as bounded by the occupied or the
 * unknown). Boundaries are traced along square edges with the set on the left
 * ("crack following" in digital topology), turning left first at pinch points
 * so that 4-connected sets stay apart, and merged into maximal straight segments.
 * A slanted edge therefore stays a staircase of unit steps: exactly what the
 * evidence says, never cutting into a square believed occupied.
 *
 * INVARIANTS: worldmodel_validate. MEMORY: one grid of WORLDMODEL_SIDE^2 Evidence
 * (3 MB) and the tree's arrays, owned by the WorldModel; scratch for tracing is
 * allocated and freed per derivation. COMPLEXITY: an impression costs O(1024)
 * squares to record, O(P x 1024) to search P candidate positions (P <= 49 + 9 x the
 * length of the move), and O(A) to derive the tree, A the seen area. */
#include "utak/mind/worldmodel.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/eye.h"
#include "utak/base/util.h"

enum { WM_HALF = WORLDMODEL_SIDE / 2 };
/* A square's p is definite, and can be predicted, within this of 0 or 1. */
#define WM_DEFINITE 0.1
/* A candidate position on a square believed occupied this surely is not tried. */
#define WM_BLOCKED_CONF 0.5
/* ... and then to the candidate nearest the prediction: each square of distance
 * costs this much. */
#define WM_DISTANCE_COST 1e-4
/* A coarse cell agreeing with the finer knowledge inside it raises that knowledge's
 * confidence by this share of what is missing. */
#define WM_AGREE_GROWTH 0.05
/* The disparity cost of a cell the model cannot predict: about what a square
 * known only from a coarse cell is expected to be wrong by. It, the two costs
 * below and WORLDMODEL_DISPARITY_MARGIN were chosen by running random walks in
 * every world and counting how often the belief ends off the true square. */
#define WM_UNKNOWN_COST 0.005
/* A halted move ends on the commanded line: ties go first to the candidate nearest
 * that line (this much per square), then to the one nearest the prediction. Both
 * are far below one foveal cell's disagreement (about 0.005). */
#define WM_LINE_COST 1e-3
/* Steps along the commanded line when listing candidate positions, squares. */
#define WM_PATH_STEP 0.5

/* Own-frame offsets of the touch squares, in Impression.touch order. */
static const int8_t wm_touch_offset[TOUCH_CELLS][2] = {{0, 1},  {1, 1},   {1, 0},  {1, -1},
                                                       {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}};

/* ---- the evidence grid --------------------------------------------------------- */

static int64_t wm_index(int32_t x, int32_t y)
{
	if (x < -WM_HALF || x >= WM_HALF || y < -WM_HALF || y >= WM_HALF)
		return -1;
	return (int64_t)(y + WM_HALF) * WORLDMODEL_SIDE + (x + WM_HALF);
}

Evidence worldmodel_evidence(const WorldModel *m, int32_t x, int32_t y)
{
	int64_t k = wm_index(x, y);
	Evidence none = {0, 0, WORLDMODEL_UNSEEN, 0};
	return k < 0 ? none : m->grid[k];
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

/* wm_update(e, q, res, m): one observation of one square (the rules of worldmodel.h). */
static void wm_update(Evidence *e, double q, int res, WorldModel *m)
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
		int count = 0;
		bool all_known = true;
		int old_occupied = 0, finer = 0;
		for (int dy = 0; dy < c.size; dy++)
			for (int dx = 0; dx < c.size; dx++) {
				int64_t k = wm_index(sx + c.ox + dx, sy + c.oy + dy);
				if (k < 0) {
					/* Outside the window: not recorded, but said in the dump.
					 */
					m->clipped = true;
					continue;
				}
				Evidence *e = &m->grid[k];
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
			if (sq[s]->res <= res)
				wm_update(sq[s], q, res, m);
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
				int64_t k = wm_index(x + c.ox + dx, y + c.oy + dy);
				if (k < 0 || m->grid[k].res == WORLDMODEL_UNSEEN) {
					ok = false;
					break;
				}
				float p = m->grid[k].p;
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
		int64_t k = wm_index(x + m->held_dx[j], y + m->held_dy[j]);
		if (k < 0 || (m->held_dx[j] == 0 && m->held_dy[j] == 0))
			continue;
		if (under)
			under[j] = m->grid[k];
		m->grid[k] = held[j];
	}
}

/* wm_lift(m, x, y, under): puts back what wm_place(m, x, y, ...) covered. Squares
 * are restored in reverse order, so that one covered twice gets its first value. */
static void wm_lift(WorldModel *m, int32_t x, int32_t y, const Evidence *under)
{
	for (int32_t j = m->held_count - 1; j >= 0; j--) {
		int64_t k = wm_index(x + m->held_dx[j], y + m->held_dy[j]);
		if (k >= 0 && !(m->held_dx[j] == 0 && m->held_dy[j] == 0))
			m->grid[k] = under[j];
	}
}

/* wm_score_holding(m, x, y, held, under, imp, &compared): wm_score of Utak on (x, y)
 * pushing: the held object moves with him, so wherever he is, it is beside him. A
 * model that left it at the predicted place would have it vote for the prediction
 * even when the push was blocked. */
static double wm_score_holding(WorldModel *m, int32_t x, int32_t y, const Evidence *held, Evidence *under,
                               const Impression *imp, int32_t *compared)
{
	wm_place(m, x, y, held, under);
	double score = wm_score(m, x, y, imp, compared);
	wm_lift(m, x, y, under);
	return score;
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
} WmSearch;

static void wm_try(WmSearch *s, int32_t x, int32_t y)
{
	int32_t ux, uy;
	worldmodel_utak_square(s->m, &ux, &uy);
	Evidence e = worldmodel_evidence(s->m, x, y);
	if (!(x == ux && y == uy) && e.res != WORLDMODEL_UNSEEN && e.p >= 0.5f &&
	    e.conf >= WM_BLOCKED_CONF)
		return; /* Utak cannot stand inside what is surely an object */
	int32_t compared;
	double score = s->held ? wm_score_holding(s->m, x, y, s->held, s->under, s->imp, &compared)
	                       : wm_score(s->m, x, y, s->imp, &compared);
	if (compared < WORLDMODEL_MIN_COMPARED)
		return;
	Vec2 c = vec2(x + 0.5, y + 0.5), ab = vec2_sub(s->to, s->from);
	double len2 = vec2_dot(ab, ab),
	       t = len2 > 0 ? vec2_dot(vec2_sub(c, s->from), ab) / len2 : 0;
	t = t < 0 ? 0 : t > 1 ? 1 : t;
	Vec2 on_line = vec2_add(s->from, vec2_scale(ab, t));
	double key = score + WM_LINE_COST * hypot(c.x - on_line.x, c.y - on_line.y) +
	             WM_DISTANCE_COST * hypot(x - s->px, y - s->py);
	if (key < s->best_key) {
		s->best_key = key;
		s->best_score = score;
		s->bx = x;
		s->by = y;
	}
}

/* ---- the held object ------------------------------------------------------------ */

/* wm_find_held(m, imp): the squares of the object Utak touches (the first object
 * colour in imp's touch order), as offsets from his square; held_count stays 0
 * when the model cannot say which squares those are. */
static void wm_find_held(WorldModel *m, const Impression *imp)
{
	m->held_count = 0;
	int k = 0;
	while (k < TOUCH_CELLS && (imp->touch[k] == '.' || imp->touch[k] == 'B'))
		k++;
	if (k == TOUCH_CELLS)
		return;
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	int32_t seed_x = ux + wm_touch_offset[k][0], seed_y = uy + wm_touch_offset[k][1];
	if (worldmodel_belief(m, seed_x, seed_y) != BELIEF_OCCUPIED)
		return;
	/* Flood fill, 4-connected, over occupied squares; the held offsets double as
	 * the stack and the visited list. */
	int32_t n = 0, next = 0;
	m->held_dx[n] = seed_x - ux;
	m->held_dy[n] = seed_y - uy;
	n++;
	while (next < n) {
		int32_t x = ux + m->held_dx[next], y = uy + m->held_dy[next];
		next++;
		static const int8_t step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
		for (int d = 0; d < 4; d++) {
			int32_t nx = x + step[d][0], ny = y + step[d][1];
			if (worldmodel_belief(m, nx, ny) != BELIEF_OCCUPIED)
				continue;
			bool seen = false;
			for (int32_t j = 0; j < n && !seen; j++)
				seen = m->held_dx[j] == nx - ux && m->held_dy[j] == ny - uy;
			if (seen)
				continue;
			if (n == WORLDMODEL_HELD_MAX) {
				m->held_count = 0; /* too big to be one object: part of the verge */
				return;
			}
			m->held_dx[n] = nx - ux;
			m->held_dy[n] = ny - uy;
			n++;
		}
	}
	m->held_count = n;
}

/* wm_prune_held(m): after a push, the held squares the eye now sees as floor: they
 * did not come along. A grasp takes one object (paper 2.2), and the model's held
 * set, found by flooding occupied squares, can take in another that touches it. */
static void wm_prune_held(WorldModel *m)
{
	int32_t ux, uy, n = 0;
	worldmodel_utak_square(m, &ux, &uy);
	for (int32_t j = 0; j < m->held_count; j++)
		if (worldmodel_belief(m, ux + m->held_dx[j], uy + m->held_dy[j]) == BELIEF_OCCUPIED) {
			m->held_dx[n] = m->held_dx[j];
			m->held_dy[n++] = m->held_dy[j];
		}
	m->held_count = n;
}

/* wm_vacate(m, from, saved): the held object's squares, Utak on `from`, leave their
 * places (predicted floor); their evidence goes to saved. */
static void wm_vacate(WorldModel *m, Vec2 from, Evidence *saved)
{
	int32_t fx = (int32_t)floor(from.x), fy = (int32_t)floor(from.y);
	for (int32_t j = 0; j < m->held_count; j++) {
		int64_t k = wm_index(fx + m->held_dx[j], fy + m->held_dy[j]);
		saved[j] = k >= 0 ? m->grid[k] : (Evidence){1, 0, WORLDMODEL_RES_PERIPHERAL, 1};
		if (k >= 0) {
			m->grid[k].p = 0;
			m->grid[k].conf = (float)(m->grid[k].conf * WORLDMODEL_CONF_CONTRADICTED);
		}
	}
}

/* wm_carry(m, from, to, deg): the predicted model of a turn: the held object's
 * squares leave their places (predicted floor) and are put down where the turn
 * takes their centres, the object turning by deg about Utak's point. (A push is
 * carried by the disparity search itself: worldmodel_accommodate.) */
static void wm_carry(WorldModel *m, Vec2 from, Vec2 to, double deg)
{
	Evidence saved[WORLDMODEL_HELD_MAX]; /* 12 KB */
	int32_t fx = (int32_t)floor(from.x), fy = (int32_t)floor(from.y);
	double c, s;
	geom_cos_sin(deg, &c, &s);
	wm_vacate(m, from, saved);
	int32_t tx = (int32_t)floor(to.x), ty = (int32_t)floor(to.y);
	for (int32_t j = 0; j < m->held_count; j++) {
		Vec2 centre = vec2(fx + m->held_dx[j] + 0.5, fy + m->held_dy[j] + 0.5);
		Vec2 moved = vec2_add(geom_rotate(centre, from, c, s), vec2_sub(to, from));
		int32_t nx = (int32_t)floor(moved.x), ny = (int32_t)floor(moved.y);
		int64_t k = wm_index(nx, ny);
		if (k >= 0 && !(nx == tx && ny == ty))
			m->grid[k] = saved[j];
	}
}

/* ---- the tree ------------------------------------------------------------------- */

/* The seen window, one square of margin round it, as a scratch belief map. */
typedef struct WmMap {
	int32_t x0, y0, w, h; /* lower-left square and size */
	uint8_t *belief;      /* Belief, row-major */
} WmMap;

static uint8_t wm_map_at(const WmMap *map, int32_t x, int32_t y)
{
	x -= map->x0;
	y -= map->y0;
	if (x < 0 || y < 0 || x >= map->w || y >= map->h)
		return BELIEF_UNKNOWN;
	return map->belief[(int64_t)y * map->w + x];
}

static float wm_conf_at(const WorldModel *m, int32_t x, int32_t y)
{
	Evidence e = worldmodel_evidence(m, x, y);
	return e.res == WORLDMODEL_UNSEEN ? 0.0f : e.conf;
}

static int32_t wm_new_node(WorldModel *m, NodeKind kind, const char *name, int32_t parent)
{
	m->node = util_grow(m->node, &m->node_cap, m->node_count + 1, sizeof *m->node);
	int32_t id = m->node_count++;
	ModelNode *n = &m->node[id];
	memset(n, 0, sizeof *n);
	n->kind = kind;
	snprintf(n->name, sizeof n->name, "%s", name);
	n->parent = parent;
	n->first_son = n->next_sibling = -1;
	n->first_ring = m->ring_count;
	if (parent >= 0) {
		int32_t *link = &m->node[parent].first_son;
		while (*link >= 0)
			link = &m->node[*link].next_sibling;
		*link = id;
	}
	return id;
}

static void wm_push_vertex(WorldModel *m, ModelVertex v)
{
	m->vertex = util_grow(m->vertex, &m->vertex_cap, m->vertex_count + 1, sizeof *m->vertex);
	m->vertex[m->vertex_count++] = v;
}

/* Directions of unit edges, counter-clockwise: a left turn is d + 1. */
enum { WM_EAST, WM_NORTH, WM_WEST, WM_SOUTH };
static const int8_t wm_step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
/* The squares left (inside) and right (outside) of a unit edge leaving vertex
 * (x, y) in direction d, as offsets from (x, y). */
static const int8_t wm_inside[4][2] = {{0, 0}, {-1, 0}, {-1, -1}, {0, -1}};
static const int8_t wm_outside[4][2] = {{0, -1}, {0, 0}, {-1, 0}, {-1, -1}};

typedef struct WmEdge {
	int32_t x, y; /* start vertex, $floor frame */
	uint8_t dir, beyond;
	float conf;
} WmEdge;

/* wm_trace(m, map, in, node): the boundary rings of the set of squares where
 * in[] (over map's window) is set, appended to node. */
static void wm_trace(WorldModel *m, const WmMap *map, const uint8_t *in, int32_t node)
{
	int32_t vw = map->w + 1, vh = map->h + 1;
	uint8_t *out =
	    util_alloc((size_t)vw * (size_t)vh, 1); /* bit d: an edge leaves in direction d */
	int32_t edge_total = 0;
	for (int32_t y = 0; y < map->h; y++)
		for (int32_t x = 0; x < map->w; x++) {
			if (!in[(int64_t)y * map->w + x])
				continue;
			for (int d = 0; d < 4; d++) {
				/* the neighbour across side d: the outside square of that edge */
				static const int8_t across[4][2] = {
				    {0, -1}, {1, 0}, {0, 1}, {-1, 0}};
				static const int8_t start[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
				int32_t nx = x + across[d][0], ny = y + across[d][1];
				bool inside = nx >= 0 && ny >= 0 && nx < map->w && ny < map->h &&
				              in[(int64_t)ny * map->w + nx];
				if (inside)
					continue;
				int32_t vx = x + start[d][0], vy = y + start[d][1];
				out[(int64_t)vy * vw + vx] |= (uint8_t)(1u << d);
				edge_total++;
			}
		}
	WmEdge *edges = util_alloc((size_t)edge_total + 1, sizeof *edges);
	for (int32_t v0 = 0; v0 < vw * vh; v0++)
		for (int d0 = 0; d0 < 4; d0++) {
			if (!(out[v0] & (1u << d0)))
				continue;
			int32_t n = 0, vx = v0 % vw, vy = v0 / vw, d = d0;
			for (;;) {
				out[(int64_t)vy * vw + vx] &= (uint8_t) ~(1u << d);
				int32_t gx = vx + map->x0, gy = vy + map->y0; /* $floor frame */
				int32_t ox = gx + wm_outside[d][0], oy = gy + wm_outside[d][1];
				int32_t ix = gx + wm_inside[d][0], iy = gy + wm_inside[d][1];
				edges[n++] =
				    (WmEdge){gx, gy, (uint8_t)d, wm_map_at(map, ox, oy),
				             (wm_conf_at(m, ix, iy) + wm_conf_at(m, ox, oy)) / 2};
				vx += wm_step[d][0];
				vy += wm_step[d][1];
				uint8_t bits = out[(int64_t)vy * vw + vx];
				if (vy * vw + vx == v0)
					bits |= (uint8_t)(1u << d0);
				int next = -1;
				for (int t = 1; t >= -1 && next < 0;
				     t--) { /* left, straight, right */
					int cand = (d + t + 4) % 4;
					if (bits & (1u << cand))
						next = cand;
				}
				if (next < 0 || (vy * vw + vx == v0 && next == d0))
					break;
				d = next;
			}
			/* Corners: where the direction or what lies beyond changes. */
			int32_t s0 = 0;
			while (s0 < n && edges[s0].dir == edges[(s0 + n - 1) % n].dir &&
			       edges[s0].beyond == edges[(s0 + n - 1) % n].beyond)
				s0++;
			if (s0 == n)
				continue; /* cannot happen for a closed loop of unit edges */
			m->ring =
			    util_grow(m->ring, &m->ring_cap, m->ring_count + 1, sizeof *m->ring);
			ModelRing *r = &m->ring[m->ring_count++];
			r->first = m->vertex_count;
			r->count = 0;
			double area2 = 0;
			for (int32_t j = 0; j < n; j++) {
				const WmEdge *e = &edges[(s0 + j) % n];
				area2 += (double)e->x * wm_step[e->dir][1] -
				         (double)e->y * wm_step[e->dir][0];
			}
			for (int32_t j = 0; j < n;) {
				const WmEdge *e = &edges[(s0 + j) % n];
				int32_t len = 0;
				double conf = 0;
				while (j + len < n && edges[(s0 + j + len) % n].dir == e->dir &&
				       edges[(s0 + j + len) % n].beyond == e->beyond) {
					conf += edges[(s0 + j + len) % n].conf;
					len++;
				}
				float corner =
				    (wm_conf_at(m, e->x, e->y) + wm_conf_at(m, e->x - 1, e->y) +
				     wm_conf_at(m, e->x, e->y - 1) +
				     wm_conf_at(m, e->x - 1, e->y - 1)) /
				    4;
				wm_push_vertex(m, (ModelVertex){vec2(e->x, e->y), corner,
				                                (float)(conf / len), e->beyond});
				r->count++;
				j += len;
			}
			r->hole = area2 < 0;
			m->node[node].ring_count++;
		}
	free(edges);
	free(out);
}

/* wm_finish_node(m, node, map, in): rectangle, squares and confidence of a node
 * whose set of squares is in[]. */
static void wm_finish_node(WorldModel *m, int32_t node, const WmMap *map, const uint8_t *in)
{
	ModelNode *n = &m->node[node];
	int32_t x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN, count = 0;
	double conf = 0;
	for (int32_t y = 0; y < map->h; y++)
		for (int32_t x = 0; x < map->w; x++)
			if (in[(int64_t)y * map->w + x]) {
				int32_t gx = x + map->x0, gy = y + map->y0;
				x0 = gx < x0 ? gx : x0;
				y0 = gy < y0 ? gy : y0;
				x1 = gx > x1 ? gx : x1;
				y1 = gy > y1 ? gy : y1;
				conf += wm_conf_at(m, gx, gy);
				count++;
			}
	if (count == 0)
		return;
	n->rect = (Box){vec2(x0, y0), vec2(x1 + 1, y1 + 1)};
	n->squares = count;
	n->conf = (float)(conf / count);
	n->relation = n->rect.lo;
}

/* What an object node was at the last derivation, to keep its number. */
typedef struct WmPrevious {
	int32_t ident;
	Box rect; /* $floor frame; for a held object, relative to Utak's point */
	bool held, used;
} WmPrevious;

static double wm_overlap(Box a, Box b)
{
	double w = fmin(a.hi.x, b.hi.x) - fmax(a.lo.x, b.lo.x),
	       h = fmin(a.hi.y, b.hi.y) - fmax(a.lo.y, b.lo.y);
	return w > 0 && h > 0 ? w * h : 0;
}

static Box wm_box_shift(Box b, Vec2 d)
{
	return (Box){vec2_add(b.lo, d), vec2_add(b.hi, d)};
}

/* wm_name_object(m, node, prev, nprev): gives the node the number of the previous
 * object whose rectangle overlaps its own most (a held object compared relative
 * to Utak, since it moved with him), or a new number. */
static void wm_name_object(WorldModel *m, int32_t node, WmPrevious *prev, int32_t nprev,
                           Vec2 prev_utak)
{
	ModelNode *n = &m->node[node];
	int32_t best = -1;
	double best_area = 0;
	for (int32_t k = 0; k < nprev; k++) {
		if (prev[k].used)
			continue;
		Box mine = n->rect, theirs = prev[k].rect;
		if (prev[k].held && n->held) {
			mine = wm_box_shift(mine, vec2_scale(m->utak, -1));
			theirs = wm_box_shift(theirs, vec2_scale(prev_utak, -1));
		}
		double area = wm_overlap(mine, theirs);
		if (area > best_area) {
			best_area = area;
			best = k;
		}
	}
	if (best >= 0) {
		prev[best].used = true;
		n->ident = prev[best].ident;
	} else {
		n->ident = ++m->next_ident;
	}
	snprintf(n->name, sizeof n->name, "object%d", (int)n->ident);
}

/* wm_seen_window(m): counts the squares seen and their rectangle (WorldModel's
 * seen_ fields): one scan of the evidence window, made by wm_derive after every
 * change to the grid. */
static void wm_seen_window(WorldModel *m)
{
	int32_t n = 0, x0 = INT32_MAX, y0 = INT32_MAX, x1 = INT32_MIN, y1 = INT32_MIN;
	for (int32_t y = -WM_HALF; y < WM_HALF; y++)
		for (int32_t x = -WM_HALF; x < WM_HALF; x++)
			if (m->grid[wm_index(x, y)].res != WORLDMODEL_UNSEEN) {
				x0 = x < x0 ? x : x0;
				y0 = y < y0 ? y : y0;
				x1 = x > x1 ? x : x1;
				y1 = y > y1 ? y : y1;
				n++;
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

/* wm_derive(m): the tree of paper 3.3 from the evidence grid. */
static void wm_derive(WorldModel *m)
{
	int32_t nprev = 0;
	WmPrevious *prev = util_alloc((size_t)m->node_count + 1, sizeof *prev);
	Vec2 prev_utak = m->node_count > 0 ? m->node[0].relation : m->utak;
	for (int32_t id = 0; id < m->node_count; id++)
		if (m->node[id].kind == NODE_OBJECT)
			prev[nprev++] = (WmPrevious){m->node[id].ident, m->node[id].rect,
			                             m->node[id].held, false};
	m->node_count = m->ring_count = m->vertex_count = 0;
	int32_t org = wm_new_node(m, NODE_ORG, "$org", -1);
	m->node[org].relation = m->utak;
	int32_t floor_node = wm_new_node(m, NODE_FLOOR, "$floor", org);
	m->node[floor_node].relation = vec2_scale(m->utak, -1);

	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	wm_seen_window(m);
	int32_t x0 = ux, y0 = uy, x1 = ux, y1 = uy;
	bool any = m->seen_count > 0;
	if (any) {
		x0 = m->seen_x0 < x0 ? m->seen_x0 : x0;
		y0 = m->seen_y0 < y0 ? m->seen_y0 : y0;
		x1 = m->seen_x1 > x1 ? m->seen_x1 : x1;
		y1 = m->seen_y1 > y1 ? m->seen_y1 : y1;
	}
	if (!any) {
		/* The default model: a square floor centred on Utak (paper 3.4.3). */
		ModelNode *f = &m->node[floor_node];
		double h = WORLDMODEL_DEFAULT_FLOOR / 2.0;
		f->rect = (Box){vec2(ux + 0.5 - h, uy + 0.5 - h), vec2(ux + 0.5 + h, uy + 0.5 + h)};
		f->relation = vec2_scale(m->utak, -1);
		f->squares = WORLDMODEL_DEFAULT_FLOOR * WORLDMODEL_DEFAULT_FLOOR;
		m->ring = util_grow(m->ring, &m->ring_cap, 1, sizeof *m->ring);
		m->ring[0] = (ModelRing){0, 4, false};
		Vec2 corner[4] = {f->rect.lo, vec2(f->rect.hi.x, f->rect.lo.y), f->rect.hi,
		                  vec2(f->rect.lo.x, f->rect.hi.y)};
		for (int k = 0; k < 4; k++)
			wm_push_vertex(m, (ModelVertex){corner[k], 0, 0, BELIEF_UNKNOWN});
		m->ring_count = 1;
		f->ring_count = 1;
		free(prev);
		return;
	}
	WmMap map = {x0 - 1, y0 - 1, x1 - x0 + 3, y1 - y0 + 3, NULL};
	size_t area = (size_t)map.w * (size_t)map.h;
	map.belief = util_alloc(area, 1);
	for (int32_t y = 0; y < map.h; y++)
		for (int32_t x = 0; x < map.w; x++)
			map.belief[(int64_t)y * map.w + x] =
			    (uint8_t)worldmodel_belief(m, x + map.x0, y + map.y0);
	uint8_t *in = util_alloc(area, 1);
	for (size_t k = 0; k < area; k++)
		in[k] = map.belief[k] == BELIEF_FLOOR;
	wm_trace(m, &map, in, floor_node);
	wm_finish_node(m, floor_node, &map, in);
	m->node[floor_node].relation = vec2_scale(m->utak, -1); /* $floor's origin seen from Utak */

	/* Objects: 4-connected occupied sets, every neighbour floor. */
	int32_t *label = util_alloc(area, sizeof *label);
	int32_t *stack = util_alloc(area, sizeof *stack);
	int32_t labels = 0, uncertain = 0;
	for (int32_t row = map.h - 1; row >= 0; row--) /* north first: the order of the map */
		for (int32_t col = 0; col < map.w; col++) {
			int64_t k0 = (int64_t)row * map.w + col;
			if (map.belief[k0] != BELIEF_OCCUPIED || label[k0])
				continue;
			int32_t id = ++labels, top = 0;
			bool isolated = true, held = false;
			label[k0] = id;
			stack[top++] = (int32_t)k0;
			memset(in, 0, area);
			while (top > 0) {
				int32_t k = stack[--top];
				int32_t x = k % map.w, y = k / map.w;
				in[k] = 1;
				for (int32_t j = 0; j < m->held_count && m->holding; j++)
					held |= x + map.x0 == ux + m->held_dx[j] &&
					        y + map.y0 == uy + m->held_dy[j];
				for (int d = 0; d < 4; d++) {
					int32_t nx = x + wm_step[d][0], ny = y + wm_step[d][1];
					uint8_t b = wm_map_at(&map, nx + map.x0, ny + map.y0);
					if (b == BELIEF_UNKNOWN)
						isolated = false;
					if (b != BELIEF_OCCUPIED)
						continue;
					int64_t kn = (int64_t)ny * map.w + nx;
					if (!label[kn]) {
						label[kn] = id;
						stack[top++] = (int32_t)kn;
					}
				}
			}
			if (!isolated) {
				/* Verge, or an object partly out of sight: recorded as uncertain.
				 */
				char name[24];
				snprintf(name, sizeof name, "uncertain%d", (int)++uncertain);
				int32_t node = wm_new_node(m, NODE_UNCERTAIN, name, floor_node);
				wm_finish_node(m, node, &map, in);
				continue;
			}
			int32_t node =
			    wm_new_node(m, NODE_OBJECT, "object", held ? org : floor_node);
			wm_trace(m, &map, in, node);
			wm_finish_node(m, node, &map, in);
			m->node[node].held = held;
			wm_name_object(m, node, prev, nprev, prev_utak);
			if (held) /* relation to $org: offset from Utak's point */
				m->node[node].relation = vec2_sub(m->node[node].rect.lo, m->utak);
		}
	free(stack);
	free(label);
	free(in);
	free(map.belief);
	free(prev);
}

/* ---- accommodation ---------------------------------------------------------------- */

void worldmodel_init(WorldModel *m)
{
	memset(m, 0, sizeof *m);
	m->grid = util_alloc((size_t)WORLDMODEL_SIDE * WORLDMODEL_SIDE, sizeof *m->grid);
	m->utak = vec2(0.5, 0.5);
	m->report.predicted = m->report.believed = m->utak;
	m->report.mismatch = m->report.best_mismatch = -1;
	wm_derive(m);
}

void worldmodel_free(WorldModel *m)
{
	free(m->grid);
	free(m->node);
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
	m->last = *imp;
	m->impressions = 1;
	wm_derive(m);
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
		if (m->holding) {
			to = vec2_add(from, vec2(cmd->dx, cmd->dy));
			held = util_alloc((size_t)m->held_count, sizeof *held);
			under = util_alloc((size_t)m->held_count, sizeof *under);
			wm_vacate(m, from, held);
		}
		break;
	case MOTOR_TURN:
		if (m->holding)
			wm_carry(m, from, to, cmd->deg);
		break;
	case MOTOR_GRASP:
		/* Granted when touch showed an object (the simulator's rule, paper 2.2). */
		wm_find_held(m, &m->last);
		m->holding = m->held_count > 0;
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
	WmSearch s = {m, imp, held, under, px, py, from, to, px, py, INFINITY, rep->mismatch};
	if (rep->compared >= WORLDMODEL_MIN_COMPARED)
		s.best_key = rep->mismatch;
	int32_t r = WORLDMODEL_DISPARITY_RADIUS;
	for (int32_t dy = r; dy >= -r; dy--)
		for (int32_t dx = -r; dx <= r; dx++)
			wm_try(&s, px + dx, py + dy);
	double len = hypot(to.x - from.x, to.y - from.y);
	for (double t = 0; t < len; t += WM_PATH_STEP) {
		Vec2 q = vec2_add(from, vec2_scale(vec2_sub(to, from), t / len));
		int32_t qx = (int32_t)floor(q.x), qy = (int32_t)floor(q.y);
		for (int32_t dy = 1; dy >= -1; dy--)
			for (int32_t dx = -1; dx <= 1; dx++)
				wm_try(&s, qx + dx, qy + dy);
	}
	rep->best_mismatch = s.best_score;
	if ((s.bx != px || s.by != py) &&
	    (rep->compared < WORLDMODEL_MIN_COMPARED ||
	     s.best_score + WORLDMODEL_DISPARITY_MARGIN < rep->mismatch)) {
		rep->corrected = true;
		m->utak = vec2_add(m->utak, vec2(s.bx - px, s.by - py));
	} else {
		rep->best_mismatch = rep->mismatch;
	}
	rep->believed = m->utak;

	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	if (held)
		wm_place(m, ux, uy, held, NULL);
	free(held);
	free(under);
	wm_observe(m, ux, uy, imp);
	if (held)
		wm_prune_held(m);
	m->last = *imp;
	m->impressions++;
	wm_derive(m);
}

/* ---- dump and validation --------------------------------------------------------- */

static const char *wm_belief_name(int b)
{
	return b == BELIEF_OCCUPIED ? "occupied" : b == BELIEF_FLOOR ? "floor" : "unknown";
}

static void wm_dump_node(const WorldModel *m, int32_t id, int depth, FILE *f)
{
	const ModelNode *n = &m->node[id];
	fprintf(f, "%*snode %d %s", 2 * depth, "", (int)id, n->name);
	if (n->kind == NODE_ORG) {
		fprintf(f, " at (%.2f, %.2f)\n", n->relation.x, n->relation.y);
	} else {
		fprintf(f,
		        "%s relation (%.2f, %.2f) rect (%.2f, %.2f)-(%.2f, %.2f) squares %d conf "
		        "%.2f\n",
		        n->held ? " held" : "", n->relation.x, n->relation.y, n->rect.lo.x,
		        n->rect.lo.y, n->rect.hi.x, n->rect.hi.y, (int)n->squares, n->conf);
		for (int32_t k = 0; k < n->ring_count; k++) {
			const ModelRing *r = &m->ring[n->first_ring + k];
			fprintf(f, "%*s%s %d vertices:\n", 2 * depth + 2, "",
			        r->hole ? "hole" : "boundary", (int)r->count);
			for (int32_t j = 0; j < r->count; j++) {
				const ModelVertex *v = &m->vertex[r->first + j];
				fprintf(f,
				        "%*s(%.2f, %.2f) conf %.2f, segment conf %.2f beyond %s\n",
				        2 * depth + 4, "", v->p.x, v->p.y, v->conf, v->seg_conf,
				        wm_belief_name(v->beyond));
			}
		}
	}
	for (int32_t s = n->first_son; s >= 0; s = m->node[s].next_sibling)
		wm_dump_node(m, s, depth + 1, f);
}

void worldmodel_dump(const WorldModel *m, FILE *f)
{
	const Accommodation *a = &m->report;
	fputs("world model: Utak's frame at the first impression (x right, y ahead = north), "
	      "unit one square, origin the lower-left corner of his first square\n",
	      f);
	fprintf(f, "impressions %d; Utak believed at (%.2f, %.2f)", (int)m->impressions, m->utak.x,
	        m->utak.y);
	fprintf(f, "%s%s\n", m->holding ? ", holding an object" : "",
	        m->clipped ? "; WARNING: impressions reached past the evidence window and were cut"
	                   : "");
	if (m->impressions > 1)
		fprintf(f,
		        "last accommodation: predicted (%.2f, %.2f), mismatch %.3f over %d cells; "
		        "%s (%.2f, "
		        "%.2f), mismatch %.3f; %d squares new, %d seen finer\n",
		        a->predicted.x, a->predicted.y, a->mismatch, (int)a->compared,
		        a->corrected ? "disparity: corrected to" : "kept", a->believed.x,
		        a->believed.y, a->best_mismatch, (int)a->new_squares,
		        (int)a->finer_squares);
	wm_dump_node(m, 0, 0, f);
	/* The belief map of the seen window. */
	int32_t ux, uy, x0 = m->seen_x0, y0 = m->seen_y0, x1 = m->seen_x1, y1 = m->seen_y1;
	worldmodel_utak_square(m, &ux, &uy);
	if (m->seen_count == 0) {
		fputs("belief map: nothing seen\n", f);
		return;
	}
	fprintf(
	    f,
	    "belief map x %d..%d, y %d..%d, north row first ('.' floor, '#' occupied, '?' unknown, "
	    "'@' Utak):\n",
	    (int)x0, (int)x1, (int)y0, (int)y1);
	for (int32_t y = y1; y >= y0; y--) {
		for (int32_t x = x0; x <= x1; x++) {
			Belief b = worldmodel_belief(m, x, y);
			fputc(x == ux && y == uy     ? '@'
			      : b == BELIEF_FLOOR    ? '.'
			      : b == BELIEF_OCCUPIED ? '#'
			                             : '?',
			      f);
		}
		fputc('\n', f);
	}
}

bool worldmodel_validate(const WorldModel *m, char *why, size_t size)
{
	if (m->node_count < 2 || m->node[0].kind != NODE_ORG || m->node[0].parent != -1 ||
	    m->node[1].kind != NODE_FLOOR || m->node[1].parent != 0) {
		snprintf(why, size, "the tree does not start $org -> $floor");
		return false;
	}
	for (int32_t id = 0; id < m->node_count; id++) {
		const ModelNode *n = &m->node[id];
		for (int32_t s = n->first_son; s >= 0; s = m->node[s].next_sibling)
			if (m->node[s].parent != id) {
				snprintf(why, size, "node %d lists son %d whose parent is %d",
				         (int)id, (int)s, (int)m->node[s].parent);
				return false;
			}
		if (id > 0 && n->parent < 0) {
			snprintf(why, size, "node %d has no parent", (int)id);
			return false;
		}
		for (int32_t k = 0; k < n->ring_count; k++) {
			const ModelRing *r = &m->ring[n->first_ring + k];
			if (r->count < 4) {
				snprintf(why, size, "node %d ring %d has %d vertices", (int)id,
				         (int)k, (int)r->count);
				return false;
			}
			for (int32_t j = 0; j < r->count; j++) {
				Vec2 a = m->vertex[r->first + j].p,
				     b = m->vertex[r->first + (j + 1) % r->count].p;
				bool axis = (a.x == b.x) != (a.y == b.y);
				bool inside = a.x >= n->rect.lo.x && a.x <= n->rect.hi.x &&
				              a.y >= n->rect.lo.y && a.y <= n->rect.hi.y;
				if (!axis || !inside) {
					snprintf(why, size, "node %d ring %d vertex %d: %s",
					         (int)id, (int)k, (int)j,
					         axis ? "outside the rectangle"
					              : "segment not axis-aligned");
					return false;
				}
			}
		}
	}
	return true;
}

bool worldmodel_ring_outlines_object(const WorldModel *m, int32_t r)
{
	const ModelRing *hole = &m->ring[r];
	if (!hole->hole)
		return false;
	for (int32_t n = 0; n < m->node_count; n++) {
		const ModelNode *node = &m->node[n];
		if (node->kind != NODE_OBJECT)
			continue;
		for (int32_t k = 0; k < node->ring_count; k++) {
			const ModelRing *o = &m->ring[node->first_ring + k];
			if (o == hole || o->count != hole->count)
				continue;
			int32_t found = 0;
			for (int32_t i = 0; i < hole->count; i++)
				for (int32_t j = 0; j < o->count; j++)
					if (m->vertex[hole->first + i].p.x == m->vertex[o->first + j].p.x &&
					    m->vertex[hole->first + i].p.y == m->vertex[o->first + j].p.y) {
						found++;
						break;
					}
			if (found == hole->count)
				return true;
		}
	}
	return false;
}
