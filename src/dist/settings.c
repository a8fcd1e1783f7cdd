/* The pixel-affecting settings as one table.  Each row is one setting: its
 * key, which names it in the canonical text (key=value) and on the command
 * line (--key value, and --no-key for the value "none"), the part of the
 * command it belongs to (none, for what the scene file decides), whether
 * the command may leave out its built-in default, the function that writes
 * its value, and whether a row that classic settings never had is in the
 * canonical text.  settings_format and settings_format_options are two
 * walks over the rows, so a row added is in both. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/number.h"
#include "base/text.h"
#include "whitted/diag.h"
#include "whitted/scene.h"
#include "whitted/settings.h"

/* Room for one value: three 17-digit numbers with exponents and commas,
 * --floor-texture's two paths and --glass's list (their CLI buffers), or
 * the plugins' record. */
#define SETTINGS_VALUE_MAX 4096

void settings_init(struct settings *s)
{
	struct scene_view classic;

	memset(s, 0, sizeof(*s));
	camera_params_default(&s->camera);
	scene_view_default(&classic);
	s->floor = true;
	s->floor_width = classic.floor_width;
	s->floor_tile = classic.floor_cell;
	s->floor_mat = classic.floor_mat;
	s->floor_from_view = true;
	s->clamp = RT_CLAMP_LEVEL;
	s->samples = 1;
}

/* The classic floor's coefficients, which the canonical text leaves out. */
static bool settings_floor_classic(const struct settings *s)
{
	const struct material *m = &s->floor_mat;
	struct scene_view classic;

	scene_view_default(&classic);
	return m->ka == classic.floor_mat.ka && m->kd == classic.floor_mat.kd &&
	       m->ks == classic.floor_mat.ks && m->kr == classic.floor_mat.kr &&
	       m->shininess == classic.floor_mat.shininess;
}

static void settings_vec3(char *buf, size_t size, struct vec3 v)
{
	char x[32], y[32], z[32];

	number_format_shortest(x, sizeof(x), v.x);
	number_format_shortest(y, sizeof(y), v.y);
	number_format_shortest(z, sizeof(z), v.z);
	snprintf(buf, size, "%s,%s,%s", x, y, z);
}

typedef void settings_value_fn(const struct settings *s, char *buf, size_t size);

static void settings_size(const struct settings *s, char *buf, size_t size)
{
	snprintf(buf, size, "%d", s->size);
}

static void settings_recursion(const struct settings *s, char *buf, size_t size)
{
	snprintf(buf, size, "%d", s->recursion);
}

static void settings_eye(const struct settings *s, char *buf, size_t size)
{
	settings_vec3(buf, size, s->camera.eye);
}

static void settings_look(const struct settings *s, char *buf, size_t size)
{
	settings_vec3(buf, size, s->camera.look);
}

static void settings_up(const struct settings *s, char *buf, size_t size)
{
	settings_vec3(buf, size, s->camera.up);
}

static void settings_fov(const struct settings *s, char *buf, size_t size)
{
	number_format_shortest(buf, size, s->camera.fov_deg);
}

static void settings_near(const struct settings *s, char *buf, size_t size)
{
	number_format_shortest(buf, size, s->camera.near);
}

static void settings_aspect(const struct settings *s, char *buf, size_t size)
{
	number_format_shortest(buf, size, s->camera.aspect);
}

static void settings_floor_finish(const struct settings *s, char *buf, size_t size)
{
	const struct material *m = &s->floor_mat;
	char v[5][32];

	number_format_shortest(v[0], sizeof(v[0]), m->ka);
	number_format_shortest(v[1], sizeof(v[1]), m->kd);
	number_format_shortest(v[2], sizeof(v[2]), m->ks);
	number_format_shortest(v[3], sizeof(v[3]), m->kr);
	number_format_shortest(v[4], sizeof(v[4]), m->shininess);
	snprintf(buf, size, "%s,%s,%s,%s,%s", v[0], v[1], v[2], v[3], v[4]);
}

static void settings_dialect(const struct settings *s, char *buf, size_t size)
{
	snprintf(buf, size, "%s", scene_dialect_name(s->dialect));
}

static void settings_samples(const struct settings *s, char *buf, size_t size)
{
	snprintf(buf, size, "%d", s->samples);
}

