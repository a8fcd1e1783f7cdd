/* The packet solvers in the baseline's instructions (SSE2, or plain C in
 * the portable build), and the choice of the widest set the processor
 * has: solve_packet_avx2.c and solve_packet_avx512.c hold the others. */
#include "base/simd.h"
#include "shapes/solve_packet.h"

#define SOLVE_LANES(name) solve_lanes_base_##name
#include "shapes/solve_packet_lanes.h"

const struct solve_packet_set solve_packet_base = {
	SOLVE_LANES(sphere), SOLVE_LANES(triangle), SOLVE_LANES(floor), SOLVE_LANES(floor_cells),
	SOLVE_LANES(sphere_normal)
};

static const struct solve_packet_set *chosen(void)
{
	switch (rt_simd_level()) {
	case RT_SIMD_AVX512:
		if (solve_packet_avx512.sphere)
			return &solve_packet_avx512;
		/* fall through */
	case RT_SIMD_AVX2:
		if (solve_packet_avx2.sphere)
			return &solve_packet_avx2;
		/* fall through */
	default:
		return &solve_packet_base;
	}
}

uint32_t solve_packet_sphere(const struct ray_packet *p, uint32_t active, struct vec3 centre,
			     double radius_sq, const double *t_min, double *t_max)
{
	return chosen()->sphere(p, active, centre, radius_sq, t_min, t_max);
}

uint32_t solve_packet_triangle(const struct ray_packet *p, uint32_t active, struct vec3 v0,
			       struct vec3 e1, struct vec3 e2, const double *t_min,
			       double *t_max)
{
	return chosen()->triangle(p, active, v0, e1, e2, t_min, t_max);
}

uint32_t solve_packet_floor(const struct ray_packet *p, uint32_t active, int bounded,
			    double half, const double *t_min, double *t_max)
{
	return chosen()->floor(p, active, bounded, half, t_min, t_max);
}

void solve_packet_floor_cells(const double *const p[3], uint32_t active, int shifted,
			      double half, double cell, double *const c[3])
{
	chosen()->floor_cells(p, active, shifted, half, cell, c);
}

void solve_packet_sphere_normal(const double *const p[3], uint32_t active, struct vec3 centre,
				double inv_radius, double *const n[3])
{
	chosen()->sphere_normal(p, active, centre, inv_radius, n);
}
