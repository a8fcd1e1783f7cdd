/* The hierarchy's walks for packets of up to ACCEL_PACKET rays, written
 * once for a set of box tests as accel_walk.h is (and included after it:
 * the AVX2 walk's; the AVX-512 walk's packets go a ray a lane instead,
 * accel_packet_rays.h).  A packet goes down the tree together: a node's boxes are tested
 * for each of its rays, and each child is entered once, for the rays that
 * meet it, in the order the packet's first ray meets them.  Every ray gets
 * what the single-ray walk gives it, to the bit: the nearest hit with the
 * keys' tie rule (accel_walk.h) does not depend on the order shapes are
 * met in, and whether a shadow ray is blocked does not either.  A ray left
 * alone in its packet walks on as a single ray.  Nothing here allocates
 * or locks. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_tree.h"

#include "accel/accel_packet_common.h"

/* Long: a walk's loop: the stack, the children's tests for each ray and the
 * leaves' packet tests share the loop's state, which the single walk keeps
 * whole too. */
static void ACCEL_WALK(intersect_packet)(const struct accel *a, const struct ray *r, int n,
					 const double *t_min, double *t_max,
					 const struct shape **hit)
{
	struct { uintptr_t slot; uint32_t mask; } stack[ACCEL_WALK_STACK + 1];
	struct walk_ray v[ACCEL_PACKET];
	struct walk_best b[ACCEL_PACKET];
	struct packet_shape_rays sr;
	uint32_t all = packet_all(n);
	size_t i;
	int top = 0;

	packet_shape_rays_load(&sr, r, n, t_min);
	for (i = 0; i < ACCEL_PACKET; i++) {
		b[i].t = t_max[i < (size_t)n ? i : 0];
		b[i].hit = NULL;
		b[i].key = 0;
	}
	for (i = 0; i < a->n_unbounded; i++)
		packet_best_test(a->unbounded[i], a->unbounded_key[i], &sr, all, b);
	if (a->n_nodes > 0 && all) {
		for (i = 0; i < (size_t)n; i++) {
			struct ray_slab rs;
			ray_slab_init(&rs, r + i);
			walk_ray_init(&v[i], &rs);
		}
		stack[top].slot = accel_slot_make(0, ACCEL_SLOT_NODE);
		stack[top++].mask = all;
	}
	while (top > 0) {
		const ACCEL_NODE *nd;
		uint32_t mask, child[ACCEL_W] = { 0 }, m;
		double e[ACCEL_W], first[ACCEL_W];
		int order[ACCEL_W], count, k, lead = -1;
		unsigned hits_any;
		uintptr_t slot;

		top--;
		slot = stack[top].slot;
		mask = stack[top].mask;
		if (!accel_slot_is_node(slot)) {
			packet_leaf_nearest(a, slot, &sr, mask, b);
			continue;
		}
		if (!(mask & (mask - 1))) {
			int one = __builtin_ctz(mask);
			ACCEL_WALK(nearest_from)(a, accel_slot_index(slot), &v[one], r + one,
						 t_min[one], &b[one]);
			continue;
		}
		nd = WALK_NODE(a, accel_slot_index(slot));
		for (m = mask; m; m &= m - 1) {
			int ray = __builtin_ctz(m);
			unsigned hits = (unsigned)node_entries(nd, &v[ray], t_min[ray], b[ray].t, e);
			if (hits && lead < 0) {
				lead = ray;
				memcpy(first, e, sizeof(first));
				for (k = 0; k < ACCEL_W; k++)
					if (!(hits >> k & 1))
						first[k] = INFINITY;
			}
			for (; hits; hits &= hits - 1)
				child[__builtin_ctz(hits)] |= (uint32_t)1 << ray;
		}
		if (lead < 0)
			continue;
		/* The children in the lead ray's order, the ones it misses
		 * last; pushed farthest first. */
		for (k = 0, hits_any = 0; k < ACCEL_W; k++)
			hits_any |= (unsigned)(child[k] != 0) << k;
		count = order_children(hits_any, first, order);
		for (k = count - 1; k >= 0; k--) {
			stack[top].slot = nd->slot[order[k]];
			stack[top++].mask = child[order[k]];
		}
	}
	for (i = 0; i < (size_t)n; i++) {
		t_max[i] = b[i].t;
		hit[i] = b[i].hit;
	}
}

/* Whether anything blocks each ray in (t_min[i], t_max[i]): the mask of
 * the rays blocked.
 * Long: a walk's loop, as intersect_packet's. */
static uint32_t ACCEL_WALK(occluded_packet)(const struct accel *a, const struct ray *r, int n,
					    const double *t_min, const double *t_max)
{
	struct { size_t node; uint32_t mask; } stack[ACCEL_WALK_STACK + 1];
	struct walk_ray v[ACCEL_PACKET];
	struct packet_shape_rays sr;
	uint32_t all = packet_all(n), open = all;
	double t[ACCEL_PACKET], t_far[ACCEL_PACKET];
	size_t i;
	int top = 0;

	packet_shape_rays_load(&sr, r, n, t_min);
	for (i = 0; i < ACCEL_PACKET; i++)
		t_far[i] = t_max[i < (size_t)n ? i : 0];
	for (i = 0; i < a->n_unbounded && open; i++) {
		memcpy(t, t_far, sizeof(t));
		open &= ~shape_intersect_packet(a->unbounded[i], &sr.p, open, sr.t_min, t);
	}
	if (a->n_nodes == 0 || !open)
		return all & ~open;
	for (i = 0; i < (size_t)n; i++) {
		struct ray_slab rs;
		ray_slab_init(&rs, r + i);
		walk_ray_init(&v[i], &rs);
	}
	stack[top].node = 0;
	stack[top++].mask = open;
	while (top > 0) {
		const ACCEL_NODE *nd;
		uint32_t mask, child[ACCEL_W] = { 0 }, m;
		int c;

		top--;
		mask = stack[top].mask & open;
		if (!mask)
			continue;
		if (!(mask & (mask - 1))) {
			int one = __builtin_ctz(mask);
			if (ACCEL_WALK(occluded_from)(a, stack[top].node, &v[one], r + one, t_min[one],
						      t_max[one]))
				open &= ~mask;
			continue;
		}
		nd = WALK_NODE(a, stack[top].node);
		for (m = mask; m; m &= m - 1) {
			int ray = __builtin_ctz(m);
			unsigned hits = (unsigned)node_hits(nd, &v[ray], t_min[ray], t_max[ray]);
			for (; hits; hits &= hits - 1)
				child[__builtin_ctz(hits)] |= (uint32_t)1 << ray;
		}
		for (c = 0; c < ACCEL_W; c++) {
			uintptr_t s = nd->slot[c];
			if (!child[c])
				continue;
			if (accel_slot_is_node(s)) {
				stack[top].node = accel_slot_index(s);
				stack[top++].mask = child[c];
				continue;
			}
			open &= ~packet_leaf_any(a, s, &sr, child[c] & open, t_far);
			if (!open)
				return all;
		}
	}
	return all & ~open;
}
