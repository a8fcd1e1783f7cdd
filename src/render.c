/* The shading model of scene-format.md (ambient, diffuse, tinted specular,
 * coloured point lights with shadows, recursive reflection, clamping) and
 * the image loop, whose threads take tiles from a shared counter. */
#include <errno.h>
#include <pthread.h>
#include <string.h>

#include "accel.h"
#include "render.h"

/* The offset for rays leaving a surface at p: relative to the size of the
 * coordinates, so that it stays above their rounding error (no acne) and
 * far below anything visible (no leaks). */
static double render_offset(struct vec3 p)
{
	/* Comparisons rather than fmax, which is a library call here; the
	 * same value for every non-NaN coordinate. */
	double m = 1.0, ax = fabs(p.x), ay = fabs(p.y), az = fabs(p.z);

	m = ax > m ? ax : m;
	m = ay > m ? ay : m;
	m = az > m ? az : m;
	return RT_EPSILON * m;
}

/* rl^shininess.  pow is exact for an exponent of 1 (the floor's), so that
 * common case skips the call without changing a bit. */
static double render_specular_power(double rl, double shininess)
{
	return shininess == 1.0 ? rl : pow(rl, shininess);
}

/* Lights handled together; see render_trace. */
#define RENDER_LIGHT_BATCH 8

static bool render_shadowed(const struct scene *s, struct vec3 p, struct vec3 l,
			    double dist, double eps)
{
	struct ray shadow;

	shadow.origin = vec3_add_scaled(p, l, eps);
	shadow.dir = l;
	/* Only blockers nearer than the light count. */
	return accel_occluded(s->accel, &shadow, eps, dist - eps);
}

struct color render_trace(const struct scene *s, const struct render_settings *rs,
			  const struct ray *r, int level, struct ray_counts *counts)
{
	double t = INFINITY, eps = render_offset(r->origin);
	const struct shape *hit = accel_intersect(s->accel, r, eps, &t);
	const struct material *m;
	struct vec3 p, n, refl;
	struct color base, c;
	double dn;
	size_t i, i0;

	if (!hit)
		return color_make(0.0, 0.0, 0.0);
	m = &hit->mat;
	p = ray_at(r, t);
	base = shape_color_at(hit, p);
	c = color_scale(base, m->ka);
	n = shape_normal(hit, p);
	dn = vec3_dot(r->dir, n);
	if (dn > 0.0) {
		n = vec3_neg(n);
		dn = -dn;
	}
	refl = vec3_add_scaled(r->dir, n, -2.0 * dn);
	eps = render_offset(p);
	for (i0 = 0; i0 < s->n_lights; i0 += RENDER_LIGHT_BATCH) {
		size_t nb = s->n_lights - i0 < RENDER_LIGHT_BATCH ? s->n_lights - i0 : RENDER_LIGHT_BATCH;
		struct vec3 l[RENDER_LIGHT_BATCH];
		double dist[RENDER_LIGHT_BATCH], nl[RENDER_LIGHT_BATCH];

		/* The directions to a batch of lights first: their square roots
		 * and divisions then overlap, where one light's used to wait for
		 * the previous light's shadow ray.  (A light at the point gives
		 * an infinite l here, which the test below never uses.) */
		for (i = 0; i < nb; i++) {
			struct vec3 to_light = vec3_sub(s->lights[i0 + i].pos, p);
			dist[i] = vec3_length(to_light);
			l[i] = vec3_scale(to_light, 1.0 / dist[i]);
			nl[i] = vec3_dot(n, l[i]);
		}
		for (i = 0; i < nb; i++) {
			double rl, k;

			if (!(dist[i] > eps))
				continue;
			if (nl[i] <= 0.0)
				continue;
			if (counts)
				counts->shadow++;
			if (render_shadowed(s, p, l[i], dist[i], eps))
				continue;
			k = m->kd * nl[i];
			rl = vec3_dot(refl, l[i]);
			if (rl > 0.0)
				k += m->ks * render_specular_power(rl, m->shininess);
			c = color_add(c, color_scale(color_mul(s->lights[i0 + i].color, base), k));
		}
	}
	if (level < rs->recursion && m->kr > 0.0) {
		struct ray bounce;
		struct color reflected;

		bounce.origin = vec3_add_scaled(p, refl, eps);
		bounce.dir = refl;
		if (counts)
			counts->reflection++;
		reflected = render_trace(s, rs, &bounce, level + 1, counts);
		c = color_add(c, color_scale(reflected, m->kr));
	}
	return rs->clamp == RT_CLAMP_LEVEL ? color_clamp(c) : c;
}

/* lround(255 c) for c in [0, 1], without the library call: v - trunc(v)
 * is exact for v in [0, 255], so comparing it with 0.5 rounds half away
 * from zero exactly as lround does.  NaN gives 0, as lround's result cast
 * to a byte does. */
static uint8_t render_channel(double c)
{
	double v = 255.0 * c;
	int i;

	if (!(v > 0.0))
		return 0;
	i = (int)v;
	return (uint8_t)(i + (v - (double)i >= 0.5));
}

void render_color_to_rgb8(struct color c, uint8_t out[3])
{
	c = color_clamp(c);
	out[0] = render_channel(c.r);
	out[1] = render_channel(c.g);
	out[2] = render_channel(c.b);
}

struct render_shared {
	const struct render_job *job;
	struct image *img;
	long next_tile;		/* taken with an atomic add */
	long tiles_done;
};

