/* The capture's command: whitted's own option parsing reads it back into
 * bit-identical camera parameters, and so into the same camera. */
#include <math.h>
#include <string.h>

#include "support.h"
#include "cli.h"
#include "command.h"

/* Splits cmd at spaces (the test's paths have none) and parses it with the
 * shared options, as whitted does. */
static void parse_back(char *cmd, struct cli_scene *o, const char **scene)
{
	static const struct option longopts[] = { CLI_SCENE_LONG, { NULL, 0, NULL, 0 } };
	char *argv[64];
	int argc = 0, c;
	struct diag d;
	char *tok;

	for (tok = strtok(cmd, " "); tok; tok = strtok(NULL, " ")) {
		assert_true(argc < 63);
		argv[argc++] = tok;
	}
	argv[argc] = NULL;
	assert_string_equal(argv[0], "whitted");
	cli_scene_init(o);
	optind = 0;	/* glibc: start a new scan */
	opterr = 0;
	while ((c = getopt_long(argc, argv, CLI_SCENE_SHORT, longopts, NULL)) != -1)
		assert_int_equal(cli_scene_option(o, c, optarg, &d), 1);
	*scene = optind < argc ? argv[optind] : NULL;
	assert_true(optind + 1 >= argc);
}

static void test_command_round_trips_camera(void **state)
{
	struct camera_params p = {
		{ 0.1, -199.99999999999997, 1e-300 }, { 1.0 / 3.0, 2e17, -7.25 },
		{ -0.0, 0.30000000000000004, 0.9539392014169456 }, 80.00000000000001
	};
	struct camera a, b;
	struct cli_scene given, back;
	const char *scene;
	char cmd[1024];
	struct diag d;

	(void)state;
	cli_scene_init(&given);
	assert_int_equal(command_format(cmd, sizeof(cmd), "scenes/scene.txt", &given, &p, 768), 0);
	parse_back(cmd, &back, &scene);
	assert_string_equal(scene, "scenes/scene.txt");
	assert_memory_equal(&back.camera, &p, sizeof(p));
	assert_int_equal(back.size, 768);
	assert_int_equal(back.recursion, 0);
	assert_false(back.no_floor);
	assert_int_equal(back.clamp, RT_CLAMP_LEVEL);
	assert_int_equal(camera_init(&a, &p, 768, &d), 0);
	assert_int_equal(camera_init(&b, &back.camera, back.size, &d), 0);
	/* Bit for bit (struct camera has padding after size). */
	assert_memory_equal(&a, &b, offsetof(struct camera, size));
	assert_int_equal(a.size, b.size);
}

static void test_command_carries_image_options(void **state)
{
	struct cli_scene given, back;
	struct camera_params p;
	const char *scene;
	char cmd[1024];

	(void)state;
	camera_params_default(&p);
	cli_scene_init(&given);
	given.recursion = 3;
	given.floor_width = 600.5;
	given.floor_tile = 0.1;
	given.clamp = RT_CLAMP_FINAL;
	assert_int_equal(command_format(cmd, sizeof(cmd), NULL, &given, &p, 64), 0);
	assert_non_null(strstr(cmd, "--test-scene"));
	parse_back(cmd, &back, &scene);
	assert_null(scene);
	assert_true(back.test_scene);
	assert_int_equal(back.recursion, 3);
	assert_true(back.floor_width == 600.5 && back.floor_tile == 0.1);
	assert_int_equal(back.clamp, RT_CLAMP_FINAL);

	given.no_floor = true;
	assert_int_equal(command_format(cmd, sizeof(cmd), "a.txt", &given, &p, 64), 0);
	assert_non_null(strstr(cmd, " --no-floor"));
	assert_null(strstr(cmd, "--floor "));
}

static void test_command_quotes_scene(void **state)
{
	char buf[64];

	(void)state;
	assert_int_equal(command_quote(buf, sizeof(buf), "scenes/a-b_c.txt"), 0);
	assert_string_equal(buf, "scenes/a-b_c.txt");
	assert_int_equal(command_quote(buf, sizeof(buf), "my scene's.txt"), 0);
	assert_string_equal(buf, "'my scene'\\''s.txt'");
	assert_int_equal(command_quote(buf, sizeof(buf), "-x.txt"), 0);
	assert_string_equal(buf, "./-x.txt");
	assert_int_equal(command_quote(buf, 4, "long.txt"), -RT_E_RANGE);
}

static void test_command_too_small(void **state)
{
	struct cli_scene given;
	struct camera_params p;
	char cmd[40];

	(void)state;
	camera_params_default(&p);
	cli_scene_init(&given);
	assert_int_equal(command_format(cmd, sizeof(cmd), "scene.txt", &given, &p, 500), -RT_E_RANGE);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_command_round_trips_camera),
		cmocka_unit_test(test_command_carries_image_options),
		cmocka_unit_test(test_command_quotes_scene),
		cmocka_unit_test(test_command_too_small),
	};
	return SUPPORT_RUN(tests, argc, argv);
}
