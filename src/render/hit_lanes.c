/* hit_lanes (hit_lanes.h): the points, the shapes' normals and colours a
 * call a shape of the packet, then the shared part in the set of
 * instructions in use (render_kernels.h). */
#include "render/render_kernels.h"

static const struct hit_lanes_set *chosen(void)
{
	return &render_kernels()->hit;
}

/* Long: the hits' lanes filled shape by shape, then the shared vector part:
 * one pass over the packet's lanes. */
void hit_lanes_fill(const struct ray_packet *r, uint32_t active, const double *t,
		    const struct shape *const *hit, struct hit_lanes *out)
{
	struct light_dirs_points *p = &out->pts;
	double *const nv[3] = { p->nx, p->ny, p->nz };
	double *const cv[3] = { out->base[0], out->base[1], out->base[2] };
	const double *const pc[3] = { p->px, p->py, p->pz };
	const struct hit_lanes_set *set = chosen();
	const uint32_t all = ((uint32_t)1 << HIT_LANES) - 1;
	double d[3][HIT_LANES];
	uint32_t left, m;
	int i, first;

	out->hits = 0;
	out->spec = 0;
	for (m = active; m; m &= m - 1)
		if (hit[__builtin_ctz(m)])
			out->hits |= (uint32_t)1 << __builtin_ctz(m);
	if (!out->hits)
		return;
	first = __builtin_ctz(out->hits);
	for (i = 0; i < HIT_LANES; i++) {
		int k = out->hits >> i & 1 ? i : first;

		out->hit[i] = hit[k];
		out->t[i] = t[k];
	}
	set->points(r, t, out->hits, p, d);
	/* Each shape once, for its lanes hit. */
	for (left = out->hits; left;) {
		const struct shape *s = out->hit[__builtin_ctz(left)];
		uint32_t same = 0;

		for (m = left; m; m &= m - 1)
			if (out->hit[__builtin_ctz(m)] == s)
				same |= (uint32_t)1 << __builtin_ctz(m);
		left &= ~same;
		/* One shape for every hit: its methods' writes past them are
		 * overwritten below. */
		if (same == out->hits) {
			shape_normal_packet(s, pc, same, nv);
			shape_color_packet(s, pc, same, cv);
		} else {
			/* The methods may write whole runs: into room of their
			 * own, of which this shape's lanes are kept. */
			double n_own[3][HIT_LANES], c_own[3][HIT_LANES];
			double *const nw[3] = { n_own[0], n_own[1], n_own[2] };
			double *const cw[3] = { c_own[0], c_own[1], c_own[2] };
			int k;

			shape_normal_packet(s, pc, same, nw);
			shape_color_packet(s, pc, same, cw);
			for (m = same; m; m &= m - 1)
				for (k = 0; k < 3; k++) {
					nv[k][__builtin_ctz(m)] = n_own[k][__builtin_ctz(m)];
					cv[k][__builtin_ctz(m)] = c_own[k][__builtin_ctz(m)];
				}
		}
		for (m = same; m; m &= m - 1) {
			int b = __builtin_ctz(m);
			if (shape_specular_color_at(s, vec3_make(p->px[b], p->py[b], p->pz[b]),
						    &out->spec_color[b]))
				out->spec |= (uint32_t)1 << b;
		}
	}
	/* The lanes not hit: the first one's values, as its copies. */
	for (m = all & ~out->hits; m; m &= m - 1) {
		int b = __builtin_ctz(m), k;
		for (k = 0; k < 3; k++) {
			nv[k][b] = nv[k][first];
			cv[k][b] = cv[k][first];
		}
	}
	set->turn(d, out);
}

void hit_lanes_point(const struct hit_lanes *h, int i, struct render_point *out)
{
	const struct light_dirs_points *p = &h->pts;

	out->hit = h->hit[i];
	out->t = h->t[i];
	out->p = vec3_make(p->px[i], p->py[i], p->pz[i]);
	out->n = vec3_make(p->nx[i], p->ny[i], p->nz[i]);
	out->refl = vec3_make(h->refl[0][i], h->refl[1][i], h->refl[2][i]);
	out->dn = h->dn[i];
	out->eps = p->eps[i];
	out->base = color_make(h->base[0][i], h->base[1][i], h->base[2][i]);
	out->spec = h->spec >> i & 1;
	out->spec_color = out->spec ? h->spec_color[i] : color_make(0.0, 0.0, 0.0);
}

void hit_lanes_offsets(const struct ray_packet *r, double *t_min)
{
	chosen()->offsets(r, t_min);
}

void hit_lanes_bounce(const struct hit_lanes *h, struct ray_packet *out)
{
	chosen()->bounce(h, out);
}
