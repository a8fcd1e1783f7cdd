/* Queries on the bounding volume hierarchy (built by accel_build.c) and
 * the list of unbounded shapes that every ray tests.  Closest-hit
 * traversal enters the nearer child first, in the same order as a tree
 * with one box per node would, so equal-distance hits resolve alike;
 * shadow rays stop at the first blocker.  Nothing here allocates or locks
 * per ray. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "accel/accel.h"
#include "accel/accel_slab.h"
#include "accel/accel_tree.h"

/* The entry distances of the ray into a node's two child boxes within
 * (t_min, t_max), INFINITY for a child it misses:
 *   entry = max(t_min, (near_k - o_k) / d_k),  exit = min(t_max, (far_k - o_k) / d_k).
 * A NaN from 0 * inf (the origin on a slab plane of a parallel ray) fails
 * the comparisons and so constrains nothing; SSE2's max and min return
 * their second operand for a NaN, which is the same rule. */
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
#include <emmintrin.h>

struct ray_slab_sse {
	__m128d o[3], inv[3];
	int near_off[3], far_off[3];	/* float offsets into bvh_node.bounds */
};

static inline void ray_slab_sse_init(struct ray_slab_sse *v, const struct ray_slab *rs)
{
	v->o[0] = _mm_set1_pd(rs->o[0]);
	v->o[1] = _mm_set1_pd(rs->o[1]);
	v->o[2] = _mm_set1_pd(rs->o[2]);
	v->inv[0] = _mm_set1_pd(rs->inv[0]);
	v->inv[1] = _mm_set1_pd(rs->inv[1]);
	v->inv[2] = _mm_set1_pd(rs->inv[2]);
	v->near_off[0] = rs->near[0] * 6;
	v->near_off[1] = rs->near[1] * 6 + 2;
	v->near_off[2] = rs->near[2] * 6 + 4;
	v->far_off[0] = 6 - rs->near[0] * 6;
	v->far_off[1] = 8 - rs->near[1] * 6;
	v->far_off[2] = 10 - rs->near[2] * 6;
}

static inline __m128d load_pair(const float *p)
{
	return _mm_cvtps_pd(_mm_castsi128_ps(_mm_loadl_epi64((const __m128i *)(const void *)p)));
}

static inline __m128d slab_t(const float *b, int off, __m128d o, __m128d inv)
{
	return _mm_mul_pd(_mm_sub_pd(load_pair(b + off), o), inv);
}

static inline void node_entries(const struct bvh_node *node, const struct ray_slab_sse *v,
				double t_min, double t_max, double entry[2])
{
	const float *b = &node->bounds[0][0][0];
	__m128d lo = _mm_set1_pd(t_min), hi = _mm_set1_pd(t_max), miss;

	lo = _mm_max_pd(slab_t(b, v->near_off[0], v->o[0], v->inv[0]), lo);
	hi = _mm_min_pd(slab_t(b, v->far_off[0], v->o[0], v->inv[0]), hi);
	lo = _mm_max_pd(slab_t(b, v->near_off[1], v->o[1], v->inv[1]), lo);
	hi = _mm_min_pd(slab_t(b, v->far_off[1], v->o[1], v->inv[1]), hi);
	lo = _mm_max_pd(slab_t(b, v->near_off[2], v->o[2], v->inv[2]), lo);
	hi = _mm_min_pd(slab_t(b, v->far_off[2], v->o[2], v->inv[2]), hi);
	/* A miss where not (lo <= hi). */
	miss = _mm_cmpnle_pd(lo, hi);
	lo = _mm_or_pd(_mm_and_pd(miss, _mm_set1_pd(INFINITY)), _mm_andnot_pd(miss, lo));
	_mm_storeu_pd(entry, lo);
}

