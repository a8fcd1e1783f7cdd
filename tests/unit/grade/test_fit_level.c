/* The camera fit's pieces: a camera to its seven numbers and back, the
 * local moves (an orbit keeps the pivot in place, a dolly its size), the
 * levels (the target is the submission's own pixels; the true camera
 * scores 0; the blur keeps a flat image flat and is the Gaussian written
 * out, bit for bit; a checkerboard finer than
 * the pixels weighs nothing), and the flow-based Jacobian against finite
 * differences on a smooth level. */
#include <math.h>
#include <string.h>

#include "course_scene.h"
#include "grade/fit.h"
#include "grade_fixture.h"
#include "support.h"

static void test_fit_view_round_trip(void **state)
{
	int k;

	(void)state;
	support_rng_seed(11);
	for (k = 0; k < 200; k++) {
		struct camera_params p, q, base;
		struct camera a, b;
		struct diag d;
		double v[FIT_DIM];
		int x, y;

		camera_params_default(&p);
		p.eye = support_random_point(300.0);
		p.look = vec3_add(p.eye, vec3_scale(support_random_direction(), support_uniform(1.0, 200.0)));
		p.up = support_random_direction();
		p.fov_deg = support_uniform(20.0, 120.0);
		if (camera_init(&a, &p, 16, &d) < 0 || fabs(vec3_normalize(vec3_sub(p.look, p.eye)).z) > 0.99)
			continue;
		camera_params_default(&base);
		fit_view_of(&p, v);
		fit_params_of(v, &base, &q);
		assert_int_equal(camera_init(&b, &q, 16, &d), 0);
		for (y = 0; y < 16; y += 5)
			for (x = 0; x < 16; x += 5) {
				struct ray ra = camera_ray(&a, x, y), rb = camera_ray(&b, x, y);
				assert_vec3_near(ra.dir, rb.dir, 1e-9);
				assert_vec3_near(ra.origin, rb.origin, 1e-9);
			}
	}
}

/* Where camera p sees point q, in pixels of a size x size image. */
static void project(const struct camera_params *p, struct vec3 q, int size, double *u, double *w)
{
	struct camera c;
	struct diag d;
	struct vec3 dv;
	double z;

	assert_int_equal(camera_init(&c, p, size, &d), 0);
	dv = vec3_sub(q, c.eye);
	z = vec3_dot(dv, c.forward);
	*u = (vec3_dot(dv, c.right) / z + c.half_width) / c.pixel_scale_x;
	*w = (c.half_height - vec3_dot(dv, c.up) / z) / c.pixel_scale;
}

/* The view v moved by amount along its move k alone (fit_view_move
 * about pivot), as camera parameters *q (fit_params_of on base), and
 * where that camera sees point pt in a 100 x 100 image. */
static void project_moved(const double *v, int k, double amount, double pivot,
			  const struct camera_params *base, struct vec3 pt,
			  struct camera_params *q, double *u, double *w)
{
	double mv[FIT_DIM] = { 0 }, m[FIT_DIM];

	mv[k] = amount;
	fit_view_move(v, mv, pivot, m);
	fit_params_of(m, base, q);
	project(q, pt, 100, u, w);
}

