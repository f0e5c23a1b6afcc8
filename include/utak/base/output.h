/* output.h - output files that are replaced whole or not at all. Not from the paper:
 * plumbing, for every file utak writes (-o, --svg, and any output added later).
 *
 * A user who gives utak an output file trusts it with that file, which may be the
 * world file the run began from. The promise:
 *   - the file is replaced only by a complete, flushed and synced copy, in one
 *     rename(2): a reader, a crash, a full disk or a file-size limit sees either
 *     the old file or the whole new one, never a part;
 *   - a path that cannot be written fails at output_open, before the run, with one
 *     line "NAME: reason" (the directory is missing or not a directory, the target
 *     is a directory, a file cannot be created there, ...);
 *   - every write, the flush, the sync and the close are checked; a failure leaves
 *     the target as it was and removes the temporary;
 *   - a temporary never outlives the program: output_abandon_all removes every
 *     one still open, and may be called from a signal handler.
 *
 * USAGE.
 *     Output out;
 *     if (output_open(&out, "result.w", &d)) ...      // before the run: d says why
 *     world_write(&world, output_stream(&out));        // any stdio writes
 *     if (output_commit(&out, &d)) ...                 // after it: d says why
 *   or output_abandon(&out) to leave the target untouched.
 *
 * HOW. output_open creates the temporary ".utak-XXXXXX" (mkstemp) in the target's
 * directory, so that the final rename stays within one file system; it takes the
 * target's permission bits, or for a new file those a plain fopen would give
 * (0666 less the umask). A symbolic link is followed: the file it names is
 * replaced and the link stays. A target that exists and is not a regular file (a
 * device such as /dev/full or /dev/null, a FIFO), or any path under /dev/ or
 * /proc/ (/dev/stdout), cannot be replaced by renaming and is written in place,
 * still with every write checked. Hard links to a replaced file keep the old
 * contents: the target is a new file under the old name.
 * STANDARD STREAMS. "-" is standard output; so is a device path that names the
 * file standard output (or error) is open on, such as /dev/stdout: the contents go
 * to that stream, after what the program printed there, and a commit flushes it
 * without closing it. (Opening /dev/stdout anew would give a second file offset:
 * when standard output is a regular file, the two writers would overwrite each
 * other.)
 *
 * MEMORY: an Output is a fixed-size value (the paths it holds are at most
 * OUTPUT_MAX_PATH bytes); at most OUTPUT_MAX_OPEN are open at once, in a static
 * table that output_abandon_all can reach from a signal handler. Not thread-safe. */
#ifndef UTAK_OUTPUT_H
#define UTAK_OUTPUT_H

#include <stdbool.h>
#include <stdio.h>

#include "utak/base/diag.h"

enum {
	OUTPUT_MAX_PATH = 4096, /* bytes of a path, its NUL included (Linux's PATH_MAX) */
	OUTPUT_MAX_OPEN = 8,    /* outputs open at once: -o, --svg and room for more */
};

typedef struct Output {
	FILE *stream;                /* where to write; NULL once committed or abandoned */
	char target[OUTPUT_MAX_PATH]; /* the file to replace, links followed */
	int slot;                    /* its temporary's entry in the static table; -1: in place */
	bool standard;               /* stream is stdout or stderr: flushed, never closed */
	char name[256];              /* the path as given, printable, for diagnostics */
} Output;

/* output_open(o, path, d): opens a temporary in path's directory (or, for a device
 * or FIFO, path itself). On failure fills d ("PATH: reason"), returns -1 and leaves
 * nothing behind. */
int output_open(Output *o, const char *path, Diag *d);

/* output_stream(o): the stream to write the contents to. */
FILE *output_stream(const Output *o);

/* output_commit(o, d): flushes, syncs and closes the temporary, then renames it over
 * the target. On any failure fills d ("PATH: reason"), removes the temporary, leaves
 * the target untouched and returns -1. Either way o is closed. */
int output_commit(Output *o, Diag *d);

/* output_abandon(o): closes o and removes its temporary; the target is untouched.
 * Safe on an Output that was committed or abandoned already. */
void output_abandon(Output *o);

/* output_abandon_all(): removes every temporary still open (unlink(2) only, so it
 * may be called from a signal handler or at exit); the streams are left alone. */
void output_abandon_all(void);

/* output_same(a, b): the two paths name the same file (the same string, or an
 * existing file reached by both; "-" is /dev/stdout). */
bool output_same(const char *a, const char *b);

/* output_flush(f, name, d): flushes a stream utak writes to, standard output among
 * them, and checks it: a write that failed now or before (a full disk, a closed
 * pipe, a file-size limit) fills d ("NAME: reason") and returns -1. */
int output_flush(FILE *f, const char *name, Diag *d);

#endif
