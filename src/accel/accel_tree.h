/* The hierarchy's layout, shared by its build (accel_build.c,
 * accel_collapse.c) and its walks (accel.c, accel_walk_avx2.c,
 * accel_walk_avx512.c) and
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

/* Which walks run, chosen at the build by the processor and the tree's
 * size (accel_build.c), and with them the tree's width. */
enum accel_walk {
	ACCEL_WALK_BASE,	/* SSE2, or plain C in the portable build: four children */
	ACCEL_WALK_AVX2,	/* eight children */
	ACCEL_WALK_AVX512	/* eight children */
};

static inline int accel_walk_width(enum accel_walk w)
{
	return w == ACCEL_WALK_BASE ? 4 : 8;
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
struct accel {
	void *nodes;		/* struct bvh4_node or bvh8_node by walk; the root first */
	size_t n_nodes;
	const struct shape **bounded;	/* in leaf order */
	uint32_t *bounded_key;		/* n_unbounded + each one's index in the scene */
	size_t n_bounded;
	const struct shape **unbounded;	/* in the scene's order */
	uint32_t *unbounded_key;	/* 0, 1, ... */
	size_t n_unbounded;
	enum accel_walk walk;
	/* A four-child tree's packets go a ray a lane (accel_packet_rays.h),
	 * in these walks' instructions: the widest usable at the build. */
	enum accel_walk rays;
};

/* accel_build with the walks `walk` (and their tree's width) whatever
 * the processor and the tree's size: for the tests, which compare the
 * walks.  The caller checks accel_walk_usable first. */
int accel_build_walk(struct shape *const *shapes, size_t n_shapes, int threads,
		     enum accel_walk walk, struct accel **out, struct diag *d);

/* Builds a->nodes and a->n_nodes, the tree of `width` (4 or 8) children
 * a node, from the binary one (its root at 0, `leaves` leaves), with up
 * to `threads` threads (the same tree for any number), in room:
 * room_bytes aligned to ACCEL_NODE_ALIGN, at least accel_collapse_room
 * nodes, which a->nodes then owns. */
void accel_collapse(struct accel *a, const struct bvh_node *binary, size_t leaves, int width,
		    int threads, void *room, size_t room_bytes);
/* The most nodes a tree of `leaves` leaves can have at `width`. */
size_t accel_collapse_room(size_t leaves, int width);

/* Whether the processor (and the build: the compiler asked for it, not
 * the portable build) runs walk w, within WHITTED_ISA's limit (sse2,
 * avx2, avx512: the widest walk allowed, to compare them). */
bool accel_walk_usable(enum accel_walk w);

/* The walks with AVX2 box tests over eight-child nodes
 * (accel_walk_avx2.c: the same boxes with the same arithmetic, lane by
 * lane, as the base walks) and with AVX-512 ones (accel_walk_avx512.c: in
 * floats, entering every box the double tests enter, no later:
 * accel_float_box.h), so the same hits.  Called only where
 * accel_walk_usable says so. */
const struct shape *accel_avx2_intersect(const struct accel *a, const struct ray *r,
					 double t_min, double *t_max);
bool accel_avx2_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max);
void accel_avx2_intersect_packet(const struct accel *a, const struct ray *r, int n,
				 const double *t_min, double *t_max, const struct shape **hit);
uint32_t accel_avx2_occluded_packet(const struct accel *a, const struct ray *r, int n,
				    const double *t_min, const double *t_max);
bool accel_avx2_compiled(void);	/* compiled for its instructions */
const struct shape *accel_avx512_intersect(const struct accel *a, const struct ray *r,
					   double t_min, double *t_max);
bool accel_avx512_occluded(const struct accel *a, const struct ray *r, double t_min,
			   double t_max);
void accel_avx512_intersect_packet(const struct accel *a, const struct ray *r, int n,
				   const double *t_min, double *t_max, const struct shape **hit);
uint32_t accel_avx512_occluded_packet(const struct accel *a, const struct ray *r, int n,
				      const double *t_min, const double *t_max);
