/* The functions by which accel.c calls a file of SIMD walks
 * (accel_walk_avx2.c, accel_walk_avx512.c), written once: the including
 * file defines ACCEL_EXPORT(name), the names they get (accel_tree.h
 * declares them), and, where it was compiled for its instructions,
 * ACCEL_WALK(name), the names of its walks, and ACCEL_COMPILED.  Compiled
 * without its instructions, it has stubs that accel_walk_usable never
 * lets run (and asks the processor itself, in accel.c, compiled for the
 * baseline). */
#include <stdbool.h>
#include <stdint.h>

#include "accel/accel_tree.h"

#ifdef ACCEL_COMPILED
const struct shape *ACCEL_EXPORT(intersect)(const struct accel *a, const struct ray *r,
					    double t_min, double *t_max)
{
	return ACCEL_WALK(intersect)(a, r, t_min, t_max);
}

bool ACCEL_EXPORT(occluded)(const struct accel *a, const struct ray *r, double t_min,
			    double t_max)
{
	return ACCEL_WALK(occluded)(a, r, t_min, t_max);
}

void ACCEL_EXPORT(intersect_packet)(const struct accel *a, const struct ray *r, int n,
				    const double *t_min, double *t_max, const struct shape **hit)
{
	ACCEL_WALK(intersect_packet)(a, r, n, t_min, t_max, hit);
}

uint32_t ACCEL_EXPORT(occluded_packet)(const struct accel *a, const struct ray *r, int n,
				       const double *t_min, const double *t_max)
{
	return ACCEL_WALK(occluded_packet)(a, r, n, t_min, t_max);
}

void ACCEL_EXPORT(rays_intersect_packet)(const struct accel *a, const struct ray *r, int n,
					 const double *t_min, double *t_max,
					 const struct shape **hit)
{
	RAYS_WALK(intersect_packet)(a, r, n, t_min, t_max, hit);
}

uint32_t ACCEL_EXPORT(rays_occluded_packet)(const struct accel *a, const struct ray *r, int n,
					    const double *t_min, const double *t_max)
{
	return RAYS_WALK(occluded_packet)(a, r, n, t_min, t_max);
}

uint32_t ACCEL_EXPORT(rays_occluded_lanes)(const struct accel *a, const struct ray_packet *p,
					   uint32_t active, const double *t_min,
					   const double *t_max)
{
	return RAYS_WALK(occluded_lanes)(a, p, active, t_min, t_max);
}

void ACCEL_EXPORT(rays_intersect_lanes)(const struct accel *a, const struct ray_packet *p,
					uint32_t active, const double *t_min, double *t_max,
					const struct shape **hit)
{
	RAYS_WALK(intersect_lanes)(a, p, active, t_min, t_max, hit);
}

bool ACCEL_EXPORT(compiled)(void)
{
	return true;
}
#else
const struct shape *ACCEL_EXPORT(intersect)(const struct accel *a, const struct ray *r,
					    double t_min, double *t_max)
{
	(void)a;
	(void)r;
	(void)t_min;
	(void)t_max;
	return NULL;
}

bool ACCEL_EXPORT(occluded)(const struct accel *a, const struct ray *r, double t_min,
			    double t_max)
{
	(void)a;
	(void)r;
	(void)t_min;
	(void)t_max;
	return false;
}

void ACCEL_EXPORT(intersect_packet)(const struct accel *a, const struct ray *r, int n,
				    const double *t_min, double *t_max, const struct shape **hit)
{
	(void)a;
	(void)r;
	(void)n;
	(void)t_min;
	(void)t_max;
	(void)hit;
}

uint32_t ACCEL_EXPORT(occluded_packet)(const struct accel *a, const struct ray *r, int n,
				       const double *t_min, const double *t_max)
{
	(void)a;
	(void)r;
	(void)n;
	(void)t_min;
	(void)t_max;
	return 0;
}

void ACCEL_EXPORT(rays_intersect_packet)(const struct accel *a, const struct ray *r, int n,
					 const double *t_min, double *t_max,
					 const struct shape **hit)
{
	ACCEL_EXPORT(intersect_packet)(a, r, n, t_min, t_max, hit);
}

uint32_t ACCEL_EXPORT(rays_occluded_packet)(const struct accel *a, const struct ray *r, int n,
					    const double *t_min, const double *t_max)
{
	return ACCEL_EXPORT(occluded_packet)(a, r, n, t_min, t_max);
}

uint32_t ACCEL_EXPORT(rays_occluded_lanes)(const struct accel *a, const struct ray_packet *p,
					   uint32_t active, const double *t_min,
					   const double *t_max)
{
	(void)a;
	(void)p;
	(void)active;
	(void)t_min;
	(void)t_max;
	return 0;
}

void ACCEL_EXPORT(rays_intersect_lanes)(const struct accel *a, const struct ray_packet *p,
					uint32_t active, const double *t_min, double *t_max,
					const struct shape **hit)
{
	(void)a;
	(void)p;
	(void)active;
	(void)t_min;
	(void)t_max;
	(void)hit;
}

bool ACCEL_EXPORT(compiled)(void)
{
	return false;
}
#endif
