/* Whole-file reads for the scene, keyframe and tile readers: one loop that
 * grows its buffer geometrically up to a limit, so no input can make a
 * reader allocate without bound. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

#include "base/alloc.h"
#include "base/file.h"

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

int file_read_all(const char *path, const char *what, size_t limit,
		  char **out, size_t *out_len, struct diag *d)
{
	bool is_stdin = strcmp(path, "-") == 0;
	const char *name = is_stdin ? "<stdin>" : path;
	FILE *f;
	int rc;

	*out = NULL;
	*out_len = 0;
	errno = 0;
	f = is_stdin ? stdin : fopen(path, "rb");
	if (!f)
		return diag_set(d, RT_E_IO, path, 0, 0, "cannot open: %s",
				errno ? strerror(errno) : "out of memory");
	rc = file_read_stream(f, name, what, limit, out, out_len, d);
	if (!is_stdin)
		fclose(f);
	return rc;
}