bool accel_avx512_compiled(void);
#ifdef RT_TEST_HOOKS
/* For the tests (in the test build only): node's children as the AVX-512 walk's float test sees
 * them for ray r in (t_min, t_max) (its mask, the entries in
 * float_entry), or -1 where that walk tests the ray in doubles; and as
 * the double test sees them (*exact_mask, exact_entry; 0 where this file
 * was compiled without AVX-512). */
int accel_avx512_node_tests(const struct bvh8_node *node, const struct ray *r, double t_min,
			    double t_max, double float_entry[8], int *exact_mask,
			    double exact_entry[8]);
/* Likewise for the small trees' packets (accel_packet_rays.h): the
 * children of node each of the ACCEL_PACKET rays r enters in (t_min[i],
 * t_max[i]) by the float test (float_child[c] bit i, the entries in
 * float_entry[c][i]), and by the double test (exact_child, exact_entry);
 * returns 1, or 0 where the float tests do not hold the packet (and
 * leave float_* alone), -1 without AVX-512 (and leave all alone). */
int accel_avx512_rays_node_tests(const struct bvh4_node *node, const struct ray *r,
				 const double *t_min, const double *t_max, uint32_t float_child[4],
				 double float_entry[4][ACCEL_PACKET], uint32_t exact_child[4],
				 double exact_entry[4][ACCEL_PACKET]);
#endif

/* The packets through a four-child tree, a ray a vector lane
 * (accel_packet_rays.h): in SSE2 or plain C (accel_packet_rays.c), AVX2
 * and AVX-512 (the walks' files); accel_intersect_packet's contract. */
void accel_rays_intersect_packet(const struct accel *a, const struct ray *r, int n,
				 const double *t_min, double *t_max, const struct shape **hit);
uint32_t accel_rays_occluded_packet(const struct accel *a, const struct ray *r, int n,
				    const double *t_min, const double *t_max);
void accel_avx2_rays_intersect_packet(const struct accel *a, const struct ray *r, int n,
				      const double *t_min, double *t_max, const struct shape **hit);
uint32_t accel_avx2_rays_occluded_packet(const struct accel *a, const struct ray *r, int n,
					 const double *t_min, const double *t_max);
void accel_avx512_rays_intersect_packet(const struct accel *a, const struct ray *r, int n,
					const double *t_min, double *t_max,
					const struct shape **hit);
uint32_t accel_avx512_rays_occluded_packet(const struct accel *a, const struct ray *r, int n,
					   const double *t_min, const double *t_max);
/* accel_occluded_lanes's contract, a ray a vector lane likewise. */
uint32_t accel_rays_occluded_lanes(const struct accel *a, const struct ray_packet *p,
				   uint32_t active, const double *t_min, const double *t_max);
uint32_t accel_avx2_rays_occluded_lanes(const struct accel *a, const struct ray_packet *p,
					uint32_t active, const double *t_min, const double *t_max);
uint32_t accel_avx512_rays_occluded_lanes(const struct accel *a, const struct ray_packet *p,
					  uint32_t active, const double *t_min,
					  const double *t_max);
/* The packets through the AVX-512 walk's eight-child tree, a ray a
 * vector lane (accel_packet_rays.h over struct bvh8_node; its
 * intersect_packet and occluded_packet are these too): the contracts of
 * accel_occluded_lanes and accel_intersect_lanes. */
uint32_t accel_avx512_rays8_occluded_lanes(const struct accel *a, const struct ray_packet *p,
					   uint32_t active, const double *t_min,
					   const double *t_max);
void accel_avx512_rays8_intersect_lanes(const struct accel *a, const struct ray_packet *p,
					uint32_t active, const double *t_min, double *t_max,
					const struct shape **hit);
/* accel_intersect_lanes's contract, a ray a vector lane likewise. */
void accel_rays_intersect_lanes(const struct accel *a, const struct ray_packet *p,
				uint32_t active, const double *t_min, double *t_max,
				const struct shape **hit);
void accel_avx2_rays_intersect_lanes(const struct accel *a, const struct ray_packet *p,
				     uint32_t active, const double *t_min, double *t_max,
				     const struct shape **hit);
void accel_avx512_rays_intersect_lanes(const struct accel *a, const struct ray_packet *p,
				       uint32_t active, const double *t_min, double *t_max,
				       const struct shape **hit);

#endif
