/* The pinhole camera: the centre pixel, orientation, field of view, the
 * errors of camera_init, and an image of one pixel. */
#include <math.h>
#include <string.h>

#include "camera.h"
#include "support.h"

static const double pi = 3.14159265358979323846;

static void init_default(struct camera *c, int size)
{
	struct camera_params p;
	struct diag d;

	camera_params_default(&p);
	diag_clear(&d);
	assert_int_equal(camera_init(c, &p, size, &d), 0);
}

static double angle_between(struct vec3 a, struct vec3 b)
{
	return acos(fmin(1.0, vec3_dot(a, b) / (vec3_length(a) * vec3_length(b))));
}

static void test_camera_defaults(void **state)
{
	struct camera_params p;

	(void)state;
	camera_params_default(&p);
	assert_vec3_near(p.eye, vec3_make(0, -200, 10), 0.0);
	assert_vec3_near(p.look, vec3_make(0, 0, 0), 0.0);
	assert_vec3_near(p.up, vec3_make(0, 0, 1), 0.0);
	assert_near(p.fov_deg, 80.0, 0.0);
}

static void test_camera_centre_pixel_looks_at_look_point(void **state)
{
	struct camera c;
	struct ray r;
	/* look - eye = (0, 200, -10), length sqrt(40100). */
	double len = sqrt(40100.0);

	(void)state;
	init_default(&c, 101);
	r = camera_ray(&c, 50, 50);
	assert_vec3_near(r.origin, vec3_make(0, -200, 10), 0.0);
	assert_vec3_near(r.dir, vec3_make(0, 200 / len, -10 / len), 1e-15);
	/* The ray passes through the look-at point at t = len. */
	assert_vec3_near(ray_at(&r, len), vec3_make(0, 0, 0), 1e-12);
	assert_near(vec3_length(r.dir), 1.0, 1e-15);
}

static void test_camera_basis(void **state)
{
	struct camera c;
	double len = sqrt(40100.0);

	(void)state;
	init_default(&c, 64);
	/* forward = (0, 200, -10) / len; right = forward x up = (1, 0, 0);
	 * up' = right x forward = (0, 10, 200) / len. */
	assert_vec3_near(c.forward, vec3_make(0, 200 / len, -10 / len), 1e-15);
	assert_vec3_near(c.right, vec3_make(1, 0, 0), 1e-15);
	assert_vec3_near(c.up, vec3_make(0, 10 / len, 200 / len), 1e-15);
	assert_near(c.half_height, tan(40.0 * pi / 180.0), 1e-15);
	assert_int_equal(c.size, 64);
}

static void test_camera_up_is_up_right_is_right(void **state)
{
	struct camera c;
	struct ray centre, above, below, right, left;

	(void)state;
	init_default(&c, 101);
	centre = camera_ray(&c, 50, 50);
	above = camera_ray(&c, 50, 49);
	below = camera_ray(&c, 50, 51);
	right = camera_ray(&c, 51, 50);
	left = camera_ray(&c, 49, 50);
	/* Row 0 is the top: the pixel above looks further up (world z and
	 * the camera's up), the one to the right towards +x. */
	assert_true(vec3_dot(above.dir, c.up) > vec3_dot(centre.dir, c.up));
	assert_true(above.dir.z > centre.dir.z);
	assert_true(below.dir.z < centre.dir.z);
	assert_true(right.dir.x > 0.0);
	assert_true(left.dir.x < 0.0);
	/* The columns through the centre have no sideways component, and
	 * the centre row no vertical one (relative to the camera). */
	assert_near(above.dir.x, 0.0, 1e-15);
	assert_near(vec3_dot(right.dir, c.up), 0.0, 1e-15);
}

static void test_camera_field_of_view(void **state)
{
	struct camera_params p;
	struct camera c;
	struct diag d;
	struct ray r;

	(void)state;
	/* 90 degrees on 2 x 2: half_height 1, pixel (0, 0) at u = -0.5,
	 * v = +0.5, so it is atan(sqrt(0.5)) off the view axis. */
	camera_params_default(&p);
	p.fov_deg = 90.0;
	assert_int_equal(camera_init(&c, &p, 2, &d), 0);
	r = camera_ray(&c, 0, 0);
	assert_near(angle_between(r.dir, c.forward), atan(sqrt(0.5)), 1e-12);
	assert_true(vec3_dot(r.dir, c.right) < 0.0);
	assert_true(vec3_dot(r.dir, c.up) > 0.0);
	/* The default 80 degrees on 101 pixels: the top-edge pixel of the
	 * centre column is at v = tan(40) (1 - 1/101) above the axis. */
	init_default(&c, 101);
	r = camera_ray(&c, 50, 0);
	assert_near(angle_between(r.dir, c.forward), atan(tan(40.0 * pi / 180.0) * 100.0 / 101.0),
		    1e-12);
	/* And the bottom edge mirrors it. */
	assert_near(angle_between(camera_ray(&c, 50, 100).dir, c.forward),
		    atan(tan(40.0 * pi / 180.0) * 100.0 / 101.0), 1e-12);
}

