/* The directions to a light a point a lane (light_dirs.h), in every set of
 * instructions this processor runs, against the shading's own arithmetic
 * (vec3_sub, vec3_length, vec3_scale by 1 / dist, vec3_dot), to the bit,
 * and the shadow rays against render_direct's (vec3_add_scaled(p, l,
 * eps), in (eps, dist - eps), asked for where dist > eps and not N.L <=
 * 0): random points and lights, a light exactly at a point (a distance of
 * 0, an infinite direction), huge and tiny distances. */
#include <math.h>
#include <stdbool.h>
#include <string.h>

#include "base/simd.h"
#include "render/render_kernels.h"
#include "render/light_dirs.h"
#include "render_fixture.h"
#include "support.h"

static bool same(double a, double b)
{
	return memcmp(&a, &b, sizeof(a)) == 0;
}

static void check_set(light_dirs_fn *set, const char *name)
{
	int k, i;

	support_rng_seed(61);
	for (k = 0; k < 4000; k++) {
		struct light_dirs_points p;
		struct light_dirs out;
		struct light_rays rays;
		uint32_t asks;
		struct vec3 pos = support_random_point(k % 5 == 0 ? 1e6 : 100);
		struct vec3 pt[LIGHT_DIRS_LANES], n[LIGHT_DIRS_LANES];

		for (i = 0; i < LIGHT_DIRS_LANES; i++) {
			double u = support_rng();
			pt[i] = u < 0.1 ? pos : u < 0.2 ? vec3_add(pos, support_random_point(1e-9))
						 : support_random_point(100);
			n[i] = support_random_direction();
			p.px[i] = pt[i].x, p.py[i] = pt[i].y, p.pz[i] = pt[i].z;
			p.nx[i] = n[i].x, p.ny[i] = n[i].y, p.nz[i] = n[i].z;
			p.eps[i] = u < 0.3 ? 1e-6 * 100 : support_uniform(0.0, 1.0);
		}
		asks = set(&p, pos, &out, k % 2 ? &rays : NULL);
		for (i = 0; i < LIGHT_DIRS_LANES; i++) {
			struct vec3 to = vec3_sub(pos, pt[i]), l;
			double dist = vec3_length(to), nl;

			l = vec3_scale(to, 1.0 / dist);
			nl = vec3_dot(n[i], l);
			if (memcmp(&dist, &out.dist[i], sizeof(dist)) != 0 ||
			    memcmp(&l.x, &out.lx[i], sizeof(double)) != 0 ||
			    memcmp(&l.y, &out.ly[i], sizeof(double)) != 0 ||
			    memcmp(&l.z, &out.lz[i], sizeof(double)) != 0 ||
			    memcmp(&nl, &out.nl[i], sizeof(nl)) != 0) {
				print_error("%s, lane %d: dist %.17g / %.17g, l (%.17g %.17g %.17g) / "
					    "(%.17g %.17g %.17g), nl %.17g / %.17g\n",
					    name, i, dist, out.dist[i], l.x, l.y, l.z, out.lx[i], out.ly[i],
					    out.lz[i], nl, out.nl[i]);
				fail();
			}
			if ((asks >> i & 1) != (dist > p.eps[i] && !(nl <= 0.0))) {
				print_error("%s, lane %d: asked %u for dist %.17g, eps %.17g, nl %.17g\n",
					    name, i, asks >> i & 1, dist, p.eps[i], nl);
				fail();
			}
			if (k % 2) {
				struct vec3 o = vec3_add_scaled(pt[i], l, p.eps[i]);
				if (!same(o.x, rays.p.ox[i]) || !same(o.y, rays.p.oy[i]) ||
				    !same(o.z, rays.p.oz[i]) || !same(l.x, rays.p.dx[i]) ||
				    !same(l.y, rays.p.dy[i]) || !same(l.z, rays.p.dz[i]) ||
				    !same(p.eps[i], rays.t_min[i]) ||
				    !same(dist - p.eps[i], rays.t_max[i])) {
					print_error("%s, lane %d: the shadow ray differs\n", name, i);
					fail();
				}
			}
		}
	}
}

/* Each set on its own (skipped, and counted so, where this processor
 * lacks it), and the one chosen at run time. */
static void test_light_dirs_set(void **state)
{
	const struct render_kernels *k = render_fixture_kernels(state);

	check_set(k->light_dirs, support_isa_tag(SUPPORT_ISA_OF(state)));
}

static void test_light_dirs_chosen_set(void **state)
{
	(void)state;
	check_set(light_dirs, "chosen");
}

SUPPORT_MAIN(SUPPORT_ISA_TESTS(test_light_dirs_set),
	     SUPPORT_TESTS(test_light_dirs_chosen_set))
