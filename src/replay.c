/* replay.c - a recording of a run, replayed cycle by cycle in a browser (see replay.h).
 * Not from the paper: it shows the paper's action cycle (3.1, steps 8-13) turn by
 * turn, with the TABLE (Figure 1), the retinal impression (Figure 2), the world model
 * (3.3) and the skeleton and pathgraph of the screen (Figure 3).
 *
 * ALGORITHM. Each hook appends to the recording what changed since the frame before,
 * as JSON text: the TABLE only inside the box of the objects that moved (their
 * polygons are compared with the last frame's), the belief map only where a square's
 * code differs from the one kept for it (a byte per evidence square), the world
 * model's tree and the screen only when their text differs from the last frame's,
 * and a plan only when the controller has run its planner again (plans_made). The
 * viewer (replay.html) rebuilds any frame by applying the changes in order.
 *
 * MEMORY: the recording's text, WORLDMODEL_SIDE^2 bytes of belief codes, the objects'
 * polygons. COMPLEXITY: a frame costs the area of the seen window (the belief scan),
 * the area of the screen, and the box of the objects that moved; never the TABLE's. */
#include "utak/replay.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/eye.h"
#include "utak/base/util.h"
#include "utak/mind/carrytask.h"
#include "utak/mind/screen.h"
#include "utak/mind/worldmodel.h"

/* The viewer, compiled in from src/replay.html (the Makefile turns its lines into
 * C strings): replay_viewer[] ends with NULL; the data goes in place of the line
 * REPLAY_DATA_MARK. */
static const char *const replay_viewer[] = {
#include "replay_viewer.inc"
    NULL,
};
#define REPLAY_DATA_MARK "@UTAK_REPLAY_DATA@"

/* Unchanged squares between two changed ones of a belief row are written out too
 * when there are at most this many: one [y, x, codes] entry costs about as much. */
#define REPLAY_BELIEF_GAP 6

enum { REPLAY_HALF = WORLDMODEL_SIDE / 2 };

/* ---- text ------------------------------------------------------------------------ */

/* A growing string: the recording is kept as the JSON it will be written as. */
typedef struct Text {
	char *s;
	int len, cap;
} Text;

static void text_reserve(Text *t, int more)
{
	t->s = util_grow(t->s, &t->cap, t->len + more + 1, 1);
}

static void text_add(Text *t, const char *s, int n)
{
	text_reserve(t, n);
	if (n > 0) /* s may be an empty Text's NULL */
		memcpy(t->s + t->len, s, (size_t)n);
	t->len += n;
	t->s[t->len] = 0;
}

static void text_puts(Text *t, const char *s)
{
	text_add(t, s, (int)strlen(s));
}

static void text_putc(Text *t, char c)
{
	text_add(t, &c, 1);
}

static void text_printf(Text *t, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	int n = vsnprintf(NULL, 0, fmt, ap);
	va_end(ap);
	text_reserve(t, n);
	va_start(ap, fmt);
	vsnprintf(t->s + t->len, (size_t)n + 1, fmt, ap);
	va_end(ap);
	t->len += n;
}

static void text_clear(Text *t)
{
	t->len = 0;
	if (t->s)
		t->s[0] = 0;
}

static void text_free(Text *t)
{
	free(t->s);
	*t = (Text){0};
}

/* text_num(t, v): v with at most 2 decimals and no trailing zeros ("-0" as "0"):
 * every coordinate recorded is a multiple of 1/2 or a confidence, and the page is
 * smaller and its diffs quieter without "13.50". */
static void text_num(Text *t, double v)
{
	char buf[64];
	snprintf(buf, sizeof buf, "%.2f", isfinite(v) ? v : 0.0);
	char *end = buf + strlen(buf);
	while (end[-1] == '0')
		*--end = 0;
	if (end[-1] == '.')
		*--end = 0;
	text_puts(t, strcmp(buf, "-0") == 0 ? "0" : buf);
}

static void text_point(Text *t, Vec2 p)
{
	text_putc(t, '[');
	text_num(t, p.x);
	text_putc(t, ',');
	text_num(t, p.y);
	text_putc(t, ']');
}

/* text_pose(t, p, theta): a carried object's pose, [x, y, theta in degrees]. */
static void text_pose(Text *t, Vec2 p, double theta)
{
	text_putc(t, '[');
	text_num(t, p.x);
	text_putc(t, ',');
	text_num(t, p.y);
	text_putc(t, ',');
	text_num(t, theta);
	text_putc(t, ']');
}

/* text_string(t, s): s as a JSON string. '<', '>' and '&' are escaped too, so that
 * nothing in the data can close the <script> element that holds it. */
static void text_string(Text *t, const char *s)
{
	text_putc(t, '"');
	for (; *s; s++) {
		unsigned char c = (unsigned char)*s;
		if (c == '"' || c == '\\')
			text_printf(t, "\\%c", c);
		else if (c < 0x20 || c == '<' || c == '>' || c == '&' || c >= 0x7f)
			text_printf(t, "\\u%04x", c);
		else
			text_putc(t, (char)c);
	}
	text_putc(t, '"');
}

/* text_run(t, c, n): n squares of code c, as RUNS (replay.h). */
static void text_run(Text *t, char c, int64_t n)
{
	text_putc(t, c);
	if (n > 1)
		text_printf(t, "%lld", (long long)n);
}

