/* The viewer's fly camera: moves along its own axes, turns the way the keys
 * say, stays orthonormal, and rebuilds as whitted's camera, nearfar's near
 * plane and aspect included. */
#include <math.h>
#include <stdlib.h>

#include "support.h"
#include "fly_camera.h"

static const double pi = 3.14159265358979323846;

static struct fly_camera default_camera(void)
{
	struct camera_params p;
	struct fly_camera c;
	struct diag d;

	camera_params_default(&p);
	assert_int_equal(fly_camera_init(&c, &p, &d), 0);
	return c;
}

static void assert_orthonormal(const struct fly_camera *c, double eps)
{
	struct vec3 r = fly_camera_right(c);

	assert_near(vec3_length(c->forward), 1.0, eps);
	assert_near(vec3_length(c->up), 1.0, eps);
	assert_near(vec3_length(r), 1.0, eps);
	assert_near(vec3_dot(c->forward, c->up), 0.0, eps);
	assert_near(vec3_dot(c->forward, r), 0.0, eps);
	assert_near(vec3_dot(c->up, r), 0.0, eps);
}

static void test_fly_camera_init_matches_camera(void **state)
{
	struct fly_camera c = default_camera();

	(void)state;
	/* Eye (0,-200,10) looking at the origin with up +z. */
	assert_vec3_near(c.eye, vec3_make(0, -200, 10), 0.0);
	assert_vec3_near(c.forward, vec3_normalize(vec3_make(0, 200, -10)), 1e-15);
	assert_vec3_near(fly_camera_right(&c), vec3_make(1, 0, 0), 1e-15);
	assert_true(c.up.z > 0.99);
	assert_near(c.fov_deg, 80.0, 0.0);
	assert_orthonormal(&c, 1e-15);
}

static void test_fly_camera_init_rejects_bad_camera(void **state)
{
	struct camera_params p;
	struct fly_camera c;
	struct diag d;

	(void)state;
	camera_params_default(&p);
	p.up = vec3_make(0, 200, -10);
	assert_int_equal(fly_camera_init(&c, &p, &d), -RT_E_INVALID);
}

static void test_fly_camera_move_along_axes(void **state)
{
	struct fly_camera c = default_camera();
	struct vec3 start = c.eye;

	(void)state;
	fly_camera_move(&c, 0, 0, 2.0);
	assert_vec3_near(c.eye, vec3_add_scaled(start, c.forward, 2.0), 1e-12);
	fly_camera_move(&c, 3.0, 0, -2.0);
	assert_vec3_near(c.eye, vec3_make(3, -200, 10), 1e-12);
	fly_camera_move(&c, -3.0, 5.0, 0);
	assert_vec3_near(c.eye, vec3_add_scaled(start, c.up, 5.0), 1e-12);
}

static void test_fly_camera_turn_directions(void **state)
{
	struct fly_camera c;
	struct camera_params p;
	struct diag d;

	(void)state;
	/* Looking along +y with up +z: right is +x. */
	camera_params_default(&p);
	p.eye = vec3_make(0, 0, 0);
	p.look = vec3_make(0, 1, 0);
	p.up = vec3_make(0, 0, 1);
	p.fov_deg = 60;
	assert_int_equal(fly_camera_init(&c, &p, &d), 0);
	fly_camera_yaw(&c, pi / 2);		/* left: now along -x */
	assert_vec3_near(c.forward, vec3_make(-1, 0, 0), 1e-15);
	assert_vec3_near(c.up, vec3_make(0, 0, 1), 1e-15);
	fly_camera_yaw(&c, -pi / 2);
	fly_camera_pitch(&c, pi / 2);		/* up: now along +z */
	assert_vec3_near(c.forward, vec3_make(0, 0, 1), 1e-15);
	assert_vec3_near(c.up, vec3_make(0, -1, 0), 1e-15);
	fly_camera_pitch(&c, -pi / 2);
	fly_camera_roll(&c, pi / 2);		/* clockwise: up becomes the old right */
	assert_vec3_near(c.forward, vec3_make(0, 1, 0), 1e-15);
	assert_vec3_near(c.up, vec3_make(1, 0, 0), 1e-15);
	assert_vec3_near(c.eye, vec3_make(0, 0, 0), 0.0);
}

static void test_fly_camera_full_turns_return(void **state)
{
	struct fly_camera c = default_camera(), start = c;
	int i;

	(void)state;
	for (i = 0; i < 180; i++)
		fly_camera_yaw(&c, 2.0 * pi / 180);
	assert_vec3_near(c.forward, start.forward, 1e-12);
	assert_vec3_near(c.up, start.up, 1e-12);
	for (i = 0; i < 180; i++)
		fly_camera_roll(&c, -2.0 * pi / 180);
	for (i = 0; i < 180; i++)
		fly_camera_pitch(&c, 2.0 * pi / 180);
	assert_vec3_near(c.forward, start.forward, 1e-12);
	assert_vec3_near(c.up, start.up, 1e-12);
}

/* 100000 random turns, as a user holding the keys down for a long time. */
static void test_fly_camera_orthonormal_after_many_turns(void **state)
{
	struct fly_camera c = default_camera();
	unsigned seed = 12345;
	int i;

	(void)state;
	for (i = 0; i < 100000; i++) {
		double a;
		seed = seed * 1103515245u + 12345u;
		a = ((seed >> 8) % 2001 - 1000) * 1e-3;
		switch ((seed >> 20) % 3) {
		case 0:
			fly_camera_yaw(&c, a);
			break;
		case 1:
			fly_camera_pitch(&c, a);
			break;
		default:
			fly_camera_roll(&c, a);
		}
	}
	assert_orthonormal(&c, 1e-14);
}

