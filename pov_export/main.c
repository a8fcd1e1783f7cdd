/* scene2pov, the command line: reads a scene with whitted's scene options
 * and writes OUT.pov and OUT.ini, which POV-Ray renders to OUT.png as
 * `whitted --clamp final` renders the scene.  The only code of the exporter
 * that reads argv, prints or chooses the exit status: 0 success, 1 a scene,
 * input or I/O error, 2 a bad command line. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "export.h"
#include "scene.h"

enum {
	EXIT_SCENE = 1,
	EXIT_USAGE = 2,
};

enum {
	OPT_FINISH = CLI_OPT_FIRST_PRIVATE,
};

struct options {
	struct cli_scene scene;
	const char *scene_path;
	const char *output;
	char *output_owned;
	struct pov_options pov;
};

static void usage(FILE *f)
{
	fprintf(f,
		"Usage: scene2pov [OPTIONS] SCENE [-o OUT.pov]\n"
		"Writes a scene.txt file as a POV-Ray 3.7 scene OUT.pov and its settings OUT.ini:\n"
		"'povray OUT.ini', run in OUT's directory, renders OUT.png as\n"
		"'whitted --clamp final' with the same options renders the scene.\n"
		"SCENE '-' reads standard input.\n"
		"\n"
		"  -o, --output OUT.pov   the scene to write; OUT.ini is written beside it\n"
		"                         (default: SCENE's base name with .pov, in the\n"
		"                         current directory)\n"
		"      --finish exact|plain  exact (default): highlights tinted by the object\n"
		"                         colour, as whitted shades them, through one light\n"
		"                         group per colour; plain: POV-Ray's ordinary white\n"
		"                         highlights, at its natural speed (for benchmarks)\n"
		"%s"
		"                         (scene2pov accepts only --clamp final: POV-Ray clamps\n"
		"                         the finished pixel)\n"
		"  -h, --help             show this help\n"
		"  -V, --version          show the version\n"
		"\n"
		"Exit status: 0 success, 1 scene, input or I/O error, 2 bad command line.\n",
		cli_scene_help);
}

static int usage_error(const char *fmt, const char *arg)
{
	fprintf(stderr, "scene2pov: error: ");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\nTry 'scene2pov --help' for more information.\n");
	return EXIT_USAGE;
}

static void print_diag(const struct diag *d, const char *kind)
{
	char line[RT_DIAG_FILE_MAX + RT_DIAG_MSG_MAX + 64];

	if (d->file[0] == '\0') {
		fprintf(stderr, "scene2pov: %s: %s\n", kind, d->msg);
		return;
	}
	diag_format(d, "scene2pov", kind, line, sizeof(line));
	fprintf(stderr, "%s\n", line);
}

static void print_note(void *ctx, const struct diag *note)
{
	const struct options *o = ctx;

	if (!o->scene.quiet)
		print_diag(note, "note");
}

static bool ends_with(const char *s, const char *suffix)
{
	size_t n = strlen(s), m = strlen(suffix);

	return n >= m && strcmp(s + n - m, suffix) == 0;
}

static int parse_args(int argc, char **argv, struct options *o)
{
	static const struct option longopts[] = {
		CLI_SCENE_LONG,
		{ "output", required_argument, NULL, 'o' },
		{ "finish", required_argument, NULL, OPT_FINISH },
		{ "help", no_argument, NULL, 'h' },
		{ "version", no_argument, NULL, 'V' },
		{ NULL, 0, NULL, 0 },
	};
	const char *base;
	struct diag d;
	int c, rc;

	memset(o, 0, sizeof(*o));
	cli_scene_init(&o->scene);
	o->pov.finish = RT_POV_FINISH_EXACT;
	opterr = 0;
	while ((c = getopt_long(argc, argv, CLI_SCENE_SHORT "o:hV", longopts, NULL)) != -1) {
		diag_clear(&d);
		/* POV-Ray clamps only the finished pixel; whitted's default
		 * clamp at every level has no POV-Ray equivalent. */
		if (c == CLI_OPT_CLAMP && strcmp(optarg, "level") == 0)
			return usage_error("%s", "--clamp level cannot be exported: POV-Ray clamps only the finished pixel (--clamp final)");
		rc = cli_scene_option(&o->scene, c, optarg, &d);
		if (rc < 0)
			return usage_error("%s", d.msg);
		if (rc > 0)
			continue;
		switch (c) {
		case 'o':
			if (optarg[0] == '\0')
				return usage_error("--output: %s", "expected a file name, found ''");
			o->output = optarg;
			break;
		case OPT_FINISH:
			if (strcmp(optarg, "exact") == 0)
				o->pov.finish = RT_POV_FINISH_EXACT;
			else if (strcmp(optarg, "plain") == 0)
				o->pov.finish = RT_POV_FINISH_PLAIN;
			else
				return usage_error("--finish: expected exact or plain, found '%s'", optarg);
			break;
		case 'h':
			usage(stdout);
			exit(0);
		case 'V':
			printf("scene2pov %s\n", RT_VERSION);
			exit(0);
		case ':':
			return usage_error("option '%s' needs a value", argv[optind - 1]);
		default:
			return usage_error("unknown option '%s'", argv[optind - 1]);
		}
	}
	if (cli_scene_operand(&o->scene, argc, argv, optind, &o->scene_path, &d) < 0)
		return usage_error("%s", d.msg);
	if (!o->output) {
		o->output_owned = cli_default_output(o->scene_path, ".pov");
		if (!o->output_owned) {
			fprintf(stderr, "scene2pov: error: out of memory\n");
			return EXIT_SCENE;
		}
		o->output = o->output_owned;
	}
	if (!ends_with(o->output, ".pov") || ends_with(o->output, "/.pov") || strcmp(o->output, ".pov") == 0)
		return usage_error("--output: expected a name ending in .pov, found '%s'", o->output);
	base = strrchr(o->output, '/');
	if (!pov_export_name_ok(base ? base + 1 : o->output))
		return usage_error("--output: POV-Ray's .ini cannot name '%s' (a quote or control character)",
				   o->output);
	return 0;
}

