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

#include "accel/accel.h"
#include "accel/accel_build.h"
#include "accel/accel_kernels.h"
#include "accel/accel_tree.h"
#include "base/alloc.h"

/* A node offers its right half to the other threads only when both halves
 * have this many refs: below that, handing work over costs more than it
 * saves. */
#define ACCEL_PARALLEL_MIN 4096

/* The AVX2 and AVX-512 walks save instructions a node but cost more to
 * set up a ray (six wide values, the upper halves cleared around every
 * shape test's call), and eight children a node cost more than four to
 * order: a small scene, whose rays visit a handful of nodes, keeps the
 * SSE2 walks over four children (callgrind, the course example of 6
 * shapes: 15% more instructions with AVX2; its render 1.13x the time with
 * eight children and AVX-512). */
#define ACCEL_SIMD_MIN_SHAPES 512


/* The build writes every node in place, into an array allocated once: the
 * subtree over refs [first, first + n) owns node indices [base, base + n -
 * 1) (a tree of n leaves has n - 1 nodes, and fewer with bigger leaves):
 * its own node at base, its left child's subtree from base + 1 and its
 * right child's from base + the left's refs.  So the halves of a node can
 * be built by different threads with no lock, no copy and no allocation.
 * The indices that bigger leaves leave unused stay unused: the walks' tree
 * (accel_collapse.c) is made from the slots, and the array then freed. */
struct build {
	struct build_ref *refs;	/* then the wide tree (see collect_refs) */
	size_t refs_bytes;
	uint32_t *order;	/* the refs' shapes in leaf order, at the end of refs' block */
	struct bvh_node *nodes;
	struct build_box box, centres;	/* of all the refs, found as they are made */
};

/* The slot of a leaf over refs[first, first + n): their place is final
 * once they make a leaf. */
static uintptr_t leaf_slot(size_t first, size_t n)
{
	assert(n >= 1 && n <= ACCEL_LEAF_MAX && ACCEL_LEAF_MAX < ACCEL_SLOT_NODE);
	return accel_slot_make(first, n);
}
/* Subtrees waiting for a thread.  Whoever splits a big node puts its
 * right-hand child here and goes on with the left; idle threads take the
 * most recent.  So the threads stay busy however unevenly the tree
 * splits, and as every subtree writes only its own nodes, which thread
 * builds it changes nothing. */
#define BUILD_TASKS_MAX 256

/* A subtree to build: over refs[first, first + n), with their box and
 * centre bounds, as a child of node `parent`, its own node (if it is not
 * a leaf) at index base, at this depth. */
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

static void build_children(struct build *b, struct build_pool *pool, struct accel_bins *bins,
			   size_t index, size_t first, size_t n, size_t split, int depth,
			   const struct build_parts *parts);

/* Builds task t's subtree as child c of its parent: a leaf, or the node
 * at t->base and what lies below it. */
static void build_child(struct build *b, struct build_pool *pool, struct accel_bins *bins, int c,
			const struct build_task *t)
{
	struct build_parts parts;
	size_t split;

	/* One ref is a leaf (half the children): no search. */
	split = t->n > 1 ? accel_choose_split(b->refs + t->first, t->n, t->depth, &t->box, &t->centres,
					      &parts, bins) : 0;
	if (split == 0) {
		b->nodes[t->parent].slot[c] = leaf_slot(t->first, t->n);
		return;
	}
	b->nodes[t->parent].slot[c] = accel_slot_make(t->base, ACCEL_SLOT_NODE);
	build_children(b, pool, bins, t->base, t->first, t->n, split, t->depth + 1, &parts);
}

/* Offers the right-hand child of a big node to the other threads; false
 * when the caller is to build it. */
static bool pool_offer(struct build_pool *pool, const struct build_task *t)
{
	bool taken = false;

	pthread_mutex_lock(&pool->lock);
	if (pool->n_tasks < BUILD_TASKS_MAX) {
		pool->task[pool->n_tasks++] = *t;
		taken = true;
		pthread_cond_signal(&pool->cond);
	}
	pthread_mutex_unlock(&pool->lock);
	return taken;
}

/* Builds both children of node `index`, which stands for refs[first,
 * first + n) split after `split` of them.  Each child writes only its own
 * slot of the node. */
static void build_children(struct build *b, struct build_pool *pool, struct accel_bins *bins,
			   size_t index, size_t first, size_t n, size_t split, int depth,
			   const struct build_parts *parts)
{
	const struct build_task front = {
		.parent = index, .first = first, .n = split, .base = index + 1, .depth = depth,
		.box = parts->front, .centres = parts->front_centres,
	};
	const struct build_task back = {
		.parent = index, .first = first + split, .n = n - split, .base = index + split,
		.depth = depth, .box = parts->back, .centres = parts->back_centres,
	};
	bool offered;

	accel_set_child_box(&b->nodes[index], 0, &parts->front);
	accel_set_child_box(&b->nodes[index], 1, &parts->back);
	offered = pool && split >= ACCEL_PARALLEL_MIN && n - split >= ACCEL_PARALLEL_MIN &&
		  pool_offer(pool, &back);
	build_child(b, pool, bins, 0, &front);
	if (!offered)
		build_child(b, pool, bins, 1, &back);
}

