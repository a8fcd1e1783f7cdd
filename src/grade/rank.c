/* The ranking of the causes against a submission: transforms exactly;
 * renders first on a sample (the pixels where the submission differs, and
 * one in 16 of the rest: enough to rank them), then the best three on
 * every pixel, so that a class's images are graded in seconds. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "grade/grade_impl.h"

/* The renders made again on every pixel after the sampled ranking: the
 * best three, but only those within GRADE_FULL_MARGIN dB of the best of
 * all (a transform's exact figure included); the rest keep the sample's
 * estimate, which is enough to rank a cause that far behind, and the
 * full renders are most of the time of an image that differs. */
#define GRADE_FULL_RENDERS 3
#define GRADE_FULL_MARGIN 3.0
#define GRADE_SAMPLE_STRIDE 4

/* Best first; equal PSNRs in the table's order. */
static int grade_rank_cmp(const void *a, const void *b)
{
	const struct grade_rank *x = a, *y = b;

	if (x->fig.psnr != y->fig.psnr)
		return x->fig.psnr > y->fig.psnr ? -1 : 1;
	return (int)x->cause - (int)y->cause;
}

/* The sample the renders are ranked on: every pixel where the submission
 * differs from the reference by more than 2 levels (or an even share of
 * them, at most GRADE_SAMPLE_DIFFERING), where the causes must be told
 * apart, and one pixel in 16 of the rest, where a cause must not change
 * what the submission has right.  Each part stands for all of its pixels
 * by its weight. */
#define GRADE_SAMPLE_DIFFERING 12000
#define GRADE_SAMPLE_MIN_PIXELS 4096

struct grade_sample {
	uint32_t *pixels;
	size_t n, n_differing;		/* the first n_differing are of the differing part */
	double w_differing, w_rest;
};

