/* The torus plugin: exact hits of known rays (through the hole, the tube
 * from outside and from inside, a tilted axis), the grazing rays over the
 * top of the tube (a double root: hit exactly at the tangent, missed just
 * above it), non-unit directions, t_max, the normal, parse errors and the
 * POV-Ray export. */
#include <math.h>
#include <stdlib.h>

#include "plugin_fixture.h"

/* Centre 0, axis z, R = 3, r = 1: the tube spans 2 <= |(x, y)| <= 4,
 * |z| <= 1. */
#define TORUS_Z "torus\n0 0 0\n0 0 5\n3 1\n1 0 0\n0.2 0.5 0.3 0\n10"

static int setup_z(void **state)
{
	*state = fixture_scene(TORUS_Z);
	return 0;
}

static int setup_tilted(void **state)
{
	/* Centre (1, 2, 3), axis y: the ring in the plane y = 2. */
	*state = fixture_scene("torus\n1 2 3\n0 2 0\n3 1\n1 0 0\n0.2 0.5 0.3 0\n10");
	return 0;
}

static void test_torus_hits_along_a_diameter(void **state)
{
	const struct shape *s = fixture_shape(state);

	/* From x = 10 inwards: the outer wall x = 4 at t = 6. */
	assert_near(fixture_hit(s, support_ray(10, 0, 0, -1, 0, 0)), 6.0, 1e-12);
	/* From the centre (in the hole): the inner wall x = 2 at t = 2. */
	assert_near(fixture_hit(s, support_ray(0, 0, 0, 1, 0, 0)), 2.0, 1e-12);
	/* From inside the tube (x = 3) outwards: x = 4 at t = 1. */
	assert_near(fixture_hit(s, support_ray(3, 0, 0, 1, 0, 0)), 1.0, 1e-12);
	/* Down onto the top of the tube at (3, 0, 1). */
	assert_near(fixture_hit(s, support_ray(3, 0, 10, 0, 0, -1)), 9.0, 1e-12);
	/* Down through the hole, and beside the ring: misses. */
	assert_near(fixture_hit(s, support_ray(0, 0, 10, 0, 0, -1)), -1.0, 0.0);
	assert_near(fixture_hit(s, support_ray(4.5, 0, 10, 0, 0, -1)), -1.0, 0.0);
	/* Pointing away: a miss. */
	assert_near(fixture_hit(s, support_ray(10, 0, 0, 1, 0, 0)), -1.0, 0.0);
}

static void test_torus_non_unit_direction(void **state)
{
	const struct shape *s = fixture_shape(state);

	/* t is in units of the direction's length: 6 / 4. */
	assert_near(fixture_hit(s, support_ray(10, 0, 0, -4, 0, 0)), 1.5, 1e-12);
	assert_near(fixture_hit(s, support_ray(3, 0, 10, 0, 0, -0.5)), 18.0, 1e-11);
}

/* The ray z = 1 along x touches the tube's top circle at x = -3 and x = 3:
 * (x^2 + 9)^2 - 36 x^2 = (x^2 - 9)^2, a double root, which the isolation
 * finds exactly; a ray just above misses, one just below hits just
 * before the tangent point. */
static void test_torus_grazing_the_top(void **state)
{
	const struct shape *s = fixture_shape(state);
	double t;

	assert_near(fixture_hit(s, support_ray(-10, 0, 1, 1, 0, 0)), 7.0, 1e-12);
	assert_near(fixture_hit(s, support_ray(-10, 0, 1 + 1e-6, 1, 0, 0)), -1.0, 0.0);
	/* At z = 1 - e the tube is crossed where (x + 3)^2 = 1 - (1 - e)^2,
	 * x = -3 - sqrt(2e - e^2). */
	t = fixture_hit(s, support_ray(-10, 0, 1 - 1e-6, 1, 0, 0));
	assert_near(t, 7.0 - sqrt(2e-6 - 1e-12), 1e-9);
	/* At a slant, grazing the outer equator at (0, 4, 0) from (-10, 4, 0)
	 * would be tangent too: x^2 + 16 on the outer circle. */
	assert_near(fixture_hit(s, support_ray(-10, 4, 0, 1, 0, 0)), 10.0, 1e-6);
}

static void test_torus_t_max_shrinks(void **state)
{
	const struct shape *s = fixture_shape(state);
	struct ray r = support_ray(10, 0, 0, -1, 0, 0);
	double t = 5.0;

	assert_false(shape_intersect(s, &r, 1e-9, &t));
	assert_near(t, 5.0, 0.0);
	t = 7.0;
	assert_true(shape_intersect(s, &r, 1e-9, &t));
	assert_near(t, 6.0, 1e-12);
	/* t_min past the first wall: the next, x = 2 at t = 8. */
	t = INFINITY;
	assert_true(shape_intersect(s, &r, 6.5, &t));
	assert_near(t, 8.0, 1e-12);
}

