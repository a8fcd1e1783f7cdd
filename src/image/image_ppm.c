/* Binary PPM (P6) output. */
#include <errno.h>
#include <string.h>

#include "whitted/image.h"

int image_write_ppm(const struct image *img, FILE *f, struct diag *d)
{
	size_t n = (size_t)img->width * (size_t)img->height * 3;

	if (fprintf(f, "P6\n%d %d\n255\n", img->width, img->height) < 0 ||
	    fwrite(img->pixels, 1, n, f) != n)
		return diag_fail(d, RT_E_IO, "cannot write PPM: %s", strerror(errno));
	return 0;
}
