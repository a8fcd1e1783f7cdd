/* What the command-line tools share: strict parsing of option values, and
 * the scene options (size, recursion, camera, floor, clamping) that whitted,
 * scene2pov and whitted-view all take.  Nothing here prints or exits. */
#ifndef RT_CLI_H
#define RT_CLI_H

#include <getopt.h>
#include <stdbool.h>

#include "camera.h"
#include "diag.h"
#include "render.h"
#include "scene.h"

#define RT_VERSION "1.0.0"

enum cli_option {
	CLI_OPT_EYE = 1000,
	CLI_OPT_LOOK,
	CLI_OPT_UP,
	CLI_OPT_FOV,
	CLI_OPT_FLOOR,
	CLI_OPT_NO_FLOOR,
	CLI_OPT_CLAMP,
	CLI_OPT_TEST_SCENE,
	CLI_OPT_FIRST_PRIVATE,	/* each tool numbers its own options from here */
};

#define CLI_SCENE_SHORT "s:r:q"
#define CLI_SCENE_LONG \
	{ "size", required_argument, NULL, 's' }, \
	{ "recursion", required_argument, NULL, 'r' }, \
	{ "quiet", no_argument, NULL, 'q' }, \
	{ "eye", required_argument, NULL, CLI_OPT_EYE }, \
	{ "look", required_argument, NULL, CLI_OPT_LOOK }, \
	{ "up", required_argument, NULL, CLI_OPT_UP }, \
	{ "fov", required_argument, NULL, CLI_OPT_FOV }, \
	{ "floor", required_argument, NULL, CLI_OPT_FLOOR }, \
	{ "no-floor", no_argument, NULL, CLI_OPT_NO_FLOOR }, \
	{ "clamp", required_argument, NULL, CLI_OPT_CLAMP }, \
	{ "test-scene", no_argument, NULL, CLI_OPT_TEST_SCENE }

/* Help text for the options above, for each tool's --help. */
extern const char cli_scene_help[];

struct cli_scene {
	int size;			/* 0: the file's */
	int recursion;			/* 0: the file's */
	struct camera_params camera;
	double floor_width, floor_tile;
	bool no_floor;
	bool test_scene;
	bool quiet;
	enum clamp_mode clamp;
	struct scene_read_options read;	/* threads: all online cores */
};

void cli_scene_init(struct cli_scene *o);
/* Handles one of the shared options.  Returns 1 when it was one, 0 when it
 * is not a shared option, or -RT_E_INVALID with a message naming it. */
int cli_scene_option(struct cli_scene *o, int opt, const char *arg, struct diag *d);

/* Loads the scene (or the test scene when path is NULL), applies the
 * overrides, adds the floor and sets up the camera; scene_prepare is left
 * to the caller.
 * Errors of the file are RT_E_SYNTAX, RT_E_RANGE, RT_E_IO or RT_E_NOMEM;
 * RT_E_INVALID means the command line (the camera) is at fault. */
int cli_scene_load(const struct cli_scene *o, const char *path,
		   scene_note_fn *note, void *note_ctx,
		   struct scene **out, struct camera *cam, struct diag *d);

/* Strict value parsers: the whole string, finite, in range; the message
 * names the option. */
int cli_parse_long(const char *opt, const char *arg, long lo, long hi, long *out, struct diag *d);
int cli_parse_double(const char *opt, const char *arg, double *out, struct diag *d);
/* n comma-separated finite numbers. */
int cli_parse_list(const char *opt, const char *arg, double *out, int n, struct diag *d);

/* The SCENE operand after the options (argv[first..argc)): exactly one,
 * or none with --test-scene.  *path is NULL for the test scene. */
int cli_scene_operand(const struct cli_scene *o, int argc, char **argv, int first,
		      const char **path, struct diag *d);

/* The default output name: SCENE's base name without its extension ("stdin"
 * for "-", "test-scene" for NULL) followed by suffix, e.g. "-tile-3.png".
 * Allocated with malloc; NULL when out of memory. */
char *cli_default_output(const char *scene_path, const char *suffix);

/* The online processor count, at least 1. */
int cli_default_threads(void);

#endif
