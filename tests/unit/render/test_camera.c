/* The pinhole camera: the centre pixel, orientation, field of view, the
 * errors of camera_init, and an image of one pixel. */
#include <math.h>
#include <string.h>

#include "base/simd.h"
#include "render/render_kernels.h"
#include "render/camera_lanes.h"
#include "render/camera_span.h"
#include "whitted/camera.h"
#include "support.h"

static const double pi = 3.14159265358979323846;

static void init_default(struct camera *c, int size)
{
	struct camera_params p = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0, 0, 0 };
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
	struct camera_params p = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0, 0, 0 };

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
	struct camera_params p = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0, 0, 0 };
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
	struct camera_params p = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0, 0, 0 };
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
	struct camera_params p = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0, 0, 0 };
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

/* The nearfar camera along +y from the origin (forward (0, 1, 0), right
 * (1, 0, 0), up (0, 0, 1)) with the given near plane, aspect and fov. */
static void init_nearfar(struct camera *c, double near, double aspect, double fov, int size)
{
	struct camera_params p = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0, 0, 0 };
	struct diag d;

	support_lens_params(&p, fov, near, aspect);
	p.eye = vec3_make(0, 0, 0);
	p.look = vec3_make(0, 1, 0);
	p.up = vec3_make(0, 0, 1);
	diag_clear(&d);
	assert_int_equal(camera_init(c, &p, size, &d), 0);
}

/* ASPECT 2 with FOVY 90 makes FOVX 180: no image plane is that wide, and
 * scene-format.md refuses it.  Just below, it is fine. */
static void test_camera_nearfar_fovx_180_refused(void **state)
{
	struct camera_params p = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0, 0, 0 };
	struct camera c;
	struct diag d;

	(void)state;
	support_lens_params(&p, 90, 1, 2);
	expect_invalid(&p, 4, "horizontal field of view");
	p.fov_deg = 89.99;
	assert_int_equal(camera_init(&c, &p, 4, &d), 0);
	p.aspect = 1e308;
	expect_invalid(&p, 4, "horizontal field of view");
	p.aspect = -1;
	expect_invalid(&p, 4, "aspect");
	p.aspect = NAN;
	expect_invalid(&p, 4, "aspect");
	p.aspect = 0;
	p.near = -1;
	expect_invalid(&p, 4, "near");
	p.near = INFINITY;
	expect_invalid(&p, 4, "near");
}

/* A 4x4 image with ASPECT 2, NEAR 1, FOVY 60 (FOVX 120): the plane at
 * distance 1 is 2 tan(60) = 2 sqrt 3 wide and 2 tan(30) = 2 / sqrt 3 high.
 * Pixel centres sit at u = (-3/4, -1/4, 1/4, 3/4) sqrt 3 across and
 * v = (3/4, 1/4, -1/4, -3/4) / sqrt 3 down, so the top-left pixel's ray
 * starts on the plane at (-3/4 sqrt 3, 1, 3/4 / sqrt 3), |.|^2 = 27/16 + 1
 * + 3/16 = 2.875, and points from the eye through it. */
static void test_camera_nearfar_rays_by_hand(void **state)
{
	const double r3 = sqrt(3.0), len = sqrt(2.875);
	struct camera c;
	struct ray r;

	(void)state;
	init_nearfar(&c, 1, 2, 60, 4);
	assert_near(c.half_width, r3, 1e-15);
	assert_near(c.half_height, 1 / r3, 1e-15);
	r = camera_ray(&c, 0, 0);
	assert_vec3_near(r.origin, vec3_make(-0.75 * r3, 1, 0.75 / r3), 1e-15);
	assert_vec3_near(r.dir, vec3_make(-0.75 * r3 / len, 1 / len, 0.75 / r3 / len), 1e-15);
	r = camera_ray(&c, 3, 3);
	assert_vec3_near(r.origin, vec3_make(0.75 * r3, 1, -0.75 / r3), 1e-15);
	assert_vec3_near(r.dir, vec3_make(0.75 * r3 / len, 1 / len, -0.75 / r3 / len), 1e-15);
	/* Next to the centre: (u, v) = (sqrt 3 / 4, 1 / (4 sqrt 3)), |.|^2 =
	 * 3/16 + 1 + 1/48 = 58/48. */
	r = camera_ray(&c, 2, 1);
	assert_vec3_near(r.origin, vec3_make(0.25 * r3, 1, 0.25 / r3), 1e-15);
	assert_vec3_near(r.dir, vec3_scale(vec3_make(0.25 * r3, 1, 0.25 / r3), 1 / sqrt(58.0 / 48)),
			 1e-15);
	/* The centre pixel of a 5x5 image starts NEAR ahead of the eye. */
	init_nearfar(&c, 1, 2, 60, 5);
	r = camera_ray(&c, 2, 2);
	assert_vec3_near(r.origin, vec3_make(0, 1, 0), 1e-15);
	assert_vec3_near(r.dir, vec3_make(0, 1, 0), 1e-15);
	/* NEAR 2.5 moves the start, not the direction. */
	init_nearfar(&c, 2.5, 2, 60, 4);
	r = camera_ray(&c, 0, 0);
	assert_vec3_near(r.origin, vec3_make(-1.875 * r3, 2.5, 1.875 / r3), 1e-14);
	assert_vec3_near(r.dir, vec3_make(-0.75 * r3 / len, 1 / len, 0.75 / r3 / len), 1e-15);
}

