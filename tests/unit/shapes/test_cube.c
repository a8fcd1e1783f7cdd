/* nearfar's cube through its table: hits from outside and inside, misses,
 * edges and corners, the t interval, face normals, bounds, the registry,
 * parsing with located errors, POV export and the mesh. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shapes/shapes.h"
#include "whitted/mesh.h"
#include "whitted/pov.h"
#include "support.h"

static const struct material mat = { { 0.0, 0.5, 1.0 }, 0.15, 0.1, 0.4, 0.45, 10.0, 0.0, 1.0 };

#define NEARFAR_BIT RT_DIALECT_BIT(RT_DIALECT_NEARFAR)

/* The handout's cube: corner (-100, -100, 10), side 40, the box
 * [-100, -60] x [-100, -60] x [10, 50]. */
static int setup_cube(void **state)
{
	return support_hold_shape(state, cube_create(vec3_make(-100, -100, 10), 40.0, &mat));
}

static void test_cube_hit_shrinks_t_max(void **state)
{
	struct ray r = support_ray(-80, -80, 100, 0, 0, -1);
	double t_max = 100.0;

	/* Down onto the top z = 50: t = 50. */
	assert_true(shape_intersect(*state, &r, 0.0, &t_max));
	assert_near(t_max, 50.0, 0.0);
	assert_false(shape_intersect(*state, &r, 0.0, &t_max));
	assert_near(t_max, 50.0, 0.0);
	t_max = 49.0;
	assert_false(shape_intersect(*state, &r, 0.0, &t_max));
	assert_near(t_max, 49.0, 0.0);
}

static void test_cube_hit_each_face(void **state)
{
	static const struct {
		double o[3], d[3], t, n[3];
	} cases[] = {
		{ { -200, -70, 20 }, { 1, 0, 0 }, 100, { -1, 0, 0 } },
		{ { 0, -70, 20 }, { -1, 0, 0 }, 60, { 1, 0, 0 } },
		{ { -90, -200, 40 }, { 0, 1, 0 }, 100, { 0, -1, 0 } },
		{ { -90, 0, 40 }, { 0, -1, 0 }, 60, { 0, 1, 0 } },
		{ { -65, -95, 0 }, { 0, 0, 1 }, 10, { 0, 0, -1 } },
		{ { -65, -95, 60 }, { 0, 0, -1 }, 10, { 0, 0, 1 } },
	};
	size_t i;

	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		struct ray r = support_ray(cases[i].o[0], cases[i].o[1], cases[i].o[2],
					   cases[i].d[0], cases[i].d[1], cases[i].d[2]);
		struct vec3 want = vec3_make(cases[i].n[0], cases[i].n[1], cases[i].n[2]);
		double t_max = INFINITY;
		struct vec3 n;

		assert_true(shape_intersect(*state, &r, 0.0, &t_max));
		assert_near(t_max, cases[i].t, 0.0);
		n = shape_normal(*state, ray_at(&r, t_max));
		assert_vec3_near(n, want, 0.0);
		assert_near(vec3_length(n), 1.0, 0.0);
	}
}

static void test_cube_slanted_hit(void **state)
{
	/* From (-20, -80, 90) towards (-60, -80, 30): direction (-40, 0, -60)
	 * reaches x = -60 at t = 1 (z = 30, on the +x face) and z = 50 at t =
	 * 2/3 (x = -46.7, outside): the +x face at t = 1. */
	struct ray r = support_ray(-20, -80, 90, -40, 0, -60);
	double t_max = INFINITY;

	assert_hit(*state, &r, 0.0, &t_max, 1.0, 1e-15);
	assert_vec3_near(shape_normal(*state, ray_at(&r, t_max)), vec3_make(1, 0, 0), 0.0);
}

static void test_cube_miss_keeps_t_max(void **state)
{
	static const double rays[][6] = {
		/* beside, above, behind, parallel outside a face, and over the
		 * top edge y = -60 (z = 72 there, and z = 50 only at y = -170) */

		  	{ -59, -80, 100, 0, 0, -1 }, { -200, -80, 51, 1, 0, 0 }, { -80, -80, 100, 0, 0, 1 },
		{ -200, -59.9, 20, 1, 0, 0 }, { -80, -20, 80, 0, -1, -0.2 },
	};

	support_assert_misses(*state, rays, sizeof(rays) / sizeof(rays[0]));
}

