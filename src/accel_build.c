/* Builds the bounding volume hierarchy: top down, each node split where a
 * 16-bin surface area heuristic puts it, the halves of big nodes built by
 * a pool of threads.  The tree is the same whatever the number of
 * threads, bit for bit. */
#include <assert.h>
#include <math.h>
#include <pthread.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "accel.h"
#include "accel_tree.h"
#include "alloc.h"
#include "scene.h"

#define ACCEL_BINS 16
/* A node offers its right half to the other threads only when both halves
 * have this many refs: below that, handing work over costs more than it
 * saves. */
#define ACCEL_PARALLEL_MIN 4096

/* A shape being sorted into the tree: its box and the shape.  The centre
 * that the heuristic sorts by is computed from the box when needed rather
 * than stored, which keeps a reference at 56 bytes (the build's memory
 * peak is the references and the nodes together). */
struct build_ref {
	double lo[3], hi[3];
	const struct shape *shape;
};

/* The build writes every node in place, into an array allocated once: the
 * subtree over refs [first, first + n) owns node indices [base, base + n -
 * 1) (a tree of n leaves has n - 1 nodes, and fewer with bigger leaves):
 * its own node at base, its left child's subtree from base + 1 and its
 * right child's from base + the left's refs.  So the halves of a node can
 * be built by different threads with no lock, no copy and no allocation,
 * and the nodes lie in depth-first order; the indices that bigger leaves
 * leave unused are squeezed out afterwards. */
struct build {
	struct build_ref *refs;
	struct bvh_node *nodes;
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

/* The box code copies a ref's or a box's bounds as six doubles in a row. */
typedef char build_ref_bounds_in_a_row[offsetof(struct build_ref, hi) == 3 * sizeof(double) ? 1 : -1];
typedef char build_box_bounds_in_a_row[offsetof(struct build_box, hi) == 3 * sizeof(double) ? 1 : -1];

/* b grows to take in the box that src begins with (a ref or a build_box:
 * its minima then its maxima, six doubles in a row, copied out).  With SSE2 that is three
 * two-lane operations; MINPD and MAXPD give their first operand where the
 * comparison holds and the second otherwise, as the plain C does, so the
 * tree is the same either way. */
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
#include <emmintrin.h>

static inline void box_grow_by(struct build_box *b, const void *src)
{
	double v[6], d[6];
	__m128d lo01, lo2hi0, hi12, b2;

	memcpy(v, src, sizeof(v));
	memcpy(d, b, sizeof(d));
	lo01 = _mm_loadu_pd(v);
	lo2hi0 = _mm_loadu_pd(v + 2);
	hi12 = _mm_loadu_pd(v + 4);
	b2 = _mm_loadu_pd(d + 2);
	_mm_storeu_pd(d, _mm_min_pd(lo01, _mm_loadu_pd(d)));
	_mm_storeu_pd(d + 2, _mm_move_sd(_mm_max_pd(lo2hi0, b2), _mm_min_pd(lo2hi0, b2)));
	_mm_storeu_pd(d + 4, _mm_max_pd(hi12, _mm_loadu_pd(d + 4)));
	memcpy(b, d, sizeof(d));
}
#else
static inline void box_grow_by(struct build_box *b, const void *src)
{
	double v[6];
	const double *lo = v, *hi = v + 3;

	memcpy(v, src, sizeof(v));

	/* Written out per axis: -O2 does not unroll the loop, and its
	 * control was a third of the binning's work. */
	b->lo[0] = lo[0] < b->lo[0] ? lo[0] : b->lo[0];
	b->lo[1] = lo[1] < b->lo[1] ? lo[1] : b->lo[1];
	b->lo[2] = lo[2] < b->lo[2] ? lo[2] : b->lo[2];
	b->hi[0] = hi[0] > b->hi[0] ? hi[0] : b->hi[0];
	b->hi[1] = hi[1] > b->hi[1] ? hi[1] : b->hi[1];
	b->hi[2] = hi[2] > b->hi[2] ? hi[2] : b->hi[2];
}
#endif

static inline void box_grow_ref(struct build_box *b, const struct build_ref *r)
{
	box_grow_by(b, r);
}

static inline void box_grow(struct build_box *b, const struct build_box *o)
{
	box_grow_by(b, o);
}

/* The float next to f towards +inf (up) or -inf, as nextafterf gives it
 * (a library call, and these run twelve times a node): one step of the
 * bit pattern, which orders floats of one sign by magnitude.  An
 * infinity steps to the largest finite float. */
static inline float float_step(float f, bool up)
{
	uint32_t u;

	if (f == 0.0f)
		u = up ? 0x00000001u : 0x80000001u;
	else {
		memcpy(&u, &f, sizeof(u));
		u = (f > 0.0f) == up ? u + 1 : u - 1;
	}
	memcpy(&f, &u, sizeof(f));
	return f;
}

static inline float float_down(double v)
{
	float f = (float)v;
	return (double)f > v ? float_step(f, false) : f;
}

static inline float float_up(double v)
{
	float f = (float)v;
	return (double)f < v ? float_step(f, true) : f;
}

/* box and centres grow to take in ref r and its centre. */
static inline void bounds_add_ref(struct build_box *box, struct build_box *centres,
				  const struct build_ref *r)
{
	int k;

	box_grow_ref(box, r);
	for (k = 0; k < 3; k++) {
		double c = ref_centre(r, k);
		centres->lo[k] = c < centres->lo[k] ? c : centres->lo[k];
		centres->hi[k] = c > centres->hi[k] ? c : centres->hi[k];
	}
}

static void refs_bounds(const struct build_ref *refs, size_t n, struct build_box *box,
			struct build_box *centres)
{
	size_t i;

