/* Reading a submitted image (PNG, BMP of 24 or 32 bits, bottom-up or
 * top-down, binary or ASCII PPM) into 8-bit RGB.  stb_image decodes PNG and
 * BMP; this file refuses what it would quietly accept (a BMP shorter than
 * its header says: stb reads the missing bytes as zeros) and reads the
 * PNM formats itself (stb has no ASCII P3, and mishandles 16-bit grey). */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdbool.h>
#include <stdint.h>
#include <string.h>

#include "base/alloc.h"
#include "base/file.h"
#include "image/image_read.h"
#include "image/png_check.h"

/* A submission larger than this is not an image of the course. */
#define IMAGE_READ_MAX_BYTES ((size_t)1 << 28)

static uint32_t le32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static unsigned le16(const unsigned char *p)
{
	return (unsigned)p[0] | (unsigned)p[1] << 8;
}

/* An uncompressed BMP (BI_RGB or BI_BITFIELDS) must hold every padded row
 * its header announces. */
static int image_check_bmp(const unsigned char *b, size_t len, const char *name, struct diag *d)
{
	unsigned long long off, hdr, bpp, comp, rowsize, need;
	long long w, h;

	if (len < 26)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0, "truncated BMP: %zu bytes, no whole header", len);
	off = le32(b + 10);
	hdr = le32(b + 14);
	if (hdr == 12) {
		w = le16(b + 18);
		h = le16(b + 20);
		bpp = le16(b + 24);
		comp = 0;
	} else {
		if (len < 34)
			return diag_set(d, RT_E_SYNTAX, name, 0, 0,
					"truncated BMP: %zu bytes, no whole header", len);
		w = (int32_t)le32(b + 18);
		h = (int32_t)le32(b + 22);
		bpp = le16(b + 28);
		comp = le32(b + 30);
	}
	if (h < 0)
		h = -h;
	/* Only uncompressed rows are read: stb_image 2.27 decodes a header
	 * with any other compression as if uncompressed, the missing bytes as
	 * zeros (a 60-byte file made 1536x4102 pixels). */
	if (comp == 1 || comp == 2)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"cannot read the image (an RLE-compressed BMP): save it uncompressed "
				"(24-bit) or as PNG");
	if (comp != 0 && comp != 3)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"cannot read the image (BMP compression %llu, not uncompressed rows): "
				"it is damaged or of a kind not read", comp);
	if (w <= 0 || h <= 0 || bpp == 0 || bpp > 32)
		return 0;	/* stb's own message says what is wrong */
	if ((unsigned long long)w * (unsigned long long)h > RT_IMAGE_READ_MAX_PIXELS)
		return image_read_over_limit(name, (unsigned long long)w, (unsigned long long)h,
					     RT_IMAGE_READ_MAX_PIXELS, d);
	rowsize = ((bpp * (unsigned long long)w + 31) / 32) * 4;
	need = off + rowsize * (unsigned long long)h;
	if (need > len)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"truncated BMP: its header gives %lldx%lld pixels of %llu bits "
				"(%llu bytes), the file has %zu",
				w, h, bpp, need, len);
	return 0;
}

/* Skips white space and # comments of a PNM header. */
static size_t pnm_skip(const unsigned char *b, size_t len, size_t i)
{
	while (i < len) {
		if (b[i] == '#') {
			while (i < len && b[i] != '\n' && b[i] != '\r')
				i++;
		} else if (isspace(b[i])) {
			i++;
		} else {
			break;
		}
	}
	return i;
}

/* A decimal number of a PNM header (at most 9 digits), or -1. */
static long pnm_number(const unsigned char *b, size_t len, size_t *i)
{
	long v = 0;
	int digits = 0;

	*i = pnm_skip(b, len, *i);
	while (*i < len && isdigit(b[*i]) && digits < 9) {
		v = v * 10 + (b[*i] - '0');
		(*i)++;
		digits++;
	}
	if (digits == 0 || (*i < len && isdigit(b[*i])))
		return -1;
	return v;
}

static int pnm_header(const unsigned char *b, size_t len, const char *name, long v[3], size_t *end,
		      struct diag *d)
{
	size_t i = 2;
	int k;

	for (k = 0; k < 3; k++) {
		v[k] = pnm_number(b, len, &i);
		if (v[k] < 0)
			return diag_set(d, RT_E_SYNTAX, name, 0, 0,
					i >= len ? "truncated PPM header" :
						   "bad PPM header: expected a number");
	}
	if (v[0] < 1 || v[1] < 1 || v[2] < 1 || v[2] > 65535)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"bad PPM header: %ldx%ld pixels, maximum value %ld", v[0], v[1], v[2]);
	if ((long long)v[0] * v[1] > RT_IMAGE_READ_MAX_PIXELS)
		return image_read_over_limit(name, (unsigned long long)v[0], (unsigned long long)v[1],
					     RT_IMAGE_READ_MAX_PIXELS, d);
	*end = i;
	return 0;
}

