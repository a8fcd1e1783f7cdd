/* The direction, distance and N.L from up to RENDER_SHADOW_POINTS points
 * to one light, a point a vector lane (light_dirs_lanes.h), in the widest
 * instructions the processor has (base/simd.h): each lane's values are
 * the shading's to the bit (vec3_sub, vec3_length, vec3_scale by 1 /
 * dist, vec3_dot), so that a packet's shadow rays and its shading share
 * them.  For render_shadow_packets. */
#ifndef RT_RENDER_LIGHT_DIRS_H
#define RT_RENDER_LIGHT_DIRS_H

#include "whitted/vec3.h"

#define LIGHT_DIRS_LANES 16

/* The points and their normals, a coordinate an array; every lane
 * filled. */
struct light_dirs_points {
	double px[LIGHT_DIRS_LANES], py[LIGHT_DIRS_LANES], pz[LIGHT_DIRS_LANES];
	double nx[LIGHT_DIRS_LANES], ny[LIGHT_DIRS_LANES], nz[LIGHT_DIRS_LANES];
};

struct light_dirs {
	double lx[LIGHT_DIRS_LANES], ly[LIGHT_DIRS_LANES], lz[LIGHT_DIRS_LANES];
	double dist[LIGHT_DIRS_LANES], nl[LIGHT_DIRS_LANES];
};

/* Every lane's direction from the point to the light at pos. */
void light_dirs(const struct light_dirs_points *p, struct vec3 pos, struct light_dirs *out);

/* One set of instructions' light_dirs (the baseline's always there; the
 * others NULL in a file compiled without them). */
extern void (*const light_dirs_base)(const struct light_dirs_points *p, struct vec3 pos,
				     struct light_dirs *out);
extern void (*const light_dirs_avx2)(const struct light_dirs_points *p, struct vec3 pos,
				     struct light_dirs *out);
extern void (*const light_dirs_avx512)(const struct light_dirs_points *p, struct vec3 pos,
				       struct light_dirs *out);

#endif
