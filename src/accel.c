/* A bounding volume hierarchy over the scene's bounded shapes, built top
 * down with a 16-bin surface area heuristic, plus a list of the unbounded
 * shapes that every ray tests.  Nodes are 32 bytes: float bounds rounded
 * outwards, so the boxes never cut off a hit, and either a leaf's range of
 * shapes or an interior node's second child (the first follows it). */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "accel.h"
#include "alloc.h"
#include "scene.h"

#define ACCEL_BINS 16
#define ACCEL_LEAF_MAX 4
#define ACCEL_STACK 128
/* Past this depth the build splits at the median, so the depth (and the
 * traversal stack) stays bounded whatever the input. */
#define ACCEL_SAH_DEPTH 40

struct bvh_node {
	float lo[3], hi[3];
	uint32_t index;		/* leaf: first shape; interior: second child */
	uint32_t count;		/* leaf: number of shapes; interior: 0 */
};

struct accel {
	struct bvh_node *nodes;
	size_t n_nodes;
	const struct shape **bounded;	/* in leaf order */
	size_t n_bounded;
	const struct shape **unbounded;
	size_t n_unbounded;
};

struct build_ref {
	struct aabb box;
	struct vec3 centre;
	const struct shape *shape;
};

struct build {
	struct build_ref *refs;
	struct bvh_node *nodes;
	size_t n_nodes, cap_nodes;
};

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

static struct aabb refs_bounds(const struct build_ref *refs, size_t n, struct aabb *centres)
{
	struct aabb box = refs[0].box;
	size_t i;

	centres->min = centres->max = refs[0].centre;
	for (i = 1; i < n; i++) {
		box = aabb_union(box, refs[i].box);
		centres->min = vec3_min(centres->min, refs[i].centre);
		centres->max = vec3_max(centres->max, refs[i].centre);
	}
	return box;
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

/* Chooses an axis and a bin boundary by the surface area heuristic.
 * Returns false when no split beats a leaf (or none is possible). */
static bool sah_split(const struct build_ref *refs, size_t n, struct aabb box,
		      struct aabb centres, int *out_axis, double *out_pos)
{
	double best = (double)n * aabb_area(box);
	bool found = false;
	int axis;

