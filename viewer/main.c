/* whitted-view, the interactive viewer: flies an OpenGL camera through a
 * scene with the keys of the course's first assignment and, on 0, traces
 * the current view with the library into capture-N.png and prints the
 * whitted command that renders the same image.  The only code here that
 * talks to GLUT, reads argv, prints or exits; GLUT is called from the main
 * thread only (the capture thread just traces and writes).
 * Standard output carries only the "captured" lines; messages go to
 * standard error. */
#define _POSIX_C_SOURCE 200809L
#include <GL/freeglut.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capture.h"
#include "cli/scene_opts.h"
#include "command.h"
#include "draw.h"
#include "cli/tool.h"
#include "fly_camera.h"
#include "whitted/render.h"
#include "whitted/scene.h"

#define VIEW_WINDOW_SIZE 500
#define VIEW_POLL_MS 100

static const double view_pi = 3.14159265358979323846;

/* GLUT's callbacks take no context: the viewer's state lives here. */
static struct viewer {
	struct cli_scene opts;
	const char *scene_path;		/* NULL: --test-scene */
	char scene_name[256];		/* for the title */
	struct scene *scene;
	struct draw draw;
	struct fly_camera cam, home;
	double move_step, home_move_step;
	double turn_deg;
	int threads;
	struct capture capture;
	int next_capture;
	char command[8192];
	int width, height;
} v;

static void usage(FILE *f)
{
	fprintf(f,
		"Usage: whitted-view [OPTIONS] SCENE\n"
		"Shows a scene.txt file in an OpenGL window to fly through; the key 0 ray traces\n"
		"the current view into capture-N.png and prints the whitted command that renders\n"
		"the same image.  Press h in the window for the keys.\n"
		"\n"
		"%s"
		"  -j, --threads N        threads for reading the file, building the hierarchy\n"
		"                         and capturing (default: all %d online cores)\n"
		"  -h, --help             show this help\n"
		"  -V, --version          show the version\n"
		"\n"
		"Exit status: 0 the window was closed, 1 scene, input or I/O error (or no\n"
		"display), 2 bad command line, 128+N when stopped by signal N (a capture in\n"
		"progress is then removed).\n",
		cli_scene_help, cli_default_threads());
}

/* One of the viewer's own options: 0, the status to stop with, or -1. */
static int viewer_option(void *ctx, int c, const char *arg)
{
	(void)ctx;
	switch (c) {
	case 'j': {
		struct diag d;
		long n;

		diag_clear(&d);
		if (number_parse_long("--threads", arg, 1, 64, &n, &d) < 0)
			return tool_usage_error("%s", d.msg);
		v.threads = v.opts.read.threads = (int)n;
		return 0;
	}
	case 'h':
		usage(stdout);
		exit(0);
	case 'V':
		tool_print_version("whitted-view");
		exit(0);
	}
	return -1;
}

static int parse_args(int argc, char **argv)
{
	static const struct option longopts[] = {
		CLI_SCENE_LONG,
		{ "threads", required_argument, NULL, 'j' },
		{ "help", no_argument, NULL, 'h' },
		{ "version", no_argument, NULL, 'V' },
		{ NULL, 0, NULL, 0 },
	};
	int rc;

	cli_scene_init(&v.opts);
	v.threads = cli_default_threads();
	rc = cli_parse_options(argc, argv, ":" CLI_SCENE_SHORT "j:hV", longopts, &v.opts,
			       viewer_option, NULL);
	if (rc != 0)
		return rc;
	v.scene_path = v.opts.path;
	if (v.opts.test_scene) {
		snprintf(v.scene_name, sizeof(v.scene_name), "test scene");
		return 0;
	}
	/* The capture's command names the file; standard input cannot be
	 * read a second time. */
	if (strcmp(v.scene_path, "-") == 0)
		return tool_usage_error("%s", "SCENE must be a file, not '-'");
	snprintf(v.scene_name, sizeof(v.scene_name), "%s",
		 strrchr(v.scene_path, '/') ? strrchr(v.scene_path, '/') + 1 : v.scene_path);
	return 0;
}

