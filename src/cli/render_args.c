/* Reading a render's command line: the options, their checks against each
 * other, and the output name and format they imply. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "base/platform.h"
#include "cli/render_args.h"
#include "cli/tool.h"
#include "whitted/frames.h"
#include "whitted/tile.h"

static void usage(FILE *f)
{
	fprintf(f,
		"Usage: whitted [OPTIONS] SCENE\n"
		"Renders a scene.txt file (Whitted ray tracing: spheres, triangles, quadrics,\n"
		"a checkerboard floor, coloured point lights, shadows, reflections) to an image.\n"
		"SCENE '-' reads standard input.\n"
		"\n"
		"  -o, --output FILE      image to write; .png, .bmp or .ppm (default: SCENE's\n"
		"                         base name with .png, in the current directory)\n"
		"      --format png|bmp|ppm  the format, when FILE's extension does not say it\n"
		"%s"
		"  -j, --threads N        threads for reading the file, building the hierarchy\n"
		"                         and rendering (default: all %d online cores)\n"
		"      --stats            print times, ray counts and peak memory on stderr\n"
		"      --max-rays N       the most rays one primary ray's tree of reflections\n"
		"                         and glass transmissions may have (default %llu,\n"
		"                         at least %d); a pixel that needs more is an error\n"
		"      --progress auto|always|never  progress bar on stderr (auto: when it is\n"
		"                         a terminal)\n"
		"      --region X0,Y0,X1,Y1  render only these pixels (0-based, X1 and Y1\n"
		"                         excluded) to a PNG tile that records its place\n"
		"                         (default name SCENE-region-X0-Y0-X1-Y1.png)\n"
		"      --grid CxR --tile K  render tile K (1..C*R, row by row from the top\n"
		"                         left) of the image cut into C columns and R rows,\n"
		"                         as --region (default name SCENE-tile-K.png)\n"
		"      --frames N         an animation of N frames: a full turn of the eye\n"
		"                         about the up axis through the look-at point, or\n"
		"                         the keyframes of --path; FILE of -o is a pattern\n"
		"                         with %%04d or a directory (default frame-%%04d.png)\n"
		"      --frame K          render only frame K (1..N) of --frames N\n"
		"      --path FILE        keyframes for --frames (lines of eye X,Y,Z look X,Y,Z\n"
		"                         up X,Y,Z fov DEGREES), interpolated linearly\n"
		"      --list-shapes      print every shape keyword, where it comes from\n"
		"                         (built in, or a plugin's file) and its dialects;\n"
		"                         with --plugin, after loading the plugins; no\n"
		"                         SCENE and no other option\n"
		"  -h, --help             show this help\n"
		"  -V, --version          show the version\n"
		"\n"
		"whitted merge -o FULL.png TILE.png...   joins region renders into the full\n"
		"image after checking they are of one scene and settings and cover it once\n"
		"(see 'whitted merge --help' and docs/distributed.md).\n"
		"\n"
		"whitted compare [OPTIONS] SCENE IMAGE   checks a student's render against the\n"
		"reference and names the likely mistake; whitted grade --scene SCENE IMAGE...\n"
		"checks a class's, with an HTML report (see their --help).\n"
		"\n"
		"whitted explain [OPTIONS] SCENE X,Y     why pixel X,Y has its colour: its rays,\n"
		"hits, lights, shadows and reflections down to the 8-bit value (--json too).\n"
		"\n"
		"Exit status: 0 success, 1 scene, input or I/O error, 2 bad command line,\n"
		"128+N when stopped by signal N (the output is then left untouched).\n",
		cli_scene_help, cli_default_threads(), (unsigned long long)RT_DEFAULT_MAX_RAYS,
		RT_MIN_MAX_RAYS);
}

/* "X0,Y0,X1,Y1": four integers. */
static int parse_region(const char *arg, struct options *o, struct diag *d)
{
	int *v[4] = { &o->x0, &o->y0, &o->x1, &o->y1 };
	char buf[128], *item = buf, *comma;
	long n;
	int i;

	if (strlen(arg) >= sizeof(buf))
		goto out_bad;
	strcpy(buf, arg);
	for (i = 0; i < 4; i++) {
		comma = strchr(item, ',');
		if ((comma == NULL) != (i == 3))
			goto out_bad;
		if (comma)
			*comma = '\0';
		if (number_parse_long("--region", item, 0, RT_MAX_IMAGE_SIZE, &n, d) < 0)
			goto out_bad;
		*v[i] = (int)n;
		item = comma + 1;
	}
	o->region = true;
	if (tile_check_region(o->x0, o->y0, o->x1, o->y1, RT_MAX_IMAGE_SIZE, RT_MAX_IMAGE_SIZE, d) < 0)
		return -RT_E_INVALID;
	return 0;
out_bad:
	return diag_fail(d, RT_E_INVALID,
			"expected X0,Y0,X1,Y1 (four integers from 0 to %d), found '%s'",
			RT_MAX_IMAGE_SIZE, arg);
}

