/* A packet of primary rays made a vector at a time, a ray a lane (in the
 * widest instructions the processor has: base/simd.h), into the layout
 * the walks take (accel_intersect_lanes): each ray camera_span_rays's to
 * the bit (w = forward + (right u + up v), then vec3_normalize's sqrt,
 * test and products, and the near plane's origin), from the products
 * right u and up v that the span and the row share.  For render_packet.c. */
#ifndef RT_RENDER_CAMERA_LANES_H
#define RT_RENDER_CAMERA_LANES_H

#include "whitted/camera.h"
#include "whitted/shape.h"

#define CAMERA_LANES 16

/* Lane i's right u and up v, a coordinate an array. */
struct camera_lanes_in {
	double ru[3][CAMERA_LANES], uv[3][CAMERA_LANES];
};

/* The rays of every lane into out's lanes [0, CAMERA_LANES). */
void camera_lanes(const struct camera *c, const struct camera_lanes_in *in,
		  struct ray_packet *out);

/* One set of instructions' camera_lanes (render_kernels.h). */
typedef void camera_lanes_fn(const struct camera *c, const struct camera_lanes_in *in,
			     struct ray_packet *out);

#endif
