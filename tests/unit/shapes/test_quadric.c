/* The general quadric through its table: roots, the clip box (inclusive,
 * per axis, the near root falling through to the far one), the linear
 * case, normals (each of the nine terms A..I alone and all together,
 * against gradients derived in the test), hits with every term, bounds,
 * parsing and POV export. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shapes/shapes.h"
#include "scene/scene_impl.h"
#include "whitted/pov.h"
#include "shapes/solve.h"
#include "support.h"

static const struct material mat = { { 0.0, 0.0, 1.0 }, 0.4, 0.2, 0.1, 0.3, 3.0, 0.0, 1.0 };
/* x^2 + y^2 + z^2 - 4 = 0: the radius-2 sphere at the origin. */
static const double sphere4[10] = { 1, 1, 1, 0, 0, 0, 0, 0, 0, -4 };

static struct shape *quadric(const double coef[10], double rx, double ry, double rz,
			     double lx, double ly, double lz)
{
	struct shape *s = quadric_create(coef, vec3_make(rx, ry, rz), vec3_make(lx, ly, lz), &mat);

	assert_non_null(s);
	return s;
}

static void test_quadric_unclipped_sphere(void **state)
{
	struct shape *s = quadric(sphere4, 0, 0, 0, 0, 0, 0);
	struct ray r = support_ray(0, 0, -10, 0, 0, 1);
	struct ray miss = support_ray(0, 2.5, -10, 0, 0, 1);
	struct ray behind = support_ray(0, 0, 10, 0, 0, 1);
	double t_max = 100.0;

	(void)state;
	/* (t - 10)^2 = 4: t = 8 and 12; the near one, shrinking t_max. */
	assert_true(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 8.0, 1e-12);
	assert_false(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 8.0, 1e-12);
	t_max = 100.0;
	assert_false(shape_intersect(s, &miss, 0.0, &t_max));
	assert_false(shape_intersect(s, &behind, 0.0, &t_max));
	assert_near(t_max, 100.0, 0.0);
	/* t_min past the near root: the far one. */
	assert_true(shape_intersect(s, &r, 9.0, &t_max));
	assert_near(t_max, 12.0, 1e-12);
	shape_destroy(s);
}

static void test_quadric_tangent_inside_non_unit(void **state)
{
	struct shape *s = quadric(sphere4, 0, 0, 0, 0, 0, 0);
	struct ray graze = support_ray(2, 0, -10, 0, 0, 1);
	struct ray inside = support_ray(0, 0, 0, 0, 1, 0);
	struct ray fast = support_ray(0, 0, -10, 0, 0, 2);
	double t_max = INFINITY;

	(void)state;
	/* x = 2: t^2 - 20 t + 100 = 0, the double root t = 10. */
	assert_hit(s, &graze, 0.0, &t_max, 10.0, 1e-9);
	/* From the centre: t = +-2, the positive one. */
	assert_hit(s, &inside, 1e-6, &t_max, 2.0, 1e-12);
	/* |d| = 2: t = 4. */
	assert_hit(s, &fast, 0.0, &t_max, 4.0, 1e-12);
	shape_destroy(s);
}

static void test_quadric_clipped_near_root_falls_through(void **state)
{
	/* The upper hemisphere z in [0, 5]: from below, the near root (z = -2,
	 * t = 8) is clipped and the far one (z = 2, t = 12) is the hit, the
	 * inside of the dome. */
	struct shape *s = quadric(sphere4, 0, 0, 0, 0, 0, 5);
	struct ray r = support_ray(0, 0, -10, 0, 0, 1);
	struct ray slant = support_ray(1, 0, -10, 0, 0, 1);
	double t_max = INFINITY;

	(void)state;
	assert_hit(s, &r, 0.0, &t_max, 12.0, 1e-12);
	/* At x = 1: z = +-sqrt(3), so t = 10 + sqrt(3). */
	assert_hit(s, &slant, 0.0, &t_max, 10.0 + sqrt(3.0), 1e-12);
	/* A far root clipped too: the lower hemisphere seen from below at
	 * x = 1, z in [-5, -1]: near root z = -sqrt(3) is in, t = 10 - sqrt(3). */
	shape_destroy(s);
	s = quadric(sphere4, 0, 0, -5, 0, 0, 4);
	assert_hit(s, &slant, 0.0, &t_max, 10.0 - sqrt(3.0), 1e-12);
	shape_destroy(s);
	/* Both roots clipped (the band z in [-1, 1] seen along the axis): a
	 * miss, and t_max untouched. */
	s = quadric(sphere4, 0, 0, -1, 0, 0, 2);
	t_max = 50.0;
	assert_false(shape_intersect(s, &r, 0.0, &t_max));
	assert_near(t_max, 50.0, 0.0);
	shape_destroy(s);
}

