/* Where the hierarchy's build splits a node: a 16-bin surface area
 * heuristic over the refs' centres (binned SAH: Wald, "On fast
 * Construction of SAH-based Bounding Volume Hierarchies", IEEE Symposium
 * on Interactive Ray Tracing 2007), a median split past the depth where
 * the heuristic stops, and the outward rounding of boxes to the floats
 * that nodes store.  The partition a split implies is accel_partition.c;
 * the boxes' arithmetic, accel_box.h. */
#include <assert.h>
#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel_box.h"

void accel_refs_bounds_grow(const struct build_ref *refs, size_t n, struct build_box *box,
			    struct build_box *centres)
{
	size_t i;

	for (i = 0; i < n; i++)
		bounds_add_ref(box, centres, &refs[i]);
}

void accel_boxes_grow(struct build_box *box, struct build_box *centres, const struct build_box *o_box,
		      const struct build_box *o_centres)
{
	box_grow(box, o_box);
	box_grow(centres, o_centres);
}

void accel_refs_bounds(const struct build_ref *refs, size_t n, struct build_box *box,
			struct build_box *centres)
{
	box_empty(box);
	box_empty(centres);
	accel_refs_bounds_grow(refs, n, box, centres);
}


/* Clamps before converting: with coordinates near DBL_MAX a centre or the
 * extent can overflow to inf and the product be NaN, and converting that
 * (or anything outside int) is undefined.  The SSE2 binning's clamp
 * (MAXPD with 0, MINPD with the last bin, truncation) gives the same
 * number for every f. */
static inline int bin_of(double c, double lo, double scale)
{
	double f = (c - lo) * scale;

	if (!(f >= 0.0))
		return 0;
	return f >= ACCEL_BINS ? ACCEL_BINS - 1 : (int)f;
}

/* Counts refs[0, n) into the (empty) bins of the usable axes, grows each
 * bin's box by its refs and sets used[axis]'s bit b for each bin b filled.
 * A bin's box is set by its first ref (the same as growing an empty box by
 * it). */
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
/* A ref's bounds (three pairs) grow a bin's box; the bins are 64 bytes
 * apart, so a bin's address is one shift from its number. */
static inline void bin_add(struct sah_bin *bin, __m128d a, __m128d m, __m128d h)
{
	double *d = bin->box.lo;
	__m128d dm = _mm_loadu_pd(d + 2);

	bin->n++;
	_mm_storeu_pd(d, _mm_min_pd(a, _mm_loadu_pd(d)));
	_mm_storeu_pd(d + 2, _mm_move_sd(_mm_max_pd(m, dm), _mm_min_pd(m, dm)));
	_mm_storeu_pd(d + 4, _mm_max_pd(h, _mm_loadu_pd(d + 4)));
}

/* The same bins, with each ref's bounds loaded once for all three axes,
 * its three centres and bin numbers computed two lanes at a time, and
 * each bin an empty box so that every ref grows its bin alike (MINPD
 * of a finite bound and +inf is the bound, as the plain C's copy; the
 * bins come empty, see struct accel_bins).  The
 * clamp is bin_of's: MAXPD with 0 gives 0 for a NaN (its second operand)
 * and for anything below, MINPD with the last bin's number caps it; an
 * axis that is not usable (its scale 0) fills its bin 0, which nothing
 * reads.  The bins in use are marked as the refs fill them (track) or, for
 * a big node, found from the counts afterwards. */
