/* The general quadric through its table: roots, the clip box (inclusive,
 * per axis, the near root falling through to the far one), the linear
 * case, normals, bounds, parsing and POV export. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pov.h"
#include "shapes/solve.h"
#include "support.h"

static const struct material mat = { { 0.0, 0.0, 1.0 }, 0.4, 0.2, 0.1, 0.3, 3.0 };
/* x^2 + y^2 + z^2 - 4 = 0: the radius-2 sphere at the origin. */
static const double sphere4[10] = { 1, 1, 1, 0, 0, 0, 0, 0, 0, -4 };

static struct shape *quadric(const double coef[10], double rx, double ry, double rz,
			     double lx, double ly, double lz)
{
	struct shape *s = quadric_create(coef, vec3_make(rx, ry, rz), vec3_make(lx, ly, lz), &mat);

	assert_non_null(s);
	return s;
}

static void test_quadric_unclipped_sphere(void **state)
{
	struct shape *s = quadric(sphere4, 0, 0, 0, 0, 0, 0);
	struct ray r = support_ray(0, 0, -10, 0, 0, 1);
	struct ray miss = support_ray(0, 2.5, -10, 0, 0, 1);
	struct ray behind = support_ray(0, 0, 10, 0, 0, 1);
	double t_max = 100.0;

	(void)state;
	/* (t - 10)^2 = 4: t = 8 and 12; the near one, shrinking t_max. */
	assert_true(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 8.0, 1e-12);
	assert_false(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 8.0, 1e-12);
	t_max = 100.0;
	assert_false(shape_intersect(s, &miss, 0.0, &t_max));
	assert_false(shape_intersect(s, &behind, 0.0, &t_max));
	assert_near(t_max, 100.0, 0.0);
	/* t_min past the near root: the far one. */
	assert_true(shape_intersect(s, &r, 9.0, &t_max));
	assert_near(t_max, 12.0, 1e-12);
	shape_destroy(s);
}

static void test_quadric_tangent_inside_non_unit(void **state)
{
	struct shape *s = quadric(sphere4, 0, 0, 0, 0, 0, 0);
	struct ray graze = support_ray(2, 0, -10, 0, 0, 1);
	struct ray inside = support_ray(0, 0, 0, 0, 1, 0);
	struct ray fast = support_ray(0, 0, -10, 0, 0, 2);
	double t_max = INFINITY;

	(void)state;
	/* x = 2: t^2 - 20 t + 100 = 0, the double root t = 10. */
	assert_true(shape_intersect(s, &graze, 0.0, &t_max));
	assert_near(t_max, 10.0, 1e-9);
	t_max = INFINITY;
	/* From the centre: t = +-2, the positive one. */
	assert_true(shape_intersect(s, &inside, 1e-6, &t_max));
	assert_near(t_max, 2.0, 1e-12);
	t_max = INFINITY;
	/* |d| = 2: t = 4. */
	assert_true(shape_intersect(s, &fast, 0.0, &t_max));
	assert_near(t_max, 4.0, 1e-12);
	shape_destroy(s);
}

static void test_quadric_clipped_near_root_falls_through(void **state)
{
	/* The upper hemisphere z in [0, 5]: from below, the near root (z = -2,
	 * t = 8) is clipped and the far one (z = 2, t = 12) is the hit, the
	 * inside of the dome. */
	struct shape *s = quadric(sphere4, 0, 0, 0, 0, 0, 5);
	struct ray r = support_ray(0, 0, -10, 0, 0, 1);
	struct ray slant = support_ray(1, 0, -10, 0, 0, 1);
	double t_max = INFINITY;

	(void)state;
	assert_true(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 12.0, 1e-12);
	/* At x = 1: z = +-sqrt(3), so t = 10 + sqrt(3). */
	t_max = INFINITY;
	assert_true(shape_intersect(s, &slant, 0.0, &t_max));
	assert_near(t_max, 10.0 + sqrt(3.0), 1e-12);
	/* A far root clipped too: the lower hemisphere seen from below at
	 * x = 1, z in [-5, -1]: near root z = -sqrt(3) is in, t = 10 - sqrt(3). */
	shape_destroy(s);
	s = quadric(sphere4, 0, 0, -5, 0, 0, 4);
	t_max = INFINITY;
	assert_true(shape_intersect(s, &slant, 0.0, &t_max));
	assert_near(t_max, 10.0 - sqrt(3.0), 1e-12);
	shape_destroy(s);
	/* Both roots clipped (the band z in [-1, 1] seen along the axis): a
	 * miss, and t_max untouched. */
	s = quadric(sphere4, 0, 0, -1, 0, 0, 2);
	t_max = 50.0;
	assert_false(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 50.0, 0.0);
	shape_destroy(s);
}

