/* Shading from nearest hits found elsewhere, with shadow rays traced in
 * packets: render_packet.c traces a block's primary rays 16 at a time,
 * then the shadow rays of their hits to each light 16 at a time, and
 * shades each pixel from those answers, to the byte what render_trace
 * gives it. */
#ifndef RT_SHADE_HIT_H
#define RT_SHADE_HIT_H

#include <stdbool.h>
#include <stdint.h>

#include "whitted/render.h"
#include "whitted/shape.h"

/* A ray's nearest hit, and what the shading needs of it. */
struct render_point {
	const struct shape *hit;
	double t;
	struct vec3 p, n, refl;	/* n turned to face the ray; refl its mirror direction */
	double dn, eps;		/* d.n (at most 0); the offset off the surface */
	struct color base, spec_color;
	bool spec;		/* spec_color is the highlight's colour */
};

/* Shadow rays answered in packets, for the first RENDER_SHADOW_LIGHTS
 * lights (the others are traced one at a time): bit b of traced[l] when
 * the ray of point b to light l was traced, of blocked[l] when it was
 * blocked; `bit` the point being shaded. */
#define RENDER_SHADOW_LIGHTS 32
struct render_shadows {
	uint32_t traced[RENDER_SHADOW_LIGHTS], blocked[RENDER_SHADOW_LIGHTS];
	int bit;
};

/* The point of ray r at t on hit (not NULL). */
void render_point_at(const struct ray *r, double t, const struct shape *hit,
		     struct render_point *h);
/* Traces, in packets, the shadow rays that shading points h[b] (those of
 * bits `mask`, at most ACCEL_PACKET of them) will ask for, and fills in
 * *out. */
void render_shadow_packets(const struct scene *s, const struct render_point *h, uint32_t mask,
			   struct render_shadows *out);
/* The colour render_trace gives ray r (level 1) whose nearest hit is h,
 * with the shadow answers of pre (NULL: each traced here). */
struct color render_shade_point(const struct scene *s, const struct render_settings *rs,
				const struct ray *r, const struct render_point *h,
				struct ray_counts *counts, const struct render_shadows *pre);

#endif
