/* Queries on the bounding volume hierarchy (built by accel_build.c and
 * accel_collapse.c) and the list of unbounded shapes that every ray
 * tests: the walks of accel_walk.h and accel_packet.h over four-child
 * nodes with SSE2 box tests (or plain C ones in the portable build), and
 * the choice between them and the AVX2 and AVX-512 ones over eight-child
 * nodes.  Nothing here allocates or locks per ray. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_slab.h"
#include "accel/accel_tree.h"
#include "base/simd.h"

#define ACCEL_NODE struct bvh4_node
#define ACCEL_W 4

/* A node's four children are tested at once: child c is entered when
 *   entry = max(t_min, (near_k - o_k) / d_k) <= exit = min(t_max, (far_k - o_k) / d_k)
 * over the three axes k (the reciprocal multiplied, in double precision
 * from the float bounds).  A NaN from 0 * inf (the origin on a slab plane
 * of a parallel ray) fails the comparisons and so constrains nothing;
 * SSE2's max and min return their second operand for a NaN, which is the
 * same rule.  node_entries returns the mask of the children entered and
 * their entries; node_hits only the mask.  Every build's arithmetic is
 * the same, lane by lane, so each takes the same path through the tree. */
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

#define ACCEL_WALK(name) walk_sse2_##name
#include "accel/accel_walk.h"

const struct shape *accel_intersect(const struct accel *a, const struct ray *r,
				    double t_min, double *t_max)
{
	switch (a->walk) {
	case ACCEL_WALK_AVX512:
		return accel_avx512_intersect(a, r, t_min, t_max);
	case ACCEL_WALK_AVX2:
		return accel_avx2_intersect(a, r, t_min, t_max);
	default:
		return walk_sse2_intersect(a, r, t_min, t_max);
	}
}

bool accel_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max)
{
	switch (a->walk) {
	case ACCEL_WALK_AVX512:
		return accel_avx512_occluded(a, r, t_min, t_max);
	case ACCEL_WALK_AVX2:
		return accel_avx2_occluded(a, r, t_min, t_max);
	default:
		return walk_sse2_occluded(a, r, t_min, t_max);
	}
}

void accel_intersect_packet(const struct accel *a, const struct ray *r, int n,
			    const double *t_min, double *t_max, const struct shape **hit)
{
	switch (a->walk) {
	case ACCEL_WALK_AVX512:
		accel_avx512_intersect_packet(a, r, n, t_min, t_max, hit);
		break;
	case ACCEL_WALK_AVX2:
		accel_avx2_intersect_packet(a, r, n, t_min, t_max, hit);
		break;
	default:
		if (a->rays == ACCEL_WALK_AVX512)
			accel_avx512_rays_intersect_packet(a, r, n, t_min, t_max, hit);
		else if (a->rays == ACCEL_WALK_AVX2)
			accel_avx2_rays_intersect_packet(a, r, n, t_min, t_max, hit);
		else
			accel_rays_intersect_packet(a, r, n, t_min, t_max, hit);
	}
}

uint32_t accel_occluded_packet(const struct accel *a, const struct ray *r, int n,
			       const double *t_min, const double *t_max)
{
	switch (a->walk) {
	case ACCEL_WALK_AVX512:
		return accel_avx512_occluded_packet(a, r, n, t_min, t_max);
	case ACCEL_WALK_AVX2:
		return accel_avx2_occluded_packet(a, r, n, t_min, t_max);
	default:
		if (a->rays == ACCEL_WALK_AVX512)
			return accel_avx512_rays_occluded_packet(a, r, n, t_min, t_max);
		if (a->rays == ACCEL_WALK_AVX2)
			return accel_avx2_rays_occluded_packet(a, r, n, t_min, t_max);
		return accel_rays_occluded_packet(a, r, n, t_min, t_max);
	}
}

uint32_t accel_occluded_lanes(const struct accel *a, const struct ray_packet *p, uint32_t active,
			      const double *t_min, const double *t_max)
{
	struct ray r[ACCEL_PACKET];
	double t0[ACCEL_PACKET], t1[ACCEL_PACKET];
	int bit[ACCEL_PACKET], n = 0, i;
	uint32_t m, packed, blocked = 0;

	if (a->walk == ACCEL_WALK_AVX512)
		return accel_avx512_rays8_occluded_lanes(a, p, active, t_min, t_max);
	if (a->walk == ACCEL_WALK_BASE) {
		if (a->rays == ACCEL_WALK_AVX512)
			return accel_avx512_rays_occluded_lanes(a, p, active, t_min, t_max);
		if (a->rays == ACCEL_WALK_AVX2)
			return accel_avx2_rays_occluded_lanes(a, p, active, t_min, t_max);
		return accel_rays_occluded_lanes(a, p, active, t_min, t_max);
	}
	/* The wide trees' packets take the rays one by one. */
	for (m = active; m; m &= m - 1) {
		bit[n] = __builtin_ctz(m);
		r[n] = ray_packet_get(p, bit[n]);
		t0[n] = t_min[bit[n]];
		t1[n] = t_max[bit[n]];
		n++;
	}
	if (n == 0)
		return 0;
	packed = accel_occluded_packet(a, r, n, t0, t1);
	for (i = 0; i < n; i++)
		blocked |= (packed >> i & 1u) << bit[i];
	return blocked;
}

