/* svg.c - a picture of a run as SVG (see svg.h). Not from the paper: the paper's
 * users watched the TABLE on a display (2.1); this is that display, with Utak's
 * beliefs and plans laid over it, labelled so that it explains itself.
 *
 * Two passes: the first finds the extent of everything to be drawn (the TABLE and
 * whatever of Utak's belief and plan strays past it), the second draws, so that the
 * view box holds every element. Text is monospace, whose width is known without a
 * font (SVG_CHAR_WIDTH of the size a character), so that the title and the legend
 * are sized to fit too. */
#include "utak/svg.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

/* Pixels around the picture, and the sizes of its text. */
#define SVG_MARGIN 10.0
#define SVG_TITLE_SIZE 13.0
#define SVG_TEXT_SIZE 11.0
#define SVG_LABEL_SIZE 10.0
/* The advance of a monospace character (DejaVu Sans Mono's is 0.602 em), rounded up. */
#define SVG_CHAR_WIDTH 0.62
/* A legend entry: its swatch, and the room between columns. */
#define SVG_SWATCH 24.0
#define SVG_LEGEND_ROW 16.0
#define SVG_LEGEND_GAP 14.0

/* Colours: the Okabe-Ito set (Okabe and Ito, "Color Universal Design", 2002) for
 * lines and marks; light tints of it for the objects' fills, so that every line
 * over them stays visible. */
#define SVG_BELIEF "#0072b2"   /* blue: believed outlines */
#define SVG_SKELETON "#009e73" /* bluish green: skeleton and pathgraph */
#define SVG_ROUTE "#d55e00"    /* vermillion: the planned route */
#define SVG_TRAIL "#000000"    /* black: the path taken */
/* Each kind of line, drawn and in the legend alike: a colour and a dash of its own. */
#define SVG_STYLE_BELIEF "stroke=\"" SVG_BELIEF "\" stroke-width=\"2\" stroke-dasharray=\"6 3\""
#define SVG_STYLE_FLOOR_EDGE "stroke=\"#333333\" stroke-width=\"1\" stroke-dasharray=\"1 3\""
#define SVG_STYLE_ROUTE "stroke=\"" SVG_ROUTE "\" stroke-width=\"2.5\" stroke-dasharray=\"8 3\""
#define SVG_STYLE_TRAIL "stroke=\"" SVG_TRAIL "\" stroke-width=\"1.5\""
#define SVG_VERGE "#555555"
#define SVG_FLOOR "#ffffff"

/* The drawing's frame: TABLE squares to pixels, and the model frame to the TABLE.
 * The model's frame is Utak's frame at the start, with its origin at the lower-left
 * corner of his first square (worldmodel.h). */
typedef struct Canvas {
	Heading heading;
	double ox, oy;        /* TABLE coordinates of the model origin */
	Box extent;           /* TABLE squares shown */
	double left, top;     /* pixel of the extent's north-west corner */
	double width, height; /* the whole picture, pixels */
} Canvas;

static Vec2 to_table(const Canvas *cv, Vec2 p)
{
	/* The frame turns about the centre of the first square, (0.5, 0.5) in both. */
	Vec2 d = world_own_to_table(cv->heading, vec2(p.x - 0.5, p.y - 0.5));
	return vec2(cv->ox + 0.5 + d.x, cv->oy + 0.5 + d.y);
}

static double px(const Canvas *cv, double x)
{
	return cv->left + (x - cv->extent.lo.x) * SVG_SCALE;
}
static double py(const Canvas *cv, double y)
{
	return cv->top + (cv->extent.hi.y - y) * SVG_SCALE;
}

static void extent_add(Box *b, Vec2 p)
{
	b->lo.x = fmin(b->lo.x, p.x), b->lo.y = fmin(b->lo.y, p.y);
	b->hi.x = fmax(b->hi.x, p.x), b->hi.y = fmax(b->hi.y, p.y);
}

/* A fill for each colour letter: tints of the Okabe-Ito colours, and greys. */
static const char *fill_of(char colour)
{
	static const char *const palette[] = {"#f5c26b", "#a6d8f5", "#f7f09a", "#e3b5cf",
	                                      "#d9b38c", "#c9c9c9", "#b3e0d1", "#f2b8a0"};
	return palette[(colour - 'A') % 8];
}

