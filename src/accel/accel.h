/* The acceleration structure: a bounding volume hierarchy (binned surface
 * area heuristic) over the bounded shapes, and a plain list of the
 * unbounded ones.  Queries allocate nothing and take no locks. */
#ifndef RT_ACCEL_H
#define RT_ACCEL_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

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

/* Packets of coherent rays (a block's primary rays, their shadow rays to
 * a light): at most ACCEL_PACKET rays r[0..n-1], each with its own
 * interval, and each ray's answer exactly what accel_intersect or
 * accel_occluded gives it alone (the same shape, the same t, ties
 * included).  hit[i] is ray i's nearest shape or NULL, t_max[i] shrunk to
 * its distance; the mask of the rays blocked. */
#define ACCEL_PACKET 16
void accel_intersect_packet(const struct accel *a, const struct ray *r, int n,
			    const double *t_min, double *t_max, const struct shape **hit);
uint32_t accel_occluded_packet(const struct accel *a, const struct ray *r, int n,
			       const double *t_min, const double *t_max);
/* Whether packets are faster than single rays here: where the walks have
 * the AVX2 or AVX-512 box tests (a tree big enough; see accel_build.c).  The plain-C
 * ones (SSE2 and portable builds) test ray by ray, slower than the single
 * walks, and in a small tree the packets' set-up costs more than their
 * walk saves (the course example: 6% more instructions). */
bool accel_packets_pay(const struct accel *a);

/* Which box tests the walks use ("avx512", "avx2", "sse2" or
 * "portable"), for --stats. */
const char *accel_walk_name(const struct accel *a);
/* Sizes, for --stats and the memory tests. */
size_t accel_node_count(const struct accel *a);
/* WHITTED_ISA's value when it names no walk (see accel_walk_usable), else
 * NULL. */
const char *accel_walk_cap_unknown(void);
size_t accel_bytes(const struct accel *a);

#endif
