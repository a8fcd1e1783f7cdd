/* The ranking with the floor's own finish: fitted to the submission
 * before the causes are ranked, and fitted again with the cause it is
 * paired with when that pair comes first (the other cause pulls a fit
 * made without it: sr20's spotlight cones, 2.47 times narrower, took the
 * highlight's coefficient from 0.25 to 0.2). */
#include <string.h>

#include "grade/grade_impl.h"

int grade_rank_with_finish(struct grade_job *job, const struct image *ref,
			   const struct image *tref, const struct image *sub, const uint8_t *skip,
			   bool truncated, struct grade_rank out[GRADE_MAX_RANKS], size_t *n,
			   struct diag *d)
{
	struct grade_rank again[GRADE_MAX_RANKS];
	struct grade_job was;
	enum grade_cause other;
	int rc, form;
	size_t m = 0;

	*n = 0;
	if ((rc = grade_fit_floor_finish(job, sub, skip, truncated, RT_CAUSE_NONE, 0, d)) < 0 ||
	    (rc = grade_rank_causes(job, ref, tref, sub, skip, out, n, d)) < 0)
		return rc;
	if (*n == 0 || out[0].also == RT_CAUSE_NONE ||
	    (out[0].cause != RT_CAUSE_FLOOR_FINISH && out[0].also != RT_CAUSE_FLOOR_FINISH))
		return 0;
	was = *job;
	other = out[0].cause == RT_CAUSE_FLOOR_FINISH ? out[0].also : out[0].cause;
	form = out[0].cause == RT_CAUSE_FLOOR_FINISH ? out[0].also_form : out[0].form;
	rc = grade_fit_floor_finish(job, sub, skip, truncated, other, form, d);
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
