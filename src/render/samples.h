/* Antialiasing by a regular grid of sub-pixel samples (--samples N). */
#ifndef RT_RENDER_SAMPLES_H
#define RT_RENDER_SAMPLES_H

#include <stdbool.h>

#include "render/ray_tree.h"
#include "whitted/render.h"

/* Renders the pixels [x0, x1) x [y0, y1) of the full image into img (whose
 * top left pixel is the job's (x0, y0)) with job->samples^2 rays each, a
 * pixel's samples one tree (ray_tree.h); stops early when the tree is
 * stopped (its x, y the pixel that went over the budget). */
void render_block_samples(const struct render_job *job, struct image *img, int x0, int y0,
			  int x1, int y1, bool packets, struct render_tree *tree);
/* The widest row of pixels whose samples go in packets. */
#define SAMPLES_ROW_MAX 64

#endif
