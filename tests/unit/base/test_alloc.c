/* The allocation-failure sweep: the Nth allocation (and every later one)
 * fails, for N = 1, 2, ... until the operation succeeds.  Each failure
 * must return -RT_E_NOMEM with a message and free everything it took
 * (LeakSanitizer checks at exit); none may crash.  And rendering
 * allocates nothing at all. */
#define _POSIX_C_SOURCE 200809L
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/alloc.h"
#include "cli/scene_opts.h"
#include "course_scene.h"
#include "scene/scene_impl.h"
#include "whitted/scenefile.h"
#include "whitted/render.h"
#include "support.h"

/* Enough to end any sweep here; a sweep that gets this far is a bug. */
#define SWEEP_MAX 100000

/* The course example plus a quadric, a degenerate triangle (a note),
 * lights and trailing text (another note). */
static const char sweep_scene[] =
	"4 64\n"
	"8\n"
	"sphere 40.0 0.0 10.0 10.0 0.0 1.0 0.0 0.4 0.2 0.2 0.2 10\n"
	"sphere -30.0 60.0 20.0 20.0 0.0 0.0 1.0 0.2 0.2 0.4 0.2 15\n"
	"sphere -15.0 15.0 45.0 15.0 1.0 1.0 0.0 0.4 0.3 0.1 0.2 5\n"
	"triangle 50 30 0 70 60 0 50 45 50 1.0 0.0 0.0 0.4 0.2 0.1 0.3 5\n"
	"triangle 70 60 0 30 60 0 50 45 50 0.0 1.0 0.0 0.4 0.2 0.1 0.3 5\n"
	"triangle 30 60 0 50 30 0 50 45 50 0.0 0.0 1.0 0.4 0.2 0.1 0.3 5\n"
	"general 1 1 1 0 0 0 -20 -20 -20 200 0 0 0 0 0 5 0.0 0.0 1.0 0.4 0.2 0.1 0.3 3\n"
	"triangle 0 0 0 1 1 1 2 2 2 1 1 1 0 0 0 0 0\n"
	"4\n"
	"70.0 70.0 70.0 1.0 0.0 0.0\n"
	"-70 70 70 0.0 0.0 1.0\n"
	"70 -70 70 1 0 0.0\n"
	"-70 -70 70 0 1.0 0\n"
	"Input explanation: the rest is ignored\n";

/* Counts the notes besides the dialect's (which every read gives). */
static void count_note(void *ctx, const struct diag *note)
{
	if (strncmp(note->msg, "read as the ", 12) != 0)
		++*(int *)ctx;
}

static void check_nomem(int rc, const struct diag *d, unsigned long n)
{
	if (rc != -RT_E_NOMEM || d->msg[0] == '\0') {
		print_error("failing from allocation %lu: rc %d, message '%s'\n", n, rc, d->msg);
		fail();
	}
}

/* Parse, add the floor and prepare, with allocations failing from n on.
 * Returns 0 when everything succeeded (the scene is left in *out). */
static int load_all(const char *text, size_t len, struct scene **out, struct diag *d, int *notes)
{
	int rc;

	*notes = 0;
	rc = scene_parse("sweep.txt", text, len, NULL, count_note, notes, out, d);
	if (rc < 0) {
		assert_null(*out);
		return rc;
	}
	if ((rc = scene_add_floor(*out, RT_FLOOR_WIDTH, RT_FLOOR_TILE, d)) < 0 ||
	    (rc = scene_prepare(*out, 1, d)) < 0) {
		assert_null((*out)->accel);
		scene_destroy(*out);
		*out = NULL;
	}
	return rc;
}

static void sweep_text(const char *text, size_t shapes, size_t lights)
{
	unsigned long n;

	for (n = 1; n < SWEEP_MAX; n++) {
		struct scene *s = NULL;
		struct diag d;
		int rc, notes;

		diag_clear(&d);
		rt_alloc_fail_from(n);
		rc = load_all(text, strlen(text), &s, &d, &notes);
		rt_alloc_fail_from(0);
		if (rc == 0) {
			/* Every allocation succeeded: the whole scene. */
			assert_int_equal(s->n_shapes, shapes + 1);
			assert_int_equal(s->n_lights, lights);
			assert_non_null(s->accel);
			scene_destroy(s);
			/* There were failures to sweep through first. */
			assert_true(n > 5);
			return;
		}
		check_nomem(rc, &d, n);
	}
	fail_msg("the load never succeeded");
}

