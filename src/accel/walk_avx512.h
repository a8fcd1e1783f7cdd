/* The AVX-512 set's walks, included by accel_kernels.c where it is
 * compiled with -mavx512f -mfma: over eight-child nodes, chosen at the
 * build where the processor has it.  A node's eight children are tested in
 * floats, eight to a 256-bit operation: half the work of the doubles the
 * other walks test in (the float boxes widened to double, eight to a
 * 512-bit operation, which a processor that splits those in two pays
 * twice), the course's 100k cloud 0.88x the time; each plane's distance
 * one multiply-add (slab_f), 0.955x more.  The float answer is
 * widened by a bound on its rounding error (accel_float_box.h), so every box
 * the double test enters is entered here too, at an entry no later: the
 * walk meets a superset of the shapes the other walks meet, in another
 * order, and since the nearest hit with the keys' tie rule and whether a
 * shadow ray is blocked do not depend on either (accel_walk.h), every
 * ray's answer, and so every image, is theirs.  A ray the bound cannot
 * hold is tested in doubles, as the other walks test it, to the bit: the
 * walks are here twice, over either test, and a ray (or a packet, if any
 * of its rays) takes the double ones from the start, so that the float
 * walk's loops carry no second test.  Packets go a ray a vector lane
 * (accel_packet_rays.h over the eight-child nodes, sixteen rays to a
 * float operation), their last few rays in a node alone. */
#include <immintrin.h>

#include "accel/accel_float_box.h"

#define ACCEL_NODE struct bvh8_node
#define ACCEL_W 8

/* v to the nearest float, broadcast: the processor's conversion, which
 * takes a finite v beyond the floats' range to +-inf (a C cast leaves
 * that undefined). */
static inline __m256 float_set1(double v)
{
	return _mm256_broadcastss_ps(_mm_cvtsd_ss(_mm_setzero_ps(), _mm_set_sd(v)));
}

/* Whether r moves along every axis, as slab_f needs. */
static inline bool ray_moves_on_every_axis(const struct ray *r)
{
	return r->dir.x != 0.0 && r->dir.y != 0.0 && r->dir.z != 0.0;
}

/* Whether the float walks can take r from t_min: the rays float_box_ray
 * holds that move along every axis; the others take the double walks. */
static inline bool float_fma_ray(const struct ray *r, double t_min)
{
	return float_box_ray(r, t_min) && ray_moves_on_every_axis(r);
}

struct walk_ray_float {
	__m256 oi[3], inv[3];	/* o inv, with o and inv rounded to floats */
	__m256 err;		/* e */
	int near_off[3], far_off[3];	/* float offsets into struct bvh8_node */
};

static inline void walk_ray_float_init(struct walk_ray_float *v, const struct ray_slab *rs)
{
	int k;

	for (k = 0; k < 3; k++) {
		v->inv[k] = float_set1(rs->inv[k]);
		v->oi[k] = _mm256_mul_ps(float_set1(rs->o[k]), v->inv[k]);
	}
	v->err = float_set1(float_box_err(rs->o, rs->inv));
	ray_slab_offsets(rs, ACCEL_W, v->near_off, v->far_off);
}

/* (b - o) inv as b inv - o inv, one multiply-add (rounded once) from the
 * ray's o inv (rounded once): within 3u |T| + 2u |o inv| of the double
 * test's T, inside the widening's 8u |T| + e (accel_float_box.h), and one
 * operation shorter than the subtraction and the product, on the walk's
 * longest chain of waits (cloud-100k's render 0.955x).  It needs inv
 * finite: (b - o) inf is +-inf, but b inf - o inf is NaN (float_fma_ray). */
