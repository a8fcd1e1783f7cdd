/* The camera fit: the camera that took a submission, found by rendering
 * candidates and comparing them with it (analysis by synthesis), coarse
 * to fine: CMA-ES on a heavily blurred image of a few hundred cells from
 * the given cameras, then on sharper and larger levels. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/alloc.h"
#include "base/thread.h"
#include "grade/cmaes.h"
#include "grade/fit.h"
#include "scene/scene_impl.h"

#define FIT_MAX_THREADS 64
#define FIT_COARSE_KEEP 32

struct fit_batch {
	const struct fit_level *level;
	const struct grade_job *job;
	const struct camera_params *base;
	const double *xs;
	double *fs;
	float *cells_out;		/* NULL, or each point's cells, 3 n_cells a point */
	double *points_out;		/* NULL, or each point's cells' points, 4 n_cells a point */
	int n, next;
	struct fit_scratch scratch[FIT_MAX_THREADS];
	int next_thread;
};

static void *fit_batch_worker(void *arg)
{
	struct fit_batch *b = arg;
	int t = __atomic_fetch_add(&b->next_thread, 1, __ATOMIC_RELAXED), i;

	while (!(b->job->cancel && *b->job->cancel) &&
	       (i = __atomic_fetch_add(&b->next, 1, __ATOMIC_RELAXED)) < b->n) {
		b->fs[i] = fit_level_score(b->level, b->job, b->base, b->xs + (size_t)i * FIT_DIM,
					   &b->scratch[t]);
		if (b->cells_out)
			memcpy(b->cells_out + (size_t)i * 3 * (size_t)b->level->n_cells, b->scratch[t].cells,
			       sizeof(float) * 3 * (size_t)b->level->n_cells);
		if (b->points_out && b->scratch[t].points)
			memcpy(b->points_out + (size_t)i * 4 * (size_t)b->level->n_cells, b->scratch[t].points,
			       sizeof(double) * 4 * (size_t)b->level->n_cells);
	}
	return NULL;
}

/* cmaes_batch_fn: the points scored on the job's threads. */
static void fit_batch_run(void *ctx, const double *xs, double *fs, int n)
{
	struct fit_batch *b = ctx;
	pthread_t threads[FIT_MAX_THREADS];
	int nt = b->job->threads < 1 ? 1 : b->job->threads, started = 0, i;

	nt = nt > n ? n : nt;
	nt = nt > FIT_MAX_THREADS ? FIT_MAX_THREADS : nt;
	b->xs = xs;
	b->fs = fs;
	b->n = n;
	b->next = 0;
	b->next_thread = 0;
	for (i = 0; i < n; i++)
		fs[i] = INFINITY;
	for (i = 1; i < nt; i++) {
		if (rt_thread_start(&threads[i], fit_batch_worker, b) != 0)
			break;
		started++;
	}
	fit_batch_worker(b);
	for (i = 1; i <= started; i++)
		pthread_join(threads[i], NULL);
}

static int fit_batch_open(struct fit_batch *b, const struct fit_level *l,
			  const struct grade_job *job, const struct camera_params *base,
			  struct diag *d)
{
	int nt = job->threads < 1 ? 1 : job->threads > FIT_MAX_THREADS ? FIT_MAX_THREADS : job->threads;
	int i, rc;

	memset(b, 0, sizeof(*b));
	b->level = l;
	b->job = job;
	b->base = base;
	for (i = 0; i < nt; i++)
		if ((rc = fit_scratch_alloc(&b->scratch[i], l, d)) < 0)
			return rc;
	return 0;
}

static void fit_batch_close(struct fit_batch *b)
{
	int i;

	for (i = 0; i < FIT_MAX_THREADS; i++)
		fit_scratch_free(&b->scratch[i]);
}

/* The levels, coarse to fine: grids searched by CMA-ES (the first from
 * the coarse search's cameras), then patches at the image's edges
 * refined by Levenberg-Marquardt. */
struct fit_stage {
	bool patches;
	bool lm;		/* grid refined by Levenberg-Marquardt, not CMA-ES */
	int cells;		/* grid: across the wider side; patches: how many */
	int ss;			/* grid: samples a cell's side */
	double sigma;		/* grid: blur in cells; patches: in 1/1000 of the wider side */
	double step;		/* CMA-ES's largest first step, in fit_scale units */
	int generations;	/* CMA-ES's; LM's iterations */
};

