/* The ranking of the causes against a submission: transforms exactly;
 * renders first on a sample (the pixels where the submission differs, and
 * one in 16 of the rest: enough to rank them), then the best three on
 * every pixel, so that a class's images are graded in seconds. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "grade/rank_sample.h"

/* The renders made again on every pixel after the sampled ranking: the
 * best three, but only those within GRADE_FULL_MARGIN dB of the best of
 * all (a transform's exact figure included); the rest keep the sample's
 * estimate, which is enough to rank a cause that far behind, and the
 * full renders are most of the time of an image that differs. */
#define GRADE_FULL_RENDERS 3
#define GRADE_FULL_MARGIN 3.0

/* The figures of ref (and tref, the better kept) transformed by map,
 * against sub; *changes false when the transform leaves ref as it is. */
static int grade_rank_map(const struct image *ref, const struct image *tref,
			  const struct image *sub, const uint8_t *skip, unsigned map,
			  struct grade_figures *f, bool *truncated, bool *changes, struct diag *d)
{
	size_t total = (size_t)ref->width * (size_t)ref->height;
	struct grade_figures g;
	struct image t;
	int rc;

	*truncated = false;
	if ((rc = grade_transform_map(ref, map, &t, d)) < 0)
		return rc;
	*changes = memcmp(t.pixels, ref->pixels, total * 3) != 0;
	grade_figures_skipping(&t, sub, skip, f);
	image_free(&t);
	if (!*changes || !tref)
		return 0;
	if ((rc = grade_transform_map(tref, map, &t, d)) < 0)
		return rc;
	grade_figures_skipping(&t, sub, skip, &g);
	image_free(&t);
	if (g.psnr > f->psnr) {
		*f = g;
		*truncated = true;
	}
	return 0;
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

/* A render to make: a cause (or pair) in one form. */
struct grade_todo {
	struct grade_rank rank;
	struct grade_variant v;
};

/* The renders of the causes: the work of grade_rank_causes, whose
 * images are freed together. */
struct grade_ranking {
	const struct grade_job *job;
	const struct image *ref, *tref, *sub;
	const uint8_t *skip;
	struct grade_sample smp;
	bool exact;			/* small: every pixel, no sample */
	struct grade_todo *todo;
	struct image *imgs, *timgs;
	size_t n_todo, cap;
};

static int grade_todo_add(struct grade_ranking *g, const struct grade_rank *r,
			  const struct grade_variant *v, struct diag *d)
{
	struct grade_todo *t;
	int rc;

	if (g->n_todo == g->cap)
		return diag_fail(d, RT_E_INVALID, "too many renders");
	t = &g->todo[g->n_todo];
	t->rank = *r;
	t->v = *v;
	if ((rc = image_alloc(&g->imgs[g->n_todo], g->ref->width, g->ref->height, d)) < 0 ||
	    (g->tref && (rc = image_alloc(&g->timgs[g->n_todo], g->ref->width, g->ref->height, d)) < 0))
		return rc;
	g->n_todo++;
	return 0;
}

/* Renders the to-dos from first on (on the sample, or every pixel when
 * full), and scores each; a render that equals the reference on what was
 * rendered gets an infinitely bad score (it changes nothing). */
static int grade_todo_run(struct grade_ranking *g, size_t first, bool full, struct diag *d)
{
	size_t total = (size_t)g->ref->width * (size_t)g->ref->height, k;
	bool every = full || g->exact;
	struct grade_variant v[GRADE_MAX_RENDERS];
	int rc;

	for (k = first; k < g->n_todo; k++)
		v[k - first] = g->todo[k].v;
	rc = grade_render_variants(g->job, v, g->imgs + first, g->tref ? g->timgs + first : NULL,
				   g->n_todo - first, every ? NULL : g->smp.pixels,
				   every ? 0 : g->smp.n, d);
	if (rc < 0)
		return rc;
	for (k = first; k < g->n_todo; k++) {
		struct grade_rank *r = &g->todo[k].rank;
		if (every ? memcmp(g->imgs[k].pixels, g->ref->pixels, total * 3) == 0
			  : grade_same_on(&g->smp, &g->imgs[k], g->ref)) {
			r->fig.psnr = -INFINITY;
			continue;
		}
		grade_better_of(every ? NULL : &g->smp, &g->imgs[k], g->tref ? &g->timgs[k] : NULL,
				g->sub, g->skip, &r->fig, &r->truncated);
		r->estimated = !every;
	}
	return 0;
}

/* The best to-do of each cause (or pair) among [first, n_todo), into
 * out (n of them, at most cap: then the cap best). */
static size_t grade_todo_best(const struct grade_ranking *g, size_t first, struct grade_rank *out,
			      size_t *idx, size_t cap)
{
	size_t n = 0, k, j;

	for (k = first; k < g->n_todo; k++) {
		const struct grade_rank *r = &g->todo[k].rank;
		if (r->fig.psnr == -INFINITY)
			continue;
		for (j = 0; j < n && !(out[j].cause == r->cause && out[j].also == r->also); j++)
			;
		if (j == n && n < cap) {
			out[n] = *r;
			idx[n++] = k;
		} else if (j == n && cap > 0) {
			/* Full: the best cap of them, not the first (the pairs of
			 * the likeliest single with every other come first).  An
			 * evicted one cannot come back in a worse form: each
			 * pair's forms are made one after another. */
			size_t worst = 0;
			for (j = 1; j < n; j++)
				worst = out[j].fig.psnr < out[worst].fig.psnr ? j : worst;
			if (r->fig.psnr > out[worst].fig.psnr) {
				out[worst] = *r;
				idx[worst] = k;
			}
		} else if (j < n && (r->fig.psnr > out[j].fig.psnr ||
				     (r->fig.psnr == out[j].fig.psnr &&
				      r->form + r->also_form < out[j].form + out[j].also_form))) {
			/* Its best form; of equals, the earlier forms (the
			 * commoner: the floor's finish rounded as students
			 * write it). */
			out[j] = *r;
			idx[j] = k;
		}
	}
	return n;
}

/* The sort moved ranks r[0..n): find each one's to-do again (from first
 * on), its cause and the other's in the very forms. */
static void grade_todo_find(const struct grade_ranking *g, size_t first,
			    const struct grade_rank *r, size_t *idx, size_t n)
{
	size_t k, j;

	for (k = 0; k < n; k++) {
		for (j = first; j < g->n_todo; j++) {
			const struct grade_rank *t = &g->todo[j].rank;
			if (t->cause == r[k].cause && t->form == r[k].form && t->also == r[k].also &&
			    (t->also == RT_CAUSE_NONE || t->also_form == r[k].also_form))
				break;
		}
		idx[k] = j;
	}
}

/* Renders in full the best few of ranks r[0..n) (sorted) made from
 * renders (index idx[k] of the to-dos), within GRADE_FULL_MARGIN dB of
 * best; their figures become exact. */
static int grade_full_renders(struct grade_ranking *g, struct grade_rank *r, const size_t *idx,
			      size_t n, double best, struct diag *d)
{
	size_t first = g->n_todo, k, made = 0;
	int rc;

	if (g->exact)
		return 0;
	for (k = 0; k < n && made < GRADE_FULL_RENDERS; k++) {
		if (!r[k].estimated || r[k].fig.psnr < best - GRADE_FULL_MARGIN)
			continue;
		if ((rc = grade_todo_add(g, &r[k], &g->todo[idx[k]].v, d)) < 0)
			return rc;
		made++;
	}
	if (made == 0)
		return 0;
	if ((rc = grade_todo_run(g, first, true, d)) < 0)
		return rc;
	for (k = first; k < g->n_todo; k++) {
		size_t j;
		for (j = 0; j < n; j++)
			if (r[j].cause == g->todo[k].rank.cause && r[j].also == g->todo[k].rank.also)
				r[j] = g->todo[k].rank;
	}
	return 0;
}

/* Best first; equal PSNRs in the table's order, a single cause before a
 * pair. */
static int grade_rank_cmp(const void *a, const void *b)
{
	const struct grade_rank *x = a, *y = b;

	if (x->fig.psnr != y->fig.psnr)
		return x->fig.psnr > y->fig.psnr ? -1 : 1;
	if (x->cause != y->cause)
		return (int)x->cause - (int)y->cause;
	return (int)x->also - (int)y->also;
}

/* The compositions of two transforms students' images show: a half turn
 * (the right vector and the up vector both wrong), and a flip or a
 * mirror with red and blue swapped (BMP's row and byte orders). */
static const enum grade_cause grade_transform_pairs[][2] = {
	{ RT_CAUSE_MIRRORED, RT_CAUSE_UPSIDE_DOWN },
	{ RT_CAUSE_UPSIDE_DOWN, RT_CAUSE_RED_BLUE },
	{ RT_CAUSE_MIRRORED, RT_CAUSE_RED_BLUE },
	{ RT_CAUSE_TRANSPOSED, RT_CAUSE_RED_BLUE },
};

static int grade_pair_add(struct grade_ranking *g, enum grade_cause a, int a_form,
			  enum grade_cause b, int b_form, const struct grade_variant *v,
			  struct diag *d)
{
	struct grade_rank r;

