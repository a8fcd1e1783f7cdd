/* Reading whole input files into memory, with a size limit. */
#ifndef RT_FILE_H
#define RT_FILE_H

#include <stddef.h>

#include "whitted/diag.h"

/* Reads the whole of path ("-": standard input, named "<stdin>" in
 * messages) into a NUL-terminated buffer from rt_malloc.  Refuses what is
 * not a regular file at once, without waiting on it (a named pipe with no
 * writer, a device, a socket: "is a named pipe, not a file"), a directory
 * ("is a directory, not a WHAT") and more than limit bytes, the latter
 * before reading when the size is known.  "-" (standard input, which may
 * be a terminal) is refused too. */
int file_read_all(const char *path, const char *what, size_t limit,
		  char **out, size_t *out_len, struct diag *d);
/* file_read_all for an input that may also be a pipe or a device (the
 * scene file: `whitted <(gen)`), read until its end, and "-" standard
 * input whatever it is; still not a directory. */
int file_read_any(const char *path, const char *what, size_t limit,
		  char **out, size_t *out_len, struct diag *d);

#endif
