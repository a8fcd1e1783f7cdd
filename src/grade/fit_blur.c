/* The camera fit's blur: a separable Gaussian over a level's cells (three
 * floats a cell), in place, the edges renormalised (the taps outside the
 * grid left out of the weights). */
#include <math.h>
#include <stddef.h>
#include <string.h>

#include "grade/fit.h"

/* The blur's reach, in cells: three sigmas, at most this. */
#define FIT_BLUR_MAX_RADIUS 24

/* The blur's passes work on a row at a time, BLUR_CHUNK pixels of it
 * summed at once (contiguous, so the compiler vectorises them); each sum
 * adds its taps in the same order as one pixel at a time would. */
#define BLUR_CHUNK 128

/* Along the rows: each pixel from its row's neighbours within r. */
static void fit_blur_rows(const float *in, float *out, int w, int h, const double *k, int r)
{
	double acc[3 * BLUR_CHUNK], ws[BLUR_CHUNK];
	int y, x0, t, j, c;

	for (y = 0; y < h; y++) {
		const float *row = in + 3 * (size_t)y * (size_t)w;
		float *o = out + 3 * (size_t)y * (size_t)w;
		for (x0 = 0; x0 < w; x0 += BLUR_CHUNK) {
			const int n = w - x0 < BLUR_CHUNK ? w - x0 : BLUR_CHUNK;
			memset(acc, 0, sizeof(acc));
			memset(ws, 0, sizeof(ws));
			for (t = -r; t <= r; t++) {
				/* Pixel x0 + j has the tap x0 + j + t inside the row. */
				const int lo = -t - x0 > 0 ? -t - x0 : 0;
				const int hi = w - t - x0 < n ? w - t - x0 : n;
				const double kt = k[t + r];
				/* Tap j of the chunk is row[3 * (x0 + t) + j]: the
				 * index is not negative from 3 * lo on. */
				const ptrdiff_t at = 3 * (ptrdiff_t)(x0 + t);
				for (j = lo; j < hi; j++)
					ws[j] += kt;
				for (j = 3 * lo; j < 3 * hi; j++)
					acc[j] += kt * row[at + j];
			}
			for (j = 0; j < n; j++)
				for (c = 0; c < 3; c++)
					o[3 * (x0 + j) + c] = (float)(acc[3 * j + c] / ws[j]);
		}
	}
}

/* Down the columns: each row from the rows within r. */
static void fit_blur_columns(const float *in, float *out, int w, int h, const double *k, int r)
{
	const int line = 3 * w;
	double acc[3 * BLUR_CHUNK];
	int y, i0, t, i;

	for (y = 0; y < h; y++)
		for (i0 = 0; i0 < line; i0 += 3 * BLUR_CHUNK) {
			const int n = line - i0 < 3 * BLUR_CHUNK ? line - i0 : 3 * BLUR_CHUNK;
			double ws = 0.0;
			memset(acc, 0, sizeof(acc));
			for (t = -r; t <= r; t++) {
				const double kt = k[t + r];
				const float *p;
				if (y + t < 0 || y + t >= h)
					continue;
				p = in + (size_t)(y + t) * (size_t)line + (size_t)i0;
				ws += kt;
				for (i = 0; i < n; i++)
					acc[i] += kt * p[i];
			}
			for (i = 0; i < n; i++)
				out[(size_t)y * (size_t)line + (size_t)(i0 + i)] = (float)(acc[i] / ws);
		}
}

void fit_blur(float *cells, float *tmp, int w, int h, double sigma)
{
	double k[2 * FIT_BLUR_MAX_RADIUS + 1];
	int r = (int)ceil(3.0 * sigma), t;

	if (!(sigma > 0.0))
		return;
	r = r > FIT_BLUR_MAX_RADIUS ? FIT_BLUR_MAX_RADIUS : r;
	for (t = -r; t <= r; t++)
		k[t + r] = exp(-(double)t * t / (2.0 * sigma * sigma));
	fit_blur_rows(cells, tmp, w, h, k, r);
	fit_blur_columns(tmp, cells, w, h, k, r);
}
