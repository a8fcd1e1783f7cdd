/* The primary rays of a block in packets of 4x4 pixels, and their hits'
 * shadow rays in one packet a light: neighbouring rays meet the same
 * nodes, which a packet then loads and tests once for all
 * (accel_intersect_packet, accel_occluded_packet: four rays to an AVX2
 * operation), and each pixel is shaded from its ray's hit with those
 * shadow answers as render_trace would shade it (shade_hit.h).  The
 * reflections and their shadows stay single rays: they part at once. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "render/render_packet.h"
#include "render/shade_hit.h"
#include "render/shade_math.h"
#include "scene/scene_impl.h"

#define PACKET_SIDE 4	/* PACKET_SIDE^2 <= ACCEL_PACKET */

bool render_packets_wanted(const struct accel *a)
{
	const char *p = getenv("WHITTED_PACKETS");

	if (p && strcmp(p, "0") == 0)
		return false;
	if (p && strcmp(p, "1") == 0)
		return true;
	return accel_packets_pay(a);
}

void render_block_packets(const struct render_job *job, struct image *img, int x0, int y0,
			  int x1, int y1, struct ray_counts *counts)
{
	const struct scene *sc = job->scene;
	int px, py;

	for (py = y0; py < y1; py += PACKET_SIDE)
		for (px = x0; px < x1; px += PACKET_SIDE) {
			struct ray r[PACKET_SIDE * PACKET_SIDE];
			double t_min[PACKET_SIDE * PACKET_SIDE], t[PACKET_SIDE * PACKET_SIDE];
			const struct shape *hit[PACKET_SIDE * PACKET_SIDE];
			struct render_point h[PACKET_SIDE * PACKET_SIDE];
			struct render_shadows shadows;
			uint32_t hits = 0;
			int n = 0, i, x, y;

			for (y = py; y < py + PACKET_SIDE && y < y1; y++)
				for (x = px; x < px + PACKET_SIDE && x < x1; x++) {
					r[n] = camera_ray(job->camera, x, y);
					t_min[n] = render_offset(r[n].origin);
					t[n++] = INFINITY;
				}
			accel_intersect_packet(sc->accel, r, n, t_min, t, hit);
			for (i = 0; i < n; i++)
				if (hit[i]) {
					render_point_at(&r[i], t[i], hit[i], &h[i]);
					hits |= (uint32_t)1 << i;
				}
			render_shadow_packets(sc, h, hits, &shadows);
			i = 0;
			for (y = py; y < py + PACKET_SIDE && y < y1; y++)
				for (x = px; x < px + PACKET_SIDE && x < x1; x++, i++) {
					uint8_t *out = img->pixels +
						       ((size_t)(y - job->y0) * (size_t)img->width +
							(size_t)(x - job->x0)) * 3;
					struct color c = color_make(0.0, 0.0, 0.0);

					counts->primary++;
					shadows.bit = i;
					if (hit[i])
						c = render_shade_point(sc, &job->settings, &r[i], &h[i],
								       counts, &shadows);
					render_color_to_rgb8(c, out);
				}
		}
}
