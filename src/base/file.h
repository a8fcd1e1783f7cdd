/* Reading whole input files into memory, with a size limit. */
#ifndef RT_FILE_H
#define RT_FILE_H

#include <stddef.h>

#include "whitted/diag.h"

/* Reads the whole of path ("-": standard input, named "<stdin>" in
 * messages) into a NUL-terminated buffer from rt_malloc.  Refuses a
 * directory ("is a directory, not a WHAT") and more than limit bytes, the
 * latter before reading when the size is known. */
int file_read_all(const char *path, const char *what, size_t limit,
		  char **out, size_t *out_len, struct diag *d);

#endif
