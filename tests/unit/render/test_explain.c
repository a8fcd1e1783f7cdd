/* explain_pixel (whitted/explain.h): its 8-bit value is the rendered
 * image's pixel for 20 random pixels of scenes of every dialect (classic,
 * spot, pyramid, nearfar with falloff and a spotlight, a course file with
 * nine lights), with glass and samples, a textured floor and --clamp
 * final; the tree's records agree with the sum (ambient plus the lit
 * lights' terms is the sum before the children; a child's parent and
 * level; a shadowed light names its blocker); the object's line is the
 * keyword's line in the file; a pixel outside the image is refused. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>

#include "cli/scene_opts.h"
#include "whitted/explain.h"
#include "whitted/render.h"
#include "support.h"

#ifndef RT_TEST_DATA_DIR
#define RT_TEST_DATA_DIR "tests/data"
#endif
#define SIZE 40
#define PIXELS 20

struct loaded {
	struct cli_scene o;
	struct scene *s;
	struct camera cam;
	struct render_settings rs;
};

/* The scene at path (relative to the repository) with the options
 * opts (NULL-ended pairs of option and value, as on the command line). */
static void load(const char *path, const char *const *opts, struct loaded *l)
{
	static char full[1024];
	struct diag d;

	snprintf(full, sizeof(full), "%s/../../%s", RT_TEST_DATA_DIR, path);
	cli_scene_init(&l->o);
	l->o.quiet = true;
	l->o.size = SIZE;
	for (; opts && opts[0]; opts += 2) {
		static const struct option longopts[] = { CLI_SCENE_LONG, { NULL, 0, NULL, 0 } };
		const struct option *op;
		char value[1024];
		int c = 0;

		for (op = longopts; op->name; op++)
			if (strcmp(op->name, opts[0]) == 0)
				c = op->val;
		assert_int_not_equal(c, 0);
		/* Paths in values are the repository's too. */
		if (strcmp(opts[0], "floor-texture") == 0)
			snprintf(value, sizeof(value), "%s/../textures/white.bmp,%s/../textures/black.png",
				 RT_TEST_DATA_DIR, RT_TEST_DATA_DIR);
		else
			snprintf(value, sizeof(value), "%s", opts[1] ? opts[1] : "");
		diag_clear(&d);
		assert_int_equal(cli_scene_option(&l->o, c, value, &d), 1);
	}
	diag_clear(&d);
	if (cli_scene_load(&l->o, full, NULL, NULL, &l->s, &l->cam, &d) < 0)
		fail_msg("%s: %s", full, d.msg);
	assert_int_equal(scene_prepare(l->s, 2, &d), 0);
	l->rs.recursion = scene_recursion(l->s);
	l->rs.clamp = l->o.clamp;
}

static void check_pixels(const char *path, const char *const *opts)
{
	struct loaded l;
	struct render_job job;
	struct image img;
	struct diag d;
	int k;

	load(path, opts, &l);
	render_job_init(&job, l.s, &l.cam, 2);
	job.settings = l.rs;
	job.samples = l.o.samples;
	assert_int_equal(image_alloc(&img, l.cam.width, l.cam.height, &d), 0);
	assert_int_equal(render_image(&job, &img, NULL, &d), 0);
	for (k = 0; k < PIXELS; k++) {
		int x = (int)(support_rng() * img.width), y = (int)(support_rng() * img.height);
		const uint8_t *px = img.pixels + ((size_t)y * (size_t)img.width + (size_t)x) * 3;
		struct explanation e;

		assert_int_equal(explain_pixel(l.s, &l.cam, &l.rs, l.o.samples, x, y, &e, &d), 0);
		if (memcmp(e.value, px, 3) != 0)
			fail_msg("%s pixel %d,%d: explained (%d, %d, %d), rendered (%d, %d, %d)", path, x,
				 y, e.value[0], e.value[1], e.value[2], px[0], px[1], px[2]);
		assert_true(e.n_rays >= (size_t)(l.o.samples > 1 ? l.o.samples * l.o.samples : 1));
		explanation_free(&e);
	}
	image_free(&img);
	scene_destroy(l.s);
}

/* A scene of each dialect: the files checked, with the stream's seed. */
struct dialect_files {
	unsigned seed;
	const char *path[2];	/* the second NULL where there is one */
};

static const struct dialect_files classic = { 30, { "scenes/scene.txt", NULL } };
static const struct dialect_files spot = {
	31, { "scenes/spot.txt", "tests/data/course-files/sadathossain01.txt" }
};
static const struct dialect_files pyramid = { 32, { "tests/data/course-files/ishtiaqniloy.txt" } };
static const struct dialect_files nearfar = { 33, { "tests/data/course-files/an-akhand.txt" } };

