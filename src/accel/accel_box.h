/* The boxes of the hierarchy's build, inline for its loops: a ref's
 * centre, a box's area, growing a box by a ref or a box (with SSE2 two
 * lanes at a time, to the same bits as the plain C), and the outward
 * rounding of a bound to a float.  Private to the build's files. */
#ifndef RT_ACCEL_BOX_H
#define RT_ACCEL_BOX_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel_build.h"

static inline double ref_centre(const struct build_ref *r, int axis)
{
	return (r->lo[axis] + r->hi[axis]) * 0.5;
}

static inline double box_area(const struct build_box *b)
{
	double ex = b->hi[0] - b->lo[0], ey = b->hi[1] - b->lo[1], ez = b->hi[2] - b->lo[2];

	return 2.0 * (ex * ey + ey * ez + ez * ex);
}

static inline void box_empty(struct build_box *b)
{
	int k;

	for (k = 0; k < 3; k++) {
		b->lo[k] = INFINITY;
		b->hi[k] = -INFINITY;
	}
}

/* The box code copies a ref's or a box's bounds as six doubles in a row. */
typedef char build_ref_bounds_in_a_row[offsetof(struct build_ref, hi) == 3 * sizeof(double) ? 1 : -1];
typedef char build_box_bounds_in_a_row[offsetof(struct build_box, hi) == 3 * sizeof(double) ? 1 : -1];

/* b grows to take in the box that src begins with (a ref or a build_box:
 * its minima then its maxima, six doubles in a row, copied out).  With SSE2 that is three
 * two-lane operations; MINPD and MAXPD give their first operand where the
 * comparison holds and the second otherwise, as the plain C does, so the
 * tree is the same either way. */
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
#include <emmintrin.h>

static inline void box_grow_by(struct build_box *b, const void *src)
{
	double v[6], d[6];
	__m128d lo01, lo2hi0, hi12, b2;

	memcpy(v, src, sizeof(v));
	memcpy(d, b, sizeof(d));
	lo01 = _mm_loadu_pd(v);
	lo2hi0 = _mm_loadu_pd(v + 2);
	hi12 = _mm_loadu_pd(v + 4);
	b2 = _mm_loadu_pd(d + 2);
	_mm_storeu_pd(d, _mm_min_pd(lo01, _mm_loadu_pd(d)));
	_mm_storeu_pd(d + 2, _mm_move_sd(_mm_max_pd(lo2hi0, b2), _mm_min_pd(lo2hi0, b2)));
	_mm_storeu_pd(d + 4, _mm_max_pd(hi12, _mm_loadu_pd(d + 4)));
	memcpy(b, d, sizeof(d));
}
#else
static inline void box_grow_by(struct build_box *b, const void *src)
{
	double v[6];
	const double *lo = v, *hi = v + 3;

	memcpy(v, src, sizeof(v));

	/* Written out per axis: -O2 does not unroll the loop, and its
	 * control was a third of the binning's work. */
	b->lo[0] = lo[0] < b->lo[0] ? lo[0] : b->lo[0];
	b->lo[1] = lo[1] < b->lo[1] ? lo[1] : b->lo[1];
	b->lo[2] = lo[2] < b->lo[2] ? lo[2] : b->lo[2];
	b->hi[0] = hi[0] > b->hi[0] ? hi[0] : b->hi[0];
	b->hi[1] = hi[1] > b->hi[1] ? hi[1] : b->hi[1];
	b->hi[2] = hi[2] > b->hi[2] ? hi[2] : b->hi[2];
}
#endif

static inline void box_grow_ref(struct build_box *b, const struct build_ref *r)
{
	box_grow_by(b, r);
}

static inline void box_grow(struct build_box *b, const struct build_box *o)
{
	box_grow_by(b, o);
}

/* v rounded down (or up) to a float: the nearest float, stepped one bit
 * pattern towards -inf (or +inf) when it lies on the wrong side of v, as
 * nextafterf would (a library call, and these run twelve times a node).
 * Floats of one sign are ordered by their patterns' magnitude; a zero
 * steps to the smallest subnormal of the side, an infinity to the largest
 * finite float.  Written with masks, not branches: whether the nearest
 * float lies above v is a coin toss, and mispredicting it was most of
 * the cost. */
static inline float float_down(double v)
{
	float f = (float)v;
	uint32_t u, stepped;

	memcpy(&u, &f, sizeof(u));
	stepped = (u & 0x7fffffffu) == 0 ? 0x80000001u : u + ((u >> 31) << 1) - 1u;
	u ^= (u ^ stepped) & -(uint32_t)((double)f > v);
	memcpy(&f, &u, sizeof(f));
	return f;
}

static inline float float_up(double v)
{
	float f = (float)v;
	uint32_t u, stepped;

	memcpy(&u, &f, sizeof(u));
	stepped = (u & 0x7fffffffu) == 0 ? 0x00000001u : u + 1u - ((u >> 31) << 1);
	u ^= (u ^ stepped) & -(uint32_t)((double)f < v);
	memcpy(&f, &u, sizeof(f));
	return f;
}

/* box and centres grow to take in ref r and its centre. */
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
/* The centres two lanes at a time: MINPD (c, lo) is the plain C's
 * c < lo ? c : lo, MAXPD (c, hi) its c > hi ? c : hi. */
static inline void bounds_add_ref(struct build_box *box, struct build_box *centres,
				  const struct build_ref *r)
{
	const __m128d half = _mm_set1_pd(0.5);
	__m128d lo01 = _mm_loadu_pd(r->lo), hi01 = _mm_loadu_pd(r->hi);
	__m128d c01 = _mm_mul_pd(_mm_add_pd(lo01, hi01), half);
	__m128d c2 = _mm_mul_sd(_mm_add_sd(_mm_load_sd(&r->lo[2]), _mm_load_sd(&r->hi[2])), half);

	box_grow_ref(box, r);
	_mm_storeu_pd(centres->lo, _mm_min_pd(c01, _mm_loadu_pd(centres->lo)));
	_mm_storeu_pd(centres->hi, _mm_max_pd(c01, _mm_loadu_pd(centres->hi)));
	_mm_store_sd(&centres->lo[2], _mm_min_sd(c2, _mm_load_sd(&centres->lo[2])));
	_mm_store_sd(&centres->hi[2], _mm_max_sd(c2, _mm_load_sd(&centres->hi[2])));
}
#else
static inline void bounds_add_ref(struct build_box *box, struct build_box *centres,
				  const struct build_ref *r)
{
	int k;

	box_grow_ref(box, r);
	for (k = 0; k < 3; k++) {
		double c = ref_centre(r, k);
		centres->lo[k] = c < centres->lo[k] ? c : centres->lo[k];
		centres->hi[k] = c > centres->hi[k] ? c : centres->hi[k];
	}
}
#endif

#endif
