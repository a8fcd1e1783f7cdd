/* A bounding volume hierarchy over the scene's bounded shapes, built top
 * down with a 16-bin surface area heuristic, plus a list of the unbounded
 * shapes that every ray tests.  A node is 64 bytes: the boxes of both its
 * children (float bounds rounded outwards, so they never cut off a hit,
 * stored child-interleaved so that one SSE2 operation tests both; plain C
 * elsewhere) and what each child is: another node, a leaf's one shape or a
 * leaf's range of shapes.  Closest-hit traversal enters the nearer child
 * first, in the same order as a tree with one box per node would, so
 * equal-distance hits resolve alike; shadow rays stop at the first
 * blocker.  Nothing here allocates or locks per ray. */
#include <assert.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "accel.h"
#include "alloc.h"
#include "scene.h"

#define ACCEL_BINS 16
#define ACCEL_LEAF_MAX 4	/* at most 7: a leaf's size is its slot's tag */
#define ACCEL_STACK 128
/* Past this depth the build splits at the median, so the depth (and the
 * traversal stack) stays bounded whatever the input. */
#define ACCEL_SAH_DEPTH 40

/* What a child slot holds, by its low three bits: 0, the one shape of a
 * leaf (a pointer: shapes are at least 8-byte aligned), so that the most
 * common leaf costs no look-up in accel.bounded; 1, a node (index << 3);
 * 2 to ACCEL_LEAF_MAX, a leaf of that many shapes from accel.bounded[slot
 * >> 3].  A null pointer is an empty slot. */
#define ACCEL_SLOT_NODE 1u

struct bvh_node {
	/* bounds[side][axis][child]: side 0 the minimum, 1 the maximum. */
	float bounds[2][3][2];
	uintptr_t slot[2];
};

struct accel {
	struct bvh_node *nodes;
	size_t n_nodes;
	const struct shape **bounded;	/* in leaf order */
	size_t n_bounded;
	const struct shape **unbounded;
	size_t n_unbounded;
};

/* A shape being sorted into the tree: its box and the shape.  The centre
 * that the heuristic sorts by is computed from the box when needed rather
 * than stored, which keeps a reference at 56 bytes (the build's memory
 * peak is the references and the nodes together). */
struct build_ref {
	double lo[3], hi[3];
	const struct shape *shape;
};

struct build {
	struct build_ref *refs;
	struct bvh_node *nodes;
	size_t n_nodes, cap_nodes;
};

/* The bounds of a set of refs and of their centres.  Comparisons rather
 * than fmin and fmax, which are library calls here: the boxes are finite,
 * so the values are the same. */
struct build_box {
	double lo[3], hi[3];
};

static inline double ref_centre(const struct build_ref *r, int axis)
{
	return (r->lo[axis] + r->hi[axis]) * 0.5;
}

static double box_area(const struct build_box *b)
{
	double ex = b->hi[0] - b->lo[0], ey = b->hi[1] - b->lo[1], ez = b->hi[2] - b->lo[2];

	return 2.0 * (ex * ey + ey * ez + ez * ex);
}

static void box_empty(struct build_box *b)
{
	int k;

	for (k = 0; k < 3; k++) {
		b->lo[k] = INFINITY;
		b->hi[k] = -INFINITY;
	}
}

/* b grows to take in the box lo..hi; written out per axis, as -O2 does not
 * unroll it and the loop control was a third of the binning's work. */
static inline void box_grow_by(struct build_box *b, const double lo[3], const double hi[3])
{
	b->lo[0] = lo[0] < b->lo[0] ? lo[0] : b->lo[0];
	b->lo[1] = lo[1] < b->lo[1] ? lo[1] : b->lo[1];
	b->lo[2] = lo[2] < b->lo[2] ? lo[2] : b->lo[2];
	b->hi[0] = hi[0] > b->hi[0] ? hi[0] : b->hi[0];
	b->hi[1] = hi[1] > b->hi[1] ? hi[1] : b->hi[1];
	b->hi[2] = hi[2] > b->hi[2] ? hi[2] : b->hi[2];
}

static inline void box_grow_ref(struct build_box *b, const struct build_ref *r)
{
	box_grow_by(b, r->lo, r->hi);
}

static inline void box_grow(struct build_box *b, const struct build_box *o)
{
	box_grow_by(b, o->lo, o->hi);
}