static void test_camera_size_one(void **state)
{
	struct camera c;
	struct ray r;
	double len = sqrt(40100.0);

	(void)state;
	init_default(&c, 1);
	r = camera_ray(&c, 0, 0);
	assert_vec3_near(r.dir, vec3_make(0, 200 / len, -10 / len), 1e-15);
}

static void test_camera_custom_view(void **state)
{
	struct camera_params p;
	struct camera c;
	struct diag d;
	struct ray r;

	(void)state;
	/* Looking down -z with +y up: right is +x. */
	p.eye = vec3_make(1, 2, 3);
	p.look = vec3_make(1, 2, -7);
	p.up = vec3_make(0, 5, 0);	/* need not be unit */
	p.fov_deg = 60;
	assert_int_equal(camera_init(&c, &p, 3, &d), 0);
	assert_vec3_near(c.forward, vec3_make(0, 0, -1), 0.0);
	assert_vec3_near(c.right, vec3_make(1, 0, 0), 0.0);
	assert_vec3_near(c.up, vec3_make(0, 1, 0), 0.0);
	/* An up that is not perpendicular to the view is made so. */
	p.up = vec3_make(0, 1, 1);
	assert_int_equal(camera_init(&c, &p, 3, &d), 0);
	assert_vec3_near(c.up, vec3_make(0, 1, 0), 1e-15);
	/* Pixel (2, 1) of 3: u = 2.5 * (2 tan 30 / 3) - tan 30 = 2/3 tan 30. */
	r = camera_ray(&c, 2, 1);
	assert_near(r.dir.x / -r.dir.z, 2.0 / 3.0 * tan(pi / 6.0), 1e-15);
	assert_near(r.dir.y, 0.0, 1e-15);
}

static void expect_invalid(const struct camera_params *p, int size, const char *words)
{
	struct camera c;
	struct diag d;

	diag_clear(&d);
	assert_int_equal(camera_init(&c, p, size, &d), -RT_E_INVALID);
	if (!strstr(d.msg, words)) {
		print_error("message '%s' does not mention '%s'\n", d.msg, words);
		fail();
	}
}

static void test_camera_errors(void **state)
{
	static const double bad_fov[] = { 0.0, -5.0, 180.0, 200.0 };
	struct camera_params p;
	struct camera c;
	struct diag d;
	size_t i;

	(void)state;
	camera_params_default(&p);
	p.look = p.eye;
	expect_invalid(&p, 10, "look-at");
	camera_params_default(&p);
	p.up = vec3_make(0, 0, 0);
	expect_invalid(&p, 10, "zero");
	/* Parallel and anti-parallel to the view (0, 200, -10). */
	p.up = vec3_make(0, 20, -1);
	expect_invalid(&p, 10, "parallel");
	p.up = vec3_make(0, -20, 1);
	expect_invalid(&p, 10, "parallel");
	camera_params_default(&p);
	for (i = 0; i < sizeof(bad_fov) / sizeof(bad_fov[0]); i++) {
		p.fov_deg = bad_fov[i];
		expect_invalid(&p, 10, "field of view");
	}
	p.fov_deg = NAN;
	expect_invalid(&p, 10, "");
	p.fov_deg = 80;
	expect_invalid(&p, 0, "size");
	p.eye.x = INFINITY;
	expect_invalid(&p, 10, "finite");
	/* The extremes inside the range are fine. */
	camera_params_default(&p);
	p.fov_deg = 0.01;
	assert_int_equal(camera_init(&c, &p, 10, &d), 0);
	p.fov_deg = 179.9;
	assert_int_equal(camera_init(&c, &p, 10, &d), 0);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_camera_defaults),
		cmocka_unit_test(test_camera_centre_pixel_looks_at_look_point),
		cmocka_unit_test(test_camera_basis),
		cmocka_unit_test(test_camera_up_is_up_right_is_right),
		cmocka_unit_test(test_camera_field_of_view),
		cmocka_unit_test(test_camera_size_one),
		cmocka_unit_test(test_camera_custom_view),
		cmocka_unit_test(test_camera_errors),
	};
	return SUPPORT_RUN(tests, argc, argv);
}
