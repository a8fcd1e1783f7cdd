/* The hierarchy's layout, shared by its build (accel_build.c) and its
 * traversal (accel.c) and private to them.  A node is 64 bytes: the boxes
 * of both its children (float bounds rounded outwards, so they never cut
 * off a hit, stored child-interleaved so that one SSE2 operation tests
 * both) and what each child is: another node, a leaf's one shape or a
 * leaf's range of shapes. */
#ifndef RT_ACCEL_TREE_H
#define RT_ACCEL_TREE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "whitted/ray.h"
#include "whitted/shape.h"

#define ACCEL_LEAF_MAX 4	/* at most 7: a leaf's size is its slot's tag */
/* Past this depth the build splits at the median, so the depth stays at
 * most ACCEL_SAH_DEPTH + 64 whatever the input, and a stack of
 * ACCEL_STACK entries holds any path's waiting children. */
#define ACCEL_SAH_DEPTH 40
#define ACCEL_STACK 128

/* What a child slot holds, by its low three bits: 0, the one shape of a
 * leaf (a pointer: shapes are at least 8-byte aligned), so that the most
 * common leaf costs no look-up in accel.bounded; 1, a node (index << 3);
 * 2 to ACCEL_LEAF_MAX, a leaf of that many shapes from accel.bounded[slot
 * >> 3].  A null pointer is an empty slot. */
#define ACCEL_SLOT_NODE 1u
#define ACCEL_SLOT_TAG_MASK 7u

/* The tag of a slot: 0 a single shape, ACCEL_SLOT_NODE a node, 2 and up
 * a leaf's count. */
static inline unsigned accel_slot_tag(uintptr_t slot)
{
	return (unsigned)(slot & ACCEL_SLOT_TAG_MASK);
}

static inline bool accel_slot_is_node(uintptr_t slot)
{
	return accel_slot_tag(slot) == ACCEL_SLOT_NODE;
}

/* The node's index, or a leaf's first position in accel.bounded. */
static inline size_t accel_slot_index(uintptr_t slot)
{
	return (size_t)(slot >> 3);
}

static inline uintptr_t accel_slot_make(size_t index, unsigned tag)
{
	return (uintptr_t)index << 3 | tag;
}

/* The node array's alignment: one node, one cache line. */
#define ACCEL_NODE_ALIGN 64

struct bvh_node {
	/* bounds[side][axis][child]: side 0 the minimum, 1 the maximum. */
	float bounds[2][3][2];
	uintptr_t slot[2];
};

struct accel {
	struct bvh_node *nodes;	/* the root first, then in depth-first order */
	size_t n_nodes;
	const struct shape **bounded;	/* in leaf order */
	size_t n_bounded;
	const struct shape **unbounded;
	size_t n_unbounded;
	bool walk_avx2;		/* the walks of accel_walk_avx2.c, where the processor has it */
};

/* The walks with AVX2 box tests (accel_walk_avx2.c): the same nodes in
 * the same order with the same arithmetic, so the same hits.  Usable only
 * where accel_avx2_usable says so (false in the portable build, on other
 * processors and where the compiler was not asked for AVX2). */
bool accel_avx2_usable(void);
const struct shape *accel_avx2_intersect(const struct accel *a, const struct ray *r,
					 double t_min, double *t_max);
bool accel_avx2_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max);
void accel_avx2_intersect_packet(const struct accel *a, const struct ray *r, int n,
				 const double *t_min, double *t_max, const struct shape **hit);
uint32_t accel_avx2_occluded_packet(const struct accel *a, const struct ray *r, int n,
				    const double *t_min, const double *t_max);

#endif
