/* The build's first step: a reference (box and shape) for every bounded
 * shape, in the scene's order, and the box and centre bounds of them all.
 * A big scene's shapes are bounded by several threads, a run of the scene
 * each (the calls through every shape's table and the reads of the shapes
 * are most of the step's time); the runs' refs are then closed up and
 * their bounds merged in the scene's order, so the result is the same to
 * the bit for any number of threads. */
#include <stdbool.h>
#include <stddef.h>
#include <string.h>

#include "accel/accel_build.h"
#include "base/thread.h"

/* Refs are bounded in runs of this many, while they are still in the
 * first-level cache. */
#define COLLECT_RUN 256
/* Each thread takes at least this many shapes: below that, starting a
 * thread costs more than it saves. */
#define COLLECT_PARALLEL_MIN 4096
#define COLLECT_THREADS_MAX 64

/* A run of the scene: shapes[first, first + n), whose refs go to
 * refs[first, first + n_bounded). */
struct collect_part {
	struct shape *const *shapes;
	struct build_ref *refs;
	size_t first, n, n_bounded;
	struct build_box box, centres;
};

bool accel_tree_box(const struct shape *s, struct aabb *box)
{
	const double m = ACCEL_COORD_MAX;

	/* Written so that a NaN fails every comparison. */
	return shape_bounds(s, box) && box->min.x >= -m && box->min.y >= -m && box->min.z >= -m &&
	       box->max.x <= m && box->max.y <= m && box->max.z <= m && box->min.x <= m &&
	       box->min.y <= m && box->min.z <= m && box->max.x >= -m && box->max.y >= -m &&
	       box->max.z >= -m;
}

static void collect_part(struct collect_part *p)
{
	struct build_ref *refs = p->refs + p->first;
	size_t i, n_bounded = 0, bounded_done = 0;

	accel_refs_bounds(refs, 0, &p->box, &p->centres);
	for (i = p->first; i < p->first + p->n; i++) {
		struct build_ref *ref = &refs[n_bounded];
		struct aabb box;
		if (n_bounded - bounded_done >= COLLECT_RUN) {
			accel_refs_bounds_grow(refs + bounded_done, n_bounded - bounded_done, &p->box,
					       &p->centres);
			bounded_done = n_bounded;
		}
		if (!accel_tree_box(p->shapes[i], &box))
			continue;
		ref->lo[0] = box.min.x;
		ref->lo[1] = box.min.y;
		ref->lo[2] = box.min.z;
		ref->hi[0] = box.max.x;
		ref->hi[1] = box.max.y;
		ref->hi[2] = box.max.z;
		ref->index = i;
		n_bounded++;
	}
	accel_refs_bounds_grow(refs + bounded_done, n_bounded - bounded_done, &p->box, &p->centres);
	p->n_bounded = n_bounded;
}

static void *collect_thread(void *arg)
{
	collect_part(arg);
	return NULL;
}

size_t accel_collect_refs(struct build_ref *refs, struct shape *const *shapes, size_t n_shapes,
			  int threads, struct build_box *box, struct build_box *centres)
{
	struct collect_part part[COLLECT_THREADS_MAX];
	size_t n_parts, k, n_bounded = 0;

	n_parts = threads < 1 ? 1 : (size_t)threads;
	if (n_parts > COLLECT_THREADS_MAX)
		n_parts = COLLECT_THREADS_MAX;
	if (n_parts > n_shapes / COLLECT_PARALLEL_MIN)
		n_parts = n_shapes / COLLECT_PARALLEL_MIN;
	if (n_parts < 1)
		n_parts = 1;
	for (k = 0; k < n_parts; k++) {
		part[k].shapes = shapes;
		part[k].refs = refs;
		part[k].first = n_shapes / n_parts * k;
		part[k].n = k + 1 < n_parts ? n_shapes / n_parts : n_shapes - part[k].first;
	}
	/* This thread takes the first run; a thread that cannot be started
	 * leaves its run to this one. */
	rt_run_parts(part, sizeof(part[0]), (int)n_parts, collect_thread);
	/* Each run's refs follow the last's, and its bounds grow the whole's
	 * as its refs would one by one: a minimum or maximum met again stays
	 * the one met first. */
	*box = part[0].box;
	*centres = part[0].centres;
	for (k = 0; k < n_parts; k++) {
		if (part[k].first != n_bounded)
			memmove(refs + n_bounded, refs + part[k].first,
				part[k].n_bounded * sizeof(*refs));
		n_bounded += part[k].n_bounded;
		if (k > 0)
			accel_boxes_grow(box, centres, &part[k].box, &part[k].centres);
	}
	return n_bounded;
}
