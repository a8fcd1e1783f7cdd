/* What every walk of the hierarchy shares, whatever its node and its box
 * tests (accel_walk.h, accel_packet.h, accel_packet_rays.h): the
 * prefetch, the best hit so far and the tie rule, the leaves' tests and
 * the children's order. */
#ifndef RT_ACCEL_WALK_COMMON
#define RT_ACCEL_WALK_COMMON

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel_slab.h"
#include "accel/accel_tree.h"


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
