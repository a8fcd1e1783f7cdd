/* whitted explain [OPTIONS] SCENE X,Y: why pixel (X, Y) of the image that
 * the same options render has its colour (render/explain.c), printed as
 * text or, with --json, as one JSON object (explain_print.c). */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/explain.h"
#include "cli/scene_opts.h"
#include "cli/tool.h"
#include "whitted/explain.h"

enum { OPT_JSON = CLI_OPT_FIRST_PRIVATE };

struct explain_options {
	struct cli_scene scene;
	int threads;
	bool json;
	int x, y;
};

static void explain_usage(void)
{
	printf("Usage: whitted explain [OPTIONS] SCENE X,Y\n"
	       "Explains why pixel X,Y (0,0 the top left) of the image that whitted renders\n"
	       "with the same options has its colour: the primary ray; the object it hits\n"
	       "(its index, keyword and line in the file), t, the point and the normal; each\n"
	       "light's ambient, diffuse and specular terms and whether its shadow ray is\n"
	       "blocked, and by which object; the reflected and refracted rays level by\n"
	       "level; the clamped sum and the 8-bit value, which is the image's pixel.\n\n");
	printf("%s", cli_scene_help);
	printf("  -j, --threads N        threads for reading the file and building the hierarchy\n"
	       "      --json             print the explanation as one JSON object\n"
	       "  -h, --help             show this help\n\n"
	       "Exit status: 0 explained, 1 the scene cannot be read or the pixel's tree of\n"
	       "rays is too large, 2 bad command line (a pixel outside the image).\n");
}

/* "X,Y": two whole numbers, each at least 0. */
static int explain_pixel_arg(const char *arg, struct explain_options *o)
{
	char *end;
	long x, y;

	x = strtol(arg, &end, 10);
	if (end == arg || *end != ',' || x < 0 || x > 1 << 20)
		return tool_usage_error("expected a pixel X,Y (whole numbers from 0), found '%s'", arg);
	arg = end + 1;
	y = strtol(arg, &end, 10);
	if (end == arg || *end != '\0' || y < 0 || y > 1 << 20)
		return tool_usage_error("expected a pixel X,Y (whole numbers from 0), found '%s'",
					arg);
	o->x = (int)x;
	o->y = (int)y;
	return 0;
}

static int explain_args(int argc, char **argv, struct explain_options *o)
{
	static const struct option longopts[] = {
		CLI_SCENE_LONG,
		{ "threads", required_argument, NULL, 'j' },
		{ "json", no_argument, NULL, OPT_JSON },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 },
	};
	struct diag d;
	long n;
	int c, rc, first;

	memset(o, 0, sizeof(*o));
	cli_scene_init(&o->scene);
	o->threads = cli_default_threads();
	opterr = 0;
	while ((c = getopt_long(argc, argv, ":" CLI_SCENE_SHORT "j:h", longopts, NULL)) != -1) {
		diag_clear(&d);
		if (c == ':')
			return tool_usage_error("option '%s' needs a value", argv[optind - 1]);
		if (c == 'h') {
			explain_usage();
			return -1;
		}
		if (c == OPT_JSON) {
			o->json = true;
			continue;
		}
		if (c == 'j') {
			if (number_parse_long("--threads", optarg, 1, 64, &n, &d) < 0)
				return tool_usage_error("%s", d.msg);
			o->threads = (int)n;
			o->scene.read.threads = (int)n;
			continue;
		}
		if ((rc = cli_scene_option_or_usage(&o->scene, c, optarg, argv, longopts)) != 0)
			return rc;
	}
	first = optind;
	if ((rc = cli_scene_and_operand(&o->scene, argc, argv, &first, "pixel X,Y", "")) != 0)
		return rc;
	return explain_pixel_arg(argv[first], o);
}

int explain_main(int argc, char **argv)
{
	struct explain_options o;
	struct explanation e;
	struct render_settings rs;
	struct scene *s = NULL;
	struct camera cam;
	struct diag d;
	int status = explain_args(argc, argv, &o), rc;

	if (status != 0)
		return status < 0 ? 0 : status;
	cli_set_signals();
	diag_clear(&d);
	rc = cli_scene_load(&o.scene, o.scene.path, tool_print_note, &o.scene.quiet, &s, &cam, &d);
	if (rc == 0)
		rc = scene_prepare(s, o.threads, &d);
	if (rc < 0) {
		tool_print_diag(&d, "error");
		scene_destroy(s);
		return tool_status_of(rc);
	}
	rs.recursion = scene_recursion(s);
	rs.clamp = o.scene.clamp;
	rc = explain_pixel(s, &cam, &rs, o.scene.samples, o.x, o.y, &e, &d);
	if (rc < 0) {
		if (rc == -RT_E_INVALID)
			status = tool_usage_error("%s", d.msg);
		else {
			tool_print_diag(&d, "error");
			status = TOOL_EXIT_FAILURE;
		}
		scene_destroy(s);
		return status;
	}
	if (o.json)
		explain_print_json(stdout, o.scene.path ? o.scene.path : "test-scene", s, &e);
	else
		explain_print_text(stdout, o.scene.path ? o.scene.path : "the test scene", s, &e);
	explanation_free(&e);
	scene_destroy(s);
	return fflush(stdout) == 0 ? TOOL_EXIT_OK : TOOL_EXIT_FAILURE;
}