static void test_alloc_sweep_scene_parse(void **state)
{
	(void)state;
	sweep_text(sweep_scene, 8, 4);
	sweep_text(course_scene, 6, 4);
}

static void test_alloc_sweep_many_objects(void **state)
{
	/* Enough objects and lights for the arrays to grow several times and
	 * for the hierarchy to need many nodes. */
	size_t cap = 200 * 64 + 64, len = 0;
	char *text = malloc(cap);
	int i;

	(void)state;
	assert_non_null(text);
	len += (size_t)snprintf(text + len, cap - len, "2 8 150\n");
	for (i = 0; i < 150; i++)
		len += (size_t)snprintf(text + len, cap - len, "sphere %d %d %d 1 1 1 1 0.1 0.1 0.1 0.1 1\n",
					i % 10 * 7, i / 10 * 7, i % 3);
	len += (size_t)snprintf(text + len, cap - len, "40\n");
	for (i = 0; i < 40; i++)
		len += (size_t)snprintf(text + len, cap - len, "%d 0 50\n", i);
	sweep_text(text, 150, 40);
	free(text);
}

static void test_alloc_sweep_prepare_again(void **state)
{
	/* A prepared scene whose re-preparation fails keeps no hierarchy and
	 * can be prepared again or destroyed. */
	struct scene *s = support_parse(course_scene);
	struct diag d;
	unsigned long n;

	(void)state;
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	for (n = 1; n < SWEEP_MAX; n++) {
		int rc;
		rt_alloc_fail_from(n);
		rc = scene_prepare(s, 1, &d);
		rt_alloc_fail_from(0);
		if (rc == 0)
			break;
		check_nomem(rc, &d, n);
		assert_null(s->accel);
	}
	assert_non_null(s->accel);
	scene_destroy(s);
}

static void test_alloc_sweep_scene_load(void **state)
{
	char path[] = "/tmp/whitted-alloc-XXXXXX";
	int fd = mkstemp(path);
	unsigned long n;

	(void)state;
	assert_true(fd >= 0);
	assert_int_equal(write(fd, sweep_scene, strlen(sweep_scene)), (ssize_t)strlen(sweep_scene));
	close(fd);
	for (n = 1; n < SWEEP_MAX; n++) {
		struct scene *s = NULL;
		struct diag d;
		int rc, notes = 0;

		diag_clear(&d);
		rt_alloc_fail_from(n);
		rc = scene_load(path, NULL, count_note, &notes, &s, &d);
		rt_alloc_fail_from(0);
		if (rc == 0) {
			assert_int_equal(s->n_shapes, 8);
			/* The degenerate triangle and the trailing text. */
			assert_int_equal(notes, 2);
			scene_destroy(s);
			break;
		}
		assert_null(s);
		check_nomem(rc, &d, n);
	}
	unlink(path);
	assert_true(n < SWEEP_MAX);
}

static void test_alloc_sweep_test_scene_and_cli_load(void **state)
{
	struct cli_scene o;
	unsigned long n;

	(void)state;
	for (n = 1; n < SWEEP_MAX; n++) {
		struct scene *s = NULL;
		struct diag d;
		int rc;

		rt_alloc_fail_from(n);
		rc = scene_test_scene(&s, &d);
		rt_alloc_fail_from(0);
		if (rc == 0) {
			scene_destroy(s);
			break;
		}
		assert_null(s);
		check_nomem(rc, &d, n);
	}
	cli_scene_init(&o);
	for (n = 1; n < SWEEP_MAX; n++) {
		struct scene *s = NULL;
		struct camera cam;
		struct diag d;
		int rc;

		rt_alloc_fail_from(n);
		rc = cli_scene_load(&o, NULL, NULL, NULL, &s, &cam, &d);
		rt_alloc_fail_from(0);
		if (rc == 0) {
			/* The test scene's sphere and the floor. */
			assert_int_equal(s->n_shapes, 2);
			scene_destroy(s);
			break;
		}
		assert_null(s);
		check_nomem(rc, &d, n);
	}
	assert_true(n < SWEEP_MAX);
}

