/* Option values and scene options shared by the command-line tools. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/platform.h"
#include "cli/plugin_opts.h"
#include "cli/scene_opts.h"
#include "cli/tool.h"

/* 2^40, or LONG_MAX where long has 32 bits (Windows). */
#define CLI_GLASS_INDEX_MAX ((long)(LONG_MAX > (1LL << 40) ? (1LL << 40) : LONG_MAX))

const char cli_scene_help[] =
	"  -s, --size N           image size in pixels (N x N), overriding the file's\n"
	"  -r, --recursion N      recursion level (1 = no reflections), overriding the file's\n"
	"      --eye X,Y,Z        camera position             (default 0,-200,10)\n"
	"      --look X,Y,Z       point the camera looks at   (default 0,0,0)\n"
	"      --up X,Y,Z         camera up direction         (default 0,0,1)\n"
	"      --fov DEGREES      vertical field of view      (default 80; pyramid\n"
	"                         files 90; nearfar files their FOVY)\n"
	"      --floor WIDTH,TILE checkerboard floor size and tile width (default 1000,20;\n"
	"                         pyramid files 1000,30; nearfar files their own,\n"
	"                         infinite)\n"
	"      --no-floor         leave the floor out\n"
	"      --dialect auto|classic|spot|pyramid|nearfar  read SCENE as that dialect\n"
	"                         of the course format (default auto: detected)\n"
	"      --lenient          read SCENE as the course's count-driven programs do:\n"
	"                         numbers after the last section that no count\n"
	"                         describes are ignored with a note, not refused\n"
	"      --clamp level|final  clamp colours at every reflection level (default)\n"
	"                         or only the finished pixel, as POV-Ray does\n"
	"      --samples N        antialiasing: an N x N grid of rays in each pixel,\n"
	"                         averaged (default 1: one ray through its centre)\n"
	"      --floor-texture WHITE[,BLACK]  a PNG or BMP image over each white cell\n"
	"                         of the floor (and one over each black cell; ',BLACK'\n"
	"                         for the black ones only): the texel is the cell's colour\n"
	"      --glass INDEX[:IOR[:KT]][,...]  make object INDEX (1-based, in the file's\n"
	"                         order) glass: index of refraction IOR (default 1.5),\n"
	"                         transmission KT in (0, 1) (default 0.8); repeatable\n"
	"      --max-scene-size SIZE  the largest scene file read, in bytes or with K,\n"
	"                         M, G or T (default an eighth of the memory the\n"
	"                         process may use, at least 256M)\n"
	"      --test-scene       the assignment's built-in test scene instead of a file\n"
	"      --plugin FILE.so   load a primitive plugin (repeatable); every .so in the\n"
	"                         directories of $WHITTED_PLUGIN_PATH (colon-separated)\n"
	"                         is loaded too\n"
	"  -q, --quiet            no notes on stderr\n";

void cli_scene_init(struct cli_scene *o)
{
	struct scene_view view;

	memset(o, 0, sizeof(*o));
	camera_params_default(&o->camera);
	o->floor_width = RT_FLOOR_WIDTH;
	o->floor_tile = RT_FLOOR_TILE;
	scene_view_default(&view);
	o->floor_mat = view.floor_mat;
	o->clamp = RT_CLAMP_LEVEL;
	o->samples = 1;
	o->read.threads = cli_default_threads();
}

static int cli_parse_vec3(const char *opt, const char *arg, struct vec3 *out, struct diag *d)
{
	double v[3];
	int rc = number_parse_list(opt, arg, v, 3, d);

	if (rc == 0)
		*out = vec3_make(v[0], v[1], v[2]);
	return rc;
}

/* --dialect's word: a dialect's name (scene.h's table). */
static int cli_parse_dialect(const char *arg, enum scene_dialect *out, struct diag *d)
{
	int found = scene_dialect_from_name(arg);
	char names[80];

	if (found >= 0) {
		*out = (enum scene_dialect)found;
		return 0;
	}
	return diag_fail(d, RT_E_INVALID, "--dialect: expected %s, found '%s'",
			 scene_dialect_names(names, sizeof(names)), arg);
}

/* A size in bytes: digits and an optional K, M, G or T (powers of 1024),
 * at least 1. */
static int cli_parse_bytes(const char *opt, const char *arg, size_t *out, struct diag *d)
{
	static const char units[] = "KMGT";
	unsigned long long n = 0, scale = 1;
	const char *p = arg, *u;

	while (*p >= '0' && *p <= '9' && n <= ULLONG_MAX / 10 - 1)
		n = n * 10 + (unsigned long long)(*p++ - '0');
	if (*p && (u = strchr(units, *p)) != NULL && p[1] == '\0') {
		scale = 1ULL << (10 * (u - units + 1));
		p++;
	}
	if (p == arg || *p || n == 0 || n > (unsigned long long)(SIZE_MAX / 2) / scale)
		return diag_fail(d, RT_E_INVALID, "%s: expected a size in bytes, or with K, M, G "
				 "or T (512M, 2G), at most half the address space, found '%s'", opt, arg);
	*out = (size_t)(n * scale);
	return 0;
}

