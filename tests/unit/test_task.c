/* test_task.c - the task reader (task.h; paper 2.3): the paper's nine sentences,
 * the short forms, and sentences that must be refused. */
#include <string.h>

#include "test.h"
#include "utak/base/task.h"

static const char *reading(const char *text)
{
	static char buf[64];
	Task t;
	Diag d;
	if (task_parse(text, &t, &d))
		return "refused";
	task_short_form(&t, buf, sizeof buf);
	return buf;
}

TEST_CASE(the_papers_nine_sentences)
{
	static const char *const cases[9][3] = {
		{"Go to the northeast corner", "go ne-corner", "(i)"},
		{"Go to the next room", "go next-room", "(ii)"},
		{"Go to the square", "go square", "(iii)"},
		{"Go round the square and return", "go round square", "(iv)"},
		{"Push the square into the northeast corner", "push square ne-corner", "(v)"},
		{"Push the square into the next room", "push square next-room", "(vi)"},
		{"Push the brick through the door", "push brick through-door", "(vii)"},
		{"Push the brick around the corner", "push brick around-corner", "(viii)"},
		{"Push the L-shaped object into the next room", "push lshape next-room", "(ix)"},
	};
	for (int i = 0; i < 9; i++) {
		TEST_CHECK(strcmp(reading(cases[i][0]), cases[i][1]) == 0);
		Task t;
		Diag d;
		TEST_CHECK(task_parse(cases[i][0], &t, &d) == 0);
		TEST_CHECK(strcmp(task_paper_number(&t), cases[i][2]) == 0);
		/* The short form reads back to the same task. */
		TEST_CHECK(strcmp(reading(cases[i][1]), cases[i][1]) == 0);
	}
}

TEST_CASE(case_punctuation_and_variants)
{
	TEST_CHECK(strcmp(reading("GO TO THE NORTHEAST CORNER."), "go ne-corner") == 0);
	TEST_CHECK(strcmp(reading("  go   to the south-west corner "), "go sw-corner") == 0);
	TEST_CHECK(strcmp(reading("Go around the triangle"), "go round triangle") == 0);
	TEST_CHECK(strcmp(reading("push the brick into the se corner"), "push brick se-corner") == 0);
	TEST_CHECK(strcmp(reading("Push the brick through the doorway!"), "push brick through-door") == 0);
	TEST_CHECK(strcmp(reading("go round lshape"), "go round lshape") == 0);
	TEST_CHECK(strcmp(reading("push l-shape nw-corner"), "push lshape nw-corner") == 0);
}

TEST_CASE(refusals)
{
	static const char *const bad[] = {
		"", "   ", "go", "go to", "go to the", "go north", "go to the north corner",
		"fly to the northeast corner", "go to the northeast corner now", "push the square",
		"push square", "push the circle into the next room", "go round the square and stay",
		"go ne-corner;rm -rf", "go to the next", "push the brick through the window",
		"go to the square square", "go to the \x01 square",
		"one two three four five six seven eight nine ten eleven twelve thirteen fourteen fifteen sixteen seventeen",
	};
	for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
		TEST_CHECK(strcmp(reading(bad[i]), "refused") == 0);
	Task t;
	Diag d;
	TEST_CHECK(task_parse("go to the moon", &t, &d) == -1);
	TEST_CHECK(strstr(d.msg, "unknown task 'go to the moon'") != NULL);
	TEST_CHECK(strstr(d.msg, "go CORNER") != NULL && strchr(d.msg, '\n') == NULL);
}

int main(void)
{
	TEST_RUN(the_papers_nine_sentences);
	TEST_RUN(case_punctuation_and_variants);
	TEST_RUN(refusals);
	return TEST_EXIT();
}
