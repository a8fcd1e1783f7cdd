/* The settings' texts: the canonical text byte for byte as tiles on disk
 * recorded it (the expected strings and hashes are those of tiles written
 * by whitted before the settings module existed), and the command-line
 * options read back by whitted's own option parser into the same
 * settings. */
#include <math.h>
#include <string.h>

#include "base/hash.h"
#include "cli/scene_opts.h"
#include "whitted/settings.h"
#include "support.h"

static uint64_t text_hash(const char *text)
{
	return hash_bytes(RT_HASH_INIT, text, strlen(text));
}

/* The canonical text of s is want, byte for byte, and hashes to hash. */
static void assert_canonical(const struct settings *s, const char *want, uint64_t hash)
{
	char text[RT_SETTINGS_TEXT_MAX];

	settings_format(s, text, sizeof(text));
	assert_string_equal(text, want);
	assert_true(text_hash(text) == hash);
}

static void test_settings_canonical_default(void **state)
{
	struct settings s;

	(void)state;
	support_settings(&s, 768, 4);
	/* docs/distributed.md's example tile. */
	assert_canonical(&s, "size=768 recursion=4 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 "
			     "floor=1000,20 clamp=level",
			     UINT64_C(0x0d6eecfc8023d2fa));
}

/* A forced dialect is a setting: the same text read as another dialect is
 * another scene.  Auto (the default) leaves the text as it was. */
static void test_settings_canonical_dialect(void **state)
{
	struct settings s;
	char text[RT_SETTINGS_TEXT_MAX], options[RT_SETTINGS_TEXT_MAX];

	(void)state;
	support_settings(&s, 768, 4);
	s.dialect = RT_DIALECT_SPOT;
	settings_format(&s, text, sizeof(text));
	assert_string_equal(text, "size=768 recursion=4 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 "
			    "floor=1000,20 clamp=level dialect=spot");
	/* whitted-view carries --dialect beside SCENE, not among these. */
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), 0);
	assert_null(strstr(options, "dialect"));
}

/* Numbers that need 16 and 17 digits, an exponent and a negative zero
 * (and the other clamp). */
static void set_hard_numbers(struct settings *s)
{
	s->camera.eye = vec3_make(0.1, -199.99999999999997, 1e-300);
	s->camera.look = vec3_make(1.0 / 3.0, 2e17, -7.25);
	s->camera.up = vec3_make(-0.0, 0.1 + 0.2, 0.9539392014169456);
	s->camera.fov_deg = 80.00000000000001;
	s->floor_width = 600.5;
	s->floor_tile = 0.1;
	s->clamp = RT_CLAMP_FINAL;
}

static void test_settings_canonical_digits(void **state)
{
	struct settings s;

	(void)state;
	support_settings(&s, 33, 2);
	set_hard_numbers(&s);
	assert_canonical(&s, "size=33 recursion=2 eye=0.1,-199.99999999999997,1e-300 "
			     "look=0.3333333333333333,2e+17,-7.25 "
			     "up=-0,0.30000000000000004,0.9539392014169455 fov=80.00000000000001 "
			     "floor=600.5,0.1 clamp=final",
			     UINT64_C(0xcfa30ec83b7f7519));
}

static void test_settings_canonical_no_floor(void **state)
{
	struct settings s;

	(void)state;
	support_settings(&s, 20, 4);
	s.floor = false;
	assert_canonical(&s, "size=20 recursion=4 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 "
			     "floor=none clamp=level",
			     UINT64_C(0x9ff302fa316485dc));
}

/* The longest numbers fit, and a short buffer is cut, never overrun. */
static void test_settings_canonical_bounds(void **state)
{
	struct settings s;
	char text[RT_SETTINGS_TEXT_MAX], small[16];
	double v = -2.2250738585072014e-308;

	(void)state;
	support_settings(&s, 1000000, 1000);
	s.camera.eye = s.camera.look = s.camera.up = vec3_make(v, v, v);
	s.camera.fov_deg = s.floor_width = s.floor_tile = v;
	settings_format(&s, text, sizeof(text));
	assert_non_null(strstr(text, " clamp=level"));
	assert_true(strlen(text) < sizeof(text) - 100);
	settings_format(&s, small, sizeof(small));
	assert_string_equal(small, "size=1000000 re");
}

