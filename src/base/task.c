/* task.c - the reader of tasks: short forms and the paper's sentences (paper 2.3). BOTH SIDES
 * (base/): the controller and the judge read the same task.
 *
 * A task is normalised (lower case, punctuation other than '-' dropped, blanks
 * folded) and cut into words; then matched against a few patterns, most specific
 * first. Words like "the", "to", "into" are part of the patterns, so a sentence
 * that does not fit one is refused rather than guessed at. */
#include "utak/base/task.h"

#include <ctype.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

enum { TASK_MAX_WORDS = 16, TASK_MAX_CHARS = 256 };

static const char task_forms[] =
	"go CORNER | go next-room | go SHAPE | go round SHAPE | push SHAPE CORNER | "
	"push SHAPE next-room | push SHAPE through-door | push SHAPE around-corner "
	"(CORNER: ne-corner nw-corner se-corner sw-corner; SHAPE: square brick lshape triangle), "
	"or the paper's sentences, e.g. 'Go to the northeast corner'";

typedef struct Words {
	char buf[TASK_MAX_CHARS + 1];
	const char *w[TASK_MAX_WORDS];
	int n, at;	/* word count; the cursor of the matcher */
} Words;

static bool words_split(Words *ws, const char *text)
{
	size_t len = strlen(text);
	if (len > TASK_MAX_CHARS)
		return false;
	size_t j = 0;
	for (size_t i = 0; i < len; i++) {
		unsigned char c = (unsigned char)text[i];
		if (isalnum(c) || c == '-')
			ws->buf[j++] = (char)tolower(c);
		else if (c == ' ' || c == '\t' || c == '\n' || c == '.' || c == ',' || c == '!' || c == '"' || c == '\'')
			ws->buf[j++] = ' ';
		else
			return false; /* anything else is no task of ours */
	}
	ws->buf[j] = 0;
	ws->n = 0;
	for (char *s = strtok(ws->buf, " "); s; s = strtok(NULL, " ")) {
		if (ws->n == TASK_MAX_WORDS)
			return false;
		ws->w[ws->n++] = s;
	}
	return ws->n > 0;
}

/* take(ws, word): the next word is `word` (any of several, separated by '|'). */
static bool take(Words *ws, const char *alternatives)
{
	if (ws->at >= ws->n)
		return false;
	const char *w = ws->w[ws->at], *a = alternatives;
	size_t n = strlen(w);
	while (*a) {
		size_t k = strcspn(a, "|");
		if (k == n && strncmp(a, w, n) == 0) {
			ws->at++;
			return true;
		}
		a += k + (a[k] == '|');
	}
	return false;
}

static bool done(const Words *ws) { return ws->at == ws->n; }

/* take_shape: square | brick | triangle | lshape | l-shape | l-shaped [object] */
static bool take_shape(Words *ws, Shape *s)
{
	if (take(ws, "square"))
		*s = SHAPE_SQUARE;
	else if (take(ws, "brick"))
		*s = SHAPE_BRICK;
	else if (take(ws, "triangle"))
		*s = SHAPE_TRIANGLE;
	else if (take(ws, "lshape|l-shape")) {
		*s = SHAPE_LSHAPE;
	} else if (take(ws, "l-shaped|lshaped")) {
		*s = SHAPE_LSHAPE;
		take(ws, "object|shape");
	} else
		return false;
	return true;
}

/* take_corner: ne-corner ... (short) or "northeast corner", "north-east corner", "ne corner". */
static bool take_corner(Words *ws, Corner *c)
{
	static const char *const shorts[] = {"ne-corner", "nw-corner", "se-corner", "sw-corner"};
	static const char *const longs[] = {"northeast|north-east|ne", "northwest|north-west|nw",
					    "southeast|south-east|se", "southwest|south-west|sw"};
	for (int k = 0; k < 4; k++)
		if (take(ws, shorts[k])) {
			*c = (Corner)(CORNER_NE + k);
			return true;
		}
	int save = ws->at;
	for (int k = 0; k < 4; k++)
		if (take(ws, longs[k])) {
			if (take(ws, "corner")) {
				*c = (Corner)(CORNER_NE + k);
				return true;
			}
			break;
		}
	ws->at = save;
	return false;
}

static bool match_short(Words *ws, Task *t)
{
	ws->at = 0;
	if (take(ws, "go")) {
		if (take_corner(ws, &t->corner)) {
			t->kind = TASK_GO_CORNER;
			return done(ws);
		}
		if (take(ws, "next-room")) {
			t->kind = TASK_GO_NEXT_ROOM;
			return done(ws);
		}
		if (take(ws, "round|around")) {
			t->kind = TASK_GO_ROUND;
			return take_shape(ws, &t->shape) && done(ws);
		}
		t->kind = TASK_GO_SHAPE;
		return take_shape(ws, &t->shape) && done(ws);
	}
	if (take(ws, "push") && take_shape(ws, &t->shape)) {
		if (take_corner(ws, &t->corner))
			t->kind = TASK_PUSH_CORNER;
		else if (take(ws, "next-room"))
			t->kind = TASK_PUSH_NEXT_ROOM;
		else if (take(ws, "through-door"))
			t->kind = TASK_PUSH_THROUGH_DOOR;
		else if (take(ws, "around-corner"))
			t->kind = TASK_PUSH_AROUND_CORNER;
		else
			return false;
		return done(ws);
	}
	return false;
}

