/* The image loop: the job's rectangle cut into 16x16 blocks that threads
 * take from a shared counter, one ray through each pixel's centre, and the
 * conversion of colours to bytes.  The image does not depend on the number
 * of threads. */
#include <pthread.h>
#include <string.h>

#include "render/render_packet.h"
#include "render/samples.h"
#include "scene/scene_impl.h"
#include "whitted/render.h"

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
	long next_block;		/* taken with an atomic add */
	bool packets;		/* render_packets_wanted */
	long blocks_done;
};

#define RENDER_MAX_THREADS 64
/* Threads take square blocks rather than rows: rays that follow each other
 * on a thread then pass through the same part of the scene, so the nodes
 * and shapes they meet are still in the cache (100k primitives, one
 * thread: 1.06 s -> 1.00 s, median of 7). */
#define RENDER_BLOCK 16

struct render_worker {
	struct render_shared *shared;
	struct ray_counts counts;
	pthread_t thread;
};

static bool render_cancelled(const struct render_job *job)
{
	return job->cancel && *job->cancel;
}

/* Renders one block of the job's rectangle, clipped to it. */
static void render_block(const struct render_job *job, struct image *img, long block,
			bool packets, struct ray_counts *counts)
{
	long blocks_x = (job->x1 - job->x0 + RENDER_BLOCK - 1) / RENDER_BLOCK;
	int tx0 = job->x0 + (int)(block % blocks_x) * RENDER_BLOCK;
	int ty0 = job->y0 + (int)(block / blocks_x) * RENDER_BLOCK;
	int tx1 = tx0 + RENDER_BLOCK < job->x1 ? tx0 + RENDER_BLOCK : job->x1;
	int ty1 = ty0 + RENDER_BLOCK < job->y1 ? ty0 + RENDER_BLOCK : job->y1;
	int x, y;

	if (job->samples > 1) {
		render_block_samples(job, img, tx0, ty0, tx1, ty1, counts);
		return;
	}
	if (packets) {
		render_block_packets(job, img, tx0, ty0, tx1, ty1, counts);
		return;
	}
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

static long render_block_count(const struct render_job *job)
{
	return (long)((job->x1 - job->x0 + RENDER_BLOCK - 1) / RENDER_BLOCK) *
	       ((job->y1 - job->y0 + RENDER_BLOCK - 1) / RENDER_BLOCK);
}

/* Renders blocks until none are left or the job is cancelled; only the
 * calling thread reports progress. */
static void render_take_blocks(struct render_worker *w, bool report)
{
	struct render_shared *sh = w->shared;
	const struct render_job *job = sh->job;
	long blocks = render_block_count(job);
	/* Counted on this thread's stack: the workers' records share cache
	 * lines, and bumping them per ray made two threads barely faster
	 * than one. */
	struct ray_counts counts = { 0, 0, 0, 0 };

	while (!render_cancelled(job)) {
		long t = __atomic_fetch_add(&sh->next_block, 1, __ATOMIC_RELAXED);
		long done;
		if (t >= blocks)
			break;
		render_block(job, sh->img, t, sh->packets, &counts);
		done = __atomic_add_fetch(&sh->blocks_done, 1, __ATOMIC_RELAXED);
		if (report && job->progress)
			job->progress(job->progress_ctx, done, blocks);
	}
	w->counts = counts;
}

static void *render_worker_main(void *arg)
{
	render_take_blocks(arg, false);
	return NULL;
}

void render_job_init(struct render_job *job, const struct scene *s, const struct camera *cam,
		     int threads)
{
	memset(job, 0, sizeof(*job));
	job->scene = s;
	job->camera = cam;
	job->settings.recursion = s->recursion;
	job->settings.clamp = RT_CLAMP_LEVEL;
	job->threads = threads;
	job->x1 = job->y1 = cam->size;
}

int render_image(const struct render_job *job, struct image *img,
		 struct ray_counts *counts, struct diag *d)
{
	struct render_worker workers[RENDER_MAX_THREADS];
	struct render_shared shared;
	int threads = job->threads, started = 0, i;
	long blocks;

	if (!job->scene->accel)
		return diag_fail(d, RT_E_INVALID, "the scene was not prepared");
	if (job->x0 < 0 || job->y0 < 0 || job->x1 > job->camera->size || job->y1 > job->camera->size ||
	    job->x0 >= job->x1 || job->y0 >= job->y1 ||
	    img->width != job->x1 - job->x0 || img->height != job->y1 - job->y0)
		return diag_fail(d, RT_E_INVALID, "bad render region");
	if (threads < 1)
		threads = 1;
	if (threads > RENDER_MAX_THREADS)
		threads = RENDER_MAX_THREADS;
	blocks = render_block_count(job);
	if (threads > blocks)
		threads = (int)blocks;
	memset(&shared, 0, sizeof(shared));
	shared.job = job;
	shared.img = img;
	shared.packets = render_packets_wanted(job->scene->accel);
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
	render_take_blocks(&workers[0], true);
	for (i = 1; i <= started; i++)
		pthread_join(workers[i].thread, NULL);
	if (job->progress)
		job->progress(job->progress_ctx, shared.blocks_done, blocks);
	if (counts) {
		memset(counts, 0, sizeof(*counts));
		for (i = 0; i <= started; i++) {
			counts->primary += workers[i].counts.primary;
			counts->shadow += workers[i].counts.shadow;
			counts->reflection += workers[i].counts.reflection;
			counts->refraction += workers[i].counts.refraction;
		}
	}
	if (render_cancelled(job))
		return diag_fail(d, RT_E_INTERRUPTED, "interrupted");
	return 0;
}
