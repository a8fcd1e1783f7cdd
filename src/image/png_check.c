/* A PNG file's structure, checked before a decoder allocates for it
 * (png_check.h).  stb_image neither checks CRCs nor stops inflating where
 * the header's image ends (a 16x16 PNG whose data inflates to gigabytes
 * took 2.1 GB), and libpng reads a tile's surplus data to its end before
 * it complains; both trust the header's size.  Here every chunk is
 * checked whole with its CRC, the size against the limit and against what
 * the compressed bytes can hold, and the data inflated into a small
 * scratch buffer, counted and dropped, up to the first byte past the
 * header's image. */
#include <stdbool.h>
#include <string.h>
#include <zlib.h>

#include "image/image_read.h"
#include "image/png_check.h"

/* Deflate expands at most 1032 times (258 bytes from 2 bits); the margin
 * covers the zlib header and a few blocks' overhead. */
#define PNG_MAX_RATIO 1040u
#define PNG_RATIO_SLACK 64u

static uint32_t png_be32(const unsigned char *p)
{
	return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | (uint32_t)p[3];
}

static bool png_chunk_name_ok(const unsigned char *t)
{
	int i;

	for (i = 0; i < 4; i++)
		if (!((t[i] >= 'A' && t[i] <= 'Z') || (t[i] >= 'a' && t[i] <= 'z')))
			return false;
	return true;
}

/* The channels of a valid colour type and bit depth, or 0. */
static unsigned png_channels(int color_type, int depth)
{
	switch (color_type) {
	case 0:
		return depth == 1 || depth == 2 || depth == 4 || depth == 8 || depth == 16 ? 1 : 0;
	case 3:
		return depth == 1 || depth == 2 || depth == 4 || depth == 8 ? 1 : 0;
	case 2:
		return depth == 8 || depth == 16 ? 3 : 0;
	case 4:
		return depth == 8 || depth == 16 ? 2 : 0;
	case 6:
		return depth == 8 || depth == 16 ? 4 : 0;
	}
	return 0;
}

/* Rows of w pixels of `bits` bits each, h of them, each with its filter
 * byte. */
static uint64_t png_pass_bytes(uint64_t w, uint64_t h, unsigned bits)
{
	return w && h ? h * (1 + (w * bits + 7) / 8) : 0;
}

/* The inflated image data the header describes (Adam7: the seven passes'
 * sub-images). */
static uint64_t png_raw_bytes(const struct png_facts *f, unsigned bits)
{
	static const unsigned x0[7] = { 0, 4, 0, 2, 0, 1, 0 }, y0[7] = { 0, 0, 4, 0, 2, 0, 1 };
	static const unsigned dx[7] = { 8, 8, 4, 4, 2, 2, 1 }, dy[7] = { 8, 8, 8, 4, 4, 2, 2 };
	uint64_t sum = 0;
	int p;

	if (!f->interlace)
		return png_pass_bytes(f->width, f->height, bits);
	for (p = 0; p < 7; p++) {
		uint64_t w = f->width > x0[p] ? (f->width - x0[p] + dx[p] - 1) / dx[p] : 0;
		uint64_t h = f->height > y0[p] ? (f->height - y0[p] + dy[p] - 1) / dy[p] : 0;
		sum += png_pass_bytes(w, h, bits);
	}
	return sum;
}

static int png_check_ihdr(const unsigned char *c, uint32_t clen, const char *name,
			  uint64_t max_pixels, struct png_facts *f, struct diag *d)
{
	unsigned channels;

	if (clen != 13)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"damaged PNG file (its IHDR chunk has %lu bytes, not 13)",
				(unsigned long)clen);
	f->width = png_be32(c);
	f->height = png_be32(c + 4);
	f->bit_depth = c[8];
	f->color_type = c[9];
	f->interlace = c[12];
	if (f->width == 0 || f->height == 0 || f->width > 0x7fffffffu || f->height > 0x7fffffffu)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"damaged PNG file (its header gives %lux%lu pixels)",
				(unsigned long)f->width, (unsigned long)f->height);
	channels = png_channels(f->color_type, f->bit_depth);
	if (!channels || c[10] != 0 || c[11] != 0 || c[12] > 1)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"damaged PNG file (its header: bit depth %d, colour type %d, "
				"compression %d, filter %d, interlace %d)",
				f->bit_depth, f->color_type, c[10], c[11], c[12]);
	if ((uint64_t)f->width * f->height > max_pixels)
		return image_read_over_limit(name, f->width, f->height, max_pixels, d);
	f->raw_bytes = png_raw_bytes(f, channels * (unsigned)f->bit_depth);
	return 0;
}

/* Inflates the IDAT chunks of b (every chunk already checked whole), into
 * a scratch buffer, up to one byte past f->raw_bytes. */
