/* Antialiasing: pixel (px, py) seen through the N x N grid of its
 * sub-pixels' centres, (px + (i + 0.5) / N, py + (j + 0.5) / N) for i, j in
 * 0..N-1, which are the pixel centres of the same image rendered N times
 * larger.  Each sample is clamped to [0, 1] (it already is under --clamp
 * level; under --clamp final this is its one clamp), the N^2 samples are
 * summed in linear colour in a fixed order and divided by N^2, and the
 * mean is rounded to 8 bits once.  So the pixel is the box average of the
 * N-times-larger image to within its rounding (one level), and it does not
 * depend on which thread or tile renders it. */
#include "accel/accel.h"
#include "render/render_packet.h"
#include "render/samples.h"
#include "render/shade_math.h"
#include "scene/scene_impl.h"

/* The samples of a row of pixels, in their order (pixel by pixel, each
 * pixel's in order), traced ACCEL_PACKET at a time (a pixel's samples,
 * or a few pixels', lie close together), each pixel's sum kept in the
 * same order as one ray at a time: the same bytes. */
static void samples_row_packets(const struct render_job *job, int x0, int x1, int y,
				const double *offset, struct render_tree *tree, uint8_t *row)
{
	struct ray_counts *counts = tree->counts;
	const int n = job->samples, nn = n * n;
	const double inv_nn = 1.0 / ((double)n * n);
	struct color sum[SAMPLES_ROW_MAX], c[ACCEL_PACKET];
	struct ray r[ACCEL_PACKET];
	int owner[ACCEL_PACKET], m = 0, x, k, i;

	for (x = x0; x < x1; x++)
		sum[x - x0] = color_make(0.0, 0.0, 0.0);
	for (x = x0; x < x1; x++)
		for (k = 0; k < nn; k++) {
			r[m] = camera_ray_at(job->camera, x + offset[k % n], y + offset[k / n]);
			owner[m++] = x - x0;
			counts->primary++;
			if (m < ACCEL_PACKET && !(x == x1 - 1 && k == nn - 1))
				continue;
			render_rays_packets(job, r, m, tree, c);
			for (i = 0; i < m; i++)
				sum[owner[i]] = color_add(sum[owner[i]], color_clamp(c[i]));
			m = 0;
		}
	for (x = x0; x < x1; x++)
		render_rgb8(color_scale(sum[x - x0], inv_nn), row + (size_t)(x - x0) * 3);
}

/* The mean of pixel (x, y)'s samples, one round of its tree. */
static struct color samples_pixel(const struct render_job *job, int x, int y,
				  const double *offset, struct render_tree *tree)
{
	const int n = job->samples, nn = n * n;
	const double inv_nn = 1.0 / ((double)n * n);
	struct color sum = color_make(0.0, 0.0, 0.0);
	struct ray next = camera_ray_at(job->camera, x + offset[0], y + offset[0]);
	int k;

	for (k = 0; k < nn; k++) {
		struct ray r = next;
		if (k + 1 < nn)
			next = camera_ray_at(job->camera, x + offset[(k + 1) % n],
					     y + offset[(k + 1) / n]);
		sum = color_add(sum, color_clamp(render_trace_tree(job->scene, &job->settings, &r, 1,
								   tree)));
	}
	return color_scale(sum, inv_nn);
}

/* The sample positions are made once per block (offsets within a pixel);
 * one ray at a time, each sample's ray is made before the previous one
 * is traced, so that its square root and division run beside that
 * trace, as render_block does for one ray a pixel. */
void render_block_samples(const struct render_job *job, struct image *img, int x0, int y0,
			  int x1, int y1, bool packets, struct render_tree *tree)
{
	const int n = job->samples, nn = n * n;
	double offset[RT_MAX_SAMPLES];
	int x, y, k;

	for (k = 0; k < n; k++)
		offset[k] = (k + 0.5) / n;
	for (y = y0; y < y1; y++) {
		uint8_t *row = img->pixels + (size_t)(y - job->y0) * (size_t)img->width * 3;
		if (!render_tree_poll(tree))
			return;
		/* A scene with glass goes ray by ray: a pixel's samples are one
		 * tree, which the rows' packets would mix with others'. */
		if (packets && !job->scene->glass && x1 - x0 <= SAMPLES_ROW_MAX) {
			samples_row_packets(job, x0, x1, y, offset, tree,
					    row + (size_t)(x0 - job->x0) * 3);
			continue;
		}
		for (x = x0; x < x1; x++) {
			struct color mean;

			render_tree_pixel(tree);
			do
				mean = samples_pixel(job, x, y, offset, tree);
			while (render_tree_again(tree, mean, nn));
			if (tree->state != RENDER_TREE_GOING) {
				tree->x = x;
				tree->y = y;
				return;
			}
			if (tree->counts)
				tree->counts->primary += (uint64_t)nn;
			render_rgb8(mean, row + (size_t)(x - job->x0) * 3);
		}
	}
}
