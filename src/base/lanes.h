/* A vector of doubles, one lane a ray of a packet, in the widest set the
 * including file is compiled for: AVX-512 (eight lanes), AVX2 (four),
 * SSE2 (two) or plain C (one: the portable build).  A kernel written with
 * these operations once is compiled once per set (a file each, with its
 * -m flag), and each lane does the plain C's arithmetic to the bit: the
 * same IEEE operations, no fused multiply-add (the files are compiled
 * with -ffp-contract=off), comparisons with C's meaning (ordered, but !=
 * true for a NaN).  A mask holds a comparison's answer a lane. */
#ifndef RT_LANES_H
#define RT_LANES_H

#include <stdint.h>

#if defined(__AVX512F__) && !defined(ACCEL_PORTABLE)
#include <immintrin.h>

#define LANES_W 8
typedef __m512d lv;
typedef __mmask8 lm;

static inline lv lv_load(const double *p) { return _mm512_loadu_pd(p); }
static inline void lv_store(double *p, lv a) { _mm512_storeu_pd(p, a); }
static inline lv lv_set1(double x) { return _mm512_set1_pd(x); }
static inline lv lv_add(lv a, lv b) { return _mm512_add_pd(a, b); }
static inline lv lv_sub(lv a, lv b) { return _mm512_sub_pd(a, b); }
static inline lv lv_mul(lv a, lv b) { return _mm512_mul_pd(a, b); }
static inline lv lv_div(lv a, lv b) { return _mm512_div_pd(a, b); }
static inline lv lv_sqrt(lv a) { return _mm512_sqrt_pd(a); }
static inline lv lv_floor(lv a)
{
	return _mm512_roundscale_pd(a, _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC);
}
/* a > b ? a : b and a < b ? a : b (b for a NaN): what max and min do */
static inline lv lv_max_first(lv a, lv b) { return _mm512_max_pd(a, b); }
static inline lv lv_min_first(lv a, lv b) { return _mm512_min_pd(a, b); }
static inline lm lv_lt(lv a, lv b) { return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ); }
static inline lm lv_le(lv a, lv b) { return _mm512_cmp_pd_mask(a, b, _CMP_LE_OQ); }
static inline lm lv_gt(lv a, lv b) { return _mm512_cmp_pd_mask(a, b, _CMP_GT_OQ); }
static inline lm lv_ge(lv a, lv b) { return _mm512_cmp_pd_mask(a, b, _CMP_GE_OQ); }
static inline lm lv_eq(lv a, lv b) { return _mm512_cmp_pd_mask(a, b, _CMP_EQ_OQ); }
static inline lm lv_ne(lv a, lv b) { return _mm512_cmp_pd_mask(a, b, _CMP_NEQ_UQ); }
/* m ? a : b, lane by lane */
static inline lv lv_sel(lm m, lv a, lv b) { return _mm512_mask_blend_pd(m, b, a); }
static inline lm lm_and(lm a, lm b) { return (lm)(a & b); }
static inline lm lm_or(lm a, lm b) { return (lm)(a | b); }
static inline lm lm_andnot(lm a, lm b) { return (lm)(~a & b); }	/* !a && b */
static inline unsigned lm_bits(lm m) { return m; }
/* The mask of the low LANES_W bits of b, lane i bit i */
static inline lm lm_from_bits(unsigned b) { return (lm)b; }
static inline lv lv_xor_bits(lv a, lv b)
{
	return _mm512_castsi512_pd(_mm512_xor_si512(_mm512_castpd_si512(a), _mm512_castpd_si512(b)));
}
static inline lv lv_and_bits(lv a, lv b)
{
	return _mm512_castsi512_pd(_mm512_and_si512(_mm512_castpd_si512(a), _mm512_castpd_si512(b)));
}
static inline lv lv_andnot_bits(lv a, lv b)
{
	return _mm512_castsi512_pd(_mm512_andnot_si512(_mm512_castpd_si512(a), _mm512_castpd_si512(b)));
}
static inline lv lv_or_bits(lv a, lv b)
{
	return _mm512_castsi512_pd(_mm512_or_si512(_mm512_castpd_si512(a), _mm512_castpd_si512(b)));
}
#elif defined(__AVX2__) && !defined(ACCEL_PORTABLE)
#include <immintrin.h>

#define LANES_W 4
typedef __m256d lv;
typedef __m256d lm;

