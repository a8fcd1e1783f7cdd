/* The scene model: settings from the file, the objects and the lights.  The
 * scene owns everything in it; scene_destroy frees it all. */
#ifndef RT_SCENE_H
#define RT_SCENE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "diag.h"
#include "material.h"
#include "shape.h"
#include "vec3.h"

/* Limits that keep any input from allocating without bound. */
#define RT_MAX_IMAGE_SIZE 32768
#define RT_MAX_PIXELS (1L << 28)
#define RT_MAX_RECURSION 256
#define RT_MAX_OBJECTS 10000000L
#define RT_MAX_LIGHTS 100000L
#define RT_MAX_SCENE_BYTES (1L << 28)	/* 256 MiB: about 2 million objects */

/* The implicit floor of every scene (the assignment's Floor(1000, 20)). */
#define RT_FLOOR_WIDTH 1000.0
#define RT_FLOOR_TILE 20.0

struct light {
	struct vec3 pos;
	struct color color;
};

struct accel;

struct scene {
	char *name;			/* the file name, for messages */
	int recursion;			/* >= 1; 1 means no reflection rays */
	int image_size;			/* the image is image_size squared */
	struct shape **shapes;
	size_t n_shapes, cap_shapes;
	struct light *lights;
	size_t n_lights, cap_lights;
	struct accel *accel;		/* built by scene_prepare */
	/* hash_bytes of the scene text as read, so that region renders can
	 * tell whether they come from the same file. */
	uint64_t source_hash;		/* 0 unless asked for */
};

/* Receives notes (trailing text, degenerate shapes) during loading. */
typedef void scene_note_fn(void *ctx, const struct diag *note);

struct scene *scene_create(const char *name);
void scene_destroy(struct scene *s);
/* Takes ownership of sh, also on failure. */
int scene_add_shape(struct scene *s, struct shape *sh, struct diag *d);
int scene_add_light(struct scene *s, struct vec3 pos, struct color color, struct diag *d);
/* Adds the checkerboard floor (width and tile > 0). */
int scene_add_floor(struct scene *s, double width, double tile, struct diag *d);

/* How to read scene text; NULL means one thread and no hash. */
struct scene_read_options {
	/* At least 1: a big file's objects are read by up to this many
	 * threads.  The scene, its notes and its errors are the same for any
	 * number. */
	int threads;
	/* Fill source_hash (a multiplication a byte, so only when wanted). */
	bool hash;
};

/* Parses scene text; name is used in diagnostics.  Adds no floor. */
int scene_parse(const char *name, const char *text, size_t len,
		const struct scene_read_options *opt, scene_note_fn *note, void *note_ctx,
		struct scene **out, struct diag *d);
/* Reads and parses a file. */
int scene_load(const char *path, const struct scene_read_options *opt,
	       scene_note_fn *note, void *note_ctx, struct scene **out, struct diag *d);
/* The assignment's built-in test scene (a red sphere and a white light). */
int scene_test_scene(struct scene **out, struct diag *d);

/* Builds the acceleration structure with up to `threads` threads (at least
 * 1; the structure is the same for any number); call after the last shape
 * is added and before rendering. */
int scene_prepare(struct scene *s, int threads, struct diag *d);

#endif
