/* The floor's finish found from a submission: students give the floor
 * coefficients of their own (0.25 each and shininess 15; 0.5 0.3 0.4 0.2
 * and 10), which change every floor pixel and hide every other
 * difference.  On the floor's own pixels the colour is linear in the
 * four coefficients, for a shininess:
 *
 *   C = clamp(ka A + kd D + ks S(n) + kr R)
 *
 * where A is the cell's colour, D and S(n) the lights' diffuse and
 * specular sums (shadows and spotlights as the reference has them) and R
 * the colour the reflected ray brings back.  Each basis is the renderer's
 * own sum with one coefficient 1 and the others 0 (unclamped where it may
 * pass 1: no reflection follows), so the fit and the render share one
 * formula; the floor seen in reflections (a sphere mirroring it) has the
 * student's finish too, the scene's in a first fit and that fit's in a
 * second.  A least-squares fit over a sample of the floor's pixels, for
 * each shininess of a list, gives the finish; RT_CAUSE_FLOOR_FINISH
 * renders it, and the ranking decides whether it explains the image. */
#include <math.h>
#include <string.h>

#include "base/alloc.h"
#include "grade/finish_lsq.h"
#include "grade/grade_impl.h"
#include "scene/scene_impl.h"

/* The floor pixels fitted at most (a sample, every k-th in raster order). */
#define FINISH_MAX_PIXELS 4096
/* ... and at least (fewer: the floor shows too little to fit on). */
#define FINISH_MIN_PIXELS 64
/* The exponents tried: the ones students write. */
static const double finish_shininess[FINISH_N_SHINE] = {
	1, 2, 3, 4, 5, 8, 10, 12, 15, 20, 25, 30, 40, 50, 64, 80, 100,
};
/* A finish is taken only when its squared error on the sample is at most
 * this share of the scene's own finish's, and it explains the floor to
 * this root mean square (levels, on the rows kept): a student's finish
 * with a narrower spotlight cone is 2.4 off, a floor of another shape
 * or seen from another camera 85 to 95 whatever its finish. */
#define FINISH_BETTER 0.7
#define FINISH_MAX_RMS 16.0
/* The first form's coefficients are rounded to this step (students
 * write 0.25, 0.4): where the fit is pulled by another difference (a
 * spotlight's cone), the round values are often the student's. */
#define FINISH_ROUND_STEP 0.05

/* The bases' colours along the rays of the sample's pixels, rendered as
 * the variant with renders (its rules, settings and floor's shape), the
 * floor seen in reflections with the finish deeper (the bases are the
 * floor's first hit only); from basis `first` on. */
static void finish_trace(const struct grade_job *job, const struct grade_variant *with,
			 const struct material *deeper, int first, const int32_t *px,
			 struct finish_sample *fs)
{
	const struct scene *s = job->scene;
	struct shade_floor fl = with->floor;
	struct render_settings unclamped = with->settings;
	size_t i;
	int b;

	fl.own_finish = true;
	fl.own_deeper = true;
	fl.deeper = *deeper;
	unclamped.clamp = RT_CLAMP_FINAL;
	for (b = first; b < FINISH_BASES; b++) {
		float *out = finish_basis(fs, b);
		/* The reflection keeps the clamping below the floor; the other
		 * bases have no reflection, and unclamped they are the sums
		 * themselves. */
		const struct render_settings *rs = b == FINISH_R ? &with->settings : &unclamped;

		memset(&fl.finish, 0, sizeof(fl.finish));
		fl.finish.color = s->floor->mat.color;
		fl.finish.ior = s->floor->mat.ior;
		if (b == FINISH_A)
			fl.finish.ka = 1.0;
		else if (b == FINISH_D)
			fl.finish.kd = 1.0;
		else if (b == FINISH_R)
			fl.finish.kr = 1.0;
		else {
			fl.finish.ks = 1.0;
			fl.finish.shininess = finish_shininess[b - FINISH_S0];
		}
		for (i = 0; i < fs->n; i++) {
			struct ray r = camera_ray(job->camera, px[2 * i], px[2 * i + 1]);
			struct color c = shade_rules_trace_floor(s, rs, with->rules, &fl, &r, 1);

			out[3 * i] = (float)c.r;
			out[3 * i + 1] = (float)c.g;
			out[3 * i + 2] = (float)c.b;
		}
	}
}

