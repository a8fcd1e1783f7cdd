/* The packet solvers of every set of instructions this processor runs
 * (solve_packet.h: SSE2 or plain C, AVX2, AVX-512) against the single-ray
 * ones, ray by ray and to the bit: the mask of the rays hit, and t_max of
 * each (shrunk to the hit's t, or left as it was), for random packets and
 * random masks, rays from inside, grazing rays, roots exactly at t_min
 * and t_max, rays through a triangle's edges and corners and in its
 * plane, degenerate triangles, rays on the floor's edges and parallel to
 * it, and directions with -0, infinite and NaN components. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/simd.h"
#include "shapes/shapes.h"
#include "shapes/solve.h"
#include "shapes/solve_packet.h"
#include "support.h"
#include "whitted/image.h"

static const struct material mat = { { 1, 1, 1 }, 0.1, 0.5, 0.2, 0.1, 5, 0.0, 1.0 };

/* The set the test is run for (its state: SUPPORT_ISA_TESTS), with its
 * name; the test is skipped, and counted so, where this processor lacks
 * it. */
static int usable_sets(void **state, const struct solve_packet_set **sets, const char **names)
{
	enum rt_simd isa = SUPPORT_ISA_OF(state);

	support_need_isa(isa, solve_packet_set_of(isa) != NULL);
	sets[0] = solve_packet_set_of(isa);
	names[0] = support_isa_tag(isa);
	return 1;
}

/* A packet of RT_PACKET_MAX rays, each with its interval. */
struct lanes {
	struct ray r[RT_PACKET_MAX];
	struct ray_packet p;
	double t_min[RT_PACKET_MAX], t_max[RT_PACKET_MAX];
};

static void lanes_pack(struct lanes *l)
{
	int i;

	for (i = 0; i < RT_PACKET_MAX; i++)
		ray_packet_set(&l->p, i, &l->r[i]);
}

/* A direction with, now and then, components -0, 0, infinite or NaN. */
static struct vec3 odd_direction(void)
{
	double c[3];
	struct vec3 d = support_random_direction();
	int k;

	c[0] = d.x, c[1] = d.y, c[2] = d.z;
	for (k = 0; k < 3; k++) {
		double u = support_rng();
		if (u < 0.05)
			c[k] = -0.0;
		else if (u < 0.1)
			c[k] = 0.0;
		else if (u < 0.12)
			c[k] = support_rng() < 0.5 ? INFINITY : -INFINITY;
		else if (u < 0.13)
			c[k] = NAN;
	}
	return vec3_make(c[0], c[1], c[2]);
}

/* What the single-ray test says of ray i: hit or not, and t_max after. */
typedef bool (*single_fn)(const void *shape, const struct ray *r, double t_min, double *t);

/* Runs `packet` on l with `active`, and compares every lane with `single`:
 * the active ones' hits and t to the bit, the others' t_max untouched. */
static void compare_lanes(const char *what, const char *set, struct lanes *l, uint32_t active,
			  uint32_t got, const double *t_after, single_fn single, const void *shape)
{
	int i;

	for (i = 0; i < RT_PACKET_MAX; i++) {
		double t = l->t_max[i];
		bool hit = false;

		if (active >> i & 1)
			hit = single(shape, &l->r[i], l->t_min[i], &t);
		if ((active >> i & 1) && (hit != (bool)(got >> i & 1) ||
					  memcmp(&t, &t_after[i], sizeof(t)) != 0)) {
			print_error("%s (%s), ray %d: o (%.17g %.17g %.17g) d (%.17g %.17g %.17g) "
				    "in (%.17g, %.17g): alone %d at %.17g, in the packet %d at %.17g\n",
				    what, set, i, l->r[i].origin.x, l->r[i].origin.y, l->r[i].origin.z,
				    l->r[i].dir.x, l->r[i].dir.y, l->r[i].dir.z, l->t_min[i],
				    l->t_max[i], hit, t, (int)(got >> i & 1), t_after[i]);
			fail();
		}
		if (!(active >> i & 1) && memcmp(&l->t_max[i], &t_after[i], sizeof(t)) != 0) {
			print_error("%s (%s): ray %d not asked about, its t_max changed\n", what, set, i);
			fail();
		}
	}
}

