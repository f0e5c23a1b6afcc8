/* test.h - the unit-test harness: a few macros in the manner of Box2D's test_macros.h.
 *
 * A test file defines cases with TEST_CASE, and a main that calls TEST_RUN for each
 * and returns TEST_EXIT(). Every case prints one line, "[PASS] name" or
 * "[FAIL] name: file:line: expression", which tests/run.sh counts. A failed check
 * ends its case (the rest of the case may depend on it) but not the file. */
#ifndef UTAK_TEST_H
#define UTAK_TEST_H

#include <math.h>
#include <setjmp.h>
#include <stdio.h>

static int test_failures;
static jmp_buf test_escape;
static const char *test_where_file;
static int test_where_line;
static const char *test_where_expr;

#define TEST_CASE(name) static void name(void)

/* TEST_CHECK(cond): the case fails, and stops, unless cond holds. */
#define TEST_CHECK(cond)                                                                 \
	do {                                                                             \
		if (!(cond)) {                                                           \
			test_where_file = __FILE__;                                      \
			test_where_line = __LINE__;                                      \
			test_where_expr = #cond;                                         \
			longjmp(test_escape, 1);                                         \
		}                                                                        \
	} while (0)

/* TEST_NEAR(a, b, tol): |a - b| <= tol, printing both values when it fails. */
#define TEST_NEAR(a, b, tol)                                                             \
	do {                                                                             \
		double test_a_ = (a), test_b_ = (b);                                     \
		if (!(fabs(test_a_ - test_b_) <= (tol))) {                               \
			fprintf(stderr, "  %s = %.9g, %s = %.9g\n", #a, test_a_, #b,    \
				test_b_);                                                \
			TEST_CHECK(fabs(test_a_ - test_b_) <= (tol));                    \
		}                                                                        \
	} while (0)

#define TEST_RUN(name)                                                                   \
	do {                                                                             \
		if (setjmp(test_escape) == 0) {                                          \
			name();                                                          \
			printf("[PASS] %s\n", #name);                                    \
		} else {                                                                 \
			test_failures++;                                                 \
			printf("[FAIL] %s: %s:%d: %s\n", #name, test_where_file,         \
			       test_where_line, test_where_expr);                        \
		}                                                                        \
		fflush(stdout);                                                          \
	} while (0)

#define TEST_EXIT() (test_failures ? 1 : 0)

#endif
