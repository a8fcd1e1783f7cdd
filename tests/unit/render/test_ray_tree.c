/* The bound on a pixel's tree of rays (render/ray_tree.h): renders of
 * glass scenes whose every byte is the whole tree's (traced here with no
 * cut-off) under both clamps and with samples, also from a first cut so
 * coarse that its first round alone changes pixels (so that the check of
 * the bytes is what keeps them); the glass sphere at recursion
 * 256 in few rays; the budget failing a render and naming the pixel, and
 * counting exactly; the cancel flag stopping one pixel's tree. */
#include <string.h>

#include "render/ray_tree.h"
#include "render/shade_math.h"
#include "whitted/camera.h"
#include "whitted/image.h"
#include "whitted/render.h"
#include "support.h"

/* A glass sphere (object 1, kr 0.5) in front of a mirror sphere and a
 * matte one, over the floor: a tree that branches at every glass hit. */
#define GLASS_SCENE \
	"%d 24 3 " \
	"sphere 0 0 30 30  0.9 0.9 1.0  0.1 0.3 0.3 0.5  8 " \
	"sphere -40 80 40 35  0.8 0.7 0.2  0.1 0.4 0.4 0.6  20 " \
	"sphere 70 60 20 20  0.2 0.4 0.9  0.3 0.6 0.2 0.0  5 " \
	"1 -100 -150 200 1 1 1"

static struct scene *glass_scene(int recursion, double kt)
{
	char text[512];
	struct scene *s;
	struct diag d;

