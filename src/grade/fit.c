/* The camera fit: the camera that took a submission, found by rendering
 * candidates and comparing them with it (analysis by synthesis), coarse
 * to fine: a coarse search of eyes and directions (fit_coarse.c), then
 * Gauss-Newton (fit_gn.c) on sharper and larger levels of the image
 * (fit_level.c), with the floor's aliases tried by name (fit_alias.c).
 * Deterministic: the same answer for any number of threads. */
#include <math.h>
#include <string.h>

#include "grade/fit_search.h"

/* The coarse search: its cameras kept, and the box of eyes about the
 * given one (radius and spacing in scene units). */
#define FIT_COARSE_KEEP 32
#define FIT_COARSE_RADIUS 160.0
#define FIT_COARSE_SPACING 40.0
/* Stage 0 refines the best this many of the starts and coarse cameras. */
#define FIT_FIRST_TRIES 12
/* The stage whose hypotheses get the last look at the floor's aliases
 * (fit_final_alias): the camera is sharp there. */
#define FIT_LAST_ALIAS_STAGE 4

/* The levels, coarse to fine: a grid of cells across the image's wider
 * side, each the mean of ss x ss samples, blurred by sigma cells; the
 * first is searched from the starts and the coarse search's cameras
 * (fit_first_stage), every level refined by Gauss-Newton for at most
 * `iterations`. */
struct fit_stage {
	int cells;
	int ss;
	double sigma;
	int iterations;
};

static const struct fit_stage fit_stages[GRADE_FIT_LEVELS] = {
	{ 32, 2, 3.0, 10 },
	{ 48, 2, 2.4, 10 },
	{ 64, 2, 1.6, 10 },
	{ 96, 1, 1.6, 10 },
	{ 128, 1, 1.2, 8 },
	{ 192, 1, 1.0, 6 },
	{ 256, 1, 0.8, 6 },
};

/* The polish: once the passes have chosen, the winner refined on a level
 * of the image's own pixels (up to 384 across), barely blurred.  The
 * stages above stop at 256 cells: on a 512 or 768 image a camera right to
 * half a cell still moves the floor's far edges by a pixel, and near the
 * horizon, where the checker aliases, that is most of what differs.  Its
 * score is not the fit's (the callers weigh the fit on the last stage's
 * level, against the given camera's score there). */
static const struct fit_stage fit_polish_stage = { 384, 1, 0.5, 3 };

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

/* Stage 0: the starts and the coarse search's cameras scored on the
 * level, Gauss-Newton from the best few, the FIT_HYPOTHESES best results
 * into hyp (best first; scores in hf, INFINITY past the last). */