static void set_title(const char *status)
{
	char title[512];

	if (status)
		snprintf(title, sizeof(title), "whitted: %s - %s", v.scene_name, status);
	else
		snprintf(title, sizeof(title), "whitted: %s", v.scene_name);
	glutSetWindowTitle(title);
}

static void print_keys(void)
{
	fprintf(stderr,
		"whitted-view keys:\n"
		"  Up / Down            move forward / back\n"
		"  Left / Right         move left / right\n"
		"  Page Up / Page Down  move up / down\n"
		"  1 / 2                turn left / right (yaw)\n"
		"  3 / 4                look up / down (pitch)\n"
		"  5 / 6                tilt clockwise / anticlockwise (roll)\n"
		"  + / -                larger / smaller steps (now %.4g units, %.3g degrees)\n"
		"  0                    ray trace this view into capture-N.png\n"
		"  r                    back to the starting view\n"
		"  h                    this help\n"
		"  q / Escape           quit\n",
		v.move_step, v.turn_deg);
}

static void on_display(void)
{
	int size = v.width < v.height ? v.width : v.height;

	/* A square viewport, centred: the tracer's image is square. */
	draw_frame(&v.draw, v.scene, &v.cam, (v.width - size) / 2, (v.height - size) / 2, size);
	glutSwapBuffers();
}

static void on_reshape(int width, int height)
{
	v.width = width;
	v.height = height;
	glutPostRedisplay();
}

static void on_poll(int value)
{
	struct diag d;
	char status[128];

	(void)value;
	if (!v.capture.running)
		return;
	if (!capture_finished(&v.capture)) {
		snprintf(status, sizeof(status), "tracing %s %d%%", v.capture.path,
			 capture_percent(&v.capture));
		set_title(status);
		glutTimerFunc(VIEW_POLL_MS, on_poll, 0);
		return;
	}
	diag_clear(&d);
	if (capture_join(&v.capture, &d) < 0) {
		tool_print_diag(&d, "error");
		set_title(NULL);
		return;
	}
	printf("captured %s: %s\n", v.capture.path, v.command);
	fflush(stdout);
	set_title(NULL);
}

static void start_capture(void)
{
	struct camera_params p;
	struct render_settings rs;
	struct settings set;
	struct camera cam;
	char path[64];
	struct diag d;
	int rc;

	if (v.capture.running) {
		fprintf(stderr, "whitted-view: still tracing %s (%d%%)\n", v.capture.path,
			capture_percent(&v.capture));
		return;
	}
	diag_clear(&d);
	fly_camera_params(&v.cam, &p);
	cli_settings(&set, &v.opts, v.scene, &p);
	/* The camera whitted builds from the printed numbers (and the near
	 * plane and aspect that it reads from the file again). */
	if (camera_init(&cam, &p, scene_image_size(v.scene), &d) < 0) {
		tool_print_diag(&d, "error");
		return;
	}
	rc = command_format(v.command, sizeof(v.command), v.scene_path, v.opts.read.dialect, &set);
	if (rc < 0) {
		diag_fail(&d, (enum rt_err)-rc, "%s",
			  rc == -RT_E_RANGE ? "the scene's path is too long for the command"
					    : "no whitted command can give this floor");
		tool_print_diag(&d, "error");
		return;
	}
	if (capture_reserve(&v.next_capture, path, sizeof(path), &d) < 0) {
		tool_print_diag(&d, "error");
		return;
	}
	rs.recursion = scene_recursion(v.scene);
	rs.clamp = v.opts.clamp;
	if (capture_start(&v.capture, v.scene, &cam, &rs, v.opts.samples, v.threads, path, &d) < 0) {
		tool_print_diag(&d, "error");
		remove(path);
		return;
	}
	set_title("tracing");
	glutTimerFunc(VIEW_POLL_MS, on_poll, 0);
}

