/* The grade module's parts: the transforms and the renders of the causes. */
#ifndef RT_GRADE_IMPL_H
#define RT_GRADE_IMPL_H

#include <stdint.h>

#include "whitted/grade.h"

/* How a cause renders in one of its forms: broken rules, other settings,
 * or rays through a corner of the pixel. */
struct grade_variant {
	unsigned rules;
	struct render_settings settings;
	bool use_rules;
	bool corner;			/* rays through (x + cx, y + cy), not the centre */
	bool wrap;			/* the bytes wrap round instead of saturating */
	double cx, cy;
};

/* A cause's renders: the ways a program commonly makes that mistake, of
 * which the one nearest the submission counts.  A render is named by an id
 * cause * GRADE_VARIANTS + variant. */
#define GRADE_VARIANTS 4
#define GRADE_MAX_RENDERS (RT_CAUSE_COUNT * GRADE_VARIANTS)
/* The id of the render with no rule broken: the reference's own pixels. */
#define GRADE_PLAIN_RENDER (-1)

/* The number of forms of cause c (1 to GRADE_VARIANTS). */
int grade_variant_count(enum grade_cause c);
/* The render named by id. */
void grade_variant_of(const struct grade_job *job, int id, struct grade_variant *v);
/* Whether cause c can change the job's image at all. */
bool grade_cause_applies(const struct grade_job *job, enum grade_cause c);

/* True for the causes that transform the reference (no render). */
bool grade_cause_is_transform(enum grade_cause c);

/* The reference transformed as cause c says. */
int grade_transform(const struct image *ref, enum grade_cause c, struct image *out, struct diag *d);

/* Renders, for each of the n renders named by ids[i] (a cause times 4
 * plus its variant, see causes.c), the listed pixels (indices y * size +
 * x; NULL: every pixel) into imgs[i], which have the camera's size, and
 * when timgs is not NULL the same colours converted by truncation into
 * timgs[i] (one trace, both conversions); threads share chunks of the list
 * of every render. */
int grade_render_causes(const struct grade_job *job, const int *ids, struct image *imgs,
			struct image *timgs, size_t n, const uint32_t *pixels, size_t n_pixels,
			struct diag *d);

/* The reference gamma-encoded with the sRGB curve (srgb) or c^(1/2.2). */
int grade_transform_gamma(const struct image *ref, bool srgb, struct image *out, struct diag *d);

#endif
