/* modeltree.c - the tree of Utak's world model: $org -> $floor -> objects, derived from
 * the evidence grid after every impression (paper 3.3, 3.4.2, 3.4.3). CONTROLLER SIDE.
 *
 * ALGORITHM. $floor is the set of floor squares and each object a 4-connected set
 * of occupied squares all of whose neighbours are floor (the isolated objects of
 * paper 3.4.2; sets touching the unknown may be verge or objects partly seen, and
 * stay part of $floor's boundary as NODE_UNCERTAIN, with the segments there marked
 * as bounded by the occupied or the unknown). Boundaries are traced along square
 * edges with the set on the left ("crack following" in digital topology), turning
 * left first at pinch points so that 4-connected sets stay apart, and merged into
 * maximal straight segments. A slanted edge therefore stays a staircase of unit
 * steps: exactly what the evidence says, never cutting into a square believed
 * occupied. An object keeps its number (ident) from one derivation to the next
 * while its rectangle overlaps the old one most (a held object compared relative
 * to Utak, since it moved with him).
 *
 * Here too, the model as utak --dump model prints it (worldmodel_dump: the last
 * accommodation, the tree, the belief map) and its checks (worldmodel_validate,
 * worldmodel_ring_outlines_object), declared in worldmodel.h.
 *
 * INVARIANTS: modeltree_validate. MEMORY: the tree's arrays, owned by the
 * WorldModel; a belief map of the seen window (one byte a square), labels and a
 * stack (four bytes each) for the derivation, freed after it. COMPLEXITY: O(A) for
 * a seen window of A squares. */
#include "utak/mind/modeltree.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"


/* The seen window, one square of margin round it, as a scratch belief map. */
typedef struct TreeMap {
	int32_t x0, y0, w, h; /* lower-left square and size */
	uint8_t *belief;      /* Belief, row-major */
} TreeMap;

static uint8_t tree_map_at(const TreeMap *map, int32_t x, int32_t y)
{
	x -= map->x0;
	y -= map->y0;
	if (x < 0 || y < 0 || x >= map->w || y >= map->h)
		return BELIEF_UNKNOWN;
	return map->belief[(int64_t)y * map->w + x];
}

static float tree_conf_at(const WorldModel *m, int32_t x, int32_t y)
{
	Evidence e = worldmodel_evidence(m, x, y);
	return e.res == WORLDMODEL_UNSEEN ? 0.0f : e.conf;
}

static int32_t tree_new_node(WorldModel *m, NodeKind kind, const char *name, int32_t parent)
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

static void tree_push_vertex(WorldModel *m, ModelVertex v)
{
	m->vertex = util_grow(m->vertex, &m->vertex_cap, m->vertex_count + 1, sizeof *m->vertex);
	m->vertex[m->vertex_count++] = v;
}

