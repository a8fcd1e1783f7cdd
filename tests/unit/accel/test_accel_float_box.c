/* The AVX-512 walk's float box tests against the double ones every other
 * walk does (accel/walk_avx512.h): wherever the double test enters a
 * child, the float test must enter it too, at an entry no later; else
 * the walks could meet different shapes and the images part.  Random
 * nodes and rays at every scale, and the hard cases on purpose: origins
 * on a box's faces, edges and corners and a surface offset away from
 * them (shadow rays), rays along a face (zero components, slabs of
 * 0 * inf), directions nearly parallel to an axis, flat and empty boxes,
 * t_max exactly at a child's entry (a tie at the hit), huge t_max; for
 * single rays over eight children and for packets of sixteen over four. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_float_box.h"
#include "accel/accel_kernels.h"
#include "accel/accel_tree.h"
#include "support.h"

#define TRIALS 400000

static double pick(const double *v, int n)
{
	return v[(int)(support_rng() * n) % n];
}

static double scale_now(void)
{
	static const double scales[] = { 1e-3, 1.0, 20.0, 100.0, 1e4, 1e6, 1e9 };

	return pick(scales, 7);
}

/* A node of eight random children around 0 at scale s: boxes, flat ones
 * (lo = hi on an axis), points, and an empty one now and then. */
static void random_node(struct bvh8_node *n, double s)
{
	int c, k;

	memset(n, 0, sizeof(*n));
	for (c = 0; c < 8; c++) {
		double kind = support_rng();

		n->slot[c] = 1;
		for (k = 0; k < 3; k++) {
			double centre = support_uniform(-s, s), half = support_uniform(0.0, s);
			if (kind < 0.15)
				half = 0.0;	/* a point */
			else if (kind < 0.35 && k == c % 3)
				half = 0.0;	/* flat */
			n->lo[k][c] = (float)(centre - half);
			n->hi[k][c] = (float)(centre + half);
			if (n->hi[k][c] < n->lo[k][c])
				n->hi[k][c] = n->lo[k][c];
		}
		if (kind > 0.97)
			for (k = 0; k < 3; k++) {
				n->lo[k][c] = INFINITY;
				n->hi[k][c] = -INFINITY;
			}
	}
}

/* A coordinate of the ray's origin on axis k: anywhere, or on one of the
 * children's planes, or just off it. */
static double origin_coord(const struct bvh8_node *n, int k, double s)
{
	double kind = support_rng();
	int c = (int)(support_rng() * 8) % 8;
	double plane = support_rng() < 0.5 ? n->lo[k][c] : n->hi[k][c];

	if (kind < 0.04)	/* below the floats' normal range */
		return support_uniform(-3000.0, 3000.0) * 0x1p-149;
	if (!isfinite(plane) || kind < 0.4)
		return support_uniform(-2.0 * s, 2.0 * s);
	if (kind < 0.7)
		return plane;
	return plane + support_uniform(-1.0, 1.0) * 1e-6 * fmax(1.0, fabs(plane));
}

static double dir_coord(void)
{
	static const double tiny[] = { 0.0, -0.0, 1e-9, -1e-9, 6e-8, -6e-8, 1e-7, -3e-7, 1e-5 };
	double kind = support_rng();

	if (kind < 0.2)
		return pick(tiny, 9);
	return support_uniform(-1.0, 1.0);
}

static void random_ray(const struct bvh8_node *n, double s, struct ray *r)
{
	double len;

	r->origin = vec3_make(origin_coord(n, 0, s), origin_coord(n, 1, s), origin_coord(n, 2, s));
	do {
		r->dir = vec3_make(dir_coord(), dir_coord(), dir_coord());
		len = vec3_length(r->dir);
	} while (!(len > 1e-3));
	/* Unit, as the renderer's are, but for a zero kept zero. */
	r->dir = vec3_scale(r->dir, 1.0 / len);
}

