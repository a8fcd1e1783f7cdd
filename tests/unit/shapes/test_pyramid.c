/* The pyramid primitive through its tables, in both placements: hits from
 * outside and inside, misses, edges and the apex, the t interval, face
 * normals, bounds, the registry's two tables, parsing with located errors,
 * POV export and the mesh. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shapes/shapes.h"
#include "whitted/mesh.h"
#include "whitted/pov.h"
#include "support.h"

static const struct material mat = { { 1.0, 0.0, 0.0 }, 0.4, 0.2, 0.1, 0.3, 5.0, 0.0, 1.0 };

#define PYRAMID_BIT RT_DIALECT_BIT(RT_DIALECT_PYRAMID)
#define NEARFAR_BIT RT_DIALECT_BIT(RT_DIALECT_NEARFAR)

/* The corner placement at the origin, base 4, height 6: base [0, 4]^2 at
 * z = 0, apex (2, 2, 6).  The side facing +x is 6 (x - 2) + 2 (z - 6) = 0,
 * that is x = 4 - z / 3; the others likewise. */
static int setup_pyramid(void **state)
{
	return support_hold_shape(state, pyramid_create(vec3_make(0, 0, 0), 4.0, 6.0, &mat));
}

static void test_pyramid_hit_shrinks_t_max(void **state)
{
	struct ray r = support_ray(3, 2, 10, 0, 0, -1);
	double t_max = 100.0;

	/* x = 3 meets the +x side at z = 3 (t = 7). */
	assert_true(shape_intersect(*state, &r, 0.0, &t_max));
	assert_near(t_max, 7.0, 1e-12);
	/* Nothing nearer than that: t_max stays. */
	assert_false(shape_intersect(*state, &r, 0.0, &t_max));
	assert_near(t_max, 7.0, 1e-12);
	/* A smaller t_max than the hit: no hit, t_max unchanged. */
	t_max = 6.5;
	assert_false(shape_intersect(*state, &r, 0.0, &t_max));
	assert_near(t_max, 6.5, 0.0);
}

static void test_pyramid_hit_each_face(void **state)
{
	/* From outside each face, aimed at a point on it: the side faces at
	 * z = 1 lie 1/3 in from the base's edges. */
	static const struct {
		double o[3], d[3], t, n[3];
	} cases[] = {
		{ { 10, 2, 1 }, { -1, 0, 0 }, 10 - 11.0 / 3, { 3, 0, 1 } },
		{ { -10, 2, 1 }, { 1, 0, 0 }, 10 + 1.0 / 3, { -3, 0, 1 } },
		{ { 2, 10, 1 }, { 0, -1, 0 }, 10 - 11.0 / 3, { 0, 3, 1 } },
		{ { 2, -10, 1 }, { 0, 1, 0 }, 10 + 1.0 / 3, { 0, -3, 1 } },
		{ { 1, 3, -5 }, { 0, 0, 1 }, 5, { 0, 0, -1 } },
	};
	size_t i;

	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		struct ray r = support_ray(cases[i].o[0], cases[i].o[1], cases[i].o[2],
					   cases[i].d[0], cases[i].d[1], cases[i].d[2]);
		struct vec3 want = vec3_normalize(vec3_make(cases[i].n[0], cases[i].n[1], cases[i].n[2]));
		double t_max = INFINITY;
		struct vec3 n;

		assert_true(shape_intersect(*state, &r, 0.0, &t_max));
		assert_near(t_max, cases[i].t, 1e-12);
		n = shape_normal(*state, ray_at(&r, t_max));
		assert_vec3_near(n, want, 1e-15);
		assert_near(vec3_length(n), 1.0, 1e-15);
	}
}

static void test_pyramid_miss_keeps_t_max(void **state)
{
	/* Above the apex, beside the base, behind the ray, below the base,
	 * and beside the cross-section [1, 3]^2 at z = 3 (inside the base's
	 * square, outside the +y side). */
	static const double rays[][6] = {
		{ 10, 2, 6.5, -1, 0, 0 }, { 5, 2, 10, 0, 0, -1 }, { 10, 2, 1, 1, 0, 0 },
		{ 2, 2, -1, 1, 0, 0 }, { 10, 3.5, 3, -1, 0, 0 }, { 2, 2, 10, 0, 0, 1 },
	};

	support_assert_misses(*state, rays, sizeof(rays) / sizeof(rays[0]));
}

