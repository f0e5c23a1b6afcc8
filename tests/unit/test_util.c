/* test_util.c - the allocation wrapper and its one out-of-memory hook (util.h): an
 * embedding program's handler sees every failure with its sizes, the default ends
 * the program with one line and exit status 3, and a handler that returns aborts. */
#include <setjmp.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <unistd.h>

#include "test.h"
#include "utak/base/util.h"

static jmp_buf util_back;
static size_t seen_n, seen_size;
static int seen_calls;

static void catch_failure(size_t n, size_t size, void *context)
{
	seen_n = n, seen_size = size;
	seen_calls += *(int *)context;
	longjmp(util_back, 1);
}

static void return_anyway(size_t n, size_t size, void *context)
{
	(void)n, (void)size, (void)context;
}

/* An overflowing request never reaches the allocator: the handler gets it. */
TEST_CASE(util_hook_sees_each_failure)
{
	int one = 1;
	seen_calls = 0;
	util_set_out_of_memory(catch_failure, &one);
	if (setjmp(util_back) == 0) {
		util_alloc(SIZE_MAX / 2, 4);
		TEST_CHECK(!"util_alloc returned from an overflowing request");
	}
	TEST_CHECK(seen_calls == 1 && seen_n == SIZE_MAX / 2 && seen_size == 4);
	void *p = util_alloc(8, 8);
	if (setjmp(util_back) == 0) {
		util_realloc(p, SIZE_MAX / 8 + 1, 8);
		TEST_CHECK(!"util_realloc returned from an overflowing request");
	}
	TEST_CHECK(seen_calls == 2 && seen_n == SIZE_MAX / 8 + 1 && seen_size == 8);
	int cap = 8;
	if (setjmp(util_back) == 0) {
		util_grow(p, &cap, INT32_MAX, 8);
		TEST_CHECK(!"util_grow returned from an overflowing request");
	}
	TEST_CHECK(seen_calls == 3);
	free(p);
	util_set_out_of_memory(NULL, NULL);
}

/* run_child(handler): the exit status or signal of a child that installs handler
 * and asks for too much, with what it wrote on stderr in err. */
static int run_child(UtilOutOfMemory *handler, char *err, size_t size)
{
	int fd[2];
	if (pipe(fd) != 0)
		return -1;
	fflush(stdout);
	pid_t pid = fork();
	if (pid == 0) {
		close(fd[0]);
		dup2(fd[1], 2);
		util_set_out_of_memory(handler, NULL);
		util_alloc(SIZE_MAX / 2, 4);
		_exit(0);
	}
	close(fd[1]);
	ssize_t got = read(fd[0], err, size - 1);
	err[got > 0 ? got : 0] = 0;
	close(fd[0]);
	int status = 0;
	waitpid(pid, &status, 0);
	return status;
}

TEST_CASE(util_default_says_one_line_and_exits_3)
{
	char err[256];
	int status = run_child(NULL, err, sizeof err);
	TEST_CHECK(WIFEXITED(status) && WEXITSTATUS(status) == 3);
	char want[128];
	snprintf(want, sizeof want, "utak: out of memory (%zu x 4 bytes)\n", SIZE_MAX / 2);
	TEST_CHECK(strcmp(err, want) == 0);
}

TEST_CASE(util_handler_that_returns_aborts)
{
	char err[256];
	int status = run_child(return_anyway, err, sizeof err);
	TEST_CHECK(WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT);
}

int main(void)
{
	TEST_RUN(util_hook_sees_each_failure);
	TEST_RUN(util_default_says_one_line_and_exits_3);
	TEST_RUN(util_handler_that_returns_aborts);
	return TEST_EXIT();
}
