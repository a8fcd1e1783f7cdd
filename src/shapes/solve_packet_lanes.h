/* The packet solvers (solve_packet.h) written once over base/lanes.h's
 * vectors: the including file, compiled for one set of instructions,
 * defines SOLVE_LANES(name), the names they get.  Each lane does solve.c's
 * (or floor.c's) operations in their order, and each early return there is
 * a lane's mask here, written as the same condition so that a NaN takes
 * the same way; so each ray's answer is the single-ray solver's to the
 * bit.  Lanes go LANES_W at a time through the runs that hold an active
 * ray (whitted/shape.h's intersect_packet contract). */
#include <math.h>
#include <stdint.h>

#include "base/lanes.h"
#include "shapes/solve_packet.h"

/* For each group of LANES_W lanes from j that holds an active one. */
#define FOR_GROUPS(active, j)                                                  \
	for ((j) = 0; (j) < RT_PACKET_MAX && (active) >> (j); (j) += LANES_W)  \
		if ((active) >> (j) & ((1u << LANES_W) - 1))

/* Stores a group's hits among the active rays: t_max of a ray hit, the
 * others their own; the group's bits of the mask. */
static inline uint32_t group_store(double *t_max, uint32_t active, int j, lm hit, lv t)
{
	hit = lm_and(hit, lm_from_bits(active >> j));
	lv_store(t_max + j, lv_sel(hit, t, lv_load(t_max + j)));
	return (uint32_t)lm_bits(hit) << j;
}

static uint32_t SOLVE_LANES(sphere)(const struct ray_packet *p, uint32_t active,
				    struct vec3 c, double radius_sq, const double *t_min,
				    double *t_max)
{
	const lv zero = lv_set1(0.0), r2 = lv_set1(radius_sq);
	uint32_t mask = 0;
	int j;

	FOR_GROUPS(active, j) {
		lv dx = lv_load(p->dx + j), dy = lv_load(p->dy + j), dz = lv_load(p->dz + j);
		lv ocx = lv_sub(lv_load(p->ox + j), lv_set1(c.x));
		lv ocy = lv_sub(lv_load(p->oy + j), lv_set1(c.y));
		lv ocz = lv_sub(lv_load(p->oz + j), lv_set1(c.z));
		lv a = lv_add(lv_add(lv_mul(dx, dx), lv_mul(dy, dy)), lv_mul(dz, dz));
		lv half_b = lv_add(lv_add(lv_mul(ocx, dx), lv_mul(ocy, dy)), lv_mul(ocz, dz));
		lv s = lv_div(lv_neg(half_b), a);
		lv px = lv_add(ocx, lv_mul(dx, s)), py = lv_add(ocy, lv_mul(dy, s));
		lv pz = lv_add(ocz, lv_mul(dz, s));
		lv disc = lv_mul(a, lv_sub(r2, lv_add(lv_add(lv_mul(px, px), lv_mul(py, py)),
						      lv_mul(pz, pz))));
		lv cc = lv_sub(lv_add(lv_add(lv_mul(ocx, ocx), lv_mul(ocy, ocy)), lv_mul(ocz, ocz)),
			       r2);
		/* solve.c returns at disc < 0; a NaN goes on there, to roots
		 * that are NaN and hit nothing. */
		lm negative = lv_lt(disc, zero);
		lv q = lv_neg(lv_add(half_b, lv_copysign(lv_sqrt(lv_sel(negative, zero, disc)), half_b)));
		lv t0 = lv_div(q, a), t1 = lv_div(cc, q);
		lm swap = lv_gt(t0, t1), q0 = lv_eq(q, zero);
		lv lo = lv_sel(q0, zero, lv_sel(swap, t1, t0));
		lv hi = lv_sel(q0, zero, lv_sel(swap, t0, t1));
		lv tn = lv_load(t_min + j), tx = lv_load(t_max + j);
		lm h0 = lm_and(lv_gt(lo, tn), lv_lt(lo, tx));
		lm h1 = lm_and(lv_gt(hi, tn), lv_lt(hi, tx));

		mask |= group_store(t_max, active, j, lm_andnot(negative, lm_or(h0, h1)), lv_sel(h0, lo, hi));
	}
	return mask;
}