/* ---- the recording ---------------------------------------------------------------- */

/* A node of the world model as written (node_text): the whole of it, and its rings'
 * vertices one by one, so that the next frame can write a ring that changed only in
 * part as a splice of this one (replay.h, model). */
typedef struct NodeText {
	Text s;      /* the node as JSON */
	Text head;   /* s up to its rings */
	int kind, ident;
	Text verts;  /* the written rings' vertices' texts, one after another */
	int *start;  /* vertex v's text is verts[start[v] .. start[v + 1]) */
	int start_cap;
	int *first;  /* ring k's vertices are first[k] .. first[k + 1] - 1 */
	int first_cap, rings;
	Text beyond; /* a character per vertex (replay.h, model) */
	Text hole;   /* a character per ring: 't' a hole, 'f' not */
} NodeText;

static void node_text_free(NodeText *nt)
{
	text_free(&nt->s);
	text_free(&nt->head);
	text_free(&nt->verts);
	text_free(&nt->beyond);
	text_free(&nt->hole);
	free(nt->start);
	free(nt->first);
}

struct Replay {
	Text head;   /* the fields known at the start */
	Text frames; /* the frames so far, each ending with ",\n" */
	Text plans;  /* the plans so far, likewise */
	int frame_count, plan_count;
	int plans_seen; /* the controller's plans_made when the last plan was recorded */
	bool act;       /* an --act run: no task, no plans */
	/* What the last frame showed, to record only changes. */
	char *belief;                               /* WORLDMODEL_SIDE^2 codes, '?' until seen */
	int32_t scan_x0, scan_y0, scan_x1, scan_y1; /* squares scanned so far (inclusive) */
	bool scanned;
	Polygon *shapes; /* each object's polygon */
	int32_t object_count;
	Text last_model, last_screen, part, part2;
	/* The world model's nodes as text, this frame's and the last's. */
	NodeText *nodes_now, *nodes_before;
	int nodes_now_cap, nodes_before_cap, nodes_before_count;
	/* The decision of the cycle being recorded (replay_decided). */
	char decided[96];
	/* The model squares every frame drew (replay.h, view), inclusive. */
	int32_t view_x0, view_y0, view_x1, view_y1;
	bool have_view;
};

static void view_add(Replay *r, int32_t x0, int32_t y0, int32_t x1, int32_t y1)
{
	if (!r->have_view) {
		r->view_x0 = x0, r->view_y0 = y0, r->view_x1 = x1, r->view_y1 = y1;
		r->have_view = true;
		return;
	}
	r->view_x0 = x0 < r->view_x0 ? x0 : r->view_x0;
	r->view_y0 = y0 < r->view_y0 ? y0 : r->view_y0;
	r->view_x1 = x1 > r->view_x1 ? x1 : r->view_x1;
	r->view_y1 = y1 > r->view_y1 ? y1 : r->view_y1;
}

/* The TABLE square's code: '.' floor, 'B' verge, the object's colour letter. */
static char table_code(const World *w, const Table *t, int32_t x, int32_t y)
{
	int32_t who = table_owner(t, x, y);
	return who == TABLE_FLOOR ? '.' : who == TABLE_VERGE ? 'B' : w->objects[who - 1].colour;
}

/* table_runs(t, w, tab, x0, y0, x1, y1): the squares of the box (x1, y1 exclusive)
 * as RUNS. */
static void table_runs(Text *t, const World *w, const Table *tab, int32_t x0, int32_t y0,
                       int32_t x1, int32_t y1)
{
	char cur = 0;
	int64_t n = 0;
	for (int32_t y = y0; y < y1; y++)
		for (int32_t x = x0; x < x1; x++) {
			char c = table_code(w, tab, x, y);
			if (c != cur && n > 0) {
				text_run(t, cur, n);
				n = 0;
			}
			cur = c;
			n++;
		}
	if (n > 0)
		text_run(t, cur, n);
}

static const char *phase_name(ControllerPhase p)
{
	static const char *const names[] = {"travel",  "grasp", "push",  "seat",
	                                    "release", "done",  "failed"};
	return (unsigned)p < sizeof names / sizeof names[0] ? names[p] : "?";
}

Replay *replay_new(const World *w, const Table *t, const char *task, const char *planner)
{
	Replay *r = util_alloc(1, sizeof *r);
	r->act = task == NULL;
	r->belief = util_alloc((size_t)WORLDMODEL_SIDE * WORLDMODEL_SIDE, 1);
	memset(r->belief, '?', (size_t)WORLDMODEL_SIDE * WORLDMODEL_SIDE);
	r->object_count = w->object_count;
	r->shapes = util_alloc((size_t)w->object_count + 1, sizeof *r->shapes);
	for (int32_t k = 0; k < w->object_count; k++)
		r->shapes[k] = w->objects[k].shape;
	r->plans_seen = 0;
	Text *h = &r->head;
	text_puts(h, "{\"format\": \"utak-replay 1\",\n\"world\": ");
	text_string(h, w->file);
	text_puts(h, ",\n\"task\": ");
	if (task)
		text_string(h, task);
	else
		text_puts(h, "null");
	text_puts(h, ",\n\"planner\": ");
	text_string(h, planner);
	text_printf(h, ",\n\"table\": {\"w\": %d, \"h\": %d, \"runs\": \"", (int)t->w, (int)t->h);
	table_runs(h, w, t, 0, 0, t->w, t->h);
	text_puts(h, "\"},\n\"objects\": [");
	for (int32_t k = 0; k < w->object_count; k++) {
		text_puts(h, k ? ", {\"name\": " : "{\"name\": ");
		text_string(h, w->objects[k].name);
		text_printf(h, ", \"colour\": \"%c\"}", w->objects[k].colour);
	}
	text_printf(h, "],\n\"heading\": \"%s\",\n", world_heading_name(w->heading));
	text_printf(h, "\"origin\": [%d, %d],\n\"eye\": [", (int)floor(w->utak.x),
	            (int)floor(w->utak.y));
	for (int32_t i = 0; i < RETINA_CELLS; i++) {
		EyeCell e = eye_cell(i);
		text_printf(h, "%s[%d,%d,%d]", i ? "," : "", e.ox, e.oy, e.size);
	}
	text_puts(h, "],\n");
	return r;
}