/* An active mask: all rays, a run, or random bits. */
static uint32_t random_mask(void)
{
	double u = support_rng();

	if (u < 0.3)
		return ~(uint32_t)0;
	if (u < 0.5)
		return 0xffu << (8 * (int)(support_rng() * 4));
	return (uint32_t)(support_rng() * 4294967296.0) | 1u << (int)(support_rng() * 32);
}

/* The interval of a ray: open, or with a bound exactly at the root the
 * single test finds (so the strict comparisons are tested). */
static void random_interval(struct lanes *l, int i, double root)
{
	double u = support_rng();

	l->t_min[i] = 1e-9;
	l->t_max[i] = INFINITY;
	if (!isfinite(root))
		root = support_uniform(0, 50);
	if (u < 0.15)
		l->t_max[i] = root;
	else if (u < 0.3)
		l->t_min[i] = root;
	else if (u < 0.4)
		l->t_max[i] = support_uniform(0, 2 * root);
	else if (u < 0.45)
		l->t_min[i] = -INFINITY;
}

struct sphere_args {
	struct vec3 c;
	double r2;
};

static bool sphere_single(const void *shape, const struct ray *r, double t_min, double *t)
{
	const struct sphere_args *s = shape;
	double hit;

	if (!solve_ray_sphere(r, s->c, s->r2, t_min, *t, &hit))
		return false;
	*t = hit;
	return true;
}

static void test_solve_packet_sphere(void **state)
{
	const struct solve_packet_set *sets[3];
	const char *names[3];
	int n_sets = usable_sets(state, sets, names), k, i, j;

	(void)state;
	support_rng_seed(41);
	for (k = 0; k < 3000; k++) {
		struct sphere_args s;
		struct lanes l;
		bool exact = k % 4 == 0;
		double radius = exact ? floor(support_uniform(1, 5))
				: support_rng() < 0.1 ? 1e-6 : support_uniform(0.1, 10);
		uint32_t active = random_mask();

		s.c = support_random_point(20);
		if (exact)
			s.c = vec3_make(floor(s.c.x), floor(s.c.y), floor(s.c.z));
		s.r2 = radius * radius;
		for (i = 0; i < RT_PACKET_MAX; i++) {
			double u = support_rng(), t = INFINITY;
			struct vec3 aim = vec3_add(s.c, support_random_point(1.2 * radius));

			/* Outside towards the sphere, from inside, grazing (the
			 * aim on the silhouette), exactly tangent or from the
			 * surface along it (a sphere of integers, a ray along an
			 * axis at the radius: a discriminant of exactly 0, and
			 * q = 0 from the surface), or anywhere. */
			l.r[i].origin = u < 0.2 ? vec3_add(s.c, support_random_point(0.5 * radius))
						: support_random_point(60);
			if (exact) {
				double off = floor(support_uniform(-3, 3));
				l.r[i].origin = vec3_make(s.c.x + radius, s.c.y + (u < 0.5 ? off : 0), s.c.z);
				l.r[i].dir = vec3_make(0, support_rng() < 0.5 ? 1 : -1, 0);
			} else if (u < 0.6) {
				l.r[i].dir = vec3_sub(aim, l.r[i].origin);
			} else if (u < 0.75) {
				struct vec3 to = vec3_sub(s.c, l.r[i].origin);
				struct vec3 side = vec3_cross(to, support_random_direction());
				l.r[i].dir = vec3_add(vec3_normalize(to),
						      vec3_scale(vec3_normalize(side),
								 radius / (vec3_length(to) + 1e-300)));
			} else {
				l.r[i].dir = odd_direction();
			}
			(void)sphere_single(&s, &l.r[i], 1e-9, &t);
			random_interval(&l, i, t);
		}
		lanes_pack(&l);
		for (j = 0; j < n_sets; j++) {
			double t[RT_PACKET_MAX];
			uint32_t got;

			memcpy(t, l.t_max, sizeof(t));
			got = sets[j]->sphere(&l.p, active, s.c, s.r2, l.t_min, t);
			compare_lanes("sphere", names[j], &l, active, got & active, t, sphere_single, &s);
		}
	}
}

struct triangle_args {
	struct vec3 v0, e1, e2;
};

static bool triangle_single(const void *shape, const struct ray *r, double t_min, double *t)
{
	const struct triangle_args *tr = shape;
	double hit;

	if (!solve_ray_triangle(r, tr->v0, tr->e1, tr->e2, t_min, *t, &hit))
		return false;
	*t = hit;
	return true;
}

