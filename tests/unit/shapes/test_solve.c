/* The pure intersection maths: stable quadratic roots, ray/sphere,
 * Moller-Trumbore ray/triangle, and the ray through a convex solid of
 * planes. */
#include <math.h>

#include "shapes/solve.h"
#include "support.h"

static void test_solve_quadratic_two_roots_ascending(void **state)
{
	double roots[2];

	(void)state;
	/* x^2 - 3x + 2 = (x - 1)(x - 2) */
	assert_int_equal(solve_quadratic(1, -3, 2, roots), 2);
	assert_near(roots[0], 1.0, 0.0);
	assert_near(roots[1], 2.0, 0.0);
	/* -x^2 + 3x - 2: the same roots, still ascending with a < 0. */
	assert_int_equal(solve_quadratic(-1, 3, -2, roots), 2);
	assert_near(roots[0], 1.0, 0.0);
	assert_near(roots[1], 2.0, 0.0);
	/* x^2 - 4 (b = 0): -2 and 2. */
	assert_int_equal(solve_quadratic(1, 0, -4, roots), 2);
	assert_near(roots[0], -2.0, 0.0);
	assert_near(roots[1], 2.0, 0.0);
	/* 2x^2 + 2x - 4 = 2 (x + 2)(x - 1) */
	assert_int_equal(solve_quadratic(2, 2, -4, roots), 2);
	assert_near(roots[0], -2.0, 0.0);
	assert_near(roots[1], 1.0, 0.0);
}

static void test_solve_quadratic_double_and_no_roots(void **state)
{
	double roots[2];

	(void)state;
	/* (x - 1)^2: disc = 4 - 4 = 0. */
	assert_int_equal(solve_quadratic(1, -2, 1, roots), 2);
	assert_near(roots[0], 1.0, 0.0);
	assert_near(roots[1], 1.0, 0.0);
	/* x^2 = 0 (b = c = 0). */
	assert_int_equal(solve_quadratic(1, 0, 0, roots), 2);
	assert_near(roots[0], 0.0, 0.0);
	assert_near(roots[1], 0.0, 0.0);
	/* x^2 + 1: disc = -4. */
	assert_int_equal(solve_quadratic(1, 0, 1, roots), 0);
	/* x^2 + x + 1: disc = -3. */
	assert_int_equal(solve_quadratic(1, 1, 1, roots), 0);
}

static void test_solve_quadratic_linear_case(void **state)
{
	double roots[2];

	(void)state;
	/* a = 0: 2x + 4 = 0 -> x = -2. */
	assert_int_equal(solve_quadratic(0, 2, 4, roots), 1);
	assert_near(roots[0], -2.0, 0.0);
	/* -4x + 1 = 0 -> x = 0.25. */
	assert_int_equal(solve_quadratic(0, -4, 1, roots), 1);
	assert_near(roots[0], 0.25, 0.0);
	/* a = b = 0: no roots, whatever c is. */
	assert_int_equal(solve_quadratic(0, 0, 1, roots), 0);
	assert_int_equal(solve_quadratic(0, 0, 0, roots), 0);
}

static void test_solve_quadratic_cancellation(void **state)
{
	double roots[2];

	(void)state;
	/* x^2 - 1e8 x + 1: roots (1e8 +- sqrt(1e16 - 4)) / 2, i.e. about 1e8
	 * and 1 / 1e8 (their product is c / a = 1).  The small root is
	 * 1e-8 + 1e-24 + ...; the textbook formula loses it entirely
	 * (1e8 - sqrt(1e16 - 4) cancels to 7.45e-9). */
	assert_int_equal(solve_quadratic(1, -1e8, 1, roots), 2);
	assert_near(roots[0], 1e-8, 1e-22);
	assert_near(roots[1], 1e8, 1e-6);
	/* The mirror image: x^2 + 1e8 x + 1. */
	assert_int_equal(solve_quadratic(1, 1e8, 1, roots), 2);
	assert_near(roots[0], -1e8, 1e-6);
	assert_near(roots[1], -1e-8, 1e-22);
	/* A tiny a: 1e-12 x^2 + x - 1.  Exactly x = (-1 +- sqrt(1 + 4e-12)) /
	 * 2e-12; the small root is 1 - 1e-12 + 2e-24 ..., and the roots sum
	 * to -b / a = -1e12, so the other is -1e12 - 1 + 1e-12. */
	assert_int_equal(solve_quadratic(1e-12, 1, -1, roots), 2);
	assert_near(roots[1], 1.0 - 1e-12, 1e-15);
	assert_near(roots[0], -1e12 - 1.0, 1e-3);
}