	snprintf(text, sizeof(text), GLASS_SCENE, recursion);
	s = support_parse(text);
	assert_int_equal(scene_set_glass(s, 0, 1.5, kt, &d), 0);
	assert_int_equal(scene_add_floor(s, 1000, 20, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	return s;
}

static void make_camera(struct camera *cam, int size)
{
	struct camera_params p;
	struct diag d;

	camera_params_default(&p);
	assert_int_equal(camera_init(cam, &p, size, &d), 0);
}

/* Pixel (x, y)'s colour with every ray of its tree (no cut), the mean of
 * its n x n samples as samples.c makes it. */
static struct color whole_tree(const struct scene *s, const struct render_settings *rs,
			       const struct camera *cam, int x, int y, int n)
{
	struct render_tree t;
	struct color sum = color_make(0.0, 0.0, 0.0);
	int i, j;

	render_tree_init(&t, s, rs, UINT64_MAX, NULL, NULL, NULL);
	t.first_cut = 0.0;
	render_tree_pixel(&t);
	if (n <= 1) {
		struct ray r = camera_ray(cam, x, y);
		return render_trace_tree(s, rs, &r, 1, &t);
	}
	for (j = 0; j < n; j++)
		for (i = 0; i < n; i++) {
			struct ray r = camera_ray_at(cam, x + (i + 0.5) / n, y + (j + 0.5) / n);
			sum = color_add(sum, color_clamp(render_trace_tree(s, rs, &r, 1, &t)));
		}
	assert_int_equal(t.state, RENDER_TREE_GOING);
	assert_true(t.lost == 0.0);
	return color_scale(sum, 1.0 / ((double)n * n));
}

static void assert_whole_tree_image(const struct scene *s, const struct render_job *job,
				    const struct image *img)
{
	int x, y;

	for (y = 0; y < img->height; y++)
		for (x = 0; x < img->width; x++) {
			uint8_t want[3];

			render_color_to_rgb8(whole_tree(s, &job->settings, job->camera, x, y,
							job->samples),
					     want);
			assert_memory_equal(img->pixels + ((size_t)y * img->width + x) * 3, want, 3);
		}
}

static void test_ray_tree_images_are_the_whole_trees(void **state)
{
	struct scene *s = glass_scene(20, 0.45);
	struct camera cam;
	struct render_job job;
	struct ray_counts counts;
	struct image img;
	struct diag d;
	int clamp, samples;

	(void)state;
	make_camera(&cam, 24);
	for (clamp = 0; clamp < 2; clamp++)
		for (samples = 1; samples <= 2; samples++) {
			render_job_init(&job, s, &cam, 2);
			job.settings.clamp = clamp ? RT_CLAMP_FINAL : RT_CLAMP_LEVEL;
			job.samples = samples;
			assert_int_equal(image_alloc(&img, 24, 24, &d), 0);
			assert_int_equal(render_image(&job, &img, &counts, &d), 0);
			assert_whole_tree_image(s, &job, &img);
			image_free(&img);
		}
	scene_destroy(s);
}

/* A first cut of a whole level: rounds that leave out that much change
 * pixels, and the check sends them round again until they are right. */
static void test_ray_tree_coarse_cut_is_checked(void **state)
{
	struct scene *s = glass_scene(20, 0.45);
	struct render_settings rs = { 20, RT_CLAMP_LEVEL };
	struct camera cam;
	int x, y, changed = 0, again = 0;

	(void)state;
	make_camera(&cam, 24);
	for (y = 0; y < 24; y++)
		for (x = 0; x < 24; x++) {
			struct ray r = camera_ray(&cam, x, y);
			struct render_tree t;
			struct color c, first;
			uint8_t got[3], want[3], one[3];
			int rounds = 0;

			render_tree_init(&t, s, &rs, 0, NULL, NULL, NULL);
			t.first_cut = 1.0 / 255.0;
			render_tree_pixel(&t);
			first = c = render_trace_tree(s, &rs, &r, 1, &t);
			while (render_tree_again(&t, c, 1)) {
				rounds++;
				c = render_trace_tree(s, &rs, &r, 1, &t);
			}
			assert_true(rounds <= 6);
			render_color_to_rgb8(c, got);
			render_color_to_rgb8(first, one);
			render_color_to_rgb8(whole_tree(s, &rs, &cam, x, y, 1), want);
			assert_memory_equal(got, want, 3);
			changed += memcmp(one, want, 3) != 0;
			again += rounds > 0;
		}
	/* Without the check these pixels would be wrong. */
	assert_true(changed > 0);
	assert_true(again >= changed);
	scene_destroy(s);
}

/* The case: one glass sphere at the format's deepest recursion. */
static void test_ray_tree_glass_sphere_at_256(void **state)
{
	struct scene *s = support_parse("256 32 1 sphere 0 0 30 30  0.9 0.9 1.0  0.1 0.3 0.3 0.5  8 "
					"1 -100 -150 200 1 1 1");
	struct camera cam;
	struct render_job job;
	struct ray_counts counts;
	struct image img;
	struct diag d;

	(void)state;
	assert_int_equal(scene_set_glass(s, 0, 1.5, 0.8, &d), 0);
	assert_int_equal(scene_add_floor(s, 1000, 20, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	make_camera(&cam, 32);
	render_job_init(&job, s, &cam, 2);
	assert_int_equal(image_alloc(&img, 32, 32, &d), 0);
	assert_int_equal(render_image(&job, &img, &counts, &d), 0);
	/* 2^255 rays without the bound; a few a pixel with it. */
	assert_true(counts.reflection + counts.refraction < 100 * 32 * 32);
	image_free(&img);
	scene_destroy(s);
}

/* kr 1 and kt 0.9: the weights grow, nothing is cut, and the first pixel
 * past the budget fails the render. */
static void test_ray_tree_budget_fails_the_render(void **state)
{
	struct scene *s = support_parse("256 16 2 "
					"sphere -31 0 30 30  0.9 0.9 1.0  0.1 0.3 0.3 1.0  8 "
					"sphere 31 0 30 30  0.9 0.9 1.0  0.1 0.3 0.3 1.0  8 "
					"1 -100 -150 200 1 1 1");
	struct camera cam;
	struct render_job job;
	struct image img;
	struct diag d;

	(void)state;
	assert_int_equal(scene_set_glass(s, 0, 1.5, 0.9, &d), 0);
	assert_int_equal(scene_set_glass(s, 1, 1.5, 0.9, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	make_camera(&cam, 16);
	render_job_init(&job, s, &cam, 2);
	job.max_rays = 20000;
	assert_int_equal(image_alloc(&img, 16, 16, &d), 0);
	assert_int_equal(render_image(&job, &img, NULL, &d), -RT_E_RANGE);
	assert_non_null(strstr(d.msg, "needs more than 20000 rays"));
	assert_non_null(strstr(d.msg, "--max-rays"));
	assert_non_null(strstr(d.msg, "pixel "));
	image_free(&img);
	scene_destroy(s);
}

/* Without glass a primary ray's tree is a chain: recursion 5 on a mirror
 * around the eye is 5 rays, which a budget of 5 allows and of 4 does
 * not; render_image takes no budget below the longest chain. */
static void test_ray_tree_budget_counts_rays(void **state)
{
	struct scene *s = support_parse("5 1 1 sphere 0 0 0 1000  1 1 1  0.1 0.3 0.3 0.5  8 "
					"1 0 -100 0 1 1 1");
	struct render_settings rs = { 5, RT_CLAMP_LEVEL };
	struct camera_params p;
	struct camera cam;
	struct render_job job;
	struct render_tree t;
	struct image img;
	struct ray r;
	struct diag d;

	(void)state;
	/* The eye inside the sphere: every ray hits it and reflects. */
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	camera_params_default(&p);
	assert_int_equal(camera_init(&cam, &p, 1, &d), 0);
	r = camera_ray(&cam, 0, 0);
	render_tree_init(&t, s, &rs, 5, NULL, NULL, NULL);
	(void)render_trace_tree(s, &rs, &r, 1, &t);
	assert_int_equal(t.state, RENDER_TREE_GOING);
	assert_int_equal(t.used - (uint64_t)t.left, 5);
	render_tree_init(&t, s, &rs, 4, NULL, NULL, NULL);
	(void)render_trace_tree(s, &rs, &r, 1, &t);
	assert_int_equal(t.state, RENDER_TREE_OVER);
	render_job_init(&job, s, &cam, 1);
	assert_int_equal(image_alloc(&img, 1, 1, &d), 0);
	job.max_rays = RT_MIN_MAX_RAYS - 1;
	assert_int_equal(render_image(&job, &img, NULL, &d), -RT_E_INVALID);
	job.max_rays = RT_MIN_MAX_RAYS;
	assert_int_equal(render_image(&job, &img, NULL, &d), 0);
	image_free(&img);
	scene_destroy(s);
}

/* A cancel flag stops a tree within RENDER_TREE_CHUNK rays. */
static void test_ray_tree_cancel_stops_a_pixel(void **state)
{
	struct scene *s = glass_scene(256, 0.9);
	struct render_settings rs = { 256, RT_CLAMP_LEVEL };
	volatile sig_atomic_t cancel = 1;
	struct camera cam;
	struct render_tree t;
	struct ray r;

	(void)state;
	make_camera(&cam, 24);
	r = camera_ray(&cam, 12, 12);
	render_tree_init(&t, s, &rs, 0, &cancel, NULL, NULL);
	(void)render_trace_tree(s, &rs, &r, 1, &t);
	assert_int_equal(t.state, RENDER_TREE_CANCELLED);
	assert_true(t.used <= RENDER_TREE_CHUNK);
	scene_destroy(s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_ray_tree_images_are_the_whole_trees,
			   test_ray_tree_coarse_cut_is_checked,
			   test_ray_tree_glass_sphere_at_256,
			   test_ray_tree_budget_fails_the_render,
			   test_ray_tree_budget_counts_rays, test_ray_tree_cancel_stops_a_pixel))
