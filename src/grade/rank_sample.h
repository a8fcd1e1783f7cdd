/* The sample of pixels the causes' renders are ranked on, private to the
 * ranking (rank.c). */
#ifndef RT_GRADE_RANK_SAMPLE_H
#define RT_GRADE_RANK_SAMPLE_H

#include <stdbool.h>
#include <stdint.h>

#include "grade/grade_impl.h"

/* The sample the renders are ranked on: every pixel where the submission
 * differs from the reference by more than 2 levels (or an even share of
 * them, at most GRADE_SAMPLE_DIFFERING), where the causes must be told
 * apart, and one pixel in 16 of the rest, where a cause must not change
 * what the submission has right.  Each part stands for all of its pixels
 * by its weight.  6000 differing pixels rank the causes as 12000 did
 * (mistakecheck's 181 first causes the same) in half the sampled
 * renders' time, most of a moved image's ranking at its given camera,
 * where every pixel differs. */
#define GRADE_SAMPLE_DIFFERING 6000
/* An image this small is ranked on every pixel. */
#define GRADE_SAMPLE_MIN_PIXELS 4096

struct grade_sample {
	uint32_t *pixels;
	size_t n, n_differing;		/* the first n_differing are of the differing part */
	double w_differing, w_rest;
};

/* The sample of sub against ref, ties (skip[i] != 0; skip may be NULL)
 * in neither part; smp->pixels freed with rt_free. */
int grade_sample_make(const struct image *ref, const struct image *sub, const uint8_t *skip,
		      struct grade_sample *smp, struct diag *d);
/* The figures of img against sub estimated from the sample. */
void grade_sample_figures(const struct grade_sample *smp, const struct image *img,
			  const struct image *sub, struct grade_figures *f);
/* Whether img equals ref on the sample: the cause changes nothing there. */
bool grade_same_on(const struct grade_sample *smp, const struct image *img,
		   const struct image *ref);
/* The nearer to sub of a render's two conversions (timg may be NULL), on
 * the sample (smp) or every pixel but the ties (smp NULL). */
void grade_better_of(const struct grade_sample *smp, const struct image *img,
		     const struct image *timg, const struct image *sub, const uint8_t *skip,
		     struct grade_figures *f, bool *truncated);

#endif