static void test_float_box_tests_enter_every_box_the_double_test_enters(void **state)
{
	long trials = 0, floats = 0, entered = 0, ties = 0;

	(void)state;
	support_need_isa(RT_SIMD_AVX512, accel_walk_usable(RT_SIMD_AVX512));
	support_rng_seed(20261203);
	for (trials = 0; trials < TRIALS; trials++) {
		struct bvh8_node n;
		struct ray r;
		double s = scale_now(), fe[8], xe[8], t_min, t_max, m;
		int fmask, xmask, c;

		random_node(&n, s);
		random_ray(&n, s, &r);
		m = fmax(1.0, fmax(fabs(r.origin.x), fmax(fabs(r.origin.y), fabs(r.origin.z))));
		t_min = support_rng() < 0.5 ? 1e-6 * m : support_rng() < 0.5 ? 0.0 : support_uniform(0.0, s);
		t_max = support_rng() < 0.3 ? INFINITY : t_min + support_uniform(0.0, 4.0 * s);
		if (support_rng() < 0.05)
			t_max = 1e300;
		if (support_rng() < 0.03)
			t_min = support_rng() * 0x1p-130;
		fmask = accel_kernels_of(RT_SIMD_AVX512)->node_tests(&n, &r, t_min, t_max, fe, &xmask, xe);
		if (xmask && support_rng() < 0.3) {
			/* Again with t_max at an entry the double test found:
			 * the tie at a hit's distance must stay entered. */
			for (c = 0; c < 8 && !(xmask >> c & 1); c++)
				;
			if (xe[c] >= t_min) {
				t_max = xe[c];
				fmask = accel_kernels_of(RT_SIMD_AVX512)->node_tests(&n, &r, t_min, t_max, fe, &xmask, xe);
				ties++;
			}
		}
		if (fmask < 0)
			continue;
		floats++;
		for (c = 0; c < 8; c++) {
			if (!(xmask >> c & 1))
				continue;
			entered++;
			if (!(fmask >> c & 1) || !(fe[c] <= xe[c]))
				fail_msg("child %d: the double test enters at %.17g, the float test %s "
					 "(%.17g); ray (%.17g %.17g %.17g) + t (%.17g %.17g %.17g), "
					 "t in (%.17g, %.17g), box x [%.9g %.9g] y [%.9g %.9g] z "
					 "[%.9g %.9g]",
					 c, xe[c], fmask >> c & 1 ? "later" : "not at all", fe[c],
					 r.origin.x, r.origin.y, r.origin.z, r.dir.x, r.dir.y, r.dir.z,
					 t_min, t_max, n.lo[0][c], n.hi[0][c], n.lo[1][c], n.hi[1][c],
					 n.lo[2][c], n.hi[2][c]);
		}
	}
	/* Not vacuous: most rays take the floats, and many boxes are met. */
	assert_true(floats > trials / 2);
	assert_true(entered > trials / 4);
	assert_true(ties > trials / 50);
}

/* A four-child node from the first four children of an eight-child one. */
static void random_node4(struct bvh4_node *n4, double s)
{
	struct bvh8_node n8;
	int c, k;

	random_node(&n8, s);
	memset(n4, 0, sizeof(*n4));
	for (c = 0; c < 4; c++) {
		n4->slot[c] = 1;
		for (k = 0; k < 3; k++) {
			n4->lo[k][c] = n8.lo[k][c];
			n4->hi[k][c] = n8.hi[k][c];
		}
	}
}

/* The small trees' packets (a ray a lane, sixteen lanes in one float
 * operation): the same property lane by lane, for packets of shadow-like
 * rays from points near the boxes and of rays from one point. */
static void test_float_box_tests_of_packets_enter_every_box_the_double_test_enters(void **state)
{
	long packets = 0, floats = 0, entered = 0;

	(void)state;
	support_need_isa(RT_SIMD_AVX512, accel_walk_usable(RT_SIMD_AVX512));
	support_rng_seed(3);
	for (packets = 0; packets < TRIALS / ACCEL_PACKET; packets++) {
		struct bvh4_node n4;
		struct bvh8_node n8;
		struct ray r[ACCEL_PACKET];
		double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET];
		double fe[4][ACCEL_PACKET], xe[4][ACCEL_PACKET];
		uint32_t fc[4], xc[4];
		double s = scale_now();
		bool one_origin = support_rng() < 0.5;
		int i, c, got;

		random_node4(&n4, s);
		memset(&n8, 0, sizeof(n8));
		memcpy(n8.lo, n4.lo, sizeof(n4.lo));	/* the planes origin_coord picks from */
		for (c = 0; c < 4; c++)
			for (i = 0; i < 3; i++) {
				n8.lo[i][c] = n4.lo[i][c];
				n8.hi[i][c] = n4.hi[i][c];
				n8.lo[i][c + 4] = n4.lo[i][c];
				n8.hi[i][c + 4] = n4.hi[i][c];
			}
		for (i = 0; i < ACCEL_PACKET; i++) {
			double m;

			random_ray(&n8, s, &r[i]);
			/* A packet with a ray nearly along an axis goes to the
			 * doubles whole: keep most packets to the floats. */
			if (support_rng() < 0.95 && !(fabs(r[i].dir.x) >= 0x1p-24 || r[i].dir.x == 0.0))
				r[i].dir.x = 0.0;
			if (support_rng() < 0.95 && !(fabs(r[i].dir.y) >= 0x1p-24 || r[i].dir.y == 0.0))
				r[i].dir.y = 0.0;
			if (support_rng() < 0.95 && !(fabs(r[i].dir.z) >= 0x1p-24 || r[i].dir.z == 0.0))
				r[i].dir.z = 0.0;
			if (one_origin && i > 0)
				r[i].origin = r[0].origin;
			m = fmax(1.0, fmax(fabs(r[i].origin.x), fmax(fabs(r[i].origin.y), fabs(r[i].origin.z))));
			t_min[i] = support_rng() < 0.6 ? 1e-6 * m : support_uniform(0.0, s);
			t_max[i] = support_rng() < 0.3 ? INFINITY : t_min[i] + support_uniform(0.0, 4.0 * s);
		}
		got = accel_kernels_of(RT_SIMD_AVX512)->rays_node_tests(&n4, r, t_min, t_max, fc, fe, xc, xe);
		assert_true(got >= 0);
		if (got == 0)
			continue;
		floats++;
		for (c = 0; c < 4; c++)
			for (i = 0; i < ACCEL_PACKET; i++) {
				if (!(xc[c] >> i & 1))
					continue;
				entered++;
				if (!(fc[c] >> i & 1) || !(fe[c][i] <= xe[c][i]))
					fail_msg("packet %ld, child %d, lane %d: the double test enters at "
						 "%.17g, the float test %s (%.17g)",
						 packets, c, i, xe[c][i], fc[c] >> i & 1 ? "later" : "not at all",
						 fe[c][i]);
			}
	}
	assert_true(floats > packets / 10);
	assert_true(entered > packets);
}

