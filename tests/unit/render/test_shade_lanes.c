/* The packets' shading a hit a lane (shade_lanes.h), in every set of
 * instructions this processor runs, against render_shade_point, the
 * shading one hit at a time, to the bit: random hits with random
 * materials (shininess 1, whole and fractional, ambient, diffuse,
 * specular and mirror weights), colours beyond 1, one to eight coloured
 * lights some of them blocked, lights behind the surface (N.L < 0), in
 * its plane (N.L = +0 and -0) and at the point (a distance within the
 * offset), a NaN N.L, a reflection's
 * colour or none, colours clamped at each level or only at the end; and
 * the count of shadow rays asked about. */
#include <math.h>
#include <string.h>

#include "base/simd.h"
#include "render/render_kernels.h"
#include "render/shade_hit.h"
#include "render/shade_lanes.h"
#include "scene/scene_impl.h"
#include "render_fixture.h"
#include "support.h"
#include "whitted/render.h"

#define SHAPES 12

static double pick(const double *v, int n)
{
	return v[(int)(support_rng() * n) % n];
}

/* A scene of SHAPES spheres (only their materials matter), half of them
 * mirrors, and n_lights point lights. */
static struct scene *lanes_scene(int n_lights)
{
	static const double shininess[] = { 1.0, 1.0, 2.0, 5.0, 10.0, 15.0, 0.5, 37.25 };
	struct scene *s = scene_create("lanes");
	struct diag d;
	int i;

	assert_non_null(s);
	for (i = 0; i < SHAPES; i++) {
		struct material m;

		memset(&m, 0, sizeof(m));
		m.color = color_make(support_rng(), support_rng(), support_rng());
		m.ka = support_uniform(0.0, 0.5);
		m.kd = support_uniform(0.0, 1.0);
		m.ks = support_uniform(0.0, 1.0);
		m.kr = i % 2 ? support_uniform(0.05, 0.9) : 0.0;
		m.shininess = pick(shininess, 8);
		m.ior = 1.0;
		assert_int_equal(scene_add_shape(s, sphere_create(vec3_make(i, 0, 0), 1.0, &m), &d), 0);
	}
	for (i = 0; i < n_lights; i++)
		assert_int_equal(scene_add_light(s, support_random_point(100),
						 color_make(support_uniform(0, 1.5), support_rng(),
							    support_rng()),
						 &d),
				 0);
	return s;
}

static struct color random_color(void)
{
	double big = support_rng() < 0.2 ? 3.0 : 1.0;

	return color_make(support_uniform(0, big), support_uniform(0, big), support_uniform(0, big));
}

