/* The triangle primitive through its table: both sides, edges, the
 * t interval, its normal, degeneracy, parsing and POV export. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shapes/shapes.h"
#include "scene/scene_impl.h"
#include "whitted/pov.h"
#include "shapes/solve.h"
#include "support.h"

static const struct material mat = { { 1.0, 0.0, 0.0 }, 0.4, 0.2, 0.1, 0.3, 5.0, 0.0, 1.0 };

/* (0,0,2) (4,0,2) (0,4,2): the right triangle with legs 4 in the plane
 * z = 2; (b - a) x (c - a) = (4,0,0) x (0,4,0) = (0,0,16). */
static int setup_triangle(void **state)
{
	return support_hold_shape(state, triangle_create(vec3_make(0, 0, 2), vec3_make(4, 0, 2),
							 vec3_make(0, 4, 2), &mat));
}

static void test_triangle_hit_from_both_sides(void **state)
{
	struct ray down = support_ray(1, 1, 10, 0, 0, -1);
	struct ray up = support_ray(1, 1, -10, 0, 0, 1);
	double t_max = INFINITY;

	/* From z = 10 down to z = 2: t = 8; from z = -10 up: t = 12. */
	assert_hit(*state, &down, 0.0, &t_max, 8.0, 1e-12);
	assert_hit(*state, &up, 0.0, &t_max, 12.0, 1e-12);
}

static void test_triangle_edges_inclusive(void **state)
{
	static const double on[][2] = {
		{ 0, 0 }, { 4, 0 }, { 0, 4 }, { 2, 0 }, { 0, 3 }, { 2, 2 }, { 1, 3 },
	};
	static const double off[][2] = {
		{ 2, -1e-9 }, { -1e-9, 2 }, { 2, 2.000001 }, { 4.000001, 0 }, { 3, 3 },
	};
	double t_max;
	size_t i;

	/* Straight down: every coordinate is a small binary fraction, so
	 * u = x / 4 and v = y / 4 are exact and the edges are hit exactly. */
	for (i = 0; i < sizeof(on) / sizeof(on[0]); i++) {
		struct ray r = support_ray(on[i][0], on[i][1], 10, 0, 0, -1);
		t_max = INFINITY;
		if (!shape_intersect(*state, &r, 0.0, &t_max)) {
			print_error("(%g, %g) is on the triangle\n", on[i][0], on[i][1]);
			fail();
		}
		assert_near(t_max, 8.0, 0.0);
	}
	for (i = 0; i < sizeof(off) / sizeof(off[0]); i++) {
		struct ray r = support_ray(off[i][0], off[i][1], 10, 0, 0, -1);
		t_max = INFINITY;
		if (shape_intersect(*state, &r, 0.0, &t_max)) {
			print_error("(%g, %g) is off the triangle\n", off[i][0], off[i][1]);
			fail();
		}
		assert_true(isinf(t_max));
	}
}

static void test_triangle_miss_behind_parallel(void **state)
{
	struct ray away = support_ray(1, 1, 10, 0, 0, 1);
	struct ray in_plane = support_ray(-5, 1, 2, 1, 0, 0);
	struct ray above = support_ray(-5, 1, 3, 1, 0, 0);
	double t_max = 50.0;

	assert_false(shape_intersect(*state, &away, 0.0, &t_max));
	/* A ray in the triangle's plane grazes it: no hit (det = 0). */
	assert_false(shape_intersect(*state, &in_plane, 0.0, &t_max));
	assert_false(shape_intersect(*state, &above, 0.0, &t_max));
	assert_near(t_max, 50.0, 0.0);
}

static void test_triangle_t_interval(void **state)
{
	struct ray r = support_ray(1, 1, 10, 0, 0, -1);
	double t_max = 8.0;

	/* The interval is open: an existing hit at 8 is not beaten. */
	assert_false(shape_intersect(*state, &r, 0.0, &t_max));
	assert_near(t_max, 8.0, 0.0);
	t_max = 100.0;
	assert_false(shape_intersect(*state, &r, 8.0, &t_max));
	assert_near(t_max, 100.0, 0.0);
	assert_true(shape_intersect(*state, &r, 7.9, &t_max));
	assert_near(t_max, 8.0, 1e-12);
}

static void test_triangle_starting_on_surface(void **state)
{
	struct ray leave = support_ray(1, 1, 2, 0, 0.6, 0.8);
	double t_max = INFINITY;

	/* A ray leaving the surface does not hit it again past t_min. */
	assert_false(shape_intersect(*state, &leave, 1e-6, &t_max));
}

static void test_triangle_non_unit_direction(void **state)
{
	struct ray r = support_ray(1, 1, 10, 0, 0, -4);
	struct ray slant = support_ray(-3, 1, 6, 1, 0, -1);
	double t_max = INFINITY;

	/* |d| = 4: t = 8 / 4 = 2. */
	assert_hit(*state, &r, 0.0, &t_max, 2.0, 1e-12);
	/* From (-3, 1, 6) along (1, 0, -1): z = 2 at t = 4, point (1, 1, 2). */
	assert_hit(*state, &slant, 0.0, &t_max, 4.0, 1e-12);
}

