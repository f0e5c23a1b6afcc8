/* diag.h - a diagnostic for bad input: one line, "FILE:LINE:COL: what is wrong".
 *
 * Readers fill a Diag and return a failure status; only main.c prints it (with
 * "utak: " in front) and chooses the exit status. */
#ifndef UTAK_DIAG_H
#define UTAK_DIAG_H

enum { DIAG_SIZE = 512 };

typedef struct Diag {
	char msg[DIAG_SIZE];
} Diag;

/* diag_set(d, file, line, col, fmt, ...): "file:line:col: message"; line or col
 * 0 leaves that part out. Returns -1, so a reader can `return diag_set(...)`. */
int diag_set(Diag *d, const char *file, int line, int col, const char *fmt, ...)
#if defined(__GNUC__)
	__attribute__((format(printf, 5, 6)))
#endif
	;

#endif
