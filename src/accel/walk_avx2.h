/* The AVX2 set's walks, included by accel_kernels.c where it is compiled
 * with -mavx2: over eight-child nodes, chosen at the build where the
 * processor has AVX2 and not AVX-512.  Two four-lane operations
 * take a plane's slab distances of a node's eight children, in the base
 * walks' arithmetic lane by lane (float bounds widened to double, then
 * (b - o) * inv, no fused multiply-add), so every box test gives the base
 * walks' answer for that box to the bit, and the images are theirs. */
#include <immintrin.h>

#define ACCEL_NODE struct bvh8_node
#define ACCEL_W 8

struct walk_ray {
	__m256d o[3], inv[3];
	int near_off[3], far_off[3];	/* float offsets into struct bvh8_node */
};

static inline void walk_ray_init(struct walk_ray *v, const struct ray_slab *rs)
{
	int k;

	for (k = 0; k < 3; k++) {
		v->o[k] = _mm256_set1_pd(rs->o[k]);
		v->inv[k] = _mm256_set1_pd(rs->inv[k]);
	}
	ray_slab_offsets(rs, ACCEL_W, v->near_off, v->far_off);
}

static inline __m256d slab_t(const float *b, int off, __m256d o, __m256d inv)
{
	return _mm256_mul_pd(_mm256_sub_pd(_mm256_cvtps_pd(_mm_loadu_ps(b + off)), o), inv);
}

/* The entries of children 4h .. 4h + 3, and the mask of those entered. */
static inline __m256d node_interval(const struct bvh8_node *node, const struct walk_ray *v,
				    int h, double t_min, double t_max, int *mask)
{
	const float *b = &node->lo[0][0] + 4 * h;
	__m256d lo = _mm256_set1_pd(t_min), hi = _mm256_set1_pd(t_max);

	lo = _mm256_max_pd(slab_t(b, v->near_off[0], v->o[0], v->inv[0]), lo);
	hi = _mm256_min_pd(slab_t(b, v->far_off[0], v->o[0], v->inv[0]), hi);
	lo = _mm256_max_pd(slab_t(b, v->near_off[1], v->o[1], v->inv[1]), lo);
	hi = _mm256_min_pd(slab_t(b, v->far_off[1], v->o[1], v->inv[1]), hi);
	lo = _mm256_max_pd(slab_t(b, v->near_off[2], v->o[2], v->inv[2]), lo);
	hi = _mm256_min_pd(slab_t(b, v->far_off[2], v->o[2], v->inv[2]), hi);
	*mask = _mm256_movemask_pd(_mm256_cmp_pd(lo, hi, _CMP_LE_OQ));
	return lo;
}

static inline int node_entries(const struct bvh8_node *node, const struct walk_ray *v,
			       double t_min, double t_max, double entry[8])
{
	int m0, m1;

	_mm256_storeu_pd(entry, node_interval(node, v, 0, t_min, t_max, &m0));
	_mm256_storeu_pd(entry + 4, node_interval(node, v, 1, t_min, t_max, &m1));
	return m0 | m1 << 4;
}

static inline int node_hits(const struct bvh8_node *node, const struct walk_ray *v,
			    double t_min, double t_max)
{
	int m0, m1;

	(void)node_interval(node, v, 0, t_min, t_max, &m0);
	(void)node_interval(node, v, 1, t_min, t_max, &m1);
	return m0 | m1 << 4;
}

#define ACCEL_WALK(name) walk_avx2_##name
#include "accel/accel_walk.h"
#include "accel/accel_packet.h"
#define RAYS_WALK(name) rays_avx2_##name
#include "accel/accel_packet_rays.h"


#define ACCEL_KERNELS_TABLE { \
	.width = 8, \
	.intersect = walk_avx2_intersect, \
	.occluded = walk_avx2_occluded, \
	.wide = { \
		.intersect_packet = walk_avx2_intersect_packet, \
		.occluded_packet = walk_avx2_occluded_packet, \
	}, \
	.packets = "a child a lane", \
	.rays4 = ACCEL_KERNELS_RAYS4(rays_avx2), \
	ACCEL_KERNELS_TEST_HOOKS(NULL, NULL) \
}
