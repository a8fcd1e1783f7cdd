/* Candidates scored in batches on the job's threads: each thread takes
 * the next point with an atomic add and scores it on the level with its
 * own scratch, so that a batch's scores do not depend on the number of
 * threads. */
#include <math.h>
#include <string.h>

#include "base/thread.h"
#include "grade/fit_search.h"

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

void fit_batch_run(void *ctx, const double *xs, double *fs, int n)
{
	struct fit_batch *b = ctx;
	int nt = b->job->threads < 1 ? 1 : b->job->threads, i;

	nt = nt > n ? n : nt;
	nt = nt > FIT_MAX_THREADS ? FIT_MAX_THREADS : nt;
	b->xs = xs;
	b->fs = fs;
	b->n = n;
	b->next = 0;
	b->next_thread = 0;
	for (i = 0; i < n; i++)
		fs[i] = INFINITY;
	rt_run_shared(nt, fit_batch_worker, b);
}

int fit_batch_open(struct fit_batch *b, const struct fit_level *l, const struct grade_job *job,
		   const struct camera_params *base, struct diag *d)
{
	int nt = job->threads < 1 ? 1 : job->threads > FIT_MAX_THREADS ? FIT_MAX_THREADS : job->threads;
	int i, rc;

	memset(b, 0, sizeof(*b));
	b->level = l;
	b->job = job;
	b->base = base;
	for (i = 0; i < nt; i++)
		if ((rc = fit_scratch_alloc(&b->scratch[i], l, d)) < 0) {
			/* The threads' scratch allocated so far goes too. */
			fit_batch_close(b);
			return rc;
		}
	return 0;
}

void fit_batch_close(struct fit_batch *b)
{
	int i;

	for (i = 0; i < FIT_MAX_THREADS; i++)
		fit_scratch_free(&b->scratch[i]);
}
