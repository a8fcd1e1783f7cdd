/* Packets through the four-child tree (the one small scenes get: see
 * accel_build.c) with each child's box tested against all the packet's
 * rays at once, a ray a vector lane (base/lanes.h: eight in one AVX-512
 * register), where the walks of accel_packet.h test a node's children at
 * once for one ray after another.  In a small tree the rays of a coherent
 * packet meet the same few nodes, so a box tested once for all sixteen
 * costs little more than for one.  Written once over base/lanes.h: the
 * including file, compiled for one set of instructions, defines
 * RAYS_WALK(name), the names the walks get.  Each lane does the single
 * walk's arithmetic on the same float boxes (accel.c: entry = max(t_min,
 * the near plane's t), exit = min(t_max, the far plane's t), a NaN
 * constraining nothing), or in AVX-512 the float tests that enter every
 * box it enters, no later (accel_float_box.h), and a shape is tested for
 * the lanes that enter its leaf against their best so far with the keys'
 * tie rule: so each ray's answer is its single walk's to the bit.
 * Nothing here allocates or locks. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_float_box.h"
#include "accel/accel_packet_common.h"
#include "accel/accel_tree.h"
#include "base/lanes.h"

#define LANES ACCEL_PACKET
/* The node the walks take, and its width: the four-child tree's unless
 * the including file says otherwise (the AVX-512 walk's eight-child
 * tree). */
#ifndef RAYS_NODE
#define RAYS_NODE struct bvh4_node
#define RAYS_W 4
#endif

#ifndef RT_ACCEL_PACKET_RAYS_COMMON
#define RT_ACCEL_PACKET_RAYS_COMMON
/* The packet's rays as the box tests take them, every lane filled: the
 * double tests' reciprocal directions, or where the AVX-512 walk's float
 * tests hold every lane tested (floats), those tests' own values
 * (accel_float_box.h) and the lanes whose axis k has its maximum as the
 * near plane. */
struct packet_rays {
	struct packet_shape_rays s;
	double inv[3][LANES];
	bool floats;
	float of[3][LANES], invf[3][LANES], errf[LANES], t_minf[LANES];
	uint32_t far_first[3];
};
#endif

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE) && ACCEL_PACKET == 16
#define RAYS_FLOATS 1
#ifndef RT_ACCEL_PACKET_RAYS_FLOATS16
#define RT_ACCEL_PACKET_RAYS_FLOATS16
/* float_box_ray's limits lowered to floats: 2^99 < 1e30, 2^122 < 1e37. */
#define RAYS_COORD_MAX 0x1p99f
#define RAYS_T_MIN_MAX 0x1p122f
/* Sixteen doubles to the nearest floats, by the processor's conversion
 * (which takes a finite value beyond the floats' range to +-inf). */
static inline __m512 rays_floats16(const double *v)
{
	__m256 lo = _mm512_cvtpd_ps(_mm512_loadu_pd(v)), hi = _mm512_cvtpd_ps(_mm512_loadu_pd(v + 8));

	return _mm512_castpd_ps(_mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_castps_pd(lo)),
						   _mm256_castps_pd(hi), 1));
}
#endif
#else
#define RAYS_FLOATS 0
#endif

/* The reciprocal directions of the double tests. */
static inline void RAYS_WALK(prepare_doubles)(struct packet_rays *v)
{
	const lv one = lv_set1(1.0), zero = lv_set1(0.0);
	int j;

	/* As ray_slab_init: + 0.0 makes -0 take the minimum as its near
	 * plane. */
	for (j = 0; j < LANES; j += LANES_W) {
		lv_store(v->inv[0] + j, lv_div(one, lv_add(lv_load(v->s.p.dx + j), zero)));
		lv_store(v->inv[1] + j, lv_div(one, lv_add(lv_load(v->s.p.dy + j), zero)));
		lv_store(v->inv[2] + j, lv_div(one, lv_add(lv_load(v->s.p.dz + j), zero)));
	}
}