static float float_down(double v)
{
	float f = (float)v;
	return (double)f > v ? nextafterf(f, -INFINITY) : f;
}

static float float_up(double v)
{
	float f = (float)v;
	return (double)f < v ? nextafterf(f, INFINITY) : f;
}

static void refs_bounds(const struct build_ref *refs, size_t n, struct build_box *box,
			struct build_box *centres)
{
	size_t i;
	int k;

	box_empty(box);
	box_empty(centres);
	for (i = 0; i < n; i++) {
		box_grow_ref(box, &refs[i]);
		for (k = 0; k < 3; k++) {
			double c = ref_centre(&refs[i], k);
			centres->lo[k] = c < centres->lo[k] ? c : centres->lo[k];
			centres->hi[k] = c > centres->hi[k] ? c : centres->hi[k];
		}
	}
}

/* Clamps before converting: with coordinates near DBL_MAX a centre or the
 * extent can overflow to inf and the product be NaN, and converting that
 * (or anything outside int) is undefined. */
static int bin_of(double c, double lo, double scale)
{
	double f = (c - lo) * scale;

	if (!(f >= 0.0))
		return 0;
	return f >= ACCEL_BINS ? ACCEL_BINS - 1 : (int)f;
}

struct sah_bin {
	struct build_box box;	/* empty while no ref falls in the bin */
	size_t n;
};

/* Chooses an axis and a bin boundary by the surface area heuristic: the
 * cost of a split, relative to its parent's, is n_left area_left +
 * n_right area_right (a traversal step is cheap next to a shape test, so
 * it is left out), against n area for a leaf.  All three axes are binned
 * in one pass over the refs.  Returns false when no split beats a leaf
 * (or none is possible). */
static bool sah_split(const struct build_ref *refs, size_t n, const struct build_box *box,
		      const struct build_box *centres, int *out_axis, double *out_pos)
{
	struct sah_bin bins[3][ACCEL_BINS];
	double best = (double)n * box_area(box), scale[3];
	bool found = false, usable[3];
	size_t i;
	int axis, b;

	for (axis = 0; axis < 3; axis++) {
		double extent = centres->hi[axis] - centres->lo[axis];
		usable[axis] = extent > 0.0;
		scale[axis] = usable[axis] ? ACCEL_BINS / extent : 0.0;
		for (b = 0; b < ACCEL_BINS; b++) {
			box_empty(&bins[axis][b].box);
			bins[axis][b].n = 0;
		}
	}
	for (i = 0; i < n; i++) {
		for (axis = 0; axis < 3; axis++) {
			struct sah_bin *bin;
			if (!usable[axis])
				continue;
			bin = &bins[axis][bin_of(ref_centre(&refs[i], axis), centres->lo[axis], scale[axis])];
			box_grow_ref(&bin->box, &refs[i]);
			bin->n++;
		}
	}
	for (axis = 0; axis < 3; axis++) {
		struct build_box left, acc;
		double right_area[ACCEL_BINS];
		size_t right_n[ACCEL_BINS], left_n = 0;

		if (!usable[axis])
			continue;
		/* Sweep from the right for the right-hand areas, then from the
		 * left.  An empty bin leaves a box as it is, so it is skipped
		 * (most bins of the many small nodes are empty). */
		box_empty(&acc);
		right_n[ACCEL_BINS - 1] = 0;
		right_area[ACCEL_BINS - 1] = 0.0;
		for (b = ACCEL_BINS - 1; b > 0; b--) {
			right_n[b - 1] = right_n[b] + bins[axis][b].n;
			if (bins[axis][b].n == 0) {
				right_area[b - 1] = right_area[b];
				continue;
			}
			box_grow(&acc, &bins[axis][b].box);
			right_area[b - 1] = box_area(&acc);
		}
		box_empty(&left);
		for (b = 0; b < ACCEL_BINS - 1; b++) {
			double cost;
			if (bins[axis][b].n > 0)
				box_grow(&left, &bins[axis][b].box);
			left_n += bins[axis][b].n;
			if (left_n == 0 || right_n[b] == 0)
				continue;
			cost = (double)left_n * box_area(&left) + (double)right_n[b] * right_area[b];
			if (cost < best) {
				best = cost;
				found = true;
				*out_axis = axis;
				*out_pos = centres->lo[axis] + (b + 1) / scale[axis];
			}
		}
	}
	return found;
}

