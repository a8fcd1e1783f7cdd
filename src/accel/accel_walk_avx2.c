/* The hierarchy's walks with AVX2 box tests, compiled with -mavx2 (the
 * Makefile, on x86) and chosen at start-up where the processor has it.
 * One four-lane operation takes a plane's slab distances of all four
 * children of a node, in the SSE2 walk's arithmetic lane by lane (float
 * bounds widened to double, then (b - o) * inv, no fused multiply-add),
 * so every entry, exit and miss is the SSE2 walk's to the bit, and so is
 * every image. */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_slab.h"
#include "accel/accel_tree.h"

#if defined(__AVX2__) && !defined(ACCEL_PORTABLE)
#include <immintrin.h>

struct walk_ray {
	__m256d o[3], inv[3];
	int near_off[3], far_off[3];	/* float offsets into struct bvh4_node */
};

static inline void walk_ray_init(struct walk_ray *v, const struct ray_slab *rs)
{
	int k;

	for (k = 0; k < 3; k++) {
		v->o[k] = _mm256_set1_pd(rs->o[k]);
		v->inv[k] = _mm256_set1_pd(rs->inv[k]);
		v->near_off[k] = rs->near[k] * 3 * ACCEL_WIDTH + ACCEL_WIDTH * k;
		v->far_off[k] = (1 - rs->near[k]) * 3 * ACCEL_WIDTH + ACCEL_WIDTH * k;
	}
}

static inline __m256d slab_t(const float *b, int off, __m256d o, __m256d inv)
{
	return _mm256_mul_pd(_mm256_sub_pd(_mm256_cvtps_pd(_mm_load_ps(b + off)), o), inv);
}

/* The entries of children 4h .. 4h + 3, and the mask of those entered. */
static inline __m256d node_interval(const struct bvh4_node *node, const struct walk_ray *v,
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

static inline int node_entries(const struct bvh4_node *node, const struct walk_ray *v,
			       double t_min, double t_max, double entry[ACCEL_WIDTH])
{
	int mask = 0, m, h;

	for (h = 0; h < ACCEL_WIDTH / 4; h++) {
		_mm256_storeu_pd(entry + 4 * h, node_interval(node, v, h, t_min, t_max, &m));
		mask |= m << 4 * h;
	}
	return mask;
}

static inline int node_hits(const struct bvh4_node *node, const struct walk_ray *v,
			    double t_min, double t_max)
{
	int mask = 0, m, h;

	for (h = 0; h < ACCEL_WIDTH / 4; h++) {
		(void)node_interval(node, v, h, t_min, t_max, &m);
		mask |= m << 4 * h;
	}
	return mask;
}

#define ACCEL_WALK(name) walk_avx2_##name
#include "accel/accel_walk.h"
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