/* The plane is centred on the view: a ray through a pixel and the one
 * through its mirror image across the centre are mirror images, and the
 * starts lie on the plane (forward . (origin - eye) = NEAR). */
static void test_camera_nearfar_plane(void **state)
{
	struct camera c;
	int px, py;

	(void)state;
	init_nearfar(&c, 3, 0.5, 100, 7);
	for (py = 0; py < 7; py++) {
		for (px = 0; px < 7; px++) {
			struct ray a = camera_ray(&c, px, py), b = camera_ray(&c, 6 - px, 6 - py);
			assert_near(a.origin.y, 3, 1e-15);
			assert_vec3_near(a.origin, vec3_make(-b.origin.x, b.origin.y, -b.origin.z),
					 1e-14);
			assert_near(vec3_length(a.dir), 1, 1e-15);
		}
	}
	/* FOVX 50: the outer pixel centres at 6/7 of tan(25) across, of
	 * tan(50) up. */
	assert_near(camera_ray(&c, 6, 3).origin.x, 3 * tan(25 * pi / 180) * 6 / 7, 1e-14);
	assert_near(camera_ray(&c, 3, 0).origin.z, 3 * tan(50 * pi / 180) * 6 / 7, 1e-14);
}

/* near 0 and aspect 0 are the classic camera bit for bit, and so is an
 * aspect of 1 (FOVX = FOVY) for the directions. */
static void test_camera_classic_unchanged(void **state)
{
	struct camera_params p = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0, 0, 0 };
	struct camera a, b;
	struct diag d;
	int px, py;

	(void)state;
	camera_params_default(&p);
	assert_true(p.near == 0 && p.aspect == 0);
	assert_int_equal(camera_init(&a, &p, 9, &d), 0);
	p.aspect = 1;
	assert_int_equal(camera_init(&b, &p, 9, &d), 0);
	for (py = 0; py < 9; py++) {
		for (px = 0; px < 9; px++) {
			struct ray ra = camera_ray(&a, px, py), rb = camera_ray(&b, px, py);
			double u = (px + 0.5) * a.pixel_scale - a.half_height;
			double v = a.half_height - (py + 0.5) * a.pixel_scale;
			struct vec3 w = vec3_normalize(vec3_add(a.forward,
				vec3_add(vec3_scale(a.right, u), vec3_scale(a.up, v))));

			assert_memory_equal(&ra.origin, &p.eye, sizeof(p.eye));
			assert_memory_equal(&ra.dir, &w, sizeof(w));
			assert_memory_equal(&rb, &ra, sizeof(ra));
		}
	}
}

/* The rays camera_lanes makes in set isa are camera_ray's to the bit: lane i the ray of column x0 + i % n
 * and of row py + i / n (as the packets lay out their rows). */
static void check_lanes(const struct camera *c, const struct camera_span *sp, int py, int n,
			enum rt_simd isa)
{
	const struct render_kernels *k = render_kernels_of(isa);
	struct camera_lanes_in in;
	struct ray_packet out;
	int i, ch;

	for (i = 0; i < CAMERA_LANES; i++) {
		int x = i % n, y = py + i / n;
		struct vec3 up_v = vec3_scale(c->up, c->half_height - (y + 0.5) * c->pixel_scale);

		for (ch = 0; ch < 3; ch++) {
			in.ru[ch][i] = vec3_component(sp->right_u[x], ch);
			in.uv[ch][i] = vec3_component(up_v, ch);
		}
	}
	k->camera_lanes(c, &in, &out);
	for (i = 0; i < CAMERA_LANES; i++) {
		struct ray got = ray_packet_get(&out, i);
		struct ray want = camera_ray(c, sp->x0 + i % n, py + i / n);

		if (memcmp(&got.origin, &want.origin, sizeof(want.origin)) != 0 ||
		    memcmp(&got.dir, &want.dir, sizeof(want.dir)) != 0) {
			print_error("camera_lanes %s, lane %d (pixel %d, %d): dir (%.17g %.17g %.17g) / (%.17g %.17g %.17g)\n",
				    support_isa_tag(isa), i, sp->x0 + i % n, py + i / n, got.dir.x,
				    got.dir.y, got.dir.z, want.dir.x, want.dir.y, want.dir.z);
			fail();
		}
	}
}

/* A block's rays made from the shared products are camera_ray's to the
 * bit, for views of every kind: default, turned and tilted, nearfar's
 * image plane and wider horizontal view, spans of 1 to 16 columns
 * anywhere in the image (its last columns too); and camera_lanes's, each
 * set of instructions on its own (skipped, and counted so, where this
 * processor lacks it). */
