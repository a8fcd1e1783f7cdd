/* The floor finish's least squares (floor_finish.c's fit): the sample
 * of floor pixels with its bases, the model, its error, the
 * non-negative least squares and the trimming of rows far off. */
#ifndef RT_GRADE_FINISH_LSQ_H
#define RT_GRADE_FINISH_LSQ_H

#include <stddef.h>
#include <stdint.h>

/* The exponents tried (floor_finish.c's list). */
#define FINISH_N_SHINE 17
/* The bases: ambient, diffuse, a specular one for each exponent, then
 * reflection (last: traced again once a finish is found). */
enum { FINISH_A, FINISH_D, FINISH_S0, FINISH_R = FINISH_S0 + FINISH_N_SHINE, FINISH_BASES };
enum { FINISH_KA, FINISH_KD, FINISH_KS, FINISH_KR, FINISH_K };

struct finish_sample {
	size_t n;			/* pixels */
	float *basis;			/* FINISH_BASES x n x 3 */
	float *target;			/* n x 3, 0..1 */
	uint8_t *use;			/* n x 3: the row counts in the fit */
};

static inline float *finish_basis(const struct finish_sample *fs, int b)
{
	return fs->basis + (size_t)b * fs->n * 3;
}

/* The model's colour of row j (pixel j / 3, channel j % 3) for the
 * coefficients k with specular basis sb. */
double finish_model(const struct finish_sample *fs, int sb, const double k[FINISH_K], size_t j);
/* The squared error of k over every row in use (the model clamped). */
double finish_error(const struct finish_sample *fs, int sb, const double k[FINISH_K]);
/* The least-squares coefficients (>= 0) for specular basis sb. */
void finish_least_squares(const struct finish_sample *fs, int sb, double k[FINISH_K]);
/* Leaves out of the fit the rows far off under k (tmp: 3 n floats). */
void finish_trim(struct finish_sample *fs, int sb, const double k[FINISH_K], float *tmp);

#endif