static void test_triangle_unit_normal(void **state)
{
	/* A slanted triangle: (0,0,0) (1,0,1) (0,1,0); (b - a) x (c - a) =
	 * (1,0,1) x (0,1,0) = (0*0 - 1*1, 1*0 - 1*0, 1*1 - 0*0) = (-1, 0, 1). */
	struct shape *s = triangle_create(vec3_make(0, 0, 0), vec3_make(1, 0, 1),
					  vec3_make(0, 1, 0), &mat);
	struct vec3 n;

	assert_vec3_near(shape_normal(*state, vec3_make(1, 1, 2)), vec3_make(0, 0, 1), 0.0);
	n = shape_normal(s, vec3_make(0.25, 0.25, 0.25));
	assert_vec3_near(n, vec3_make(-sqrt(0.5), 0, sqrt(0.5)), 1e-15);
	assert_near(vec3_length(n), 1.0, 1e-15);
	shape_destroy(s);
}

static void test_triangle_bounds(void **state)
{
	struct shape *s = triangle_create(vec3_make(1, -2, 3), vec3_make(-4, 5, 0),
					  vec3_make(2, 2, 7), &mat);
	struct aabb box;

	(void)state;
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-4, -2, 0), 0.0);
	assert_vec3_near(box.max, vec3_make(2, 5, 7), 0.0);
	shape_destroy(s);
}

static void test_triangle_degenerate(void **state)
{
	/* Collinear vertices, and a repeated vertex. */
	struct shape *line = triangle_create(vec3_make(0, 0, 0), vec3_make(1, 1, 1),
					     vec3_make(2, 2, 2), &mat);
	struct shape *point = triangle_create(vec3_make(1, 1, 1), vec3_make(1, 1, 1),
					      vec3_make(0, 0, 1), &mat);
	struct ray r = support_ray(1, 1, 10, 0, 0, -1);
	double t_max = INFINITY;

	assert_null(shape_degenerate(*state));
	assert_non_null(shape_degenerate(line));
	assert_non_null(shape_degenerate(point));
	assert_false(shape_intersect(line, &r, 0.0, &t_max));
	assert_false(shape_intersect(point, &r, 0.0, &t_max));
	shape_destroy(line);
	shape_destroy(point);
}

static void test_triangle_parse(void **state)
{
	struct scene *sc = support_parse("1 1\n1\ntriangle\n50 30 0\n70 60 0\n50 45 50\n"
					 "1.0 0.0 0.0\n0.4 0.2 0.1 0.3\n5\n0\n");
	struct aabb box;

	(void)state;
	assert_int_equal(sc->n_shapes, 1);
	assert_ptr_equal(sc->shapes[0]->ops, shape_ops_find("triangle", 8));
	assert_true(shape_bounds(sc->shapes[0], &box));
	assert_vec3_near(box.min, vec3_make(50, 30, 0), 0.0);
	assert_vec3_near(box.max, vec3_make(70, 60, 50), 0.0);
	assert_near(sc->shapes[0]->mat.kr, 0.3, 0.0);
	assert_near(sc->shapes[0]->mat.shininess, 5.0, 0.0);
	scene_destroy(sc);
}

static void test_triangle_export_pov(void **state)
{
	struct shape *s = triangle_create(vec3_make(50, 30, 0), vec3_make(70, 60, 0.3),
					  vec3_make(-50, 45, 50), &mat);
	struct shape *line = triangle_create(vec3_make(0, 0, 0), vec3_make(1, 1, 1),
					     vec3_make(2, 2, 2), &mat);
	double v[9];
	char *text = support_export_pov(s, RT_POV_FINISH_PLAIN);

	(void)state;
	assert_int_equal(sscanf(text, "triangle { <%lf,%lf,%lf>, <%lf,%lf,%lf>, <%lf,%lf,%lf>",
				&v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6], &v[7], &v[8]), 9);
	assert_near(v[0], 50, 0.0);
	assert_near(v[1], 30, 0.0);
	assert_near(v[2], 0, 0.0);
	assert_near(v[3], 70, 0.0);
	assert_near(v[4], 60, 0.0);
	/* The second vertex is stored as v0 + e1: 0 + (0.3 - 0) is still 0.3. */
	assert_true(v[5] == 0.3);
	assert_near(v[6], -50, 0.0);
	assert_near(v[7], 45, 0.0);
	assert_near(v[8], 50, 0.0);
	assert_non_null(strstr(text, "texture { pigment { rgb <1,0,0> }"));
	free(text);
	/* A degenerate triangle is a comment, not an object. */
	text = support_export_pov(line, RT_POV_FINISH_PLAIN);
	assert_memory_equal(text, "//", 2);
	assert_null(strstr(text, "triangle {"));
	free(text);
	shape_destroy(s);
	shape_destroy(line);
}

SUPPORT_MAIN(SUPPORT_FIXTURE_TESTS(setup_triangle, support_drop_shape,
				   test_triangle_hit_from_both_sides,
				   test_triangle_edges_inclusive,
				   test_triangle_miss_behind_parallel, test_triangle_t_interval,
				   test_triangle_starting_on_surface,
				   test_triangle_non_unit_direction, test_triangle_unit_normal),
	     SUPPORT_TESTS(test_triangle_bounds),
	     SUPPORT_FIXTURE_TESTS(setup_triangle, support_drop_shape, test_triangle_degenerate),
	     SUPPORT_TESTS(test_triangle_parse, test_triangle_export_pov))
