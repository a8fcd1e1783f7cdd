/* The Whitted sum of shade.c for up to SHADE_LANES hits at once, a hit a
 * vector lane, in the widest instructions the processor has (base/simd.h):
 * for the hits a packet (render_packet.c) shades that need nothing but
 * the plain sum, that is point lights without falloff, a surface without
 * a texture's highlight colour, no glass, and their reflection's colour
 * already known.  Each lane does render_direct's and render_shade_from's
 * operations in their order (the same products, the sums in the lights'
 * order, the same tests written so that a NaN takes the same way, pow
 * called for each lane that needs it), so its colour is theirs to the
 * bit.  For render_packet.c; nothing here allocates or locks. */
#ifndef RT_RENDER_SHADE_LANES_H
#define RT_RENDER_SHADE_LANES_H

#include <stdint.h>

#include "render/shade_hit.h"
#include "whitted/scene.h"

#define SHADE_LANES RENDER_SHADOW_POINTS

/* The hits, a value an array; lanes not in `lanes` are not read. */
struct shade_lanes {
	uint32_t lanes;		/* the hits to shade */
	uint32_t reflects;	/* of them, those adding kr times seen */
	int clamp;		/* clamp each colour to [0, 1] (RT_CLAMP_LEVEL) */
	double base[3][SHADE_LANES];	/* the surface colour C */
	double ka[SHADE_LANES], kd[SHADE_LANES], ks[SHADE_LANES], kr[SHADE_LANES];
	double shininess[SHADE_LANES];
	double refl[3][SHADE_LANES];	/* R, the mirror direction */
	double eps[SHADE_LANES];	/* the offset off the surface */
	double seen[3][SHADE_LANES];	/* the colour the reflection sees */
};

/* The colours of in's lanes into out (a channel an array), lit by the
 * n_lights (at most RENDER_SHADOW_KEPT) point lights, every one without
 * falloff or cone, whose directions and shadow answers pre has; returns
 * how many shadow rays the sum asked about (ray_counts.shadow). */
uint64_t shade_lanes(const struct shade_lanes *in, const struct render_shadows *pre,
		     const struct light *lights, size_t n_lights, double out[3][SHADE_LANES]);

/* One set of instructions' shade_lanes (render_kernels.h). */
typedef uint64_t shade_lanes_fn(const struct shade_lanes *in, const struct render_shadows *pre,
				const struct light *lights, size_t n_lights,
				double out[3][SHADE_LANES]);

#endif
