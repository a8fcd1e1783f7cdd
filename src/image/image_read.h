/* The image readers behind image_read: stb_image's decoder, and the
 * checks and formats it lacks. */
#ifndef RT_IMAGE_READ_H
#define RT_IMAGE_READ_H

#include <stddef.h>

#include "whitted/image.h"

/* Refused before decoding: 64 Mpixels (192 MB of RGB). */
#define RT_IMAGE_READ_MAX_PIXELS (1LL << 26)

/* PNG and BMP through stb_image, to 8-bit RGB; img->pixels is
 * from rt_malloc (image_free frees it). */
int image_stb_decode(const unsigned char *data, size_t len, const char *name,
		     struct image *img, struct diag *d);

#endif
