/* A PNG's image data (what its IDAT chunks hold), compressed in parallel,
 * and the whole-PNG writer that image_png.c and the tiles (dist/tile_png.c)
 * share, so that a tile of the whole image has the very same image data. */
#ifndef RT_PNG_IDAT_H
#define RT_PNG_IDAT_H

#include <png.h>
#include <stdio.h>

#include "whitted/diag.h"
#include "whitted/image.h"

/* The rows of a strip, the unit compressed by one thread. */
#define PNG_IDAT_STRIP_ROWS 64

/* The zlib stream of img's filtered rows. */
struct png_idat {
	unsigned char *data;
	size_t len;
};

int png_idat_compress(const struct image *img, struct png_idat *out, struct diag *d);
void png_idat_free(struct png_idat *z);

/* The strips of img, compressed while it is still being made: after
 * png_idat_strips_open, a thread in [0, threads) that has made the rows of
 * band k (rows [k PNG_IDAT_STRIP_ROWS, (k + 1) PNG_IDAT_STRIP_ROWS), the
 * last band shorter) final calls png_idat_strips_band_done(st, k, thread),
 * once per band; no two calls with the same thread at once.  Calls for
 * different bands may come from different threads at the same time.
 * png_idat_strips_finish, once every thread is done, compresses what is
 * left and joins the strips: the same stream as png_idat_compress's
 * (png_idat_strips_write instead writes the file from the strips).  img
 * must stay in place (its pixels may change only in bands not yet told)
 * until png_idat_strips_free. */
struct png_idat_strips;

int png_idat_strips_open(const struct image *img, int threads, struct png_idat_strips **out,
			 struct diag *d);
void png_idat_strips_band_done(struct png_idat_strips *st, int band, int thread);
int png_idat_strips_finish(struct png_idat_strips *st, struct png_idat *out, struct diag *d);
void png_idat_strips_free(struct png_idat_strips *st);

/* For the writer (png_write.c): the strips compressed (those no
 * band_done call compressed, here) and the stream's trailer made; then
 * the stream's pieces, k in [0, png_idat_piece_count): the zlib header,
 * the strips in order, the trailer; their total length; and the image. */
int png_idat_strips_seal(struct png_idat_strips *st, struct diag *d);
int png_idat_piece_count(const struct png_idat_strips *st);
const unsigned char *png_idat_piece(const struct png_idat_strips *st, int k, size_t *len);
size_t png_idat_stream_len(const struct png_idat_strips *st);
const struct image *png_idat_strips_image(const struct png_idat_strips *st);

/* libpng's last error, for the message: a reader's or writer's error
 * pointer is its png_message, and png_message_error (its error callback)
 * keeps the text and returns to the guard (png_longjmp); warnings (an
 * unusual but readable chunk) change nothing (png_message_warning). */
struct png_message {
	char text[200];
};
void png_message_error(png_structp png, png_const_charp msg);
void png_message_warning(png_structp png, png_const_charp msg);

/* Called after png_set_IHDR and before png_write_info, to add chunks;
 * it runs inside the writer's error guard and may call libpng freely. */
typedef void png_idat_extra_fn(png_structp png, png_infop info, void *ctx);

/* Writes st's image as an 8-bit RGB PNG with an sRGB chunk to f: IHDR,
 * sRGB, whatever extra adds (may be NULL), the image data (st's strips,
 * those not yet compressed compressed here, once every thread that calls
 * png_idat_strips_band_done is done), IEND. */
int png_idat_strips_write(struct png_idat_strips *st, FILE *f, png_idat_extra_fn *extra,
			  void *ctx, struct diag *d);
/* The same with img's image data compressed here. */
int png_idat_write_file(const struct image *img, FILE *f, png_idat_extra_fn *extra, void *ctx,
			struct diag *d);

#endif
