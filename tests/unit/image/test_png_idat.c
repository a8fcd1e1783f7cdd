/* The PNG image data compressed in strips on threads: zlib itself
 * decompresses the joined stream (checksum included) to the Up-filtered
 * rows of the image, for heights below, at and across the strip size;
 * libpng reads the whole file back to the same pixels; and each allocation
 * that fails is reported as out of memory without a leak.  Strips handed
 * over band by band (in any order, from several threads, some never) give
 * the very same stream, and image_png_writer the very same file as
 * image_write. */
#define _POSIX_C_SOURCE 200809L
#include <png.h>
#include <pthread.h>
#include <unistd.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "base/alloc.h"
#include "image/png_idat.h"
#include "support.h"

/* Noise with flat runs, as rendered pictures have both. */
static void fill_pixels(struct image *img, unsigned seed)
{
	size_t n = (size_t)img->width * (size_t)img->height * 3, i;

	for (i = 0; i < n; i++) {
		seed = seed * 1103515245u + 12345u;
		img->pixels[i] = (i / 97) % 3 == 0 ? (unsigned char)(seed >> 16) : (unsigned char)(i / 500);
	}
}

static void check_stream(const struct image *img, const struct png_idat *z)
{
	size_t stride = (size_t)img->width * 3, x;
	uLongf len = (uLongf)((stride + 1) * (size_t)img->height);
	unsigned char *raw = malloc(len + 1);
	int y;

	assert_non_null(raw);
	assert_int_equal(uncompress(raw, &len, z->data, (uLong)z->len), Z_OK);
	assert_int_equal(len, (stride + 1) * (size_t)img->height);
	for (y = 0; y < img->height; y++) {
		const unsigned char *f = raw + (size_t)y * (stride + 1);
		const unsigned char *row = img->pixels + (size_t)y * stride;

		assert_int_equal(f[0], 2);	/* Up */
		for (x = 0; x < stride; x++) {
			unsigned above = y > 0 ? (row - stride)[x] : 0;
			assert_int_equal((f[1 + x] + above) & 255u, row[x]);
		}
	}
	free(raw);
}

static void check_file(const struct image *img)
{
	FILE *f = tmpfile();
	png_image png;
	unsigned char *buf;
	long size;
	struct diag d;

	assert_non_null(f);
	memset(&d, 0, sizeof(d));
	assert_int_equal(png_idat_write_file(img, f, NULL, NULL, &d), 0);
	size = ftell(f);
	assert_true(size > 0);
	buf = malloc((size_t)size);
	assert_non_null(buf);
	rewind(f);
	assert_int_equal(fread(buf, 1, (size_t)size, f), (size_t)size);
	fclose(f);
	memset(&png, 0, sizeof(png));
	png.version = PNG_IMAGE_VERSION;
	assert_true(png_image_begin_read_from_memory(&png, buf, (size_t)size));
	assert_int_equal(png.width, (png_uint_32)img->width);
	assert_int_equal(png.height, (png_uint_32)img->height);
	png.format = PNG_FORMAT_RGB;
	{
		unsigned char *px = malloc(PNG_IMAGE_SIZE(png));
		assert_non_null(px);
		assert_true(png_image_finish_read(&png, NULL, px, 0, NULL));
		assert_memory_equal(px, img->pixels, (size_t)img->width * (size_t)img->height * 3);
		free(px);
	}
	free(buf);
}

/* Heights below, at and across the strip size; widths whose rows of 3,
 * 15, 18, 111 and 4608 bytes reach each of the filter's loops (sixteen
 * bytes, eight, one). */
static void test_png_idat_heights(void **state)
{
	static const int heights[] = { 1, 2, 63, 64, 65, 128, 200 };
	static const int widths[] = { 1, 5, 6, 37, 1536 };
	size_t i, k;

	(void)state;
	for (k = 0; k < sizeof(widths) / sizeof(widths[0]); k++) {
		for (i = 0; i < sizeof(heights) / sizeof(heights[0]); i++) {
			struct image img;
			struct png_idat z;
			struct diag d;

			if (widths[k] > 100 && heights[i] > 65)
				continue;
			memset(&d, 0, sizeof(d));
			assert_int_equal(image_alloc(&img, widths[k], heights[i], &d), 0);
			fill_pixels(&img, (unsigned)(i + 7 * k) + 1);
			assert_int_equal(png_idat_compress(&img, &z, &d), 0);
			check_stream(&img, &z);
			png_idat_free(&z);
			check_file(&img);
			image_free(&img);
		}
	}
}

typedef int compress_fn(const struct image *img, struct png_idat *z, struct diag *d);

