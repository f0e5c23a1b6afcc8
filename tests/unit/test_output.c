/* test_output.c - output files replaced whole or not at all (output.h), checked
 * against the file system itself: what the target holds, and which files the
 * directory holds, before and after each step; a full device (/dev/full) and a
 * file-size limit (setrlimit, in a child process) for writes that fail. */
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test.h"
#include "utak/base/output.h"

static char dir[64];

/* path_in(name): a path in the test's directory (one static buffer per call site
 * would do; four rotating ones let a check name two paths). */
static const char *path_in(const char *name)
{
	static char buf[4][256];
	static int next;
	char *p = buf[next++ % 4];
	snprintf(p, sizeof buf[0], "%s/%s", dir, name);
	return p;
}

static void put(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");
	fputs(text, f);
	fclose(f);
}

/* holds(path, text): the file holds exactly text. */
static bool holds(const char *path, const char *text)
{
	char buf[256] = "";
	FILE *f = fopen(path, "r");
	if (!f)
		return false;
	size_t n = fread(buf, 1, sizeof buf - 1, f);
	fclose(f);
	buf[n] = 0;
	return strcmp(buf, text) == 0;
}

/* temporaries(): how many of the directory's files are temporaries (.utak-*). */
static int temporaries(void)
{
	DIR *d = opendir(dir);
	int n = 0;
	for (struct dirent *e; d && (e = readdir(d));)
		n += strncmp(e->d_name, ".utak-", 6) == 0;
	if (d)
		closedir(d);
	return n;
}

static mode_t mode_of(const char *path)
{
	struct stat st;
	return stat(path, &st) == 0 ? st.st_mode & 07777 : 0;
}

TEST_CASE(a_new_file_appears_whole_at_commit)
{
	const char *target = path_in("new.txt");
	unlink(target);
	Output o;
	Diag d;
	TEST_CHECK(output_open(&o, target, &d) == 0);
	TEST_CHECK(temporaries() == 1 && access(target, F_OK) != 0);
	fputs("hello\n", output_stream(&o));
	TEST_CHECK(access(target, F_OK) != 0); /* nothing under the name before the commit */
	TEST_CHECK(output_commit(&o, &d) == 0);
	TEST_CHECK(holds(target, "hello\n"));
	TEST_CHECK(temporaries() == 0 && output_stream(&o) == NULL);
	mode_t mask = umask(0);
	umask(mask);
	TEST_CHECK(mode_of(target) == (0666 & ~mask));
}

TEST_CASE(a_replaced_file_is_old_until_commit_and_keeps_its_mode)
{
	const char *target = path_in("old.txt");
	put(target, "old\n");
	chmod(target, 0604);
	Output o;
	Diag d;
	TEST_CHECK(output_open(&o, target, &d) == 0);
	fputs("new\n", output_stream(&o));
	fflush(output_stream(&o));
	TEST_CHECK(holds(target, "old\n"));
	TEST_CHECK(output_commit(&o, &d) == 0);
	TEST_CHECK(holds(target, "new\n") && mode_of(target) == 0604 && temporaries() == 0);
}

TEST_CASE(abandon_leaves_the_target_and_no_temporary)
{
	const char *target = path_in("kept.txt");
	put(target, "kept\n");
	Output o;
	Diag d;
	TEST_CHECK(output_open(&o, target, &d) == 0);
	fputs("lost\n", output_stream(&o));
	output_abandon(&o);
	output_abandon(&o); /* twice is safe */
	TEST_CHECK(holds(target, "kept\n") && temporaries() == 0);
}

TEST_CASE(paths_that_cannot_be_written_fail_at_open)
{
	put(path_in("regular"), "x");
	char long_path[OUTPUT_MAX_PATH + 8];
	memset(long_path, 'a', sizeof long_path - 1);
	long_path[sizeof long_path - 1] = 0;
	static const struct {
		const char *name, *why;
	} cases[] = {
		{"nodir/x", "No such file or directory"}, {"regular/x", "Not a directory"},
		{"", "Is a directory"},                    {"nodir/", "Is a directory"},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		const char *p = path_in(cases[i].name);
		char want[512];
		snprintf(want, sizeof want, "%s: %s", p, cases[i].why);
		Output o;
		Diag d;
		TEST_CHECK(output_open(&o, p, &d) == -1);
		TEST_CHECK(strcmp(d.msg, want) == 0);
		TEST_CHECK(output_stream(&o) == NULL && temporaries() == 0);
	}
	Output o;
	Diag d;
	TEST_CHECK(output_open(&o, "", &d) == -1 && strcmp(d.msg, ": No such file or directory") == 0);
	TEST_CHECK(output_open(&o, long_path, &d) == -1 && strstr(d.msg, "File name too long"));
	/* A control byte in a name reaches the diagnostic as '?'. */
	TEST_CHECK(output_open(&o, path_in("nodir/a\033b"), &d) == -1 && strstr(d.msg, "nodir/a?b: No such"));
}

TEST_CASE(a_full_device_is_written_in_place_and_fails_at_commit)
{
	Output o;
	Diag d;
	TEST_CHECK(output_open(&o, "/dev/full", &d) == 0);
	fputs("anything\n", output_stream(&o));
	TEST_CHECK(output_commit(&o, &d) == -1);
	TEST_CHECK(strcmp(d.msg, "/dev/full: No space left on device") == 0);
	struct stat st;
	TEST_CHECK(stat("/dev/full", &st) == 0 && S_ISCHR(st.st_mode)); /* never renamed over */
	TEST_CHECK(output_open(&o, "/dev/null", &d) == 0);
	fputs("anything\n", output_stream(&o));
	TEST_CHECK(output_commit(&o, &d) == 0);
	TEST_CHECK(stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode));
}