	for (axis = 0; axis < 3; axis++) {
		double lo = vec3_component(centres.min, axis);
		double extent = vec3_component(centres.max, axis) - lo;
		struct aabb bin_box[ACCEL_BINS], right_box[ACCEL_BINS];
		size_t bin_count[ACCEL_BINS] = { 0 }, left_n = 0, right_n[ACCEL_BINS];
		bool bin_used[ACCEL_BINS] = { false };
		struct aabb left = { { 0, 0, 0 }, { 0, 0, 0 } };
		double scale;
		size_t i;
		int b;

		if (!(extent > 0.0))
			continue;
		scale = ACCEL_BINS / extent;
		for (i = 0; i < n; i++) {
			b = bin_of(vec3_component(refs[i].centre, axis), lo, scale);
			bin_box[b] = bin_used[b] ? aabb_union(bin_box[b], refs[i].box) : refs[i].box;
			bin_used[b] = true;
			bin_count[b]++;
		}
		/* Sweep from the right for the right-hand boxes, then from the left. */
		right_n[ACCEL_BINS - 1] = 0;
		for (b = ACCEL_BINS - 1; b > 0; b--) {
			bool have = b < ACCEL_BINS - 1 && right_n[b] > 0;
			right_n[b - 1] = right_n[b] + bin_count[b];
			if (bin_used[b])
				right_box[b - 1] = have ? aabb_union(right_box[b], bin_box[b]) : bin_box[b];
			else if (have)
				right_box[b - 1] = right_box[b];
		}
		for (b = 0; b < ACCEL_BINS - 1; b++) {
			double cost;
			if (bin_used[b])
				left = left_n > 0 ? aabb_union(left, bin_box[b]) : bin_box[b];
			left_n += bin_count[b];
			if (left_n == 0 || right_n[b] == 0)
				continue;
			/* Cost relative to the parent's: one traversal step is cheap
			 * next to a shape test, so it is left out. */
			cost = (double)left_n * aabb_area(left) + (double)right_n[b] * aabb_area(right_box[b]);
			if (cost < best) {
				best = cost;
				found = true;
				*out_axis = axis;
				*out_pos = lo + (b + 1) / scale;
			}
		}
	}
	return found;
}

static size_t partition(struct build_ref *refs, size_t n, int axis, double pos)
{
	size_t i = 0, j = n;

	while (i < j) {
		if (vec3_component(refs[i].centre, axis) < pos) {
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
	double ca = ((const struct build_ref *)a)->centre.x, cb = ((const struct build_ref *)b)->centre.x;
	return (ca > cb) - (ca < cb);
}

static int compare_centre_y(const void *a, const void *b)
{
	double ca = ((const struct build_ref *)a)->centre.y, cb = ((const struct build_ref *)b)->centre.y;
	return (ca > cb) - (ca < cb);
}

static int compare_centre_z(const void *a, const void *b)
{
	double ca = ((const struct build_ref *)a)->centre.z, cb = ((const struct build_ref *)b)->centre.z;
	return (ca > cb) - (ca < cb);
}

/* Splits at the median along the widest centre axis, for when the
 * heuristic gives up on a node that is still too big or the tree is
 * already deep (rare, so a sort is cheap enough). */
static size_t median_split(struct build_ref *refs, size_t n, struct aabb centres)
{
	static int (*const compare[3])(const void *, const void *) = {
		compare_centre_x, compare_centre_y, compare_centre_z
	};
	struct vec3 e = vec3_sub(centres.max, centres.min);
	int axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;

	qsort(refs, n, sizeof(*refs), compare[axis]);
	return n / 2;
}

static int push_node(struct build *b, size_t *index)
{
	if (b->n_nodes == b->cap_nodes) {
		size_t cap = b->cap_nodes ? b->cap_nodes * 2 : 64;
		struct bvh_node *p = rt_reallocarray(b->nodes, cap, sizeof(*p));
		if (!p)
			return -RT_E_NOMEM;
		b->nodes = p;
		b->cap_nodes = cap;
	}
	*index = b->n_nodes++;
	return 0;
}

static void set_node_box(struct bvh_node *node, struct aabb box)
{
	int k;

	for (k = 0; k < 3; k++) {
		node->lo[k] = float_down(vec3_component(box.min, k));
		node->hi[k] = float_up(vec3_component(box.max, k));
	}
}

static int build_node(struct build *b, size_t first, size_t n, int depth)
{
	struct build_ref *refs = b->refs + first;
	struct aabb centres, box = refs_bounds(refs, n, &centres);
	size_t index, split = 0;
	double pos = 0.0;
	int axis = 0, rc;

	if ((rc = push_node(b, &index)) < 0)
		return rc;
	set_node_box(&b->nodes[index], box);
	if (n > 1 && depth < ACCEL_SAH_DEPTH && sah_split(refs, n, box, centres, &axis, &pos))
		split = partition(refs, n, axis, pos);
	if ((split == 0 || split == n) && n > ACCEL_LEAF_MAX)
		split = median_split(refs, n, centres);
	if (split == 0 || split == n) {
		b->nodes[index].index = (uint32_t)first;
		b->nodes[index].count = (uint32_t)n;
		return 0;
	}
	b->nodes[index].count = 0;
	if ((rc = build_node(b, first, split, depth + 1)) < 0)
		return rc;
	b->nodes[index].index = (uint32_t)b->n_nodes;
	return build_node(b, first + split, n - split, depth + 1);
}

int accel_build(const struct scene *s, struct accel **out, struct diag *d)
{
	struct build b = { NULL, NULL, 0, 0 };
	struct accel *a;
	size_t i;
	int rc = -RT_E_NOMEM;

	*out = NULL;
	a = rt_calloc(1, sizeof(*a));
	if (!a)
		goto out_nomem;
	a->bounded = rt_reallocarray(NULL, s->n_shapes, sizeof(*a->bounded));
	a->unbounded = rt_reallocarray(NULL, s->n_shapes, sizeof(*a->unbounded));
	b.refs = rt_reallocarray(NULL, s->n_shapes, sizeof(*b.refs));
	if (!a->bounded || !a->unbounded || !b.refs)
		goto out_free;
	for (i = 0; i < s->n_shapes; i++) {
		struct build_ref *ref = &b.refs[a->n_bounded];
		if (shape_bounds(s->shapes[i], &ref->box)) {
			ref->centre = aabb_centre(ref->box);
			ref->shape = s->shapes[i];
			a->n_bounded++;
		} else {
			a->unbounded[a->n_unbounded++] = s->shapes[i];
		}
	}
	if (a->n_bounded > 0) {
		if ((rc = build_node(&b, 0, a->n_bounded, 0)) < 0)
			goto out_free;
		for (i = 0; i < a->n_bounded; i++)
			a->bounded[i] = b.refs[i].shape;
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

struct ray_slab {
	double o[3], inv[3];
};

static void ray_slab_init(struct ray_slab *rs, const struct ray *r)
{
	rs->o[0] = r->origin.x;
	rs->o[1] = r->origin.y;
	rs->o[2] = r->origin.z;
	/* Adding 0.0 turns -0 into +0.  For a ray running along a face of a
	 * box, 1 / -0 = -inf makes that slab (NaN, -inf) or (+inf, NaN), which
	 * cuts the ray off; 1 / +0 makes it (NaN, +inf) or (-inf, NaN), which
	 * leaves the ray alone, as the inclusive box requires. */
	rs->inv[0] = 1.0 / (r->dir.x + 0.0);
	rs->inv[1] = 1.0 / (r->dir.y + 0.0);
	rs->inv[2] = 1.0 / (r->dir.z + 0.0);
}

/* The entry distance of the ray into the node's box within (t_min, t_max),
 * or INFINITY when it misses.  A NaN from 0 * inf (the origin on a slab
 * plane of a parallel ray) fails neither comparison and so constrains
 * nothing. */
static double node_entry(const struct bvh_node *node, const struct ray_slab *rs,
			 double t_min, double t_max)
{
	int k;

	for (k = 0; k < 3; k++) {
		double t0 = (node->lo[k] - rs->o[k]) * rs->inv[k];
		double t1 = (node->hi[k] - rs->o[k]) * rs->inv[k];
		if (t0 > t1) {
			double tmp = t0;
			t0 = t1;
			t1 = tmp;
		}
		if (t0 > t_min)
			t_min = t0;
		if (t1 < t_max)
			t_max = t1;
		if (t_min > t_max)
			return INFINITY;
	}
	return t_min;
}

const struct shape *accel_intersect(const struct accel *a, const struct ray *r,
				    double t_min, double *t_max)
{
	const struct shape *hit = NULL;
	struct { uint32_t node; double entry; } stack[ACCEL_STACK];
	struct ray_slab rs;
	size_t i;
	int top = 0;

	for (i = 0; i < a->n_unbounded; i++)
		if (shape_intersect(a->unbounded[i], r, t_min, t_max))
			hit = a->unbounded[i];
	if (a->n_nodes == 0)
		return hit;
	ray_slab_init(&rs, r);
	stack[0].node = 0;
	stack[0].entry = node_entry(&a->nodes[0], &rs, t_min, *t_max);
	top = stack[0].entry == INFINITY ? 0 : 1;
	while (top > 0) {
		const struct bvh_node *node;
		top--;
		/* A nearer hit found since the push may have passed this node. */
		if (stack[top].entry > *t_max)
			continue;
		node = &a->nodes[stack[top].node];
		if (node->count > 0) {
			uint32_t k;
			for (k = 0; k < node->count; k++) {
				const struct shape *sh = a->bounded[node->index + k];
				if (shape_intersect(sh, r, t_min, t_max))
					hit = sh;
			}
		} else {
			uint32_t near = (uint32_t)(node - a->nodes) + 1, far = node->index;
			double t_near = node_entry(&a->nodes[near], &rs, t_min, *t_max);
			double t_far = node_entry(&a->nodes[far], &rs, t_min, *t_max);
			if (t_far < t_near) {
				double tt = t_near;
				uint32_t tmp = near;
				near = far;
				far = tmp;
				t_near = t_far;
				t_far = tt;
			}
			if (t_far != INFINITY) {
				stack[top].node = far;
				stack[top++].entry = t_far;
			}
			if (t_near != INFINITY) {
				stack[top].node = near;
				stack[top++].entry = t_near;
			}
		}
	}
	return hit;
}

bool accel_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max)
{
	uint32_t stack[ACCEL_STACK];
	struct ray_slab rs;
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
	stack[top++] = 0;
	while (top > 0) {
		const struct bvh_node *node = &a->nodes[stack[--top]];
		if (node_entry(node, &rs, t_min, t_max) == INFINITY)
			continue;
		if (node->count > 0) {
			uint32_t k;
			for (k = 0; k < node->count; k++) {
				double t = t_max;
				if (shape_intersect(a->bounded[node->index + k], r, t_min, &t))
					return true;
			}
		} else {
			stack[top++] = node->index;
			stack[top++] = (uint32_t)(node - a->nodes) + 1;
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