static void test_pyramid_apex_and_edges(void **state)
{
	struct ray apex = support_ray(2, 2, 10, 0, 0, -1);
	double t_max = INFINITY;
	double eps = 1e-9;

	/* Straight down onto the apex: a corner hits, at t = 4. */
	assert_hit(*state, &apex, 0.0, &t_max, 4.0, 0.0);
	/* Just inside and just outside the base's edge x = 4, from below. */
	{
		struct ray in = support_ray(4 - eps, 2, -5, 0, 0, 1);
		struct ray out = support_ray(4 + eps, 2, -5, 0, 0, 1);
		assert_hit(*state, &in, 0.0, &t_max, 5.0, 0.0);
		t_max = INFINITY;
		assert_false(shape_intersect(*state, &out, 0.0, &t_max));
	}
	/* Just inside and outside the slanted edge from (4, 0, 0) to the
	 * apex, at its midpoint (3, 1, 3): the cross-section at z = 3 is
	 * [1, 3]^2, and the line x - y = 2 touches it at that corner only. */
	{
		struct ray in = support_ray(-2 - eps, -4, 3, 1, 1, 0);
		struct ray out = support_ray(-2 + eps, -4, 3, 1, 1, 0);
		assert_hit(*state, &in, 0.0, &t_max, 5.0, 1e-8);
		t_max = INFINITY;
		assert_false(shape_intersect(*state, &out, 0.0, &t_max));
	}
}

static void test_pyramid_from_inside(void **state)
{
	struct ray r = support_ray(2.5, 2, 1, 1, 0, 0);
	struct ray up = support_ray(1, 1, 0.5, 0, 0, 1);
	struct ray down = support_ray(1, 1, 0.5, 0, 0, -1);
	double t_max = INFINITY;

	/* Out through the +x side at x = 11/3: t = 7/6, normal (3, 0, 1)/√10. */
	assert_hit(*state, &r, 1e-9, &t_max, 7.0 / 6.0, 1e-12);
	assert_vec3_near(shape_normal(*state, ray_at(&r, t_max)),
			 vec3_normalize(vec3_make(3, 0, 1)), 1e-15);
	/* Up from (1, 1, 0.5): the -x and -y sides meet x = 1 at z = 3 (t =
	 * 2.5); down: the base at t = 0.5. */
	assert_hit(*state, &up, 1e-9, &t_max, 2.5, 1e-12);
	assert_hit(*state, &down, 1e-9, &t_max, 0.5, 1e-12);
	assert_vec3_near(shape_normal(*state, ray_at(&down, t_max)), vec3_make(0, 0, -1), 0.0);
}

static void test_pyramid_t_min_and_behind(void **state)
{
	struct ray r = support_ray(10, 2, 1, -1, 0, 0);
	struct ray away = support_ray(10, 2, 1, 1, 0, 0);
	double t_max = INFINITY;

	/* In at x = 11/3 (t = 19/3), out at x = 1/3 (t = 29/3): with t_min
	 * past the entry, the exit. */
	assert_hit(*state, &r, 7.0, &t_max, 29.0 / 3.0, 1e-12);
	t_max = INFINITY;
	assert_false(shape_intersect(*state, &r, 10.0, &t_max));
	assert_true(isinf(t_max));
	assert_false(shape_intersect(*state, &away, 0.0, &t_max));
	assert_true(isinf(t_max));
}

static void test_pyramid_non_unit_direction(void **state)
{
	struct ray r = support_ray(10, 2, 1, -0.5, 0, 0);
	struct ray in = support_ray(2.5, 2, 1, 3, 0, 0);
	double t_max = INFINITY;

	/* |d| = 0.5: twice the distance, 2 (10 - 11/3). */
	assert_hit(*state, &r, 0.0, &t_max, 2.0 * (10 - 11.0 / 3), 1e-12);
	/* |d| = 3 from inside: (11/3 - 2.5) / 3. */
	assert_hit(*state, &in, 1e-9, &t_max, 7.0 / 18.0, 1e-12);
}