/* A thread of the pool: takes tasks until there are none and no thread
 * is building one (which could offer more). */
static void *pool_work(void *arg)
{
	struct build_pool *pool = arg;
	struct accel_bins bins;

	accel_bins_init(&bins);
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
		build_child(pool->b, pool, &bins, 1, &t);
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
static void build_parallel(struct build *b, struct accel_bins *bins, size_t n, size_t split,
			   const struct build_parts *parts, int threads)
{
	struct build_pool pool;
	pthread_t thread[64];
	int k, started = 0;

	if (threads > 64)
		threads = 64;
	if (threads < 2 || n < 2 * ACCEL_PARALLEL_MIN ||
	    pthread_mutex_init(&pool.lock, NULL) != 0) {
		build_children(b, NULL, bins, 0, 0, n, split, 1, parts);
		return;
	}
	if (pthread_cond_init(&pool.cond, NULL) != 0) {
		pthread_mutex_destroy(&pool.lock);
		build_children(b, NULL, bins, 0, 0, n, split, 1, parts);
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
	build_children(b, &pool, bins, 0, 0, n, split, 1, parts);
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
	struct build_box box, centres;
	struct build_parts parts;
	struct accel_bins bins;
	size_t split;
	int k;

	accel_bins_init(&bins);
	box = b->box;
	centres = b->centres;
	split = accel_choose_split(b->refs, n, 0, &box, &centres, &parts, &bins);
	if (split == 0) {
		accel_set_child_box(&b->nodes[0], 0, &box);
		b->nodes[0].slot[0] = leaf_slot(0, n);
		for (k = 0; k < 3; k++) {
			b->nodes[0].bounds[0][k][1] = INFINITY;
			b->nodes[0].bounds[1][k][1] = -INFINITY;
		}
		b->nodes[0].slot[1] = 0;
		return;
	}
	build_parallel(b, &bins, n, split, &parts, threads);
}

/* The refs of the bounded shapes, in the scene's order, with their box and
 * centre bounds, and the list of the unbounded ones. */
static int collect_refs(struct shape *const *shapes, size_t n_shapes, int threads, int width,
			struct accel *a, struct build *b)
{
	size_t i, n_unbounded, tree, count, bytes;

	/* The refs' block takes the wide tree once they are done with
	 * (accel_collapse), so it is aligned for it and big enough for any
	 * (accel_collapse_room), and past both it keeps the leaf order's
	 * shape indices (b->order) while the binary nodes and the tree
	 * coexist: the pages of the room that the tree does not need are
	 * never touched. */
	tree = accel_collapse_room(n_shapes, width);
	if (tree > SIZE_MAX / 2 / accel_node_bytes(width) || n_shapes > SIZE_MAX / 2 / 64)
		return -RT_E_NOMEM;
	bytes = tree * accel_node_bytes(width);
	if (bytes < n_shapes * sizeof(*b->refs))
		bytes = n_shapes * sizeof(*b->refs);
	count = (bytes + n_shapes * sizeof(*b->order) + sizeof(*b->refs) - 1) / sizeof(*b->refs);
	b->refs = rt_array_huge(ACCEL_NODE_ALIGN, count, sizeof(*b->refs));
	if (!b->refs)
		return -RT_E_NOMEM;
	b->refs_bytes = bytes;
	b->order = (uint32_t *)(void *)((char *)b->refs + bytes);
	a->n_bounded = accel_collect_refs(b->refs, shapes, n_shapes, threads, &b->box, &b->centres);
	n_unbounded = n_shapes - a->n_bounded;
	a->unbounded = rt_reallocarray(NULL, n_unbounded, sizeof(*a->unbounded));
	a->unbounded_key = rt_reallocarray(NULL, n_unbounded, sizeof(*a->unbounded_key));
	if (!a->unbounded || !a->unbounded_key)
		return -RT_E_NOMEM;
	/* From the end, where a view's floor is, until all are found: in the
	 * scene's order, without a second pass over a big scene's shapes. */
	a->n_unbounded = n_unbounded;
	for (i = n_shapes; i-- > 0 && n_unbounded > 0;) {
		struct aabb box;
		if (!accel_tree_box(shapes[i], &box)) {
			a->unbounded[--n_unbounded] = shapes[i];
			a->unbounded_key[n_unbounded] = (uint32_t)n_unbounded;
		}
	}
	return 0;
}

/* The shapes in leaf order and their keys (accel_tree.h), in one block:
 * the pointers, then the keys; from b->order, made once the binary nodes
 * are freed, so that the tree, the binary nodes and this block are never
 * all resident at once (gen-1M at eight children: a peak of 280.6 MiB
 * against 288.2 with this block made before the collapse).  0 or
 * -RT_E_NOMEM. */
static int leaf_order(struct accel *a, const struct build *b, struct shape *const *shapes)
{
	size_t n = a->n_bounded, i;
	void *block = rt_array_huge(sizeof(void *), n, sizeof(*a->bounded) + sizeof(*a->bounded_key));

	if (!block)
		return -RT_E_NOMEM;
	a->bounded = block;
	a->bounded_key = (uint32_t *)(void *)(a->bounded + n);
	for (i = 0; i < n; i++) {
		size_t index = b->order[i];
		a->bounded_key[i] = (uint32_t)(a->n_unbounded + index);
		a->bounded[i] = shapes[index];
	}
	return 0;
}

/* The walks for a scene of n_shapes: the set in use (the widest the
 * processor has), for a scene big enough to pay for them. */
static enum rt_simd choose_walk(size_t n_shapes)
{
	return n_shapes < ACCEL_SIMD_MIN_SHAPES ? RT_SIMD_BASE : rt_simd_level();
}

int accel_build(struct shape *const *shapes, size_t n_shapes, int threads, struct accel **out,
		struct diag *d)
{
	return accel_build_walk(shapes, n_shapes, threads, choose_walk(n_shapes), out, d);
}

/* Long: the build's phases (refs, binary tree, collapse, the shapes' order)
 * in sequence with one exit that frees what was made. */
int accel_build_walk(struct shape *const *shapes, size_t n_shapes, int threads,
		     enum rt_simd walk, struct accel **out, struct diag *d)
{
	struct build b = { .refs = NULL, .nodes = NULL };
	const struct accel_kernels *k = accel_kernels_of(walk);
	struct accel *a;
	int width;

	*out = NULL;
	if (!k)
		return diag_fail(d, RT_E_INVALID, "this build has no %s walks", rt_simd_name(walk));
	width = k->width;
	/* A slot holds an index of 29 bits (accel_tree.h), a key 32. */
	if (n_shapes > ACCEL_SHAPES_MAX)
		return diag_fail(d, RT_E_RANGE,
				 "%zu objects: the hierarchy holds at most %lu", n_shapes,
				 (unsigned long)ACCEL_SHAPES_MAX);
	a = rt_calloc(1, sizeof(*a));
	if (!a)
		goto out_nomem;
	a->walk = k;
	a->walk_set = walk;
	a->width = width;
	accel_set_rays(a, rt_simd_level());
	if (collect_refs(shapes, n_shapes, threads, width, a, &b) < 0)
		goto out_free;
	if (a->n_bounded > 0) {
		size_t cap = a->n_bounded > 1 ? a->n_bounded - 1 : 1, i;
		void *nodes;
		b.nodes = rt_array_huge(sizeof(void *), cap, sizeof(*b.nodes));
		if (!b.nodes)
			goto out_free;
		build_root(&b, a->n_bounded, threads);
		for (i = 0; i < a->n_bounded; i++)
			b.order[i] = (uint32_t)b.refs[i].index;
		/* The refs are done with: their memory takes the wide tree
		 * (collect_refs made it big enough), so that the build's peak
		 * is the refs and the binary nodes, or the binary nodes and
		 * the tree, not all three. */
		accel_collapse(a, b.nodes, a->n_bounded, width, threads, b.refs, b.refs_bytes);
		b.refs = NULL;
		rt_free(b.nodes);
		b.nodes = NULL;
		if (leaf_order(a, &b, shapes) < 0)
			goto out_free;
		/* The tree's block shrunk to the tree: the room it did not
		 * use, and b.order, go. */
		nodes = rt_aligned_shrink(a->nodes, ACCEL_NODE_ALIGN, a->n_nodes,
					  accel_node_bytes(width));
		if (nodes)
			a->nodes = nodes;
		rt_release_free_memory();
	}
	rt_free(b.refs);
	*out = a;
	return 0;
out_free:
	rt_free(b.nodes);
	rt_free(b.refs);
	accel_destroy(a);
out_nomem:
	return diag_fail(d, RT_E_NOMEM, "out of memory building the scene's hierarchy");
}

void accel_destroy(struct accel *a)
{
	if (!a)
		return;
	rt_free(a->nodes);
	rt_free(a->bounded);	/* and bounded_key, in the same block */
	rt_free(a->unbounded);
	rt_free(a->unbounded_key);
	rt_free(a);
}