void replay_free(Replay *r)
{
	if (!r)
		return;
	text_free(&r->head);
	text_free(&r->frames);
	text_free(&r->plans);
	text_free(&r->last_model);
	text_free(&r->last_screen);
	text_free(&r->part);
	text_free(&r->part2);
	for (int i = 0; i < r->nodes_now_cap; i++)
		node_text_free(&r->nodes_now[i]);
	for (int i = 0; i < r->nodes_before_cap; i++)
		node_text_free(&r->nodes_before[i]);
	free(r->nodes_now);
	free(r->nodes_before);
	free(r->belief);
	free(r->shapes);
	free(r);
}

/* ---- plans ------------------------------------------------------------------------- */

static const char step_letter[4] = {'n', 'e', 's', 'w'};

/* plan_edge_steps(t, pg, e): the edge's chain from its first cell, one letter a step. */
static void plan_edge_steps(Text *t, const Pathgraph *pg, const PathgraphEdge *e)
{
	for (int32_t k = 1; k < e->count; k++) {
		int32_t a = pg->cells[e->first + k - 1], b = pg->cells[e->first + k];
		int32_t dx = b % pg->w - a % pg->w, dy = b / pg->w - a / pg->w;
		int d = dy == 1 ? 0 : dx == 1 ? 1 : dy == -1 ? 2 : 3;
		text_putc(t, step_letter[d]);
	}
}

static void plan_path(Text *t, const Path *p, Vec2 origin)
{
	text_putc(t, '[');
	for (int i = 0; i < p->count; i++) {
		if (i)
			text_putc(t, ',');
		text_point(t, vec2_add(p->pts[i], origin));
	}
	text_putc(t, ']');
}

/* record_plan(r, c, step): the controller's last plan, if it has made one since the
 * last recorded. */
static void record_plan(Replay *r, const Controller *c, const char *step, int cycle)
{
	if (r->act || c->plans_made == r->plans_seen)
		return;
	r->plans_seen = c->plans_made;
	const Planner *p = &c->planner;
	Text *t = &r->plans;
	Vec2 origin = vec2(c->plan_x0, c->plan_y0);
	text_printf(t,
	            "{\"cycle\": %d, \"step\": \"%s\", \"planner\": \"%s\", \"x0\": %d, \"y0\": "
	            "%d, \"w\": %d, \"h\": %d",
	            cycle, step, planner_name(p->kind), (int)c->plan_x0, (int)c->plan_y0,
	            (int)p->grid.w, (int)p->grid.h);
	text_printf(t, ", \"ok\": %s, \"exploring\": %s, \"goal\": ",
	            p->found.count > 0 ? "true" : "false", c->exploring ? "true" : "false");
	text_point(t, c->goal);
	view_add(r, c->plan_x0, c->plan_y0, c->plan_x0 + p->grid.w - 1, c->plan_y0 + p->grid.h - 1);
	if (p->have_graph && p->skeleton.w == p->grid.w && p->skeleton.h == p->grid.h) {
		const Pathgraph *pg = &p->pathgraph;
		static const char kind_letter[] = {'j', 'e', 'l', 'p'};
		/* The skeleton is the edges' cells and the vertices' cells, and the few
		 * cells of junction sets that no edge passes through: those are listed. */
		const Skeleton *s = &p->skeleton;
		uint8_t *covered = util_alloc((size_t)s->w * (size_t)s->h, 1);
		for (int32_t k = 0; k < pg->cell_count; k++)
			covered[pg->cells[k]] = 1;
		for (int32_t v = 0; v < pg->vertex_count; v++)
			covered[pg->vertices[v].y * s->w + pg->vertices[v].x] = 1;
		text_puts(t, ",\n  \"skeleton_more\": [");
		bool first = true;
		for (int32_t j = 0; j < s->h; j++)
			for (int32_t i = 0; i < s->w; i++)
				if (skeleton_on(s, i, j) && !covered[j * s->w + i]) {
					text_printf(t, "%s[%d,%d]", first ? "" : ",", (int)i,
					            (int)j);
					first = false;
				}
		free(covered);
		text_puts(t, "],\n  \"vertices\": [");
		for (int32_t v = 0; v < pg->vertex_count; v++)
			text_printf(t, "%s[%d,%d,\"%c\"]", v ? "," : "", (int)pg->vertices[v].x,
			            (int)pg->vertices[v].y, kind_letter[pg->vertices[v].kind & 3]);
		text_puts(t, "],\n  \"edges\": [");
		for (int32_t k = 0; k < pg->edge_count; k++) {
			const PathgraphEdge *e = &pg->edges[k];
			int32_t c0 = pg->cells[e->first];
			text_printf(t, "%s[%d,%d,%d,%d,\"", k ? "," : "", (int)e->v0, (int)e->v1,
			            (int)(c0 % pg->w), (int)(c0 / pg->w));
			plan_edge_steps(t, pg, e);
			text_puts(t, "\"]");
		}
		text_putc(t, ']');
	}
	text_puts(t, ",\n  \"found\": ");
	plan_path(t, &p->found, origin);
	text_puts(t, ", \"found_length\": ");
	text_num(t, p->found_length);
	text_puts(t, ",\n  \"taut\": ");
	plan_path(t, &p->taut, origin);
	text_puts(t, ", \"taut_length\": ");
	text_num(t, p->taut_length);
	text_printf(t, ", \"expanded\": %lld", (long long)p->expanded);
	/* A plan that found no path leaves the route of the one before: not this plan's. */
	text_puts(t, ",\n  \"route\": ");
	if (p->found.count > 0)
		plan_path(t, &c->route, vec2(0, 0));
	else
		text_puts(t, "[]");
	text_puts(t, "},\n");
	r->plan_count++;
}