static void test_quadric_clip_box_inclusive(void **state)
{
	/* z in [-2, 0]: the near root is exactly z = -2 (t = 8, computed
	 * exactly: 8 = 10 - 2), on the box's face, and counts. */
	struct shape *s = quadric(sphere4, 0, 0, -2, 0, 0, 2);
	struct ray up = support_ray(0, 0, -10, 0, 0, 1);
	struct ray down = support_ray(0, 0, 10, 0, 0, -1);
	double t_max = INFINITY;

	(void)state;
	assert_hit(s, &up, 0.0, &t_max, 8.0, 0.0);
	/* From above: z = 2 is clipped, z = -2 (t = 12) is on the face. */
	assert_hit(s, &down, 0.0, &t_max, 12.0, 0.0);
	shape_destroy(s);
	/* The upper face: z in [-5, -2] still contains z = -2. */
	s = quadric(sphere4, 0, 0, -5, 0, 0, 3);
	assert_hit(s, &up, 0.0, &t_max, 8.0, 0.0);
	shape_destroy(s);
	/* And z in [-5, -2.0000001] does not. */
	s = quadric(sphere4, 0, 0, -5, 0, 0, 2.9999999);
	t_max = INFINITY;
	assert_false(shape_intersect(s, &up, 0.0, &t_max));
	shape_destroy(s);
}

static void test_quadric_clip_each_axis(void **state)
{
	/* For each axis, the half x_k in [0, 5] (the other axes unclipped):
	 * the ray along that axis from -10 meets -2 (clipped) and then 2. */
	int axis;

	(void)state;
	for (axis = 0; axis < 3; axis++) {
		double ext[3] = { 0, 0, 0 }, o[3] = { 0, 0, 0 }, d[3] = { 0, 0, 0 };
		struct shape *s;
		struct ray r;
		double t_max = INFINITY;
		struct aabb box;

		ext[axis] = 5;
		o[axis] = -10;
		d[axis] = 1;
		s = quadric(sphere4, 0, 0, 0, ext[0], ext[1], ext[2]);
		r = support_ray(o[0], o[1], o[2], d[0], d[1], d[2]);
		assert_true(shape_intersect(s, &r, 0.0, &t_max));
		assert_near(t_max, 12.0, 1e-12);
		/* Clipped on one axis: unbounded. */
		assert_false(shape_bounds(s, &box));
		shape_destroy(s);
	}
}

static void test_quadric_bounds_only_when_clipped_on_all_axes(void **state)
{
	struct shape *s;
	struct aabb box;

	(void)state;
	s = quadric(sphere4, 0, 0, 0, 0, 0, 0);
	assert_false(shape_bounds(s, &box));
	shape_destroy(s);
	s = quadric(sphere4, -3, 0, 0, 6, 0, 0);
	assert_false(shape_bounds(s, &box));
	shape_destroy(s);
	s = quadric(sphere4, -3, -3, 0, 6, 6, 0);
	assert_false(shape_bounds(s, &box));
	shape_destroy(s);
	s = quadric(sphere4, -3, -2, -1, 6, 5, 4);
	assert_true(shape_bounds(s, &box));
	assert_vec3_near(box.min, vec3_make(-3, -2, -1), 0.0);
	assert_vec3_near(box.max, vec3_make(3, 3, 3), 0.0);
	shape_destroy(s);
}

static void test_quadric_clip_on_three_axes(void **state)
{
	/* The sphere cut to the box [0, 5]^3: the octant x, y, z >= 0. */
	struct shape *s = quadric(sphere4, 0, 0, 0, 5, 5, 5);
	/* Along z at x = y = 1: z = +-sqrt(2), only +sqrt(2) is in the box,
	 * t = 10 + sqrt(2). */
	struct ray in = support_ray(1, 1, -10, 0, 0, 1);
	/* At x = -1 the whole line is outside the box. */
	struct ray out = support_ray(-1, 1, -10, 0, 0, 1);
	double t_max = INFINITY;

	(void)state;
	assert_hit(s, &in, 0.0, &t_max, 10.0 + sqrt(2.0), 1e-12);
	t_max = INFINITY;
	assert_false(shape_intersect(s, &out, 0.0, &t_max));
	shape_destroy(s);
}