/* The text of s with XML's special characters escaped. */
static void put_text(FILE *f, const char *s)
{
	for (; *s; s++) {
		if (*s == '<')
			fputs("&lt;", f);
		else if (*s == '>')
			fputs("&gt;", f);
		else if (*s == '&')
			fputs("&amp;", f);
		else if (*s == '"')
			fputs("&quot;", f);
		else if ((unsigned char)*s >= 0x20 && (unsigned char)*s < 0x7f)
			fputc(*s, f);
	}
}

static double text_width(const char *s, double size)
{
	return (double)strlen(s) * SVG_CHAR_WIDTH * size;
}

/* ---- what Utak believes ------------------------------------------------------------- */

/* The rings drawn: every ring of an object, and $floor's rings but the holes that
 * are objects' outlines. */
static bool ring_drawn(const WorldModel *m, const ModelNode *node, const ModelRing *r)
{
	return node->kind == NODE_OBJECT ||
	       (node->kind == NODE_FLOOR &&
	        !worldmodel_ring_outlines_object(m, (int32_t)(r - m->ring)));
}

static void ring_path(FILE *f, const Canvas *cv, const WorldModel *m, const ModelRing *r)
{
	for (int32_t i = 0; i < r->count; i++) {
		Vec2 q = to_table(cv, m->vertex[r->first + i].p);
		fprintf(f, "%s%.1f,%.1f", i ? " L" : "M", px(cv, q.x), py(cv, q.y));
	}
	fputs(" Z", f);
}

static void draw_model(FILE *f, const Canvas *cv, const WorldModel *m)
{
	fputs("<g id=\"floor-edge\" fill=\"none\" " SVG_STYLE_FLOOR_EDGE ">\n", f);
	for (int32_t n = 0; n < m->node_count; n++) {
		const ModelNode *node = &m->node[n];
		if (node->kind != NODE_FLOOR)
			continue;
		fputs("<path d=\"", f);
		for (int32_t k = 0; k < node->ring_count; k++)
			if (ring_drawn(m, node, &m->ring[node->first_ring + k])) {
				fputs(k ? " " : "", f);
				ring_path(f, cv, m, &m->ring[node->first_ring + k]);
			}
		fputs("\"/>\n", f);
	}
	fputs("</g>\n<g id=\"model\" fill=\"none\" " SVG_STYLE_BELIEF ">\n", f);
	for (int32_t n = 0; n < m->node_count; n++) {
		const ModelNode *node = &m->node[n];
		if (node->kind != NODE_OBJECT)
			continue;
		fputs("<path class=\"object\" d=\"", f);
		for (int32_t k = 0; k < node->ring_count; k++) {
			fputs(k ? " " : "", f);
			ring_path(f, cv, m, &m->ring[node->first_ring + k]);
		}
		fputs("\"><title>", f);
		put_text(f, node->name);
		fprintf(f, "%s, confidence %.2f</title></path>\n", node->held ? " (held)" : "",
		        node->conf);
	}
	fputs("</g>\n", f);
}

/* ---- the drawing --------------------------------------------------------------------- */

/* The extent of everything drawn, in TABLE squares. */
static Box find_extent(const Canvas *cv, const World *w, const Table *t, const Controller *c,
                       const Vec2 *trail, int n)
{
	(void)w;
	Box b = {vec2(0, 0), vec2(t->w, t->h)};
	const WorldModel *m = &c->model;
	for (int32_t k = 0; k < m->node_count; k++) {
		const ModelNode *node = &m->node[k];
		for (int32_t r = 0; r < node->ring_count; r++) {
			const ModelRing *ring = &m->ring[node->first_ring + r];
			if (!ring_drawn(m, node, ring))
				continue;
			for (int32_t i = 0; i < ring->count; i++)
				extent_add(&b, to_table(cv, m->vertex[ring->first + i].p));
		}
	}
	const Planner *p = &c->planner;
	if (p->have_graph)
		for (int32_t j = 0; j < p->skeleton.h; j++)
			for (int32_t i = 0; i < p->skeleton.w; i++)
				if (skeleton_on(&p->skeleton, i, j)) {
					extent_add(
					    &b, to_table(cv, vec2(c->plan_x0 + i, c->plan_y0 + j)));
					extent_add(&b, to_table(cv, vec2(c->plan_x0 + i + 1,
					                                 c->plan_y0 + j + 1)));
				}
	for (int i = 0; i < c->route.count; i++)
		extent_add(&b, to_table(cv, c->route.pts[i]));
	for (int i = 0; i < n; i++)
		extent_add(&b, trail[i]);
	/* Half a square of room for the marks drawn round points (Utak, the start). */
	b.lo.x = floor(b.lo.x - 0.5), b.lo.y = floor(b.lo.y - 0.5);
	b.hi.x = ceil(b.hi.x + 0.5), b.hi.y = ceil(b.hi.y + 0.5);
	return b;
}