static void test_cube_edges_and_corners(void **state)
{
	const double eps = 1e-9;
	/* Along the top face's plane z = 50: on the boundary, it enters at
	 * x = -100. */
	struct ray along = support_ray(-200, -80, 50, 1, 0, 0);
	/* Through the corner (-60, -60, 50) only, along (1, 1, 1)... */
	struct ray corner = support_ray(-61, -61, 51, 1, 1, -1);
	/* ...and at the edge x = -60, y = -60, just inside and outside. */
	struct ray in = support_ray(-50 - eps, -70, 30, -1, 1, 0);
	struct ray out = support_ray(-50 + eps, -70, 30, -1, 1, 0);
	double t_max = INFINITY;

	assert_hit(*state, &along, 0.0, &t_max, 100.0, 0.0);
	assert_hit(*state, &corner, 0.0, &t_max, 1.0, 1e-12);
	assert_hit(*state, &in, 0.0, &t_max, 10.0, 1e-8);
	t_max = INFINITY;
	assert_false(shape_intersect(*state, &out, 0.0, &t_max));
}

static void test_cube_from_inside(void **state)
{
	struct ray r = support_ray(-80, -80, 30, 0, 1, 0);
	struct ray slow = support_ray(-80, -80, 30, 0, 0, -0.25);
	double t_max = INFINITY;

	/* Out through y = -60: t = 20, normal +y. */
	assert_hit(*state, &r, 1e-9, &t_max, 20.0, 0.0);
	assert_vec3_near(shape_normal(*state, ray_at(&r, t_max)), vec3_make(0, 1, 0), 0.0);
	/* |d| = 1/4 down to z = 10: 20 / (1/4) = 80. */
	assert_hit(*state, &slow, 1e-9, &t_max, 80.0, 0.0);
	assert_vec3_near(shape_normal(*state, ray_at(&slow, t_max)), vec3_make(0, 0, -1), 0.0);
}

static void test_cube_t_min_and_non_unit(void **state)
{
	struct ray r = support_ray(-200, -70, 20, 2, 0, 0);
	double t_max = INFINITY;

	/* |d| = 2: in at x = -100 (t = 50), out at x = -60 (t = 70). */
	assert_hit(*state, &r, 0.0, &t_max, 50.0, 0.0);
	assert_hit(*state, &r, 50.0, &t_max, 70.0, 0.0);
	t_max = INFINITY;
	assert_false(shape_intersect(*state, &r, 70.0, &t_max));
	assert_true(isinf(t_max));
}

static void test_cube_bounds_and_table(void **state)
{
	struct aabb box;

	assert_true(shape_bounds(*state, &box));
	assert_vec3_near(box.min, vec3_make(-100, -100, 10), 0.0);
	assert_vec3_near(box.max, vec3_make(-60, -60, 50), 0.0);
	assert_null(shape_degenerate(*state));
	assert_false(shape_is_textured(*state));
	assert_near(shape_color_at(*state, vec3_make(-80, -80, 50)).b, 1.0, 0.0);
	/* The cube is nearfar's keyword and only nearfar's. */
	assert_ptr_equal(((const struct shape *)*state)->ops,
			 shape_ops_find_in("cube", 4, NEARFAR_BIT));
	assert_int_equal(((const struct shape *)*state)->ops->dialects, NEARFAR_BIT);
	assert_null(shape_ops_find_in("cube", 4, RT_DIALECT_BIT(RT_DIALECT_CLASSIC)));
	assert_null(shape_ops_find_in("cube", 4, RT_DIALECT_BIT(RT_DIALECT_SPOT)));
	assert_null(shape_ops_find_in("cube", 4, RT_DIALECT_BIT(RT_DIALECT_PYRAMID)));
}

static void test_cube_degenerate_by_rounding(void **state)
{
	struct shape *flat = cube_create(vec3_make(1e20, 0, 0), 1.0, &mat);
	const struct mesh_options opt = { { { -20, -20, -20 }, { 30, 30, 30 } }, 32 };
	struct mesh m;

	(void)state;
	assert_non_null(flat);
	assert_non_null(shape_degenerate(flat));
	mesh_init(&m);
	assert_int_equal(shape_tessellate(flat, &opt, &m), 0);
	assert_int_equal(m.n_vertices, 0);
	mesh_free(&m);
	shape_destroy(flat);
}

static void test_cube_parse(void **state)
{
	const struct shape_ops *ops = shape_ops_find_in("cube", 4, NEARFAR_BIT);
	struct shape *s;
	struct diag d;
	struct aabb box;

	(void)state;
	assert_non_null(ops);
	assert_int_equal(support_parse_object(ops, "-100 -100 10\n40.0\n0.0 0.5 1.0\n0.15 0.1 0.4 0.45\n10\n",
				    &s, &d), 0);
	assert_ptr_equal(s->ops, ops);
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-100, -100, 10), 0.0);
	assert_vec3_near(box.max, vec3_make(-60, -60, 50), 0.0);
	assert_material(&s->mat, 0.0, 0.5, 1.0, 0.15, 0.1, 0.4, 0.45, 10.0);
	shape_destroy(s);
}

