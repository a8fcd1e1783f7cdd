/* The gate's figures between two images against values computed by hand,
 * the gate's edges, the difference picture, and the transforms of the
 * reference (each pixel where the cause puts it). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "course_scene.h"
#include "grade/grade_impl.h"
#include "grade_fixture.h"
#include "support.h"

static void image_of(struct image *img, int w, int h, const uint8_t *px)
{
	struct diag d;

	assert_int_equal(image_alloc(img, w, h, &d), 0);
	memcpy(img->pixels, px, (size_t)w * (size_t)h * 3);
}

static void test_grade_figures_by_hand(void **state)
{
	static const uint8_t a[12] = { 10, 20, 30, 40, 50, 60, 70, 80, 90, 100, 110, 120 };
	uint8_t b[12];
	struct image ia, ib;
	struct grade_figures f;

	(void)state;
	memcpy(b, a, sizeof(b));
	b[4] += 10;	/* one channel of pixel 1 off by 10 */
	b[9] += 3;	/* one of pixel 3 off by 3 */
	image_of(&ia, 2, 2, a);
	image_of(&ib, 2, 2, b);
	grade_figures_of(&ia, &ib, 1, 0, 0, &f);
	assert_int_equal(f.pixels, 4);
	assert_near(f.mean_error, 13.0 / 12.0, 1e-12);
	assert_near(f.psnr, 10.0 * log10(255.0 * 255.0 * 12.0 / 109.0), 1e-9);
	assert_near(f.off2, 0.5, 0.0);
	assert_near(f.off8, 0.25, 0.0);
	assert_near(f.off32, 0.0, 0.0);
	assert_false(f.match);
	grade_figures_of(&ia, &ia, 1, 0, 0, &f);
	assert_true(isinf(f.psnr));
	assert_true(f.match);
	image_free(&ia);
	image_free(&ib);
}

static void test_grade_gate_edges(void **state)
{
	/* 1000 x 1 pixels, 2 of them off by 3 levels in one channel: 0.2 %
	 * off by > 2 is within the gate, 3 pixels are not. */
	uint8_t *a = calloc(3000, 1), *b = calloc(3000, 1);
	struct image ia, ib;
	struct grade_figures f;

	(void)state;
	b[0] = b[3] = 3;
	image_of(&ia, 1000, 1, a);
	image_of(&ib, 1000, 1, b);
	grade_figures_of(&ia, &ib, 1, 0, 0, &f);
	assert_near(f.off2, 0.002, 1e-15);
	assert_true(f.match);
	ib.pixels[6] = 3;
	grade_figures_of(&ia, &ib, 1, 0, 0, &f);
	assert_false(f.match);
	image_free(&ia);
	image_free(&ib);
	free(a);
	free(b);
}

static void test_grade_outliers_left_out(void **state)
{
	/* 100 x 100: the worst 0.02 % is 2 pixels.  One pixel off by 150 in
	 * each channel fails the plain PSNR (10 log10(65025 * 10000 / 22500)
	 * = 44.6 dB) but is left out of the gate's; 3 such pixels are more
	 * than the > 8 clause allows. */
	uint8_t *a = calloc(30000, 1), *b = calloc(30000, 1);
	struct image ia, ib;
	struct grade_figures f;

	(void)state;
	memset(b + 300, 150, 3);
	b[3000] = 2;	/* a pixel off by 2: kept */
	image_of(&ia, 100, 100, a);
	image_of(&ib, 100, 100, b);
	grade_figures_of(&ia, &ib, 1, 0, 0, &f);
	assert_near(f.psnr, 10.0 * log10(65025.0 * 30000.0 / (3.0 * 22500.0 + 4.0)), 1e-9);
	assert_int_equal(f.left_out, 2);
	assert_true(isinf(f.psnr_gate));
	assert_true(f.match);
	/* A third pixel of many off by 1 stays in: its error decides. */
	memset(b + 600, 150, 3);
	memset(b + 900, 1, 3);
	ib.pixels[300] = 150;
	memcpy(ib.pixels, b, 30000);
	grade_figures_of(&ia, &ib, 1, 0, 0, &f);
	assert_int_equal(f.left_out, 2);
	assert_near(f.psnr_gate, 10.0 * log10(65025.0 * 3.0 * 9998.0 / 7.0), 1e-9);
	assert_true(f.match);
	memset(ib.pixels + 1200, 150, 3);
	grade_figures_of(&ia, &ib, 1, 0, 0, &f);
	assert_false(f.match);
	assert_near(f.off8, 0.0003, 1e-15);
	image_free(&ia);
	image_free(&ib);
	free(a);
	free(b);
}

