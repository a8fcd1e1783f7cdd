/* CMA-ES, the covariance matrix adaptation evolution strategy (Hansen,
 * "The CMA Evolution Strategy: A Tutorial", 2016), for the camera fit:
 * a derivative-free minimiser for a few dimensions that learns the
 * valleys of its function (an eye further back looks like a narrower
 * field of view).  Deterministic for a seed; allocates nothing. */
#ifndef RT_GRADE_CMAES_H
#define RT_GRADE_CMAES_H

#include <stdint.h>

#define CMAES_MAX_DIM 8
#define CMAES_MAX_LAMBDA 32

/* f's values at n points, point i at xs[i * dim .. i * dim + dim): the
 * caller may evaluate them on several threads. */
typedef void cmaes_batch_fn(void *ctx, const double *xs, double *fs, int n);

struct cmaes_options {
	int dim;		/* 1 .. CMAES_MAX_DIM */
	int lambda;		/* points a generation, 4 .. CMAES_MAX_LAMBDA */
	int generations;	/* at most */
	double sigma;		/* the first step, in units of scale */
	double sigma_stop;	/* stop when the steps fall below this (units of scale) */
	uint64_t seed;
	/* In and out, when not NULL: the covariance to start from (NULL: the
	 * identity) and the one learnt, and the last step's size, so that a
	 * search can go on where another stopped (on a sharper image). */
	double (*cov)[CMAES_MAX_DIM];
	double *sigma_out;
};

/* Minimises f from the mean x (in: the start; out: the best point seen),
 * each coordinate measured in units of scale[i].  Returns f at the best
 * point, and the evaluations made in *evals when evals is not NULL. */
double cmaes_minimise(const struct cmaes_options *o, double *x, const double *scale,
		      cmaes_batch_fn *f, void *ctx, long *evals);

#endif
