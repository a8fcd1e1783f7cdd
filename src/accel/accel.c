/* Queries on the bounding volume hierarchy (built by accel_build.c and
 * accel_collapse.c) and the list of unbounded shapes that every ray
 * tests: each through the walks of the tree's set of instructions
 * (accel_kernels.h), chosen at the build.  Nothing here allocates or
 * locks per ray. */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_kernels.h"
#include "accel/accel_tree.h"
#include "base/simd.h"

RT_SIMD_TABLES(struct accel_kernels, accel_kernels, accel_sets);

const struct accel_kernels *accel_kernels_of(enum rt_simd s)
{
	return (unsigned)s < RT_SIMD_COUNT ? accel_sets[s] : NULL;
}

const struct shape *accel_intersect(const struct accel *a, const struct ray *r,
				    double t_min, double *t_max)
{
	return a->walk->intersect(a, r, t_min, t_max);
}

bool accel_occluded(const struct accel *a, const struct ray *r, double t_min, double t_max)
{
	return a->walk->occluded(a, r, t_min, t_max);
}

/* A four-child tree's packets go a ray a lane in the set in use (rays4 of
 * a->rays); a wide tree's by its own walks. */
void accel_intersect_packet(const struct accel *a, const struct ray *r, int n,
			    const double *t_min, double *t_max, const struct shape **hit)
{
	if (a->walk->wide.intersect_packet)
		a->walk->wide.intersect_packet(a, r, n, t_min, t_max, hit);
	else
		a->rays->rays4.intersect_packet(a, r, n, t_min, t_max, hit);
}

uint32_t accel_occluded_packet(const struct accel *a, const struct ray *r, int n,
			       const double *t_min, const double *t_max)
{
	if (a->walk->wide.occluded_packet)
		return a->walk->wide.occluded_packet(a, r, n, t_min, t_max);
	return a->rays->rays4.occluded_packet(a, r, n, t_min, t_max);
}

/* The active lanes of p as rays, with their ranges and lane numbers (the
 * other wide trees' packets take the rays one by one); their count. */
static int lanes_gather(const struct ray_packet *p, uint32_t active, const double *t_min,
			const double *t_max, struct ray *r, double *t0, double *t1, int *bit)
{
	uint32_t m;
	int n = 0;

	for (m = active; m; m &= m - 1) {
		bit[n] = __builtin_ctz(m);
		r[n] = ray_packet_get(p, bit[n]);
		t0[n] = t_min[bit[n]];
		t1[n] = t_max[bit[n]];
		n++;
	}
	return n;
}

uint32_t accel_occluded_lanes(const struct accel *a, const struct ray_packet *p, uint32_t active,
			      const double *t_min, const double *t_max)
{
	struct ray r[ACCEL_PACKET];
	double t0[ACCEL_PACKET], t1[ACCEL_PACKET];
	int bit[ACCEL_PACKET], n, i;
	uint32_t packed, blocked = 0;

	if (a->walk->wide.occluded_lanes)
		return a->walk->wide.occluded_lanes(a, p, active, t_min, t_max);
	if (!a->walk->wide.occluded_packet)
		return a->rays->rays4.occluded_lanes(a, p, active, t_min, t_max);
	n = lanes_gather(p, active, t_min, t_max, r, t0, t1, bit);
	if (n == 0)
		return 0;
	packed = accel_occluded_packet(a, r, n, t0, t1);
	for (i = 0; i < n; i++)
		blocked |= (packed >> i & 1u) << bit[i];
	return blocked;
}

void accel_intersect_lanes(const struct accel *a, const struct ray_packet *p, uint32_t active,
			   const double *t_min, double *t_max, const struct shape **hit)
{
	struct ray r[ACCEL_PACKET];
	double t0[ACCEL_PACKET], t1[ACCEL_PACKET];
	const struct shape *h[ACCEL_PACKET];
	int bit[ACCEL_PACKET], n, i;

	if (a->walk->wide.intersect_lanes) {
		a->walk->wide.intersect_lanes(a, p, active, t_min, t_max, hit);
		return;
	}
	if (!a->walk->wide.intersect_packet) {
		a->rays->rays4.intersect_lanes(a, p, active, t_min, t_max, hit);
		return;
	}
	n = lanes_gather(p, active, t_min, t_max, r, t0, t1, bit);
	if (n == 0)
		return;
	accel_intersect_packet(a, r, n, t0, t1, h);
	for (i = 0; i < n; i++) {
		t_max[bit[i]] = t1[i];
		hit[bit[i]] = h[i];
	}
}

bool accel_packets_pay(const struct accel *a)
{
	return a->walk_set != RT_SIMD_BASE || a->rays_set != RT_SIMD_BASE;
}

bool accel_packets_scatter_pay(const struct accel *a)
{
	return !a->walk->wide.intersect_packet && a->rays_set != RT_SIMD_BASE;
}

bool accel_packets_wanted(const struct accel *a)
{
	const char *p = getenv("WHITTED_PACKETS");

	if (p && strcmp(p, "0") == 0)
		return false;
	if (p && strcmp(p, "1") == 0)
		return true;
	return a && accel_packets_pay(a);
}

void accel_set_rays(struct accel *a, enum rt_simd s)
{
	a->rays_set = s;
	a->rays = accel_kernels_of(s);
	if (a->walk->packets)
		snprintf(a->packets_name, sizeof(a->packets_name), "%s packets, %s",
			 rt_simd_name(a->walk_set), a->walk->packets);
	else
		snprintf(a->packets_name, sizeof(a->packets_name), "%s packets, a ray a lane",
			 rt_simd_name(s));
}

const char *accel_packets_name(const struct accel *a)
{
	if (!a || !accel_packets_wanted(a))
		return "no packets";
	return a->packets_name;
}

const char *accel_walk_name(const struct accel *a)
{
	return rt_simd_name(a ? a->walk_set : RT_SIMD_BASE);
}

bool accel_walk_usable(enum rt_simd s)
{
	return s <= rt_simd_level() && accel_kernels_of(s) != NULL;
}

size_t accel_node_count(const struct accel *a)
{
	return a ? a->n_nodes : 0;
}

size_t accel_bytes(const struct accel *a)
{
	if (!a)
		return 0;
	return sizeof(*a) + a->n_nodes * accel_node_bytes(a->width) +
	       (a->n_bounded + a->n_unbounded) * (sizeof(const struct shape *) + sizeof(uint32_t));
}
