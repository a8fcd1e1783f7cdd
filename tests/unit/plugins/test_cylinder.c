/* The cylinder plugin: the side and both caps hit at known t, from
 * outside and inside, a tangent ray (hit) and one just outside (miss),
 * rays past a cap, non-unit directions, t_max, the normals, the bounds of
 * a slanted one, parse errors and the POV-Ray export. */
#include <math.h>
#include <stdlib.h>

#include "plugin_fixture.h"

/* Axis (0,0,0) to (0,0,10), radius 2. */
#define UPRIGHT "cylinder\n0 0 0\n0 0 10\n2\n1 0 0\n0.2 0.5 0.3 0\n10"

static int setup_upright(void **state)
{
	*state = fixture_scene(UPRIGHT);
	return 0;
}

static void test_cylinder_side_and_caps(void **state)
{
	const struct shape *s = fixture_shape(state);

	assert_near(fixture_hit(s, support_ray(5, 0, 5, -1, 0, 0)), 3.0, 0.0);
	assert_near(fixture_hit(s, support_ray(0, 0, 20, 0, 0, -1)), 10.0, 0.0);
	assert_near(fixture_hit(s, support_ray(1, 1, -4, 0, 0, 1)), 4.0, 0.0);
	/* From inside: out through the side, and through the top cap. */
	assert_near(fixture_hit(s, support_ray(0, 0, 5, 1, 0, 0)), 2.0, 0.0);
	assert_near(fixture_hit(s, support_ray(0, 0, 5, 0, 0, 1)), 5.0, 0.0);
	/* Slanting in through the top cap's rim region: enters at z = 10. */
	assert_near(fixture_hit(s, support_ray(0, 0, 12, 1, 0, -1)), 2.0, 0.0);
	/* Past the caps, and pointing away: misses. */
	assert_near(fixture_hit(s, support_ray(5, 0, 11, -1, 0, 0)), -1.0, 0.0);
	assert_near(fixture_hit(s, support_ray(5, 0, -0.5, -1, 0, 0)), -1.0, 0.0);
	assert_near(fixture_hit(s, support_ray(5, 0, 5, 1, 0, 0)), -1.0, 0.0);
}

/* The ray x = 2 along y touches the side: (y)^2 + 4 - 4 = 0 at y = 0, a
 * double root; x = 2 + 1e-9 misses. */
static void test_cylinder_tangent(void **state)
{
	const struct shape *s = fixture_shape(state);

	assert_near(fixture_hit(s, support_ray(2, -5, 5, 0, 1, 0)), 5.0, 0.0);
	assert_near(fixture_hit(s, support_ray(2 + 1e-9, -5, 5, 0, 1, 0)), -1.0, 0.0);
	/* Along the side, parallel to the axis: it meets the bottom cap's
	 * rim only, at z = 0. */
	assert_near(fixture_hit(s, support_ray(2, 0, -3, 0, 0, 1)), 3.0, 0.0);
	assert_near(fixture_hit(s, support_ray(2.001, 0, -3, 0, 0, 1)), -1.0, 0.0);
}

static void test_cylinder_non_unit_and_t_max(void **state)
{
	const struct shape *s = fixture_shape(state);
	struct ray r = support_ray(5, 0, 5, -3, 0, 0);
	double t = 0.9;

	assert_near(fixture_hit(s, r), 1.0, 1e-15);
	assert_false(shape_intersect(s, &r, 1e-9, &t));
	assert_near(t, 0.9, 0.0);
	t = INFINITY;
	assert_true(shape_intersect(s, &r, 1.1, &t));
	assert_near(t, 7.0 / 3.0, 1e-15);
}

static void test_cylinder_normals(void **state)
{
	const struct shape *s = fixture_shape(state);

	assert_vec3_near(shape_normal(s, vec3_make(2, 0, 5)), vec3_make(1, 0, 0), 0.0);
	assert_vec3_near(shape_normal(s, vec3_make(0, -2, 3)), vec3_make(0, -1, 0), 0.0);
	assert_vec3_near(shape_normal(s, vec3_make(0.5, 0.5, 10)), vec3_make(0, 0, 1), 0.0);
	assert_vec3_near(shape_normal(s, vec3_make(0.5, 0.5, 0)), vec3_make(0, 0, -1), 0.0);
}

static void test_cylinder_slanted_bounds(void **state)
{
	struct scene *sc = fixture_scene("cylinder\n0 0 0\n3 0 4\n1\n1 0 0\n0.2 0.5 0.3 0\n10");
	const struct shape *s = scene_shape(sc, 0);
	struct aabb box;

	(void)state;
	/* Axis (0.6, 0, 0.8): the caps span sqrt(1 - u_k^2) = 0.8, 1, 0.6. */
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-0.8, -1, -0.6), 1e-15);
	assert_vec3_near(box.max, vec3_make(3.8, 1, 4.6), 1e-15);
	/* Down the axis from beyond the top: the cap at distance 5. */
	assert_near(fixture_hit(s, support_ray(6, 0, 8, -0.6, 0, -0.8)), 5.0, 1e-12);
	scene_destroy(sc);
}

static void test_cylinder_parse_errors(void **state)
{
	(void)state;
	assert_scene_error("1\n64\n\n1\ncylinder\n1 2 3\n1 2 3\n2\n", -RT_E_RANGE, 7, 0,
			   "cylinder ends are the same point (it has no axis)");
	assert_scene_error_part("1\n64\n\n1\ncylinder\n0 0 0\n0 0 1\n-2\n", -RT_E_RANGE, 8, 1,
				"cylinder radius must be > 0");
	/* A radius whose square underflows to 0 (a line) or overflows. */
	assert_scene_error("1\n64\n\n1\ncylinder\n0 0 0\n0 0 1\n1e-200\n", -RT_E_RANGE, 8, 1,
			   "cylinder radius must be > 0, with a square that is finite and not 0 (about 1e-154 to 1e154), found 1e-200");
	assert_scene_error_part("1\n64\n\n1\ncylinder\n0 0 0\n0 0 1\n1e200\n", -RT_E_RANGE, 8, 0,
				"found 1e+200");
}

static void test_cylinder_export_pov(void **state)
{
	char *text = support_export_pov(fixture_shape(state), RT_POV_FINISH_PLAIN);

	assert_non_null(strstr(text, "cylinder { <0,0,0>, <0,0,10>, 2\n  texture"));
	free(text);
}

FIXTURE_MAIN("cylinder",
	     SUPPORT_FIXTURE_TESTS(setup_upright, fixture_destroy, test_cylinder_side_and_caps,
				   test_cylinder_tangent, test_cylinder_non_unit_and_t_max,
				   test_cylinder_normals),
	     SUPPORT_TESTS(test_cylinder_slanted_bounds, test_cylinder_parse_errors),
	     SUPPORT_FIXTURE_TESTS(setup_upright, fixture_destroy, test_cylinder_export_pov))