/* Binary P5 (grey) and P6: the raster after the header's one white-space
 * byte, 1 or (maximum > 255) 2 big-endian bytes a sample, must be whole;
 * samples are scaled to 0..255.  Read here rather than by stb_image, whose
 * 2.27 converts 16-bit grey with the 8-bit routine (a heap overflow that
 * tests/fuzz/images/crash-p5-16bit.pgm found). */
static int image_read_pnm(const unsigned char *b, size_t len, const char *name, struct image *img,
			  struct diag *d)
{
	long v[3];
	size_t end, n, k;
	unsigned long long need;
	int rc = pnm_header(b, len, name, v, &end, d);
	unsigned channels = b[1] == '6' ? 3u : 1u, width = v[2] > 255 ? 2u : 1u;

	if (rc < 0)
		return rc;
	need = (unsigned long long)v[0] * (unsigned long long)v[1] * channels * width;
	if (end + 1 + need > len)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"truncated PPM: its header gives %ldx%ld pixels (%llu bytes of "
				"pixels), the file has %zu bytes after the header",
				v[0], v[1], need, len > end + 1 ? len - end - 1 : 0);
	if ((rc = image_alloc(img, (int)v[0], (int)v[1], d)) < 0)
		return rc;
	b += end + 1;
	n = (size_t)v[0] * (size_t)v[1];
	for (k = 0; k < n * channels; k++) {
		long s = width == 2 ? (long)b[2 * k] << 8 | b[2 * k + 1] : (long)b[k];
		uint8_t level;
		if (s > v[2]) {
			image_free(img);
			return diag_set(d, RT_E_SYNTAX, name, 0, 0,
					"bad PPM sample %zu: %ld, above the maximum %ld", k + 1, s, v[2]);
		}
		level = (uint8_t)((s * 255 + v[2] / 2) / v[2]);
		if (channels == 3) {
			img->pixels[k] = level;
		} else {
			img->pixels[3 * k] = img->pixels[3 * k + 1] = img->pixels[3 * k + 2] = level;
		}
	}
	return 0;
}

/* ASCII P3: every sample a number up to the maximum, scaled to 0..255. */
static int image_read_p3(const unsigned char *b, size_t len, const char *name, struct image *img,
			 struct diag *d)
{
	long v[3], s;
	size_t end, n, k;
	int rc = pnm_header(b, len, name, v, &end, d);

	if (rc < 0)
		return rc;
	n = (size_t)v[0] * (size_t)v[1] * 3;
	/* Each sample is a digit at least, and white space between two:
	 * checked before the image is allocated. */
	if (len - end < 2 * n - 1)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"truncated PPM: its header gives %ldx%ld pixels (%zu samples), the "
				"file has %zu bytes after the header", v[0], v[1], n, len - end);
	if ((rc = image_alloc(img, (int)v[0], (int)v[1], d)) < 0)
		return rc;
	for (k = 0; k < n; k++) {
		s = pnm_number(b, len, &end);
		if (s < 0 || s > v[2]) {
			image_free(img);
			if (s < 0 && pnm_skip(b, len, end) >= len)
				return diag_set(d, RT_E_SYNTAX, name, 0, 0,
						"truncated PPM: %zu of %zu samples", k, n);
			return diag_set(d, RT_E_SYNTAX, name, 0, 0,
					"bad PPM sample %zu: expected a number from 0 to %ld", k + 1, v[2]);
		}
		img->pixels[k] = (uint8_t)((s * 255 + v[2] / 2) / v[2]);
	}
	return 0;
}

static uint32_t be32(const unsigned char *p)
{
	return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | (uint32_t)p[3];
}

/* stb_image 2.27 copies a first IDAT chunk of length 0 to a null pointer
 * (undefined behaviour that tests/fuzz/images/crash-png-empty-idat.png
 * found); such a chunk holds nothing, so a copy without it is the same
 * image.  *out is NULL when there is none (data is then read as it is). */
