/* The scene options (size, recursion, camera, floor, clamping) that
 * whitted, scene2pov and whitted-view all take, read with getopt_long.
 * Program code: the library has no command line.  Nothing here prints or
 * exits. */
#ifndef RT_CLI_SCENE_OPTS_H
#define RT_CLI_SCENE_OPTS_H

#include <getopt.h>
#include <stdbool.h>

#include "whitted/camera.h"
#include "whitted/diag.h"
#include "base/number.h"
#include "whitted/render.h"
#include "whitted/scene.h"
#include "whitted/scenefile.h"
#include "whitted/settings.h"
#include "whitted/version.h"

enum cli_option {
	CLI_OPT_EYE = 1000,
	CLI_OPT_LOOK,
	CLI_OPT_UP,
	CLI_OPT_FOV,
	CLI_OPT_FLOOR,
	CLI_OPT_NO_FLOOR,
	CLI_OPT_CLAMP,
	CLI_OPT_TEST_SCENE,
	CLI_OPT_DIALECT,
	CLI_OPT_SAMPLES,
	CLI_OPT_FLOOR_TEXTURE,
	CLI_OPT_GLASS,
	CLI_OPT_PLUGIN,
	CLI_OPT_LENIENT,
	CLI_OPT_MAX_SCENE_SIZE,
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
	{ "test-scene", no_argument, NULL, CLI_OPT_TEST_SCENE }, \
	{ "dialect", required_argument, NULL, CLI_OPT_DIALECT }, \
	{ "samples", required_argument, NULL, CLI_OPT_SAMPLES }, \
	{ "floor-texture", required_argument, NULL, CLI_OPT_FLOOR_TEXTURE }, \
	{ "glass", required_argument, NULL, CLI_OPT_GLASS }, \
	{ "plugin", required_argument, NULL, CLI_OPT_PLUGIN }, \
	{ "lenient", no_argument, NULL, CLI_OPT_LENIENT }, \
	{ "max-scene-size", required_argument, NULL, CLI_OPT_MAX_SCENE_SIZE }

#define CLI_MAX_GLASS 64
#define CLI_GLASS_IOR 1.5	/* --glass's default index of refraction (crown glass) */
#define CLI_GLASS_KT 0.8	/* and transmission */

#define CLI_PLUGINS_MAX 32

/* Help text for the options above, for each tool's --help. */
extern const char cli_scene_help[];

/* After cli_scene_load, camera and the floor's fields hold what the scene
 * is rendered with: the options where given, else what the file's dialect
 * says (scene_view_of). */
struct cli_scene {
	int size;			/* 0: the file's */
	int recursion;			/* 0: the file's */
	struct camera_params camera;
	bool fov_given;			/* --fov: else the file's dialect decides */
	bool camera_given;		/* --eye, --look or --up */
	double floor_width, floor_tile;	/* width INFINITY: nearfar's checkerboard */
	struct material floor_mat;
	bool floor_given;		/* --floor: a classic floor of that size */
	bool no_floor;
	bool test_scene;
	bool quiet;
	const char *path;		/* the SCENE operand; NULL for --test-scene */
	enum clamp_mode clamp;
	int samples;			/* --samples N: N x N rays a pixel; 1 by default */
	/* --floor-texture WHITE[,BLACK]: the images' paths (NULL: none),
	 * pointing into floor_texture_arg. */
	const char *floor_texture[2];
	char floor_texture_arg[2048];
	/* --glass INDEX[:IOR[:KT]][,...]: objects made glass, in the order
	 * given, and their canonical text ("INDEX:IOR:KT,...") for settings. */
	struct cli_glass { long index; double ior, kt; } glass[CLI_MAX_GLASS];
	int n_glass;
	char glass_text[CLI_MAX_GLASS * 48];
	struct scene_read_options read;	/* threads: all online cores */
	/* --plugin FILE.so, in order: loaded (with WHITTED_PLUGIN_PATH's) by
	 * cli_scene_load, or cli_plugins_load (cli/plugin_opts.h). */
	const char *plugins[CLI_PLUGINS_MAX];
	int n_plugins;
	bool list_shapes;		/* whitted --list-shapes: no SCENE */
	/* The first option given other than --plugin, -q and --list-shapes
	 * ("--size", "-o"): "" when none; --list-shapes refuses it. */
	char other_option[40];
};

void cli_scene_init(struct cli_scene *o);

/* A tool's own option c with its value: 0 when taken, a positive exit
 * status to stop with (a usage error already printed), or -1 when it is
 * not one of the tool's. */
typedef int cli_option_fn(void *ctx, int c, const char *arg);

/* Reads argv with getopt_long (shortopts should start with ':'): the
 * shared scene options into *scene, the tool's own through own(ctx, ...),
 * then the SCENE operand into scene->path.  Prints a usage error and
 * returns TOOL_EXIT_USAGE for a bad command line; 0 otherwise.  own sees
 * every option first (returning -1 passes it on to the shared ones). */
int cli_parse_options(int argc, char **argv, const char *shortopts,
		      const struct option *longopts, struct cli_scene *scene,
		      cli_option_fn *own, void *ctx);
/* Handles one of the shared options.  Returns 1 when it was one, 0 when it
 * is not a shared option, or -RT_E_INVALID with a message naming it. */
int cli_scene_option(struct cli_scene *o, int opt, const char *arg, struct diag *d);
/* cli_scene_option for the option getopt_long just read (c '?': one it
 * did not know) at argv[optind - 1]: 0 when it was a shared one, else
 * the usage error printed and its exit status. */
int cli_scene_option_or_usage(struct cli_scene *o, int c, const char *arg, char **argv,
			      const struct option *longopts);

/* Loads the scene (or the test scene when path is NULL), applies the
 * overrides, adds the floor and sets up the camera, recording in o the
 * camera and floor it used; scene_prepare is left
 * to the caller.
 * Errors of the file are RT_E_SYNTAX, RT_E_RANGE, RT_E_IO or RT_E_NOMEM;
 * RT_E_INVALID means the command line (the camera) is at fault. */
int cli_scene_load(struct cli_scene *o, const char *path,
		   diag_note_fn *note, void *note_ctx,
		   struct scene **out, struct camera *cam, struct diag *d);

/* The SCENE operand after the options (argv[first..argc)): exactly one,
 * or none with --test-scene.  *path is NULL for the test scene. */
int cli_scene_operand(const struct cli_scene *o, int argc, char **argv, int first,
		      const char **path, struct diag *d);

/* SCENE (unless --test-scene) into o->path, then exactly one operand more:
 * 0, or the usage error printed ("no IMAGE given"; "one IMAGE expected,
 * found also 'x'" and hint) and TOOL_EXIT_USAGE.  *first moves past
 * SCENE. */
int cli_scene_and_operand(struct cli_scene *o, int argc, char **argv, int *first, const char *what,
			  const char *hint);

/* The default output name: SCENE's base name without its extension ("stdin"
 * for "-", "test-scene" for NULL) followed by suffix, e.g. "-tile-3.png".
 * Allocated with malloc; NULL when out of memory. */
char *cli_default_output(const char *scene_path, const char *suffix);

/* The online processor count, at least 1. */
int cli_default_threads(void);

/* The settings of an image of s seen by cam, from the scene options
 * (plugins aside: the caller adds them where its text records them). */
void cli_settings(struct settings *out, const struct cli_scene *o, const struct scene *s,
		  const struct camera_params *cam);
/* The render job for the whole image of s seen by cam, with the options
 * that reach the render (clamp, samples) and max_rays (0: the default). */
void cli_render_job(struct render_job *job, const struct cli_scene *o, const struct scene *s,
		    const struct camera *cam, int threads, uint64_t max_rays);

#endif
