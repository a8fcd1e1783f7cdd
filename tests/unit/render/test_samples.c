/* --samples N (render_job.samples): a pixel is round(255 mean) of the N x N
 * rays through its sub-pixel centres, each clamped (checked against
 * render_trace of those rays); the sub-pixel rays are the pixel-centre rays
 * of the camera N times larger (camera_ray_at against camera_ray); 0 and 1
 * are one ray a pixel, bit for bit; the image is the same for any thread
 * count and region, and with the samples traced in packets or one by one
 * (the same ray counts too); N*N primary rays a pixel are counted. */
#define _POSIX_C_SOURCE 200809L	/* setenv */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "course_scene.h"
#include "scene/scene_impl.h"
#include "whitted/render.h"
#include "render_fixture.h"
#include "support.h"

/* The course scene with its floor, prepared, and *cam the default camera
 * at size x size. */
static struct scene *course(struct camera *cam, int size)
{
	struct scene *s = support_parse(course_scene);
	struct diag d;

	assert_int_equal(scene_add_floor(s, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	support_default_camera(cam, size);
	return s;
}

static void render(const struct scene *s, const struct camera *cam, int samples, int threads,
		   int x0, int y0, int x1, int y1, enum clamp_mode clamp, struct image *img,
		   struct ray_counts *counts)
{
	struct render_job job;

	render_job_init(&job, s, cam, threads);
	job.samples = samples;
	job.settings.clamp = clamp;
	render_fixture_region(&job, x0, y0, x1, y1, img, counts);
}

/* Frees the three images a test rendered, then its scene. */
static void release(struct scene *s, struct image *a, struct image *b, struct image *c)
{
	image_free(a);
	image_free(b);
	image_free(c);
	scene_destroy(s);
}

static void test_samples_pixel_is_the_clamped_mean(void **state)
{
	static const enum clamp_mode modes[2] = { RT_CLAMP_LEVEL, RT_CLAMP_FINAL };
	struct camera cam;
	struct scene *s = course(&cam, 24);
	struct render_settings rs;
	struct image img;
	int m, n, px, py, i, j;

	(void)state;
	rs.recursion = s->recursion;
	for (m = 0; m < 2; m++) {
		rs.clamp = modes[m];
		for (n = 2; n <= 4; n++) {
			render(s, &cam, n, 2, 0, 0, 24, 24, modes[m], &img, NULL);
			for (py = 0; py < 24; py++) {
				for (px = 0; px < 24; px++) {
					struct color sum = color_make(0, 0, 0);
					uint8_t want[3];
					for (j = 0; j < n; j++)
						for (i = 0; i < n; i++) {
							struct ray r = camera_ray_at(&cam, px + (i + 0.5) / n,
										     py + (j + 0.5) / n);
							sum = color_add(sum, color_clamp(render_trace(s, &rs, &r, 1,
												      NULL)));
						}
					render_color_to_rgb8(color_scale(sum, 1.0 / (n * n)), want);
					assert_memory_equal(img.pixels + ((size_t)py * 24 + (size_t)px) * 3,
							    want, 3);
				}
			}
			image_free(&img);
		}
	}
	scene_destroy(s);
}

static void test_samples_are_the_big_image_centres(void **state)
{
	struct camera_params cp;
	struct camera small, big;
	struct diag d;
	int n = 3, x, y;

	(void)state;
	camera_params_default(&cp);
	cp.near = 2.0;
	cp.aspect = 1.3;
	assert_int_equal(camera_init(&small, &cp, 20, &d), 0);
	assert_int_equal(camera_init(&big, &cp, 60, &d), 0);
	for (y = 0; y < 60; y += 7)
		for (x = 0; x < 60; x += 5) {
			struct ray a = camera_ray_at(&small, (x + 0.5) / n, (y + 0.5) / n);
			struct ray b = camera_ray(&big, x, y);
			assert_vec3_near(a.dir, b.dir, 1e-14);
			assert_vec3_near(a.origin, b.origin, 1e-12);
		}
}

static void test_samples_one_is_the_default(void **state)
{
	struct camera cam;
	struct scene *s = course(&cam, 40);
	struct image a, b, c;

	(void)state;
	render(s, &cam, 0, 1, 0, 0, 40, 40, RT_CLAMP_LEVEL, &a, NULL);
	render(s, &cam, 1, 1, 0, 0, 40, 40, RT_CLAMP_LEVEL, &b, NULL);
	render(s, &cam, 2, 1, 0, 0, 40, 40, RT_CLAMP_LEVEL, &c, NULL);
	assert_memory_equal(a.pixels, b.pixels, 40 * 40 * 3);
	assert_true(memcmp(a.pixels, c.pixels, 40 * 40 * 3) != 0);
	release(s, &a, &b, &c);
}

static void test_samples_threads_and_regions(void **state)
{
	struct camera cam;
	struct scene *s = course(&cam, 37);
	struct ray_counts counts;
	struct image full, other, part;
	int y;

	(void)state;
	render(s, &cam, 3, 1, 0, 0, 37, 37, RT_CLAMP_LEVEL, &full, &counts);
	assert_true(counts.primary == 37 * 37 * 9);
	render(s, &cam, 3, 5, 0, 0, 37, 37, RT_CLAMP_LEVEL, &other, NULL);
	assert_memory_equal(full.pixels, other.pixels, 37 * 37 * 3);
	render(s, &cam, 3, 2, 5, 9, 30, 21, RT_CLAMP_LEVEL, &part, NULL);
	for (y = 9; y < 21; y++)
		assert_memory_equal(part.pixels + (size_t)(y - 9) * 25 * 3,
				    full.pixels + ((size_t)y * 37 + 5) * 3, 25 * 3);
	release(s, &full, &other, &part);
}

/* WHITTED_PACKETS=1 and 0: the samples of a row in packets, and one ray
 * at a time; N from 2 (a packet holds four pixels' samples) to 5 (a
 * pixel's 25 samples span two packets), both clamps, a block edge inside
 * the region. */
static void test_samples_packets_same_as_single_rays(void **state)
{
	struct camera cam;
	struct scene *s = course(&cam, 41);
	int n, clamp;

	(void)state;
	for (n = 2; n <= 5; n++)
		for (clamp = 0; clamp < 2; clamp++) {
			enum clamp_mode mode = clamp ? RT_CLAMP_FINAL : RT_CLAMP_LEVEL;
			struct ray_counts c1, c0;
			struct image one, other;

			assert_int_equal(setenv("WHITTED_PACKETS", "1", 1), 0);
			render(s, &cam, n, 2, 3, 5, 38, 30, mode, &one, &c1);
			assert_int_equal(setenv("WHITTED_PACKETS", "0", 1), 0);
			render(s, &cam, n, 2, 3, 5, 38, 30, mode, &other, &c0);
			assert_int_equal(unsetenv("WHITTED_PACKETS"), 0);
			assert_memory_equal(one.pixels, other.pixels, (size_t)35 * 25 * 3);
			assert_true(c1.primary == c0.primary && c1.shadow == c0.shadow &&
				    c1.reflection == c0.reflection);
			assert_true(c1.primary == (uint64_t)35 * 25 * (uint64_t)(n * n));
			image_free(&one);
			image_free(&other);
		}
	scene_destroy(s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_samples_pixel_is_the_clamped_mean,
			   test_samples_are_the_big_image_centres,
			   test_samples_one_is_the_default, test_samples_threads_and_regions,
			   test_samples_packets_same_as_single_rays))
