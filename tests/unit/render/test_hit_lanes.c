/* A packet's hits a lane (hit_lanes.h) against render_point_at, hit by
 * hit and to the bit: the point, the normal turned to face the ray, d.N,
 * the mirror direction, the offset, the colour and the highlight's colour,
 * for packets over a sphere, a triangle, a cube, a clipped quadric (no
 * packet methods: the shapes' defaults), the square floor, the infinite
 * one and a textured one, mixed in one packet, with misses, random masks
 * of lanes and rays from either side; the lanes not hit copies of the
 * first one hit; and the vector parts of every set of instructions this
 * processor runs against the scalar arithmetic (the points, the turned
 * normal, d.N, R, the offsets of points and of origins, render_bounce),
 * with normals facing either way, d.N of 0 and -0, and huge, tiny,
 * infinite and NaN values. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/simd.h"
#include "render/render_kernels.h"
#include "render/hit_lanes.h"
#include "render/shade_math.h"
#include "shapes/shapes.h"
#include "render_fixture.h"
#include "support.h"
#include "whitted/image.h"

static const struct material mat = { { 0.3, 0.6, 0.9 }, 0.1, 0.5, 0.2, 0.1, 5, 0.0, 1.0 };

/* To the bit; any NaN for a NaN (which NaN an operation gives depends on
 * its operands' order, which the compiler chooses; no later step tells
 * one from another). */
static bool same(double a, double b)
{
	return memcmp(&a, &b, sizeof(a)) == 0 || (isnan(a) && isnan(b));
}

static bool same_vec(struct vec3 a, struct vec3 b)
{
	return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}

static bool same_color(struct color a, struct color b)
{
	return same(a.r, b.r) && same(a.g, b.g) && same(a.b, b.b);
}

/* A value for the shared part: ordinary, huge, tiny, 0, -0, inf or NaN. */
static double odd_value(void)
{
	double u = support_rng();

	if (u < 0.05)
		return 0.0;
	if (u < 0.1)
		return -0.0;
	if (u < 0.12)
		return support_rng() < 0.5 ? INFINITY : -INFINITY;
	if (u < 0.13)
		return NAN;
	if (u < 0.2)
		return support_uniform(-1, 1) * 1e200;
	if (u < 0.25)
		return support_uniform(-1, 1) * 1e-200;
	return support_uniform(-300, 300);
}

static void check_set(const struct hit_lanes_set *set, const char *name)
{
	int k, i;

	support_rng_seed(71);
	for (k = 0; k < 20000; k++) {
		struct hit_lanes h;
		double d[3][HIT_LANES];
		struct vec3 dv[HIT_LANES], nv[HIT_LANES], pv[HIT_LANES];

		for (i = 0; i < HIT_LANES; i++) {
			bool plain = support_rng() < 0.6;
			dv[i] = plain ? support_random_direction()
				      : vec3_make(odd_value(), odd_value(), odd_value());
			nv[i] = plain ? support_random_direction()
				      : vec3_make(odd_value(), odd_value(), odd_value());
			/* d.N of exactly 0 and -0 */
			if (support_rng() < 0.1) {
				dv[i] = vec3_make(1, 0, 0);
				nv[i] = vec3_make(support_rng() < 0.5 ? 0.0 : -0.0, 1, 0);
			}
			pv[i] = plain ? support_random_point(support_rng() < 0.5 ? 0.5 : 500)
				      : vec3_make(odd_value(), odd_value(), odd_value());
			d[0][i] = dv[i].x, d[1][i] = dv[i].y, d[2][i] = dv[i].z;
			h.pts.nx[i] = nv[i].x, h.pts.ny[i] = nv[i].y, h.pts.nz[i] = nv[i].z;
			h.pts.px[i] = pv[i].x, h.pts.py[i] = pv[i].y, h.pts.pz[i] = pv[i].z;
		}
		set->turn(d, &h);
		for (i = 0; i < HIT_LANES; i++) {
			/* render_point_in's lines */
			struct vec3 n = nv[i], refl;
			double dn = vec3_dot(dv[i], n), eps = render_offset(pv[i]);

			if (dn > 0.0) {
				n = vec3_neg(n);
				dn = -dn;
			}
			refl = vec3_add_scaled(dv[i], n, -2.0 * dn);
			if (!same_vec(n, vec3_make(h.pts.nx[i], h.pts.ny[i], h.pts.nz[i])) ||
			    !same(dn, h.dn[i]) || !same(eps, h.pts.eps[i]) ||
			    !same_vec(refl, vec3_make(h.refl[0][i], h.refl[1][i], h.refl[2][i]))) {
				print_error("%s, lane %d: d (%.17g %.17g %.17g) n (%.17g %.17g %.17g): "
					    "dn %.17g / %.17g, eps %.17g / %.17g, refl.x %.17g / %.17g\n",
					    name, i, dv[i].x, dv[i].y, dv[i].z, nv[i].x, nv[i].y, nv[i].z, dn,
					    h.dn[i], eps, h.pts.eps[i], refl.x, h.refl[0][i]);
				fail();
			}
		}
	}
}