static void test_torus_normals(void **state)
{
	const struct shape *s = fixture_shape(state);

	assert_vec3_near(shape_normal(s, vec3_make(4, 0, 0)), vec3_make(1, 0, 0), 1e-15);
	assert_vec3_near(shape_normal(s, vec3_make(2, 0, 0)), vec3_make(-1, 0, 0), 1e-15);
	assert_vec3_near(shape_normal(s, vec3_make(0, 3, 1)), vec3_make(0, 0, 1), 1e-15);
	assert_vec3_near(shape_normal(s, vec3_make(0, -3 - sqrt(0.5), sqrt(0.5))),
			 vec3_make(0, -sqrt(0.5), sqrt(0.5)), 1e-15);
}

static void test_torus_tilted_axis(void **state)
{
	const struct shape *s = fixture_shape(state);
	struct aabb box;

	/* Down the axis direction y onto the tube's top at (4, 3, 3). */
	assert_near(fixture_hit(s, support_ray(4, 12, 3, 0, -1, 0)), 9.0, 1e-12);
	assert_vec3_near(shape_normal(s, vec3_make(4, 3, 3)), vec3_make(0, 1, 0), 1e-15);
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-3, 1, -1), 1e-12);
	assert_vec3_near(box.max, vec3_make(5, 3, 7), 1e-12);
}

/* Distance from p to the tube's surface (negative inside) of the torus of
 * centre c, unit axis a, radii R and r: the distance to the core circle,
 * less r.  Independent of the quartic. */
static double tube_distance(struct vec3 p, struct vec3 c, struct vec3 a, double R, double r)
{
	struct vec3 q = vec3_sub(p, c);
	double h = vec3_dot(q, a);
	double rho = vec3_length(vec3_add_scaled(q, a, -h));

	return sqrt((rho - R) * (rho - R) + h * h) - r;
}

static double lcg(unsigned long long *x)
{
	*x = *x * 6364136223846793005ULL + 1442695040888963407ULL;
	return (double)(*x >> 11) / 9007199254740992.0;
}

/* Rays that graze the tube: from a random point of the surface along a
 * random tangent direction, moved off the surface along the normal by
 * 1e-7 to 1e-2 (in or out), then started 20 back.  A hit must be on the
 * surface (to 1e-9), and no point of the ray before it (sampled every
 * 0.005) may be clearly inside the tube; a miss must have no sampled
 * point clearly inside. */
static void test_torus_grazing_rays_agree_with_the_geometry(void **state)
{
	const struct shape *s = fixture_shape(state);
	const struct vec3 c = vec3_make(0.5, -1, 2), a = vec3_make(1.0 / 3, 2.0 / 3, 2.0 / 3);
	unsigned long long seed = 2026;
	int i, hits = 0;

	for (i = 0; i < 600; i++) {
		double u = 6.283185307179586 * lcg(&seed), v = 6.283185307179586 * lcg(&seed);
		double off = pow(10.0, -7.0 + 5.0 * lcg(&seed)) * (lcg(&seed) < 0.5 ? -1.0 : 1.0);
		struct vec3 e1 = vec3_normalize(vec3_cross(a, vec3_make(1, 0, 0))), e2 = vec3_cross(a, e1);
		struct vec3 radial = vec3_add(vec3_scale(e1, cos(u)), vec3_scale(e2, sin(u)));
		struct vec3 n = vec3_add(vec3_scale(radial, cos(v)), vec3_scale(a, sin(v)));
		struct vec3 p = vec3_add(vec3_add_scaled(c, radial, 3.0), vec3_scale(n, 1.0 + off));
		struct vec3 t1 = vec3_normalize(vec3_cross(n, a)), t2 = vec3_cross(n, t1), d;
		double w = 6.283185307179586 * lcg(&seed), t, k;
		struct ray r;

		if (!vec3_is_finite(t1) || vec3_dot(t1, t1) == 0.0)
			continue;
		d = vec3_add(vec3_scale(t1, cos(w)), vec3_scale(t2, sin(w)));
		r = support_ray(p.x - 20 * d.x, p.y - 20 * d.y, p.z - 20 * d.z, d.x, d.y, d.z);
		t = fixture_hit(s, r);
		if (t >= 0.0) {
			hits++;
			assert_near(tube_distance(ray_at(&r, t), c, a, 3.0, 1.0), 0.0, 1e-9);
		}
		for (k = 0.0; k < (t >= 0.0 ? t : 40.0); k += 0.005)
			if (tube_distance(ray_at(&r, k), c, a, 3.0, 1.0) < -1e-9) {
				print_error("ray %d (offset %g): inside at t = %.17g before its hit %.17g\n", i,
					    off, k, t);
				fail();
			}
	}
	/* The rays moved inwards hit by their start, some moved outwards
	 * the tube farther on (385 of 600 hit). */
	assert_true(hits > 100 && hits < 600);
}