static void test_pyramid_unit_normals(void **state)
{
	/* Points on each face of a pyramid off the origin (base [1, 6] x
	 * [-2, 3] at z = 4, apex (3.5, 0.5, 7)): each face's normal, unit. */
	struct shape *s = pyramid_create(vec3_make(1, -2, 4), 5.0, 3.0, &mat);
	const double h = 3.0, e = 2.5, len = sqrt(h * h + e * e);
	struct {
		struct vec3 p, n;
	} cases[5];
	size_t i;

	(void)state;
	assert_non_null(s);
	/* The +x side at height 1 (a third of the way up) lies 1/3 of e in. */
	cases[0].p = vec3_make(6 - e / 3, 0.5, 5);
	cases[0].n = vec3_make(h / len, 0, e / len);
	cases[1].p = vec3_make(1 + e / 3, 0, 5);
	cases[1].n = vec3_make(-h / len, 0, e / len);
	cases[2].p = vec3_make(3, 3 - e / 3, 5);
	cases[2].n = vec3_make(0, h / len, e / len);
	cases[3].p = vec3_make(4, -2 + e / 3, 5);
	cases[3].n = vec3_make(0, -h / len, e / len);
	cases[4].p = vec3_make(2, 2, 4);
	cases[4].n = vec3_make(0, 0, -1);
	for (i = 0; i < 5; i++) {
		struct vec3 n = shape_normal(s, cases[i].p);
		assert_vec3_near(n, cases[i].n, 1e-15);
		assert_near(vec3_length(n), 1.0, 1e-15);
	}
	shape_destroy(s);
}

static void test_pyramid_bounds_both_placements(void **state)
{
	/* The handouts' examples: the 2019 file's corner pyramid (0, 0, 0.1),
	 * base 30, height 60; the Jan 2023 file's centred one at (-40, 0, 5),
	 * width 30, height 40. */
	struct shape *corner = pyramid_create(vec3_make(0, 0, 0.1), 30.0, 60.0, &mat);
	struct shape *centred = pyramid_create_centred(vec3_make(-40, 0, 5), 30.0, 40.0, &mat);
	struct ray down = support_ray(15, 15, 100, 0, 0, -1);
	struct ray apex = support_ray(-40, 0, 100, 0, 0, -1);
	struct aabb box;
	double t_max = INFINITY;

	(void)state;
	assert_non_null(corner);
	assert_non_null(centred);
	assert_true(shape_bounds(corner, &box));
	assert_vec3_near(box.min, vec3_make(0, 0, 0.1), 0.0);
	assert_vec3_near(box.max, vec3_make(30, 30, 60.1), 1e-12);
	assert_true(shape_bounds(centred, &box));
	assert_vec3_near(box.min, vec3_make(-55, -15, 5), 0.0);
	assert_vec3_near(box.max, vec3_make(-25, 15, 45), 0.0);
	/* The apexes: (15, 15, 60.1) and (-40, 0, 45). */
	assert_hit(corner, &down, 0.0, &t_max, 100 - 60.1, 1e-12);
	assert_hit(centred, &apex, 0.0, &t_max, 55.0, 1e-12);
	/* The tables: the dialect each placement is read in, one keyword. */
	assert_ptr_equal(corner->ops, shape_ops_find_in("pyramid", 7, PYRAMID_BIT));
	assert_ptr_equal(centred->ops, shape_ops_find_in("pyramid", 7, NEARFAR_BIT));
	assert_ptr_not_equal(corner->ops, centred->ops);
	assert_string_equal(corner->ops->keyword, "pyramid");
	assert_string_equal(centred->ops->keyword, "pyramid");
	assert_int_equal(corner->ops->dialects, PYRAMID_BIT);
	assert_int_equal(centred->ops->dialects, NEARFAR_BIT);
	/* Nothing to note, the material's colour everywhere. */
	assert_null(shape_degenerate(corner));
	assert_null(shape_degenerate(centred));
	assert_false(shape_is_textured(corner));
	assert_near(shape_color_at(corner, vec3_make(15, 15, 0.1)).r, 1.0, 0.0);
	shape_destroy(corner);
	shape_destroy(centred);
}

