/* test_path.c - the Path polyline (path.h): length by hand computation. */
#include "test.h"
#include "utak/plan/path.h"

TEST_CASE(path_length_by_hand)
{
	Path p;
	path_init(&p);
	TEST_NEAR(path_length(&p), 0.0, 0);
	path_push(&p, vec2(0, 0));
	path_push(&p, vec2(3, 4));   /* 5 */
	path_push(&p, vec2(3, 10));  /* 6 */
	path_push(&p, vec2(4, 11));  /* sqrt 2 */
	TEST_NEAR(path_length(&p), 11 + sqrt(2.0), 1e-12);
	TEST_CHECK(p.count == 4);
	path_free(&p);
}

int main(void)
{
	TEST_RUN(path_length_by_hand);
	return TEST_EXIT();
}