static void test_quadric_clip_box_inclusive(void **state)
{
	/* z in [-2, 0]: the near root is exactly z = -2 (t = 8, computed
	 * exactly: 8 = 10 - 2), on the box's face, and counts. */
	struct shape *s = quadric(sphere4, 0, 0, -2, 0, 0, 2);
	struct ray up = support_ray(0, 0, -10, 0, 0, 1);
	struct ray down = support_ray(0, 0, 10, 0, 0, -1);
	double t_max = INFINITY;

	(void)state;
	assert_true(shape_intersect(s, &up, 0.0, &t_max));
	assert_near(t_max, 8.0, 0.0);
	/* From above: z = 2 is clipped, z = -2 (t = 12) is on the face. */
	t_max = INFINITY;
	assert_true(shape_intersect(s, &down, 0.0, &t_max));
	assert_near(t_max, 12.0, 0.0);
	shape_destroy(s);
	/* The upper face: z in [-5, -2] still contains z = -2. */
	s = quadric(sphere4, 0, 0, -5, 0, 0, 3);
	t_max = INFINITY;
	assert_true(shape_intersect(s, &up, 0.0, &t_max));
	assert_near(t_max, 8.0, 0.0);
	shape_destroy(s);
	/* And z in [-5, -2.0000001] does not. */
	s = quadric(sphere4, 0, 0, -5, 0, 0, 2.9999999);
	t_max = INFINITY;
	assert_false(shape_intersect(s, &up, 0.0, &t_max));
	shape_destroy(s);
}

static void test_quadric_clip_each_axis(void **state)
{
	/* For each axis, the half x_k in [0, 5] (the other axes unclipped):
	 * the ray along that axis from -10 meets -2 (clipped) and then 2. */
	int axis;

	(void)state;
	for (axis = 0; axis < 3; axis++) {
		double ext[3] = { 0, 0, 0 }, o[3] = { 0, 0, 0 }, d[3] = { 0, 0, 0 };
		struct shape *s;
		struct ray r;
		double t_max = INFINITY;
		struct aabb box;

		ext[axis] = 5;
		o[axis] = -10;
		d[axis] = 1;
		s = quadric(sphere4, 0, 0, 0, ext[0], ext[1], ext[2]);
		r = support_ray(o[0], o[1], o[2], d[0], d[1], d[2]);
		assert_true(shape_intersect(s, &r, 0.0, &t_max));
		assert_near(t_max, 12.0, 1e-12);
		/* Clipped on one axis: unbounded. */
		assert_false(shape_bounds(s, &box));
		shape_destroy(s);
	}
}

static void test_quadric_bounds_only_when_clipped_on_all_axes(void **state)
{
	struct shape *s;
	struct aabb box;

	(void)state;
	s = quadric(sphere4, 0, 0, 0, 0, 0, 0);
	assert_false(shape_bounds(s, &box));
	shape_destroy(s);
	s = quadric(sphere4, -3, 0, 0, 6, 0, 0);
	assert_false(shape_bounds(s, &box));
	shape_destroy(s);
	s = quadric(sphere4, -3, -3, 0, 6, 6, 0);
	assert_false(shape_bounds(s, &box));
	shape_destroy(s);
	s = quadric(sphere4, -3, -2, -1, 6, 5, 4);
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-3, -2, -1), 0.0);
	assert_vec3_near(box.max, vec3_make(3, 3, 3), 0.0);
	shape_destroy(s);
}

