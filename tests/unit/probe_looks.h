/* probe_looks.h - the probe's looks made by exact rasterisation, for the unit tests
 * of the probe (test_probe.c) and of what the senses tell of corners
 * (test_cutcorner.c): a polygon projected onto squares by the TABLE's own rule
 * (geom_project), pushed to each corner in turn with motion's error, and projected
 * again on the eye's grid; the looks go into sq_x, sq_y, sq_n, bx, by, nb, cells, nc
 * and looks. Test-only (issue 13, paper 3.3); include after probe.h. */
#ifndef UTAK_TEST_PROBE_LOOKS_H
#define UTAK_TEST_PROBE_LOOKS_H

enum { FIELD = 64, MOST = FIELD * FIELD, BUDGET = PROBE_BUDGET };
static int32_t sq_x[MOST], sq_y[MOST], sq_n;

static void span(void *ctx, int32_t y, int32_t x0, int32_t x1)
{
	(void)ctx;
	for (int32_t x = x0; x <= x1; x++) {
		sq_x[sq_n] = x;
		sq_y[sq_n++] = y;
	}
}

/* splitmix(seed): the next 64 bits of SplitMix64 (Steele, Lea and Flood 2014), as
 * motion.h draws them. */
static uint64_t splitmix(uint64_t *seed)
{
	uint64_t z = (*seed += 0x9e3779b97f4a7c15u);
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
	return z ^ (z >> 31);
}

/* uniform(seed): in [0, 1). */
static double uniform(uint64_t *seed)
{
	return (double)(splitmix(seed) >> 11) / 9007199254740992.0;
}

/* gaussian(seed): a standard Gaussian (SplitMix64 and Box-Muller, as motion.h). */
static double gaussian(uint64_t *seed)
{
	double u[2];
	for (int i = 0; i < 2; i++)
		u[i] = ((double)(splitmix(seed) >> 11) + 0.5) / 9007199254740992.0;
	return sqrt(-2 * log(u[0])) * cos(6.283185307179586 * u[1]);
}

static Polygon moved(const Polygon *p, double dx, double dy)
{
	Polygon q = *p;
	for (int i = 0; i < q.count; i++)
		q.v[i] = vec2(q.v[i].x + dx, q.v[i].y + dy);
	return q;
}

/* Noise the disparity has not shown: the controller's slack is PROBE_SLACK_RATE
 * whatever sigma is (probe.h); else at least 4 sigma, as when it has. */
static bool unseen_noise;

/* probe(p, corners, n, sigma, f, size, seed): p seen, then pushed to each of the n
 * corners in turn, each push going astray by a Gaussian of sigma squares per
 * square pushed (motion.h), and seen after each in cells of `size`, the eye's grid
 * on Utak's square: his point starts at f within his square (0, 0) and moves with
 * the object. Judged as the controller does: slack PROBE_SLACK_RATE (at least
 * 4 sigma, but for unseen_noise) times the root of the squared lengths pushed, the
 * point unplaced; the error between two looks within the rate times the root of
 * the squared lengths pushed between them (ProbeLook.rate). */
static int32_t bx[MOST], by[MOST], nb, nc;
static ProbeCell cells[PROBE_LOOKS * MOST / 4];
static ProbeLook looks[PROBE_LOOKS];

/* observe(...): probe's looks, into bx, by, nb, cells, nc and looks. */
static void observe(const Polygon *p, const Vec2 *corners, int n, double sigma, Vec2 f, int32_t size,
		    uint64_t *seed)
{
	static uint8_t own[MOST];
	sq_n = 0;
	geom_project(p, FIELD, FIELD, span, NULL);
	nb = sq_n;
	memcpy(bx, sq_x, sizeof bx[0] * (size_t)nb);
	memcpy(by, sq_y, sizeof by[0] * (size_t)nb);
	int32_t x0 = FIELD, y0 = FIELD, x1 = 0, y1 = 0;
	for (int32_t i = 0; i < nb; i++) {
		x0 = bx[i] < x0 ? bx[i] : x0;
		y0 = by[i] < y0 ? by[i] : y0;
		x1 = bx[i] > x1 ? bx[i] : x1;
		y1 = by[i] > y1 ? by[i] : y1;
	}
	nc = 0;
	Vec2 at = vec2(0, 0), err = vec2(0, 0);
	double pushed_sq = 0, rate = unseen_noise ? PROBE_SLACK_RATE : fmax(PROBE_SLACK_RATE, 4 * sigma);
	for (int l = 0; l < n; l++) {
		Vec2 step = vec2_sub(corners[l], at);
		double len = hypot(step.x, step.y);
		pushed_sq += len * len;
		err = vec2_add(err, vec2(sigma * len * gaussian(seed), sigma * len * gaussian(seed)));
		at = corners[l];
		looks[l] = (ProbeLook){corners[l], rate * sqrt(pushed_sq), PROBE_ANY_SHIFT, rate};
		Polygon q = moved(p, at.x + err.x, at.y + err.y);
		/* The eye's grid: Utak's square now, from his first (0, 0). */
		int32_t gx = (int32_t)floor(f.x + at.x + err.x), gy = (int32_t)floor(f.y + at.y + err.y);
		sq_n = 0;
		geom_project(&q, FIELD, FIELD, span, NULL);
		memset(own, 0, sizeof own);
		for (int32_t i = 0; i < sq_n; i++)
			own[sq_y[i] * FIELD + sq_x[i]] = 1;
		/* Cells on the grid seen, recorded as if it had not moved. */
		for (int32_t y = ((y0 - 2) & ~1); y <= y1 + 2; y += size)
			for (int32_t x = ((x0 - 2) & ~1); x <= x1 + 2; x += size) {
				int32_t k = 0;
				for (int32_t j = 0; j < size; j++)
					for (int32_t i = 0; i < size; i++)
						k += own[(y + gy + j) * FIELD + x + gx + i];
				cells[nc++] = (ProbeCell){x, y, size, k, l};
			}
	}
}

#endif
