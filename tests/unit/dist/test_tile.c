/* Tiles: the record and its region checks, the whitted-tile text, and tile
 * PNGs written and read back through libpng, with their chunks checked in
 * the file's bytes and damaged files refused. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/hash.h"
#include "dist/tile_text.h"
#include "whitted/image.h"
#include "whitted/tile.h"
#include "support.h"

static char tmpdir[64];

static int setup_dir(void **state)
{
	const char *base = getenv("TMPDIR");

	(void)state;
	snprintf(tmpdir, sizeof(tmpdir), "%s/test_tile.XXXXXX", base && *base ? base : "/tmp");
	return mkdtemp(tmpdir) ? 0 : -1;
}

static int teardown_dir(void **state)
{
	char cmd[128];

	(void)state;
	snprintf(cmd, sizeof(cmd), "rm -rf '%s'", tmpdir);
	if (system(cmd) != 0)
		fprintf(stderr, "test_tile: could not remove %s\n", tmpdir);
	return 0;
}

static const char *tmp_path(const char *name)
{
	static char path[128];

	snprintf(path, sizeof(path), "%s/%s", tmpdir, name);
	return path;
}

static void spill(const char *path, const void *b, size_t n)
{
	FILE *f = fopen(path, "wb");

	assert_non_null(f);
	assert_int_equal(fwrite(b, 1, n, f), n);
	assert_int_equal(fclose(f), 0);
}

static uint32_t get32(const unsigned char *p)
{
	return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

/* The offset of the first chunk of this type (its length field), or 0. */
static size_t find_chunk(const unsigned char *b, size_t n, const char *type)
{
	size_t pos = 8;

	while (pos + 12 <= n) {
		if (memcmp(b + pos + 4, type, 4) == 0)
			return pos;
		pos += 12 + get32(b + pos);
	}
	return 0;
}

/* The 16x16 render's settings and a gradient for its region. */
static void make_tile(struct tile_info *info, struct image *img, int x0, int y0, int x1, int y1)
{
	struct settings s;
	struct diag d;
	int i;

	support_settings(&s, 16, 3);
	tile_info_init(info, &s, UINT64_C(0x0123456789abcdef), x0, y0, x1, y1);
	assert_int_equal(image_alloc(img, x1 - x0, y1 - y0, &d), 0);
	for (i = 0; i < img->width * img->height * 3; i++)
		img->pixels[i] = (uint8_t)(i * 7 + 3);
}

static void test_tile_info_init(void **state)
{
	struct tile_info info;
	struct image img;

	(void)state;
	make_tile(&info, &img, 3, 2, 10, 7);
	image_free(&img);
	assert_int_equal(info.full_width, 16);
	assert_int_equal(info.full_height, 16);
	assert_int_equal(info.x0, 3);
	assert_int_equal(info.y1, 7);
	assert_string_equal(info.options, "size=16 recursion=3 eye=0,-200,10 look=0,0,0 up=0,0,1 "
			    "fov=80 floor=1000,20 clamp=level");
	assert_true(info.options_hash == hash_bytes(RT_HASH_INIT, info.options, strlen(info.options)));
}

static void test_tile_check_region(void **state)
{
	struct diag d;

	(void)state;
	assert_int_equal(tile_check_region(0, 0, 16, 16, 16, 16, &d), 0);
	assert_int_equal(tile_check_region(4, 0, 4, 16, 16, 16, &d), -RT_E_INVALID);
	assert_non_null(strstr(d.msg, "empty or inverted"));
	assert_int_equal(tile_check_region(0, 0, 17, 16, 16, 16, &d), -RT_E_INVALID);
	assert_non_null(strstr(d.msg, "outside the 16x16 image"));
	assert_int_equal(tile_check_region(-1, 0, 5, 5, 16, 16, &d), -RT_E_INVALID);
}

static void test_tile_text_round_trip(void **state)
{
	struct tile_info info, back;
	struct image img;
	char text[RT_TILE_TEXT_MAX];
	struct diag d;

	(void)state;
	make_tile(&info, &img, 3, 2, 10, 7);
	image_free(&img);
	tile_text_format(&info, text, sizeof(text));
	assert_string_equal(text, "version 1\nfull-size 16 16\nregion 3 2 10 7\n"
			    "scene-hash 0123456789abcdef\noptions-hash b57ccb43f1003c77\n"
			    "options size=16 recursion=3 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 "
			    "floor=1000,20 clamp=level");
	assert_int_equal(tile_text_parse("t.png", text, strlen(text), &back, &d), 0);
	assert_memory_equal(&back, &info, sizeof(info));
}