/* Leaves out of the fit the pixels where the bases are all alike, and
 * those on a cell's edge: whose cell colour (the ambient basis) is not
 * their four neighbours' too.  A
 * camera a fraction of a pixel off, or rays through the pixels' corners,
 * changes their colour wholly; on a small image that is most of the
 * floor, and a fit on them finds a finish that is none. */
static void finish_inside_cells(const struct grade_job *job, const struct grade_variant *with,
				const int32_t *px, struct finish_sample *fs)
{
	static const int dx[4] = { 1, -1, 0, 0 }, dy[4] = { 0, 0, 1, -1 };
	struct shade_floor fl = with->floor;
	const float *a = finish_basis(fs, FINISH_A), *d = finish_basis(fs, FINISH_D);
	const float *refl = finish_basis(fs, FINISH_R);
	size_t i;
	int k;

	fl.own_finish = true;
	memset(&fl.finish, 0, sizeof(fl.finish));
	fl.finish.ka = 1.0;
	for (i = 0; i < fs->n; i++) {
		/* The bases all alike: the variant's ray meets no floor there
		 * (a floor cause's other floor), or a black cell that sees
		 * black, which says nothing of the finish either. */
		if (memcmp(a + 3 * i, d + 3 * i, 3 * sizeof(float)) == 0 &&
		    memcmp(a + 3 * i, refl + 3 * i, 3 * sizeof(float)) == 0) {
			memset(fs->use + 3 * i, 0, 3);
			continue;
		}
		for (k = 0; k < 4; k++) {
			struct ray r = camera_ray(job->camera, px[2 * i] + dx[k], px[2 * i + 1] + dy[k]);
			struct color c = shade_rules_trace_floor(job->scene, &with->settings, with->rules,
								 &fl, &r, 1);

			if ((float)c.r != a[3 * i] || (float)c.g != a[3 * i + 1] ||
			    (float)c.b != a[3 * i + 2]) {
				memset(fs->use + 3 * i, 0, 3);
				break;
			}
		}
	}
}

/* The basis of the exponent nearest n (the scene's own finish). */
static int finish_basis_of(double n)
{
	size_t i, best = 0;

	for (i = 1; i < FINISH_N_SHINE; i++)
		if (fabs(finish_shininess[i] - n) < fabs(finish_shininess[best] - n))
			best = i;
	return FINISH_S0 + (int)best;
}

/* Whether pixel i may be in the sample: the floor's, not marked in skip,
 * its four neighbours the floor's too. */
static bool finish_candidate(const int32_t *ids, const uint8_t *skip, int w, int h, size_t i)
{
	const size_t x = i % (size_t)w, y = i / (size_t)w;

	return ids[i] == GRADE_ID_FLOOR && !(skip && skip[i]) && x > 0 && y > 0 &&
	       x + 1 < (size_t)w && y + 1 < (size_t)h && ids[i - 1] == GRADE_ID_FLOOR &&
	       ids[i + 1] == GRADE_ID_FLOOR && ids[i - (size_t)w] == GRADE_ID_FLOOR &&
	       ids[i + (size_t)w] == GRADE_ID_FLOOR;
}

/* The sample: every k-th floor pixel that finish_candidate takes; 0 when
 * the floor shows too little to fit four numbers on. */
