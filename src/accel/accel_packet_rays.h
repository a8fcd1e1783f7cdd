/* Packets through the four-child tree (the one small scenes get: see
 * accel_build.c) with each child's box tested against all the packet's
 * rays at once, a ray a vector lane (base/lanes.h: eight in one AVX-512
 * register), where the walks of accel_packet.h test a node's children at
 * once for one ray after another.  In a small tree the rays of a coherent
 * packet meet the same few nodes, so a box tested once for all sixteen
 * costs little more than for one.  Written once over base/lanes.h: the
 * including file, compiled for one set of instructions, defines
 * RAYS_WALK(name), the names the walks get.  Each lane does the single
 * walk's arithmetic on the same float boxes (accel.c: entry = max(t_min,
 * the near plane's t), exit = min(t_max, the far plane's t), a NaN
 * constraining nothing), and a shape is tested for the lanes that enter
 * its leaf against their best so far with the keys' tie rule: so each
 * ray's answer is its single walk's to the bit.  Nothing here allocates
 * or locks. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_packet_common.h"
#include "accel/accel_tree.h"
#include "base/lanes.h"

#define LANES ACCEL_PACKET

#ifndef RT_ACCEL_PACKET_RAYS_COMMON
#define RT_ACCEL_PACKET_RAYS_COMMON
/* The packet's rays as the box tests take them, every lane filled. */
struct packet_rays {
	struct packet_shape_rays s;
	double o[3][LANES], inv[3][LANES];
};
#endif

static inline void RAYS_WALK(load)(struct packet_rays *v, const struct ray *r, int n,
				   const double *t_min)
{
	const lv one = lv_set1(1.0), zero = lv_set1(0.0);
	int j;

	packet_shape_rays_load(&v->s, r, n, t_min);
	memcpy(v->o[0], v->s.p.ox, sizeof(v->o[0]));
	memcpy(v->o[1], v->s.p.oy, sizeof(v->o[1]));
	memcpy(v->o[2], v->s.p.oz, sizeof(v->o[2]));
	/* As ray_slab_init: + 0.0 makes -0 take the minimum as its near
	 * plane. */
	for (j = 0; j < LANES; j += LANES_W) {
		lv_store(v->inv[0] + j, lv_div(one, lv_add(lv_load(v->s.p.dx + j), zero)));
		lv_store(v->inv[1] + j, lv_div(one, lv_add(lv_load(v->s.p.dy + j), zero)));
		lv_store(v->inv[2] + j, lv_div(one, lv_add(lv_load(v->s.p.dz + j), zero)));
	}
}

/* The lanes of `mask` entering each child of node nd within (t_min,
 * t_max[lane]) into child[c] (none for an empty slot), and, where entry
 * is not NULL, the entries of the groups of lanes tested.  The four
 * children go together, a group of lanes at a time: their tests are
 * independent, so they overlap, where one child after another waited on
 * each test's chain of maxima and minima. */
static inline void RAYS_WALK(node_lanes)(const struct bvh4_node *nd, const struct packet_rays *v,
					 uint32_t mask, const double *t_max, double (*entry)[LANES],
					 uint32_t child[4])
{
	const lv zero = lv_set1(0.0);
	int j, k, c;

	for (c = 0; c < 4; c++)
		child[c] = 0;
	for (j = 0; j < LANES; j += LANES_W) {
		lv o[3], inv[3], tn, tx;
		lm far_first[3];

		if (!(mask >> j & ((1u << LANES_W) - 1)))
			continue;
		tn = lv_load(v->s.t_min + j);
		tx = lv_load(t_max + j);
		for (k = 0; k < 3; k++) {
			o[k] = lv_load(v->o[k] + j);
			inv[k] = lv_load(v->inv[k] + j);
			far_first[k] = lv_lt(inv[k], zero);
		}
		for (c = 0; c < 4; c++) {
			lv lo = tn, hi = tx;

			if (!nd->slot[c])
				continue;
			for (k = 0; k < 3; k++) {
				lv b0 = lv_set1(nd->lo[k][c]), b1 = lv_set1(nd->hi[k][c]);
				lv t0 = lv_mul(lv_sub(lv_sel(far_first[k], b1, b0), o[k]), inv[k]);
				lv t1 = lv_mul(lv_sub(lv_sel(far_first[k], b0, b1), o[k]), inv[k]);
				lo = lv_max_first(t0, lo);
				hi = lv_min_first(t1, hi);
			}
			if (entry)
				lv_store(entry[c] + j, lo);
			child[c] |= (uint32_t)lm_bits(lv_le(lo, hi)) << j;
		}
	}
	for (c = 0; c < 4; c++)
		child[c] &= mask;
}

