/* Zip files of submissions, read with libzip where this build has it
 * (RT_HAVE_LIBZIP, from the Makefile's pkg-config probe). */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "cli/grade_inputs.h"
#include "whitted/image.h"

#ifdef RT_HAVE_LIBZIP
#include <zip.h>

/* The largest entry read: a 16384 x 16384 BMP and some. */
#define GRADE_ZIP_MAX_ENTRY ((zip_uint64_t)800 << 20)

/* Whether an entry's name is an image's (and no folder, nor a resource
 * fork of macOS's). */
static int grade_zip_wanted(const char *name)
{
	size_t len = strlen(name);

	if (len == 0 || name[len - 1] == '/' || strstr(name, "__MACOSX/"))
		return 0;
	return grade_is_image_name(name);
}

int grade_zip_read(const char *path, struct grade_inputs *out, struct diag *d)
{
	int err = 0, rc = 0;
	zip_int64_t n, i;
	zip_t *z = zip_open(path, ZIP_RDONLY, &err);

	if (!z) {
		zip_error_t e;
		zip_error_init_with_code(&e, err);
		rc = diag_fail(d, RT_E_IO, "%s: cannot read the zip file: %s", path, zip_error_strerror(&e));
		zip_error_fini(&e);
		return rc;
	}
	n = zip_get_num_entries(z, 0);
	for (i = 0; i < n && rc == 0; i++) {
		const char *name = zip_get_name(z, (zip_uint64_t)i, 0);
		char *label;
		unsigned char *data;
		zip_stat_t st;
		zip_file_t *f;
		zip_int64_t got;

		if (!name || !grade_zip_wanted(name))
			continue;
		if (zip_stat_index(z, (zip_uint64_t)i, 0, &st) < 0 || !(st.valid & ZIP_STAT_SIZE)) {
			rc = diag_fail(d, RT_E_IO, "%s: %s: cannot read its size", path, name);
			break;
		}
		if (st.size > GRADE_ZIP_MAX_ENTRY) {
			rc = diag_fail(d, RT_E_RANGE, "%s: %s: %llu bytes, more than any image graded",
				       path, name, (unsigned long long)st.size);
			break;
		}
		if (!(data = rt_malloc(st.size ? (size_t)st.size : 1)) ||
		    !(label = rt_malloc(strlen(path) + strlen(name) + 2))) {
			rt_free(data);
			rc = diag_fail(d, RT_E_NOMEM, "out of memory for %s", name);
			break;
		}
		sprintf(label, "%s:%s", path, name);
		f = zip_fopen_index(z, (zip_uint64_t)i, 0);
		got = f ? zip_fread(f, data, st.size) : -1;
		if (f)
			zip_fclose(f);
		if (got < 0 || (zip_uint64_t)got != st.size) {
			rc = diag_fail(d, RT_E_IO, "%s: cannot read it from the zip file (damaged?)", label);
			rt_free(data);
		} else {
			rc = grade_inputs_add(out, label, NULL, data, (size_t)st.size, d);
		}
		rt_free(label);
	}
	zip_discard(z);
	return rc;
}

#else

int grade_zip_read(const char *path, struct grade_inputs *out, struct diag *d)
{
	(void)out;
	return diag_fail(d, RT_E_IO, "%s: this whitted was built without libzip, so it reads no "
			 "zip files: unzip it and give the folder (or install libzip-dev and "
			 "rebuild)", path);
}

#endif
