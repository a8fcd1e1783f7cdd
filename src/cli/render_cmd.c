/* whitted's render: loads the scene, builds its hierarchy, and renders the
 * still image, the region or each frame to its file. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "cli/cli.h"
#include "cli/plugin_opts.h"
#include "cli/render_args.h"
#include "cli/report.h"
#include "cli/tool.h"
#include "whitted/frames.h"
#include "whitted/render.h"
#include "whitted/settings.h"
#include "whitted/tile.h"

/* Tile K of the grid, counted row by row from the top left; the cuts
 * are at floor(i * size / n), so the tiles cover any size exactly. */
static int grid_region(struct options *o, int size, struct diag *d)
{
	long long k = o->tile - 1, col = k % o->grid_cols, row = k / o->grid_cols;

	o->x0 = (int)(col * size / o->grid_cols);
	o->x1 = (int)((col + 1) * size / o->grid_cols);
	o->y0 = (int)(row * size / o->grid_rows);
	o->y1 = (int)((row + 1) * size / o->grid_rows);
	o->region = true;
	if (o->grid_cols > size || o->grid_rows > size)
		return diag_fail(d, RT_E_INVALID, "a %dx%d grid is finer than the %dx%d image",
				o->grid_cols, o->grid_rows, size, size);
	return 0;
}

/* Fails early, before a long render, when the output's directory cannot
 * take a new file. */
static int check_output_dir(const char *path, struct diag *d)
{
	const char *slash = strrchr(path, '/');
	struct stat st;
	char dir[4096];

	if (image_path_is_direct(path))
		return 0;
	if (!slash)
		snprintf(dir, sizeof(dir), ".");
	else if (slash == path)
		snprintf(dir, sizeof(dir), "/");
	else
		snprintf(dir, sizeof(dir), "%.*s", (int)(slash - path), path);
	if (stat(dir, &st) == 0 && !S_ISDIR(st.st_mode))
		return diag_set(d, RT_E_IO, path, 0, 0, "cannot write: %s", strerror(ENOTDIR));
	if (access(dir, W_OK | X_OK) != 0)
		return diag_set(d, RT_E_IO, path, 0, 0, "cannot write: %s", strerror(errno));
	return 0;
}

/* The settings of an image seen through params: everything besides the
 * scene text that decides its pixels, for its tile and --stats. */
static void settings_of(const struct options *o, const struct scene *s,
			const struct camera_params *params, struct settings *out)
{
	cli_settings(out, &o->scene, s, params);
	out->plugins = cli_plugins_used(s);
}

struct run_times {
	double render, write;
	struct ray_counts counts;
	struct settings settings;	/* of the last image */
};

/* Renders the image (or the region) seen by cam and writes it to name.
 * Long: one render's steps (job, image, render, write, stats) with one exit
 * that frees them. */
static int render_one(const struct options *o, const struct scene *s, const struct camera *cam,
		      const struct camera_params *params, const char *name, struct run_times *t,
		      struct diag *d)
{
	struct progress_bar bar = { -1 };
	struct ray_counts counts;
	struct tile_info info;
	struct render_job job;
	struct image img = { 0, 0, NULL };
	struct image_png_writer *png = NULL;
	double t0, t1, t2;
	int rc;

	cli_render_job(&job, &o->scene, s, cam, o->threads, o->max_rays);
	if (o->region) {
		job.x0 = o->x0;
		job.y0 = o->y0;
		job.x1 = o->x1;
		job.y1 = o->y1;
	}
	job.cancel = &cli_cancelled;
	if (o->progress == PROGRESS_ALWAYS || (o->progress == PROGRESS_AUTO && isatty(STDERR_FILENO))) {
		job.progress = report_progress;
		job.progress_ctx = &bar;
	}
	if ((rc = check_output_dir(name, d)) < 0 ||
	    (rc = image_alloc(&img, job.x1 - job.x0, job.y1 - job.y0, d)) < 0)
		return rc;
	/* A whole PNG is compressed band by band by the render's threads as
	 * it is rendered, when they take every processor: the write is then
	 * only the file.  With processors to spare, the write compresses on
	 * all of them after the render, sooner than fewer threads would
	 * during it. */
	if (!o->region && o->format == RT_FORMAT_PNG && o->threads >= cli_default_threads()) {
		if ((rc = image_png_writer_open(&img, job.threads, &png, d)) < 0)
			goto out_free;
		job.band_rows = image_png_writer_band_rows();
		job.band_done = image_png_writer_band_done;
		job.band_ctx = png;
	}
	t0 = report_now();
	rc = render_image(&job, &img, &counts, d);
	t1 = report_now();
	if (rc < 0) {
		if (job.progress)
			fputc('\n', stderr);
		goto out_free;
	}
	settings_of(o, s, params, &t->settings);
	if (o->region) {
		tile_info_init(&info, &t->settings, scene_source_hash(s), job.x0, job.y0, job.x1,
			       job.y1);
		rc = tile_write(name, &img, &info, &cli_cancelled, d);
	} else if (png) {
		rc = image_png_writer_write(png, name, &cli_cancelled, d);
	} else {
		rc = image_write(&img, name, o->format, &cli_cancelled, d);
	}
	t2 = report_now();
	t->render += t1 - t0;
	t->write += t2 - t1;
	t->counts.primary += counts.primary;
	t->counts.shadow += counts.shadow;
	t->counts.reflection += counts.reflection;
	t->counts.refraction += counts.refraction;
out_free:
	image_png_writer_free(png);
	image_free(&img);
	return rc;
}