/* Reads the options with whitted's parser into the settings they set. */
static void parse_options(const char *options, struct settings *out)
{
	static const struct option longopts[] = { CLI_SCENE_LONG, { NULL, 0, NULL, 0 } };
	char buf[1100], *argv[64], *tok;
	struct cli_scene o;
	int argc = 0, c;
	struct diag d;

	snprintf(buf, sizeof(buf), "whitted%s", options);
	for (tok = strtok(buf, " "); tok; tok = strtok(NULL, " ")) {
		assert_true(argc < 63);
		argv[argc++] = tok;
	}
	argv[argc] = NULL;
	cli_scene_init(&o);
	optind = 0;	/* glibc: start a new scan */
	opterr = 0;
	while ((c = getopt_long(argc, argv, CLI_SCENE_SHORT, longopts, NULL)) != -1)
		assert_int_equal(cli_scene_option(&o, c, optarg, &d), 1);
	assert_int_equal(optind, argc);
	support_settings(out, o.size, o.recursion);
	out->camera = o.camera;
	out->floor = !o.no_floor;
	out->floor_width = o.floor_width;
	out->floor_tile = o.floor_tile;
	out->clamp = o.clamp;
}

static void assert_options_round_trip(const struct settings *s)
{
	char options[1024], a[RT_SETTINGS_TEXT_MAX], b[RT_SETTINGS_TEXT_MAX];
	struct settings back;

	assert_int_equal(settings_format_options(s, options, sizeof(options)), 0);
	parse_options(options, &back);
	settings_format(s, a, sizeof(a));
	settings_format(&back, b, sizeof(b));
	assert_string_equal(a, b);
	assert_memory_equal(&back.camera, &s->camera, sizeof(s->camera));
}

static void test_settings_options_round_trip(void **state)
{
	struct settings s;

	(void)state;
	support_settings(&s, 768, 4);
	assert_options_round_trip(&s);
	set_hard_numbers(&s);
	assert_options_round_trip(&s);
	s.floor = false;
	assert_options_round_trip(&s);
}

static void test_settings_options_text(void **state)
{
	struct settings s;
	char options[512];

	(void)state;
	support_settings(&s, 64, 3);
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), 0);
	/* The view first; the floor and clamping at their defaults left out. */
	assert_string_equal(options, " --eye 0,-200,10 --look 0,0,0 --up 0,0,1 --fov 80 --size 64 "
			    "--recursion 3");
	s.floor_width = 1200;
	s.floor_tile = 25;
	s.clamp = RT_CLAMP_FINAL;
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), 0);
	assert_string_equal(options, " --eye 0,-200,10 --look 0,0,0 --up 0,0,1 --fov 80 --size 64 "
			    "--recursion 3 --floor 1200,25 --clamp final");
	s.floor = false;
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), 0);
	assert_non_null(strstr(options, " --recursion 3 --no-floor --clamp final"));
	assert_int_equal(settings_format_options(&s, options, 20), -RT_E_RANGE);
	assert_int_equal(settings_format_options(&s, options, 0), -RT_E_RANGE);
}

/* The nearfar view's settings: near, aspect, the infinite floor and its
 * finish each in the text; a classic text with any of them at its classic
 * value is the classic text. */
static void nearfar_settings(struct settings *s)
{
	support_settings(s, 768, 3);
	s->camera.fov_deg = 80;
	s->camera.near = 1;
	s->camera.aspect = 1.5;
	s->floor_width = INFINITY;
	s->floor_tile = 50;
	s->floor_mat.ka = 0.1;
	s->floor_mat.kd = 0.3;
	s->floor_mat.ks = 0;
	s->floor_mat.kr = 0.6;
}

