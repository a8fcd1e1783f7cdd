/* The hierarchy's walks, nearest hit and any hit, written once for each
 * set of box tests: the file that includes this defines ACCEL_NODE and
 * ACCEL_W, the node type and its width, struct walk_ray, walk_ray_init,
 * node_entries and node_hits (accel.c: SSE2 or plain C over four
 * children; accel_walk_avx2.c and accel_walk_avx512.c: AVX2 and AVX-512
 * over eight) and ACCEL_WALK(name), the names the walks get.
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

#ifndef RT_ACCEL_WALK_COMMON
#define RT_ACCEL_WALK_COMMON

/* At most ACCEL_WIDTH_MAX - 1 children wait for each node on the path
 * down. */
#define ACCEL_WALK_STACK ((ACCEL_WIDTH_MAX - 1) * ACCEL_STACK)
#ifndef ACCEL_PREFETCH
#define ACCEL_PREFETCH 1
#endif

/* Asks for the memory of every child a ray enters before it uses any: a
 * node's lines, a leaf's first shape.  The walks wait mostly on loads
 * that miss the cache (perf, gen-100k: the first box of a node and the
 * first field of a leaf's shape); so they miss together instead of one
 * after another.  slot: the node's slots; node_bytes: the tree's node
 * size. */
static inline void prefetch_children(const struct accel *a, const uint32_t *slot_of,
				     unsigned mask, size_t node_bytes)
{
	for (; ACCEL_PREFETCH && mask; mask &= mask - 1) {
		uintptr_t slot = slot_of[__builtin_ctz(mask)];
		if (accel_slot_is_node(slot)) {
			const char *p = (const char *)a->nodes + accel_slot_index(slot) * node_bytes;
			size_t line;
			for (line = 0; line < node_bytes; line += 64)
				__builtin_prefetch(p + line);
			/* And the last line where a node can end in one the
			 * loop missed: nodes lie at multiples of the lowest
			 * bit of their size from a line's start, so a
			 * 112-byte node from 48 bytes on spans three lines;
			 * a 224-byte one (from 0 or 32) never needs this. */
			if (64 - ((node_bytes & -node_bytes) < 64 ? (node_bytes & -node_bytes) : 64) +
				    node_bytes > (node_bytes + 63) / 64 * 64)
				__builtin_prefetch(p + node_bytes - 1);
		} else if (accel_slot_tag(slot) > 0) {
			__builtin_prefetch(a->bounded[accel_slot_index(slot)]);
		}
	}
}

/* The least double above x (x itself for +inf and NaN): the bound that
 * lets a shape's test report a hit at exactly x. */
static inline double next_up(double x)
{
	uint64_t bits;

	if (!(x < INFINITY))
		return x;
	if (x == 0.0)
		return 4.9406564584124654e-324;	/* the least subnormal */
	memcpy(&bits, &x, sizeof(bits));
	bits += x > 0.0 ? 1 : (uint64_t)-1;
	memcpy(&x, &bits, sizeof(x));
	return x;
}

/* The best hit so far of one ray. */
struct walk_best {
	double t;
	const struct shape *hit;
	uint32_t key;
};

/* Tests shape sh, of key `key`, against the best so far. */
static inline void best_test(struct walk_best *b, const struct shape *sh, uint32_t key,
			     const struct ray *r, double t_min)
{
	double t = b->hit ? next_up(b->t) : b->t;

	if (shape_intersect(sh, r, t_min, &t) && (t < b->t || key < b->key)) {
		b->t = t;
		b->hit = sh;
		b->key = key;
	}
}

static inline void leaf_nearest(const struct accel *a, uintptr_t slot, const struct ray *r,
				double t_min, struct walk_best *b)
{
	size_t pos = accel_slot_index(slot);
	unsigned count = accel_slot_tag(slot), k;

	for (k = 0; k < count; k++)
		best_test(b, a->bounded[pos + k], a->bounded_key[pos + k], r, t_min);
}

/* Whether any shape of a leaf slot is hit within (t_min, t_max). */
static inline bool leaf_occluded(const struct accel *a, uintptr_t slot, const struct ray *r,
				 double t_min, double t_max)
{
	size_t pos = accel_slot_index(slot);
	unsigned count = accel_slot_tag(slot), k;

	for (k = 0; k < count; k++) {
		double t = t_max;
		if (shape_intersect(a->bounded[pos + k], r, t_min, &t))
			return true;
	}
	return false;
}

/* The hit children of a node (mask), nearest first by entry e: how many,
 * their numbers in order[].  Equal entries keep the children's order. */
static inline int order_children(unsigned mask, const double *e, int *order)
{
	int n = 0, c, j;

	for (; mask; mask &= mask - 1) {
		c = __builtin_ctz(mask);
		for (j = n; j > 0 && e[order[j - 1]] > e[c]; j--)
			order[j] = order[j - 1];
		order[j] = c;
		n++;
	}
	return n;
}

#endif

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