static void test_alloc_image(void **state)
{
	struct image img;
	struct diag d;

	(void)state;
	rt_alloc_fail_from(1);
	assert_int_equal(image_alloc(&img, 16, 16, &d), -RT_E_NOMEM);
	rt_alloc_fail_from(0);
	assert_null(img.pixels);
	assert_non_null(strstr(d.msg, "out of memory"));
	image_free(&img);
	rt_alloc_fail_from(2);
	assert_int_equal(image_alloc(&img, 16, 16, &d), 0);
	rt_alloc_fail_from(0);
	image_free(&img);
}

static void test_alloc_image_write(void **state)
{
	char dir[] = "/tmp/whitted-alloc-XXXXXX", path[64];
	struct image img;
	struct diag d;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(path, sizeof(path), "%s/out.ppm", dir);
	assert_int_equal(image_alloc(&img, 4, 4, &d), 0);
	/* The temporary file's name is the one allocation. */
	rt_alloc_fail_from(1);
	assert_int_equal(image_write(&img, path, RT_FORMAT_PPM, NULL, &d), -RT_E_NOMEM);
	rt_alloc_fail_from(0);
	assert_int_equal(access(path, F_OK), -1);
	/* The directory is still empty, so rmdir works. */
	assert_int_equal(rmdir(dir), 0);
	image_free(&img);
}

static void test_alloc_render_allocates_nothing(void **state)
{
	struct scene *s = support_prepared(course_scene, true);
	struct render_job job;
	struct camera cam;
	struct image img;
	struct diag d;
	struct ray r;
	struct render_settings rs = { 4, RT_CLAMP_LEVEL };

	(void)state;
	support_default_camera(&cam, 24);
	assert_int_equal(image_alloc(&img, 24, 24, &d), 0);
	render_job_init(&job, s, &cam, 3);
	job.settings = rs;
	/* Every allocation would fail; none is attempted. */
	rt_alloc_fail_from(1);
	assert_int_equal(render_image(&job, &img, NULL, &d), 0);
	r = camera_ray(&cam, 12, 12);
	(void)render_trace(s, &rs, &r, 1, NULL);
	assert_int_equal(rt_alloc_fail_from(0), 0);
	image_free(&img);
	scene_destroy(s);
}

/* Aligned blocks: aligned, their shrink keeps the elements and the
 * alignment, overflow and the failure switch refuse. */
static void test_alloc_aligned(void **state)
{
	unsigned char *p, *q;
	size_t i;

	(void)state;
	p = rt_aligned_array(64, 100000, 64);
	assert_non_null(p);
	assert_int_equal((uintptr_t)p % 64, 0);
	for (i = 0; i < 100000 * 64; i++)
		p[i] = (unsigned char)(i * 7);
	q = rt_aligned_shrink(p, 64, 30001, 64);
	assert_non_null(q);
	assert_int_equal((uintptr_t)q % 64, 0);
	for (i = 0; i < 30001 * 64; i++)
		assert_int_equal(q[i], (unsigned char)(i * 7));
	rt_free(q);
	assert_null(rt_aligned_array(64, SIZE_MAX / 2, 4));
	rt_alloc_fail_from(1);
	assert_null(rt_aligned_array(64, 10, 10));
	rt_alloc_fail_from(0);
}

/* Big zeroed buffers: small ones as rt_calloc, big ones aligned to the
 * huge page and zeroed to the last byte (the image's size of a 1536 px
 * render among them, and sizes whose huge pages the zeroing threads share
 * unevenly), each over memory just filled and freed; overflow and the
 * failure switch refuse, rt_free frees either. */
