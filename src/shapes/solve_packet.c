/* The packet solvers of the set of instructions in use: one table a set,
 * compiled from solve_kernels.c (base/simd.h). */
#include <stddef.h>

#include "base/simd.h"
#include "shapes/solve_packet.h"

RT_SIMD_TABLES(struct solve_packet_set, solve_kernels, solve_sets);

const struct solve_packet_set *solve_packet_set_of(enum rt_simd s)
{
	return (unsigned)s < RT_SIMD_COUNT ? solve_sets[s] : NULL;
}

static const struct solve_packet_set *chosen(void)
{
	return solve_sets[rt_simd_level()];
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
