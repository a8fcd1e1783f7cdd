/* The ray/sphere, ray/triangle and floor tests over a packet's rays
 * (whitted/shape.h's intersect_packet contract: runs of RT_PACKET_RUN, the
 * mask of the rays hit, t_max shrunk for them), each ray's t to the bit
 * the single-ray test's (solve.c, floor.c), in the widest vector
 * instructions the processor has (base/simd.h). */
#ifndef RT_SHAPES_SOLVE_PACKET_H
#define RT_SHAPES_SOLVE_PACKET_H

#include <stdint.h>

#include "base/simd.h"
#include "whitted/shape.h"

uint32_t solve_packet_sphere(const struct ray_packet *p, uint32_t active, struct vec3 centre,
			     double radius_sq, const double *t_min, double *t_max);
uint32_t solve_packet_triangle(const struct ray_packet *p, uint32_t active, struct vec3 v0,
			       struct vec3 e1, struct vec3 e2, const double *t_min,
			       double *t_max);
/* The plane z = 0; where bounded, only its square |x|, |y| < half
 * (half-open, as floor.c's). */
uint32_t solve_packet_floor(const struct ray_packet *p, uint32_t active, int bounded,
			    double half, const double *t_min, double *t_max);

/* The colours of floor.c's untextured checkerboard at the points of
 * `active` (shifted: the square's cells, from -half; else the infinite
 * plane's, from 0), and the sphere's normals: each lane's value the
 * scalar method's to the bit (whitted/shape.h's color_packet and
 * normal_packet contract). */
void solve_packet_floor_cells(const double *const p[3], uint32_t active, int shifted,
			      double half, double cell, double *const c[3]);
void solve_packet_sphere_normal(const double *const p[3], uint32_t active, struct vec3 centre,
				double inv_radius, double *const n[3]);

/* One set of instructions' solvers (solve_packet_lanes.h, compiled per set
 * from solve_kernels.c). */
struct solve_packet_set {
	uint32_t (*sphere)(const struct ray_packet *p, uint32_t active, struct vec3 centre,
			   double radius_sq, const double *t_min, double *t_max);
	uint32_t (*triangle)(const struct ray_packet *p, uint32_t active, struct vec3 v0,
			     struct vec3 e1, struct vec3 e2, const double *t_min, double *t_max);
	uint32_t (*floor)(const struct ray_packet *p, uint32_t active, int bounded, double half,
			  const double *t_min, double *t_max);
	void (*floor_cells)(const double *const p[3], uint32_t active, int shifted, double half,
			    double cell, double *const c[3]);
	void (*sphere_normal)(const double *const p[3], uint32_t active, struct vec3 centre,
			      double inv_radius, double *const n[3]);
};

/* The solvers of set s, or NULL where the build has none (the tests). */
const struct solve_packet_set *solve_packet_set_of(enum rt_simd s);

#endif
