/* Frames: output patterns, the orbit and keyframe interpolation. */
#include <string.h>

#include "whitted/frames.h"
#include "support.h"

static void test_frames_pattern(void **state)
{
	struct diag d;
	char buf[64];
	bool numbered;

	(void)state;
	assert_int_equal(frames_pattern_check("out/frame-%04d.png", &numbered, &d), 0);
	assert_true(numbered);
	assert_int_equal(frames_name("out/frame-%04d.png", 7, buf, sizeof(buf), &d), 0);
	assert_string_equal(buf, "out/frame-0007.png");
	assert_int_equal(frames_name("100%%-%d.png", 12, buf, sizeof(buf), &d), 0);
	assert_string_equal(buf, "100%-12.png");
	assert_int_equal(frames_pattern_check("plain.png", &numbered, &d), 0);
	assert_false(numbered);
	assert_int_equal(frames_pattern_check("x%s.png", &numbered, &d), -RT_E_INVALID);
	assert_int_equal(frames_pattern_check("x%d%d.png", &numbered, &d), -RT_E_INVALID);
	assert_int_equal(frames_pattern_check("x%00d.png", &numbered, &d), -RT_E_INVALID);
	assert_int_equal(frames_name("%09d-long-name.png", 1, buf, 8, &d), -RT_E_RANGE);
}

static void test_frames_orbit(void **state)
{
	struct camera_params base, out;

	(void)state;
	camera_params_default(&base);
	frames_orbit(&base, 1, 4, &out);
	assert_true(memcmp(&out, &base, sizeof(out)) == 0);
	/* A quarter turn counter-clockwise about +z: (0,-200) -> (200,0). */
	frames_orbit(&base, 2, 4, &out);
	assert_vec3_near(out.eye, vec3_make(200, 0, 10), 1e-12);
	frames_orbit(&base, 3, 4, &out);
	assert_vec3_near(out.eye, vec3_make(0, 200, 10), 1e-12);
	assert_vec3_near(out.look, base.look, 0.0);
	assert_near(out.fov_deg, base.fov_deg, 0.0);
}

static void test_frames_path_interpolation(void **state)
{
	struct camera_params keys[3], out;
	struct frame_path p = { keys, 3 };

	(void)state;
	camera_params_default(&keys[0]);
	keys[1] = keys[0];
	keys[1].eye = vec3_make(0, -100, 50);
	keys[1].fov_deg = 60;
	keys[2] = keys[1];
	keys[2].eye = vec3_make(100, -100, 50);
	frames_on_path(&p, 1, 5, &out);
	assert_vec3_near(out.eye, keys[0].eye, 0.0);
	frames_on_path(&p, 2, 5, &out);
	assert_vec3_near(out.eye, vec3_make(0, -150, 30), 0.0);
	assert_near(out.fov_deg, 70, 0.0);
	frames_on_path(&p, 3, 5, &out);
	assert_vec3_near(out.eye, keys[1].eye, 0.0);
	frames_on_path(&p, 4, 5, &out);
	assert_vec3_near(out.eye, vec3_make(50, -100, 50), 0.0);
	frames_on_path(&p, 5, 5, &out);
	assert_vec3_near(out.eye, keys[2].eye, 0.0);
	frames_on_path(&p, 1, 1, &out);
	assert_vec3_near(out.eye, keys[0].eye, 0.0);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_frames_pattern, test_frames_orbit,
			   test_frames_path_interpolation))