static bool settings_has_samples(const struct settings *s)
{
	return s->samples != 1;
}

static void settings_floor_texture(const struct settings *s, char *buf, size_t size)
{
	snprintf(buf, size, "%s%s%s", s->floor_texture[0] ? s->floor_texture[0] : "",
		 s->floor_texture[1] ? "," : "", s->floor_texture[1] ? s->floor_texture[1] : "");
}

static bool settings_has_floor_texture(const struct settings *s)
{
	return s->floor && (s->floor_texture[0] || s->floor_texture[1]);
}

/* The images' contents, in the canonical text only: a texture changed
 * under the same name is another setting, which no option says. */
static void settings_floor_texture_hash(const struct settings *s, char *buf, size_t size)
{
	snprintf(buf, size, "%016llx", (unsigned long long)s->floor_texture_hash);
}

static void settings_glass(const struct settings *s, char *buf, size_t size)
{
	snprintf(buf, size, "%s", s->glass ? s->glass : "");
}

static bool settings_has_glass(const struct settings *s)
{
	return s->glass && s->glass[0];
}

static bool settings_has_dialect(const struct settings *s)
{
	return s->dialect != RT_DIALECT_AUTO;
}

static void settings_plugins(const struct settings *s, char *buf, size_t size)
{
	snprintf(buf, size, "%s", s->plugins);
}

static bool settings_has_plugins(const struct settings *s)
{
	return s->plugins && s->plugins[0];
}

static bool settings_has_near(const struct settings *s)
{
	return s->camera.near != 0.0;
}

static bool settings_has_aspect(const struct settings *s)
{
	return s->camera.aspect != 0.0;
}

static bool settings_has_floor_finish(const struct settings *s)
{
	return s->floor && !settings_floor_classic(s);
}

static void settings_floor(const struct settings *s, char *buf, size_t size)
{
	char w[32], t[32];

	if (!s->floor) {
		snprintf(buf, size, "none");
		return;
	}
	number_format_shortest(w, sizeof(w), s->floor_width);
	number_format_shortest(t, sizeof(t), s->floor_tile);
	snprintf(buf, size, "%s,%s", w, t);
}

static void settings_clamp(const struct settings *s, char *buf, size_t size)
{
	snprintf(buf, size, "%s", s->clamp == RT_CLAMP_FINAL ? "final" : "level");
}

/* The floor's option (see settings_option_fn).  --floor W,T makes a finite
 * floor of the classic coefficients, which every view but nearfar's gives:
 * such a floor is written as --floor W,T (but for the built-in 1000,20
 * when it is the view's, as always); the infinite floor, or one of other
 * coefficients, is left to the scene file when it is the view's. */
static int settings_floor_option(const struct settings *s, const char *value,
				 const char *fallback)
{
	bool expressible = s->floor_width != INFINITY && settings_floor_classic(s);

	if (!s->floor)
		return 0;
	if (s->floor_from_view)
		return !expressible || strcmp(value, fallback) == 0;
	/* --floor keeps the file's finish, so it says any finite floor. */
	return s->floor_width != INFINITY ? 0 : -1;
}

/* The command names the view first and the image's options after it, the
 * order in which whitted-view has always printed them.  What the scene
 * file decides (nearfar's near plane, aspect and floor finish) is in the
 * canonical text only: no option sets it, and whitted reading the same
 * file gets it again. */
enum settings_part {
	SETTINGS_VIEW,
	SETTINGS_IMAGE,
	SETTINGS_FILE,
};

typedef bool settings_present_fn(const struct settings *s);
/* Whether the command carries the row's option: 1 leaves it out, 0 writes
 * value (the row's text; fallback is the built-in default's), -1 when no
 * option can say it. */
typedef int settings_option_fn(const struct settings *s, const char *value,
			       const char *fallback);

struct settings_field {
	const char *key;
	enum settings_part part;
	bool omit_default;	/* the command leaves out the built-in default */
	settings_value_fn *value;
	settings_present_fn *present;	/* NULL: always in the canonical text */
	settings_option_fn *option;	/* NULL: as omit_default says */
	/* The value is a path (or paths): the command quotes it for the shell,
	 * and "none" is then a file's name, not --no-KEY. */
	bool path;
};

