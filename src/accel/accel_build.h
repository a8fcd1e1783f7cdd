/* What the hierarchy's build (accel_build.c: the tree, its threads, its
 * nodes) shares with the split search (accel_split.c: boxes, the binned
 * surface area heuristic, the partition); private to the two. */
#ifndef RT_ACCEL_BUILD_H
#define RT_ACCEL_BUILD_H

#include <stdbool.h>
#include <stddef.h>

#include "accel/accel_tree.h"

/* A shape being sorted into the tree: its box and its index.  The centre
 * that the heuristic sorts by is computed from the box when needed rather
 * than stored, which keeps a reference at 56 bytes (the build's memory
 * peak is the references and the nodes together). */
struct build_ref {
	double lo[3], hi[3];
	size_t index;		/* the shape's, in the scene */
};


/* The bounds of a set of refs and of their centres.  Comparisons rather
 * than fmin and fmax, which are library calls here: the boxes are finite,
 * so the values are the same. */
struct build_box {
	double lo[3], hi[3];
};


/* The box of a shape that goes into the tree: true when shape_bounds
 * gives one whose coordinates are all within +-ACCEL_COORD_MAX (no NaN,
 * no infinity), so that every box of the tree is finite and quantizes
 * (accel_collapse.c).  Any other shape is tested by every ray, as an
 * unbounded one is. */
#define ACCEL_COORD_MAX 1e30
bool accel_tree_box(const struct shape *s, struct aabb *box);

#define ACCEL_BINS 16

struct sah_bin {
	struct build_box box;	/* empty while no ref falls in the bin */
	size_t n;
	size_t pad;		/* 64 bytes: a bin's address is a shift of its number */
};

/* A thread's bins for the split search, empty (every box empty, every
 * count 0) between searches: a search empties only the bins it used, so a
 * small node does not pay for clearing all 48. */
struct accel_bins {
	struct sah_bin bin[3][ACCEL_BINS];
};

void accel_bins_init(struct accel_bins *bins);

/* The box and the centre bounds of refs[0, n). */
void accel_refs_bounds(const struct build_ref *refs, size_t n, struct build_box *box,
		 struct build_box *centres);
/* box and centres grown by refs[0, n) in order, as accel_refs_bounds
 * grows them: the bounds of a set met in parts, the same to the bit. */
void accel_refs_bounds_grow(const struct build_ref *refs, size_t n, struct build_box *box,
			    struct build_box *centres);
/* box and centres grown by another set's bounds (o_box, o_centres), as
 * by that set's refs one by one after box and centres' own. */
void accel_boxes_grow(struct build_box *box, struct build_box *centres, const struct build_box *o_box,
		      const struct build_box *o_centres);
/* The refs of the bounded shapes among shapes[0, n_shapes), in order, at
 * the front of refs (room for n_shapes), with their box and centre
 * bounds, found with up to `threads` threads; returns how many. */
size_t accel_collect_refs(struct build_ref *refs, struct shape *const *shapes, size_t n_shapes,
			  int threads, struct build_box *box, struct build_box *centres);
/* The two parts of a node's refs at a split: each one's box and the
 * bounds of its refs' centres (the children's boxes, and what their own
 * splits are searched over). */
struct build_parts {
	struct build_box front, front_centres;
	struct build_box back, back_centres;
};

/* Where to split refs[0, n), whose box and centre bounds are given
 * (sorting them so), or 0 to make them a leaf; parts receives the box
 * and centre bounds of both parts. */
size_t accel_choose_split(struct build_ref *refs, size_t n, int depth, const struct build_box *box,
		    const struct build_box *centres, struct build_parts *parts,
		    struct accel_bins *bins);
/* Moves the refs whose centre lies below pos along axis to the front and
 * returns how many there are; parts receives the box and the centre
 * bounds of the front part and of the back part. */
size_t accel_partition(struct build_ref *refs, size_t n, int axis, double pos,
		       struct build_parts *parts);
/* accel_choose_split without the short cut for two refs: every node
 * binned, as the short cut must match (for the tests). */
size_t accel_choose_split_binned(struct build_ref *refs, size_t n, int depth,
				 const struct build_box *box, const struct build_box *centres,
				 struct build_parts *parts, struct accel_bins *bins);
/* Child c's box in the node, rounded outwards to floats. */
void accel_set_child_box(struct bvh_node *node, int c, const struct build_box *box);

#endif
