/* hit_lanes' shared part (hit_lanes.h) written once over base/lanes.h's
 * vectors: the including file, compiled for one set of instructions,
 * defines HIT_LANES_FN(name), the name it gets.  The scalar lines each
 * step stands for are shade.c's render_point_in and shade_math.h's
 * render_offset. */
#include "base/lanes.h"
#include "render/hit_lanes.h"
#include "whitted/render.h"

static void HIT_LANES_FN(turn)(double (*d)[HIT_LANES], struct hit_lanes *out)
{
	const lv zero = lv_set1(0.0), one = lv_set1(1.0), sign = lv_set1(-0.0);
	struct light_dirs_points *p = &out->pts;
	int j;

	for (j = 0; j < HIT_LANES; j += LANES_W) {
		lv dx = lv_load(d[0] + j), dy = lv_load(d[1] + j), dz = lv_load(d[2] + j);
		lv nx = lv_load(p->nx + j), ny = lv_load(p->ny + j), nz = lv_load(p->nz + j);
		/* dn = vec3_dot(d, n); if (dn > 0) { n = -n; dn = -dn; } */
		lv dn = lv_add(lv_add(lv_mul(dx, nx), lv_mul(dy, ny)), lv_mul(dz, nz));
		lm flip = lv_gt(dn, zero);
		lv m = one, k;

		nx = lv_sel(flip, lv_neg(nx), nx);
		ny = lv_sel(flip, lv_neg(ny), ny);
		nz = lv_sel(flip, lv_neg(nz), nz);
		dn = lv_sel(flip, lv_neg(dn), dn);
		lv_store(p->nx + j, nx);
		lv_store(p->ny + j, ny);
		lv_store(p->nz + j, nz);
		lv_store(out->dn + j, dn);
		/* refl = vec3_add_scaled(d, n, -2.0 * dn) */
		k = lv_mul(lv_set1(-2.0), dn);
		lv_store(out->refl[0] + j, lv_add(dx, lv_mul(nx, k)));
		lv_store(out->refl[1] + j, lv_add(dy, lv_mul(ny, k)));
		lv_store(out->refl[2] + j, lv_add(dz, lv_mul(nz, k)));
		/* render_offset: m = ax > m ? ax : m, then ay, then az */
		m = lv_max_first(lv_andnot_bits(sign, lv_load(p->px + j)), m);
		m = lv_max_first(lv_andnot_bits(sign, lv_load(p->py + j)), m);
		m = lv_max_first(lv_andnot_bits(sign, lv_load(p->pz + j)), m);
		lv_store(p->eps + j, lv_mul(lv_set1(RT_EPSILON), m));
	}
}

/* render_offset of each origin: m = ax > m ? ax : m, then ay, then az. */
static void HIT_LANES_FN(offsets)(const struct ray_packet *r, double *t_min)
{
	const lv sign = lv_set1(-0.0);
	int j;

	for (j = 0; j < HIT_LANES; j += LANES_W) {
		lv m = lv_set1(1.0);

		m = lv_max_first(lv_andnot_bits(sign, lv_load(r->ox + j)), m);
		m = lv_max_first(lv_andnot_bits(sign, lv_load(r->oy + j)), m);
		m = lv_max_first(lv_andnot_bits(sign, lv_load(r->oz + j)), m);
		lv_store(t_min + j, lv_mul(lv_set1(RT_EPSILON), m));
	}
}

/* render_bounce: origin vec3_add_scaled(p, refl, eps), direction refl. */
static void HIT_LANES_FN(bounce)(const struct hit_lanes *h, struct ray_packet *out)
{
	int j;

	for (j = 0; j < HIT_LANES; j += LANES_W) {
		lv eps = lv_load(h->pts.eps + j);
		lv rx = lv_load(h->refl[0] + j), ry = lv_load(h->refl[1] + j);
		lv rz = lv_load(h->refl[2] + j);

		lv_store(out->ox + j, lv_add(lv_load(h->pts.px + j), lv_mul(rx, eps)));
		lv_store(out->oy + j, lv_add(lv_load(h->pts.py + j), lv_mul(ry, eps)));
		lv_store(out->oz + j, lv_add(lv_load(h->pts.pz + j), lv_mul(rz, eps)));
		lv_store(out->dx + j, rx);
		lv_store(out->dy + j, ry);
		lv_store(out->dz + j, rz);
	}
}

/* Each hit's point (ray_at: vec3_add_scaled(origin, dir, t)) into out's
 * points, and its ray's direction into d; the lanes not in `hits` (not
 * 0) copies of its first lane's. */
static void HIT_LANES_FN(points)(const struct ray_packet *r, const double *t, uint32_t hits,
				 struct light_dirs_points *out, double (*d)[HIT_LANES])
{
	const double *const o_of[3] = { r->ox, r->oy, r->oz }, *const d_of[3] = { r->dx, r->dy, r->dz };
	double *const p_of[3] = { out->px, out->py, out->pz };
	int first = __builtin_ctz(hits), j, k;
	const lv t0 = lv_set1(t[first]);

	for (k = 0; k < 3; k++) {
		const lv o0 = lv_set1(o_of[k][first]), d0 = lv_set1(d_of[k][first]);

		for (j = 0; j < HIT_LANES; j += LANES_W) {
			lm on = lm_from_bits(hits >> j);
			lv dk = lv_sel(on, lv_load(d_of[k] + j), d0);
			lv tk = lv_sel(on, lv_load(t + j), t0);
			lv ok = lv_sel(on, lv_load(o_of[k] + j), o0);

			lv_store(d[k] + j, dk);
			lv_store(p_of[k] + j, lv_add(ok, lv_mul(dk, tk)));
		}
	}
}
