/* The small formulas of the Whitted sum that shade.c (every render, and
 * the renders with a rule broken for whitted compare) and the packets'
 * lanes share, inline so that the per-ray path calls nothing. */
#ifndef RT_SHADE_MATH_H
#define RT_SHADE_MATH_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
#include <emmintrin.h>
#endif

#include "whitted/material.h"
#include "whitted/render.h"
#include "whitted/vec3.h"

/* The offset for rays leaving a surface at p: relative to the size of the
 * coordinates, so that it stays above their rounding error (no acne) and
 * far below anything visible (no leaks). */
static inline double render_offset(struct vec3 p)
{
	/* Comparisons rather than fmax, which is a library call here; the
	 * same value for every non-NaN coordinate. */
	double m = 1.0, ax = fabs(p.x), ay = fabs(p.y), az = fabs(p.z);

	m = ax > m ? ax : m;
	m = ay > m ? ay : m;
	m = az > m ? az : m;
	return RT_EPSILON * m;
}

/* rl^shininess.  pow is exact for an exponent of 1 (the floor's), so that
 * common case skips the call without changing a bit. */
static inline double render_specular_power(double rl, double shininess)
{
	return shininess == 1.0 ? rl : pow(rl, shininess);
}

/* color_clamp01(v) without its two branches, which a picture's colours
 * leave to chance: MAXSD(v, 0) is v > 0 ? v : 0 and MINSD(1, m) is
 * 1 < m ? 1 : m, to the bit (the second operand wins ties and NaNs), so
 * NaN and -0 become +0 as there.  The plain C twin is color_clamp01. */
static inline double render_clamp01(double v)
{
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
	__m128d m = _mm_max_sd(_mm_set_sd(v), _mm_setzero_pd());

	return _mm_cvtsd_f64(_mm_min_sd(_mm_set_sd(1.0), m));
#else
	return color_clamp01(v);
#endif
}

static inline struct color render_clamp(struct color c)
{
	return color_make(render_clamp01(c.r), render_clamp01(c.g), render_clamp01(c.b));
}

/* lround(255 c) for c in [0, 1], without the library call or a
 * comparison: with v = 255 c = i + f (i whole, f in [0, 1)), v + v is
 * exact and its whole part is 2 i + (f >= 1/2), so adding 1 and halving
 * gives i + (f >= 1/2), which rounds half away from zero as lround does.
 * (NaN was made 0 by the clamp, as lround's result cast to a byte would
 * be.) */
static inline uint8_t render_channel(double c)
{
	double v = 255.0 * c;

	return (uint8_t)(((int)(v + v) + 1) >> 1);
}

/* render_color_to_rgb8, inline for the block loops. */
static inline void render_rgb8(struct color c, uint8_t out[3])
{
	c = render_clamp(c);
	out[0] = render_channel(c.r);
	out[1] = render_channel(c.g);
	out[2] = render_channel(c.b);
}

/* The refracted direction of unit d through a surface of unit normal n
 * facing the ray (d.n = dn <= 0), eta = n1 / n2 (Snell: n1 sin i = n2
 * sin t): t = eta d + (eta cos i - cos t) n with cos i = -dn and cos t =
 * sqrt(1 - eta^2 (1 - cos^2 i)).  False for total internal reflection
 * (the root's argument < 0). */
static inline bool render_refract(struct vec3 d, struct vec3 n, double dn, double eta,
				  struct vec3 *t)
{
	double cos_i = -dn, k = 1.0 - eta * eta * (1.0 - cos_i * cos_i);

	if (k < 0.0)
		return false;
	*t = vec3_normalize(vec3_add(vec3_scale(d, eta), vec3_scale(n, eta * cos_i - sqrt(k))));
	return true;
}

#endif