static int finish_sample_of(const struct grade_job *job, const struct image *sub,
			    const uint8_t *skip, bool truncated, struct finish_sample *fs,
			    int32_t **px_out, struct diag *d)
{
	const size_t total = (size_t)sub->width * (size_t)sub->height;
	int32_t *ids = rt_reallocarray(NULL, total, sizeof(*ids)), *px = NULL;
	size_t i, count = 0, step, n = 0;
	int rc, c;

	if (!ids)
		return diag_fail(d, RT_E_NOMEM, "out of memory for the object ids");
	if ((rc = grade_object_ids(job, ids, d)) < 0)
		goto out;
	for (i = 0; i < total; i++)
		count += finish_candidate(ids, skip, sub->width, sub->height, i);
	rc = 0;
	if (count < FINISH_MIN_PIXELS)
		goto out;
	step = (count + FINISH_MAX_PIXELS - 1) / FINISH_MAX_PIXELS;
	fs->n = (count + step - 1) / step;
	if (!(px = rt_reallocarray(NULL, 2 * fs->n, sizeof(*px))) ||
	    !(fs->basis = rt_reallocarray(NULL, (size_t)FINISH_BASES * 3 * fs->n, sizeof(float))) ||
	    !(fs->target = rt_reallocarray(NULL, 3 * fs->n, sizeof(float))) ||
	    !(fs->use = rt_malloc(3 * fs->n))) {
		rc = diag_fail(d, RT_E_NOMEM, "out of memory for the floor's finish");
		goto out;
	}
	for (i = 0, count = 0; i < total && n < fs->n; i++) {
		if (!finish_candidate(ids, skip, sub->width, sub->height, i) || count++ % step)
			continue;
		px[2 * n] = (int32_t)(i % (size_t)sub->width);
		px[2 * n + 1] = (int32_t)(i / (size_t)sub->width);
		for (c = 0; c < 3; c++) {
			uint8_t b = sub->pixels[3 * i + c];

			fs->target[3 * n + c] = b == 255 ? 1.0f
				: (float)((b + (truncated ? 0.5 : 0.0)) / 255.0);
			fs->use[3 * n + c] = 1;
		}
		n++;
	}
	fs->n = n;
	rc = 1;
out:
	rt_free(ids);
	if (rc <= 0) {
		rt_free(px);
		px = NULL;
	}
	*px_out = px;
	return rc;
}

/* v, rounded to FINISH_ROUND_STEP when round. */
static double finish_value(double v, bool round)
{
	return round ? FINISH_ROUND_STEP * floor(v / FINISH_ROUND_STEP + 0.5) : v;
}

static bool finish_same(const struct material *a, const struct material *b)
{
	return a->ka == b->ka && a->kd == b->kd && a->ks == b->ks && a->kr == b->kr &&
	       a->shininess == b->shininess;
}

/* The fit on the sample (bases traced, rows in use marked): for each
 * exponent the least squares, then again without the rows far off under
 * the best (cells' and objects' edges, other objects' reflections); the
 * finishes into job when the best fits clearly better than own. */
static void finish_fit(struct finish_sample *fs, float *tmp, const struct material *own,
		       struct grade_job *job)
{
	const double own_k[FINISH_K] = { own->ka, own->kd, own->ks, own->kr };
	double k[FINISH_K], best_k[FINISH_K], e, best_e = INFINITY;
	int sb, best_sb = finish_basis_of(own->shininess), pass, form;
	size_t j, used = 0;

	memcpy(best_k, own_k, sizeof(best_k));
	job->n_floor_finishes = 0;

	for (pass = 0; pass < 2; pass++) {
		best_e = INFINITY;
		for (sb = FINISH_S0; sb < FINISH_R; sb++) {
			finish_least_squares(fs, sb, k);
			if ((e = finish_error(fs, sb, k)) < best_e) {
				best_e = e;
				best_sb = sb;
				memcpy(best_k, k, sizeof(k));
			}
		}
		if (pass == 0)
			finish_trim(fs, best_sb, best_k, tmp);
	}
	for (j = 0; j < 3 * fs->n; j++)
		used += fs->use[j];
	if (!(best_e <= FINISH_BETTER * finish_error(fs, finish_basis_of(own->shininess), own_k)) ||
	    !(best_e <= used * (FINISH_MAX_RMS / 255.0) * (FINISH_MAX_RMS / 255.0)))
		return;
	for (form = 0; form < 2; form++) {
		struct material *m = &job->floor_finishes[job->n_floor_finishes];

		*m = *own;
		m->ka = finish_value(best_k[FINISH_KA], form == 0);
		m->kd = finish_value(best_k[FINISH_KD], form == 0);
		m->ks = finish_value(best_k[FINISH_KS], form == 0);
		m->kr = finish_value(best_k[FINISH_KR], form == 0);
		m->shininess = m->ks > 0.0 ? finish_shininess[best_sb - FINISH_S0] : own->shininess;
		if (!finish_same(m, own) &&
		    (job->n_floor_finishes == 0 || !finish_same(m, &job->floor_finishes[0])))
			job->n_floor_finishes++;
	}
}