static void test_camera_span_is_camera_ray(void **state)
{
	enum rt_simd isa = SUPPORT_ISA_OF(state);
	static const struct {
		struct vec3 eye, look, up;
		double fov, near, aspect;
		int size;
	} views[] = {
		{ { 0, -200, 10 }, { 0, 0, 0 }, { 0, 0, 1 }, 80, 0, 0, 99 },
		{ { 31.5, -7.25, 80 }, { -3, 12, 1.5 }, { 0.2, 0.1, 1 }, 37.5, 0, 0, 1536 },
		{ { 1e5, 2e5, -3e4 }, { 0, 0, 0 }, { 0, 0, -1 }, 120, 0, 0, 17 },
		{ { 0, -50, 20 }, { 0, 0, 10 }, { 0, 0, 1 }, 60, 12.5, 1.5, 200 },
		{ { -5, 5, 5 }, { 5, -5, 0 }, { 1, 1, 1 }, 10, 0.001, 0.3, 1 },
	};
	size_t k;

	support_need_isa(isa, render_kernels_of(isa) != NULL);
	for (k = 0; k < sizeof(views) / sizeof(views[0]); k++) {
		struct camera_params p = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0, 0, 0 };
		struct camera c;
		struct diag d;
		int x0, n, py;

		p.eye = views[k].eye;
		p.look = views[k].look;
		p.up = views[k].up;
		p.fov_deg = views[k].fov;
		p.near = views[k].near;
		p.aspect = views[k].aspect;
		assert_int_equal(camera_init(&c, &p, views[k].size, &d), 0);
		for (x0 = 0; x0 < c.size; x0 += 1 + c.size / 7) {
			for (n = 1; n <= CAMERA_SPAN_MAX && x0 + n <= c.size; n += 5) {
				struct camera_span sp;
				struct ray rays[CAMERA_SPAN_MAX];
				int i;

				camera_span_init(&sp, &c, x0, x0 + n);
				for (py = 0; py < c.size; py += 1 + c.size / 5) {
					camera_span_rays(&sp, &c, py, rays);
					for (i = 0; i < n; i++) {
						struct ray want = camera_ray(&c, x0 + i, py);
						assert_memory_equal(&rays[i].origin, &want.origin,
								    sizeof(want.origin));
						assert_memory_equal(&rays[i].dir, &want.dir,
								    sizeof(want.dir));
					}
					check_lanes(&c, &sp, py, n, isa);
				}
			}
		}
	}
}

/* camera_project undoes camera_plane_point: the look-at point is the
 * image's middle at its distance; the plane's right edge at 101 pixels;
 * any point of the image comes back to within rounding, on a rolled,
 * non-square camera too; a direction behind the eye has a negative
 * depth. */
static void test_camera_project(void **state)
{
	struct camera_params p = { { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, 0, 0, 0 };
	struct camera c;
	struct diag d;
	double x, y;
	int i, j;

	(void)state;
	init_default(&c, 101);
	assert_near(camera_project(&c, vec3_make(0, 200, -10), &x, &y), sqrt(40100.0), 1e-12);
	assert_near(x, 50.5, 1e-12);
	assert_near(y, 50.5, 1e-12);
	assert_near(camera_project(&c, vec3_add_scaled(c.forward, c.right, c.half_width), &x, &y), 1.0,
		    1e-15);
	assert_near(x, 101.0, 1e-12);
	assert_near(y, 50.5, 1e-12);
	assert_true(camera_project(&c, vec3_neg(c.forward), &x, &y) < 0.0);

	p.eye = vec3_make(31.5, -7.25, 80);
	p.look = vec3_make(-3, 12, 1.5);
	p.up = vec3_make(0.2, 0.1, 1);
	p.fov_deg = 37.5;
	p.aspect = 1.5;
	assert_int_equal(camera_init_rect(&c, &p, 300, 120, &d), 0);
	for (j = 0; j <= 120; j += 15)
		for (i = 0; i <= 300; i += 25) {
			struct vec3 w = camera_plane_point(&c, i, j);
			struct ray r = camera_ray_at(&c, i, j);
			assert_vec3_near(vec3_normalize(w), r.dir, 1e-15);
			/* Any point along the direction, far along it too. */
			assert_true(camera_project(&c, vec3_scale(w, 250.0), &x, &y) > 0.0);
			assert_near(x, i, 1e-9);
			assert_near(y, j, 1e-9);
		}
}

SUPPORT_MAIN(SUPPORT_TESTS(test_camera_defaults, test_camera_project, test_camera_centre_pixel_looks_at_look_point,
			   test_camera_basis, test_camera_up_is_up_right_is_right,
			   test_camera_field_of_view, test_camera_size_one,
			   test_camera_custom_view, test_camera_errors,
			   test_camera_nearfar_fovx_180_refused,
			   test_camera_nearfar_rays_by_hand, test_camera_nearfar_plane,
			   test_camera_classic_unchanged),
	     SUPPORT_ISA_TESTS(test_camera_span_is_camera_ray))
