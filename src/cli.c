/* Option values and scene options shared by the command-line tools. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"

const char cli_scene_help[] =
	"  -s, --size N           image size in pixels (N x N), overriding the file's\n"
	"  -r, --recursion N      recursion level (1 = no reflections), overriding the file's\n"
	"      --eye X,Y,Z        camera position             (default 0,-200,10)\n"
	"      --look X,Y,Z       point the camera looks at   (default 0,0,0)\n"
	"      --up X,Y,Z         camera up direction         (default 0,0,1)\n"
	"      --fov DEGREES      vertical field of view      (default 80)\n"
	"      --floor WIDTH,TILE checkerboard floor size and tile width (default 1000,20)\n"
	"      --no-floor         leave the floor out\n"
	"      --clamp level|final  clamp colours at every reflection level (default)\n"
	"                         or only the finished pixel, as POV-Ray does\n"
	"      --test-scene       the assignment's built-in test scene instead of a file\n"
	"  -q, --quiet            no notes on stderr\n";

void cli_scene_init(struct cli_scene *o)
{
	memset(o, 0, sizeof(*o));
	camera_params_default(&o->camera);
	o->floor_width = RT_FLOOR_WIDTH;
	o->floor_tile = RT_FLOOR_TILE;
	o->clamp = RT_CLAMP_LEVEL;
	o->read.threads = cli_default_threads();
}

int cli_parse_double(const char *opt, const char *arg, double *out, struct diag *d)
{
	char *end;
	double v;

	errno = 0;
	v = strtod(arg, &end);
	if (end == arg || *end != '\0' || !isfinite(v) || arg[strspn(arg, "0123456789+-.eE")] != '\0')
		return diag_set(d, RT_E_INVALID, "", 0, 0, "%s: expected a finite number, found '%s'",
				opt, arg);
	*out = v;
	return 0;
}

int cli_parse_long(const char *opt, const char *arg, long lo, long hi, long *out, struct diag *d)
{
	char *end;
	long v;

	errno = 0;
	v = strtol(arg, &end, 10);
	if (end == arg || *end != '\0' || errno == ERANGE || v < lo || v > hi ||
	    arg[strspn(arg, "0123456789+-")] != '\0')
		return diag_set(d, RT_E_INVALID, "", 0, 0,
				"%s: expected an integer from %ld to %ld, found '%s'", opt, lo, hi, arg);
	*out = v;
	return 0;
}

int cli_parse_list(const char *opt, const char *arg, double *out, int n, struct diag *d)
{
	char buf[256];
	char *item = buf;
	int i;

	if (strlen(arg) >= sizeof(buf))
		goto out_bad;
	strcpy(buf, arg);
	for (i = 0; i < n; i++) {
		char *comma = strchr(item, ',');
		if ((comma == NULL) != (i == n - 1))
			goto out_bad;
		if (comma)
			*comma = '\0';
		if (cli_parse_double(opt, item, &out[i], d) < 0)
			goto out_bad;
		item = comma + 1;
	}
	return 0;
out_bad:
	return diag_set(d, RT_E_INVALID, "", 0, 0, "%s: expected %d comma-separated numbers%s, found '%s'",
			opt, n, n == 3 ? " X,Y,Z" : "", arg);
}

static int cli_parse_vec3(const char *opt, const char *arg, struct vec3 *out, struct diag *d)
{
	double v[3];
	int rc = cli_parse_list(opt, arg, v, 3, d);

	if (rc == 0)
		*out = vec3_make(v[0], v[1], v[2]);
	return rc;
}

int cli_scene_option(struct cli_scene *o, int opt, const char *arg, struct diag *d)
{
	double v[2];
	long n;
	int rc = 0;

	switch (opt) {
	case 's':
		rc = cli_parse_long("--size", arg, 1, RT_MAX_IMAGE_SIZE, &n, d);
		if (rc == 0 && n * n > RT_MAX_PIXELS)
			rc = diag_set(d, RT_E_INVALID, "", 0, 0, "--size: %ld x %ld is more than %ld pixels",
				      n, n, RT_MAX_PIXELS);
		o->size = (int)n;
		break;
	case 'r':
		rc = cli_parse_long("--recursion", arg, 1, RT_MAX_RECURSION, &n, d);
		o->recursion = (int)n;
		break;
	case 'q':
		o->quiet = true;
		break;
	case CLI_OPT_EYE:
		rc = cli_parse_vec3("--eye", arg, &o->camera.eye, d);
		break;
	case CLI_OPT_LOOK:
		rc = cli_parse_vec3("--look", arg, &o->camera.look, d);
		break;
	case CLI_OPT_UP:
		rc = cli_parse_vec3("--up", arg, &o->camera.up, d);
		break;
	case CLI_OPT_FOV:
		rc = cli_parse_double("--fov", arg, &o->camera.fov_deg, d);
		if (rc == 0 && !(o->camera.fov_deg > 0.0 && o->camera.fov_deg < 180.0))
			rc = diag_set(d, RT_E_INVALID, "", 0, 0,
				      "--fov: expected degrees between 0 and 180 (exclusive), found '%s'", arg);
		break;
	case CLI_OPT_FLOOR:
		rc = cli_parse_list("--floor", arg, v, 2, d);
		if (rc == 0 && !(v[0] > 0.0 && v[1] > 0.0 && v[0] / v[1] <= 1e9))
			rc = diag_set(d, RT_E_INVALID, "", 0, 0,
				      "--floor: WIDTH and TILE must be > 0 (and at most 1e9 tiles across), found '%s'",
				      arg);
		o->floor_width = v[0];
		o->floor_tile = v[1];
		break;
	case CLI_OPT_NO_FLOOR:
		o->no_floor = true;
		break;
	case CLI_OPT_CLAMP:
		if (strcmp(arg, "level") == 0)
			o->clamp = RT_CLAMP_LEVEL;
		else if (strcmp(arg, "final") == 0)
			o->clamp = RT_CLAMP_FINAL;
		else
			rc = diag_set(d, RT_E_INVALID, "", 0, 0, "--clamp: expected 'level' or 'final', found '%s'",
				      arg);
		break;
	case CLI_OPT_TEST_SCENE:
		o->test_scene = true;
		break;
	default:
		return 0;
	}
	return rc < 0 ? rc : 1;
}

int cli_scene_load(const struct cli_scene *o, const char *path,
		   scene_note_fn *note, void *note_ctx,
		   struct scene **out, struct camera *cam, struct diag *d)
{
	struct scene *s = NULL;
	int rc;

	*out = NULL;
	rc = path ? scene_load(path, &o->read, note, note_ctx, &s, d) : scene_test_scene(&s, d);
	if (rc < 0)
		return rc;
	if (o->size)
		s->image_size = o->size;
	if (o->recursion)
		s->recursion = o->recursion;
	if (!o->no_floor && (rc = scene_add_floor(s, o->floor_width, o->floor_tile, d)) < 0)
		goto out_destroy;
	if ((rc = camera_init(cam, &o->camera, s->image_size, d)) < 0)
		goto out_destroy;
	*out = s;
	return 0;
out_destroy:
	scene_destroy(s);
	return rc;
}

int cli_scene_operand(const struct cli_scene *o, int argc, char **argv, int first,
		      const char **path, struct diag *d)
{
	*path = NULL;
	if (o->test_scene) {
		if (first != argc)
			return diag_set(d, RT_E_INVALID, "", 0, 0,
					"--test-scene takes no SCENE, found '%s'", argv[first]);
		return 0;
	}
	if (first == argc)
		return diag_set(d, RT_E_INVALID, "", 0, 0, "no SCENE given");
	if (first + 1 != argc)
		return diag_set(d, RT_E_INVALID, "", 0, 0, "one SCENE expected, found also '%s'",
				argv[first + 1]);
	*path = argv[first];
	return 0;
}

char *cli_default_output(const char *scene_path, const char *suffix)
{
	const char *base, *dot;
	size_t len;
	char *out;

	if (!scene_path)
		scene_path = "test-scene";
	else if (strcmp(scene_path, "-") == 0)
		scene_path = "stdin";
	base = strrchr(scene_path, '/');
	base = base ? base + 1 : scene_path;
	dot = strrchr(base, '.');
	len = dot && dot != base ? (size_t)(dot - base) : strlen(base);
	out = malloc(len + strlen(suffix) + 1);
	if (out) {
		memcpy(out, base, len);
		strcpy(out + len, suffix);
	}
	return out;
}

int cli_default_threads(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);

	return n < 1 ? 1 : n > 64 ? 64 : (int)n;
}
