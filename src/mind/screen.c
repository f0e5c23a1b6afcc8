/* screen.c - projecting the world model onto the screen (paper 3.2, 3.6). CONTROLLER SIDE.
 *
 * The world model's belief about each square (worldmodel_belief) decides the
 * cell: floor is space, never seen is unknown, occupied is an object when it lies
 * in the containing rectangle of one of the model's object nodes (the name of the
 * object over it, paper 3.6), else verge. COMPLEXITY: one pass over the screen's
 * cells (the window of what was seen is kept by the model). */
#include "utak/mind/screen.h"

#include <math.h>
#include <stdlib.h>

#include "utak/base/util.h"

void screen_init(Screen *s) { *s = (Screen){0}; }

void screen_free(Screen *s)
{
	free(s->label);
	grid_free(&s->free);
	grid_free(&s->fixed);
	*s = (Screen){0};
}

int32_t screen_label(const Screen *s, int32_t i, int32_t j)
{
	if (i < 0 || j < 0 || i >= s->w || j >= s->h)
		return SCREEN_VERGE;
	return s->label[(int64_t)j * s->w + i];
}

/* object_at(m, x, y): the object node whose squares hold square (x, y), or -1.
 * (Occupied sets the model cannot yet read, its uncertain nodes, count as verge:
 * planning treats them as fixed until they are seen to be objects; so do those
 * touch has shown to be wall, m->wall_ident.) */
static int32_t object_at(const WorldModel *m, int32_t x, int32_t y)
{
	int32_t k = worldmodel_node_at(m, x, y);
	if (k < 0 || m->node[k].kind != NODE_OBJECT)
		return -1;
	for (int32_t w = 0; w < m->wall_count; w++)
		if (m->wall_ident[w] == m->node[k].ident)
			return -1;
	return k;
}

void screen_build(Screen *s, const WorldModel *m, const Vec2 *extra, int n)
{
	screen_free(s);
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	int32_t lo_x = ux, lo_y = uy, hi_x = ux, hi_y = uy;
	if (m->seen_count > 0) { /* everything seen, kept by the model */
		lo_x = m->seen_x0 < lo_x ? m->seen_x0 : lo_x;
		hi_x = m->seen_x1 > hi_x ? m->seen_x1 : hi_x;
		lo_y = m->seen_y0 < lo_y ? m->seen_y0 : lo_y;
		hi_y = m->seen_y1 > hi_y ? m->seen_y1 : hi_y;
	}
	for (int i = 0; i < n; i++) {
		int32_t x = (int32_t)floor(extra[i].x), y = (int32_t)floor(extra[i].y);
		lo_x = x < lo_x ? x : lo_x;
		hi_x = x > hi_x ? x : hi_x;
		lo_y = y < lo_y ? y : lo_y;
		hi_y = y > hi_y ? y : hi_y;
	}
	s->x0 = lo_x - SCREEN_MARGIN;
	s->y0 = lo_y - SCREEN_MARGIN;
	s->w = hi_x - lo_x + 1 + 2 * SCREEN_MARGIN;
	s->h = hi_y - lo_y + 1 + 2 * SCREEN_MARGIN;
	s->label = util_alloc((size_t)s->w * (size_t)s->h, sizeof *s->label);
	grid_init(&s->free, s->w, s->h, GRID_BLOCKED);
	grid_init(&s->fixed, s->w, s->h, GRID_BLOCKED);
	for (int32_t j = 0; j < s->h; j++)
		for (int32_t i = 0; i < s->w; i++) {
			int64_t k = (int64_t)j * s->w + i;
			int32_t x = s->x0 + i, y = s->y0 + j, label;
			switch (worldmodel_belief(m, x, y)) {
			case BELIEF_FLOOR:
				label = SCREEN_SPACE;
				break;
			case BELIEF_UNKNOWN:
				label = SCREEN_UNKNOWN;
				break;
			default:
				label = object_at(m, x, y);
				if (label < 0)
					label = SCREEN_VERGE;
			}
			s->label[k] = label;
			s->free.cells[k] = label == SCREEN_SPACE || label == SCREEN_UNKNOWN ? GRID_FREE : GRID_BLOCKED;
			s->fixed.cells[k] = label == SCREEN_VERGE ? GRID_BLOCKED : GRID_FREE;
		}
	/* Utak's own square, and the object he holds: touch shows its letter, so it is
	 * an object, space to the rooms, even where the model cannot part it from a
	 * wall it is pressed against (pushed into a corner, its set joins the verge:
	 * counted as wall, it would cut the corner beyond it off the room). */
	s->fixed.cells[(int64_t)(uy - s->y0) * s->w + (ux - s->x0)] = GRID_FREE;
	for (int32_t h = 0; m->holding && h < m->held_count; h++) {
		int32_t i = ux + m->held_dx[h] - s->x0, j = uy + m->held_dy[h] - s->y0;
		if (i >= 0 && j >= 0 && i < s->w && j < s->h)
			s->fixed.cells[(int64_t)j * s->w + i] = GRID_FREE;
	}
}

void screen_dump(const Screen *s, const WorldModel *m, FILE *f)
{
	int32_t ux, uy;
	worldmodel_utak_square(m, &ux, &uy);
	fprintf(f, "screen %d x %d, cell (0, 0) = model square (%d, %d), north at the top:\n", (int)s->w,
		(int)s->h, (int)s->x0, (int)s->y0);
	char *line = util_alloc((size_t)s->w + 2, 1);
	for (int32_t j = s->h - 1; j >= 0; j--) {
		for (int32_t i = 0; i < s->w; i++) {
			int32_t label = s->label[(int64_t)j * s->w + i];
			char c = label == SCREEN_SPACE ? '.' : label == SCREEN_UNKNOWN ? '?' : label == SCREEN_VERGE ? '#'
				 : (char)('a' + (m->node[label].ident - 1) % 26);
			if (s->x0 + i == ux && s->y0 + j == uy)
				c = '@';
			line[i] = c;
		}
		line[s->w] = '\n';
		fwrite(line, 1, (size_t)s->w + 1, f);
	}
	free(line);
}
