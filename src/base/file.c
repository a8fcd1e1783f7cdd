/* Whole-file reads for the scene, keyframe and tile readers: one loop that
 * grows its buffer geometrically up to a limit, so no input can make a
 * reader allocate without bound. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "base/alloc.h"
#include "base/file.h"
#include "base/platform.h"

static int file_too_large(const char *name, size_t limit, struct diag *d)
{
	return diag_set(d, RT_E_RANGE, name, 0, 0, "the file is larger than the limit of %lu bytes",
			(unsigned long)limit);
}

static int file_read_stream(FILE *f, const char *name, const char *what, size_t limit,
			    char **out, size_t *out_len, struct diag *d)
{
	size_t cap = 65536, len = 0;
	struct stat st;
	char *buf;

	if (fstat(fileno(f), &st) == 0) {
		if (S_ISDIR(st.st_mode))
			return diag_set(d, RT_E_IO, name, 0, 0, "is a directory, not %s %s",
					what[0] && strchr("aeiou", what[0]) ? "an" : "a", what);
		if (S_ISREG(st.st_mode)) {
			if ((unsigned long long)st.st_size > limit)
				return file_too_large(name, limit, d);
			if ((size_t)st.st_size >= cap)
				cap = (size_t)st.st_size + 1;
		}
	}
	buf = rt_malloc(cap);
	if (!buf)
		return diag_set(d, RT_E_NOMEM, name, 0, 0, "out of memory reading the file");
	for (;;) {
		size_t n;
		/* One byte stays free for the terminating NUL. */
		if (cap - len < 2) {
			char *p;
			if (len > limit) {
				rt_free(buf);
				return file_too_large(name, limit, d);
			}
			/* limit + 2 cannot wrap: file_read_path caps the limit. */
			cap = cap * 2 > limit + 2 ? limit + 2 : cap * 2;
			p = rt_reallocarray(buf, cap, 1);
			if (!p) {
				rt_free(buf);
				return diag_set(d, RT_E_NOMEM, name, 0, 0, "out of memory reading the file");
			}
			buf = p;
		}
		n = fread(buf + len, 1, cap - len - 1, f);
		len += n;
		if (n == 0)
			break;
	}
	if (ferror(f)) {
		int err = errno;
		rt_free(buf);
		return diag_set(d, RT_E_IO, name, 0, 0, "cannot read: %s", strerror(err));
	}
	if (len > limit) {
		rt_free(buf);
		return file_too_large(name, limit, d);
	}
	buf[len] = '\0';
	*out = buf;
	*out_len = len;
	return 0;
}

/* What a file that is not a regular one is, for the message. */
static const char *file_kind(mode_t mode)
{
	if (S_ISFIFO(mode))
		return "a named pipe";
	if (S_ISCHR(mode))
		return "a character device";
	if (S_ISBLK(mode))
		return "a block device";
	if (S_ISSOCK(mode))
		return "a socket";
	return "not a regular file";
}

/* Opens path for reading: only a regular file (or a directory, which the
 * read refuses with its own message) when `regular`, opened without
 * waiting (a named pipe's open waits for a writer; O_NONBLOCK's does not,
 * and fstat then tells what it is). */
static FILE *file_open(const char *path, bool regular, struct diag *d)
{
	struct stat st;
	FILE *f;
	int fd;

	errno = 0;
	if (!regular) {
		f = fopen(path, "rb");
		if (!f)
			diag_set(d, RT_E_IO, path, 0, 0, "cannot open: %s",
				 errno ? strerror(errno) : "out of memory");
		return f;
	}
	fd = open(path, O_RDONLY | O_NONBLOCK | RT_O_BINARY);
	if (fd < 0) {
		int err = errno;

		/* A socket cannot be opened at all (ENXIO): say what it is. */
		if (stat(path, &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode))
			diag_set(d, RT_E_IO, path, 0, 0,
				 "is %s, not a file (only a scene may come from a pipe)",
				 file_kind(st.st_mode));
		else
			diag_set(d, RT_E_IO, path, 0, 0, "cannot open: %s", strerror(err));
		return NULL;
	}
	if (fstat(fd, &st) != 0) {
		diag_set(d, RT_E_IO, path, 0, 0, "cannot open: %s", strerror(errno));
		close(fd);
		return NULL;
	}
	if (!S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode)) {
		diag_set(d, RT_E_IO, path, 0, 0, "is %s, not a file (only a scene may come from a pipe)",
			 file_kind(st.st_mode));
		close(fd);
		return NULL;
	}
	f = fdopen(fd, "rb");
	if (!f) {
		diag_set(d, RT_E_IO, path, 0, 0, "cannot open: %s",
			 errno ? strerror(errno) : "out of memory");
		close(fd);
	}
	return f;
}

static int file_read_path(const char *path, const char *what, size_t limit, bool regular,
			  char **out, size_t *out_len, struct diag *d)
{
	bool is_stdin = strcmp(path, "-") == 0;
	const char *name = is_stdin ? "<stdin>" : path;
	FILE *f;
	int rc;

	*out = NULL;
	*out_len = 0;
	/* The buffer is the limit and 2 bytes: kept from wrapping round. */
	if (limit > SIZE_MAX / 2)
		limit = SIZE_MAX / 2;
	/* Standard input may be a terminal or a pipe nobody writes to: only
	 * the scene is read from it. */
	if (is_stdin && regular)
		return diag_set(d, RT_E_IO, path, 0, 0,
				"is standard input, not a file (only a scene may come from a pipe)");
	f = is_stdin ? stdin : file_open(path, regular, d);
	if (!f)
		return -RT_E_IO;
	rc = file_read_stream(f, name, what, limit, out, out_len, d);
	if (!is_stdin)
		fclose(f);
	return rc;
}

int file_read_all(const char *path, const char *what, size_t limit,
		  char **out, size_t *out_len, struct diag *d)
{
	return file_read_path(path, what, limit, true, out, out_len, d);
}

int file_read_any(const char *path, const char *what, size_t limit,
		  char **out, size_t *out_len, struct diag *d)
{
	return file_read_path(path, what, limit, false, out, out_len, d);
}
