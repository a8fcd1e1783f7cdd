/* The hierarchy's walks over eight-child nodes with AVX-512 box tests,
 * compiled with -mavx512f (the Makefile, on x86) and chosen at the build
 * where the processor has it.  A node's eight children are tested in
 * floats, eight to a 256-bit operation: half the work of the doubles the
 * other walks test in (the float boxes widened to double, eight to a
 * 512-bit operation, which a processor that splits those in two pays
 * twice), the course's 100k cloud 0.88x the time.  The float answer is
 * widened by a bound on its rounding error (accel_float_box.h), so every box
 * the double test enters is entered here too, at an entry no later: the
 * walk meets a superset of the shapes the other walks meet, in another
 * order, and since the nearest hit with the keys' tie rule and whether a
 * shadow ray is blocked do not depend on either (accel_walk.h), every
 * ray's answer, and so every image, is theirs.  A ray the bound cannot
 * hold is tested in doubles, as the other walks test it, to the bit: the
 * walks are here twice, over either test, and a ray (or a packet, if any
 * of its rays) takes the double ones from the start, so that the float
 * walk's loops carry no second test. */
#include <math.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_float_box.h"
#include "accel/accel_slab.h"
#include "accel/accel_tree.h"

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#include <immintrin.h>

#define ACCEL_NODE struct bvh8_node
#define ACCEL_W 8

/* v to the nearest float, broadcast: the processor's conversion, which
 * takes a finite v beyond the floats' range to +-inf (a C cast leaves
 * that undefined). */
static inline __m256 float_set1(double v)
{
	return _mm256_broadcastss_ps(_mm_cvtsd_ss(_mm_setzero_ps(), _mm_set_sd(v)));
}

struct walk_ray_float {
	__m256 o[3], inv[3];	/* rounded to the nearest float */
	__m256 err;		/* e */
	int near_off[3], far_off[3];	/* float offsets into struct bvh8_node */
};

static inline void walk_ray_float_init(struct walk_ray_float *v, const struct ray_slab *rs)
{
	int k;

	for (k = 0; k < 3; k++) {
		v->o[k] = float_set1(rs->o[k]);
		v->inv[k] = float_set1(rs->inv[k]);
	}
	v->err = float_set1(float_box_err(rs->o, rs->inv));
	ray_slab_offsets(rs, ACCEL_W, v->near_off, v->far_off);
}

static inline __m256 slab_f(const float *b, int off, __m256 o, __m256 inv)
{
	return _mm256_mul_ps(_mm256_sub_ps(_mm256_loadu_ps(b + off), o), inv);
}

/* The children's entries, and the mask of those entered: the float test
 * widened as above, max and min with the second operand winning a NaN as
 * in the double test. */
static inline __m512d node_interval_float(const struct bvh8_node *node,
					  const struct walk_ray_float *v, double t_min,
					  double t_max, int *mask)
{
	const float *b = &node->lo[0][0];
	__m256 lo = float_set1(t_min), hi = float_set1(t_max);

	lo = _mm256_max_ps(slab_f(b, v->near_off[0], v->o[0], v->inv[0]), lo);
	hi = _mm256_min_ps(slab_f(b, v->far_off[0], v->o[0], v->inv[0]), hi);
	lo = _mm256_max_ps(slab_f(b, v->near_off[1], v->o[1], v->inv[1]), lo);
	hi = _mm256_min_ps(slab_f(b, v->far_off[1], v->o[1], v->inv[1]), hi);
	lo = _mm256_max_ps(slab_f(b, v->near_off[2], v->o[2], v->inv[2]), lo);
	hi = _mm256_min_ps(slab_f(b, v->far_off[2], v->o[2], v->inv[2]), hi);
	lo = _mm256_fmsub_ps(lo, _mm256_set1_ps(1.0f - FLOAT_BOX_REL), v->err);
	hi = _mm256_fmadd_ps(hi, _mm256_set1_ps(1.0f + FLOAT_BOX_REL), v->err);
	*mask = _mm256_movemask_ps(_mm256_cmp_ps(lo, hi, _CMP_LE_OQ));
	return _mm512_cvtps_pd(lo);
}

static inline int node_entries_float(const struct bvh8_node *node, const struct walk_ray_float *v,
				     double t_min, double t_max, double entry[8])
{
	int mask;

	_mm512_storeu_pd(entry, node_interval_float(node, v, t_min, t_max, &mask));
	return mask;
}

static inline int node_hits_float(const struct bvh8_node *node, const struct walk_ray_float *v,
				  double t_min, double t_max)
{
	int mask;

	(void)node_interval_float(node, v, t_min, t_max, &mask);
	return mask;
}

struct walk_ray_exact {
	__m512d o[3], inv[3];
	int near_off[3], far_off[3];	/* float offsets into struct bvh8_node */
};

static inline void walk_ray_exact_init(struct walk_ray_exact *v, const struct ray_slab *rs)
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

/* The double test: the other walks' arithmetic lane by lane (float bounds
 * widened to double, then (b - o) * inv, no fused multiply-add; max and
 * min return their second operand for a NaN, as SSE2's do). */
static inline __m512d node_interval_exact(const struct bvh8_node *node,
					  const struct walk_ray_exact *v, double t_min,
					  double t_max, int *mask)
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

static inline int node_entries_exact(const struct bvh8_node *node, const struct walk_ray_exact *v,
				     double t_min, double t_max, double entry[8])
{
	int mask;

	_mm512_storeu_pd(entry, node_interval_exact(node, v, t_min, t_max, &mask));
	return mask;
}

