/* whitted, the command line: reads a scene, renders it (or a region of it,
 * or the frames of an animation) and writes the images; `whitted merge`
 * joins region renders.  The only code that reads argv, prints to stderr
 * or chooses the exit status: 0 success, 1 a scene, input or I/O error, 2 a
 * bad command line, 128 + the signal when interrupted. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "accel.h"
#include "cli.h"
#include "frames.h"
#include "image.h"
#include "merge.h"
#include "render.h"
#include "scene.h"
#include "tile.h"

enum {
	EXIT_SCENE = 1,
	EXIT_USAGE = 2,
};

enum {
	OPT_STATS = CLI_OPT_FIRST_PRIVATE,
	OPT_PROGRESS,
	OPT_FORMAT,
	OPT_REGION,
	OPT_FRAMES,
	OPT_FRAME,
	OPT_PATH,
	OPT_GRID,
	OPT_TILE,
};

#define NAME_MAX_LEN 4096

enum progress_mode { PROGRESS_AUTO, PROGRESS_ALWAYS, PROGRESS_NEVER };

struct options {
	struct cli_scene scene;
	const char *scene_path;
	const char *output;
	char *output_owned;
	enum image_format format;
	int threads;
	bool stats;
	enum progress_mode progress;
	bool region;
	int x0, y0, x1, y1;		/* the region, end-exclusive */
	int frames;			/* 0: a still image */
	int frame;			/* 0: every frame */
	const char *path_file;		/* keyframes; NULL: the orbit */
	bool numbered;			/* output is a pattern with a frame number */
	int grid_cols, grid_rows;	/* --grid; 0: none */
	int tile;			/* --tile K of the grid, 1-based */
};

static volatile sig_atomic_t cancelled;

static void on_signal(int sig)
{
	cancelled = sig;
}

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
		"  -h, --help             show this help\n"
		"  -V, --version          show the version\n"
		"\n"
		"whitted merge -o FULL.png TILE.png...   joins region renders into the full\n"
		"image after checking they are of one scene and settings and cover it once\n"
		"(see 'whitted merge --help' and docs/distributed.md).\n"
		"\n"
		"Exit status: 0 success, 1 scene, input or I/O error, 2 bad command line,\n"
		"128+N when stopped by signal N (the output is then left untouched).\n",
		cli_scene_help, cli_default_threads());
}

static int usage_error(const char *fmt, const char *arg)
{
	fprintf(stderr, "whitted: error: ");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\nTry 'whitted --help' for more information.\n");
	return EXIT_USAGE;
}

static void print_diag(const struct diag *d, const char *kind)
{
	char line[RT_DIAG_FILE_MAX + RT_DIAG_MSG_MAX + 64];

	diag_format(d, "whitted", kind, line, sizeof(line));
	fprintf(stderr, "%s\n", line);
}

static void print_note(void *ctx, const struct diag *note)
{
	const struct options *o = ctx;

	if (!o->scene.quiet)
		print_diag(note, "note");
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
		if (cli_parse_long("--region", item, 0, RT_MAX_IMAGE_SIZE, &n, d) < 0)
			goto out_bad;
		*v[i] = (int)n;
		item = comma + 1;
	}
	o->region = true;
	if (tile_check_region(o->x0, o->y0, o->x1, o->y1, RT_MAX_IMAGE_SIZE, RT_MAX_IMAGE_SIZE, d) < 0)
		return -RT_E_INVALID;
	return 0;
