/* The renders of the causes: threads share chunks of pixels of every
 * render (a cause in one of its forms), and the reference render. */
#include <math.h>
#include <pthread.h>
#include <string.h>

#include "base/thread.h"
#include "grade/grade_impl.h"
#include "render/shade_rules.h"

#define GRADE_MAX_THREADS 64

struct grade_work {
	const struct grade_job *job;
	const struct grade_variant *variants;
	struct image *imgs;
	struct image *timgs;		/* NULL, or the same colours converted by truncation */
	const uint32_t *pixels;		/* NULL: every pixel */
	size_t n_pixels, chunks;	/* per cause */
	long next, total;
};

#define GRADE_CHUNK 256

/* camera_ray through the point (x + cx, y + cy) of the image, cx = cy =
 * 0.5 being the centre, with camera_ray's own arithmetic (so that a
 * corner on the axis is exactly on it, as in the student's program). */
static struct ray grade_corner_ray(const struct camera *c, int x, int y, double cx, double cy)
{
	double u = (x + cx) * c->pixel_scale_x - c->half_width;
	double v = c->half_height - (y + cy) * c->pixel_scale;
	struct vec3 w = vec3_add(c->forward, vec3_add(vec3_scale(c->right, u), vec3_scale(c->up, v)));
	struct ray r;

	r.origin = c->eye;
	if (c->near > 0.0)
		r.origin = vec3_add_scaled(r.origin, w, c->near);
	r.dir = vec3_normalize(w);
	return r;
}

static struct color grade_sample(const struct grade_work *w, const struct grade_variant *v,
				 const struct ray *r)
{
	return v->use_rules ? shade_rules_trace(w->job->scene, &v->settings, v->rules, r, 1)
			    : render_trace(w->job->scene, &v->settings, r, 1, NULL);
}

/* The colour of pixel (x, y) as the variant renders it, as render_image
 * does: one ray through the centre (or the corner) of the pixel, or with
 * --samples N the mean of the N x N grid's clamped samples (render/
 * samples.c), each moved to its sub-pixel's corner for that cause.  The
 * one place the causes make their pixels. */
static struct color grade_pixel(const struct grade_work *w, const struct grade_variant *v, int x,
				int y)
{
	const struct camera *cam = w->job->camera;
	const int n = w->job->samples > 1 ? w->job->samples : 1;
	struct color sum = color_make(0.0, 0.0, 0.0);
	struct ray r;
	int i, j;

	if (n == 1) {
		r = v->corner ? grade_corner_ray(cam, x, y, v->cx, v->cy) : camera_ray(cam, x, y);
		return grade_sample(w, v, &r);
	}
	for (j = 0; j < n; j++)
		for (i = 0; i < n; i++) {
			r = v->corner ? grade_corner_ray(cam, x, y, (i + v->cx) / n, (j + v->cy) / n)
				      : camera_ray_at(cam, x + (i + 0.5) / n, y + (j + 0.5) / n);
			sum = color_add(sum, color_clamp(grade_sample(w, v, &r)));
		}
	return color_scale(sum, 1.0 / ((double)n * n));
}

/* floor(255 c) of the clamped channel: what (unsigned char)(c * 255)
 * stores, the course's own conversion. */
static uint8_t grade_trunc_channel(double c)
{
	double v = 255.0 * (c < 1.0 ? c : 1.0);

	return v > 0.0 ? (uint8_t)(int)v : 0;
}

/* The byte of a channel never clamped: the low 8 bits of round(255 c) (0
 * below 0, as shade_rules.c's rules_wrap), or of the truncation (int)(255 c)
 * as C converts it, two's complement for a negative value. */
static uint8_t grade_wrap_channel(double c, bool truncate)
{
	double v = 255.0 * c, b;

	if (v != v)
		return 0;
	if (!truncate) {
		b = floor(v + 0.5);
		return b > 0.0 ? (uint8_t)fmod(b, 256.0) : 0;
	}
	b = fmod(trunc(v), 256.0);
	return (uint8_t)(b < 0.0 ? b + 256.0 : b);
}

static void grade_store(const struct grade_variant *v, struct color c, uint8_t *round,
			uint8_t *trunc_out)
{
	if (v->wrap) {
		round[0] = grade_wrap_channel(c.r, false);
		round[1] = grade_wrap_channel(c.g, false);
		round[2] = grade_wrap_channel(c.b, false);
		if (trunc_out) {
			trunc_out[0] = grade_wrap_channel(c.r, true);
			trunc_out[1] = grade_wrap_channel(c.g, true);
			trunc_out[2] = grade_wrap_channel(c.b, true);
		}
		return;
	}
	render_color_to_rgb8(c, round);
	if (trunc_out) {
		trunc_out[0] = grade_trunc_channel(c.r);
		trunc_out[1] = grade_trunc_channel(c.g);
		trunc_out[2] = grade_trunc_channel(c.b);
	}
}