/* ---- frames ------------------------------------------------------------------------- */

/* belief_code(m, x, y): the square's code (replay.h, belief). */
static char belief_code(const WorldModel *m, int32_t x, int32_t y)
{
	Belief b = worldmodel_belief(m, x, y);
	if (b == BELIEF_UNKNOWN)
		return '?';
	Evidence e = worldmodel_evidence(m, x, y);
	return (b == BELIEF_FLOOR ? "upif" : "UPIF")[e.res & 3];
}

/* record_belief(r, t, m): the squares whose code changed, scanning the squares ever
 * seen and Utak's own (every change lies there), and those scanned before (a square
 * that was Utak's goes back to unknown when it was never seen). */
static void record_belief(Replay *r, Text *t, const WorldModel *m)
{
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	int32_t x0 = ux, y0 = uy, x1 = ux, y1 = uy;
	if (m->seen_count > 0) {
		x0 = m->seen_x0 < x0 ? m->seen_x0 : x0;
		y0 = m->seen_y0 < y0 ? m->seen_y0 : y0;
		x1 = m->seen_x1 > x1 ? m->seen_x1 : x1;
		y1 = m->seen_y1 > y1 ? m->seen_y1 : y1;
	}
	if (r->scanned) {
		x0 = r->scan_x0 < x0 ? r->scan_x0 : x0;
		y0 = r->scan_y0 < y0 ? r->scan_y0 : y0;
		x1 = r->scan_x1 > x1 ? r->scan_x1 : x1;
		y1 = r->scan_y1 > y1 ? r->scan_y1 : y1;
	}
	/* The evidence window bounds what the model can hold. */
	x0 = x0 < -REPLAY_HALF ? -REPLAY_HALF : x0;
	y0 = y0 < -REPLAY_HALF ? -REPLAY_HALF : y0;
	x1 = x1 > REPLAY_HALF - 1 ? REPLAY_HALF - 1 : x1;
	y1 = y1 > REPLAY_HALF - 1 ? REPLAY_HALF - 1 : y1;
	r->scan_x0 = x0, r->scan_y0 = y0, r->scan_x1 = x1, r->scan_y1 = y1;
	r->scanned = true;
	view_add(r, x0, y0, x1, y1);
	text_puts(t, ",\n \"belief\": [");
	bool first = true;
	char *row_codes = util_alloc((size_t)(x1 - x0 + 1), 1);
	for (int32_t y = y0; y <= y1; y++) {
		char *old = r->belief + (size_t)(y + REPLAY_HALF) * WORLDMODEL_SIDE + REPLAY_HALF;
		for (int32_t x = x0; x <= x1; x++)
			row_codes[x - x0] = belief_code(m, x, y);
		for (int32_t x = x0; x <= x1;) {
			if (row_codes[x - x0] == old[x]) {
				x++;
				continue;
			}
			/* A run of changes, joined across short gaps. */
			int32_t end = x + 1, gap = 0;
			for (int32_t k = x + 1; k <= x1 && gap <= REPLAY_BELIEF_GAP; k++) {
				if (row_codes[k - x0] != old[k]) {
					end = k + 1;
					gap = 0;
				} else {
					gap++;
				}
			}
			text_printf(t, "%s[%d,%d,\"", first ? "" : ",", (int)y, (int)x);
			text_add(t, row_codes + (x - x0), end - x);
			text_puts(t, "\"]");
			memcpy(old + x, row_codes + (x - x0), (size_t)(end - x));
			first = false;
			x = end;
		}
	}
	free(row_codes);
	text_putc(t, ']');
}

static const char *node_kind(NodeKind k)
{
	return k == NODE_FLOOR       ? "floor"
	       : k == NODE_OBJECT    ? "object"
	       : k == NODE_UNCERTAIN ? "uncertain"
	                             : "org";
}

