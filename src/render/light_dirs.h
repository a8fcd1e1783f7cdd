/* The direction, distance and N.L from up to RENDER_SHADOW_POINTS points
 * to one light, a point a vector lane (light_dirs_lanes.h), in the widest
 * instructions the processor has (base/simd.h): each lane's values are
 * the shading's to the bit (vec3_sub, vec3_length, vec3_scale by 1 /
 * dist, vec3_dot), so that a packet's shadow rays and its shading share
 * them; and the shadow rays themselves, as render_direct makes them
 * (from p + eps l along l, to dist - eps), made a vector at a time into
 * the lanes the walks take (accel_occluded_lanes).  For
 * render_shadow_packets. */
#ifndef RT_RENDER_LIGHT_DIRS_H
#define RT_RENDER_LIGHT_DIRS_H

#include <stdint.h>

#include "whitted/shape.h"
#include "whitted/vec3.h"

#define LIGHT_DIRS_LANES 16

/* The points, their normals and offsets, a coordinate an array; every
 * lane filled. */
struct light_dirs_points {
	double px[LIGHT_DIRS_LANES], py[LIGHT_DIRS_LANES], pz[LIGHT_DIRS_LANES];
	double nx[LIGHT_DIRS_LANES], ny[LIGHT_DIRS_LANES], nz[LIGHT_DIRS_LANES];
	double eps[LIGHT_DIRS_LANES];
};

struct light_dirs {
	double lx[LIGHT_DIRS_LANES], ly[LIGHT_DIRS_LANES], lz[LIGHT_DIRS_LANES];
	double dist[LIGHT_DIRS_LANES], nl[LIGHT_DIRS_LANES];
};

/* Each lane's shadow ray: from p + eps l along l, in (eps, dist - eps). */
struct light_rays {
	struct ray_packet p;	/* lanes below LIGHT_DIRS_LANES */
	double t_min[LIGHT_DIRS_LANES], t_max[LIGHT_DIRS_LANES];
};

/* Every lane's direction from the point to the light at pos, and where
 * rays is not NULL its shadow ray; returns the lanes whose shading asks
 * for that ray (dist > eps and not N.L <= 0, as render_direct tests). */
uint32_t light_dirs(const struct light_dirs_points *p, struct vec3 pos, struct light_dirs *out,
		    struct light_rays *rays);

/* One set of instructions' light_dirs (render_kernels.h). */
typedef uint32_t light_dirs_fn(const struct light_dirs_points *p, struct vec3 pos,
			       struct light_dirs *out, struct light_rays *rays);

#endif
