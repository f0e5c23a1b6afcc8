/* movingai.c - readers for the Moving AI .map and .scen files (see movingai.h), the
 * benchmark input of the paper 4.1 comparison. Not an algorithm: careful parsing,
 * one "FILE:LINE: message" per error. */
#include "utak/plan/movingai.h"

#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

/* The longest line accepted: a row of the largest map we plan on plus slack. */
#define MOVINGAI_MAX_LINE 65536
/* The largest side accepted: keeps w * h well inside int32_t cell indices. */
#define MOVINGAI_MAX_SIDE 16384

double movingai_tolerance(double optimum)
{
	return 1e-3 + 1e-5 * optimum;
}

static void movingai_error(char *err, const char *path, long line, const char *fmt, ...)
{
	char msg[256];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	if (line > 0)
		snprintf(err, MOVINGAI_ERROR_SIZE, "%s:%ld: %s", path, line, msg);
	else
		snprintf(err, MOVINGAI_ERROR_SIZE, "%s: %s", path, msg);
}

/* movingai_getline: the next line without its CR/LF; false at end of file. A line
 * longer than the buffer is an error, reported through *too_long. */
static bool movingai_getline(FILE *f, char *buf, size_t size, bool *too_long)
{
	*too_long = false;
	if (!fgets(buf, (int)size, f))
		return false;
	size_t n = strlen(buf);
	if (n == size - 1 && buf[n - 1] != '\n' && !feof(f)) {
		*too_long = true;
		return true;
	}
	while (n > 0 && (buf[n - 1] == '\n' || buf[n - 1] == '\r'))
		buf[--n] = '\0';
	return true;
}

/* movingai_header_int: parses "KEY N" with 1 <= N <= MOVINGAI_MAX_SIDE. */
static bool movingai_header_int(const char *line, const char *key, int32_t *out)
{
	size_t k = strlen(key);
	if (strncmp(line, key, k) != 0 || line[k] != ' ')
		return false;
	char *end;
	errno = 0;
	long v = strtol(line + k + 1, &end, 10);
	if (errno || *end != '\0' || v < 1 || v > MOVINGAI_MAX_SIDE)
		return false;
	*out = (int32_t)v;
	return true;
}

bool movingai_read_map(const char *path, Grid *grid, char err[MOVINGAI_ERROR_SIZE])
{
	*grid = (Grid){0};
	FILE *f = fopen(path, "r");
	if (!f) {
		movingai_error(err, path, 0, "cannot open: %s", strerror(errno));
		return false;
	}
	char *buf = util_alloc(MOVINGAI_MAX_LINE, 1);
	bool too_long, ok = false;
	long line = 0;
	int32_t w = 0, h = 0;
	static const char *const want[4] = {"type octile", "height", "width", "map"};
	for (int i = 0; i < 4; i++) {
		line++;
		if (!movingai_getline(f, buf, MOVINGAI_MAX_LINE, &too_long) || too_long) {
			movingai_error(err, path, line, "expected \"%s\" in the header", want[i]);
			goto out;
		}
		bool good = i == 1   ? movingai_header_int(buf, "height", &h)
		            : i == 2 ? movingai_header_int(buf, "width", &w)
		                     : strcmp(buf, want[i]) == 0;
		if (!good) {
			movingai_error(err, path, line,
			               i == 1 || i == 2 ? "expected \"%s N\" with 1 <= N <= 16384"
			                                : "expected \"%s\"",
			               want[i]);
			goto out;
		}
	}
	grid_init(grid, w, h, GRID_BLOCKED);
	for (int32_t y = 0; y < h; y++) {
		line++;
		if (!movingai_getline(f, buf, MOVINGAI_MAX_LINE, &too_long)) {
			movingai_error(err, path, line, "the map has %d rows, the header says %d",
			               (int)y, (int)h);
			goto out;
		}
		size_t n = too_long ? MOVINGAI_MAX_LINE : strlen(buf);
		if (n != (size_t)w) {
			movingai_error(err, path, line, "row of %zu cells, the header says %d", n,
			               (int)w);
			goto out;
		}
		for (int32_t x = 0; x < w; x++) {
			char c = buf[x];
			if (c == '.' || c == 'G' || c == 'S')
				grid->cells[(size_t)y * w + x] = GRID_FREE;
			else if (c == '@' || c == 'O' || c == 'T' || c == 'W')
				grid->cells[(size_t)y * w + x] = GRID_BLOCKED;
			else {
				movingai_error(err, path, line, "column %d: unknown terrain '%c'",
				               (int)x + 1, c);
				goto out;
			}
		}
	}
	/* Anything after the rows must be blank. */
	while (movingai_getline(f, buf, MOVINGAI_MAX_LINE, &too_long)) {
		line++;
		if (too_long || buf[strspn(buf, " \t")] != '\0') {
			movingai_error(err, path, line, "text after the %d rows of the map",
			               (int)h);
			goto out;
		}
	}
	ok = true;
out:
	free(buf);
	fclose(f);
	if (!ok)
		grid_free(grid);
	return ok;
}

