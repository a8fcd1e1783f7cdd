/* The partition of a node's refs at a split, with the bounds of both
 * parts found in the same pass (with SSE2, each ref kept in registers
 * while it is looked at; the plain C gives the same bits). */
#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel_box.h"

/* Moves the refs whose centre lies below pos along axis to the front and
 * returns how many there are; parts receives the box and the centre
 * bounds of the front part and of the back part.  Each ref met at the
 * front is either kept or swapped with the last unsorted one, which is
 * looked at next. */
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
/* A ref in registers: its bounds as three pairs and its shape. */
struct ref_regs {
	__m128d lo01, lo2hi0, hi12;
	size_t index;
};

static inline struct ref_regs ref_load(const struct build_ref *r)
{
	struct ref_regs v;

	v.lo01 = _mm_loadu_pd(r->lo);
	v.lo2hi0 = _mm_loadu_pd(r->lo + 2);
	v.hi12 = _mm_loadu_pd(r->hi + 1);
	v.index = r->index;
	return v;
}

static inline void ref_store(struct build_ref *r, struct ref_regs v)
{
	_mm_storeu_pd(r->lo, v.lo01);
	_mm_storeu_pd(r->lo + 2, v.lo2hi0);
	_mm_storeu_pd(r->hi + 1, v.hi12);
	r->index = v.index;
}

/* One side's box and centre bounds, in registers. */
struct side_regs {
	__m128d lo01, lo2hi0, hi12;	/* the box, laid out as a ref's bounds */
	__m128d clo01, chi01, clo2, chi2;	/* the centres' */
};

static inline void side_empty(struct side_regs *s)
{
	const __m128d inf = _mm_set1_pd(INFINITY), ninf = _mm_set1_pd(-INFINITY);

	s->lo01 = inf;
	s->lo2hi0 = _mm_set_pd(-INFINITY, INFINITY);
	s->hi12 = ninf;
	s->clo01 = s->clo2 = inf;
	s->chi01 = s->chi2 = ninf;
}

/* As bounds_add_ref, operand for operand: the same values to the bit. */
static inline void side_add(struct side_regs *s, struct ref_regs v, __m128d c01, __m128d c2)
{
	s->lo01 = _mm_min_pd(v.lo01, s->lo01);
	s->lo2hi0 = _mm_move_sd(_mm_max_pd(v.lo2hi0, s->lo2hi0), _mm_min_pd(v.lo2hi0, s->lo2hi0));
	s->hi12 = _mm_max_pd(v.hi12, s->hi12);
	s->clo01 = _mm_min_pd(c01, s->clo01);
	s->chi01 = _mm_max_pd(c01, s->chi01);
	s->clo2 = _mm_min_sd(c2, s->clo2);
	s->chi2 = _mm_max_sd(c2, s->chi2);
}

static void side_store(const struct side_regs *s, struct build_box *box, struct build_box *centres)
{
	_mm_storeu_pd(box->lo, s->lo01);
	_mm_storeu_pd(box->lo + 2, s->lo2hi0);
	_mm_storeu_pd(box->hi + 1, s->hi12);
	_mm_storeu_pd(centres->lo, s->clo01);
	_mm_storeu_pd(centres->hi, s->chi01);
	_mm_store_sd(&centres->lo[2], s->clo2);
	_mm_store_sd(&centres->hi[2], s->chi2);
}

/* The ref being looked at stays in registers: one swapped in from the
 * back is never stored and loaded again before its side is known (a
 * 16-byte load of what narrower stores wrote waits for them to reach the
 * cache), and each ref is read once.  The centre along axis is the plain
 * C's (lo + hi) * 0.5, compared with pos as it does. */
size_t accel_partition(struct build_ref *refs, size_t n, int axis, double pos,
		       struct build_parts *parts)
{
	const __m128d half = _mm_set1_pd(0.5), p = _mm_set1_pd(pos);
	struct side_regs left, right;
	struct ref_regs cur;
	size_t i = 0, j = n;

	side_empty(&left);
	side_empty(&right);
	if (n > 0)
		cur = ref_load(&refs[0]);
	while (i < j) {
		__m128d hi01 = _mm_shuffle_pd(cur.lo2hi0, cur.hi12, 1);
		__m128d c01 = _mm_mul_pd(_mm_add_pd(cur.lo01, hi01), half);
		__m128d c2 = _mm_mul_sd(_mm_add_sd(cur.lo2hi0, _mm_unpackhi_pd(cur.hi12, cur.hi12)), half);
		int below = _mm_movemask_pd(_mm_cmplt_pd(c01, p)) |
			    _mm_movemask_pd(_mm_cmplt_sd(c2, p)) << 2;

		if (below >> axis & 1) {
			/* A store where cur came from, unless from the back. */
			side_add(&left, cur, c01, c2);
			ref_store(&refs[i], cur);
			if (++i < j)
				cur = ref_load(&refs[i]);
		} else {
			struct ref_regs next;
			side_add(&right, cur, c01, c2);
			next = ref_load(&refs[--j]);
			ref_store(&refs[j], cur);
			cur = next;
		}
	}
	side_store(&left, &parts->front, &parts->front_centres);
	side_store(&right, &parts->back, &parts->back_centres);
	return i;
}
#else
size_t accel_partition(struct build_ref *refs, size_t n, int axis, double pos,
		       struct build_parts *parts)
{
	size_t i = 0, j = n;

	box_empty(&parts->front);
	box_empty(&parts->front_centres);
	box_empty(&parts->back);
	box_empty(&parts->back_centres);
	while (i < j) {
		if (ref_centre(&refs[i], axis) < pos) {
			bounds_add_ref(&parts->front, &parts->front_centres, &refs[i]);
			i++;
		} else {
			struct build_ref tmp = refs[i];
			bounds_add_ref(&parts->back, &parts->back_centres, &tmp);
			refs[i] = refs[--j];
			refs[j] = tmp;
		}
	}
	return i;
}
#endif
