/* The message for an image over the size limit, the same whichever reader
 * (image_read's own formats, stb_image, the PNG check) meets it first. */
#include <math.h>

#include "image/image_read.h"

int image_read_over_limit(const char *name, unsigned long long w, unsigned long long h,
			  unsigned long long max_pixels, struct diag *d)
{
	unsigned long long side = (unsigned long long)sqrt((double)max_pixels);

	if (side * side == max_pixels)
		return diag_set(d, RT_E_RANGE, name, 0, 0,
				"%llux%llu is over the limit of %llu pixels (%llux%llu)", w, h, max_pixels,
				side, side);
	return diag_set(d, RT_E_RANGE, name, 0, 0, "%llux%llu is over the limit of %llu pixels", w,
			h, max_pixels);
}