#define RENDER_MAX_THREADS 64
/* Threads take square tiles rather than rows: rays that follow each other
 * on a thread then pass through the same part of the scene, so the nodes
 * and shapes they meet are still in the cache (100k primitives, one
 * thread: 1.06 s -> 1.00 s, median of 7). */
#define RENDER_TILE 16

struct render_worker {
	struct render_shared *shared;
	struct ray_counts counts;
	pthread_t thread;
};

static bool render_cancelled(const struct render_job *job)
{
	return job->cancel && *job->cancel;
}

/* Renders one tile of the job's rectangle, clipped to it. */
static void render_tile(const struct render_job *job, struct image *img, long tile,
			struct ray_counts *counts)
{
	long tiles_x = (job->x1 - job->x0 + RENDER_TILE - 1) / RENDER_TILE;
	int tx0 = job->x0 + (int)(tile % tiles_x) * RENDER_TILE;
	int ty0 = job->y0 + (int)(tile / tiles_x) * RENDER_TILE;
	int tx1 = tx0 + RENDER_TILE < job->x1 ? tx0 + RENDER_TILE : job->x1;
	int ty1 = ty0 + RENDER_TILE < job->y1 ? ty0 + RENDER_TILE : job->y1;
	int x, y;

	for (y = ty0; y < ty1; y++) {
		uint8_t *row = img->pixels + (size_t)(y - job->y0) * (size_t)img->width * 3;
		struct ray next = camera_ray(job->camera, tx0, y);
		for (x = tx0; x < tx1; x++) {
			struct ray r = next;
			struct color c;
			/* The next pixel's ray is made before this one is traced:
			 * its square root and division then run beside the trace
			 * instead of holding up the next one. */
			if (x + 1 < tx1)
				next = camera_ray(job->camera, x + 1, y);
			counts->primary++;
			c = render_trace(job->scene, &job->settings, &r, 1, counts);
			render_color_to_rgb8(c, row + (size_t)(x - job->x0) * 3);
		}
	}
}

static long render_tile_count(const struct render_job *job)
{
	return (long)((job->x1 - job->x0 + RENDER_TILE - 1) / RENDER_TILE) *
	       ((job->y1 - job->y0 + RENDER_TILE - 1) / RENDER_TILE);
}

/* Renders tiles until none are left or the job is cancelled; only the
 * calling thread reports progress. */
static void render_take_tiles(struct render_worker *w, bool report)
{
	struct render_shared *sh = w->shared;
	const struct render_job *job = sh->job;
	long tiles = render_tile_count(job);
	/* Counted on this thread's stack: the workers' records share cache
	 * lines, and bumping them per ray made two threads barely faster
	 * than one. */
	struct ray_counts counts = { 0, 0, 0 };

	while (!render_cancelled(job)) {
		long t = __atomic_fetch_add(&sh->next_tile, 1, __ATOMIC_RELAXED);
		long done;
		if (t >= tiles)
			break;
		render_tile(job, sh->img, t, &counts);
		done = __atomic_add_fetch(&sh->tiles_done, 1, __ATOMIC_RELAXED);
		if (report && job->progress)
			job->progress(job->progress_ctx, done, tiles);
	}
	w->counts = counts;
}

static void *render_worker_main(void *arg)
{
	render_take_tiles(arg, false);
	return NULL;
}

int render_image(const struct render_job *job, struct image *img,
		 struct ray_counts *counts, struct diag *d)
{
	struct render_worker workers[RENDER_MAX_THREADS];
	struct render_shared shared;
	int threads = job->threads, started = 0, i;
	long tiles;

	if (!job->scene->accel)
		return diag_set(d, RT_E_INVALID, "", 0, 0, "the scene was not prepared");
	if (job->x0 < 0 || job->y0 < 0 || job->x1 > job->camera->size || job->y1 > job->camera->size ||
	    job->x0 >= job->x1 || job->y0 >= job->y1 ||
	    img->width != job->x1 - job->x0 || img->height != job->y1 - job->y0)
		return diag_set(d, RT_E_INVALID, "", 0, 0, "bad render region");
	if (threads < 1)
		threads = 1;
	if (threads > RENDER_MAX_THREADS)
		threads = RENDER_MAX_THREADS;
	tiles = render_tile_count(job);
	if (threads > tiles)
		threads = (int)tiles;
	memset(&shared, 0, sizeof(shared));
	shared.job = job;
	shared.img = img;
	for (i = 0; i < threads; i++) {
		memset(&workers[i].counts, 0, sizeof(workers[i].counts));
		workers[i].shared = &shared;
	}
	/* The calling thread is worker 0; the others are started here. */
	for (i = 1; i < threads; i++) {
		if (pthread_create(&workers[i].thread, NULL, render_worker_main, &workers[i]) != 0)
			break;
		started++;
	}
	render_take_tiles(&workers[0], true);
	for (i = 1; i <= started; i++)
		pthread_join(workers[i].thread, NULL);
	if (job->progress)
		job->progress(job->progress_ctx, shared.tiles_done, tiles);
	if (counts) {
		memset(counts, 0, sizeof(*counts));
		for (i = 0; i <= started; i++) {
			counts->primary += workers[i].counts.primary;
			counts->shadow += workers[i].counts.shadow;
			counts->reflection += workers[i].counts.reflection;
		}
	}
	if (render_cancelled(job))
		return diag_set(d, RT_E_INTERRUPTED, "", 0, 0, "interrupted");
	return 0;
}
