/* The Whitted shading model of scene-format.md and the image loop. */
#ifndef RT_RENDER_H
#define RT_RENDER_H

#include <stdbool.h>
#include <signal.h>
#include <stdint.h>

#include "camera.h"
#include "diag.h"
#include "image.h"
#include "material.h"
#include "ray.h"
#include "scene.h"

enum clamp_mode {
	RT_CLAMP_LEVEL,		/* clamp at every recursion level (the assignment) */
	RT_CLAMP_FINAL,		/* clamp only the finished pixel (POV-Ray) */
};

struct ray_counts {
	uint64_t primary, shadow, reflection;
	uint64_t refraction;	/* the rays glass transmits (--glass) */
};

struct render_settings {
	int recursion;		/* >= 1 */
	enum clamp_mode clamp;
};

/* Self-intersection offset: secondary rays start this far along their
 * direction and hits must lie further than this (scene units). */
#define RT_EPSILON 1e-6

/* The colour seen along a ray with unit direction, at recursion level
 * `level` (a primary ray is level 1).  Counts rays into *counts when it is
 * not NULL.  Allocates nothing.  Its bytes (render_color_to_rgb8) are the
 * whole tree's; a tree over RT_DEFAULT_MAX_RAYS rays is cut short there
 * (render_image fails such a pixel instead). */
struct color render_trace(const struct scene *s, const struct render_settings *rs,
			  const struct ray *r, int level, struct ray_counts *counts);

/* round(255 * clamp(c)) per channel. */
void render_color_to_rgb8(struct color c, uint8_t out[3]);

struct render_job {
	const struct scene *scene;
	const struct camera *camera;
	struct render_settings settings;
	int threads;			/* >= 1 */
	/* The rectangle of the full image to render, end-exclusive; the image
	 * is (x1 - x0) x (y1 - y0). */
	int x0, y0, x1, y1;
	/* Polled every few thousand rays (and at every pixel or packet of
	 * pixels), so that a signal stops even one huge pixel; may be NULL. */
	const volatile sig_atomic_t *cancel;
	/* The most rays the tree of one primary ray (a pixel's, or a sample's)
	 * may have, its reflections and transmissions (0: RT_DEFAULT_MAX_RAYS;
	 * else at least RT_MIN_MAX_RAYS): a pixel that needs more fails the
	 * render with RT_E_RANGE, naming it.  No image is changed by a limit
	 * it does not reach. */
	uint64_t max_rays;
	/* Called now and then with the work done and the total (in blocks of
	 * 16x16 pixels); may be NULL. */
	void (*progress)(void *ctx, long done, long total);
	void *progress_ctx;
	/* Antialiasing: 0 or 1 is one ray through each pixel's centre (the
	 * course's); N > 1 traces the N x N grid of the pixel's sub-pixel
	 * centres and averages them (render/samples.c). */
	int samples;
	/* Told when rows are final: the rectangle's rows, cut into bands of
	 * band_rows rows from its top (the last band may be shorter); when
	 * the last block that covers part of band k is rendered, the thread
	 * that rendered it calls band_done(band_ctx, k, thread), thread in
	 * [0, threads).  Each band is told once (not at all when the render
	 * is cancelled first), calls for different bands may come at the
	 * same time, a thread's own calls one after the other.  No calls
	 * when band_done is NULL or band_rows < 1 (image_png_writer_band_done
	 * compresses a PNG's rows this way).  A promise of the installed API,
	 * not the PNG writer's detail: any program may write or send rows
	 * beside the render with it (a PNG's strips, a socket's stream, a
	 * window), which the image alone at the end cannot give. */
	int band_rows;
	void (*band_done)(void *ctx, int band, int thread);
	void *band_ctx;
};

/* A job for the whole image that cam sees (cam->width x cam->height): the scene's
 * recursion level, clamping at every level, `threads` threads, no cancel,
 * no progress.  Callers change what they need after it. */
void render_job_init(struct render_job *job, const struct scene *s, const struct camera *cam,
		     int threads);

/* The default of render_job's max_rays (--max-rays): 2^20 rays a tree;
 * the least, the longest chain of reflections without glass. */
#define RT_DEFAULT_MAX_RAYS ((uint64_t)1 << 20)
#define RT_MIN_MAX_RAYS RT_MAX_RECURSION

/* The largest --samples N (N x N rays a pixel). */
#define RT_MAX_SAMPLES 16

/* Renders into img, which must have the rectangle's size.  Threads take
 * 16x16 blocks from a shared counter; the image does not depend on their number. */
int render_image(const struct render_job *job, struct image *img,
		 struct ray_counts *counts, struct diag *d);

#endif