static size_t partition(struct build_ref *refs, size_t n, int axis, double pos)
{
	size_t i = 0, j = n;

	while (i < j) {
		if (ref_centre(&refs[i], axis) < pos) {
			i++;
		} else {
			struct build_ref tmp = refs[i];
			refs[i] = refs[--j];
			refs[j] = tmp;
		}
	}
	return i;
}

/* Orders refs by their centre along one axis, for the median split. */
static int compare_centre_x(const void *a, const void *b)
{
	double ca = ref_centre(a, 0), cb = ref_centre(b, 0);
	return (ca > cb) - (ca < cb);
}

static int compare_centre_y(const void *a, const void *b)
{
	double ca = ref_centre(a, 1), cb = ref_centre(b, 1);
	return (ca > cb) - (ca < cb);
}

static int compare_centre_z(const void *a, const void *b)
{
	double ca = ref_centre(a, 2), cb = ref_centre(b, 2);
	return (ca > cb) - (ca < cb);
}

/* Splits at the median along the widest centre axis, for when the
 * heuristic gives up on a node that is still too big or the tree is
 * already deep (rare, so a sort is cheap enough). */
static size_t median_split(struct build_ref *refs, size_t n, const struct build_box *centres)
{
	static int (*const compare[3])(const void *, const void *) = {
		compare_centre_x, compare_centre_y, compare_centre_z
	};
	double ex = centres->hi[0] - centres->lo[0], ey = centres->hi[1] - centres->lo[1];
	double ez = centres->hi[2] - centres->lo[2];
	int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;

	qsort(refs, n, sizeof(*refs), compare[axis]);
	return n / 2;
}

static int push_node(struct build *b, size_t *index)
{
	if (b->n_nodes == b->cap_nodes) {
		size_t cap = b->cap_nodes ? b->cap_nodes * 2 : 64;
		struct bvh_node *p;
		if (cap > UINTPTR_MAX >> 3)
			return -RT_E_NOMEM;
		p = rt_reallocarray(b->nodes, cap, sizeof(*p));
		if (!p)
			return -RT_E_NOMEM;
		b->nodes = p;
		b->cap_nodes = cap;
	}
	*index = b->n_nodes++;
	return 0;
}

static void set_child_box(struct bvh_node *node, int c, const struct build_box *box)
{
	int k;

	for (k = 0; k < 3; k++) {
		node->bounds[0][k][c] = float_down(box->lo[k]);
		node->bounds[1][k][c] = float_up(box->hi[k]);
	}
}

/* Where to split refs[first, first + n) (sorting them so), or 0 to make
 * them a leaf; *box receives their bounds. */
static size_t choose_split(struct build *b, size_t first, size_t n, int depth,
			   struct build_box *box)
{
	struct build_ref *refs = b->refs + first;
	struct build_box centres;
	size_t split = 0;
	double pos = 0.0;
	int axis = 0;

	refs_bounds(refs, n, box, &centres);
	if (n > 1 && depth < ACCEL_SAH_DEPTH && sah_split(refs, n, box, &centres, &axis, &pos))
		split = partition(refs, n, axis, pos);
	if ((split == 0 || split == n) && n > ACCEL_LEAF_MAX)
		split = median_split(refs, n, &centres);
	return split == n ? 0 : split;
}

/* The slot of a leaf over refs[first, first + n): their place is final
 * once they make a leaf. */
static uintptr_t leaf_slot(const struct build *b, size_t first, size_t n)
{
	uintptr_t one = (uintptr_t)b->refs[first].shape;

	assert(n >= 1 && n <= ACCEL_LEAF_MAX && ACCEL_LEAF_MAX <= 7);
	if (n > 1)
		return (uintptr_t)first << 3 | n;
	assert((one & 7) == 0);
	return one;
}

/* Builds the subtree over refs[first, first + n) and describes it as child
 * c of node `parent`: its box, and a leaf or the node built for it. */