static inline lv lv_load(const double *p) { return _mm256_loadu_pd(p); }
static inline void lv_store(double *p, lv a) { _mm256_storeu_pd(p, a); }
static inline lv lv_set1(double x) { return _mm256_set1_pd(x); }
static inline lv lv_add(lv a, lv b) { return _mm256_add_pd(a, b); }
static inline lv lv_sub(lv a, lv b) { return _mm256_sub_pd(a, b); }
static inline lv lv_mul(lv a, lv b) { return _mm256_mul_pd(a, b); }
static inline lv lv_div(lv a, lv b) { return _mm256_div_pd(a, b); }
static inline lv lv_sqrt(lv a) { return _mm256_sqrt_pd(a); }
static inline lv lv_floor(lv a) { return _mm256_floor_pd(a); }
/* a > b ? a : b and a < b ? a : b (b for a NaN): what max and min do */
static inline lv lv_max_first(lv a, lv b) { return _mm256_max_pd(a, b); }
static inline lv lv_min_first(lv a, lv b) { return _mm256_min_pd(a, b); }
static inline lm lv_lt(lv a, lv b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
static inline lm lv_le(lv a, lv b) { return _mm256_cmp_pd(a, b, _CMP_LE_OQ); }
static inline lm lv_gt(lv a, lv b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
static inline lm lv_ge(lv a, lv b) { return _mm256_cmp_pd(a, b, _CMP_GE_OQ); }
static inline lm lv_eq(lv a, lv b) { return _mm256_cmp_pd(a, b, _CMP_EQ_OQ); }
static inline lm lv_ne(lv a, lv b) { return _mm256_cmp_pd(a, b, _CMP_NEQ_UQ); }
static inline lv lv_sel(lm m, lv a, lv b) { return _mm256_blendv_pd(b, a, m); }
static inline lm lm_and(lm a, lm b) { return _mm256_and_pd(a, b); }
static inline lm lm_or(lm a, lm b) { return _mm256_or_pd(a, b); }
static inline lm lm_andnot(lm a, lm b) { return _mm256_andnot_pd(a, b); }
static inline unsigned lm_bits(lm m) { return (unsigned)_mm256_movemask_pd(m); }
static inline lm lm_from_bits(unsigned b)
{
	const __m256i bit = _mm256_set_epi64x(8, 4, 2, 1);

	return _mm256_castsi256_pd(
		_mm256_cmpeq_epi64(_mm256_and_si256(_mm256_set1_epi64x((long long)b), bit), bit));
}
static inline lv lv_xor_bits(lv a, lv b) { return _mm256_xor_pd(a, b); }
static inline lv lv_and_bits(lv a, lv b) { return _mm256_and_pd(a, b); }
static inline lv lv_andnot_bits(lv a, lv b) { return _mm256_andnot_pd(a, b); }
static inline lv lv_or_bits(lv a, lv b) { return _mm256_or_pd(a, b); }
#elif defined(__SSE2__) && !defined(ACCEL_PORTABLE)
#include <emmintrin.h>
#include <math.h>

#define LANES_W 2
typedef __m128d lv;
typedef __m128d lm;

static inline lv lv_load(const double *p) { return _mm_loadu_pd(p); }
static inline void lv_store(double *p, lv a) { _mm_storeu_pd(p, a); }
static inline lv lv_set1(double x) { return _mm_set1_pd(x); }
static inline lv lv_add(lv a, lv b) { return _mm_add_pd(a, b); }
static inline lv lv_sub(lv a, lv b) { return _mm_sub_pd(a, b); }
static inline lv lv_mul(lv a, lv b) { return _mm_mul_pd(a, b); }
static inline lv lv_div(lv a, lv b) { return _mm_div_pd(a, b); }
static inline lv lv_sqrt(lv a) { return _mm_sqrt_pd(a); }
/* SSE2 has no rounding instruction: floor, lane by lane. */
static inline lv lv_floor(lv a)
{
	double v[2];

	_mm_storeu_pd(v, a);
	return _mm_set_pd(floor(v[1]), floor(v[0]));
}
/* a > b ? a : b and a < b ? a : b (b for a NaN): what max and min do */
static inline lv lv_max_first(lv a, lv b) { return _mm_max_pd(a, b); }
static inline lv lv_min_first(lv a, lv b) { return _mm_min_pd(a, b); }
static inline lm lv_lt(lv a, lv b) { return _mm_cmplt_pd(a, b); }
static inline lm lv_le(lv a, lv b) { return _mm_cmple_pd(a, b); }
static inline lm lv_gt(lv a, lv b) { return _mm_cmpgt_pd(a, b); }
static inline lm lv_ge(lv a, lv b) { return _mm_cmpge_pd(a, b); }
static inline lm lv_eq(lv a, lv b) { return _mm_cmpeq_pd(a, b); }
static inline lm lv_ne(lv a, lv b) { return _mm_cmpneq_pd(a, b); }
static inline lv lv_sel(lm m, lv a, lv b) { return _mm_or_pd(_mm_and_pd(m, a), _mm_andnot_pd(m, b)); }
static inline lm lm_and(lm a, lm b) { return _mm_and_pd(a, b); }
static inline lm lm_or(lm a, lm b) { return _mm_or_pd(a, b); }
static inline lm lm_andnot(lm a, lm b) { return _mm_andnot_pd(a, b); }
static inline unsigned lm_bits(lm m) { return (unsigned)_mm_movemask_pd(m); }
static inline lm lm_from_bits(unsigned b)
{
	return _mm_castsi128_pd(_mm_set_epi64x(-(long long)(b >> 1 & 1), -(long long)(b & 1)));
}
static inline lv lv_xor_bits(lv a, lv b) { return _mm_xor_pd(a, b); }
static inline lv lv_and_bits(lv a, lv b) { return _mm_and_pd(a, b); }
static inline lv lv_andnot_bits(lv a, lv b) { return _mm_andnot_pd(a, b); }
static inline lv lv_or_bits(lv a, lv b) { return _mm_or_pd(a, b); }
#else
#include <math.h>
#include <string.h>

#define LANES_W 1
typedef double lv;
typedef int lm;

static inline lv lv_load(const double *p) { return *p; }
static inline void lv_store(double *p, lv a) { *p = a; }
static inline lv lv_set1(double x) { return x; }
static inline lv lv_add(lv a, lv b) { return a + b; }
static inline lv lv_sub(lv a, lv b) { return a - b; }
static inline lv lv_mul(lv a, lv b) { return a * b; }
static inline lv lv_div(lv a, lv b) { return a / b; }
static inline lv lv_sqrt(lv a) { return sqrt(a); }
static inline lv lv_floor(lv a) { return floor(a); }
static inline lv lv_max_first(lv a, lv b) { return a > b ? a : b; }
static inline lv lv_min_first(lv a, lv b) { return a < b ? a : b; }
static inline lm lv_lt(lv a, lv b) { return a < b; }
static inline lm lv_le(lv a, lv b) { return a <= b; }
static inline lm lv_gt(lv a, lv b) { return a > b; }
static inline lm lv_ge(lv a, lv b) { return a >= b; }
static inline lm lv_eq(lv a, lv b) { return a == b; }
static inline lm lv_ne(lv a, lv b) { return a != b; }
static inline lv lv_sel(lm m, lv a, lv b) { return m ? a : b; }
static inline lm lm_and(lm a, lm b) { return a & b; }
static inline lm lm_or(lm a, lm b) { return a | b; }
static inline lm lm_andnot(lm a, lm b) { return !a && b; }
static inline unsigned lm_bits(lm m) { return (unsigned)m; }
static inline lm lm_from_bits(unsigned b) { return (lm)(b & 1); }
static inline lv lv_bits_op(lv a, lv b, int op)
{
	uint64_t x, y;

	memcpy(&x, &a, sizeof(x));
	memcpy(&y, &b, sizeof(y));
	x = op == 0 ? x ^ y : op == 1 ? x & y : op == 2 ? ~x & y : x | y;
	memcpy(&a, &x, sizeof(a));
	return a;
}
static inline lv lv_xor_bits(lv a, lv b) { return lv_bits_op(a, b, 0); }
static inline lv lv_and_bits(lv a, lv b) { return lv_bits_op(a, b, 1); }
static inline lv lv_andnot_bits(lv a, lv b) { return lv_bits_op(a, b, 2); }
static inline lv lv_or_bits(lv a, lv b) { return lv_bits_op(a, b, 3); }
#endif

/* -a (the sign bit flipped, as C's unary minus) */
static inline lv lv_neg(lv a)
{
	return lv_xor_bits(a, lv_set1(-0.0));
}

/* copysign(a, b) */
static inline lv lv_copysign(lv a, lv b)
{
	lv sign = lv_set1(-0.0);

	return lv_or_bits(lv_andnot_bits(sign, a), lv_and_bits(sign, b));
}

#endif
