/* test_movingai.c - the Moving AI readers (movingai.h): a good map and scenario
 * file, CRLF line ends, blank trailing lines, start == goal, and the exact one-line
 * message of every malformed input the readers diagnose. */
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "test.h"
#include "utak/plan/movingai.h"

/* write_file: a file under TMPDIR holding text; returns its path (static buffer
 * per slot). */
static const char *write_file(int slot, const char *name, const char *text)
{
	static char path[4][256];
	const char *dir = getenv("TMPDIR") ? getenv("TMPDIR") : "/tmp";
	snprintf(path[slot], sizeof path[slot], "%s/utak-movingai-%ld-%s", dir, (long)getpid(),
	         name);
	FILE *f = fopen(path[slot], "wb");
	if (!f)
		return NULL;
	fputs(text, f);
	fclose(f);
	return path[slot];
}

/* ends_with: the message ends with want (the front is the temporary path). */
static bool ends_with(const char *msg, const char *want)
{
	size_t n = strlen(msg), k = strlen(want);
	if (n < k || strcmp(msg + n - k, want) != 0) {
		fprintf(stderr, "  message \"%s\", want \"...%s\"\n", msg, want);
		return false;
	}
	return true;
}

TEST_CASE(movingai_reads_good_files)
{
	char err[MOVINGAI_ERROR_SIZE];
	const char *m =
	    write_file(0, "a.map", "type octile\r\nheight 2\r\nwidth 3\r\nmap\r\n.@T\r\nGSW\r\n");
	TEST_CHECK(m);
	Grid g;
	TEST_CHECK(movingai_read_map(m, &g, err));
	TEST_CHECK(g.w == 3 && g.h == 2);
	TEST_CHECK(grid_free_at(&g, 0, 0) && !grid_free_at(&g, 1, 0) && !grid_free_at(&g, 2, 0));
	TEST_CHECK(grid_free_at(&g, 0, 1) && grid_free_at(&g, 1, 1) && !grid_free_at(&g, 2, 1));
	const char *s = write_file(1, "a.scen",
	                           "version 1\n3\tmaps/x/a.map\t3\t2\t0\t0\t1\t1\t1.41421356\n"
	                           "0\ta.map\t3\t2\t1\t1\t1\t1\t0\n\n\n");
	MovingAiScen scen;
	TEST_CHECK(movingai_read_scen(s, &g, &scen, err));
	TEST_CHECK(scen.count == 2);
	TEST_CHECK(scen.problems[0].bucket == 3 && scen.problems[0].gx == 1 &&
	           scen.problems[0].gy == 1);
	TEST_NEAR(scen.problems[0].optimum, 1.41421356, 0);
	TEST_CHECK(scen.problems[1].line == 3 && scen.problems[1].optimum == 0);
	movingai_scen_free(&scen);
	grid_free(&g);
	unlink(m);
	unlink(s);
}

TEST_CASE(movingai_diagnoses_bad_maps)
{
	static const struct {
		const char *text, *message;
	} cases[] = {
	    {"type octagon\n", ":1: expected \"type octile\""},
	    {"type octile\nheight 0\n", ":2: expected \"height N\" with 1 <= N <= 16384"},
	    {"type octile\nheight 2\nwidth 3\nmap\n...\n",
	     ":6: the map has 1 rows, the header says 2"},
	    {"type octile\nheight 1\nwidth 3\nmap\n....\n",
	     ":5: row of 4 cells, the header says 3"},
	    {"type octile\nheight 1\nwidth 3\nmap\n.x.\n", ":5: column 2: unknown terrain 'x'"},
	    {"type octile\nheight 1\nwidth 3\nmap\n...\n\nzz\n",
	     ":7: text after the 1 rows of the map"},
	};
	char err[MOVINGAI_ERROR_SIZE];
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		const char *m = write_file(0, "bad.map", cases[i].text);
		Grid g;
		TEST_CHECK(!movingai_read_map(m, &g, err));
		TEST_CHECK(g.cells == NULL);
		TEST_CHECK(ends_with(err, cases[i].message));
		unlink(m);
	}
	TEST_CHECK(!movingai_read_map("/nonexistent/utak.map", &(Grid){0}, err));
	TEST_CHECK(ends_with(err, "/nonexistent/utak.map: cannot open: No such file or directory"));
}

TEST_CASE(movingai_diagnoses_bad_scenarios)
{
	static const struct {
		const char *text, *message;
	} cases[] = {
	    {"version 2\n", ":1: expected \"version 1\""},
	    {"version 1\n0\ta.map\t3\t2\t0\t0\t1\n", ":2: 7 TAB-separated fields, expected 9"},
	    {"version 1\nx\ta.map\t3\t2\t0\t0\t1\t1\t1\n", ":2: field 1: bad bucket \"x\""},
	    {"version 1\n0\ta.map\t2\t3\t0\t0\t1\t1\t1\n",
	     ":2: map size \"2 x 3\" (width, height) differs from the map's 3 x 2"},
	    {"version 1\n0\ta.map\t3\t2\t3\t0\t1\t1\t1\n",
	     ":2: field 5: \"3\" is not a column inside the map"},
	    {"version 1\n0\ta.map\t3\t2\t0\t0\t1\t0\t1\n",
	     ":2: the goal cell is blocked on the map"},
	    {"version 1\n0\ta.map\t3\t2\t0\t0\t1\t1\t-1\n", ":2: field 9: bad length \"-1\""},
	};
	char err[MOVINGAI_ERROR_SIZE];
	const char *m = write_file(0, "a.map", "type octile\nheight 2\nwidth 3\nmap\n.@.\n...\n");
	Grid g;
	TEST_CHECK(movingai_read_map(m, &g, err));
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		const char *s = write_file(1, "bad.scen", cases[i].text);
		MovingAiScen scen;
		TEST_CHECK(!movingai_read_scen(s, &g, &scen, err));
		TEST_CHECK(scen.count == 0 && scen.problems == NULL);
		TEST_CHECK(ends_with(err, cases[i].message));
		unlink(s);
	}
	grid_free(&g);
	unlink(m);
}

int main(void)
{
	TEST_RUN(movingai_reads_good_files);
	TEST_RUN(movingai_diagnoses_bad_maps);
	TEST_RUN(movingai_diagnoses_bad_scenarios);
	return TEST_EXIT();
}
