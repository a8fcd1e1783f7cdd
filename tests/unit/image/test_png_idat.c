/* The PNG image data compressed in strips on threads: zlib itself
 * decompresses the joined stream (checksum included) to the Up-filtered
 * rows of the image, for heights below, at and across the strip size;
 * libpng reads the whole file back to the same pixels; and each allocation
 * that fails is reported as out of memory without a leak. */
#define _POSIX_C_SOURCE 200809L
#include <png.h>
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
			unsigned above = y > 0 ? row[x - stride] : 0;
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

static void test_png_idat_heights(void **state)
{
	static const int heights[] = { 1, 2, 63, 64, 65, 128, 200 };
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(heights) / sizeof(heights[0]); i++) {
		struct image img;
		struct png_idat z;
		struct diag d;

		memset(&d, 0, sizeof(d));
		assert_int_equal(image_alloc(&img, 37, heights[i], &d), 0);
		fill_pixels(&img, (unsigned)i + 1);
		assert_int_equal(png_idat_compress(&img, &z, &d), 0);
		check_stream(&img, &z);
		png_idat_free(&z);
		check_file(&img);
		image_free(&img);
	}
}

static void test_png_idat_out_of_memory(void **state)
{
	struct image img;
	struct png_idat z;
	struct diag d;
	unsigned long n;
	int rc;

	(void)state;
	memset(&d, 0, sizeof(d));
	assert_int_equal(image_alloc(&img, 20, 150, &d), 0);
	fill_pixels(&img, 7);
	for (n = 1;; n++) {
		rt_alloc_fail_from(n);
		rc = png_idat_compress(&img, &z, &d);
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

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_png_idat_heights),
		cmocka_unit_test(test_png_idat_out_of_memory),
	};

	return SUPPORT_RUN(tests, argc, argv);
}
