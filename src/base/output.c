/* output.c - output files replaced whole or not at all (see output.h). Not from the
 * paper: plumbing.
 *
 * ALGORITHM: the classic safe replacement of a file (as in editors and sed -i):
 * write a temporary in the same directory, flush it, fsync it, close it, rename it
 * over the target (atomic within one file system, POSIX rename(2)), then fsync the
 * directory so that the new name is durable too.
 * INVARIANT: a slot of the static table is active exactly while its temporary may
 * exist on disk; output_abandon_all unlinks the active ones. */
/* realpath(3) is XSI: POSIX base (the Makefile's -D_POSIX_C_SOURCE) leaves it out. */
#define _XOPEN_SOURCE 700

#include "utak/base/output.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The temporary's name in the target's directory: hidden, and short, so that a
 * target name of any legal length leaves room for it. */
#define OUTPUT_TEMP_NAME "/.utak-XXXXXX"

/* The temporaries, reachable from a signal handler: active[i] is set while
 * temp[i] may exist. */
static char output_temp[OUTPUT_MAX_OPEN][OUTPUT_MAX_PATH];
static volatile sig_atomic_t output_active[OUTPUT_MAX_OPEN];

/* output_set_name(o, path): the path as diagnostics show it: printable ASCII only,
 * so that a control byte in a name never reaches the terminal raw. */
static void output_set_name(Output *o, const char *path)
{
	size_t n = 0;
	for (; path[n] && n + 1 < sizeof o->name; n++) {
		unsigned char c = (unsigned char)path[n];
		o->name[n] = c >= 0x20 && c <= 0x7e ? (char)c : '?';
	}
	o->name[n] = 0;
}

/* stream_error(f): the error of a stream's writes so far, 0 if none. A write that
 * failed inside an earlier printf keeps its data buffered (glibc), so fflush tries
 * it again and says why; EIO when it no longer can. */
static int stream_error(FILE *f)
{
	errno = 0;
	if (fflush(f) == 0 && !ferror(f))
		return 0;
	return errno ? errno : EIO;
}

/* in_place(path): paths that name devices and the process's own files, which no
 * rename can replace (/dev/stdout is a link into /proc). */
static bool in_place(const char *path)
{
	return strncmp(path, "/dev/", 5) == 0 || strncmp(path, "/proc/", 6) == 0;
}

/* resolve(o, path, st, exists): fills o->target with the file to replace (a
 * symbolic link followed) and *st with its status. Returns 0 or an errno. */
static int resolve(Output *o, const char *path, struct stat *st, bool *exists)
{
	*exists = false;
	if (lstat(path, st) != 0)
		return errno == ENOENT ? 0 : errno;
	*exists = true;
	if (!S_ISLNK(st->st_mode))
		return 0;
	char *real = realpath(path, NULL);
	if (!real)
		return errno;
	size_t n = strlen(real);
	int err = n < sizeof o->target ? 0 : ENAMETOOLONG;
	if (!err)
		memcpy(o->target, real, n + 1);
	free(real);
	if (!err && stat(o->target, st) != 0)
		err = errno;
	return err;
}

/* open_temp(o, st, exists): the temporary beside o->target, with the target's
 * permissions (or a new file's), registered in a free slot. Returns 0 or an errno. */
static int open_temp(Output *o, const struct stat *st, bool exists)
{
	int slot = 0;
	while (slot < OUTPUT_MAX_OPEN && output_active[slot])
		slot++;
	if (slot == OUTPUT_MAX_OPEN)
		return EMFILE;
	const char *slash = strrchr(o->target, '/');
	size_t dir_len = slash ? (size_t)(slash - o->target) : 1;
	const char *dir = slash ? o->target : ".";
	if (slash && slash[1] == 0)
		return EISDIR; /* "name/": no file name after the last '/' */
	if (dir_len + sizeof OUTPUT_TEMP_NAME > OUTPUT_MAX_PATH)
		return ENAMETOOLONG;
	char *temp = output_temp[slot];
	memcpy(temp, dir, dir_len);
	memcpy(temp + dir_len, OUTPUT_TEMP_NAME, sizeof OUTPUT_TEMP_NAME);
	/* Active before it exists, so that no moment has a file the table lacks. */
	output_active[slot] = 1;
	int fd = mkstemp(temp);
	if (fd < 0) {
		int err = errno;
		output_active[slot] = 0;
		return err;
	}
	mode_t mode;
	if (exists) {
		mode = st->st_mode & 07777;
		/* Root replacing another user's file keeps its owner; for anyone else
		 * this fails harmlessly and the file is the writer's, as with fopen. */
		if (st->st_uid != geteuid() || st->st_gid != getegid())
			(void)!fchown(fd, st->st_uid, st->st_gid);
	} else {
		mode = umask(0);
		umask(mode);
		mode = 0666 & ~mode;
	}
	/* A file system without permission bits refuses fchmod; the contents, which
	 * are what is promised, do not depend on it. */
	(void)!fchmod(fd, mode);
	o->stream = fdopen(fd, "w");
	if (!o->stream) {
		int err = errno;
		close(fd);
		unlink(temp);
		output_active[slot] = 0;
		return err;
	}
	o->slot = slot;
	return 0;
}

/* standard_stream(path): stdout or stderr when path names the file it is open on
 * ("-" always standard output), else NULL. */
