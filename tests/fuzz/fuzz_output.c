/* fuzz_output.c - fuzzes the output files of -o, --svg and --html (output.h) over
 * the paths a user might give them: existing files, directories, links (good and
 * dangling, to files and to directories), names that do not exist yet, ".",
 * doubled and trailing slashes, and the devices /dev/null and /dev/full.
 *
 * INPUT: byte 0 chooses what is done (bit 0: abandon instead of commit; bit 1:
 * /dev/full; bit 2: /dev/null, instead of a path in the scratch directory); then
 * up to FUZZ_OUTPUT_PARTS bytes up to a NUL, each one component of the path (from
 * the table below, so that no path leaves the scratch directory); the rest is the
 * contents written.
 *
 * THE PROMISE checked: output_open succeeds, or fails with one printable line and
 * changes nothing; after a commit that succeeds the target holds exactly the
 * contents; after an abandon or a failed commit it holds what it held before; and
 * in every case no temporary is left and no other file of the scratch directory
 * has changed. The scratch directory (under TMPDIR) is made afresh for every
 * input and removed at exit. */
#include <dirent.h>
#include <errno.h>
#include <stdbool.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fuzz.h"
#include "utak/base/output.h"

enum { FUZZ_OUTPUT_PARTS = 6, FUZZ_OUTPUT_SNAPSHOT = 4096 };

static const char *const part[] = {"file", "dir", "link", "dangling", "dirlink", "new", ".", "", "dir/file"};
enum { PART_COUNT = sizeof part / sizeof part[0] };

static char scratch[256];

/* The files of the scratch directory, made afresh for each input. */
static const char *const entries[] = {"file", "dir/file", "link", "dangling", "dirlink"};
enum { ENTRY_COUNT = sizeof entries / sizeof entries[0] };

static void scratch_path(char *out, size_t size, const char *name)
{
	snprintf(out, size, "%s/%s", scratch, name);
}

/* empty_dir(path): removes every entry of a directory but its subdirectories. A
 * target may be any new name the parts make, in the scratch directory or in dir
 * (the only directory, reached also through dirlink), so no fixed list will do. */
static void empty_dir(const char *path)
{
	DIR *d = opendir(path);
	if (!d)
		return;
	char p[1024];
	for (struct dirent *e; (e = readdir(d));) {
		snprintf(p, sizeof p, "%s/%s", path, e->d_name);
		struct stat st;
		if (lstat(p, &st) == 0 && !S_ISDIR(st.st_mode))
			unlink(p);
	}
	closedir(d);
}

static void remove_scratch(void)
{
	char p[512];
	scratch_path(p, sizeof p, "dir");
	empty_dir(p);
	rmdir(p);
	empty_dir(scratch);
	rmdir(scratch);
}

static void make_scratch(void)
{
	if (!scratch[0]) {
		const char *tmp = getenv("TMPDIR");
		snprintf(scratch, sizeof scratch, "%s/utak-fuzz-output.%d", tmp ? tmp : "/tmp", (int)getpid());
		atexit(remove_scratch);
	}
	remove_scratch();
	char p[512], q[512];
	FUZZ_CHECK(mkdir(scratch, 0700) == 0, "mkdir %s: %s", scratch, strerror(errno));
	scratch_path(p, sizeof p, "dir");
	FUZZ_CHECK(mkdir(p, 0700) == 0, "mkdir %s", p);
	for (int i = 0; i < 2; i++) {
		scratch_path(p, sizeof p, entries[i]);
		FILE *f = fopen(p, "w");
		FUZZ_CHECK(f != NULL, "fopen %s", p);
		fprintf(f, "old %s\n", entries[i]);
		fclose(f);
	}
	static const char *const link_to[][2] = {{"link", "file"}, {"dangling", "nowhere/at/all"}, {"dirlink", "dir"}};
	for (int i = 0; i < 3; i++) {
		scratch_path(q, sizeof q, link_to[i][0]);
		FUZZ_CHECK(symlink(link_to[i][1], q) == 0, "symlink %s", q);
	}
}

/* Snapshot: the contents of a file (following links), or that there is none. */
typedef struct Snapshot {
	bool exists;
	size_t len;
	char text[FUZZ_OUTPUT_SNAPSHOT];
} Snapshot;

static void snapshot(const char *path, Snapshot *s)
{
	struct stat st;
	s->exists = stat(path, &st) == 0 && S_ISREG(st.st_mode);
	s->len = 0;
	if (!s->exists)
		return;
	FILE *f = fopen(path, "rb");
	FUZZ_CHECK(f != NULL, "fopen %s", path);
	s->len = fread(s->text, 1, sizeof s->text, f);
	fclose(f);
}