static inline void bin_run(struct sah_bin bins[3][ACCEL_BINS], const struct build_ref *refs,
			   size_t n, const struct build_box *centres, const double scale[3],
			   unsigned used[3], bool track)
{
	const __m128d half = _mm_set1_pd(0.5), zero = _mm_setzero_pd();
	const __m128d last = _mm_set1_pd(ACCEL_BINS - 1);
	const __m128d lo01 = _mm_loadu_pd(centres->lo), lo2 = _mm_set_sd(centres->lo[2]);
	const __m128d sc01 = _mm_loadu_pd(scale), sc2 = _mm_set_sd(scale[2]);
	unsigned used0 = 0, used1 = 0, used2 = 0;
	size_t i;

	for (i = 0; i < n; i++) {
		const double *r = refs[i].lo;
		__m128d a = _mm_loadu_pd(r), m = _mm_loadu_pd(r + 2), h = _mm_loadu_pd(r + 4);
		__m128d c01 = _mm_mul_pd(_mm_add_pd(a, _mm_loadu_pd(r + 3)), half);
		__m128d c2 = _mm_mul_sd(_mm_add_sd(m, _mm_unpackhi_pd(h, h)), half);
		__m128d f01 = _mm_mul_pd(_mm_sub_pd(c01, lo01), sc01);
		__m128d f2 = _mm_mul_sd(_mm_sub_sd(c2, lo2), sc2);
		__m128i k01 = _mm_cvttpd_epi32(_mm_min_pd(_mm_max_pd(f01, zero), last));
		__m128i k2 = _mm_cvttpd_epi32(_mm_min_sd(_mm_max_sd(f2, zero), last));
		unsigned b0 = (unsigned)_mm_cvtsi128_si32(k01);
		unsigned b1 = (unsigned)_mm_cvtsi128_si32(_mm_srli_si128(k01, 4));
		unsigned b2 = (unsigned)_mm_cvtsi128_si32(k2);

		if (track) {
			used0 |= 1u << b0;
			used1 |= 1u << b1;
			used2 |= 1u << b2;
		}
		bin_add(&bins[0][b0], a, m, h);
		bin_add(&bins[1][b1], a, m, h);
		bin_add(&bins[2][b2], a, m, h);
	}
	used[0] = used0;
	used[1] = used1;
	used[2] = used2;
}

/* A node of many refs fills most bins: its bins in use are found from
 * their counts afterwards rather than marked ref by ref. */
#define BIN_MARK_MAX 64

static void bin_refs(struct sah_bin bins[3][ACCEL_BINS], const struct build_ref *refs, size_t n,
		     const struct build_box *centres, const double scale[3], const bool usable[3],
		     unsigned used[3])
{
	int axis, b;

	(void)usable;
	if (n <= BIN_MARK_MAX) {
		bin_run(bins, refs, n, centres, scale, used, true);
		return;
	}
	bin_run(bins, refs, n, centres, scale, used, false);
	for (axis = 0; axis < 3; axis++)
		for (b = 0; b < ACCEL_BINS; b++)
			used[axis] |= (unsigned)(bins[axis][b].n > 0) << b;
}
#else
static void bin_refs(struct sah_bin bins[3][ACCEL_BINS], const struct build_ref *refs, size_t n,
		     const struct build_box *centres, const double scale[3], const bool usable[3],
		     unsigned used[3])
{
	size_t i;
	int axis, b;

	for (i = 0; i < n; i++) {
		for (axis = 0; axis < 3; axis++) {
			struct sah_bin *bin;
			if (!usable[axis])
				continue;
			bin = &bins[axis][bin_of(ref_centre(&refs[i], axis), centres->lo[axis], scale[axis])];
			if (bin->n++ == 0)
				memcpy(&bin->box, &refs[i], sizeof(bin->box));
			else
				box_grow_ref(&bin->box, &refs[i]);
		}
	}
	for (axis = 0; axis < 3; axis++) {
		used[axis] = 0;
		for (b = 0; b < ACCEL_BINS; b++)
			if (bins[axis][b].n > 0)
				used[axis] |= 1u << b;
	}
}
#endif

/* The number of the lowest bit set in m (not 0). */
static inline int lowest_bit(unsigned m)
{
#if defined(__GNUC__)
	return __builtin_ctz(m);
#else
	int b = 0;

	while (!(m & 1u)) {
		m >>= 1;
		b++;
	}
	return b;
#endif
}

/* The best cut between the bins of one axis (lo and scale place the bins
 * along it): when one costs less than *best, sets *best and the cut's
 * position and returns true. */