static int setup_tilted_random(void **state)
{
	*state = fixture_scene("torus\n0.5 -1 2\n1 2 2\n3 1\n1 0 0\n0.2 0.5 0.3 0\n10");
	return 0;
}

static void test_torus_parse_errors(void **state)
{
	(void)state;
	assert_scene_error("1\n64\n\n1\ntorus\n0 0 0\n0 0 0\n3 1\n1 0 0\n0 0 0 0\n1\n0\n", -RT_E_RANGE,
			   7, 0, "torus axis must be a non-zero, finite vector");
	assert_scene_error_part("1\n64\n\n1\ntorus\n0 0 0\n0 0 1\n3 4\n1 0 0\n0 0 0 0\n1\n0\n",
				-RT_E_RANGE, 8, 3,
				"minor radius must be > 0 and below the major radius 3");
	assert_scene_error_part("1\n64\n\n1\ntorus\n0 0 0\n0 0 1\nbig 1\n", -RT_E_SYNTAX, 8, 1,
				"torus major radius");
}

/* An axis is any non-zero vector, however small or large its components:
 * (5e-324, 0, 0) is the x axis, (1e300, 1e300, 0) the diagonal, and the
 * torus the same as with (1, 0, 0) and (1, 1, 0). */
static void test_torus_tiny_and_huge_axes(void **state)
{
	static const char *const pairs[][2] = {
		{ "torus\n0 0 0\n5e-324 0 0\n3 1\n1 0 0\n0.2 0.5 0.3 0\n10",
		  "torus\n0 0 0\n1 0 0\n3 1\n1 0 0\n0.2 0.5 0.3 0\n10" },
		{ "torus\n0 0 0\n1e300 1e300 0\n3 1\n1 0 0\n0.2 0.5 0.3 0\n10",
		  "torus\n0 0 0\n1 1 0\n3 1\n1 0 0\n0.2 0.5 0.3 0\n10" },
	};
	size_t i;

	(void)state;
	for (i = 0; i < 2; i++) {
		struct scene *odd = fixture_scene(pairs[i][0]), *plain = fixture_scene(pairs[i][1]);
		struct ray r = support_ray(0.3, 0.2, 10, 0, 0, -1);
		double t;

		assert_non_null(odd);
		assert_non_null(plain);
		t = fixture_hit(scene_shape(plain, 0), r);
		assert_true(t > 0.0);
		assert_near(fixture_hit(scene_shape(odd, 0), r), t, 1e-12);
		scene_destroy(odd);
		scene_destroy(plain);
	}
}

/* A minor radius whose square underflows is refused where it is read. */
static void test_torus_tiny_minor_radius(void **state)
{
	(void)state;
	assert_scene_error("1\n64\n\n1\ntorus\n0 0 0\n0 0 1\n3 1e-200\n1 0 0\n0 0 0 0\n1\n0\n",
			   -RT_E_RANGE, 8, 3,
			   "torus minor radius must be > 0, with a square that is not 0 (above about 1e-154), found 1e-200");
	assert_scene_error("1\n64\n\n1\ntorus\n0 0 0\n0 0 1\n3 -1\n1 0 0\n0 0 0 0\n1\n0\n", -RT_E_RANGE,
			   8, 0, NULL);
}

static void test_torus_export_pov(void **state)
{
	char *text = support_export_pov(fixture_shape(state), RT_POV_FINISH_PLAIN);

	/* POV-Ray's torus round y, turned so that y is the axis z. */
	assert_non_null(strstr(text, "torus { 3, 1 sturm"));
	/* x to u = (1,0,0) x w = (0,-1,0), y to w, z to -(w x u) = (-1,0,0). */
	assert_non_null(strstr(text, "matrix <0, -1, 0, 0, 0, 1, -1, 0, 0, 0, 0, 0>"));
	free(text);
}

FIXTURE_MAIN("torus",
	     SUPPORT_FIXTURE_TESTS(setup_z, fixture_destroy, test_torus_hits_along_a_diameter,
				   test_torus_non_unit_direction, test_torus_grazing_the_top,
				   test_torus_t_max_shrinks, test_torus_normals),
	     SUPPORT_FIXTURE_TESTS(setup_tilted, fixture_destroy, test_torus_tilted_axis),
	     SUPPORT_FIXTURE_TESTS(setup_tilted_random, fixture_destroy,
				   test_torus_grazing_rays_agree_with_the_geometry),
	     SUPPORT_TESTS(test_torus_parse_errors, test_torus_tiny_and_huge_axes,
			   test_torus_tiny_minor_radius),
	     SUPPORT_FIXTURE_TESTS(setup_z, fixture_destroy, test_torus_export_pov))
