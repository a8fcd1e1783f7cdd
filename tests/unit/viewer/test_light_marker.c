/* The lights' markers and GL parameters: a spotlight's cone of lines opens
 * at its cutoff around its axis, a point light is a dot, and GL gets a
 * spotlight only for the cutoffs it has. */
#include <math.h>

#include "support.h"
#include "light_marker.h"

static const double pi = 3.14159265358979323846;

static struct light spot(struct vec3 pos, struct vec3 axis, double cutoff)
{
	struct light l = { pos, { 0.2, 1.0, 0.4 }, 0.0, true, axis, cutoff, 0.0 };

	l.axis = vec3_normalize(axis);
	l.cos_cutoff = cos(cutoff * pi / 180.0);
	return l;
}

static void test_light_marker_perpendicular_is_unit_and_normal(void **state)
{
	const struct vec3 axes[] = {
		{ 0, 0, 1 }, { 0, 0, -1 }, { 1, 0, 0 }, { 0, -1, 0 }, { 1, 1, 1 }, { 1e-9, 0, 1 },
		{ -0.3, 0.9, 0.1 },
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(axes) / sizeof(axes[0]); i++) {
		struct vec3 a = vec3_normalize(axes[i]);
		struct vec3 e = light_marker_perpendicular(a);
		assert_near(vec3_length(e), 1.0, 1e-15);
		assert_near(vec3_dot(a, e), 0.0, 1e-15);
	}
}

static void test_light_marker_point_light_is_a_dot(void **state)
{
	struct light l = { { 1, 2, 3 }, { 1, 1, 1 }, 0.0, false, { 0, 0, 0 }, 0.0, 0.0 };
	struct light_marker m;

	(void)state;
	light_marker_make(&l, 10.0, &m);
	assert_int_equal(m.n_rim, 0);
	assert_vec3_near(m.apex, l.pos, 0.0);
	assert_vec3_near(m.tip, l.pos, 0.0);
}

/* Every rim point is `length` from the apex at the cutoff's angle from
 * the axis, and the rim goes evenly around it. */
static void check_cone(const struct light *l, double length)
{
	struct light_marker m;
	struct vec3 a = vec3_normalize(l->axis), centre = vec3_make(0, 0, 0);
	double chord = -1.0;
	int k;

	light_marker_make(l, length, &m);
	assert_int_equal(m.n_rim, RT_LIGHT_MARKER_RIM);
	assert_vec3_near(m.apex, l->pos, 0.0);
	assert_vec3_near(m.tip, vec3_add_scaled(l->pos, a, length), 1e-12);
	for (k = 0; k < m.n_rim; k++) {
		struct vec3 r = vec3_sub(m.rim[k], l->pos);
		struct vec3 next = m.rim[(k + 1) % m.n_rim];
		double c = vec3_length(vec3_sub(next, m.rim[k]));

		assert_near(vec3_length(r), length, 1e-12 * length);
		assert_near(vec3_dot(vec3_normalize(r), a), cos(l->cutoff_deg * pi / 180.0), 1e-12);
		if (chord < 0)
			chord = c;
		assert_near(c, chord, 1e-9 * length);
		centre = vec3_add_scaled(centre, r, 1.0 / m.n_rim);
	}
	/* The rim's centre lies on the axis, at length cos(cutoff). */
	assert_vec3_near(centre, vec3_scale(a, length * cos(l->cutoff_deg * pi / 180.0)),
			 1e-12 * length);
}

static void test_light_marker_cone_opens_at_cutoff(void **state)
{
	struct light l;

	(void)state;
	/* an-akhand.txt's spotlight: at (-70, 70, 70), aimed at (-10, 10, 10). */
	l = spot(vec3_make(-70, 70, 70), vec3_make(60, -60, -60), 30.0);
	check_cone(&l, 26.0);
	/* munzer2.txt's: under the floor, up the z axis, 12 degrees. */
	l = spot(vec3_make(100, 100, -200), vec3_make(0, 0, 1), 12.0);
	check_cone(&l, 55.0);
	/* Wider than a half space, and the whole sphere. */
	l = spot(vec3_make(20, 40, 110), vec3_make(0, 0.3, 1), 125.0);
	check_cone(&l, 3.0);
	l = spot(vec3_make(0, 0, 0), vec3_make(1, 0, 0), 180.0);
	check_cone(&l, 1.0);
}

static void test_light_marker_gl_cutoff(void **state)
{
	struct light point = { { 0, 0, 0 }, { 1, 1, 1 }, 0.0, false, { 0, 0, 0 }, 0.0, 0.0 };
	struct light l;

	(void)state;
	assert_near(light_marker_gl_cutoff(&point), 180.0, 0.0);
	l = spot(vec3_make(0, 0, 0), vec3_make(0, 0, 1), 30.0);
	assert_near(light_marker_gl_cutoff(&l), 30.0, 0.0);
	l = spot(vec3_make(0, 0, 0), vec3_make(0, 0, 1), 90.0);
	assert_near(light_marker_gl_cutoff(&l), 90.0, 0.0);
	/* GL has no cone wider than 90 degrees: a point light instead. */
	l = spot(vec3_make(0, 0, 0), vec3_make(0, 0, 1), 90.5);
	assert_near(light_marker_gl_cutoff(&l), 180.0, 0.0);
	l = spot(vec3_make(0, 0, 0), vec3_make(0, 0, 1), 180.0);
	assert_near(light_marker_gl_cutoff(&l), 180.0, 0.0);
}

/* 1 / (1 + q d^2) against exp(-falloff d^2): equal where the falloff is
 * small, as in the course files (d = 100, falloff 2e-6). */
static void test_light_marker_gl_quadratic(void **state)
{
	struct light l = spot(vec3_make(0, 0, 0), vec3_make(0, 0, 1), 30.0);
	double q, d2 = 100.0 * 100.0;

	(void)state;
	assert_near(light_marker_gl_quadratic(&l), 0.0, 0.0);
	l.falloff = 0.000002;
	q = light_marker_gl_quadratic(&l);
	assert_near(1.0 / (1.0 + q * d2), exp(-l.falloff * d2), 1e-3);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_light_marker_perpendicular_is_unit_and_normal,
			   test_light_marker_point_light_is_a_dot,
			   test_light_marker_cone_opens_at_cutoff, test_light_marker_gl_cutoff,
			   test_light_marker_gl_quadratic))
