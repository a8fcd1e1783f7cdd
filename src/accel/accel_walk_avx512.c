/* The hierarchy's walks over eight-child nodes with AVX-512 box tests,
 * compiled with -mavx512f (the Makefile, on x86) and chosen at the build
 * where the processor has it.  One eight-lane operation takes a plane's
 * slab distances of all eight children of a node, in the base walks'
 * arithmetic lane by lane (float bounds widened to double, then
 * (b - o) * inv, no fused multiply-add; max and min return their second
 * operand for a NaN, as SSE2's do), so every box test gives the base
 * walks' answer for that box to the bit, and the images are theirs. */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_slab.h"
#include "accel/accel_tree.h"

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#include <immintrin.h>

#define ACCEL_NODE struct bvh8_node
#define ACCEL_W 8

struct walk_ray {
	__m512d o[3], inv[3];
	int near_off[3], far_off[3];	/* float offsets into struct bvh8_node */
};

static inline void walk_ray_init(struct walk_ray *v, const struct ray_slab *rs)
{
	int k;

	for (k = 0; k < 3; k++) {
		v->o[k] = _mm512_set1_pd(rs->o[k]);
		v->inv[k] = _mm512_set1_pd(rs->inv[k]);
	}
	ray_slab_offsets(rs, ACCEL_W, v->near_off, v->far_off);
}

/* A plane of the eight children: 32 bytes, at a multiple of 32 in the
 * array of 224-byte nodes from a 64-byte boundary; loaded unaligned all
 * the same (no slower where it is aligned), so that a tree moved by its
 * shrink to a lesser boundary still walks. */
static inline __m512d slab_t(const float *b, int off, __m512d o, __m512d inv)
{
	return _mm512_mul_pd(_mm512_sub_pd(_mm512_cvtps_pd(_mm256_loadu_ps(b + off)), o), inv);
}

/* The children's entries, and the mask of those entered. */
static inline __m512d node_interval(const struct bvh8_node *node, const struct walk_ray *v,
				    double t_min, double t_max, int *mask)
{
	const float *b = &node->lo[0][0];
	__m512d lo = _mm512_set1_pd(t_min), hi = _mm512_set1_pd(t_max);

	lo = _mm512_max_pd(slab_t(b, v->near_off[0], v->o[0], v->inv[0]), lo);
	hi = _mm512_min_pd(slab_t(b, v->far_off[0], v->o[0], v->inv[0]), hi);
	lo = _mm512_max_pd(slab_t(b, v->near_off[1], v->o[1], v->inv[1]), lo);
	hi = _mm512_min_pd(slab_t(b, v->far_off[1], v->o[1], v->inv[1]), hi);
	lo = _mm512_max_pd(slab_t(b, v->near_off[2], v->o[2], v->inv[2]), lo);
	hi = _mm512_min_pd(slab_t(b, v->far_off[2], v->o[2], v->inv[2]), hi);
	*mask = (int)_mm512_cmp_pd_mask(lo, hi, _CMP_LE_OQ);
	return lo;
}

static inline int node_entries(const struct bvh8_node *node, const struct walk_ray *v,
			       double t_min, double t_max, double entry[8])
{
	int mask;

	_mm512_storeu_pd(entry, node_interval(node, v, t_min, t_max, &mask));
	return mask;
}

static inline int node_hits(const struct bvh8_node *node, const struct walk_ray *v,
			    double t_min, double t_max)
{
	int mask;

	(void)node_interval(node, v, t_min, t_max, &mask);
	return mask;
}

#define ACCEL_WALK(name) walk_avx512_##name
#include "accel/accel_walk.h"
#include "accel/accel_packet.h"
#define RAYS_WALK(name) rays_avx512_##name
#include "accel/accel_packet_rays.h"

#define ACCEL_COMPILED 1
#endif

#define ACCEL_EXPORT(name) accel_avx512_##name
#include "accel/accel_walk_export.h"