static void RAYS_WALK(intersect_packet)(const struct accel *a, const struct ray *r, int n,
					     const double *t_min, double *t_max,
					const struct shape **hit)
{
	struct { uintptr_t slot; uint32_t mask; } stack[ACCEL_WALK_STACK + 1];
	struct packet_rays v;
	struct walk_best b[LANES];
	double bt[LANES];
	uint32_t all = packet_all(n);
	size_t i;
	int top = 0;

	RAYS_WALK(load)(&v, r, n, t_min);
	for (i = 0; i < LANES; i++) {
		b[i].t = t_max[i < (size_t)n ? i : 0];
		b[i].hit = NULL;
		b[i].key = 0;
	}
	for (i = 0; i < a->n_unbounded; i++)
		packet_best_test(a->unbounded[i], a->unbounded_key[i], &v.s, all, b);
	if (a->n_nodes > 0) {
		stack[top].slot = accel_slot_make(0, ACCEL_SLOT_NODE);
		stack[top++].mask = all;
	}
	while (top > 0) {
		const struct bvh4_node *nd;
		uint32_t mask, child[4];
		double e[4][LANES], first[4];
		int order[4], count, c, k, lead;
		unsigned in_any = 0;
		uintptr_t slot;

		top--;
		slot = stack[top].slot;
		mask = stack[top].mask;
		if (!accel_slot_is_node(slot)) {
			packet_leaf_nearest(a, slot, &v.s, mask, b);
			continue;
		}
		nd = &((const struct bvh4_node *)a->nodes)[accel_slot_index(slot)];
		for (i = 0; i < LANES; i++)
			bt[i] = b[i].t;
		RAYS_WALK(node_lanes)(nd, &v, mask, bt, e, child);
		for (c = 0; c < 4; c++)
			in_any |= (unsigned)(child[c] != 0) << c;
		if (!in_any)
			continue;
		/* The children in the order the packet's first ray meets
		 * them (the ones it misses last), pushed farthest first. */
		lead = __builtin_ctz(mask);
		for (c = 0; c < 4; c++)
			first[c] = child[c] >> lead & 1 ? e[c][lead] : INFINITY;
		count = order_children(in_any, first, order);
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

static uint32_t RAYS_WALK(occluded_packet)(const struct accel *a, const struct ray *r, int n,
					   const double *t_min, const double *t_max)
{
	struct { size_t node; uint32_t mask; } stack[ACCEL_WALK_STACK + 1];
	struct packet_rays v;
	uint32_t all = packet_all(n), open = all;
	double t[LANES], t_far[LANES];
	size_t i;
	int top = 0;

	RAYS_WALK(load)(&v, r, n, t_min);
	for (i = 0; i < LANES; i++)
		t_far[i] = t_max[i < (size_t)n ? i : 0];
	for (i = 0; i < a->n_unbounded && open; i++) {
		memcpy(t, t_far, sizeof(t));
		open &= ~shape_intersect_packet(a->unbounded[i], &v.s.p, open, v.s.t_min, t);
	}
	if (a->n_nodes == 0 || !open)
		return all & ~open;
	stack[top].node = 0;
	stack[top++].mask = open;
	while (top > 0) {
		const struct bvh4_node *nd;
		uint32_t mask, child[4];
		int c;

		top--;
		mask = stack[top].mask & open;
		if (!mask)
			continue;
		nd = &((const struct bvh4_node *)a->nodes)[stack[top].node];
		RAYS_WALK(node_lanes)(nd, &v, mask, t_far, NULL, child);
		for (c = 0; c < 4; c++) {
			uintptr_t s = nd->slot[c];
			uint32_t in = child[c] & open;

			if (!in)
				continue;
			if (accel_slot_is_node(s)) {
				stack[top].node = accel_slot_index(s);
				stack[top++].mask = in;
				continue;
			}
			open &= ~packet_leaf_any(a, s, &v.s, in, t_far);
			if (!open)
				return all;
		}
	}
	return all & ~open;
}
#undef LANES