static void test_pyramid_degenerate_by_rounding(void **state)
{
	/* A height that vanishes when added to z = 1e20. */
	struct shape *flat = pyramid_create(vec3_make(0, 0, 1e20), 4.0, 1.0, &mat);
	const struct mesh_options opt = { { { -20, -20, -20 }, { 30, 30, 30 } }, 32 };
	struct mesh m;

	(void)state;
	assert_non_null(flat);
	assert_non_null(shape_degenerate(flat));
	assert_non_null(strstr(shape_degenerate(flat), "will not be visible"));
	mesh_init(&m);
	assert_int_equal(shape_tessellate(flat, &opt, &m), 0);
	assert_int_equal(m.n_vertices, 0);
	mesh_free(&m);
	shape_destroy(flat);
}

static void test_pyramid_parse_both_placements(void **state)
{
	const struct shape_ops *corner_ops = shape_ops_find_in("pyramid", 7, PYRAMID_BIT);
	const struct shape_ops *centred_ops = shape_ops_find_in("pyramid", 7, NEARFAR_BIT);
	/* The same tokens, read by each table. */
	const char *text = "-40.0 0.0 5.0\n30.0 40.0\n1.0 0.0 0.0\n0.4 0.2 0.0 0.4\n1\n";
	struct shape *s;
	struct diag d;
	struct aabb box;

	(void)state;
	assert_non_null(corner_ops);
	assert_non_null(centred_ops);
	assert_int_equal(support_parse_object(corner_ops, text, &s, &d), 0);
	assert_ptr_equal(s->ops, corner_ops);
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-40, 0, 5), 0.0);
	assert_vec3_near(box.max, vec3_make(-10, 30, 45), 0.0);
	assert_near(s->mat.color.r, 1.0, 0.0);
	assert_coefficients(&s->mat, 0.4, 0.2, 0.0, 0.4, 1.0);
	shape_destroy(s);
	assert_int_equal(support_parse_object(centred_ops, text, &s, &d), 0);
	assert_ptr_equal(s->ops, centred_ops);
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-55, -15, 5), 0.0);
	assert_vec3_near(box.max, vec3_make(-25, 15, 45), 0.0);
	shape_destroy(s);
}

/* Each parse error: the code, the line and column of the offending token,
 * and the message, read as the corner placement or (centred) the centred
 * one. */
static void test_pyramid_parse_errors(void **state)
{
	static const struct {
		bool centred;
		struct support_object_error e;
	} cases[] = {
		{ false, { "0 0 0\n0 5\n1 0 0\n0.4 0.2 0.1 0.3\n5\n", RT_E_RANGE, 2, 1,
		           "pyramid base length must be > 0, found 0" } },
		{ false, { "0 0 0\n10  -5\n1 0 0\n0.4 0.2 0.1 0.3\n5\n", RT_E_RANGE, 2, 5,
		           "pyramid height must be > 0, found -5" } },
		{ true, { "0 0 0\n-1 5\n1 0 0\n0.4 0.2 0.1 0.3\n5\n", RT_E_RANGE, 2, 1,
		          "pyramid base width must be > 0, found -1" } },
		{ true, { "0 0 0 10 0 1 0 0 0.4 0.2 0.1 0.3 5", RT_E_RANGE, 1, 10,
		          "pyramid height must be > 0, found 0" } },
		{ false, { "0 0 0 1e200 5 1 0 0 0.4 0.2 0.1 0.3 5", RT_E_RANGE, 1, 7,
		           "pyramid base length is too large" } },
		{ false, { "0 0 abc 10 5", RT_E_SYNTAX, 1, 5,
		           "expected a number (pyramid corner), found 'abc'" } },
		{ true, { "0 0\n\n  x", RT_E_SYNTAX, 3, 3,
		          "expected a number (pyramid base centre), found 'x'" } },
		{ false, { "0 0 0 10", RT_E_SYNTAX, 1, 9,
		           "expected a number (pyramid height), found end of file" } },
		/* The material is checked too: a colour out of [0, 1]. */
		{ false, { "0 0 0 10 5\n1 2 0\n0.4 0.2 0.1 0.3 5", RT_E_RANGE, 2, 3,
		           "colour component must be in [0, 1]" } },
		{ false, { "0 0 0 nan 5", RT_E_RANGE, 1, 7,
		           "expected a finite decimal number (pyramid base length)" } },
	};
	const struct shape_ops *corner_ops = shape_ops_find_in("pyramid", 7, PYRAMID_BIT);
	const struct shape_ops *centred_ops = shape_ops_find_in("pyramid", 7, NEARFAR_BIT);
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++)
		support_assert_object_error(cases[i].centred ? centred_ops : corner_ops, &cases[i].e);
}

