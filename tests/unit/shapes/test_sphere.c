/* The sphere primitive through its table: hits, misses, t_min/t_max,
 * normals, bounds, parsing and POV export. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shapes/shapes.h"
#include "scene/scene_impl.h"
#include "whitted/pov.h"
#include "shapes/solve.h"
#include "support.h"

static const struct material mat = { { 0.25, 0.5, 1.0 }, 0.4, 0.3, 0.2, 0.1, 7.0, 0.0, 1.0 };

/* A radius-2 sphere at the origin. */
static int setup_sphere(void **state)
{
	return support_hold_shape(state, sphere_create(vec3_make(0, 0, 0), 2.0, &mat));
}

static void test_sphere_hit_shrinks_t_max(void **state)
{
	struct ray r = support_ray(0, 0, -10, 0, 0, 1);
	double t_max = 100.0;

	/* |(0, 0, -10 + t)| = 2 at t = 8 and 12: the near one. */
	assert_true(shape_intersect(*state, &r, 0.0, &t_max));
	assert_near(t_max, 8.0, 1e-12);
	/* A second query with that t_max finds nothing nearer and leaves it. */
	assert_false(shape_intersect(*state, &r, 0.0, &t_max));
	assert_near(t_max, 8.0, 1e-12);
}

static void test_sphere_miss_keeps_t_max(void **state)
{
	struct ray r = support_ray(0, 2.5, -10, 0, 0, 1);
	struct ray away = support_ray(0, 0, -10, 0, 0, -1);
	double t_max = 100.0;

	assert_false(shape_intersect(*state, &r, 0.0, &t_max));
	assert_near(t_max, 100.0, 0.0);
	/* Behind the origin: roots -12 and -8. */
	assert_false(shape_intersect(*state, &away, 0.0, &t_max));
	assert_near(t_max, 100.0, 0.0);
}

static void test_sphere_tangent(void **state)
{
	struct ray graze = support_ray(0, 2, -10, 0, 0, 1);
	double t_max = INFINITY;

	/* y = 2 touches the sphere at (0, 2, 0), t = 10. */
	assert_hit(*state, &graze, 0.0, &t_max, 10.0, 1e-9);
}

static void test_sphere_from_inside(void **state)
{
	struct ray r = support_ray(0, 0, 1, 0, 0, 1);
	double t_max = INFINITY;

	/* From (0, 0, 1): roots -3 and 1; the exit at z = 2. */
	assert_hit(*state, &r, 1e-6, &t_max, 1.0, 1e-12);
}

static void test_sphere_t_min_respected(void **state)
{
	struct ray r = support_ray(0, 0, -10, 0, 0, 1);
	double t_max = INFINITY;

	assert_hit(*state, &r, 9.0, &t_max, 12.0, 1e-12);
	t_max = INFINITY;
	assert_false(shape_intersect(*state, &r, 12.5, &t_max));
	assert_true(isinf(t_max));
}

static void test_sphere_non_unit_direction(void **state)
{
	struct ray r = support_ray(0, 0, -10, 0, 0, 0.5);
	double t_max = INFINITY;

	/* |d| = 0.5: t = 8 / 0.5 = 16. */
	assert_hit(*state, &r, 0.0, &t_max, 16.0, 1e-12);
}

static void test_sphere_unit_normals(void **state)
{
	struct vec3 c = vec3_make(1, 2, 3);
	struct shape *s = sphere_create(c, 2.5, &mat);
	static const double dirs[][3] = {
		{ 1, 0, 0 }, { 0, -1, 0 }, { 0, 0, 1 }, { 0.6, 0.8, 0 }, { 0, 0.6, -0.8 },
		{ 2.0 / 3, -1.0 / 3, 2.0 / 3 },
	};
	size_t i;

	(void)state;
	assert_non_null(s);
	for (i = 0; i < sizeof(dirs) / sizeof(dirs[0]); i++) {
		struct vec3 u = vec3_make(dirs[i][0], dirs[i][1], dirs[i][2]);
		struct vec3 n = shape_normal(s, vec3_add_scaled(c, u, 2.5));
		assert_vec3_near(n, u, 1e-15);
		assert_near(vec3_length(n), 1.0, 1e-15);
	}
	shape_destroy(s);
}

static void test_sphere_hit_off_centre(void **state)
{
	struct shape *s = sphere_create(vec3_make(1, 2, 3), 2.5, &mat);
	struct ray r = support_ray(1, 2 + 1.5, -7, 0, 0, 1);
	double t_max = INFINITY;
	struct vec3 n;

	(void)state;
	/* 1.5 off the axis of a radius-2.5 sphere: the chord's half-length
	 * is sqrt(6.25 - 2.25) = 2, so z = 3 - 2 = 1 and t = 8. */
	assert_hit(s, &r, 0.0, &t_max, 8.0, 1e-12);
	/* The normal there is (0, 1.5, -2) / 2.5. */
	n = shape_normal(s, ray_at(&r, t_max));
	assert_vec3_near(n, vec3_make(0, 0.6, -0.8), 1e-12);
	shape_destroy(s);
}

