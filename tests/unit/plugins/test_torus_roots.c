/* The torus plugin's root isolation (torus_roots of plugins/torus.c, the
 * file included here for its static helpers): real roots of a polynomial
 * of degree <= 4 inside an interval, on quartics whose roots are known
 * exactly: four simple ones, a double root that touches zero, a triple
 * one, two roots 2e-6 apart (a ray grazing the tube), a pair that has just
 * gone complex (a ray just missing it), and roots at or past the ends. */
#include <float.h>
#include <math.h>

/* Before cmocka's header, whose fail() macro would rewrite host->fail. */
#include "../../../plugins/torus.c"

#include "support.h"

static double coef[5];

static int roots_of(double c0, double c1, double c2, double c3, double c4, double lo, double hi,
		    double out[4])
{
	coef[0] = c0, coef[1] = c1, coef[2] = c2, coef[3] = c3, coef[4] = c4;
	return torus_roots(coef, 4, lo, hi, out);
}

/* A simple root of coef's quartic found as well as doubles allow: within
 * the error of evaluating the quartic there (2 eps sum |c_i| |x|^i, the
 * bound of Horner's rule) over the slope, plus one ulp.  Any root finder
 * working in doubles can be that far off, and no further. */
static void assert_root(double got, double want)
{
	double size = 0.0, slope = 0.0, tol;
	int i;

	for (i = 4; i >= 0; i--)
		size += fabs(coef[i]) * pow(fabs(want), i);
	for (i = 4; i >= 1; i--)
		slope += i * coef[i] * pow(want, i - 1);
	tol = 2.0 * DBL_EPSILON * size / fabs(slope) + (nextafter(fabs(want), INFINITY) - fabs(want));
	if (!(fabs(got - want) <= tol))
		fail_msg("%.17g, expected %.17g (to %g)", got, want, tol);
}

/* Equal, or within `ulps` units in the last place of want. */
static void assert_near_ulps(double got, double want, double ulps)
{
	double tol = ulps * (nextafter(fabs(want), INFINITY) - fabs(want));

	if (!(fabs(got - want) <= tol))
		fail_msg("%.17g, expected %.17g (to %g ulp)", got, want, ulps);
}

/* (x - 1)(x - 2)(x - 3)(x - 4) = x^4 - 10 x^3 + 35 x^2 - 50 x + 24. */
static void test_torus_roots_four_simple(void **state)
{
	double r[4];

	(void)state;
	assert_int_equal(roots_of(24, -50, 35, -10, 1, -10, 10, r), 4);
	assert_root(r[0], 1.0);
	assert_root(r[1], 2.0);
	assert_root(r[2], 3.0);
	assert_root(r[3], 4.0);
	/* Only those inside the interval. */
	assert_int_equal(roots_of(24, -50, 35, -10, 1, 1.5, 3.5, r), 2);
	assert_root(r[0], 2.0);
	assert_root(r[1], 3.0);
	assert_int_equal(roots_of(24, -50, 35, -10, 1, 4.5, 100, r), 0);
}

/* (x - 1)^2 (x - 3)(x + 2) = x^4 - 3 x^3 - 3 x^2 + 11 x - 6: the double
 * root at 1, where the quartic touches 0 without crossing, is the
 * derivative's root and exactly a zero of the quartic. */
static void test_torus_roots_double(void **state)
{
	double r[4];

	(void)state;
	assert_int_equal(roots_of(-6, 11, -3, -3, 1, -10, 10, r), 3);
	assert_root(r[0], -2.0);
	assert_true(r[1] == 1.0);
	assert_root(r[2], 3.0);
}

/* (x - 2)^3 (x + 1) = x^4 - 5 x^3 + 6 x^2 + 4 x - 8: the triple root
 * crosses zero, once. */
static void test_torus_roots_triple(void **state)
{
	double r[4];

	(void)state;
	assert_int_equal(roots_of(-8, 4, 6, -5, 1, -10, 10, r), 2);
	assert_root(r[0], -1.0);
	assert_true(fabs(r[1] - 2.0) < 1e-5);
}

/* (x^2 - e^2)(x^2 - 25), e = 1e-6: a ray that grazes the tube meets it
 * twice, 2e-6 apart; both roots are found, each to a relative 1e-9.
 * With e^2 of the other sign, (x^2 + e^2)(x^2 - 25), the pair is complex
 * (the ray just misses): only +-5. */
static void test_torus_roots_grazing(void **state)
{
	const double e2 = 1e-12;
	double r[4];

	(void)state;
	assert_int_equal(roots_of(25 * e2, 0, -(25 + e2), 0, 1, -10, 10, r), 4);
	assert_root(r[0], -5.0);
	assert_true(fabs(r[1] + 1e-6) < 1e-15);
	assert_true(fabs(r[2] - 1e-6) < 1e-15);
	assert_root(r[3], 5.0);
	assert_int_equal(roots_of(-25 * e2, 0, -(25 - e2), 0, 1, -10, 10, r), 2);
	assert_root(r[0], -5.0);
	assert_root(r[1], 5.0);
}

/* A root exactly at an end of the interval counts once. */
static void test_torus_roots_at_the_ends(void **state)
{
	double r[4];

	(void)state;
	assert_int_equal(roots_of(24, -50, 35, -10, 1, 1, 4, r), 4);
	assert_true(r[0] == 1.0);
	assert_true(r[3] == 4.0);
	assert_int_equal(roots_of(24, -50, 35, -10, 1, 2, 2, r), 1);
	assert_true(r[0] == 2.0);
}

/* The lower degrees the recursion goes through: x^2 - 2 and 3 x - 1. */
static void test_torus_roots_lower_degrees(void **state)
{
	const double quad[3] = { -2, 0, 1 }, line[2] = { -1, 3 };
	double r[4];

	(void)state;
	assert_int_equal(torus_roots(quad, 2, -5, 5, r), 2);
	assert_near_ulps(r[0], -sqrt(2.0), 2);
	assert_near_ulps(r[1], sqrt(2.0), 2);
	assert_int_equal(torus_roots(line, 1, -5, 5, r), 1);
	assert_near_ulps(r[0], 1.0 / 3.0, 1);
	assert_int_equal(torus_roots(line, 1, 0.5, 5, r), 0);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_torus_roots_four_simple, test_torus_roots_double,
			   test_torus_roots_triple, test_torus_roots_grazing,
			   test_torus_roots_at_the_ends, test_torus_roots_lower_degrees))