/* "CxR": columns and rows. */
static int parse_grid(const char *arg, struct options *o, struct diag *d)
{
	char buf[64], *x;
	long c, r;

	if (strlen(arg) >= sizeof(buf))
		goto out_bad;
	strcpy(buf, arg);
	x = strchr(buf, 'x');
	if (!x)
		goto out_bad;
	*x = '\0';
	if (number_parse_long("--grid", buf, 1, RT_MAX_IMAGE_SIZE, &c, d) < 0 ||
	    number_parse_long("--grid", x + 1, 1, RT_MAX_IMAGE_SIZE, &r, d) < 0)
		goto out_bad;
	o->grid_cols = (int)c;
	o->grid_rows = (int)r;
	return 0;
out_bad:
	return diag_fail(d, RT_E_INVALID,
			"expected COLUMNSxROWS (integers from 1 to %d), found '%s'", RT_MAX_IMAGE_SIZE, arg);
}

static bool is_directory(const char *path)
{
	struct stat st;
	size_t len = strlen(path);

	return (len > 0 && path[len - 1] == '/') || (stat(path, &st) == 0 && S_ISDIR(st.st_mode));
}

/* Picks the output name (a pattern with --frames) and its format. */
static int resolve_output(struct options *o)
{
	char suffix[96] = "", name[NAME_MAX_LEN];
	struct diag d;
	const char *dir;

	if (o->region)
		snprintf(suffix, sizeof(suffix), "-region-%d-%d-%d-%d", o->x0, o->y0, o->x1, o->y1);
	else if (o->grid_cols)
		snprintf(suffix, sizeof(suffix), "-tile-%d", o->tile);
	if (o->frames) {
		if (!o->output || is_directory(o->output)) {
			dir = o->output ? o->output : "";
			if (strlen(dir) + strlen(suffix) + 32 >= sizeof(name))
				return tool_usage_error("--output: '%s' is too long", dir);
			snprintf(name, sizeof(name), "%s%s%.*s%s.png", dir,
				 dir[0] && dir[strlen(dir) - 1] != '/' ? "/" : "",
				 (int)strlen(RT_FRAMES_PATTERN) - 4, RT_FRAMES_PATTERN, suffix);
			o->output_owned = strdup(name);
			if (!o->output_owned)
				return tool_out_of_memory();
			o->output = o->output_owned;
		}
		diag_clear(&d);
		if (frames_pattern_check(o->output, &o->numbered, &d) < 0)
			return tool_usage_error("--output: %s", d.msg);
		if (!o->numbered && !o->frame)
			return tool_usage_error("--output: with --frames, give a pattern with %%04d or a directory, found '%s'",
					   o->output);
	} else if (!o->output) {
		strcat(suffix, ".png");
		o->output_owned = cli_default_output(o->scene_path, suffix);
		if (!o->output_owned)
			return tool_out_of_memory();
		o->output = o->output_owned;
	}
	if (o->format == RT_FORMAT_UNKNOWN) {
		o->format = image_format_from_path(o->output);
		if (o->format == RT_FORMAT_UNKNOWN) {
			char ext[64];
			return tool_usage_error("--output: cannot tell the format of '%s' (use %s, or --format)",
						o->output, image_format_names(ext, sizeof(ext), "."));
		}
	}
	if ((o->region || o->grid_cols) && o->format != RT_FORMAT_PNG)
		return tool_usage_error("--region, --grid: tiles are PNG files (their place is kept in PNG chunks), found '%s'",
				   o->output);
	return 0;
}

static const struct option render_longopts[] = {
	CLI_SCENE_LONG,
	{ "output", required_argument, NULL, 'o' },
	{ "format", required_argument, NULL, OPT_FORMAT },
	{ "threads", required_argument, NULL, 'j' },
	{ "stats", no_argument, NULL, OPT_STATS },
	{ "progress", required_argument, NULL, OPT_PROGRESS },
	{ "region", required_argument, NULL, OPT_REGION },
	{ "frames", required_argument, NULL, OPT_FRAMES },
	{ "frame", required_argument, NULL, OPT_FRAME },
	{ "path", required_argument, NULL, OPT_PATH },
	{ "grid", required_argument, NULL, OPT_GRID },
	{ "tile", required_argument, NULL, OPT_TILE },
	{ "list-shapes", no_argument, NULL, OPT_LIST_SHAPES },
	{ "max-rays", required_argument, NULL, OPT_MAX_RAYS },
	{ "help", no_argument, NULL, 'h' },
	{ "version", no_argument, NULL, 'V' },
	{ NULL, 0, NULL, 0 },
};

