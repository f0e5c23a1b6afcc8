/* act.h - the reader of motor-command scripts, as given to --act (paper 2.2).
 *
 * "move 3 0; grasp; push 0 5; turn 90; release": commands separated by ';' or
 * newlines, each a keyword and its numbers (displacements in Utak's frame, in
 * squares; turns in degrees, counter-clockwise positive); '#' begins a comment that
 * runs to the end of its line. Grammar in man/utak.1. */
#ifndef UTAK_ACT_H
#define UTAK_ACT_H

#include <stddef.h>
#include <stdio.h>

#include "utak/base/diag.h"
#include "utak/impression.h"

enum {
	ACT_MAX_COMMANDS = 10000,	/* commands in one script */
	ACT_MAX_BYTES = 1 << 20,	/* length of one script */
};
/* The largest displacement (squares) or turn (degrees) one command may ask for:
 * far more than any TABLE, small enough that step counts stay exact integers. */
#define ACT_MAX_MAGNITUDE 1e6

/* act_parse(text, len, &cmds, &count, d): reads a script given on the command line;
 * on failure fills d with "--act:LINE:COL: ..." and returns -1 (*cmds NULL, *count
 * 0). The caller frees *cmds. act_parse_named does the same for a script called
 * name in diagnostics; act_read_stream reads one from an open stream (--act-file,
 * "-" for standard input). A '#' begins a comment that runs to the end of its line. */
int act_parse(const char *text, size_t len, MotorCommand **cmds, int *count, Diag *d);
int act_parse_named(const char *name, const char *text, size_t len, MotorCommand **cmds, int *count,
		    Diag *d);
int act_read_stream(const char *name, FILE *f, MotorCommand **cmds, int *count, Diag *d);

#endif