static int grade_sample_make(const struct image *ref, const struct image *sub,
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
		differs[i] = worst > 2;
		nd += differs[i];
	}
	step = (nd + GRADE_SAMPLE_DIFFERING - 1) / GRADE_SAMPLE_DIFFERING;
	step = step < 1 ? 1 : step;
	for (i = 0, nd = 0; i < total; i++) {
		if (differs[i] && nd++ % step == 0)
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
static void grade_sample_figures(const struct grade_sample *smp, const struct image *img,
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
static bool grade_same_on(const struct grade_sample *smp, const struct image *img,
			  const struct image *ref)
{
	size_t j;

	for (j = 0; j < smp->n; j++)
		if (memcmp(img->pixels + 3 * (size_t)smp->pixels[j], ref->pixels + 3 * (size_t)smp->pixels[j], 3) != 0)
			return false;
	return true;
}

/* The better of the two gamma curves against sub, applied to the rounded
 * reference or (tref not NULL) the truncated one. */
static int grade_rank_gamma(const struct image *ref, const struct image *tref,
			    const struct image *sub, struct grade_figures *f, bool *truncated,
			    struct diag *d)
{
	struct grade_figures g;
	struct image t;
	int pass, rc;

	*truncated = false;
	for (pass = 0; pass < (tref ? 4 : 2); pass++) {
		if ((rc = grade_transform_gamma(pass < 2 ? ref : tref, pass % 2 == 0, &t, d)) < 0)
			return rc;
		grade_figures_of(&t, sub, 1, 0, 0, pass == 0 ? f : &g);
		image_free(&t);
		if (pass > 0 && g.psnr > f->psnr) {
			*f = g;
			*truncated = pass >= 2;
		}
	}
	return 0;
}

/* The figures of the cause's transform of ref (and of tref, the better
 * kept) against sub; *changes false when the transform leaves ref as it is. */
static int grade_rank_transform(const struct image *ref, const struct image *tref,
				const struct image *sub, enum grade_cause c,
				struct grade_rank *out, bool *changes, struct diag *d)
{
	size_t total = (size_t)ref->width * (size_t)ref->height;
	struct grade_figures g;
	struct image t;
	int rc;

	if ((rc = grade_transform(ref, c, &t, d)) < 0)
		return rc;
	*changes = memcmp(t.pixels, ref->pixels, total * 3) != 0;
	out->cause = c;
	out->estimated = false;
	out->truncated = false;
	out->first_equal = false;
	grade_figures_of(&t, sub, 1, 0, 0, &out->fig);
	image_free(&t);
	if (!*changes)
		return 0;
	if (c == RT_CAUSE_GAMMA)
		return grade_rank_gamma(ref, tref, sub, &out->fig, &out->truncated, d);
	if (!tref)
		return 0;
	if ((rc = grade_transform(tref, c, &t, d)) < 0)
		return rc;
	grade_figures_of(&t, sub, 1, 0, 0, &g);
	image_free(&t);
	if (g.psnr > out->fig.psnr) {
		out->fig = g;
		out->truncated = true;
	}
	return 0;
}

/* The nearer to sub of a render's two conversions (timg may be NULL). */
static void grade_better_of(const struct grade_sample *smp, const struct image *img,
			    const struct image *timg, const struct image *sub,
			    struct grade_figures *f, bool *truncated)
{
	struct grade_figures g;

	*truncated = false;
	if (smp)
		grade_sample_figures(smp, img, sub, f);
	else
		grade_figures_of(img, sub, 1, 0, 0, f);
	if (!timg)
		return;
	if (smp)
		grade_sample_figures(smp, timg, sub, &g);
	else
		grade_figures_of(timg, sub, 1, 0, 0, &g);
	if (g.psnr > f->psnr) {
		*f = g;
		*truncated = true;
	}
}

/* Marks the causes whose figures equal the first one's exactly (a scene
 * symmetric left-right with an even number of tiles: mirrored and tiles
 * swapped are the same image): none of them is preferred. */
static void grade_mark_first_equal(struct grade_rank *r, size_t n)
{
	size_t k;

	for (k = 0; k < n; k++)
		r[k].first_equal = false;
	for (k = 1; k < n && !r[0].estimated; k++) {
		if (r[k].estimated || r[k].fig.psnr != r[0].fig.psnr ||
		    r[k].fig.off2 != r[0].fig.off2 || r[k].fig.mean_error != r[0].fig.mean_error)
			break;
		r[0].first_equal = r[k].first_equal = true;
	}
}

int grade_rank_causes(const struct grade_job *job, const struct image *ref,
		      const struct image *tref, const struct image *sub,
		      struct grade_rank out[RT_CAUSE_COUNT], size_t *n, struct diag *d)
{
	struct image imgs[GRADE_MAX_RENDERS], timgs[GRADE_MAX_RENDERS];
	struct image fimgs[GRADE_FULL_RENDERS], ftimgs[GRADE_FULL_RENDERS];
	int renders[GRADE_MAX_RENDERS], full[GRADE_FULL_RENDERS] = { 0 }, best_id[RT_CAUSE_COUNT];
	struct grade_rank sampled[RT_CAUSE_COUNT];
	struct grade_sample smp;
	size_t n_renders = 0, n_full = 0, k, j, i = 0, total = (size_t)ref->width * (size_t)ref->height;
	bool exact = total <= GRADE_SAMPLE_MIN_PIXELS;
	int size = ref->width, rc = 0, v;

	*n = 0;
	memset(imgs, 0, sizeof(imgs));
	memset(timgs, 0, sizeof(timgs));
	memset(fimgs, 0, sizeof(fimgs));
	memset(ftimgs, 0, sizeof(ftimgs));
	memset(best_id, 0, sizeof(best_id));
	if ((rc = grade_sample_make(ref, sub, &smp, d)) < 0)
		return rc;
	for (k = 0; k < RT_CAUSE_COUNT; k++) {
		enum grade_cause c = (enum grade_cause)k;
		bool changes;
		if (!grade_cause_applies(job, c))
			continue;
		if (grade_cause_is_transform(c)) {
			if ((rc = grade_rank_transform(ref, tref, sub, c, &out[*n], &changes, d)) < 0)
				goto out;
			*n += changes;
			continue;
		}
		for (v = 0; v < grade_variant_count(c); v++) {
			if ((rc = image_alloc(&imgs[n_renders], size, size, d)) < 0 ||
			    (tref && (rc = image_alloc(&timgs[n_renders], size, size, d)) < 0))
				goto out;
			renders[n_renders++] = (int)k * GRADE_VARIANTS + v;
		}
	}
	rc = grade_render_causes(job, renders, imgs, tref ? timgs : NULL, n_renders,
				 exact ? NULL : smp.pixels, exact ? 0 : smp.n, d);
	if (rc < 0)
		goto out;
	/* Each cause once, by its variant nearest the submission. */
	for (k = 0; k < n_renders; k++) {
		enum grade_cause c = (enum grade_cause)(renders[k] / GRADE_VARIANTS);
		struct grade_figures f;
		bool truncated;
		if (exact ? memcmp(imgs[k].pixels, ref->pixels, total * 3) == 0
			  : grade_same_on(&smp, &imgs[k], ref))
			continue;
		grade_better_of(exact ? NULL : &smp, &imgs[k], tref ? &timgs[k] : NULL, sub, &f,
				&truncated);
		for (j = 0; j < i && sampled[j].cause != c; j++)
			;
		if (j == i) {
			sampled[i].cause = c;
			sampled[i].estimated = !exact;
			sampled[i].fig = f;
			sampled[i].truncated = truncated;
			sampled[i].first_equal = false;
			best_id[c] = renders[k];
			i++;
		} else if (f.psnr > sampled[j].fig.psnr) {
			sampled[j].fig = f;
			sampled[j].truncated = truncated;
			best_id[c] = renders[k];
		}
	}
	qsort(sampled, i, sizeof(sampled[0]), grade_rank_cmp);
	if (!exact) {
		double best = i > 0 ? sampled[0].fig.psnr : -INFINITY;
		for (k = 0; k < *n; k++)
			best = out[k].fig.psnr > best ? out[k].fig.psnr : best;
		while (n_full < i && n_full < GRADE_FULL_RENDERS &&
		       sampled[n_full].fig.psnr >= best - GRADE_FULL_MARGIN)
			n_full++;
		for (k = 0; k < n_full; k++) {
			full[k] = best_id[sampled[k].cause];
			if ((rc = image_alloc(&fimgs[k], size, size, d)) < 0 ||
			    (tref && (rc = image_alloc(&ftimgs[k], size, size, d)) < 0))
				goto out;
		}
		if ((rc = grade_render_causes(job, full, fimgs, tref ? ftimgs : NULL, n_full, NULL, 0,
					      d)) < 0)
			goto out;
		for (k = 0; k < n_full; k++) {
			sampled[k].estimated = false;
			grade_better_of(NULL, &fimgs[k], tref ? &ftimgs[k] : NULL, sub, &sampled[k].fig,
					&sampled[k].truncated);
		}
	}
	memcpy(out + *n, sampled, i * sizeof(sampled[0]));
	*n += i;
	qsort(out, *n, sizeof(out[0]), grade_rank_cmp);
	grade_mark_first_equal(out, *n);
out:
	for (k = 0; k < GRADE_MAX_RENDERS; k++) {
		image_free(&imgs[k]);
		image_free(&timgs[k]);
	}
	for (k = 0; k < GRADE_FULL_RENDERS; k++) {
		image_free(&fimgs[k]);
		image_free(&ftimgs[k]);
	}
	rt_free(smp.pixels);
	return rc;
}