static void test_sphere_bounds_and_defaults(void **state)
{
	struct shape *s = sphere_create(vec3_make(1, 2, 3), 2.5, &mat);
	struct aabb box;

	(void)state;
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-1.5, -0.5, 0.5), 0.0);
	assert_vec3_near(box.max, vec3_make(3.5, 4.5, 5.5), 0.0);
	/* No colour_at and no degenerate: the defaults. */
	assert_near(shape_color_at(s, vec3_make(0, 0, 0)).g, 0.5, 0.0);
	assert_null(shape_degenerate(s));
	shape_destroy(s);
}

static void test_sphere_parse(void **state)
{
	struct scene *sc = support_parse("1 1\n1\nsphere 1 -2 3.5 4  0.25 0.5 1  0.4 0.3 0.2 0.1 7\n0\n");
	struct shape *s;
	struct aabb box;
	struct ray r = support_ray(1, -2, -10, 0, 0, 1);
	double t_max = INFINITY;

	(void)state;
	s = support_only_shape(sc, "sphere");
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-3, -6, -0.5), 0.0);
	assert_vec3_near(box.max, vec3_make(5, 2, 7.5), 0.0);
	/* z = 3.5 - 4 = -0.5, t = 9.5. */
	assert_hit(s, &r, 0.0, &t_max, 9.5, 1e-12);
	assert_material(&s->mat, 0.25, 0.5, 1.0, 0.4, 0.3, 0.2, 0.1, 7.0);
	scene_destroy(sc);
}

static void test_sphere_export_pov(void **state)
{
	struct shape *s = sphere_create(vec3_make(1, -2, 0.1), 2.5, &mat);
	double x, y, z, r, cr, cg, cb, ka, kd, ks, sh, kr;
	char *text = support_export_pov(s, RT_POV_FINISH_PLAIN), *tex;

	(void)state;
	assert_int_equal(sscanf(text, "sphere { <%lf,%lf,%lf>, %lf", &x, &y, &z, &r), 4);
	assert_near(x, 1.0, 0.0);
	assert_near(y, -2.0, 0.0);
	/* 0.1 is written with 17 digits and reads back as the same double. */
	assert_true(z == 0.1);
	assert_near(r, 2.5, 0.0);
	tex = strstr(text, "texture {");
	assert_non_null(tex);
	assert_int_equal(sscanf(tex, "texture { pigment { rgb <%lf,%lf,%lf> } finish { ambient %lf "
				"diffuse %lf phong %lf phong_size %lf reflection { %lf } } }",
				&cr, &cg, &cb, &ka, &kd, &ks, &sh, &kr), 8);
	assert_near(cr, 0.25, 0.0);
	assert_near(cg, 0.5, 0.0);
	assert_near(cb, 1.0, 0.0);
	assert_near(ka, 0.4, 0.0);
	assert_near(kd, 0.3, 0.0);
	assert_near(ks, 0.2, 0.0);
	assert_near(sh, 7.0, 0.0);
	assert_near(kr, 0.1, 0.0);
	/* One object: the text ends with the sphere's closing brace. */
	assert_string_equal(text + strlen(text) - 2, "}\n");
	free(text);

	/* Exact mode: a white pigment and the ambient carries KA * colour. */
	text = support_export_pov(s, RT_POV_FINISH_EXACT);
	tex = strstr(text, "texture {");
	assert_non_null(tex);
	assert_int_equal(sscanf(tex, "texture { pigment { rgb 1 } finish { ambient rgb <%lf,%lf,%lf>",
				&cr, &cg, &cb), 3);
	assert_near(cr, 0.4 * 0.25, 1e-17);
	assert_near(cg, 0.4 * 0.5, 1e-17);
	assert_near(cb, 0.4, 1e-17);
	free(text);
	shape_destroy(s);
}

SUPPORT_MAIN(SUPPORT_FIXTURE_TESTS(setup_sphere, support_drop_shape, test_sphere_hit_shrinks_t_max,
				   test_sphere_miss_keeps_t_max, test_sphere_tangent,
				   test_sphere_from_inside, test_sphere_t_min_respected,
				   test_sphere_non_unit_direction),
	     SUPPORT_TESTS(test_sphere_unit_normals, test_sphere_hit_off_centre,
			   test_sphere_bounds_and_defaults, test_sphere_parse,
			   test_sphere_export_pov))
