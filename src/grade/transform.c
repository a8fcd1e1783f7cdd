/* The causes made from the reference itself: the image mirrored,
 * flipped, transposed, its red and blue swapped, or any of these at once
 * (a half turn is a mirror and a flip).  Each writes a new image of the
 * reference's size. */
#include <string.h>

#include "grade/grade_impl.h"

int grade_transform_map(const struct image *ref, unsigned map, struct image *out, struct diag *d)
{
	int w = ref->width, h = ref->height, x, y, rc = image_alloc(out, w, h, d);

	if (rc < 0)
		return rc;
	if ((map & GRADE_MAP_TRANSPOSE) && w != h)
		map &= ~(unsigned)GRADE_MAP_TRANSPOSE;
	for (y = 0; y < h; y++) {
		for (x = 0; x < w; x++) {
			uint8_t *o = out->pixels + ((size_t)y * (size_t)w + (size_t)x) * 3;
			const uint8_t *s;
			int sx = x, sy = y, t;

			/* The pixel of the reference this one shows, as
			 * render_causes.c's grade_render_chunk maps a render. */
			if (map & GRADE_MAP_TRANSPOSE) {
				t = sx;
				sx = sy;
				sy = t;
			}
			if (map & GRADE_MAP_MIRROR)
				sx = w - 1 - sx;
			if (map & GRADE_MAP_FLIP)
				sy = h - 1 - sy;
			s = ref->pixels + ((size_t)sy * (size_t)w + (size_t)sx) * 3;
			if (map & GRADE_MAP_RED_BLUE) {
				o[0] = s[2];
				o[1] = s[1];
				o[2] = s[0];
			} else {
				memcpy(o, s, 3);
			}
		}
	}
	return 0;
}
