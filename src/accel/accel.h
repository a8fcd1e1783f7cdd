/* The acceleration structure: a bounding volume hierarchy (binned surface
 * area heuristic) over the bounded shapes, and a plain list of the
 * unbounded ones.  Queries allocate nothing and take no locks. */
#ifndef RT_ACCEL_H
#define RT_ACCEL_H

#include <stdbool.h>
#include <stddef.h>

#include "whitted/diag.h"
#include "whitted/ray.h"
#include "whitted/shape.h"

struct accel;

/* Builds with up to `threads` threads (at least 1); the tree is the same
 * for any number. */
int accel_build(struct shape *const *shapes, size_t n_shapes, int threads, struct accel **out,
		struct diag *d);
void accel_destroy(struct accel *a);

/* The nearest shape hit with t in (t_min, *t_max), shrinking *t_max; NULL
 * when nothing is hit. */
const struct shape *accel_intersect(const struct accel *a, const struct ray *r,
				    double t_min, double *t_max);
/* Whether anything is hit with t in (t_min, t_max); stops at the first. */
bool accel_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max);

/* Which box tests the walks use ("avx2", "sse2" or "portable"), for
 * --stats. */
const char *accel_walk_name(const struct accel *a);
/* Sizes, for --stats and the memory tests. */
size_t accel_node_count(const struct accel *a);
size_t accel_bytes(const struct accel *a);

#endif