static void draw_table(FILE *f, const Canvas *cv, const World *w, const Table *t)
{
	fprintf(f, "<g id=\"table\" stroke=\"none\">\n");
	fprintf(f, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"/>\n",
	        px(cv, 0), py(cv, t->h), (double)t->w * SVG_SCALE, (double)t->h * SVG_SCALE,
	        SVG_FLOOR);
	/* One rectangle per run of same-owner squares in a row; each object's squares
	 * summed for the place of its name. */
	double *sum = util_alloc(3 * ((size_t)w->object_count + 1), sizeof *sum);
	for (int32_t y = 0; y < t->h; y++)
		for (int32_t x = 0; x < t->w;) {
			int32_t who = table_owner(t, x, y), x1 = x;
			while (x1 + 1 < t->w && table_owner(t, x1 + 1, y) == who)
				x1++;
			if (who != TABLE_FLOOR)
				fprintf(f,
				        "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%d\" "
				        "fill=\"%s\"/>\n",
				        px(cv, x), py(cv, y + 1), (double)(x1 - x + 1) * SVG_SCALE,
				        SVG_SCALE,
				        who == TABLE_VERGE ? SVG_VERGE
				                           : fill_of(w->objects[who - 1].colour));
			if (who > 0) {
				double k = x1 - x + 1;
				sum[3 * (who - 1)] += k * (x + x1 + 1) / 2,
				    sum[3 * (who - 1) + 1] += k * (y + 0.5);
				sum[3 * (who - 1) + 2] += k;
			}
			x = x1 + 1;
		}
	fprintf(f,
	        "</g>\n<g id=\"objects\" font-family=\"monospace\" font-size=\"%.0f\" "
	        "text-anchor=\"middle\" "
	        "fill=\"#000000\">\n",
	        SVG_LABEL_SIZE);
	for (int32_t k = 0; k < w->object_count; k++) {
		if (sum[3 * k + 2] == 0)
			continue;
		double x = px(cv, sum[3 * k] / sum[3 * k + 2]),
		       y = py(cv, sum[3 * k + 1] / sum[3 * k + 2]) + 3.5;
		/* Kept inside the picture when the object lies at its edge. */
		double half = text_width(w->objects[k].name, SVG_LABEL_SIZE) / 2;
		x = fmax(half + 1, fmin(cv->width - half - 1, x));
		fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">", x, y);
		put_text(f, w->objects[k].name);
		fputs("</text>\n", f);
	}
	fputs("</g>\n", f);
	free(sum);
}

