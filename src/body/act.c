/* act.c - the reader of motor-command scripts for --act and --act-file (paper 2.2: the
 * five motor outputs). */
#include "utak/body/act.h"

#include <errno.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "utak/base/util.h"

typedef struct ActReader {
	const char *name; /* "--act", or the script file's name, for diagnostics */
	const char *s;
	size_t len, at;
	int line, col;	/* of s[at], 1-based */
	Diag *d;
} ActReader;

static void skip_blanks(ActReader *r)
{
	while (r->at < r->len && (r->s[r->at] == ' ' || r->s[r->at] == '\t' || r->s[r->at] == '\r')) {
		r->at++;
		r->col++;
	}
}

/* skip_comment(r): a '#' and the rest of its line, up to (not over) the newline. */
static void skip_comment(ActReader *r)
{
	while (r->at < r->len && r->s[r->at] != '\n') {
		r->at++;
		r->col++;
	}
}

/* next_word(r, &start, &n): the next word up to a blank, ';', '#' or newline. */
static bool next_word(ActReader *r, size_t *start, size_t *n)
{
	skip_blanks(r);
	*start = r->at;
	while (r->at < r->len && !strchr(" \t\r\n;#", r->s[r->at])) {
		r->at++;
		r->col++;
	}
	*n = r->at - *start;
	return *n > 0;
}

static int act_fail(ActReader *r, int col, const char *msg, const char *word, size_t n)
{
	if (word)
		return diag_set(r->d, r->name, r->line, col, "%s '%.*s'", msg, (int)(n > 32 ? 32 : n), word);
	return diag_set(r->d, r->name, r->line, col, "%s", msg);
}

static int read_number(ActReader *r, const char *after, double *v)
{
	size_t start, n;
	char buf[64], msg[64];
	if (!next_word(r, &start, &n)) {
		snprintf(msg, sizeof msg, "expected a number after '%s'", after);
		return act_fail(r, r->col, msg, NULL, 0);
	}
	int col = r->col - (int)n;
	if (n >= sizeof buf)
		return act_fail(r, col, "expected a number, found", r->s + start, n);
	memcpy(buf, r->s + start, n);
	buf[n] = 0;
	/* Plain decimals only: strtod would also take "inf", "nan" and hex. */
	for (size_t i = 0; i < n; i++)
		if (!strchr("0123456789.eE+-", buf[i]))
			return act_fail(r, col, "expected a number, found", r->s + start, n);
	char *end;
	*v = strtod(buf, &end);
	if (end != buf + n || !isfinite(*v))
		return act_fail(r, col, "expected a number, found", r->s + start, n);
	if (fabs(*v) > ACT_MAX_MAGNITUDE)
		return act_fail(r, col, "number is too large (the most is 1000000)", NULL, 0);
	if (*v == 0)
		*v = 0;
	return 0;
}

int act_parse(const char *text, size_t len, MotorCommand **cmds, int *count, Diag *d)
{
	return act_parse_named("--act", text, len, cmds, count, d);
}

int act_read_stream(const char *name, FILE *f, MotorCommand **cmds, int *count, Diag *d)
{
	char *buf;
	size_t len;
	*cmds = NULL;
	*count = 0;
	if (util_read_stream(f, ACT_MAX_BYTES, &buf, &len) != 0)
		return diag_set(d, name, 0, 0, "cannot read: %s", strerror(errno));
	int status = act_parse_named(name, buf, len, cmds, count, d);
	free(buf);
	return status;
}

int act_parse_named(const char *name, const char *text, size_t len, MotorCommand **cmds, int *count,
		    Diag *d)
{
	ActReader r = {.name = name, .s = text, .len = len, .line = 1, .col = 1, .d = d};
	int cap = 0;
	*cmds = NULL;
	*count = 0;
	if (len > ACT_MAX_BYTES)
		return diag_set(d, name, 0, 0, "script is over the limit of %d bytes", ACT_MAX_BYTES);
	if (memchr(text, 0, len))
		return diag_set(d, name, 0, 0, "script holds a NUL byte");
	/* Plain ASCII only, as in a world file: a stray byte would otherwise be
	 * echoed raw into the diagnostic and onto the user's terminal. */
	for (size_t i = 0, line = 1, col = 1; i < len; i++, col++) {
		unsigned char c = (unsigned char)text[i];
		if (c == '\n') {
			line++;
			col = 0;
		} else if ((c < 0x20 && c != '\t' && c != '\r') || c > 0x7e) {
			return diag_set(d, name, (int)line, (int)col,
					"unexpected byte 0x%02x (a script is plain ASCII text)", c);
		}
	}
	for (;;) {
		size_t start, n;
		if (!next_word(&r, &start, &n)) {
			if (r.at >= r.len)
				break;
			if (r.s[r.at] == '#') {
				skip_comment(&r);
				continue;
			}
			char c = r.s[r.at++];
			if (c == '\n') {
				r.line++;
				r.col = 1;
			} else {
				r.col++; /* an empty command between separators is allowed */
			}
			continue;
		}
		int col = r.col - (int)n;
		const char *w = r.s + start;
		MotorCommand c = {0};
		static const char *const names[] = {"move", "grasp", "push", "turn", "release"};
		int k = 0;
		while (k < 5 && !(strlen(names[k]) == n && memcmp(names[k], w, n) == 0))
			k++;
		if (k == 5) {
			free(*cmds);
			*cmds = NULL;
			*count = 0;
			return act_fail(&r, col,
					"unknown command (move DX DY, grasp, push DX DY, turn DEG, release):",
					w, n);
		}
		c.kind = (MotorKind)k;
		int status = 0;
		if (c.kind == MOTOR_MOVE || c.kind == MOTOR_PUSH)
			status = read_number(&r, names[k], &c.dx) || read_number(&r, names[k], &c.dy);
		else if (c.kind == MOTOR_TURN)
			status = read_number(&r, names[k], &c.deg);
		if (status == 0) {
			skip_blanks(&r);
			if (r.at < r.len && !strchr(";#\n", r.s[r.at])) {
				size_t s2, n2;
				int col2 = r.col;
				next_word(&r, &s2, &n2);
				char msg[64];
				snprintf(msg, sizeof msg, "too many words for '%s':", names[k]);
				status = act_fail(&r, col2, msg, r.s + s2, n2);
			}
		}
		if (status == 0 && *count >= ACT_MAX_COMMANDS)
			status = diag_set(d, r.name, r.line, col, "too many commands (the most is %d)",
					  ACT_MAX_COMMANDS);
		if (status != 0) {
			free(*cmds);
			*cmds = NULL;
			*count = 0;
			return -1;
		}
		*cmds = util_grow(*cmds, &cap, *count + 1, sizeof **cmds);
		(*cmds)[(*count)++] = c;
	}
	return 0;
}
