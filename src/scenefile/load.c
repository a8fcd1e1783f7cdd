/* Loading a scene file from disk or standard input, and the assignment's
 * built-in test scene, read like a file. */
#include <string.h>

#include "base/alloc.h"
#include "base/file.h"
#include "whitted/scenefile.h"

int scene_load(const char *path, const struct scene_read_options *opt,
	       diag_note_fn *note, void *note_ctx, struct scene **out, struct diag *d)
{
	const char *name = strcmp(path, "-") == 0 ? "<stdin>" : path;
	char *text;
	size_t len;
	int rc;

	*out = NULL;
	rc = file_read_any(path, "scene file", RT_MAX_SCENE_BYTES, &text, &len, d);
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
	static const struct scene_read_options opt = { 1, true, RT_DIALECT_AUTO, false };

	return scene_parse("<test scene>", text, sizeof(text) - 1, &opt, NULL, NULL, out, d);
}