/* compress made to fail at its first allocation, then its second, and so
 * on until it succeeds: every failure reported as out of memory (without
 * a leak: the sanitizer build finds those), and the stream it then makes
 * the image's (20 x 150, fill_pixels with seed). */
static void check_out_of_memory(compress_fn *compress, unsigned seed)
{
	struct image img;
	struct png_idat z;
	struct diag d;
	unsigned long n;
	int rc;

	memset(&d, 0, sizeof(d));
	assert_int_equal(image_alloc(&img, 20, 150, &d), 0);
	fill_pixels(&img, seed);
	for (n = 1;; n++) {
		rt_alloc_fail_from(n);
		rc = compress(&img, &z, &d);
		rt_alloc_fail_from(0);
		if (rc == 0)
			break;
		assert_int_equal(rc, -RT_E_NOMEM);
	}
	assert_true(n > 1);
	check_stream(&img, &z);
	png_idat_free(&z);
	image_free(&img);
}

static void test_png_idat_out_of_memory(void **state)
{
	(void)state;
	check_out_of_memory(png_idat_compress, 7);
}

/* The bands of the image told in the order `order` (a permutation of
 * some of them), by `threads` threads taking turns. */
struct band_feed {
	struct png_idat_strips *st;
	const int *order;
	int n, threads, thread;
};

static void *band_feed_main(void *arg)
{
	struct band_feed *f = arg;
	int k;

	for (k = f->thread; k < f->n; k += f->threads)
		png_idat_strips_band_done(f->st, f->order[k], f->thread);
	return NULL;
}

static void feed_bands(struct png_idat_strips *st, const int *order, int n, int threads)
{
	struct band_feed feeds[4];
	pthread_t tids[4];
	int t;

	for (t = 0; t < threads; t++) {
		feeds[t].st = st;
		feeds[t].order = order;
		feeds[t].n = n;
		feeds[t].threads = threads;
		feeds[t].thread = t;
		assert_int_equal(pthread_create(&tids[t], NULL, band_feed_main, &feeds[t]), 0);
	}
	for (t = 0; t < threads; t++)
		pthread_join(tids[t], NULL);
}

static void test_png_idat_bands_same_stream(void **state)
{
	static const int heights[] = { 1, 63, 64, 65, 200, 640 };
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(heights) / sizeof(heights[0]); i++) {
		int n = (heights[i] + PNG_IDAT_STRIP_ROWS - 1) / PNG_IDAT_STRIP_ROWS, k, round;
		int order[16];
		struct image img;
		struct png_idat want;
		struct diag d;

		memset(&d, 0, sizeof(d));
		assert_true(n <= 16);
		assert_int_equal(image_alloc(&img, 41, heights[i], &d), 0);
		fill_pixels(&img, (unsigned)i + 3);
		assert_int_equal(png_idat_compress(&img, &want, &d), 0);
		/* Round 0: top to bottom; 1: bottom to top; 2: shuffled; 3: every
		 * other band only (the rest left to the finish); 4: none. */
		for (round = 0; round < 5; round++) {
			struct png_idat_strips *st;
			struct png_idat got;
			unsigned seed = 12345u + (unsigned)round;
			int told = n;

			for (k = 0; k < n; k++)
				order[k] = round == 1 ? n - 1 - k : k;
			if (round == 2) {
				for (k = n - 1; k > 0; k--) {
					int j, tmp;
					seed = seed * 1103515245u + 12345u;
					j = (int)((seed >> 16) % (unsigned)(k + 1));
					tmp = order[k];
					order[k] = order[j];
					order[j] = tmp;
				}
			}
			if (round == 3) {
				for (k = 0; k < n; k += 2)
					order[k / 2] = k;
				told = (n + 1) / 2;
			}
			if (round == 4)
				told = 0;
			assert_int_equal(png_idat_strips_open(&img, 3, &st, &d), 0);
			/* Threads outside [0, threads) are ignored. */
			png_idat_strips_band_done(st, 0, 99);
			png_idat_strips_band_done(st, 0, -1);
			feed_bands(st, order, told, round == 0 ? 1 : 3);
			assert_int_equal(png_idat_strips_finish(st, &got, &d), 0);
			assert_int_equal(got.len, want.len);
			assert_memory_equal(got.data, want.data, want.len);
			png_idat_free(&got);
			png_idat_strips_free(st);
		}
		png_idat_free(&want);
		image_free(&img);
	}
}

/* A strip's filter reads the last row of the band above it, so it may be
 * compressed only once both bands are final: bands filled and told one at
 * a time from the bottom up, each only after its own rows are written,
 * must still give the one-pass stream. */