/* A ray from an origin below the floats' normal range (its rounding off
 * by an absolute 2^-150, not a relative u), which once missed a box the
 * double test entered (from the review of the float tests). */
static void test_float_box_tests_origins_below_the_normal_floats(void **state)
{
	struct bvh8_node n;
	struct ray r;
	double fe[8], xe[8];
	int xmask, fmask, c, k;

	(void)state;
	support_need_isa(RT_SIMD_AVX512, accel_walk_usable(RT_SIMD_AVX512));
	memset(&n, 0, sizeof(n));
	for (c = 0; c < 8; c++) {
		n.slot[c] = 1;
		for (k = 0; k < 3; k++) {
			n.lo[k][c] = INFINITY;
			n.hi[k][c] = -INFINITY;
		}
	}
	n.lo[0][0] = 0, n.hi[0][0] = 1;
	n.lo[1][0] = -1, n.hi[1][0] = 0;
	n.lo[2][0] = -1, n.hi[2][0] = 1;
	r.origin = vec3_make(-1000.51 * 0x1p-149, -2001.02 * 1.0000001 * 0x1p-149, 0.0);
	r.dir = vec3_make(0x1p-24, 0x1p-23, 1.0);
	fmask = accel_kernels_of(RT_SIMD_AVX512)->node_tests(&n, &r, 0.0, INFINITY, fe, &xmask, xe);
	assert_int_equal(xmask & 1, 1);
	assert_true(fmask < 0 || ((fmask & 1) && fe[0] <= xe[0]));
}

/* The rays the bound cannot hold go to the double test. */
static void test_float_box_tests_leave_rays_they_cannot_bound_to_doubles(void **state)
{
	static const struct vec3 origins[] = { { 2e30, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 }, { 0, 0, 0 },
					       { 0, 0, 0 } };
	static const struct vec3 dirs[] = { { 1, 0, 0 }, { 1e-9, 1, 0 }, { NAN, 1, 0 }, { 0, 1, 0 },
					    { 0x1p70, 1, 0 } };
	static const double t_mins[] = { 0.0, 0.0, 0.0, -1.0, 0.0 };
	struct bvh8_node n;
	double fe[8], xe[8];
	int xmask, i;

	(void)state;
	support_need_isa(RT_SIMD_AVX512, accel_walk_usable(RT_SIMD_AVX512));
	support_rng_seed(7);
	random_node(&n, 1.0);
	for (i = 0; i < 5; i++) {
		struct ray r;

		r.origin = origins[i];
		r.dir = dirs[i];
		assert_int_equal(accel_kernels_of(RT_SIMD_AVX512)->node_tests(&n, &r, t_mins[i], INFINITY, fe, &xmask, xe), -1);
	}
}

/* The packets' check of the same limits (accel_packet_rays.h), made on
 * the values rounded to floats: a packet goes to the float tests only if
 * float_box_ray holds for each of its rays, never looser.  Packets of
 * ordinary rays with one ray, or all, at or beside a limit: an origin's
 * coordinate about 1e30 and 2^99, a direction's about 2^-24 and 2^64 or
 * rounding to float 0 without being 0, t_min about 0 (signed zeros, a
 * tiny negative) and 1e37, NaN and infinities; and the share of packets
 * the floats take, so that the check is not simply refusing them all. */
