/* test_regions.c - region finding and interpretation (regions.h, CONTROLLER SIDE), on
 * impressions drawn by hand. */
#include <string.h>

#include "test.h"
#include "utak/base/eye.h"
#include "utak/mind/regions.h"

static void set_square(Impression *imp, int ox, int oy, uint8_t level)
{
	imp->level[eye_cell_at(ox, oy)] = level;
}

TEST_CASE(regions_verge_object_utak)
{
	Impression imp;
	memset(&imp, 0, sizeof imp);
	for (int i = 0; i < RETINA_CELLS; i++)
		if (eye_cell(i).zone == EYE_PERIPHERAL)
			imp.level[i] = 5; /* a ring of verge all round */
	set_square(&imp, 0, 0, 7);        /* Utak */
	set_square(&imp, 2, 2, 7);        /* a two-square object in the fovea */
	set_square(&imp, 2, 3, 7);
	set_square(&imp, 3, 1, 7); /* ... and one square diagonal to it: a separate region */
	Regions r;
	regions_find(&r, &imp);
	TEST_CHECK(r.count == 5);
	TEST_CHECK(r.floor_regions == 1);
	int32_t verge = r.region_of[eye_cell_at(-16, -16)], floor = r.region_of[eye_cell_at(-1, 0)];
	int32_t obj = r.region_of[eye_cell_at(2, 2)], diag = r.region_of[eye_cell_at(3, 1)];
	int32_t utak = r.region_of[eye_cell_at(0, 0)];
	TEST_CHECK(obj == r.region_of[eye_cell_at(2, 3)] && obj != diag);
	TEST_CHECK(r.region[verge].reading == REGION_VERGE);
	TEST_CHECK(r.region[floor].reading == REGION_FLOOR);
	TEST_CHECK(r.region[obj].reading == REGION_OBJECT && r.region[obj].surrounded_by == floor);
	TEST_CHECK(r.region[diag].reading == REGION_OBJECT);
	TEST_CHECK(r.region[utak].reading == REGION_UTAK);
	TEST_CHECK(regions_surrounds(&r, verge, floor) && !regions_surrounds(&r, floor, verge));
	TEST_CHECK(regions_surrounds(&r, floor, obj));
}

TEST_CASE(regions_uncertain_and_two_floors)
{
	Impression imp;
	memset(&imp, 0, sizeof imp);
	/* A wall across the whole field through Utak's row: two floor regions, and a
	 * non-zero region touching the border that surrounds nothing: uncertain. */
	for (int ox = -16; ox < 16; ox++)
		set_square(&imp, ox, 0, 3);
	set_square(&imp, 0, 0, 7);
	Regions r;
	regions_find(&r, &imp);
	TEST_CHECK(r.count == 3 && r.floor_regions == 2);
	int32_t wall = r.region_of[eye_cell_at(0, 0)];
	TEST_CHECK(r.region[wall].reading == REGION_UNCERTAIN && r.region[wall].on_border);
	TEST_CHECK(r.region[wall].has_utak);
}

TEST_CASE(regions_object_touching_border_is_uncertain)
{
	Impression imp;
	memset(&imp, 0, sizeof imp);
	set_square(&imp, 0, 0, 7);
	imp.level[eye_cell_at(-16, 12)] = 4; /* a peripheral corner cell */
	Regions r;
	regions_find(&r, &imp);
	int32_t corner = r.region_of[eye_cell_at(-16, 12)];
	TEST_CHECK(r.region[corner].reading == REGION_UNCERTAIN);
	TEST_CHECK(r.region[r.region_of[eye_cell_at(0, 0)]].reading == REGION_UTAK);
}

int main(void)
{
	TEST_RUN(regions_verge_object_utak);
	TEST_RUN(regions_uncertain_and_two_floors);
	TEST_RUN(regions_object_touching_border_is_uncertain);
	return TEST_EXIT();
}