#if RAYS_FLOATS
/* The float tests' values, all sixteen lanes at once, where float_box_ray
 * holds for every lane of `active` (else false, and the double tests
 * take the packet): o and t_min to the nearest float, inv the inverse of
 * d rounded to a float (within 2u of 1 / d: accel_float_box.h), e from
 * those in float (at least 4u |o inv| (1 - 5u), as the bound wants).
 * float_box_ray's limits are checked on the rounded values, which is
 * what costs nothing here: rounding to nearest keeps order, so a rounded
 * value strictly inside a limit that is itself a float (ACCEL_COORD_MAX
 * and FLOAT_BOX_T_MIN_MAX lowered to one) comes from a double inside it
 * too.  A value on a limit goes to the doubles, as do the lanes whose t_min
 * rounds to a zero with its sign bit set.  A direction's coordinate that
 * rounds to 0 is looked at in double: float_box_ray wants it exactly 0.
 * (Checking the doubles before rounding them took 3.5% of the course
 * example's render.) */
static inline bool RAYS_WALK(prepare_floats)(struct packet_rays *v, uint32_t active)
{
	const __m512 zero = _mm512_setzero_ps(), one = _mm512_set1_ps(1.0f);
	const __m512 inf = _mm512_set1_ps(INFINITY);
	const double *o_of[3] = { v->s.p.ox, v->s.p.oy, v->s.p.oz };
	const double *d_of[3] = { v->s.p.dx, v->s.p.dy, v->s.p.dz };
	const __m512 t = rays_floats16(v->s.t_min);
	__m512 o[3], d[3], e = zero;
	__mmask16 hold, zeros[3];
	int k;

	hold = _mm512_cmp_epi32_mask(_mm512_castps_si512(t), _mm512_setzero_si512(), _MM_CMPINT_NLT) &
	       _mm512_cmp_ps_mask(t, _mm512_set1_ps(RAYS_T_MIN_MAX), _CMP_LT_OQ);
	for (k = 0; k < 3; k++) {
		__m512 ad;

		o[k] = rays_floats16(o_of[k]);
		d[k] = rays_floats16(d_of[k]);
		ad = _mm512_abs_ps(d[k]);
		zeros[k] = _mm512_cmp_ps_mask(d[k], zero, _CMP_EQ_OQ);
		hold &= _mm512_cmp_ps_mask(_mm512_abs_ps(o[k]), _mm512_set1_ps(RAYS_COORD_MAX),
					   _CMP_LT_OQ) &
			_mm512_cmp_ps_mask(ad, _mm512_set1_ps((float)FLOAT_BOX_DIR_MAX), _CMP_LT_OQ) &
			(_mm512_cmp_ps_mask(ad, _mm512_set1_ps((float)FLOAT_BOX_DIR_MIN), _CMP_GT_OQ) |
			 zeros[k]);
	}
	if ((hold & active) != active)
		return false;
	for (k = 0; k < 3; k++) {
		uint32_t m;

		for (m = zeros[k] & active; m; m &= m - 1)
			if (d_of[k][__builtin_ctz(m)] != 0.0)
				return false;
	}
	for (k = 0; k < 3; k++) {
		__m512 inv = _mm512_div_ps(one, _mm512_add_ps(d[k], zero));
		__m512 oi = _mm512_abs_ps(_mm512_mul_ps(o[k], inv));
		__mmask16 finite = _mm512_cmp_ps_mask(_mm512_abs_ps(inv), inf, _CMP_NEQ_UQ);

		_mm512_storeu_ps(v->of[k], o[k]);
		_mm512_storeu_ps(v->invf[k], inv);
		v->far_first[k] = _mm512_cmp_ps_mask(inv, zero, _CMP_LT_OQ);
		e = _mm512_mask_blend_ps(finite & _mm512_cmp_ps_mask(oi, e, _CMP_GT_OQ), e, oi);
	}
	e = _mm512_mul_ps(_mm512_mul_ps(e, _mm512_set1_ps((float)FLOAT_BOX_ABS)),
			  _mm512_set1_ps(1.0f + 0x1p-20f));
	e = _mm512_max_ps(e, _mm512_set1_ps((float)FLOAT_BOX_ERR_MIN));
	_mm512_storeu_ps(v->errf, e);
	_mm512_storeu_ps(v->t_minf, t);
	return true;
}
#endif

