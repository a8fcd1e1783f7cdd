/* The floor's finish found from a submission: a render with the floor's
 * coefficients and shininess another (a student's 0.25 each and 15; 0.5
 * 0.3 0.4 0.2 and 10) gives them back exactly, rounded to the students'
 * 0.05; the reference's own image gives none; and the ranking names the
 * finish first, its render the submission's very image.  The submissions
 * are made here pixel by pixel with the rules' trace and a floor of that
 * finish (the fit sees only their bytes). */
#include <math.h>
#include <string.h>

#include "course_scene.h"
#include "grade/grade_impl.h"
#include "render/shade_rules.h"
#include "grade_fixture.h"
#include "support.h"

#define SIZE 96

struct setup {
	struct scene *s;
	struct camera cam;
	struct grade_job job;
};

static void setup_make(struct setup *t)
{
	struct camera_params p;
	struct diag d;

	t->s = grade_fixture_scene(course_scene, &p);
	assert_int_equal(camera_init(&t->cam, &p, SIZE, &d), 0);
	grade_fixture_job(&t->job, t->s, &t->cam, t->s->recursion, 2);
}

/* The submission with the floor's finish f (NULL: the scene's) and the
 * rules broken. */
static void submission(const struct grade_job *job, const struct material *f, unsigned rules,
		       struct image *sub)
{
	struct shade_floor fl = { .own_finish = f != NULL };
	struct diag d;
	int x, y;

	if (f)
		fl.finish = *f;
	assert_int_equal(image_alloc(sub, SIZE, SIZE, &d), 0);
	for (y = 0; y < SIZE; y++)
		for (x = 0; x < SIZE; x++) {
			struct ray r = camera_ray(job->camera, x, y);
			struct color c = shade_rules_trace_floor(job->scene, &job->settings, rules, &fl,
								 &r, 1);
			render_color_to_rgb8(c, sub->pixels + 3 * ((size_t)y * SIZE + x));
		}
}

static void test_floor_finish_found(void **state)
{
	static const double finishes[][5] = {
		{ 0.25, 0.25, 0.25, 0.25, 15.0 },
		{ 0.5, 0.3, 0.4, 0.2, 10.0 },
		{ 0.3, 0.6, 0.0, 0.1, 1.0 },
	};
	struct setup t;
	struct diag d;
	size_t k;

	(void)state;
	setup_make(&t);
	for (k = 0; k < sizeof(finishes) / sizeof(finishes[0]); k++) {
		struct material f = t.s->floor->mat;
		const struct material *got = &t.job.floor_finishes[0];
		struct image sub;

		f.ka = finishes[k][0];
		f.kd = finishes[k][1];
		f.ks = finishes[k][2];
		f.kr = finishes[k][3];
		f.shininess = finishes[k][4];
		submission(&t.job, &f, 0, &sub);
		assert_int_equal(grade_fit_floor_finish(&t.job, &sub, NULL, false, NULL, &d), 0);
		assert_true(t.job.n_floor_finishes >= 1);
		assert_near(got->ka, f.ka, 1e-12);
		assert_near(got->kd, f.kd, 1e-12);
		assert_near(got->ks, f.ks, 1e-12);
		assert_near(got->kr, f.kr, 1e-12);
		/* Without a highlight the exponent is the scene's. */
		assert_near(got->shininess, f.ks > 0.0 ? f.shininess : t.s->floor->mat.shininess, 0.0);
		/* The values as fitted (the floor in the spheres' reflections
		 * with the finish found first): within 0.005. */
		if (t.job.n_floor_finishes == 2) {
			assert_near(t.job.floor_finishes[1].ka, f.ka, 0.005);
			assert_near(t.job.floor_finishes[1].kd, f.kd, 0.005);
			assert_near(t.job.floor_finishes[1].ks, f.ks, 0.005);
			assert_near(t.job.floor_finishes[1].kr, f.kr, 0.005);
		}
		image_free(&sub);
	}
	scene_destroy(t.s);
}

static void test_floor_finish_none(void **state)
{
	struct setup t;
	struct diag d;
	struct image sub;

	(void)state;
	setup_make(&t);
	/* The reference itself, and the same with no shadows (a spatial
	 * difference no finish makes): the scene's own finish fits best. */
	submission(&t.job, NULL, 0, &sub);
	t.job.n_floor_finishes = 2;
	assert_int_equal(grade_fit_floor_finish(&t.job, &sub, NULL, false, NULL, &d), 0);
	assert_int_equal(t.job.n_floor_finishes, 0);
	image_free(&sub);
	/* --samples: not fitted. */
	submission(&t.job, NULL, RT_RULE_NO_SHADOWS, &sub);
	t.job.samples = 2;
	assert_int_equal(grade_fit_floor_finish(&t.job, &sub, NULL, false, NULL, &d), 0);
	assert_int_equal(t.job.n_floor_finishes, 0);
	image_free(&sub);
	scene_destroy(t.s);
}

static void test_floor_finish_ranked(void **state)
{
	struct setup t;
	struct material f;
	struct grade_rank ranks[GRADE_MAX_RANKS];
	struct image ref, tref, sub, img;
	struct grade_figures fig;
	struct diag d;
	size_t n;

	(void)state;
	setup_make(&t);
	f = t.s->floor->mat;
	f.ka = 0.25;
	f.kd = 0.25;
	f.ks = 0.25;
	f.kr = 0.25;
	f.shininess = 15.0;
	/* The finish and the highlight left white at once: named as the
	 * pair, whose render is the submission's very image. */
	submission(&t.job, &f, RT_RULE_WHITE_SPECULAR, &sub);
	assert_int_equal(grade_render_reference(&t.job, &ref, &d), 0);
	assert_int_equal(grade_render_truncated(&t.job, &tref, &d), 0);
	assert_int_equal(grade_fit_floor_finish(&t.job, &sub, NULL, false, NULL, &d), 0);
	assert_true(t.job.n_floor_finishes >= 1);
	assert_int_equal(grade_rank_causes(&t.job, &ref, &tref, &sub, NULL, ranks, &n, &d), 0);
	assert_true(n > 0);
	assert_true((ranks[0].cause == RT_CAUSE_FLOOR_FINISH && ranks[0].also == RT_CAUSE_WHITE_SPECULAR) ||
		    (ranks[0].cause == RT_CAUSE_WHITE_SPECULAR && ranks[0].also == RT_CAUSE_FLOOR_FINISH));
	assert_int_equal(grade_cause_image(&t.job, &ref, &ranks[0], &img, &d), 0);
	grade_figures_of(&img, &sub, 1, 0, 0, &fig);
	assert_true(isinf(fig.psnr));
	image_free(&img);
	image_free(&ref);
	image_free(&tref);
	image_free(&sub);
	scene_destroy(t.s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_floor_finish_found, test_floor_finish_none,
			   test_floor_finish_ranked))