static void test_solve_packet_triangle(void **state)
{
	const struct solve_packet_set *sets[3];
	const char *names[3];
	int n_sets = usable_sets(state, sets, names), k, i, j;

	(void)state;
	support_rng_seed(43);
	for (k = 0; k < 3000; k++) {
		struct triangle_args tr;
		struct lanes l;
		struct vec3 b;
		uint32_t active = random_mask();
		double u = support_rng();

		/* Small integer corners (so that edges and corners are hit
		 * exactly), real ones, or a degenerate triangle. */
		if (u < 0.4) {
			struct vec3 c[3];
			int m;
			for (m = 0; m < 3; m++)
				c[m] = vec3_make(floor(support_uniform(-4, 4)), floor(support_uniform(-4, 4)),
						 floor(support_uniform(-4, 4)));
			tr.v0 = c[0];
			b = c[1];
			tr.e1 = vec3_sub(b, c[0]);
			tr.e2 = vec3_sub(c[2], c[0]);
		} else {
			tr.v0 = support_random_point(10);
			b = vec3_add(tr.v0, support_random_point(5));
			tr.e1 = vec3_sub(b, tr.v0);
			tr.e2 = u < 0.5 ? vec3_scale(tr.e1, support_uniform(-2, 2)) : support_random_point(5);
		}
		for (i = 0; i < RT_PACKET_MAX; i++) {
			double w = support_rng(), t = INFINITY;
			/* A point of the triangle's plane: inside, on an edge or
			 * a corner (u, v of 0, 1 or halves), or outside. */
			double a = w < 0.5 ? 0.5 * (int)(support_rng() * 3) : support_uniform(-0.3, 1.3);
			double c = w < 0.5 ? 0.5 * (int)(support_rng() * 3) : support_uniform(-0.3, 1.3);
			struct vec3 on = vec3_add(tr.v0, vec3_add(vec3_scale(tr.e1, a), vec3_scale(tr.e2, c)));

			if (w < 0.7) {
				l.r[i].origin = vec3_make(floor(support_uniform(-20, 20)), floor(support_uniform(-20, 20)),
							  floor(support_uniform(-20, 20)));
				l.r[i].dir = vec3_sub(on, l.r[i].origin);
			} else if (w < 0.8) {
				/* In the plane. */
				l.r[i].origin = on;
				l.r[i].dir = support_rng() < 0.5 ? tr.e1 : vec3_sub(tr.e2, tr.e1);
				l.r[i].origin = vec3_sub(l.r[i].origin, vec3_scale(l.r[i].dir, 3));
			} else {
				l.r[i].origin = support_random_point(20);
				l.r[i].dir = odd_direction();
			}
			(void)triangle_single(&tr, &l.r[i], 1e-9, &t);
			random_interval(&l, i, t);
		}
		lanes_pack(&l);
		for (j = 0; j < n_sets; j++) {
			double t[RT_PACKET_MAX];
			uint32_t got;

			memcpy(t, l.t_max, sizeof(t));
			got = sets[j]->triangle(&l.p, active, tr.v0, tr.e1, tr.e2, l.t_min, t);
			compare_lanes("triangle", names[j], &l, active, got & active, t, triangle_single,
				      &tr);
		}
	}
}

static bool floor_single(const void *shape, const struct ray *r, double t_min, double *t)
{
	return shape_intersect(shape, r, t_min, t);
}

/* The finite floor (a square of 40, half 20) and the infinite one, through
 * each set directly and through the floors' own packet methods. */
