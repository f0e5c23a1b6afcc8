/* world.c - the world-file reader and writer (paper 2.1; grammar in man/utak.5). SIMULATOR SIDE.
 *
 * A world file is read whole into memory, then line by line: each line is cut
 * into words with their columns, and each statement checked as it is read, so
 * that every complaint can name the file, line and column of the word at fault.
 * Nothing is defaulted silently: a missing `table` or `utak` is an error; the
 * verge alone has a default (the outermost ring of squares), as documented. */
#include "utak/body/world.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

enum { MAX_WORDS = 2 * GEOM_MAX_VERTICES + 8 }; /* enough for the longest statement, plus spare */

typedef struct Word {
	const char *s;	/* not NUL-terminated */
	int32_t len;
	int32_t col;	/* 1-based column */
} Word;

typedef struct Reader {
	World *w;
	Diag *d;
	const char *name;
	int32_t line;
	Word words[MAX_WORDS + 1];
	int32_t count;		/* words on this line (capped at MAX_WORDS + 1) */
	int32_t table_line, verge_line;
	int walls_cap, objects_cap;
} Reader;

static int fail(Reader *r, int col, const char *fmt, const char *arg)
{
	char msg[DIAG_SIZE];
	snprintf(msg, sizeof msg, fmt, arg);
	return diag_set(r->d, r->name, r->line, col, "%s", msg);
}

static bool word_is(const Word *w, const char *s)
{
	return (size_t)w->len == strlen(s) && memcmp(w->s, s, (size_t)w->len) == 0;
}

/* word_text: a printable copy of a word for messages, cut short when long. */
static const char *word_text(const Word *w, char *buf, size_t size)
{
	size_t n = (size_t)w->len < size - 4 ? (size_t)w->len : size - 4;
	memcpy(buf, w->s, n);
	strcpy(buf + n, (size_t)w->len > n ? "..." : "");
	return buf;
}

/* split_line(r, s, len): cuts a line into words; '#' starts a comment. */
static int split_line(Reader *r, const char *s, int32_t len)
{
	r->count = 0;
	for (int32_t i = 0; i < len;) {
		unsigned char c = (unsigned char)s[i];
		if (c == '#')
			break;
		if (c == ' ' || c == '\t') {
			i++;
			continue;
		}
		if (c < 0x21 || c > 0x7e)
			return diag_set(r->d, r->name, r->line, i + 1,
					"unexpected byte 0x%02x (a world file is plain ASCII text)", c);
		int32_t j = i;
		while (j < len && s[j] != ' ' && s[j] != '\t' && s[j] != '#' &&
		       (unsigned char)s[j] >= 0x21 && (unsigned char)s[j] <= 0x7e)
			j++;
		if (r->count <= MAX_WORDS)
			r->words[r->count] = (Word){s + i, j - i, i + 1};
		r->count++;
		i = j;
	}
	return 0;
}

/* parse_number(r, w, &v): a decimal real: digits, an optional fraction, an
 * optional exponent. Negative, non-finite and malformed numbers are errors. */
static int parse_number(Reader *r, const Word *w, double *v)
{
	char buf[64], shown[40];
	const char *s = w->s;
	int32_t i = 0, n = w->len, digits = 0;
	if (i < n && (s[i] == '-' || s[i] == '+'))
		i++;
	while (i < n && s[i] >= '0' && s[i] <= '9')
		i++, digits++;
	if (i < n && s[i] == '.')
		for (i++; i < n && s[i] >= '0' && s[i] <= '9'; i++)
			digits++;
	if (digits > 0 && i < n && (s[i] == 'e' || s[i] == 'E')) {
		int32_t j = i + 1;
		if (j < n && (s[j] == '-' || s[j] == '+'))
			j++;
		if (j < n && s[j] >= '0' && s[j] <= '9') {
			while (j < n && s[j] >= '0' && s[j] <= '9')
				j++;
			i = j;
		}
	}
	if (digits == 0 || i != n || n >= (int32_t)sizeof buf)
		return fail(r, w->col, "expected a number, found '%s'", word_text(w, shown, sizeof shown));
	memcpy(buf, s, (size_t)n);
	buf[n] = 0;
	errno = 0;
	*v = strtod(buf, NULL);
	if (!isfinite(*v))
		return fail(r, w->col, "number '%s' is out of range", word_text(w, shown, sizeof shown));
	if (*v < 0)
		return fail(r, w->col, "negative number '%s' (coordinates start at 0)",
			    word_text(w, shown, sizeof shown));
	if (*v == 0)
		*v = 0; /* no negative zero */
	return 0;
}