static inline int node_hits_exact(const struct bvh8_node *node, const struct walk_ray_exact *v,
				  double t_min, double t_max)
{
	int mask;

	(void)node_interval_exact(node, v, t_min, t_max, &mask);
	return mask;
}

/* The walks twice: over the float tests, and over the double ones. */
#define walk_ray walk_ray_float
#define walk_ray_init walk_ray_float_init
#define node_entries node_entries_float
#define node_hits node_hits_float
#define ACCEL_WALK(name) walk_avx512_float_##name
#include "accel/accel_walk.h"
#include "accel/accel_packet.h"
#undef walk_ray
#undef walk_ray_init
#undef node_entries
#undef node_hits
#undef ACCEL_WALK

#define walk_ray walk_ray_exact
#define walk_ray_init walk_ray_exact_init
#define node_entries node_entries_exact
#define node_hits node_hits_exact
#define ACCEL_WALK(name) walk_avx512_exact_##name
#include "accel/accel_walk.h"
#include "accel/accel_packet.h"
#undef walk_ray
#undef walk_ray_init
#undef node_entries
#undef node_hits
#undef ACCEL_WALK

/* Each ray, or packet, over the float tests where they can bound its
 * error. */
static bool walk_floats_all(const struct ray *r, int n, const double *t_min)
{
	int i;

	for (i = 0; i < n; i++)
		if (!float_box_ray(r + i, t_min[i]))
			return false;
	return true;
}

static const struct shape *walk_avx512_intersect(const struct accel *a, const struct ray *r,
						 double t_min, double *t_max)
{
	return float_box_ray(r, t_min) ? walk_avx512_float_intersect(a, r, t_min, t_max)
				     : walk_avx512_exact_intersect(a, r, t_min, t_max);
}

static bool walk_avx512_occluded(const struct accel *a, const struct ray *r, double t_min,
				 double t_max)
{
	return float_box_ray(r, t_min) ? walk_avx512_float_occluded(a, r, t_min, t_max)
				     : walk_avx512_exact_occluded(a, r, t_min, t_max);
}

static void walk_avx512_intersect_packet(const struct accel *a, const struct ray *r, int n,
					 const double *t_min, double *t_max,
					 const struct shape **hit)
{
	if (walk_floats_all(r, n, t_min))
		walk_avx512_float_intersect_packet(a, r, n, t_min, t_max, hit);
	else
		walk_avx512_exact_intersect_packet(a, r, n, t_min, t_max, hit);
}

static uint32_t walk_avx512_occluded_packet(const struct accel *a, const struct ray *r, int n,
					    const double *t_min, const double *t_max)
{
	return walk_floats_all(r, n, t_min)
		       ? walk_avx512_float_occluded_packet(a, r, n, t_min, t_max)
		       : walk_avx512_exact_occluded_packet(a, r, n, t_min, t_max);
}

#ifdef RT_TEST_HOOKS
int accel_avx512_node_tests(const struct bvh8_node *node, const struct ray *r, double t_min,
			    double t_max, double float_entry[8], int *exact_mask,
			    double exact_entry[8])
{
	struct ray_slab rs;
	struct walk_ray_float f;
	struct walk_ray_exact x;
	int mask = -1;

	ray_slab_init(&rs, r);
	walk_ray_exact_init(&x, &rs);
	*exact_mask = node_entries_exact(node, &x, t_min, t_max, exact_entry);
	if (float_box_ray(r, t_min)) {
		walk_ray_float_init(&f, &rs);
		mask = node_entries_float(node, &f, t_min, t_max, float_entry);
	}
	return mask;
}

#endif

#define ACCEL_WALK(name) walk_avx512_##name
#define RAYS_WALK(name) rays_avx512_##name
#include "accel/accel_packet_rays.h"

#ifdef RT_TEST_HOOKS
int accel_avx512_rays_node_tests(const struct bvh4_node *node, const struct ray *r,
				 const double *t_min, const double *t_max, uint32_t float_child[4],
				 double float_entry[4][ACCEL_PACKET], uint32_t exact_child[4],
				 double exact_entry[4][ACCEL_PACKET])
{
	struct packet_rays v;
	bool floats;

	rays_avx512_load(&v, r, ACCEL_PACKET, t_min);
	floats = v.floats;
	rays_avx512_prepare_doubles(&v);
	rays_avx512_node_lanes(node, &v, packet_all(ACCEL_PACKET), t_max, exact_entry, exact_child);
	if (!floats)
		return 0;
	rays_avx512_node_lanes_floats(node, &v, packet_all(ACCEL_PACKET), t_max, float_entry, 0,
				      NULL, float_child);
	return 1;
}

#endif

#define ACCEL_COMPILED 1
#elif defined(RT_TEST_HOOKS)
int accel_avx512_node_tests(const struct bvh8_node *node, const struct ray *r, double t_min,
			    double t_max, double float_entry[8], int *exact_mask,
			    double exact_entry[8])
{
	(void)node;
	(void)r;
	(void)t_min;
	(void)t_max;
	(void)float_entry;
	(void)exact_entry;
	*exact_mask = 0;
	return -1;
}

int accel_avx512_rays_node_tests(const struct bvh4_node *node, const struct ray *r,
				 const double *t_min, const double *t_max, uint32_t float_child[4],
				 double float_entry[4][ACCEL_PACKET], uint32_t exact_child[4],
				 double exact_entry[4][ACCEL_PACKET])
{
	(void)node;
	(void)r;
	(void)t_min;
	(void)t_max;
	(void)float_child;
	(void)float_entry;
	(void)exact_child;
	(void)exact_entry;
	return -1;
}
#endif

#define ACCEL_EXPORT(name) accel_avx512_##name
#include "accel/accel_walk_export.h"
