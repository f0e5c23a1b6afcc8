/* svg.c - a picture of a run as SVG (see svg.h). Not from the paper: the paper's
 * users watched the TABLE on a display (2.1); this is that display, with Utak's
 * beliefs and plans laid over it. */
#include "utak/svg.h"

#include <math.h>

/* The model's frame is Utak's frame at the start, with its origin at the lower-left
 * corner of his first square; to_table maps a model point onto the TABLE. */
typedef struct Frame {
	Heading h;
	double ox, oy; /* TABLE coordinates of the model origin */
	int32_t height;
} Frame;

static Vec2 to_table(const Frame *fr, Vec2 p)
{
	/* The model origin is a square's corner; the frame turns about the centre of
	 * that square, which is (0.5, 0.5) in both frames. */
	Vec2 d = world_own_to_table(fr->h, vec2(p.x - 0.5, p.y - 0.5));
	return vec2(fr->ox + 0.5 + d.x, fr->oy + 0.5 + d.y);
}

/* px, py: SVG pixels of a TABLE point (SVG's y grows down). */
static double px(double x) { return x * SVG_SCALE; }
static double py(const Frame *fr, double y) { return (fr->height - y) * SVG_SCALE; }

static const char *fill_of(char colour)
{
	static const char *const palette[] = {"#d95f02", "#7570b3", "#e7298a", "#66a61e", "#e6ab02", "#a6761d",
					      "#1b9e77", "#666666"};
	return palette[(colour - 'A') % 8];
}

static void polyline(FILE *f, const Frame *fr, const Vec2 *p, int n, bool model, const char *style)
{
	fprintf(f, "<polyline fill=\"none\" %s points=\"", style);
	for (int i = 0; i < n; i++) {
		Vec2 q = model ? to_table(fr, p[i]) : p[i];
		fprintf(f, "%s%.2f,%.2f", i ? " " : "", px(q.x), py(fr, q.y));
	}
	fputs("\"/>\n", f);
}

void svg_draw(FILE *f, const World *w, const Table *t, const Controller *c, const Vec2 *trail, int n)
{
	int32_t sx = (int32_t)floor(trail[0].x), sy = (int32_t)floor(trail[0].y);
	Frame fr = {w->heading, sx, sy, t->h};
	fprintf(f, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
	fprintf(f, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%d\" height=\"%d\" viewBox=\"0 0 %d %d\">\n",
		(int)t->w * SVG_SCALE, (int)t->h * SVG_SCALE, (int)t->w * SVG_SCALE, (int)t->h * SVG_SCALE);
	fprintf(f, "<title>utak: %s</title>\n", w->file);
	fprintf(f, "<rect width=\"100%%\" height=\"100%%\" fill=\"#fafaf5\"/>\n");
	/* The TABLE: one rectangle per run of same-owner squares in a row. */
	fprintf(f, "<g id=\"table\" stroke=\"none\">\n");
	for (int32_t y = 0; y < t->h; y++)
		for (int32_t x = 0; x < t->w;) {
			int32_t who = table_owner(t, x, y), x1 = x;
			while (x1 + 1 < t->w && table_owner(t, x1 + 1, y) == who)
				x1++;
			if (who != TABLE_FLOOR)
				fprintf(f, "<rect x=\"%.0f\" y=\"%.0f\" width=\"%.0f\" height=\"%d\" fill=\"%s\"/>\n", px(x),
					py(&fr, y + 1), px(x1 - x + 1), SVG_SCALE,
					who == TABLE_VERGE ? "#444444" : fill_of(w->objects[who - 1].colour));
			x = x1 + 1;
		}
	fprintf(f, "</g>\n");
	/* What Utak believes: the world model's boundaries. */
	const WorldModel *m = &c->model;
	fprintf(f, "<g id=\"model\">\n");
	for (int32_t r = 0; r < m->ring_count; r++) {
		const ModelRing *ring = &m->ring[r];
		Vec2 pts[WORLDMODEL_SIDE];
		int k = 0;
		for (int32_t i = 0; i <= ring->count && k < WORLDMODEL_SIDE; i++)
			pts[k++] = m->vertex[ring->first + i % ring->count].p;
		polyline(f, &fr, pts, k, true, "stroke=\"#1f78b4\" stroke-width=\"2\" stroke-dasharray=\"4 3\"");
	}
	fprintf(f, "</g>\n");
	/* The last plan's skeleton and pathgraph vertices, on the screen it was made on. */
	const Planner *p = &c->planner;
	if (p->have_graph && p->skeleton.w == c->screen.w && p->skeleton.h == c->screen.h) {
		fprintf(f, "<g id=\"skeleton\" fill=\"#33a02c\" fill-opacity=\"0.45\">\n");
		for (int32_t j = 0; j < p->skeleton.h; j++)
			for (int32_t i = 0; i < p->skeleton.w; i++)
				if (skeleton_on(&p->skeleton, i, j)) {
					Vec2 q = to_table(&fr, vec2(c->screen.x0 + i + 0.5, c->screen.y0 + j + 0.5));
					fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.1f\"/>\n", px(q.x), py(&fr, q.y),
						SVG_SCALE * 0.2);
				}
		for (int32_t v = 0; v < p->pathgraph.vertex_count; v++) {
			const PathgraphVertex *pv = &p->pathgraph.vertices[v];
			Vec2 q = to_table(&fr, vec2(c->screen.x0 + pv->x + 0.5, c->screen.y0 + pv->y + 0.5));
			fprintf(f, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"%.1f\" fill=\"#006d2c\" fill-opacity=\"1\"/>\n",
				px(q.x), py(&fr, q.y), SVG_SCALE * 0.4);
		}
		fprintf(f, "</g>\n");
	}
	/* The route he planned last, and the path he took. */
	if (c->route.count > 1)
		polyline(f, &fr, c->route.pts, c->route.count, true,
			 "id=\"route\" stroke=\"#ff7f00\" stroke-width=\"2\"");
	polyline(f, &fr, trail, n, false, "id=\"trail\" stroke=\"#e31a1c\" stroke-width=\"2.5\"");
	Vec2 u = trail[n - 1];
	fprintf(f, "<circle id=\"utak\" cx=\"%.2f\" cy=\"%.2f\" r=\"%d\" fill=\"#000000\"/>\n", px(u.x), py(&fr, u.y),
		SVG_SCALE / 2);
	fprintf(f, "</svg>\n");
}