static void test_solve_ray_sphere_hit_near_root(void **state)
{
	struct ray r = support_ray(0, 0, -10, 0, 0, 1);
	double t = -1;

	(void)state;
	/* |(0, 0, -10 + t)|^2 = 4: t = 8 or 12; the near one. */
	assert_true(solve_ray_sphere(&r, vec3_make(0, 0, 0), 4.0, 0.0, INFINITY, &t));
	assert_near(t, 8.0, 1e-12);
	/* t_min past the near root gives the far one. */
	assert_true(solve_ray_sphere(&r, vec3_make(0, 0, 0), 4.0, 9.0, INFINITY, &t));
	assert_near(t, 12.0, 1e-12);
	/* t_max before the near root: a miss (and t untouched). */
	t = -1;
	assert_false(solve_ray_sphere(&r, vec3_make(0, 0, 0), 4.0, 0.0, 7.5, &t));
	assert_near(t, -1.0, 0.0);
	/* The interval is open: t_max = 8 exactly is a miss of the near root
	 * (and the far one is beyond it). */
	assert_false(solve_ray_sphere(&r, vec3_make(0, 0, 0), 4.0, 0.0, 8.0, &t));
	/* t_min = 12 exactly excludes both. */
	assert_false(solve_ray_sphere(&r, vec3_make(0, 0, 0), 4.0, 12.0, INFINITY, &t));
}

static void test_solve_ray_sphere_inside_behind_miss(void **state)
{
	struct ray inside = support_ray(0, 0, 0, 0, 0, 1);
	struct ray behind = support_ray(0, 0, 10, 0, 0, 1);
	struct ray miss = support_ray(3, 0, -10, 0, 0, 1);
	double t = -1;

	(void)state;
	/* From the centre: roots -2 and 2, only 2 is in front. */
	assert_true(solve_ray_sphere(&inside, vec3_make(0, 0, 0), 4.0, 0.0, INFINITY, &t));
	assert_near(t, 2.0, 1e-12);
	/* The sphere entirely behind the origin: roots -12 and -8. */
	assert_false(solve_ray_sphere(&behind, vec3_make(0, 0, 0), 4.0, 0.0, INFINITY, &t));
	/* Passing 3 from the centre of a radius-2 sphere. */
	assert_false(solve_ray_sphere(&miss, vec3_make(0, 0, 0), 4.0, 0.0, INFINITY, &t));
}

static void test_solve_ray_sphere_tangent(void **state)
{
	struct ray graze = support_ray(2, 0, -10, 0, 0, 1);
	struct ray past = support_ray(2.000001, 0, -10, 0, 0, 1);
	double t = -1;

	(void)state;
	/* x = 2 touches the radius-2 sphere at (2, 0, 0): the double root
	 * t = 10 counts as a hit. */
	assert_true(solve_ray_sphere(&graze, vec3_make(0, 0, 0), 4.0, 0.0, INFINITY, &t));
	assert_near(t, 10.0, 1e-9);
	assert_false(solve_ray_sphere(&past, vec3_make(0, 0, 0), 4.0, 0.0, INFINITY, &t));
}