/* "WHITE[,BLACK]": either may be empty, not both; at most one comma. */
static int cli_parse_floor_texture(struct cli_scene *o, const char *arg, struct diag *d)
{
	char *buf = o->floor_texture_arg, *comma;

	if (strlen(arg) >= sizeof(o->floor_texture_arg))
		return diag_fail(d, RT_E_INVALID, "--floor-texture: the file names are too long");
	strcpy(buf, arg);
	comma = strchr(buf, ',');
	if (comma) {
		*comma = '\0';
		if (strchr(comma + 1, ','))
			return diag_fail(d, RT_E_INVALID,
					 "--floor-texture: expected WHITE[,BLACK] (one comma), found '%s'", arg);
	}
	o->floor_texture[0] = buf[0] ? buf : NULL;
	o->floor_texture[1] = comma && comma[1] ? comma + 1 : NULL;
	if (!o->floor_texture[0] && !o->floor_texture[1])
		return diag_fail(d, RT_E_INVALID,
				 "--floor-texture: expected WHITE[,BLACK] image files, found '%s'", arg);
	return 0;
}

/* One "INDEX[:IOR[:KT]]" item (NUL-terminated, cut from the list). */
static int cli_parse_glass_item(struct cli_scene *o, char *item, struct diag *d)
{
	struct cli_glass *g = &o->glass[o->n_glass];
	char *ior = strchr(item, ':'), *kt = NULL;
	int rc, i;

	if (o->n_glass == CLI_MAX_GLASS)
		return diag_fail(d, RT_E_INVALID, "--glass: at most %d objects", CLI_MAX_GLASS);
	if (ior) {
		*ior++ = '\0';
		kt = strchr(ior, ':');
		if (kt)
			*kt++ = '\0';
	}
	g->ior = CLI_GLASS_IOR;
	g->kt = CLI_GLASS_KT;
	if ((rc = number_parse_long("--glass INDEX", item, 1, CLI_GLASS_INDEX_MAX, &g->index, d)) < 0 ||
	    (ior && (rc = number_parse_double("--glass IOR", ior, &g->ior, d)) < 0) ||
	    (kt && (rc = number_parse_double("--glass KT", kt, &g->kt, d)) < 0))
		return rc;
	if (!(g->ior > 0.0 && isfinite(g->ior)))
		return diag_fail(d, RT_E_INVALID, "--glass: IOR must be finite and > 0, found '%s'", ior);
	if (!(g->kt > 0.0 && g->kt < 1.0))
		return diag_fail(d, RT_E_INVALID, "--glass: KT must be in (0, 1), found '%s'", kt);
	for (i = 0; i < o->n_glass; i++)
		if (o->glass[i].index == g->index)
			return diag_fail(d, RT_E_INVALID, "--glass: object %ld is named twice",
					 g->index);
	o->n_glass++;
	return 0;
}

/* The objects in order of index, and the settings text of them: the same
 * for the same glass however the list was ordered. */
static void cli_glass_text(struct cli_scene *o)
{
	char num[3][32];
	size_t len = 0;
	int i, j;

	for (i = 1; i < o->n_glass; i++) {
		struct cli_glass g = o->glass[i];

		for (j = i; j > 0 && o->glass[j - 1].index > g.index; j--)
			o->glass[j] = o->glass[j - 1];
		o->glass[j] = g;
	}
	o->glass_text[0] = '\0';
	for (i = 0; i < o->n_glass; i++) {
		snprintf(num[0], sizeof(num[0]), "%ld", o->glass[i].index);
		number_format_shortest(num[1], sizeof(num[1]), o->glass[i].ior);
		number_format_shortest(num[2], sizeof(num[2]), o->glass[i].kt);
		snprintf(o->glass_text + len, sizeof(o->glass_text) - len, "%s%s:%s:%s",
			 len ? "," : "", num[0], num[1], num[2]);
		len = strlen(o->glass_text);
	}
}

/* "INDEX[:IOR[:KT]][,INDEX...]". */
static int cli_parse_glass(struct cli_scene *o, const char *arg, struct diag *d)
{
	char buf[1024], *item = buf, *comma;
	int rc;

	if (strlen(arg) >= sizeof(buf))
		return diag_fail(d, RT_E_INVALID, "--glass: the list is too long");
	strcpy(buf, arg);
	for (;;) {
		comma = strchr(item, ',');
		if (comma)
			*comma = '\0';
		if ((rc = cli_parse_glass_item(o, item, d)) < 0)
			return rc;
		if (!comma) {
			cli_glass_text(o);
			return 0;
		}
		item = comma + 1;
	}
}

