/* The safe write: a temporary file in the output's directory renamed over
 * it, so that a failed or interrupted write never leaves a partial file
 * and never touches an existing one; a pipe, a terminal or a device is
 * written in place. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/alloc.h"
#include "base/platform.h"
#include "whitted/image.h"

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
