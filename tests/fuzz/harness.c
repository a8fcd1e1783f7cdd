/* The fuzz target: scene_parse on arbitrary bytes, then, for a scene that
 * parses, the floor, scene_prepare, a camera and a render of a 3 x 3 image
 * with recursion at most 3, so that every stage that reads parsed values
 * runs on them.  Diagnostics are formatted to check that they stay well
 * formed (NUL-terminated, within the buffer). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plugin/loader.h"

#include "scene/scene_impl.h"
#include "whitted/scenefile.h"
#include "whitted/camera.h"
#include "whitted/diag.h"
#include "whitted/image.h"
#include "whitted/render.h"
#include "whitted/scene.h"

#include "harness.h"

#define FUZZ_IMAGE 3
#define FUZZ_RECURSION 3

static void fuzz_check_diag(const struct diag *d)
{
	char line[RT_DIAG_FILE_MAX + RT_DIAG_MSG_MAX + 64];

	diag_format(d, "whitted", "error", line, sizeof(line));
	if (strlen(line) >= sizeof(line) || memchr(d->msg, '\n', strlen(d->msg)))
		__builtin_trap();
}

int fuzz_init(void)
{
	struct diag d;

	diag_clear(&d);
	if (plugin_load_dirs(getenv("WHITTED_PLUGIN_PATH"), NULL, NULL, &d) < 0) {
		fprintf(stderr, "fuzz: %s\n", d.msg);
		return -1;
	}
	return 0;
}

static void fuzz_note(void *ctx, const struct diag *note)
{
	(void)ctx;
	fuzz_check_diag(note);
}

static void fuzz_render(struct scene *s)
{
	struct camera_params cp;
	struct camera cam;
	struct render_job job;
	struct image img = { 0, 0, NULL };
	struct diag d;

	diag_clear(&d);
	if (s->recursion > FUZZ_RECURSION)
		s->recursion = FUZZ_RECURSION;
	/* The floor and the camera of the file's dialect, as the tools use
	 * them. */
	if (scene_add_view_floor(s, &d) < 0 || scene_prepare(s, 1, &d) < 0)
		return;
	camera_params_default(&cp);
	cp.fov_deg = scene_view_of(s)->fov_deg;
	cp.near = scene_view_of(s)->near;
	cp.aspect = scene_view_of(s)->aspect;
	if (camera_init(&cam, &cp, FUZZ_IMAGE, &d) < 0 ||
	    image_alloc(&img, FUZZ_IMAGE, FUZZ_IMAGE, &d) < 0)
		return;
	render_job_init(&job, s, &cam, 1);
	if (render_image(&job, &img, NULL, &d) < 0)
		fuzz_check_diag(&d);
	image_free(&img);
}

int fuzz_scene_one(const uint8_t *data, size_t size)
{
	struct scene *s = NULL;
	struct diag d;
	int rc;

	diag_clear(&d);
	rc = scene_parse("fuzz.txt", (const char *)data, size, NULL, fuzz_note, NULL, &s, &d);
	if (rc < 0) {
		/* A failed parse reports a located error and returns nothing. */
		if (s != NULL || d.msg[0] == '\0' || d.line < 0 || d.col < 0)
			__builtin_trap();
		fuzz_check_diag(&d);
		return 0;
	}
	if (s->image_size < 1 || s->recursion < 1)
		__builtin_trap();
	fuzz_render(s);
	scene_destroy(s);
	return 0;
}
