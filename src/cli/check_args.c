/* The command lines of `whitted compare` and `whitted grade`: the render
 * options of whitted (scene_opts.c: size, recursion, camera, floor,
 * dialect, clamping; a new one there reaches both commands) and their own. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>

#include "cli/check.h"
#include "cli/tool.h"

enum {
	OPT_DIFF = CLI_OPT_FIRST_PRIVATE,
	OPT_JSON,
	OPT_CSV,
	OPT_SCENE,
	OPT_NO_FIT,
	OPT_MARKS,
};

static void check_usage(bool grade)
{
	if (grade)
		printf("Usage: whitted grade [OPTIONS] --scene SCENE [-o REPORT.html] [--csv FILE] IMAGE...\n"
		       "Checks every submitted IMAGE against the reference render of SCENE (made\n"
		       "with the same options) and prints one row per image: its verdict against\n"
		       "the gate, its PSNR and the likely mistake.  -o writes a self-contained HTML\n"
		       "report (images inlined) with the reference, each submission and their\n"
		       "difference side by side.\n\n");
	else
		printf("Usage: whitted compare [OPTIONS] SCENE IMAGE\n"
		       "Renders the reference of SCENE with the options given and compares IMAGE\n"
		       "(PNG, BMP of 24 or 32 bits bottom-up or top-down, PPM P6 or P3) with it:\n"
		       "PSNR, mean error, the share of pixels off by more than 2, 8 and 32 levels,\n"
		       "and the verdict against the gate (>= 60 dB, <= 0.2%% of pixels off by > 2,\n"
		       "<= 0.02%% by > 8).  When it differs, names the likely mistakes, best first,\n"
		       "each rendered (one rule of the assignment broken) or made from the reference\n"
		       "(mirrored, flipped, transposed, red/blue swapped, gamma-encoded).\n\n");
	printf("%s", cli_scene_help);
	printf("  -j, --threads N        threads for the renders (default: %d, the cores)\n",
	       cli_default_threads());
	if (grade)
		printf("      --scene SCENE      the scene file the images are renders of (required)\n"
		       "  -o, --output FILE      write the HTML report to FILE\n"
		       "      --csv FILE         write the rows as CSV to FILE\n");
	else
		printf("      --diff FILE        write the difference: |reference - image| times 8\n"
		       "                         beside a mask (yellow: off by > 2, red: > 8); .png,\n"
		       "                         .bmp or .ppm\n"
		       "      --json             print the figures and causes as JSON\n");
	printf("  -h, --help             show this help\n\n");
	if (grade)
		printf("Exit status: 0 every image matches, 3 an image differs or is unreadable\n"
		       "(its row says why; the report is still written), 1 the scene cannot be\n"
		       "rendered or a report cannot be written, 2 bad command line.\n");
	else
		printf("Exit status: 0 the image matches, 3 it differs, 1 the scene or the image\n"
		       "cannot be read or the image has another size (the message gives both),\n"
		       "2 bad command line.\n");
}

static int check_option(struct check_options *o, int c, const char *arg)
{
	struct diag d;
	long n;

	diag_clear(&d);
	switch (c) {
	case 'j':
		if (number_parse_long("--threads", arg, 1, 64, &n, &d) < 0)
			return tool_usage_error("%s", d.msg);
		o->threads = (int)n;
		o->scene.read.threads = (int)n;
		return 0;
	case OPT_DIFF:
		if (o->grade)
			break;
		if (arg[0] == '\0')
			return tool_usage_error("--diff: expected a file name, found ''");
		if (image_format_from_path(arg) == RT_FORMAT_UNKNOWN)
			return tool_usage_error("--diff: cannot tell the format of '%s' (use .png, .bmp or .ppm)", arg);
		o->diff_path = arg;
		return 0;
	case OPT_JSON:
		if (o->grade)
			break;
		o->json = true;
		return 0;
	case 'o':
		if (!o->grade)
			break;
		if (arg[0] == '\0')
			return tool_usage_error("--output: expected a file name, found ''");
		o->report_path = arg;
		return 0;
	case OPT_CSV:
		if (!o->grade)
			break;
		if (arg[0] == '\0')
			return tool_usage_error("--csv: expected a file name, found ''");
		o->csv_path = arg;
		return 0;
	case OPT_SCENE:
		if (!o->grade)
			break;
		if (o->n_scenes == CHECK_MAX_SCENES)
			return tool_usage_error("--scene: at most %d scenes", CHECK_MAX_SCENES);
		o->scenes[o->n_scenes++] = arg;
		o->scene.path = o->scenes[0];
		return 0;
	case OPT_NO_FIT:
		o->no_fit = true;
		return 0;
	case OPT_MARKS:
		if (!o->grade)
			break;
		if (arg[0] == '\0')
			return tool_usage_error("--marks: expected a file name, found ''");
		o->marks_path = arg;
		return 0;
	}
	return -1;
}

int check_args_parse(int argc, char **argv, bool grade, struct check_options *o)
{
	static const struct option compare_longopts[] = {
		CLI_SCENE_LONG,
		{ "threads", required_argument, NULL, 'j' },
		{ "diff", required_argument, NULL, OPT_DIFF },
		{ "json", no_argument, NULL, OPT_JSON },
		{ "no-camera-fit", no_argument, NULL, OPT_NO_FIT },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 },
	};
	static const struct option grade_longopts[] = {
		CLI_SCENE_LONG,
		{ "threads", required_argument, NULL, 'j' },
		{ "output", required_argument, NULL, 'o' },
		{ "csv", required_argument, NULL, OPT_CSV },
		{ "scene", required_argument, NULL, OPT_SCENE },
		{ "marks", required_argument, NULL, OPT_MARKS },
		{ "no-camera-fit", no_argument, NULL, OPT_NO_FIT },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 },
	};
	const struct option *longopts = grade ? grade_longopts : compare_longopts;
	struct diag d;
	int c, rc, first;

	memset(o, 0, sizeof(*o));
	cli_scene_init(&o->scene);
	o->grade = grade;
	o->threads = cli_default_threads();
	opterr = 0;
	while ((c = getopt_long(argc, argv, grade ? ":" CLI_SCENE_SHORT "j:o:h" : ":" CLI_SCENE_SHORT "j:h",
				 longopts, NULL)) != -1) {
		if (c == ':')
			return tool_usage_error("option '%s' needs a value", argv[optind - 1]);
		if (c == 'h') {
			check_usage(grade);
			return -1;
		}
		rc = c == '?' ? -1 : check_option(o, c, optarg);
		if (rc > 0)
			return rc;
		if (rc == 0)
			continue;
		diag_clear(&d);
		rc = c == '?' ? 0 : cli_scene_option(&o->scene, c, optarg, &d);
		if (rc < 0)
			return tool_usage_error("%s", d.msg);
		if (rc == 0)
			return tool_unknown_option(argv[optind - 1], longopts);
	}
	first = optind;
	if (grade) {
		if (!o->scene.path && !o->scene.test_scene)
			return tool_usage_error("no scene given (--scene SCENE)");
		if (o->scene.path && o->scene.test_scene)
			return tool_usage_error("--test-scene and --scene both given");
		if (first == argc)
			return tool_usage_error("no IMAGE given");
	} else {
		if (!o->scene.test_scene) {
			if (first == argc)
				return tool_usage_error("no SCENE given");
			o->scene.path = argv[first++];
		}
		if (first == argc)
			return tool_usage_error("no IMAGE given");
		if (first + 1 != argc)
			return tool_usage_error("one IMAGE expected, found also '%s' (whitted grade takes many)",
						argv[first + 1]);
	}
	o->images = argv + first;
	o->n_images = argc - first;
	return 0;
}