/* What the box tests need of v's rays besides the shapes' (filled), for
 * the lanes of `active`: the float tests' values where they hold those
 * lanes, else the double tests'. */
static inline void RAYS_WALK(prepare)(struct packet_rays *v, uint32_t active)
{
	(void)active;
#if RAYS_FLOATS
	v->floats = RAYS_WALK(prepare_floats)(v, active);
	if (v->floats)
		return;
#endif
	v->floats = false;
	RAYS_WALK(prepare_doubles)(v);
}

static inline void RAYS_WALK(load)(struct packet_rays *v, const struct ray *r, int n,
				   const double *t_min)
{
	packet_shape_rays_load(&v->s, r, n, t_min);
	RAYS_WALK(prepare)(v, packet_all(n));
}

#if RAYS_FLOATS
/* node_lanes in floats, all sixteen lanes in one operation, widened as
 * accel_float_box.h says: every child the double test enters for a lane
 * is entered, at an entry no later; so the walks meet a superset of the
 * shapes, and give the same answers.  For packets whose every lane the
 * float tests hold (v->floats). */
static inline void RAYS_WALK(node_lanes_floats)(const RAYS_NODE *nd,
						const struct packet_rays *v, uint32_t mask,
						const double *t_max, double (*entry)[LANES],
						int lead, double *first, uint32_t child[RAYS_W])
{
	const __m512 down = _mm512_set1_ps(1.0f - FLOAT_BOX_REL), up = _mm512_set1_ps(1.0f + FLOAT_BOX_REL);
	const __m512 tn = _mm512_loadu_ps(v->t_minf), tx = rays_floats16(t_max);
	const __m512 err = _mm512_loadu_ps(v->errf);
	__m512 o[3], inv[3];
	int c, k;

	for (k = 0; k < 3; k++) {
		o[k] = _mm512_loadu_ps(v->of[k]);
		inv[k] = _mm512_loadu_ps(v->invf[k]);
	}
	for (c = 0; c < RAYS_W; c++) {
		__m512 lo = tn, hi = tx;

		child[c] = 0;
		if (!nd->slot[c])
			continue;
		for (k = 0; k < 3; k++) {
			__m512 b0 = _mm512_set1_ps(nd->lo[k][c]), b1 = _mm512_set1_ps(nd->hi[k][c]);
			__mmask16 ff = (__mmask16)v->far_first[k];
			__m512 t0 = _mm512_mul_ps(_mm512_sub_ps(_mm512_mask_blend_ps(ff, b0, b1), o[k]), inv[k]);
			__m512 t1 = _mm512_mul_ps(_mm512_sub_ps(_mm512_mask_blend_ps(ff, b1, b0), o[k]), inv[k]);
			lo = _mm512_max_ps(t0, lo);
			hi = _mm512_min_ps(t1, hi);
		}
		lo = _mm512_fmsub_ps(lo, down, err);
		hi = _mm512_fmadd_ps(hi, up, err);
		child[c] = (uint32_t)_mm512_cmp_ps_mask(lo, hi, _CMP_LE_OQ) & mask;
		if (entry) {
			_mm512_storeu_pd(entry[c], _mm512_cvtps_pd(_mm512_castps512_ps256(lo)));
			_mm512_storeu_pd(entry[c] + 8,
					 _mm512_cvtps_pd(_mm256_castpd_ps(
						 _mm512_extractf64x4_pd(_mm512_castps_pd(lo), 1))));
		}
		if (first) {
			/* The lead lane's entry alone, which is all the order
			 * reads: one lane out of the vector, not sixteen. */
			float lanes[LANES];

			_mm512_storeu_ps(lanes, lo);
			first[c] = child[c] >> lead & 1 ? (double)lanes[lead] : INFINITY;
		}
	}
}
#endif