static void test_cube_parse_errors(void **state)
{
	static const struct support_object_error cases[] = {
		{ "0 0 0\n0\n1 0 0\n0.4 0.2 0.1 0.3\n5\n", RT_E_RANGE, 2, 1,
		  "cube side must be > 0, found 0" },
		{ "0 0 0  -2.5 1 0 0 0.4 0.2 0.1 0.3 5", RT_E_RANGE, 1, 8,
		  "cube side must be > 0, found -2.5" },
		{ "0 0 0 1e151 1 0 0 0.4 0.2 0.1 0.3 5", RT_E_RANGE, 1, 7,
		  "cube side is too large" },
		{ "-100 -100\ncube", RT_E_SYNTAX, 2, 1,
		  "expected a number (cube corner), found 'cube'" },
		{ "1 2 3\n\t4x", RT_E_SYNTAX, 2, 2,
		  "expected a number (cube side), found '4x'" },
		{ "1 2 3 4\n0.5 0.5 0.5\n0.4 -0.2 0.1 0.3 5", RT_E_RANGE, 3, 5,
		  "diffuse coefficient must be >= 0" },
		{ "1 2 3 4 1 1 1 0 0 0 0", RT_E_SYNTAX, 1, 22,
		  "expected a number (shininess), found end of file" },
	};
	const struct shape_ops *ops = shape_ops_find_in("cube", 4, NEARFAR_BIT);
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++)
		support_assert_object_error(ops, &cases[i]);
}

static void test_cube_export_pov(void **state)
{
	struct shape *s = cube_create(vec3_make(0.1, -2, 3), 0.7, &mat);
	char *text = support_export_pov(s, RT_POV_FINISH_PLAIN), *tex;
	double x0, y0, z0, x1, y1, z1;

	(void)state;
	assert_non_null(s);
	assert_int_equal(sscanf(text, "box { <%lf,%lf,%lf>, <%lf,%lf,%lf>", &x0, &y0, &z0, &x1, &y1,
				&z1), 6);
	/* Exactly the corners whitted uses. */
	assert_true(x0 == 0.1 && y0 == -2 && z0 == 3);
	assert_true(x1 == 0.1 + 0.7 && y1 == -2 + 0.7 && z1 == 3 + 0.7);
	tex = strstr(text, "texture {");
	assert_non_null(tex);
	assert_non_null(strstr(tex, "pigment { rgb <0,0.5,1> } finish { ambient 0.15 diffuse 0.1 "
				    "phong 0.4 phong_size 10 reflection { 0.45 } } }"));
	assert_string_equal(text + strlen(text) - 2, "}\n");
	free(text);
	shape_destroy(s);
}

static void test_cube_mesh(void **state)
{
	const struct mesh_options opt = { { { -20, -20, -20 }, { 30, 30, 30 } }, 32 };
	struct mesh m;
	size_t i;

	mesh_init(&m);
	assert_true(shape_tessellates(*state));
	assert_int_equal(shape_tessellate(*state, &opt, &m), 0);
	assert_int_equal(m.n_vertices, 36);
	for (i = 0; i < m.n_vertices; i += 3) {
		struct vec3 p[3], n[3], c;
		struct ray r;
		double t = INFINITY;
		int k;
		for (k = 0; k < 3; k++) {
			p[k] = mesh_vertex(&m, i + k, &n[k], NULL);
			assert_true(p[k].x == -100 || p[k].x == -60);
			assert_true(p[k].y == -100 || p[k].y == -60);
			assert_true(p[k].z == 10 || p[k].z == 50);
		}
		c = vec3_scale(vec3_add(p[0], vec3_add(p[1], p[2])), 1.0 / 3.0);
		for (k = 0; k < 3; k++)
			assert_vec3_near(n[k], shape_normal(*state, c), 0.0);
		r.origin = vec3_add(c, n[0]);
		r.dir = vec3_neg(n[0]);
		assert_true(shape_intersect(*state, &r, 0.0, &t));
		assert_near(t, 1.0, 1e-12);
	}
	mesh_free(&m);
}

SUPPORT_MAIN(SUPPORT_FIXTURE_TESTS(setup_cube, support_drop_shape, test_cube_hit_shrinks_t_max,
				   test_cube_hit_each_face, test_cube_slanted_hit,
				   test_cube_miss_keeps_t_max, test_cube_edges_and_corners,
				   test_cube_from_inside, test_cube_t_min_and_non_unit,
				   test_cube_bounds_and_table),
	     SUPPORT_TESTS(test_cube_degenerate_by_rounding, test_cube_parse,
			   test_cube_parse_errors, test_cube_export_pov),
	     SUPPORT_FIXTURE_TESTS(setup_cube, support_drop_shape, test_cube_mesh))