static void test_solve_packet_floor(void **state)
{
	const struct solve_packet_set *sets[3];
	const char *names[3];
	int n_sets = usable_sets(state, sets, names), k, i, j, f;
	struct shape *floors[2];

	(void)state;
	floors[0] = floor_create_view(40, 4, &mat);
	floors[1] = floor_create_view(INFINITY, 4, &mat);
	assert_non_null(floors[0]);
	assert_non_null(floors[1]);
	assert_non_null(floors[0]->ops->intersect_packet);
	assert_non_null(floors[1]->ops->intersect_packet);
	support_rng_seed(47);
	for (k = 0; k < 3000; k++) {
		struct lanes l;
		uint32_t active = random_mask();

		for (i = 0; i < RT_PACKET_MAX; i++) {
			double u = support_rng(), t = INFINITY;

			if (u < 0.4) {
				/* Straight down onto a point of a whole or half
				 * coordinate: the square's edges x, y = +-20 among
				 * them. */
				l.r[i].origin = vec3_make(0.5 * floor(support_uniform(-50, 50)),
							  0.5 * floor(support_uniform(-50, 50)),
							  support_uniform(-10, 10));
				l.r[i].dir = vec3_make(0, support_rng() < 0.2 ? -0.0 : 0.0,
						       support_rng() < 0.5 ? -1.0 : 1.0);
			} else if (u < 0.55) {
				/* Parallel to the plane, or in it. */
				l.r[i].origin = vec3_make(support_uniform(-30, 30), support_uniform(-30, 30),
							  support_rng() < 0.5 ? 0.0 : support_uniform(-5, 5));
				l.r[i].dir = vec3_make(support_uniform(-1, 1), support_uniform(-1, 1),
						       support_rng() < 0.5 ? -0.0 : 0.0);
			} else if (u < 0.85) {
				l.r[i].origin = support_random_point(40);
				l.r[i].dir = vec3_sub(vec3_make(support_uniform(-30, 30),
								support_uniform(-30, 30), 0),
						      l.r[i].origin);
			} else {
				l.r[i].origin = support_random_point(40);
				l.r[i].dir = odd_direction();
			}
			(void)floor_single(floors[0], &l.r[i], 1e-9, &t);
			random_interval(&l, i, t);
		}
		lanes_pack(&l);
		for (f = 0; f < 2; f++) {
			double t[RT_PACKET_MAX];
			uint32_t got;

			for (j = 0; j < n_sets; j++) {
				memcpy(t, l.t_max, sizeof(t));
				got = sets[j]->floor(&l.p, active, f == 0, 20.0, l.t_min, t);
				compare_lanes(f ? "infinite floor" : "floor", names[j], &l, active,
					      got & active, t, floor_single, floors[f]);
			}
			memcpy(t, l.t_max, sizeof(t));
			got = shape_intersect_packet(floors[f], &l.p, active, l.t_min, t);
			compare_lanes(f ? "infinite floor's method" : "floor's method", "chosen", &l,
				      active, got, t, floor_single, floors[f]);
		}
	}
	shape_destroy(floors[0]);
	shape_destroy(floors[1]);
}

/* The sphere's and the triangle's own packet methods (the set the
 * processor's widest instructions choose) give their intersect's answers. */
static void test_solve_packet_shape_methods(void **state)
{
	struct shape *shapes[2];
	int k, i, m;

	(void)state;
	shapes[0] = sphere_create(vec3_make(1, 2, 3), 4, &mat);
	shapes[1] = triangle_create(vec3_make(-3, 0, 0), vec3_make(3, 1, 0), vec3_make(0, 4, 2), &mat);
	support_rng_seed(53);
	for (m = 0; m < 2; m++) {
		assert_non_null(shapes[m]);
		assert_non_null(shapes[m]->ops->intersect_packet);
		for (k = 0; k < 500; k++) {
			struct lanes l;
			double t[RT_PACKET_MAX];
			uint32_t active = random_mask(), got;

			for (i = 0; i < RT_PACKET_MAX; i++) {
				l.r[i].origin = support_random_point(15);
				l.r[i].dir = vec3_sub(support_random_point(4), l.r[i].origin);
				random_interval(&l, i, support_uniform(0, 20));
			}
			lanes_pack(&l);
			memcpy(t, l.t_max, sizeof(t));
			got = shape_intersect_packet(shapes[m], &l.p, active, l.t_min, t);
			compare_lanes(shapes[m]->ops->keyword, "chosen", &l, active, got, t, floor_single,
				      shapes[m]);
		}
		shape_destroy(shapes[m]);
	}
}

/* A point for the cell and normal tests: anywhere, on a cell's edge
 * (a multiple of the cell, then shifted as the square's cells are), huge
 * (cells past 2^31, sums past 2^53), -0, infinite or NaN now and then. */