/* The lanes of `mask` entering each child of node nd within (t_min,
 * t_max[lane]) into child[c] (none for an empty slot), and, where entry
 * is not NULL, the entries of the groups of lanes tested.  The four
 * children go together, a group of lanes at a time: their tests are
 * independent, so they overlap, where one child after another waited on
 * each test's chain of maxima and minima. */
static inline void RAYS_WALK(node_lanes)(const RAYS_NODE *nd, const struct packet_rays *v,
					 uint32_t mask, const double *t_max, double (*entry)[LANES],
					 uint32_t child[RAYS_W])
{
	const lv zero = lv_set1(0.0);
	const double *o_of[3] = { v->s.p.ox, v->s.p.oy, v->s.p.oz };
	int j, k, c;

	for (c = 0; c < RAYS_W; c++)
		child[c] = 0;
	for (j = 0; j < LANES; j += LANES_W) {
		lv o[3], inv[3], tn, tx;
		lm far_first[3];

		if (!(mask >> j & ((1u << LANES_W) - 1)))
			continue;
		tn = lv_load(v->s.t_min + j);
		tx = lv_load(t_max + j);
		for (k = 0; k < 3; k++) {
			o[k] = lv_load(o_of[k] + j);
			inv[k] = lv_load(v->inv[k] + j);
			far_first[k] = lv_lt(inv[k], zero);
		}
		for (c = 0; c < RAYS_W; c++) {
			lv lo = tn, hi = tx;

			if (!nd->slot[c])
				continue;
			for (k = 0; k < 3; k++) {
				lv b0 = lv_set1(nd->lo[k][c]), b1 = lv_set1(nd->hi[k][c]);
				lv t0 = lv_mul(lv_sub(lv_sel(far_first[k], b1, b0), o[k]), inv[k]);
				lv t1 = lv_mul(lv_sub(lv_sel(far_first[k], b0, b1), o[k]), inv[k]);
				lo = lv_max_first(t0, lo);
				hi = lv_min_first(t1, hi);
			}
			if (entry)
				lv_store(entry[c] + j, lo);
			child[c] |= (uint32_t)lm_bits(lv_le(lo, hi)) << j;
		}
	}
	for (c = 0; c < RAYS_W; c++)
		child[c] &= mask;
}

/* The children's lanes by the float tests where they hold the packet,
 * else by the double ones; where first is not NULL, each child's entry
 * for the packet's lead lane (the lowest of mask), INFINITY for a child
 * that lane does not enter. */
static inline __attribute__((always_inline)) void
RAYS_WALK(node_test)(const RAYS_NODE *nd, const struct packet_rays *v, uint32_t mask,
		     const double *t_max, double *first, uint32_t child[RAYS_W])
{
	int lead = __builtin_ctz(mask), c;

#if RAYS_FLOATS
	if (v->floats) {
		RAYS_WALK(node_lanes_floats)(nd, v, mask, t_max, NULL, lead, first, child);
		return;
	}
#endif
	{
		double e[RAYS_W][LANES];

		RAYS_WALK(node_lanes)(nd, v, mask, t_max, first ? e : NULL, child);
		for (c = 0; first && c < RAYS_W; c++)
			first[c] = child[c] >> lead & 1 ? e[c][lead] : INFINITY;
	}
}

/* The nearest hits of v's rays of `all` (not 0), loaded, from t_max[i]
 * down. */