out_bad:
	return diag_set(d, RT_E_INVALID, "", 0, 0,
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
	if (cli_parse_long("--grid", buf, 1, RT_MAX_IMAGE_SIZE, &c, d) < 0 ||
	    cli_parse_long("--grid", x + 1, 1, RT_MAX_IMAGE_SIZE, &r, d) < 0)
		goto out_bad;
	o->grid_cols = (int)c;
	o->grid_rows = (int)r;
	return 0;
out_bad:
	return diag_set(d, RT_E_INVALID, "", 0, 0,
			"expected COLUMNSxROWS (integers from 1 to %d), found '%s'", RT_MAX_IMAGE_SIZE, arg);
}

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
		return diag_set(d, RT_E_INVALID, "", 0, 0, "a %dx%d grid is finer than the %dx%d image",
				o->grid_cols, o->grid_rows, size, size);
	return 0;
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
				return usage_error("--output: '%s' is too long", dir);
			snprintf(name, sizeof(name), "%s%s%.*s%s.png", dir,
				 dir[0] && dir[strlen(dir) - 1] != '/' ? "/" : "",
				 (int)strlen(RT_FRAMES_PATTERN) - 4, RT_FRAMES_PATTERN, suffix);
			o->output_owned = strdup(name);
			if (!o->output_owned) {
				fprintf(stderr, "whitted: error: out of memory\n");
				return EXIT_SCENE;
			}
			o->output = o->output_owned;
		}
		diag_clear(&d);
		if (frames_pattern_check(o->output, &o->numbered, &d) < 0)
			return usage_error("--output: %s", d.msg);
		if (!o->numbered && !o->frame)
			return usage_error("--output: with --frames, give a pattern with %%04d or a directory, found '%s'",
					   o->output);
	} else if (!o->output) {
		strcat(suffix, ".png");
		o->output_owned = cli_default_output(o->scene_path, suffix);
		if (!o->output_owned) {
			fprintf(stderr, "whitted: error: out of memory\n");
			return EXIT_SCENE;
		}
		o->output = o->output_owned;
	}
	if (o->format == RT_FORMAT_UNKNOWN) {
		o->format = image_format_from_path(o->output);
		if (o->format == RT_FORMAT_UNKNOWN)
			return usage_error("--output: cannot tell the format of '%s' (use .png, .bmp or .ppm, or --format)",
					   o->output);
	}
	if ((o->region || o->grid_cols) && o->format != RT_FORMAT_PNG)
		return usage_error("--region, --grid: tiles are PNG files (their place is kept in PNG chunks), found '%s'",
				   o->output);
	return 0;
}

static int parse_args(int argc, char **argv, struct options *o)
{
	static const struct option longopts[] = {
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
		{ "help", no_argument, NULL, 'h' },
		{ "version", no_argument, NULL, 'V' },
		{ NULL, 0, NULL, 0 },
	};
	struct diag d;
	long n;
	int c, rc;

	memset(o, 0, sizeof(*o));
	cli_scene_init(&o->scene);
	o->threads = cli_default_threads();
	opterr = 0;
	while ((c = getopt_long(argc, argv, ":" CLI_SCENE_SHORT "o:j:hV", longopts, NULL)) != -1) {
		diag_clear(&d);
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
		case OPT_FORMAT:
			o->format = image_format_from_name(optarg);
			if (o->format == RT_FORMAT_UNKNOWN)
				return usage_error("--format: expected png, bmp or ppm, found '%s'", optarg);
			break;
		case 'j':
			if (cli_parse_long("--threads", optarg, 1, 64, &n, &d) < 0)
				return usage_error("%s", d.msg);
			o->threads = o->scene.read.threads = (int)n;
			break;
		case OPT_STATS:
			o->stats = true;
			break;
		case OPT_PROGRESS:
			if (strcmp(optarg, "auto") == 0)
				o->progress = PROGRESS_AUTO;
			else if (strcmp(optarg, "always") == 0)
				o->progress = PROGRESS_ALWAYS;
			else if (strcmp(optarg, "never") == 0)
				o->progress = PROGRESS_NEVER;
			else
				return usage_error("--progress: expected auto, always or never, found '%s'", optarg);
			break;
		case OPT_REGION:
			if (parse_region(optarg, o, &d) < 0)
				return usage_error("--region: %s", d.msg);
			break;
		case OPT_FRAMES:
			if (cli_parse_long("--frames", optarg, 1, RT_MAX_FRAMES, &n, &d) < 0)
				return usage_error("%s", d.msg);
			o->frames = (int)n;
			break;
		case OPT_FRAME:
			if (cli_parse_long("--frame", optarg, 1, RT_MAX_FRAMES, &n, &d) < 0)
				return usage_error("%s", d.msg);
			o->frame = (int)n;
			break;
		case OPT_PATH:
			if (optarg[0] == '\0')
				return usage_error("--path: %s", "expected a file name, found ''");
			o->path_file = optarg;
			break;
		case OPT_GRID:
			if (parse_grid(optarg, o, &d) < 0)
				return usage_error("--grid: %s", d.msg);
			break;
		case OPT_TILE:
			if (cli_parse_long("--tile", optarg, 1, RT_MAX_PIXELS, &n, &d) < 0)
				return usage_error("%s", d.msg);
			o->tile = (int)n;
			break;
		case 'h':
			usage(stdout);
			exit(0);
		case 'V':
			printf("whitted %s\n", RT_VERSION);
			exit(0);
		case ':':
			return usage_error("option '%s' needs a value", argv[optind - 1]);
		default:
			return usage_error("unknown option '%s'", argv[optind - 1]);
		}
	}
	if (cli_scene_operand(&o->scene, argc, argv, optind, &o->scene_path, &d) < 0)
		return usage_error("%s", d.msg);
	if (o->frame && !o->frames)
		return usage_error("%s", "--frame K needs --frames N");
	if (o->frame > o->frames) {
		char msg[96];
		snprintf(msg, sizeof(msg), "--frame %d is past the last frame of --frames %d",
			 o->frame, o->frames);
		return usage_error("%s", msg);
	}
	if (o->path_file && !o->frames)
		return usage_error("--path %s needs --frames N", o->path_file);
	if (!o->grid_cols != !o->tile)
		return usage_error("%s", o->tile ? "--tile K needs --grid COLUMNSxROWS" :
				   "--grid COLUMNSxROWS needs --tile K");
	if (o->grid_cols && o->region)
		return usage_error("%s", "--region and --grid cannot be combined");
	if ((long)o->tile > (long)o->grid_cols * o->grid_rows) {
		char msg[96];
		snprintf(msg, sizeof(msg), "--tile %d is past the last tile of --grid %dx%d",
			 o->tile, o->grid_cols, o->grid_rows);
		return usage_error("%s", msg);
	}
	return resolve_output(o);
}

