/* The hierarchy's layout, shared by its build (accel_build.c,
 * accel_collapse.c) and its walks (accel.c, accel_kernels.c) and
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

#include "accel/accel.h"
#include "base/simd.h"
#include "whitted/diag.h"
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

/* The most shapes a tree holds: a slot's index has 29 bits. */
#define ACCEL_SHAPES_MAX ((size_t)1 << 29)

static inline uintptr_t accel_slot_make(size_t index, unsigned tag)
{
	return (uintptr_t)index << 3 | tag;
}

/* The four-child node array's alignment: a cache line. */
#define ACCEL_NODE_ALIGN 64

/* The build's binary node: bounds[side][axis][child], side 0 the
 * minimum, 1 the maximum.  No walk reads it, so it is packed (56 bytes,
 * not a cache line): it and the wide tree coexist at the build's memory
 * peak. */
struct bvh_node {
	float bounds[2][3][2];
	uint32_t slot[2];
};

/* The walks' nodes, side by side in an array aligned to a cache line:
 * lo[axis][child] and hi[axis][child], the children's float boxes (the
 * binary tree's, widened: see accel_collapse.c), side by side so that one
 * SIMD operation takes a plane of a node's children, then the children's
 * slots.  An empty child has lo +inf and hi -inf on every axis, a box no
 * ray enters, and a slot of 0, a leaf of no shapes.  The SSE2 and plain C
 * walks (and every walk of a small tree) take four children a node, 112
 * bytes; the AVX2 and AVX-512 walks of a big tree eight, 224 bytes (a
 * plane is then one AVX-512 operation or two AVX2 ones, and the tree is
 * shallower: gen-100k 0.92x, cloud-100k 0.84x the time of four children
 * with AVX2).  Both are the same layout at two widths, which the collapse
 * writes through struct node_view.  (Padded to 128 bytes, the four-child
 * tree did not fit in the build's refs, and the walks were no faster;
 * boxes quantized to bytes made the walks slower: the dequantizing cost
 * more than the halved memory saved.) */
#define ACCEL_WIDTH_MAX 8

struct bvh4_node {
	float lo[3][4], hi[3][4];
	uint32_t slot[4];
};

struct bvh8_node {
	float lo[3][8], hi[3][8];
	uint32_t slot[8];
};

/* A node of either width, field by field: the bytes of a node of width w
 * are 3w floats of lo, 3w of hi, then w slots. */
static inline size_t accel_node_bytes(int width)
{
	return (size_t)width * (6 * sizeof(float) + sizeof(uint32_t));
}

/* Which shape wins an exact tie, whatever order a walk meets them in:
 * the one of the lower key.  An unbounded shape's key is its place among
 * the unbounded ones, a bounded shape's the number of unbounded ones plus
 * its index in the scene: so the floor (and any unbounded quadric) wins a
 * tie, as in POV-Ray (a glass cube standing on the floor: a ray inside it
 * meets its bottom face and the floor at the same t, and goes on into the
 * floor), and otherwise the shape earlier in the scene.  That is a plain
 * loop's answer over the unbounded shapes and then the bounded ones, in
 * the scene's order, with a strict comparison.  So the nearest hit does
 * not depend on the tree's shape, its width or the order of its walk,
 * and every walk (eight lanes, four or two, packets or single rays, any
 * thread count) gives the same image. */
struct accel_kernels;

struct accel {
	void *nodes;		/* struct bvh4_node or bvh8_node by walk; the root first */
	size_t n_nodes;
	const struct shape **bounded;	/* in leaf order */
	uint32_t *bounded_key;		/* n_unbounded + each one's index in the scene */
	size_t n_bounded;
	const struct shape **unbounded;	/* in the scene's order */
	uint32_t *unbounded_key;	/* 0, 1, ... */
	size_t n_unbounded;
	/* The walks, of a set of instructions chosen at the build by the
	 * processor and the tree's size (accel_build.c), and the width of
	 * the tree they take (accel_kernels.h). */
	const struct accel_kernels *walk;
	enum rt_simd walk_set;
	int width;
	/* A four-child tree's packets go a ray a lane (accel_packet_rays.h)
	 * in this set's instructions: the one in use. */
	const struct accel_kernels *rays;
	enum rt_simd rays_set;
	char packets_name[64];		/* for --stats: "avx2 packets, a ray a lane" */
};

/* accel_build with the walks of set `walk` (and their tree's width)
 * whatever the processor and the tree's size: for the tests, which
 * compare the walks.  The caller checks accel_walk_usable first. */
int accel_build_walk(struct shape *const *shapes, size_t n_shapes, int threads,
		     enum rt_simd walk, struct accel **out, struct diag *d);
/* The packets of a's four-child tree a ray a lane in set s (the tests
 * compare them; the build takes the set in use). */
void accel_set_rays(struct accel *a, enum rt_simd s);

/* Builds a->nodes and a->n_nodes, the tree of `width` (4 or 8) children
 * a node, from the binary one (its root at 0, `leaves` leaves), with up
 * to `threads` threads (the same tree for any number), in room:
 * room_bytes aligned to ACCEL_NODE_ALIGN, at least accel_collapse_room
 * nodes, which a->nodes then owns. */
void accel_collapse(struct accel *a, const struct bvh_node *binary, size_t leaves, int width,
		    int threads, void *room, size_t room_bytes);
/* The most nodes a tree of `leaves` leaves can have at `width`. */
size_t accel_collapse_room(size_t leaves, int width);

/* Whether set s's walks run here: the build has them and s is no wider
 * than the set in use (base/simd.h: the processor's, within WHITTED_ISA's
 * limit). */
bool accel_walk_usable(enum rt_simd s);

#endif