/* node_text(nt, m, node): one node of the tree with its rings (worldmodel.h), into
 * nt. A node's confidence to 2 decimals, a segment's to 1: it is drawn, not read.
 * $floor's holes that are objects' outlines are left out: the objects' rings are
 * the same. */
static void node_text(NodeText *nt, const WorldModel *m, const ModelNode *node)
{
	Text *t = &nt->head;
	text_clear(t);
	text_clear(&nt->s);
	text_clear(&nt->verts);
	text_clear(&nt->beyond);
	text_clear(&nt->hole);
	nt->kind = (int)node->kind, nt->ident = (int)node->ident, nt->rings = 0;
	text_puts(t, "{\"kind\": ");
	text_string(t, node_kind(node->kind));
	text_puts(t, ", \"name\": ");
	text_string(t, node->name);
	text_printf(t,
	            ", \"ident\": %d, \"held\": %s, \"squares\": %d, \"conf\": ", (int)node->ident,
	            node->held ? "true" : "false", (int)node->squares);
	text_num(t, node->conf);
	text_puts(t, ", \"rect\": [");
	text_num(t, node->rect.lo.x);
	text_putc(t, ',');
	text_num(t, node->rect.lo.y);
	text_putc(t, ',');
	text_num(t, node->rect.hi.x);
	text_putc(t, ',');
	text_num(t, node->rect.hi.y);
	text_puts(t, "]");
	int nv = 0;
	for (int32_t k = 0; k < node->ring_count; k++) {
		const ModelRing *ring = &m->ring[node->first_ring + k];
		if (node->kind == NODE_FLOOR &&
		    worldmodel_ring_outlines_object(m, node->first_ring + k))
			continue;
		nt->first = util_grow(nt->first, &nt->first_cap, nt->rings + 2, sizeof *nt->first);
		nt->first[nt->rings++] = nv;
		text_putc(&nt->hole, ring->hole ? 't' : 'f');
		for (int32_t i = 0; i < ring->count; i++) {
			const ModelVertex *v = &m->vertex[ring->first + i];
			nt->start = util_grow(nt->start, &nt->start_cap, nv + 2, sizeof *nt->start);
			nt->start[nv++] = nt->verts.len;
			text_putc(&nt->verts, '[');
			text_num(&nt->verts, v->p.x);
			text_putc(&nt->verts, ',');
			text_num(&nt->verts, v->p.y);
			text_printf(&nt->verts, ",%.1f]", v->seg_conf);
			uint8_t b = v->beyond;
			text_putc(&nt->beyond, b == BELIEF_OCCUPIED ? 'o' : b == BELIEF_UNKNOWN ? 'u' : 'f');
		}
	}
	nt->first = util_grow(nt->first, &nt->first_cap, nt->rings + 2, sizeof *nt->first);
	nt->first[nt->rings] = nv;
	nt->start = util_grow(nt->start, &nt->start_cap, nv + 2, sizeof *nt->start);
	nt->start[nv] = nt->verts.len;
	/* The whole node: its head, then each ring in full. */
	text_add(&nt->s, nt->head.s, nt->head.len);
	text_puts(&nt->s, ", \"rings\": [");
	for (int k = 0; k < nt->rings; k++) {
		int a = nt->first[k], b = nt->first[k + 1];
		text_printf(&nt->s, "%s{\"hole\": %s, \"v\": [", k ? ", " : "",
		            nt->hole.s[k] == 't' ? "true" : "false");
		for (int v = a; v < b; v++) {
			if (v > a)
				text_putc(&nt->s, ',');
			text_add(&nt->s, nt->verts.s + nt->start[v], nt->start[v + 1] - nt->start[v]);
		}
		text_puts(&nt->s, "], \"beyond\": \"");
		text_add(&nt->s, nt->beyond.s + a, b - a);
		text_puts(&nt->s, "\"}");
	}
	text_puts(&nt->s, "]}");
}

/* same_vertex(x, v, y, w): vertex v of node x is written as vertex w of node y. */
static bool same_vertex(const NodeText *x, int v, const NodeText *y, int w)
{
	int n = x->start[v + 1] - x->start[v];
	return n == y->start[w + 1] - y->start[w] && x->beyond.s[v] == y->beyond.s[w] &&
	       memcmp(x->verts.s + x->start[v], y->verts.s + y->start[w], (size_t)n) == 0;
}

/* node_splice(t, nt, like, j): node nt written against node j of the frame before
 * (like, the same object): "like": j, and each ring k that both have as "from": [k,
 * p, q], its first p and last q vertices being like's ring k's, the rest in "v" and
 * "beyond" (replay.h, model). Exploring, the floor's outline grows by a few vertices
 * a cycle: this keeps its cost to what changed. */