static int fit_first_stage(struct fit_batch *b, const struct camera_params *starts, int n_starts,
			   const struct image *sub, enum fit_reach reach,
			   double hyp[FIT_HYPOTHESES][FIT_DIM],
			   double *hf, long *evals, struct diag *d)
{
	double xs[(8 + FIT_COARSE_KEEP) * FIT_DIM], fs[8 + FIT_COARSE_KEEP], cs[FIT_COARSE_KEEP];
	int n = n_starts > 8 ? 8 : n_starts, t, k, rc;

	for (k = 0; k < FIT_HYPOTHESES; k++)
		hf[k] = INFINITY;
	for (k = 0; k < n; k++)
		fit_view_of(&starts[k], xs + k * FIT_DIM);
	if ((rc = fit_coarse_search(b->job, b->level->variant, reach, &starts[0], sub, FIT_COARSE_RADIUS,
				    FIT_COARSE_SPACING,
				    fit_scene_centre(b->job->scene),
				    (double (*)[FIT_DIM])(xs + n * FIT_DIM), cs, FIT_COARSE_KEEP, d)) < 0)
		return rc;
	n += FIT_COARSE_KEEP;
	fit_batch_run(b, xs, fs, n);
	*evals += n;
	for (t = 0; t < FIT_FIRST_TRIES; t++) {
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
		f = fit_gn(b, x, x[FIT_FOV] / fit_stages[0].cells, &pivot, fit_stages[0].iterations, &ev, d, &rc);
		*evals += ev;
		if (rc < 0)
			return rc;
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
 * reference's) fitted; each level's best score into out's levels, and the
 * fit abandoned (score INFINITY) where it is farther than bound's.
 * Long: one loop over the stages carries the hypotheses, their scores and
 * pivots from level to level; cut up, that state would travel through every
 * part. */
static int fit_run(const struct grade_job *job, const struct camera_params *starts, int n_starts,
		   const struct image *sub, const struct grade_variant *variant, enum fit_reach reach,
		   int first, const double *bound, struct grade_fit *out, struct diag *d)
{
	const int n_stages = GRADE_FIT_LEVELS;
	const int wide = sub->width > sub->height ? sub->width : sub->height;
	double hyp[FIT_HYPOTHESES][FIT_DIM], hf[FIT_HYPOTHESES], pivot[FIT_HYPOTHESES];
	double prev_sigma = INFINITY;
	int s, k, n_hyp = 1, rc = 0, eff, prev_cells = 0;

	memset(out, 0, sizeof(*out));
	out->camera = starts[0];
	out->cause = RT_CAUSE_NONE;
	out->also = RT_CAUSE_NONE;
	for (k = 0; k < FIT_HYPOTHESES; k++)
		pivot[k] = 100.0;
	for (k = 0; k < n_stages; k++)
		out->levels[k] = INFINITY;
	fit_view_of(&starts[0], hyp[0]);
	for (s = first; s < n_stages; s++) {
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
		if (s == 0) {
			rc = fit_first_stage(&batch, starts, n_starts, sub, reach, hyp, hf, &evals, d);
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
			if (s == first && variant && (variant->rules & RT_RULE_FLOOR_SWAPPED))
				fit_odd_alias(&batch, hyp[0], &evals);
			for (k = 0; k < n_hyp && rc == 0; k++) {
				hf[k] = fit_gn(&batch, hyp[k], hyp[k][FIT_FOV] / level.h, &pivot[k],
					       st->iterations, &evals, d, &rc);
				if (rc == 0 && s == FIT_LAST_ALIAS_STAGE &&
				    fit_final_alias(&batch, hyp[k], &hf[k], &evals))
					hf[k] = fit_gn(&batch, hyp[k], hyp[k][FIT_FOV] / level.h, &pivot[k],
						       st->iterations, &evals, d, &rc);
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
		fit_batch_close(&batch);
		fit_level_free(&level);
		(void)pixel_deg;
		if (rc < 0)
			return rc;
		if (job->cancel && *job->cancel)
			return diag_fail(d, RT_E_INTERRUPTED, "interrupted");
		if (n_hyp == 0)
			break;
		out->levels[s] = hf[0];
		if (bound && s >= FIT_GUARD_FIRST_STAGE && hf[0] > bound[s]) {
			out->score = INFINITY;
			return 0;
		}
	}
	fit_params_of(hyp[0], &starts[0], &out->camera);
	return 0;
}

int fit_screen(const struct grade_job *job, const struct camera_params *starts, int n_starts,
	       const struct image *sub, const struct grade_variant *variant, double *score,
	       struct diag *d)
{
	double stop[GRADE_FIT_LEVELS];
	struct grade_fit out;
	int k, rc;

	/* A bound no level meets ends the pass on the guard's first level,
	 * its score recorded. */
	for (k = 0; k < GRADE_FIT_LEVELS; k++)
		stop[k] = k < FIT_GUARD_FIRST_STAGE ? INFINITY : -INFINITY;
	rc = fit_run(job, starts, n_starts, sub, variant, FIT_REACH_NEAR, 0, stop, &out, d);
	*score = out.levels[FIT_GUARD_FIRST_STAGE];
	return rc;
}

/* The dolly line: a camera moved along its view and zoomed to keep the
 * scene's middle the same size sees much the same (only the near objects'
 * parallax and the near floor differ), and the passes can settle tens of
 * units too far back or forward, on one of the floor's aliases.  So after
 * them, cameras along that line (steps as shares of the distance to the
 * scene's middle), each refined on a blurred level, and the fit run on
 * from the best when it beats the camera found there. */
#define FIT_DOLLY_STAGE 3
static const double fit_dolly_steps[] = { -0.3, -0.15, 0.15, 0.3 };
#define FIT_DOLLY_STEPS (sizeof(fit_dolly_steps) / sizeof(fit_dolly_steps[0]))
#define FIT_DOLLY_ITERATIONS 6

/* The best camera on the dolly line about out's into *best: 1 when it
 * beats out's on the level, 0 when none does. */
static int fit_dolly_scan(const struct grade_job *job, const struct camera_params *start,
			  const struct image *sub, const struct grade_variant *variant,
			  struct grade_fit *out, struct camera_params *best, struct diag *d)
{
	struct fit_level level;
	struct fit_batch batch;
	double x[FIT_DIM], xs[FIT_DOLLY_STEPS][FIT_DIM], f0, fb = INFINITY, pixel_deg, pivot;
	long evals = 0;
	size_t k, pick = FIT_DOLLY_STEPS;
	struct vec3 f;
	int rc;

	fit_view_of(&out->camera, x);
	f = vec3_normalize(vec3_sub(out->camera.look, out->camera.eye));
	pivot = vec3_dot(vec3_sub(fit_scene_centre(job->scene), out->camera.eye), f);
	if (!(pivot > 1.0))
		return 0;
	if ((rc = fit_stage_level(&fit_stages[FIT_DOLLY_STAGE], sub, x[FIT_FOV], &level, &pixel_deg, d)) < 0)
		return rc;
	level.variant = variant;
	if ((rc = fit_batch_open(&batch, &level, job, start, d)) < 0) {
		fit_level_free(&level);
		return rc;
	}
	{
		double p0 = 100.0;
		f0 = fit_gn(&batch, x, x[FIT_FOV] / level.h, &p0, FIT_DOLLY_ITERATIONS, &evals, d, &rc);
	}
	for (k = 0; k < FIT_DOLLY_STEPS && rc == 0; k++) {
		double q[FIT_DIM] = { 0 }, fk, pk = 100.0;
		q[FIT_DOLLY] = fit_dolly_steps[k] * pivot;
		fit_view_move(x, q, pivot, xs[k]);
		fk = fit_gn(&batch, xs[k], xs[k][FIT_FOV] / level.h, &pk, FIT_DOLLY_ITERATIONS, &evals, d, &rc);
		if (fk < f0 && fk < fb) {
			fb = fk;
			pick = k;
		}
	}
	fit_batch_close(&batch);
	fit_level_free(&level);
	out->evals += evals;
	if (rc < 0)
		return rc;
	if (pick == FIT_DOLLY_STEPS)
		return 0;
	fit_params_of(xs[pick], start, best);
	return 1;
}

/* A fit whose last level is within this mean squared grey difference
 * has its camera to a small fraction of a cell there: the polish would
 * not move it by a visible amount, and is skipped. */
#define FIT_POLISHED_SCORE 0.25

/* The camera in out refined on the polish level (fit_polish_stage), unless
 * it is already within FIT_POLISHED_SCORE; out's scores stay the last
 * stage's. */
int fit_polish(const struct grade_job *job, const struct camera_params *start,
	       const struct image *sub, const struct grade_variant *variant, struct grade_fit *out,
	       struct diag *d)
{
	struct fit_level level;
	struct fit_batch batch;
	double x[FIT_DIM], pixel_deg, pivot = 100.0;
	long evals = 0;
	int rc;

	if (out->score <= FIT_POLISHED_SCORE)
		return 0;
	fit_view_of(&out->camera, x);
	if ((rc = fit_stage_level(&fit_polish_stage, sub, x[FIT_FOV], &level, &pixel_deg, d)) < 0)
		return rc;
	level.variant = variant;
	if ((rc = fit_batch_open(&batch, &level, job, start, d)) < 0) {
		fit_level_free(&level);
		return rc;
	}
	(void)fit_gn(&batch, x, x[FIT_FOV] / level.h, &pivot, fit_polish_stage.iterations, &evals, d, &rc);
	fit_batch_close(&batch);
	fit_level_free(&level);
	out->evals += evals;
	if (rc < 0)
		return rc;
	fit_params_of(x, start, &out->camera);
	return 0;
}

/* Keeps the later fit `again` in out when it ran and scores lower on the
 * same last level (true then); either way out counts both fits'
 * candidates. */
bool fit_keep_better(struct grade_fit *out, struct grade_fit *again)
{
	if (again->evals > 0 && again->score < out->score) {
		again->evals += out->evals;
		again->start_score = out->start_score;
		memcpy(again->levels, out->levels, sizeof(out->levels));
		*out = *again;
		return true;
	}
	out->evals += again->evals;
	return false;
}

/* A second pass (and the refit with a cause) starts on this level:
 * blurred enough to leave the floor's alias a first pass settled on for
 * the true camera a few cells away, sharp enough to stay near. */
#define FIT_REFIT_FIRST_STAGE 2
/* A first pass whose last level is within this mean squared grey
 * difference (a level's rounding is 1/12; 1 is 48 dB) found the camera:
 * no alias looks that much like the image, so no second pass. */
#define FIT_SETTLED_SCORE 1.0

/* The passes from the starts with the variant's colours (NULL: the
 * reference's): the first, and unless it settled, a second from where it
 * ended and the dolly line. */
int fit_passes(const struct grade_job *job, const struct camera_params *starts, int n_starts,
	       const struct image *sub, const struct grade_variant *variant, enum fit_reach reach,
	       const double *bound, struct grade_fit *out, struct diag *d)
{
	struct grade_fit again;
	int rc = fit_run(job, starts, n_starts, sub, variant, reach, 0, bound, out, d);

	/* The first pass ends on the floor's alias nearest its coarse
	 * guess; a second from where it ended, with one hypothesis, often
	 * finds the camera that alias hid (the same last level: the scores
	 * compare). */
	if (rc < 0 || (bound && isinf(out->score)))
		return rc;	/* failed, or abandoned by the guard */
	if (out->score > FIT_SETTLED_SCORE) {
		if ((rc = fit_run(job, &out->camera, 1, sub, variant, reach, FIT_REFIT_FIRST_STAGE, NULL,
				  &again, d)) < 0)
			return rc;
		fit_keep_better(out, &again);
	}
	if (out->score > FIT_SETTLED_SCORE) {
		struct camera_params moved;
		if ((rc = fit_dolly_scan(job, &starts[0], sub, variant, out, &moved, d)) < 0)
			return rc;
		if (rc > 0) {
			if ((rc = fit_run(job, &moved, 1, sub, variant, reach, FIT_DOLLY_STAGE + 1, NULL,
					  &again, d)) < 0)
				return rc;
			fit_keep_better(out, &again);
		}
	}
	return 0;
}

int grade_fit_camera_with(const struct grade_job *job, const struct camera_params *start,
			  enum grade_cause cause, int form, const struct image *sub,
			  const struct grade_fit *bound, struct grade_fit *out, struct diag *d)
{
	struct grade_variant v;
	int rc;

	/* The fit's levels trace through pixel centres and saturate: a
	 * cause that moves the rays to the corners or wraps the bytes is not
	 * fitted (nor is a transform, which is no render). */
	if (grade_cause_is_transform(cause) || !grade_variant_of(job, cause, form, &v) || v.corner ||
	    v.wrap)
		return diag_fail(d, RT_E_INVALID, "the cause has no such form to fit");
	rc = fit_run(job, start, 1, sub, &v, FIT_REACH_NEAR, FIT_REFIT_FIRST_STAGE,
		     bound ? bound->levels : NULL,
		     out, d);
	out->cause = cause;
	out->form = form;
	return rc < 0 || (bound && isinf(out->score)) ? rc : fit_polish(job, start, sub, &v, out, d);
}
