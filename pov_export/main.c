/* scene2pov, the command line: reads a scene with whitted's scene options
 * and writes OUT.pov and OUT.ini, which POV-Ray renders to OUT.png as
 * `whitted --clamp final` renders the scene.  The only code of the exporter
 * that reads argv, prints or chooses the exit status: 0 success, 1 a scene,
 * input or I/O error, 2 a bad command line. */
#define _XOPEN_SOURCE 700	/* realpath */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/platform.h"
#include "cli/scene_opts.h"
#include "cli/tool.h"
#include "export.h"
#include "whitted/image.h"
#include "whitted/scene.h"

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

static bool ends_with(const char *s, const char *suffix)
{
	size_t n = strlen(s), m = strlen(suffix);

	return n >= m && strcmp(s + n - m, suffix) == 0;
}

/* One of scene2pov's own options: 0, the status to stop with, or -1 when
 * it is not one. */
static int pov_option(void *ctx, int c, const char *arg)
{
	struct options *o = ctx;

	switch (c) {
	case 'o':
		return tool_file_arg("--output", arg, &o->output);
	case CLI_OPT_CLAMP:
		/* POV-Ray clamps only the finished pixel; whitted's default
		 * clamp at every level has no POV-Ray equivalent. */
		if (strcmp(arg, "level") == 0)
			return tool_usage_error("--clamp level cannot be exported: POV-Ray clamps only the finished pixel (--clamp final)");
		return -1;
	case CLI_OPT_SAMPLES:
		/* POV-Ray's own supersampling (+A, method 1 or 2) does not place
		 * or weigh its samples as whitted's grid does (45 dB apart at 3
		 * x 3), so nothing in the .ini could honour N > 1. */
		if (strcmp(arg, "1") == 0)
			return -1;
		return tool_usage_error("--samples %s cannot be exported: POV-Ray's antialiasing is not whitted's N x N grid; "
					"export at --size N*S and reduce the image by N x N box averaging (as povcheck does)",
					arg);
	case OPT_FINISH:
		if (strcmp(arg, "exact") == 0)
			o->pov.finish = RT_POV_FINISH_EXACT;
		else if (strcmp(arg, "plain") == 0)
			o->pov.finish = RT_POV_FINISH_PLAIN;
		else
			return tool_usage_error("--finish: expected exact or plain, found '%s'", arg);
		return 0;
	case 'h':
		usage(stdout);
		exit(0);
	case 'V':
		tool_print_version("scene2pov");
		exit(0);
	}
	return -1;
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
	int rc;

	memset(o, 0, sizeof(*o));
	cli_scene_init(&o->scene);
	o->pov.finish = RT_POV_FINISH_EXACT;
	rc = cli_parse_options(argc, argv, ":" CLI_SCENE_SHORT "o:hV", longopts, &o->scene, pov_option, o);
	if (rc != 0)
		return rc;
	o->scene_path = o->scene.path;
	if (!o->output) {
		o->output_owned = cli_default_output(o->scene_path, ".pov");
		if (!o->output_owned)
			return tool_out_of_memory();
		o->output = o->output_owned;
	}
	if (!ends_with(o->output, ".pov") || ends_with(o->output, "/.pov") || strcmp(o->output, ".pov") == 0)
		return tool_usage_error("--output: expected a name ending in .pov, found '%s'", o->output);
	base = strrchr(o->output, '/');
	if (!pov_export_name_ok(base ? base + 1 : o->output))
		return tool_usage_error("--output: POV-Ray's .ini cannot name '%s' (a quote or control character)",
				   o->output);
	return 0;
}