	box_empty(box);
	box_empty(centres);
	for (i = 0; i < n; i++)
		bounds_add_ref(box, centres, &refs[i]);
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
		/* A bin's box is set by its first ref (the same as growing an
		 * empty box by it), so only the counts need clearing. */
		for (b = 0; b < ACCEL_BINS; b++)
			bins[axis][b].n = 0;
	}
	for (i = 0; i < n; i++) {
		for (axis = 0; axis < 3; axis++) {
			struct sah_bin *bin;
			if (!usable[axis])
				continue;
			bin = &bins[axis][bin_of(ref_centre(&refs[i], axis), centres->lo[axis], scale[axis])];
			if (bin->n++ == 0)
				memcpy(&bin->box, &refs[i], sizeof(bin->box));
			else
				box_grow_ref(&bin->box, &refs[i]);
		}
	}
	for (axis = 0; axis < 3; axis++) {
		struct build_box left, acc;
		double right_area[ACCEL_BINS];
		size_t right_n[ACCEL_BINS], left_n = 0;
		int used[ACCEL_BINS], n_used = 0, j;

		if (!usable[axis])
			continue;
		/* Only the bins that hold refs matter (most bins of the many
		 * small nodes are empty): a cut after an empty bin makes the
		 * same halves at the same cost as the cut after the last bin
		 * before it that holds refs, which comes first and wins. */
		for (b = 0; b < ACCEL_BINS; b++)
			if (bins[axis][b].n > 0)
				used[n_used++] = b;
		if (n_used < 2)
			continue;
		/* Sweep from the right for the right-hand areas and counts of
		 * the cuts after used[0 .. n_used - 2], then from the left. */
		acc = bins[axis][used[n_used - 1]].box;
		right_n[n_used - 2] = bins[axis][used[n_used - 1]].n;
		right_area[n_used - 2] = box_area(&acc);
		for (j = n_used - 2; j > 0; j--) {
			box_grow(&acc, &bins[axis][used[j]].box);
			right_n[j - 1] = right_n[j] + bins[axis][used[j]].n;
			right_area[j - 1] = box_area(&acc);
		}
		left = bins[axis][used[0]].box;
		for (j = 0; j < n_used - 1; j++) {
			double cost;
			if (j > 0)
				box_grow(&left, &bins[axis][used[j]].box);
			left_n += bins[axis][used[j]].n;
			cost = (double)left_n * box_area(&left) + (double)right_n[j] * right_area[j];
			if (cost < best) {
				best = cost;
				found = true;
				*out_axis = axis;
				*out_pos = centres->lo[axis] + (used[j] + 1) / scale[axis];
			}
		}
	}
	return found;
}

