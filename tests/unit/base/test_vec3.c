/* Vector maths: exact values. */
#include "support.h"

static void test_vec3_dot_and_cross(void **state)
{
	struct vec3 x = vec3_make(1, 0, 0), y = vec3_make(0, 1, 0);

	(void)state;
	assert_near(vec3_dot(vec3_make(1, 2, 3), vec3_make(4, -5, 6)), 12.0, 0.0);
	assert_vec3_near(vec3_cross(x, y), vec3_make(0, 0, 1), 0.0);
	assert_vec3_near(vec3_cross(y, x), vec3_make(0, 0, -1), 0.0);
}

static void test_vec3_normalize(void **state)
{
	(void)state;
	assert_vec3_near(vec3_normalize(vec3_make(3, 0, 4)), vec3_make(0.6, 0, 0.8), 1e-15);
	/* The zero vector stays zero rather than becoming NaN. */
	assert_vec3_near(vec3_normalize(vec3_make(0, 0, 0)), vec3_make(0, 0, 0), 0.0);
}

static void test_vec3_add_scaled(void **state)
{
	(void)state;
	assert_vec3_near(vec3_add_scaled(vec3_make(1, 2, 3), vec3_make(1, -1, 0.5), 2.0),
			 vec3_make(3, 0, 4), 0.0);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_vec3_dot_and_cross, test_vec3_normalize, test_vec3_add_scaled))
