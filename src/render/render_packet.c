/* The primary rays of a block in packets of 4x4 pixels, and their hits'
 * shadow rays in one packet a light: neighbouring rays meet the same
 * nodes, which a packet then loads and tests once for all
 * (accel_intersect_packet, accel_occluded_packet: four rays to an AVX2
 * operation), and each pixel is shaded from its ray's hit with those
 * shadow answers as render_trace would shade it (shade_hit.h).  Mirrors'
 * reflections go on as packets of their own, down to PACKET_DEPTH, where
 * the packets' walks take a ray a lane (accel_packets_scatter_pay: the
 * reflected rays part, and a ray a lane does not mind); elsewhere they
 * are single rays. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "render/camera_lanes.h"
#include "render/camera_span.h"
#include "render/hit_lanes.h"
#include "render/render_packet.h"
#include "render/shade_lanes.h"
#include "render/shade_hit.h"
#include "render/shade_math.h"
#include "scene/scene_impl.h"

/* A packet's shadow rays are one accel packet, their directions one
 * light_dirs call and the shape tests whole runs of RT_PACKET_RUN lanes. */
typedef char packet_widths_agree[ACCEL_PACKET == RENDER_SHADOW_POINTS &&
						 ACCEL_PACKET == LIGHT_DIRS_LANES &&
						 ACCEL_PACKET % RT_PACKET_RUN == 0 &&
						 ACCEL_PACKET <= RT_PACKET_MAX ? 1 : -1];

#define PACKET_SIDE 4	/* PACKET_SIDE^2 <= ACCEL_PACKET */

/* A packet's lanes are the walks', the camera's and the hits' alike. */
typedef char packet_lanes_agree[ACCEL_PACKET == CAMERA_LANES && ACCEL_PACKET == HIT_LANES &&
						PACKET_SIDE * PACKET_SIDE <= ACCEL_PACKET
					? 1
					: -1];

/* The lanes [0, n). */
static uint32_t packet_lanes(int n)
{
	return n >= 32 ? ~(uint32_t)0 : ((uint32_t)1 << n) - 1;
}

bool render_packets_wanted(const struct accel *a)
{
	return accel_packets_wanted(a);
}

/* Packets go down this many levels of reflection where a packet's rays
 * need not agree (accel_packets_scatter_pay); deeper ones are traced ray
 * by ray by the shading (a level's frame is about 12 KB of stack, which
 * the workers have: base/thread.h). */
#define PACKET_DEPTH 8

/* The hits among h's that shade_lanes shades as render_shade_point
 * would (shade_lanes.h: point lights only, all of whose shadow answers
 * the packet has; no highlight colour of a texture; no glass; a mirror's
 * reflection seen already: lane i of `reflects`, whose colour is seen[i]),
 * with what it needs of them in *sum; the other lanes are filled too, as
 * the vectors read them. */
static uint32_t lean_lanes(const struct render_job *job, const struct hit_lanes *h,
			   uint32_t reflects, const struct color *seen, int level,
			   struct shade_lanes *sum)
{
	const struct scene *sc = job->scene;
	bool deeper = level < job->settings.recursion;
	uint32_t hits = h->hits, lean = 0;
	int i, k;

	if (!hits || sc->n_special_lights || sc->n_lights > RENDER_SHADOW_KEPT)
		return 0;
	sum->reflects = 0;
	sum->clamp = job->settings.clamp == RT_CLAMP_LEVEL;
	for (i = 0; i < SHADE_LANES; i++) {
		const struct material *m = &h->hit[i]->mat;
		int q = hits >> i & 1 ? i : __builtin_ctz(hits);
		bool reflected = reflects >> i & 1;

		if (hits >> i & 1 && !(h->spec >> i & 1) && !(m->kt > 0.0) &&
		    (reflected || !(deeper && m->kr > 0.0))) {
			lean |= (uint32_t)1 << i;
			sum->reflects |= (uint32_t)reflected << i;
		}
		sum->ka[i] = m->ka;
		sum->kd[i] = m->kd;
		sum->ks[i] = m->ks;
		sum->kr[i] = m->kr;
		sum->shininess[i] = m->shininess;
		sum->seen[0][i] = reflected ? seen[i].r : h->base[0][q];
		sum->seen[1][i] = reflected ? seen[i].g : h->base[1][q];
		sum->seen[2][i] = reflected ? seen[i].b : h->base[2][q];
	}
	for (k = 0; k < 3; k++) {
		memcpy(sum->base[k], h->base[k], sizeof(sum->base[k]));
		memcpy(sum->refl[k], h->refl[k], sizeof(sum->refl[k]));
	}
	memcpy(sum->eps, h->pts.eps, sizeof(sum->eps));
	sum->lanes = lean;
	return lean;
}

/* Traces, in packets, the shadow rays that the shading points of pts'
 * lanes `mask` (at most ACCEL_PACKET of them; every lane filled) will ask
 * for (shade.c's render_direct and render_direct_full), and fills in
 * *out. */