static void test_png_idat_strip_waits_for_band_above(void **state)
{
	static const int heights[] = { 65, 128, 200 };
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(heights) / sizeof(heights[0]); i++) {
		int n = (heights[i] + PNG_IDAT_STRIP_ROWS - 1) / PNG_IDAT_STRIP_ROWS, b;
		size_t stride = 41 * 3;
		struct image img, ref;
		struct png_idat want, got;
		struct png_idat_strips *st;
		struct diag d;

		memset(&d, 0, sizeof(d));
		assert_int_equal(image_alloc(&img, 41, heights[i], &d), 0);
		assert_int_equal(image_alloc(&ref, 41, heights[i], &d), 0);
		fill_pixels(&ref, (unsigned)i + 7);
		memset(img.pixels, 0, stride * (size_t)heights[i]);
		assert_int_equal(png_idat_compress(&ref, &want, &d), 0);
		assert_int_equal(png_idat_strips_open(&img, 1, &st, &d), 0);
		for (b = n - 1; b >= 0; b--) {
			int y0 = b * PNG_IDAT_STRIP_ROWS;
			int y1 = y0 + PNG_IDAT_STRIP_ROWS < heights[i] ? y0 + PNG_IDAT_STRIP_ROWS : heights[i];

			memcpy(img.pixels + (size_t)y0 * stride, ref.pixels + (size_t)y0 * stride,
			       (size_t)(y1 - y0) * stride);
			png_idat_strips_band_done(st, b, 0);
		}
		assert_int_equal(png_idat_strips_finish(st, &got, &d), 0);
		assert_int_equal(got.len, want.len);
		assert_memory_equal(got.data, want.data, want.len);
		png_idat_free(&got);
		png_idat_free(&want);
		png_idat_strips_free(st);
		image_free(&img);
		image_free(&ref);
	}
}

/* The public writer: the same file as image_write, told all bands, some
 * or none. */
static void test_png_writer_same_file(void **state)
{
	char dir[] = "/tmp/test_png_writer.XXXXXX", a[64], b[64];
	struct image img;
	struct diag d;
	int told;

	(void)state;
	assert_non_null(mkdtemp(dir));
	snprintf(a, sizeof(a), "%s/a.png", dir);
	snprintf(b, sizeof(b), "%s/b.png", dir);
	memset(&d, 0, sizeof(d));
	assert_int_equal(image_alloc(&img, 30, 150, &d), 0);
	fill_pixels(&img, 11);
	assert_int_equal(image_write(&img, a, RT_FORMAT_PNG, NULL, &d), 0);
	assert_int_equal(image_png_writer_band_rows(), PNG_IDAT_STRIP_ROWS);
	for (told = 0; told <= 3; told++) {
		struct image_png_writer *w;
		unsigned char *fa, *fb;
		size_t la, lb;
		int k;

		assert_int_equal(image_png_writer_open(&img, 1, &w, &d), 0);
		for (k = 0; k < told; k++)
			image_png_writer_band_done(w, k, 0);
		assert_int_equal(image_png_writer_write(w, b, NULL, &d), 0);
		image_png_writer_free(w);
		fa = support_read_file(a, &la);
		fb = support_read_file(b, &lb);
		assert_true(la > 0 && lb > 0);
		assert_int_equal(la, lb);
		assert_memory_equal(fa, fb, la);
		free(fa);
		free(fb);
	}
	image_png_writer_free(NULL);
	unlink(a);
	unlink(b);
	rmdir(dir);
	image_free(&img);
}

/* The image in two bands (told 1 then 0) through the strips. */
static int compress_in_bands(const struct image *img, struct png_idat *z, struct diag *d)
{
	struct png_idat_strips *st = NULL;
	int rc = png_idat_strips_open(img, 2, &st, d);

	if (rc != 0) {
		assert_null(st);
		return rc;
	}
	png_idat_strips_band_done(st, 1, 1);
	png_idat_strips_band_done(st, 0, 0);
	rc = png_idat_strips_finish(st, z, d);
	png_idat_strips_free(st);
	return rc;
}

/* Every allocation that fails, in the opening, in the strips compressed
 * band by band or in the finish, is reported as out of memory without a
 * leak (the sanitizer build finds those). */
static void test_png_idat_bands_out_of_memory(void **state)
{
	(void)state;
	check_out_of_memory(compress_in_bands, 5);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_png_idat_heights, test_png_idat_out_of_memory,
			   test_png_idat_bands_same_stream,
			   test_png_idat_strip_waits_for_band_above, test_png_writer_same_file,
			   test_png_idat_bands_out_of_memory))
