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
 * not NULL.  Allocates nothing. */
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
	const volatile sig_atomic_t *cancel;	/* polled per block; may be NULL */
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
	 * compresses a PNG's rows this way). */
	int band_rows;
	void (*band_done)(void *ctx, int band, int thread);
	void *band_ctx;
};

/* A job for the whole image that cam sees (cam->width x cam->height): the scene's
 * recursion level, clamping at every level, `threads` threads, no cancel,
 * no progress.  Callers change what they need after it. */
void render_job_init(struct render_job *job, const struct scene *s, const struct camera *cam,
		     int threads);

/* The largest --samples N (N x N rays a pixel). */
#define RT_MAX_SAMPLES 16

/* Renders into img, which must have the rectangle's size.  Threads take
 * 16x16 blocks from a shared counter; the image does not depend on their number. */
int render_image(const struct render_job *job, struct image *img,
		 struct ray_counts *counts, struct diag *d);

#endif