static void test_fit_moves(void **state)
{
	struct camera_params p, base, q;
	double v[FIT_DIM], m[FIT_DIM], zero[FIT_DIM] = { 0 }, u0, w0, u1, w1, pivot = 150.0;
	struct vec3 centre, f, side;
	int k;

	(void)state;
	camera_params_default(&p);
	p.eye = vec3_make(30.0, -180.0, 40.0);
	p.look = vec3_make(0.0, 0.0, 10.0);
	camera_params_default(&base);
	fit_view_of(&p, v);
	fit_view_move(v, zero, pivot, m);
	for (k = 0; k < FIT_DIM; k++)
		assert_near(m[k], v[k], 1e-9);
	fit_params_of(v, &base, &p);
	f = vec3_normalize(vec3_sub(p.look, p.eye));
	centre = vec3_add_scaled(p.eye, f, pivot);
	project(&p, centre, 100, &u0, &w0);
	/* An orbit either way keeps the pivot where it was. */
	for (k = FIT_ORBIT_YAW; k <= FIT_ORBIT_PITCH; k++) {
		project_moved(v, k, 7.0, pivot, &base, centre, &q, &u1, &w1);
		assert_near(u1, u0, 1e-6);
		assert_near(w1, w0, 1e-6);
		assert_true(vec3_length(vec3_sub(q.eye, p.eye)) > 10.0);
	}
	/* A dolly keeps a point beside the pivot, at its depth, in place. */
	side = vec3_add_scaled(centre, vec3_normalize(vec3_cross(f, vec3_make(0, 0, 1))), 20.0);
	project(&p, side, 100, &u0, &w0);
	project_moved(v, FIT_DOLLY, 40.0, pivot, &base, side, &q, &u1, &w1);
	assert_near(u1, u0, 1e-6);
	assert_near(w1, w0, 1e-6);
	assert_near(vec3_length(vec3_sub(q.eye, p.eye)), 40.0, 1e-9);
}

struct setup {
	struct scene *scene;
	struct camera cam;
	struct camera_params params;
	struct grade_job job;
	struct image sub;
};

