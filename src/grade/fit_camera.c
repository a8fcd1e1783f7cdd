/* The camera fit as a whole: the plain passes, then, when no camera comes
 * near, the passes pulled by a mistake rendered in the reference's place
 * and the floor's shape (fit_floor.c), and the polish of the nearest. */
#include <math.h>
#include <string.h>

#include "grade/fit_search.h"

/* A fit this far from the image (a mean squared grey difference on the
 * last level: 15 is about 4 levels everywhere) was pulled away by a
 * mistake that changes most of the image: the passes are made once more
 * with each of these rendered in place of the reference (the camera and
 * the mistake fitted at once), and the nearest of all kept.  Gamma and no
 * shadows (where a big object shadows the floor) make most pixels
 * brighter, and the plain reference's nearest camera sees more of the
 * bright parts; swapped tiles make the floor's every cell the wrong
 * colour, and the plain fit ends a dolly and an alias away.  The later
 * refit with a cause (grade_fit_camera_with) starts from the camera
 * found, too near to leave such a camera; docs/validation.md (the camera
 * fit, step 7) has the cases. */
#define FIT_PULLED_SCORE 15.0
/* ... and one still this far after the pulled passes is searched with
 * the floor's other shapes (fit_floor.c): 50, about 7 levels everywhere,
 * which no camera of the scene's floor comes near. */
#define FIT_SHAPE_SCORE 50.0
/* ... and one still this far after those is searched once more, plainly,
 * from eyes all round the scene's middle (FIT_REACH_ROUND): a student
 * who walked the camera round the objects or over them.  Last, since its
 * first look costs as much as the others' and most images never need it;
 * bounded by the plain pass, level by level. */
#define FIT_FAR_SCORE 100.0
static const struct {
	enum grade_cause cause;
	int form;
} fit_pulling_causes[] = {
	{ RT_CAUSE_GAMMA, 0 },
	{ RT_CAUSE_FLOOR_SWAPPED, 0 },
	{ RT_CAUSE_NO_SHADOWS, 0 },
};

int grade_fit_camera(const struct grade_job *job, const struct camera_params *starts,
		     int n_starts, const struct image *sub, struct grade_fit *out, struct diag *d)
{
	struct grade_variant pulls[sizeof(fit_pulling_causes) / sizeof(fit_pulling_causes[0])], shape;
	const struct grade_variant *kept = NULL;
	size_t k;
	int rc = fit_passes(job, starts, n_starts, sub, NULL, FIT_REACH_NEAR, NULL, out, d);

	if (rc < 0)
		return rc;
	for (k = 0; k < sizeof(pulls) / sizeof(pulls[0]) && out->score > FIT_PULLED_SCORE; k++) {
		struct grade_fit again;
		if (!grade_variant_of(job, fit_pulling_causes[k].cause, fit_pulling_causes[k].form, &pulls[k]))
			continue;
		if ((rc = fit_passes(job, starts, n_starts, sub, &pulls[k], FIT_REACH_NEAR, out->levels,
				     &again, d)) < 0)
			return rc;
		again.cause = fit_pulling_causes[k].cause;
		again.form = fit_pulling_causes[k].form;
		if (fit_keep_better(out, &again))
			kept = &pulls[k];
	}
	if (out->score > FIT_SHAPE_SCORE) {
		if ((rc = fit_floor_shape(job, starts, n_starts, sub, out, &shape, d)) < 0)
			return rc;
		if (rc > 0)
			kept = &shape;
	}
	if (out->score > FIT_FAR_SCORE) {
		struct grade_fit again;
		if ((rc = fit_passes(job, starts, n_starts, sub, NULL, FIT_REACH_ROUND, out->levels,
				     &again, d)) < 0)
			return rc;
		if (fit_keep_better(out, &again))
			kept = NULL;
	}
	return fit_polish(job, &starts[0], sub, kept, out, d);
}