static void check_set(shade_lanes_fn *set, const char *name)
{
	int trial;

	support_rng_seed(1203);
	for (trial = 0; trial < 3000; trial++) {
		int n_lights = 1 + trial % RENDER_SHADOW_KEPT, level = 1 + trial % 3, i, j;
		struct scene *s = lanes_scene(n_lights);
		struct render_settings rs = { 3, trial % 2 ? RT_CLAMP_LEVEL : RT_CLAMP_FINAL };
		struct render_point h[SHADE_LANES];
		struct color seen[SHADE_LANES];
		struct render_shadows pre;
		struct shade_lanes in;
		struct ray_counts counts;
		double out[3][SHADE_LANES];
		uint64_t asked;

		memset(&pre, 0, sizeof(pre));
		memset(&in, 0, sizeof(in));
		memset(&counts, 0, sizeof(counts));
		in.clamp = rs.clamp == RT_CLAMP_LEVEL;
		for (i = 0; i < SHADE_LANES; i++) {
			const struct shape *sh = s->shapes[(int)(support_rng() * SHAPES) % SHAPES];
			const struct material *m = &sh->mat;

			memset(&h[i], 0, sizeof(h[i]));
			h[i].hit = sh;
			h[i].p = support_random_point(50);
			h[i].n = support_random_direction();
			h[i].refl = support_random_direction();
			h[i].eps = 1e-6 * 50;
			h[i].base = random_color();
			seen[i] = random_color();
			if (support_rng() < 0.9)
				in.lanes |= 1u << i;
			/* A mirror's reflection is known below the last level;
			 * at it, a mirror reflects nothing. */
			if (m->kr > 0.0 && level < rs.recursion)
				in.reflects |= (in.lanes >> i & 1u) << i;
			in.base[0][i] = h[i].base.r;
			in.base[1][i] = h[i].base.g;
			in.base[2][i] = h[i].base.b;
			in.ka[i] = m->ka;
			in.kd[i] = m->kd;
			in.ks[i] = m->ks;
			in.kr[i] = m->kr;
			in.shininess[i] = m->shininess;
			in.refl[0][i] = h[i].refl.x;
			in.refl[1][i] = h[i].refl.y;
			in.refl[2][i] = h[i].refl.z;
			in.eps[i] = h[i].eps;
			in.seen[0][i] = seen[i].r;
			in.seen[1][i] = seen[i].g;
			in.seen[2][i] = seen[i].b;
		}
		for (j = 0; j < n_lights; j++) {
			struct light_dirs *dl = &pre.dirs[j];

			pre.traced[j] = ~(uint32_t)0;
			pre.blocked[j] = (uint32_t)(support_rng() * 65536.0);
			for (i = 0; i < SHADE_LANES; i++) {
				double u = support_rng();
				struct vec3 to = vec3_sub(s->lights[j].pos, h[i].p), l;
				double dist = vec3_length(to), nl;

				if (u < 0.05)
					dist = h[i].eps * support_rng();	/* the light at the point */
				l = vec3_scale(to, 1.0 / vec3_length(to));
				/* N.L exactly +0 and -0 (a light in the surface's
				 * plane, on either side): no light, no shadow ray. */
				nl = u > 0.97 ? NAN : u > 0.94 ? -0.0 : u > 0.91 ? 0.0 : vec3_dot(h[i].n, l);
				dl->lx[i] = l.x;
				dl->ly[i] = l.y;
				dl->lz[i] = l.z;
				dl->dist[i] = dist;
				dl->nl[i] = nl;
			}
		}
		asked = set(&in, &pre, s->lights, s->n_lights, out);
		for (i = 0; i < SHADE_LANES; i++) {
			struct ray r = { h[i].p, h[i].refl };
			struct color want;

			if (!(in.lanes >> i & 1))
				continue;
			pre.bit = i;
			want = render_shade_point(s, &rs, &r, &h[i], level, &counts, &pre,
						  in.reflects >> i & 1 ? &seen[i] : NULL);
			if (memcmp(&want.r, &out[0][i], sizeof(double)) != 0 ||
			    memcmp(&want.g, &out[1][i], sizeof(double)) != 0 ||
			    memcmp(&want.b, &out[2][i], sizeof(double)) != 0) {
				print_error("%s, trial %d, lane %d: (%.17g %.17g %.17g), the shading "
					    "(%.17g %.17g %.17g)\n",
					    name, trial, i, out[0][i], out[1][i], out[2][i], want.r, want.g,
					    want.b);
				fail();
			}
		}
		assert_int_equal(asked, counts.shadow);
		scene_destroy(s);
	}
}

/* Each set on its own (skipped, and counted so, where this processor
 * lacks it), and the one chosen at run time. */
static void test_shade_lanes_set(void **state)
{
	const struct render_kernels *k = render_fixture_kernels(state);

	check_set(k->shade_lanes, support_isa_tag(SUPPORT_ISA_OF(state)));
}

static void test_shade_lanes_chosen_set(void **state)
{
	(void)state;
	check_set(shade_lanes, "chosen");
}

SUPPORT_MAIN(SUPPORT_ISA_TESTS(test_shade_lanes_set),
	     SUPPORT_TESTS(test_shade_lanes_chosen_set))
