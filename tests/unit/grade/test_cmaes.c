/* CMA-ES: the minimum of functions whose answer is known, from far away
 * and along narrow valleys; the same answer for the same seed; NaNs as
 * the worst; the covariance it hands on. */
#include <math.h>
#include <string.h>

#include "grade/cmaes.h"
#include "support.h"

struct quad {
	int dim;
	double centre[CMAES_MAX_DIM];
	double scale[CMAES_MAX_DIM];	/* the valley's widths */
	double turn;			/* the valley turned in the (0, 1) plane */
	long calls;
};

static double quad_at(const struct quad *q, const double *x)
{
	double v[CMAES_MAX_DIM], s = 0.0;
	int i;

	for (i = 0; i < q->dim; i++)
		v[i] = x[i] - q->centre[i];
	if (q->dim >= 2) {
		double a = cos(q->turn) * v[0] + sin(q->turn) * v[1];
		double b = -sin(q->turn) * v[0] + cos(q->turn) * v[1];
		v[0] = a;
		v[1] = b;
	}
	for (i = 0; i < q->dim; i++)
		s += (v[i] / q->scale[i]) * (v[i] / q->scale[i]);
	return s;
}

static void quad_batch(void *ctx, const double *xs, double *fs, int n)
{
	struct quad *q = ctx;
	int i;

	for (i = 0; i < n; i++)
		fs[i] = quad_at(q, xs + i * q->dim);
	q->calls += n;
}

static void setup_valley(struct quad *q)
{
	static const double c[7] = { 12.0, -7.5, 3.25, 40.0, -11.0, 0.5, 80.0 };
	int i;

	memset(q, 0, sizeof(*q));
	q->dim = 7;
	for (i = 0; i < 7; i++) {
		q->centre[i] = c[i];
		q->scale[i] = 1.0;
	}
	q->scale[1] = 0.01;	/* a valley a hundred times narrower than long */
	q->turn = 0.6;
}

static void test_cmaes_finds_a_narrow_turned_valley(void **state)
{
	const double unit[7] = { 10, 10, 10, 10, 10, 10, 10 };
	struct cmaes_options o = { 7, 12, 400, 1.0, 1e-8, 42, NULL, NULL };
	struct quad q;
	double x[7] = { 0 };
	long evals;
	int i;

	(void)state;
	setup_valley(&q);
	assert_true(cmaes_minimise(&o, x, unit, quad_batch, &q, &evals) < 1e-10);
	for (i = 0; i < 7; i++)
		assert_near(x[i], q.centre[i], 1e-4);
	assert_int_equal(evals, q.calls);
	assert_true(evals % 12 == 0 && evals <= 400 * 12);
}

static void test_cmaes_same_seed_same_answer(void **state)
{
	const double unit[7] = { 10, 10, 10, 10, 10, 10, 10 };
	struct cmaes_options o = { 7, 10, 30, 1.0, 0.0, 7, NULL, NULL };
	struct quad q1, q2;
	double a[7] = { 0 }, b[7] = { 0 };
	double fa, fb;

	(void)state;
	setup_valley(&q1);
	setup_valley(&q2);
	fa = cmaes_minimise(&o, a, unit, quad_batch, &q1, NULL);
	fb = cmaes_minimise(&o, b, unit, quad_batch, &q2, NULL);
	assert_true(fa == fb);
	assert_memory_equal(a, b, sizeof(a));
	/* Another seed: another path, the same minimum once it runs long. */
	o.seed = 8;
	o.generations = 400;
	o.sigma_stop = 1e-8;
	assert_true(cmaes_minimise(&o, b, unit, quad_batch, &q2, NULL) < 1e-10);
}

/* NaN where x0 > 0: the minimum of the rest (x0 = 0 on the boundary). */
static void nan_batch(void *ctx, const double *xs, double *fs, int n)
{
	int i;

	(void)ctx;
	for (i = 0; i < n; i++) {
		const double *x = xs + 2 * i;
		fs[i] = x[0] > 0.0 ? NAN : (x[0] + 1.0) * (x[0] + 1.0) + (x[1] - 2.0) * (x[1] - 2.0);
	}
}

static void test_cmaes_nan_is_the_worst(void **state)
{
	const double unit[2] = { 1, 1 };
	struct cmaes_options o = { 2, 8, 300, 0.5, 1e-9, 3, NULL, NULL };
	double x[2] = { -3.0, -3.0 };

	(void)state;
	assert_true(cmaes_minimise(&o, x, unit, nan_batch, NULL, NULL) < 1e-12);
	assert_near(x[0], -1.0, 1e-6);
	assert_near(x[1], 2.0, 1e-6);
}

/* The covariance learnt along a valley turned 45 degrees: its largest
 * axis is 1 (the step goes into sigma_out), along the valley. */
static void test_cmaes_hands_on_its_covariance(void **state)
{
	const double unit[2] = { 1, 1 };
	double cov[CMAES_MAX_DIM][CMAES_MAX_DIM] = { { 1, 0 }, { 0, 1 } }, sigma = 0.0;
	struct cmaes_options o = { 2, 8, 60, 1.0, 0.0, 5, cov, &sigma };
	struct quad q;
	double x[2] = { 3.0, -3.0 };

	(void)state;
	memset(&q, 0, sizeof(q));
	q.dim = 2;
	q.scale[0] = 1.0;
	q.scale[1] = 0.05;
	q.turn = 0.785398163397448;
	cmaes_minimise(&o, x, unit, quad_batch, &q, NULL);
	assert_true(sigma > 0.0);
	assert_true(fmax(cov[0][0], cov[1][1]) <= 1.0 + 1e-12);
	/* Along the valley (1, 1)/sqrt 2 it is wide, across it narrow. */
	assert_true(cov[0][0] + cov[1][1] + 2.0 * cov[0][1] > 10.0 * (cov[0][0] + cov[1][1] - 2.0 * cov[0][1]));
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_cmaes_finds_a_narrow_turned_valley),
		cmocka_unit_test(test_cmaes_same_seed_same_answer),
		cmocka_unit_test(test_cmaes_nan_is_the_worst),
		cmocka_unit_test(test_cmaes_hands_on_its_covariance),
	};

	return SUPPORT_RUN(tests, argc, argv);
}
