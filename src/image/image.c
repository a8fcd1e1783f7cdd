/* Image buffers, format selection and the safe write: a temporary file in
 * the output's directory renamed over it, so that a failed or interrupted
 * write never leaves a partial image and never touches an existing one. */
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

/* The permissions a new file would get, so that the renamed temporary file
 * looks like one created in place. */
static mode_t image_new_file_mode(void)
{
	mode_t mask = umask(0);

	umask(mask);
	return 0666 & ~mask;
}

static bool image_cancelled(const volatile sig_atomic_t *cancel)
{
	return cancel && *cancel;
}

/* Writes to a non-regular file (a pipe, a terminal, a device) in place. */
static int image_write_direct(const char *path, image_fill_fn *fill, void *ctx,
			      struct diag *d)
{
	FILE *f = fopen(path, "wb");
	int rc;

	if (!f)
		return diag_set(d, RT_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
	rc = fill(ctx, f, d);
	if (fclose(f) != 0 && rc == 0)
		rc = diag_set(d, RT_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
	if (rc < 0 && d->file[0] == '\0')
		snprintf(d->file, sizeof(d->file), "%s", path);
	return rc;
}

bool image_path_is_direct(const char *path)
{
	struct stat st;

	/* /dev/stdout is a symbolic link to the descriptor, whose file may be
	 * regular: a temporary file in /dev renamed over the link would
	 * replace /dev/stdout itself. */
	if (strncmp(path, "/dev/", 5) == 0 || strncmp(path, "/proc/", 6) == 0)
		return true;
	return stat(path, &st) == 0 && !S_ISREG(st.st_mode);
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

/* Fills the open temporary file fd, gives it the output's mode and closes
 * it, whatever happens. */
static int image_fill_fd(int fd, mode_t mode, const char *path, image_fill_fn *fill, void *ctx,
			 struct diag *d)
{
	FILE *f = fdopen(fd, "wb");
	int rc;

	if (!f) {
		rc = diag_set(d, RT_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
		close(fd);
		return rc;
	}
	rc = fill(ctx, f, d);
	if (rc == 0 && fflush(f) != 0)
		rc = diag_set(d, RT_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
	if (rc == 0 && rt_file_set_mode(fd, (unsigned)mode) != 0)
		rc = diag_set(d, RT_E_IO, path, 0, 0, "cannot set permissions: %s", strerror(errno));
	if (fclose(f) != 0 && rc == 0)
		rc = diag_set(d, RT_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
	return rc;
}

int image_write_file(const char *path, image_fill_fn *fill, void *ctx,
		     const volatile sig_atomic_t *cancel, struct diag *d)
{
	const char *slash = strrchr(path, '/');
	size_t dir_len = slash ? (size_t)(slash - path) + 1 : 0;
	struct stat st;
	mode_t mode;
	char *tmp;
	int fd, rc;

	if (image_path_is_direct(path))
		return image_write_direct(path, fill, ctx, d);
	if (stat(path, &st) == 0) {
		if (!S_ISREG(st.st_mode))
			return image_write_direct(path, fill, ctx, d);
		mode = st.st_mode & 07777;
	} else {
		mode = image_new_file_mode();
	}
	tmp = rt_malloc(strlen(path) + 16);
	if (!tmp)
		return diag_fail(d, RT_E_NOMEM, "out of memory");
	memcpy(tmp, path, dir_len);
	/* At most 200 bytes of the name, so that the temporary name fits in
	 * NAME_MAX (255) whenever the output's name does. */
	sprintf(tmp + dir_len, ".%.200s.XXXXXX", path + dir_len);
	fd = mkstemp(tmp);
	if (fd < 0) {
		rc = diag_set(d, RT_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
		goto out_free;
	}
	rc = image_fill_fd(fd, mode, path, fill, ctx, d);
	if (rc == 0 && image_cancelled(cancel))
		rc = diag_fail(d, RT_E_INTERRUPTED, "interrupted");
	if (rc < 0)
		goto out_unlink;
	if (rt_rename_over(tmp, path) != 0) {
		rc = diag_set(d, RT_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
		goto out_unlink;
	}
	rt_free(tmp);
	return 0;
out_unlink:
	unlink(tmp);
	if (d->file[0] == '\0' && rc != -RT_E_INTERRUPTED)
		snprintf(d->file, sizeof(d->file), "%s", path);
out_free:
	rt_free(tmp);
	return rc;
}