static double odd_coordinate(double half, double cell)
{
	double u = support_rng();

	if (u < 0.25)
		return floor(support_uniform(-60, 60)) * cell - half;
	if (u < 0.3)
		return -0.0;
	if (u < 0.4)
		return support_uniform(-1, 1) * ldexp(1.0, (int)support_uniform(30, 70)) * cell;
	if (u < 0.42)
		return support_rng() < 0.5 ? INFINITY : -INFINITY;
	if (u < 0.43)
		return NAN;
	return support_uniform(-600, 600);
}

static bool same_bits(double a, double b)
{
	return memcmp(&a, &b, sizeof(a)) == 0;
}

/* Fills the lanes of `active`'s runs of p with points; the others NaN, so
 * that a method reading outside the runs it may read shows. */
static void random_points(double p[3][RT_PACKET_MAX], uint32_t active, double half, double cell,
			  bool finite)
{
	int i, k;

	for (i = 0; i < RT_PACKET_MAX; i++)
		for (k = 0; k < 3; k++) {
			double v = odd_coordinate(half, cell);
			/* A texel's place is not defined past the finite (floor.c
			 * is never asked there: hit points are finite). */
			while (finite && !(fabs(v) < 1e15))
				v = odd_coordinate(half, cell);
			p[k][i] = active >> (i / RT_PACKET_RUN * RT_PACKET_RUN) & 0xffu
					  ? (k == 2 ? 0.0 : v)
					  : NAN;
		}
}

/* The checkerboard's colours of every set against floor.c's color_at
 * (the square and the infinite plane), to the bit. */
static void test_solve_packet_floor_cells(void **state)
{
	const struct solve_packet_set *sets[3];
	const char *names[3];
	int n_sets = usable_sets(state, sets, names), k, i, j, ch;

	(void)state;
	support_rng_seed(43);
	for (k = 0; k < 4000; k++) {
		double cell = k % 3 == 0 ? 20 : k % 3 == 1 ? 30 : support_uniform(0.01, 100);
		double width = k % 2 ? 1000 : INFINITY, half = width / 2;
		struct shape *fl = floor_create_view(width, cell, &mat);
		double p[3][RT_PACKET_MAX], c[3][RT_PACKET_MAX];
		const double *const pv[3] = { p[0], p[1], p[2] };
		double *const cv[3] = { c[0], c[1], c[2] };
		uint32_t active = random_mask();

		assert_non_null(fl);
		random_points(p, active, k % 2 ? half : 0.0, cell, false);
		for (j = 0; j <= n_sets; j++) {
			for (i = 0; i < RT_PACKET_MAX; i++)
				c[0][i] = c[1][i] = c[2][i] = -1.0;
			/* Each set's kernel, then the floor's own method. */
			if (j < n_sets)
				sets[j]->floor_cells(pv, active, k % 2, half, cell, cv);
			else
				shape_color_packet(fl, pv, active, cv);
			for (i = 0; i < RT_PACKET_MAX; i++) {
				struct color want;
				if (!(active >> i & 1))
					continue;
				want = shape_color_at(fl, vec3_make(p[0][i], p[1][i], p[2][i]));
				for (ch = 0; ch < 3; ch++)
					if (!same_bits(c[ch][i], ch == 0 ? want.r : ch == 1 ? want.g : want.b)) {
						print_error("floor cells (%s, width %g, cell %.17g), lane %d at (%.17g, %.17g): %.17g, color_at %.17g\n",
							    j < n_sets ? names[j] : "method", width, cell, i,
							    p[0][i], p[1][i], c[ch][i], want.r);
						fail();
					}
			}
		}
		shape_destroy(fl);
	}
}

/* The normals of the sphere (every set's kernel and its method), the
 * triangle and the floor against their normal methods, to the bit, and
 * a textured floor's colours against its color_at; lanes outside the
 * mask's runs are never written. */