static void test_float_box_tests_of_packets_leave_rays_they_cannot_bound_to_doubles(void **state)
{
	static const double coord[] = { 1e30, -1e30, 0x1p99, -0x1p99, 0x1p99 * (1 - 0x1p-53),
					0x1p99 * (1 + 0x1p-52), 6e29, 1e30 * (1 - 0x1p-52), NAN,
					INFINITY, 1e-310 };
	static const double dir[] = { 0x1p-24, -0x1p-24, 0x1p-24 * (1 - 0x1p-40),
				      0x1p-24 * (1 + 0x1p-40), 0x1p-24 * (1 + 0x1p-22), 1e-46,
				      -1e-46, 1e-300, 0x1p-149, 0x1p-127, -0.0, 0x1p64, -0x1p64,
				      0x1p64 * (1 - 0x1p-52), 0x1p64 * (1 - 0x1p-23),
				      0x1p64 * (1 + 0x1p-52), NAN, -INFINITY };
	static const double start[] = { 0.0, -0.0, -1e-300, 1e-300, -0x1p-149, 1e37, 0x1p122,
					0x1p122 * (1 - 0x1p-52), 0x1p122 * (1 - 0x1p-23), 5e36,
					1e37 * (1 + 0x1p-52), NAN, INFINITY };
	struct bvh4_node n4;
	long floats = 0, trials = 0;
	int k;

	(void)state;
	support_need_isa(RT_SIMD_AVX512, accel_walk_usable(RT_SIMD_AVX512));
	support_rng_seed(13);
	random_node4(&n4, 1.0);
	for (k = 0; k < 60000; k++) {
		struct ray r[ACCEL_PACKET];
		double t_min[ACCEL_PACKET], t_max[ACCEL_PACKET], fe[4][ACCEL_PACKET], xe[4][ACCEL_PACKET];
		uint32_t fc[4], xc[4];
		int lane = (int)(support_rng() * ACCEL_PACKET), all = k % 5 == 0, i, got;
		bool hold = true;

		for (i = 0; i < ACCEL_PACKET; i++) {
			double *o, *d;
			int axis = (int)(support_rng() * 3);

			r[i].origin = vec3_make(support_uniform(-50, 50), support_uniform(-50, 50),
						support_uniform(-50, 50));
			r[i].dir = vec3_make(support_uniform(0.1, 1), -support_uniform(0.1, 1),
					     support_uniform(0.1, 1));
			t_min[i] = 1e-6;
			t_max[i] = INFINITY;
			if (i != lane && !all)
				continue;
			o = axis == 0 ? &r[i].origin.x : axis == 1 ? &r[i].origin.y : &r[i].origin.z;
			d = axis == 0 ? &r[i].dir.x : axis == 1 ? &r[i].dir.y : &r[i].dir.z;
			switch (k % 3) {
			case 0:
				*o = pick(coord, (int)(sizeof(coord) / sizeof(coord[0])));
				break;
			case 1:
				*d = pick(dir, (int)(sizeof(dir) / sizeof(dir[0])));
				break;
			default:
				t_min[i] = pick(start, (int)(sizeof(start) / sizeof(start[0])));
			}
		}
		for (i = 0; i < ACCEL_PACKET; i++)
			hold = hold && float_box_ray(&r[i], t_min[i]);
		got = accel_kernels_of(RT_SIMD_AVX512)->rays_node_tests(&n4, r, t_min, t_max, fc, fe, xc, xe);
		assert_true(got >= 0);
		trials++;
		floats += got;
		if (got == 1 && !hold) {
			for (i = 0; i < ACCEL_PACKET && float_box_ray(&r[i], t_min[i]); i++)
				;
			fail_msg("packet %d took the float tests, but its lane %d cannot: origin %a %a %a, "
				 "direction %a %a %a, t_min %a",
				 k, i, r[i].origin.x, r[i].origin.y, r[i].origin.z, r[i].dir.x, r[i].dir.y,
				 r[i].dir.z, t_min[i]);
		}
	}
	print_message("%ld of %ld packets took the float tests\n", floats, trials);
	assert_true(floats > trials / 10);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_float_box_tests_enter_every_box_the_double_test_enters,
			   test_float_box_tests_leave_rays_they_cannot_bound_to_doubles,
			   test_float_box_tests_origins_below_the_normal_floats,
			   test_float_box_tests_of_packets_enter_every_box_the_double_test_enters,
			   test_float_box_tests_of_packets_leave_rays_they_cannot_bound_to_doubles))