static void draw_plan(FILE *f, const Canvas *cv, const Controller *c)
{
	const Planner *p = &c->planner;
	if (!p->have_graph)
		return;
	/* The skeleton's cells, small, so that the pathgraph reads over them. */
	fprintf(f, "<g id=\"skeleton\" fill=\"%s\" fill-opacity=\"0.45\" stroke=\"none\">\n",
	        SVG_SKELETON);
	double cell = SVG_SCALE * 0.5;
	for (int32_t j = 0; j < p->skeleton.h; j++)
		for (int32_t i = 0; i < p->skeleton.w; i++)
			if (skeleton_on(&p->skeleton, i, j)) {
				Vec2 q =
				    to_table(cv, vec2(c->plan_x0 + i + 0.5, c->plan_y0 + j + 0.5));
				fprintf(f,
				        "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" "
				        "height=\"%.1f\"/>\n",
				        px(cv, q.x) - cell / 2, py(cv, q.y) - cell / 2, cell, cell);
			}
	fputs("</g>\n", f);
	const Pathgraph *pg = &p->pathgraph;
	fprintf(f, "<g id=\"pathgraph\" stroke=\"%s\">\n", SVG_SKELETON);
	for (int32_t e = 0; e < pg->edge_count; e++) {
		const PathgraphEdge *edge = &pg->edges[e];
		fputs("<polyline fill=\"none\" stroke-width=\"1.5\" points=\"", f);
		for (int32_t k = 0; k < edge->count; k++) {
			int32_t cellno = pg->cells[edge->first + k];
			Vec2 q = to_table(cv, vec2(c->plan_x0 + cellno % pg->w + 0.5,
			                           c->plan_y0 + cellno / pg->w + 0.5));
			fprintf(f, "%s%.1f,%.1f", k ? " " : "", px(cv, q.x), py(cv, q.y));
		}
		fputs("\"/>\n", f);
	}
	for (int32_t v = 0; v < pg->vertex_count; v++) {
		const PathgraphVertex *pv = &pg->vertices[v];
		Vec2 q = to_table(cv, vec2(c->plan_x0 + pv->x + 0.5, c->plan_y0 + pv->y + 0.5));
		fprintf(f,
		        "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"%s\" stroke=\"#ffffff\" "
		        "stroke-width=\"1\"/>\n",
		        px(cv, q.x), py(cv, q.y), SVG_SCALE * 0.35, SVG_SKELETON);
	}
	fputs("</g>\n", f);
}

static void draw_paths(FILE *f, const Canvas *cv, const World *w, const Controller *c,
                       const Vec2 *trail, int n)
{
	/* The path taken, an arrow at each turn and at the end giving the direction: a
	 * halt on a straight line (ten moves of one square west) is no corner of the
	 * polyline, so that its arrows mark where the path bends, not crowd it. */
	fputs("<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"7\" refY=\"5\" "
	      "markerWidth=\"7\" markerHeight=\"7\" orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 Z\" "
	      "fill=\"" SVG_TRAIL "\"/></marker></defs>\n",
	      f);
	fputs("<polyline id=\"trail\" fill=\"none\" " SVG_STYLE_TRAIL
	      " marker-mid=\"url(#arrow)\" marker-end=\"url(#arrow)\" points=\"",
	      f);
	Vec2 last = trail[0];
	for (int i = 0; i < n; i++) {
		if (i > 0 && trail[i].x == last.x && trail[i].y == last.y)
			continue; /* a command that moved him nowhere */
		if (i > 0 && i + 1 < n) {
			Vec2 a = vec2_sub(trail[i], last), b = vec2_sub(trail[i + 1], trail[i]);
			if (fabs(a.x * b.y - a.y * b.x) < 1e-9 && a.x * b.x + a.y * b.y > 0)
				continue; /* straight on */
		}
		fprintf(f, "%s%.1f,%.1f", i ? " " : "", px(cv, trail[i].x), py(cv, trail[i].y));
		last = trail[i];
	}
	fputs("\"/>\n", f);
	/* The route he planned last, on top. */
	if (c->route.count > 1) {
		fputs("<polyline id=\"route\" fill=\"none\" " SVG_STYLE_ROUTE
		      " stroke-linecap=\"round\" points=\"",
		      f);
		for (int i = 0; i < c->route.count; i++) {
			Vec2 q = to_table(cv, c->route.pts[i]);
			fprintf(f, "%s%.1f,%.1f", i ? " " : "", px(cv, q.x), py(cv, q.y));
		}
		fputs("\"/>\n", f);
	}
	fprintf(
	    f,
	    "<circle id=\"start\" cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"none\" stroke=\"%s\" "
	    "stroke-width=\"2\"/>\n",
	    px(cv, trail[0].x), py(cv, trail[0].y), SVG_SCALE * 0.6, SVG_TRAIL);
	/* Utak where he ended, and the way he faces. */
	Vec2 u = trail[n - 1], ahead = world_own_to_table(w->heading, vec2(0, 1));
	fprintf(f, "<g id=\"utak\"><circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"%s\"/>",
	        px(cv, u.x), py(cv, u.y), SVG_SCALE * 0.45, SVG_TRAIL);
	fprintf(f,
	        "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" "
	        "stroke-width=\"2\"/></g>\n",
	        px(cv, u.x), py(cv, u.y), px(cv, u.x + ahead.x), py(cv, u.y + ahead.y), SVG_TRAIL);
}