static void test_tile_text_refused(void **state)
{
	struct tile_info info, back;
	struct image img;
	char text[RT_TILE_TEXT_MAX], bad[RT_TILE_TEXT_MAX + 16];
	struct diag d;

	(void)state;
	make_tile(&info, &img, 3, 2, 10, 7);
	image_free(&img);
	tile_text_format(&info, text, sizeof(text));
	/* A trailing newline, a second space, an upper-case hash digit. */
	snprintf(bad, sizeof(bad), "%s\n", text);
	assert_int_equal(tile_text_parse("t.png", bad, strlen(bad), &back, &d), -RT_E_SYNTAX);
	assert_string_equal(d.msg, "malformed whitted-tile chunk");
	assert_string_equal(d.file, "t.png");
	snprintf(bad, sizeof(bad), "%s", text);
	memcpy(strstr(bad, "region 3"), "region  3", 9);
	assert_int_equal(tile_text_parse("t.png", bad, strlen(bad), &back, &d), -RT_E_SYNTAX);
	snprintf(bad, sizeof(bad), "%s", text);
	*strstr(bad, "abcdef") = 'A';
	assert_int_equal(tile_text_parse("t.png", bad, strlen(bad), &back, &d), -RT_E_SYNTAX);
	/* Another version, the options edited, a region outside. */
	snprintf(bad, sizeof(bad), "version 2%s", text + 9);
	assert_int_equal(tile_text_parse("t.png", bad, strlen(bad), &back, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "version 2"));
	snprintf(bad, sizeof(bad), "%s", text);
	*strstr(bad, "recursion=3") = 'R';
	assert_int_equal(tile_text_parse("t.png", bad, strlen(bad), &back, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "options hash does not match"));
	snprintf(bad, sizeof(bad), "%s", text);
	memcpy(strstr(bad, "region 3 2 10 7"), "region 3 2 19 7", 15);
	assert_int_equal(tile_text_parse("t.png", bad, strlen(bad), &back, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "does not fit the 16x16 image"));
}

static void test_tile_png_round_trip(void **state)
{
	struct tile_info info, back;
	struct image img, pixels;
	const char *path = tmp_path("round.png");
	struct diag d;

	(void)state;
	make_tile(&info, &img, 3, 2, 10, 7);
	assert_int_equal(tile_write(path, &img, &info, NULL, &d), 0);
	assert_int_equal(tile_read(path, &back, NULL, &d), 0);
	assert_memory_equal(&back, &info, sizeof(info));
	memset(&back, 0, sizeof(back));
	assert_int_equal(tile_read(path, &back, &pixels, &d), 0);
	assert_memory_equal(&back, &info, sizeof(info));
	assert_int_equal(pixels.width, 7);
	assert_int_equal(pixels.height, 5);
	assert_memory_equal(pixels.pixels, img.pixels, 7 * 5 * 3);
	image_free(&pixels);
	image_free(&img);
}

/* The bytes of the tile 3 2 10 7 (make_tile) written to path; *info its
 * record.  The caller frees them. */
static unsigned char *written_tile(struct tile_info *info, const char *path, size_t *n)
{
	struct image img;
	struct diag d;

	make_tile(info, &img, 3, 2, 10, 7);
	assert_int_equal(tile_write(path, &img, info, NULL, &d), 0);
	image_free(&img);
	return support_read_file(path, n);
}

/* The chunks in the file: oFFs, vpAg and tEXt, all before the image data. */
static void test_tile_png_chunks(void **state)
{
	static const unsigned char offs[9] = { 0, 0, 0, 3, 0, 0, 0, 2, 0 };
	static const unsigned char vpag[9] = { 0, 0, 0, 16, 0, 0, 0, 16, 0 };
	struct tile_info info;
	const char *path = tmp_path("chunks.png");
	char text[RT_TILE_TEXT_MAX];
	size_t n, o, v, t, idat;
	unsigned char *b;

	(void)state;
	b = written_tile(&info, path, &n);
	o = find_chunk(b, n, "oFFs");
	v = find_chunk(b, n, "vpAg");
	t = find_chunk(b, n, "tEXt");
	idat = find_chunk(b, n, "IDAT");
	assert_true(o && v && t && idat && o < idat && v < idat && t < idat);
	assert_int_equal(get32(b + o), 9);
	assert_memory_equal(b + o + 8, offs, 9);
	assert_int_equal(get32(b + v), 9);
	assert_memory_equal(b + v + 8, vpag, 9);
	tile_text_format(&info, text, sizeof(text));
	assert_int_equal(get32(b + t), sizeof(RT_TILE_KEYWORD) + strlen(text));
	assert_memory_equal(b + t + 8, RT_TILE_KEYWORD, sizeof(RT_TILE_KEYWORD));
	assert_memory_equal(b + t + 8 + sizeof(RT_TILE_KEYWORD), text, strlen(text));
	free(b);
}

/* One byte changed in a chunk's data: RT_E_SYNTAX for a bad CRC, whether
 * the pixels are read or only the head (every chunk's CRC is checked
 * before libpng reads any: image/png_check.c). */