/* The camera of frame k (or of the still image when k is 0). */
static void frame_camera(const struct options *o, const struct frame_path *path, int k,
			 struct camera_params *params)
{
	if (k == 0)
		*params = o->scene.camera;
	else if (o->path_file)
		frames_on_path(path, k, o->frames, params);
	else
		frames_orbit(&o->scene.camera, k, o->frames, params);
}

/* The frames to render: 0 alone for a still image. */
static void frame_range(const struct options *o, int *first, int *last)
{
	*first = o->frame ? o->frame : o->frames ? 1 : 0;
	*last = o->frame ? o->frame : o->frames;
}

/* Every camera is checked before the first frame is written.  An orbit
 * keeps the angle between view and up, so only a keyframe can fail. */
static int check_cameras(const struct options *o, const struct frame_path *path, int size,
			 struct diag *d)
{
	struct camera_params params;
	struct camera cam;
	int k, first, last;

	frame_range(o, &first, &last);
	for (k = first; k <= last; k++) {
		frame_camera(o, path, k, &params);
		if (camera_init(&cam, &params, size, d) < 0) {
			char msg[RT_DIAG_MSG_MAX];
			snprintf(msg, sizeof(msg), "%s", d->msg);
			return diag_set(d, RT_E_RANGE, o->path_file ? o->path_file : "", 0, 0,
					"frame %d: %.480s", k, msg);
		}
	}
	return 0;
}

static int render_frames(const struct options *o, const struct scene *s,
			 const struct frame_path *path, struct run_times *times, struct diag *d)
{
	struct camera_params params;
	struct camera cam;
	char name[NAME_MAX_LEN];
	int rc = 0, k, first, last;

	frame_range(o, &first, &last);
	for (k = first; k <= last; k++) {
		frame_camera(o, path, k, &params);
		if ((rc = camera_init(&cam, &params, scene_image_size(s), d)) < 0)
			return rc;
		if (k && o->numbered)
			rc = frames_name(o->output, k, name, sizeof(name), d);
		else
			snprintf(name, sizeof(name), "%s", o->output);
		if (rc < 0 || (rc = render_one(o, s, &cam, &params, name, times, d)) < 0)
			return rc;
	}
	return 0;
}

static int run(struct options *o)
{
	struct frame_path path = { NULL, 0 };
	struct run_times times;
	struct scene *s = NULL;
	struct camera cam;
	struct diag d;
	double t0, t1, t2;
	int rc, status = TOOL_EXIT_FAILURE;

	diag_clear(&d);
	memset(&times, 0, sizeof(times));
	t0 = report_now();
	/* Only tiles carry the scene's hash, to tell their scene apart. */
	o->scene.read.hash = o->region || o->grid_cols;
	rc = cli_scene_load(&o->scene, o->scene_path, tool_print_note, &o->scene.quiet, &s, &cam, &d);
	if (rc < 0) {
		tool_print_diag(&d, "error");
		return rc == -RT_E_INVALID ? TOOL_EXIT_USAGE : TOOL_EXIT_FAILURE;
	}
	if ((o->grid_cols && grid_region(o, scene_image_size(s), &d) < 0) ||
	    (o->region && tile_check_region(o->x0, o->y0, o->x1, o->y1, scene_image_size(s), scene_image_size(s), &d) < 0)) {
		fprintf(stderr, "whitted: error: %s: %s\n", o->grid_cols ? "--grid" : "--region", d.msg);
		scene_destroy(s);
		return TOOL_EXIT_USAGE;
	}
	if (o->path_file && (rc = frames_path_load(o->path_file, &o->scene.camera, &path, &d)) < 0)
		goto out;
	t1 = report_now();
	if ((rc = scene_prepare(s, o->threads, &d)) < 0)
		goto out;
	t2 = report_now();
	if ((rc = check_cameras(o, &path, scene_image_size(s), &d)) < 0 ||
	    (rc = render_frames(o, s, &path, &times, &d)) < 0)
		goto out;
	if (o->stats) {
		struct report_times rt = { t1 - t0, t2 - t1, times.render, times.write };
		report_stats(s, &times.settings, &times.counts, o->threads, &rt);
	}
	status = 0;
out:
	if (rc < 0) {
		/* A signal that interrupted a system call (opening a FIFO that
		 * nobody reads) shows as an I/O error: the status names the signal. */
		if (rc == -RT_E_INTERRUPTED || cli_cancelled)
			status = 128 + (int)cli_cancelled;
		tool_print_diag(&d, "error");
	}
	frames_path_free(&path);
	scene_destroy(s);
	return status;
}

/* whitted --list-shapes: the registry after loading the plugins. */
static int list_shapes(const struct options *o)
{
	bool quiet = o->scene.quiet;
	struct diag d;

	diag_clear(&d);
	if (cli_plugins_load(o->scene.plugins, o->scene.n_plugins, tool_print_note, &quiet,
			     &d) < 0) {
		tool_print_diag(&d, "error");
		return TOOL_EXIT_FAILURE;
	}
	cli_print_shapes(stdout);
	return 0;
}

int render_main(int argc, char **argv)
{
	struct options o;
	int status = render_args_parse(argc, argv, &o);

	if (status == 0 && o.scene.list_shapes) {
		status = list_shapes(&o);
	} else if (status == 0) {
		cli_set_signals();
		status = run(&o);
	}
	free(o.output_owned);
	return status;
}
