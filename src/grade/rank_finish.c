/* The ranking with the floor's own finish: fitted to the submission
 * before the causes are ranked, and fitted again with the likeliest cause
 * rendered too (the cause it is paired with pulls a fit made without it:
 * sr20's spotlight cones, 2.47 times narrower, took the highlight's
 * coefficient from 0.25 to 0.2; the tiles swapped defeat it). */
#include <string.h>

#include "grade/grade_impl.h"

int grade_rank_with_finish(struct grade_job *job, const struct image *ref,
			   const struct image *tref, const struct image *sub, const uint8_t *skip,
			   bool truncated, struct grade_rank out[GRADE_MAX_RANKS], size_t *n,
			   struct diag *d)
{
	struct grade_rank again[GRADE_MAX_RANKS], with;
	struct grade_job was;
	int rc;
	size_t m = 0;

	*n = 0;
	if ((rc = grade_fit_floor_finish(job, sub, skip, truncated, NULL, d)) < 0 ||
	    (rc = grade_rank_causes(job, ref, tref, sub, skip, out, n, d)) < 0 || *n == 0)
		return rc;
	/* The likeliest without the finish: the cause it is paired with, or
	 * the likeliest itself (one or a pair) when it has none. */
	with = out[0];
	if (with.cause == RT_CAUSE_FLOOR_FINISH) {
		with.cause = with.also;
		with.form = with.also_form;
		with.also = RT_CAUSE_NONE;
	} else if (with.also == RT_CAUSE_FLOOR_FINISH) {
		with.also = RT_CAUSE_NONE;
	}
	if (with.cause == RT_CAUSE_NONE || out[0].fig.match)
		return 0;
	was = *job;
	rc = grade_fit_floor_finish(job, sub, skip, truncated, &with, d);
	if (rc == 0 && job->n_floor_finishes > 0)
		rc = grade_rank_causes(job, ref, tref, sub, skip, again, &m, d);
	if (rc == 0 && job->n_floor_finishes > 0 && m > 0 && again[0].fig.psnr > out[0].fig.psnr) {
		memcpy(out, again, m * sizeof(again[0]));
		*n = m;
		return 0;
	}
	*job = was;
	return rc;
}
