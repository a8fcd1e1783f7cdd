/* The implicit checkerboard floor: the plane z = 0 over [-W/2, W/2)^2,
 * tile parity, normal, bounds and POV export. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "pov.h"
#include "support.h"

/* The assignment's Floor(1000, 20). */
static int setup_floor(void **state)
{
	*state = floor_create(1000.0, 20.0);
	return *state ? 0 : -1;
}

static int teardown_floor(void **state)
{
	shape_destroy(*state);
	return 0;
}

static bool white_at(const struct shape *s, double x, double y)
{
	struct color c = shape_color_at(s, vec3_make(x, y, 0));

	/* Only pure white or pure black. */
	assert_true((c.r == 1.0 && c.g == 1.0 && c.b == 1.0) ||
		    (c.r == 0.0 && c.g == 0.0 && c.b == 0.0));
	return c.r == 1.0;
}

static void test_floor_hit_from_above_and_below(void **state)
{
	struct ray down = support_ray(3, 4, 10, 0, 0, -1);
	struct ray up = support_ray(3, 4, -10, 0, 0, 1);
	struct ray slant = support_ray(0, 0, 10, 3, 4, -5);
	double t_max = INFINITY;

	assert_true(shape_intersect(*state, &down, 0.0, &t_max));
	assert_near(t_max, 10.0, 0.0);
	t_max = INFINITY;
	assert_true(shape_intersect(*state, &up, 0.0, &t_max));
	assert_near(t_max, 10.0, 0.0);
	/* Non-unit direction (|d| = sqrt(50)): z = 10 - 5t = 0 at t = 2. */
	t_max = INFINITY;
	assert_true(shape_intersect(*state, &slant, 0.0, &t_max));
	assert_near(t_max, 2.0, 0.0);
}

static void test_floor_miss_parallel_behind(void **state)
{
	struct ray parallel = support_ray(0, 0, 10, 1, 0, 0);
	struct ray in_plane = support_ray(0, 0, 0, 1, 0, 0);
	struct ray away = support_ray(0, 0, 10, 0, 0, 1);
	double t_max = 42.0;

	assert_false(shape_intersect(*state, &parallel, 0.0, &t_max));
	assert_false(shape_intersect(*state, &in_plane, 0.0, &t_max));
	assert_false(shape_intersect(*state, &away, 0.0, &t_max));
	assert_near(t_max, 42.0, 0.0);
}

static void test_floor_t_interval(void **state)
{
	struct ray down = support_ray(3, 4, 10, 0, 0, -1);
	double t_max = 10.0;

	/* Open interval: a hit at exactly t_max or t_min does not count. */
	assert_false(shape_intersect(*state, &down, 0.0, &t_max));
	assert_near(t_max, 10.0, 0.0);
	t_max = INFINITY;
	assert_false(shape_intersect(*state, &down, 10.0, &t_max));
	assert_true(isinf(t_max));
	t_max = 10.5;
	assert_true(shape_intersect(*state, &down, 9.5, &t_max));
	assert_near(t_max, 10.0, 0.0);
}

static void test_floor_extent_half_open(void **state)
{
	static const double in[][2] = {
		{ -500, 0 }, { 0, -500 }, { -500, -500 }, { 499.999, 499.999 }, { 0, 0 },
	};
	static const double out[][2] = {
		{ 500, 0 }, { 0, 500 }, { -500.001, 0 }, { 0, -500.001 }, { 600, 600 },
	};
	double t_max;
	size_t i;

	for (i = 0; i < sizeof(in) / sizeof(in[0]); i++) {
		struct ray r = support_ray(in[i][0], in[i][1], 10, 0, 0, -1);
		t_max = INFINITY;
		if (!shape_intersect(*state, &r, 0.0, &t_max)) {
			print_error("(%g, %g) is on the floor\n", in[i][0], in[i][1]);
			fail();
		}
	}
	for (i = 0; i < sizeof(out) / sizeof(out[0]); i++) {
		struct ray r = support_ray(out[i][0], out[i][1], 10, 0, 0, -1);
		t_max = INFINITY;
		if (shape_intersect(*state, &r, 0.0, &t_max)) {
			print_error("(%g, %g) is off the floor\n", out[i][0], out[i][1]);
			fail();
		}
	}
}

