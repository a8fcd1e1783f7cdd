/* The fine search: Gauss-Newton with Levenberg-Marquardt's damping in the
 * local moves of fit_view_move, about the middle of what the camera sees,
 * on one level. */
#include <math.h>
#include <string.h>

#include "base/alloc.h"
#include "grade/fit_search.h"

/* The dampings and step lengths tried at once in each iteration. */
#define FIT_LM_TRIALS 6

/* The steps of the local moves (fit_view_move) for the Jacobians at
 * level of pixel_deg degrees a cell: about a third of a cell. */
void fit_move_steps(const double *v, double pivot, double pixel_deg, double *h)
{
	double hang = 0.35 * pixel_deg, hrad = hang * 3.14159265358979323846 / 180.0;

	(void)v;
	h[FIT_ORBIT_YAW] = h[FIT_ORBIT_PITCH] = hang;
	h[FIT_TURN_ROLL] = 1.5 * hang;
	h[FIT_PAN_X] = h[FIT_PAN_Y] = hrad * pivot;
	h[FIT_DOLLY] = 3.0 * hrad * pivot;
	h[FIT_ZOOM] = hang;
}

/* The distance along the view to the middle of what camera v sees:
 * the median depth of the points (w 1) of a render, else 100. */
static double fit_pivot_of(const double *v, const double *points, int n)
{
	struct camera_params base, p;
	struct vec3 f;
	double depth[512];
	int m = 0, k, step = n / 512 + 1, i, j;

	memset(&base, 0, sizeof(base));
	fit_params_of(v, &base, &p);
	f = vec3_normalize(vec3_sub(p.look, p.eye));
	for (k = 0; k < n && m < 512; k += step)
		if (points[4 * k + 3] != 0.0) {
			double z = vec3_dot(vec3_sub(vec3_make(points[4 * k], points[4 * k + 1], points[4 * k + 2]), p.eye), f);
			if (z > 0.0)
				depth[m++] = z;
		}
	if (m == 0)
		return 100.0;
	for (i = 1; i < m; i++)
		for (j = i; j > 0 && depth[j - 1] > depth[j]; j--) {
			double t = depth[j];
			depth[j] = depth[j - 1];
			depth[j - 1] = t;
		}
	return depth[m / 2] > 1.0 ? depth[m / 2] : 1.0;
}

/* Solves the n x n system a x = b (a symmetric positive definite after
 * damping) by Gaussian elimination with partial pivoting; false when
 * singular. */
static bool fit_solve(int n, double a[FIT_DIM][FIT_DIM + 1], double *x)
{
	int i, j, k;

	for (i = 0; i < n; i++) {
		int p = i;
		for (k = i + 1; k < n; k++)
			if (fabs(a[k][i]) > fabs(a[p][i]))
				p = k;
		if (!(fabs(a[p][i]) > 1e-300))
			return false;
		for (k = 0; k <= n; k++) {
			double t = a[i][k];
			a[i][k] = a[p][k];
			a[p][k] = t;
		}
		for (k = i + 1; k < n; k++) {
			double f = a[k][i] / a[i][i];
			for (j = i; j <= n; j++)
				a[k][j] -= f * a[i][j];
		}
	}
	for (i = n - 1; i >= 0; i--) {
		double s = a[i][n];
		for (j = i + 1; j < n; j++)
			s -= a[i][j] * x[j];
		x[i] = s / a[i][i];
	}
	return true;
}

/* Gauss-Newton with Levenberg-Marquardt's damping on a grid level, the
 * Jacobian from the render's own gradient and the flow of its points
 * (fit_level_jacobian: no extra renders); each iteration tries
 * FIT_LM_TRIALS dampings at once and goes on from the best, whose render
 * gives the next Jacobian.  Returns the score at x, which it moves.
 * Long: an iteration's Jacobian, normal equations, trials and acceptance
 * share the level's buffers and the damping; apart they would pass all of
 * them along. */
