/* The quad plugin: both triangles of a square hit from both sides, its
 * edges and outside, non-unit directions, t_max, the normal, the notes of
 * a degenerate and of a non-planar quad, parse errors and the POV-Ray
 * export as a mesh. */
#include <math.h>
#include <stdlib.h>

#include "plugin_fixture.h"

/* The square -1..1 x -1..1 in the plane z = 0, corners counter-clockwise:
 * triangles 1-2-3 (x >= y) and 1-3-4 (x <= y). */
#define SQUARE "quad\n-1 -1 0\n1 -1 0\n1 1 0\n-1 1 0\n1 0 0\n0.2 0.5 0.3 0\n10"

static int setup_square(void **state)
{
	*state = fixture_scene(SQUARE);
	return 0;
}

static void test_quad_hits_both_triangles_from_both_sides(void **state)
{
	const struct shape *s = fixture_shape(state);

	assert_near(fixture_hit(s, support_ray(0.5, -0.25, 5, 0, 0, -1)), 5.0, 0.0);
	assert_near(fixture_hit(s, support_ray(-0.5, 0.5, 5, 0, 0, -1)), 5.0, 0.0);
	assert_near(fixture_hit(s, support_ray(-0.5, 0.5, -3, 0, 0, 1)), 3.0, 0.0);
	/* On the diagonal and on a corner: hit; just outside an edge: not. */
	assert_near(fixture_hit(s, support_ray(0.25, 0.25, 1, 0, 0, -1)), 1.0, 0.0);
	assert_near(fixture_hit(s, support_ray(1, 1, 1, 0, 0, -1)), 1.0, 0.0);
	assert_near(fixture_hit(s, support_ray(1.0001, 0, 1, 0, 0, -1)), -1.0, 0.0);
	assert_near(fixture_hit(s, support_ray(0, -1.0001, 1, 0, 0, -1)), -1.0, 0.0);
	/* Behind the ray, and parallel to the plane: no hit. */
	assert_near(fixture_hit(s, support_ray(0, 0, 1, 0, 0, 1)), -1.0, 0.0);
	assert_near(fixture_hit(s, support_ray(-5, 0, 0, 1, 0, 0)), -1.0, 0.0);
}

static void test_quad_non_unit_direction_and_t_max(void **state)
{
	const struct shape *s = fixture_shape(state);
	struct ray r = support_ray(0.5, 0.5, 5, 0, 0, -2);
	double t = 2.0;

	assert_near(fixture_hit(s, r), 2.5, 0.0);
	assert_false(shape_intersect(s, &r, 1e-9, &t));
	assert_near(t, 2.0, 0.0);
	t = 3.0;
	assert_true(shape_intersect(s, &r, 1e-9, &t));
	assert_near(t, 2.5, 0.0);
}

static void test_quad_normal_and_bounds(void **state)
{
	const struct shape *s = fixture_shape(state);
	struct aabb box;

	assert_vec3_near(shape_normal(s, vec3_make(0.5, -0.5, 0)), vec3_make(0, 0, 1), 0.0);
	assert_vec3_near(shape_normal(s, vec3_make(-0.5, 0.5, 0)), vec3_make(0, 0, 1), 0.0);
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-1, -1, 0), 0.0);
	assert_vec3_near(box.max, vec3_make(1, 1, 0), 0.0);
	assert_null(shape_degenerate(s));
}

static void test_quad_degenerate_and_non_planar(void **state)
{
	struct scene *line = fixture_scene("quad\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n1 0 0\n0.2 0.5 0.3 0\n10");
	struct scene *bent = fixture_scene("quad\n0 0 0\n2 0 0\n2 2 0\n0 2 1\n1 0 0\n0.2 0.5 0.3 0\n10");
	const struct shape *l = scene_shape(line, 0), *b = scene_shape(bent, 0);
	char *text;

	(void)state;
	assert_string_equal(shape_degenerate(l),
			    "is degenerate (its corners are collinear) and will not be visible");
	assert_near(fixture_hit(l, support_ray(1, 0, 1, 0, 0, -1)), -1.0, 0.0);
	text = support_export_pov(l, RT_POV_FINISH_PLAIN);
	assert_non_null(strstr(text, "// a degenerate quad"));
	free(text);
	assert_non_null(strstr(shape_degenerate(b), "is not planar"));
	/* Triangle 1-2-3 is in z = 0; 1-3-4 rises to z = 1 at (0, 2). */
	assert_near(fixture_hit(b, support_ray(1.5, 0.5, 5, 0, 0, -1)), 5.0, 0.0);
	/* On 1-3-4, z = (y - x) / 2: 0.5 at (0.5, 1.5). */
	assert_near(fixture_hit(b, support_ray(0.5, 1.5, 5, 0, 0, -1)), 4.5, 1e-15);
	assert_vec3_near(shape_normal(b, vec3_make(1.5, 0.5, 0)), vec3_make(0, 0, 1), 0.0);
	/* (2,2,0) x (0,2,1) = (2,-2,4), over its length sqrt(24). */
	assert_vec3_near(shape_normal(b, vec3_make(0.5, 1.5, 0.75)),
			 vec3_make(2 / sqrt(24), -2 / sqrt(24), 4 / sqrt(24)), 1e-15);
	scene_destroy(line);
	scene_destroy(bent);
}

static void test_quad_parse_errors(void **state)
{
	(void)state;
	assert_scene_error("1\n64\n\n1\nquad\n0 0 0\n1 0 0\n1 x 0\n", -RT_E_SYNTAX, 8, 3,
			   "expected a number (quad corner), found 'x'");
	assert_scene_error("1\n64\n\n1\nquad\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n", -RT_E_RANGE,
			   10, 0, NULL);
}

static void test_quad_export_pov(void **state)
{
	char *text = support_export_pov(fixture_shape(state), RT_POV_FINISH_PLAIN);

	assert_non_null(strstr(text, "mesh {\n  triangle { <-1,-1,0>, <1,-1,0>, <1,1,0> }\n"
				     "  triangle { <-1,-1,0>, <1,1,0>, <-1,1,0> }\n  texture"));
	free(text);
}

FIXTURE_MAIN("quad",
	     SUPPORT_FIXTURE_TESTS(setup_square, fixture_destroy,
				   test_quad_hits_both_triangles_from_both_sides,
				   test_quad_non_unit_direction_and_t_max,
				   test_quad_normal_and_bounds),
	     SUPPORT_TESTS(test_quad_degenerate_and_non_planar, test_quad_parse_errors),
	     SUPPORT_FIXTURE_TESTS(setup_square, fixture_destroy, test_quad_export_pov))
