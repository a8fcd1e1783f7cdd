/* The camera fit's search, private to the fit's files: candidates scored
 * in batches on the job's threads (fit_batch.c), the fine search by
 * Gauss-Newton (fit_gn.c) and the floor's aliases (fit_alias.c), which
 * fit.c's stages run. */
#ifndef RT_GRADE_FIT_SEARCH_H
#define RT_GRADE_FIT_SEARCH_H

#include <stdbool.h>

#include "grade/fit.h"

#define FIT_MAX_THREADS 64

/* A pass given the plain pass's levels (struct grade_fit) as its bound
 * stops on the first level from this one on where its best is farther:
 * the levels are the submission's, so the scores compare, and a mistake
 * that explains the image beats the plain reference there already.  On
 * images nothing explains, such passes were a third of compare's time. */
#define FIT_GUARD_FIRST_STAGE 1

/* A level's candidates scored on the job's threads, each with its own
 * scratch; optionally each candidate's cells and points kept. */
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

int fit_batch_open(struct fit_batch *b, const struct fit_level *l, const struct grade_job *job,
		   const struct camera_params *base, struct diag *d);
/* The n points xs (FIT_DIM each) scored into fs (INFINITY: no camera). */
void fit_batch_run(void *ctx, const double *xs, double *fs, int n);
void fit_batch_close(struct fit_batch *b);

/* The steps of the local moves for the Jacobians at a level of pixel_deg
 * degrees a cell: about a third of a cell. */
void fit_move_steps(const double *v, double pivot, double pixel_deg, double *h);
/* Gauss-Newton with Levenberg-Marquardt's damping from x (moved to the
 * result) on the batch's level, for at most iterations; *pivot_out gets
 * the distance to the middle of what x sees.  Returns the score at x;
 * *rc < 0 on failure (out of memory). */
double fit_gn(struct fit_batch *b, double *x, double pixel_deg, double *pivot_out, int iterations,
	      long *evals, struct diag *d, int *rc);

/* x and its floor's aliases (as they are, and turned to keep the scene's
 * middle in view) scored on the level: the best n_out into out and fout,
 * x itself first; returns how many. */
int fit_floor_aliases(struct fit_batch *b, const double *x, double out[][FIT_DIM], double *fout,
		      int n_out, long *evals);
/* x's aliases within two cells, as they are (and, for a cause's floor,
 * one cell along x or y); x moves to the best when it is better than *fx.
 * True when it moved. */
bool fit_final_alias(struct fit_batch *b, double *x, double *fx, long *evals);
/* x or one of its eyes a cell along x or y (as they are), the best on the
 * level, into x: where a refit with a cause's floor (the tiles swapped)
 * starts, since the plain fit of such an image ends on that alias. */
void fit_odd_alias(struct fit_batch *b, double *x, long *evals);

/* The passes from the starts with the variant's colours (NULL: the
 * reference's): the first and, unless it settled, a second from where it
 * ended and the dolly line; abandoned (score INFINITY) on the first level
 * farther than bound's (NULL: never); the first look as far as reach
 * says. */
int fit_passes(const struct grade_job *job, const struct camera_params *starts, int n_starts,
	       const struct image *sub, const struct grade_variant *variant, enum fit_reach reach,
	       const double *bound, struct grade_fit *out, struct diag *d);
/* The first pass with the variant up to the guard's first level (the
 * coarse search, stage 0 and the aliases of stage 1): its best score
 * there (level FIT_GUARD_FIRST_STAGE) into *score, a cheap look at a
 * variant before a whole pass. */
int fit_screen(const struct grade_job *job, const struct camera_params *starts, int n_starts,
	       const struct image *sub, const struct grade_variant *variant, double *score,
	       struct diag *d);
/* The camera in out refined on the image's own pixels (the polish),
 * unless its last level is already within a small fraction of a cell;
 * out's scores stay the last stage's. */
int fit_polish(const struct grade_job *job, const struct camera_params *start,
	       const struct image *sub, const struct grade_variant *variant, struct grade_fit *out,
	       struct diag *d);
/* Keeps the later fit `again` in out when it ran and scores lower on the
 * last level (out's levels, the plain pass's, stay); true when it did. */
bool fit_keep_better(struct grade_fit *out, struct grade_fit *again);

/* The floor's shape fitted with the camera, when no camera comes near
 * with the scene's floor (out's score): widths, then cells at the best
 * width.  A shape that comes nearer goes into out (its causes in cause
 * and also) and its variant into *shape; returns 1 then, 0 when none did,
 * < 0 on failure. */
int fit_floor_shape(const struct grade_job *job, const struct camera_params *starts,
		    int n_starts, const struct image *sub, struct grade_fit *out,
		    struct grade_variant *shape, struct diag *d);

#endif