static void quit(void)
{
	struct diag d;

	if (v.capture.running) {
		capture_cancel(&v.capture);
		capture_join(&v.capture, &d);
	}
	glutLeaveMainLoop();
}

static void change_steps(double factor)
{
	v.move_step *= factor;
	v.turn_deg = fmin(30.0, fmax(0.1, v.turn_deg * sqrt(factor)));
	fprintf(stderr, "whitted-view: steps %.4g units, %.3g degrees\n", v.move_step, v.turn_deg);
}

static void on_key(unsigned char key, int x, int y)
{
	double turn = v.turn_deg * view_pi / 180.0;

	(void)x;
	(void)y;
	switch (key) {
	case '1': fly_camera_yaw(&v.cam, turn); break;
	case '2': fly_camera_yaw(&v.cam, -turn); break;
	case '3': fly_camera_pitch(&v.cam, turn); break;
	case '4': fly_camera_pitch(&v.cam, -turn); break;
	case '5': fly_camera_roll(&v.cam, turn); break;
	case '6': fly_camera_roll(&v.cam, -turn); break;
	case '+': case '=': change_steps(2.0); return;
	case '-': case '_': change_steps(0.5); return;
	case '0': start_capture(); return;
	case 'h': case 'H': print_keys(); return;
	case 'r': case 'R':
		v.cam = v.home;
		v.move_step = v.home_move_step;
		v.turn_deg = 3.0;
		break;
	case 'q': case 'Q': case 27: quit(); return;
	default: return;
	}
	glutPostRedisplay();
}

static void on_special(int key, int x, int y)
{
	double s = v.move_step;

	(void)x;
	(void)y;
	switch (key) {
	case GLUT_KEY_UP: fly_camera_move(&v.cam, 0, 0, s); break;
	case GLUT_KEY_DOWN: fly_camera_move(&v.cam, 0, 0, -s); break;
	case GLUT_KEY_LEFT: fly_camera_move(&v.cam, -s, 0, 0); break;
	case GLUT_KEY_RIGHT: fly_camera_move(&v.cam, s, 0, 0); break;
	case GLUT_KEY_PAGE_UP: fly_camera_move(&v.cam, 0, s, 0); break;
	case GLUT_KEY_PAGE_DOWN: fly_camera_move(&v.cam, 0, -s, 0); break;
	default: return;
	}
	glutPostRedisplay();
}

/* SIGINT, SIGTERM or SIGHUP: the signal, for on_signal_poll. */
static volatile sig_atomic_t viewer_signal;
/* The exit status once the main loop has returned: 128 + the signal. */
static int viewer_status;

static void on_signal(int sig)
{
	viewer_signal = sig;
}

/* Polled by a timer: after a signal, the capture in progress is cancelled
 * and joined (its unfinished capture-N.png removed) and the viewer quits
 * with 128 + the signal, as whitted does. */
static void on_signal_poll(int value)
{
	struct diag d;

	(void)value;
	if (!viewer_signal) {
		glutTimerFunc(VIEW_POLL_MS, on_signal_poll, 0);
		return;
	}
	if (v.capture.running) {
		capture_cancel(&v.capture);
		capture_join(&v.capture, &d);
	}
	viewer_status = 128 + (int)viewer_signal;
	glutLeaveMainLoop();
}

static void catch_signals(void)
{
	struct sigaction sa;

	memset(&sa, 0, sizeof(sa));
	sa.sa_handler = on_signal;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	sigaction(SIGHUP, &sa, NULL);
	glutTimerFunc(VIEW_POLL_MS, on_signal_poll, 0);
}

/* freeglut's fatal errors (no display to open): one line of ours, then
 * the exit freeglut would have made. */
