/* Shading from nearest hits found elsewhere, with shadow rays traced in
 * packets: render_packet.c traces a block's primary rays 16 at a time,
 * then the shadow rays of their hits to each light 16 at a time, and
 * shades each pixel from those answers, to the byte what render_trace
 * gives it. */
#ifndef RT_SHADE_HIT_H
#define RT_SHADE_HIT_H

#include <stdbool.h>
#include <stdint.h>

#include "render/light_dirs.h"
#include "render/ray_tree.h"
#include "whitted/render.h"
#include "whitted/shape.h"
#include "whitted/vec3.h"

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
 * blocked; `bit` the point being shaded.  For the first
 * RENDER_SHADOW_KEPT lights, the direction to the light from each point,
 * its distance and N.L, as the shading computes them (the same
 * arithmetic), made once for the shadow rays and the shading both. */
#define RENDER_SHADOW_LIGHTS 32
#define RENDER_SHADOW_KEPT 8
#define RENDER_SHADOW_POINTS 16	/* ACCEL_PACKET, LIGHT_DIRS_LANES */
struct render_shadows {
	uint32_t traced[RENDER_SHADOW_LIGHTS], blocked[RENDER_SHADOW_LIGHTS];
	int bit;
	struct light_dirs dirs[RENDER_SHADOW_KEPT];
};

/* The point of ray r at t on hit (not NULL). */
void render_point_at(const struct ray *r, double t, const struct shape *hit,
		     struct render_point *h);
/* The reflection of the ray that met point h, as the shading makes it. */
static inline void render_bounce(const struct render_point *h, struct ray *out)
{
	out->origin = vec3_add_scaled(h->p, h->refl, h->eps);
	out->dir = h->refl;
}

/* Whether the shading of a point on `hit` at `level` traces a reflection that
 * render_shade_point can take from its caller: a mirror that is not glass
 * (glass's reflection depends on the glass stack and total internal
 * reflection, and is traced by the shading itself). */
static inline bool render_reflects(const struct render_settings *rs, const struct shape *hit,
				   int level)
{
	return level < rs->recursion && hit->mat.kr > 0.0 && !(hit->mat.kt > 0.0);
}

/* The colour render_trace gives ray r at `level` (outside any glass)
 * whose nearest hit is h, with the shadow answers of pre (NULL: each
 * traced here) and, where render_reflects, the colour its reflection
 * (render_bounce) sees, from the caller (NULL: traced here).  The rays it
 * traces are tree's (ray_tree.h), r being of that weight in its pixel
 * (the product of the coefficients along its path). */
struct color render_shade_point_tree(const struct scene *s, const struct render_settings *rs,
				     const struct ray *r, const struct render_point *h, int level,
				     struct render_tree *tree, double weight,
				     const struct render_shadows *pre, const struct color *reflected);
/* render_shade_point_tree with a tree that cuts nothing and no budget:
 * for a scene without glass, whose rays are a chain no longer than the
 * recursion level (the tests' entry). */
struct color render_shade_point(const struct scene *s, const struct render_settings *rs,
				const struct ray *r, const struct render_point *h, int level,
				struct ray_counts *counts, const struct render_shadows *pre,
				const struct color *reflected);

#endif