/* In the order of the canonical text, which tiles already on disk fix;
 * rows that classic settings leave out may go anywhere. */
static const struct settings_field settings_fields[] = {
	{ "size", SETTINGS_IMAGE, false, settings_size, NULL, NULL, false },
	{ "recursion", SETTINGS_IMAGE, false, settings_recursion, NULL, NULL, false },
	{ "eye", SETTINGS_VIEW, false, settings_eye, NULL, NULL, false },
	{ "look", SETTINGS_VIEW, false, settings_look, NULL, NULL, false },
	{ "up", SETTINGS_VIEW, false, settings_up, NULL, NULL, false },
	{ "fov", SETTINGS_VIEW, false, settings_fov, NULL, NULL, false },
	{ "near", SETTINGS_FILE, false, settings_near, settings_has_near, NULL, false },
	{ "aspect", SETTINGS_FILE, false, settings_aspect, settings_has_aspect, NULL, false },
	{ "floor", SETTINGS_IMAGE, true, settings_floor, NULL, settings_floor_option, false },
	{ "floor-finish", SETTINGS_FILE, false, settings_floor_finish, settings_has_floor_finish,
	  NULL, false },
	{ "clamp", SETTINGS_IMAGE, true, settings_clamp, NULL, NULL, false },
	/* The command carries a forced dialect itself (whitted-view prints
	 * its --dialect beside SCENE). */
	{ "dialect", SETTINGS_FILE, false, settings_dialect, settings_has_dialect, NULL, false },
	{ "samples", SETTINGS_IMAGE, true, settings_samples, settings_has_samples, NULL, false },
	{ "floor-texture", SETTINGS_IMAGE, true, settings_floor_texture, settings_has_floor_texture,
	  NULL, true },
	{ "floor-texture-hash", SETTINGS_FILE, false, settings_floor_texture_hash,
	  settings_has_floor_texture, NULL, false },
	{ "glass", SETTINGS_IMAGE, true, settings_glass, settings_has_glass, NULL, false },
	/* The command's --plugin options are the program's to print. */
	{ "plugins", SETTINGS_FILE, false, settings_plugins, settings_has_plugins, NULL, false },
};

#define SETTINGS_FIELDS (sizeof(settings_fields) / sizeof(settings_fields[0]))

void settings_format(const struct settings *s, char *buf, size_t size)
{
	struct text_buf o;
	char value[SETTINGS_VALUE_MAX];
	size_t i;

	if (size == 0)
		return;
	text_init(&o, buf, size);
	for (i = 0; i < SETTINGS_FIELDS; i++) {
		if (settings_fields[i].present && !settings_fields[i].present(s))
			continue;
		settings_fields[i].value(s, value, sizeof(value));
		text_printf(&o, "%s%s=%s", i ? " " : "", settings_fields[i].key, value);
	}
}

int settings_format_options(const struct settings *s, char *buf, size_t size)
{
	static const enum settings_part parts[] = { SETTINGS_VIEW, SETTINGS_IMAGE };
	struct text_buf o;
	char value[SETTINGS_VALUE_MAX], fallback[SETTINGS_VALUE_MAX];
	struct settings defaults;
	size_t p, i;

	if (size == 0)
		return -RT_E_RANGE;
	text_init(&o, buf, size);
	settings_init(&defaults);
	for (p = 0; p < sizeof(parts) / sizeof(parts[0]); p++) {
		for (i = 0; i < SETTINGS_FIELDS; i++) {
			const struct settings_field *f = &settings_fields[i];

			if (f->part != parts[p])
				continue;
			f->value(s, value, sizeof(value));
			if (f->omit_default) {
				int leave;

				f->value(&defaults, fallback, sizeof(fallback));
				leave = f->option ? f->option(s, value, fallback)
						  : strcmp(value, fallback) == 0;
				if (leave < 0)
					return -RT_E_INVALID;
				if (leave)
					continue;
			}
			if (f->path) {
				text_printf(&o, " --%s ", f->key);
				text_shell_word(&o, value);
			} else if (strcmp(value, "none") == 0) {
				text_printf(&o, " --no-%s", f->key);
			} else {
				text_printf(&o, " --%s %s", f->key, value);
			}
		}
	}
	return o.full ? -RT_E_RANGE : 0;
}
