/* The walks' wide tree (four or eight children a node) from the build's
 * binary one.  Each node takes its binary node's two children and then,
 * while it has fewer than the width, opens the child node of the largest
 * surface area into that
 * node's two children: the children a ray is most likely to enter come
 * up, and a node's boxes are tested in one operation instead of across
 * two levels.  The boxes are the binary tree's floats widened by a
 * margin, pad: a shape's own arithmetic may put a hit on its box's face a
 * rounding step outside the box, or before the box's computed entry
 * (a ray grazing the bottom edge of a pyramid on the floor), and a box
 * test that cut such a hit off would make the nearest hit depend on
 * which shapes the walk met first (which t_max a box was tested with).
 * pad is 2^-24 of the largest coordinate of the scene's box: no hit
 * lies that far outside its shape's box, and no box test costs more.
 * Deterministic: the same binary tree gives the same nodes in the same
 * order. */
#include <assert.h>
#include <math.h>
#include <pthread.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel_tree.h"

struct wide_child {
	uintptr_t slot;
	float lo[3], hi[3];
};

static float child_area(const struct wide_child *c)
{
	float d[3];
	int k;

	for (k = 0; k < 3; k++)
		d[k] = c->hi[k] - c->lo[k];
	return d[0] * d[1] + d[1] * d[2] + d[2] * d[0];
}

/* Child c of a binary node; a child node's own memory is asked for at
 * once, as it is soon opened or walked (the collapse waits mostly on
 * those loads: a node's second child lies far from it). */
static void child_of(const struct bvh_node *binary, const struct bvh_node *node, int c,
		     struct wide_child *out)
{
	int k;

	out->slot = node->slot[c];
	if (accel_slot_is_node(out->slot))
		__builtin_prefetch(&binary[accel_slot_index(out->slot)]);
	for (k = 0; k < 3; k++) {
		out->lo[k] = node->bounds[0][k][c];
		out->hi[k] = node->bounds[1][k][c];
	}
}

/* The margin for a tree whose root is binary[0]: 2^-24 of its largest
 * finite coordinate, at least half a float step of every coordinate, so
 * that the float sums below move each bound out by about pad. */
static float tree_pad(const struct bvh_node *root)
{
	double s = 0.0;
	int side, k, c;

	for (side = 0; side < 2; side++)
		for (k = 0; k < 3; k++)
			for (c = 0; c < 2; c++) {
				double v = fabs((double)root->bounds[side][k][c]);
				if (v < INFINITY && v > s)
					s = v;
			}
	return (float)(s * 0x1.02p-24);
}

/* The children of the wide node standing for binary node b; how many (1
 * to width).  Their node slots still name binary nodes. */
static int gather(const struct bvh_node *binary, size_t b, int width,
		  struct wide_child child[ACCEL_WIDTH_MAX])
{
	int n = 0, c;

	/* The root of a tree that is one leaf has an empty child: left out. */
	for (c = 0; c < 2; c++)
		if (binary[b].slot[c] != 0)
			child_of(binary, &binary[b], c, &child[n++]);
	while (n < width) {
		int open = -1;
		float best = -1.0f;
		for (c = 0; c < n; c++) {
			float area;
			if (!accel_slot_is_node(child[c].slot))
				continue;
			/* NaN areas (infinite boxes) count as the largest. */
			area = child_area(&child[c]);
			if (open < 0 || !(area <= best)) {
				open = c;
				best = area;
			}
		}
		if (open < 0)
			break;
		/* Its two children take its place, in order: so the children
		 * stay in the binary tree's depth-first order, which is the
		 * order of its array, and the walk below reads that array
		 * forwards (a stream, not a cache miss a node). */
		b = accel_slot_index(child[open].slot);
		for (c = n; c > open + 1; c--)
			child[c] = child[c - 1];
		child_of(binary, &binary[b], 0, &child[open]);
		child_of(binary, &binary[b], 1, &child[open + 1]);
		n++;
	}
	return n;
}

/* The tree being made: its nodes, of `width` children. */
struct wide_tree {
	char *nodes;
	int width;
};

/* Node i's fields (see struct bvh4_node): lo[axis * width + child], hi
 * likewise, slot[child]. */
struct node_view {
	float *lo, *hi;
	uint32_t *slot;
};

static struct node_view node_at(const struct wide_tree *t, size_t i)
{
	struct node_view v;

	v.lo = (float *)(void *)(t->nodes + i * accel_node_bytes(t->width));
	v.hi = v.lo + 3 * t->width;
	v.slot = (uint32_t *)(void *)(v.hi + 3 * t->width);
	return v;
}

static void write_node(const struct wide_tree *t, size_t i, const struct wide_child *child,
		       int n, float pad)
{
	struct node_view v = node_at(t, i);
	int c, k, w = t->width;

	for (c = 0; c < w; c++) {
		for (k = 0; k < 3; k++) {
			v.lo[k * w + c] = c < n ? child[c].lo[k] - pad : INFINITY;
			v.hi[k * w + c] = c < n ? child[c].hi[k] + pad : -INFINITY;
		}
		v.slot[c] = c < n ? (uint32_t)child[c].slot : 0;
	}
}

/* Makes nodes [first, last) of one level: each from the binary node its
 * parent left in its slot[0], its node children's slots still naming
 * binary nodes (the binary tree's own slots), to be numbered by
 * number_children. */