static void test_alloc_calloc_huge(void **state)
{
	static const size_t sizes[] = {1, 4096, ((size_t)2 << 20) - 1, (size_t)2 << 20,
				       (size_t)1536 * 1536 * 3, ((size_t)6 << 20) + 1,
				       ((size_t)5 << 20) + 7, ((size_t)17 << 21) - 3};
	size_t k, i;

	(void)state;
	for (k = 0; k < sizeof(sizes) / sizeof(sizes[0]); k++) {
		unsigned char *p = rt_calloc_huge(sizes[k], 1);

		assert_non_null(p);
		if (sizes[k] >= (size_t)2 << 20)
			assert_int_equal((uintptr_t)p % ((size_t)2 << 20), 0);
		for (i = 0; i < sizes[k]; i++)
			if (p[i] != 0)
				fail_msg("byte %zu of %zu is %d", i, sizes[k], p[i]);
		memset(p, 0xa5, sizes[k]);
		rt_free(p);
	}
	assert_null(rt_calloc_huge(SIZE_MAX / 2, 4));
	assert_null(rt_calloc_huge(SIZE_MAX, 1));
	rt_alloc_fail_from(1);
	assert_null(rt_calloc_huge((size_t)4 << 20, 1));
	assert_null(rt_calloc_huge(10, 10));
	rt_alloc_fail_from(0);
}

/* Big arrays: from 32 MiB on aligned to the huge page, below it to the
 * alignment asked; writable to the last byte; overflow and the failure
 * switch refuse; rt_aligned_shrink keeps the elements. */
static void test_alloc_array_huge(void **state)
{
	static const size_t sizes[] = {256, ((size_t)32 << 20) - 64, (size_t)32 << 20,
				       ((size_t)40 << 20) + 64};
	size_t k;

	(void)state;
	for (k = 0; k < sizeof(sizes) / sizeof(sizes[0]); k++) {
		unsigned char *p = rt_array_huge(64, sizes[k] / 64, 64), *q;

		assert_non_null(p);
		assert_int_equal((uintptr_t)p % (sizes[k] >= ((size_t)32 << 20) ? (size_t)2 << 20 : 64),
				 0);
		memset(p, 0x5a, sizes[k]);
		p[sizes[k] - 1] = 7;
		q = rt_aligned_shrink(p, 64, sizes[k] / 128, 64);
		assert_non_null(q);
		assert_int_equal(q[0], 0x5a);
		assert_int_equal(q[sizes[k] / 128 * 64 - 1], 0x5a);
		rt_free(q);
	}
	assert_null(rt_array_huge(64, SIZE_MAX / 2, 4));
	assert_null(rt_array_huge(64, SIZE_MAX, 1));
	rt_alloc_fail_from(1);
	assert_null(rt_array_huge(64, (size_t)1 << 20, 64));
	assert_null(rt_array_huge(64, 10, 10));
	rt_alloc_fail_from(0);
}

static void test_alloc_counter(void **state)
{
	void *p;

	(void)state;
	/* rt_alloc_fail_from returns the allocations attempted since the
	 * previous call, failed ones included. */
	rt_alloc_fail_from(0);
	p = rt_malloc(8);
	rt_free(p);
	p = rt_calloc(2, 8);
	rt_free(p);
	assert_int_equal(rt_alloc_fail_from(3), 2);
	p = rt_malloc(1);
	assert_non_null(p);
	rt_free(p);
	p = rt_strdup("ab");
	assert_non_null(p);
	rt_free(p);
	assert_null(rt_malloc(1));
	assert_null(rt_strdup("x"));
	p = rt_reallocarray(NULL, 4, 4);
	assert_null(p);
	assert_int_equal(rt_alloc_fail_from(0), 5);
	/* An overflowing size fails without counting as an attempt. */
	assert_null(rt_reallocarray(NULL, SIZE_MAX / 2, 4));
	assert_int_equal(rt_alloc_fail_from(0), 0);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_alloc_counter, test_alloc_aligned, test_alloc_sweep_scene_parse,
			   test_alloc_sweep_many_objects, test_alloc_sweep_prepare_again,
			   test_alloc_sweep_scene_load,
			   test_alloc_sweep_test_scene_and_cli_load, test_alloc_calloc_huge,
			   test_alloc_array_huge, test_alloc_image, test_alloc_image_write,
			   test_alloc_render_allocates_nothing))