static double now_seconds(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + ts.tv_nsec * 1e-9;
}

struct progress_bar {
	int last_percent;
};

static void show_progress(void *ctx, long done, long total)
{
	struct progress_bar *bar = ctx;
	int percent = (int)(100 * done / total), filled = percent * 30 / 100;

	if (percent == bar->last_percent)
		return;
	bar->last_percent = percent;
	fprintf(stderr, "\rrendering %3d%% [%.*s%*s]", percent, filled,
		"==============================", 30 - filled, "");
	if (done == total)
		fprintf(stderr, "\r%*s\r", 48, "");
	fflush(stderr);
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

static void print_stats(const struct scene *s, const struct ray_counts *rc, int threads,
			double t_parse, double t_build, double t_render, double t_write)
{
	struct rusage ru;
	double total = (double)(rc->primary + rc->shadow + rc->reflection);

	getrusage(RUSAGE_SELF, &ru);
	fprintf(stderr,
		"scene:    %zu objects, %zu lights, %dx%d, recursion %d, %zu hierarchy nodes (%.1f MiB)\n"
		"time:     parse %.3f s, build %.3f s, render %.3f s (%d threads), write %.3f s\n"
		"rays:     %llu primary, %llu shadow, %llu reflection, %.2f M rays/s\n"
		"memory:   %.1f MiB peak resident\n",
		s->n_shapes, s->n_lights, s->image_size, s->image_size, s->recursion,
		accel_node_count(s->accel), accel_bytes(s->accel) / 1048576.0, t_parse, t_build, t_render, threads, t_write,
		(unsigned long long)rc->primary, (unsigned long long)rc->shadow,
		(unsigned long long)rc->reflection, t_render > 0 ? total / t_render * 1e-6 : 0.0,
		ru.ru_maxrss / 1024.0);
}

/* The settings a tile records: everything besides the scene text that
 * decides its pixels. */
static void tile_settings_of(const struct options *o, const struct scene *s,
			     const struct camera_params *params, struct tile_settings *ts)
{
	ts->size = s->image_size;
	ts->recursion = s->recursion;
	ts->camera = *params;
	ts->floor = !o->scene.no_floor;
	ts->floor_width = o->scene.floor_width;
	ts->floor_tile = o->scene.floor_tile;
	ts->clamp = o->scene.clamp;
}

struct run_times {
	double render, write;
	struct ray_counts counts;
};

/* Renders the image (or the region) seen by cam and writes it to name. */
static int render_one(const struct options *o, const struct scene *s, const struct camera *cam,
		      const struct camera_params *params, const char *name, struct run_times *t,
		      struct diag *d)
{
	struct progress_bar bar = { -1 };
	struct ray_counts counts;
	struct tile_settings ts;
	struct tile_info info;
	struct render_job job;
	struct image img = { 0, 0, NULL };
	double t0, t1, t2;
	int rc;

	memset(&job, 0, sizeof(job));
	job.scene = s;
	job.camera = cam;
	job.settings.recursion = s->recursion;
	job.settings.clamp = o->scene.clamp;
	job.threads = o->threads;
	job.x1 = job.y1 = s->image_size;
	if (o->region) {
		job.x0 = o->x0;
		job.y0 = o->y0;
		job.x1 = o->x1;
		job.y1 = o->y1;
	}
	job.cancel = &cancelled;
	if (o->progress == PROGRESS_ALWAYS || (o->progress == PROGRESS_AUTO && isatty(STDERR_FILENO))) {
		job.progress = show_progress;
		job.progress_ctx = &bar;
	}
	if ((rc = check_output_dir(name, d)) < 0 ||
	    (rc = image_alloc(&img, job.x1 - job.x0, job.y1 - job.y0, d)) < 0)
		return rc;
	t0 = now_seconds();
	rc = render_image(&job, &img, &counts, d);
	t1 = now_seconds();
	if (rc < 0) {
		if (job.progress)
			fputc('\n', stderr);
		goto out_free;
	}
	if (o->region) {
		tile_settings_of(o, s, params, &ts);
		tile_info_init(&info, &ts, s->source_hash, job.x0, job.y0, job.x1, job.y1);
		rc = tile_write(name, &img, &info, &cancelled, d);
	} else {
		rc = image_write(&img, name, o->format, &cancelled, d);
	}
	t2 = now_seconds();
	t->render += t1 - t0;
	t->write += t2 - t1;
	t->counts.primary += counts.primary;
	t->counts.shadow += counts.shadow;
	t->counts.reflection += counts.reflection;
out_free:
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

static int run(struct options *o)
{
	struct frame_path path = { NULL, 0 };
	struct camera_params params;
	struct run_times times;
	struct scene *s = NULL;
	struct camera cam;
	struct diag d;
	char name[NAME_MAX_LEN];
	double t0, t1, t2;
	int rc, k, first, last, status = EXIT_SCENE;

	diag_clear(&d);
	memset(&times, 0, sizeof(times));
	t0 = now_seconds();
	/* Only tiles carry the scene's hash, to tell their scene apart. */
	o->scene.read.hash = o->region || o->grid_cols;
	rc = cli_scene_load(&o->scene, o->scene_path, print_note, o, &s, &cam, &d);
	if (rc < 0) {
		print_diag(&d, "error");
		return rc == -RT_E_INVALID ? EXIT_USAGE : EXIT_SCENE;
	}
	if ((o->grid_cols && grid_region(o, s->image_size, &d) < 0) ||
	    (o->region && tile_check_region(o->x0, o->y0, o->x1, o->y1, s->image_size, s->image_size, &d) < 0)) {
		fprintf(stderr, "whitted: error: %s: %s\n", o->grid_cols ? "--grid" : "--region", d.msg);
		scene_destroy(s);
		return EXIT_USAGE;
	}
	if (o->path_file && (rc = frames_path_load(o->path_file, &o->scene.camera, &path, &d)) < 0)
		goto out;
	t1 = now_seconds();
	if ((rc = scene_prepare(s, o->threads, &d)) < 0)
		goto out;
	t2 = now_seconds();
	first = o->frame ? o->frame : o->frames ? 1 : 0;
	last = o->frame ? o->frame : o->frames;
	/* Every camera is checked before the first frame is written.  An orbit
	 * keeps the angle between view and up, so only a keyframe can fail. */
	for (k = first; k <= last; k++) {
		frame_camera(o, &path, k, &params);
		if ((rc = camera_init(&cam, &params, s->image_size, &d)) < 0) {
			char msg[RT_DIAG_MSG_MAX];
			snprintf(msg, sizeof(msg), "%s", d.msg);
			rc = diag_set(&d, RT_E_RANGE, o->path_file ? o->path_file : "", 0, 0,
				      "frame %d: %.480s", k, msg);
			goto out;
		}
	}
	for (k = first; k <= last; k++) {
		frame_camera(o, &path, k, &params);
		if ((rc = camera_init(&cam, &params, s->image_size, &d)) < 0)
			goto out;
		if (k && o->numbered)
			rc = frames_name(o->output, k, name, sizeof(name), &d);
		else
			snprintf(name, sizeof(name), "%s", o->output);
		if (rc < 0 || (rc = render_one(o, s, &cam, &params, name, &times, &d)) < 0)
			goto out;
	}
	if (o->stats)
		print_stats(s, &times.counts, o->threads, t1 - t0, t2 - t1, times.render, times.write);
	status = 0;
out:
	if (rc < 0) {
		/* A signal that interrupted a system call (opening a FIFO that
		 * nobody reads) shows as an I/O error: the status names the signal. */
		if (rc == -RT_E_INTERRUPTED || cancelled)
			status = 128 + (int)cancelled;
		print_diag(&d, "error");
	}
	frames_path_free(&path);
	scene_destroy(s);
	return status;
}

static void merge_usage(FILE *f)
{
	fprintf(f,
		"Usage: whitted merge -o FULL.png TILE.png...\n"
		"Joins the tiles of one render (whitted --region) into the full image.  The\n"
		"tiles must come from the same scene file and pixel-affecting options (size,\n"
		"recursion, camera, floor, clamping) and cover the image exactly once; any\n"
		"order.  The result is the image a single whitted run writes, byte for byte.\n"
		"\n"
		"  -o, --output FILE      the full image; .png, .bmp or .ppm (required)\n"
		"      --format png|bmp|ppm  the format, when FILE's extension does not say it\n"
		"  -h, --help             show this help\n"
		"\n"
		"Exit status: 0 success, 1 a missing, overlapping, foreign or unreadable tile\n"
		"or an I/O error (nothing is written), 2 bad command line.\n");
}

static int merge_usage_error(const char *fmt, const char *arg)
{
	fprintf(stderr, "whitted merge: error: ");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\nTry 'whitted merge --help' for more information.\n");
	return EXIT_USAGE;
}

/* whitted merge: argv[0] is "merge". */
static int merge_main(int argc, char **argv)
{
	static const struct option longopts[] = {
		{ "output", required_argument, NULL, 'o' },
		{ "format", required_argument, NULL, OPT_FORMAT },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 },
	};
	enum image_format format = RT_FORMAT_UNKNOWN;
	const char *output = NULL;
	struct image img = { 0, 0, NULL };
	struct diag d;
	int c, rc;

	opterr = 0;
	while ((c = getopt_long(argc, argv, ":o:h", longopts, NULL)) != -1) {
		switch (c) {
		case 'o':
			if (optarg[0] == '\0')
				return merge_usage_error("--output: %s", "expected a file name, found ''");
			output = optarg;
			break;
		case OPT_FORMAT:
			format = image_format_from_name(optarg);
			if (format == RT_FORMAT_UNKNOWN)
				return merge_usage_error("--format: expected png, bmp or ppm, found '%s'", optarg);
			break;
		case 'h':
			merge_usage(stdout);
			return 0;
		case ':':
			return merge_usage_error("option '%s' needs a value", argv[optind - 1]);
		default:
			return merge_usage_error("unknown option '%s'", argv[optind - 1]);
		}
	}
	if (!output)
		return merge_usage_error("%s", "no output given (-o FULL.png)");
	if (optind == argc)
		return merge_usage_error("%s", "no tiles given");
	if (format == RT_FORMAT_UNKNOWN) {
		format = image_format_from_path(output);
		if (format == RT_FORMAT_UNKNOWN)
			return merge_usage_error("--output: cannot tell the format of '%s' (use .png, .bmp or .ppm, or --format)",
						 output);
	}
	diag_clear(&d);
	rc = merge_tiles((const char *const *)(argv + optind), (size_t)(argc - optind), &img, NULL, &d);
	if (rc == 0)
		rc = image_write(&img, output, format, &cancelled, &d);
	image_free(&img);
	if (rc < 0) {
		print_diag(&d, "error");
		return rc == -RT_E_INTERRUPTED || cancelled ? 128 + (int)cancelled : EXIT_SCENE;
	}
	return 0;
}

static void set_signals(void)
{
	struct sigaction sa, old_sa;

	memset(&sa, 0, sizeof(sa));
	sa.sa_handler = on_signal;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	/* A closed terminal stops the render cleanly too, unless the hang-up
	 * is ignored (nohup). */
	if (sigaction(SIGHUP, NULL, &old_sa) == 0 && old_sa.sa_handler != SIG_IGN)
		sigaction(SIGHUP, &sa, NULL);
	/* A file-size limit then fails the write with EFBIG instead of killing
	 * us with a temporary file left behind. */
	signal(SIGXFSZ, SIG_IGN);
}

int main(int argc, char **argv)
{
	struct options o;
	int status;

	/* A subcommand comes first; a scene file named "merge" is ./merge. */
	if (argc >= 2 && strcmp(argv[1], "merge") == 0) {
		set_signals();
		return merge_main(argc - 1, argv + 1);
	}
	status = parse_args(argc, argv, &o);
	if (status != 0) {
		free(o.output_owned);
		return status;
	}
	set_signals();
	status = run(&o);
	free(o.output_owned);
	return status;
}