/* Whether the job's image can be fitted with the rank's cause (and its
 * second cause, in their forms) rendered too (NULL: the reference), its
 * render into with: one ray a pixel, a plain checker (a texture's cells
 * are not the checker's colours), causes the rules' trace makes whole
 * (not the finish itself, a transform, the pixels' corners or a colour
 * curve). */
static bool finish_fits(const struct grade_job *job, const struct image *sub,
			const struct grade_rank *also, struct grade_variant *with)
{
	const struct scene *s = job->scene;
	struct grade_variant a, b;
	struct color spec;

	grade_variant_plain(job, with);
	if (also) {
		if (also->cause == RT_CAUSE_FLOOR_FINISH || also->also == RT_CAUSE_FLOOR_FINISH ||
		    !grade_variant_of(job, also->cause, also->form, &a))
			return false;
		if (also->also == RT_CAUSE_NONE)
			*with = a;
		else if (!grade_variant_of(job, also->also, also->also_form, &b) ||
			 !grade_variant_combine(&a, &b, with))
			return false;
		if (with->map || with->corner || with->gamma || with->wrap)
			return false;
	}
	return s->floor && job->samples <= 1 && sub->width == job->camera->width &&
	       sub->height == job->camera->height &&
	       !shape_specular_color_at(s->floor, vec3_make(0.0, 0.0, 0.0), &spec);
}

int grade_fit_floor_finish(struct grade_job *job, const struct image *sub, const uint8_t *skip,
			   bool truncated, const struct grade_rank *also, struct diag *d)
{
	struct grade_variant with;
	struct finish_sample fs;
	const struct material *own;
	int32_t *px = NULL;
	float *tmp = NULL;
	uint8_t *kept = NULL;
	size_t i, used = 0;
	int rc;

	job->n_floor_finishes = 0;
	memset(&fs, 0, sizeof(fs));
	if (!finish_fits(job, sub, also, &with))
		return 0;
	if ((rc = finish_sample_of(job, sub, skip, truncated, &fs, &px, d)) <= 0)
		goto out;
	if (!(tmp = rt_reallocarray(NULL, 3 * fs.n, sizeof(float))) || !(kept = rt_malloc(3 * fs.n))) {
		rc = diag_fail(d, RT_E_NOMEM, "out of memory for the floor's finish");
		goto out;
	}
	own = &job->scene->floor->mat;
	finish_trace(job, &with, own, FINISH_A, px, &fs);
	finish_inside_cells(job, &with, px, &fs);
	memcpy(kept, fs.use, 3 * fs.n);
	for (i = 0; i < 3 * fs.n; i++)
		used += fs.use[i];
	if (used < 3 * FINISH_MIN_PIXELS)
		goto out;
	/* The floor seen in reflections has the student's finish too: with
	 * the scene's in the first fit, with the first fit's in the second
	 * (kr 0.259 for 0.25 in the first, where spheres mirror the floor). */
	finish_fit(&fs, tmp, own, job);
	if (job->n_floor_finishes > 0) {
		struct material first = job->floor_finishes[job->n_floor_finishes - 1];

		finish_trace(job, &with, &first, FINISH_R, px, &fs);
		memcpy(fs.use, kept, 3 * fs.n);
		finish_fit(&fs, tmp, own, job);
	}
out:
	rt_free(px);
	rt_free(tmp);
	rt_free(kept);
	rt_free(fs.basis);
	rt_free(fs.target);
	rt_free(fs.use);
	return rc < 0 ? rc : 0;
}