static size_t make_level(const struct bvh_node *binary, const struct wide_tree *t, size_t first,
			 size_t last, float pad)
{
	size_t i, children = 0;

	for (i = first; i < last; i++) {
		struct wide_child child[ACCEL_WIDTH_MAX];
		int n, c;

		/* The binary nodes of the coming turns, asked for ahead (the
		 * pass waits mostly on those loads: a 56-megabyte array at 1M
		 * shapes, a node's second child far from it), two stages
		 * deep: a node's binary node eight turns ahead, its
		 * children four turns ahead. */
		if (i + 8 < last)
			__builtin_prefetch(&binary[node_at(t, i + 8).slot[0]]);
		if (i + 4 < last) {
			const struct bvh_node *ahead = &binary[node_at(t, i + 4).slot[0]];
			for (c = 0; c < 2; c++)
				if (accel_slot_is_node(ahead->slot[c]))
					__builtin_prefetch(&binary[accel_slot_index(ahead->slot[c])]);
		}
		n = gather(binary, node_at(t, i).slot[0], t->width, child);
		write_node(t, i, child, n, pad);
		for (c = 0; c < n; c++)
			children += accel_slot_is_node(child[c].slot);
	}
	return children;
}

/* The node children of nodes [first, last), numbered from `next` in
 * order: each child's slot then names it, and its slot[0] the binary node
 * it is made from.  Returns the next number. */
static size_t number_children(const struct wide_tree *t, size_t first, size_t last, size_t next)
{
	size_t i;
	int c;

	for (i = first; i < last; i++) {
		uint32_t *slot = node_at(t, i).slot;
		for (c = 0; c < t->width; c++) {
			if (!accel_slot_is_node(slot[c]))
				continue;
			node_at(t, next).slot[0] = (uint32_t)accel_slot_index(slot[c]);
			slot[c] = (uint32_t)accel_slot_make(next++, ACCEL_SLOT_NODE);
		}
	}
	return next;
}

/* A level's second half, made by a thread of its own. */
struct level_half {
	const struct bvh_node *binary;
	const struct wide_tree *tree;
	size_t first, last, next;
	float pad;
	bool number;		/* false: make the nodes; true: number their children */
	size_t children;	/* made: how many of the nodes' children are nodes */
};

static void *level_half_run(void *arg)
{
	struct level_half *h = arg;

	if (h->number)
		number_children(h->tree, h->first, h->last, h->next);
	else
		h->children = make_level(h->binary, h->tree, h->first, h->last, h->pad);
	return NULL;
}

/* Runs h's work on a thread of its own and `self` on this one, or both
 * here when no thread can be had: the same nodes either way. */
static void split_level(struct level_half *self, struct level_half *h)
{
	pthread_t t;
	bool started = pthread_create(&t, NULL, level_half_run, h) == 0;

	level_half_run(self);
	if (started)
		pthread_join(t, NULL);
	else
		level_half_run(h);
}

/* Levels this big are made by two threads. */
#define COLLAPSE_PARALLEL_MIN 8192

/* The wide nodes in breadth-first order, level by level, the children of
 * a node side by side, into t (room for any tree of its leaves): node i
 * made from the binary node its parent left in its slot[0].  Breadth
 * first, the binary nodes a level reads are known before it starts, so
 * they are asked for ahead; a big level is made by two threads, each
 * half's children numbered after the first half's, so the nodes are the
 * same for any thread count.  Returns the node count. */
static size_t collapse(const struct bvh_node *binary, const struct wide_tree *t, int threads)
{
	float pad = tree_pad(&binary[0]);
	size_t first = 0, last = 1;

	node_at(t, 0).slot[0] = 0;
	while (first < last) {
		size_t next;
		if (threads > 1 && last - first >= COLLAPSE_PARALLEL_MIN) {
			size_t mid = first + (last - first) / 2;
			struct level_half lo = { binary, t, first, mid, 0, pad, false, 0 };
			struct level_half hi = { binary, t, mid, last, 0, pad, false, 0 };
			split_level(&lo, &hi);
			lo.number = hi.number = true;
			lo.next = last;
			hi.next = last + lo.children;
			split_level(&lo, &hi);
			next = hi.next + hi.children;
		} else {
			(void)make_level(binary, t, first, last, pad);
			next = number_children(t, first, last, last);
		}
		first = last;
		last = next;
	}
	return last;
}

/* A tree of L leaves: a node with fewer children than the width has only
 * leaves below it (it stopped opening), at least two, and the others
 * have `width` children; counting the children, N - 1 + L, gives at most
 * (L - 1 + (w - 2) P) / (w - 1) nodes, P <= L / 2 of them partial:
 * 2L/3 for four children, 4L/7 for eight. */
size_t accel_collapse_room(size_t leaves, int width)
{
	return leaves / 2 * (size_t)width / (size_t)(width - 1) + 2;
}

void accel_collapse(struct accel *a, const struct bvh_node *binary, size_t leaves, int width,
		    int threads, void *room, size_t room_bytes)
{
	struct wide_tree t;

	assert(room && (uintptr_t)room % ACCEL_NODE_ALIGN == 0 &&
	       accel_collapse_room(leaves, width) <= room_bytes / accel_node_bytes(width));
	(void)leaves;
	(void)room_bytes;
	t.nodes = room;
	t.width = width;
	a->nodes = room;
	a->n_nodes = collapse(binary, &t, threads);
}