static void test_settings_canonical_nearfar(void **state)
{
	struct settings s;
	char text[RT_SETTINGS_TEXT_MAX];

	(void)state;
	nearfar_settings(&s);
	settings_format(&s, text, sizeof(text));
	assert_string_equal(text, "size=768 recursion=3 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 "
			    "near=1 aspect=1.5 floor=inf,50 floor-finish=0.1,0.3,0,0.6,1 clamp=level");
	s.floor = false;
	settings_format(&s, text, sizeof(text));
	assert_string_equal(text, "size=768 recursion=3 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 "
			    "near=1 aspect=1.5 floor=none clamp=level");
	/* Each row apart, and back to the classic text. */
	nearfar_settings(&s);
	s.camera.near = 0;
	s.camera.aspect = 0;
	settings_format(&s, text, sizeof(text));
	assert_string_equal(text, "size=768 recursion=3 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 "
			    "floor=inf,50 floor-finish=0.1,0.3,0,0.6,1 clamp=level");
	s.floor_width = 1000;
	s.floor_tile = 20;
	s.floor_mat.ka = 0.4;
	s.floor_mat.kd = 0.2;
	s.floor_mat.ks = 0.2;
	s.floor_mat.kr = 0.2;
	s.recursion = 4;
	settings_format(&s, text, sizeof(text));
	assert_true(text_hash(text) == UINT64_C(0x0d6eecfc8023d2fa));
	s.floor_mat.shininess = 2;
	settings_format(&s, text, sizeof(text));
	assert_non_null(strstr(text, " floor=1000,20 floor-finish=0.4,0.2,0.2,0.2,2 clamp=level"));
	/* The colour does not shape the floor's pixels (the cells are white
	 * and black): it is not in the text. */
	s.floor_mat.shininess = 1;
	s.floor_mat.color = color_make(0.5, 0.5, 0.5);
	settings_format(&s, text, sizeof(text));
	assert_true(text_hash(text) == UINT64_C(0x0d6eecfc8023d2fa));
}

/* What the file decides is in no option; the view's floor is left to the
 * file unless --floor can say it; a floor only a view can give, chosen
 * otherwise, has no command. */
/* The plugins a scene used are a setting (another build of a plugin may
 * be another image), at the end; none ("" or NULL) leaves the text as it
 * was; no option carries them (the programs print their own --plugin). */
static void test_settings_canonical_plugins(void **state)
{
	struct settings s;
	char text[RT_SETTINGS_TEXT_MAX], options[1024];

	(void)state;
	support_settings(&s, 768, 4);
	s.plugins = "";
	settings_format(&s, text, sizeof(text));
	assert_string_equal(text, "size=768 recursion=4 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 "
			    "floor=1000,20 clamp=level");
	s.plugins = "quad@1.0#0123456789abcdef,torus@1.0#fedcba9876543210";
	settings_format(&s, text, sizeof(text));
	assert_string_equal(text, "size=768 recursion=4 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 "
			    "floor=1000,20 clamp=level "
			    "plugins=quad@1.0#0123456789abcdef,torus@1.0#fedcba9876543210");
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), 0);
	assert_null(strstr(options, "plugin"));
}

static void test_settings_options_nearfar(void **state)
{
	struct settings s;
	char options[512];

	(void)state;
	nearfar_settings(&s);
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), 0);
	assert_string_equal(options, " --eye 0,-200,10 --look 0,0,0 --up 0,0,1 --fov 80 --size 768 "
			    "--recursion 3");
	s.floor = false;
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), 0);
	assert_string_equal(options, " --eye 0,-200,10 --look 0,0,0 --up 0,0,1 --fov 80 --size 768 "
			    "--recursion 3 --no-floor");
	/* --floor 1000,20 given for a nearfar file. */
	support_settings(&s, 8, 1);
	s.camera.near = 1;
	s.floor_from_view = false;
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), 0);
	assert_non_null(strstr(options, " --recursion 1 --floor 1000,20"));
	/* The pyramid view's floor: the same floor as --floor 1000,30 makes. */
	s.floor_from_view = true;
	s.floor_tile = 30;
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), 0);
	assert_non_null(strstr(options, " --recursion 1 --floor 1000,30"));
	nearfar_settings(&s);
	s.floor_from_view = false;
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), -RT_E_INVALID);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_settings_canonical_default, test_settings_canonical_dialect,
			   test_settings_canonical_digits, test_settings_canonical_no_floor,
			   test_settings_canonical_bounds, test_settings_options_round_trip,
			   test_settings_options_text, test_settings_canonical_nearfar,
			   test_settings_options_nearfar, test_settings_canonical_plugins))
