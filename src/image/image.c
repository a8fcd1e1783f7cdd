/* Image buffers, format selection and an image written in its format
 * (through image_write_file's safe write, image_file.c). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/alloc.h"
#include "base/platform.h"
#include "base/text.h"
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

/* The formats, one row each: everything else (the options' words and
 * messages, the extensions, the writers, the reader's detection, the
 * POV-Ray export of textures) reads them from here. */
static const struct image_format_row {
	const char *name;
	const char *magic;	/* the file's first bytes */
	size_t magic_len;
	int (*write)(const struct image *img, FILE *f, struct diag *d);
} image_formats[] = {
	[RT_FORMAT_PNG] = { "png", "\x89PNG\r\n\x1a\n", 8, image_write_png },
	[RT_FORMAT_BMP] = { "bmp", "BM", 2, image_write_bmp },
	[RT_FORMAT_PPM] = { "ppm", "P", 1, image_write_ppm },
};
#define IMAGE_FORMATS ((int)(sizeof(image_formats) / sizeof(image_formats[0])))

enum image_format image_format_from_name(const char *name)
{
	int f;

	for (f = RT_FORMAT_UNKNOWN + 1; f < IMAGE_FORMATS; f++)
		if (strcasecmp(name, image_formats[f].name) == 0)
			return (enum image_format)f;
	return RT_FORMAT_UNKNOWN;
}

const char *image_format_name(enum image_format fmt)
{
	return fmt > RT_FORMAT_UNKNOWN && (int)fmt < IMAGE_FORMATS ? image_formats[fmt].name : "?";
}

const char *image_format_names(char *buf, size_t size, const char *prefix)
{
	const char *names[IMAGE_FORMATS];
	int f;

	for (f = RT_FORMAT_UNKNOWN + 1; f < IMAGE_FORMATS; f++)
		names[f - 1] = image_formats[f].name;
	return text_word_list(buf, size, prefix, names, IMAGE_FORMATS - 1);
}

enum image_format image_format_of_bytes(const unsigned char *data, size_t len)
{
	int f;

	for (f = RT_FORMAT_UNKNOWN + 1; f < IMAGE_FORMATS; f++)
		if (len >= image_formats[f].magic_len &&
		    memcmp(data, image_formats[f].magic, image_formats[f].magic_len) == 0)
			return (enum image_format)f;
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
	if (fmt > RT_FORMAT_UNKNOWN && (int)fmt < IMAGE_FORMATS)
		return image_formats[fmt].write(img, f, d);
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

