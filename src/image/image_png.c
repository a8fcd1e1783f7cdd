/* PNG output: the image data compressed for speed on several threads
 * (png_idat.c), the chunks written by libpng. */
#include "image/png_idat.h"
#include "whitted/image.h"

int image_write_png(const struct image *img, FILE *f, struct diag *d)
{
	return png_idat_write_file(img, f, NULL, NULL, d);
}