/* parse_points(r, first, p): words first.. as x y pairs inside the TABLE. */
static int parse_points(Reader *r, int32_t first, Polygon *p, const char *what)
{
	int32_t n = r->count - first;
	char msg[96];
	if (n % 2 != 0) {
		snprintf(msg, sizeof msg, "%s has an odd number of coordinates (%d)", what, (int)n);
		return fail(r, r->words[r->count > MAX_WORDS ? MAX_WORDS : r->count - 1].col, "%s", msg);
	}
	if (n / 2 < 3) {
		snprintf(msg, sizeof msg, "%s needs at least 3 points, found %d", what, (int)(n / 2));
		return fail(r, r->words[0].col, "%s", msg);
	}
	if (n / 2 > GEOM_MAX_VERTICES) {
		snprintf(msg, sizeof msg, "%s has %d points; the most is %d", what, (int)(n / 2),
			 GEOM_MAX_VERTICES);
		return fail(r, r->words[0].col, "%s", msg);
	}
	p->count = n / 2;
	for (int32_t i = 0; i < p->count; i++) {
		const Word *wx = &r->words[first + 2 * i], *wy = wx + 1;
		if (parse_number(r, wx, &p->v[i].x) || parse_number(r, wy, &p->v[i].y))
			return -1;
		if (p->v[i].x > r->w->w || p->v[i].y > r->w->h) {
			snprintf(msg, sizeof msg, "point (%g, %g) lies outside the %d x %d TABLE",
				 p->v[i].x, p->v[i].y, (int)r->w->w, (int)r->w->h);
			return fail(r, wx->col, "%s", msg);
		}
	}
	if (!geom_polygon_is_simple(p)) {
		snprintf(msg, sizeof msg, "%s is not a simple polygon (its edges cross or overlap)", what);
		return fail(r, r->words[first].col, "%s", msg);
	}
	return 0;
}

static int need_words(Reader *r, int32_t want, const char *usage)
{
	char msg[128];
	if (r->count < want) {
		snprintf(msg, sizeof msg, "too few words: expected '%s'", usage);
		return fail(r, r->words[r->count - 1].col, "%s", msg);
	}
	if (r->count > want) {
		snprintf(msg, sizeof msg, "too many words: expected '%s'", usage);
		return fail(r, r->words[want].col, "%s", msg);
	}
	return 0;
}

static int statement_table(Reader *r)
{
	if (r->table_line > 0) {
		char msg[64];
		snprintf(msg, sizeof msg, "repeated 'table' (first given on line %d)", (int)r->table_line);
		return fail(r, r->words[0].col, "%s", msg);
	}
	if (need_words(r, 3, "table W H"))
		return -1;
	double v[2];
	for (int i = 0; i < 2; i++) {
		const Word *w = &r->words[1 + i];
		char shown[40];
		if (parse_number(r, w, &v[i]))
			return -1;
		if (v[i] != floor(v[i]) || v[i] < 1)
			return fail(r, w->col, "the TABLE's size must be a whole number of squares, found '%s'",
				    word_text(w, shown, sizeof shown));
		if (v[i] > WORLD_MAX_SIDE)
			return diag_set(r->d, r->name, r->line, w->col,
					"TABLE side %.0f is over the limit of %d squares", v[i], WORLD_MAX_SIDE);
	}
	if (v[0] < 3 || v[1] < 3)
		return fail(r, r->words[1].col, "%s", "the TABLE must be at least 3 x 3 squares");
	if (v[0] * v[1] > WORLD_MAX_SQUARES)
		return diag_set(r->d, r->name, r->line, r->words[1].col,
				"TABLE of %.0f x %.0f squares is over the limit of %d squares", v[0], v[1],
				WORLD_MAX_SQUARES);
	r->w->w = (int32_t)v[0];
	r->w->h = (int32_t)v[1];
	r->table_line = r->line;
	/* The default verge: the outermost ring of squares (man utak.5). */
	Polygon *g = &r->w->verge;
	g->count = 4;
	g->v[0] = vec2(1, 1);
	g->v[1] = vec2(v[0] - 1, 1);
	g->v[2] = vec2(v[0] - 1, v[1] - 1);
	g->v[3] = vec2(1, v[1] - 1);
	return 0;
}

