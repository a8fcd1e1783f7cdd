/* The implicit checkerboard floor: the plane z = 0 over [-W/2, W/2)^2,
 * tile parity, normal, bounds and POV export; the material of
 * floor_create_view; and nearfar's infinite checkerboard, its own cells'
 * parity across negative coordinates and far out (past 2^31 and 2^53),
 * no extent, no bounds, and its POV plane. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shapes/shapes.h"
#include "whitted/pov.h"
#include "support.h"

/* The assignment's Floor(1000, 20). */
static int setup_floor(void **state)
{
	return support_hold_shape(state, floor_create(1000.0, 20.0));
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

	assert_hit(*state, &down, 0.0, &t_max, 10.0, 0.0);
	assert_hit(*state, &up, 0.0, &t_max, 10.0, 0.0);
	/* Non-unit direction (|d| = sqrt(50)): z = 10 - 5t = 0 at t = 2. */
	assert_hit(*state, &slant, 0.0, &t_max, 2.0, 0.0);
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
	assert_coefficients(&s->mat, 0.4, 0.2, 0.2, 0.2, 1.0);
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-500, -500, 0), 0.0);
	assert_vec3_near(box.max, vec3_make(500, 500, 0), 0.0);
	assert_null(shape_degenerate(s));
	/* The floor is not a keyword of the file format. */
	assert_null(shape_ops_find("floor", 5));
}

static void test_floor_export_pov(void **state)
{
	struct pov_options opt = { RT_POV_FINISH_EXACT, false, { NULL, NULL } };
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

/* nearfar's coefficients KA KD 0 KR, shininess 1; the colour is not used. */
static const struct material nearfar_mat = { { 0.3, 0.6, 0.9 }, 0.1, 0.3, 0.0, 0.6, 1.0, 0.0, 1.0 };

static void test_floor_view_finite_keeps_rule(void **state)
{
	/* The pyramid dialect's floor: 1000 wide, tiles 30, the classic rule
	 * (cell floor((x + 500) / 30)) and the given coefficients. */
	struct shape *s = floor_create_view(1000.0, 30.0, &nearfar_mat);
	struct shape *classic = floor_create(1000.0, 30.0);
	struct ray r = support_ray(499, 0, 10, 0, 0, -1);
	struct ray off = support_ray(500, 0, 10, 0, 0, -1);
	struct aabb box;
	double t_max = INFINITY;
	int i;

	(void)state;
	assert_non_null(s);
	assert_non_null(classic);
	assert_ptr_equal(s->ops, classic->ops);
	assert_coefficients(&s->mat, 0.1, 0.3, 0.0, 0.6, 1.0);
	assert_near(s->mat.color.r, 1.0, 0.0);
	/* (0, 0): (500 / 30 -> 16) + 16, white; x = 10: 510 / 30 = 17 exactly:
	 * black; the parities agree with the classic floor of those tiles. */
	assert_true(white_at(s, 0, 0));
	assert_false(white_at(s, 10, 0));
	assert_false(white_at(s, -20.001, 0));	/* 479.999 / 30 -> 15, + 16 */
	assert_true(white_at(s, -20, 0));	/* 480 / 30 = 16 exactly, + 16 */
	for (i = -40; i <= 40; i++)
		assert_true(white_at(s, 13.7 * i, -7.1 * i) == white_at(classic, 13.7 * i, -7.1 * i));
	assert_true(shape_intersect(s, &r, 0.0, &t_max));
	t_max = INFINITY;
	assert_false(shape_intersect(s, &off, 0.0, &t_max));
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.max, vec3_make(500, 500, 0), 0.0);
	shape_destroy(s);
	shape_destroy(classic);
}