static void node_splice(Text *t, const NodeText *nt, const NodeText *like, int j)
{
	text_add(t, nt->head.s, nt->head.len);
	text_printf(t, ", \"like\": %d, \"rings\": [", j);
	for (int k = 0; k < nt->rings; k++) {
		int a = nt->first[k], b = nt->first[k + 1], p = 0, q = 0;
		text_printf(t, "%s{\"hole\": %s, ", k ? ", " : "", nt->hole.s[k] == 't' ? "true" : "false");
		if (k < like->rings) {
			int la = like->first[k], lb = like->first[k + 1];
			while (a + p < b && la + p < lb && same_vertex(nt, a + p, like, la + p))
				p++;
			while (a + p + q < b && la + p + q < lb && same_vertex(nt, b - 1 - q, like, lb - 1 - q))
				q++;
			text_printf(t, "\"from\": [%d, %d, %d], ", k, p, q);
		}
		text_puts(t, "\"v\": [");
		for (int v = a + p; v < b - q; v++) {
			if (v > a + p)
				text_putc(t, ',');
			text_add(t, nt->verts.s + nt->start[v], nt->start[v + 1] - nt->start[v]);
		}
		text_puts(t, "], \"beyond\": \"");
		text_add(t, nt->beyond.s + a + p, b - q - (a + p));
		text_puts(t, "\"}");
	}
	text_puts(t, "]}");
}

/* record_model(r, t, m): Utak's believed point, the last accommodation, and the
 * nodes below $org, when any of it changed since the last frame. A node the same as
 * in the last frame is written as its index there. */
static void record_model(Replay *r, Text *t, const WorldModel *m)
{
	const Accommodation *a = &m->report;
	Text *head = &r->part;
	text_clear(head);
	text_puts(head, "{\"utak\": ");
	text_point(head, m->utak);
	text_puts(head, ", \"predicted\": ");
	text_point(head, a->predicted);
	text_puts(head, ", \"mismatch\": ");
	text_num(head, a->mismatch);
	text_puts(head, ", \"best_mismatch\": ");
	text_num(head, a->best_mismatch);
	text_printf(
	    head, ", \"compared\": %d, \"corrected\": %s, \"new\": %d, \"finer\": %d, \"nodes\": [",
	    (int)a->compared, a->corrected ? "true" : "false", (int)a->new_squares,
	    (int)a->finer_squares);
	int count = 0;
	for (int32_t n = 0; n < m->node_count; n++)
		if (m->node[n].kind != NODE_ORG) {
			if (count == r->nodes_now_cap) {
				int old_cap = r->nodes_now_cap;
				r->nodes_now = util_grow(r->nodes_now, &r->nodes_now_cap, count + 1,
				                         sizeof *r->nodes_now);
				memset(r->nodes_now + old_cap, 0,
				       sizeof *r->nodes_now * (size_t)(r->nodes_now_cap - old_cap));
			}
			node_text(&r->nodes_now[count++], m, &m->node[n]);
		}
	bool same = r->frame_count > 0 && count == r->nodes_before_count &&
	            strcmp(head->s, r->last_model.s) == 0;
	for (int i = 0; same && i < count; i++)
		same = strcmp(r->nodes_now[i].s.s, r->nodes_before[i].s.s) == 0;
	if (!same) {
		text_puts(t, ",\n \"model\": ");
		text_add(t, head->s, head->len);
		for (int i = 0; i < count; i++) {
			const NodeText *now = &r->nodes_now[i];
			int before = -1, like = -1;
			for (int j = 0; j < r->nodes_before_count && before < 0; j++) {
				const NodeText *b = &r->nodes_before[j];
				if (strcmp(now->s.s, b->s.s) == 0)
					before = j;
				else if (like < 0 && b->kind == now->kind && b->ident == now->ident)
					like = j;
			}
			text_puts(t, i ? ",\n   " : "\n   ");
			if (before >= 0) {
				text_printf(t, "%d", before);
				continue;
			}
			/* The same object as one of the frame before: its changes, when shorter. */
			Text *spliced = &r->part2;
			text_clear(spliced);
			if (like >= 0)
				node_splice(spliced, now, &r->nodes_before[like], like);
			if (like >= 0 && spliced->len < now->s.len)
				text_add(t, spliced->s, spliced->len);
			else
				text_add(t, now->s.s, now->s.len);
		}
		text_puts(t, "]}");
	}
	text_clear(&r->last_model);
	text_add(&r->last_model, head->s, head->len);
	/* This frame's nodes are the next frame's "before": swap the lists. */
	NodeText *swap = r->nodes_before;
	int swap_cap = r->nodes_before_cap;
	r->nodes_before = r->nodes_now, r->nodes_before_cap = r->nodes_now_cap;
	r->nodes_now = swap, r->nodes_now_cap = swap_cap;
	r->nodes_before_count = count;
}

/* screen_code(c, i, j): cell (i, j)'s code (replay.h, screen). */
static char screen_code(const Controller *c, int32_t i, int32_t j)
{
	const Screen *s = &c->screen;
	int32_t label = screen_label(s, i, j);
	bool same = c->space.w == s->w && c->space.h == s->h;
	bool blocked = same && !grid_free_at(&c->space, i, j);
	if (label == SCREEN_SPACE)
		return blocked ? 'x' : '.';
	if (label == SCREEN_UNKNOWN)
		return blocked ? 'z' : '?';
	if (label == SCREEN_VERGE)
		return '#';
	return label < c->model.node_count && c->model.node[label].held ? 'h' : 'o';
}

static void screen_text(Text *t, const Controller *c)
{
	const Screen *s = &c->screen;
	text_printf(t, "{\"x0\": %d, \"y0\": %d, \"w\": %d, \"h\": %d, \"cells\": \"", (int)s->x0,
	            (int)s->y0, (int)s->w, (int)s->h);
	char cur = 0;
	int64_t n = 0;
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			char code = screen_code(c, i, j);
			if (code != cur && n > 0) {
				text_run(t, cur, n);
				n = 0;
			}
			cur = code;
			n++;
		}
	if (n > 0)
		text_run(t, cur, n);
	text_puts(t, "\"}");
}

