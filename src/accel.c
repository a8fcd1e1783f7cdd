/* Queries on the bounding volume hierarchy (built by accel_build.c) and
 * the list of unbounded shapes that every ray tests.  Closest-hit
 * traversal enters the nearer child first, in the same order as a tree
 * with one box per node would, so equal-distance hits resolve alike;
 * shadow rays stop at the first blocker.  Nothing here allocates or locks
 * per ray. */
#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "accel.h"
#include "accel_tree.h"

/* What the box tests need of a ray, computed once per ray: the reciprocal
 * direction, and for each axis which side of a box the ray meets first, so
 * that the test needs no swap and no branch per axis. */
struct ray_slab {
	double o[3], inv[3];
	int near[3];		/* 0: the minimum is the near plane; 1: the maximum */
};

static inline void ray_slab_init(struct ray_slab *rs, const struct ray *r)
{
	int k;

	rs->o[0] = r->origin.x;
	rs->o[1] = r->origin.y;
	rs->o[2] = r->origin.z;
	/* Adding 0.0 turns -0 into +0, so that a zero component always
	 * takes the minimum as its near plane.  (For a ray running along a
	 * face of a box, one slab value is then NaN, which constrains
	 * nothing, and the other +-inf on the side that keeps the ray.) */
	rs->inv[0] = 1.0 / (r->dir.x + 0.0);
	rs->inv[1] = 1.0 / (r->dir.y + 0.0);
	rs->inv[2] = 1.0 / (r->dir.z + 0.0);
	for (k = 0; k < 3; k++)
		rs->near[k] = rs->inv[k] < 0.0;
}

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

/* Tests the shapes of a leaf slot for the nearest hit. */
static inline const struct shape *leaf_intersect(const struct accel *a, uintptr_t slot,
						 const struct ray *r, double t_min, double *t_max,
						 const struct shape *hit)
{
	unsigned count = (unsigned)(slot & 7), k;

	if (count == 0) {
		const struct shape *sh = (const struct shape *)slot;
		return sh && shape_intersect(sh, r, t_min, t_max) ? sh : hit;
	}
	for (k = 0; k < count; k++) {
		const struct shape *sh = a->bounded[(slot >> 3) + k];
		if (shape_intersect(sh, r, t_min, t_max))
			hit = sh;
	}
	return hit;
}

/* Whether any shape of a leaf slot is hit within (t_min, t_max). */
static inline bool leaf_occluded(const struct accel *a, uintptr_t slot, const struct ray *r,
				 double t_min, double t_max)
{
	unsigned count = (unsigned)(slot & 7), k;
	double t = t_max;

	if (count == 0) {
		const struct shape *sh = (const struct shape *)slot;
		return sh && shape_intersect(sh, r, t_min, &t);
	}
	for (k = 0; k < count; k++) {
		t = t_max;
		if (shape_intersect(a->bounded[(slot >> 3) + k], r, t_min, &t))
			return true;
	}
	return false;
}

const struct shape *accel_intersect(const struct accel *a, const struct ray *r,
				    double t_min, double *t_max)
{
	const struct shape *hit = NULL;
	struct { uintptr_t slot; double entry; } stack[ACCEL_STACK];
	struct ray_slab rs;
	struct ray_slab_sse v;
	uintptr_t node = 0;
	size_t i;
	int top = 0;

	for (i = 0; i < a->n_unbounded; i++)
		if (shape_intersect(a->unbounded[i], r, t_min, t_max))
			hit = a->unbounded[i];
	if (a->n_nodes == 0)
		return hit;
	ray_slab_init(&rs, r);
	ray_slab_sse_init(&v, &rs);
	for (;;) {
		const struct bvh_node *n = &a->nodes[node];
		double e[2];
		int near = 0, far = 1;

		node_entries(n, &v, t_min, *t_max, e);
		if (e[1] < e[0]) {
			near = 1;
			far = 0;
		}
		if (e[near] != INFINITY) {
			/* The farther child waits on the stack; the nearer one is
			 * entered now, a leaf's shapes tested at once. */
			if (e[far] != INFINITY) {
				stack[top].slot = n->slot[far];
				stack[top++].entry = e[far];
			}
			if ((n->slot[near] & 7) == ACCEL_SLOT_NODE) {
				node = n->slot[near] >> 3;
				continue;
			}
			hit = leaf_intersect(a, n->slot[near], r, t_min, t_max, hit);
		}
		/* Back up to the nearest waiting child that a hit found since has
		 * not ruled out. */
		for (;;) {
			if (top == 0)
				return hit;
			top--;
			if (stack[top].entry > *t_max)
				continue;
			if ((stack[top].slot & 7) == ACCEL_SLOT_NODE)
				break;
			hit = leaf_intersect(a, stack[top].slot, r, t_min, t_max, hit);
		}
		node = stack[top].slot >> 3;
	}
}

bool accel_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max)
{
	uintptr_t stack[ACCEL_STACK];
	struct ray_slab rs;
	struct ray_slab_sse v;
	size_t i;
	int top = 0;

	for (i = 0; i < a->n_unbounded; i++) {
		double t = t_max;
		if (shape_intersect(a->unbounded[i], r, t_min, &t))
			return true;
	}
	if (a->n_nodes == 0)
		return false;
	ray_slab_init(&rs, r);
	ray_slab_sse_init(&v, &rs);
	stack[top++] = 0;
	while (top > 0) {
		const struct bvh_node *n = &a->nodes[stack[--top]];
		int hits = node_hits(n, &v, t_min, t_max), c;

		/* Any blocker will do, so leaves are tested as they are met and
		 * only nodes wait on the stack. */
		for (c = 0; c < 2; c++) {
			if (!(hits & (1 << c)))
				continue;
			if ((n->slot[c] & 7) == ACCEL_SLOT_NODE)
				stack[top++] = n->slot[c] >> 3;
			else if (leaf_occluded(a, n->slot[c], r, t_min, t_max))
				return true;
		}
	}
	return false;
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