/* In a child: a file-size limit of 4 KiB, SIGXFSZ ignored (as utak does), and 64 KiB
 * written over a file of 4 bytes. Exits 0 when the commit failed with EFBIG and left
 * the target as it was with no temporary. */
static int limited_child(const char *target)
{
	signal(SIGXFSZ, SIG_IGN);
	struct rlimit lim = {4096, 4096};
	if (setrlimit(RLIMIT_FSIZE, &lim) != 0)
		return 10;
	Output o;
	Diag d;
	if (output_open(&o, target, &d) != 0)
		return 11;
	for (int i = 0; i < 4096; i++)
		fputs("0123456789abcde\n", output_stream(&o));
	char want[300];
	snprintf(want, sizeof want, "%s: File too large", target);
	if (output_commit(&o, &d) != -1 || strcmp(d.msg, want) != 0)
		return 12;
	return holds(target, "old\n") && temporaries() == 0 ? 0 : 13;
}

TEST_CASE(a_file_size_limit_mid_write_leaves_the_target)
{
	const char *target = path_in("limited.txt");
	put(target, "old\n");
	fflush(stdout);
	pid_t pid = fork();
	TEST_CHECK(pid >= 0);
	if (pid == 0)
		_exit(limited_child(target));
	int status;
	TEST_CHECK(waitpid(pid, &status, 0) == pid);
	TEST_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 0);
	TEST_CHECK(holds(target, "old\n"));
}

TEST_CASE(a_link_is_followed_and_stays_a_link)
{
	const char *file = path_in("real.txt"), *link = path_in("link.txt");
	put(file, "old\n");
	unlink(link);
	TEST_CHECK(symlink("real.txt", link) == 0);
	Output o;
	Diag d;
	TEST_CHECK(output_open(&o, link, &d) == 0);
	fputs("new\n", output_stream(&o));
	TEST_CHECK(output_commit(&o, &d) == 0);
	struct stat st;
	TEST_CHECK(lstat(link, &st) == 0 && S_ISLNK(st.st_mode));
	TEST_CHECK(holds(file, "new\n") && temporaries() == 0);
	const char *dangling = path_in("dangling.txt");
	unlink(dangling);
	TEST_CHECK(symlink("nowhere/at/all", dangling) == 0);
	TEST_CHECK(output_open(&o, dangling, &d) == -1 && strstr(d.msg, "a symbolic link to a file that does not"));
}

TEST_CASE(abandon_all_removes_every_temporary)
{
	Output a, b;
	Diag d;
	TEST_CHECK(output_open(&a, path_in("a.txt"), &d) == 0 && output_open(&b, path_in("b.txt"), &d) == 0);
	TEST_CHECK(temporaries() == 2);
	output_abandon_all();
	TEST_CHECK(temporaries() == 0);
	output_abandon(&a);
	output_abandon(&b);
	TEST_CHECK(access(path_in("a.txt"), F_OK) != 0 && access(path_in("b.txt"), F_OK) != 0);
}

TEST_CASE(flush_reports_a_stream_that_failed)
{
	FILE *f = fopen("/dev/full", "w");
	TEST_CHECK(f != NULL);
	for (int i = 0; i < 2000; i++)
		fprintf(f, "line %d\n", i); /* past stdio's buffer: an earlier write failed */
	Diag d;
	TEST_CHECK(output_flush(f, "standard output", &d) == -1);
	TEST_CHECK(strcmp(d.msg, "standard output: No space left on device") == 0);
	fclose(f);
	TEST_CHECK(output_flush(stdout, "standard output", &d) == 0);
}

TEST_CASE(same_file_by_name_or_by_link)
{
	const char *a = path_in("same.txt"), *b = path_in("same-link.txt"), *c = path_in("other.txt");
	put(a, "x");
	put(c, "y");
	unlink(b);
	TEST_CHECK(symlink("same.txt", b) == 0);
	TEST_CHECK(output_same(a, a) && output_same(a, b) && !output_same(a, c));
	TEST_CHECK(!output_same(path_in("none1"), path_in("none2")));
}

int main(void)
{
	snprintf(dir, sizeof dir, "%s/utak-output.XXXXXX", getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp");
	if (strlen(dir) >= sizeof dir - 1 || !mkdtemp(dir)) {
		printf("[FAIL] test_output: no temporary directory\n");
		return 1;
	}
	TEST_RUN(a_new_file_appears_whole_at_commit);
	TEST_RUN(a_replaced_file_is_old_until_commit_and_keeps_its_mode);
	TEST_RUN(abandon_leaves_the_target_and_no_temporary);
	TEST_RUN(paths_that_cannot_be_written_fail_at_open);
	TEST_RUN(a_full_device_is_written_in_place_and_fails_at_commit);
	TEST_RUN(a_file_size_limit_mid_write_leaves_the_target);
	TEST_RUN(a_link_is_followed_and_stays_a_link);
	TEST_RUN(abandon_all_removes_every_temporary);
	TEST_RUN(flush_reports_a_stream_that_failed);
	TEST_RUN(same_file_by_name_or_by_link);
	char cmd[128];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
	if (system(cmd) != 0)
		printf("[FAIL] test_output: could not remove %s\n", dir);
	return TEST_EXIT();
}
