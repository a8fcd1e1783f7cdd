/* Image buffers, format selection and an image written in its format
 * (through image_write_file's safe write, image_file.c). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/alloc.h"
#include "base/platform.h"
#include "whitted/image.h"

int image_alloc(struct image *img, int width, int height, struct diag *d)
{
	img->width = width;
	img->height = height;
	img->pixels = NULL;
	if (width < 1 || height < 1)
		return diag_fail(d, RT_E_INVALID, "bad image size %dx%d", width, height);
	img->pixels = rt_calloc_huge((size_t)width * (size_t)height, 3);
	if (!img->pixels)
		return diag_fail(d, RT_E_NOMEM, "out of memory for a %dx%d image",
				width, height);
	return 0;
}

void image_free(struct image *img)
{
	rt_free(img->pixels);
	img->pixels = NULL;
}

enum image_format image_format_from_name(const char *name)
{
	if (strcasecmp(name, "png") == 0)
		return RT_FORMAT_PNG;
	if (strcasecmp(name, "bmp") == 0)
		return RT_FORMAT_BMP;
	if (strcasecmp(name, "ppm") == 0)
		return RT_FORMAT_PPM;
	return RT_FORMAT_UNKNOWN;
}

enum image_format image_format_from_path(const char *path)
{
	const char *slash = strrchr(path, '/');
	const char *dot = strrchr(slash ? slash + 1 : path, '.');

	return dot ? image_format_from_name(dot + 1) : RT_FORMAT_UNKNOWN;
}

static int image_write_stream(const struct image *img, FILE *f, enum image_format fmt,
			      struct diag *d)
{
	switch (fmt) {
	case RT_FORMAT_PNG:
		return image_write_png(img, f, d);
	case RT_FORMAT_BMP:
		return image_write_bmp(img, f, d);
	case RT_FORMAT_PPM:
		return image_write_ppm(img, f, d);
	case RT_FORMAT_UNKNOWN:
		break;
	}
	return diag_fail(d, RT_E_INVALID, "unknown image format");
}

struct image_fill_ctx {
	const struct image *img;
	enum image_format fmt;
};

static int image_fill(void *ctx, FILE *f, struct diag *d)
{
	const struct image_fill_ctx *c = ctx;

	return image_write_stream(c->img, f, c->fmt, d);
}

int image_write(const struct image *img, const char *path, enum image_format fmt,
		const volatile sig_atomic_t *cancel, struct diag *d)
{
	struct image_fill_ctx c;

	c.img = img;
	c.fmt = fmt;
	return image_write_file(path, image_fill, &c, cancel, d);
}