/* Directions of unit edges, counter-clockwise: a left turn is d + 1. */
enum { TREE_EAST, TREE_NORTH, TREE_WEST, TREE_SOUTH };
static const int8_t tree_step[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
/* The squares left (inside) and right (outside) of a unit edge leaving vertex
 * (x, y) in direction d, as offsets from (x, y). */
static const int8_t tree_inside[4][2] = {{0, 0}, {-1, 0}, {-1, -1}, {0, -1}};
static const int8_t tree_outside[4][2] = {{0, -1}, {0, 0}, {-1, 0}, {-1, -1}};

typedef struct TreeEdge {
	int32_t x, y; /* start vertex, $floor frame */
	uint8_t dir, beyond;
	float conf;
} TreeEdge;

/* tree_trace(m, map, in, node): the boundary rings of the set of squares where
 * in[] (over map's window) is set, appended to node. */
static void tree_trace(WorldModel *m, const TreeMap *map, const uint8_t *in, int32_t node)
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
	TreeEdge *edges = util_alloc((size_t)edge_total + 1, sizeof *edges);
	for (int32_t v0 = 0; v0 < vw * vh; v0++)
		for (int d0 = 0; d0 < 4; d0++) {
			if (!(out[v0] & (1u << d0)))
				continue;
			int32_t n = 0, vx = v0 % vw, vy = v0 / vw, d = d0;
			for (;;) {
				out[(int64_t)vy * vw + vx] &= (uint8_t) ~(1u << d);
				int32_t gx = vx + map->x0, gy = vy + map->y0; /* $floor frame */
				int32_t ox = gx + tree_outside[d][0], oy = gy + tree_outside[d][1];
				int32_t ix = gx + tree_inside[d][0], iy = gy + tree_inside[d][1];
				edges[n++] =
				    (TreeEdge){gx, gy, (uint8_t)d, tree_map_at(map, ox, oy),
				             (tree_conf_at(m, ix, iy) + tree_conf_at(m, ox, oy)) / 2};
				vx += tree_step[d][0];
				vy += tree_step[d][1];
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
				const TreeEdge *e = &edges[(s0 + j) % n];
				area2 += (double)e->x * tree_step[e->dir][1] -
				         (double)e->y * tree_step[e->dir][0];
			}
			for (int32_t j = 0; j < n;) {
				const TreeEdge *e = &edges[(s0 + j) % n];
				int32_t len = 0;
				double conf = 0;
				while (j + len < n && edges[(s0 + j + len) % n].dir == e->dir &&
				       edges[(s0 + j + len) % n].beyond == e->beyond) {
					conf += edges[(s0 + j + len) % n].conf;
					len++;
				}
				float corner =
				    (tree_conf_at(m, e->x, e->y) + tree_conf_at(m, e->x - 1, e->y) +
				     tree_conf_at(m, e->x, e->y - 1) +
				     tree_conf_at(m, e->x - 1, e->y - 1)) /
				    4;
				tree_push_vertex(m, (ModelVertex){vec2(e->x, e->y), corner,
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

/* tree_finish_node(m, node, map, in): rectangle, squares and confidence of a node
 * whose set of squares is in[]. */
static void tree_finish_node(WorldModel *m, int32_t node, const TreeMap *map, const uint8_t *in)
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
				conf += tree_conf_at(m, gx, gy);
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
typedef struct TreePrevious {
	int32_t ident;
	Box rect; /* $floor frame; for a held object, relative to Utak's point */
	bool held, used;
} TreePrevious;

static double tree_overlap(Box a, Box b)
{
	double w = fmin(a.hi.x, b.hi.x) - fmax(a.lo.x, b.lo.x),
	       h = fmin(a.hi.y, b.hi.y) - fmax(a.lo.y, b.lo.y);
	return w > 0 && h > 0 ? w * h : 0;
}

static Box tree_box_shift(Box b, Vec2 d)
{
	return (Box){vec2_add(b.lo, d), vec2_add(b.hi, d)};
}

/* tree_name_object(m, node, prev, nprev): gives the node the number of the previous
 * object whose rectangle overlaps its own most (a held object compared relative
 * to Utak, since it moved with him), or a new number. */
static void tree_name_object(WorldModel *m, int32_t node, TreePrevious *prev, int32_t nprev,
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
			mine = tree_box_shift(mine, vec2_scale(m->utak, -1));
			theirs = tree_box_shift(theirs, vec2_scale(prev_utak, -1));
		}
		double area = tree_overlap(mine, theirs);
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

/* modeltree_derive(m): the tree of paper 3.3 from the evidence grid (modeltree.h). */
void modeltree_derive(WorldModel *m)
{
	int32_t nprev = 0;
	TreePrevious *prev = util_alloc((size_t)m->node_count + 1, sizeof *prev);
	Vec2 prev_utak = m->node_count > 0 ? m->node[0].relation : m->utak;
	for (int32_t id = 0; id < m->node_count; id++)
		if (m->node[id].kind == NODE_OBJECT)
			prev[nprev++] = (TreePrevious){m->node[id].ident, m->node[id].rect,
			                             m->node[id].held, false};
	m->node_count = m->ring_count = m->vertex_count = 0;
	int32_t org = tree_new_node(m, NODE_ORG, "$org", -1);
	m->node[org].relation = m->utak;
	int32_t floor_node = tree_new_node(m, NODE_FLOOR, "$floor", org);
	m->node[floor_node].relation = vec2_scale(m->utak, -1);

	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
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
			tree_push_vertex(m, (ModelVertex){corner[k], 0, 0, BELIEF_UNKNOWN});
		m->ring_count = 1;
		f->ring_count = 1;
		free(prev);
		return;
	}
	TreeMap map = {x0 - 1, y0 - 1, x1 - x0 + 3, y1 - y0 + 3, NULL};
	size_t area = (size_t)map.w * (size_t)map.h;
	map.belief = util_alloc(area, 1);
	for (int32_t y = 0; y < map.h; y++)
		for (int32_t x = 0; x < map.w; x++)
			map.belief[(int64_t)y * map.w + x] =
			    (uint8_t)worldmodel_belief(m, x + map.x0, y + map.y0);
	uint8_t *in = util_alloc(area, 1);
	for (size_t k = 0; k < area; k++)
		in[k] = map.belief[k] == BELIEF_FLOOR;
	tree_trace(m, &map, in, floor_node);
	tree_finish_node(m, floor_node, &map, in);
	m->node[floor_node].relation = vec2_scale(m->utak, -1); /* $floor's origin seen from Utak */

	/* Objects: 4-connected occupied sets, every neighbour floor. */
	int32_t *label = util_alloc(area, sizeof *label);
	int32_t *stack = util_alloc(area, sizeof *stack);
	int32_t labels = 0, uncertain = 0, comp_cap = 0;
	int32_t *comp_node = NULL; /* a component's node, by label */
	for (int32_t row = map.h - 1; row >= 0; row--) /* north first: the order of the map */
		for (int32_t col = 0; col < map.w; col++) {
			int64_t k0 = (int64_t)row * map.w + col;
			if (map.belief[k0] != BELIEF_OCCUPIED || label[k0])
				continue;
			int32_t id = ++labels, top = 0;
			comp_node = util_grow(comp_node, &comp_cap, id + 1, sizeof *comp_node);
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
					int32_t nx = x + tree_step[d][0], ny = y + tree_step[d][1];
					uint8_t b = tree_map_at(&map, nx + map.x0, ny + map.y0);
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
				int32_t node = tree_new_node(m, NODE_UNCERTAIN, name, floor_node);
				tree_finish_node(m, node, &map, in);
				comp_node[id] = node;
				continue;
			}
			int32_t node =
			    tree_new_node(m, NODE_OBJECT, "object", held ? org : floor_node);
			comp_node[id] = node;
			tree_trace(m, &map, in, node);
			tree_finish_node(m, node, &map, in);
			m->node[node].held = held;
			tree_name_object(m, node, prev, nprev, prev_utak);
			if (held) /* relation to $org: offset from Utak's point */
				m->node[node].relation = vec2_sub(m->node[node].rect.lo, m->utak);
		}
	/* Which node holds each occupied square: the label map, renumbered. */
	for (size_t k = 0; k < area; k++)
		label[k] = label[k] ? comp_node[label[k]] : -1;
	free(m->node_at);
	m->node_at = label;
	m->node_at_x0 = map.x0;
	m->node_at_y0 = map.y0;
	m->node_at_w = map.w;
	m->node_at_h = map.h;
	free(comp_node);
	free(stack);
	free(in);
	free(map.belief);
	free(prev);
}


/* ---- dump and validation --------------------------------------------------------- */

static const char *tree_belief_name(int b)
{
	return b == BELIEF_OCCUPIED ? "occupied" : b == BELIEF_FLOOR ? "floor" : "unknown";
}

void modeltree_dump(const WorldModel *m, int32_t id, int depth, FILE *f)
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
				        tree_belief_name(v->beyond));
			}
		}
	}
	for (int32_t s = n->first_son; s >= 0; s = m->node[s].next_sibling)
		modeltree_dump(m, s, depth + 1, f);
}

bool modeltree_validate(const WorldModel *m, char *why, size_t size)
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

/* ---- the model printed and checked (moved from worldmodel.c, which had passed
 * 1,000 lines; declared in worldmodel.h) ------------------------------------------ */

void worldmodel_dump(const WorldModel *m, FILE *f)
{
	const Accommodation *a = &m->report;
	fputs("world model: Utak's frame at the first impression (x right, y ahead = north), "
	      "unit one square, origin the lower-left corner of his first square\n",
	      f);
	fprintf(f, "impressions %d; Utak believed at (%.2f, %.2f)", (int)m->impressions, m->utak.x,
	        m->utak.y);
	fprintf(f, "%s%s\n", m->holding ? ", holding an object" : "",
	        m->clipped ? "; WARNING: impressions reached past the model's reach and were cut"
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
	modeltree_dump(m, 0, 0, f);
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
	return modeltree_validate(m, why, size);
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