static void assert_damage_refused(const unsigned char *good, size_t n, const char *type)
{
	const char *path = tmp_path("damaged.png");
	unsigned char *b = malloc(n);
	struct tile_info info;
	struct image img;
	char want[64];
	size_t at;
	struct diag d;

	assert_non_null(b);
	memcpy(b, good, n);
	at = find_chunk(b, n, type);
	assert_true(at > 0);
	b[at + 8 + get32(b + at) / 2] ^= 0x10;
	spill(path, b, n);
	free(b);
	snprintf(want, sizeof(want), "bad CRC in its %s chunk", type);
	assert_int_equal(tile_read(path, &info, NULL, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, want));
	assert_int_equal(tile_read(path, &info, &img, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, want));
	assert_string_equal(d.file, path);
}

static void test_tile_png_damaged(void **state)
{
	struct tile_info info;
	struct image img;
	const char *path = tmp_path("good.png");
	unsigned char *b;
	size_t n;
	struct diag d;

	(void)state;
	b = written_tile(&info, path, &n);
	assert_damage_refused(b, n, "tEXt");
	assert_damage_refused(b, n, "oFFs");
	assert_damage_refused(b, n, "vpAg");
	assert_damage_refused(b, n, "IHDR");
	assert_damage_refused(b, n, "IDAT");
	/* Cut short in the chunks, then in the image data: both reads see it. */
	path = tmp_path("short.png");
	spill(path, b, 60);
	assert_int_equal(tile_read(path, &info, NULL, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "truncated PNG file"));
	spill(path, b, n - 20);
	assert_int_equal(tile_read(path, &info, NULL, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "truncated PNG file"));
	assert_int_equal(tile_read(path, &info, &img, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "truncated PNG file"));
	free(b);
}

static void test_tile_not_a_tile(void **state)
{
	struct tile_info info;
	struct image img;
	const char *path;
	struct diag d;

	(void)state;
	path = tmp_path("scene.txt");
	spill(path, "2\n4\n", 4);
	assert_int_equal(tile_read(path, &info, NULL, &d), -RT_E_SYNTAX);
	assert_string_equal(d.msg, "not a PNG file");
	path = tmp_path("empty.png");
	spill(path, "", 0);
	assert_int_equal(tile_read(path, &info, NULL, &d), -RT_E_SYNTAX);
	assert_string_equal(d.msg, "not a PNG file");
	path = tmp_path("plain.png");
	assert_int_equal(image_alloc(&img, 4, 4, &d), 0);
	memset(img.pixels, 200, 4 * 4 * 3);
	assert_int_equal(image_write(&img, path, RT_FORMAT_PNG, NULL, &d), 0);
	image_free(&img);
	assert_int_equal(tile_read(path, &info, NULL, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "not a whitted tile"));
	assert_int_equal(tile_read(tmp_path("missing.png"), &info, NULL, &d), -RT_E_IO);
}

/* A tile compresses its pixels as image_write compresses a PNG: a tile of
 * the whole image has the very same image data. */
static void test_tile_png_same_image_data(void **state)
{
	struct tile_info info;
	struct image img;
	const char *tile = tmp_path("whole-tile.png");
	const char *plain = tmp_path("whole.png");
	unsigned char *a, *b;
	size_t na, nb, ia, ib;
	struct diag d;

	(void)state;
	make_tile(&info, &img, 0, 0, 16, 16);
	assert_int_equal(tile_write(tile, &img, &info, NULL, &d), 0);
	assert_int_equal(image_write(&img, plain, RT_FORMAT_PNG, NULL, &d), 0);
	image_free(&img);
	a = support_read_file(tile, &na);
	b = support_read_file(plain, &nb);
	ia = find_chunk(a, na, "IDAT");
	ib = find_chunk(b, nb, "IDAT");
	assert_true(ia && ib);
	/* From the first IDAT on: the image data and IEND. */
	assert_int_equal(na - ia, nb - ib);
	assert_memory_equal(a + ia, b + ib, na - ia);
	free(a);
	free(b);
}

static void test_tile_write_refused(void **state)
{
	struct tile_info info;
	struct image img;
	struct diag d;

	(void)state;
	make_tile(&info, &img, 3, 2, 10, 7);
	info.x1 = 11;
	assert_int_equal(tile_write(tmp_path("wrong.png"), &img, &info, NULL, &d), -RT_E_INVALID);
	assert_int_equal(access(tmp_path("wrong.png"), F_OK), -1);
	info.x1 = 10;
	assert_int_equal(tile_write(tmp_path("nodir/t.png"), &img, &info, NULL, &d), -RT_E_IO);
	image_free(&img);
}

SUPPORT_MAIN_AROUND(setup_dir, teardown_dir,
		    SUPPORT_TESTS(test_tile_info_init, test_tile_check_region,
				  test_tile_text_round_trip, test_tile_text_refused,
				  test_tile_png_round_trip, test_tile_png_chunks,
				  test_tile_png_damaged, test_tile_not_a_tile,
				  test_tile_png_same_image_data, test_tile_write_refused))