static void render_shadow_packets(const struct scene *s, const struct light_dirs_points *pts,
				  uint32_t mask, struct render_shadows *out)
{
	size_t nl = s->n_lights < RENDER_SHADOW_LIGHTS ? s->n_lights : RENDER_SHADOW_LIGHTS, j;
	struct light_rays rays;

	if (!mask)
		return;
	for (j = 0; j < nl; j++) {
		const struct light *lt = &s->lights[j];
		struct light_dirs own, *dirs = j < RENDER_SHADOW_KEPT ? &out->dirs[j] : &own;
		uint32_t m, asks;

		/* The rays render_direct (or render_direct_full) makes, by the
		 * same arithmetic, and only where it makes one. */
		asks = light_dirs(pts, lt->pos, dirs, &rays) & mask;
		if (lt->spot)
			for (m = asks; m; m &= m - 1) {
				int b = __builtin_ctz(m);
				struct vec3 l = vec3_make(dirs->lx[b], dirs->ly[b], dirs->lz[b]);
				if (!(-vec3_dot(l, lt->axis) >= lt->cos_cutoff))
					asks &= ~((uint32_t)1 << b);
			}
		out->traced[j] = asks;
		out->blocked[j] = asks ? accel_occluded_lanes(s->accel, &rays.p, asks, rays.t_min,
							      rays.t_max)
				       : 0;
	}
}

/* The colours of r's rays of `active` (bits below ACCEL_PACKET) at
 * `level`, into out's lanes, as render_trace gives them: the nearest hits
 * in one packet, their shadow rays in one packet a light, and their
 * reflections (the mirrors' that are not glass) in one packet more, a
 * level down, each in its hit's lane.  Lane i's rays are trees[i]'s, of
 * weight weight[i] in their pixel (weight NULL: a scene without glass,
 * whose lanes share trees[0], which cuts nothing).
 * Long: a packet's shading in the order of the single rays' (ambient, lights,
 * reflection), over the lanes' shared arrays. */
static void shade_packet(const struct render_job *job, const struct ray_packet *r,
			 uint32_t active, int level, struct render_tree *trees,
			 const double *weight, struct color *out)
{
	const struct scene *sc = job->scene;
	struct ray_counts *counts = trees[0].counts;
	int depth = accel_packets_scatter_pay(sc->accel) ? PACKET_DEPTH : 1;
	double t_min[ACCEL_PACKET], t[ACCEL_PACKET];
	const struct shape *hit[ACCEL_PACKET];
	struct hit_lanes h;
	struct render_shadows shadows;
	struct ray_packet bounce;
	struct color seen[ACCEL_PACKET];
	uint32_t reflects = 0, lean, m;
	struct shade_lanes sum;
	int i;

	hit_lanes_offsets(r, t_min);
	for (i = 0; i < ACCEL_PACKET; i++)
		t[i] = INFINITY;
	accel_intersect_lanes(sc->accel, r, active, t_min, t, hit);
	hit_lanes_fill(r, active, t, hit, &h);
	/* A reflection the lane's tree will cut is left to the shading, which
	 * cuts it as a single ray's would (the same rays, the same sum). */
	if (level < depth)
		for (m = h.hits; m; m &= m - 1) {
			i = __builtin_ctz(m);
			if (render_reflects(&job->settings, h.hit[i], level) &&
			    !(weight && render_tree_would_cut(&trees[i], sc, &job->settings,
							     weight[i] * h.hit[i]->mat.kr, level + 1)))
				reflects |= (uint32_t)1 << i;
		}
	render_shadow_packets(sc, &h.pts, h.hits, &shadows);
	if (reflects) {
		double bw[ACCEL_PACKET];

		if (weight)
			for (m = reflects; m; m &= m - 1) {
				i = __builtin_ctz(m);
				bw[i] = weight[i] * h.hit[i]->mat.kr;
			}
		hit_lanes_bounce(&h, &bounce);
		shade_packet(job, &bounce, reflects, level + 1, trees, weight ? bw : NULL, seen);
	}
	lean = lean_lanes(job, &h, reflects, seen, level, &sum);
	if (lean) {
		double c[3][SHADE_LANES];

		counts->shadow += shade_lanes(&sum, &shadows, sc->lights, sc->n_lights, c);
		counts->reflection += (uint64_t)__builtin_popcount(sum.reflects);
		for (m = lean; m; m &= m - 1) {
			i = __builtin_ctz(m);
			out[i] = color_make(c[0][i], c[1][i], c[2][i]);
		}
	}
	for (m = active & ~lean; m; m &= m - 1) {
		struct render_point q;
		struct ray ri;

		i = __builtin_ctz(m);
		out[i] = color_make(0.0, 0.0, 0.0);
		if (!(h.hits >> i & 1))
			continue;
		shadows.bit = i;
		hit_lanes_point(&h, i, &q);
		ri = ray_packet_get(r, i);
		out[i] = render_shade_point_tree(sc, &job->settings, &ri, &q, level,
						 &trees[weight ? i : 0], weight ? weight[i] : 1.0,
						 &shadows, reflects >> i & 1 ? &seen[i] : NULL);
	}
}