static void test_floor_infinite_parity_negative(void **state)
{
	/* Cells of 50 from the origin: (floor(x / 50), floor(y / 50)), white
	 * when the sum is even. */
	struct shape *s = floor_create_view(INFINITY, 50.0, &nearfar_mat);

	(void)state;
	assert_non_null(s);
	assert_true(white_at(s, 0, 0));			/* 0 + 0 */
	assert_true(white_at(s, 49.999, 49.999));	/* 0 + 0 */
	assert_false(white_at(s, 50, 0));		/* 1 + 0 */
	assert_true(white_at(s, 50, 50));		/* 1 + 1 */
	/* Just below zero is cell -1, not 0 (no truncation towards zero). */
	assert_false(white_at(s, -0.001, 0));		/* -1 + 0 */
	assert_false(white_at(s, 0, -0.001));
	assert_true(white_at(s, -0.001, -0.001));	/* -1 + -1 */
	/* x = -50 is cell -1 exactly; just below, -2. */
	assert_false(white_at(s, -50, 0));
	assert_true(white_at(s, -50.001, 0));
	assert_true(white_at(s, -75, 125));		/* -2 + 2 */
	assert_false(white_at(s, -125, 0));		/* -3 */
	assert_true(white_at(s, -125, -125));		/* -3 + -3 */
	/* Far out: -2e7 + (2e7 + 1) is odd, -2e7 + 2e7 even. */
	assert_false(white_at(s, -1e9, 1e9 + 50));
	assert_true(white_at(s, -1e9, 1e9 + 49));
	shape_destroy(s);
}

/* The parity of cells whose index sum is near and past 2^31 (where the
 * low bit of the sum as an int no longer serves) and near 2^53 (where
 * every double is even), on cells of 1: white exactly when
 * fmod(|i + j|, 2) == 0, the rule's own form. */
static void test_floor_infinite_parity_far_out(void **state)
{
	static const double sums[] = { 2147483646.0, 2147483647.0, 2147483648.0, 2147483649.0,
				       4294967297.0, 9007199254740991.0, 9007199254740992.0,
				       1e300 };
	struct shape *s = floor_create_view(INFINITY, 1.0, &nearfar_mat);
	size_t k;
	int d, sign;

	(void)state;
	assert_non_null(s);
	for (k = 0; k < sizeof(sums) / sizeof(sums[0]); k++) {
		for (sign = -1; sign <= 1; sign += 2) {
			for (d = -2; d <= 2; d++) {
				/* Cell (i, 3): x = i + 0.25 lies in cell i while i has
				 * room for the quarter, else it is i itself. */
				double i = sign * sums[k] + d - 3.0;
				double x = fabs(i) < 1e15 ? i + 0.25 : i;
				double ci = floor(x), sum = ci + 3.0;
				bool want = fmod(fabs(sum), 2.0) == 0.0;

				if (white_at(s, x, 3.5) != want) {
					print_error("cell %.17g + 3: want %s\n", ci, want ? "white" : "black");
					fail();
				}
			}
		}
	}
	assert_false(white_at(s, NAN, 0));
	assert_false(white_at(s, INFINITY, 0));
	shape_destroy(s);
}

