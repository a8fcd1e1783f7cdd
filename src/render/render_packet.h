/* A block's primary rays traced as packets (render_packet.c). */
#ifndef RT_RENDER_PACKET_H
#define RT_RENDER_PACKET_H

#include <stdbool.h>

#include "accel/accel.h"
#include "render/ray_tree.h"
#include "whitted/render.h"

/* Whether to trace packets: where they pay (accel_packets_pay), unless
 * WHITTED_PACKETS=0 asks for one ray at a time or WHITTED_PACKETS=1 for
 * packets anyway (to compare: the images are the same). */
bool render_packets_wanted(const struct accel *a);
/* Renders the pixels [x0, x1) x [y0, y1) of the job's image, one ray
 * through each centre, as render_image.c's loop does, to the byte, each
 * pixel's rays a tree like `tree` (its counts not NULL; ray_tree.h);
 * stops early when one stops (tree's state, x and y then say so). */
void render_block_packets(const struct render_job *job, struct image *img, int x0, int y0,
			  int x1, int y1, struct render_tree *tree);
/* out[i] = render_trace(job's scene and settings, r[i], level 1), for
 * rays r[0..n) (any n, best neighbours), traced ACCEL_PACKET at a time;
 * counts all but the primary rays into tree->counts, as render_trace
 * does.  Not for scenes with glass (their trees are not weighed here:
 * samples.c sends them ray by ray). */
void render_rays_packets(const struct render_job *job, const struct ray *r, int n,
			 struct render_tree *tree, struct color *out);

#endif
