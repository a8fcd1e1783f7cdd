/* The packets' walks of the four-child tree a ray a lane
 * (accel_packet_rays.h) in the baseline's instructions: SSE2's two lanes,
 * or plain C's one in the portable build.  accel_walk_avx2.c and
 * accel_walk_avx512.c hold the wider ones. */
#include "accel/accel_tree.h"

#define RAYS_WALK(name) rays_base_##name
#include "accel/accel_packet_rays.h"

void accel_rays_intersect_packet(const struct accel *a, const struct ray *r, int n,
				 const double *t_min, double *t_max, const struct shape **hit)
{
	RAYS_WALK(intersect_packet)(a, r, n, t_min, t_max, hit);
}

uint32_t accel_rays_occluded_lanes(const struct accel *a, const struct ray_packet *p,
				   uint32_t active, const double *t_min, const double *t_max)
{
	return RAYS_WALK(occluded_lanes)(a, p, active, t_min, t_max);
}

uint32_t accel_rays_occluded_packet(const struct accel *a, const struct ray *r, int n,
				    const double *t_min, const double *t_max)
{
	return RAYS_WALK(occluded_packet)(a, r, n, t_min, t_max);
}

void accel_rays_intersect_lanes(const struct accel *a, const struct ray_packet *p,
				uint32_t active, const double *t_min, double *t_max,
				const struct shape **hit)
{
	RAYS_WALK(intersect_lanes)(a, p, active, t_min, t_max, hit);
}