/* True when (x, y) lies inside the triangle's projection on z (strictly,
 * by a margin). */
static bool covers(const double v[9], double x, double y)
{
	double d[3];
	int k;

	for (k = 0; k < 3; k++) {
		const double *a = v + 3 * k, *b = v + 3 * ((k + 1) % 3);
		d[k] = (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
	}
	return (d[0] > 1e-9 && d[1] > 1e-9 && d[2] > 1e-9) ||
	       (d[0] < -1e-9 && d[1] < -1e-9 && d[2] < -1e-9);
}

/* The base's triangles (those n of them in v whose corners all lie at
 * height z) cover the square [x0, x0 + b] x [y0, y0 + b] once: a point near
 * the middle of each of its edges lies in exactly one of them. */
static void assert_base_covered(const double (*v)[9], int n, double x0, double y0, double b,
				double z)
{
	const double in[4][2] = {
		{ x0 + 0.5 * b, y0 + 0.05 * b }, { x0 + 0.95 * b, y0 + 0.5 * b },
		{ x0 + 0.5 * b, y0 + 0.95 * b }, { x0 + 0.05 * b, y0 + 0.5 * b },
	};
	int i, k, hits;

	for (k = 0; k < 4; k++) {
		hits = 0;
		for (i = 0; i < n; i++)
			if (v[i][2] == z && v[i][5] == z && v[i][8] == z)
				hits += covers(v[i], in[k][0], in[k][1]);
		assert_int_equal(hits, 1);
	}
}

/* The six triangles' corners in the POV text, in order. */
static int pov_triangles(const char *text, double v[6][9])
{
	const char *at = text;
	int n = 0;

	while (n < 6 && (at = strstr(at, "triangle { ")) != NULL) {
		if (sscanf(at, "triangle { <%lf,%lf,%lf>, <%lf,%lf,%lf>, <%lf,%lf,%lf> }",
			   &v[n][0], &v[n][1], &v[n][2], &v[n][3], &v[n][4], &v[n][5],
			   &v[n][6], &v[n][7], &v[n][8]) != 9)
			return -1;
		n++;
		at++;
	}
	return n;
}

static void test_pyramid_export_pov(void **state)
{
	struct shape *s = pyramid_create(vec3_make(0.1, -2, 3), 4.0, 6.0, &mat);
	char *text = support_export_pov(s, RT_POV_FINISH_PLAIN), *tex, *at;
	double v[6][9], area_z = 0.0;
	int i, k, n = 0;

	(void)state;
	assert_non_null(s);
	assert_true(strncmp(text, "mesh {\n", 7) == 0);
	assert_int_equal(pov_triangles(text, v), 6);
	for (at = text; (at = strstr(at, "triangle {")) != NULL; at++)
		n++;
	assert_int_equal(n, 6);
	/* Every corner is one of the five, written exactly (0.1 + 4 reads
	 * back as the same double), and the base's two triangles cover the
	 * square: their areas projected on z sum to 16. */
	for (i = 0; i < 6; i++) {
		for (k = 0; k < 3; k++) {
			double x = v[i][3 * k], y = v[i][3 * k + 1], z = v[i][3 * k + 2];
			bool base = (x == 0.1 || x == 0.1 + 4.0) && (y == -2 || y == 2) && z == 3;
			bool apex = x == 0.1 + 2.0 && y == 0 && z == 9;
			assert_true(base || apex);
		}
		if (v[i][2] == 3 && v[i][5] == 3 && v[i][8] == 3)
			area_z += 0.5 * fabs((v[i][3] - v[i][0]) * (v[i][7] - v[i][1]) -
					     (v[i][6] - v[i][0]) * (v[i][4] - v[i][1]));
	}
	assert_near(area_z, 16.0, 1e-12);
	assert_base_covered((const double (*)[9])v, 6, 0.1, -2, 4, 3);
	assert_non_null(strstr(text, "inside_vector <0,0,1>"));
	tex = strstr(text, "texture {");
	assert_non_null(tex);
	assert_non_null(strstr(tex, "pigment { rgb <1,0,0> } finish { ambient 0.4 diffuse 0.2 "
				    "phong 0.1 phong_size 5 reflection { 0.3 } } }"));
	/* One object: the text ends with the mesh's closing brace. */
	assert_string_equal(text + strlen(text) - 2, "}\n");
	free(text);
	text = support_export_pov(s, RT_POV_FINISH_EXACT);
	assert_non_null(strstr(text, "texture { pigment { rgb 1 } finish { ambient rgb <0.4,0,0>"));
	free(text);
	shape_destroy(s);
}

static void test_pyramid_mesh(void **state)
{
	const struct mesh_options opt = { { { -20, -20, -20 }, { 30, 30, 30 } }, 32 };
	struct shape *s = pyramid_create_centred(vec3_make(1, 2, 3), 4.0, 6.0, &mat);
	struct mesh m;
	size_t i;
	double area = 0.0, v[6][9];

	(void)state;
	assert_non_null(s);
	mesh_init(&m);
	assert_true(shape_tessellates(s));
	assert_int_equal(shape_tessellate(s, &opt, &m), 0);
	assert_int_equal(m.n_vertices, 18);
	for (i = 0; i < m.n_vertices; i += 3) {
		struct vec3 p[3], n[3], c, face;
		struct ray r;
		double t = INFINITY;
		int k;
		for (k = 0; k < 3; k++) {
			p[k] = mesh_vertex(&m, i + k, &n[k], NULL);
			v[i / 3][3 * k] = p[k].x;
			v[i / 3][3 * k + 1] = p[k].y;
			v[i / 3][3 * k + 2] = p[k].z;
		}
		c = vec3_scale(vec3_add(p[0], vec3_add(p[1], p[2])), 1.0 / 3.0);
		/* Flat: the face's normal at every corner, the one the shape
		 * gives at the centroid, and the winding agrees with it. */
		for (k = 0; k < 3; k++)
			assert_vec3_near(n[k], shape_normal(s, c), 1e-6);
		face = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
		assert_true(vec3_dot(face, n[0]) > 0.0);
		area += 0.5 * vec3_length(face);
		/* A ray from outside the centroid back along the normal meets
		 * the shape there. */
		r.origin = vec3_add(c, n[0]);
		r.dir = vec3_neg(n[0]);
		assert_true(shape_intersect(s, &r, 0.0, &t));
		assert_near(t, 1.0, 1e-6);
	}
	/* The base 16 and four sides of base 4 and slant height √(36 + 4). */
	assert_near(area, 16.0 + 4 * 0.5 * 4.0 * sqrt(40.0), 1e-4);
	assert_base_covered((const double (*)[9])v, 6, -1, 0, 4, 3);
	mesh_free(&m);
	shape_destroy(s);
}

SUPPORT_MAIN(SUPPORT_FIXTURE_TESTS(setup_pyramid, support_drop_shape,
				   test_pyramid_hit_shrinks_t_max, test_pyramid_hit_each_face,
				   test_pyramid_miss_keeps_t_max, test_pyramid_apex_and_edges,
				   test_pyramid_from_inside, test_pyramid_t_min_and_behind,
				   test_pyramid_non_unit_direction),
	     SUPPORT_TESTS(test_pyramid_unit_normals, test_pyramid_bounds_both_placements,
			   test_pyramid_degenerate_by_rounding,
			   test_pyramid_parse_both_placements, test_pyramid_parse_errors,
			   test_pyramid_export_pov, test_pyramid_mesh))