static int png_drop_empty_idat(const unsigned char *data, size_t len, unsigned char **out,
			       size_t *out_len, struct diag *d)
{
	size_t off = 8, n = 8;
	bool found = false;
	unsigned char *copy;

	*out = NULL;
	while (off + 12 <= len && be32(data + off) <= len - off - 12) {
		uint32_t chunk = be32(data + off);
		if (chunk == 0 && memcmp(data + off + 4, "IDAT", 4) == 0)
			found = true;
		off += 12 + chunk;
	}
	if (!found)
		return 0;
	if (!(copy = rt_malloc(len)))
		return diag_fail(d, RT_E_NOMEM, "out of memory reading the image");
	memcpy(copy, data, 8);
	off = 8;
	while (off + 12 <= len && be32(data + off) <= len - off - 12) {
		uint32_t chunk = be32(data + off);
		if (!(chunk == 0 && memcmp(data + off + 4, "IDAT", 4) == 0)) {
			memcpy(copy + n, data + off, 12 + (size_t)chunk);
			n += 12 + (size_t)chunk;
		}
		off += 12 + chunk;
	}
	memcpy(copy + n, data + off, len - off);
	*out = copy;
	*out_len = n + len - off;
	return 0;
}

/* The name of an image format that is not read, by its magic bytes, or
 * NULL. */
static const char *image_other_format(const unsigned char *b, size_t len)
{
	if (len >= 6 && (memcmp(b, "GIF87a", 6) == 0 || memcmp(b, "GIF89a", 6) == 0))
		return "GIF";
	if (len >= 12 && memcmp(b, "RIFF", 4) == 0 && memcmp(b + 8, "WEBP", 4) == 0)
		return "WebP";
	if (len >= 4 && (memcmp(b, "II*\0", 4) == 0 || memcmp(b, "MM\0*", 4) == 0))
		return "TIFF";
	if (len >= 4 && memcmp(b, "qoif", 4) == 0)
		return "QOI";
	return NULL;
}

int image_read_memory(const unsigned char *data, size_t len, const char *name, struct image *img,
		      enum image_format *format, struct diag *d)
{
	int rc;

	img->width = img->height = 0;
	img->pixels = NULL;
	if (format)
		*format = image_format_of_bytes(data, len);
	if (len == 0)
		return diag_set(d, RT_E_SYNTAX, name, 0, 0, "an empty file, not an image");
	if (len >= 2 && data[0] == 'B' && data[1] == 'M') {
		if ((rc = image_check_bmp(data, len, name, d)) < 0)
			return rc;
	} else if (len >= 2 && data[0] == 'P' && (data[1] == '5' || data[1] == '6')) {
		return image_read_pnm(data, len, name, img, d);
	} else if (len >= 2 && data[0] == 'P' && data[1] == '3') {
		return image_read_p3(data, len, name, img, d);
	} else if (len >= 8 && memcmp(data, "\x89PNG\r\n\x1a\n", 8) == 0) {
		struct png_facts facts;
		unsigned char *clean;
		size_t clean_len;
		/* What stb_image does not check (CRCs, a size within the limit
		 * and the file's means, data no more than the header's), before
		 * it allocates anything. */
		if ((rc = png_check(data, len, name, RT_IMAGE_READ_MAX_PIXELS, true, &facts, d)) < 0) {
			char why[RT_DIAG_MSG_MAX];

			if (rc != -RT_E_SYNTAX || !d)
				return rc;
			snprintf(why, sizeof(why), "%s", d->msg);
			return diag_set(d, RT_E_SYNTAX, name, 0, 0,
					"cannot read the image (%s): it is damaged or truncated", why);
		}
		if ((rc = png_drop_empty_idat(data, len, &clean, &clean_len, d)) < 0)
			return rc;
		if (clean) {
			rc = image_stb_decode(clean, clean_len, name, img, d);
			rt_free(clean);
			return rc;
		}
	} else if (len >= 3 && data[0] == 0xff && data[1] == 0xd8 && data[2] == 0xff) {
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"a JPEG image, which is not accepted: JPEG is lossy (its pixels are "
				"not the ones the program computed); save the image as PNG or BMP");
	} else if (image_other_format(data, len)) {
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"a %s image, which is not read: save the image as PNG or BMP",
				image_other_format(data, len));
	} else {
		return diag_set(d, RT_E_SYNTAX, name, 0, 0,
				"not an image: PNG, BMP or PPM expected (the file starts with "
				"neither \\x89PNG, BM, P3, P5 nor P6)");
	}
	return image_stb_decode(data, len, name, img, d);
}

int image_read(const char *path, struct image *img, enum image_format *format, struct diag *d)
{
	char *data;
	size_t len;
	int rc;

	img->width = img->height = 0;
	img->pixels = NULL;
	if ((rc = file_read_all(path, "image", IMAGE_READ_MAX_BYTES, &data, &len, d)) < 0)
		return rc;
	rc = image_read_memory((const unsigned char *)data, len, path, img, format, d);
	rt_free(data);
	return rc;
}