static bool match_sentence(Words *ws, Task *t)
{
	ws->at = 0;
	if (take(ws, "go")) {
		if (take(ws, "round|around")) {
			t->kind = TASK_GO_ROUND;
			if (!take(ws, "the") || !take_shape(ws, &t->shape))
				return false;
			if (take(ws, "and") && !take(ws, "return"))
				return false;
			return done(ws);
		}
		if (!take(ws, "to") || !take(ws, "the"))
			return false;
		if (take_corner(ws, &t->corner)) {
			t->kind = TASK_GO_CORNER;
			return done(ws);
		}
		if (take(ws, "next")) {
			t->kind = TASK_GO_NEXT_ROOM;
			return take(ws, "room") && done(ws);
		}
		t->kind = TASK_GO_SHAPE;
		return take_shape(ws, &t->shape) && done(ws);
	}
	if (take(ws, "push") && take(ws, "the") && take_shape(ws, &t->shape)) {
		if (take(ws, "into|to|in")) {
			if (!take(ws, "the"))
				return false;
			if (take_corner(ws, &t->corner)) {
				t->kind = TASK_PUSH_CORNER;
				return done(ws);
			}
			t->kind = TASK_PUSH_NEXT_ROOM;
			return take(ws, "next") && take(ws, "room") && done(ws);
		}
		if (take(ws, "through")) {
			t->kind = TASK_PUSH_THROUGH_DOOR;
			return take(ws, "the") && take(ws, "door|doorway") && done(ws);
		}
		if (take(ws, "around|round")) {
			t->kind = TASK_PUSH_AROUND_CORNER;
			return take(ws, "the") && take(ws, "corner") && done(ws);
		}
	}
	return false;
}

int task_parse(const char *text, Task *t, Diag *d)
{
	Words ws;
	*t = (Task){0};
	if (words_split(&ws, text)) {
		Task a = {0};
		if (match_short(&ws, &a) || (a = (Task){0}, match_sentence(&ws, &a))) {
			*t = a;
			return 0;
		}
	}
	char shown[48];
	size_t n = strlen(text);
	snprintf(shown, sizeof shown, "%.40s%s", text, n > 40 ? "..." : "");
	for (char *s = shown; *s; s++)
		if (!isprint((unsigned char)*s))
			*s = '?';
	return diag_set(d, "task", 0, 0, "unknown task '%s'; the forms are: %s", shown, task_forms);
}

const char *task_shape_name(Shape s)
{
	static const char *const names[] = {"nothing", "square", "brick", "lshape", "triangle"};
	return names[s];
}

const char *task_corner_name(Corner c)
{
	static const char *const names[] = {"none", "ne-corner", "nw-corner", "se-corner", "sw-corner"};
	return names[c];
}

void task_corner_signs(Corner c, int *sx, int *sy)
{
	*sx = c == CORNER_NE || c == CORNER_SE ? 1 : -1;
	*sy = c == CORNER_NE || c == CORNER_NW ? 1 : -1;
}

void task_short_form(const Task *t, char *buf, size_t size)
{
	const char *shape = task_shape_name(t->shape), *corner = task_corner_name(t->corner);
	switch (t->kind) {
	case TASK_GO_CORNER:
		snprintf(buf, size, "go %s", corner);
		break;
	case TASK_GO_NEXT_ROOM:
		snprintf(buf, size, "go next-room");
		break;
	case TASK_GO_SHAPE:
		snprintf(buf, size, "go %s", shape);
		break;
	case TASK_GO_ROUND:
		snprintf(buf, size, "go round %s", shape);
		break;
	case TASK_PUSH_CORNER:
		snprintf(buf, size, "push %s %s", shape, corner);
		break;
	case TASK_PUSH_NEXT_ROOM:
		snprintf(buf, size, "push %s next-room", shape);
		break;
	case TASK_PUSH_THROUGH_DOOR:
		snprintf(buf, size, "push %s through-door", shape);
		break;
	case TASK_PUSH_AROUND_CORNER:
		snprintf(buf, size, "push %s around-corner", shape);
		break;
	}
}

const char *task_paper_number(const Task *t)
{
	switch (t->kind) {
	case TASK_GO_CORNER:
		return t->corner == CORNER_NE ? "(i)" : NULL;
	case TASK_GO_NEXT_ROOM:
		return "(ii)";
	case TASK_GO_SHAPE:
		return t->shape == SHAPE_SQUARE ? "(iii)" : NULL;
	case TASK_GO_ROUND:
		return t->shape == SHAPE_SQUARE ? "(iv)" : NULL;
	case TASK_PUSH_CORNER:
		return t->shape == SHAPE_SQUARE && t->corner == CORNER_NE ? "(v)" : NULL;
	case TASK_PUSH_NEXT_ROOM:
		return t->shape == SHAPE_SQUARE ? "(vi)" : t->shape == SHAPE_LSHAPE ? "(ix)" : NULL;
	case TASK_PUSH_THROUGH_DOOR:
		return t->shape == SHAPE_BRICK ? "(vii)" : NULL;
	case TASK_PUSH_AROUND_CORNER:
		return t->shape == SHAPE_BRICK ? "(viii)" : NULL;
	}
	return NULL;
}
