/* The difference picture of compare --diff and grade's report: the two
 * halves of grade_diff_image, the ties (either colour right) in blue, the
 * outline of each object that differs in cyan, and a legend under them
 * in a small bitmap font. */
#include <string.h>

#include "grade/grade_impl.h"

/* 5 x 7 glyphs, a row a byte, the leftmost pixel in bit 4. */
struct grade_glyph {
	char c;
	uint8_t rows[7];
};

static const struct grade_glyph grade_font[] = {
	{ '>', { 0x10, 0x08, 0x04, 0x02, 0x04, 0x08, 0x10 } },
	{ '2', { 0x0e, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1f } },
	{ '8', { 0x0e, 0x11, 0x11, 0x0e, 0x11, 0x11, 0x0e } },
	{ ':', { 0x00, 0x04, 0x00, 0x00, 0x00, 0x04, 0x00 } },
	{ 'a', { 0x00, 0x00, 0x0e, 0x01, 0x0f, 0x11, 0x0f } },
	{ 'b', { 0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x1e } },
	{ 'c', { 0x00, 0x00, 0x0e, 0x10, 0x10, 0x11, 0x0e } },
	{ 'd', { 0x01, 0x01, 0x0d, 0x13, 0x11, 0x11, 0x0f } },
	{ 'e', { 0x00, 0x00, 0x0e, 0x11, 0x1f, 0x10, 0x0e } },
	{ 'f', { 0x06, 0x09, 0x08, 0x1c, 0x08, 0x08, 0x08 } },
	{ 'g', { 0x00, 0x0f, 0x11, 0x11, 0x0f, 0x01, 0x0e } },
	{ 'h', { 0x10, 0x10, 0x16, 0x19, 0x11, 0x11, 0x11 } },
	{ 'i', { 0x04, 0x00, 0x0c, 0x04, 0x04, 0x04, 0x0e } },
	{ 'j', { 0x02, 0x00, 0x06, 0x02, 0x02, 0x12, 0x0c } },
	{ 'l', { 0x0c, 0x04, 0x04, 0x04, 0x04, 0x04, 0x0e } },
	{ 'n', { 0x00, 0x00, 0x16, 0x19, 0x11, 0x11, 0x11 } },
	{ 'o', { 0x00, 0x00, 0x0e, 0x11, 0x11, 0x11, 0x0e } },
	{ 'r', { 0x00, 0x00, 0x16, 0x19, 0x10, 0x10, 0x10 } },
	{ 's', { 0x00, 0x00, 0x0e, 0x10, 0x0e, 0x01, 0x1e } },
	{ 't', { 0x08, 0x08, 0x1c, 0x08, 0x08, 0x09, 0x06 } },
	{ 'u', { 0x00, 0x00, 0x11, 0x11, 0x11, 0x13, 0x0d } },
	{ 'x', { 0x00, 0x00, 0x11, 0x0a, 0x04, 0x0a, 0x11 } },
	{ 'y', { 0x00, 0x00, 0x11, 0x11, 0x0f, 0x01, 0x0e } },
	{ '|', { 0x04, 0x04, 0x04, 0x04, 0x04, 0x04, 0x04 } },
	{ '-', { 0x00, 0x00, 0x00, 0x1f, 0x00, 0x00, 0x00 } },
};

static void grade_put(struct image *img, int x, int y, const uint8_t rgb[3])
{
	if (x >= 0 && y >= 0 && x < img->width && y < img->height)
		memcpy(img->pixels + 3 * ((size_t)y * (size_t)img->width + (size_t)x), rgb, 3);
}

/* Text at (x, y), each font pixel scale x scale; returns the x after it. */
static int grade_text(struct image *img, int x, int y, int scale, const char *s,
		      const uint8_t rgb[3])
{
	for (; *s; s++, x += 6 * scale) {
		size_t g;
		int r, c, i, j;
		for (g = 0; g < sizeof(grade_font) / sizeof(grade_font[0]) && grade_font[g].c != *s; g++)
			;
		if (g == sizeof(grade_font) / sizeof(grade_font[0]))
			continue;
		for (r = 0; r < 7; r++)
			for (c = 0; c < 5; c++)
				if (grade_font[g].rows[r] >> (4 - c) & 1)
					for (j = 0; j < scale; j++)
						for (i = 0; i < scale; i++)
							grade_put(img, x + c * scale + i, y + r * scale + j, rgb);
	}
	return x;
}

static int grade_swatch(struct image *img, int x, int y, int scale, const uint8_t rgb[3],
			const char *label)
{
	static const uint8_t white[3] = { 230, 230, 230 };
	int i, j;

	for (j = 0; j < 7 * scale; j++)
		for (i = 0; i < 7 * scale; i++)
			grade_put(img, x + i, y + j, rgb);
	return grade_text(img, x + 9 * scale, y, scale, label, white) + 8 * scale;
}

static const uint8_t grade_tie_rgb[3] = { 30, 50, 110 };
static const uint8_t grade_outline_rgb[3] = { 0, 230, 230 };

int grade_diff_picture(const struct image *ref, const struct image *sub, const uint8_t *ties,
		       const int32_t *ids, const uint8_t *differs, struct image *out,
		       struct diag *d)
{
	static const uint8_t white[3] = { 230, 230, 230 }, yellow[3] = { 255, 210, 0 },
			     red[3] = { 255, 0, 0 };
	struct image top;
	int w = ref->width, h = ref->height, scale = w >= 400 ? 2 : 1, band = 11 * scale, x, y, rc;

	if ((rc = grade_diff_image(ref, sub, &top, d)) < 0)
		return rc;
	if ((rc = image_alloc(out, top.width, h + band, d)) < 0) {
		image_free(&top);
		return rc;
	}
	memset(out->pixels, 0, (size_t)out->width * (size_t)out->height * 3);
	memcpy(out->pixels, top.pixels, (size_t)top.width * (size_t)h * 3);
	image_free(&top);
	for (y = 0; y < h; y++)
		for (x = 0; x < w; x++) {
			size_t i = (size_t)y * (size_t)w + (size_t)x;
			if (ties && ties[i])
				grade_put(out, w + x, y, grade_tie_rgb);
			/* An outline: a pixel of an object that differs beside
			 * a pixel of another object. */
			if (ids && differs) {
				int32_t id = ids[i];
				size_t slot = id == GRADE_ID_BACKGROUND ? 0 : id == GRADE_ID_FLOOR ? 1
					      : (size_t)id + 2;
				bool edge = (x > 0 && ids[i - 1] != id) || (x + 1 < w && ids[i + 1] != id) ||
					    (y > 0 && ids[i - (size_t)w] != id) ||
					    (y + 1 < h && ids[i + (size_t)w] != id);
				if (edge && differs[slot])
					grade_put(out, w + x, y, grade_outline_rgb);
			}
		}
	grade_text(out, 2 * scale, h + 2 * scale, scale, "difference x8", white);
	x = w + 2 * scale;
	x = grade_swatch(out, x, h + 2 * scale, scale, yellow, "off by > 2");
	x = grade_swatch(out, x, h + 2 * scale, scale, red, "> 8");
	x = grade_swatch(out, x, h + 2 * scale, scale, grade_tie_rgb, "tie");
	grade_swatch(out, x, h + 2 * scale, scale, grade_outline_rgb, "object differs");
	return 0;
}