static void RAYS_WALK(intersect_rays)(const struct accel *a, const struct packet_rays *v,
				      uint32_t all, double *t_max, const struct shape **hit)
{
	struct { uintptr_t slot; uint32_t mask; } stack[ACCEL_WALK_STACK + 1];
	struct walk_best b[LANES];
	double bt[LANES];
	uint32_t m;
	size_t i;
	int top = 0, first = __builtin_ctz(all);

	for (i = 0; i < LANES; i++) {
		b[i].t = t_max[all >> i & 1 ? (int)i : first];
		b[i].hit = NULL;
		b[i].key = 0;
	}
	for (i = 0; i < a->n_unbounded; i++)
		packet_best_test(a->unbounded[i], a->unbounded_key[i], &v->s, all, b);
	if (a->n_nodes > 0) {
		stack[top].slot = accel_slot_make(0, ACCEL_SLOT_NODE);
		stack[top++].mask = all;
	}
	while (top > 0) {
		const RAYS_NODE *nd;
		uint32_t mask, child[RAYS_W];
		double first[RAYS_W];
		int order[RAYS_W], count, c, k;
		unsigned in_any = 0;
		uintptr_t slot;

		top--;
		slot = stack[top].slot;
		mask = stack[top].mask;
		if (!accel_slot_is_node(slot)) {
			packet_leaf_nearest(a, slot, &v->s, mask, b);
			continue;
		}
#ifdef RAYS_SINGLE_MAX
		/* A few rays left: on alone, each by its single walk. */
		if (__builtin_popcount(mask) <= RAYS_SINGLE_MAX) {
			for (m = mask; m; m &= m - 1)
				RAYS_LANE_NEAREST(a, accel_slot_index(slot), v, __builtin_ctz(m),
						  &b[__builtin_ctz(m)]);
			continue;
		}
#endif
		nd = &((const RAYS_NODE *)a->nodes)[accel_slot_index(slot)];
		for (i = 0; i < LANES; i++)
			bt[i] = b[i].t;
		RAYS_WALK(node_test)(nd, v, mask, bt, first, child);
		for (c = 0; c < RAYS_W; c++)
			in_any |= (unsigned)(child[c] != 0) << c;
		if (!in_any)
			continue;
		if (RAYS_W > 4)
			prefetch_children(a, nd->slot, in_any, sizeof(*nd));
		/* The children in the order the packet's first ray meets
		 * them (the ones it misses last), pushed farthest first. */
		count = order_children(in_any, first, order);
		for (k = count - 1; k >= 0; k--) {
			stack[top].slot = nd->slot[order[k]];
			stack[top++].mask = child[order[k]];
		}
	}
	for (m = all; m; m &= m - 1) {
		i = (size_t)__builtin_ctz(m);
		t_max[i] = b[i].t;
		hit[i] = b[i].hit;
	}
}

static void RAYS_WALK(intersect_packet)(const struct accel *a, const struct ray *r, int n,
					const double *t_min, double *t_max,
					const struct shape **hit)
{
	struct packet_rays v;

	if (n <= 0)
		return;
	RAYS_WALK(load)(&v, r, n, t_min);
	RAYS_WALK(intersect_rays)(a, &v, packet_all(n), t_max, hit);
}

/* from's n arrays (the packet's coordinates, then t_min, and t_max
 * where a walk takes it from there) into to's, the lanes not in `active`
 * copies of the first one in it, as the shapes' packet methods may read
 * them (whitted/shape.h): the caller's may hold no ray at all. */
static inline void RAYS_WALK(lanes_copy)(const double *const *from, double *const *to, int n,
					 uint32_t active)
{
	int first = __builtin_ctz(active), j, k;

	for (k = 0; k < n; k++) {
		const lv copy = lv_set1(from[k][first]);
		for (j = 0; j < LANES; j += LANES_W)
			lv_store(to[k] + j, lv_sel(lm_from_bits(active >> j), lv_load(from[k] + j), copy));
	}
}

/* accel_intersect_lanes: the packet's lanes of `active` as they are. */
static void RAYS_WALK(intersect_lanes)(const struct accel *a, const struct ray_packet *p,
				       uint32_t active, const double *t_min, double *t_max,
				       const struct shape **hit)
{
	const double *from[7] = { p->ox, p->oy, p->oz, p->dx, p->dy, p->dz, t_min };
	struct packet_rays v;
	double *const to[7] = { v.s.p.ox, v.s.p.oy, v.s.p.oz, v.s.p.dx, v.s.p.dy, v.s.p.dz,
				v.s.t_min };

	if (!active)
		return;
	RAYS_WALK(lanes_copy)(from, to, 7, active);
	RAYS_WALK(prepare)(&v, active);
	RAYS_WALK(intersect_rays)(a, &v, active, t_max, hit);
}