static void test_floor_infinite_everywhere(void **state)
{
	struct shape *s = floor_create_view(INFINITY, 50.0, &nearfar_mat);
	struct ray far = support_ray(1e6, -3e7, 10, 0, 0, -1);
	struct ray slant = support_ray(0, 0, 10, 3e4, -4e4, -5);
	struct ray parallel = support_ray(0, 0, 10, 1, 0, 0);
	struct ray away = support_ray(0, 0, 10, 0, 0, 1);
	struct ray up = support_ray(-7e5, 2e5, -4, 0, 0, 2);
	struct aabb box;
	double t_max = INFINITY;

	(void)state;
	assert_non_null(s);
	/* Far beyond any finite floor's square, from above and below; a
	 * non-unit direction. */
	assert_hit(s, &far, 0.0, &t_max, 10.0, 0.0);
	assert_hit(s, &slant, 0.0, &t_max, 2.0, 0.0);
	assert_hit(s, &up, 0.0, &t_max, 2.0, 0.0);
	/* The open interval shrinks and is kept. */
	t_max = 2.0;
	assert_false(shape_intersect(s, &up, 0.0, &t_max));
	assert_false(shape_intersect(s, &up, 2.0, &t_max));
	assert_near(t_max, 2.0, 0.0);
	t_max = 42.0;
	assert_false(shape_intersect(s, &parallel, 0.0, &t_max));
	assert_false(shape_intersect(s, &away, 0.0, &t_max));
	assert_near(t_max, 42.0, 0.0);
	assert_vec3_near(shape_normal(s, vec3_make(-1e5, 3, 0)), vec3_make(0, 0, 1), 0.0);
	/* Unbounded in x and y; flat at z = 0. */
	assert_false(shape_bounds(s, &box));
	assert_true(box.min.x == -INFINITY && box.max.x == INFINITY);
	assert_true(box.min.y == -INFINITY && box.max.y == INFINITY);
	assert_true(box.min.z == 0.0 && box.max.z == 0.0);
	assert_true(shape_is_textured(s));
	assert_null(shape_degenerate(s));
	/* The material: the given coefficients, a white tile colour. */
	assert_coefficients(&s->mat, 0.1, 0.3, 0.0, 0.6, 1.0);
	assert_near(s->mat.color.g, 1.0, 0.0);
	shape_destroy(s);
}

static void test_floor_infinite_export_pov(void **state)
{
	struct shape *s = floor_create_view(INFINITY, 50.0, &nearfar_mat);
	char *text = support_export_pov(s, RT_POV_FINISH_EXACT), *at;
	double scale, tx, ty, tz;
	const char *head = "plane { z, 0\n  texture { checker\n";

	(void)state;
	assert_true(strncmp(text, head, strlen(head)) == 0);
	/* White first, then black, each with the floor's finish (plain:
	 * the exact mode does not apply to a varying colour). */
	at = strstr(text, "checker");
	assert_non_null(strstr(at, "pigment { rgb <1,1,1> } finish { ambient 0.1 diffuse 0.3 phong 0 "
				   "phong_size 1 reflection { 0.6 } } }"));
	assert_non_null(strstr(at, "pigment { rgb <0,0,0> } finish { ambient 0.1 diffuse 0.3 phong 0 "
				   "phong_size 1 reflection { 0.6 } } }"));
	assert_true(strstr(at, "rgb <1,1,1>") < strstr(at, "rgb <0,0,0>"));
	/* Cell (0, 0) from the origin: no x or y translation. */
	at = strstr(text, "scale ");
	assert_non_null(at);
	assert_int_equal(sscanf(at, "scale %lf translate <%lf,%lf,%lf>", &scale, &tx, &ty, &tz), 4);
	assert_near(scale, 50, 0.0);
	assert_near(tx, 0, 0.0);
	assert_near(ty, 0, 0.0);
	assert_near(tz, -25, 0.0);
	assert_string_equal(text + strlen(text) - 6, "  }\n}\n");
	free(text);
	shape_destroy(s);
}

SUPPORT_MAIN(SUPPORT_FIXTURE_TESTS(setup_floor, support_drop_shape,
				   test_floor_hit_from_above_and_below,
				   test_floor_miss_parallel_behind, test_floor_t_interval,
				   test_floor_extent_half_open, test_floor_normal_is_up,
				   test_floor_tile_parity),
	     SUPPORT_TESTS(test_floor_parity_other_sizes),
	     SUPPORT_FIXTURE_TESTS(setup_floor, support_drop_shape, test_floor_material_and_bounds,
				   test_floor_export_pov),
	     SUPPORT_TESTS(test_floor_view_finite_keeps_rule,
			   test_floor_infinite_parity_negative,
			   test_floor_infinite_parity_far_out, test_floor_infinite_everywhere,
			   test_floor_infinite_export_pov))
