/* Raw image samples for the comparison tools.  PNG goes through libpng's
 * full API, not the simplified one the library uses: POV-Ray writes a gAMA
 * chunk of 1.0 into its PNGs, and png_image_finish_read honours it,
 * converting linear samples to sRGB, while the comparison must see the
 * bytes as stored.  The full API reports errors by longjmp, hence the
 * setjmp here (allowed for this one reason). */
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imgio.h"

/* Keeps any input from allocating without bound (whitted's own limits). */
#define IMGIO_MAX_SIDE 32768
#define IMGIO_MAX_PIXELS (1L << 28)

struct imgio_png_ctx {
	char *msg;
	png_bytep *rows;
};

static void imgio_png_error(png_structp png, png_const_charp text)
{
	struct imgio_png_ctx *ctx = png_get_error_ptr(png);

	snprintf(ctx->msg, IMGIO_MSG_MAX, "PNG: %s", text);
	png_longjmp(png, 1);
}

static void imgio_png_warning(png_structp png, png_const_charp text)
{
	(void)png;
	(void)text;
}

static int imgio_alloc(struct imgio_image *img, long w, long h, char *msg)
{
	if (w < 1 || h < 1 || w > IMGIO_MAX_SIDE || h > IMGIO_MAX_SIDE || w * h > IMGIO_MAX_PIXELS) {
		snprintf(msg, IMGIO_MSG_MAX, "unsupported image size %ldx%ld", w, h);
		return -1;
	}
	img->rgb = malloc((size_t)w * (size_t)h * 3);
	if (!img->rgb) {
		snprintf(msg, IMGIO_MSG_MAX, "out of memory");
		return -1;
	}
	img->width = (int)w;
	img->height = (int)h;
	return 0;
}

static int imgio_read_png(FILE *f, struct imgio_image *img, char *msg)
{
	struct imgio_png_ctx ctx = { msg, NULL };
	png_structp png;
	png_infop info = NULL;
	png_uint_32 w, h, y;
	int depth, type;

	png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, imgio_png_error, imgio_png_warning);
	if (!png || !(info = png_create_info_struct(png))) {
		png_destroy_read_struct(&png, NULL, NULL);
		snprintf(msg, IMGIO_MSG_MAX, "out of memory");
		return -1;
	}
	if (setjmp(png_jmpbuf(png))) {
		png_destroy_read_struct(&png, &info, NULL);
		free(ctx.rows);
		imgio_free(img);
		return -1;
	}
	png_init_io(png, f);
	png_read_info(png, info);
	png_get_IHDR(png, info, &w, &h, &depth, &type, NULL, NULL, NULL);
	/* Shape every file into 8-bit RGB; no gamma or alpha-mode call, so
	 * the samples keep their stored values. */
	if (depth == 16)
		png_set_strip_16(png);
	if (type == PNG_COLOR_TYPE_PALETTE)
		png_set_palette_to_rgb(png);
	if (type == PNG_COLOR_TYPE_GRAY && depth < 8)
		png_set_expand_gray_1_2_4_to_8(png);
	if (type == PNG_COLOR_TYPE_GRAY || type == PNG_COLOR_TYPE_GRAY_ALPHA)
		png_set_gray_to_rgb(png);
	if (type & PNG_COLOR_MASK_ALPHA)
		png_set_strip_alpha(png);
	png_set_interlace_handling(png);
	png_read_update_info(png, info);
	if (png_get_rowbytes(png, info) != (size_t)w * 3)
		png_error(png, "cannot convert to 8-bit RGB");
	if (imgio_alloc(img, (long)w, (long)h, msg) < 0)
		png_longjmp(png, 1);
	ctx.rows = malloc(h * sizeof(*ctx.rows));
	if (!ctx.rows)
		png_error(png, "out of memory");
	for (y = 0; y < h; y++)
		ctx.rows[y] = img->rgb + (size_t)y * w * 3;
	png_read_image(png, ctx.rows);
	png_read_end(png, NULL);
	png_destroy_read_struct(&png, &info, NULL);
	free(ctx.rows);
	return 0;
}

/* The next header number of a PPM, skipping whitespace and # comments. */
static long imgio_ppm_number(FILE *f)
{
	long v = 0;
	int c, digits = 0;

	while ((c = getc(f)) != EOF) {
		if (c == '#') {
			while ((c = getc(f)) != EOF && c != '\n')
				;
		} else if (c != ' ' && c != '\t' && c != '\r' && c != '\n') {
			break;
		}
	}
	while (c >= '0' && c <= '9' && digits < 9) {
		v = v * 10 + (c - '0');
		digits++;
		c = getc(f);
	}
	/* One whitespace character ends the number (and the header). */
	if (digits == 0 || (c != ' ' && c != '\t' && c != '\r' && c != '\n'))
		return -1;
	return v;
}

static int imgio_read_ppm(FILE *f, struct imgio_image *img, char *msg)
{
	long w = imgio_ppm_number(f), h = imgio_ppm_number(f), maxval = imgio_ppm_number(f);
	size_t n;

	if (w < 0 || h < 0 || maxval != 255) {
		snprintf(msg, IMGIO_MSG_MAX, "PPM: expected a P6 header with maxval 255");
		return -1;
	}
	if (imgio_alloc(img, w, h, msg) < 0)
		return -1;
	n = (size_t)w * (size_t)h * 3;
	if (fread(img->rgb, 1, n, f) != n) {
		snprintf(msg, IMGIO_MSG_MAX, "PPM: the file ends before the last pixel");
		imgio_free(img);
		return -1;
	}
	return 0;
}