struct writer {
	const struct scene *scene;
	const struct camera *cam;
	const struct pov_options *pov;
	const char *pov_base, *png_base;
};

/* Writes the .pov or the .ini; on failure the file is removed, so that a
 * half-written scene is never left for POV-Ray to render. */
static int write_file(const char *path, const struct writer *w, bool ini, struct diag *d)
{
	FILE *f = fopen(path, "w");
	int rc;

	if (!f)
		return diag_set(d, RT_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
	if (ini)
		rc = pov_export_ini(f, w->pov_base, w->png_base, w->scene->image_size, d);
	else
		rc = pov_export_scene(f, w->scene, w->cam, w->pov, d);
	if (fclose(f) != 0 && rc == 0)
		rc = diag_set(d, RT_E_IO, "", 0, 0, "write error: %s", strerror(errno));
	if (rc < 0) {
		if (d->file[0] == '\0')
			snprintf(d->file, sizeof(d->file), "%s", path);
		remove(path);
	}
	return rc;
}

/* path with its last four characters (".pov") replaced by ext. */
static char *replace_ext(const char *path, const char *ext)
{
	size_t len = strlen(path) - 4;
	char *out = malloc(len + strlen(ext) + 1);

	if (out) {
		memcpy(out, path, len);
		strcpy(out + len, ext);
	}
	return out;
}

static int run(struct options *o)
{
	struct scene *s = NULL;
	struct camera cam;
	struct writer w;
	struct diag d;
	const char *slash = strrchr(o->output, '/');
	char *ini_path = replace_ext(o->output, ".ini");
	char *png_base = replace_ext(slash ? slash + 1 : o->output, ".png");
	int rc, status = EXIT_SCENE;

	diag_clear(&d);
	if (!ini_path || !png_base) {
		rc = diag_set(&d, RT_E_NOMEM, "", 0, 0, "out of memory");
		goto out;
	}
	rc = cli_scene_load(&o->scene, o->scene_path, print_note, o, &s, &cam, &d);
	if (rc < 0) {
		if (rc == -RT_E_INVALID)
			status = EXIT_USAGE;
		goto out;
	}
	w.scene = s;
	w.cam = &cam;
	w.pov = &o->pov;
	w.pov_base = slash ? slash + 1 : o->output;
	w.png_base = png_base;
	if ((rc = write_file(o->output, &w, false, &d)) < 0)
		goto out;
	if ((rc = write_file(ini_path, &w, true, &d)) < 0) {
		remove(o->output);
		goto out;
	}
	status = 0;
out:
	if (rc < 0)
		print_diag(&d, "error");
	scene_destroy(s);
	free(ini_path);
	free(png_base);
	return status;
}

int main(int argc, char **argv)
{
	struct options o;
	int status;

	status = parse_args(argc, argv, &o);
	if (status == 0)
		status = run(&o);
	free(o.output_owned);
	return status;
}
