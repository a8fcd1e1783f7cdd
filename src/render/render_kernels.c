/* The render's kernels in one set of instructions: compiled by the
 * Makefile once per set (with its -m flags and -DRT_SIMD_KERNEL=<suffix>)
 * into the table render_kernels_<suffix> (render_kernels.h). */
#include "render/render_kernels.h"

#define CAMERA_LANES_FN(name) kernel_camera_##name
#include "render/camera_lanes_lanes.h"
#define HIT_LANES_FN(name) kernel_hit_##name
#include "render/hit_lanes_lanes.h"
#define LIGHT_DIRS(name) kernel_light_##name
#include "render/light_dirs_lanes.h"
#define SHADE_LANES_FN(name) kernel_shade_##name
#include "render/shade_lanes_sum.h"

extern const struct render_kernels RT_SIMD_KERNEL_NAME(render_kernels);
const struct render_kernels RT_SIMD_KERNEL_NAME(render_kernels) = {
	.camera_lanes = kernel_camera_rays,
	.hit = {
		.points = kernel_hit_points,
		.turn = kernel_hit_turn,
		.offsets = kernel_hit_offsets,
		.bounce = kernel_hit_bounce,
	},
	.light_dirs = kernel_light_dirs,
	.shade_lanes = kernel_shade_sum,
};