static void test_quadric_clip_on_three_axes(void **state)
{
	/* The sphere cut to the box [0, 5]^3: the octant x, y, z >= 0. */
	struct shape *s = quadric(sphere4, 0, 0, 0, 5, 5, 5);
	/* Along z at x = y = 1: z = +-sqrt(2), only +sqrt(2) is in the box,
	 * t = 10 + sqrt(2). */
	struct ray in = support_ray(1, 1, -10, 0, 0, 1);
	/* At x = -1 the whole line is outside the box. */
	struct ray out = support_ray(-1, 1, -10, 0, 0, 1);
	double t_max = INFINITY;

	(void)state;
	assert_true(shape_intersect(s, &in, 0.0, &t_max));
	assert_near(t_max, 10.0 + sqrt(2.0), 1e-12);
	t_max = INFINITY;
	assert_false(shape_intersect(s, &out, 0.0, &t_max));
	shape_destroy(s);
}

static void test_quadric_linear_case(void **state)
{
	/* The plane z - 3 = 0 (I = 1, J = -3): no quadratic term at all. */
	static const double plane[10] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, -3 };
	/* The paraboloid x^2 - z = 0 along z: qa = 0 for this direction,
	 * x0^2 - (z0 + t) = 0 so from (1, 0, -5) t = 1 + 5 = 6. */
	static const double para[10] = { 1, 0, 0, 0, 0, 0, 0, 0, -1, 0 };
	/* The cylinder x^2 + y^2 = 4 along its axis: qa = qb = 0, no root. */
	static const double cyl[10] = { 1, 1, 0, 0, 0, 0, 0, 0, 0, -4 };
	struct shape *p = quadric(plane, 0, 0, 0, 0, 0, 0);
	struct shape *q = quadric(para, 0, 0, 0, 0, 0, 0);
	struct shape *c = quadric(cyl, 0, 0, 0, 0, 0, 0);
	struct ray up = support_ray(0.5, 0.5, 0, 0, 0, 1);
	struct ray r = support_ray(1, 0, -5, 0, 0, 1);
	struct ray axis = support_ray(1, 0, -5, 0, 0, 1);
	double t_max = INFINITY;

	(void)state;
	assert_true(shape_intersect(p, &up, 0.0, &t_max));
	assert_near(t_max, 3.0, 0.0);
	assert_vec3_near(shape_normal(p, vec3_make(0.5, 0.5, 3)), vec3_make(0, 0, 1), 0.0);
	t_max = INFINITY;
	assert_true(shape_intersect(q, &r, 0.0, &t_max));
	assert_near(t_max, 6.0, 0.0);
	/* The gradient (2x, 0, -1) at (1, 0, 1) is (2, 0, -1) / sqrt(5). */
	assert_vec3_near(shape_normal(q, vec3_make(1, 0, 1)),
			 vec3_make(2 / sqrt(5.0), 0, -1 / sqrt(5.0)), 1e-15);
	t_max = INFINITY;
	assert_false(shape_intersect(c, &axis, 0.0, &t_max));
	/* The plane clipped to z in [0, 2] is never hit. */
	shape_destroy(p);
	p = quadric(plane, 0, 0, 0, 0, 0, 2);
	assert_false(shape_intersect(p, &up, 0.0, &t_max));
	shape_destroy(p);
	shape_destroy(q);
	shape_destroy(c);
}