	memset(&r, 0, sizeof(r));
	r.cause = a;
	r.form = a_form;
	r.also = b;
	r.also_form = b_form;
	return grade_todo_add(g, &r, v, d);
}

/* A floor cause changes most of the image, so the forms a pair's causes
 * came nearest in alone need not be their best together: two floor
 * causes make one floor (400 wide is no better than 500 with the
 * dialect's cells, and much better with cells of 10), and a floor's own
 * finish hides which form of a spotlight's cone is right (sr20: the
 * spotlights left out alone, the PI macro with the finish).  So each
 * cause's other forms with the other's best (sides: bit 0 y's forms, bit
 * 1 x's), for the GRADE_FLOOR_SWEPT likeliest pairs of two floor causes
 * and the GRADE_FINISH_SWEPT likeliest of the floor's finish with
 * another cause (each sweep is about a dozen renders). */
#define GRADE_FLOOR_SWEPT 2
#define GRADE_FINISH_SWEPT 2
static int grade_floor_pair_forms(struct grade_ranking *g, const struct grade_rank *x,
				  const struct grade_rank *y, unsigned sides, struct diag *d)
{
	const struct grade_rank *fixed[2] = { x, y }, *swept[2] = { y, x };
	struct grade_variant va, vb, v;
	int side, f, rc;

	for (side = 0; side < 2; side++) {
		if (!(sides & (1u << side)) ||
		    !grade_variant_of(g->job, fixed[side]->cause, fixed[side]->form, &va))
			continue;
		for (f = 0; f < GRADE_VARIANTS; f++) {
			if (f == swept[side]->form ||
			    !grade_variant_of(g->job, swept[side]->cause, f, &vb) ||
			    !grade_variant_combine(&va, &vb, &v))
				continue;
			rc = side == 0 ? grade_pair_add(g, x->cause, x->form, y->cause, f, &v, d)
				       : grade_pair_add(g, x->cause, f, y->cause, y->form, &v, d);
			if (rc < 0)
				return rc;
		}
	}
	return 0;
}

/* The singles a pair is made of: the best GRADE_PAIR_FROM of them with
 * one another, and the best with every other (a floor's error can hide
 * a small second cause far down the singles: sr38's white highlight,
 * eighth alone, is 48 dB with the tiles swapped). */
#define GRADE_PAIR_FROM 5
/* A pair is listed only this much nearer than the better of its two
 * causes alone: a second cause that changes nearly nothing is no pair.
 * Long: the pairs made from the best singles, rendered and kept when clearly
 * nearer, over the ranking's one to-do list. */
#define GRADE_PAIR_GAIN 1.0

static int grade_rank_pairs(struct grade_ranking *g, struct grade_rank *out, size_t *n,
			    struct diag *d)
{
	struct grade_rank pairs[GRADE_MAX_PAIRS + GRADE_MAX_PAIRS];
	size_t idx[2 * GRADE_MAX_PAIRS], first = g->n_todo, np, k, j, m = 0;
	size_t from = *n < GRADE_PAIR_FROM ? *n : GRADE_PAIR_FROM;
	int swept = 0, finish_swept = 0, rc;
	unsigned sides;

