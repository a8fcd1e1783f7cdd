/* The primary rays of a block of pixels, made a row at a time from what
 * the block's rows share: each column's right * u once for the block,
 * each row's up * v once for the row.  Every ray is camera_ray's to the
 * bit (the same operations on the same values, in the same order); only
 * the repeats are gone.  For render_block. */
#ifndef RT_CAMERA_SPAN_H
#define RT_CAMERA_SPAN_H

#include "whitted/camera.h"
#include "whitted/ray.h"
#include "whitted/vec3.h"

/* The widest span, in pixels. */
#define CAMERA_SPAN_MAX 16

struct camera_span {
	int x0, n;				/* the columns [x0, x0 + n) */
	struct vec3 right_u[CAMERA_SPAN_MAX];	/* right * u of each */
};

/* The span of the columns [x0, x1), x1 - x0 in [1, CAMERA_SPAN_MAX]. */
void camera_span_init(struct camera_span *sp, const struct camera *c, int x0, int x1);
/* out[i] = camera_ray(c, sp->x0 + i, py) for i in [0, sp->n). */
void camera_span_rays(const struct camera_span *sp, const struct camera *c, int py,
		      struct ray *out);

#endif
