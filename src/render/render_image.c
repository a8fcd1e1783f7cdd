/* The image loop: the job's rectangle cut into 16x16 blocks that threads
 * take from a shared counter, one ray through each pixel's centre (a
 * pixel's rays one tree, ray_tree.h: traced again where what its cut-off
 * left out could change its bytes), the conversion of colours to bytes,
 * and the word that a band of rows is final (for a writer that works
 * beside the render).  The image does not depend on the number of
 * threads.  A signal stops it within a pixel's RENDER_TREE_CHUNK rays (or
 * a packet's pixels); a pixel over the budget stops every thread. */
#include <pthread.h>
#include <stdbool.h>
#include <string.h>

#include "base/alloc.h"
#include "base/thread.h"
#include "render/camera_span.h"
#include "render/render_packet.h"
#include "render/samples.h"
#include "render/shade_math.h"
#include "scene/scene_impl.h"
#include "whitted/render.h"

void render_color_to_rgb8(struct color c, uint8_t out[3])
{
	render_rgb8(c, out);
}

struct render_shared {
	const struct render_job *job;
	struct image *img;
	long next_block;		/* taken with an atomic add */
	bool packets;		/* render_packets_wanted */
	int halt;		/* set once, atomically, by the first pixel over the budget */
	int over_x, over_y;	/* that pixel, written by the thread that set halt */
	long blocks_done;
	long *band_left;		/* blocks not yet rendered per band; NULL: no bands */
	pthread_mutex_t band_lock;	/* over band_left */
};

#define RENDER_MAX_THREADS 64
/* Threads take square blocks rather than rows: rays that follow each other
 * on a thread then pass through the same part of the scene, so the nodes
 * and shapes they meet are still in the cache (100k primitives, one
 * thread: 1.06 s -> 1.00 s, median of 7). */
#define RENDER_BLOCK 16
#if RENDER_BLOCK > CAMERA_SPAN_MAX
#error "a block row must fit in a camera span"
#endif

struct render_worker {
	struct render_shared *shared;
	struct ray_counts counts;
	int index;			/* 0 .. threads - 1 */
	pthread_t thread;
};

static bool render_cancelled(const struct render_job *job)
{
	return job->cancel && *job->cancel;
}

/* Renders one block of the job's rectangle, clipped to it; stops early
 * when the tree stops (its x, y the pixel over the budget). */
static void render_block(const struct render_job *job, struct image *img, long block,
			bool packets, struct render_tree *tree)
{
	long blocks_x = (job->x1 - job->x0 + RENDER_BLOCK - 1) / RENDER_BLOCK;
	int tx0 = job->x0 + (int)(block % blocks_x) * RENDER_BLOCK;
	int ty0 = job->y0 + (int)(block / blocks_x) * RENDER_BLOCK;
	int tx1 = tx0 + RENDER_BLOCK < job->x1 ? tx0 + RENDER_BLOCK : job->x1;
	int ty1 = ty0 + RENDER_BLOCK < job->y1 ? ty0 + RENDER_BLOCK : job->y1;
	struct camera_span span;
	int x, y;

	if (job->samples > 1) {
		render_block_samples(job, img, tx0, ty0, tx1, ty1, packets, tree);
		return;
	}
	if (packets) {
		render_block_packets(job, img, tx0, ty0, tx1, ty1, tree);
		return;
	}
	camera_span_init(&span, job->camera, tx0, tx1);
	for (y = ty0; y < ty1; y++) {
		struct ray rays[RENDER_BLOCK];
		uint8_t bytes[RENDER_BLOCK * 3], *dst;

		/* The row's rays all at once: their square roots and divisions
		 * run side by side, and beside the first traces. */
		camera_span_rays(&span, job->camera, y, rays);
		for (x = tx0; x < tx1; x++) {
			struct color c;

			tree->counts->primary++;
			render_tree_pixel(tree);
			do
				c = render_trace_tree(job->scene, &job->settings, &rays[x - tx0], 1, tree);
			while (render_tree_again(tree, c, 1));
			if (tree->state != RENDER_TREE_GOING) {
				tree->x = x;
				tree->y = y;
				return;
			}
			render_rgb8(c, bytes + (x - tx0) * 3);
		}
		/* The row's 48 bytes go out at once: a block's row shares cache
		 * lines with its neighbours', which another thread is likely
		 * writing at the same time, pixel by pixel.  (A whole row's
		 * constant size makes the copy three moves, not a call.) */
		dst = img->pixels + ((size_t)(y - job->y0) * (size_t)img->width +
				     (size_t)(tx0 - job->x0)) * 3;
		if (tx1 - tx0 == RENDER_BLOCK)
			memcpy(dst, bytes, sizeof(bytes));
		else
			memcpy(dst, bytes, (size_t)(tx1 - tx0) * 3);
	}
}

static long render_block_count(const struct render_job *job)
{
	return (long)((job->x1 - job->x0 + RENDER_BLOCK - 1) / RENDER_BLOCK) *
	       ((job->y1 - job->y0 + RENDER_BLOCK - 1) / RENDER_BLOCK);
}

/* The bands that the rows [r0, r0 + RENDER_BLOCK) of the rectangle
 * (clipped to it) meet. */
static void render_bands_of(const struct render_job *job, int r0, int *b0, int *b1)
{
	int r1 = r0 + RENDER_BLOCK < job->y1 - job->y0 ? r0 + RENDER_BLOCK : job->y1 - job->y0;

	*b0 = r0 / job->band_rows;
	*b1 = (r1 - 1) / job->band_rows;
}