static void test_solve_ray_sphere_non_unit_direction(void **state)
{
	struct ray r = support_ray(0, 0, -10, 0, 0, 2);
	struct ray slanted = support_ray(-10, 0, -10, 3, 0, 3);
	double t = -1;

	(void)state;
	/* With |d| = 2, t is half the distance: 8 / 2 = 4. */
	assert_true(solve_ray_sphere(&r, vec3_make(0, 0, 0), 4.0, 0.0, INFINITY, &t));
	assert_near(t, 4.0, 1e-12);
	/* Along (1, 0, 1) from (-10, 0, -10): the sphere of radius 2 at the
	 * origin is met at distance 10 sqrt(2) - 2 from the origin, i.e.
	 * t = (10 sqrt(2) - 2) / |(3, 0, 3)| = (10 sqrt(2) - 2) / (3 sqrt(2)). */
	assert_true(solve_ray_sphere(&slanted, vec3_make(0, 0, 0), 4.0, 0.0, INFINITY, &t));
	assert_near(t, (10.0 * sqrt(2.0) - 2.0) / (3.0 * sqrt(2.0)), 1e-12);
}

static void test_solve_ray_sphere_small_and_far(void **state)
{
	struct ray r = support_ray(0.5, 0, 0, 0, 0, 1);
	double t = -1;

	(void)state;
	/* A unit sphere a million units away, hit 0.5 off its axis:
	 * t = 1e6 - sqrt(1 - 0.25). */
	assert_true(solve_ray_sphere(&r, vec3_make(0, 0, 1e6), 1.0, 0.0, INFINITY, &t));
	assert_near(t, 1e6 - sqrt(0.75), 1e-9);
}

static void test_solve_ray_triangle_both_sides(void **state)
{
	struct vec3 v0 = vec3_make(0, 0, 0), e1 = vec3_make(1, 0, 0), e2 = vec3_make(0, 1, 0);
	struct ray above = support_ray(0.25, 0.25, 5, 0, 0, -1);
	struct ray below = support_ray(0.25, 0.25, -5, 0, 0, 1);
	double t = -1;

	(void)state;
	assert_true(solve_ray_triangle(&above, v0, e1, e2, 0.0, INFINITY, &t));
	assert_near(t, 5.0, 0.0);
	t = -1;
	assert_true(solve_ray_triangle(&below, v0, e1, e2, 0.0, INFINITY, &t));
	assert_near(t, 5.0, 0.0);
}

static void test_solve_ray_triangle_edges_inclusive(void **state)
{
	static const double on[][2] = {
		{ 0, 0 }, { 1, 0 }, { 0, 1 },		/* the vertices */
		{ 0.5, 0 }, { 0, 0.5 }, { 0.5, 0.5 },	/* a point on each edge */
	};
	static const double off[][2] = {
		{ 0.5, -1e-9 }, { -1e-9, 0.5 }, { 0.5 + 1e-9, 0.5 }, { 1.5, 0.5 }, { -0.1, -0.1 },
	};
	struct vec3 v0 = vec3_make(0, 0, 0), e1 = vec3_make(1, 0, 0), e2 = vec3_make(0, 1, 0);
	double t;
	size_t i;

	(void)state;
	/* Straight down onto the unit right triangle in z = 0: u = x and
	 * v = y exactly, t = 5. */
	for (i = 0; i < sizeof(on) / sizeof(on[0]); i++) {
		struct ray r = support_ray(on[i][0], on[i][1], 5, 0, 0, -1);
		t = -1;
		if (!solve_ray_triangle(&r, v0, e1, e2, 0.0, INFINITY, &t)) {
			print_error("(%g, %g) should be on the triangle\n", on[i][0], on[i][1]);
			fail();
		}
		assert_near(t, 5.0, 0.0);
	}
	for (i = 0; i < sizeof(off) / sizeof(off[0]); i++) {
		struct ray r = support_ray(off[i][0], off[i][1], 5, 0, 0, -1);
		if (solve_ray_triangle(&r, v0, e1, e2, 0.0, INFINITY, &t)) {
			print_error("(%g, %g) should be off the triangle\n", off[i][0], off[i][1]);
			fail();
		}
	}
}