/* carry_text(t, c): the planned poses of a carried object (replay.h, carry). For
 * the tasks (vi)-(ix), the carry planner's (carrytask.h): its own outline of the held
 * object about Utak's believed point, then the pose after each command still ahead,
 * a turn turning the object about Utak's point (paper 3.6). Otherwise the push
 * planner's, at Utak's believed point and each waypoint still ahead, without
 * turning; the footprint is the held node's rings about Utak's point. */
static void carry_text(Text *t, const Controller *c)
{
	const WorldModel *m = &c->model;
	const CarryTask *ct = c->carry;
	if (ct && c->phase == PHASE_PUSH && ct->have_carry && ct->held.count > 2) {
		text_puts(t, ",\n \"carry\": {\"footprint\": [[");
		for (int32_t i = 0; i < ct->held.count; i++) {
			if (i)
				text_putc(t, ',');
			text_point(t, vec2_sub(ct->held.v[i], m->utak));
		}
		text_puts(t, "]], \"poses\": [");
		text_pose(t, m->utak, 0);
		double theta = 0;
		for (int i = ct->next; i < ct->count; i++) {
			if (ct->cmd[i].kind == MOTOR_TURN)
				theta += ct->cmd[i].deg;
			text_putc(t, ',');
			text_pose(t, ct->expect[i], theta);
		}
		text_puts(t, "]}");
		return;
	}
	if (c->phase != PHASE_PUSH || !c->have_plan || c->route.count == 0)
		return;
	int32_t held = -1;
	for (int32_t n = 0; n < m->node_count && held < 0; n++)
		if (m->node[n].held && m->node[n].ring_count > 0)
			held = n;
	if (held < 0)
		return;
	const ModelNode *node = &m->node[held];
	text_puts(t, ",\n \"carry\": {\"footprint\": [");
	for (int32_t k = 0; k < node->ring_count; k++) {
		const ModelRing *ring = &m->ring[node->first_ring + k];
		text_puts(t, k ? ",[" : "[");
		for (int32_t i = 0; i < ring->count; i++) {
			if (i)
				text_putc(t, ',');
			text_point(t, vec2_sub(m->vertex[ring->first + i].p, m->utak));
		}
		text_putc(t, ']');
	}
	text_puts(t, "], \"poses\": [");
	text_pose(t, m->utak, 0);
	for (int i = c->next; i < c->route.count; i++) {
		text_putc(t, ',');
		text_pose(t, c->route.pts[i], 0);
	}
	text_puts(t, "]}");
}

/* table_changes(r, t, w, tab): the box of every object whose polygon changed since
 * the last frame, before and after, as [[x, y, w, h, runs]]. */
static void table_changes(Replay *r, Text *t, const World *w, const Table *tab)
{
	bool any = false;
	double lx = 0, ly = 0, hx = 0, hy = 0;
	for (int32_t k = 0; k < r->object_count && k < w->object_count; k++) {
		if (memcmp(&r->shapes[k], &w->objects[k].shape, sizeof r->shapes[k]) == 0)
			continue;
		Box a = geom_polygon_box(&r->shapes[k]), b = geom_polygon_box(&w->objects[k].shape);
		double x0 = fmin(a.lo.x, b.lo.x), y0 = fmin(a.lo.y, b.lo.y);
		double x1 = fmax(a.hi.x, b.hi.x), y1 = fmax(a.hi.y, b.hi.y);
		lx = any ? fmin(lx, x0) : x0, ly = any ? fmin(ly, y0) : y0;
		hx = any ? fmax(hx, x1) : x1, hy = any ? fmax(hy, y1) : y1;
		any = true;
		r->shapes[k] = w->objects[k].shape;
	}
	if (!any)
		return;
	/* A square belongs to a polygon that meets its interior (utak(5), the digital representation), so the
	 * squares the box meets, and one more for rounding, hold every change. */
	int32_t x0 = (int32_t)floor(lx) - 1, y0 = (int32_t)floor(ly) - 1;
	int32_t x1 = (int32_t)ceil(hx) + 1, y1 = (int32_t)ceil(hy) + 1;
	x0 = x0 < 0 ? 0 : x0, y0 = y0 < 0 ? 0 : y0;
	x1 = x1 > tab->w ? tab->w : x1, y1 = y1 > tab->h ? tab->h : y1;
	if (x0 >= x1 || y0 >= y1)
		return;
	text_printf(t, ",\n \"table\": [[%d,%d,%d,%d,\"", (int)x0, (int)y0, (int)(x1 - x0),
	            (int)(y1 - y0));
	table_runs(t, w, tab, x0, y0, x1, y1);
	text_puts(t, "\"]]");
}