static const struct fit_stage fit_stages[] = {
	{ false, false, 32, 2, 3.0, 1.0, 60 },
	{ false, true, 48, 2, 2.4, 0.3, 10 },
	{ false, true, 64, 2, 1.6, 0.15, 10 },
	{ false, true, 96, 1, 1.6, 0.1, 10 },
	{ false, true, 128, 1, 1.2, 0.07, 8 },
	{ false, true, 192, 1, 1.0, 0.0, 6 },
	{ false, true, 256, 1, 0.8, 0.0, 6 },
};

static double fit_clock(void)
{
	struct timespec t;

	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double fit_env(const char *name, double def)
{
	const char *s = getenv(name);

	return s && *s ? atof(s) : def;
}

/* The steps of the local moves (fit_view_move) for the Jacobians at
 * level of pixel_deg degrees a cell: about a third of a cell. */
static void fit_move_steps(const double *v, double pivot, double pixel_deg, double *h)
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

#define FIT_LM_TRIALS 6

/* Gauss-Newton with Levenberg-Marquardt's damping on a grid level, the
 * Jacobian from the render's own gradient and the flow of its points
 * (fit_level_jacobian: no extra renders); each iteration tries
 * FIT_LM_TRIALS dampings at once and goes on from the best, whose render
 * gives the next Jacobian.  Returns the score at x, which it moves. */
static double fit_gn(struct fit_batch *b, double *x, double pixel_deg, double *pivot_out,
		     int iterations, long *evals, struct diag *d, int *rc)
{
	const struct fit_level *l = b->level;
	const size_t n = 3 * (size_t)l->n_cells;
	double xs[FIT_LM_TRIALS * FIT_DIM], fs[FIT_LM_TRIALS], cost, lambda = 1e-2;
	float *cells = rt_reallocarray(NULL, n * FIT_LM_TRIALS, sizeof(float));
	double *points = rt_reallocarray(NULL, 4 * (size_t)l->n_cells * FIT_LM_TRIALS, sizeof(double));
	float *jac = rt_reallocarray(NULL, n * FIT_DIM, sizeof(float));
	struct fit_scratch cur;
	double h[FIT_DIM], pivot = *pivot_out, fd_scale = fit_env("FIT_FD_SCALE", 3.0);
	int it, i, j, k, fd_every = (int)fit_env("FIT_FD_EVERY", 0);
	float *fd_cells = fd_every > 0 ? rt_reallocarray(NULL, n * FIT_DIM, sizeof(float)) : NULL;
	size_t q2;

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

		if (fd_every > 0 && it % fd_every == 0) {
			/* The Jacobian by forward differences of steps fd_scale h:
			 * what the image's gradient misses (reflections move
			 * otherwise than the surfaces they are seen in). */
			double ps[FIT_DIM * FIT_DIM], pf[FIT_DIM];
			for (k = 0; k < FIT_DIM; k++) {
				double q[FIT_DIM] = { 0 };
				q[k] = h[k] * fd_scale;
				fit_view_move(x, q, pivot, ps + k * FIT_DIM);
			}
			b->cells_out = fd_cells;
			b->points_out = NULL;
			fit_batch_run(b, ps, pf, FIT_DIM);
			b->cells_out = cells;
			b->points_out = points;
			*evals += FIT_DIM;
			for (k = 0; k < FIT_DIM; k++)
				for (q2 = 0; q2 < n; q2++)
					jac[(size_t)k * n + q2] = pf[k] < INFINITY ? (float)((fd_cells[(size_t)k * n + q2] - cells[q2]) / (h[k] * fd_scale)) : 0.0f;
		} else {
			fit_level_jacobian(l, b->job, b->base, x, h, pivot, &cur, jac);
		}
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
		if (getenv("FIT_DEBUGJ") && it == 0) {
			double sw = 0.0;
			for (q = 0; q < n; q++)
				sw += l->weight ? l->weight[q / 3] : 1.0;
			for (k = 0; k < FIT_DIM; k++) {
				double pp[2 * FIT_DIM], pf2[2], qv[FIT_DIM] = { 0 }, t = fit_env("FIT_DEBUGJ", 3.0);
				qv[k] = h[k] * t;
				fit_view_move(x, qv, pivot, pp);
				qv[k] = -h[k] * t;
				fit_view_move(x, qv, pivot, pp + FIT_DIM);
				b->cells_out = NULL;
				b->points_out = NULL;
				fit_batch_run(b, pp, pf2, 2);
				fprintf(stderr, "  d%d: analytic %.4g  fd %.4g   (f+ %.3f f- %.3f f0 %.3f)\n", k, 2.0 * g[k] / sw,
					(pf2[0] - pf2[1]) / (2.0 * h[k] * t), pf2[0], pf2[1], cost);
			}
			b->cells_out = cells;
			b->points_out = points;
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
		if (getenv("FIT_TRACE"))
			fprintf(stderr, "  gn %d: %.3f -> %.3f (trial %d)\n", it, cost, fs[best], best);
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
	rt_free(fd_cells);
	return cost;
}

/* The hypotheses the first stages carry: the stage-0 refinements of the
 * best starting cameras, each refined on the next levels until the one
 * that fits best there is clear. */
#define FIT_HYPOTHESES 5
#define FIT_HYPOTHESIS_STAGES 3
/* ... and the best two of them on, through the sharper levels up to this
 * stage: a view from another side (the checkerboard turned a right angle)
 * can look as near as the right one while the image is still blurred. */
#define FIT_PAIR_STAGES 5
/* The hypotheses whose floor aliases are tried. */
#define FIT_ALIAS_HYPOTHESES 3

/* A pattern search in the local moves (nearly independent, so one at a
 * time will do): each iteration scores x moved by +-step along each
 * move, puts a parabola through each triple and tries the sum of the
 * parabolas' minima too; the steps halve when nothing improves.  For the
 * last levels, where the score near the truth is a narrow valley that
 * the Jacobian's linear model misjudges. */
static double fit_polish(struct fit_batch *b, double *x, double pivot, const double *h0,
			 double f0, int iterations, double shrink_to, long *evals)
{
	double step[FIT_DIM], xs[(2 * FIT_DIM + 4) * FIT_DIM], fs[2 * FIT_DIM + 4], dir[FIT_DIM] = { 0 };
	int it, k, halvings = 0, n_pts;
	bool have_dir = false;

	memcpy(step, h0, sizeof(step));
	if (!(f0 < INFINITY)) {
		fit_batch_run(b, x, &f0, 1);
		*evals += 1;
	}
	for (it = 0; it < iterations; it++) {
		double q[FIT_DIM] = { 0 }, fbest = f0;
		int best = -1;

		for (k = 0; k < FIT_DIM; k++) {
			double m[FIT_DIM] = { 0 };
			m[k] = step[k];
			fit_view_move(x, m, pivot, xs + (2 * k) * FIT_DIM);
			m[k] = -step[k];
			fit_view_move(x, m, pivot, xs + (2 * k + 1) * FIT_DIM);
		}
		fit_batch_run(b, xs, fs, 2 * FIT_DIM);
		*evals += 2 * FIT_DIM;
		for (k = 0; k < FIT_DIM; k++) {
			double fp = fs[2 * k], fm = fs[2 * k + 1], a = 0.5 * (fp + fm) - f0, c = 0.5 * (fp - fm), t;
			if (fp < INFINITY && fm < INFINITY && a > 0.0)
				t = -c / (2.0 * a);
			else
				t = fp < fm ? 1.0 : -1.0;
			t = t > 1.0 ? 1.0 : t < -1.0 ? -1.0 : t;
			q[k] = t * step[k];
		}
		fit_view_move(x, q, pivot, xs + 2 * FIT_DIM * FIT_DIM);
		n_pts = 2 * FIT_DIM + 1;
		/* Along the last iteration's move, 1, 2 and 4 times it: the
		 * valley's own direction, which steps along the moves only zigzag
		 * down (Powell's idea). */
		if (have_dir)
			for (k = 0; k < 3; k++, n_pts++)
				for (int i = 0; i < FIT_DIM; i++)
					xs[n_pts * FIT_DIM + i] = x[i] + (double)(1 << k) * dir[i];
		fit_batch_run(b, xs + 2 * FIT_DIM * FIT_DIM, fs + 2 * FIT_DIM, n_pts - 2 * FIT_DIM);
		*evals += n_pts - 2 * FIT_DIM;
		for (k = 0; k < n_pts; k++)
			if (fs[k] < fbest) {
				fbest = fs[k];
				best = k;
			}
		if (getenv("FIT_TRACE"))
			fprintf(stderr, "  polish %d: %.3f -> %.3f (%d)\n", it, f0, fbest, best);
		if (best < 0) {
			for (k = 0; k < FIT_DIM; k++)
				step[k] *= 0.5;
			have_dir = false;
			if (++halvings > shrink_to)
				break;
			continue;
		}
		for (k = 0; k < FIT_DIM; k++)
			dir[k] = xs[best * FIT_DIM + k] - x[k];
		have_dir = true;
		memcpy(x, xs + best * FIT_DIM, sizeof(double) * FIT_DIM);
		f0 = fbest;
	}
	return f0;
}

/* CMA-ES in the local moves about x (each in units of h): learns the
 * narrow valley of the last levels, where neither the linear model nor
 * steps along the moves get far. */
struct fit_local {
	struct fit_batch *b;
	const double *x0;
	double pivot;
};

static void fit_local_batch(void *ctx, const double *qs, double *fs, int n)
{
	struct fit_local *lc = ctx;
	double xs[CMAES_MAX_LAMBDA * FIT_DIM];
	int i;

	for (i = 0; i < n; i++)
		fit_view_move(lc->x0, qs + i * FIT_DIM, lc->pivot, xs + i * FIT_DIM);
	fit_batch_run(lc->b, xs, fs, n);
}

static double fit_local_cmaes(struct fit_batch *b, double *x, double pivot, const double *h,
			      double f0, int generations, uint64_t seed, long *evals)
{
	struct fit_local lc = { b, NULL, pivot };
	struct cmaes_options o;
	double x0[FIT_DIM], q[FIT_DIM] = { 0 }, f;
	long ev = 0;

	memcpy(x0, x, sizeof(x0));
	lc.x0 = x0;
	memset(&o, 0, sizeof(o));
	o.dim = FIT_DIM;
	o.lambda = (int)fit_env("FIT_CMA_LAMBDA", 10);
	o.generations = generations;
	o.sigma = fit_env("FIT_CMA_SIGMA", 1.0);
	o.sigma_stop = 0.02;
	o.seed = seed;
	f = cmaes_minimise(&o, q, h, fit_local_batch, &lc, &ev);
	*evals += ev;
	if (f < f0) {
		fit_view_move(x0, q, pivot, x);
		return f;
	}
	return f0;
}

/* The middle of the scene's objects (the floor and unbounded shapes
 * aside): the point the alias moves keep in view. */
struct vec3 fit_scene_centre(const struct scene *s)
{
	struct vec3 sum = vec3_make(0.0, 0.0, 0.0);
	size_t i, n = 0;

	for (i = 0; i < s->n_shapes; i++) {
		struct aabb box;
		if (s->shapes[i] == s->floor || !shape_bounds(s->shapes[i], &box) ||
		    !vec3_is_finite(box.min) || !vec3_is_finite(box.max))
			continue;
		sum = vec3_add(sum, vec3_scale(vec3_add(box.min, box.max), 0.5));
		n++;
	}
	return n ? vec3_scale(sum, 1.0 / (double)n) : sum;
}

/* The checkerboard looks the same from eyes a whole diagonal cell apart
 * (white where i + j is even): the blurred levels cannot tell them apart
 * by the floor, only by the objects, which are small.  So each such
 * neighbour of x, up to FIT_ALIAS_REACH cells each way along both
 * diagonals, is scored, turned to keep the scene's middle where x sees
 * it and zoomed to keep its size, and x moves to the best. */
#define FIT_ALIAS_REACH 4

static int fit_floor_aliases(struct fit_batch *b, const double *x, double out[][FIT_DIM],
			     double *fout, int n_out, long *evals)
{
	const struct scene_view *v = scene_view_of(b->job->scene);
	enum { N = 2 * (2 * FIT_ALIAS_REACH + 1) * (2 * FIT_ALIAS_REACH + 1) };
	double xs[N * FIT_DIM], fs[N], c = v->floor_cell, dist0;
	struct vec3 eye0;
	struct camera_params base, p;
	struct vec3 centre, f0;
	int i, j, n = 0, k, m, best = -1;

	if (!scene_has_floor(b->job->scene) || !(c > 0.0) || !isfinite(c))
		return 0;
	memset(&base, 0, sizeof(base));
	fit_params_of(x, &base, &p);
	eye0 = p.eye;
	centre = fit_scene_centre(b->job->scene);
	f0 = vec3_normalize(vec3_sub(p.look, p.eye));
	dist0 = vec3_dot(vec3_sub(centre, eye0), f0);
	for (i = -FIT_ALIAS_REACH; i <= FIT_ALIAS_REACH; i++)
		for (j = -FIT_ALIAS_REACH; j <= FIT_ALIAS_REACH; j++) {
			struct camera_params q = p;
			struct vec3 shift = vec3_make(c * (i + j), c * (i - j), 0.0), f;
			double dist;
			if (i == 0 && j == 0)
				best = n;
			q.eye = vec3_add(p.eye, shift);
			/* As it is, which keeps the floor where it was; and turned
			 * to the scene, which keeps the objects. */
			q.look = vec3_add(q.eye, f0);
			fit_view_of(&q, xs + n * FIT_DIM);
			n++;
			if (i == 0 && j == 0)
				continue;
			/* The ray to the centre turns as much as the eye moved
			 * round it; the field scales with its distance along
			 * the view. */
			f = vec3_normalize(vec3_sub(vec3_add_scaled(eye0, f0, dist0 > 1.0 ? dist0 : 1.0), q.eye));
			q.look = vec3_add(q.eye, f);
			dist = vec3_dot(vec3_sub(centre, q.eye), f);
			if (dist0 > 1.0 && dist > 1.0)
				q.fov_deg = 2.0 * atan(tan(p.fov_deg * 3.14159265358979323846 / 360.0) * dist0 / dist) *
					    360.0 / (2.0 * 3.14159265358979323846);
			fit_view_of(&q, xs + n * FIT_DIM);
			n++;
		}
	fit_batch_run(b, xs, fs, n);
	*evals += n;
	/* The best n_out, x itself among them whatever its place (the
	 * blurred level may not yet tell x from its aliases). */
	memcpy(out[0], xs + best * FIT_DIM, sizeof(double) * FIT_DIM);
	fout[0] = fs[best];
	fs[best] = INFINITY;
	for (m = 1; m < n_out; m++) {
		int pick = -1;
		for (k = 0; k < n; k++)
			if (fs[k] < INFINITY && (pick < 0 || fs[k] < fs[pick]))
				pick = k;
		if (pick < 0)
			break;
		memcpy(out[m], xs + pick * FIT_DIM, sizeof(double) * FIT_DIM);
		fout[m] = fs[pick];
		fs[pick] = INFINITY;
	}
	return m;
}

/* Once the camera is sharp, the floor's aliases once more, as they are
 * (the same direction and field of view): an eye two cells off along the
 * view is what the blurred levels could not tell apart, and the sharp one
 * can by the objects.  True when x moved (to a better alias). */
#define FIT_LAST_ALIAS_STAGE 4

static bool fit_final_alias(struct fit_batch *b, double *x, double *fx, long *evals)
{
	static const int odd[4][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } };
	const struct scene_view *v = scene_view_of(b->job->scene);
	double xs[28 * FIT_DIM], fs[28], c = v->floor_cell;
	int i, j, n = 0, k, best = -1;

	if (!scene_has_floor(b->job->scene) || !(c > 0.0) || !isfinite(c))
		return false;
	for (i = -2; i <= 2; i++)
		for (j = -2; j <= 2; j++) {
			if (i == 0 && j == 0)
				continue;
			memcpy(xs + n * FIT_DIM, x, sizeof(double) * FIT_DIM);
			xs[n * FIT_DIM + FIT_X] += c * (i + j);
			xs[n * FIT_DIM + FIT_Y] += c * (i - j);
			n++;
		}
	/* A cause's floor (the tiles swapped) may fit a cell off the plain
	 * one's: the eye one cell along x or y, which swaps the tiles. */
	for (k = 0; b->level->variant && k < 4; k++) {
		memcpy(xs + n * FIT_DIM, x, sizeof(double) * FIT_DIM);
		xs[n * FIT_DIM + FIT_X] += c * odd[k][0];
		xs[n * FIT_DIM + FIT_Y] += c * odd[k][1];
		n++;
	}
	fit_batch_run(b, xs, fs, n);
	*evals += n;
	for (k = 0; k < n; k++)
		if (fs[k] < *fx && (best < 0 || fs[k] < fs[best]))
			best = k;
	if (best < 0)
		return false;
	memcpy(x, xs + best * FIT_DIM, sizeof(double) * FIT_DIM);
	*fx = fs[best];
	return true;
}

/* Stage 0: the starts and the coarse search's cameras scored on the
 * level, Gauss-Newton from the best few, the FIT_HYPOTHESES best results
 * into hyp (best first; scores in hf, INFINITY past the last). */
static int fit_first_stage(struct fit_batch *b, const struct camera_params *starts, int n_starts,
			   const struct image *sub, double hyp[FIT_HYPOTHESES][FIT_DIM],
			   double *hf, long *evals, struct diag *d)
{
	double xs[(8 + FIT_COARSE_KEEP) * FIT_DIM], fs[8 + FIT_COARSE_KEEP], cs[FIT_COARSE_KEEP];
	int n = n_starts > 8 ? 8 : n_starts, tries = (int)fit_env("FIT_TRIES", 6), t, k, rc;

	for (k = 0; k < FIT_HYPOTHESES; k++)
		hf[k] = INFINITY;
	for (k = 0; k < n; k++)
		fit_view_of(&starts[k], xs + k * FIT_DIM);
	if ((rc = fit_coarse_search(b->job, &starts[0], sub, fit_env("FIT_RADIUS", 160),
				    fit_env("FIT_SPACING", 40), fit_scene_centre(b->job->scene),
				    (double (*)[FIT_DIM])(xs + n * FIT_DIM), cs, FIT_COARSE_KEEP, d)) < 0)
		return rc;
	n += FIT_COARSE_KEEP;
	fit_batch_run(b, xs, fs, n);
	*evals += n;
	if (getenv("FIT_TRACE"))
		for (k = 0; k < n; k++)
			fprintf(stderr, "fit: candidate %d: %.2f  %.1f %.1f %.1f  %.2f %.2f %.2f %.2f\n", k, fs[k],
				xs[k * FIT_DIM], xs[k * FIT_DIM + 1], xs[k * FIT_DIM + 2], xs[k * FIT_DIM + 3],
				xs[k * FIT_DIM + 4], xs[k * FIT_DIM + 5], xs[k * FIT_DIM + 6]);
	for (t = 0; t < tries; t++) {
		double x[FIT_DIM], f, pivot = 100.0;
		int pick = -1, i;
		long ev = 0;

		for (k = 0; k < n; k++)
			if (fs[k] < INFINITY && (pick < 0 || fs[k] < fs[pick]))
				pick = k;
		if (pick < 0)
			break;
		memcpy(x, xs + pick * FIT_DIM, sizeof(x));
		fs[pick] = INFINITY;
		f = fit_gn(b, x, x[FIT_FOV] / 32.0, &pivot, (int)fit_env("FIT_S0_GN", 10), &ev, d, &rc);
		*evals += ev;
		if (rc < 0)
			return rc;
		if (getenv("FIT_TRACE"))
			fprintf(stderr, "fit: try %d from %d: %.3f  %.1f %.1f %.1f  %.2f %.2f %.2f %.2f\n", t, pick, f,
				x[0], x[1], x[2], x[3], x[4], x[5], x[6]);
		for (k = 0; k < FIT_HYPOTHESES; k++)
			if (f < hf[k]) {
				for (i = FIT_HYPOTHESES - 1; i > k; i--) {
					hf[i] = hf[i - 1];
					memcpy(hyp[i], hyp[i - 1], sizeof(hyp[i]));
				}
				hf[k] = f;
				memcpy(hyp[k], x, sizeof(hyp[k]));
				break;
			}
	}
	return 0;
}

/* The level of stage st for an image of sub's size, and its cells' angle
 * at field of view fov. */
static int fit_stage_level(const struct fit_stage *st, const struct image *sub, double fov,
			   struct fit_level *level, double *pixel_deg, struct diag *d)
{
	int w, h;

	w = sub->width >= sub->height ? st->cells : (int)lround((double)st->cells * sub->width / sub->height);
	h = sub->height >= sub->width ? st->cells : (int)lround((double)st->cells * sub->height / sub->width);
	w = w < 1 ? 1 : w > sub->width ? sub->width : w;
	h = h < 1 ? 1 : h > sub->height ? sub->height : h;
	*pixel_deg = fov / h;
	return fit_level_grid(level, sub, w, h, st->ss, st->sigma, d);
}

/* The fit from stage `first` on: from the starts' coarse search (first
 * 0), or refined from starts[0] alone; the variant's colours (NULL: the
 * reference's) fitted. */
static int fit_run(const struct grade_job *job, const struct camera_params *starts, int n_starts,
		   const struct image *sub, const struct grade_variant *variant, int first,
		   struct grade_fit *out, struct diag *d)
{
	const int n_stages = (int)(sizeof(fit_stages) / sizeof(fit_stages[0]));
	const int wide = sub->width > sub->height ? sub->width : sub->height;
	double hyp[FIT_HYPOTHESES][FIT_DIM], hf[FIT_HYPOTHESES], pivot[FIT_HYPOTHESES];
	double t_start = fit_clock(), prev_sigma = INFINITY;
	int s, k, n_hyp = 1, rc = 0, eff, prev_cells = 0;

	memset(out, 0, sizeof(*out));
	out->camera = starts[0];
	for (k = 0; k < FIT_HYPOTHESES; k++)
		pivot[k] = 100.0;
	fit_view_of(&starts[0], hyp[0]);
	for (s = first; s < n_stages && s < (int)fit_env("FIT_STAGES", 99); s++) {
		const struct fit_stage *st = &fit_stages[s];
		struct fit_level level;
		struct fit_batch batch;
		double pixel_deg;
		long evals = 0;

		/* A small image's levels stop at its pixels: then only their
		 * blur goes on shrinking. */
		eff = st->cells < wide ? st->cells : wide;
		if (s > first && eff == prev_cells && !(st->sigma < prev_sigma))
			continue;
		prev_cells = eff;
		prev_sigma = st->sigma;
		if ((rc = fit_stage_level(st, sub, hyp[0][FIT_FOV], &level, &pixel_deg, d)) < 0)
			return rc;
		level.variant = variant;

		if ((rc = fit_batch_open(&batch, &level, job, &starts[0], d)) < 0) {
			fit_level_free(&level);
			return rc;
		}
		if (s == 0 && getenv("FIT_START")) {
			sscanf(getenv("FIT_START"), "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &hyp[0][0], &hyp[0][1], &hyp[0][2],
			       &hyp[0][3], &hyp[0][4], &hyp[0][5], &hyp[0][6]);
			n_hyp = 1;
			s = (int)fit_env("FIT_FROM", 3) - 1;
		} else if (s == 0) {
			rc = fit_first_stage(&batch, starts, n_starts, sub, hyp, hf, &evals, d);
			for (n_hyp = 0; n_hyp < FIT_HYPOTHESES && hf[n_hyp] < INFINITY; n_hyp++)
				;
		} else {
			if (s == 1 && n_hyp > 0) {
				/* Each of the best hypotheses and its two best
				 * aliases, scored on this level, go on: the best
				 * FIT_HYPOTHESES of them. */
				double more[FIT_ALIAS_HYPOTHESES * 3][FIT_DIM], mf[FIT_ALIAS_HYPOTHESES * 3];
				int nm = 0, a, t;
				for (k = 0; k < n_hyp && k < FIT_ALIAS_HYPOTHESES; k++)
					nm += fit_floor_aliases(&batch, hyp[k], more + nm, mf + nm, 3, &evals);
				if (nm > 0) {
					n_hyp = 0;
					for (a = 0; a < nm; a++) {
						for (t = 0; t < n_hyp && hf[t] <= mf[a]; t++)
							;
						if (t >= FIT_HYPOTHESES)
							continue;
						if (n_hyp < FIT_HYPOTHESES)
							n_hyp++;
						memmove(hyp + t + 1, hyp + t, sizeof(hyp[0]) * (size_t)(n_hyp - 1 - t));
						memmove(hf + t + 1, hf + t, sizeof(hf[0]) * (size_t)(n_hyp - 1 - t));
						memcpy(hyp[t], more[a], sizeof(hyp[t]));
						hf[t] = mf[a];
					}
					for (t = 0; t < n_hyp; t++)
						pivot[t] = 100.0;
				}
			}
			for (k = 0; k < n_hyp && rc == 0; k++) {
				hf[k] = fit_gn(&batch, hyp[k], hyp[k][FIT_FOV] / level.h, &pivot[k],
					       st->generations, &evals, d, &rc);
				if (rc == 0 && s == FIT_LAST_ALIAS_STAGE &&
				    fit_final_alias(&batch, hyp[k], &hf[k], &evals))
					hf[k] = fit_gn(&batch, hyp[k], hyp[k][FIT_FOV] / level.h, &pivot[k],
						       st->generations, &evals, d, &rc);
				if (rc == 0 && s >= (int)fit_env("FIT_CMA_FROM", 99)) {
					double h0[FIT_DIM];
					fit_move_steps(hyp[k], pivot[k], hyp[k][FIT_FOV] / level.h, h0);
					hf[k] = fit_local_cmaes(&batch, hyp[k], pivot[k], h0, hf[k],
								(int)fit_env("FIT_CMA_GENS", 25), 0x5eed0200u + (uint64_t)s, &evals);
				}
				if (rc == 0 && s >= (int)fit_env("FIT_POLISH_FROM", 99)) {
					double h0[FIT_DIM];
					fit_move_steps(hyp[k], pivot[k], hyp[k][FIT_FOV] / level.h, h0);
					for (int k2 = 0; k2 < FIT_DIM; k2++)
						h0[k2] *= fit_env("FIT_POLISH_STEP", 1.5);
					hf[k] = fit_polish(&batch, hyp[k], pivot[k], h0, hf[k],
							   (int)fit_env("FIT_POLISH_ITERS", 12), fit_env("FIT_POLISH_HALVE", 4), &evals);
				}
			}
		}
		/* The best first; past the hypotheses' stages, the best alone. */
		for (k = 1; k < n_hyp; k++)
			if (hf[k] < hf[0]) {
				double t[FIT_DIM], tf = hf[0], tp = pivot[0];
				memcpy(t, hyp[0], sizeof(t));
				memcpy(hyp[0], hyp[k], sizeof(t));
				memcpy(hyp[k], t, sizeof(t));
				hf[0] = hf[k];
				hf[k] = tf;
				pivot[0] = pivot[k];
				pivot[k] = tp;
			}
		if (s + 1 >= FIT_PAIR_STAGES)
			n_hyp = n_hyp > 0 ? 1 : 0;
		else if (s + 1 >= FIT_HYPOTHESIS_STAGES && n_hyp > 2)
			n_hyp = 2;
		out->evals += evals;
		out->score = hf[0];
		{
			/* The given camera on the same level, for the caller to
			 * weigh the fit by (grey: red and blue swapped alike). */
			double v0[FIT_DIM];
			fit_view_of(&starts[0], v0);
			fit_batch_run(&batch, v0, &out->start_score, 1);
		}
		if (getenv("FIT_TRACE"))
			fprintf(stderr, "fit: [%.2fs] stage %d (%d cells): %.3f after %ld evals  %.2f %.2f %.2f  %.3f %.3f %.3f %.3f\n",
				fit_clock() - t_start, s, level.n_cells, hf[0], evals,
				hyp[0][0], hyp[0][1], hyp[0][2], hyp[0][3], hyp[0][4], hyp[0][5], hyp[0][6]);
		fit_batch_close(&batch);
		fit_level_free(&level);
		(void)pixel_deg;
		if (rc < 0)
			return rc;
		if (job->cancel && *job->cancel)
			return diag_fail(d, RT_E_INTERRUPTED, "interrupted");
		if (n_hyp == 0)
			break;
	}
	fit_params_of(hyp[0], &starts[0], &out->camera);
	return 0;
}

/* A second pass (and the refit with a cause) starts on this level:
 * blurred enough to leave the floor's alias a first pass settled on for
 * the true camera a few cells away, sharp enough to stay near. */
#define FIT_REFIT_FIRST_STAGE 2
/* A first pass whose last level is within this mean squared grey
 * difference (a level's rounding is 1/12; 1 is 48 dB) found the camera:
 * no alias looks that much like the image, so no second pass. */
#define FIT_SETTLED_SCORE 1.0

int grade_fit_camera(const struct grade_job *job, const struct camera_params *starts,
		     int n_starts, const struct image *sub, struct grade_fit *out, struct diag *d)
{
	struct grade_fit again;
	int rc = fit_run(job, starts, n_starts, sub, NULL, 0, out, d);

	/* The first pass ends on the floor's alias nearest its coarse
	 * guess; a second from where it ended, with one hypothesis, often
	 * finds the camera that alias hid (the same last level: the scores
	 * compare). */
	if (rc < 0 || out->score <= FIT_SETTLED_SCORE || (int)fit_env("FIT_PASSES", 2) < 2)
		return rc;
	if ((rc = fit_run(job, &out->camera, 1, sub, NULL, FIT_REFIT_FIRST_STAGE, &again, d)) < 0)
		return rc;
	if (again.evals > 0 && again.score < out->score) {
		again.evals += out->evals;
		again.start_score = out->start_score;
		*out = again;
	} else {
		out->evals += again.evals;
	}
	return 0;
}

int grade_fit_camera_with(const struct grade_job *job, const struct camera_params *start,
			  enum grade_cause cause, int form, const struct image *sub,
			  struct grade_fit *out, struct diag *d)
{
	struct grade_variant v;

	/* The fit's levels trace through pixel centres and saturate: a
	 * cause that moves the rays to the corners or wraps the bytes is not
	 * fitted (nor is a transform, which is no render). */
	if (grade_cause_is_transform(cause) || !grade_variant_of(job, cause, form, &v) || v.corner ||
	    v.wrap)
		return diag_fail(d, RT_E_INVALID, "the cause has no such form to fit");
	return fit_run(job, start, 1, sub, &v, FIT_REFIT_FIRST_STAGE, out, d);
}
