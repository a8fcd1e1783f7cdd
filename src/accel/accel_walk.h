/* The hierarchy's walks, nearest hit and any hit, written once for each
 * set of box tests: the file that includes this defines ACCEL_NODE and
 * ACCEL_W, the node type and its width, struct walk_ray, walk_ray_init,
 * node_entries and node_hits (walk_base.h: SSE2 or plain C over four
 * children; walk_avx2.h and walk_avx512.h: AVX2 and AVX-512 over eight,
 * each compiled in accel_kernels.c for its set) and ACCEL_WALK(name), the names the walks get.
 *
 * The nearest hit is the nearest t, and on an exact tie the shape with
 * the lower key (accel_tree.h): a shape that ties the best so far is
 * tested up to one step past its t (next_up), and kept only if its key is
 * lower.  So the answer is a plain loop's over the scene, whatever order
 * the walk meets the shapes in.  The walk enters the nearest child first
 * and skips a waiting child once a hit is nearer than its entry (a child
 * entered exactly at the hit's t may still hold a tie).  Shadow rays stop
 * at the first blocker.  Nothing here allocates or locks per ray. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel_slab.h"
#include "accel/accel_tree.h"
#include "accel/accel_walk_common.h"

/* Node i of the tree the including file walks. */
#define WALK_NODE(a, i) (&((const ACCEL_NODE *)(a)->nodes)[i])

/* The nearest hit under node `node` for one ray, from the best so far. */
static inline __attribute__((always_inline)) void
ACCEL_WALK(nearest_from)(const struct accel *a, size_t node, const struct walk_ray *v,
			 const struct ray *r, double t_min, struct walk_best *best)
{
	struct { uintptr_t slot; double entry; } stack[ACCEL_WALK_STACK];
	struct walk_best b = *best;
	uintptr_t slot;
	int top = 0;

	for (;;) {
		const ACCEL_NODE *n = WALK_NODE(a, node);
		double e[ACCEL_W];
		int mask = node_entries(n, v, t_min, b.t, e);

		if (mask) {
			int order[ACCEL_W], k = 1, count;
			prefetch_children(a, n->slot, (unsigned)mask, sizeof(*n));
			if (mask & (mask - 1)) {
				/* The farther children wait, farthest deepest. */
				count = order_children((unsigned)mask, e, order);
				for (k = count - 1; k > 0; k--) {
					stack[top].slot = n->slot[order[k]];
					stack[top++].entry = e[order[k]];
				}
			} else {
				order[0] = __builtin_ctz((unsigned)mask);
			}
			slot = n->slot[order[0]];
			if (accel_slot_is_node(slot)) {
				node = accel_slot_index(slot);
				continue;
			}
			leaf_nearest(a, slot, r, t_min, &b);
		}
		/* Back up to the nearest waiting child that a hit found since
		 * has not ruled out. */
		for (;;) {
			if (top == 0) {
				*best = b;
				return;
			}
			top--;
			if (stack[top].entry > b.t)
				continue;
			slot = stack[top].slot;
			if (accel_slot_is_node(slot))
				break;
			leaf_nearest(a, slot, r, t_min, &b);
		}
		node = accel_slot_index(slot);
	}
}

static const struct shape *ACCEL_WALK(intersect)(const struct accel *a, const struct ray *r,
						 double t_min, double *t_max)
{
	struct walk_best b = { *t_max, NULL, 0 };
	size_t i;

	for (i = 0; i < a->n_unbounded; i++)
		best_test(&b, a->unbounded[i], a->unbounded_key[i], r, t_min);
	if (a->n_nodes > 0) {
		struct ray_slab rs;
		struct walk_ray v;

		ray_slab_init(&rs, r);
		walk_ray_init(&v, &rs);
		ACCEL_WALK(nearest_from)(a, 0, &v, r, t_min, &b);
	}
	*t_max = b.t;
	return b.hit;
}

/* Whether anything under node `node` blocks the ray in (t_min, t_max).
 * Any blocker will do, so leaves are tested as they are met and only
 * nodes wait on the stack. */
static inline __attribute__((always_inline)) bool
ACCEL_WALK(occluded_from)(const struct accel *a, size_t node, const struct walk_ray *v,
			  const struct ray *r, double t_min, double t_max)
{
	size_t stack[ACCEL_WALK_STACK];
	int top = 0;

	stack[top++] = node;
	while (top > 0) {
		const ACCEL_NODE *n = WALK_NODE(a, stack[--top]);
		unsigned mask = (unsigned)node_hits(n, v, t_min, t_max);

		prefetch_children(a, n->slot, mask, sizeof(*n));
		for (; mask; mask &= mask - 1) {
			uintptr_t slot = n->slot[__builtin_ctz(mask)];
			if (accel_slot_is_node(slot))
				stack[top++] = accel_slot_index(slot);
			else if (leaf_occluded(a, slot, r, t_min, t_max))
				return true;
		}
	}
	return false;
}

static bool ACCEL_WALK(occluded)(const struct accel *a, const struct ray *r, double t_min,
				 double t_max)
{
	struct ray_slab rs;
	struct walk_ray v;
	size_t i;

	for (i = 0; i < a->n_unbounded; i++) {
		double t = t_max;
		if (shape_intersect(a->unbounded[i], r, t_min, &t))
			return true;
	}
	if (a->n_nodes == 0)
		return false;
	ray_slab_init(&rs, r);
	walk_ray_init(&v, &rs);
	return ACCEL_WALK(occluded_from)(a, 0, &v, r, t_min, t_max);
}