/* record_frame(r, ...): one frame (replay.h, frames); line is the trace line. */
static void record_frame(Replay *r, const World *w, const Table *tab, const Impression *imp,
                         const Controller *c, int cycle, const char *line)
{
	Text *t = &r->frames;
	text_printf(t, "{\"cycle\": %d,\n \"line\": ", cycle);
	text_string(t, line);
	if (!r->act) {
		text_printf(t, ",\n \"phase\": \"%s\"", phase_name(c->phase));
		if (cycle > 0)
			text_printf(t, ", \"decided\": %s", r->decided);
	}
	text_puts(t, ",\n \"utak\": ");
	text_point(t, w->utak);
	text_printf(t, ", \"held\": %d", (int)w->held);
	table_changes(r, t, w, tab);
	text_puts(t, ",\n \"retina\": \"");
	for (int i = 0; i < RETINA_CELLS; i++)
		text_putc(t, (char)('0' + (imp->level[i] & 7)));
	text_puts(t, "\", \"touch\": ");
	char touch[TOUCH_CELLS + 1];
	memcpy(touch, imp->touch, TOUCH_CELLS);
	touch[TOUCH_CELLS] = 0;
	text_string(t, touch);
	record_belief(r, t, &c->model);
	record_model(r, t, &c->model);
	if (c->screen.w > 0) {
		text_clear(&r->part);
		screen_text(&r->part, c);
		if (r->last_screen.len == 0 || strcmp(r->part.s, r->last_screen.s) != 0) {
			text_puts(t, ",\n \"screen\": ");
			text_add(t, r->part.s, r->part.len);
			text_clear(&r->last_screen);
			text_add(&r->last_screen, r->part.s, r->part.len);
		}
		view_add(r, c->screen.x0, c->screen.y0, c->screen.x0 + c->screen.w - 1,
		         c->screen.y0 + c->screen.h - 1);
	}
	if (!r->act) {
		text_printf(t, ",\n \"plan\": %d, \"next\": %d",
		            c->have_plan ? r->plan_count - 1 : -1, c->next);
		carry_text(t, c);
	}
	text_puts(t, "},\n");
	r->frame_count++;
}

void replay_start(Replay *r, const World *w, const Table *t, const Impression *imp,
                  const Controller *c)
{
	record_plan(r, c, "7", 0);
	record_frame(r, w, t, imp, c, 0,
	             r->act ? "start: the first impression" : "start: steps 1-7");
}

void replay_decided(Replay *r, const Controller *c)
{
	record_plan(r, c, "9", c->cycle);
	snprintf(r->decided, sizeof r->decided, "{\"phase\": \"%s\", \"plan\": %d, \"next\": %d}",
	         phase_name(c->phase), c->have_plan ? r->plan_count - 1 : -1, c->next);
}

void replay_cycle(Replay *r, const World *w, const Table *t, const Impression *imp,
                  const Controller *c, const MotorCommand *cmd, const MotorOutcome *out)
{
	record_plan(r, c, "13", c->cycle);
	/* The trace line, as main.c prints it. */
	char line[sizeof c->note + 256 + 32];
	char motion[256] = "";
	FILE *f = fmemopen(motion, sizeof motion - 1, "w");
	if (f) {
		motion_print(cmd, out, f);
		fclose(f);
	}
	if (r->act)
		snprintf(line, sizeof line, "act %d: %s", r->frame_count, motion);
	else
		snprintf(line, sizeof line, "cycle %d: %s | %s", c->cycle, motion, c->note);
	record_frame(r, w, t, imp, c, r->act ? r->frame_count : c->cycle, line);
}

/* ---- the page ------------------------------------------------------------------------ */

int replay_write(Replay *r, const char *verdict, FILE *f)
{
	int i = 0, status = 0;
	for (; replay_viewer[i] && strcmp(replay_viewer[i], REPLAY_DATA_MARK) != 0; i++)
		if (fputs(replay_viewer[i], f) == EOF || fputc('\n', f) == EOF)
			return -1;
	Text tail = {0};
	text_puts(&tail, "\"verdict\": ");
	text_string(&tail, verdict ? verdict : "");
	text_printf(&tail, ",\n\"cycles\": %d,\n\"view\": [%d, %d, %d, %d],\n\"plans\": [\n",
	            r->frame_count - 1, (int)r->view_x0, (int)r->view_y0, (int)r->view_x1 + 1,
	            (int)r->view_y1 + 1);
	/* The lists' last ",\n" is written as "\n": JSON allows no trailing comma. */
	int plans_len = r->plans.len >= 2 ? r->plans.len - 2 : 0;
	int frames_len = r->frames.len >= 2 ? r->frames.len - 2 : 0;
	if (fwrite(r->head.s, 1, (size_t)r->head.len, f) != (size_t)r->head.len ||
	    fwrite(tail.s, 1, (size_t)tail.len, f) != (size_t)tail.len ||
	    fwrite(r->plans.s ? r->plans.s : "", 1, (size_t)plans_len, f) != (size_t)plans_len ||
	    fputs(plans_len ? "\n],\n\"frames\": [\n" : "],\n\"frames\": [\n", f) == EOF ||
	    fwrite(r->frames.s ? r->frames.s : "", 1, (size_t)frames_len, f) !=
	        (size_t)frames_len ||
	    fputs("\n]}\n", f) == EOF)
		status = -1;
	text_free(&tail);
	for (i += replay_viewer[i] ? 1 : 0; status == 0 && replay_viewer[i]; i++)
		if (fputs(replay_viewer[i], f) == EOF || fputc('\n', f) == EOF)
			status = -1;
	if (status == 0 && ferror(f)) {
		errno = errno ? errno : EIO;
		status = -1;
	}
	return status;
}