void accel_intersect_lanes(const struct accel *a, const struct ray_packet *p, uint32_t active,
			   const double *t_min, double *t_max, const struct shape **hit)
{
	struct ray r[ACCEL_PACKET];
	double t0[ACCEL_PACKET], t1[ACCEL_PACKET];
	const struct shape *h[ACCEL_PACKET];
	int bit[ACCEL_PACKET], n = 0, i;
	uint32_t m;

	if (a->walk == ACCEL_WALK_AVX512) {
		accel_avx512_rays8_intersect_lanes(a, p, active, t_min, t_max, hit);
		return;
	}
	if (a->walk == ACCEL_WALK_BASE) {
		if (a->rays == ACCEL_WALK_AVX512)
			accel_avx512_rays_intersect_lanes(a, p, active, t_min, t_max, hit);
		else if (a->rays == ACCEL_WALK_AVX2)
			accel_avx2_rays_intersect_lanes(a, p, active, t_min, t_max, hit);
		else
			accel_rays_intersect_lanes(a, p, active, t_min, t_max, hit);
		return;
	}
	/* The wide trees' packets take the rays one by one. */
	for (m = active; m; m &= m - 1) {
		bit[n] = __builtin_ctz(m);
		r[n] = ray_packet_get(p, bit[n]);
		t0[n] = t_min[bit[n]];
		t1[n] = t_max[bit[n]];
		n++;
	}
	if (n == 0)
		return;
	accel_intersect_packet(a, r, n, t0, t1, h);
	for (i = 0; i < n; i++) {
		t_max[bit[i]] = t1[i];
		hit[bit[i]] = h[i];
	}
}

bool accel_packets_pay(const struct accel *a)
{
	return a->walk != ACCEL_WALK_BASE || a->rays != ACCEL_WALK_BASE;
}

bool accel_packets_scatter_pay(const struct accel *a)
{
	return a->walk == ACCEL_WALK_BASE && a->rays != ACCEL_WALK_BASE;
}

bool accel_packets_wanted(const struct accel *a)
{
	const char *p = getenv("WHITTED_PACKETS");

	if (p && strcmp(p, "0") == 0)
		return false;
	if (p && strcmp(p, "1") == 0)
		return true;
	return a && accel_packets_pay(a);
}

static const char *walk_isa(enum accel_walk w)
{
	return rt_simd_name(w == ACCEL_WALK_AVX512 ? RT_SIMD_AVX512
			    : w == ACCEL_WALK_AVX2 ? RT_SIMD_AVX2 : RT_SIMD_BASE);
}

const char *accel_packets_name(const struct accel *a)
{
	static const char *const rays[] = { NULL, "avx2 packets, a ray a lane",
					    "avx512 packets, a ray a lane" };
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
	const char *base_rays = "sse2 packets, a ray a lane";
#else
	const char *base_rays = "portable packets, a ray a lane";
#endif

	if (!a || !accel_packets_wanted(a))
		return "no packets";
	if (a->walk != ACCEL_WALK_BASE)
		return a->walk == ACCEL_WALK_AVX512 ? "avx512 packets, a ray a lane, few rays alone"
						    : "avx2 packets, a child a lane";
	return a->rays == ACCEL_WALK_BASE ? base_rays : rays[a->rays];
}

const char *accel_walk_name(const struct accel *a)
{
	return walk_isa(a ? a->walk : ACCEL_WALK_BASE);
}

/* A wide walk runs where the set of instructions in use (base/simd.h:
 * the processor's widest, within WHITTED_ISA's limit) has its
 * instructions and the file was compiled for them. */
bool accel_walk_usable(enum accel_walk w)
{
	switch (w) {
	case ACCEL_WALK_AVX512:
		return rt_simd_level() >= RT_SIMD_AVX512 && accel_avx512_compiled();
	case ACCEL_WALK_AVX2:
		return rt_simd_level() >= RT_SIMD_AVX2 && accel_avx2_compiled();
	default:
		return true;
	}
}

size_t accel_node_count(const struct accel *a)
{
	return a ? a->n_nodes : 0;
}

size_t accel_bytes(const struct accel *a)
{
	if (!a)
		return 0;
	return sizeof(*a) + a->n_nodes * accel_node_bytes(accel_walk_width(a->walk)) +
	       (a->n_bounded + a->n_unbounded) * (sizeof(const struct shape *) + sizeof(uint32_t));
}
