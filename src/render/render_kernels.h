/* The render's vector kernels, one table a set of instructions: written
 * once over base/lanes.h (camera_lanes_lanes.h, hit_lanes_lanes.h,
 * light_dirs_lanes.h, shade_lanes_sum.h) and compiled by the Makefile
 * from render_kernels.c once per set the build has (base/simd.h); each
 * lane does the single rays' arithmetic to the bit. */
#ifndef RT_RENDER_KERNELS_H
#define RT_RENDER_KERNELS_H

#include "base/simd.h"
#include "render/camera_lanes.h"
#include "render/hit_lanes.h"
#include "render/light_dirs.h"
#include "render/shade_lanes.h"

struct render_kernels {
	camera_lanes_fn *camera_lanes;
	struct hit_lanes_set hit;
	light_dirs_fn *light_dirs;
	shade_lanes_fn *shade_lanes;
};

/* The table of set s, or NULL where the build has none (the tests). */
const struct render_kernels *render_kernels_of(enum rt_simd s);
/* The table of the set in use (rt_simd_level). */
const struct render_kernels *render_kernels(void);

#endif
