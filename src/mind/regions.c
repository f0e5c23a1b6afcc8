/* regions.c - region finding and interpretation of a retinal impression (paper 3.4.1, 3.4.2).
 * CONTROLLER SIDE: reads only the Impression and the eye's anatomy (eye.h).
 *
 * ALGORITHM. Regions: flood fill over the cells in cell order, spreading to
 * edge-adjacent cells of the same zero/non-zero kind (paper 3.4.1). Surrounding
 * (see regions.h): for each region A, flood from every border cell not in A through
 * cells not in A; the regions other than A left unreached are those A surrounds.
 * Interpretation follows paper 3.4.2 rule by rule; what no rule decides is
 * "uncertain", never guessed.
 * INVARIANT: every cell belongs to exactly one region; regions are numbered by
 * their lowest cell.
 * MEMORY: all inside Regions, fixed size. COMPLEXITY: O(R x C x N) for the
 * surround test, R regions, C = 160 cells, N <= EYE_MAX_NEIGHBOURS: small. */
#include "utak/mind/regions.h"

#include <string.h>

#include "utak/base/eye.h"

/* regions_reach(r, a, reached): marks the cells reachable from the border without
 * entering region a. */
static void regions_reach(const Regions *r, int32_t a, bool reached[RETINA_CELLS])
{
	int32_t stack[RETINA_CELLS], top = 0;
	memset(reached, 0, RETINA_CELLS * sizeof reached[0]);
	for (int32_t i = 0; i < RETINA_CELLS; i++)
		if (eye_on_border(i) && r->region_of[i] != a) {
			reached[i] = true;
			stack[top++] = i;
		}
	while (top > 0) {
		int32_t i = stack[--top];
		const int32_t *nb;
		int32_t n = eye_neighbours(i, &nb);
		for (int32_t k = 0; k < n; k++) {
			int32_t j = nb[k];
			if (!reached[j] && r->region_of[j] != a) {
				reached[j] = true;
				stack[top++] = j;
			}
		}
	}
}

bool regions_surrounds(const Regions *r, int32_t a, int32_t b)
{
	if (a == b || r->region[b].on_border)
		return false;
	bool reached[RETINA_CELLS];
	regions_reach(r, a, reached);
	for (int32_t i = 0; i < RETINA_CELLS; i++)
		if (r->region_of[i] == b && reached[i])
			return false;
	return true;
}

void regions_find(Regions *r, const Impression *imp)
{
	memset(r, 0, sizeof *r);
	for (int32_t i = 0; i < RETINA_CELLS; i++)
		r->region_of[i] = -1;
	int32_t utak_cell = eye_cell_at(0, 0);
	for (int32_t seed = 0; seed < RETINA_CELLS; seed++) {
		if (r->region_of[seed] >= 0)
			continue;
		int32_t id = r->count++;
		Region *g = &r->region[id];
		g->nonzero = imp->level[seed] > 0;
		g->first_cell = seed;
		g->surrounded_by = -1;
		int32_t stack[RETINA_CELLS], top = 0;
		r->region_of[seed] = id;
		stack[top++] = seed;
		while (top > 0) {
			int32_t i = stack[--top];
			EyeCell c = eye_cell(i);
			g->cells++;
			g->squares += c.size * c.size;
			g->on_border |= eye_on_border(i);
			g->has_utak |= i == utak_cell;
			const int32_t *nb;
			int32_t n = eye_neighbours(i, &nb);
			for (int32_t k = 0; k < n; k++) {
				int32_t j = nb[k];
				if (r->region_of[j] < 0 && (imp->level[j] > 0) == g->nonzero) {
					r->region_of[j] = id;
					stack[top++] = j;
				}
			}
		}
	}
	/* Who surrounds whom: one flood per region. */
	bool surrounds[RETINA_CELLS][RETINA_CELLS]; /* [a][b]: region a surrounds region b */
	memset(surrounds, 0, sizeof surrounds);
	for (int32_t a = 0; a < r->count; a++) {
		bool reached[RETINA_CELLS], seen_b[RETINA_CELLS];
		regions_reach(r, a, reached);
		for (int32_t b = 0; b < r->count; b++)
			seen_b[b] = false;
		for (int32_t i = 0; i < RETINA_CELLS; i++)
			if (reached[i])
				seen_b[r->region_of[i]] = true;
		for (int32_t b = 0; b < r->count; b++)
			surrounds[a][b] = b != a && !r->region[b].on_border && !seen_b[b];
	}
	for (int32_t b = 0; b < r->count; b++)
		for (int32_t a = 0; a < r->count; a++)
			if (surrounds[a][b] && !r->region[a].nonzero &&
			    r->region[b].surrounded_by < 0)
				r->region[b].surrounded_by = a;
	for (int32_t b = 0; b < r->count; b++) {
		Region *g = &r->region[b];
		if (!g->nonzero) {
			g->reading = REGION_FLOOR;
			r->floor_regions++;
			continue;
		}
		bool surrounds_floor = false;
		for (int32_t z = 0; z < r->count; z++)
			surrounds_floor |= !r->region[z].nonzero && surrounds[b][z];
		if (g->has_utak && g->cells == 1)
			g->reading = REGION_UTAK;
		else if (g->surrounded_by >= 0)
			g->reading = REGION_OBJECT;
		else if (surrounds_floor)
			g->reading = REGION_VERGE;
		else
			g->reading = REGION_UNCERTAIN;
	}
}

const char *regions_reading_name(RegionReading reading)
{
	static const char *const names[] = {"floor", "verge", "object", "utak", "uncertain"};
	return names[reading];
}

static char regions_letter(int32_t id)
{
	static const char letters[] = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ";
	return id < (int32_t)(sizeof letters - 1) ? letters[id] : '#';
}

void regions_dump(const Regions *r, FILE *f)
{
	fprintf(f, "regions %d, floor regions %d%s\n", (int)r->count, (int)r->floor_regions,
	        r->floor_regions > 1 ? " (connected beyond view)" : "");
	for (int32_t id = 0; id < r->count; id++) {
		const Region *g = &r->region[id];
		fprintf(f, "region %c %s %s cells %d squares %d%s", regions_letter(id),
		        g->nonzero ? "nonzero" : "zero", regions_reading_name(g->reading),
		        (int)g->cells, (int)g->squares, g->on_border ? " border" : "");
		if (g->has_utak && g->reading != REGION_UTAK)
			fputs(" with-utak", f);
		if (g->surrounded_by >= 0)
			fprintf(f, " in %c", regions_letter(g->surrounded_by));
		fputs(":", f);
		for (int32_t i = 0; i < RETINA_CELLS; i++)
			if (r->region_of[i] == id)
				fprintf(f, " %d", (int)i);
		fputc('\n', f);
	}
	for (int32_t row = 0; row < RETINA_FIELD; row++) {
		char line[RETINA_FIELD + 1];
		for (int32_t col = 0; col < RETINA_FIELD; col++) {
			int32_t ox, oy;
			eye_offset_of(col, row, &ox, &oy);
			line[col] = regions_letter(r->region_of[eye_cell_at(ox, oy)]);
		}
		line[RETINA_FIELD] = '\n';
		fwrite(line, 1, sizeof line, f);
	}
}
