/* The base set's walks, included by accel_kernels.c where it is compiled
 * for SSE2 (or, in the portable build or on another processor, plain C):
 * a node's four children tested at once.
 *
 * Child c is entered when
 *   entry = max(t_min, (near_k - o_k) / d_k) <= exit = min(t_max, (far_k - o_k) / d_k)
 * over the three axes k (the reciprocal multiplied, in double precision
 * from the float bounds).  A NaN from 0 * inf (the origin on a slab plane
 * of a parallel ray) fails the comparisons and so constrains nothing;
 * SSE2's max and min return their second operand for a NaN, which is the
 * same rule.  node_entries returns the mask of the children entered and
 * their entries; node_hits only the mask.  Every build's arithmetic is
 * the same, lane by lane, so each takes the same path through the tree. */
#define ACCEL_NODE struct bvh4_node
#define ACCEL_W 4

#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
#include <emmintrin.h>

struct walk_ray {
	__m128d o[3], inv[3];
	int near_off[3], far_off[3];	/* float offsets into struct bvh4_node */
};

static inline void walk_ray_init(struct walk_ray *v, const struct ray_slab *rs)
{
	int k;

	for (k = 0; k < 3; k++) {
		v->o[k] = _mm_set1_pd(rs->o[k]);
		v->inv[k] = _mm_set1_pd(rs->inv[k]);
	}
	ray_slab_offsets(rs, ACCEL_W, v->near_off, v->far_off);
}

/* The slab distances of children 0-1 and 2-3 at one plane. */
static inline void slab_t(const float *b, int off, __m128d o, __m128d inv, __m128d *t01,
			  __m128d *t23)
{
	__m128 f = _mm_loadu_ps(b + off);

	*t01 = _mm_mul_pd(_mm_sub_pd(_mm_cvtps_pd(f), o), inv);
	*t23 = _mm_mul_pd(_mm_sub_pd(_mm_cvtps_pd(_mm_movehl_ps(f, f)), o), inv);
}

static inline void node_interval(const struct bvh4_node *node, const struct walk_ray *v,
				 double t_min, double t_max, __m128d lo[2], __m128d hi[2])
{
	const float *b = &node->lo[0][0];
	__m128d t01, t23;
	int k;

	lo[0] = lo[1] = _mm_set1_pd(t_min);
	hi[0] = hi[1] = _mm_set1_pd(t_max);
	for (k = 0; k < 3; k++) {
		slab_t(b, v->near_off[k], v->o[k], v->inv[k], &t01, &t23);
		lo[0] = _mm_max_pd(t01, lo[0]);
		lo[1] = _mm_max_pd(t23, lo[1]);
		slab_t(b, v->far_off[k], v->o[k], v->inv[k], &t01, &t23);
		hi[0] = _mm_min_pd(t01, hi[0]);
		hi[1] = _mm_min_pd(t23, hi[1]);
	}
}

static inline int node_entries(const struct bvh4_node *node, const struct walk_ray *v,
			       double t_min, double t_max, double entry[4])
{
	__m128d lo[2], hi[2];

	node_interval(node, v, t_min, t_max, lo, hi);
	_mm_storeu_pd(entry, lo[0]);
	_mm_storeu_pd(entry + 2, lo[1]);
	return _mm_movemask_pd(_mm_cmple_pd(lo[0], hi[0])) |
	       _mm_movemask_pd(_mm_cmple_pd(lo[1], hi[1])) << 2;
}

static inline int node_hits(const struct bvh4_node *node, const struct walk_ray *v,
			    double t_min, double t_max)
{
	__m128d lo[2], hi[2];

	node_interval(node, v, t_min, t_max, lo, hi);
	return _mm_movemask_pd(_mm_cmple_pd(lo[0], hi[0])) |
	       _mm_movemask_pd(_mm_cmple_pd(lo[1], hi[1])) << 2;
}
#else
struct walk_ray {
	struct ray_slab rs;
};

static inline void walk_ray_init(struct walk_ray *v, const struct ray_slab *rs)
{
	v->rs = *rs;
}

static inline int node_entries(const struct bvh4_node *node, const struct walk_ray *v,
			       double t_min, double t_max, double entry[4])
{
	const struct ray_slab *rs = &v->rs;
	int c, k, mask = 0;

	for (c = 0; c < 4; c++) {
		double lo = t_min, hi = t_max;
		for (k = 0; k < 3; k++) {
			double b0 = rs->near[k] ? node->hi[k][c] : node->lo[k][c];
			double b1 = rs->near[k] ? node->lo[k][c] : node->hi[k][c];
			double t0 = (b0 - rs->o[k]) * rs->inv[k];
			double t1 = (b1 - rs->o[k]) * rs->inv[k];
			lo = t0 > lo ? t0 : lo;
			hi = t1 < hi ? t1 : hi;
		}
		entry[c] = lo;
		mask |= (lo <= hi) << c;
	}
	return mask;
}

static inline int node_hits(const struct bvh4_node *node, const struct walk_ray *v,
			    double t_min, double t_max)
{
	double e[4];

	return node_entries(node, v, t_min, t_max, e);
}
#endif

#define ACCEL_WALK(name) walk_base_##name
#include "accel/accel_walk.h"
#define RAYS_WALK(name) rays_base_##name
#include "accel/accel_packet_rays.h"

/* A four-child tree's packets (and rays in place) go a ray a lane in the
 * widest set (accel.c takes them from rays4 of the set in use). */
#define ACCEL_KERNELS_TABLE { \
	.width = 4, \
	.intersect = walk_base_intersect, \
	.occluded = walk_base_occluded, \
	.rays4 = ACCEL_KERNELS_RAYS4(rays_base), \
	ACCEL_KERNELS_TEST_HOOKS(NULL, NULL) \
}