static void grade_render_chunk(const struct grade_work *w, long item)
{
	size_t which = (size_t)item / w->chunks;
	const struct grade_variant *v = &w->variants[which];
	struct image *img = &w->imgs[which], *timg = w->timgs ? &w->timgs[which] : NULL;
	size_t first = ((size_t)item % w->chunks) * GRADE_CHUNK, k;
	size_t last = first + GRADE_CHUNK < w->n_pixels ? first + GRADE_CHUNK : w->n_pixels;

	for (k = first; k < last; k++) {
		uint32_t i = w->pixels ? w->pixels[k] : (uint32_t)k;
		int x = (int)(i % (uint32_t)img->width), y = (int)(i / (uint32_t)img->width);
		grade_store(v, grade_pixel(w, v, x, y), img->pixels + (size_t)i * 3,
			    timg ? timg->pixels + (size_t)i * 3 : NULL);
	}
}

static void *grade_worker(void *arg)
{
	struct grade_work *w = arg;
	const volatile sig_atomic_t *cancel = w->job->cancel;

	while (!(cancel && *cancel)) {
		long item = __atomic_fetch_add(&w->next, 1, __ATOMIC_RELAXED);
		if (item >= w->total)
			break;
		grade_render_chunk(w, item);
	}
	return NULL;
}

int grade_render_causes(const struct grade_job *job, const int *ids, struct image *imgs,
			struct image *timgs, size_t n, const uint32_t *pixels, size_t n_pixels,
			struct diag *d)
{
	struct grade_variant variants[GRADE_MAX_RENDERS];
	pthread_t threads[GRADE_MAX_THREADS];
	struct grade_work w;
	int nthreads = job->threads, started = 0, i;
	size_t k;

	if (n > GRADE_MAX_RENDERS)
		return diag_fail(d, RT_E_INVALID, "too many renders");
	for (k = 0; k < n; k++)
		grade_variant_of(job, ids[k], &variants[k]);
	memset(&w, 0, sizeof(w));
	w.job = job;
	w.variants = variants;
	w.imgs = imgs;
	w.timgs = timgs;
	w.pixels = pixels;
	w.n_pixels = pixels ? n_pixels : (size_t)job->camera->size * (size_t)job->camera->size;
	w.chunks = (w.n_pixels + GRADE_CHUNK - 1) / GRADE_CHUNK;
	w.total = (long)(n * w.chunks);
	if (w.total == 0)
		return 0;
	nthreads = nthreads < 1 ? 1 : nthreads > GRADE_MAX_THREADS ? GRADE_MAX_THREADS : nthreads;
	for (i = 1; i < nthreads; i++) {
		if (rt_thread_start(&threads[i], grade_worker, &w) != 0)
			break;
		started++;
	}
	grade_worker(&w);
	for (i = 1; i <= started; i++)
		pthread_join(threads[i], NULL);
	if (job->cancel && *job->cancel)
		return diag_fail(d, RT_E_INTERRUPTED, "interrupted");
	return 0;
}

int grade_render_reference(const struct grade_job *job, struct image *ref, struct diag *d)
{
	struct render_job rj;
	int rc;

	if ((rc = image_alloc(ref, job->camera->size, job->camera->size, d)) < 0)
		return rc;
	render_job_init(&rj, job->scene, job->camera, job->threads);
	rj.settings = job->settings;
	rj.samples = job->samples > 1 ? job->samples : 1;
	rj.cancel = job->cancel;
	if ((rc = render_image(&rj, ref, NULL, d)) < 0)
		image_free(ref);
	return rc;
}

int grade_cause_image(const struct grade_job *job, const struct image *ref, enum grade_cause c,
		      struct image *out, struct diag *d)
{
	int rc, id = (int)c * GRADE_VARIANTS;

	if (grade_cause_is_transform(c))
		return grade_transform(ref, c, out, d);
	if ((rc = image_alloc(out, ref->width, ref->height, d)) < 0)
		return rc;
	if ((rc = grade_render_causes(job, &id, out, NULL, 1, NULL, 0, d)) < 0)
		image_free(out);
	return rc;
}

int grade_render_truncated(const struct grade_job *job, struct image *out, struct diag *d)
{
	struct image rounded;
	int rc, id = GRADE_PLAIN_RENDER;

	if ((rc = image_alloc(&rounded, job->camera->size, job->camera->size, d)) < 0)
		return rc;
	if ((rc = image_alloc(out, job->camera->size, job->camera->size, d)) == 0 &&
	    (rc = grade_render_causes(job, &id, &rounded, out, 1, NULL, 0, d)) < 0)
		image_free(out);
	image_free(&rounded);
	return rc;
}