static void test_quadric_unit_normals(void **state)
{
	/* The cylinder (x - 1)^2 + y^2 = 4, i.e. x^2 + y^2 - 2x - 3 = 0
	 * (G = -2, J = -3): at (3, 0, 7) the gradient (2x - 2, 2y, 0) is
	 * (4, 0, 0), at (1, 2, -1) it is (0, 4, 0).  And the ellipsoid
	 * x^2 + 4 y^2 + 9 z^2 = 36. */
	static const double cyl[10] = { 1, 1, 0, 0, 0, 0, -2, 0, 0, -3 };
	static const double ell[10] = { 1, 4, 9, 0, 0, 0, 0, 0, 0, -36 };
	struct shape *c = quadric(cyl, 0, 0, 0, 0, 0, 0);
	struct shape *e = quadric(ell, 0, 0, 0, 0, 0, 0);
	struct vec3 n;

	(void)state;
	assert_vec3_near(shape_normal(c, vec3_make(3, 0, 7)), vec3_make(1, 0, 0), 0.0);
	assert_vec3_near(shape_normal(c, vec3_make(1, 2, -1)), vec3_make(0, 1, 0), 0.0);
	/* On the ellipsoid at (0, 0, 2): gradient (2x, 8y, 18z) = (0, 0, 36). */
	assert_vec3_near(shape_normal(e, vec3_make(0, 0, 2)), vec3_make(0, 0, 1), 0.0);
	/* At (sqrt(18), 0, sqrt(2)) (18 + 18 = 36): (2 sqrt(18), 0, 18 sqrt(2))
	 * = sqrt(2) (6, 0, 18), direction (1, 0, 3) / sqrt(10). */
	n = shape_normal(e, vec3_make(sqrt(18.0), 0, sqrt(2.0)));
	assert_vec3_near(n, vec3_make(1 / sqrt(10.0), 0, 3 / sqrt(10.0)), 1e-15);
	assert_near(vec3_length(n), 1.0, 1e-15);
	shape_destroy(c);
	shape_destroy(e);
}

static void test_quadric_cross_terms(void **state)
{
	/* xy - 1 = 0 (D = 1): the hyperbola y = 1 / x extruded along z.  The
	 * ray from (-1, 0.5, 0) along +x meets x y = 1 at x = 2: t = 3. */
	static const double hyp[10] = { 0, 0, 0, 1, 0, 0, 0, 0, 0, -1 };
	/* xz - 1 (E) along +z from (0.5, 0, -1): z = 2, t = 3;
	 * yz - 1 (F) along +y from (0, -1, 0.25): y = 4, t = 5. */
	static const double xz[10] = { 0, 0, 0, 0, 1, 0, 0, 0, 0, -1 };
	static const double yz[10] = { 0, 0, 0, 0, 0, 1, 0, 0, 0, -1 };
	struct shape *s;
	struct ray r;
	double t_max;

	(void)state;
	s = quadric(hyp, 0, 0, 0, 0, 0, 0);
	r = support_ray(-1, 0.5, 0, 1, 0, 0);
	t_max = INFINITY;
	assert_true(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 3.0, 1e-12);
	/* Gradient (y, x, 0) at (2, 0.5, 0): (0.5, 2, 0) / sqrt(4.25). */
	assert_vec3_near(shape_normal(s, vec3_make(2, 0.5, 0)),
			 vec3_make(0.5 / sqrt(4.25), 2 / sqrt(4.25), 0), 1e-15);
	shape_destroy(s);
	s = quadric(xz, 0, 0, 0, 0, 0, 0);
	r = support_ray(0.5, 0, -1, 0, 0, 1);
	t_max = INFINITY;
	assert_true(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 3.0, 1e-12);
	shape_destroy(s);
	s = quadric(yz, 0, 0, 0, 0, 0, 0);
	r = support_ray(0, -1, 0.25, 0, 1, 0);
	t_max = INFINITY;
	assert_true(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 5.0, 1e-12);
	shape_destroy(s);
}

