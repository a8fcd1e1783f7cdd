/* The image reader on hand-made files: a 3x2 BMP of 24 bits (bottom-up,
 * rows padded to 4 bytes, B G R), of 32 bits, top-down; P6 and P3 (with a
 * maximum of 15, scaled); and the refusals: truncated, not an image. */
#include <string.h>

#include "whitted/image.h"
#include "support.h"

/* The image: top row red, green, blue; bottom row white, black, grey 128. */
static const uint8_t want[18] = {
	255, 0, 0, 0, 255, 0, 0, 0, 255,
	255, 255, 255, 0, 0, 0, 128, 128, 128,
};

static size_t bmp_make(uint8_t *out, int bits, bool top_down)
{
	int bpp = bits / 8, row = (3 * bpp + 3) & ~3, y, x;
	size_t raster = (size_t)row * 2, n = 54 + raster;
	int32_t h = top_down ? -2 : 2;

	memset(out, 0, n);
	out[0] = 'B';
	out[1] = 'M';
	out[2] = (uint8_t)n;
	out[10] = 54;
	out[14] = 40;
	out[18] = 3;
	memcpy(out + 22, &h, 4);	/* little-endian on the test machines */
	out[26] = 1;
	out[28] = (uint8_t)bits;
	for (y = 0; y < 2; y++) {
		int file_row = top_down ? y : 1 - y;
		for (x = 0; x < 3; x++) {
			const uint8_t *p = want + 3 * (3 * y + x);
			uint8_t *o = out + 54 + (size_t)file_row * (size_t)row + (size_t)(x * bpp);
			o[0] = p[2];
			o[1] = p[1];
			o[2] = p[0];
		}
	}
	return n;
}

static void read_ok(const uint8_t *data, size_t n)
{
	struct image img;
	struct diag d;

	assert_int_equal(image_read_memory(data, n, "t", &img, NULL, &d), 0);
	assert_int_equal(img.width, 3);
	assert_int_equal(img.height, 2);
	assert_memory_equal(img.pixels, want, sizeof(want));
	image_free(&img);
}

static void test_image_read_bmp24_bottom_up_padded(void **state)
{
	uint8_t buf[128];

	(void)state;
	read_ok(buf, bmp_make(buf, 24, false));
}

static void test_image_read_bmp32_and_top_down(void **state)
{
	uint8_t buf[128];

	(void)state;
	read_ok(buf, bmp_make(buf, 32, false));
	read_ok(buf, bmp_make(buf, 24, true));
}

static void test_image_read_ppm(void **state)
{
	uint8_t p6[64];
	const char *p3 = "P3\n# max 15\n3 2\n15\n15 0 0  0 15 0  0 0 15\n15 15 15 0 0 0 8 8 8\n";
	struct image img;
	struct diag d;
	int n = snprintf((char *)p6, sizeof(p6), "P6\n3 2\n255\n");

	(void)state;
	memcpy(p6 + n, want, sizeof(want));
	read_ok(p6, (size_t)n + sizeof(want));
	assert_int_equal(image_read_memory((const uint8_t *)p3, strlen(p3), "t", &img, NULL, &d), 0);
	/* 8 of 15 is round(8 * 255 / 15) = 136. */
	assert_int_equal(img.pixels[15], 136);
	assert_memory_equal(img.pixels, want, 15);
	image_free(&img);
	/* 16 bits, big-endian: 0x8080 of 65535 is 128; P5 grey fills R, G, B. */
	assert_int_equal(image_read_memory((const uint8_t *)"P6\n1 1\n65535\n\x80\x80\0\0\xff\xff", 20,
					   "t", &img, NULL, &d), 0);
	assert_int_equal(img.pixels[0], 128);
	assert_int_equal(img.pixels[1], 0);
	assert_int_equal(img.pixels[2], 255);
	image_free(&img);
	assert_int_equal(image_read_memory((const uint8_t *)"P5\n1 1\n1000\n\x01\xf4", 15, "t", &img, NULL, &d), 0);
	assert_int_equal(img.pixels[0], 128);
	assert_int_equal(img.pixels[2], 128);
	image_free(&img);
}

static void test_image_read_refusals(void **state)
{
	uint8_t buf[128];
	struct image img;
	struct diag d;
	size_t n = bmp_make(buf, 24, false);

	(void)state;
	assert_int_equal(image_read_memory(buf, n - 1, "t.bmp", &img, NULL, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "truncated BMP"));
	assert_null(img.pixels);
	assert_int_equal(image_read_memory((const uint8_t *)"P6\n3 2\n255\nabc", 14, "t", &img, NULL, &d),
			 -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "truncated PPM"));
	assert_int_equal(image_read_memory((const uint8_t *)"hello", 5, "t", &img, NULL, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "not an image"));
	assert_int_equal(image_read_memory((const uint8_t *)"\x89PNG\r\n\x1a\nxx", 10, "t", &img, NULL, &d),
			 -RT_E_SYNTAX);
	assert_int_equal(image_read_memory(buf, 0, "t", &img, NULL, &d), -RT_E_SYNTAX);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_image_read_bmp24_bottom_up_padded,
			   test_image_read_bmp32_and_top_down, test_image_read_ppm,
			   test_image_read_refusals))