int cli_scene_option_or_usage(struct cli_scene *o, int c, const char *arg, char **argv,
			      const struct option *longopts)
{
	struct diag d;
	int rc;

	diag_clear(&d);
	rc = c == '?' ? 0 : cli_scene_option(o, c, arg, &d);
	if (rc < 0)
		return tool_usage_error("%s", d.msg);
	if (rc == 0)
		return tool_unknown_option(argv[optind - 1], longopts);
	return 0;
}

/* Long: the shared options' one switch, a case of two or three lines each. */
int cli_scene_option(struct cli_scene *o, int opt, const char *arg, struct diag *d)
{
	double v[2];
	long n;
	int rc = 0;

	switch (opt) {
	case 's':
		rc = number_parse_long("--size", arg, 1, RT_MAX_IMAGE_SIZE, &n, d);
		if (rc == 0 && n * n > RT_MAX_PIXELS)
			rc = diag_fail(d, RT_E_INVALID, "--size: %ld x %ld is more than %ld pixels",
				      n, n, RT_MAX_PIXELS);
		o->size = (int)n;
		break;
	case 'r':
		rc = number_parse_long("--recursion", arg, 1, RT_MAX_RECURSION, &n, d);
		o->recursion = (int)n;
		break;
	case 'q':
		o->quiet = true;
		break;
	case CLI_OPT_EYE:
		o->camera_given = true;
		rc = cli_parse_vec3("--eye", arg, &o->camera.eye, d);
		break;
	case CLI_OPT_LOOK:
		o->camera_given = true;
		rc = cli_parse_vec3("--look", arg, &o->camera.look, d);
		break;
	case CLI_OPT_UP:
		o->camera_given = true;
		rc = cli_parse_vec3("--up", arg, &o->camera.up, d);
		break;
	case CLI_OPT_FOV:
		o->fov_given = true;
		rc = number_parse_double("--fov", arg, &o->camera.fov_deg, d);
		if (rc == 0 && !(o->camera.fov_deg > 0.0 && o->camera.fov_deg < 180.0))
			rc = diag_fail(d, RT_E_INVALID,
				      "--fov: expected degrees between 0 and 180 (exclusive), found '%s'", arg);
		break;
	case CLI_OPT_FLOOR:
		rc = number_parse_list("--floor", arg, v, 2, d);
		if (rc == 0 && !(v[0] > 0.0 && v[1] > 0.0 && v[0] / v[1] <= 1e9))
			rc = diag_fail(d, RT_E_INVALID,
				      "--floor: WIDTH and TILE must be > 0 (and at most 1e9 tiles across), found '%s'",
				      arg);
		o->floor_width = v[0];
		o->floor_tile = v[1];
		o->floor_given = true;
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
			rc = diag_fail(d, RT_E_INVALID, "--clamp: expected 'level' or 'final', found '%s'",
				      arg);
		break;
	case CLI_OPT_DIALECT:
		rc = cli_parse_dialect(arg, &o->read.dialect, d);
		break;
	case CLI_OPT_SAMPLES:
		rc = number_parse_long("--samples", arg, 1, RT_MAX_SAMPLES, &n, d);
		o->samples = (int)n;
		break;
	case CLI_OPT_FLOOR_TEXTURE:
		rc = cli_parse_floor_texture(o, arg, d);
		break;
	case CLI_OPT_GLASS:
		rc = cli_parse_glass(o, arg, d);
		break;
	case CLI_OPT_TEST_SCENE:
		o->test_scene = true;
		break;
	case CLI_OPT_LENIENT:
		o->read.lenient = true;
		break;
	case CLI_OPT_MAX_SCENE_SIZE:
		rc = cli_parse_bytes("--max-scene-size", arg, &o->read.max_bytes, d);
		break;
	case CLI_OPT_PLUGIN:
		if (arg[0] == '\0')
			rc = diag_fail(d, RT_E_INVALID, "--plugin: expected a file name, found ''");
		else if (o->n_plugins == CLI_PLUGINS_MAX)
			rc = diag_fail(d, RT_E_INVALID, "--plugin: at most %d plugins", CLI_PLUGINS_MAX);
		else
			o->plugins[o->n_plugins++] = arg;
		break;
	default:
		return 0;
	}
	return rc < 0 ? rc : 1;
}

/* The camera and the floor: the options where given, else the file's. */
static void cli_scene_resolve(struct cli_scene *o, const struct scene_view *v)
{
	if (!o->fov_given)
		o->camera.fov_deg = v->fov_deg;
	o->camera.near = v->near;
	o->camera.aspect = v->aspect;
	if (!o->floor_given) {
		o->floor_width = v->floor_width;
		o->floor_tile = v->floor_cell;
	}
	o->floor_mat = v->floor_mat;
}

