/* PNG output: the image data compressed for speed on several threads
 * (png_idat.c), the chunks written by libpng; and the same file with its
 * image data compressed during the render, strip by strip, by the render's
 * own threads (image_png_writer), so that little is left to do after it. */
#include "base/alloc.h"
#include "image/png_idat.h"
#include "whitted/image.h"

int image_write_png(const struct image *img, FILE *f, struct diag *d)
{
	return png_idat_write_file(img, f, NULL, NULL, d);
}

struct image_png_writer {
	const struct image *img;
	struct png_idat_strips *strips;
};

int image_png_writer_open(const struct image *img, int threads, struct image_png_writer **out,
			  struct diag *d)
{
	struct image_png_writer *w;
	int rc;

	*out = NULL;
	if (!(w = rt_malloc(sizeof(*w))))
		return diag_fail(d, RT_E_NOMEM, "out of memory compressing the PNG");
	w->img = img;
	if ((rc = png_idat_strips_open(img, threads, &w->strips, d)) < 0) {
		rt_free(w);
		return rc;
	}
	*out = w;
	return 0;
}

int image_png_writer_band_rows(void)
{
	return PNG_IDAT_STRIP_ROWS;
}

void image_png_writer_band_done(void *writer, int band, int thread)
{
	struct image_png_writer *w = writer;

	png_idat_strips_band_done(w->strips, band, thread);
}

/* image_write_file's fill: the chunks from the strips, so that an error
 * names the file as image_write's do. */
static int image_png_writer_fill(void *ctx, FILE *f, struct diag *d)
{
	struct image_png_writer *w = ctx;

	return png_idat_strips_write(w->strips, f, NULL, NULL, d);
}

int image_png_writer_write(struct image_png_writer *w, const char *path,
			   const volatile sig_atomic_t *cancel, struct diag *d)
{
	return image_write_file(path, image_png_writer_fill, w, cancel, d);
}

void image_png_writer_free(struct image_png_writer *w)
{
	if (!w)
		return;
	png_idat_strips_free(w->strips);
	rt_free(w);
}