static int build_node(struct build *b, size_t parent, int c, size_t first, size_t n, int depth)
{
	struct build_box box;
	size_t index, split = choose_split(b, first, n, depth, &box);
	int rc;

	set_child_box(&b->nodes[parent], c, &box);
	if (split == 0) {
		b->nodes[parent].slot[c] = leaf_slot(b, first, n);
		return 0;
	}
	if ((rc = push_node(b, &index)) < 0)
		return rc;
	b->nodes[parent].slot[c] = (uintptr_t)index << 3 | ACCEL_SLOT_NODE;
	if ((rc = build_node(b, index, 0, first, split, depth + 1)) < 0)
		return rc;
	return build_node(b, index, 1, first + split, n - split, depth + 1);
}

/* The root node holds the two halves of the whole set; a set that makes
 * one leaf sits beside an empty child whose box no ray can enter (its
 * minimum is +inf and its maximum -inf on every axis). */
static int build_root(struct build *b, size_t n)
{
	struct build_box box;
	size_t root, split;
	int rc, k;

	if ((rc = push_node(b, &root)) < 0)
		return rc;
	split = choose_split(b, 0, n, 0, &box);
	if (split == 0) {
		set_child_box(&b->nodes[root], 0, &box);
		b->nodes[root].slot[0] = leaf_slot(b, 0, n);
		for (k = 0; k < 3; k++) {
			b->nodes[root].bounds[0][k][1] = INFINITY;
			b->nodes[root].bounds[1][k][1] = -INFINITY;
		}
		b->nodes[root].slot[1] = 0;
		return 0;
	}
	if ((rc = build_node(b, root, 0, 0, split, 1)) < 0)
		return rc;
	return build_node(b, root, 1, split, n - split, 1);
}

int accel_build(const struct scene *s, struct accel **out, struct diag *d)
{
	struct build b = { NULL, NULL, 0, 0 };
	struct accel *a;
	size_t i, n_unbounded = 0;
	int rc = -RT_E_NOMEM;

	*out = NULL;
	a = rt_calloc(1, sizeof(*a));
	if (!a)
		goto out_nomem;
	b.refs = rt_reallocarray(NULL, s->n_shapes, sizeof(*b.refs));
	if (!b.refs)
		goto out_free;
	for (i = 0; i < s->n_shapes; i++) {
		struct build_ref *ref = &b.refs[a->n_bounded];
		struct aabb box;
		if (shape_bounds(s->shapes[i], &box)) {
			ref->lo[0] = box.min.x;
			ref->lo[1] = box.min.y;
			ref->lo[2] = box.min.z;
			ref->hi[0] = box.max.x;
			ref->hi[1] = box.max.y;
			ref->hi[2] = box.max.z;
			ref->shape = s->shapes[i];
			a->n_bounded++;
		} else {
			n_unbounded++;
		}
	}
	a->unbounded = rt_reallocarray(NULL, n_unbounded, sizeof(*a->unbounded));
	if (!a->unbounded)
		goto out_free;
	for (i = 0; i < s->n_shapes; i++) {
		struct aabb box;
		if (!shape_bounds(s->shapes[i], &box))
			a->unbounded[a->n_unbounded++] = s->shapes[i];
	}
	if (a->n_bounded > 0) {
		const struct shape **leaf_order = (const struct shape **)(void *)b.refs;
		if ((rc = build_root(&b, a->n_bounded)) < 0)
			goto out_free;
		/* The shapes in leaf order go to the front of the refs' own
		 * memory (pointer i lands before ref i is read, never on a ref
		 * still to be read), which then shrinks: no third array at the
		 * build's memory peak. */
		for (i = 0; i < a->n_bounded; i++)
			leaf_order[i] = b.refs[i].shape;
		a->bounded = rt_reallocarray(leaf_order, a->n_bounded, sizeof(*a->bounded));
		if (!a->bounded)
			a->bounded = leaf_order;
		b.refs = NULL;
		a->nodes = b.nodes;
		a->n_nodes = b.n_nodes;
		b.nodes = NULL;
	}
	rt_free(b.refs);
	*out = a;
	return 0;
out_free:
	rt_free(b.nodes);
	rt_free(b.refs);
	accel_destroy(a);
out_nomem:
	return diag_set(d, RT_E_NOMEM, "", 0, 0, "out of memory building the scene's hierarchy");
}

void accel_destroy(struct accel *a)
{
	if (!a)
		return;
	rt_free(a->nodes);
	rt_free(a->bounded);
	rt_free(a->unbounded);
	rt_free(a);
}

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
