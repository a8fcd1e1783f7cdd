/* The settings of --samples, --floor-texture and --glass: each in the
 * canonical text (so that tiles of other values are refused) and in the
 * options, after the rows tiles already on disk fixed, left out at their
 * defaults (so that every earlier text stays byte for byte); the shared
 * option parser's canonical --glass list; and the values the options
 * give read back by that parser into the same text.  The textures'
 * contents are in the text (floor-texture-hash) but in no option. */
#include <string.h>

#include "cli/scene_opts.h"
#include "whitted/settings.h"
#include "support.h"

static const char classic_text[] =
	"size=64 recursion=3 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 floor=1000,20 clamp=level";

static void base(struct settings *s)
{
	support_settings(s, 64, 3);
}

static void test_settings_features_defaults_leave_the_text(void **state)
{
	struct settings s;
	char text[RT_SETTINGS_TEXT_MAX];

	(void)state;
	base(&s);
	assert_int_equal(s.samples, 1);
	settings_format(&s, text, sizeof(text));
	assert_string_equal(text, classic_text);
	s.glass = "";
	settings_format(&s, text, sizeof(text));
	assert_string_equal(text, classic_text);
}

static void test_settings_features_in_the_text(void **state)
{
	struct settings s;
	char text[RT_SETTINGS_TEXT_MAX], options[RT_SETTINGS_TEXT_MAX];

	(void)state;
	base(&s);
	s.samples = 3;
	s.floor_texture[0] = "/t/w.bmp";
	s.floor_texture[1] = "/t/b.png";
	s.floor_texture_hash = UINT64_C(0x0123456789abcdef);
	s.glass = "2:1.5:0.8,4:1.33:0.5";
	settings_format(&s, text, sizeof(text));
	assert_string_equal(text, "size=64 recursion=3 eye=0,-200,10 look=0,0,0 up=0,0,1 fov=80 "
			    "floor=1000,20 clamp=level samples=3 floor-texture=/t/w.bmp,/t/b.png "
			    "floor-texture-hash=0123456789abcdef glass=2:1.5:0.8,4:1.33:0.5");
	assert_int_equal(settings_format_options(&s, options, sizeof(options)), 0);
	assert_string_equal(options, " --eye 0,-200,10 --look 0,0,0 --up 0,0,1 --fov 80 --size 64 "
			    "--recursion 3 --samples 3 --floor-texture /t/w.bmp,/t/b.png "
			    "--glass 2:1.5:0.8,4:1.33:0.5");
	/* Only the black cells' texture; and no texture without a floor. */
	s.floor_texture[0] = NULL;
	settings_format(&s, text, sizeof(text));
	assert_non_null(strstr(text, " floor-texture=,/t/b.png "));
	s.floor = false;
	settings_format(&s, text, sizeof(text));
	assert_null(strstr(text, "floor-texture"));
}

static void test_settings_features_long_paths_fit(void **state)
{
	struct settings s;
	char path[2][2000], text[RT_SETTINGS_TEXT_MAX];

	(void)state;
	base(&s);
	memset(path[0], 'w', sizeof(path[0]) - 1);
	memset(path[1], 'b', sizeof(path[1]) - 1);
	path[0][sizeof(path[0]) - 1] = path[1][sizeof(path[1]) - 1] = '\0';
	s.floor_texture[0] = path[0];
	s.floor_texture[1] = path[1];
	settings_format(&s, text, sizeof(text));
	assert_int_equal(strlen(text), strlen(classic_text) + strlen(" floor-texture=,") + 2 * 1999 +
			 strlen(" floor-texture-hash=0000000000000000"));
}

static void test_settings_features_parsed(void **state)
{
	struct cli_scene o;
	struct diag d;

	(void)state;
	cli_scene_init(&o);
	assert_int_equal(cli_scene_option(&o, CLI_OPT_SAMPLES, "4", &d), 1);
	assert_int_equal(o.samples, 4);
	assert_int_equal(cli_scene_option(&o, CLI_OPT_SAMPLES, "17", &d), -RT_E_INVALID);
	assert_int_equal(cli_scene_option(&o, CLI_OPT_GLASS, "2,3:1.33", &d), 1);
	assert_int_equal(cli_scene_option(&o, CLI_OPT_GLASS, "7:1.6:0.25", &d), 1);
	assert_string_equal(o.glass_text, "2:1.5:0.8,3:1.33:0.8,7:1.6:0.25");
	assert_int_equal(o.n_glass, 3);
	assert_int_equal(o.glass[2].index, 7);
	assert_int_equal(cli_scene_option(&o, CLI_OPT_FLOOR_TEXTURE, "w.bmp,b.png", &d), 1);
	assert_string_equal(o.floor_texture[0], "w.bmp");
	assert_string_equal(o.floor_texture[1], "b.png");
	assert_int_equal(cli_scene_option(&o, CLI_OPT_FLOOR_TEXTURE, ",b.png", &d), 1);
	assert_null(o.floor_texture[0]);
	assert_string_equal(o.floor_texture[1], "b.png");
	assert_int_equal(cli_scene_option(&o, CLI_OPT_FLOOR_TEXTURE, "w.png", &d), 1);
	assert_string_equal(o.floor_texture[0], "w.png");
	assert_null(o.floor_texture[1]);
	assert_int_equal(cli_scene_option(&o, CLI_OPT_FLOOR_TEXTURE, ",", &d), -RT_E_INVALID);
	assert_int_equal(cli_scene_option(&o, CLI_OPT_FLOOR_TEXTURE, "a,b,c", &d), -RT_E_INVALID);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_settings_features_defaults_leave_the_text,
			   test_settings_features_in_the_text,
			   test_settings_features_long_paths_fit, test_settings_features_parsed))
