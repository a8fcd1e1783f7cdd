/* The hierarchy's two walks, nearest hit and any hit, written once for
 * each set of box tests: the file that includes this defines struct
 * ray_slab_sse, ray_slab_sse_init, node_entries and node_hits (accel.c: SSE2
 * or plain C; accel_walk_avx2.c: AVX2) and ACCEL_WALK(name), the names the
 * walks get.  Closest-hit traversal enters the nearer child first, in the
 * same order as a tree with one box per node would, so equal-distance hits
 * resolve alike; shadow rays stop at the first blocker.  Nothing here
 * allocates or locks per ray. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "accel/accel_slab.h"
#include "accel/accel_tree.h"

/* Tests the shapes of a leaf slot for the nearest hit. */
static inline const struct shape *leaf_intersect(const struct accel *a, uintptr_t slot,
						 const struct ray *r, double t_min, double *t_max,
						 const struct shape *hit)
{
	unsigned count = accel_slot_tag(slot), k;

	if (count == 0) {
		const struct shape *sh = (const struct shape *)slot;
		return sh && shape_intersect(sh, r, t_min, t_max) ? sh : hit;
	}
	for (k = 0; k < count; k++) {
		const struct shape *sh = a->bounded[accel_slot_index(slot) + k];
		if (shape_intersect(sh, r, t_min, t_max))
			hit = sh;
	}
	return hit;
}

/* Whether any shape of a leaf slot is hit within (t_min, t_max). */
static inline bool leaf_occluded(const struct accel *a, uintptr_t slot, const struct ray *r,
				 double t_min, double t_max)
{
	unsigned count = accel_slot_tag(slot), k;
	double t = t_max;

	if (count == 0) {
		const struct shape *sh = (const struct shape *)slot;
		return sh && shape_intersect(sh, r, t_min, &t);
	}
	for (k = 0; k < count; k++) {
		t = t_max;
		if (shape_intersect(a->bounded[accel_slot_index(slot) + k], r, t_min, &t))
			return true;
	}
	return false;
}

/* The nearest-hit walk of the subtree under `node`, the hit so far
 * `hit`, for a ray left alone in its packet (accel_packet.h): the loop of
 * ACCEL_WALK(intersect) below, which keeps its own copy.  Shared, the
 * single walk read the ray's values through a pointer after every shape's
 * call instead of keeping them in registers: fewer instructions, but the
 * course example's render 5-10% slower in paired runs. */
static const struct shape *ACCEL_WALK(subtree)(const struct accel *a, size_t node,
						      const struct ray_slab_sse *vp,
						      const struct ray *r, double t_min,
						      double *t_max, const struct shape *hit)
{
	struct { uintptr_t slot; double entry; } stack[ACCEL_STACK];
	int top = 0;

	for (;;) {
		const struct bvh_node *n = &a->nodes[node];
		double e[2];
		int near = 0, far = 1;

		node_entries(n, vp, t_min, *t_max, e);
		if (e[1] < e[0]) {
			near = 1;
			far = 0;
		}
		if (e[near] != INFINITY) {
			/* The farther child waits on the stack; the nearer one is
			 * entered now, a leaf's shapes tested at once. */
			if (e[far] != INFINITY) {
				stack[top].slot = n->slot[far];
				stack[top++].entry = e[far];
			}
			if (accel_slot_is_node(n->slot[near])) {
				node = accel_slot_index(n->slot[near]);
				continue;
			}
			hit = leaf_intersect(a, n->slot[near], r, t_min, t_max, hit);
		}
		/* Back up to the nearest waiting child that a hit found since has
		 * not ruled out. */
		for (;;) {
			if (top == 0)
				return hit;
			top--;
			if (stack[top].entry > *t_max)
				continue;
			if (accel_slot_is_node(stack[top].slot))
				break;
			hit = leaf_intersect(a, stack[top].slot, r, t_min, t_max, hit);
		}
		node = accel_slot_index(stack[top].slot);
	}
}

