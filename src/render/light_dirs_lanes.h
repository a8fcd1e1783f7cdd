/* light_dirs (light_dirs.h) written once over base/lanes.h's vectors: the
 * including file, compiled for one set of instructions, defines
 * LIGHT_DIRS(name), the name it gets. */
#include "base/lanes.h"
#include "render/light_dirs.h"

static uint32_t LIGHT_DIRS(dirs)(const struct light_dirs_points *p, struct vec3 pos,
				 struct light_dirs *out, struct light_rays *rays)
{
	const lv one = lv_set1(1.0), x = lv_set1(pos.x), y = lv_set1(pos.y), z = lv_set1(pos.z);
	const lv zero = lv_set1(0.0);
	uint32_t asks = 0;
	int j;

	for (j = 0; j < LIGHT_DIRS_LANES; j += LANES_W) {
		lv tx = lv_sub(x, lv_load(p->px + j)), ty = lv_sub(y, lv_load(p->py + j));
		lv tz = lv_sub(z, lv_load(p->pz + j));
		lv dist = lv_sqrt(lv_add(lv_add(lv_mul(tx, tx), lv_mul(ty, ty)), lv_mul(tz, tz)));
		lv inv = lv_div(one, dist), nl, eps = lv_load(p->eps + j);
		lv lx = lv_mul(tx, inv), ly = lv_mul(ty, inv), lz = lv_mul(tz, inv);

		lv_store(out->lx + j, lx);
		lv_store(out->ly + j, ly);
		lv_store(out->lz + j, lz);
		lv_store(out->dist + j, dist);
		nl = lv_add(lv_add(lv_mul(lv_load(p->nx + j), lx), lv_mul(lv_load(p->ny + j), ly)),
			    lv_mul(lv_load(p->nz + j), lz));
		lv_store(out->nl + j, nl);
		/* if (!(dist > eps)) continue; if (nl <= 0.0) continue; */
		asks |= (uint32_t)lm_bits(lm_andnot(lv_le(nl, zero), lv_gt(dist, eps))) << j;
		if (!rays)
			continue;
		/* vec3_add_scaled(p, l, eps), l; eps, dist - eps */
		lv_store(rays->p.ox + j, lv_add(lv_load(p->px + j), lv_mul(lx, eps)));
		lv_store(rays->p.oy + j, lv_add(lv_load(p->py + j), lv_mul(ly, eps)));
		lv_store(rays->p.oz + j, lv_add(lv_load(p->pz + j), lv_mul(lz, eps)));
		lv_store(rays->p.dx + j, lx);
		lv_store(rays->p.dy + j, ly);
		lv_store(rays->p.dz + j, lz);
		lv_store(rays->t_min + j, eps);
		lv_store(rays->t_max + j, lv_sub(dist, eps));
	}
	return asks;
}