double fit_gn(struct fit_batch *b, double *x, double pixel_deg, double *pivot_out, int iterations,
	      long *evals, struct diag *d, int *rc)
{
	const struct fit_level *l = b->level;
	const size_t n = 3 * (size_t)l->n_cells;
	double xs[FIT_LM_TRIALS * FIT_DIM], fs[FIT_LM_TRIALS], cost, lambda = 1e-2;
	float *cells = rt_reallocarray(NULL, n * FIT_LM_TRIALS, sizeof(float));
	double *points = rt_reallocarray(NULL, 4 * (size_t)l->n_cells * FIT_LM_TRIALS, sizeof(double));
	float *jac = rt_reallocarray(NULL, n * FIT_DIM, sizeof(float));
	struct fit_scratch cur;
	double h[FIT_DIM], pivot = *pivot_out;
	int it, i, j, k;

	*rc = 0;
	cur.cells = cells;
	cur.tmp = NULL;
	cur.points = points;
	if (!cells || !points || !jac) {
		*rc = diag_fail(d, RT_E_NOMEM, "out of memory for the camera fit");
		cost = INFINITY;
		goto out;
	}
	for (k = 0; k < b->job->threads && k < FIT_MAX_THREADS; k++)
		if (!b->scratch[k].points && (*rc = fit_scratch_points(&b->scratch[k], l, d)) < 0) {
			cost = INFINITY;
			goto out;
		}
	b->cells_out = cells;
	b->points_out = points;
	fit_batch_run(b, x, fs, 1);
	*evals += 1;
	cost = fs[0];
	if (cost < INFINITY)
		*pivot_out = pivot = fit_pivot_of(x, points, l->n_cells);
	fit_move_steps(x, pivot, pixel_deg, h);
	for (it = 0; it < iterations && cost < INFINITY; it++) {
		double a[FIT_DIM][FIT_DIM + 1], jt_j[FIT_DIM][FIT_DIM], g[FIT_DIM];
		/* Three dampings, and the least damped step at a quarter, half
		 * and twice its length: near the truth the linear model's step
		 * is right in direction more often than in length. */
		double lambdas[FIT_LM_TRIALS] = { lambda * 0.1, lambda, lambda * 10.0, lambda * 0.1,
						  lambda * 0.1, lambda * 0.1 };
		const double lengths[FIT_LM_TRIALS] = { 1.0, 1.0, 1.0, 0.25, 0.5, 2.0 };
		int best = -1;
		size_t q;

		fit_level_jacobian(l, b->job, b->base, x, h, pivot, &cur, jac);
		memset(jt_j, 0, sizeof(jt_j));
		memset(g, 0, sizeof(g));
		for (q = 0; q < n; q++) {
			double wq = l->weight ? l->weight[q / 3] : 1.0, r = wq * (cells[q] - l->target[q]);
			if (wq == 0.0)
				continue;
			for (i = 0; i < FIT_DIM; i++) {
				double ji = jac[(size_t)i * n + q];
				g[i] += ji * r;
				for (j = 0; j <= i; j++)
					jt_j[i][j] += wq * ji * jac[(size_t)j * n + q];
			}
		}
		for (k = 0; k < FIT_LM_TRIALS; k++) {
			double step[FIT_DIM];
			for (i = 0; i < FIT_DIM; i++) {
				for (j = 0; j < FIT_DIM; j++)
					a[i][j] = j <= i ? jt_j[i][j] : jt_j[j][i];
				a[i][i] += lambdas[k] * (jt_j[i][i] > 1e-9 ? jt_j[i][i] : 1e-9);
				a[i][FIT_DIM] = -g[i];
			}
			if (!fit_solve(FIT_DIM, a, step))
				memset(step, 0, sizeof(step));
			for (i = 0; i < FIT_DIM; i++)
				step[i] *= lengths[k];
			fit_view_move(x, step, pivot, xs + k * FIT_DIM);
		}
		fit_batch_run(b, xs, fs, FIT_LM_TRIALS);
		*evals += FIT_LM_TRIALS;
		for (k = 0; k < FIT_LM_TRIALS; k++)
			if (fs[k] < cost && (best < 0 || fs[k] < fs[best]))
				best = k;
		if (best < 0) {
			/* Back to the render at x for the next Jacobian. */
			lambda *= 1000.0;
			if (lambda > 1e6)
				break;
			fit_batch_run(b, x, fs, 1);
			*evals += 1;
			continue;
		}
		memcpy(x, xs + best * FIT_DIM, sizeof(double) * FIT_DIM);
		if (best > 0) {
			memcpy(cells, cells + (size_t)best * n, sizeof(float) * n);
			memcpy(points, points + (size_t)best * 4 * l->n_cells, sizeof(double) * 4 * l->n_cells);
		}
		if (cost - fs[best] < 2e-3 * cost) {
			cost = fs[best];
			break;
		}
		cost = fs[best];
		lambda = lambdas[best];
	}
out:
	b->cells_out = NULL;
	b->points_out = NULL;
	rt_free(cells);
	rt_free(points);
	rt_free(jac);
	return cost;
}