/* Moves the refs whose centre lies below pos along axis to the front and
 * returns how many there are; bounds receives the box and the centre
 * bounds of the front part, then of the back part. */
static size_t partition(struct build_ref *refs, size_t n, int axis, double pos,
			struct build_box bounds[4])
{
	size_t i = 0, j = n;

	box_empty(&bounds[0]);
	box_empty(&bounds[1]);
	box_empty(&bounds[2]);
	box_empty(&bounds[3]);
	while (i < j) {
		if (ref_centre(&refs[i], axis) < pos) {
			bounds_add_ref(&bounds[0], &bounds[1], &refs[i]);
			i++;
		} else {
			struct build_ref tmp = refs[i];
			bounds_add_ref(&bounds[2], &bounds[3], &tmp);
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
static void set_child_box(struct bvh_node *node, int c, const struct build_box *box)
{
	int k;

	for (k = 0; k < 3; k++) {
		node->bounds[0][k][c] = float_down(box->lo[k]);
		node->bounds[1][k][c] = float_up(box->hi[k]);
	}
}
/* Where to split refs[first, first + n), whose box and centre bounds are
 * given (sorting them so), or 0 to make them a leaf; bounds receives the
 * box and centre bounds of both parts. */
static size_t choose_split(struct build *b, size_t first, size_t n, int depth,
			   const struct build_box *box, const struct build_box *centres,
			   struct build_box bounds[4])
{
	struct build_ref *refs = b->refs + first;
	size_t split = 0;
	double pos = 0.0;
	int axis = 0;

	if (n > 1 && depth < ACCEL_SAH_DEPTH && sah_split(refs, n, box, centres, &axis, &pos))
		split = partition(refs, n, axis, pos, bounds);
	if ((split == 0 || split == n) && n > ACCEL_LEAF_MAX) {
		split = median_split(refs, n, centres);
		refs_bounds(refs, split, &bounds[0], &bounds[1]);
		refs_bounds(refs + split, n - split, &bounds[2], &bounds[3]);
	}
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
/* Subtrees waiting for a thread.  Whoever splits a big node puts its
 * right-hand child here and goes on with the left; idle threads take the
 * most recent.  So the threads stay busy however unevenly the tree
 * splits, and as every subtree writes only its own nodes, which thread
 * builds it changes nothing. */
#define BUILD_TASKS_MAX 256

struct build_task {
	size_t parent, first, n, base;
	int depth;
	struct build_box box, centres;
};

struct build_pool {
	struct build *b;
	pthread_mutex_t lock;
	pthread_cond_t cond;
	struct build_task task[BUILD_TASKS_MAX];
	int n_tasks;
	int busy;		/* threads building a task */
};

static void build_children(struct build *b, struct build_pool *pool, size_t index, size_t first,
			   size_t n, size_t split, int depth, const struct build_box bounds[4]);

/* Builds the subtree over refs[first, first + n), with the given box and
 * centre bounds, as child c of node `parent`: a leaf, or the node at index
 * base and what lies below it. */
static void build_child(struct build *b, struct build_pool *pool, size_t parent, int c,
			size_t first, size_t n, size_t base, int depth,
			const struct build_box *box, const struct build_box *centres)
{
	struct build_box bounds[4];
	size_t split = choose_split(b, first, n, depth, box, centres, bounds);

	if (split == 0) {
		b->nodes[parent].slot[c] = leaf_slot(b, first, n);
		return;
	}
	b->nodes[parent].slot[c] = (uintptr_t)base << 3 | ACCEL_SLOT_NODE;
	build_children(b, pool, base, first, n, split, depth + 1, bounds);
}

/* Offers the right-hand child of a big node to the other threads; false
 * when the caller is to build it. */
static bool pool_offer(struct build_pool *pool, size_t parent, size_t first, size_t n,
		       size_t base, int depth, const struct build_box *box,
		       const struct build_box *centres)
{
	bool taken = false;

	pthread_mutex_lock(&pool->lock);
	if (pool->n_tasks < BUILD_TASKS_MAX) {
		struct build_task *t = &pool->task[pool->n_tasks++];
		t->parent = parent;
		t->first = first;
		t->n = n;
		t->base = base;
		t->depth = depth;
		t->box = *box;
		t->centres = *centres;
		taken = true;
		pthread_cond_signal(&pool->cond);
	}
	pthread_mutex_unlock(&pool->lock);
	return taken;
}

/* Builds both children of node `index`, which stands for refs[first,
 * first + n) split after `split` of them.  Each child writes only its own
 * slot of the node. */
static void build_children(struct build *b, struct build_pool *pool, size_t index, size_t first,
			   size_t n, size_t split, int depth, const struct build_box bounds[4])
{
	bool offered;

	set_child_box(&b->nodes[index], 0, &bounds[0]);
	set_child_box(&b->nodes[index], 1, &bounds[2]);
	offered = pool && split >= ACCEL_PARALLEL_MIN && n - split >= ACCEL_PARALLEL_MIN &&
		  pool_offer(pool, index, first + split, n - split, index + split, depth,
			     &bounds[2], &bounds[3]);
	build_child(b, pool, index, 0, first, split, index + 1, depth, &bounds[0], &bounds[1]);
	if (!offered)
		build_child(b, pool, index, 1, first + split, n - split, index + split, depth,
			    &bounds[2], &bounds[3]);
}

/* A thread of the pool: takes tasks until there are none and no thread
 * is building one (which could offer more). */
static void *pool_work(void *arg)
{
	struct build_pool *pool = arg;

	pthread_mutex_lock(&pool->lock);
	for (;;) {
		struct build_task t;
		while (pool->n_tasks == 0 && pool->busy > 0)
			pthread_cond_wait(&pool->cond, &pool->lock);
		if (pool->n_tasks == 0)
			break;
		t = pool->task[--pool->n_tasks];
		pool->busy++;
		pthread_mutex_unlock(&pool->lock);
		build_child(pool->b, pool, t.parent, 1, t.first, t.n, t.base, t.depth, &t.box,
			    &t.centres);
		pthread_mutex_lock(&pool->lock);
		pool->busy--;
	}
	/* The last one out wakes the others to find the same. */
	pthread_cond_broadcast(&pool->cond);
	pthread_mutex_unlock(&pool->lock);
	return NULL;
}

/* Builds below the root's two children with up to `threads` threads: this
 * one and threads - 1 others (fewer when they cannot be started; with
 * none, this one builds everything). */
static void build_parallel(struct build *b, size_t n, size_t split, const struct build_box bounds[4],
			   int threads)
{
	struct build_pool pool;
	pthread_t thread[64];
	int k, started = 0;

	if (threads > 64)
		threads = 64;
	if (threads < 2 || n < 2 * ACCEL_PARALLEL_MIN ||
	    pthread_mutex_init(&pool.lock, NULL) != 0) {
		build_children(b, NULL, 0, 0, n, split, 1, bounds);
		return;
	}
	if (pthread_cond_init(&pool.cond, NULL) != 0) {
		pthread_mutex_destroy(&pool.lock);
		build_children(b, NULL, 0, 0, n, split, 1, bounds);
		return;
	}
	pool.b = b;
	pool.n_tasks = 0;
	/* This thread counts as busy until its own part is built, so that
	 * the others wait for the tasks it will offer. */
	pool.busy = 1;
	for (k = 0; k < threads - 1; k++) {
		if (pthread_create(&thread[started], NULL, pool_work, &pool) != 0)
			break;
		started++;
	}
	build_children(b, &pool, 0, 0, n, split, 1, bounds);
	pthread_mutex_lock(&pool.lock);
	pool.busy--;
	pthread_cond_broadcast(&pool.cond);
	pthread_mutex_unlock(&pool.lock);
	pool_work(&pool);
	for (k = 0; k < started; k++)
		pthread_join(thread[k], NULL);
	pthread_cond_destroy(&pool.cond);
	pthread_mutex_destroy(&pool.lock);
}

/* Node 0 holds the two halves of the whole set; a set that makes one leaf
 * sits beside an empty child whose box no ray can enter (its minimum is
 * +inf and its maximum -inf on every axis). */
static void build_root(struct build *b, size_t n, int threads)
{
	struct build_box box, centres, bounds[4];
	size_t split;
	int k;

	refs_bounds(b->refs, n, &box, &centres);
	split = choose_split(b, 0, n, 0, &box, &centres, bounds);
	if (split == 0) {
		set_child_box(&b->nodes[0], 0, &box);
		b->nodes[0].slot[0] = leaf_slot(b, 0, n);
		for (k = 0; k < 3; k++) {
			b->nodes[0].bounds[0][k][1] = INFINITY;
			b->nodes[0].bounds[1][k][1] = -INFINITY;
		}
		b->nodes[0].slot[1] = 0;
		return;
	}
	build_parallel(b, n, split, bounds, threads);
}

/* Moves the nodes the tree uses to the front of the array, keeping their
 * order, and returns how many there are.  Depth-first order is index
 * order, so a node only ever moves down onto an index already passed, and
 * its parent, met before it, has already moved. */
static size_t squeeze_nodes(struct bvh_node *nodes)
{
	struct { size_t old, parent; int c; } stack[ACCEL_STACK];
	size_t next = 1;
	int top = 0, c;

	for (c = 1; c >= 0; c--) {
		if ((nodes[0].slot[c] & 7) == ACCEL_SLOT_NODE) {
			stack[top].old = nodes[0].slot[c] >> 3;
			stack[top].parent = 0;
			stack[top++].c = c;
		}
	}
	while (top > 0) {
		size_t old, index = next++;
		top--;
		old = stack[top].old;
		nodes[index] = nodes[old];
		nodes[stack[top].parent].slot[stack[top].c] = (uintptr_t)index << 3 | ACCEL_SLOT_NODE;
		for (c = 1; c >= 0; c--) {
			if ((nodes[index].slot[c] & 7) != ACCEL_SLOT_NODE)
				continue;
			assert(top < ACCEL_STACK);
			stack[top].old = nodes[index].slot[c] >> 3;
			stack[top].parent = index;
			stack[top++].c = c;
		}
	}
	return next;
}

int accel_build(const struct scene *s, int threads, struct accel **out, struct diag *d)
{
	struct build b = { NULL, NULL };
	struct accel *a;
	size_t i, n_unbounded = 0;

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
		struct bvh_node *nodes;
		size_t cap = a->n_bounded > 1 ? a->n_bounded - 1 : 1;
		b.nodes = rt_reallocarray(NULL, cap, sizeof(*b.nodes));
		if (!b.nodes)
			goto out_free;
		build_root(&b, a->n_bounded, threads);
		a->n_nodes = squeeze_nodes(b.nodes);
		nodes = rt_reallocarray(b.nodes, a->n_nodes, sizeof(*b.nodes));
		a->nodes = nodes ? nodes : b.nodes;
		b.nodes = NULL;
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
