/* PNG into memory (libpng's simplified API), for images embedded in a
 * report as data: URIs. */
#include <png.h>
#include <string.h>

#include "base/alloc.h"
#include "whitted/image.h"

int image_encode_png(const struct image *img, unsigned char **out, size_t *out_len,
		     struct diag *d)
{
	png_image png;
	png_alloc_size_t size = 0;
	unsigned char *buf;

	*out = NULL;
	*out_len = 0;
	memset(&png, 0, sizeof(png));
	png.version = PNG_IMAGE_VERSION;
	png.width = (png_uint_32)img->width;
	png.height = (png_uint_32)img->height;
	png.format = PNG_FORMAT_RGB;
	if (!png_image_write_to_memory(&png, NULL, &size, 0, img->pixels, 0, NULL))
		return diag_fail(d, RT_E_IO, "cannot encode PNG: %s", png.message);
	if (!(buf = rt_malloc(size)))
		return diag_fail(d, RT_E_NOMEM, "out of memory for a PNG of %lu bytes",
				 (unsigned long)size);
	if (!png_image_write_to_memory(&png, buf, &size, 0, img->pixels, 0, NULL)) {
		rt_free(buf);
		return diag_fail(d, RT_E_IO, "cannot encode PNG: %s", png.message);
	}
	*out = buf;
	*out_len = size;
	return 0;
}