static void on_glut_error(const char *fmt, va_list ap)
{
	char why[256];

	vsnprintf(why, sizeof(why), fmt, ap);
	fprintf(stderr, "%s: error: %s (whitted-view needs an X display: run it on a desktop, "
		"or under xvfb-run; whitted renders without one)\n", tool_name(), why);
	scene_destroy(v.scene);
	exit(TOOL_EXIT_FAILURE);
}

static void on_close(void)
{
	struct diag d;

	if (v.capture.running) {
		capture_cancel(&v.capture);
		capture_join(&v.capture, &d);
	}
}

/* Loads the scene and sets up the camera before any window opens, so that
 * a bad file or option fails like whitted does. */
static int load(void)
{
	struct camera cam;
	struct aabb box;
	struct diag d;
	int rc;

	diag_clear(&d);
	rc = cli_scene_load(&v.opts, v.scene_path, tool_print_note, &v.opts.quiet, &v.scene, &cam, &d);
	if (rc < 0) {
		tool_print_diag(&d, "error");
		return rc == -RT_E_INVALID ? TOOL_EXIT_USAGE : TOOL_EXIT_FAILURE;
	}
	if (scene_prepare(v.scene, v.threads, &d) < 0 || fly_camera_init(&v.cam, &v.opts.camera, &d) < 0) {
		tool_print_diag(&d, "error");
		return TOOL_EXIT_FAILURE;
	}
	v.home = v.cam;
	box = draw_scene_box(v.scene);
	/* About 50 steps across the scene. */
	v.move_step = v.home_move_step = vec3_length(vec3_sub(box.max, box.min)) / 50.0;
	v.turn_deg = 3.0;
	v.next_capture = 1;
	return 0;
}

int main(int argc, char **argv)
{
	char *glut_argv[] = { argv[0], NULL };
	int glut_argc = 1, status;
	struct diag d;

	tool_set_name("whitted-view");
	if ((status = parse_args(argc, argv)) != 0 || (status = load()) != 0) {
		scene_destroy(v.scene);
		return status;
	}
	/* GLUT sees no arguments of ours; the display comes from DISPLAY. */
	if (!getenv("DISPLAY") || !getenv("DISPLAY")[0]) {
		fprintf(stderr, "%s: error: no display: DISPLAY is not set (whitted-view needs an X "
			"display: run it on a desktop, or under xvfb-run; whitted renders without "
			"one)\n", tool_name());
		scene_destroy(v.scene);
		return TOOL_EXIT_FAILURE;
	}
	glutInitErrorFunc(on_glut_error);
	glutInit(&glut_argc, glut_argv);
	glutSetOption(GLUT_ACTION_ON_WINDOW_CLOSE, GLUT_ACTION_GLUTMAINLOOP_RETURNS);
	glutInitDisplayMode(GLUT_RGB | GLUT_DOUBLE | GLUT_DEPTH);
	glutInitWindowSize(VIEW_WINDOW_SIZE, VIEW_WINDOW_SIZE);
	v.width = v.height = VIEW_WINDOW_SIZE;
	glutCreateWindow("whitted");
	set_title(NULL);
	diag_clear(&d);
	if (draw_init(&v.draw, v.scene, tool_print_note, &v.opts.quiet, &d) < 0) {
		tool_print_diag(&d, "error");
		scene_destroy(v.scene);
		return TOOL_EXIT_FAILURE;
	}
	glutDisplayFunc(on_display);
	glutReshapeFunc(on_reshape);
	glutKeyboardFunc(on_key);
	glutSpecialFunc(on_special);
	glutCloseFunc(on_close);
	catch_signals();
	fprintf(stderr, "whitted-view: %s, %zu objects, %zu lights; press h for the keys\n",
		v.scene_name, scene_shape_count(v.scene), scene_light_count(v.scene));
	glutMainLoop();
	scene_destroy(v.scene);
	return viewer_status;
}
