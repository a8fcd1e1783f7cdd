/* whitted, the command line: reads a scene, renders it and writes the
 * image.  The only code that reads argv, prints to stderr or chooses the
 * exit status: 0 success, 1 a scene, input or I/O error, 2 a bad command
 * line, 128 + the signal when interrupted. */
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
#include "image.h"
#include "render.h"
#include "scene.h"

enum {
	EXIT_SCENE = 1,
	EXIT_USAGE = 2,
};

enum {
	OPT_STATS = CLI_OPT_FIRST_PRIVATE,
	OPT_PROGRESS,
	OPT_FORMAT,
};

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
		"  -j, --threads N        render threads (default: all %d online cores)\n"
		"      --stats            print times, ray counts and peak memory on stderr\n"
		"      --progress auto|always|never  progress bar on stderr (auto: when it is\n"
		"                         a terminal)\n"
		"  -h, --help             show this help\n"
		"  -V, --version          show the version\n"
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

	diag_format(d, kind, line, sizeof(line));
	fprintf(stderr, "%s\n", line);
}

static void print_note(void *ctx, const struct diag *note)
{
	const struct options *o = ctx;

	if (!o->scene.quiet)
		print_diag(note, "note");
}

/* SCENE's base name with its extension replaced by .png. */
static char *default_output(const char *scene_path)
{
	const char *base = strrchr(scene_path, '/');
	const char *dot;
	size_t len;
	char *out;

	if (strcmp(scene_path, "-") == 0)
		scene_path = "stdin";
	base = base ? base + 1 : scene_path;
	dot = strrchr(base, '.');
	len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
	out = malloc(len + 5);
	if (out) {
		memcpy(out, base, len);
		strcpy(out + len, ".png");
	}
	return out;
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
			o->threads = (int)n;
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
	if (o->scene.test_scene) {
		if (optind != argc)
			return usage_error("--test-scene takes no SCENE, found '%s'", argv[optind]);
	} else {
		if (optind == argc)
			return usage_error("%s", "no SCENE given");
		if (optind + 1 != argc)
			return usage_error("one SCENE expected, found also '%s'", argv[optind + 1]);
		o->scene_path = argv[optind];
	}
	if (!o->output) {
		o->output_owned = default_output(o->scene_path ? o->scene_path : "test-scene");
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
	return 0;
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
		"scene:    %zu objects, %zu lights, %dx%d, recursion %d, %zu hierarchy nodes\n"
		"time:     parse %.3f s, build %.3f s, render %.3f s (%d threads), write %.3f s\n"
		"rays:     %llu primary, %llu shadow, %llu reflection, %.2f M rays/s\n"
		"memory:   %.1f MiB peak resident\n",
		s->n_shapes, s->n_lights, s->image_size, s->image_size, s->recursion,
		accel_node_count(s->accel), t_parse, t_build, t_render, threads, t_write,
		(unsigned long long)rc->primary, (unsigned long long)rc->shadow,
		(unsigned long long)rc->reflection, t_render > 0 ? total / t_render * 1e-6 : 0.0,
		ru.ru_maxrss / 1024.0);
}

static int run(struct options *o)
{
	struct progress_bar bar = { -1 };
	struct ray_counts counts;
	struct render_job job;
	struct scene *s = NULL;
	struct camera cam;
	struct image img = { 0, 0, NULL };
	struct diag d;
	double t0, t1, t2, t3, t4;
	int rc, status = EXIT_SCENE;

	diag_clear(&d);
	memset(&job, 0, sizeof(job));
	t0 = now_seconds();
	rc = cli_scene_load(&o->scene, o->scene_path, print_note, o, &s, &cam, &d);
	if (rc < 0) {
		print_diag(&d, "error");
		return rc == -RT_E_INVALID ? EXIT_USAGE : EXIT_SCENE;
	}
	t1 = now_seconds();
	if ((rc = scene_prepare(s, &d)) < 0)
		goto out;
	t2 = now_seconds();
	if ((rc = check_output_dir(o->output, &d)) < 0 ||
	    (rc = image_alloc(&img, s->image_size, s->image_size, &d)) < 0)
		goto out;
	job.scene = s;
	job.camera = &cam;
	job.settings.recursion = s->recursion;
	job.settings.clamp = o->scene.clamp;
	job.threads = o->threads;
	job.x1 = job.y1 = s->image_size;
	job.cancel = &cancelled;
	if (o->progress == PROGRESS_ALWAYS || (o->progress == PROGRESS_AUTO && isatty(STDERR_FILENO))) {
		job.progress = show_progress;
		job.progress_ctx = &bar;
	}
	rc = render_image(&job, &img, &counts, &d);
	t3 = now_seconds();
	if (rc < 0)
		goto out;
	rc = image_write(&img, o->output, o->format, &cancelled, &d);
	t4 = now_seconds();
	if (rc < 0)
		goto out;
	if (o->stats)
		print_stats(s, &counts, o->threads, t1 - t0, t2 - t1, t3 - t2, t4 - t3);
	status = 0;
out:
	if (rc < 0) {
		/* A signal that interrupted a system call (opening a FIFO that
		 * nobody reads) shows as an I/O error: the status names the signal. */
		if (rc == -RT_E_INTERRUPTED || cancelled)
			status = 128 + (int)cancelled;
		if (job.progress)
			fputc('\n', stderr);
		print_diag(&d, "error");
	}
	image_free(&img);
	scene_destroy(s);
	return status;
}

int main(int argc, char **argv)
{
	struct sigaction sa, old_sa;
	struct options o;
	int status;

	status = parse_args(argc, argv, &o);
	if (status != 0) {
		free(o.output_owned);
		return status;
	}
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
	status = run(&o);
	free(o.output_owned);
	return status;
}
