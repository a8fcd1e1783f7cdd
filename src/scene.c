/* The scene model: ownership of shapes and lights, loading from files and
 * the built-in test scene. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "accel.h"
#include "alloc.h"
#include "file.h"
#include "scene.h"

struct scene *scene_create(const char *name)
{
	struct scene *s = rt_calloc(1, sizeof(*s));

	if (!s)
		return NULL;
	s->name = rt_strdup(name ? name : "");
	if (!s->name) {
		rt_free(s);
		return NULL;
	}
	s->recursion = 1;
	s->image_size = 1;
	return s;
}

void scene_destroy(struct scene *s)
{
	size_t i;

	if (!s)
		return;
	accel_destroy(s->accel);
	for (i = 0; i < s->n_shapes; i++)
		shape_destroy(s->shapes[i]);
	rt_free(s->shapes);
	rt_free(s->lights);
	rt_free(s->name);
	rt_free(s);
}

/* Grows an array geometrically, so that a file's counts never make us
 * allocate for objects that are not there. */
static int scene_grow(void **array, size_t *cap, size_t need, size_t elem)
{
	size_t new_cap;
	void *p;

	if (need <= *cap)
		return 0;
	new_cap = *cap ? *cap * 2 : 16;
	while (new_cap < need)
		new_cap *= 2;
	p = rt_reallocarray(*array, new_cap, elem);
	if (!p)
		return -RT_E_NOMEM;
	*array = p;
	*cap = new_cap;
	return 0;
}

int scene_add_shape(struct scene *s, struct shape *sh, struct diag *d)
{
	if (s->n_shapes >= (size_t)RT_MAX_OBJECTS + 1) {
		shape_destroy(sh);
		return diag_set(d, RT_E_RANGE, s->name, 0, 0, "more than %ld objects", RT_MAX_OBJECTS);
	}
	if (scene_grow((void **)&s->shapes, &s->cap_shapes, s->n_shapes + 1, sizeof(*s->shapes)) < 0) {
		shape_destroy(sh);
		return diag_set(d, RT_E_NOMEM, s->name, 0, 0, "out of memory");
	}
	s->shapes[s->n_shapes++] = sh;
	return 0;
}

int scene_add_light(struct scene *s, struct vec3 pos, struct color color, struct diag *d)
{
	if (s->n_lights >= (size_t)RT_MAX_LIGHTS)
		return diag_set(d, RT_E_RANGE, s->name, 0, 0, "more than %ld lights", RT_MAX_LIGHTS);
	if (scene_grow((void **)&s->lights, &s->cap_lights, s->n_lights + 1, sizeof(*s->lights)) < 0)
		return diag_set(d, RT_E_NOMEM, s->name, 0, 0, "out of memory");
	s->lights[s->n_lights].pos = pos;
	s->lights[s->n_lights].color = color;
	s->n_lights++;
	return 0;
}

int scene_add_floor(struct scene *s, double width, double tile, struct diag *d)
{
	struct shape *floor;

	if (!(width > 0.0) || !(tile > 0.0) || !isfinite(width) || !isfinite(tile))
		return diag_set(d, RT_E_INVALID, "", 0, 0,
				"floor width and tile size must be finite and > 0");
	floor = floor_create(width, tile);
	if (!floor)
		return diag_set(d, RT_E_NOMEM, s->name, 0, 0, "out of memory");
	return scene_add_shape(s, floor, d);
}

int scene_load(const char *path, const struct scene_read_options *opt,
	       scene_note_fn *note, void *note_ctx, struct scene **out, struct diag *d)
{
	const char *name = strcmp(path, "-") == 0 ? "<stdin>" : path;
	char *text;
	size_t len;
	int rc;

	*out = NULL;
	rc = file_read_all(path, "scene file", RT_MAX_SCENE_BYTES, &text, &len, d);
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
	static const struct scene_read_options opt = { 1, true };

	return scene_parse("<test scene>", text, sizeof(text) - 1, &opt, NULL, NULL, out, d);
}

int scene_prepare(struct scene *s, int threads, struct diag *d)
{
	accel_destroy(s->accel);
	s->accel = NULL;
	return accel_build(s, threads, &s->accel, d);
}