static bool same_snapshot(const Snapshot *a, const Snapshot *b)
{
	return a->exists == b->exists && a->len == b->len && memcmp(a->text, b->text, a->len) == 0;
}

/* no_temporaries(): no ".utak-" file in the scratch directory or in dir. */
static bool no_temporaries(void)
{
	char p[512];
	for (int k = 0; k < 2; k++) {
		if (k == 0)
			snprintf(p, sizeof p, "%s", scratch);
		else
			scratch_path(p, sizeof p, "dir");
		DIR *d = opendir(p);
		FUZZ_CHECK(d != NULL, "opendir %s", p);
		for (struct dirent *e; (e = readdir(d));)
			if (strncmp(e->d_name, ".utak-", 6) == 0) {
				closedir(d);
				return false;
			}
		closedir(d);
	}
	return true;
}

static bool printable_line(const char *msg)
{
	if (!msg[0])
		return false;
	for (const char *c = msg; *c; c++)
		if ((unsigned char)*c < 0x20 || (unsigned char)*c > 0x7e)
			return false;
	return true;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (size == 0)
		return 0;
	make_scratch();
	uint8_t how = data[0];
	size_t at = 1;
	char path[1024];
	if (how & 2)
		snprintf(path, sizeof path, "/dev/full");
	else if (how & 4)
		snprintf(path, sizeof path, "/dev/null");
	else
		snprintf(path, sizeof path, "%s", scratch);
	for (int n = 0; at < size && data[at] != 0 && n < FUZZ_OUTPUT_PARTS; n++, at++)
		if (!(how & 6)) {
			size_t len = strlen(path);
			snprintf(path + len, sizeof path - len, "/%s", part[data[at] % PART_COUNT]);
		}
	at += at < size; /* the NUL */
	const uint8_t *contents = data + at;
	size_t contents_len = size - at;
	bool devnull = strcmp(path, "/dev/null") == 0, devfull = strcmp(path, "/dev/full") == 0;

	/* Every file of the scratch directory before: only the target may change. */
	Snapshot before[ENTRY_COUNT], target_before, after;
	char p[512];
	for (int i = 0; i < ENTRY_COUNT; i++) {
		scratch_path(p, sizeof p, entries[i]);
		snapshot(p, &before[i]);
	}
	snapshot(path, &target_before);

	Output o;
	Diag d;
	bool committed = false;
	if (output_open(&o, path, &d) != 0) {
		FUZZ_CHECK(printable_line(d.msg), "bad diagnostic '%s'", d.msg);
		FUZZ_CHECK(output_stream(&o) == NULL, "a failed open left a stream");
	} else {
		fwrite(contents, 1, contents_len, output_stream(&o));
		if (how & 1) {
			output_abandon(&o);
		} else if (output_commit(&o, &d) == 0) {
			committed = true;
		} else {
			FUZZ_CHECK(printable_line(d.msg), "bad diagnostic '%s'", d.msg);
			FUZZ_CHECK(devfull, "the commit of '%s' failed: %s", path, d.msg); /* disk space aside */
		}
		FUZZ_CHECK(output_stream(&o) == NULL, "still open after commit or abandon");
	}
	FUZZ_CHECK(!devfull || !committed || contents_len == 0, "/dev/full took %zu bytes", contents_len);
	FUZZ_CHECK(no_temporaries(), "a temporary was left for '%s'", path);
	snapshot(path, &after);
	if (committed && !devnull && !devfull) {
		FUZZ_CHECK(after.exists && after.len == (contents_len < FUZZ_OUTPUT_SNAPSHOT ? contents_len
											 : FUZZ_OUTPUT_SNAPSHOT) &&
				   memcmp(after.text, contents, after.len) == 0,
			   "'%s' does not hold what was written", path);
	} else if (!committed) {
		FUZZ_CHECK(same_snapshot(&after, &target_before), "'%s' changed though not committed", path);
	}
	/* The other files: unchanged, unless the target is one of them (or a link to one). */
	for (int i = 0; i < ENTRY_COUNT; i++) {
		scratch_path(p, sizeof p, entries[i]);
		Snapshot now;
		snapshot(p, &now);
		if (!same_snapshot(&now, &before[i]))
			FUZZ_CHECK(committed && output_same(p, path), "'%s' changed, writing '%s'", p, path);
	}
	return 0;
}
