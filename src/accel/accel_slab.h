/* What every box test of the hierarchy's walks needs of a ray (the walks
 * of accel.c and accel_walk_avx2.c); private to src/accel/. */
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

#endif
