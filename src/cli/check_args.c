/* The command lines of `whitted compare` and `whitted grade`: the render
 * options of whitted (scene_opts.c: size, recursion, camera, floor,
 * dialect, clamping; a new one there reaches both commands) and their own. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>

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
		printf("Usage: whitted grade [OPTIONS] --scene SCENE [--scene SCENE2 ...] [-o REPORT.html]\n"
		       "                     [--csv FILE] [--marks FILE] IMAGE|FOLDER|ZIP...\n"
		       "Checks every submitted image against the reference render of its scene (made\n"
		       "with the same options) as whitted compare does (the camera that took it\n"
		       "found when it is not the given one) and prints one row per image: its\n"
		       "verdict, its PSNR, its points and the likely mistake, then the class's\n"
		       "summary.  FOLDER and ZIP (a Moodle download: NAME_ID_assignsubmission_file_\n"
		       "folders give the student and the id) are searched for PNG, BMP and PPM\n"
		       "images.  With several scenes an image goes to the scene whose name its file\n"
		       "name contains, else to its student's next scene.  -o writes a\n"
		       "self-contained HTML report (images inlined, tables that sort and filter).\n\n");
	else
		printf("Usage: whitted compare [OPTIONS] SCENE IMAGE\n"
		       "Renders the reference of SCENE with the options given and compares IMAGE\n"
		       "(PNG, BMP of 24 or 32 bits bottom-up or top-down, PPM P6 or P3; compared at\n"
		       "its own size) with it: PSNR, mean error, the share of pixels off by more\n"
		       "than 2, 8 and 32 levels, and the verdict against the gate (>= 60 dB, <= 0.2%%\n"
		       "of pixels off by > 2, <= 0.02%% by > 8), ties (pixels where either colour is\n"
		       "right) left out.  When no known mistake explains it, finds the camera that\n"
		       "took it (moved before the capture) and judges it there.  Names the likely\n"
		       "mistakes, best first, one or two at once, each rendered (a rule of the\n"
		       "assignment broken, another recursion level or floor) or made from the\n"
		       "reference (mirrored, flipped, transposed, red/blue swapped), and says\n"
		       "where the image differs object by object.\n\n");
	printf("%s", cli_scene_help);
	printf("  -j, --threads N        threads for the renders (default: %d, the cores)\n"
	       "      --no-camera-fit    judge the image at the camera given only\n",
	       cli_default_threads());
	if (grade)
		printf("      --scene SCENE      a scene file the images are renders of (required;\n"
		       "                         repeatable: one column a scene)\n"
		       "  -o, --output FILE      write the HTML report to FILE\n"
		       "      --csv FILE         write the rows as CSV to FILE\n"
		       "      --marks FILE       the points table (lines 'match 10', 'camera 10',\n"
		       "                         'cause 6', 'cause no-shadows 7', 'close 4',\n"
		       "                         'differs 2', 'unreadable 0': these are the defaults)\n");
	else
		printf("      --diff FILE        write the difference: |reference - image| times 8\n"
		       "                         beside a mask (yellow: off by > 2, red: > 8, blue: a\n"
		       "                         tie, cyan: an object that differs) and a legend;\n"
		       "                         .png, .bmp or .ppm\n"
		       "      --json             print the figures, the camera, the causes and the\n"
		       "                         objects as JSON\n");
	printf("  -h, --help             show this help\n\n");
	if (grade)
		printf("Exit status: 0 every image matches, 3 an image differs or is unreadable\n"
		       "(its row says why; the report is still written), 1 a scene cannot be\n"
		       "rendered, an operand read or a report written (checked before grading),\n"
		       "2 bad command line.\n");
	else
		printf("Exit status: 0 the image matches (at the camera given, or at the one found),\n"
		       "3 it differs, 1 the scene or the image cannot be read, 2 bad command line.\n");
}

/* Long: compare's and grade's options, a case each in one switch. */
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
		if (image_format_from_path(arg) == RT_FORMAT_UNKNOWN) {
			char ext[64];
			return tool_usage_error("--diff: cannot tell the format of '%s' (use %s)", arg,
						image_format_names(ext, sizeof(ext), "."));
		}
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
		return tool_file_arg("--output", arg, &o->report_path);
	case OPT_CSV:
		if (!o->grade)
			break;
		return tool_file_arg("--csv", arg, &o->csv_path);
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
		return tool_file_arg("--marks", arg, &o->marks_path);
	}
	return -1;
}

/* Whether a file starts as a PNG, a BMP or a PPM does (the operands of
 * compare given the wrong way round). */
static bool check_looks_like_image(const char *path)
{
	unsigned char b[8] = { 0 };
	struct stat st;
	FILE *f;
	size_t n;

	/* Only a regular file: opening a named pipe would wait for a writer. */
	if (strcmp(path, "-") == 0 || stat(path, &st) != 0 || !S_ISREG(st.st_mode) ||
	    !(f = fopen(path, "rb")))
		return false;
	n = fread(b, 1, sizeof(b), f);
	fclose(f);
	return (n >= 8 && memcmp(b, "\x89PNG\r\n\x1a\n", 8) == 0) || (n >= 2 && b[0] == 'B' && b[1] == 'M') ||
	       (n >= 2 && b[0] == 'P' && (b[1] == '3' || b[1] == '6'));
}

/* Long: the two commands' option tables and getopt's loop, then the operands'
 * checks, as getopt wants them in one place. */
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
		if ((rc = cli_scene_option_or_usage(&o->scene, c, optarg, argv, longopts)) != 0)
			return rc;
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
		if ((rc = cli_scene_and_operand(&o->scene, argc, argv, &first, "IMAGE",
						" (whitted grade takes many)")) != 0)
			return rc;
		if (o->scene.path && check_looks_like_image(o->scene.path) &&
		    !check_looks_like_image(argv[first]))
			return tool_usage_error("'%s' is an image and '%s' is not: SCENE comes first "
						"(whitted compare SCENE IMAGE)", o->scene.path, argv[first]);
	}
	o->images = argv + first;
	o->n_images = argc - first;
	return 0;
}