static void test_floor_normal_is_up(void **state)
{
	assert_vec3_near(shape_normal(*state, vec3_make(0, 0, 0)), vec3_make(0, 0, 1), 0.0);
	assert_vec3_near(shape_normal(*state, vec3_make(-123, 456, 0)), vec3_make(0, 0, 1), 0.0);
}

static void test_floor_tile_parity(void **state)
{
	/* i = floor((x + 500) / 20), j = floor((y + 500) / 20), white when
	 * i + j is even.  (0, 0): i = j = 25, 50 is even: white. */
	assert_true(white_at(*state, 0, 0));
	assert_true(white_at(*state, 19.999, 19.999));	/* 25 + 25 */
	/* x = 20: 520 / 20 = 26 exactly, the next tile: 51, black. */
	assert_false(white_at(*state, 20, 0));
	assert_false(white_at(*state, 0, 20));
	assert_true(white_at(*state, 20, 20));		/* 26 + 26 */
	/* Negative coordinates: x = -0.001 gives 499.999 / 20 -> 24: black. */
	assert_false(white_at(*state, -0.001, 0));
	assert_false(white_at(*state, 0, -0.001));
	assert_true(white_at(*state, -0.001, -0.001));	/* 24 + 24 */
	/* x = -20: 480 / 20 = 24 exactly: 24 + 25, black; just below, 23. */
	assert_false(white_at(*state, -20, 0));
	assert_true(white_at(*state, -20.001, 0));
	/* The corner tile (0, 0) at (-500, -500): white; (-481, -500) is
	 * still tile 0; (-480, -500) is tile 1: black. */
	assert_true(white_at(*state, -500, -500));
	assert_true(white_at(*state, -481, -500));
	assert_false(white_at(*state, -480, -500));
	/* The last tile (49, 49) at (499, 499): 98, white; (49, 0) at
	 * (499, -500): black. */
	assert_true(white_at(*state, 499, 499));
	assert_false(white_at(*state, 499, -500));
	/* Where x + W/2 < 0 (outside the extent) the formula still holds:
	 * (-510, 0): i = floor(-10 / 20) = -1, j = 25, 24: white;
	 * (-530, 0): i = -2, 23: black. */
	assert_true(white_at(*state, -510, 0));
	assert_false(white_at(*state, -530, 0));
}

static void test_floor_parity_other_sizes(void **state)
{
	/* Floor(30, 20): half = 15, i = floor((x + 15) / 20): x in [-15, 5)
	 * is tile 0, [5, 15) tile 1. */
	struct shape *s = floor_create(30.0, 20.0);
	/* Floor(100, 10): half = 50, the tile boundary at x = 0 ((0 + 50) / 10
	 * = 5 exactly): x = 0 is tile 5, x = -1e-9 tile 4. */
	struct shape *t = floor_create(100.0, 10.0);

	(void)state;
	assert_true(white_at(s, -15, -15));
	assert_true(white_at(s, 4.999, 4.999));
	assert_false(white_at(s, 5, 0));
	assert_false(white_at(s, -15, 5));
	assert_true(white_at(s, 5, 5));
	/* (5 + 5) even for x = y = 0, (4 + 5) odd just left of 0. */
	assert_true(white_at(t, 0, 0));
	assert_false(white_at(t, -1e-9, 0));
	assert_true(white_at(t, -1e-9, -1e-9));
	shape_destroy(s);
	shape_destroy(t);
}