void render_rays_packets(const struct render_job *job, const struct ray *r, int n,
			 struct render_tree *tree, struct color *out)
{
	struct render_tree shared;
	struct ray_packet p;
	int i, k;

	render_tree_unbound(&shared, tree->counts);
	for (i = 0; i < n; i += ACCEL_PACKET) {
		int m = n - i < ACCEL_PACKET ? n - i : ACCEL_PACKET;

		/* The lanes past the rays: copies of the first. */
		for (k = 0; k < ACCEL_PACKET; k++)
			ray_packet_set(&p, k, &r[i + (k < m ? k : 0)]);
		shade_packet(job, &p, packet_lanes(m), 1, &shared, NULL, out + i);
	}
}

/* Long: the block's loop over its 4x4 packets: primary rays, their trees and
 * the shading in one pass, whose locals are the packet's lanes. */
void render_block_packets(const struct render_job *job, struct image *img, int x0, int y0,
			  int x1, int y1, struct render_tree *tree)
{
	const struct camera *cam = job->camera;
	const bool glass = job->scene->glass;
	struct render_tree trees[ACCEL_PACKET];
	double ones[ACCEL_PACKET];
	struct camera_span span;
	int px, py, w = x1 - x0, k;

	/* With glass each lane's pixel a tree of its own, as the thread's
	 * (a primary ray of weight 1); without, the lanes share one that
	 * bounds nothing: their rays are chains of mirrors' no longer than
	 * the recursion level (the cancel flag is polled for each packet). */
	render_tree_unbound(&trees[0], tree->counts);
	for (k = 0; glass && k < ACCEL_PACKET; k++) {
		trees[k] = *tree;
		ones[k] = 1.0;
	}
	camera_span_init(&span, cam, x0, x1);
	for (py = y0; py < y1; py += PACKET_SIDE) {
		/* Each row's up * v, as camera_span_rays makes it; then the rays
		 * of each packet of PACKET_SIDE x PACKET_SIDE pixels, a lane a
		 * ray in the order of their rows. */
		struct vec3 up_v[PACKET_SIDE];
		uint8_t bytes[PACKET_SIDE][CAMERA_SPAN_MAX * 3];
		int rows_n = y1 - py < PACKET_SIDE ? y1 - py : PACKET_SIDE, y;

		for (y = 0; y < rows_n; y++)
			up_v[y] = vec3_scale(cam->up, cam->half_height - (py + y + 0.5) * cam->pixel_scale);
		for (px = 0; px < w; px += PACKET_SIDE) {
			struct camera_lanes_in in;
			struct ray_packet r;
			struct color c[PACKET_SIDE * PACKET_SIDE];
			int cols = w - px < PACKET_SIDE ? w - px : PACKET_SIDE, n = 0, i = 0, x;

			for (y = 0; y < rows_n; y++)
				for (x = px; x < px + cols; x++, n++) {
					in.ru[0][n] = span.right_u[x].x;
					in.ru[1][n] = span.right_u[x].y;
					in.ru[2][n] = span.right_u[x].z;
					in.uv[0][n] = up_v[y].x;
					in.uv[1][n] = up_v[y].y;
					in.uv[2][n] = up_v[y].z;
				}
			/* The lanes past the packet's rays: copies of its first. */
			for (i = n; i < CAMERA_LANES; i++)
				for (k = 0; k < 3; k++) {
					in.ru[k][i] = in.ru[k][0];
					in.uv[k][i] = in.uv[k][0];
				}
			camera_lanes(cam, &in, &r);
			if (!render_tree_poll(tree))
				return;
			for (i = 0; glass && i < n; i++) {
				render_tree_pixel(&trees[i]);
				render_tree_ray(&trees[i]);
			}
			shade_packet(job, &r, packet_lanes(n), 1, trees, glass ? ones : NULL, c);
			tree->counts->primary += (uint64_t)n;
			/* A pixel whose bytes what its tree left out could change
			 * is traced again alone (the same arithmetic as its
			 * lane's), with a finer cut (ray_tree.h). */
			for (i = 0; glass && i < n; i++) {
				struct ray ri = ray_packet_get(&r, i);

				while (render_tree_again(&trees[i], c[i], 1))
					c[i] = render_trace_tree(job->scene, &job->settings, &ri, 1,
								 &trees[i]);
				if (trees[i].state != RENDER_TREE_GOING) {
					tree->state = trees[i].state;
					tree->x = x0 + px + i % cols;
					tree->y = py + i / cols;
					return;
				}
			}
			for (y = 0, i = 0; y < rows_n; y++)
				for (x = px; x < px + cols; x++)
					render_rgb8(c[i++], bytes[y] + x * 3);
		}
		/* A row's bytes go out at once, as render_block's. */
		for (y = 0; y < rows_n; y++)
			memcpy(img->pixels + ((size_t)(py + y - job->y0) * (size_t)img->width +
					      (size_t)(x0 - job->x0)) * 3,
			       bytes[y], (size_t)w * 3);
	}
}