static void test_solve_ray_triangle_parallel_behind_interval(void **state)
{
	struct vec3 v0 = vec3_make(0, 0, 0), e1 = vec3_make(1, 0, 0), e2 = vec3_make(0, 1, 0);
	struct ray parallel = support_ray(-1, 0.25, 0, 1, 0, 0);
	struct ray away = support_ray(0.25, 0.25, 5, 0, 0, 1);
	struct ray down = support_ray(0.25, 0.25, 5, 0, 0, -1);
	struct ray fast = support_ray(0.25, 0.25, 5, 0, 0, -2);
	double t = -1;

	(void)state;
	/* In the triangle's plane: det = 0, no hit. */
	assert_false(solve_ray_triangle(&parallel, v0, e1, e2, 0.0, INFINITY, &t));
	/* The triangle behind the origin: t = -5. */
	assert_false(solve_ray_triangle(&away, v0, e1, e2, 0.0, INFINITY, &t));
	/* The open interval (t_min, t_max). */
	assert_false(solve_ray_triangle(&down, v0, e1, e2, 0.0, 5.0, &t));
	assert_false(solve_ray_triangle(&down, v0, e1, e2, 5.0, INFINITY, &t));
	assert_true(solve_ray_triangle(&down, v0, e1, e2, 4.999, 5.001, &t));
	assert_near(t, 5.0, 0.0);
	/* |d| = 2: t = 5 / 2. */
	assert_true(solve_ray_triangle(&fast, v0, e1, e2, 0.0, INFINITY, &t));
	assert_near(t, 2.5, 0.0);
}

static void test_solve_ray_triangle_slanted(void **state)
{
	/* The triangle (0,0,0) (2,0,2) (0,2,0) lies in the plane z = x.  A ray
	 * from (0.5, 0.5, 10) straight down meets it at z = 0.5: t = 9.5. */
	struct vec3 v0 = vec3_make(0, 0, 0), e1 = vec3_make(2, 0, 2), e2 = vec3_make(0, 2, 0);
	struct ray r = support_ray(0.5, 0.5, 10, 0, 0, -1);
	double t = -1;

	(void)state;
	assert_true(solve_ray_triangle(&r, v0, e1, e2, 0.0, INFINITY, &t));
	assert_near(t, 9.5, 1e-12);
}

/* The unit cube [0, 1]^3 as six half-spaces, unit normals out. */
static const struct solve_plane unit_cube[6] = {
	{ { -1, 0, 0 }, 0 }, { { 1, 0, 0 }, 1 }, { { 0, -1, 0 }, 0 },
	{ { 0, 1, 0 }, 1 }, { { 0, 0, -1 }, 0 }, { { 0, 0, 1 }, 1 },
};

static void test_solve_ray_convex_enter_and_leave(void **state)
{
	struct ray in = support_ray(-1, 0.5, 0.5, 1, 0, 0);
	struct ray inside = support_ray(0.25, 0.5, 0.5, 1, 0, 0);
	struct ray fast = support_ray(-1, 0.5, 0.5, 4, 0, 0);
	double t = -1.0;

	(void)state;
	/* Enters at x = 0 (t = 1), leaves at x = 1 (t = 2). */
	assert_true(solve_ray_convex(&in, unit_cube, 6, 0.0, INFINITY, &t));
	assert_near(t, 1.0, 0.0);
	/* Past the entry (t_min = 1 is excluded), the exit. */
	assert_true(solve_ray_convex(&in, unit_cube, 6, 1.0, INFINITY, &t));
	assert_near(t, 2.0, 0.0);
	/* Past both, or with t_max at the entry (excluded): nothing. */
	assert_false(solve_ray_convex(&in, unit_cube, 6, 2.0, INFINITY, &t));
	assert_false(solve_ray_convex(&in, unit_cube, 6, 0.0, 1.0, &t));
	/* From inside: the exit at x = 1. */
	assert_true(solve_ray_convex(&inside, unit_cube, 6, 0.0, INFINITY, &t));
	assert_near(t, 0.75, 0.0);
	/* |dir| = 4: a quarter of the distance. */
	assert_true(solve_ray_convex(&fast, unit_cube, 6, 0.0, INFINITY, &t));
	assert_near(t, 0.25, 0.0);
}

