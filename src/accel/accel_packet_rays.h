/* Packets through the four-child tree (the one small scenes get: see
 * accel_build.c) with each child's box tested against all the packet's
 * rays at once, a ray a vector lane (base/lanes.h: eight in one AVX-512
 * register), where the walks of accel_packet.h test a node's children at
 * once for one ray after another.  In a small tree the rays of a coherent
 * packet meet the same few nodes, so a box tested once for all sixteen
 * costs little more than for one.  Written once over base/lanes.h: the
 * including file, compiled for one set of instructions, defines
 * RAYS_WALK(name), the names the walks get.  Each lane does the single
 * walk's arithmetic on the same float boxes (walk_base.h: entry = max(t_min,
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

#include "accel/accel_packet_rays_load.h"

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
 * down.
 * Long: a walk's loop over the stack, the lanes' box tests and the leaves,
 * whose state the loop shares. */
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
 * rays, loaded.
 * Long: a walk's loop, as intersect_rays'. */
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
