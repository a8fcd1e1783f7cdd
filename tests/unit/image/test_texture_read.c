/* image_read: a hand-made 24-bit bottom-up BMP of 3 x 2 (rows padded to 12
 * bytes) read as its pixels top row first; PNG and BMP written by the
 * library's own writers read back equal (two implementations, libpng's
 * and ours against stb_image); the format told by the bytes; and the
 * errors: a missing file, an empty one, text, a PNG cut short, a BMP whose
 * rows are cut short (which stb_image alone would take). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "whitted/image.h"
#include "support.h"

static char dir[] = "/tmp/test_texture_read.XXXXXX";

static int make_dir(void **state)
{
	(void)state;
	return mkdtemp(dir) ? 0 : -1;
}

static int remove_dir(void **state)
{
	char cmd[64];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf %s", dir);
	return system(cmd) == 0 ? 0 : -1;
}

static const char *path_of(const char *name)
{
	static char buf[128];

	snprintf(buf, sizeof(buf), "%s/%s", dir, name);
	return buf;
}

static void write_bytes(const char *name, const unsigned char *b, size_t n)
{
	FILE *f = fopen(path_of(name), "wb");

	assert_non_null(f);
	assert_int_equal(fwrite(b, 1, n, f), n);
	assert_int_equal(fclose(f), 0);
}

/* 3 x 2, 24-bit, bottom-up: the file's first row is the image's bottom
 * row; each pixel is B G R; rows are padded to 12 bytes. */
static const unsigned char bmp_3x2[] = {
	'B', 'M', 78, 0, 0, 0, 0, 0, 0, 0, 54, 0, 0, 0,
	40, 0, 0, 0, 3, 0, 0, 0, 2, 0, 0, 0, 1, 0, 24, 0, 0, 0, 0, 0,
	24, 0, 0, 0, 0x13, 0x0b, 0, 0, 0x13, 0x0b, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
	/* bottom row: (10, 20, 30) (40, 50, 60) (70, 80, 90) */
	30, 20, 10, 60, 50, 40, 90, 80, 70, 0, 0, 0,
	/* top row: (255, 0, 0) (0, 255, 0) (0, 0, 255) */
	0, 0, 255, 0, 255, 0, 255, 0, 0, 0, 0, 0,
};

static void test_image_read_bmp_bottom_up(void **state)
{
	static const uint8_t want[18] = { 255, 0, 0, 0, 255, 0, 0, 0, 255,
					  10, 20, 30, 40, 50, 60, 70, 80, 90 };
	struct image img;
	enum image_format fmt = RT_FORMAT_UNKNOWN;
	struct diag d;

	(void)state;
	write_bytes("a.bmp", bmp_3x2, sizeof(bmp_3x2));
	assert_int_equal(image_read(path_of("a.bmp"), &img, &fmt, &d), 0);
	assert_int_equal(img.width, 3);
	assert_int_equal(img.height, 2);
	assert_int_equal(fmt, RT_FORMAT_BMP);
	assert_memory_equal(img.pixels, want, sizeof(want));
	image_free(&img);
}

static void test_image_read_round_trip(void **state)
{
	static const enum image_format formats[2] = { RT_FORMAT_PNG, RT_FORMAT_BMP };
	static const char *names[2] = { "b.png", "b.bmp" };
	struct image src, back;
	enum image_format fmt;
	struct diag d;
	int k, i;

	(void)state;
	assert_int_equal(image_alloc(&src, 5, 3, &d), 0);
	for (i = 0; i < 5 * 3 * 3; i++)
		src.pixels[i] = (uint8_t)(i * 17 + 3);
	for (k = 0; k < 2; k++) {
		assert_int_equal(image_write(&src, path_of(names[k]), formats[k], NULL, &d), 0);
		assert_int_equal(image_read(path_of(names[k]), &back, &fmt, &d), 0);
		assert_int_equal(fmt, formats[k]);
		assert_int_equal(back.width, 5);
		assert_int_equal(back.height, 3);
		assert_memory_equal(back.pixels, src.pixels, 5 * 3 * 3);
		image_free(&back);
	}
	image_free(&src);
}

static void expect_error(const char *name, int code, const char *msg)
{
	struct image img;
	struct diag d;

	assert_int_equal(image_read(path_of(name), &img, NULL, &d), code);
	assert_null(img.pixels);
	assert_non_null(strstr(d.msg, msg));
	assert_string_equal(d.file, path_of(name));
}

static void test_image_read_errors(void **state)
{
	unsigned char png[64];
	struct image src;
	struct diag d;
	FILE *f;
	size_t n;

	(void)state;
	assert_int_equal(image_alloc(&src, 4, 4, &d), 0);
	memset(src.pixels, 99, 4 * 4 * 3);
	assert_int_equal(image_write(&src, path_of("c.png"), RT_FORMAT_PNG, NULL, &d), 0);
	image_free(&src);
	expect_error("missing.png", -RT_E_IO, "cannot open");
	write_bytes("empty.png", (const unsigned char *)"", 0);
	expect_error("empty.png", -RT_E_SYNTAX, "an empty file, not an image");
	write_bytes("text.png", (const unsigned char *)"3\n160\n\n0\n", 9);
	expect_error("text.png", -RT_E_SYNTAX, "not an image");
	f = fopen(path_of("c.png"), "rb");
	assert_non_null(f);
	n = fread(png, 1, sizeof(png), f);
	fclose(f);
	assert_true(n > 40);
	write_bytes("cut.png", png, 40);
	expect_error("cut.png", -RT_E_SYNTAX, "cannot read the image");
	write_bytes("cut.bmp", bmp_3x2, sizeof(bmp_3x2) - 5);
	expect_error("cut.bmp", -RT_E_SYNTAX, "truncated BMP");
}

SUPPORT_MAIN_AROUND(make_dir, remove_dir,
		    SUPPORT_TESTS(test_image_read_bmp_bottom_up, test_image_read_round_trip,
				  test_image_read_errors))
