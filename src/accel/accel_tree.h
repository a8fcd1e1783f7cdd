/* The hierarchy's layout, shared by its build (accel_build.c,
 * accel_collapse.c) and its walks (accel.c, accel_walk_avx2.c) and
 * private to them.  The build makes a binary tree (struct bvh_node: the
 * float boxes of two children, rounded outwards so that they never cut
 * off a hit), which accel_collapse.c turns into the tree the walks use:
 * four children a node (struct bvh4_node, one cache line), their boxes
 * side by side so that one four-lane operation tests all four. */
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

/* What a child slot holds, by its low three bits: ACCEL_SLOT_NODE, a
 * node (index << 3); 0 to ACCEL_LEAF_MAX, a leaf of that many shapes from
 * accel.bounded[slot >> 3] (0: an empty slot, whose box no ray enters). */
#define ACCEL_SLOT_NODE 7u
#define ACCEL_SLOT_TAG_MASK 7u

/* The tag of a slot: ACCEL_SLOT_NODE a node, else a leaf's count. */
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

/* The four-child node array's alignment: a cache line. */
#define ACCEL_NODE_ALIGN 64

/* The build's binary node: bounds[side][axis][child], side 0 the
 * minimum, 1 the maximum.  No walk reads it, so it is packed (56 bytes,
 * not a cache line): it and the four-child tree coexist at the build's
 * memory peak. */
struct bvh_node {
	float bounds[2][3][2];
	uint32_t slot[2];
};

#define ACCEL_WIDTH 4

/* The walks' node, 112 bytes (nodes side by side in an array aligned to
 * a cache line: padded to 128, the tree did not fit in the build's refs,
 * and the walks were no faster): lo[axis][child] and hi[axis][child],
 * the children's float boxes (the binary tree's, widened: see
 * accel_collapse.c), side by side so that one four-lane operation takes a
 * plane of all four.  An empty child has lo +inf and hi -inf on every
 * axis, a box no ray enters, and a slot of 0, a leaf of no shapes.
 * (Boxes quantized to bytes, one cache line a node, made the walks slower
 * here: the dequantizing cost more than the halved memory saved.) */
struct bvh4_node {
	float lo[3][ACCEL_WIDTH], hi[3][ACCEL_WIDTH];
	uint32_t slot[ACCEL_WIDTH];
};

/* Which shape wins an exact tie, whatever order a walk meets them in:
 * the one of the lower key.  An unbounded shape's key is its place among
 * the unbounded ones, a bounded shape's the number of unbounded ones plus
 * its index in the scene: so the floor (and any unbounded quadric) wins a
 * tie, as in POV-Ray (a glass cube standing on the floor: a ray inside it
 * meets its bottom face and the floor at the same t, and goes on into the
 * floor), and otherwise the shape earlier in the scene.  That is a plain
 * loop's answer over the unbounded shapes and then the bounded ones, in
 * the scene's order, with a strict comparison.  So the nearest hit does
 * not depend on the tree's shape or the order of its walk, and every walk
 * (four lanes or two, packets or single rays, any thread count) gives
 * the same image. */
struct accel {
	struct bvh4_node *nodes;	/* the root first */
	size_t n_nodes;
	const struct shape **bounded;	/* in leaf order */
	uint32_t *bounded_key;		/* n_unbounded + each one's index in the scene */
	size_t n_bounded;
	const struct shape **unbounded;	/* in the scene's order */
	uint32_t *unbounded_key;	/* 0, 1, ... */
	size_t n_unbounded;
	bool walk_avx2;		/* the walks of accel_walk_avx2.c, where the processor has it */
};

/* Builds a->nodes and a->n_nodes, the four-child tree, from the binary
 * one (its root at 0, `leaves` leaves), with up to `threads` threads (the
 * same tree for any number), in room: room_bytes aligned to
 * ACCEL_NODE_ALIGN, enough for any tree of that many leaves (3L/4 + 2
 * nodes), which a->nodes then owns. */
void accel_collapse(struct accel *a, const struct bvh_node *binary, size_t leaves, int threads,
		    void *room, size_t room_bytes);

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
