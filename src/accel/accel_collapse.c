/* The walks' four-child tree from the build's binary one.  Each node
 * takes its binary node's two children and then, while it has fewer than
 * four, opens the child node of the largest surface area into that
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
#include <math.h>
#include <stdbool.h>
#include <string.h>

#include "accel/accel_tree.h"
#include "base/alloc.h"
#include "whitted/diag.h"

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

static void child_of(const struct bvh_node *node, int c, struct wide_child *out)
{
	int k;

	out->slot = node->slot[c];
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

/* The children of the four-child node standing for binary node b; how
 * many (1 to 4).  Their node slots still name binary nodes. */
static int gather(const struct bvh_node *binary, size_t b, struct wide_child child[ACCEL_WIDTH])
{
	int n = 0, c;

	/* The root of a tree that is one leaf has an empty child: left out. */
	for (c = 0; c < 2; c++)
		if (binary[b].slot[c] != 0)
			child_of(&binary[b], c, &child[n++]);
	while (n < ACCEL_WIDTH) {
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
		b = accel_slot_index(child[open].slot);
		child_of(&binary[b], 0, &child[open]);
		child_of(&binary[b], 1, &child[n++]);
	}
	return n;
}

static void write_node(struct bvh4_node *node, const struct wide_child *child, int n, float pad)
{
	int c, k;

	memset(node, 0, sizeof(*node));
	for (c = 0; c < ACCEL_WIDTH; c++) {
		for (k = 0; k < 3; k++) {
			node->lo[k][c] = c < n ? child[c].lo[k] - pad : INFINITY;
			node->hi[k][c] = c < n ? child[c].hi[k] + pad : -INFINITY;
		}
		node->slot[c] = c < n ? (uint32_t)child[c].slot : 0;
	}
}

/* The number of four-child nodes, or their making into nodes[]: nodes in
 * depth-first order, a node's first child's subtree first. */
static size_t collapse(const struct bvh_node *binary, struct bvh4_node *nodes)
{
	float pad = tree_pad(&binary[0]);
	struct { size_t b, parent; int c; } stack[ACCEL_STACK * ACCEL_WIDTH];
	size_t next = 0;
	int top = 0;

	stack[top].b = 0;
	stack[top].parent = 0;
	stack[top++].c = -1;
	while (top > 0) {
		struct wide_child child[ACCEL_WIDTH];
		size_t index = next++;
		int n, c;

		top--;
		n = gather(binary, stack[top].b, child);
		if (nodes && stack[top].c >= 0)
			nodes[stack[top].parent].slot[stack[top].c] =
				accel_slot_make(index, ACCEL_SLOT_NODE);
		if (nodes)
			write_node(&nodes[index], child, n, pad);
		for (c = n - 1; c >= 0; c--) {
			if (!accel_slot_is_node(child[c].slot))
				continue;
			stack[top].b = accel_slot_index(child[c].slot);
			stack[top].parent = index;
			stack[top++].c = c;
		}
	}
	return next;
}

int accel_collapse(struct accel *a, const struct bvh_node *binary)
{
	size_t count;

	count = collapse(binary, NULL);
	a->nodes = rt_aligned_array(ACCEL_NODE_ALIGN, count, sizeof(*a->nodes));
	if (!a->nodes)
		return -RT_E_NOMEM;
	a->n_nodes = collapse(binary, a->nodes);
	return 0;
}