static uint32_t SOLVE_LANES(triangle)(const struct ray_packet *p, uint32_t active,
				      struct vec3 v0, struct vec3 e1, struct vec3 e2,
				      const double *t_min, double *t_max)
{
	const lv zero = lv_set1(0.0), one = lv_set1(1.0);
	const lv e1x = lv_set1(e1.x), e1y = lv_set1(e1.y), e1z = lv_set1(e1.z);
	const lv e2x = lv_set1(e2.x), e2y = lv_set1(e2.y), e2z = lv_set1(e2.z);
	uint32_t mask = 0;
	int j;

	FOR_GROUPS(active, j) {
		lv dx = lv_load(p->dx + j), dy = lv_load(p->dy + j), dz = lv_load(p->dz + j);
		/* pvec = dir x e2, det = e1 . pvec */
		lv pvx = lv_sub(lv_mul(dy, e2z), lv_mul(dz, e2y));
		lv pvy = lv_sub(lv_mul(dz, e2x), lv_mul(dx, e2z));
		lv pvz = lv_sub(lv_mul(dx, e2y), lv_mul(dy, e2x));
		lv det = lv_add(lv_add(lv_mul(e1x, pvx), lv_mul(e1y, pvy)), lv_mul(e1z, pvz));
		lv inv = lv_div(one, det);
		lv tvx = lv_sub(lv_load(p->ox + j), lv_set1(v0.x));
		lv tvy = lv_sub(lv_load(p->oy + j), lv_set1(v0.y));
		lv tvz = lv_sub(lv_load(p->oz + j), lv_set1(v0.z));
		lv u = lv_mul(lv_add(lv_add(lv_mul(tvx, pvx), lv_mul(tvy, pvy)), lv_mul(tvz, pvz)),
			      inv);
		/* qvec = tvec x e1 */
		lv qvx = lv_sub(lv_mul(tvy, e1z), lv_mul(tvz, e1y));
		lv qvy = lv_sub(lv_mul(tvz, e1x), lv_mul(tvx, e1z));
		lv qvz = lv_sub(lv_mul(tvx, e1y), lv_mul(tvy, e1x));
		lv v = lv_mul(lv_add(lv_add(lv_mul(dx, qvx), lv_mul(dy, qvy)), lv_mul(dz, qvz)), inv);
		lv t = lv_mul(lv_add(lv_add(lv_mul(e2x, qvx), lv_mul(e2y, qvy)), lv_mul(e2z, qvz)),
			      inv);
		lm miss = lm_or(lm_or(lv_eq(det, zero), lm_or(lv_lt(u, zero), lv_gt(u, one))),
				lm_or(lv_lt(v, zero), lv_gt(lv_add(u, v), one)));
		lm in = lm_and(lv_gt(t, lv_load(t_min + j)), lv_lt(t, lv_load(t_max + j)));

		mask |= group_store(t_max, active, j, lm_andnot(miss, in), t);
	}
	return mask;
}

static uint32_t SOLVE_LANES(floor)(const struct ray_packet *p, uint32_t active, int bounded,
				   double half, const double *t_min, double *t_max)
{
	const lv zero = lv_set1(0.0), lo = lv_set1(-half), hi = lv_set1(half);
	uint32_t mask = 0;
	int j;

	FOR_GROUPS(active, j) {
		lv dz = lv_load(p->dz + j);
		lv t = lv_div(lv_neg(lv_load(p->oz + j)), dz);
		lm in = lm_and(lm_and(lv_ne(dz, zero), lv_gt(t, lv_load(t_min + j))),
			       lv_lt(t, lv_load(t_max + j)));

		if (bounded) {
			lv x = lv_add(lv_load(p->ox + j), lv_mul(t, lv_load(p->dx + j)));
			lv y = lv_add(lv_load(p->oy + j), lv_mul(t, lv_load(p->dy + j)));
			lm out = lm_or(lm_or(lv_lt(x, lo), lv_ge(x, hi)), lm_or(lv_lt(y, lo), lv_ge(y, hi)));
			in = lm_andnot(out, in);
		}
		mask |= group_store(t_max, active, j, in, t);
	}
	return mask;
}

/* floor.c's floor_cell_color of cells (floor(cx), floor(cy)), cx = (x +
 * half) / cell where shifted (the square), x / cell otherwise (the
 * infinite plane), and likewise cy: white (1) where i + j is even, black
 * (0) otherwise, into each channel.  h = |i + j| / 2 is a whole number
 * (and finite) exactly when the sum is even: below 2^31, where
 * floor_cell_color takes the sum's low bit, the sum is a whole number
 * held exactly, so the two agree; beyond, it is floor_cell_color's own
 * test. */
static void SOLVE_LANES(floor_cells)(const double *const p[3], uint32_t active, int shifted,
				     double half, double cell, double *const c[3])
{
	const lv hv = lv_set1(half), cv = lv_set1(cell), inf = lv_set1(INFINITY);
	const lv one = lv_set1(1.0), zero = lv_set1(0.0);
	int j;

	FOR_GROUPS(active, j) {
		lv x = lv_load(p[0] + j), y = lv_load(p[1] + j), i, k, h, white;

		if (shifted) {
			x = lv_add(x, hv);
			y = lv_add(y, hv);
		}
		i = lv_floor(lv_div(x, cv));
		k = lv_floor(lv_div(y, cv));
		h = lv_mul(lv_set1(0.5), lv_andnot_bits(lv_set1(-0.0), lv_add(i, k)));
		white = lv_sel(lm_and(lv_eq(h, lv_floor(h)), lv_ne(h, inf)), one, zero);
		lv_store(c[0] + j, white);
		lv_store(c[1] + j, white);
		lv_store(c[2] + j, white);
	}
}

/* sphere.c's normal: (p - centre) inv_radius. */
static void SOLVE_LANES(sphere_normal)(const double *const p[3], uint32_t active,
				       struct vec3 centre, double inv_radius, double *const n[3])
{
	const lv s = lv_set1(inv_radius);
	int j;

	FOR_GROUPS(active, j) {
		lv_store(n[0] + j, lv_mul(lv_sub(lv_load(p[0] + j), lv_set1(centre.x)), s));
		lv_store(n[1] + j, lv_mul(lv_sub(lv_load(p[1] + j), lv_set1(centre.y)), s));
		lv_store(n[2] + j, lv_mul(lv_sub(lv_load(p[2] + j), lv_set1(centre.z)), s));
	}
}