/* An integer option in [lo, hi] into *out; 0 or the usage error's status. */
static int int_option(const char *name, const char *arg, long lo, long hi, int *out)
{
	struct diag d;
	long n;

	diag_clear(&d);
	if (number_parse_long(name, arg, lo, hi, &n, &d) < 0)
		return tool_usage_error("%s", d.msg);
	*out = (int)n;
	return 0;
}

/* One option of the render's own (not a shared scene option): 0, or the
 * status to stop with.  One case per option, as getopt_long reports them.
 * Long: the render's options, a case each in one switch. */
static int render_option(void *ctx, int c, const char *arg)
{
	struct options *o = ctx;
	struct diag d;

	diag_clear(&d);
	switch (c) {
	case 'o':
		return tool_file_arg("--output", arg, &o->output);
	case OPT_FORMAT:
		o->format = image_format_from_name(arg);
		if (o->format == RT_FORMAT_UNKNOWN) {
			char names[64];
			return tool_usage_error("--format: expected %s, found '%s'",
						image_format_names(names, sizeof(names), ""), arg);
		}
		return 0;
	case 'j':
		if (int_option("--threads", arg, 1, 64, &o->threads) != 0)
			return TOOL_EXIT_USAGE;
		o->scene.read.threads = o->threads;
		return 0;
	case OPT_STATS:
		o->stats = true;
		return 0;
	case OPT_PROGRESS:
		if (strcmp(arg, "auto") == 0)
			o->progress = PROGRESS_AUTO;
		else if (strcmp(arg, "always") == 0)
			o->progress = PROGRESS_ALWAYS;
		else if (strcmp(arg, "never") == 0)
			o->progress = PROGRESS_NEVER;
		else
			return tool_usage_error("--progress: expected auto, always or never, found '%s'", arg);
		return 0;
	case OPT_REGION:
		return parse_region(arg, o, &d) < 0 ? tool_usage_error("--region: %s", d.msg) : 0;
	case OPT_FRAMES:
		return int_option("--frames", arg, 1, RT_MAX_FRAMES, &o->frames);
	case OPT_FRAME:
		return int_option("--frame", arg, 1, RT_MAX_FRAMES, &o->frame);
	case OPT_PATH:
		return tool_file_arg("--path", arg, &o->path_file);
	case OPT_GRID:
		return parse_grid(arg, o, &d) < 0 ? tool_usage_error("--grid: %s", d.msg) : 0;
	case OPT_TILE:
		return int_option("--tile", arg, 1, RT_MAX_PIXELS, &o->tile);
	case OPT_LIST_SHAPES:
		o->scene.list_shapes = true;
		return 0;
	case OPT_MAX_RAYS: {
		long n;

		if (number_parse_long("--max-rays", arg, RT_MIN_MAX_RAYS, LONG_MAX, &n, &d) < 0)
			return tool_usage_error("%s", d.msg);
		o->max_rays = (uint64_t)n;
		return 0;
	}
	case 'h':
		usage(stdout);
		exit(0);
	case 'V':
		tool_print_version("whitted");
		exit(0);
	}
	return -1;
}

/* The options that only make sense together. */
static int check_combinations(const struct options *o)
{
	if (o->frame && !o->frames)
		return tool_usage_error("--frame K needs --frames N");
	if (o->frame > o->frames)
		return tool_usage_error("--frame %d is past the last frame of --frames %d",
					o->frame, o->frames);
	if (o->path_file && !o->frames)
		return tool_usage_error("--path %s needs --frames N", o->path_file);
	if (!o->grid_cols != !o->tile)
		return tool_usage_error("%s", o->tile ? "--tile K needs --grid COLUMNSxROWS" :
					"--grid COLUMNSxROWS needs --tile K");
	if (o->grid_cols && o->region)
		return tool_usage_error("--region and --grid cannot be combined");
	if ((long)o->tile > (long)o->grid_cols * o->grid_rows)
		return tool_usage_error("--tile %d is past the last tile of --grid %dx%d",
					o->tile, o->grid_cols, o->grid_rows);
	return 0;
}

int render_args_parse(int argc, char **argv, struct options *o)
{
	int rc;

	memset(o, 0, sizeof(*o));
	cli_scene_init(&o->scene);
	o->threads = cli_default_threads();
	rc = cli_parse_options(argc, argv, ":" CLI_SCENE_SHORT "o:j:hV", render_longopts, &o->scene,
			       render_option, o);
	if (rc != 0)
		return rc;
	o->scene_path = o->scene.path;
	if (o->scene.list_shapes && o->scene.path)
		return tool_usage_error("--list-shapes takes no SCENE, found '%s'", o->scene.path);
	if (o->scene.list_shapes && o->scene.other_option[0])
		return tool_usage_error("--list-shapes takes only --plugin and -q, found %s",
					o->scene.other_option);
	if (o->scene.list_shapes)
		return 0;
	if ((rc = check_combinations(o)) != 0)
		return rc;
	return resolve_output(o);
}