static inline __m256 slab_f(const float *b, int off, __m256 oi, __m256 inv)
{
	return _mm256_fmsub_ps(_mm256_loadu_ps(b + off), inv, oi);
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

	lo = _mm256_max_ps(slab_f(b, v->near_off[0], v->oi[0], v->inv[0]), lo);
	hi = _mm256_min_ps(slab_f(b, v->far_off[0], v->oi[0], v->inv[0]), hi);
	lo = _mm256_max_ps(slab_f(b, v->near_off[1], v->oi[1], v->inv[1]), lo);
	hi = _mm256_min_ps(slab_f(b, v->far_off[1], v->oi[1], v->inv[1]), hi);
	lo = _mm256_max_ps(slab_f(b, v->near_off[2], v->oi[2], v->inv[2]), lo);
	hi = _mm256_min_ps(slab_f(b, v->far_off[2], v->oi[2], v->inv[2]), hi);
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
#undef walk_ray
#undef walk_ray_init
#undef node_entries
#undef node_hits
#undef ACCEL_WALK

/* Each ray over the float tests where they can bound its error. */
static const struct shape *walk_avx512_intersect(const struct accel *a, const struct ray *r,
						 double t_min, double *t_max)
{
	return float_fma_ray(r, t_min) ? walk_avx512_float_intersect(a, r, t_min, t_max)
				     : walk_avx512_exact_intersect(a, r, t_min, t_max);
}

static bool walk_avx512_occluded(const struct accel *a, const struct ray *r, double t_min,
				 double t_max)
{
	return float_fma_ray(r, t_min) ? walk_avx512_float_occluded(a, r, t_min, t_max)
				     : walk_avx512_exact_occluded(a, r, t_min, t_max);
}

#ifdef RT_TEST_HOOKS
static int walk_avx512_node_tests(const struct bvh8_node *node, const struct ray *r, double t_min,
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
	if (float_fma_ray(r, t_min)) {
		walk_ray_float_init(&f, &rs);
		mask = node_entries_float(node, &f, t_min, t_max, float_entry);
	}
	return mask;
}

#endif

#define ACCEL_WALK(name) walk_avx512_##name
#define RAYS_WALK(name) rays_avx512_##name
#include "accel/accel_packet_rays.h"
#undef RAYS_WALK

/* The same packets, a ray a lane, over the eight-child tree, where a
 * node's few rays left (at most four of the sixteen) go on alone: their
 * single walks from there, in floats or doubles as the packet's tests.
 * A box tested against all sixteen rays in one operation costs as much
 * as against one, and the rays of a coherent packet stay together for
 * the tree's first levels; past them, where a packet's rays part, each
 * walks at the single walk's cost (cloud-100k 0.95x, gen-100k 0.9x the
 * time of a node's children a lane for each ray, accel_packet.h). */
static inline void rays8_lane_nearest(const struct accel *a, size_t node,
				      const struct packet_rays *v, int i, struct walk_best *b)
{
	struct ray r = ray_packet_get(&v->s.p, i);
	struct ray_slab rs;

	ray_slab_init(&rs, &r);
	/* v->floats: float_box_ray holds for every lane already. */
	if (v->floats && ray_moves_on_every_axis(&r)) {
		struct walk_ray_float w;
		walk_ray_float_init(&w, &rs);
		walk_avx512_float_nearest_from(a, node, &w, &r, v->s.t_min[i], b);
	} else {
		struct walk_ray_exact w;
		walk_ray_exact_init(&w, &rs);
		walk_avx512_exact_nearest_from(a, node, &w, &r, v->s.t_min[i], b);
	}
}

static inline bool rays8_lane_occluded(const struct accel *a, size_t node,
				       const struct packet_rays *v, int i, double t_max)
{
	struct ray r = ray_packet_get(&v->s.p, i);
	struct ray_slab rs;

	ray_slab_init(&rs, &r);
	/* v->floats: float_box_ray holds for every lane already. */
	if (v->floats && ray_moves_on_every_axis(&r)) {
		struct walk_ray_float w;
		walk_ray_float_init(&w, &rs);
		return walk_avx512_float_occluded_from(a, node, &w, &r, v->s.t_min[i], t_max);
	} else {
		struct walk_ray_exact w;
		walk_ray_exact_init(&w, &rs);
		return walk_avx512_exact_occluded_from(a, node, &w, &r, v->s.t_min[i], t_max);
	}
}

#define RAYS_NODE struct bvh8_node
#define RAYS_W 8
#define RAYS_SINGLE_MAX 4
#define RAYS_LANE_NEAREST rays8_lane_nearest
#define RAYS_LANE_OCCLUDED rays8_lane_occluded
#define RAYS_WALK(name) rays8_avx512_##name
#include "accel/accel_packet_rays.h"

#undef RAYS_WALK
#define RAYS_WALK(name) rays_avx512_##name

/* The eight-child tree's packets are those a ray a lane. */
static void walk_avx512_intersect_packet(const struct accel *a, const struct ray *r, int n,
					 const double *t_min, double *t_max,
					 const struct shape **hit)
{
	rays8_avx512_intersect_packet(a, r, n, t_min, t_max, hit);
}

static uint32_t walk_avx512_occluded_packet(const struct accel *a, const struct ray *r, int n,
					    const double *t_min, const double *t_max)
{
	return rays8_avx512_occluded_packet(a, r, n, t_min, t_max);
}

#ifdef RT_TEST_HOOKS
static int walk_avx512_rays_node_tests(const struct bvh4_node *node, const struct ray *r,
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


#define ACCEL_KERNELS_TABLE { \
	.width = 8, \
	.intersect = walk_avx512_intersect, \
	.occluded = walk_avx512_occluded, \
	.wide = { \
		.intersect_packet = walk_avx512_intersect_packet, \
		.occluded_packet = walk_avx512_occluded_packet, \
		.intersect_lanes = rays8_avx512_intersect_lanes, \
		.occluded_lanes = rays8_avx512_occluded_lanes, \
	}, \
	.packets = "a ray a lane, few rays alone", \
	.rays4 = ACCEL_KERNELS_RAYS4(rays_avx512), \
	ACCEL_KERNELS_TEST_HOOKS(walk_avx512_node_tests, walk_avx512_rays_node_tests) \
}