static void test_quadric_linear_case(void **state)
{
	/* The plane z - 3 = 0 (I = 1, J = -3): no quadratic term at all. */
	static const double plane[10] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, -3 };
	/* The paraboloid x^2 - z = 0 along z: qa = 0 for this direction,
	 * x0^2 - (z0 + t) = 0 so from (1, 0, -5) t = 1 + 5 = 6. */
	static const double para[10] = { 1, 0, 0, 0, 0, 0, 0, 0, -1, 0 };
	/* The cylinder x^2 + y^2 = 4 along its axis: qa = qb = 0, no root. */
	static const double cyl[10] = { 1, 1, 0, 0, 0, 0, 0, 0, 0, -4 };
	struct shape *p = quadric(plane, 0, 0, 0, 0, 0, 0);
	struct shape *q = quadric(para, 0, 0, 0, 0, 0, 0);
	struct shape *c = quadric(cyl, 0, 0, 0, 0, 0, 0);
	struct ray up = support_ray(0.5, 0.5, 0, 0, 0, 1);
	struct ray r = support_ray(1, 0, -5, 0, 0, 1);
	struct ray axis = support_ray(1, 0, -5, 0, 0, 1);
	double t_max = INFINITY;

	(void)state;
	assert_hit(p, &up, 0.0, &t_max, 3.0, 0.0);
	assert_vec3_near(shape_normal(p, vec3_make(0.5, 0.5, 3)), vec3_make(0, 0, 1), 0.0);
	assert_hit(q, &r, 0.0, &t_max, 6.0, 0.0);
	/* The gradient (2x, 0, -1) at (1, 0, 1) is (2, 0, -1) / sqrt(5). */
	assert_vec3_near(shape_normal(q, vec3_make(1, 0, 1)),
			 vec3_make(2 / sqrt(5.0), 0, -1 / sqrt(5.0)), 1e-15);
	t_max = INFINITY;
	assert_false(shape_intersect(c, &axis, 0.0, &t_max));
	/* The plane clipped to z in [0, 2] is never hit. */
	shape_destroy(p);
	p = quadric(plane, 0, 0, 0, 0, 0, 2);
	assert_false(shape_intersect(p, &up, 0.0, &t_max));
	shape_destroy(p);
	shape_destroy(q);
	shape_destroy(c);
}

static void test_quadric_unit_normals(void **state)
{
	/* The cylinder (x - 1)^2 + y^2 = 4, i.e. x^2 + y^2 - 2x - 3 = 0
	 * (G = -2, J = -3): at (3, 0, 7) the gradient (2x - 2, 2y, 0) is
	 * (4, 0, 0), at (1, 2, -1) it is (0, 4, 0).  And the ellipsoid
	 * x^2 + 4 y^2 + 9 z^2 = 36. */
	static const double cyl[10] = { 1, 1, 0, 0, 0, 0, -2, 0, 0, -3 };
	static const double ell[10] = { 1, 4, 9, 0, 0, 0, 0, 0, 0, -36 };
	struct shape *c = quadric(cyl, 0, 0, 0, 0, 0, 0);
	struct shape *e = quadric(ell, 0, 0, 0, 0, 0, 0);
	struct vec3 n;

	(void)state;
	assert_vec3_near(shape_normal(c, vec3_make(3, 0, 7)), vec3_make(1, 0, 0), 0.0);
	assert_vec3_near(shape_normal(c, vec3_make(1, 2, -1)), vec3_make(0, 1, 0), 0.0);
	/* On the ellipsoid at (0, 0, 2): gradient (2x, 8y, 18z) = (0, 0, 36). */
	assert_vec3_near(shape_normal(e, vec3_make(0, 0, 2)), vec3_make(0, 0, 1), 0.0);
	/* At (sqrt(18), 0, sqrt(2)) (18 + 18 = 36): (2 sqrt(18), 0, 18 sqrt(2))
	 * = sqrt(2) (6, 0, 18), direction (1, 0, 3) / sqrt(10). */
	n = shape_normal(e, vec3_make(sqrt(18.0), 0, sqrt(2.0)));
	assert_vec3_near(n, vec3_make(1 / sqrt(10.0), 0, 3 / sqrt(10.0)), 1e-15);
	assert_near(vec3_length(n), 1.0, 1e-15);
	shape_destroy(c);
	shape_destroy(e);
}

