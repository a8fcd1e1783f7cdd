/* The hierarchy's walks, one table a set of instructions: compiled by the
 * Makefile from accel_kernels.c once per set the build has (base/simd.h),
 * each over the node tests of its set (walk_base.h, walk_avx2.h,
 * walk_avx512.h) and the walks written once over them (accel_walk.h,
 * accel_packet.h, accel_packet_rays.h).  Every walk gives every ray the
 * same answer (accel_tree.h: the keys' tie rule), so the images do not
 * depend on the set. */
#ifndef RT_ACCEL_KERNELS_H
#define RT_ACCEL_KERNELS_H

#include <stdbool.h>
#include <stdint.h>

#include "accel/accel_tree.h"
#include "base/simd.h"

/* Packets through a tree, with the contracts of accel_intersect_packet,
 * accel_occluded_packet, accel_intersect_lanes and accel_occluded_lanes. */
struct accel_packet_walks {
	void (*intersect_packet)(const struct accel *a, const struct ray *r, int n,
				 const double *t_min, double *t_max, const struct shape **hit);
	uint32_t (*occluded_packet)(const struct accel *a, const struct ray *r, int n,
				    const double *t_min, const double *t_max);
	void (*intersect_lanes)(const struct accel *a, const struct ray_packet *p, uint32_t active,
				const double *t_min, double *t_max, const struct shape **hit);
	uint32_t (*occluded_lanes)(const struct accel *a, const struct ray_packet *p,
				   uint32_t active, const double *t_min, const double *t_max);
};

struct accel_kernels {
	/* The children of a node of the tree this set's walks take (4 or
	 * 8): the build makes the tree that wide. */
	int width;
	/* A single ray's walks: accel_intersect's and accel_occluded's
	 * contracts. */
	const struct shape *(*intersect)(const struct accel *a, const struct ray *r, double t_min,
					 double *t_max);
	bool (*occluded)(const struct accel *a, const struct ray *r, double t_min, double t_max);
	/* Packets through this set's wide tree (all NULL in a set whose tree
	 * has four children, whose packets go through rays4 of the set in
	 * use; the lanes NULL where the rays in place go one by one through
	 * the packets), and how they go, for --stats ("a child a lane"). */
	struct accel_packet_walks wide;
	const char *packets;
	/* Packets a ray a vector lane through a four-child tree (a small
	 * scene's) in this set. */
	struct accel_packet_walks rays4;
#ifdef RT_TEST_HOOKS
	/* For the tests (the test build only; NULL but in AVX-512): node's
	 * children as the float test sees them for ray r in (t_min, t_max)
	 * (its mask, the entries in float_entry), or -1 where the walk tests
	 * the ray in doubles; and as the double test sees them (*exact_mask,
	 * exact_entry). */
	int (*node_tests)(const struct bvh8_node *node, const struct ray *r, double t_min,
			  double t_max, double float_entry[8], int *exact_mask, double exact_entry[8]);
	/* Likewise for the four-child tree's packets: the children of node
	 * each of the ACCEL_PACKET rays r enters in (t_min[i], t_max[i]) by
	 * the float test (float_child[c] bit i, the entries in
	 * float_entry[c][i]), and by the double test (exact_child,
	 * exact_entry); returns 1, or 0 where the float tests do not hold
	 * the packet (and leave float_* alone). */
	int (*rays_node_tests)(const struct bvh4_node *node, const struct ray *r,
			       const double *t_min, const double *t_max, uint32_t float_child[4],
			       double float_entry[4][ACCEL_PACKET], uint32_t exact_child[4],
			       double exact_entry[4][ACCEL_PACKET]);
#endif
};

/* The table of set s, or NULL where the build has none. */
const struct accel_kernels *accel_kernels_of(enum rt_simd s);

#endif
