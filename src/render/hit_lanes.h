/* A packet's nearest hits, a value an array (a hit a vector lane), with
 * what the shading needs of each: the values render_point_at gives it
 * (shade_hit.h), to the bit, made with the shapes' packet methods
 * (normal_packet, color_packet: a call a shape of the packet, not three
 * calls a hit) and, for what every shape shares (d.N, N turned to face
 * the ray, the mirror direction, the offset), in the widest instructions
 * the processor has (base/simd.h).  For render_packet.c; nothing here
 * allocates or locks. */
#ifndef RT_RENDER_HIT_LANES_H
#define RT_RENDER_HIT_LANES_H

#include <stdint.h>

#include "render/light_dirs.h"
#include "render/shade_hit.h"
#include "whitted/ray.h"
#include "whitted/shape.h"

#define HIT_LANES LIGHT_DIRS_LANES

/* Every lane filled: a lane not hit holds a copy of the first one hit
 * (where any is), as light_dirs and the vectors read them. */
struct hit_lanes {
	uint32_t hits;			/* the lanes hit */
	uint32_t spec;			/* of them, those whose highlight has spec_color */
	const struct shape *hit[HIT_LANES];
	double t[HIT_LANES];
	struct light_dirs_points pts;	/* p; N turned to face the ray; the offset */
	double refl[3][HIT_LANES];	/* R = d - 2 (d.N) N */
	double dn[HIT_LANES];		/* d.N, at most 0 */
	double base[3][HIT_LANES];	/* the surface colour */
	struct color spec_color[HIT_LANES];
};

/* The hits of r's rays of `active` (bits below HIT_LANES): hit[i] ray
 * i's nearest shape (NULL: none) at t[i]. */
void hit_lanes_fill(const struct ray_packet *r, uint32_t active, const double *t,
		    const struct shape *const *hit, struct hit_lanes *out);
/* Lane i (hit) as render_point_at gives it. */
void hit_lanes_point(const struct hit_lanes *h, int i, struct render_point *out);
/* render_offset of each lane's origin: t_min of rays leaving a surface. */
void hit_lanes_offsets(const struct ray_packet *r, double *t_min);
/* Each lane's reflection as render_bounce makes it (from p + eps R along
 * R), into out's lanes below HIT_LANES. */
void hit_lanes_bounce(const struct hit_lanes *h, struct ray_packet *out);

/* One set of instructions' vector parts (hit_lanes_lanes.h), every lane:
 * points makes the hits' points (lanes not hit copies of the first one)
 * and their rays' directions; turn makes, from the directions d (a coordinate an array) and the
 * normals in out->pts, d.N, N turned, R and, from the points, the
 * offsets; offsets and bounce are the functions above (render_kernels.h). */
struct hit_lanes_set {
	void (*points)(const struct ray_packet *r, const double *t, uint32_t hits,
		       struct light_dirs_points *out, double (*d)[HIT_LANES]);
	void (*turn)(double (*d)[HIT_LANES], struct hit_lanes *out);
	void (*offsets)(const struct ray_packet *r, double *t_min);
	void (*bounce)(const struct hit_lanes *h, struct ray_packet *out);
};

#endif
