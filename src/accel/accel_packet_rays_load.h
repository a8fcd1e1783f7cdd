/* The first half of accel_packet_rays.h's template, included by it: a
 * packet's rays as its box tests take them (struct packet_rays), loaded
 * and prepared, in doubles, or with AVX-512 in floats where those hold
 * every lane.  Like that file it is included once per set of
 * instructions, with RAYS_WALK, RAYS_NODE and LANES defined. */
#ifndef RT_ACCEL_PACKET_RAYS_COMMON
#define RT_ACCEL_PACKET_RAYS_COMMON
/* The packet's rays as the box tests take them, every lane filled: the
 * double tests' reciprocal directions, or where the AVX-512 walk's float
 * tests hold every lane tested (floats), those tests' own values
 * (accel_float_box.h) and the lanes whose axis k has its maximum as the
 * near plane. */
struct packet_rays {
	struct packet_shape_rays s;
	double inv[3][LANES];
	bool floats;
	float of[3][LANES], invf[3][LANES], errf[LANES], t_minf[LANES];
	uint32_t far_first[3];
};
#endif

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE) && ACCEL_PACKET == 16
#define RAYS_FLOATS 1
#ifndef RT_ACCEL_PACKET_RAYS_FLOATS16
#define RT_ACCEL_PACKET_RAYS_FLOATS16
/* float_box_ray's limits lowered to floats: 2^99 < 1e30, 2^122 < 1e37. */
#define RAYS_COORD_MAX 0x1p99f
#define RAYS_T_MIN_MAX 0x1p122f
/* Sixteen doubles to the nearest floats, by the processor's conversion
 * (which takes a finite value beyond the floats' range to +-inf). */
static inline __m512 rays_floats16(const double *v)
{
	__m256 lo = _mm512_cvtpd_ps(_mm512_loadu_pd(v)), hi = _mm512_cvtpd_ps(_mm512_loadu_pd(v + 8));

	return _mm512_castpd_ps(_mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_castps_pd(lo)),
						   _mm256_castps_pd(hi), 1));
}
#endif
#else
#define RAYS_FLOATS 0
#endif

/* The reciprocal directions of the double tests. */
static inline void RAYS_WALK(prepare_doubles)(struct packet_rays *v)
{
	const lv one = lv_set1(1.0), zero = lv_set1(0.0);
	int j;

	/* As ray_slab_init: + 0.0 makes -0 take the minimum as its near
	 * plane. */
	for (j = 0; j < LANES; j += LANES_W) {
		lv_store(v->inv[0] + j, lv_div(one, lv_add(lv_load(v->s.p.dx + j), zero)));
		lv_store(v->inv[1] + j, lv_div(one, lv_add(lv_load(v->s.p.dy + j), zero)));
		lv_store(v->inv[2] + j, lv_div(one, lv_add(lv_load(v->s.p.dz + j), zero)));
	}
}

#if RAYS_FLOATS
/* The float tests' values, all sixteen lanes at once, where float_box_ray
 * holds for every lane of `active` (else false, and the double tests
 * take the packet): o and t_min to the nearest float, inv the inverse of
 * d rounded to a float (within 2u of 1 / d: accel_float_box.h), e from
 * those in float (at least 4u |o inv| (1 - 5u), as the bound wants).
 * float_box_ray's limits are checked on the rounded values, which is
 * what costs nothing here: rounding to nearest keeps order, so a rounded
 * value strictly inside a limit that is itself a float (ACCEL_COORD_MAX
 * and FLOAT_BOX_T_MIN_MAX lowered to one) comes from a double inside it
 * too.  A value on a limit goes to the doubles, as do the lanes whose t_min
 * rounds to a zero with its sign bit set.  A direction's coordinate that
 * rounds to 0 is looked at in double: float_box_ray wants it exactly 0.
 * (Checking the doubles before rounding them took 3.5% of the course
 * example's render.) */