static void test_quadric_parse(void **state)
{
	struct scene *sc = support_parse(
		"1 1\n1\ngeneral\n"
		"1 1 1 0 0 0 -20 -20 -20 200\t- A B C D E F G H I J\n"
		"0 0 0 0 0 5\t- cube reference point, length, width, height\n"
		"0.0 0.0 1.0\t- color\n0.4 0.2 0.1 0.3\t- coefficients\n3\t\t- shininess\n0\n");
	struct shape *s;
	struct aabb box;
	/* (x-10)^2 + (y-10)^2 + (z-10)^2 = 100: the sphere of radius 10 at
	 * (10, 10, 10), clipped to z in [0, 5].  Along z at x = y = 10 the
	 * roots are z = 0 and 20; z = 0 is on the box's face. */
	struct ray r = support_ray(10, 10, -10, 0, 0, 1);
	double t_max = INFINITY;

	(void)state;
	assert_int_equal(sc->n_shapes, 1);
	s = sc->shapes[0];
	assert_ptr_equal(s->ops, shape_ops_find("general", 7));
	assert_false(shape_bounds(s, &box));
	assert_true(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 10.0, 1e-12);
	assert_near(s->mat.color.b, 1.0, 0.0);
	assert_near(s->mat.shininess, 3.0, 0.0);
	scene_destroy(sc);
}

static void test_quadric_export_pov(void **state)
{
	static const double coef[10] = { 1, 2, 3, 4, 5, 6, -7, -8, -9, 0.1 };
	struct shape *s = quadric(coef, -1, 0, 2, 3, 0, 4);
	struct shape *u = quadric(coef, 0, 0, 0, 0, 0, 0);
	double v[10], hx, lx, hz, lz;
	char *text = support_export_pov(s, RT_POV_FINISH_PLAIN), *clip;

	(void)state;
	assert_int_equal(sscanf(text, "quadric { <%lf,%lf,%lf>, <%lf,%lf,%lf>, <%lf,%lf,%lf>, %lf",
				&v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6], &v[7], &v[8], &v[9]),
			 10);
	assert_near(v[0], 1, 0.0);
	assert_near(v[1], 2, 0.0);
	assert_near(v[2], 3, 0.0);
	assert_near(v[3], 4, 0.0);
	assert_near(v[4], 5, 0.0);
	assert_near(v[5], 6, 0.0);
	assert_near(v[6], -7, 0.0);
	assert_near(v[7], -8, 0.0);
	assert_near(v[8], -9, 0.0);
	assert_true(v[9] == 0.1);
	/* Clipped on x to [-1, 2] and z to [2, 6], not on y. */
	clip = strstr(text, "clipped_by");
	assert_non_null(clip);
	assert_int_equal(sscanf(clip, "clipped_by { intersection { plane { x, %lf } plane { -x, %lf }"
				" plane { z, %lf } plane { -z, %lf } } }", &hx, &lx, &hz, &lz), 4);
	/* plane { x, 2 } keeps x <= 2; plane { -x, 1 } keeps -x <= 1. */
	assert_near(hx, 2, 0.0);
	assert_near(lx, 1, 0.0);
	assert_near(hz, 6, 0.0);
	assert_near(lz, -2, 0.0);
	assert_null(strstr(text, "plane { y"));
	free(text);
	text = support_export_pov(u, RT_POV_FINISH_PLAIN);
	assert_null(strstr(text, "clipped_by"));
	assert_non_null(strstr(text, "texture {"));
	free(text);
	shape_destroy(s);
	shape_destroy(u);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_quadric_unclipped_sphere),
		cmocka_unit_test(test_quadric_tangent_inside_non_unit),
		cmocka_unit_test(test_quadric_clipped_near_root_falls_through),
		cmocka_unit_test(test_quadric_clip_box_inclusive),
		cmocka_unit_test(test_quadric_clip_each_axis),
		cmocka_unit_test(test_quadric_bounds_only_when_clipped_on_all_axes),
		cmocka_unit_test(test_quadric_clip_on_three_axes),
		cmocka_unit_test(test_quadric_linear_case),
		cmocka_unit_test(test_quadric_unit_normals),
		cmocka_unit_test(test_quadric_cross_terms),
		cmocka_unit_test(test_quadric_parse),
		cmocka_unit_test(test_quadric_export_pov),
	};
	return SUPPORT_RUN(tests, argc, argv);
}