static inline bool sah_sweep(const struct sah_bin bins[ACCEL_BINS], unsigned used_bins,
			     double lo, double scale, double *best, double *out_pos)
{
	struct build_box left, acc;
	double right_area[ACCEL_BINS], right_n[ACCEL_BINS], left_n = 0.0, least = *best;
	int used[ACCEL_BINS], n_used = 0, j, cut = -1;

	/* Only the bins that hold refs matter (most bins of the many small
	 * nodes are empty): a cut after an empty bin makes the same halves at
	 * the same cost as the cut after the last bin before it that holds
	 * refs, which comes first and wins. */
	for (; used_bins; used_bins &= used_bins - 1)
		used[n_used++] = lowest_bit(used_bins);
	if (n_used < 2)
		return false;
	/* Sweep from the right for the right-hand areas and counts of the
	 * cuts after used[0 .. n_used - 2], then from the left.  The counts
	 * are summed as doubles, which hold them exactly; the best cut is
	 * kept in locals and its position worked out once. */
	acc = bins[used[n_used - 1]].box;
	right_n[n_used - 2] = (double)bins[used[n_used - 1]].n;
	right_area[n_used - 2] = box_area(&acc);
	for (j = n_used - 2; j > 0; j--) {
		box_grow(&acc, &bins[used[j]].box);
		right_n[j - 1] = right_n[j] + (double)bins[used[j]].n;
		right_area[j - 1] = box_area(&acc);
	}
	left = bins[used[0]].box;
	for (j = 0; j < n_used - 1; j++) {
		double cost;
		if (j > 0)
			box_grow(&left, &bins[used[j]].box);
		left_n += (double)bins[used[j]].n;
		cost = left_n * box_area(&left) + right_n[j] * right_area[j];
		if (cost < least) {
			least = cost;
			cut = j;
		}
	}
	if (cut < 0)
		return false;
	*best = least;
	*out_pos = lo + (used[cut] + 1) / scale;
	return true;
}

/* Chooses an axis and a bin boundary by the surface area heuristic: the
 * cost of a split, relative to its parent's, is n_left area_left +
 * n_right area_right (a traversal step is cheap next to a shape test, so
 * it is left out), against n area for a leaf.  All three axes are binned
 * in one pass over the refs.  Returns false when no split beats a leaf
 * (or none is possible). */
static bool sah_split(const struct build_ref *refs, size_t n, const struct build_box *box,
		      const struct build_box *centres, struct sah_bin bins[3][ACCEL_BINS],
		      int *out_axis, double *out_pos)
{
	double best = (double)n * box_area(box), scale[3];
	bool found = false, usable[3];
	unsigned used[3];
	int axis, b;

	for (axis = 0; axis < 3; axis++) {
		double extent = centres->hi[axis] - centres->lo[axis];
		usable[axis] = extent > 0.0;
		scale[axis] = usable[axis] ? ACCEL_BINS / extent : 0.0;
	}
	bin_refs(bins, refs, n, centres, scale, usable, used);
	for (axis = 0; axis < 3; axis++) {
		if (usable[axis] && sah_sweep(bins[axis], used[axis], centres->lo[axis], scale[axis], &best, out_pos)) {
			found = true;
			*out_axis = axis;
		}
	}
	/* Empty again for the next search. */
	for (axis = 0; axis < 3; axis++) {
		for (; used[axis]; used[axis] &= used[axis] - 1) {
			b = lowest_bit(used[axis]);
			box_empty(&bins[axis][b].box);
			bins[axis][b].n = 0;
		}
	}
	return found;
}

/* Orders refs by their centre along one axis, for the median split. */
static int compare_centre_x(const void *a, const void *b)
{
	double ca = ref_centre(a, 0), cb = ref_centre(b, 0);
	return (ca > cb) - (ca < cb);
}

static int compare_centre_y(const void *a, const void *b)
{
	double ca = ref_centre(a, 1), cb = ref_centre(b, 1);
	return (ca > cb) - (ca < cb);
}

static int compare_centre_z(const void *a, const void *b)
{
	double ca = ref_centre(a, 2), cb = ref_centre(b, 2);
	return (ca > cb) - (ca < cb);
}

/* Splits at the median along the widest centre axis, for when the
 * heuristic gives up on a node that is still too big or the tree is
 * already deep (rare, so a sort is cheap enough). */