/* Every band's count of the blocks that cover part of it; NULL when the
 * job wants no bands, or there is no memory (then rc is -RT_E_NOMEM). */
static long *render_bands_alloc(const struct render_job *job, int *rc)
{
	int rows = job->y1 - job->y0, r, b, b0, b1;
	long blocks_x = (job->x1 - job->x0 + RENDER_BLOCK - 1) / RENDER_BLOCK;
	long *left;

	*rc = 0;
	if (!job->band_done || job->band_rows < 1 || rows < 1)
		return NULL;
	left = rt_calloc((size_t)(1 + (rows - 1) / job->band_rows), sizeof(*left));
	if (!left) {
		*rc = -RT_E_NOMEM;
		return NULL;
	}
	for (r = 0; r < rows; r += RENDER_BLOCK) {
		render_bands_of(job, r, &b0, &b1);
		for (b = b0; b <= b1; b++)
			left[b] += blocks_x;
	}
	return left;
}

/* Block `block` is rendered: the bands it was the last of are told (a
 * block's 16 rows meet at most 16 bands).  The counts are kept under a
 * lock, taken once a block, so that every thread's pixels of a band are
 * visible to the thread that tells it, as helgrind can see (it does not
 * see the ordering that atomic counts would give). */
static void render_bands_count(struct render_shared *sh, long block, int thread)
{
	const struct render_job *job = sh->job;
	long blocks_x = (job->x1 - job->x0 + RENDER_BLOCK - 1) / RENDER_BLOCK;
	bool finished[RENDER_BLOCK];
	int b, b0, b1;

	render_bands_of(job, (int)(block / blocks_x) * RENDER_BLOCK, &b0, &b1);
	pthread_mutex_lock(&sh->band_lock);
	for (b = b0; b <= b1; b++)
		finished[b - b0] = --sh->band_left[b] == 0;
	pthread_mutex_unlock(&sh->band_lock);
	for (b = b0; b <= b1; b++)
		if (finished[b - b0])
			job->band_done(job->band_ctx, b, thread);
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
	struct render_tree tree;

	render_tree_init(&tree, job->scene, &job->settings, job->max_rays, job->cancel, &sh->halt,
			 &counts);
	while (render_tree_poll(&tree)) {
		long t = __atomic_fetch_add(&sh->next_block, 1, __ATOMIC_RELAXED);
		long done;
		if (t >= blocks)
			break;
		render_block(job, sh->img, t, sh->packets, &tree);
		if (tree.state == RENDER_TREE_OVER) {
			int none = 0;

			if (__atomic_compare_exchange_n(&sh->halt, &none, 1, false, __ATOMIC_ACQ_REL,
							__ATOMIC_ACQUIRE)) {
				sh->over_x = tree.x;
				sh->over_y = tree.y;
			}
			break;
		}
		if (tree.state != RENDER_TREE_GOING)
			break;
		if (sh->band_left)
			render_bands_count(sh, t, w->index);
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
	job->x1 = cam->width;
	job->y1 = cam->height;
}

/* Long: the image loop's set-up, its threads and their join, and the band
 * writer's hand-over, which share the one render_shared. */
int render_image(const struct render_job *job, struct image *img,
		 struct ray_counts *counts, struct diag *d)
{
	struct render_worker workers[RENDER_MAX_THREADS];
	struct render_shared shared;
	int threads = job->threads, started = 0, i, rc;
	long blocks;

	if (!job->scene->accel)
		return diag_fail(d, RT_E_INVALID, "the scene was not prepared");
	if (job->x0 < 0 || job->y0 < 0 || job->x1 > job->camera->width || job->y1 > job->camera->height ||
	    job->x0 >= job->x1 || job->y0 >= job->y1 ||
	    img->width != job->x1 - job->x0 || img->height != job->y1 - job->y0)
		return diag_fail(d, RT_E_INVALID, "bad render region");
	if (job->max_rays && job->max_rays < RT_MIN_MAX_RAYS)
		return diag_fail(d, RT_E_INVALID, "the ray budget must be at least %d, found %llu",
				 RT_MIN_MAX_RAYS, (unsigned long long)job->max_rays);
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
	shared.band_left = render_bands_alloc(job, &rc);
	if (rc < 0)
		return diag_fail(d, RT_E_NOMEM, "out of memory");
	pthread_mutex_init(&shared.band_lock, NULL);
	shared.packets = render_packets_wanted(job->scene->accel);
	for (i = 0; i < threads; i++) {
		memset(&workers[i].counts, 0, sizeof(workers[i].counts));
		workers[i].shared = &shared;
		workers[i].index = i;
	}
	/* The calling thread is worker 0; the others are started here. */
	for (i = 1; i < threads; i++) {
		if (rt_thread_start(&workers[i].thread, render_worker_main, &workers[i]) != 0)
			break;
		started++;
	}
	render_take_blocks(&workers[0], true);
	for (i = 1; i <= started; i++)
		pthread_join(workers[i].thread, NULL);
	pthread_mutex_destroy(&shared.band_lock);
	rt_free(shared.band_left);
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
	if (shared.halt)
		return diag_fail(d, RT_E_RANGE,
				 "pixel %d,%d: a ray's tree of reflections and transmissions through "
				 "glass needs more than %llu rays at recursion %d; --max-rays N allows "
				 "more, a lower recursion needs fewer",
				 shared.over_x, shared.over_y,
				 (unsigned long long)(job->max_rays ? job->max_rays : RT_DEFAULT_MAX_RAYS),
				 job->settings.recursion);
	if (render_cancelled(job))
		return diag_fail(d, RT_E_INTERRUPTED, "interrupted");
	return 0;
}