static int png_check_inflate(const unsigned char *b, size_t end, const char *name,
			     const struct png_facts *f, struct diag *d)
{
	unsigned char scratch[16384];
	uint64_t total = 0;
	size_t off = 8;
	bool ended = false;
	z_stream z;
	int zrc = Z_OK;

	memset(&z, 0, sizeof(z));
	if (inflateInit(&z) != Z_OK)
		return diag_set(d, RT_E_NOMEM, name, 0, 0, "out of memory checking the PNG");
	while (off < end && !ended) {
		uint32_t clen = png_be32(b + off);

		if (memcmp(b + off + 4, "IDAT", 4) == 0) {
			z.next_in = (unsigned char *)(b + off + 8);
			z.avail_in = clen;
			/* On while input is left, or while the scratch buffer
			 * fills (output may be pending with no input left). */
			do {
				z.next_out = scratch;
				z.avail_out = sizeof(scratch);
				zrc = inflate(&z, Z_NO_FLUSH);
				total += sizeof(scratch) - z.avail_out;
				if (total > f->raw_bytes) {
					inflateEnd(&z);
					return diag_set(d, RT_E_SYNTAX, name, 0, 0,
							"too much image data: the header's %lux%lu needs "
							"%llu bytes, the data inflates to more",
							(unsigned long)f->width, (unsigned long)f->height,
							(unsigned long long)f->raw_bytes);
				}
				if (zrc == Z_STREAM_END)
					ended = true;
			} while (zrc == Z_OK && (z.avail_in > 0 || z.avail_out == 0));
			if (zrc != Z_OK && zrc != Z_BUF_ERROR && zrc != Z_STREAM_END)
				break;
		}
		off += 12 + (size_t)clen;
	}
	inflateEnd(&z);
	if (zrc != Z_OK && zrc != Z_BUF_ERROR && zrc != Z_STREAM_END)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0, "damaged PNG file (its image data: %s)",
				zrc == Z_MEM_ERROR ? "out of memory" : z.msg ? z.msg : "not a zlib stream");
	if (!ended || total < f->raw_bytes)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"not enough image data: the header's %lux%lu needs %llu bytes, the "
				"data %s after %llu: truncated or damaged",
				(unsigned long)f->width, (unsigned long)f->height,
				(unsigned long long)f->raw_bytes, ended ? "ends" : "stops",
				(unsigned long long)total);
	return 0;
}

int png_check(const unsigned char *b, size_t len, const char *name, uint64_t max_pixels,
	      bool data, struct png_facts *out, struct diag *d)
{
	struct png_facts f;
	uint64_t idat = 0;
	size_t off = 8;
	bool have_ihdr = false;
	int rc;

	memset(&f, 0, sizeof(f));
	if (len < 8 || memcmp(b, "\x89PNG\r\n\x1a\n", 8) != 0)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0, "not a PNG file");
	for (;;) {
		const unsigned char *t = b + off + 4;
		uint32_t clen;

		if (len - off < 12)
			return diag_set(d, RT_E_SYNTAX, name, 0, 0,
					"truncated PNG file: %s at byte %zu",
					len == off ? "it ends without an IEND chunk" : "a chunk cut short",
					off);
		clen = png_be32(b + off);
		if (clen > 0x7fffffffu || !png_chunk_name_ok(t))
			return diag_set(d, RT_E_SYNTAX, name, 0, 0,
					"damaged PNG file (no chunk at byte %zu)", off);
		if (clen > len - off - 12)
			return diag_set(d, RT_E_SYNTAX, name, 0, 0,
					"truncated PNG file: its %.4s chunk is cut short", (const char *)t);
		if (crc32(crc32(0L, Z_NULL, 0), t, 4 + clen) != png_be32(t + 4 + clen))
			return diag_set(d, RT_E_SYNTAX, name, 0, 0,
					"damaged PNG file (bad CRC in its %.4s chunk)", (const char *)t);
		if (!have_ihdr) {
			if (memcmp(t, "IHDR", 4) != 0)
				return diag_set(d, RT_E_SYNTAX, name, 0, 0,
						"damaged PNG file (its first chunk is %.4s, not IHDR)",
						(const char *)t);
			if ((rc = png_check_ihdr(t + 4, clen, name, max_pixels, &f, d)) < 0)
				return rc;
			have_ihdr = true;
		} else if (memcmp(t, "IDAT", 4) == 0) {
			idat += clen;
		} else if (memcmp(t, "IEND", 4) == 0) {
			f.end = off + 12 + clen;
			break;
		}
		off += 12 + (size_t)clen;
	}
	if (f.raw_bytes > (idat + PNG_RATIO_SLACK) * PNG_MAX_RATIO)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"the header's %lux%lu needs %llu bytes of image data, more than its "
				"%llu compressed bytes can hold: truncated or damaged",
				(unsigned long)f.width, (unsigned long)f.height,
				(unsigned long long)f.raw_bytes, (unsigned long long)idat);
	if (data && (rc = png_check_inflate(b, f.end, name, &f, d)) < 0)
		return rc;
	*out = f;
	return 0;
}
