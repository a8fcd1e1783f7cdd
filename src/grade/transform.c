/* The causes that are a transform of the reference rather than a render:
 * the image mirrored, upside down, transposed, with red and blue swapped,
 * or gamma-encoded.  Each writes a new image of the reference's size. */
#include <math.h>
#include <string.h>

#include "grade/grade_impl.h"

/* The gamma encoding of a linear 8-bit level, as a lookup table: the
 * sRGB curve, or the plain power 1/2.2 that many programs apply. */
static void grade_gamma_table(uint8_t table[256], bool srgb)
{
	int i;

	for (i = 0; i < 256; i++) {
		double c = i / 255.0, e;
		if (srgb)
			e = c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1.0 / 2.4) - 0.055;
		else
			e = pow(c, 1.0 / 2.2);
		table[i] = (uint8_t)floor(255.0 * e + 0.5);
	}
}

static int grade_transform_with(const struct image *ref, enum grade_cause c, bool srgb,
				struct image *out, struct diag *d)
{
	int w = ref->width, h = ref->height, x, y, rc = image_alloc(out, w, h, d);
	uint8_t table[256];

	if (rc < 0)
		return rc;
	if (c == RT_CAUSE_GAMMA)
		grade_gamma_table(table, srgb);
	for (y = 0; y < h; y++) {
		for (x = 0; x < w; x++) {
			const uint8_t *s;
			uint8_t *o = out->pixels + ((size_t)y * (size_t)w + (size_t)x) * 3;
			int sx = x, sy = y;

			if (c == RT_CAUSE_MIRRORED)
				sx = w - 1 - x;
			else if (c == RT_CAUSE_UPSIDE_DOWN)
				sy = h - 1 - y;
			else if (c == RT_CAUSE_TRANSPOSED && w == h) {
				sx = y;
				sy = x;
			}
			s = ref->pixels + ((size_t)sy * (size_t)w + (size_t)sx) * 3;
			if (c == RT_CAUSE_RED_BLUE) {
				o[0] = s[2];
				o[1] = s[1];
				o[2] = s[0];
			} else if (c == RT_CAUSE_GAMMA) {
				o[0] = table[s[0]];
				o[1] = table[s[1]];
				o[2] = table[s[2]];
			} else {
				memcpy(o, s, 3);
			}
		}
	}
	return 0;
}

int grade_transform(const struct image *ref, enum grade_cause c, struct image *out, struct diag *d)
{
	return grade_transform_with(ref, c, true, out, d);
}

int grade_transform_gamma(const struct image *ref, bool srgb, struct image *out, struct diag *d)
{
	return grade_transform_with(ref, RT_CAUSE_GAMMA, srgb, out, d);
}