static void test_grade_transforms(void **state)
{
	/* 2 x 2: p00 p10 / p01 p11. */
	static const uint8_t a[12] = { 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12 };
	static const uint8_t mirrored[12] = { 4, 5, 6, 1, 2, 3, 10, 11, 12, 7, 8, 9 };
	static const uint8_t flipped[12] = { 7, 8, 9, 10, 11, 12, 1, 2, 3, 4, 5, 6 };
	static const uint8_t transposed[12] = { 1, 2, 3, 7, 8, 9, 4, 5, 6, 10, 11, 12 };
	static const uint8_t swapped[12] = { 3, 2, 1, 6, 5, 4, 9, 8, 7, 12, 11, 10 };
	static const uint8_t half_turn[12] = { 10, 11, 12, 7, 8, 9, 4, 5, 6, 1, 2, 3 };
	static const uint8_t flipped_swapped[12] = { 9, 8, 7, 12, 11, 10, 3, 2, 1, 6, 5, 4 };
	static const struct {
		unsigned map;
		const uint8_t *want;
	} maps[] = {
		{ GRADE_MAP_MIRROR, mirrored },
		{ GRADE_MAP_FLIP, flipped },
		{ GRADE_MAP_TRANSPOSE, transposed },
		{ GRADE_MAP_RED_BLUE, swapped },
		/* Two at once: a half turn, and BMP's rows and bytes both wrong. */
		{ GRADE_MAP_MIRROR | GRADE_MAP_FLIP, half_turn },
		{ GRADE_MAP_FLIP | GRADE_MAP_RED_BLUE, flipped_swapped },
	};
	struct image ia, t;
	struct diag d;
	size_t i;

	(void)state;
	image_of(&ia, 2, 2, a);
	for (i = 0; i < sizeof(maps) / sizeof(maps[0]); i++) {
		assert_int_equal(grade_transform_map(&ia, maps[i].map, &t, &d), 0);
		assert_memory_equal(t.pixels, maps[i].want, 12);
		image_free(&t);
	}
	image_free(&ia);
}

static void test_grade_diff_image(void **state)
{
	static const uint8_t a[6] = { 90, 90, 90, 0, 0, 0 };
	static const uint8_t b[6] = { 90, 90, 90, 0, 5, 0 };
	struct image ia, ib, out;
	struct diag d;

	(void)state;
	image_of(&ia, 2, 1, a);
	image_of(&ib, 2, 1, b);
	assert_int_equal(grade_diff_image(&ia, &ib, &out, &d), 0);
	assert_int_equal(out.width, 4);
	/* left: |a - b| x 8; right: the reference dimmed (270 / 9 = 30), yellow where > 2. */
	assert_int_equal(out.pixels[0], 0);
	assert_int_equal(out.pixels[4], 40);
	assert_int_equal(out.pixels[6], 30);
	assert_int_equal(out.pixels[9], 255);
	assert_int_equal(out.pixels[10], 210);
	assert_int_equal(out.pixels[11], 0);
	image_free(&out);
	image_free(&ia);
	image_free(&ib);
}

/* Every allocation of the ranking (72 pixels: the sample, then full
 * renders) and of the PNG reader failing in turn: each fails cleanly with
 * RT_E_NOMEM (ASan's leak check covers the rest) until all succeed. */
