/* What every box test of the hierarchy's walks needs of a ray (the walks
 * of walk_base.h, walk_avx2.h and walk_avx512.h); private to src/accel/. */
#ifndef RT_ACCEL_SLAB_H
#define RT_ACCEL_SLAB_H

#include "whitted/ray.h"

/* What the box tests need of a ray, computed once per ray: the reciprocal
 * direction, and for each axis which side of a box the ray meets first, so
 * that the test needs no swap and no branch per axis. */
struct ray_slab {
	double o[3], inv[3];
	int near[3];		/* 0: the minimum is the near plane; 1: the maximum */
};

static inline void ray_slab_init(struct ray_slab *rs, const struct ray *r)
{
	int k;

	rs->o[0] = r->origin.x;
	rs->o[1] = r->origin.y;
	rs->o[2] = r->origin.z;
	/* Adding 0.0 turns -0 into +0, so that a zero component always
	 * takes the minimum as its near plane.  (For a ray running along a
	 * face of a box, one slab value is then NaN, which constrains
	 * nothing, and the other +-inf on the side that keeps the ray.) */
	rs->inv[0] = 1.0 / (r->dir.x + 0.0);
	rs->inv[1] = 1.0 / (r->dir.y + 0.0);
	rs->inv[2] = 1.0 / (r->dir.z + 0.0);
	for (k = 0; k < 3; k++)
		rs->near[k] = rs->inv[k] < 0.0;
}

/* Where a node of `width` children keeps each axis's near and far
 * planes, in floats from its start (lo[3][width], then hi[3][width]): the
 * box tests read a plane with one offset, no swap. */
static inline void ray_slab_offsets(const struct ray_slab *rs, int width, int near_off[3],
				    int far_off[3])
{
	int k;

	for (k = 0; k < 3; k++) {
		near_off[k] = rs->near[k] * 3 * width + width * k;
		far_off[k] = (1 - rs->near[k]) * 3 * width + width * k;
	}
}

#endif