static int statement_verge(Reader *r)
{
	if (r->verge_line > 0) {
		char msg[64];
		snprintf(msg, sizeof msg, "repeated 'verge' (first given on line %d)", (int)r->verge_line);
		return fail(r, r->words[0].col, "%s", msg);
	}
	if (parse_points(r, 1, &r->w->verge, "the verge"))
		return -1;
	r->w->verge_given = true;
	r->verge_line = r->line;
	return 0;
}

static int statement_wall(Reader *r)
{
	World *w = r->w;
	if (w->wall_count >= WORLD_MAX_OBJECTS)
		return diag_set(r->d, r->name, r->line, 1, "too many walls; the most is %d", WORLD_MAX_OBJECTS);
	Polygon p;
	if (parse_points(r, 1, &p, "a wall"))
		return -1;
	int cap = r->walls_cap;
	w->walls = util_grow(w->walls, &r->walls_cap, w->wall_count + 1, sizeof *w->walls);
	w->wall_lines = util_grow(w->wall_lines, &cap, w->wall_count + 1, sizeof *w->wall_lines);
	w->walls[w->wall_count] = p;
	w->wall_lines[w->wall_count++] = r->line;
	return 0;
}

static bool is_name(const Word *w)
{
	if (!((w->s[0] >= 'a' && w->s[0] <= 'z') || (w->s[0] >= 'A' && w->s[0] <= 'Z') || w->s[0] == '_'))
		return false;
	for (int32_t i = 1; i < w->len; i++) {
		char c = w->s[i];
		if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
		      c == '_' || c == '-'))
			return false;
	}
	return true;
}

static int statement_object(Reader *r)
{
	World *w = r->w;
	char shown[40];
	if (r->count < 3)
		return fail(r, r->words[r->count - 1].col, "%s",
			    "too few words: expected 'object NAME COLOUR X1 Y1 ... Xn Yn'");
	const Word *name = &r->words[1], *colour = &r->words[2];
	if (!is_name(name))
		return fail(r, name->col, "bad object name '%s' (a letter or _, then letters, digits, _ or -)",
			    word_text(name, shown, sizeof shown));
	if (name->len > WORLD_MAX_NAME)
		return diag_set(r->d, r->name, r->line, name->col, "object name is over %d characters",
				WORLD_MAX_NAME);
	for (int32_t i = 0; i < w->object_count; i++)
		if (word_is(name, w->objects[i].name))
			return diag_set(r->d, r->name, r->line, name->col,
					"object name '%s' is already used on line %d", w->objects[i].name,
					(int)w->objects[i].line);
	if (colour->len != 1 || colour->s[0] < 'A' || colour->s[0] > 'Z')
		return fail(r, colour->col, "bad colour '%s' (one capital letter A-Z)",
			    word_text(colour, shown, sizeof shown));
	if (colour->s[0] == 'B')
		return fail(r, colour->col, "%s", "colour B is the verge's; an object takes another letter");
	if (w->object_count >= WORLD_MAX_OBJECTS)
		return diag_set(r->d, r->name, r->line, 1, "too many objects; the most is %d",
				WORLD_MAX_OBJECTS);
	WorldObject o = {0};
	memcpy(o.name, name->s, (size_t)name->len);
	o.colour = colour->s[0];
	o.line = r->line;
	if (parse_points(r, 3, &o.shape, "an object"))
		return -1;
	w->objects = util_grow(w->objects, &r->objects_cap, w->object_count + 1, sizeof *w->objects);
	w->objects[w->object_count++] = o;
	return 0;
}

