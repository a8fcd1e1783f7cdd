/* The packet solvers in one set of instructions (solve_packet_lanes.h):
 * compiled by the Makefile once per set (with its -m flags and
 * -DRT_SIMD_KERNEL=<suffix>) into the table solve_kernels_<suffix>
 * (solve_packet.h). */
#include "base/simd.h"
#include "shapes/solve_packet.h"

#define SOLVE_LANES(name) kernel_solve_##name
#include "shapes/solve_packet_lanes.h"

extern const struct solve_packet_set RT_SIMD_KERNEL_NAME(solve_kernels);
const struct solve_packet_set RT_SIMD_KERNEL_NAME(solve_kernels) = {
	.sphere = kernel_solve_sphere,
	.triangle = kernel_solve_triangle,
	.floor = kernel_solve_floor,
	.floor_cells = kernel_solve_floor_cells,
	.sphere_normal = kernel_solve_sphere_normal,
};