/* Which rays of `all` anything blocks in (t_min, t_far[lane]): v's
 * rays, loaded. */
static uint32_t RAYS_WALK(occluded_rays)(const struct accel *a, const struct packet_rays *v,
					 uint32_t all, const double *t_far)
{
	struct { size_t node; uint32_t mask; } stack[ACCEL_WALK_STACK + 1];
	uint32_t open = all;
	double t[LANES];
	size_t i;
	int top = 0;

	for (i = 0; i < a->n_unbounded && open; i++) {
		memcpy(t, t_far, sizeof(t));
		open &= ~shape_intersect_packet(a->unbounded[i], &v->s.p, open, v->s.t_min, t);
	}
	if (a->n_nodes == 0 || !open)
		return all & ~open;
	stack[top].node = 0;
	stack[top++].mask = open;
	while (top > 0) {
		const RAYS_NODE *nd;
		uint32_t mask, child[RAYS_W];
		int c;

		top--;
		mask = stack[top].mask & open;
		if (!mask)
			continue;
#ifdef RAYS_SINGLE_MAX
		if (__builtin_popcount(mask) <= RAYS_SINGLE_MAX) {
			uint32_t m;
			for (m = mask; m; m &= m - 1)
				if (RAYS_LANE_OCCLUDED(a, stack[top].node, v, __builtin_ctz(m),
						       t_far[__builtin_ctz(m)]))
					open &= ~((uint32_t)1 << __builtin_ctz(m));
			if (!open)
				return all;
			continue;
		}
#endif
		nd = &((const RAYS_NODE *)a->nodes)[stack[top].node];
		RAYS_WALK(node_test)(nd, v, mask, t_far, NULL, child);
		if (RAYS_W > 4) {
			unsigned in_any = 0;
			for (c = 0; c < RAYS_W; c++)
				in_any |= (unsigned)(child[c] != 0) << c;
			prefetch_children(a, nd->slot, in_any, sizeof(*nd));
		}
		for (c = 0; c < RAYS_W; c++) {
			uintptr_t s = nd->slot[c];
			uint32_t in = child[c] & open;

			if (!in)
				continue;
			if (accel_slot_is_node(s)) {
				stack[top].node = accel_slot_index(s);
				stack[top++].mask = in;
				continue;
			}
			open &= ~packet_leaf_any(a, s, &v->s, in, t_far);
			if (!open)
				return all;
		}
	}
	return all & ~open;
}

static uint32_t RAYS_WALK(occluded_packet)(const struct accel *a, const struct ray *r, int n,
					   const double *t_min, const double *t_max)
{
	struct packet_rays v;
	double t_far[LANES];
	size_t i;

	RAYS_WALK(load)(&v, r, n, t_min);
	for (i = 0; i < LANES; i++)
		t_far[i] = t_max[i < (size_t)n ? i : 0];
	return RAYS_WALK(occluded_rays)(a, &v, packet_all(n), t_far);
}

/* accel_occluded_lanes: the packet's lanes as they are, those of
 * `active` traced. */
static uint32_t RAYS_WALK(occluded_lanes)(const struct accel *a, const struct ray_packet *p,
					  uint32_t active, const double *t_min,
					  const double *t_max)
{
	const double *from[8] = { p->ox, p->oy, p->oz, p->dx, p->dy, p->dz, t_min, t_max };
	struct packet_rays v;
	double t_far[LANES];
	double *const to[8] = { v.s.p.ox, v.s.p.oy, v.s.p.oz, v.s.p.dx, v.s.p.dy, v.s.p.dz,
				v.s.t_min, t_far };

	if (!active)
		return 0;
	/* The lanes not traced: a light at its point has no ray. */
	RAYS_WALK(lanes_copy)(from, to, 8, active);
	RAYS_WALK(prepare)(&v, active);
	return RAYS_WALK(occluded_rays)(a, &v, active, t_far);
}
#undef LANES
#undef RAYS_FLOATS
#undef RAYS_NODE
#undef RAYS_W
#undef RAYS_SINGLE_MAX