static int statement_utak(Reader *r)
{
	World *w = r->w;
	if (w->utak_line > 0) {
		char msg[64];
		snprintf(msg, sizeof msg, "repeated 'utak' (first given on line %d)", (int)w->utak_line);
		return fail(r, r->words[0].col, "%s", msg);
	}
	if (need_words(r, 4, "utak X Y HEADING"))
		return -1;
	double x, y;
	if (parse_number(r, &r->words[1], &x) || parse_number(r, &r->words[2], &y))
		return -1;
	if (x >= w->w || y >= w->h)
		return diag_set(r->d, r->name, r->line, r->words[1].col,
				"Utak's point (%g, %g) lies outside the %d x %d TABLE", x, y, (int)w->w,
				(int)w->h);
	static const char *const names[4] = {"north", "east", "south", "west"};
	const Word *h = &r->words[3];
	int k = 0;
	while (k < 4 && !word_is(h, names[k]))
		k++;
	if (k == 4) {
		char shown[40];
		return fail(r, h->col, "bad heading '%s' (north, east, south or west)",
			    word_text(h, shown, sizeof shown));
	}
	w->utak = vec2(x, y);
	w->heading = (Heading)k;
	w->utak_line = r->line;
	return 0;
}

static int statement(Reader *r)
{
	const Word *k = &r->words[0];
	char shown[40];
	if (r->table_line == 0 && !word_is(k, "table")) {
		if (word_is(k, "verge") || word_is(k, "wall") || word_is(k, "object") || word_is(k, "utak"))
			return fail(r, k->col, "'%s' before 'table' (the TABLE's size must come first)",
				    word_text(k, shown, sizeof shown));
	}
	if (r->count > MAX_WORDS) {
		/* Past the words kept: say it as parse_points would, in points. */
		bool object = word_is(k, "object"), polygon = object || word_is(k, "wall") || word_is(k, "verge");
		if (!polygon)
			return diag_set(r->d, r->name, r->line, r->words[MAX_WORDS].col, "too many words (%d)",
					(int)r->count);
		return diag_set(r->d, r->name, r->line, r->words[MAX_WORDS].col, "%s has %d points; the most is %d",
				object ? "an object" : word_is(k, "wall") ? "a wall" : "the verge",
				(int)(r->count - (object ? 3 : 1)) / 2, GEOM_MAX_VERTICES);
	}
	if (word_is(k, "table"))
		return statement_table(r);
	if (word_is(k, "verge"))
		return statement_verge(r);
	if (word_is(k, "wall"))
		return statement_wall(r);
	if (word_is(k, "object"))
		return statement_object(r);
	if (word_is(k, "utak"))
		return statement_utak(r);
	return fail(r, k->col, "unknown keyword '%s' (table, verge, wall, object or utak)",
		    word_text(k, shown, sizeof shown));
}

int world_parse(World *w, const char *name, const char *text, size_t len, Diag *d)
{
	*w = (World){0};
	w->held = -1;
	snprintf(w->file, sizeof w->file, "%s", name);
	Reader r = {.w = w, .d = d, .name = name};
	if (len > WORLD_MAX_BYTES)
		return diag_set(d, name, 0, 0, "file is over the limit of %d bytes", WORLD_MAX_BYTES);
	if (memchr(text, 0, len)) {
		const char *z = memchr(text, 0, len);
		int32_t line = 1, col = 1;
		for (const char *s = text; s < z; s++) {
			line += *s == '\n';
			col = *s == '\n' ? 1 : col + 1;
		}
		world_free(w);
		return diag_set(d, name, line, col, "binary data (a NUL byte); a world file is text");
	}
	size_t at = 0;
	int status = 0;
	while (at < len && status == 0) {
		const char *s = text + at, *nl = memchr(s, '\n', len - at);
		size_t n = nl ? (size_t)(nl - s) : len - at;
		at += n + 1;
		r.line++;
		if (n > 0 && s[n - 1] == '\r')
			n--;
		if (n > WORLD_MAX_LINE) {
			status = diag_set(d, name, r.line, WORLD_MAX_LINE + 1,
					  "line is over the limit of %d characters", WORLD_MAX_LINE);
			break;
		}
		status = split_line(&r, s, (int32_t)n);
		if (status == 0 && r.count > 0)
			status = statement(&r);
	}
	if (status == 0 && r.table_line == 0)
		status = diag_set(d, name, 0, 0, len == 0 ? "empty world file (it needs 'table' and 'utak')"
							    : "no 'table' statement");
	if (status == 0 && w->utak_line == 0)
		status = diag_set(d, name, 0, 0, "no 'utak' statement (where is Utak?)");
	if (status != 0)
		world_free(w);
	return status;
}

