/* The figures of the gate between two images of the same size, and the
 * picture of where they differ.  PSNR over the three channels, a pixel off
 * by its worst channel, as tests/tools/imgcmp; but the gate's PSNR clause
 * here leaves out the worst pixels the > 8 clause allows (0.02 %): an
 * isolated pixel on a seam or the horizon, already forgiven by that clause,
 * would otherwise decide the verdict alone (one pixel 141 levels off in
 * 203 x 203 is 51 dB).  imgcmp and povcheck's gate keep the plain PSNR. */
#include <math.h>
#include <stdlib.h>

#include "whitted/grade.h"

/* At most this many pixels are left out of the PSNR clause (the worst
 * 0.02 % of 20 megapixels); a larger image has fewer left out, never more. */
#define GRADE_MAX_LEFT_OUT 4096

/* heap[0..n) a min-heap: push v, or replace the least when it is full. */
static void grade_heap_offer(int *heap, long *n, long cap, int v)
{
	long i = 0, c;

	if (*n < cap) {
		i = (*n)++;
		while (i > 0 && heap[(i - 1) / 2] > v) {
			heap[i] = heap[(i - 1) / 2];
			i = (i - 1) / 2;
		}
		heap[i] = v;
		return;
	}
	if (cap == 0 || v <= heap[0])
		return;
	for (;;) {
		c = 2 * i + 1;
		if (c >= *n)
			break;
		if (c + 1 < *n && heap[c + 1] < heap[c])
			c++;
		if (heap[c] >= v)
			break;
		heap[i] = heap[c];
		i = c;
	}
	heap[i] = v;
}

static double grade_psnr_of(double sq, double n)
{
	sq /= 3.0 * (n > 0.0 ? n : 1.0);
	return sq == 0.0 ? INFINITY : 10.0 * log10(255.0 * 255.0 / sq);
}

static void grade_figures_in(const struct image *a, const struct image *b, int stride, int ox,
			     int oy, const uint8_t *skip, struct grade_figures *f)
{
	long n = 0, off2 = 0, off8 = 0, off32 = 0, n_worst = 0, cap, nx, ny, j;
	double sum = 0.0, sq = 0.0, worst_sq = 0.0;
	int x, y, k, heap[GRADE_MAX_LEFT_OUT];

	if (stride < 1)
		stride = 1;
	nx = a->width > ox % stride ? (a->width - ox % stride + stride - 1) / stride : 0;
	ny = a->height > oy % stride ? (a->height - oy % stride + stride - 1) / stride : 0;
	cap = (long)floor(RT_GRADE_MAX_OFF8 * (double)(nx * ny));
	cap = cap < GRADE_MAX_LEFT_OUT ? cap : GRADE_MAX_LEFT_OUT;
	for (y = oy % stride; y < a->height; y += stride) {
		const uint8_t *pa = a->pixels + (size_t)y * (size_t)a->width * 3;
		const uint8_t *pb = b->pixels + (size_t)y * (size_t)b->width * 3;
		for (x = ox % stride; x < a->width; x += stride) {
			int worst = 0, q = 0;
			if (skip && skip[(size_t)y * (size_t)a->width + (size_t)x])
				continue;
			for (k = 0; k < 3; k++) {
				int dv = abs((int)pa[3 * x + k] - (int)pb[3 * x + k]);
				sum += dv;
				q += dv * dv;
				worst = dv > worst ? dv : worst;
			}
			sq += q;
			if (q > 0)
				grade_heap_offer(heap, &n_worst, cap, q);
			off2 += worst > 2;
			off8 += worst > 8;
			off32 += worst > 32;
			n++;
		}
	}
	for (j = 0; j < n_worst; j++)
		worst_sq += heap[j];
	f->pixels = n;
	f->left_out = n_worst;
	if (n == 0)
		n = 1;
	f->mean_error = sum / (3.0 * (double)n);
	f->psnr = grade_psnr_of(sq, (double)n);
	f->psnr_gate = grade_psnr_of(sq - worst_sq, (double)(n - n_worst));
	f->off2 = (double)off2 / (double)n;
	f->off8 = (double)off8 / (double)n;
	f->off32 = (double)off32 / (double)n;
	f->match = f->psnr_gate >= RT_GRADE_MIN_PSNR && f->off2 <= RT_GRADE_MAX_OFF2 &&
		   f->off8 <= RT_GRADE_MAX_OFF8;
}

void grade_figures_of(const struct image *a, const struct image *b, int stride, int ox, int oy,
		      struct grade_figures *f)
{
	grade_figures_in(a, b, stride, ox, oy, NULL, f);
}

void grade_figures_skipping(const struct image *a, const struct image *b, const uint8_t *skip,
			    struct grade_figures *f)
{
	grade_figures_in(a, b, 1, 0, 0, skip, f);
}

int grade_diff_image(const struct image *ref, const struct image *sub, struct image *out,
		     struct diag *d)
{
	int x, y, k, rc = image_alloc(out, 2 * ref->width, ref->height, d);

	if (rc < 0)
		return rc;
	for (y = 0; y < ref->height; y++) {
		const uint8_t *pa = ref->pixels + (size_t)y * (size_t)ref->width * 3;
		const uint8_t *pb = sub->pixels + (size_t)y * (size_t)sub->width * 3;
		uint8_t *left = out->pixels + (size_t)y * (size_t)out->width * 3;
		uint8_t *right = left + (size_t)ref->width * 3;
		for (x = 0; x < ref->width; x++) {
			int worst = 0;
			for (k = 0; k < 3; k++) {
				int dv = abs((int)pa[3 * x + k] - (int)pb[3 * x + k]);
				left[3 * x + k] = (uint8_t)(8 * dv > 255 ? 255 : 8 * dv);
				worst = dv > worst ? dv : worst;
			}
			if (worst > 8) {
				right[3 * x] = 255;
				right[3 * x + 1] = 0;
				right[3 * x + 2] = 0;
			} else if (worst > 2) {
				right[3 * x] = 255;
				right[3 * x + 1] = 210;
				right[3 * x + 2] = 0;
			} else {
				uint8_t g = (uint8_t)((pa[3 * x] + pa[3 * x + 1] + pa[3 * x + 2]) / 9);
				right[3 * x] = right[3 * x + 1] = right[3 * x + 2] = g;
			}
		}
	}
	return 0;
}
