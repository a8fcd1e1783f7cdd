/* The hierarchy's walks for packets of up to ACCEL_PACKET rays, written
 * once for each set of box tests as accel_walk.h is: the file that
 * includes this defines struct packet_slab, packet_slab_init and
 * packet_node (accel_packet_c.h: plain C; accel_walk_avx2.c: AVX2) and
 * ACCEL_WALK(name).
 *
 * Every ray of a packet gets what the single-ray walk gives it, to the
 * bit, ties included, because each ray meets the same nodes and shapes in
 * the same order with the same t_max as it would alone: a ray's box test
 * here is accel_walk.h's, lane by lane, and where the rays of a packet
 * disagree on which child is nearer, the packet visits the children in
 * both orders, each ray only in its own (near child A for the rays that
 * enter A first, then B for those that enter B first and for A's rays
 * that also meet B, then A again for B's rays that also meet A).  Waiting
 * children keep each ray's entry distance, so that a hit found since rules
 * them out ray by ray as it does alone.  Shadow rays need no order: any
 * blocker will do, and whether one is reachable does not depend on the
 * order (t_max does not shrink).  Nothing here allocates or locks. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_tree.h"

/* Tests a leaf's shapes, one after another, for the rays of `mask`: each
 * ray meets them in the order the single-ray walk does. */
static inline void packet_leaf(const struct accel *a, uintptr_t slot, const struct ray *r,
			       uint32_t mask, const double *t_min, double *t_max,
			       const struct shape **hit)
{
	unsigned count = accel_slot_tag(slot), k;
	const struct shape *one = (const struct shape *)slot, *const *sh = &one;
	uint32_t m;

	if (count == 0) {
		if (!one)
			return;
		count = 1;
	} else {
		sh = a->bounded + accel_slot_index(slot);
	}
	for (k = 0; k < count; k++)
		for (m = shape_intersect_packet(sh[k], r, mask, t_min, t_max); m; m &= m - 1)
			hit[__builtin_ctz(m)] = sh[k];
}

/* The rays of `mask` that a leaf's shapes block in (t_min, t_max); t is
 * scratch for the shapes to shrink. */
static inline uint32_t packet_leaf_any(const struct accel *a, uintptr_t slot,
				       const struct ray *r, uint32_t mask, const double *t_min,
				       const double *t_max, double *t)
{
	unsigned count = accel_slot_tag(slot), k;
	const struct shape *one = (const struct shape *)slot, *const *sh = &one;
	uint32_t blocked = 0, m;

	if (count == 0) {
		if (!one)
			return 0;
		count = 1;
	} else {
		sh = a->bounded + accel_slot_index(slot);
	}
	for (k = 0; k < count && mask; k++) {
		for (m = mask; m; m &= m - 1)
			t[__builtin_ctz(m)] = t_max[__builtin_ctz(m)];
		m = shape_intersect_packet(sh[k], r, mask, t_min, t);
		blocked |= m;
		mask &= ~m;
	}
	return blocked;
}

/* The rays of `mask` whose entry is not beyond their t_max. */
static inline uint32_t packet_in_reach(uint32_t mask, const double *entry, const double *t_max)
{
	uint32_t m, keep = 0;

	for (m = mask; m; m &= m - 1) {
		int i = __builtin_ctz(m);
		if (!(entry[i] > t_max[i]))
			keep |= (uint32_t)1 << i;
	}
	return keep;
}

/* The rays' intervals, in arrays of ACCEL_PACKET for the box tests (the
 * lanes past n are never used). */
static inline void packet_copy_in(double *to, const double *from, int n)
{
	int i;

	for (i = 0; i < ACCEL_PACKET; i++)
		to[i] = i < n ? from[i] : 0.0;
}

/* A ray left alone in its packet walks the rest of the subtree as it
 * would alone (accel_walk.h): the packet's box tests would cost as much
 * for one ray as for four. */
static inline void packet_alone(const struct accel *a, size_t node, const struct ray *r,
				uint32_t mask, const double *t_min, double *t_max,
				const struct shape **hit)
{
	int i = __builtin_ctz(mask);
	struct ray_slab rs;
	struct ray_slab_sse v;

	ray_slab_init(&rs, r + i);
	ray_slab_sse_init(&v, &rs);
	hit[i] = ACCEL_WALK(subtree)(a, node, &v, r + i, t_min[i], t_max + i, hit[i]);
}

