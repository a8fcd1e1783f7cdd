/* Loading a scene file from disk or standard input, and the assignment's
 * built-in test scene, read like a file. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "base/alloc.h"
#include "base/file.h"
#include "base/platform.h"
#include "whitted/scenefile.h"

/* The smallest default limit, the one whole files were read under. */
#define SCENE_MIN_MAX_BYTES ((size_t)256 << 20)

size_t scene_default_max_bytes(void)
{
	unsigned long long mem = rt_memory_bytes() / 8;

	if (mem < SCENE_MIN_MAX_BYTES)
		return SCENE_MIN_MAX_BYTES;
	/* Within half the address space (a 32-bit build on a big machine). */
	return mem > (unsigned long long)(SIZE_MAX / 2) ? SIZE_MAX / 2 : (size_t)mem;
}

/* n bytes for a message: "256 MiB", "2.9 GiB", "100 KiB", "1000 bytes". */
static const char *scene_format_bytes(size_t n, char *buf, size_t size)
{
	if (n >= (size_t)1 << 30)
		snprintf(buf, size, "%.1f GiB", (double)n / (double)(1u << 30));
	else if (n >= (size_t)1 << 20)
		snprintf(buf, size, "%.0f MiB", (double)n / (double)(1u << 20));
	else if (n >= (size_t)1 << 10)
		snprintf(buf, size, "%.0f KiB", (double)n / 1024.0);
	else
		snprintf(buf, size, "%zu byte%s", n, n == 1 ? "" : "s");
	return buf;
}

int scene_load(const char *path, const struct scene_read_options *opt,
	       diag_note_fn *note, void *note_ctx, struct scene **out, struct diag *d)
{
	const char *name = strcmp(path, "-") == 0 ? "<stdin>" : path;
	char *text;
	size_t len, limit;
	int rc;

	*out = NULL;
	limit = opt && opt->max_bytes ? opt->max_bytes : scene_default_max_bytes();
	rc = file_read_any(path, "scene file", limit, &text, &len, d);
	if (rc == -RT_E_RANGE) {
		char size[32], def[32];
		return diag_set(d, RT_E_RANGE, name, 0, 0,
				"the scene file is larger than the limit of %s (--max-scene-size SIZE "
				"changes it; the default here is %s: an eighth of the memory this process may "
				"use, at least 256 MiB)",
				scene_format_bytes(limit, size, sizeof(size)),
				scene_format_bytes(scene_default_max_bytes(), def, sizeof(def)));
	}
	if (rc < 0)
		return rc;
	rc = scene_parse(name, text, len, opt, note, note_ctx, out, d);
	rt_free(text);
	return rc;
}

int scene_test_scene(struct scene **out, struct diag *d)
{
	static const char text[] =
		"4 768\n"
		"1\n"
		"sphere 0 0 10  10  1 0 0  0.4 0.2 0.2 0.2  1\n"
		"1\n"
		"-50 50 50  1 1 1\n";

	/* Hashed like a file, for the tiles of the test scene. */
	static const struct scene_read_options opt = { 1, true, RT_DIALECT_AUTO, false, 0 };

	return scene_parse("<test scene>", text, sizeof(text) - 1, &opt, NULL, NULL, out, d);
}