static long imgio_le(const unsigned char *p, int n)
{
	unsigned long v = 0;
	int i;

	for (i = n - 1; i >= 0; i--)
		v = (v << 8) | p[i];
	/* Sign-extend a 32-bit value (BMP heights may be negative). */
	if (n == 4 && (v & 0x80000000UL))
		return -(long)((~v & 0xffffffffUL) + 1);
	return (long)v;
}

static int imgio_read_bmp(FILE *f, struct imgio_image *img, char *msg)
{
	unsigned char hdr[54];
	long offset, w, h, stride, y, x;
	bool top_down;
	unsigned char *row;

	if (fread(hdr, 1, sizeof(hdr), f) != sizeof(hdr) || imgio_le(hdr + 14, 4) < 40 ||
	    imgio_le(hdr + 26, 2) != 1 || imgio_le(hdr + 28, 2) != 24 || imgio_le(hdr + 30, 4) != 0) {
		snprintf(msg, IMGIO_MSG_MAX, "BMP: only uncompressed 24-bit files are read");
		return -1;
	}
	offset = imgio_le(hdr + 10, 4);
	w = imgio_le(hdr + 18, 4);
	h = imgio_le(hdr + 22, 4);
	top_down = h < 0;
	if (top_down)
		h = -h;
	if (imgio_alloc(img, w, h, msg) < 0)
		return -1;
	stride = (w * 3 + 3) & ~3L;
	row = malloc((size_t)stride);
	if (!row || offset < 54 || fseek(f, offset, SEEK_SET) != 0) {
		snprintf(msg, IMGIO_MSG_MAX, row ? "BMP: bad pixel offset" : "out of memory");
		goto out_fail;
	}
	for (y = 0; y < h; y++) {
		uint8_t *dst = img->rgb + (size_t)(top_down ? y : h - 1 - y) * (size_t)w * 3;
		if (fread(row, 1, (size_t)stride, f) != (size_t)stride) {
			snprintf(msg, IMGIO_MSG_MAX, "BMP: the file ends before the last pixel");
			goto out_fail;
		}
		for (x = 0; x < w; x++) {
			dst[3 * x] = row[3 * x + 2];
			dst[3 * x + 1] = row[3 * x + 1];
			dst[3 * x + 2] = row[3 * x];
		}
	}
	free(row);
	return 0;
out_fail:
	free(row);
	imgio_free(img);
	return -1;
}

int imgio_read(const char *path, struct imgio_image *img, char msg[IMGIO_MSG_MAX])
{
	unsigned char magic[8];
	FILE *f;
	size_t n;
	int rc;

	img->width = img->height = 0;
	img->rgb = NULL;
	f = fopen(path, "rb");
	if (!f) {
		snprintf(msg, IMGIO_MSG_MAX, "cannot open");
		return -1;
	}
	n = fread(magic, 1, sizeof(magic), f);
	rewind(f);
	if (n == 8 && png_sig_cmp(magic, 0, 8) == 0) {
		rc = imgio_read_png(f, img, msg);
	} else if (n >= 2 && magic[0] == 'P' && magic[1] == '6') {
		fseek(f, 2, SEEK_SET);
		rc = imgio_read_ppm(f, img, msg);
	} else if (n >= 2 && magic[0] == 'B' && magic[1] == 'M') {
		rc = imgio_read_bmp(f, img, msg);
	} else {
		snprintf(msg, IMGIO_MSG_MAX, "not a PNG, binary PPM or BMP file");
		rc = -1;
	}
	fclose(f);
	return rc;
}

int imgio_write_png(const char *path, const struct imgio_image *img, bool gama1,
		    char msg[IMGIO_MSG_MAX])
{
	struct imgio_png_ctx ctx = { msg, NULL };
	png_structp png;
	png_infop info = NULL;
	FILE *f = fopen(path, "wb");
	int y;

	if (!f) {
		snprintf(msg, IMGIO_MSG_MAX, "cannot write");
		return -1;
	}
	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, imgio_png_error, imgio_png_warning);
	if (!png || !(info = png_create_info_struct(png))) {
		png_destroy_write_struct(&png, NULL);
		fclose(f);
		snprintf(msg, IMGIO_MSG_MAX, "out of memory");
		return -1;
	}
	if (setjmp(png_jmpbuf(png))) {
		png_destroy_write_struct(&png, &info);
		fclose(f);
		remove(path);
		return -1;
	}
	png_init_io(png, f);
	png_set_IHDR(png, info, (png_uint_32)img->width, (png_uint_32)img->height, 8,
		     PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
		     PNG_FILTER_TYPE_DEFAULT);
	if (gama1)
		png_set_gAMA(png, info, 1.0);
	png_write_info(png, info);
	for (y = 0; y < img->height; y++)
		png_write_row(png, img->rgb + (size_t)y * (size_t)img->width * 3);
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
	if (fclose(f) != 0) {
		snprintf(msg, IMGIO_MSG_MAX, "write error");
		remove(path);
		return -1;
	}
	return 0;
}

void imgio_free(struct imgio_image *img)
{
	free(img->rgb);
	img->rgb = NULL;
	img->width = img->height = 0;
}