/* The parameters rebuild the viewer's frame through camera_init. */
static void test_fly_camera_params_rebuild_frame(void **state)
{
	struct fly_camera c = default_camera();
	struct camera_params p;
	struct camera cam;
	struct diag d;
	int i;

	(void)state;
	for (i = 0; i < 37; i++) {
		fly_camera_yaw(&c, 0.3);
		fly_camera_pitch(&c, 0.2);
		fly_camera_roll(&c, 0.1);
		fly_camera_move(&c, 5, -3, 7);
	}
	fly_camera_params(&c, &p);
	assert_int_equal(camera_init(&cam, &p, 500, &d), 0);
	assert_vec3_near(cam.eye, c.eye, 0.0);
	assert_vec3_near(cam.forward, c.forward, 1e-14);
	assert_vec3_near(cam.up, c.up, 1e-14);
	assert_vec3_near(cam.right, fly_camera_right(&c), 1e-14);
	assert_near(cam.half_height, tan(80.0 * pi / 360.0), 0.0);
}

/* Far from the origin the look-at point keeps the direction accurate. */
static void test_fly_camera_params_far_from_origin(void **state)
{
	struct fly_camera c = default_camera();
	struct camera_params p;
	struct camera cam;
	struct diag d;

	(void)state;
	c.eye = vec3_make(1e12, -3e12, 2e11);
	fly_camera_yaw(&c, 0.7);
	fly_camera_params(&c, &p);
	assert_int_equal(camera_init(&cam, &p, 500, &d), 0);
	assert_vec3_near(cam.forward, c.forward, 1e-9);
	assert_vec3_near(cam.up, c.up, 1e-9);
}

/* nearfar's lens: the near plane and the aspect pass through the moves
 * and turns unchanged, bit for bit, so that the capture's camera_init on
 * the parameters is the camera whitted builds from the file and the
 * printed eye, look, up and fov. */
static void test_fly_camera_params_keep_near_and_aspect(void **state)
{
	struct camera_params p, back;
	struct fly_camera c;
	struct camera cam;
	struct diag d;

	(void)state;
	support_lens_params(&p, 80.00000000000001, 1.0, 1.77777777777778);
	assert_int_equal(fly_camera_init(&c, &p, &d), 0);
	assert_true(c.near == p.near && c.aspect == p.aspect && c.fov_deg == p.fov_deg);
	/* Untouched, the parameters give back the camera it was given. */
	fly_camera_params(&c, &back);
	assert_true(back.near == p.near && back.aspect == p.aspect && back.fov_deg == p.fov_deg);
	assert_int_equal(camera_init(&cam, &back, 720, &d), 0);
	assert_vec3_near(cam.forward, vec3_normalize(vec3_sub(p.look, p.eye)), 1e-15);
	assert_near(cam.half_width, tan(p.aspect * p.fov_deg * pi / 360.0), 0.0);
	assert_near(cam.near, 1.0, 0.0);
	fly_camera_yaw(&c, 0.4);
	fly_camera_pitch(&c, -0.1);
	fly_camera_roll(&c, 0.05);
	fly_camera_move(&c, 3, 4, 5);
	fly_camera_params(&c, &back);
	assert_memory_equal(&back.near, &p.near, sizeof(p.near));
	assert_memory_equal(&back.aspect, &p.aspect, sizeof(p.aspect));
	assert_memory_equal(&back.fov_deg, &p.fov_deg, sizeof(p.fov_deg));
	assert_int_equal(camera_init(&cam, &back, 720, &d), 0);
	assert_vec3_near(cam.forward, c.forward, 1e-14);
	assert_vec3_near(cam.up, c.up, 1e-14);
	assert_near(cam.half_height, tan(p.fov_deg * pi / 360.0), 0.0);
	assert_near(cam.half_width, tan(p.aspect * p.fov_deg * pi / 360.0), 0.0);
	assert_near(cam.near, 1.0, 0.0);

	/* The classic camera's zeros stay zeros. */
	camera_params_default(&p);
	assert_int_equal(fly_camera_init(&c, &p, &d), 0);
	fly_camera_yaw(&c, 0.4);
	fly_camera_params(&c, &back);
	assert_true(back.near == 0.0 && back.aspect == 0.0);
}

/* The checks are camera_init's: an aspect that makes the horizontal view
 * 180 degrees or more is refused. */
static void test_fly_camera_init_rejects_wide_aspect(void **state)
{
	struct camera_params p;
	struct fly_camera c;
	struct diag d;

	(void)state;
	camera_params_default(&p);
	p.aspect = 2.25;	/* 2.25 x 80 = 180 */
	assert_int_equal(fly_camera_init(&c, &p, &d), -RT_E_INVALID);
	p.aspect = 2.0;
	p.near = -1.0;
	assert_int_equal(fly_camera_init(&c, &p, &d), -RT_E_INVALID);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_fly_camera_init_matches_camera,
			   test_fly_camera_init_rejects_bad_camera,
			   test_fly_camera_move_along_axes, test_fly_camera_turn_directions,
			   test_fly_camera_full_turns_return,
			   test_fly_camera_orthonormal_after_many_turns,
			   test_fly_camera_params_rebuild_frame,
			   test_fly_camera_params_far_from_origin,
			   test_fly_camera_params_keep_near_and_aspect,
			   test_fly_camera_init_rejects_wide_aspect))