static inline bool RAYS_WALK(prepare_floats)(struct packet_rays *v, uint32_t active)
{
	const __m512 zero = _mm512_setzero_ps(), one = _mm512_set1_ps(1.0f);
	const __m512 inf = _mm512_set1_ps(INFINITY);
	const double *o_of[3] = { v->s.p.ox, v->s.p.oy, v->s.p.oz };
	const double *d_of[3] = { v->s.p.dx, v->s.p.dy, v->s.p.dz };
	const __m512 t = rays_floats16(v->s.t_min);
	__m512 o[3], d[3], e = zero;
	__mmask16 hold, zeros[3];
	int k;

	hold = _mm512_cmp_epi32_mask(_mm512_castps_si512(t), _mm512_setzero_si512(), _MM_CMPINT_NLT) &
	       _mm512_cmp_ps_mask(t, _mm512_set1_ps(RAYS_T_MIN_MAX), _CMP_LT_OQ);
	for (k = 0; k < 3; k++) {
		__m512 ad;

		o[k] = rays_floats16(o_of[k]);
		d[k] = rays_floats16(d_of[k]);
		ad = _mm512_abs_ps(d[k]);
		zeros[k] = _mm512_cmp_ps_mask(d[k], zero, _CMP_EQ_OQ);
		hold &= _mm512_cmp_ps_mask(_mm512_abs_ps(o[k]), _mm512_set1_ps(RAYS_COORD_MAX),
					   _CMP_LT_OQ) &
			_mm512_cmp_ps_mask(ad, _mm512_set1_ps((float)FLOAT_BOX_DIR_MAX), _CMP_LT_OQ) &
			(_mm512_cmp_ps_mask(ad, _mm512_set1_ps((float)FLOAT_BOX_DIR_MIN), _CMP_GT_OQ) |
			 zeros[k]);
	}
	if ((hold & active) != active)
		return false;
	for (k = 0; k < 3; k++) {
		uint32_t m;

		for (m = zeros[k] & active; m; m &= m - 1)
			if (d_of[k][__builtin_ctz(m)] != 0.0)
				return false;
	}
	for (k = 0; k < 3; k++) {
		__m512 inv = _mm512_div_ps(one, _mm512_add_ps(d[k], zero));
		__m512 oi = _mm512_abs_ps(_mm512_mul_ps(o[k], inv));
		__mmask16 finite = _mm512_cmp_ps_mask(_mm512_abs_ps(inv), inf, _CMP_NEQ_UQ);

		_mm512_storeu_ps(v->of[k], o[k]);
		_mm512_storeu_ps(v->invf[k], inv);
		v->far_first[k] = _mm512_cmp_ps_mask(inv, zero, _CMP_LT_OQ);
		e = _mm512_mask_blend_ps(finite & _mm512_cmp_ps_mask(oi, e, _CMP_GT_OQ), e, oi);
	}
	e = _mm512_mul_ps(_mm512_mul_ps(e, _mm512_set1_ps((float)FLOAT_BOX_ABS)),
			  _mm512_set1_ps(1.0f + 0x1p-20f));
	e = _mm512_max_ps(e, _mm512_set1_ps((float)FLOAT_BOX_ERR_MIN));
	_mm512_storeu_ps(v->errf, e);
	_mm512_storeu_ps(v->t_minf, t);
	return true;
}
#endif

/* What the box tests need of v's rays besides the shapes' (filled), for
 * the lanes of `active`: the float tests' values where they hold those
 * lanes, else the double tests'. */
static inline void RAYS_WALK(prepare)(struct packet_rays *v, uint32_t active)
{
	(void)active;
#if RAYS_FLOATS
	v->floats = RAYS_WALK(prepare_floats)(v, active);
	if (v->floats)
		return;
#endif
	v->floats = false;
	RAYS_WALK(prepare_doubles)(v);
}

static inline void RAYS_WALK(load)(struct packet_rays *v, const struct ray *r, int n,
				   const double *t_min)
{
	packet_shape_rays_load(&v->s, r, n, t_min);
	RAYS_WALK(prepare)(v, packet_all(n));
}