/* ---- the legend ---------------------------------------------------------------------- */

typedef enum Swatch {
	SW_FILL,
	SW_BELIEF,
	SW_FLOOR_EDGE,
	SW_SKELETON,
	SW_VERTEX,
	SW_TRAIL,
	SW_ROUTE,
	SW_START,
	SW_UTAK
} Swatch;

typedef struct LegendEntry {
	Swatch kind;
	const char *fill;
	char label[64];
} LegendEntry;

enum { SVG_LEGEND_MAX = 24 };

static int legend_entries(const World *w, const Controller *c, LegendEntry *e)
{
	int n = 0;
	e[n++] = (LegendEntry){SW_FILL, SVG_VERGE, "verge and walls"};
	for (int32_t k = 0; k < w->object_count && n < SVG_LEGEND_MAX - 9; k++) {
		bool again = false; /* one entry per colour */
		for (int32_t j = 0; j < k; j++)
			again |= w->objects[j].colour == w->objects[k].colour;
		if (again)
			continue;
		e[n] = (LegendEntry){SW_FILL, fill_of(w->objects[k].colour), ""};
		snprintf(e[n++].label, sizeof e[0].label, "object %c (%.40s)", w->objects[k].colour,
		         w->objects[k].name);
	}
	e[n++] = (LegendEntry){SW_BELIEF, NULL, "believed object"};
	e[n++] = (LegendEntry){SW_FLOOR_EDGE, NULL, "edge of believed floor"};
	if (c->planner.have_graph) {
		e[n++] = (LegendEntry){SW_SKELETON, NULL, "skeleton, last plan"};
		e[n++] = (LegendEntry){SW_VERTEX, NULL, "pathgraph (Figure 3)"};
	}
	e[n++] = (LegendEntry){SW_TRAIL, NULL, "path taken"};
	if (c->route.count > 1)
		e[n++] = (LegendEntry){SW_ROUTE, NULL, "route planned last"};
	e[n++] = (LegendEntry){SW_START, NULL, "start"};
	e[n++] = (LegendEntry){SW_UTAK, NULL, "Utak at the end"};
	return n;
}

static double legend_column_width(const LegendEntry *e, int n)
{
	double wmax = 0;
	for (int i = 0; i < n; i++)
		wmax = fmax(wmax, text_width(e[i].label, SVG_TEXT_SIZE));
	return SVG_SWATCH + 6 + wmax + SVG_LEGEND_GAP;
}

static void draw_swatch(FILE *f, const LegendEntry *e, double x, double y)
{
	double mid = y - 4, x1 = x + SVG_SWATCH;
	switch (e->kind) {
	case SW_FILL:
		fprintf(f,
		        "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"10\" fill=\"%s\" "
		        "stroke=\"#000000\" "
		        "stroke-width=\"0.5\"/>\n",
		        x, mid - 5, SVG_SWATCH, e->fill);
		break;
	case SW_BELIEF:
	case SW_FLOOR_EDGE:
	case SW_ROUTE:
	case SW_TRAIL: {
		const char *style = e->kind == SW_BELIEF       ? SVG_STYLE_BELIEF
		                    : e->kind == SW_FLOOR_EDGE ? SVG_STYLE_FLOOR_EDGE
		                    : e->kind == SW_ROUTE      ? SVG_STYLE_ROUTE
		                                               : SVG_STYLE_TRAIL
		                        " marker-end=\"url(#arrow)\"";
		fprintf(f, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" %s/>\n", x, mid,
		        x1 - 4, mid, style);
		break;
	}
	case SW_SKELETON:
		for (int k = 0; k < 4; k++)
			fprintf(f,
			        "<rect x=\"%.1f\" y=\"%.1f\" width=\"6\" height=\"6\" fill=\"%s\" "
			        "fill-opacity=\"0.45\"/>\n",
			        x + 6.0 * k, mid - 3, SVG_SKELETON);
		break;
	case SW_VERTEX:
		fprintf(f,
		        "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" "
		        "stroke-width=\"1.5\"/>\n",
		        x, mid, x1, mid, SVG_SKELETON);
		fprintf(
		    f,
		    "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4.2\" fill=\"%s\" stroke=\"#ffffff\"/>\n",
		    x + SVG_SWATCH / 2, mid, SVG_SKELETON);
		break;
	case SW_START:
		fprintf(f,
		        "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"none\" stroke=\"%s\" "
		        "stroke-width=\"2\"/>\n",
		        x + SVG_SWATCH / 2, mid, SVG_SCALE * 0.6, SVG_TRAIL);
		break;
	case SW_UTAK:
		fprintf(f, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"%.1f\" fill=\"%s\"/>\n",
		        x + SVG_SWATCH / 2, mid, SVG_SCALE * 0.45, SVG_TRAIL);
		break;
	}
}

