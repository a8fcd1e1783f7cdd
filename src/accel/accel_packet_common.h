/* What the packet walks share (accel_packet.h, accel_packet_rays.h):
 * the packet as the shapes take it, and the leaves' tests for a packet's
 * rays against their best so far. */
#ifndef RT_ACCEL_PACKET_COMMON
#define RT_ACCEL_PACKET_COMMON

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_tree.h"
#include "accel/accel_walk_common.h"

/* A packet's rays as the shapes take them, and their t_min: every lane
 * filled (those past the n rays with ray 0, or those of no ray with a
 * copy of another), as intersect_packet may read whole runs.  A ray
 * tested alone is made from its lane (ray_packet_get: the same values). */
struct packet_shape_rays {
	struct ray_packet p;
	double t_min[ACCEL_PACKET];
};

/* A shape is tested for at most this many of a packet's rays one ray at a
 * time: a packet method takes a whole run for one ray as for eight.  (In
 * an eight-child tree the packets reach most leaves with a ray or two;
 * the course example 0.96x the time with 2 than with 0, the 100k scenes
 * the same.) */
#define PACKET_SINGLE_MAX 2

static inline void packet_shape_rays_load(struct packet_shape_rays *s, const struct ray *r, int n,
					  const double *t_min)
{
	int i;

	for (i = 0; i < ACCEL_PACKET; i++) {
		int j = i < n ? i : 0;
		ray_packet_set(&s->p, i, r + j);
		s->t_min[i] = t_min[j];
	}
}

static inline bool packet_few(uint32_t mask)
{
	return __builtin_popcount(mask) <= PACKET_SINGLE_MAX;
}

/* The bound a shape is tested to against each ray's best so far: the best
 * t, or one step past it once there is a hit (the tie rule). */
static inline void packet_bounds(const struct walk_best *b, uint32_t mask, double *t)
{
	int i;

	for (i = 0; i < ACCEL_PACKET; i++)
		t[i] = b[i].t;
	for (; mask; mask &= mask - 1) {
		i = __builtin_ctz(mask);
		if (b[i].hit)
			t[i] = next_up(b[i].t);
	}
}

/* Tests shape sh, of key `key`, for the rays of `mask` against their
 * best so far. */
static inline void packet_best_test(const struct shape *sh, uint32_t key,
				    const struct packet_shape_rays *s, uint32_t mask,
				    struct walk_best *b)
{
	double t[ACCEL_PACKET];
	uint32_t m;

	if (packet_few(mask)) {
		for (m = mask; m; m &= m - 1) {
			int i = __builtin_ctz(m);
			struct ray one = ray_packet_get(&s->p, i);
			best_test(&b[i], sh, key, &one, s->t_min[i]);
		}
		return;
	}
	packet_bounds(b, mask, t);
	for (m = shape_intersect_packet(sh, &s->p, mask, s->t_min, t); m; m &= m - 1) {
		int i = __builtin_ctz(m);
		if (t[i] < b[i].t || key < b[i].key) {
			b[i].t = t[i];
			b[i].hit = sh;
			b[i].key = key;
		}
	}
}

static inline void packet_leaf_nearest(const struct accel *a, uintptr_t slot,
				       const struct packet_shape_rays *s, uint32_t mask,
				       struct walk_best *b)
{
	size_t pos = accel_slot_index(slot);
	unsigned count = accel_slot_tag(slot), k;

	for (k = 0; k < count; k++)
		packet_best_test(a->bounded[pos + k], a->bounded_key[pos + k], s, mask, b);
}

/* The rays of `mask` that a leaf's shapes block in (t_min, t_max);
 * t_max has every lane. */
static inline uint32_t packet_leaf_any(const struct accel *a, uintptr_t slot,
				       const struct packet_shape_rays *s, uint32_t mask,
				       const double *t_max)
{
	size_t pos = accel_slot_index(slot);
	unsigned count = accel_slot_tag(slot), k;
	uint32_t blocked = 0, m;
	double t[ACCEL_PACKET];

	if (packet_few(mask)) {
		for (m = mask; m; m &= m - 1) {
			int i = __builtin_ctz(m);
			struct ray one = ray_packet_get(&s->p, i);
			if (leaf_occluded(a, slot, &one, s->t_min[i], t_max[i]))
				blocked |= (uint32_t)1 << i;
		}
		return blocked;
	}
	for (k = 0; k < count && mask; k++) {
		/* A copy for the shape to shrink: a blocker's distance does
		 * not matter here. */
		memcpy(t, t_max, sizeof(t));
		m = shape_intersect_packet(a->bounded[pos + k], &s->p, mask, s->t_min, t);
		blocked |= m;
		mask &= ~m;
	}
	return blocked;
}

static inline uint32_t packet_all(int n)
{
	return n >= 32 ? ~(uint32_t)0 : ((uint32_t)1 << n) - 1;
}

#endif
