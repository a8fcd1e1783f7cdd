/* A PNG's image data (what its IDAT chunks hold), compressed in parallel,
 * and the whole-PNG writer that image_png.c and the tiles (dist/tile_png.c)
 * share, so that a tile of the whole image has the very same image data. */
#ifndef RT_PNG_IDAT_H
#define RT_PNG_IDAT_H

#include <png.h>
#include <stdio.h>

#include "whitted/diag.h"
#include "whitted/image.h"

/* The zlib stream of img's filtered rows. */
struct png_idat {
	unsigned char *data;
	size_t len;
};

int png_idat_compress(const struct image *img, struct png_idat *out, struct diag *d);
void png_idat_free(struct png_idat *z);

/* Called after png_set_IHDR and before png_write_info, to add chunks;
 * it runs inside the writer's error guard and may call libpng freely. */
typedef void png_idat_extra_fn(png_structp png, png_infop info, void *ctx);

/* Writes img as an 8-bit RGB PNG with an sRGB chunk to f: IHDR, sRGB,
 * whatever extra adds (may be NULL), the image data, IEND. */
int png_idat_write_file(const struct image *img, FILE *f, png_idat_extra_fn *extra, void *ctx,
			struct diag *d);

#endif
