/* png_check (image/png_check.c): PNGs that libpng writes, in every colour
 * type and bit depth, interlaced or not, at odd sizes, pass (the image
 * data the header describes is computed as libpng lays it out); every cut
 * of one and a CRC damaged in each of its chunks is refused; data
 * inflating past the header's image, or short of it, is refused; sizes
 * over the limit are named; a small file claiming a large image is refused
 * before anything is inflated. */
#include <png.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "image/png_check.h"
#include "support.h"

struct mem {
	unsigned char *b;
	size_t n, cap;
};

static void mem_write(png_structp png, png_bytep data, size_t n)
{
	struct mem *m = png_get_io_ptr(png);

	if (m->n + n > m->cap) {
		m->cap = (m->n + n) * 2;
		m->b = realloc(m->b, m->cap);
		assert_non_null(m->b);
	}
	memcpy(m->b + m->n, data, n);
	m->n += n;
}

static void mem_flush(png_structp png)
{
	(void)png;
}

/* A w x h PNG of that colour type, depth and interlace, written by
 * libpng; the caller frees m->b. */
static void write_png(struct mem *m, unsigned w, unsigned h, int color, int depth, int interlace)
{
	png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
	png_infop info = png_create_info_struct(png);
	size_t rowbytes;
	unsigned char *row;
	unsigned y, pass, passes;

	assert_non_null(info);
	memset(m, 0, sizeof(*m));
	if (setjmp(png_jmpbuf(png)))
		fail_msg("libpng could not write the test image");
	png_set_write_fn(png, m, mem_write, mem_flush);
	png_set_IHDR(png, info, w, h, depth, color, interlace, PNG_COMPRESSION_TYPE_DEFAULT,
		     PNG_FILTER_TYPE_DEFAULT);
	if (color == PNG_COLOR_TYPE_PALETTE) {
		png_color pal[256];
		memset(pal, 0, sizeof(pal));
		png_set_PLTE(png, info, pal, 1 << depth);
	}
	png_write_info(png, info);
	rowbytes = png_get_rowbytes(png, info);
	row = calloc(rowbytes ? rowbytes : 1, 1);
	assert_non_null(row);
	passes = (unsigned)png_set_interlace_handling(png);
	for (pass = 0; pass < passes; pass++)
		for (y = 0; y < h; y++) {
			memset(row, (int)(y * 37 + pass), rowbytes);
			png_write_row(png, row);
		}
	png_write_end(png, info);
	png_destroy_write_struct(&png, &info);
	free(row);
}

static void test_png_check_passes_what_libpng_writes(void **state)
{
	static const struct { int color, depth; } kinds[] = {
		{ PNG_COLOR_TYPE_GRAY, 1 },	  { PNG_COLOR_TYPE_GRAY, 2 },
		{ PNG_COLOR_TYPE_GRAY, 4 },	  { PNG_COLOR_TYPE_GRAY, 8 },
		{ PNG_COLOR_TYPE_GRAY, 16 },	  { PNG_COLOR_TYPE_RGB, 8 },
		{ PNG_COLOR_TYPE_RGB, 16 },	  { PNG_COLOR_TYPE_PALETTE, 1 },
		{ PNG_COLOR_TYPE_PALETTE, 4 },	  { PNG_COLOR_TYPE_PALETTE, 8 },
		{ PNG_COLOR_TYPE_GRAY_ALPHA, 8 }, { PNG_COLOR_TYPE_RGB_ALPHA, 8 },
		{ PNG_COLOR_TYPE_RGB_ALPHA, 16 },
	};
	static const unsigned sizes[][2] = { { 1, 1 }, { 1, 9 }, { 5, 3 }, { 17, 2 }, { 33, 31 } };
	size_t k, s;
	int il;

	(void)state;
	for (k = 0; k < sizeof(kinds) / sizeof(kinds[0]); k++)
		for (s = 0; s < sizeof(sizes) / sizeof(sizes[0]); s++)
			for (il = 0; il < 2; il++) {
				struct png_facts f;
				struct mem m;
				struct diag d;
				int rc;

				write_png(&m, sizes[s][0], sizes[s][1], kinds[k].color, kinds[k].depth,
					  il ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE);
				rc = png_check(m.b, m.n, "t.png", 1 << 20, true, &f, &d);
				if (rc != 0)
					fail_msg("colour type %d depth %d %ux%u interlace %d: %s",
						 kinds[k].color, kinds[k].depth, sizes[s][0], sizes[s][1],
						 il, d.msg);
				assert_int_equal(f.width, sizes[s][0]);
				assert_int_equal(f.end, m.n);
				free(m.b);
			}
}

static uint32_t be32(const unsigned char *p)
{
	return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3];
}

