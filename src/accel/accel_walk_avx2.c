/* The hierarchy's walks with AVX2 box tests, compiled with -mavx2 (the
 * Makefile, on x86) and chosen at build time where the processor has it.
 * One four-lane operation computes an axis's slab distances of both
 * children at their near and far planes: the far lanes' reciprocal is
 * negated, so they hold -(far - o) / d exactly, and one MAXPD per axis
 * takes both max(entry) and -min(exit) (MAXPD (-a, -b) is -MINPD (a, b),
 * NaNs and ties included).  So every entry, exit and miss is the SSE2
 * walk's to the bit, and so is every image. */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_slab.h"
#include "accel/accel_tree.h"

#if defined(__AVX2__) && !defined(ACCEL_PORTABLE)
#include <immintrin.h>

struct ray_slab_sse {
	__m256d o[3], inv[3];	/* inv: lanes 0-1 the reciprocal, lanes 2-3 its negation */
	int near_off[3], far_off[3];	/* float offsets into bvh_node.bounds */
};

static inline void ray_slab_sse_init(struct ray_slab_sse *v, const struct ray_slab *rs)
{
	int k;

	for (k = 0; k < 3; k++) {
		v->o[k] = _mm256_set1_pd(rs->o[k]);
		v->inv[k] = _mm256_set_pd(-rs->inv[k], -rs->inv[k], rs->inv[k], rs->inv[k]);
		v->near_off[k] = rs->near[k] * 6 + 2 * k;
		v->far_off[k] = (1 - rs->near[k]) * 6 + 2 * k;
	}
}

/* Lanes 0-1 the children's near-plane distances, 2-3 their negated
 * far-plane distances, along one axis. */
static inline __m256d slab4(const float *b, int near_off, int far_off, __m256d o, __m256d inv)
{
	__m128d pair = _mm_load_sd((const double *)(const void *)(b + near_off));
	__m128 f;

	pair = _mm_loadh_pd(pair, (const double *)(const void *)(b + far_off));
	f = _mm_castpd_ps(pair);
	return _mm256_mul_pd(_mm256_sub_pd(_mm256_cvtps_pd(f), o), inv);
}

/* Lanes 0-1 the entries (lo), and in *hi the exits. */
static inline __m128d node_interval(const struct bvh_node *node, const struct ray_slab_sse *v,
				    double t_min, double t_max, __m128d *hi)
{
	const float *b = &node->bounds[0][0][0];
	__m256d acc = _mm256_set_pd(-t_max, -t_max, t_min, t_min);

	acc = _mm256_max_pd(slab4(b, v->near_off[0], v->far_off[0], v->o[0], v->inv[0]), acc);
	acc = _mm256_max_pd(slab4(b, v->near_off[1], v->far_off[1], v->o[1], v->inv[1]), acc);
	acc = _mm256_max_pd(slab4(b, v->near_off[2], v->far_off[2], v->o[2], v->inv[2]), acc);
	*hi = _mm_xor_pd(_mm256_extractf128_pd(acc, 1), _mm_set1_pd(-0.0));
	return _mm256_castpd256_pd128(acc);
}

static inline void node_entries(const struct bvh_node *node, const struct ray_slab_sse *v,
				double t_min, double t_max, double entry[2])
{
	__m128d hi, lo = node_interval(node, v, t_min, t_max, &hi);
	__m128d miss = _mm_cmpnle_pd(lo, hi);

	lo = _mm_or_pd(_mm_and_pd(miss, _mm_set1_pd(INFINITY)), _mm_andnot_pd(miss, lo));
	_mm_storeu_pd(entry, lo);
}

static inline int node_hits(const struct bvh_node *node, const struct ray_slab_sse *v,
			    double t_min, double t_max)
{
	__m128d hi, lo = node_interval(node, v, t_min, t_max, &hi);

	return _mm_movemask_pd(_mm_cmple_pd(lo, hi));
}

#define ACCEL_WALK(name) walk_avx2_##name
#include "accel/accel_walk.h"

/* The packet walks' box tests, four rays to an operation: the rays'
 * values side by side, each lane's arithmetic that of node_entries above
 * (and of accel.c's), the near and far planes picked per lane by the sign
 * of the ray's direction instead of by offset. */
struct packet_slab {
	double o[3][ACCEL_PACKET], inv[3][ACCEL_PACKET];
	double near[3][ACCEL_PACKET];	/* -1 where the maximum is the near plane, else 0 */
};

static inline void packet_slab_init(struct packet_slab *ps, const struct ray *r, int n)
{
	int i, k;

	memset(ps, 0, sizeof(*ps));
	for (i = 0; i < n; i++) {
		struct ray_slab rs;
		ray_slab_init(&rs, r + i);
		for (k = 0; k < 3; k++) {
			ps->o[k][i] = rs.o[k];
			ps->inv[k][i] = rs.inv[k];
			ps->near[k][i] = rs.near[k] ? -1.0 : 0.0;
		}
	}
}