static FILE *standard_stream(const char *path)
{
	if (strcmp(path, "-") == 0)
		return stdout;
	struct stat st, sf;
	if (stat(path, &st) != 0)
		return NULL;
	if (fstat(STDOUT_FILENO, &sf) == 0 && sf.st_dev == st.st_dev && sf.st_ino == st.st_ino)
		return stdout;
	if (fstat(STDERR_FILENO, &sf) == 0 && sf.st_dev == st.st_dev && sf.st_ino == st.st_ino)
		return stderr;
	return NULL;
}

int output_open(Output *o, const char *path, Diag *d)
{
	o->stream = NULL;
	o->slot = -1;
	o->standard = false;
	o->target[0] = 0;
	output_set_name(o, path);
	if (strcmp(path, "-") == 0)
		output_set_name(o, "standard output");
	size_t n = strlen(path);
	int err = 0;
	if (n == 0)
		err = ENOENT;
	else if (n >= sizeof o->target)
		err = ENAMETOOLONG;
	if (err)
		return diag_set(d, o->name, 0, 0, "%s", strerror(err));
	memcpy(o->target, path, n + 1);
	struct stat st;
	bool exists = false;
	if (!in_place(path) && strcmp(path, "-") != 0) {
		err = resolve(o, path, &st, &exists);
		if (err == ENOENT && exists)
			return diag_set(d, o->name, 0, 0, "a symbolic link to a file that does not exist");
		if (!err && exists && S_ISDIR(st.st_mode))
			err = EISDIR;
		if (!err && exists && S_ISREG(st.st_mode) && access(o->target, W_OK) != 0)
			err = errno;
		if (!err && (!exists || S_ISREG(st.st_mode)))
			err = open_temp(o, &st, exists);
		if (err)
			return diag_set(d, o->name, 0, 0, "%s", strerror(err));
		if (o->stream)
			return 0;
	}
	/* A device, FIFO or socket, or a path under /dev/ or /proc/: in place; through
	 * the program's own stream when it is standard output or error. */
	o->stream = standard_stream(o->target);
	o->standard = o->stream != NULL;
	if (!o->stream)
		o->stream = fopen(o->target, "w");
	if (!o->stream)
		return diag_set(d, o->name, 0, 0, "%s", strerror(errno));
	return 0;
}

FILE *output_stream(const Output *o)
{
	return o->stream;
}

/* release(o): forgets the temporary, removing it when remove is set. */
static void release(Output *o, bool remove)
{
	if (o->slot >= 0) {
		if (remove)
			unlink(output_temp[o->slot]);
		output_active[o->slot] = 0;
		o->slot = -1;
	}
}

/* sync_directory(path): makes a rename in path's directory durable. Best effort:
 * the file is in place by now, and a directory that cannot be synced (some file
 * systems refuse) is no reason to report the output as lost. */
static void sync_directory(const char *path)
{
	char dir[OUTPUT_MAX_PATH];
	const char *slash = strrchr(path, '/');
	size_t n = slash ? (size_t)(slash - path) : 0;
	if (slash && n == 0)
		n = 1; /* the root directory */
	memcpy(dir, slash ? path : ".", slash ? n : 1);
	dir[slash ? n : 1] = 0;
	int fd = open(dir, O_RDONLY | O_DIRECTORY);
	if (fd >= 0) {
		(void)fsync(fd);
		close(fd);
	}
}

int output_commit(Output *o, Diag *d)
{
	if (!o->stream)
		return diag_set(d, o->name, 0, 0, "not open");
	int err = stream_error(o->stream);
	/* fsync: the data must be on disk before the rename makes it the file. A
	 * device written in place is not synced (a terminal or pipe refuses). */
	if (!err && o->slot >= 0 && fsync(fileno(o->stream)) != 0 && errno != EINVAL)
		err = errno;
	if (!o->standard && fclose(o->stream) != 0 && !err)
		err = errno ? errno : EIO;
	o->stream = NULL;
	if (!err && o->slot >= 0 && rename(output_temp[o->slot], o->target) != 0)
		err = errno;
	if (err) {
		release(o, true);
		return diag_set(d, o->name, 0, 0, "%s", strerror(err));
	}
	if (o->slot >= 0)
		sync_directory(o->target);
	release(o, false);
	return 0;
}

void output_abandon(Output *o)
{
	if (o->stream && !o->standard)
		fclose(o->stream);
	o->stream = NULL;
	release(o, true);
}

void output_abandon_all(void)
{
	for (int i = 0; i < OUTPUT_MAX_OPEN; i++)
		if (output_active[i]) {
			unlink(output_temp[i]);
			output_active[i] = 0;
		}
}

bool output_same(const char *a, const char *b)
{
	struct stat sa, sb;
	if (strcmp(a, b) == 0)
		return true;
	a = strcmp(a, "-") == 0 ? "/dev/stdout" : a;
	b = strcmp(b, "-") == 0 ? "/dev/stdout" : b;
	return stat(a, &sa) == 0 && stat(b, &sb) == 0 && sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

int output_flush(FILE *f, const char *name, Diag *d)
{
	int err = stream_error(f);
	if (err)
		return diag_set(d, name, 0, 0, "%s", strerror(err));
	return 0;
}