static void test_quadric_cross_terms(void **state)
{
	/* xy - 1 = 0 (D = 1): the hyperbola y = 1 / x extruded along z.  The
	 * ray from (-1, 0.5, 0) along +x meets x y = 1 at x = 2: t = 3. */
	static const double hyp[10] = { 0, 0, 0, 1, 0, 0, 0, 0, 0, -1 };
	/* xz - 1 (E) along +z from (0.5, 0, -1): z = 2, t = 3;
	 * yz - 1 (F) along +y from (0, -1, 0.25): y = 4, t = 5. */
	static const double xz[10] = { 0, 0, 0, 0, 1, 0, 0, 0, 0, -1 };
	static const double yz[10] = { 0, 0, 0, 0, 0, 1, 0, 0, 0, -1 };
	struct shape *s;
	struct ray r;
	double t_max;

	(void)state;
	s = quadric(hyp, 0, 0, 0, 0, 0, 0);
	r = support_ray(-1, 0.5, 0, 1, 0, 0);
	assert_hit(s, &r, 0.0, &t_max, 3.0, 1e-12);
	/* Gradient (y, x, 0) at (2, 0.5, 0): (0.5, 2, 0) / sqrt(4.25). */
	assert_vec3_near(shape_normal(s, vec3_make(2, 0.5, 0)),
			 vec3_make(0.5 / sqrt(4.25), 2 / sqrt(4.25), 0), 1e-15);
	shape_destroy(s);
	s = quadric(xz, 0, 0, 0, 0, 0, 0);
	r = support_ray(0.5, 0, -1, 0, 0, 1);
	assert_hit(s, &r, 0.0, &t_max, 3.0, 1e-12);
	shape_destroy(s);
	s = quadric(yz, 0, 0, 0, 0, 0, 0);
	r = support_ray(0, -1, 0.25, 0, 1, 0);
	assert_hit(s, &r, 0.0, &t_max, 5.0, 1e-12);
	shape_destroy(s);
}

/* F(P) = A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J,
 * evaluated term by term, as scene-format.md writes it. */
static double quadric_value(const double k[10], struct vec3 p)
{
	return k[0] * p.x * p.x + k[1] * p.y * p.y + k[2] * p.z * p.z + k[3] * p.x * p.y +
	       k[4] * p.x * p.z + k[5] * p.y * p.z + k[6] * p.x + k[7] * p.y + k[8] * p.z + k[9];
}

/* The gradient of F by central differences of F itself: exact for a
 * polynomial of degree 2 (its third derivatives vanish), up to rounding,
 * with h a power of two. */
static struct vec3 quadric_gradient_by_differences(const double k[10], struct vec3 p)
{
	const double h = 0.5;

	return vec3_make((quadric_value(k, vec3_make(p.x + h, p.y, p.z)) -
			  quadric_value(k, vec3_make(p.x - h, p.y, p.z))) / (2 * h),
			 (quadric_value(k, vec3_make(p.x, p.y + h, p.z)) -
			  quadric_value(k, vec3_make(p.x, p.y - h, p.z))) / (2 * h),
			 (quadric_value(k, vec3_make(p.x, p.y, p.z + h)) -
			  quadric_value(k, vec3_make(p.x, p.y, p.z - h))) / (2 * h));
}