	/* The transforms' compositions, exactly. */
	for (k = 0; k < sizeof(grade_transform_pairs) / sizeof(grade_transform_pairs[0]); k++) {
		enum grade_cause a = grade_transform_pairs[k][0], b = grade_transform_pairs[k][1];
		struct grade_variant va, vb;
		struct grade_rank r;
		bool changes;
		if (!grade_variant_of(g->job, a, 0, &va) || !grade_variant_of(g->job, b, 0, &vb))
			continue;
		memset(&r, 0, sizeof(r));
		r.cause = a;
		r.also = b;
		if ((rc = grade_rank_map(g->ref, g->tref, g->sub, g->skip, va.map | vb.map, &r.fig,
					 &r.truncated, &changes, d)) < 0)
			return rc;
		if (changes && m < GRADE_MAX_PAIRS)
			pairs[m++] = r;
	}
	/* Two of the likeliest singles at once, each pair in the forms each
	 * cause came nearest in (and two floors in more). */
	for (k = 0; k < from; k++)
		for (j = k + 1; j < (k == 0 ? *n : from); j++) {
			struct grade_variant va, vb, v;
			const struct grade_rank *x = &out[k], *y = &out[j];
			if (x->also != RT_CAUSE_NONE || y->also != RT_CAUSE_NONE)
				continue;
			if (x->cause > y->cause) {
				const struct grade_rank *t = x;
				x = y;
				y = t;
			}
			if (!grade_variant_of(g->job, x->cause, x->form, &va) ||
			    !grade_variant_of(g->job, y->cause, y->form, &vb) ||
			    !grade_variant_combine(&va, &vb, &v))
				continue;
			if (va.map && vb.map)
				continue;	/* two transforms: done exactly above */
			if ((rc = grade_pair_add(g, x->cause, x->form, y->cause, y->form, &v, d)) < 0)
				return rc;
			/* With the floor's finish: its other form (rounded or
			 * as fitted) with every cause, and the other cause's
			 * forms for the likeliest few; two floors apart. */
			sides = 0;
			if ((va.floor_changes | vb.floor_changes) & GRADE_FLOOR_FINISH)
				sides = finish_swept++ < GRADE_FINISH_SWEPT ? 3u
					: vb.floor_changes & GRADE_FLOOR_FINISH ? 1u : 2u;
			else if (va.floor_changes && vb.floor_changes && swept++ < GRADE_FLOOR_SWEPT)
				sides = 3u;
			if (sides && (rc = grade_floor_pair_forms(g, x, y, sides, d)) < 0)
				return rc;
		}
	if ((rc = grade_todo_run(g, first, false, d)) < 0)
		return rc;
	np = grade_todo_best(g, first, pairs + m, idx + m, GRADE_MAX_PAIRS);
	for (k = 0; k < m; k++)
		idx[k] = 0;
	qsort(pairs + m, np, sizeof(pairs[0]), grade_rank_cmp);
	grade_todo_find(g, first, pairs + m, idx + m, np);
	if (np > 0 && (rc = grade_full_renders(g, pairs + m, idx + m, np, pairs[m].fig.psnr, d)) < 0)
		return rc;
	np += m;
	/* A pair counts when it beats each of its causes alone. */
	for (k = 0; k < np && *n < GRADE_MAX_RANKS; k++) {
		double alone = -INFINITY;
		for (j = 0; j < *n; j++)
			if (out[j].also == RT_CAUSE_NONE &&
			    (out[j].cause == pairs[k].cause || out[j].cause == pairs[k].also))
				alone = out[j].fig.psnr > alone ? out[j].fig.psnr : alone;
		if (pairs[k].fig.psnr >= alone + GRADE_PAIR_GAIN)
			out[(*n)++] = pairs[k];
	}
	return 0;
}

/* Long: the ranking's phases (sample, singles, pairs, full renders, order) in
 * sequence over one struct grade_ranking, each a call; what is left is their
 * bookkeeping. */
int grade_rank_causes(const struct grade_job *job, const struct image *ref,
		      const struct image *tref, const struct image *sub, const uint8_t *skip,
		      struct grade_rank out[GRADE_MAX_RANKS], size_t *n, struct diag *d)
{
	struct grade_ranking g;
	struct grade_rank singles[RT_CAUSE_COUNT];
	size_t idx[RT_CAUSE_COUNT], k, ns, total = (size_t)ref->width * (size_t)ref->height;
	double best = -INFINITY;
	int rc = 0, form;

