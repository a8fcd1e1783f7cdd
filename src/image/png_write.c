/* Whole PNG files through libpng (IHDR, sRGB, a caller's chunks, IEND)
 * around image data compressed in strips (png_idat.c), written chunk by
 * chunk straight from the strips. */
#include <errno.h>
#include <setjmp.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

#include "image/png_idat.h"

/* libpng's own IDAT size for the simplified writer. */
#define PNG_IDAT_CHUNK 8192

/* The libpng side: one write structure and the message of its error. */
struct png_idat_writer {
	png_structp png;
	png_infop info;
	const struct image *img;
	const struct png_idat_strips *st;	/* sealed */
	FILE *f;
	png_idat_extra_fn *extra;
	void *ctx;
	struct png_message msg;
};

void png_message_error(png_structp png, png_const_charp msg)
{
	struct png_message *m = png_get_error_ptr(png);

	snprintf(m->text, sizeof(m->text), "%s", msg);
	png_longjmp(png, 1);
}

void png_message_warning(png_structp png, png_const_charp msg)
{
	(void)png;
	(void)msg;
}

/* The sealed stream in IDAT chunks of PNG_IDAT_CHUNK bytes (the last
 * shorter), straight from its pieces: joining them first cost a copy and
 * the faults of a buffer the size of the file. */
static void png_idat_chunks(struct png_idat_writer *w)
{
	static const png_byte idat[5] = "IDAT";
	size_t total = png_idat_stream_len(w->st), pos, len, used = 0;
	const unsigned char *p;
	int k = 0, n = png_idat_piece_count(w->st);

	p = png_idat_piece(w->st, k, &len);
	for (pos = 0; pos < total; pos += PNG_IDAT_CHUNK) {
		size_t left = total - pos < PNG_IDAT_CHUNK ? total - pos : PNG_IDAT_CHUNK;

		png_write_chunk_start(w->png, idat, (png_uint_32)left);
		while (left > 0) {
			size_t take = len - used < left ? len - used : left;

			png_write_chunk_data(w->png, p + used, take);
			used += take;
			left -= take;
			if (used == len && k + 1 < n) {
				p = png_idat_piece(w->st, ++k, &len);
				used = 0;
			}
		}
		png_write_chunk_end(w->png);
	}
}

static void png_idat_steps(struct png_idat_writer *w)
{
	static const png_byte iend[5] = "IEND";

	png_init_io(w->png, w->f);
	png_set_IHDR(w->png, w->info, (png_uint_32)w->img->width, (png_uint_32)w->img->height, 8,
		     PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
		     PNG_FILTER_TYPE_DEFAULT);
	/* As libpng's simplified writer marks every 8-bit image. */
	png_set_sRGB(w->png, w->info, PNG_sRGB_INTENT_PERCEPTUAL);
	if (w->extra)
		w->extra(w->png, w->info, w->ctx);
	png_write_info(w->png, w->info);
	png_idat_chunks(w);
	/* png_write_end would refuse: it counts only the IDATs it wrote
	 * itself. */
	png_write_chunk(w->png, iend, NULL, 0);
}

/* Runs the steps; false when libpng failed in them (w->msg says why).
 * Everything the steps change lives in *w, so nothing needs to be
 * volatile. */
static bool png_idat_guard(struct png_idat_writer *w)
{
	if (setjmp(png_jmpbuf(w->png)))
		return false;
	png_idat_steps(w);
	return true;
}

int png_idat_strips_write(struct png_idat_strips *st, FILE *f, png_idat_extra_fn *extra,
			  void *ctx, struct diag *d)
{
	struct png_idat_writer w;
	bool ok;
	int rc;

	if ((rc = png_idat_strips_seal(st, d)) < 0)
		return rc;
	memset(&w, 0, sizeof(w));
	w.img = png_idat_strips_image(st);
	w.st = st;
	w.f = f;
	w.extra = extra;
	w.ctx = ctx;
	w.png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &w.msg, png_message_error, png_message_warning);
	if (w.png)
		w.info = png_create_info_struct(w.png);
	if (!w.info) {
		png_destroy_write_struct(&w.png, NULL);
		return diag_fail(d, RT_E_NOMEM, "out of memory for a PNG");
	}
	errno = 0;
	ok = png_idat_guard(&w);
	png_destroy_write_struct(&w.png, &w.info);
	/* The caller flushes (image_write_file): a small file fails there. */
	if (ok && !ferror(f))
		return 0;
	/* libpng says only "Write Error" when the stream fails: the reason
	 * (a full disk, a file-size limit) is in errno. */
	if (ferror(f) && errno != 0)
		return diag_fail(d, RT_E_IO, "cannot write PNG: %s", strerror(errno));
	return diag_fail(d, RT_E_IO, "cannot write PNG: %s", ok ? "write error" : w.msg.text);
}

int png_idat_write_file(const struct image *img, FILE *f, png_idat_extra_fn *extra, void *ctx,
			struct diag *d)
{
	struct png_idat_strips *st;
	int rc;

	if ((rc = png_idat_strips_open(img, 1, &st, d)) < 0)
		return rc;
	rc = png_idat_strips_write(st, f, extra, ctx, d);
	png_idat_strips_free(st);
	return rc;
}