static inline void packet_node(const struct bvh_node *node, const struct packet_slab *ps,
			       uint32_t mask, const double *t_min, const double *t_max,
			       double *e0, double *e1, uint32_t *h0, uint32_t *h1, uint32_t *n1)
{
	const __m256d inf = _mm256_set1_pd(INFINITY);
	__m256d b[2][3][2];
	uint32_t hit0 = 0, hit1 = 0, near1 = 0;
	int g, c, k;

	for (c = 0; c < 2; c++)
		for (k = 0; k < 3; k++) {
			b[c][k][0] = _mm256_set1_pd(node->bounds[0][k][c]);
			b[c][k][1] = _mm256_set1_pd(node->bounds[1][k][c]);
		}
	for (g = 0; g < ACCEL_PACKET; g += 4) {
		__m256d lo[2], hi[2], e[2];
		if (!(mask >> g & 15))
			continue;
		lo[0] = lo[1] = _mm256_loadu_pd(t_min + g);
		hi[0] = hi[1] = _mm256_loadu_pd(t_max + g);
		for (k = 0; k < 3; k++) {
			__m256d o = _mm256_loadu_pd(ps->o[k] + g);
			__m256d inv = _mm256_loadu_pd(ps->inv[k] + g);
			__m256d nr = _mm256_loadu_pd(ps->near[k] + g);
			for (c = 0; c < 2; c++) {
				__m256d ta = _mm256_mul_pd(_mm256_sub_pd(b[c][k][0], o), inv);
				__m256d tb = _mm256_mul_pd(_mm256_sub_pd(b[c][k][1], o), inv);
				/* max(slab, lo) keeps lo for a NaN slab, as alone. */
				lo[c] = _mm256_max_pd(_mm256_blendv_pd(ta, tb, nr), lo[c]);
				hi[c] = _mm256_min_pd(_mm256_blendv_pd(tb, ta, nr), hi[c]);
			}
		}
		for (c = 0; c < 2; c++)
			e[c] = _mm256_blendv_pd(lo[c], inf, _mm256_cmp_pd(lo[c], hi[c], _CMP_NLE_UQ));
		_mm256_storeu_pd(e0 + g, e[0]);
		_mm256_storeu_pd(e1 + g, e[1]);
		hit0 |= (uint32_t)_mm256_movemask_pd(_mm256_cmp_pd(e[0], inf, _CMP_NEQ_UQ)) << g;
		hit1 |= (uint32_t)_mm256_movemask_pd(_mm256_cmp_pd(e[1], inf, _CMP_NEQ_UQ)) << g;
		near1 |= (uint32_t)_mm256_movemask_pd(_mm256_cmp_pd(e[1], e[0], _CMP_LT_OQ)) << g;
	}
	*h0 = hit0;
	*h1 = hit1;
	*n1 = near1;
}

#include "accel/accel_packet.h"

/* WHITTED_ISA=sse2 keeps the SSE2 walks, to compare the two. */
bool accel_avx2_usable(void)
{
	const char *isa = getenv("WHITTED_ISA");

	if (isa && strcmp(isa, "sse2") == 0)
		return false;
	return __builtin_cpu_supports("avx2");
}

const struct shape *accel_avx2_intersect(const struct accel *a, const struct ray *r,
					 double t_min, double *t_max)
{
	return walk_avx2_intersect(a, r, t_min, t_max);
}

bool accel_avx2_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max)
{
	return walk_avx2_occluded(a, r, t_min, t_max);
}

void accel_avx2_intersect_packet(const struct accel *a, const struct ray *r, int n,
				 const double *t_min, double *t_max, const struct shape **hit)
{
	walk_avx2_intersect_packet(a, r, n, t_min, t_max, hit);
}

uint32_t accel_avx2_occluded_packet(const struct accel *a, const struct ray *r, int n,
				    const double *t_min, const double *t_max)
{
	return walk_avx2_occluded_packet(a, r, n, t_min, t_max);
}
#else
bool accel_avx2_usable(void)
{
	return false;
}

const struct shape *accel_avx2_intersect(const struct accel *a, const struct ray *r,
					 double t_min, double *t_max)
{
	(void)a;
	(void)r;
	(void)t_min;
	(void)t_max;
	return NULL;
}

bool accel_avx2_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max)
{
	(void)a;
	(void)r;
	(void)t_min;
	(void)t_max;
	return false;
}

void accel_avx2_intersect_packet(const struct accel *a, const struct ray *r, int n,
				 const double *t_min, double *t_max, const struct shape **hit)
{
	(void)a;
	(void)r;
	(void)n;
	(void)t_min;
	(void)t_max;
	(void)hit;
}

uint32_t accel_avx2_occluded_packet(const struct accel *a, const struct ray *r, int n,
				    const double *t_min, const double *t_max)
{
	(void)a;
	(void)r;
	(void)n;
	(void)t_min;
	(void)t_max;
	return 0;
}
#endif
