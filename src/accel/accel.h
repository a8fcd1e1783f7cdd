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
/* accel_occluded_packet for the rays of p's lanes in `active` (bits
 * below ACCEL_PACKET), left where they are: the mask of those blocked.
 * The lanes not active may hold anything (even no ray: NaN): the walks
 * give the shapes copies of an active one there.  For shadow rays made a
 * vector at a time (render_shadow_packets), which then need no gathering
 * into single rays and back. */
uint32_t accel_occluded_lanes(const struct accel *a, const struct ray_packet *p, uint32_t active,
			      const double *t_min, const double *t_max);
/* accel_intersect_packet for the rays of p's lanes in `active` (bits
 * below ACCEL_PACKET), left where they are: hit[i] and t_max[i] of those
 * lanes only (the others are not written, and what they hold, in p,
 * t_min and t_max, is not used: it may be anything, the arrays must
 * only have every lane).  For rays made a vector at a time (the camera's, a packet's
 * reflections, which keep their hits' lanes). */
void accel_intersect_lanes(const struct accel *a, const struct ray_packet *p, uint32_t active,
			   const double *t_min, double *t_max, const struct shape **hit);
/* Whether packets are faster than single rays here: where the walks have
 * the AVX2 or AVX-512 box tests (a tree big enough; see accel_build.c),
 * or a small tree's packets go a ray a vector lane in AVX2 or AVX-512
 * (accel_packet_rays.h: the course example 0.78x the time of single
 * rays).  With SSE2's two lanes alone they gain nothing. */
bool accel_packets_pay(const struct accel *a);
/* Whether packets pay even when their rays part (reflections off curved
 * mirrors): where they go a ray a lane, whose box tests cost the same
 * whatever the rays do.  The eight-child trees' packets, a node's children
 * a lane, pay only for coherent rays (gen-100k 1.17x the time with
 * reflections in packets). */
bool accel_packets_scatter_pay(const struct accel *a);
/* Whether the renderer traces packets: where they pay, unless
 * WHITTED_PACKETS=0 asks for one ray at a time or WHITTED_PACKETS=1 for
 * packets anyway (to compare: the images are the same). */
bool accel_packets_wanted(const struct accel *a);
/* How the packets go, for --stats: "no packets", or the instructions and
 * whether a vector lane is a ray (a small tree's packets) or a node's
 * child (a big tree's). */
const char *accel_packets_name(const struct accel *a);

/* Which box tests the walks use ("avx512", "avx2", "sse2" or
 * "portable"), for --stats. */
const char *accel_walk_name(const struct accel *a);
/* Sizes, for --stats and the memory tests. */
size_t accel_node_count(const struct accel *a);
size_t accel_bytes(const struct accel *a);

#endif
