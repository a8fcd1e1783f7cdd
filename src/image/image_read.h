/* The image readers behind image_read: stb_image's decoder, and the
 * checks and formats it lacks. */
#ifndef RT_IMAGE_READ_H
#define RT_IMAGE_READ_H

#include <stddef.h>

#include "whitted/image.h"

/* Refused before decoding: 64 Mpixels (192 MB of RGB). */
#define RT_IMAGE_READ_MAX_PIXELS (1LL << 26)

/* The message for an image of w x h pixels over max_pixels, named:
 * "30000x30000 is over the limit of 67108864 pixels (8192x8192)";
 * returns -RT_E_RANGE. */
int image_read_over_limit(const char *name, unsigned long long w, unsigned long long h,
			  unsigned long long max_pixels, struct diag *d);

/* PNG and BMP through stb_image, to 8-bit RGB; img->pixels is
 * from rt_malloc (image_free frees it). */
int image_stb_decode(const unsigned char *data, size_t len, const char *name,
		     struct image *img, struct diag *d);

#endif