static void test_png_check_refuses_cuts_and_damage(void **state)
{
	struct png_facts f;
	struct mem m;
	struct diag d;
	size_t cut, off = 8;
	unsigned char *bad;

	(void)state;
	write_png(&m, 9, 7, PNG_COLOR_TYPE_RGB, 8, PNG_INTERLACE_NONE);
	for (cut = 0; cut < m.n; cut++)
		if (png_check(m.b, cut, "t.png", 1 << 20, true, &f, &d) == 0)
			fail_msg("a copy cut at %zu of %zu bytes passed", cut, m.n);
	bad = malloc(m.n);
	assert_non_null(bad);
	while (off + 12 <= m.n) {
		uint32_t n = be32(m.b + off);
		char want[64];

		memcpy(bad, m.b, m.n);
		bad[off + 8 + n] ^= 0x40;	/* the CRC's first byte */
		assert_int_equal(png_check(bad, m.n, "t.png", 1 << 20, false, &f, &d), -RT_E_SYNTAX);
		snprintf(want, sizeof(want), "bad CRC in its %.4s chunk", (const char *)m.b + off + 4);
		assert_non_null(strstr(d.msg, want));
		off += 12 + n;
	}
	free(bad);
	free(m.b);
}

static size_t put_chunk(unsigned char *b, const char *type, const unsigned char *data, uint32_t n)
{
	uint32_t crc;

	b[0] = (unsigned char)(n >> 24);
	b[1] = (unsigned char)(n >> 16);
	b[2] = (unsigned char)(n >> 8);
	b[3] = (unsigned char)n;
	memcpy(b + 4, type, 4);
	if (n)
		memcpy(b + 8, data, n);
	crc = (uint32_t)crc32(crc32(0L, Z_NULL, 0), b + 4, 4 + n);
	b[8 + n] = (unsigned char)(crc >> 24);
	b[9 + n] = (unsigned char)(crc >> 16);
	b[10 + n] = (unsigned char)(crc >> 8);
	b[11 + n] = (unsigned char)crc;
	return 12 + n;
}

/* A w x h 8-bit RGB PNG header and one IDAT of `raw` zero bytes
 * compressed; *len its size; the caller frees it. */
static unsigned char *make_png(uint32_t w, uint32_t h, size_t raw, size_t *len)
{
	unsigned char ihdr[13] = { 0 }, *zeros = calloc(raw ? raw : 1, 1), *b;
	uLongf zn = compressBound((uLong)raw);
	unsigned char *z = malloc(zn);
	size_t n = 8;

	assert_non_null(zeros);
	assert_non_null(z);
	assert_int_equal(compress2(z, &zn, zeros, (uLong)raw, 9), Z_OK);
	b = malloc(8 + 25 + 12 + zn + 12);
	assert_non_null(b);
	memcpy(b, "\x89PNG\r\n\x1a\n", 8);
	ihdr[0] = (unsigned char)(w >> 24), ihdr[1] = (unsigned char)(w >> 16);
	ihdr[2] = (unsigned char)(w >> 8), ihdr[3] = (unsigned char)w;
	ihdr[4] = (unsigned char)(h >> 24), ihdr[5] = (unsigned char)(h >> 16);
	ihdr[6] = (unsigned char)(h >> 8), ihdr[7] = (unsigned char)h;
	ihdr[8] = 8;
	ihdr[9] = 2;
	n += put_chunk(b + n, "IHDR", ihdr, 13);
	n += put_chunk(b + n, "IDAT", z, (uint32_t)zn);
	n += put_chunk(b + n, "IEND", NULL, 0);
	free(zeros);
	free(z);
	*len = n;
	return b;
}

static void test_png_check_data_and_size(void **state)
{
	struct png_facts f;
	struct diag d;
	unsigned char *b;
	size_t n;

	(void)state;
	/* 16x16 RGB: 16 rows of 1 + 48 bytes. */
	b = make_png(16, 16, 784, &n);
	assert_int_equal(png_check(b, n, "t.png", 1 << 20, true, &f, &d), 0);
	assert_int_equal(f.raw_bytes, 784);
	free(b);
	b = make_png(16, 16, 785, &n);
	assert_int_equal(png_check(b, n, "t.png", 1 << 20, true, &f, &d), -RT_E_SYNTAX);
	assert_string_equal(d.msg, "too much image data: the header's 16x16 needs 784 bytes, the data inflates to more");
	/* Without the data's check (a header's read), the same file passes. */
	assert_int_equal(png_check(b, n, "t.png", 1 << 20, false, &f, &d), 0);
	free(b);
	/* 64 MiB of zeros for the same 16x16. */
	b = make_png(16, 16, (size_t)64 << 20, &n);
	assert_int_equal(png_check(b, n, "t.png", 1 << 20, true, &f, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "too much image data"));
	free(b);
	b = make_png(16, 16, 783, &n);
	assert_int_equal(png_check(b, n, "t.png", 1 << 20, true, &f, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "not enough image data"));
	free(b);
	b = make_png(30000, 30000, 784, &n);
	assert_int_equal(png_check(b, n, "t.png", (uint64_t)1 << 26, true, &f, &d), -RT_E_RANGE);
	assert_string_equal(d.msg, "30000x30000 is over the limit of 67108864 pixels (8192x8192)");
	/* Within the limit, but more than 784 compressed bytes can hold. */
	assert_int_equal(png_check(b, n, "t.png", (uint64_t)1 << 30, true, &f, &d), -RT_E_SYNTAX);
	assert_non_null(strstr(d.msg, "the header's 30000x30000 needs 2700030000 bytes of image data, "
				      "more than its"));
	free(b);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_png_check_passes_what_libpng_writes,
			   test_png_check_refuses_cuts_and_damage, test_png_check_data_and_size))