static void test_solve_ray_convex_misses(void **state)
{
	struct ray behind = support_ray(-1, 0.5, 0.5, -1, 0, 0);
	struct ray beside = support_ray(-1, 1.5, 0.5, 1, 0, 0);
	struct ray slanted = support_ray(-1, 0.5, 0.5, 1, 2, 0);
	double t = -1.0;

	(void)state;
	assert_false(solve_ray_convex(&behind, unit_cube, 6, 0.0, INFINITY, &t));
	/* Parallel to the y planes, outside one of them. */
	assert_false(solve_ray_convex(&beside, unit_cube, 6, 0.0, INFINITY, &t));
	/* Leaves y < 1 at t = 0.25, before it enters x > 0 at t = 1. */
	assert_false(solve_ray_convex(&slanted, unit_cube, 6, 0.0, INFINITY, &t));
	assert_near(t, -1.0, 0.0);
}

static void test_solve_ray_convex_edges_inclusive(void **state)
{
	/* In the plane of the face y = 1: on the boundary counts as inside. */
	struct ray along = support_ray(-1, 1, 0.5, 1, 0, 0);
	/* Through the edge x = 0, y = 0 only, at t = 0.5: enters and leaves
	 * there at once. */
	struct ray graze = support_ray(-0.5, 0.5, 0.5, 1, -1, 0);
	struct ray past = support_ray(-0.5, 0.5 - 1e-9, 0.5, 1, -1, 0);
	double t = -1.0;

	(void)state;
	assert_true(solve_ray_convex(&along, unit_cube, 6, 0.0, INFINITY, &t));
	assert_near(t, 1.0, 0.0);
	assert_true(solve_ray_convex(&graze, unit_cube, 6, 0.0, INFINITY, &t));
	assert_near(t, 0.5, 0.0);
	assert_false(solve_ray_convex(&past, unit_cube, 6, 0.0, INFINITY, &t));
}

static void test_solve_convex_face(void **state)
{
	static const double on[6][3] = {
		{ 0, 0.5, 0.5 }, { 1, 0.3, 0.7 }, { 0.2, 0, 0.9 },
		{ 0.5, 1, 0.5 }, { 0.1, 0.1, 0 }, { 0.9, 0.2, 1 },
	};
	int i;

	(void)state;
	for (i = 0; i < 6; i++)
		assert_int_equal(solve_convex_face(unit_cube, 6, vec3_make(on[i][0], on[i][1], on[i][2])), i);
	/* Off the surface: the plane it is farthest outside of, or least
	 * inside. */
	assert_int_equal(solve_convex_face(unit_cube, 6, vec3_make(3, 0.5, 2)), 1);
	assert_int_equal(solve_convex_face(unit_cube, 6, vec3_make(0.5, 0.45, 0.1)), 4);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_solve_quadratic_two_roots_ascending,
			   test_solve_quadratic_double_and_no_roots,
			   test_solve_quadratic_linear_case, test_solve_quadratic_cancellation,
			   test_solve_ray_sphere_hit_near_root,
			   test_solve_ray_sphere_inside_behind_miss,
			   test_solve_ray_sphere_tangent,
			   test_solve_ray_sphere_non_unit_direction,
			   test_solve_ray_sphere_small_and_far,
			   test_solve_ray_triangle_both_sides,
			   test_solve_ray_triangle_edges_inclusive,
			   test_solve_ray_triangle_parallel_behind_interval,
			   test_solve_ray_triangle_slanted,
			   test_solve_ray_convex_enter_and_leave, test_solve_ray_convex_misses,
			   test_solve_ray_convex_edges_inclusive, test_solve_convex_face))
