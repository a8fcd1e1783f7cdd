/* shade_lanes (shade_lanes.h) written once over base/lanes.h's vectors:
 * the including file, compiled for one set of instructions, defines
 * SHADE_LANES_FN(name), the name it gets.  The scalar lines each step
 * stands for are shade.c's render_direct, render_specular,
 * render_light_term and render_shade_from (with the rules 0). */
#include <math.h>

#include "base/lanes.h"
#include "render/shade_lanes.h"

/* Long: render_direct, render_light_term and render_shade_from in vector form,
 * step for step in their order, which is what keeps the bits equal; split,
 * the steps would no longer read against those lines. */
static uint64_t SHADE_LANES_FN(sum)(const struct shade_lanes *in,
				    const struct render_shadows *pre,
				    const struct light *lights, size_t n_lights,
				    double out[3][SHADE_LANES])
{
	const lv zero = lv_set1(0.0), one = lv_set1(1.0);
	const unsigned group = (1u << LANES_W) - 1;
	uint64_t asked = 0;
	int j;

	for (j = 0; j < SHADE_LANES; j += LANES_W) {
		unsigned lanes = in->lanes >> j & group;
		lv br, bg, bb, kd, ks, eps, rx, ry, rz, cr, cg, cb;
		lv dr = zero, dg = zero, db = zero;
		lm own;
		size_t i;

		if (!lanes)
			continue;
		own = lm_from_bits(lanes);
		br = lv_load(in->base[0] + j);
		bg = lv_load(in->base[1] + j);
		bb = lv_load(in->base[2] + j);
		kd = lv_load(in->kd + j);
		ks = lv_load(in->ks + j);
		eps = lv_load(in->eps + j);
		rx = lv_load(in->refl[0] + j);
		ry = lv_load(in->refl[1] + j);
		rz = lv_load(in->refl[2] + j);
		for (i = 0; i < n_lights; i++) {
			const struct light_dirs *dl = &pre->dirs[i];
			lv lx = lv_load(dl->lx + j), ly = lv_load(dl->ly + j), lz = lv_load(dl->lz + j);
			lv nl = lv_load(dl->nl + j), k, rl, pw;
			/* if (!(dist > eps)) continue; if (nl <= 0.0) continue; */
			lm asks = lm_and(own, lm_andnot(lv_le(nl, zero),
							lv_gt(lv_load(dl->dist + j), eps)));
			unsigned lit = lm_bits(asks) & ~(pre->blocked[i] >> j), up, m;
			double rls[LANES_W], pws[LANES_W];
			lm on;

			asked += (uint64_t)__builtin_popcount(lm_bits(asks));
			if (!lit)
				continue;
			on = lm_from_bits(lit);
			/* k = kd nl; if (R.L > 0) k += ks rl^shininess */
			k = lv_mul(kd, nl);
			rl = lv_add(lv_add(lv_mul(rx, lx), lv_mul(ry, ly)), lv_mul(rz, lz));
			up = lm_bits(lv_gt(rl, zero)) & lit;
			lv_store(rls, rl);
			lv_store(pws, rl);
			for (m = up; m; m &= m - 1) {
				int b = __builtin_ctz(m);
				double shin = in->shininess[j + b];
				/* render_specular_power */
				if (shin != 1.0)
					pws[b] = pow(rls[b], shin);
			}
			pw = lv_load(pws);
			k = lv_sel(lm_from_bits(up), lv_add(k, lv_mul(ks, pw)), k);
			/* c += (Lc C) k */
			dr = lv_sel(on, lv_add(dr, lv_mul(lv_mul(lv_set1(lights[i].color.r), br), k)), dr);
			dg = lv_sel(on, lv_add(dg, lv_mul(lv_mul(lv_set1(lights[i].color.g), bg), k)), dg);
			db = lv_sel(on, lv_add(db, lv_mul(lv_mul(lv_set1(lights[i].color.b), bb), k)), db);
		}
		/* c = ka C + the direct sum */
		{
			lv ka = lv_load(in->ka + j);
			cr = lv_add(lv_mul(br, ka), dr);
			cg = lv_add(lv_mul(bg, ka), dg);
			cb = lv_add(lv_mul(bb, ka), db);
		}
		/* + kr I(reflection) */
		if (in->reflects >> j & group) {
			lm refl = lm_from_bits(in->reflects >> j & group);
			lv kr = lv_load(in->kr + j);
			cr = lv_sel(refl, lv_add(cr, lv_mul(lv_load(in->seen[0] + j), kr)), cr);
			cg = lv_sel(refl, lv_add(cg, lv_mul(lv_load(in->seen[1] + j), kr)), cg);
			cb = lv_sel(refl, lv_add(cb, lv_mul(lv_load(in->seen[2] + j), kr)), cb);
		}
		/* render_clamp01: MAXSD(v, 0), then MINSD(1, that) */
		if (in->clamp) {
			cr = lv_min_first(one, lv_max_first(cr, zero));
			cg = lv_min_first(one, lv_max_first(cg, zero));
			cb = lv_min_first(one, lv_max_first(cb, zero));
		}
		lv_store(out[0] + j, cr);
		lv_store(out[1] + j, cg);
		lv_store(out[2] + j, cb);
	}
	return asked;
}