static const struct shape *ACCEL_WALK(intersect)(const struct accel *a, const struct ray *r,
						 double t_min, double *t_max)
{
	const struct shape *hit = NULL;
	struct { uintptr_t slot; double entry; } stack[ACCEL_STACK];
	struct ray_slab rs;
	struct ray_slab_sse v;
	uintptr_t node = 0;
	size_t i;
	int top = 0;

	for (i = 0; i < a->n_unbounded; i++)
		if (shape_intersect(a->unbounded[i], r, t_min, t_max))
			hit = a->unbounded[i];
	if (a->n_nodes == 0)
		return hit;
	ray_slab_init(&rs, r);
	ray_slab_sse_init(&v, &rs);
	for (;;) {
		const struct bvh_node *n = &a->nodes[node];
		double e[2];
		int near = 0, far = 1;

		node_entries(n, &v, t_min, *t_max, e);
		if (e[1] < e[0]) {
			near = 1;
			far = 0;
		}
		if (e[near] != INFINITY) {
			/* The farther child waits on the stack; the nearer one is
			 * entered now, a leaf's shapes tested at once. */
			if (e[far] != INFINITY) {
				stack[top].slot = n->slot[far];
				stack[top++].entry = e[far];
			}
			if (accel_slot_is_node(n->slot[near])) {
				node = accel_slot_index(n->slot[near]);
				continue;
			}
			hit = leaf_intersect(a, n->slot[near], r, t_min, t_max, hit);
		}
		/* Back up to the nearest waiting child that a hit found since has
		 * not ruled out. */
		for (;;) {
			if (top == 0)
				return hit;
			top--;
			if (stack[top].entry > *t_max)
				continue;
			if (accel_slot_is_node(stack[top].slot))
				break;
			hit = leaf_intersect(a, stack[top].slot, r, t_min, t_max, hit);
		}
		node = accel_slot_index(stack[top].slot);
	}
}

/* The any-hit walk of the subtree under `node`, for a ray left alone in
 * its packet (accel_packet.h).  The same loop as ACCEL_WALK(occluded)
 * below, which keeps its own copy: calling this from there cost 3% more
 * instructions in the shadow walk (callgrind, cloud-100k). */
static bool ACCEL_WALK(occluded_subtree)(const struct accel *a, size_t node,
					 const struct ray_slab_sse *vp, const struct ray *r,
					 double t_min, double t_max)
{
	uintptr_t stack[ACCEL_STACK];
	int top = 0;

	stack[top++] = node;
	while (top > 0) {
		const struct bvh_node *n = &a->nodes[stack[--top]];
		int hits = node_hits(n, vp, t_min, t_max), c;

		for (c = 0; c < 2; c++) {
			if (!(hits & (1 << c)))
				continue;
			if (accel_slot_is_node(n->slot[c]))
				stack[top++] = accel_slot_index(n->slot[c]);
			else if (leaf_occluded(a, n->slot[c], r, t_min, t_max))
				return true;
		}
	}
	return false;
}

static bool ACCEL_WALK(occluded)(const struct accel *a, const struct ray *r, double t_min,
				 double t_max)
{
	uintptr_t stack[ACCEL_STACK];
	struct ray_slab rs;
	struct ray_slab_sse v;
	size_t i;
	int top = 0;

	for (i = 0; i < a->n_unbounded; i++) {
		double t = t_max;
		if (shape_intersect(a->unbounded[i], r, t_min, &t))
			return true;
	}
	if (a->n_nodes == 0)
		return false;
	ray_slab_init(&rs, r);
	ray_slab_sse_init(&v, &rs);
	stack[top++] = 0;
	while (top > 0) {
		const struct bvh_node *n = &a->nodes[stack[--top]];
		int hits = node_hits(n, &v, t_min, t_max), c;

		/* Any blocker will do, so leaves are tested as they are met and
		 * only nodes wait on the stack. */
		for (c = 0; c < 2; c++) {
			if (!(hits & (1 << c)))
				continue;
			if (accel_slot_is_node(n->slot[c]))
				stack[top++] = accel_slot_index(n->slot[c]);
			else if (leaf_occluded(a, n->slot[c], r, t_min, t_max))
				return true;
		}
	}
	return false;
}
