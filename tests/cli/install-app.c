/* A program outside the tree, built against an installed whitted through
 * pkg-config by tests/cli/install-test.sh: it renders a scene file through
 * the public API only, as `whitted -s SIZE -o OUT.ppm SCENE` does.
 * Usage: install-app SCENE|--test-scene SIZE OUT.ppm */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <whitted/camera.h>
#include <whitted/diag.h>
#include <whitted/image.h>
#include <whitted/render.h>
#include <whitted/scene.h>
#include <whitted/scenefile.h>
#include <whitted/version.h>

static void print_note(void *ctx, const struct diag *note)
{
	char line[RT_DIAG_FILE_MAX + RT_DIAG_MSG_MAX + 64];

	(void)ctx;
	diag_format(note, "install-app", "note", line, sizeof(line));
	fprintf(stderr, "%s\n", line);
}

int main(int argc, char **argv)
{
	struct scene_read_options read = { 2, false, RT_DIALECT_AUTO, false, 0 };
	struct camera_params params;
	struct camera cam;
	struct render_job job;
	struct image img = { 0, 0, NULL };
	struct scene *s = NULL;
	struct diag d;
	int rc, status = 1;

	if (argc != 4) {
		fprintf(stderr, "usage: install-app SCENE|--test-scene SIZE OUT.ppm (whitted %s)\n",
			RT_VERSION);
		return 2;
	}
	diag_clear(&d);
	if (strcmp(argv[1], "--test-scene") == 0)
		rc = scene_test_scene(&s, &d);
	else
		rc = scene_load(argv[1], &read, print_note, NULL, &s, &d);
	if (rc < 0)
		goto out;
	camera_params_default(&params);
	if ((rc = scene_set_image_size(s, atol(argv[2]), &d)) < 0 ||
	    (rc = scene_add_floor(s, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d)) < 0 ||
	    (rc = camera_init(&cam, &params, scene_image_size(s), &d)) < 0 ||
	    (rc = scene_prepare(s, 2, &d)) < 0 ||
	    (rc = image_alloc(&img, scene_image_size(s), scene_image_size(s), &d)) < 0)
		goto out;
	render_job_init(&job, s, &cam, 2);
	if ((rc = render_image(&job, &img, NULL, &d)) < 0 ||
	    (rc = image_write(&img, argv[3], RT_FORMAT_PPM, NULL, &d)) < 0)
		goto out;
	status = 0;
out:
	if (status) {
		char line[RT_DIAG_FILE_MAX + RT_DIAG_MSG_MAX + 64];
		diag_format(&d, "install-app", "error", line, sizeof(line));
		fprintf(stderr, "%s\n", line);
	}
	image_free(&img);
	scene_destroy(s);
	return status;
}