static void test_floor_material_and_bounds(void **state)
{
	const struct shape *s = *state;
	struct aabb box;

	/* Coefficients 0.4 0.2 0.2 0.2, shininess 1. */
	assert_near(s->mat.ka, 0.4, 0.0);
	assert_near(s->mat.kd, 0.2, 0.0);
	assert_near(s->mat.ks, 0.2, 0.0);
	assert_near(s->mat.kr, 0.2, 0.0);
	assert_near(s->mat.shininess, 1.0, 0.0);
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-500, -500, 0), 0.0);
	assert_vec3_near(box.max, vec3_make(500, 500, 0), 0.0);
	assert_null(shape_degenerate(s));
	/* The floor is not a keyword of the file format. */
	assert_null(shape_ops_find("floor", 5));
}

static void test_floor_export_pov(void **state)
{
	struct pov_options opt = { RT_POV_FINISH_EXACT };
	FILE *f = tmpfile();
	double p[15], scale, tx, ty, tz;
	char text[4096], *at;
	size_t n;
	int i;

	assert_non_null(f);
	assert_int_equal(shape_export_pov(*state, f, &opt), 0);
	rewind(f);
	n = fread(text, 1, sizeof(text) - 1, f);
	text[n] = '\0';
	fclose(f);
	assert_int_equal(sscanf(text, "polygon { 5, <%lf,%lf,%lf>, <%lf,%lf,%lf>, <%lf,%lf,%lf>, "
				"<%lf,%lf,%lf>, <%lf,%lf,%lf>",
				&p[0], &p[1], &p[2], &p[3], &p[4], &p[5], &p[6], &p[7], &p[8],
				&p[9], &p[10], &p[11], &p[12], &p[13], &p[14]), 15);
	{
		/* The closed square (-500,-500) (500,-500) (500,500) (-500,500)
		 * (-500,-500) in z = 0. */
		static const double want[15] = {
			-500, -500, 0, 500, -500, 0, 500, 500, 0, -500, 500, 0, -500, -500, 0
		};
		for (i = 0; i < 15; i++)
			assert_near(p[i], want[i], 0.0);
	}
	at = strstr(text, "checker");
	assert_non_null(at);
	/* The white tile first, then the black, both plain textures (the
	 * floor ignores the exact mode). */
	assert_non_null(strstr(at, "pigment { rgb <1,1,1> }"));
	assert_non_null(strstr(at, "pigment { rgb <0,0,0> }"));
	assert_true(strstr(at, "rgb <1,1,1>") < strstr(at, "rgb <0,0,0>"));
	at = strstr(text, "scale ");
	assert_non_null(at);
	assert_int_equal(sscanf(at, "scale %lf translate <%lf,%lf,%lf>", &scale, &tx, &ty, &tz), 4);
	assert_near(scale, 20, 0.0);
	assert_near(tx, -500, 0.0);
	assert_near(ty, -500, 0.0);
	assert_near(tz, -10, 0.0);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test_setup_teardown(test_floor_hit_from_above_and_below, setup_floor, teardown_floor),
		cmocka_unit_test_setup_teardown(test_floor_miss_parallel_behind, setup_floor, teardown_floor),
		cmocka_unit_test_setup_teardown(test_floor_t_interval, setup_floor, teardown_floor),
		cmocka_unit_test_setup_teardown(test_floor_extent_half_open, setup_floor, teardown_floor),
		cmocka_unit_test_setup_teardown(test_floor_normal_is_up, setup_floor, teardown_floor),
		cmocka_unit_test_setup_teardown(test_floor_tile_parity, setup_floor, teardown_floor),
		cmocka_unit_test(test_floor_parity_other_sizes),
		cmocka_unit_test_setup_teardown(test_floor_material_and_bounds, setup_floor, teardown_floor),
		cmocka_unit_test_setup_teardown(test_floor_export_pov, setup_floor, teardown_floor),
	};
	return SUPPORT_RUN(tests, argc, argv);
}