static size_t median_split(struct build_ref *refs, size_t n, const struct build_box *centres)
{
	static int (*const compare[3])(const void *, const void *) = {
		compare_centre_x, compare_centre_y, compare_centre_z
	};
	double ex = centres->hi[0] - centres->lo[0], ey = centres->hi[1] - centres->lo[1];
	double ez = centres->hi[2] - centres->lo[2];
	int axis = ex >= ey && ex >= ez ? 0 : ey >= ez ? 1 : 2;

	qsort(refs, n, sizeof(*refs), compare[axis]);
	return n / 2;
}
void accel_bins_init(struct accel_bins *bins)
{
	int axis, b;

	for (axis = 0; axis < 3; axis++) {
		for (b = 0; b < ACCEL_BINS; b++) {
			box_empty(&bins->bin[axis][b].box);
			bins->bin[axis][b].n = 0;
		}
	}
}

void accel_set_child_box(struct bvh_node *node, int c, const struct build_box *box)
{
	int k;

	for (k = 0; k < 3; k++) {
		node->bounds[0][k][c] = float_down(box->lo[k]);
		node->bounds[1][k][c] = float_up(box->hi[k]);
	}
}
/* Where to split refs[0, n), whose box and centre bounds are
 * given (sorting them so), or 0 to make them a leaf; parts receives the
 * box and centre bounds of both parts. */
/* The box a bin holding only ref r has, as the binning makes it. */
static inline void bin_box_of(struct build_box *b, const struct build_ref *r)
{
#if defined(__SSE2__) && !defined(ACCEL_PORTABLE)
	box_empty(b);
	box_grow_ref(b, r);
#else
	memcpy(b, r, sizeof(*b));
#endif
}

/* sah_split for two refs (a third of all nodes), without the bins: on an
 * axis where their centres differ the one at the centres' minimum falls
 * in bin 0 and the other in bin bin_of(maximum), the only cut is after
 * bin 0 and costs the sum of their bins' areas, the same on every such
 * axis (the sum is the same whichever ref is on the left), so the first
 * axis whose bins differ wins if that beats a leaf. */
static bool pair_split(const struct build_ref refs[2], const struct build_box *box,
		       const struct build_box *centres, int *out_axis, double *out_pos)
{
	struct build_box b0, b1;
	double cost;
	int axis;

	bin_box_of(&b0, &refs[0]);
	bin_box_of(&b1, &refs[1]);
	for (axis = 0; axis < 3; axis++) {
		double extent = centres->hi[axis] - centres->lo[axis], scale;
		if (!(extent > 0.0))
			continue;
		scale = ACCEL_BINS / extent;
		if (bin_of(centres->hi[axis], centres->lo[axis], scale) == 0)
			continue;
		if (ref_centre(&refs[0], axis) == centres->lo[axis])
			cost = 1.0 * box_area(&b0) + 1.0 * box_area(&b1);
		else
			cost = 1.0 * box_area(&b1) + 1.0 * box_area(&b0);
		if (!(cost < 2.0 * box_area(box)))
			return false;
		*out_axis = axis;
		*out_pos = centres->lo[axis] + 1 / scale;
		return true;
	}
	return false;
}

static size_t choose_split(struct build_ref *refs, size_t n, int depth, const struct build_box *box,
			   const struct build_box *centres, struct build_parts *parts,
			   struct accel_bins *bins, bool pairs)
{
	size_t split = 0;
	double pos = 0.0;
	int axis = 0;
	bool found = false;

	if (n > 1 && depth < ACCEL_SAH_DEPTH)
		found = n == 2 && pairs ? pair_split(refs, box, centres, &axis, &pos) :
			sah_split(refs, n, box, centres, bins->bin, &axis, &pos);
	if (found)
		split = accel_partition(refs, n, axis, pos, parts);
	if ((split == 0 || split == n) && n > ACCEL_LEAF_MAX) {
		split = median_split(refs, n, centres);
		accel_refs_bounds(refs, split, &parts->front, &parts->front_centres);
		accel_refs_bounds(refs + split, n - split, &parts->back, &parts->back_centres);
	}
	return split == n ? 0 : split;
}

size_t accel_choose_split(struct build_ref *refs, size_t n, int depth, const struct build_box *box,
			  const struct build_box *centres, struct build_parts *parts,
			  struct accel_bins *bins)
{
	return choose_split(refs, n, depth, box, centres, parts, bins, true);
}

size_t accel_choose_split_binned(struct build_ref *refs, size_t n, int depth,
				 const struct build_box *box, const struct build_box *centres,
				 struct build_parts *parts, struct accel_bins *bins)
{
	return choose_split(refs, n, depth, box, centres, parts, bins, false);
}