/* ---- the document --------------------------------------------------------------------- */

void svg_draw(FILE *f, const World *w, const Table *t, const Controller *c, const Vec2 *trail,
              int n, const char *title, const char *verdict)
{
	Canvas cv = {.heading = w->heading, .ox = floor(trail[0].x), .oy = floor(trail[0].y)};
	cv.extent = find_extent(&cv, w, t, c, trail, n);
	LegendEntry legend[SVG_LEGEND_MAX];
	int entries = legend_entries(w, c, legend);
	double colw = legend_column_width(legend, entries);
	double picture_w = (cv.extent.hi.x - cv.extent.lo.x) * SVG_SCALE;
	double picture_h = (cv.extent.hi.y - cv.extent.lo.y) * SVG_SCALE;
	char heading[320];
	snprintf(heading, sizeof heading, "utak: %s", title);
	double inner = fmax(picture_w, fmax(colw, fmax(text_width(heading, SVG_TITLE_SIZE),
	                                               text_width(verdict, SVG_TEXT_SIZE))));
	int columns = (int)fmax(1, floor((inner + SVG_LEGEND_GAP) / colw));
	int rows = (entries + columns - 1) / columns;
	double head = SVG_MARGIN + SVG_TITLE_SIZE + 6 + SVG_TEXT_SIZE + 10;
	cv.width = ceil(inner + 2 * SVG_MARGIN);
	cv.height = ceil(head + picture_h + 10 + rows * SVG_LEGEND_ROW + SVG_MARGIN);
	cv.left = SVG_MARGIN + (inner - picture_w) / 2;
	cv.top = head;

	fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
	fprintf(f,
	        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
	        "viewBox=\"0 0 %.0f %.0f\">\n",
	        cv.width, cv.height, cv.width, cv.height);
	fputs("<title>", f);
	put_text(f, heading);
	fputs(": ", f);
	put_text(f, verdict);
	fputs("</title>\n", f);
	fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"#ffffff\"/>\n");
	fprintf(f, "<g id=\"title\" font-family=\"monospace\" fill=\"#000000\">\n");
	fprintf(f, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%.0f\" font-weight=\"bold\">",
	        SVG_MARGIN, SVG_MARGIN + SVG_TITLE_SIZE - 2, SVG_TITLE_SIZE);
	put_text(f, heading);
	fprintf(f, "</text>\n<text x=\"%.1f\" y=\"%.1f\" font-size=\"%.0f\">", SVG_MARGIN,
	        SVG_MARGIN + SVG_TITLE_SIZE + 6 + SVG_TEXT_SIZE - 2, SVG_TEXT_SIZE);
	put_text(f, verdict);
	fputs("</text>\n</g>\n", f);
	draw_table(f, &cv, w, t);
	draw_model(f, &cv, &c->model);
	draw_plan(f, &cv, c);
	draw_paths(f, &cv, w, c, trail, n);
	fprintf(f,
	        "<g id=\"legend\" font-family=\"monospace\" font-size=\"%.0f\" fill=\"#000000\">\n",
	        SVG_TEXT_SIZE);
	for (int i = 0; i < entries; i++) {
		double x = SVG_MARGIN + (i / rows) * colw,
		       y = head + picture_h + 10 + (i % rows + 1) * SVG_LEGEND_ROW - 3;
		draw_swatch(f, &legend[i], x, y);
		fprintf(f, "<text x=\"%.1f\" y=\"%.1f\">", x + SVG_SWATCH + 6, y);
		put_text(f, legend[i].label);
		fputs("</text>\n", f);
	}
	fputs("</g>\n</svg>\n", f);
}