	*n = 0;
	memset(&g, 0, sizeof(g));
	g.job = job;
	g.ref = ref;
	g.tref = tref;
	g.sub = sub;
	g.skip = skip;
	g.exact = total <= GRADE_SAMPLE_MIN_PIXELS;
	g.cap = GRADE_MAX_RENDERS;
	g.todo = rt_calloc(g.cap, sizeof(*g.todo));
	g.imgs = rt_calloc(g.cap, sizeof(*g.imgs));
	g.timgs = rt_calloc(g.cap, sizeof(*g.timgs));
	if (!g.todo || !g.imgs || !g.timgs) {
		rc = diag_fail(d, RT_E_NOMEM, "out of memory for the causes");
		goto out;
	}
	if ((rc = grade_sample_make(ref, sub, skip, &g.smp, d)) < 0)
		goto out;
	for (k = 0; k < RT_CAUSE_COUNT; k++) {
		enum grade_cause c = (enum grade_cause)k;
		for (form = 0; form < GRADE_VARIANTS; form++) {
			struct grade_variant v;
			struct grade_rank r;
			bool changes;
			if (!grade_variant_of(job, c, form, &v))
				continue;
			memset(&r, 0, sizeof(r));
			r.cause = c;
			r.form = form;
			r.also = RT_CAUSE_NONE;
			if (grade_cause_is_transform(c)) {
				if ((rc = grade_rank_map(ref, tref, sub, skip, v.map, &r.fig, &r.truncated,
							 &changes, d)) < 0)
					goto out;
				if (changes)
					out[(*n)++] = r;
				continue;
			}
			if ((rc = grade_todo_add(&g, &r, &v, d)) < 0)
				goto out;
		}
	}
	if ((rc = grade_todo_run(&g, 0, false, d)) < 0)
		goto out;
	ns = grade_todo_best(&g, 0, singles, idx, RT_CAUSE_COUNT);
	qsort(singles, ns, sizeof(singles[0]), grade_rank_cmp);
	grade_todo_find(&g, 0, singles, idx, ns);
	for (k = 0; k < *n; k++)
		best = out[k].fig.psnr > best ? out[k].fig.psnr : best;
	best = ns > 0 && singles[0].fig.psnr > best ? singles[0].fig.psnr : best;
	if ((rc = grade_full_renders(&g, singles, idx, ns, best, d)) < 0)
		goto out;
	memcpy(out + *n, singles, ns * sizeof(singles[0]));
	*n += ns;
	qsort(out, *n, sizeof(out[0]), grade_rank_cmp);
	if (*n > 0 && !out[0].fig.match && (rc = grade_rank_pairs(&g, out, n, d)) < 0)
		goto out;
	qsort(out, *n, sizeof(out[0]), grade_rank_cmp);
	grade_mark_first_equal(out, *n);
out:
	/* Every slot: a failure can leave one allocated past n_todo. */
	for (k = 0; k < g.cap && g.imgs && g.timgs; k++) {
		image_free(&g.imgs[k]);
		image_free(&g.timgs[k]);
	}
	rt_free(g.todo);
	rt_free(g.imgs);
	rt_free(g.timgs);
	rt_free(g.smp.pixels);
	return rc;
}
