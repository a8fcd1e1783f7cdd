/* The ranking's exact figures are its own renders': every cause and pair
 * that grade_rank_causes rendered in full (not estimated) has the PSNR of
 * grade_cause_image's image of it against the submission, after the
 * sorts that reorder the sample's ranks (a pair once took another pair's
 * render: sr04's floor 400 wide with cells of 10 read 13.1 dB, not 23.0).
 * The submission is the course scene at 96 pixels (sampled: more than
 * GRADE_SAMPLE_MIN_PIXELS) with two rules broken at once, made here by
 * shade_rules_trace pixel by pixel. */
#include <math.h>
#include <string.h>

#include "course_scene.h"
#include "grade/grade_impl.h"
#include "render/shade_rules.h"
#include "grade_fixture.h"
#include "support.h"

#define SIZE 96

static void submission(const struct grade_job *job, unsigned rules, const struct shade_floor *fl,
		       struct image *sub)
{
	struct diag d;
	int x, y;

	assert_int_equal(image_alloc(sub, SIZE, SIZE, &d), 0);
	for (y = 0; y < SIZE; y++)
		for (x = 0; x < SIZE; x++) {
			struct ray r = camera_ray(job->camera, x, y);
			struct color c = shade_rules_trace_floor(job->scene, &job->settings, rules, fl, &r, 1);
			render_color_to_rgb8(c, sub->pixels + 3 * ((size_t)y * SIZE + x));
		}
}

static void test_rank_exact_figures(void **state)
{
	/* Two rules; a floor 400 wide with cells of 10 (two floor causes). */
	static const struct shade_floor small = { .moved = true, .half = 200.0, .cell = 10.0,
						  .ox = -200.0, .oy = -200.0 };
	static const struct {
		unsigned rules;
		const struct shade_floor *floor;
	} made[] = {
		{ RT_RULE_WHITE_SPECULAR | RT_RULE_NO_SHADOWS, NULL },
		{ 0, &small },
	};
	struct camera_params p;
	struct scene *s = grade_fixture_scene(course_scene, &p);
	struct grade_rank ranks[GRADE_MAX_RANKS];
	struct grade_job job;
	struct camera cam;
	struct diag d;
	size_t n, k, m;
	int exact_pairs = 0;

	(void)state;
	assert_int_equal(camera_init(&cam, &p, SIZE, &d), 0);
	grade_fixture_job(&job, s, &cam, s->recursion, 2);
	for (m = 0; m < sizeof(made) / sizeof(made[0]); m++) {
		struct image ref, tref, sub;
		assert_int_equal(grade_render_reference(&job, &ref, &d), 0);
		assert_int_equal(grade_render_truncated(&job, &tref, &d), 0);
		submission(&job, made[m].rules, made[m].floor, &sub);
		assert_int_equal(grade_rank_causes(&job, &ref, &tref, &sub, NULL, ranks, &n, &d), 0);
		assert_true(n > 0);
		/* Each submission's two differences, named first as a pair that
		 * is its very image. */
		assert_int_equal(ranks[0].also != RT_CAUSE_NONE, 1);
		assert_true(isinf(ranks[0].fig.psnr) && !ranks[0].estimated);
		for (k = 0; k < n; k++) {
			struct grade_figures f;
			struct image img;
			if (ranks[k].estimated || ranks[k].truncated)
				continue;
			assert_int_equal(grade_cause_image(&job, &ref, &ranks[k], &img, &d), 0);
			grade_figures_of(&img, &sub, 1, 0, 0, &f);
			if (isinf(f.psnr))
				assert_true(isinf(ranks[k].fig.psnr));
			else
				assert_near(ranks[k].fig.psnr, f.psnr, 1e-9);
			exact_pairs += ranks[k].also != RT_CAUSE_NONE;
			image_free(&img);
		}
		image_free(&sub);
		image_free(&ref);
		image_free(&tref);
	}
	/* The property was checked on pairs, not on singles only. */
	assert_true(exact_pairs >= 2);
	scene_destroy(s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_rank_exact_figures))