static void setup_make(struct setup *s, int size)
{
	struct diag d;

	s->scene = support_parse(course_scene);
	assert_int_equal(scene_add_floor(s->scene, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_prepare(s->scene, 1, &d), 0);
	camera_params_default(&s->params);
	s->params.eye = vec3_make(25.0, -170.0, 35.0);
	assert_int_equal(camera_init(&s->cam, &s->params, size, &d), 0);
	grade_fixture_job(&s->job, s->scene, &s->cam, scene_recursion(s->scene), 1);
	assert_int_equal(grade_render_reference(&s->job, &s->sub, &d), 0);
}

static void setup_free(struct setup *s)
{
	image_free(&s->sub);
	scene_destroy(s->scene);
}

static void test_fit_level_true_camera_scores_nothing(void **state)
{
	struct setup s;
	struct fit_level l;
	struct fit_scratch sc;
	struct diag d;
	double v[FIT_DIM], moved[FIT_DIM];
	int i, j;

	(void)state;
	setup_make(&s, 60);
	assert_int_equal(fit_level_grid(&l, &s.sub, 20, 20, 2, 1.5, &d), 0);
	assert_int_equal(fit_scratch_alloc(&sc, &l, &d), 0);
	/* The cells' samples are the submission's own pixels. */
	for (i = 0; i < l.n_samples; i++) {
		assert_true(l.sx[i] >= 0 && l.sx[i] < 60 && l.sy[i] >= 0 && l.sy[i] < 60);
		assert_true(l.sx[i] / 3 == (i / 4) % 20 && l.sy[i] / 3 == (i / 4) / 20);
	}
	fit_view_of(&s.params, v);
	/* The true camera: the render's colours, rounded in the image, so
	 * within half a level. */
	assert_true(fit_level_score(&l, &s.job, &s.params, v, &sc) < 0.25);
	memcpy(moved, v, sizeof(moved));
	moved[FIT_YAW] += 2.0;
	/* Two degrees off: far from it (a hundred times the true one's). */
	assert_true(fit_level_score(&l, &s.job, &s.params, moved, &sc) > 25.0);
	/* A camera that cannot be: the worst score. */
	moved[FIT_FOV] = 175.0;
	assert_true(isinf(fit_level_score(&l, &s.job, &s.params, moved, &sc)));
	fit_scratch_free(&sc);
	fit_level_free(&l);
	(void)j;
	setup_free(&s);
}

static void test_fit_blur_keeps_flat_and_sum(void **state)
{
	float img[3 * 21 * 21], tmp[3 * 21 * 21];
	double before = 0.0, after = 0.0;
	int i;

	(void)state;
	for (i = 0; i < 3 * 21 * 21; i++)
		img[i] = 42.0f;
	fit_blur(img, tmp, 21, 21, 1.7);
	for (i = 0; i < 3 * 21 * 21; i++)
		assert_near(img[i], 42.0, 1e-4);
	/* A point far from the edges (no cell its blur reaches is short of
	 * kernel) spreads but keeps its mass. */
	memset(img, 0, sizeof(img));
	img[3 * (10 * 21 + 10)] = 90.0f;
	for (i = 0; i < 3 * 21 * 21; i += 3)
		before += img[i];
	fit_blur(img, tmp, 21, 21, 0.8);
	for (i = 0; i < 3 * 21 * 21; i += 3)
		after += img[i];
	assert_near(after, before, 1e-3);
	assert_true(img[3 * (10 * 21 + 10)] < 45.0f && img[3 * (10 * 21 + 11)] > 1.0f);
}

/* The blur is the Gaussian written out pixel by pixel: each output the
 * sum of the taps inside the grid (t from -r up, weights exp(-t^2 / 2
 * sigma^2), r = ceil(3 sigma) at most 24) over the sum of their weights,
 * rows first, then columns; bit for bit, on sizes about the blur's chunk
 * of 128 pixels, and a kernel wider than the grid. */
static void naive_pass(const float *in, float *out, int w, int h, double sigma, bool rows)
{
	int r = (int)ceil(3.0 * sigma), x, y, t, c;

	r = r > 24 ? 24 : r;
	for (y = 0; y < h; y++)
		for (x = 0; x < w; x++) {
			double sum[3] = { 0.0, 0.0, 0.0 }, ws = 0.0;
			for (t = -r; t <= r; t++) {
				int xx = rows ? x + t : x, yy = rows ? y : y + t;
				double k = exp(-(double)t * t / (2.0 * sigma * sigma));
				if (xx < 0 || xx >= w || yy < 0 || yy >= h)
					continue;
				for (c = 0; c < 3; c++)
					sum[c] += k * in[3 * (yy * w + xx) + c];
				ws += k;
			}
			for (c = 0; c < 3; c++)
				out[3 * (y * w + x) + c] = (float)(sum[c] / ws);
		}
}

static void test_fit_blur_is_the_gaussian(void **state)
{
	static const int sizes[][2] = { { 1, 1 }, { 129, 3 }, { 3, 130 }, { 257, 2 }, { 40, 33 } };
	static const double sigmas[] = { 0.5, 1.7, 3.0, 20.0 };
	size_t a, b;
	int i;

	(void)state;
	support_rng_seed(29);
	for (a = 0; a < sizeof(sizes) / sizeof(sizes[0]); a++)
		for (b = 0; b < sizeof(sigmas) / sizeof(sigmas[0]); b++) {
			const int w = sizes[a][0], h = sizes[a][1], n = 3 * w * h;
			float *img = test_malloc(sizeof(float) * (size_t)n);
			float *tmp = test_malloc(sizeof(float) * (size_t)n);
			float *want = test_malloc(sizeof(float) * (size_t)n);
			float *mid = test_malloc(sizeof(float) * (size_t)n);
			for (i = 0; i < n; i++)
				img[i] = (float)support_uniform(0.0, 255.0);
			naive_pass(img, mid, w, h, sigmas[b], true);
			naive_pass(mid, want, w, h, sigmas[b], false);
			fit_blur(img, tmp, w, h, sigmas[b]);
			if (memcmp(img, want, sizeof(float) * (size_t)n) != 0)
				fail_msg("%dx%d, sigma %g: the blur differs from the Gaussian written out", w, h,
					 sigmas[b]);
			test_free(img);
			test_free(tmp);
			test_free(want);
			test_free(mid);
		}
}

/* A checkerboard of single pixels weighs nothing; a straight edge counts. */
static void test_fit_level_weighs_aliased_cells(void **state)
{
	struct image img;
	struct fit_level l;
	struct diag d;
	int x, y;

	(void)state;
	assert_int_equal(image_alloc(&img, 40, 40, &d), 0);
	for (y = 0; y < 40; y++)
		for (x = 0; x < 40; x++) {
			uint8_t v = x < 20 ? (uint8_t)(((x + y) & 1) * 255) : (uint8_t)(x < 30 ? 0 : 255);
			memset(img.pixels + 3 * (y * 40 + x), v, 3);
		}
	assert_int_equal(fit_level_grid(&l, &img, 4, 4, 1, 0.0, &d), 0);
	assert_near(l.weight[0], 0.0, 0.0);		/* the fine checker */
	assert_near(l.weight[1 * 4 + 1], 0.0, 0.0);
	assert_near(l.weight[2 * 4 + 2], 1.0, 0.0);	/* flat */
	assert_near(l.weight[2 * 4 + 3 - 1], 1.0, 0.0);	/* the edge at x = 30 */
	fit_level_free(&l);
	image_free(&img);
}

/* On a blurred level the Jacobian from the image's flow agrees with the
 * score's finite differences in sign and rough size. */
static void test_fit_level_jacobian_against_differences(void **state)
{
	struct setup s;
	struct fit_level l;
	struct fit_scratch sc, s2;
	struct diag d;
	double v[FIT_DIM], h[FIT_DIM] = { 0.8, 0.8, 1.2, 1.2, 0.8, 0.8, 0.6 }, pivot = 180.0;
	float *jac, *base;
	size_t n;
	int k;

	(void)state;
	setup_make(&s, 96);
	assert_int_equal(fit_level_grid(&l, &s.sub, 48, 48, 2, 2.0, &d), 0);
	assert_int_equal(fit_scratch_alloc(&sc, &l, &d), 0);
	assert_int_equal(fit_scratch_alloc(&s2, &l, &d), 0);
	assert_int_equal(fit_scratch_points(&sc, &l, &d), 0);
	n = 3 * (size_t)l.n_cells;
	fit_view_of(&s.params, v);
	assert_int_equal(fit_level_render(&l, &s.job, &s.params, v, &sc), 0);
	base = test_malloc(n * sizeof(float));
	memcpy(base, sc.cells, n * sizeof(float));
	jac = test_malloc(n * FIT_DIM * sizeof(float));
	fit_level_jacobian(&l, &s.job, &s.params, v, h, pivot, &sc, jac);
	for (k = 0; k < FIT_DIM; k++) {
		double q[FIT_DIM] = { 0 }, m[FIT_DIM], dot = 0.0, na = 0.0, nb = 0.0;
		size_t i;
		q[k] = h[k];
		fit_view_move(v, q, pivot, m);
		assert_int_equal(fit_level_render(&l, &s.job, &s.params, m, &s2), 0);
		for (i = 0; i < n; i++) {
			double fd = (s2.cells[i] - base[i]) / h[k], an = jac[(size_t)k * n + i];
			dot += fd * an;
			na += an * an;
			nb += fd * fd;
		}
		/* The same direction in the space of the cells. */
		assert_true(dot / sqrt(na * nb) > 0.7);
	}
	test_free(jac);
	test_free(base);
	fit_scratch_free(&sc);
	fit_scratch_free(&s2);
	fit_level_free(&l);
	setup_free(&s);
}

/* A level fitted to a cause's image (the submission has no shadows):
 * the camera that took it scores nothing with the cause rendered in
 * place of the reference, and far from nothing without it; and the fit
 * with the cause refuses a transform (a mirror is no render) and rays
 * through the pixels' corners. */
static void test_fit_level_with_a_cause(void **state)
{
	struct setup s;
	struct fit_level l;
	struct fit_scratch sc;
	struct grade_variant var;
	struct grade_rank r;
	struct grade_fit fit;
	struct image shadowless;
	struct diag d;
	double v[FIT_DIM];

	(void)state;
	setup_make(&s, 60);
	memset(&r, 0, sizeof(r));
	r.cause = RT_CAUSE_NO_SHADOWS;
	r.also = RT_CAUSE_NONE;
	assert_int_equal(grade_cause_image(&s.job, &s.sub, &r, &shadowless, &d), 0);
	assert_int_equal(fit_level_grid(&l, &shadowless, 20, 20, 2, 1.5, &d), 0);
	assert_int_equal(fit_scratch_alloc(&sc, &l, &d), 0);
	fit_view_of(&s.params, v);
	assert_true(fit_level_score(&l, &s.job, &s.params, v, &sc) > 4.0);
	assert_true(grade_variant_of(&s.job, RT_CAUSE_NO_SHADOWS, 0, &var));
	l.variant = &var;
	assert_true(fit_level_score(&l, &s.job, &s.params, v, &sc) < 0.25);
	fit_scratch_free(&sc);
	fit_level_free(&l);

	/* From the true camera the fit with the cause stays there. */
	assert_int_equal(grade_fit_camera_with(&s.job, &s.params, RT_CAUSE_NO_SHADOWS, 0, &shadowless,
					       NULL, &fit, &d), 0);
	assert_true(fit.score < 0.5);
	assert_vec3_near(fit.camera.eye, s.params.eye, 0.5);
	/* Bounded by a plain fit's levels: kept when it comes nearer on
	 * every level, abandoned (score infinite, no camera) on the first
	 * where it is farther. */
	{
		struct grade_fit bound, again;
		int k, last;
		for (k = 0; k < GRADE_FIT_LEVELS; k++)
			bound.levels[k] = 1.0;
		assert_int_equal(grade_fit_camera_with(&s.job, &s.params, RT_CAUSE_NO_SHADOWS, 0,
						       &shadowless, &bound, &again, &d), 0);
		assert_true(again.score == fit.score);
		assert_true(again.levels[2] < 1.0 && again.levels[GRADE_FIT_LEVELS - 1] < 1.0);
		assert_true(isinf(again.levels[0]) && isinf(again.levels[1]));
		for (k = 0; k < GRADE_FIT_LEVELS; k++)
			bound.levels[k] = k < 3 ? INFINITY : 0.0;
		assert_int_equal(grade_fit_camera_with(&s.job, &s.params, RT_CAUSE_NO_SHADOWS, 0,
						       &shadowless, &bound, &again, &d), 0);
		assert_true(isinf(again.score));
		/* Its last level (a 60-pixel image skips the levels finer
		 * than it whose blur does not shrink) is the first bounded
		 * one it reached; the finer ones were not tried. */
		for (last = GRADE_FIT_LEVELS - 1; last >= 0 && isinf(again.levels[last]); last--)
			;
		assert_true(last >= 3 && last < GRADE_FIT_LEVELS - 1 && again.levels[last] > 0.0);
		for (k = 3; k < last; k++)
			assert_true(isinf(again.levels[k]));
	}
	assert_int_equal(grade_fit_camera_with(&s.job, &s.params, RT_CAUSE_MIRRORED, 0, &shadowless,
					       NULL, &fit, &d), -RT_E_INVALID);
	assert_true(strstr(d.msg, "form") != NULL);
	/* Rays through the pixels' corners: not what the fit's levels render. */
	assert_int_equal(grade_fit_camera_with(&s.job, &s.params, RT_CAUSE_PIXEL_CORNERS, 0, &shadowless,
					       NULL, &fit, &d), -RT_E_INVALID);
	image_free(&shadowless);
	setup_free(&s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_fit_view_round_trip, test_fit_moves,
			   test_fit_level_true_camera_scores_nothing,
			   test_fit_blur_keeps_flat_and_sum, test_fit_blur_is_the_gaussian,
			   test_fit_level_weighs_aliased_cells,
			   test_fit_level_jacobian_against_differences,
			   test_fit_level_with_a_cause))