static void test_solve_packet_normal_methods(void **state)
{
	const struct solve_packet_set *sets[3];
	const char *names[3];
	int n_sets = usable_sets(state, sets, names), k, i, j, ch, m;
	struct shape *shapes[5];
	char path[] = "/tmp/whitted-cells-XXXXXX";
	struct image img;
	struct diag d;
	int fd;

	(void)state;
	/* A 3 x 2 texture of distinct texels. */
	fd = mkstemp(path);
	assert_true(fd >= 0);
	close(fd);
	assert_int_equal(image_alloc(&img, 3, 2, &d), 0);
	for (i = 0; i < 18; i++)
		img.pixels[i] = (uint8_t)(i * 14 + 3);
	assert_int_equal(image_write(&img, path, RT_FORMAT_PNG, NULL, &d), 0);
	image_free(&img);
	shapes[0] = sphere_create(vec3_make(1, -2, 3), 4.5, &mat);
	shapes[1] = triangle_create(vec3_make(-3, 0, 0), vec3_make(3, 1, 0), vec3_make(0, 4, 2), &mat);
	shapes[2] = floor_create_view(1000, 20, &mat);
	shapes[3] = floor_create_view(INFINITY, 7, &mat);
	shapes[4] = floor_create_view(1000, 20, &mat);
	for (m = 0; m < 5; m++)
		assert_non_null(shapes[m]);
	assert_int_equal(floor_set_textures(shapes[4], path, path, &d), 0);
	unlink(path);
	support_rng_seed(47);
	for (k = 0; k < 2000; k++) {
		double p[3][RT_PACKET_MAX], n[3][RT_PACKET_MAX], c[3][RT_PACKET_MAX];
		const double *const pv[3] = { p[0], p[1], p[2] };
		double *const nv[3] = { n[0], n[1], n[2] };
		double *const cv[3] = { c[0], c[1], c[2] };
		uint32_t active = random_mask(), runs = 0;

		m = k % 5;
		random_points(p, active, 0.0, 20, m == 4);
		for (i = 0; i < RT_PACKET_MAX; i++)
			if (active >> (i / RT_PACKET_RUN * RT_PACKET_RUN) & 0xffu)
				runs |= (uint32_t)1 << i;
		if (m == 0)
			for (i = 0; i < RT_PACKET_MAX; i++)
				if (runs >> i & 1)
					p[2][i] = support_uniform(-5, 9);
		for (j = 0; j <= (m == 0 ? n_sets : 0); j++) {
			for (i = 0; i < RT_PACKET_MAX; i++)
				for (ch = 0; ch < 3; ch++)
					n[ch][i] = c[ch][i] = -7.0;
			if (m == 0 && j < n_sets)
				sets[j]->sphere_normal(pv, active, vec3_make(1, -2, 3), 1.0 / 4.5, nv);
			else
				shape_normal_packet(shapes[m], pv, active, nv);
			shape_color_packet(shapes[m], pv, active, cv);
			for (i = 0; i < RT_PACKET_MAX; i++) {
				struct vec3 want;
				struct color col;
				if (!(runs >> i & 1)) {
					for (ch = 0; ch < 3; ch++)
						if (n[ch][i] != -7.0 || c[ch][i] != -7.0) {
							print_error("%s: lane %d, outside the mask's runs, written\n",
								    shapes[m]->ops->keyword, i);
							fail();
						}
					continue;
				}
				if (!(active >> i & 1))
					continue;
				want = shape_normal(shapes[m], vec3_make(p[0][i], p[1][i], p[2][i]));
				col = shape_color_at(shapes[m], vec3_make(p[0][i], p[1][i], p[2][i]));
				if (!same_bits(n[0][i], want.x) || !same_bits(n[1][i], want.y) ||
				    !same_bits(n[2][i], want.z) || !same_bits(c[0][i], col.r) ||
				    !same_bits(c[1][i], col.g) || !same_bits(c[2][i], col.b)) {
					print_error("%s #%d (%s), lane %d at (%.17g %.17g %.17g): n (%.17g %.17g %.17g) / (%.17g %.17g %.17g), c %.17g / %.17g\n",
						    shapes[m]->ops->keyword, m, m == 0 && j < n_sets ? names[j] : "method",
						    i, p[0][i], p[1][i], p[2][i], n[0][i], n[1][i], n[2][i], want.x,
						    want.y, want.z, c[0][i], col.r);
					fail();
				}
			}
		}
	}
	for (m = 0; m < 5; m++)
		shape_destroy(shapes[m]);
}

SUPPORT_MAIN(SUPPORT_ISA_TESTS(test_solve_packet_sphere),
	     SUPPORT_ISA_TESTS(test_solve_packet_triangle),
	     SUPPORT_ISA_TESTS(test_solve_packet_floor),
	     SUPPORT_TESTS(test_solve_packet_shape_methods),
	     SUPPORT_ISA_TESTS(test_solve_packet_floor_cells),
	     SUPPORT_ISA_TESTS(test_solve_packet_normal_methods))
