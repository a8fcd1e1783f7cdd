/* Reading scene files (scene-format.md) into a scene. */
#ifndef RT_SCENEFILE_H
#define RT_SCENEFILE_H

#include <stdbool.h>
#include <stddef.h>

#include "diag.h"
#include "scene.h"

/* How to read scene text; NULL means one thread and no hash. */
struct scene_read_options {
	/* At least 1: a big file's objects are read by up to this many
	 * threads.  The scene, its notes and its errors are the same for any
	 * number. */
	int threads;
	/* Fill the source hash (a multiplication a byte, so only when wanted). */
	bool hash;
	/* RT_DIALECT_AUTO (0) detects the dialect from the text (see
	 * docs/scene-format.md); any other value reads the file as that one. */
	enum scene_dialect dialect;
	/* Read as the course's count-driven programs do: once the last
	 * section's count is read, whatever follows is ignored with a note
	 * naming its line, where the strict reading refuses numbers that no
	 * count describes.  For `compare --lenient` and `grade --lenient`. */
	bool lenient;
	/* The largest file scene_load reads, in bytes; 0: the default,
	 * scene_default_max_bytes(). */
	size_t max_bytes;
};

/* The default limit on a scene file's size: an eighth of the memory this
 * process may use (the machine's, or its address-space limit where lower:
 * reading, the scene and the hierarchy's build take about six times the
 * file's size at their peak), at least 256 MiB; 256 MiB where the memory
 * is unknown. */
size_t scene_default_max_bytes(void);

/* Parses scene text; name is used in diagnostics.  Adds no floor (the
 * scene's view says which floor the file's dialect has: scene_view_of and
 * scene_add_view_floor).  A note says which dialect was read. */
int scene_parse(const char *name, const char *text, size_t len,
		const struct scene_read_options *opt, diag_note_fn *note, void *note_ctx,
		struct scene **out, struct diag *d);
/* Reads and parses a file ("-": standard input). */
int scene_load(const char *path, const struct scene_read_options *opt,
	       diag_note_fn *note, void *note_ctx, struct scene **out, struct diag *d);

/* The assignment's built-in test scene (a red sphere and a white light),
 * read like a file (with its hash, for tiles). */
int scene_test_scene(struct scene **out, struct diag *d);

#endif