/* offsets and bounce: render_offset of each origin, render_bounce of
 * each lane. */
static void check_rays(const struct hit_lanes_set *set, const char *name)
{
	int k, i;

	support_rng_seed(79);
	for (k = 0; k < 20000; k++) {
		struct ray_packet r, b;
		struct hit_lanes h;
		double t_min[HIT_LANES];

		for (i = 0; i < HIT_LANES; i++) {
			bool plain = support_rng() < 0.6;
			struct vec3 o = plain ? support_random_point(support_rng() < 0.5 ? 0.5 : 500)
					      : vec3_make(odd_value(), odd_value(), odd_value());
			r.ox[i] = o.x, r.oy[i] = o.y, r.oz[i] = o.z;
			h.pts.px[i] = odd_value(), h.pts.py[i] = odd_value(), h.pts.pz[i] = odd_value();
			h.refl[0][i] = odd_value(), h.refl[1][i] = odd_value(), h.refl[2][i] = odd_value();
			h.pts.eps[i] = plain ? 1e-6 * support_uniform(1, 500) : odd_value();
		}
		set->offsets(&r, t_min);
		set->bounce(&h, &b);
		/* points: ray_at of the hit lanes, the others the first's */
		{
			double t[HIT_LANES], d[3][HIT_LANES];
			struct light_dirs_points pts;
			uint32_t hits = (uint32_t)(support_rng() * 65535.0) + 1;
			int first = __builtin_ctz(hits);

			for (i = 0; i < HIT_LANES; i++) {
				r.dx[i] = odd_value(), r.dy[i] = odd_value(), r.dz[i] = odd_value();
				t[i] = support_rng() < 0.8 ? support_uniform(0, 1000) : odd_value();
			}
			set->points(&r, t, hits, &pts, d);
			for (i = 0; i < HIT_LANES; i++) {
				int k2 = hits >> i & 1 ? i : first;
				struct ray ray = ray_packet_get(&r, k2);
				struct vec3 at = ray_at(&ray, t[k2]);

				if (!same_vec(at, vec3_make(pts.px[i], pts.py[i], pts.pz[i])) ||
				    !same_vec(ray.dir, vec3_make(d[0][i], d[1][i], d[2][i]))) {
					print_error("%s, lane %d (of 0x%x): point x %.17g / %.17g\n", name,
						    i, hits, at.x, pts.px[i]);
					fail();
				}
			}
		}
		for (i = 0; i < HIT_LANES; i++) {
			struct render_point q;
			struct ray want;
			double eps = render_offset(vec3_make(r.ox[i], r.oy[i], r.oz[i]));

			q.p = vec3_make(h.pts.px[i], h.pts.py[i], h.pts.pz[i]);
			q.refl = vec3_make(h.refl[0][i], h.refl[1][i], h.refl[2][i]);
			q.eps = h.pts.eps[i];
			render_bounce(&q, &want);
			if (!same(eps, t_min[i]) ||
			    !same_vec(want.origin, vec3_make(b.ox[i], b.oy[i], b.oz[i])) ||
			    !same_vec(want.dir, vec3_make(b.dx[i], b.dy[i], b.dz[i]))) {
				print_error("%s, lane %d: offset %.17g / %.17g, bounce o.x %.17g / %.17g\n",
					    name, i, eps, t_min[i], want.origin.x, b.ox[i]);
				fail();
			}
		}
	}
}

/* Each set on its own, skipped (and counted so) where this processor
 * lacks it. */
static void test_hit_lanes_sets(void **state)
{
	const struct render_kernels *k = render_fixture_kernels(state);
	const char *tag = support_isa_tag(SUPPORT_ISA_OF(state));

	check_set(&k->hit, tag);
	check_rays(&k->hit, tag);
}

#define N_SHAPES 7

/* The nearest of the shapes along r, by a plain loop; NULL for none. */
static const struct shape *nearest(struct shape *const *shapes, int n, const struct ray *r,
				   double t_min, double *t)
{
	const struct shape *best = NULL;
	int k;

	*t = INFINITY;
	for (k = 0; k < n; k++)
		if (shape_intersect(shapes[k], r, t_min, t))
			best = shapes[k];
	return best;
}