static void test_grade_allocation_failures(void **state)
{
	struct scene *s = support_parse(course_scene);
	struct grade_rank ranks[GRADE_MAX_RANKS];
	struct camera_params p;
	struct grade_job job;
	struct camera cam;
	struct image ref, tref, sub, back;
	unsigned char *png;
	size_t n, png_len;
	unsigned long k;
	struct diag d;
	int rc;

	(void)state;
	assert_int_equal(scene_add_floor(s, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	camera_params_default(&p);
	assert_int_equal(camera_init(&cam, &p, 72, &d), 0);
	grade_fixture_job(&job, s, &cam, s->recursion, 2);
	assert_int_equal(grade_render_reference(&job, &ref, &d), 0);
	assert_int_equal(grade_transform_map(&ref, GRADE_MAP_RED_BLUE, &sub, &d), 0);
	assert_int_equal(image_encode_png(&sub, &png, &png_len, &d), 0);
	assert_int_equal(grade_render_truncated(&job, &tref, &d), 0);
	/* floor(255 c) is round(255 c) or one less, and not always the same. */
	for (k = 0, n = 0; k < (unsigned long)72 * 72 * 3; k++) {
		assert_true(tref.pixels[k] == ref.pixels[k] || tref.pixels[k] + 1 == ref.pixels[k]);
		n += tref.pixels[k] != ref.pixels[k];
	}
	assert_true(n > 1000);
	for (k = 1;; k++) {
		rt_alloc_fail_from(k);
		rc = grade_rank_causes(&job, &ref, &tref, &sub, NULL, ranks, &n, &d);
		rt_alloc_fail_from(0);
		if (rc == 0)
			break;
		assert_int_equal(rc, -RT_E_NOMEM);
	}
	assert_true(k > 3);
	assert_int_equal(ranks[0].cause, RT_CAUSE_RED_BLUE);
	for (k = 1;; k++) {
		rt_alloc_fail_from(k);
		rc = image_read_memory(png, png_len, "t.png", &back, NULL, &d);
		rt_alloc_fail_from(0);
		if (rc == 0)
			break;
		assert_int_equal(rc, -RT_E_NOMEM);
		assert_null(back.pixels);
	}
	assert_memory_equal(back.pixels, sub.pixels, (size_t)72 * 72 * 3);
	image_free(&back);
	rt_free(png);
	image_free(&sub);
	image_free(&ref);
	image_free(&tref);
	scene_destroy(s);
}

/* The never-clamped byte both ways from one trace: ka 3 on a grey of 0.5
 * is 1.5; round(382.5) = 383 keeps 127, (int)382.5 = 382 keeps 126. */
static void test_grade_wrap_both_ways(void **state)
{
	struct scene *s = support_parse("1\n8\n1\nsphere\n0 0 0\n1\n0.5 0.5 0.5\n3 0 0 0\n1\n0\n");
	struct camera_params p;
	struct grade_job job;
	struct camera cam;
	struct image round, trunc;
	struct grade_variant wrap, plain;
	struct diag d;

	(void)state;
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	camera_params_default(&p);
	assert_int_equal(camera_init(&cam, &p, 1, &d), 0);
	grade_fixture_job(&job, s, &cam, s->recursion, 1);
	assert_int_equal(image_alloc(&round, 1, 1, &d), 0);
	assert_int_equal(image_alloc(&trunc, 1, 1, &d), 0);
	assert_true(grade_variant_of(&job, RT_CAUSE_NEVER_CLAMP, 0, &wrap));
	grade_variant_plain(&job, &plain);
	assert_int_equal(grade_render_variants(&job, &wrap, &round, &trunc, 1, NULL, 0, &d), 0);
	assert_int_equal(round.pixels[0], 127);
	assert_int_equal(trunc.pixels[0], 126);
	assert_int_equal(grade_render_variants(&job, &plain, &round, &trunc, 1, NULL, 0, &d), 0);
	assert_int_equal(round.pixels[0], 255);
	assert_int_equal(trunc.pixels[0], 255);
	image_free(&round);
	image_free(&trunc);
	scene_destroy(s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_grade_figures_by_hand, test_grade_gate_edges,
			   test_grade_transforms, test_grade_diff_image,
			   test_grade_allocation_failures, test_grade_outliers_left_out,
			   test_grade_wrap_both_ways))