/* Long: the load's steps in order (plugins, the file, the overrides, the
 * floor, the camera), each failing to one exit. */
int cli_scene_load(struct cli_scene *o, const char *path, diag_note_fn *note, void *note_ctx,
		   struct scene **out, struct camera *cam, struct diag *d)
{
	struct scene *s = NULL;
	int rc, i;

	*out = NULL;
	if ((rc = cli_plugins_load(o->plugins, o->n_plugins, note, note_ctx, d)) < 0)
		return rc;
	rc = path ? scene_load(path, &o->read, note, note_ctx, &s, d) : scene_test_scene(&s, d);
	if (rc < 0)
		return rc;
	if ((o->size && (rc = scene_set_image_size(s, o->size, d)) < 0) ||
	    (o->recursion && (rc = scene_set_recursion(s, o->recursion, d)) < 0))
		goto out_destroy;
	for (i = 0; i < o->n_glass; i++) {
		const struct shape *sh;

		if ((rc = scene_set_glass(s, (size_t)(o->glass[i].index - 1), o->glass[i].ior,
					  o->glass[i].kt, d)) < 0)
			goto out_destroy;
		/* Glass is entered at one hit and left at the next on it: what
		 * is not a solid (a triangle, an open quadric) bends rays that
		 * never come out, as no real object does. */
		sh = scene_shape(s, (size_t)(o->glass[i].index - 1));
		if (note && !shape_closed(sh)) {
			struct diag n;

			diag_set(&n, RT_OK, path ? path : "", 0, 0,
				 "object %ld (%s) is not a closed solid: refraction through it "
				 "is only approximate", o->glass[i].index, sh->ops->keyword);
			note(note_ctx, &n);
		}
	}
	cli_scene_resolve(o, scene_view_of(s));
	if (o->no_floor && (o->floor_texture[0] || o->floor_texture[1])) {
		rc = diag_fail(d, RT_E_INVALID, "--floor-texture needs the floor, but --no-floor leaves it out");
		goto out_destroy;
	}
	if (!o->no_floor) {
		/* --floor resizes the file's floor: its finish stays the dialect's. */
		if (o->floor_given || o->floor_texture[0] || o->floor_texture[1]) {
			struct scene_view v = *scene_view_of(s);

			if (o->floor_given) {
				v.floor_width = o->floor_width;
				v.floor_cell = o->floor_tile;
			}
			v.floor_texture[0] = o->floor_texture[0];
			v.floor_texture[1] = o->floor_texture[1];
			scene_set_view(s, &v);
		}
		if ((rc = scene_add_view_floor(s, d)) < 0)
			goto out_destroy;
	}
	if ((rc = camera_init(cam, &o->camera, scene_image_size(s), d)) < 0)
		goto out_destroy;
	*out = s;
	return 0;
out_destroy:
	scene_destroy(s);
	return rc;
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
	int n = rt_cpu_count();

	return n > 64 ? 64 : n;
}

static void cli_note_other_option(struct cli_scene *scene, int c, const char *name)
{
	if (scene->other_option[0] || c == '?' || c == 'q' ||
	    (name && (strcmp(name, "plugin") == 0 || strcmp(name, "list-shapes") == 0 ||
		      strcmp(name, "quiet") == 0)))
		return;
	if (name)
		snprintf(scene->other_option, sizeof(scene->other_option), "--%s", name);
	else
		snprintf(scene->other_option, sizeof(scene->other_option), "-%c", c);
}

int cli_parse_options(int argc, char **argv, const char *shortopts,
		      const struct option *longopts, struct cli_scene *scene,
		      cli_option_fn *own, void *ctx)
{
	struct diag d;
	int c, rc;

	int at = -1;

	opterr = 0;
	while ((c = getopt_long(argc, argv, shortopts, longopts, &at)) != -1) {
		if (c == ':')
			return tool_usage_error("option '%s' needs a value", argv[optind - 1]);
		cli_note_other_option(scene, c, at >= 0 ? longopts[at].name : NULL);
		at = -1;
		/* The tool's own handler comes first, so that it can refuse a
		 * shared option's value (scene2pov and --clamp level). */
		rc = c == '?' ? -1 : own(ctx, c, optarg);
		if (rc > 0)
			return rc;
		if (rc == 0)
			continue;
		if ((rc = cli_scene_option_or_usage(scene, c, optarg, argv, longopts)) != 0)
			return rc;
	}
	if (cli_scene_operand(scene, argc, argv, optind, &scene->path, &d) < 0)
		return tool_usage_error("%s", d.msg);
	return 0;
}
