/* The renders of the causes: threads share chunks of pixels of every
 * render (a cause in one of its forms), and the reference render. */
#include <math.h>
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

/* The ray through the point (x + cx, y + cy) of the image, cx = cy = 0.5
 * being the centre: camera_ray's own arithmetic (x + cx is exact), so that
 * a corner on the axis is exactly on it, as in the student's program. */
static struct ray grade_corner_ray(const struct camera *c, int x, int y, double cx, double cy)
{
	return camera_ray_at(c, x + cx, y + cy);
}

struct color grade_variant_trace(const struct grade_job *job, const struct grade_variant *v,
				 const struct ray *r)
{
	return v->use_rules ? shade_rules_trace_floor(job->scene, &v->settings, v->rules,
						      v->other_floor ? &v->floor : NULL, r, 1)
			    : render_trace(job->scene, &v->settings, r, 1, NULL);
}

bool grade_variant_traces_plain(const struct grade_job *job, const struct grade_variant *v)
{
	return !v || (!v->use_rules && v->settings.recursion == job->settings.recursion &&
		      v->settings.clamp == job->settings.clamp);
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
		return grade_variant_trace(w->job, v, &r);
	}
	for (j = 0; j < n; j++)
		for (i = 0; i < n; i++) {
			r = v->corner ? grade_corner_ray(cam, x, y, (i + v->cx) / n, (j + v->cy) / n)
				      : camera_ray_at(cam, x + (i + 0.5) / n, y + (j + 0.5) / n);
			sum = color_add(sum, color_clamp(grade_variant_trace(w->job, v, &r)));
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
 * below 0, as shade_rules.c's shade_rules_wrap), or of the truncation (int)(255 c)
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

/* A channel gamma-encoded: the sRGB curve (curve 1) or c^(1/2.2). */
static double grade_gamma(double c, int curve)
{
	c = c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c;
	if (curve == 1)
		return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
	return pow(c, 1.0 / 2.2);
}

struct color grade_variant_encode(const struct grade_variant *v, struct color c)
{
	if (!v->gamma)
		return c;
	return color_make(grade_gamma(c.r, v->gamma), grade_gamma(c.g, v->gamma),
			  grade_gamma(c.b, v->gamma));
}

static void grade_store(const struct grade_variant *v, struct color c, uint8_t *round,
			uint8_t *trunc_out)
{
	c = grade_variant_encode(v, c);
	if (v->map & GRADE_MAP_RED_BLUE)
		c = color_make(c.b, c.g, c.r);
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
		int x = (int)(i % (uint32_t)img->width), y = (int)(i / (uint32_t)img->width), t;
		/* The pixel the map takes this one from. */
		if (v->map & GRADE_MAP_TRANSPOSE) {
			t = x;
			x = y;
			y = t;
		}
		if (v->map & GRADE_MAP_MIRROR)
			x = img->width - 1 - x;
		if (v->map & GRADE_MAP_FLIP)
			y = img->height - 1 - y;
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

int grade_render_variants(const struct grade_job *job, const struct grade_variant *variants,
			  struct image *imgs, struct image *timgs, size_t n,
			  const uint32_t *pixels, size_t n_pixels, struct diag *d)
{
	struct grade_work w;
	int nthreads = job->threads;

	memset(&w, 0, sizeof(w));
	w.job = job;
	w.variants = variants;
	w.imgs = imgs;
	w.timgs = timgs;
	w.pixels = pixels;
	w.n_pixels = pixels ? n_pixels : (size_t)job->camera->width * (size_t)job->camera->height;
	w.chunks = (w.n_pixels + GRADE_CHUNK - 1) / GRADE_CHUNK;
	w.total = (long)(n * w.chunks);
	if (w.total == 0)
		return 0;
	nthreads = nthreads < 1 ? 1 : nthreads > GRADE_MAX_THREADS ? GRADE_MAX_THREADS : nthreads;
	rt_run_shared(nthreads, grade_worker, &w);
	if (job->cancel && *job->cancel)
		return diag_fail(d, RT_E_INTERRUPTED, "interrupted");
	return 0;
}

int grade_render_reference(const struct grade_job *job, struct image *ref, struct diag *d)
{
	struct render_job rj;
	int rc;

	if ((rc = image_alloc(ref, job->camera->width, job->camera->height, d)) < 0)
		return rc;
	render_job_init(&rj, job->scene, job->camera, job->threads);
	rj.settings = job->settings;
	rj.samples = job->samples > 1 ? job->samples : 1;
	rj.cancel = job->cancel;
	if ((rc = render_image(&rj, ref, NULL, d)) < 0)
		image_free(ref);
	return rc;
}

int grade_cause_image(const struct grade_job *job, const struct image *ref,
		      const struct grade_rank *r, struct image *out, struct diag *d)
{
	struct grade_variant v, also;
	int rc;

	if (r->also == RT_CAUSE_NONE && grade_cause_is_transform(r->cause))
		return grade_transform_map(ref, grade_cause_map(r->cause), out, d);
	if (!grade_variant_of(job, r->cause, r->form, &v))
		return diag_fail(d, RT_E_INVALID, "no such form of the cause");
	if (r->also != RT_CAUSE_NONE) {
		struct grade_variant one = v;
		if (!grade_variant_of(job, r->also, r->also_form, &also) ||
		    !grade_variant_combine(&one, &also, &v))
			return diag_fail(d, RT_E_INVALID, "no such pair of causes");
	}
	if ((rc = image_alloc(out, ref->width, ref->height, d)) < 0)
		return rc;
	if ((rc = grade_render_variants(job, &v, out, NULL, 1, NULL, 0, d)) < 0)
		image_free(out);
	return rc;
}

int grade_render_truncated(const struct grade_job *job, struct image *out, struct diag *d)
{
	struct image rounded;
	struct grade_variant plain;
	int rc;

	grade_variant_plain(job, &plain);
	if ((rc = image_alloc(&rounded, job->camera->width, job->camera->height, d)) < 0)
		return rc;
	if ((rc = image_alloc(out, job->camera->width, job->camera->height, d)) == 0 &&
	    (rc = grade_render_variants(job, &plain, &rounded, out, 1, NULL, 0, d)) < 0)
		image_free(out);
	image_free(&rounded);
	return rc;
}

/* The camera c turned by a small angle about its up (yaw) or right axis,
 * or zoomed by the factor 1 + angle. */
static void grade_camera_nudge(const struct camera *c, int which, double angle, struct camera *out)
{
	double cs = cos(angle), sn = sin(angle);

	*out = *c;
	if (which == 0) {
		out->forward = vec3_add(vec3_scale(c->forward, cs), vec3_scale(c->right, sn));
		out->right = vec3_sub(vec3_scale(c->right, cs), vec3_scale(c->forward, sn));
	} else if (which == 1) {
		out->forward = vec3_add(vec3_scale(c->forward, cs), vec3_scale(c->up, sn));
		out->up = vec3_sub(vec3_scale(c->up, cs), vec3_scale(c->forward, sn));
	} else {
		out->half_width *= 1.0 + angle;
		out->half_height *= 1.0 + angle;
		out->pixel_scale *= 1.0 + angle;
		out->pixel_scale_x *= 1.0 + angle;
	}
}

int grade_tie_mask(const struct grade_job *job, const struct image *ref, double angle,
		   uint8_t *mask, long *n_ties, struct diag *d)
{
	struct grade_job nudged = *job;
	struct camera cam;
	struct image img = { 0, 0, NULL };
	size_t total = (size_t)ref->width * (size_t)ref->height, i;
	int k, rc = 0;

	memset(mask, 0, total);
	*n_ties = 0;
	nudged.camera = &cam;
	for (k = 0; k < 6 && rc == 0; k++) {
		grade_camera_nudge(job->camera, k / 2, k % 2 ? -angle : angle, &cam);
		if ((rc = grade_render_reference(&nudged, &img, d)) < 0)
			break;
		for (i = 0; i < total; i++)
			if (memcmp(img.pixels + 3 * i, ref->pixels + 3 * i, 3) != 0 && !mask[i]) {
				mask[i] = 1;
				(*n_ties)++;
			}
		image_free(&img);
	}
	return rc;
}
