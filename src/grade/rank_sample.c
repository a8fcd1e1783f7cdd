/* The sample the causes' renders are ranked on, and the figures it
 * estimates (rank_sample.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "grade/rank_sample.h"

#define GRADE_SAMPLE_STRIDE 4

int grade_sample_make(const struct image *ref, const struct image *sub, const uint8_t *skip,
			     struct grade_sample *smp, struct diag *d)
{
	size_t total = (size_t)ref->width * (size_t)ref->height, i, nd = 0, step, taken = 0, rest = 0;
	uint8_t *differs = rt_calloc(total, 1);

	memset(smp, 0, sizeof(*smp));
	if (!differs || !(smp->pixels = rt_reallocarray(NULL, total, sizeof(uint32_t)))) {
		rt_free(differs);
		return diag_fail(d, RT_E_NOMEM, "out of memory for the sample");
	}
	for (i = 0; i < total; i++) {
		int k, worst = 0;
		for (k = 0; k < 3; k++) {
			int dv = abs((int)ref->pixels[3 * i + k] - (int)sub->pixels[3 * i + k]);
			worst = dv > worst ? dv : worst;
		}
		/* 2: a tie, in neither part. */
		differs[i] = skip && skip[i] ? 2 : worst > 2;
		nd += differs[i] == 1;
	}
	step = (nd + GRADE_SAMPLE_DIFFERING - 1) / GRADE_SAMPLE_DIFFERING;
	step = step < 1 ? 1 : step;
	for (i = 0, nd = 0; i < total; i++) {
		if (differs[i] == 1 && nd++ % step == 0)
			smp->pixels[smp->n++] = (uint32_t)i;
	}
	smp->n_differing = smp->n;
	taken = smp->n;
	for (i = 0; i < total; i++) {
		int x = (int)(i % (size_t)ref->width), y = (int)(i / (size_t)ref->width);
		if (differs[i])
			continue;
		rest++;
		if (x % GRADE_SAMPLE_STRIDE == GRADE_SAMPLE_STRIDE / 2 &&
		    y % GRADE_SAMPLE_STRIDE == GRADE_SAMPLE_STRIDE / 2)
			smp->pixels[smp->n++] = (uint32_t)i;
	}
	smp->w_differing = taken ? (double)nd / (double)taken : 0.0;
	smp->w_rest = smp->n > taken ? (double)rest / (double)(smp->n - taken) : 0.0;
	rt_free(differs);
	return 0;
}

/* The figures of img against sub estimated from the sample. */
void grade_sample_figures(const struct grade_sample *smp, const struct image *img,
				 const struct image *sub, struct grade_figures *f)
{
	double sum = 0.0, sq = 0.0, off2 = 0.0, off8 = 0.0, off32 = 0.0, n = 0.0;
	size_t j;

	for (j = 0; j < smp->n; j++) {
		size_t i = smp->pixels[j];
		double w = j < smp->n_differing ? smp->w_differing : smp->w_rest, s = 0.0, q = 0.0;
		int k, worst = 0;
		for (k = 0; k < 3; k++) {
			int dv = abs((int)img->pixels[3 * i + k] - (int)sub->pixels[3 * i + k]);
			s += dv;
			q += (double)dv * dv;
			worst = dv > worst ? dv : worst;
		}
		sum += w * s;
		sq += w * q;
		off2 += worst > 2 ? w : 0.0;
		off8 += worst > 8 ? w : 0.0;
		off32 += worst > 32 ? w : 0.0;
		n += w;
	}
	n = n > 0.0 ? n : 1.0;
	f->pixels = (long)smp->n;
	f->mean_error = sum / (3.0 * n);
	sq /= 3.0 * n;
	f->psnr = sq == 0.0 ? INFINITY : 10.0 * log10(255.0 * 255.0 / sq);
	f->psnr_gate = f->psnr;		/* an estimate: nothing left out */
	f->left_out = 0;
	f->off2 = off2 / n;
	f->off8 = off8 / n;
	f->off32 = off32 / n;
	f->match = f->psnr >= RT_GRADE_MIN_PSNR && f->off2 <= RT_GRADE_MAX_OFF2 &&
		   f->off8 <= RT_GRADE_MAX_OFF8;
}

/* Whether img equals ref on the sample: the cause changes nothing there. */
bool grade_same_on(const struct grade_sample *smp, const struct image *img,
			  const struct image *ref)
{
	size_t j;

	for (j = 0; j < smp->n; j++)
		if (memcmp(img->pixels + 3 * (size_t)smp->pixels[j], ref->pixels + 3 * (size_t)smp->pixels[j], 3) != 0)
			return false;
	return true;
}

/* The nearer to sub of a render's two conversions (timg may be NULL). */
void grade_better_of(const struct grade_sample *smp, const struct image *img,
			    const struct image *timg, const struct image *sub, const uint8_t *skip,
			    struct grade_figures *f, bool *truncated)
{
	struct grade_figures g;

	*truncated = false;
	if (smp)
		grade_sample_figures(smp, img, sub, f);
	else
		grade_figures_skipping(img, sub, skip, f);
	if (!timg)
		return;
	if (smp)
		grade_sample_figures(smp, timg, sub, &g);
	else
		grade_figures_skipping(timg, sub, skip, &g);
	if (g.psnr > f->psnr) {
		*f = g;
		*truncated = true;
	}
}