static void test_hit_lanes_fill(void **state)
{
	const double coef[10] = { 1, 2, 0.5, 0, 0, 0, 0, 0, 0, -30 };
	char path[] = "/tmp/whitted-hits-XXXXXX";
	struct shape *shapes[N_SHAPES];
	struct image img;
	struct diag d;
	int fd, k, i, m, checked = 0;

	(void)state;
	fd = mkstemp(path);
	assert_true(fd >= 0);
	close(fd);
	assert_int_equal(image_alloc(&img, 2, 3, &d), 0);
	for (i = 0; i < 18; i++)
		img.pixels[i] = (uint8_t)(i * 13 + 7);
	assert_int_equal(image_write(&img, path, RT_FORMAT_PNG, NULL, &d), 0);
	image_free(&img);
	shapes[0] = sphere_create(vec3_make(10, 5, 8), 6, &mat);
	shapes[1] = triangle_create(vec3_make(-30, 0, 1), vec3_make(-5, 10, 1), vec3_make(-15, 5, 25),
				    &mat);
	shapes[2] = cube_create(vec3_make(5, -25, 0), 10, &mat);
	shapes[3] = quadric_create(coef, vec3_make(-10, -10, 5), vec3_make(8, 8, 8), &mat);
	shapes[4] = floor_create_view(1000, 20, &mat);
	shapes[5] = floor_create_view(INFINITY, 13, &mat);
	shapes[6] = floor_create_view(1000, 30, &mat);
	for (k = 0; k < N_SHAPES; k++)
		assert_non_null(shapes[k]);
	assert_int_equal(floor_set_textures(shapes[6], path, NULL, &d), 0);
	unlink(path);
	support_rng_seed(73);
	for (k = 0; k < 6000; k++) {
		/* The objects with one of the three floors (their planes agree). */
		struct shape *scene[5] = { shapes[0], shapes[1], shapes[2], shapes[3],
					   shapes[4 + k % 3] };
		struct ray r[HIT_LANES];
		struct ray_packet rp;
		double t[HIT_LANES];
		const struct shape *hit[HIT_LANES];
		struct hit_lanes h;
		int first = -1;
		uint32_t active = support_rng() < 0.5 ? 0xffffu
				  : (uint32_t)(support_rng() * 65536.0) & 0xffffu;
		struct vec3 eye = vec3_add(support_random_point(60), vec3_make(0, 0, 20));

		for (i = 0; i < HIT_LANES; i++) {
			struct vec3 aim = support_random_point(40);
			r[i].origin = support_rng() < 0.2 ? support_random_point(60) : eye;
			r[i].dir = vec3_normalize(vec3_sub(aim, r[i].origin));
			ray_packet_set(&rp, i, &r[i]);
			hit[i] = NULL;
			t[i] = -3.0;	/* not read where not active */
			if (!(active >> i & 1))
				continue;
			hit[i] = nearest(scene, 5, &r[i], render_offset(r[i].origin), &t[i]);
			if (hit[i] && first < 0)
				first = i;
		}
		hit_lanes_fill(&rp, active, t, hit, &h);
		for (i = 0; i < HIT_LANES; i++)
			if ((h.hits >> i & 1) != (hit[i] != NULL)) {
				print_error("packet %d, ray %d: hits bit %u\n", k, i, h.hits >> i & 1);
				fail();
			}
		for (i = 0; i < HIT_LANES && first >= 0; i++) {
			int src = h.hits >> i & 1 ? i : first;
			struct render_point want, got;

			render_point_at(&r[src], t[src], hit[src], &want);
			hit_lanes_point(&h, i, &got);
			got.spec = h.spec >> src & 1;
			if (got.spec)
				got.spec_color = h.spec_color[src];
			if (got.hit != want.hit || !same(got.t, want.t) || !same_vec(got.p, want.p) ||
			    !same_vec(got.n, want.n) || !same_vec(got.refl, want.refl) ||
			    !same(got.dn, want.dn) || !same(got.eps, want.eps) ||
			    !same_color(got.base, want.base) || got.spec != want.spec ||
			    (want.spec && !same_color(got.spec_color, want.spec_color))) {
				print_error("packet %d, lane %d (ray %d, a %s): p (%.17g %.17g %.17g) / "
					    "(%.17g %.17g %.17g), n.z %.17g / %.17g, base %.17g / %.17g, "
					    "spec %d / %d\n",
					    k, i, src, want.hit->ops->keyword, got.p.x, got.p.y, got.p.z,
					    want.p.x, want.p.y, want.p.z, got.n.z, want.n.z, got.base.r,
					    want.base.r, got.spec, want.spec);
				fail();
			}
			checked += h.hits >> i & 1;
		}
	}
	/* The packets met every kind of hit, lit from both sides. */
	assert_true(checked > 20000);
	for (m = 0; m < N_SHAPES; m++)
		shape_destroy(shapes[m]);
}

SUPPORT_MAIN(SUPPORT_ISA_TESTS(test_hit_lanes_sets),
	     SUPPORT_TESTS(test_hit_lanes_fill))