static void ACCEL_WALK(intersect_packet)(const struct accel *a, const struct ray *r, int n,
					 const double *t_min_in, double *t_max_in,
					 const struct shape **hit)
{
	/* Waiting child j keeps its rays' entries in entry[buf[j]]: the box
	 * test writes them straight into the next two, and a push that wants
	 * them the other way round swaps two indices instead of copying.  At
	 * most two children wait for each node on the path down, so twice the
	 * single walk's stack holds them. */
	struct { uintptr_t slot; uint32_t mask; } stack[2 * ACCEL_STACK];
	double entry[2 * ACCEL_STACK + 2][ACCEL_PACKET];
	int buf[2 * ACCEL_STACK + 2];
	double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET];
	struct packet_slab ps;
	uint32_t all = n >= 32 ? ~(uint32_t)0 : ((uint32_t)1 << n) - 1, mask = all, m;
	size_t node = 0;
	size_t i;
	int top = 0;

	packet_copy_in(t_min, t_min_in, n);
	packet_copy_in(t_max, t_max_in, n);
	for (i = 0; i < (size_t)n; i++)
		hit[i] = NULL;
	for (i = 0; i < a->n_unbounded; i++)
		for (m = shape_intersect_packet(a->unbounded[i], r, all, t_min, t_max); m; m &= m - 1)
			hit[__builtin_ctz(m)] = a->unbounded[i];
	if (a->n_nodes == 0 || !all)
		goto done;
	for (i = 0; i < 2 * ACCEL_STACK + 2; i++)
		buf[i] = (int)i;
	packet_slab_init(&ps, r, n);
	for (;;) {
		const struct bvh_node *nd = &a->nodes[node];
		double *e0 = entry[buf[top]], *e1 = entry[buf[top + 1]];
		uint32_t h0, h1, n1, first0, first1, then0, then1;
		uintptr_t go;

		if (!(mask & (mask - 1))) {
			packet_alone(a, node, r, mask, t_min, t_max, hit);
			goto pop;
		}
		packet_node(nd, &ps, mask, t_min, t_max, e0, e1, &h0, &h1, &n1);
		/* Child 1 is a ray's nearer only when strictly nearer, as alone. */
		first0 = mask & h0 & ~n1;
		first1 = mask & n1 & h1;
		then1 = first1 | (first0 & h1);
		then0 = first1 & h0;
		/* Waiting, deepest first: child 0 for child 1's rays that also
		 * meet it, then child 1 for the rest of its rays. */
		if (first0 && then0) {
			stack[top].slot = nd->slot[0];
			stack[top++].mask = then0;
			stack[top].slot = nd->slot[1];
			stack[top++].mask = then1;
		} else if (first0 && then1) {
			int b = buf[top];
			buf[top] = buf[top + 1];
			buf[top + 1] = b;
			stack[top].slot = nd->slot[1];
			stack[top++].mask = then1;
		} else if (then0) {
			stack[top].slot = nd->slot[0];
			stack[top++].mask = then0;
		}
		if (first0 | first1) {
			mask = first0 ? first0 : first1;
			go = nd->slot[first0 ? 0 : 1];
			if (accel_slot_is_node(go)) {
				node = accel_slot_index(go);
				continue;
			}
			packet_leaf(a, go, r, mask, t_min, t_max, hit);
		}
pop:
		for (;;) {
			if (top == 0)
				goto done;
			top--;
			mask = packet_in_reach(stack[top].mask, entry[buf[top]], t_max);
			if (!mask)
				continue;
			if (accel_slot_is_node(stack[top].slot))
				break;
			packet_leaf(a, stack[top].slot, r, mask, t_min, t_max, hit);
		}
		node = accel_slot_index(stack[top].slot);
	}
done:
	memcpy(t_max_in, t_max, (size_t)n * sizeof(*t_max));
}

/* Whether anything blocks each ray in (t_min[i], t_max[i]): the mask of
 * the rays blocked. */
static uint32_t ACCEL_WALK(occluded_packet)(const struct accel *a, const struct ray *r, int n,
					    const double *t_min_in, const double *t_max_in)
{
	struct { uintptr_t slot; uint32_t mask; } stack[ACCEL_STACK + 1];
	double e0[ACCEL_PACKET], e1[ACCEL_PACKET], t[ACCEL_PACKET];
	double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET];
	struct packet_slab ps;
	uint32_t all = n >= 32 ? ~(uint32_t)0 : ((uint32_t)1 << n) - 1, open = all;
	size_t i;
	int top = 0;

	packet_copy_in(t_min, t_min_in, n);
	packet_copy_in(t_max, t_max_in, n);
	/* t is a copy that the shapes may shrink: a blocker's distance
	 * does not matter here. */
	for (i = 0; i < a->n_unbounded && open; i++) {
		memcpy(t, t_max, (size_t)n * sizeof(*t));
		open &= ~shape_intersect_packet(a->unbounded[i], r, open, t_min, t);
	}
	if (a->n_nodes == 0 || !open)
		return all & ~open;
	packet_slab_init(&ps, r, n);
	stack[top].slot = accel_slot_make(0, ACCEL_SLOT_NODE);
	stack[top++].mask = open;
	while (top > 0) {
		const struct bvh_node *nd;
		uint32_t mask, h[2], n1;
		int c;

		top--;
		mask = stack[top].mask & open;
		if (!mask)
			continue;
		if (!(mask & (mask - 1))) {
			/* Alone: the single walk, as for the nearest hit. */
			int i1 = __builtin_ctz(mask);
			struct ray_slab rs;
			struct ray_slab_sse v;

			ray_slab_init(&rs, r + i1);
			ray_slab_sse_init(&v, &rs);
			if (ACCEL_WALK(occluded_subtree)(a, accel_slot_index(stack[top].slot), &v,
							 r + i1, t_min[i1], t_max[i1]))
				open &= ~mask;
			continue;
		}
		nd = &a->nodes[accel_slot_index(stack[top].slot)];
		packet_node(nd, &ps, mask, t_min, t_max, e0, e1, &h[0], &h[1], &n1);
		for (c = 0; c < 2; c++) {
			uintptr_t s = nd->slot[c];
			uint32_t m = h[c] & mask;
			if (!m)
				continue;
			if (accel_slot_is_node(s)) {
				stack[top].slot = s;
				stack[top++].mask = m;
				continue;
			}
			open &= ~packet_leaf_any(a, s, r, m, t_min, t_max, t);
			if (!open)
				return all;
		}
	}
	return all & ~open;
}