struct writer {
	const struct scene *scene;
	const struct camera *cam;
	const struct pov_options *pov;
	const char *pov_base, *png_base;
	const char *dir;		/* the .pov's absolute directory, or NULL */
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
		rc = pov_export_ini(f, w->pov_base, w->png_base, w->dir, scene_image_size(w->scene), d);
	else
		rc = pov_export_scene(f, w->scene, w->cam, w->pov, d);
	if (fclose(f) != 0 && rc == 0)
		rc = diag_fail(d, RT_E_IO, "write error: %s", strerror(errno));
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

/* The floor's textures as opaque 24-bit PNGs of the texels whitted
 * decoded, OUT-floor-white.png and OUT-floor-black.png beside OUT.pov, for
 * the image_maps to name (pov_options floor_texture): POV-Ray then reads
 * what whitted reads whatever the input was (an alpha channel, 32-bit or
 * top-down rows).  Each is written through a temporary file; on failure
 * those written are removed.  paths[k] and names[k] (the base name) are
 * set for each texture written, NULL otherwise; free paths[k]. */
static int write_textures(const struct scene *s, const char *output, char *paths[2],
			  const char *names[2], struct diag *d)
{
	static const char *const suffix[2] = { "-floor-white.png", "-floor-black.png" };
	int k, rc;

	for (k = 0; k < 2; k++) {
		const struct image *img = scene_floor_texture(s, k);
		const char *slash;

		paths[k] = NULL;
		names[k] = NULL;
		if (!img)
			continue;
		paths[k] = replace_ext(output, suffix[k]);
		if (!paths[k])
			rc = diag_fail(d, RT_E_NOMEM, "out of memory");
		else
			rc = image_write(img, paths[k], RT_FORMAT_PNG, NULL, d);
		if (rc < 0) {
			free(paths[k]);
			paths[k] = NULL;
			if (k == 1 && paths[0]) {
				remove(paths[0]);
				free(paths[0]);
				paths[0] = NULL;
				names[0] = NULL;
			}
			return rc;
		}
		slash = strrchr(paths[k], '/');
		names[k] = slash ? slash + 1 : paths[k];
	}
	return 0;
}

/* The absolute directory of path (malloc'd), for an .ini that works from
 * any directory; NULL when it cannot be had or an .ini cannot name it (a
 * quote in it): the .ini's names are then relative. */
static char *absolute_dir(const char *path)
{
	const char *slash = strrchr(path, '/');
	char *dir, *abs;

	if (!slash)
		dir = strdup(".");
	else if (slash == path)
		dir = strdup("/");
	else if ((dir = malloc((size_t)(slash - path) + 1)) != NULL) {
		memcpy(dir, path, (size_t)(slash - path));
		dir[slash - path] = '\0';
	}
	if (!dir)
		return NULL;
	abs = rt_real_path(dir);
	free(dir);
	if (abs && !pov_export_name_ok(abs)) {
		free(abs);
		abs = NULL;
	}
	return abs;
}

static void remove_textures(char *paths[2])
{
	int k;

	for (k = 0; k < 2; k++)
		if (paths[k])
			remove(paths[k]);
}

/* Long: scene2pov's steps in order (load, export, write, the files' cleanup)
 * with one exit for each. */
static int run(struct options *o)
{
	struct scene *s = NULL;
	struct camera cam;
	struct writer w;
	struct diag d;
	const char *slash = strrchr(o->output, '/');
	char *ini_path = replace_ext(o->output, ".ini");
	char *png_base = replace_ext(slash ? slash + 1 : o->output, ".png");
	char *tex_paths[2] = { NULL, NULL };
	char *dir = NULL;
	int rc, status = TOOL_EXIT_FAILURE;

	diag_clear(&d);
	if (!ini_path || !png_base) {
		rc = diag_fail(&d, RT_E_NOMEM, "out of memory");
		goto out;
	}
	rc = cli_scene_load(&o->scene, o->scene_path, tool_print_note, &o->scene.quiet, &s, &cam, &d);
	if (rc < 0) {
		if (rc == -RT_E_INVALID)
			status = TOOL_EXIT_USAGE;
		goto out;
	}
	if (pov_export_near_hides(s, &cam)) {
		struct diag note;

		diag_set(&note, RT_OK, o->scene_path ? o->scene_path : "", 0, 0,
			 "a shape lies partly nearer than the image plane, where whitted sees "
			 "nothing: POV-Ray's camera has no near plane and may show it");
		tool_print_note(&o->scene.quiet, &note);
	}
	if ((rc = write_textures(s, o->output, tex_paths, o->pov.floor_texture, &d)) < 0)
		goto out;
	w.scene = s;
	w.cam = &cam;
	w.pov = &o->pov;
	w.pov_base = slash ? slash + 1 : o->output;
	w.png_base = png_base;
	w.dir = dir = absolute_dir(o->output);
	if ((rc = write_file(o->output, &w, false, &d)) < 0) {
		remove_textures(tex_paths);
		goto out;
	}
	if ((rc = write_file(ini_path, &w, true, &d)) < 0) {
		remove(o->output);
		remove_textures(tex_paths);
		goto out;
	}
	/* What was written, and how to render it. */
	printf("scene2pov: wrote %s and %s", o->output, ini_path);
	if (tex_paths[0] || tex_paths[1])
		printf(" (with %s%s%s)", tex_paths[0] ? tex_paths[0] : "",
		       tex_paths[0] && tex_paths[1] ? ", " : "", tex_paths[1] ? tex_paths[1] : "");
	printf("; 'povray %s' renders %s%s%s\n", ini_path, dir ? dir : "", dir ? "/" : "", png_base);
	status = fflush(stdout) == 0 ? 0 : TOOL_EXIT_FAILURE;
out:
	if (rc < 0)
		tool_print_diag(&d, "error");
	free(tex_paths[0]);
	free(tex_paths[1]);
	free(dir);
	scene_destroy(s);
	free(ini_path);
	free(png_base);
	return status;
}

int main(int argc, char **argv)
{
	struct options o;
	int status;

	tool_set_name("scene2pov");
	status = parse_args(argc, argv, &o);
	if (status == 0)
		status = run(&o);
	free(o.output_owned);
	return status;
}