void movingai_scen_free(MovingAiScen *scen)
{
	free(scen->problems);
	*scen = (MovingAiScen){0};
}

/* movingai_field_int / _double: parse a whole TAB-separated field. */
static bool movingai_field_int(const char *s, long lo, long hi, int32_t *out)
{
	char *end;
	errno = 0;
	long v = strtol(s, &end, 10);
	if (errno || end == s || *end != '\0' || v < lo || v > hi)
		return false;
	*out = (int32_t)v;
	return true;
}

static bool movingai_field_double(const char *s, double *out)
{
	char *end;
	errno = 0;
	double v = strtod(s, &end);
	if (errno || end == s || *end != '\0' || !(v >= 0) || v > 1e9)
		return false;
	*out = v;
	return true;
}

bool movingai_read_scen(const char *path, const Grid *grid, MovingAiScen *scen,
                        char err[MOVINGAI_ERROR_SIZE])
{
	*scen = (MovingAiScen){0};
	scen->map_w = grid->w;
	scen->map_h = grid->h;
	FILE *f = fopen(path, "r");
	if (!f) {
		movingai_error(err, path, 0, "cannot open: %s", strerror(errno));
		return false;
	}
	char *buf = util_alloc(MOVINGAI_MAX_LINE, 1);
	bool too_long, ok = false;
	long line = 1;
	if (!movingai_getline(f, buf, MOVINGAI_MAX_LINE, &too_long) || too_long ||
	    (strcmp(buf, "version 1") != 0 && strcmp(buf, "version 1.0") != 0)) {
		movingai_error(err, path, line, "expected \"version 1\"");
		goto out;
	}
	while (movingai_getline(f, buf, MOVINGAI_MAX_LINE, &too_long)) {
		line++;
		if (too_long) {
			movingai_error(err, path, line, "line too long");
			goto out;
		}
		if (buf[strspn(buf, " \t")] == '\0')
			continue;
		char *field[9];
		int nf = 0;
		for (char *p = buf;; p++) {
			if (nf < 9)
				field[nf] = p;
			nf++;
			p = strchr(p, '\t');
			if (!p)
				break;
			*p = '\0';
		}
		if (nf != 9) {
			movingai_error(err, path, line, "%d TAB-separated fields, expected 9", nf);
			goto out;
		}
		MovingAiProblem pr = {.line = (int32_t)line};
		int32_t mw, mh;
		if (!movingai_field_int(field[0], 0, INT32_MAX, &pr.bucket)) {
			movingai_error(err, path, line, "field 1: bad bucket \"%s\"", field[0]);
			goto out;
		}
		if (!movingai_field_int(field[2], 1, MOVINGAI_MAX_SIDE, &mw) ||
		    !movingai_field_int(field[3], 1, MOVINGAI_MAX_SIDE, &mh) || mw != grid->w ||
		    mh != grid->h) {
			movingai_error(
			    err, path, line,
			    "map size \"%s x %s\" (width, height) differs from the map's "
			    "%d x %d",
			    field[2], field[3], (int)grid->w, (int)grid->h);
			goto out;
		}
		int32_t *coord[4] = {&pr.sx, &pr.sy, &pr.gx, &pr.gy};
		for (int i = 0; i < 4; i++) {
			int32_t hi = (i % 2 == 0 ? grid->w : grid->h) - 1;
			if (!movingai_field_int(field[4 + i], 0, hi, coord[i])) {
				movingai_error(err, path, line,
				               "field %d: \"%s\" is not a %s inside the map", 5 + i,
				               field[4 + i], i % 2 == 0 ? "column" : "row");
				goto out;
			}
		}
		if (!grid_free_at(grid, pr.sx, pr.sy) || !grid_free_at(grid, pr.gx, pr.gy)) {
			movingai_error(err, path, line, "the %s cell is blocked on the map",
			               grid_free_at(grid, pr.sx, pr.sy) ? "goal" : "start");
			goto out;
		}
		if (!movingai_field_double(field[8], &pr.optimum)) {
			movingai_error(err, path, line, "field 9: bad length \"%s\"", field[8]);
			goto out;
		}
		scen->problems =
		    util_grow(scen->problems, &scen->cap, scen->count + 1, sizeof *scen->problems);
		scen->problems[scen->count++] = pr;
	}
	ok = true;
out:
	free(buf);
	fclose(f);
	if (!ok)
		movingai_scen_free(scen);
	return ok;
}
