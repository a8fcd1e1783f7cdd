/* The web page's entry points into the library (make web, emscripten):
 * the whitted command line itself for compare, grade and explain (their
 * JSON and CSV on stdout, their messages on stderr, which the page's
 * worker collects), and a render in parts for the Web Workers: each loads
 * and prepares the scene with the command line's own options code, then
 * renders the bands of rows the page hands it.  The bands of one image
 * are the image's rows, byte for byte (a pixel does not depend on which
 * region renders it). */
#define _POSIX_C_SOURCE 200809L
#include <getopt.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"
#include "cli/render_args.h"
#include "cli/tool.h"
#include "whitted/render.h"

/* main.c's main, renamed by the web build. */
int whitted_main(int argc, char **argv);
void web_argv_reset(void);
int web_argv_push(const char *arg);
int web_cli(void);
int web_render_begin(void);
int web_render_width(void);
int web_render_height(void);
int web_render_rows(int y0, int y1, uint8_t *out);
void web_render_end(void);

#define WEB_MAX_ARGS 256

static char *args[WEB_MAX_ARGS + 1];
static int n_args;

void web_argv_reset(void)
{
	while (n_args > 0)
		free(args[--n_args]);
	args[0] = NULL;
}

int web_argv_push(const char *arg)
{
	if (n_args == WEB_MAX_ARGS || !(args[n_args] = strdup(arg)))
		return -1;
	args[++n_args] = NULL;
	return 0;
}

/* getopt starts afresh (musl: optind 0), and no signal is pending. */
static void web_fresh(void)
{
	optind = 0;
	cli_cancelled = 0;
}

int web_cli(void)
{
	int rc;

	web_fresh();
	rc = whitted_main(n_args, args);
	fflush(stdout);
	fflush(stderr);
	return rc;
}

static struct {
	struct options o;
	struct scene *scene;
	struct camera cam;
	bool open;
} web;

void web_render_end(void)
{
	if (!web.open)
		return;
	scene_destroy(web.scene);
	free(web.o.output_owned);
	memset(&web, 0, sizeof(web));
}

/* The scene of a render command line (args: whitted [OPTIONS] SCENE),
 * loaded and prepared as whitted does; its size then
 * web_render_width/height.  Returns the exit status whitted would (the
 * message on stderr). */
int web_render_begin(void)
{
	struct diag d;
	int rc;

	web_render_end();
	web_fresh();
	tool_set_name("whitted");
	if ((rc = render_args_parse(n_args, args, &web.o)) != 0) {
		free(web.o.output_owned);
		memset(&web, 0, sizeof(web));
		fflush(stderr);
		return rc < 0 ? TOOL_EXIT_USAGE : rc;
	}
	web.open = true;
	diag_clear(&d);
	rc = cli_scene_load(&web.o.scene, web.o.scene_path, tool_print_note, &web.o.scene.quiet,
			    &web.scene, &web.cam, &d);
	if (rc == 0)
		rc = scene_prepare(web.scene, 1, &d);
	if (rc < 0) {
		tool_print_diag(&d, "error");
		fflush(stderr);
		web_render_end();
		return tool_status_of(rc);
	}
	fflush(stderr);
	return 0;
}

int web_render_width(void)
{
	return web.open ? web.cam.width : 0;
}

int web_render_height(void)
{
	return web.open ? web.cam.height : 0;
}

/* Rows [y0, y1) of the image as RGB into out (width * (y1 - y0) * 3
 * bytes): 0, or the exit status with the message on stderr. */
int web_render_rows(int y0, int y1, uint8_t *out)
{
	struct render_job job;
	struct image img;
	struct diag d;
	int rc;

	if (!web.open)
		return TOOL_EXIT_USAGE;
	cli_render_job(&job, &web.o.scene, web.scene, &web.cam, 1, web.o.max_rays);
	job.y0 = y0;
	job.y1 = y1;
	img.width = web.cam.width;
	img.height = y1 - y0;
	img.pixels = out;
	diag_clear(&d);
	if ((rc = render_image(&job, &img, NULL, &d)) < 0) {
		tool_print_diag(&d, "error");
		fflush(stderr);
		return tool_status_of(rc);
	}
	return 0;
}