static void test_quadric_normal_each_term(void **state)
{
	/* Each of A..I alone (J = -1), at P = (2, 3, 5), against the gradient
	 * of that one term written out by hand:
	 *   A x^2: (2x, 0, 0) = (4, 0, 0)    D xy: (y, x, 0) = (3, 2, 0)
	 *   B y^2: (0, 2y, 0) = (0, 6, 0)    E xz: (z, 0, x) = (5, 0, 2)
	 *   C z^2: (0, 0, 2z) = (0, 0, 10)   F yz: (0, z, y) = (0, 5, 3)
	 *   G x: (1, 0, 0)   H y: (0, 1, 0)   I z: (0, 0, 1) */
	static const double grad[9][3] = {
		{ 4, 0, 0 }, { 0, 6, 0 }, { 0, 0, 10 }, { 3, 2, 0 }, { 5, 0, 2 }, { 0, 5, 3 },
		{ 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
	};
	static const char names[] = "ABCDEFGHI";
	struct vec3 p = vec3_make(2, 3, 5);
	int term;

	(void)state;
	for (term = 0; term < 9; term++) {
		double coef[10] = { 0, 0, 0, 0, 0, 0, 0, 0, 0, -1 };
		struct shape *s;
		struct vec3 n, want = vec3_normalize(vec3_make(grad[term][0], grad[term][1],
							       grad[term][2]));

		coef[term] = 1;
		s = quadric(coef, 0, 0, 0, 0, 0, 0);
		n = shape_normal(s, p);
		if (!(fabs(n.x - want.x) <= 1e-15 && fabs(n.y - want.y) <= 1e-15 &&
		      fabs(n.z - want.z) <= 1e-15)) {
			print_error("%c alone: normal (%.17g, %.17g, %.17g), expected (%.17g, %.17g, "
				    "%.17g)\n", names[term], n.x, n.y, n.z, want.x, want.y, want.z);
			fail();
		}
		shape_destroy(s);
	}
}

static void test_quadric_normal_all_terms(void **state)
{
	/* Every coefficient non-zero and different, at points put on the
	 * surface by the choice of J: the unit normal is the gradient (of
	 * the differences above) over its length. */
	static const double base[2][9] = {
		{ 1, 2, 3, 0.5, -0.7, 0.9, -1.1, 1.3, -1.7 },
		{ -0.4, 0.8, 0.25, -1.5, 1.25, -0.6, 2, -3, 0.75 },
	};
	static const double pts[][3] = {
		{ 1, 2, 3 }, { -2.5, 0.5, 1.5 }, { 0.3, -4, 2 }, { 7, -1, -6 }, { 0.1, 0.2, -0.3 },
	};
	size_t b, i;

	(void)state;
	for (b = 0; b < 2; b++) {
		for (i = 0; i < sizeof(pts) / sizeof(pts[0]); i++) {
			double coef[10];
			struct vec3 p = vec3_make(pts[i][0], pts[i][1], pts[i][2]), n, want;
			struct shape *s;

			memcpy(coef, base[b], sizeof(base[b]));
			coef[9] = 0;
			coef[9] = -quadric_value(coef, p);
			want = vec3_normalize(quadric_gradient_by_differences(coef, p));
			s = quadric(coef, 0, 0, 0, 0, 0, 0);
			n = shape_normal(s, p);
			assert_vec3_near(n, want, 1e-13);
			shape_destroy(s);
		}
	}
}

/* The roots of F(o + t d) from three values of F along the ray (the test's
 * own substitution): with f(t) = qa t^2 + qb t + qc, qc = f(0),
 * qb = (f(1) - f(-1)) / 2, qa = (f(1) + f(-1)) / 2 - f(0). */
static int quadric_roots_by_values(const double k[10], struct ray r, double t[2])
{
	double f0 = quadric_value(k, r.origin);
	double fp = quadric_value(k, vec3_add(r.origin, r.dir));
	double fm = quadric_value(k, vec3_sub(r.origin, r.dir));
	double qa = (fp + fm) / 2 - f0, qb = (fp - fm) / 2, qc = f0, disc;

	disc = qb * qb - 4 * qa * qc;
	if (disc < 0)
		return 0;
	t[0] = (-qb - sqrt(disc)) / (2 * qa);
	t[1] = (-qb + sqrt(disc)) / (2 * qa);
	if (t[0] > t[1]) {
		double tmp = t[0];
		t[0] = t[1];
		t[1] = tmp;
	}
	return 2;
}

static void test_quadric_hit_all_terms(void **state)
{
	/* The ellipsoid-like x^2 + 2 y^2 + 3 z^2 + 0.5 xy - 0.7 xz + 0.9 yz
	 * - 1.1 x + 1.3 y - 1.7 z - 20 = 0 (positive definite: bounded), from
	 * outside along many directions: the nearest root in front, and F = 0
	 * at the hit. */
	static const double coef[10] = { 1, 2, 3, 0.5, -0.7, 0.9, -1.1, 1.3, -1.7, -20 };
	struct shape *s = quadric(coef, 0, 0, 0, 0, 0, 0);
	int i, hits = 0;

	(void)state;
	for (i = 0; i < 64; i++) {
		double a = 0.3 * i, e = 0.11 * i - 3.5;
		struct vec3 o = vec3_make(30 * cos(a) * cos(e), 30 * sin(a) * cos(e), 30 * sin(e));
		struct vec3 aim = vec3_make(0.5 * sin(1.7 * i), 0.4 * cos(2.3 * i), 0.3 * sin(0.9 * i));
		struct ray r;
		double t[2], t_max = INFINITY;

		r.origin = o;
		r.dir = vec3_normalize(vec3_sub(aim, o));
		if (quadric_roots_by_values(coef, r, t) == 0 || t[0] <= 0) {
			assert_false(shape_intersect(s, &r, 1e-6, &t_max));
			continue;
		}
		hits++;
		assert_true(shape_intersect(s, &r, 1e-6, &t_max));
		assert_near(t_max, t[0], 1e-9);
		assert_near(quadric_value(coef, ray_at(&r, t_max)), 0.0, 1e-9);
	}
	assert_true(hits > 40);
	shape_destroy(s);
}

static void test_quadric_parse(void **state)
{
	struct scene *sc = support_parse(
		"1 1\n1\ngeneral\n"
		"1 1 1 0 0 0 -20 -20 -20 200\t- A B C D E F G H I J\n"
		"0 0 0 0 0 5\t- cube reference point, length, width, height\n"
		"0.0 0.0 1.0\t- color\n0.4 0.2 0.1 0.3\t- coefficients\n3\t\t- shininess\n0\n");
	struct shape *s;
	struct aabb box;
	/* (x-10)^2 + (y-10)^2 + (z-10)^2 = 100: the sphere of radius 10 at
	 * (10, 10, 10), clipped to z in [0, 5].  Along z at x = y = 10 the
	 * roots are z = 0 and 20; z = 0 is on the box's face. */
	struct ray r = support_ray(10, 10, -10, 0, 0, 1);
	double t_max = INFINITY;

	(void)state;
	s = support_only_shape(sc, "general");
	assert_false(shape_bounds(s, &box));
	assert_hit(s, &r, 0.0, &t_max, 10.0, 1e-12);
	assert_near(s->mat.color.b, 1.0, 0.0);
	assert_near(s->mat.shininess, 3.0, 0.0);
	scene_destroy(sc);
}

static void test_quadric_export_pov(void **state)
{
	static const double coef[10] = { 1, 2, 3, 4, 5, 6, -7, -8, -9, 0.1 };
	struct shape *s = quadric(coef, -1, 0, 2, 3, 0, 4);
	struct shape *u = quadric(coef, 0, 0, 0, 0, 0, 0);
	double v[10], hx, lx, hz, lz;
	char *text = support_export_pov(s, RT_POV_FINISH_PLAIN), *clip;

	(void)state;
	assert_int_equal(sscanf(text, "quadric { <%lf,%lf,%lf>, <%lf,%lf,%lf>, <%lf,%lf,%lf>, %lf",
				&v[0], &v[1], &v[2], &v[3], &v[4], &v[5], &v[6], &v[7], &v[8], &v[9]),
			 10);
	assert_near(v[0], 1, 0.0);
	assert_near(v[1], 2, 0.0);
	assert_near(v[2], 3, 0.0);
	assert_near(v[3], 4, 0.0);
	assert_near(v[4], 5, 0.0);
	assert_near(v[5], 6, 0.0);
	assert_near(v[6], -7, 0.0);
	assert_near(v[7], -8, 0.0);
	assert_near(v[8], -9, 0.0);
	assert_true(v[9] == 0.1);
	/* Clipped on x to [-1, 2] and z to [2, 6], not on y. */
	clip = strstr(text, "clipped_by");
	assert_non_null(clip);
	assert_int_equal(sscanf(clip, "clipped_by { intersection { plane { x, %lf } plane { -x, %lf }"
				" plane { z, %lf } plane { -z, %lf } } }", &hx, &lx, &hz, &lz), 4);
	/* plane { x, 2 } keeps x <= 2; plane { -x, 1 } keeps -x <= 1. */
	assert_near(hx, 2, 0.0);
	assert_near(lx, 1, 0.0);
	assert_near(hz, 6, 0.0);
	assert_near(lz, -2, 0.0);
	assert_null(strstr(text, "plane { y"));
	free(text);
	text = support_export_pov(u, RT_POV_FINISH_PLAIN);
	assert_null(strstr(text, "clipped_by"));
	assert_non_null(strstr(text, "texture {"));
	free(text);
	shape_destroy(s);
	shape_destroy(u);
}

static bool closed(const double coef[10], double rx, double ry, double rz, double lx, double ly,
		   double lz)
{
	struct shape *s = quadric(coef, rx, ry, rz, lx, ly, lz);
	bool c = shape_closed(s);

	shape_destroy(s);
	return c;
}

static void test_quadric_closed_only_as_a_whole_ellipsoid(void **state)
{
	/* (x-1)^2/4 + (y+2)^2 + (z-3)^2/9 = 1 times 36, with xy and yz
	 * terms a rotation would give them kept definite: 9 x^2 + 36 y^2 +
	 * 4 z^2 + ... */
	static const double ell[10] = { 9, 36, 4, 0, 0, 0, -18, 144, -24, 9 + 144 + 36 - 36 };
	static const double neg[10] = { -1, -1, -1, 0, 0, 0, 0, 0, 60, -500 };
	static const double tilted[10] = { 2, 2, 1, 1, 0, 0.5, 0, 0, 0, -1 };
	static const double hyperboloid[10] = { 1, 1, -1, 0, 0, 0, 0, 0, 0, -1 };
	static const double cylinder[10] = { 1, 1, 0, 0, 0, 0, 0, 0, 0, -1 };
	static const double empty[10] = { 1, 1, 1, 0, 0, 0, 0, 0, 0, 1 };
	static const double point[10] = { 1, 1, 1, 0, 0, 0, 0, 0, 0, 0 };
	static const double plane[10] = { 0, 0, 0, 0, 0, 0, 0, 0, 1, 0 };
	static const double saddle[10] = { 1, 1, 1, 3, 0, 0, 0, 0, 0, -1 };

	(void)state;
	assert_true(closed(sphere4, 0, 0, 0, 0, 0, 0));
	assert_true(closed(ell, 0, 0, 0, 0, 0, 0));
	/* The negated sphere of radius 20 about (0, 0, 30). */
	assert_true(closed(neg, 0, 0, 0, 0, 0, 0));
	assert_true(closed(tilted, 0, 0, 0, 0, 0, 0));
	/* Its extent is x in [-1, 3], y in [-3, -1], z in [0, 6]: a box
	 * holding it leaves it closed, one cutting it opens it. */
	assert_true(closed(ell, -1, -3, 0, 4, 2, 6));
	assert_true(closed(ell, -5, -5, -5, 10, 10, 0));
	assert_false(closed(ell, -1, -3, 0.1, 4, 2, 6));
	assert_false(closed(ell, -1, -3, 0, 3.9, 2, 6));
	assert_false(closed(sphere4, -3, -3, -1, 6, 6, 4));
	/* Extent 0 on z: clipped on x and y only, around it. */
	assert_true(closed(sphere4, -3, -3, -1, 6, 6, 0));
	assert_false(closed(hyperboloid, 0, 0, 0, 0, 0, 0));
	assert_false(closed(hyperboloid, -5, -5, -5, 10, 10, 10));
	assert_false(closed(cylinder, 0, 0, -1, 0, 0, 2));
	assert_false(closed(empty, 0, 0, 0, 0, 0, 0));
	assert_false(closed(point, 0, 0, 0, 0, 0, 0));
	assert_false(closed(plane, 0, 0, 0, 0, 0, 0));
	/* x^2 + y^2 + z^2 + 3 xy: the xy minor 1 - 9/4 < 0. */
	assert_false(closed(saddle, 0, 0, 0, 0, 0, 0));
}

SUPPORT_MAIN(SUPPORT_TESTS(test_quadric_unclipped_sphere, test_quadric_tangent_inside_non_unit,
			   test_quadric_clipped_near_root_falls_through,
			   test_quadric_clip_box_inclusive, test_quadric_clip_each_axis,
			   test_quadric_bounds_only_when_clipped_on_all_axes,
			   test_quadric_clip_on_three_axes, test_quadric_linear_case,
			   test_quadric_unit_normals, test_quadric_cross_terms,
			   test_quadric_normal_each_term, test_quadric_normal_all_terms,
			   test_quadric_hit_all_terms, test_quadric_parse,
			   test_quadric_export_pov,
			   test_quadric_closed_only_as_a_whole_ellipsoid))
