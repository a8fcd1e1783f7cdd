/* The float box tests of the AVX-512 walks (walk_avx512.h, and the
 * small trees' packets in accel_packet_rays.h): which rays they can
 * bound, and by how much they widen.  Private to src/accel/.
 *
 * The float test is (b - o) * inv for the plane b, each operand and
 * result rounded to a float: with u = 2^-24, o off by at most u |o| and
 * inv within 2u of 1 / d (the nearest float of the double inverse, or
 * the float inverse of d's nearest float), so the slab distance T =
 * (b - o) inv comes out within 4u |T| + u |o inv| (to first order; the
 * double test's own error is 2^-52 |T|).  The single-ray walk takes it
 * as one multiply-add, b inv - p with p = o inv rounded once: with the
 * multiply-add's one rounding, within 3u |T| + 2u |o inv|, inside the
 * same widening; that needs inv finite (b inf - o inf is NaN), so a ray
 * along an axis takes the double walk there.  The walks widen each interval
 * [lo, hi] to [lo (1 - 8u) - e, hi (1 + 8u) + e] with e at least
 * 4u (1 - 5u) max |o inv| over the axes: the interval then holds the
 * double test's with 3u |T| to spare, the widening's own rounding
 * included.  (lo is at least t_min >= 0, so the product
 * lowers it; hi below 0 is at most the error below it where the double
 * test enters, which e then covers.)  An axis along which the ray does
 * not move (inv infinite) has no error to bound: its distances are +-inf
 * as in doubles, or NaN (constraining nothing) where the origin rounded
 * onto the plane, and an end at +-inf stays there.  The bound needs every
 * distance finite in float: box coordinates and the origin's of at most
 * ACCEL_COORD_MAX (1e30) and |inv| of at most 2^24 make |b - o| |inv| at
 * most 3.4e37, and t_min must be at most 1e37.  Relative errors need
 * normal floats: below 2^-126 a rounding is off by up to 2^-150 however
 * small the value (an origin's coordinate, t_min, a product), so e is at
 * least 2^-100 (whose widening is far below any distance the renderer
 * meets: its t_min is at least 1e-6), and |d| is at most 2^64, so that
 * inv stays a normal float.  Other rays (float_box_ray false: a far
 * origin, a direction nearly but not quite parallel to an axis or too
 * long, a NaN, a t_min below 0) are tested in doubles, as the other walks
 * test them, to the bit.  tests/unit/accel/test_accel_float_box.c holds
 * the bound to random boxes and rays. */
#ifndef RT_ACCEL_FLOAT_BOX_H
#define RT_ACCEL_FLOAT_BOX_H

#include <math.h>
#include <stdbool.h>

#include "accel/accel_build.h"
#include "whitted/ray.h"

#define FLOAT_BOX_REL 0x1p-21f		/* 8u */
#define FLOAT_BOX_ABS 0x1p-22		/* 4u */
#define FLOAT_BOX_DIR_MIN 0x1p-24	/* |inv| at most 2^24 */
#define FLOAT_BOX_DIR_MAX 0x1p64	/* inv a normal float */
#define FLOAT_BOX_ERR_MIN 0x1p-100	/* e's floor, over the subnormals' rounding */
#define FLOAT_BOX_T_MIN_MAX 1e37

/* Whether the float tests can bound ray r from t_min on. */
static inline bool float_box_ray(const struct ray *r, double t_min)
{
	const double o[3] = { r->origin.x, r->origin.y, r->origin.z };
	const double d[3] = { r->dir.x, r->dir.y, r->dir.z };
	int k;

	if (!(t_min >= 0.0 && t_min <= FLOAT_BOX_T_MIN_MAX))
		return false;
	for (k = 0; k < 3; k++)
		if (!(fabs(o[k]) <= ACCEL_COORD_MAX) || !(fabs(d[k]) <= FLOAT_BOX_DIR_MAX) ||
		    !(d[k] == 0.0 || fabs(d[k]) >= FLOAT_BOX_DIR_MIN))
			return false;
	return true;
}

/* e of a ray, from its origin and reciprocal direction, rounded up (and
 * then some) on its way to a float by the caller. */
static inline double float_box_err(const double o[3], const double inv[3])
{
	double e = 0.0;
	int k;

	for (k = 0; k < 3; k++)
		if (inv[k] != INFINITY && inv[k] != -INFINITY && fabs(o[k] * inv[k]) > e)
			e = fabs(o[k] * inv[k]);
	e = e * FLOAT_BOX_ABS * (1.0 + 0x1p-20);
	return e > FLOAT_BOX_ERR_MIN ? e : FLOAT_BOX_ERR_MIN;
}

#endif