int world_read_stream(World *w, const char *name, FILE *f, Diag *d)
{
	*w = (World){0};
	char *buf;
	size_t len;
	if (util_read_stream(f, WORLD_MAX_BYTES, &buf, &len) != 0)
		return diag_set(d, name, 0, 0, "cannot read (is it a directory?)");
	int status = world_parse(w, name, buf, len, d);
	free(buf);
	return status;
}

int world_read(World *w, const char *path, Diag *d)
{
	*w = (World){0};
	FILE *f = fopen(path, "rb");
	if (!f)
		return diag_set(d, path, 0, 0, "cannot open: %s", strerror(errno));
	int status = world_read_stream(w, path, f, d);
	fclose(f);
	return status;
}

void world_free(World *w)
{
	free(w->walls);
	free(w->wall_lines);
	free(w->objects);
	w->walls = NULL;
	w->wall_lines = NULL;
	w->objects = NULL;
	w->wall_count = w->object_count = 0;
}

/* print_number: the shortest of %.15g, %.16g, %.17g that reads back exactly, so
 * that a written world reads back to the same state and prints deterministically. */
static void print_number(FILE *f, double v)
{
	char buf[40];
	for (int prec = 15; prec <= 17; prec++) {
		snprintf(buf, sizeof buf, "%.*g", prec, v);
		if (strtod(buf, NULL) == v)
			break;
	}
	fputs(buf, f);
}

static void print_points(FILE *f, const Polygon *p)
{
	for (int32_t i = 0; i < p->count; i++) {
		fputc(' ', f);
		print_number(f, p->v[i].x);
		fputc(' ', f);
		print_number(f, p->v[i].y);
	}
	fputc('\n', f);
}

void world_write(const World *w, FILE *f)
{
	fprintf(f, "# written by utak\ntable %d %d\n", (int)w->w, (int)w->h);
	if (w->verge_given) {
		fputs("verge", f);
		print_points(f, &w->verge);
	}
	for (int32_t i = 0; i < w->wall_count; i++) {
		fputs("wall", f);
		print_points(f, &w->walls[i]);
	}
	for (int32_t i = 0; i < w->object_count; i++) {
		fprintf(f, "object %s %c", w->objects[i].name, w->objects[i].colour);
		print_points(f, &w->objects[i].shape);
	}
	fputs("utak ", f);
	print_number(f, w->utak.x);
	fputc(' ', f);
	print_number(f, w->utak.y);
	fprintf(f, " %s\n", world_heading_name(w->heading));
}

Vec2 world_own_to_table(Heading h, Vec2 v)
{
	switch (h) {
	case HEADING_NORTH:
		return v;
	case HEADING_EAST: /* ahead is east, right is south */
		return vec2(v.y, -v.x);
	case HEADING_SOUTH:
		return vec2(-v.x, -v.y);
	case HEADING_WEST: /* ahead is west, right is north */
		return vec2(-v.y, v.x);
	}
	return v;
}

const char *world_heading_name(Heading h)
{
	static const char *const names[4] = {"north", "east", "south", "west"};
	return names[h & 3];
}

void world_touch_square(const World *w, int k, int32_t *x, int32_t *y)
{
	static const int8_t own[8][2] = {{0, 1}, {1, 1}, {1, 0}, {1, -1}, {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}};
	Vec2 d = world_own_to_table(w->heading, vec2(own[k & 7][0], own[k & 7][1]));
	*x = (int32_t)floor(w->utak.x) + (int32_t)d.x;
	*y = (int32_t)floor(w->utak.y) + (int32_t)d.y;
}