/* Bit c set when the ray enters child c's box within (t_min, t_max). */
static inline int node_hits(const struct bvh_node *node, const struct ray_slab_sse *v,
			    double t_min, double t_max)
{
	const float *b = &node->bounds[0][0][0];
	__m128d lo = _mm_set1_pd(t_min), hi = _mm_set1_pd(t_max);

	lo = _mm_max_pd(slab_t(b, v->near_off[0], v->o[0], v->inv[0]), lo);
	hi = _mm_min_pd(slab_t(b, v->far_off[0], v->o[0], v->inv[0]), hi);
	lo = _mm_max_pd(slab_t(b, v->near_off[1], v->o[1], v->inv[1]), lo);
	hi = _mm_min_pd(slab_t(b, v->far_off[1], v->o[1], v->inv[1]), hi);
	lo = _mm_max_pd(slab_t(b, v->near_off[2], v->o[2], v->inv[2]), lo);
	hi = _mm_min_pd(slab_t(b, v->far_off[2], v->o[2], v->inv[2]), hi);
	return _mm_movemask_pd(_mm_cmple_pd(lo, hi));
}
#else
struct ray_slab_sse {
	struct ray_slab rs;
};

static inline void ray_slab_sse_init(struct ray_slab_sse *v, const struct ray_slab *rs)
{
	v->rs = *rs;
}

static inline void node_entries(const struct bvh_node *node, const struct ray_slab_sse *v,
				double t_min, double t_max, double entry[2])
{
	const struct ray_slab *rs = &v->rs;
	int c, k;

	for (c = 0; c < 2; c++) {
		double lo = t_min, hi = t_max;
		for (k = 0; k < 3; k++) {
			double t0 = (node->bounds[rs->near[k]][k][c] - rs->o[k]) * rs->inv[k];
			double t1 = (node->bounds[1 - rs->near[k]][k][c] - rs->o[k]) * rs->inv[k];
			lo = t0 > lo ? t0 : lo;
			hi = t1 < hi ? t1 : hi;
		}
		entry[c] = lo <= hi ? lo : INFINITY;
	}
}

static inline int node_hits(const struct bvh_node *node, const struct ray_slab_sse *v,
			    double t_min, double t_max)
{
	double e[2];

	node_entries(node, v, t_min, t_max, e);
	return (e[0] != INFINITY) | (e[1] != INFINITY) << 1;
}
#endif

#define ACCEL_WALK(name) walk_sse2_##name
#include "accel/accel_walk.h"
#include "accel/accel_packet_c.h"
#include "accel/accel_packet.h"

const struct shape *accel_intersect(const struct accel *a, const struct ray *r,
				    double t_min, double *t_max)
{
	if (a->walk_avx2)
		return accel_avx2_intersect(a, r, t_min, t_max);
	return walk_sse2_intersect(a, r, t_min, t_max);
}

bool accel_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max)
{
	if (a->walk_avx2)
		return accel_avx2_occluded(a, r, t_min, t_max);
	return walk_sse2_occluded(a, r, t_min, t_max);
}

void accel_intersect_packet(const struct accel *a, const struct ray *r, int n,
			    const double *t_min, double *t_max, const struct shape **hit)
{
	if (a->walk_avx2)
		accel_avx2_intersect_packet(a, r, n, t_min, t_max, hit);
	else
		walk_sse2_intersect_packet(a, r, n, t_min, t_max, hit);
}

uint32_t accel_occluded_packet(const struct accel *a, const struct ray *r, int n,
			       const double *t_min, const double *t_max)
{
	if (a->walk_avx2)
		return accel_avx2_occluded_packet(a, r, n, t_min, t_max);
	return walk_sse2_occluded_packet(a, r, n, t_min, t_max);
}

bool accel_packets_pay(const struct accel *a)
{
	return a->walk_avx2;
}

const char *accel_walk_name(const struct accel *a)
{
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
	return a && a->walk_avx2 ? "avx2" : "sse2";
#else
	(void)a;
	return "portable";
#endif
}

size_t accel_node_count(const struct accel *a)
{
	return a ? a->n_nodes : 0;
}

size_t accel_bytes(const struct accel *a)
{
	if (!a)
		return 0;
	return sizeof(*a) + a->n_nodes * sizeof(*a->nodes) +
	       (a->n_bounded + a->n_unbounded) * sizeof(const struct shape *);
}
