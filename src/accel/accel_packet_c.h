/* The packet walks' box tests in plain C, ray by ray (accel.c: the SSE2
 * and the portable builds): each ray's entries are accel.c's portable
 * node_entries to the bit, the same arithmetic as the SIMD tests. */
#ifndef RT_ACCEL_PACKET_C_H
#define RT_ACCEL_PACKET_C_H

#include <math.h>
#include <stdint.h>

#include "accel/accel.h"
#include "accel/accel_slab.h"
#include "accel/accel_tree.h"

struct packet_slab {
	struct ray_slab rs[ACCEL_PACKET];
};

static inline void packet_slab_init(struct packet_slab *ps, const struct ray *r, int n)
{
	int i;

	for (i = 0; i < n; i++)
		ray_slab_init(&ps->rs[i], r + i);
}

/* e0[i], e1[i]: ray i's entries into the two children (INFINITY for a
 * miss), for the rays of `mask`; bits of h0, h1 the children met, of n1
 * the rays for which child 1 is strictly nearer. */
static inline void packet_node(const struct bvh_node *node, const struct packet_slab *ps,
			       uint32_t mask, const double *t_min, const double *t_max,
			       double *e0, double *e1, uint32_t *h0, uint32_t *h1, uint32_t *n1)
{
	uint32_t m, hit0 = 0, hit1 = 0, near1 = 0;

	for (m = mask; m; m &= m - 1) {
		int i = __builtin_ctz(m), c, k;
		const struct ray_slab *rs = &ps->rs[i];
		double e[2];

		for (c = 0; c < 2; c++) {
			double lo = t_min[i], hi = t_max[i];
			for (k = 0; k < 3; k++) {
				double t0 = (node->bounds[rs->near[k]][k][c] - rs->o[k]) * rs->inv[k];
				double t1 = (node->bounds[1 - rs->near[k]][k][c] - rs->o[k]) * rs->inv[k];
				lo = t0 > lo ? t0 : lo;
				hi = t1 < hi ? t1 : hi;
			}
			e[c] = lo <= hi ? lo : INFINITY;
		}
		e0[i] = e[0];
		e1[i] = e[1];
		hit0 |= (uint32_t)(e[0] != INFINITY) << i;
		hit1 |= (uint32_t)(e[1] != INFINITY) << i;
		near1 |= (uint32_t)(e[1] < e[0]) << i;
	}
	*h0 = hit0;
	*h1 = hit1;
	*n1 = near1;
}

#endif