/* check_pixels on each file of the dialect_files *state points at. */
static void test_explain_value_is_the_pixel(void **state)
{
	const struct dialect_files *f = *state;
	int i;

	support_rng_seed(f->seed);
	for (i = 0; i < 2 && f->path[i]; i++)
		check_pixels(f->path[i], NULL);
}

static void test_explain_value_is_the_pixel_options(void **state)
{
	static const char *const glass[] = { "glass", "2", "samples", "2", NULL };
	static const char *const cube[] = { "glass", "1", "recursion", "5", NULL };
	static const char *const tex[] = { "floor-texture", "", "clamp", "final", NULL };

	(void)state;
	support_rng_seed(34);
	check_pixels("scenes/sphere.txt", glass);
	check_pixels("scenes/nearfar.txt", cube);
	check_pixels("scenes/scene.txt", tex);
}

/* The line of the n-th (1-based) line of path that starts with keyword. */
static int keyword_line(const char *path, const char *keyword, long n)
{
	char full[1024], line[512];
	FILE *f;
	int at = 0;

	snprintf(full, sizeof(full), "%s/../../%s", RT_TEST_DATA_DIR, path);
	assert_non_null(f = fopen(full, "r"));
	while (fgets(line, sizeof(line), f)) {
		at++;
		if (strncmp(line, keyword, strlen(keyword)) == 0 && --n == 0)
			break;
	}
	fclose(f);
	return n == 0 ? at : -1;
}

static void test_explain_tree_records(void **state)
{
	struct loaded l;
	struct diag d;
	int x, y, hits = 0, shadowed = 0, children = 0;

	(void)state;
	load("scenes/scene.txt", NULL, &l);
	for (y = 0; y < SIZE; y += 3)
		for (x = 0; x < SIZE; x += 3) {
			struct explanation e;
			size_t i, k;

			assert_int_equal(explain_pixel(l.s, &l.cam, &l.rs, 1, x, y, &e, &d), 0);
			assert_int_equal(e.rays[0].kind, EXPLAIN_PRIMARY);
			assert_int_equal(e.rays[0].parent, -1);
			for (i = 0; i < e.n_rays; i++) {
				const struct explain_ray *r = &e.rays[i];
				struct color sum;
				if (!r->hit)
					continue;
				hits++;
				if (!r->object.floor) {
					/* The how-manieth object of its keyword it is. */
					long nth = 0, j;
					for (j = 0; j < r->object.index; j++)
						nth += strcmp(scene_shape(l.s, (size_t)j)->ops->keyword,
							      r->object.keyword) == 0;
					assert_int_equal(r->object.line,
							 keyword_line("scenes/scene.txt", r->object.keyword, nth));
				}
				sum = r->ambient;
				for (k = 0; k < r->n_lights; k++) {
					const struct explain_light *lt = &e.lights[r->first_light + k];
					if (lt->state == EXPLAIN_SHADOWED) {
						shadowed++;
						assert_true(lt->blocker_known);
					}
				}
				sum = color_add(sum, r->direct);
				if (r->reflected >= 0) {
					children++;
					assert_int_equal(e.rays[r->reflected].parent, (long)i);
					assert_int_equal(e.rays[r->reflected].level, r->level + 1);
					sum = color_add(sum, color_scale(r->reflected_color, r->k_reflected));
				}
				assert_memory_equal(&sum, &r->sum, sizeof(sum));
			}
			explanation_free(&e);
		}
	assert_true(hits > 100);
	assert_true(shadowed > 0);
	assert_true(children > 0);
	scene_destroy(l.s);
}

static void test_explain_outside_the_image(void **state)
{
	struct loaded l;
	struct explanation e;
	struct diag d;

	(void)state;
	load("scenes/scene.txt", NULL, &l);
	assert_int_equal(explain_pixel(l.s, &l.cam, &l.rs, 1, SIZE, 0, &e, &d), -RT_E_INVALID);
	assert_non_null(strstr(d.msg, "outside"));
	assert_int_equal(explain_pixel(l.s, &l.cam, &l.rs, 1, 0, -1, &e, &d), -RT_E_INVALID);
	scene_destroy(l.s);
}

SUPPORT_MAIN(SUPPORT_DATA_TEST("test_explain_value_is_the_pixel_classic",
				test_explain_value_is_the_pixel, &classic),
	     SUPPORT_DATA_TEST("test_explain_value_is_the_pixel_spot",
				test_explain_value_is_the_pixel, &spot),
	     SUPPORT_DATA_TEST("test_explain_value_is_the_pixel_pyramid",
				test_explain_value_is_the_pixel, &pyramid),
	     SUPPORT_DATA_TEST("test_explain_value_is_the_pixel_nearfar",
				test_explain_value_is_the_pixel, &nearfar),
	     SUPPORT_TESTS(test_explain_value_is_the_pixel_options, test_explain_tree_records,
			   test_explain_outside_the_image))
