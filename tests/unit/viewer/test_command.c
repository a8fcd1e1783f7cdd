/* The capture's command: whitted's own option parsing reads it back into
 * bit-identical camera parameters, and so into the same camera; for a
 * nearfar file, with the near plane and aspect that whitted reads from the
 * file again. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <wordexp.h>

#include "support.h"
#include "cli/scene_opts.h"
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
		{ -0.0, 0.30000000000000004, 0.9539392014169456 }, 80.00000000000001, 0.0, 0.0
	};
	struct camera a, b;
	struct cli_scene back;
	struct settings set;
	const char *scene;
	char cmd[1024];
	struct diag d;

	(void)state;
	settings_init(&set);
	set.camera = p;
	set.size = 768;
	set.recursion = 4;
	assert_int_equal(command_format(cmd, sizeof(cmd), "scenes/scene.txt", RT_DIALECT_AUTO,
					&set), 0);
	parse_back(cmd, &back, &scene);
	assert_string_equal(scene, "scenes/scene.txt");
	assert_memory_equal(&back.camera, &p, sizeof(p));
	assert_int_equal(back.size, 768);
	assert_int_equal(back.recursion, 4);
	assert_false(back.no_floor);
	assert_int_equal(back.clamp, RT_CLAMP_LEVEL);
	assert_int_equal(camera_init(&a, &p, 768, &d), 0);
	assert_int_equal(camera_init(&b, &back.camera, back.size, &d), 0);
	/* Bit for bit (struct camera has padding after size). */
	assert_memory_equal(&a, &b, offsetof(struct camera, size));
	assert_int_equal(a.size, b.size);
}

/* The command line of the course's default view, as whitted-view has
 * always printed it: the defaults of the floor and clamping left out. */
static void test_command_default_text(void **state)
{
	struct settings set;
	char cmd[1024];

	(void)state;
	support_settings(&set, 768, 4);
	assert_int_equal(command_format(cmd, sizeof(cmd), "scenes/scene.txt", RT_DIALECT_AUTO,
					&set), 0);
	assert_string_equal(cmd, "whitted scenes/scene.txt --eye 0,-200,10 --look 0,0,0 --up 0,0,1 "
			    "--fov 80 --size 768 --recursion 4");
}

static void test_command_carries_image_options(void **state)
{
	struct cli_scene given, back;
	struct camera_params p;
	struct settings set;
	struct scene *s;
	struct camera cam;
	const char *scene;
	char cmd[1024];
	struct diag d;

	(void)state;
	camera_params_default(&p);
	p.fov_deg = 55.5;
	cli_scene_init(&given);
	given.recursion = 3;
	given.floor_width = 600.5;
	given.floor_tile = 0.1;
	given.floor_given = true;
	given.clamp = RT_CLAMP_FINAL;
	assert_int_equal(cli_scene_load(&given, NULL, NULL, NULL, &s, &cam, &d), 0);
	cli_settings(&set, &given, s, &p);
	scene_destroy(s);
	assert_int_equal(set.recursion, 3);
	assert_int_equal(command_format(cmd, sizeof(cmd), NULL, RT_DIALECT_AUTO, &set), 0);
	assert_non_null(strstr(cmd, "--test-scene"));
	parse_back(cmd, &back, &scene);
	assert_null(scene);
	assert_true(back.test_scene);
	assert_int_equal(back.recursion, 3);
	assert_true(back.camera.fov_deg == 55.5);
	assert_true(back.floor_width == 600.5 && back.floor_tile == 0.1);
	assert_int_equal(back.clamp, RT_CLAMP_FINAL);

	set.floor = false;
	assert_int_equal(command_format(cmd, sizeof(cmd), "a.txt", RT_DIALECT_AUTO, &set), 0);
	assert_non_null(strstr(cmd, " --no-floor"));
	assert_null(strstr(cmd, "--floor "));
}

/* akib1689.txt of the course files (Jan 2023 handout): near 1, FOVY 80,
 * aspect 1.77777777777778, an infinite checkerboard of cells 50. */
static const char nearfar_text[] =
	"1 1000 80 1.77777777777778\n3\n720\n\n50\n0.1 0.3 0.6\n\n2\n\n"
	"cube\n-100 -100 10\n40.0\n0.0 0.5 1.0\n0.15 0.1 0.4 0.45\n10\n\n"
	"pyramid\n-40.0 0.0 5.0\n30.0 40.0\n1.0 0.0 0.0\n0.4 0.2 0.0 0.4\n1\n\n"
	"1\n50.0 50.0 60.0\n0.000002\n\n"
	"1\n-50.0 50.0 50.0\n0.0000002\n-10 10 10 30\n";

/* Writes nearfar_text to a new file; the caller removes it. */
static void write_nearfar(char *path, size_t size)
{
	int fd;

	snprintf(path, size, "%s/whitted-test-command-XXXXXX", "/tmp");
	fd = mkstemp(path);
	assert_true(fd >= 0);
	assert_int_equal(write(fd, nearfar_text, sizeof(nearfar_text) - 1),
			 (long)(sizeof(nearfar_text) - 1));
	assert_int_equal(close(fd), 0);
}

static int load_quiet(struct cli_scene *o, const char *path, struct scene **s, struct camera *cam)
{
	struct diag d;

	diag_clear(&d);
	return cli_scene_load(o, path, NULL, NULL, s, cam, &d);
}

/* A capture of a nearfar file: the command prints the view's eye, look,
 * up and fov, no near plane, aspect or floor (whitted takes them from the
 * file), and whitted, loading the same file with it, builds the very
 * camera the capture traced with. */
static void test_command_nearfar_round_trip(void **state)
{
	struct cli_scene given, back;
	struct camera_params p;
	struct settings set;
	struct scene *s;
	struct camera cam, cam_back;
	const char *scene;
	char path[64], cmd[1024];
	struct diag d;

	(void)state;
	write_nearfar(path, sizeof(path));
	cli_scene_init(&given);
	assert_int_equal(load_quiet(&given, path, &s, &cam), 0);
	assert_true(given.camera.near == 1.0 && given.camera.aspect == 1.77777777777778);
	assert_true(given.camera.fov_deg == 80.0 && isinf(given.floor_width));
	/* Where the viewer's keys took the camera; the lens is the file's. */
	p = given.camera;
	p.eye = vec3_make(-31.25, -187.5000000000001, 23.5);
	p.look = vec3_make(1.0 / 3.0, 0.1, 4.75);
	p.up = vec3_make(0.0625, 0.1, 0.99);
	cli_settings(&set, &given, s, &p);
	assert_true(set.floor_from_view);
	assert_true(set.floor_mat.ka == 0.1 && set.floor_mat.kd == 0.3 && set.floor_mat.kr == 0.6);
	assert_int_equal(command_format(cmd, sizeof(cmd), path, RT_DIALECT_AUTO, &set), 0);
	assert_null(strstr(cmd, "--floor"));
	assert_null(strstr(cmd, "--dialect"));
	assert_null(strstr(cmd, "near"));
	assert_null(strstr(cmd, "aspect"));
	assert_non_null(strstr(cmd, " --fov 80 --size 720 --recursion 3"));
	assert_int_equal(camera_init(&cam, &p, scene_image_size(s), &d), 0);
	scene_destroy(s);

	parse_back(cmd, &back, &scene);
	assert_string_equal(scene, path);
	assert_int_equal(load_quiet(&back, scene, &s, &cam_back), 0);
	assert_memory_equal(&back.camera, &p, sizeof(p));
	assert_int_equal(scene_image_size(s), 720);
	assert_true(isinf(back.floor_width) && back.floor_tile == 50.0);
	scene_destroy(s);
	assert_memory_equal(&cam, &cam_back, offsetof(struct camera, size));
	assert_memory_equal(&cam.half_width, &cam_back.half_width,
			    sizeof(struct camera) - offsetof(struct camera, half_width));
	remove(path);
}

/* A dialect forced on the viewer is forced on whitted too; --floor on a
 * nearfar file is a classic floor, which the command says. */
static void test_command_carries_dialect_and_floor(void **state)
{
	struct cli_scene given, back;
	struct settings set;
	struct scene *s;
	struct camera cam;
	const char *scene;
	char path[64], cmd[1024];

	(void)state;
	write_nearfar(path, sizeof(path));
	cli_scene_init(&given);
	given.read.dialect = RT_DIALECT_NEARFAR;
	given.floor_given = true;
	given.floor_width = 1000.0;
	given.floor_tile = 20.0;
	assert_int_equal(load_quiet(&given, path, &s, &cam), 0);
	cli_settings(&set, &given, s, &given.camera);
	assert_false(set.floor_from_view);
	scene_destroy(s);
	assert_int_equal(command_format(cmd, sizeof(cmd), path, RT_DIALECT_NEARFAR, &set), 0);
	assert_non_null(strstr(cmd, " --dialect nearfar --eye "));
	assert_non_null(strstr(cmd, " --floor 1000,20"));
	parse_back(cmd, &back, &scene);
	assert_int_equal(back.read.dialect, RT_DIALECT_NEARFAR);
	assert_true(back.floor_given && back.floor_width == 1000.0 && back.floor_tile == 20.0);
	/* The test scene has no file to read as a dialect. */
	assert_int_equal(command_format(cmd, sizeof(cmd), NULL, RT_DIALECT_NEARFAR, &set), 0);
	assert_null(strstr(cmd, "--dialect"));
	remove(path);
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

/* The command split into words as sh would (wordexp, no command
 * substitution), parsed with the shared options. */
static void parse_shell(const char *cmd, struct cli_scene *o, const char **scene, wordexp_t *we)
{
	static const struct option longopts[] = { CLI_SCENE_LONG, { NULL, 0, NULL, 0 } };
	struct diag d;
	int c;

	assert_int_equal(wordexp(cmd, we, WRDE_NOCMD | WRDE_UNDEF), 0);
	assert_string_equal(we->we_wordv[0], "whitted");
	cli_scene_init(o);
	optind = 0;
	opterr = 0;
	while ((c = getopt_long((int)we->we_wordc, we->we_wordv, CLI_SCENE_SHORT, longopts,
				NULL)) != -1)
		assert_int_equal(cli_scene_option(o, c, optarg, &d), 1);
	*scene = optind < (int)we->we_wordc ? we->we_wordv[optind] : NULL;
	assert_true(optind + 1 >= (int)we->we_wordc);
}

static void test_command_quotes_texture_paths(void **state)
{
	/* Paths with a space, a quote and a '$', and a texture named none
	 * (a file, not --no-floor-texture): the shell gives them back. */
	struct cli_scene back;
	struct settings set;
	const char *scene;
	char cmd[1024];
	wordexp_t we;

	(void)state;
	support_settings(&set, 64, 2);
	set.floor_texture[0] = "my tex/it's $HOME.bmp";
	set.floor_texture[1] = "none";
	assert_int_equal(command_format(cmd, sizeof(cmd), "a scene.txt", RT_DIALECT_AUTO, &set),
			 0);
	assert_null(strstr(cmd, "--no-floor-texture"));
	parse_shell(cmd, &back, &scene, &we);
	assert_string_equal(scene, "a scene.txt");
	assert_string_equal(back.floor_texture[0], "my tex/it's $HOME.bmp");
	assert_string_equal(back.floor_texture[1], "none");
	wordfree(&we);
	/* A black texture alone, named none. */
	set.floor_texture[0] = NULL;
	assert_int_equal(command_format(cmd, sizeof(cmd), "s.txt", RT_DIALECT_AUTO, &set), 0);
	assert_non_null(strstr(cmd, " --floor-texture ,none"));
	parse_shell(cmd, &back, &scene, &we);
	assert_null(back.floor_texture[0]);
	assert_string_equal(back.floor_texture[1], "none");
	wordfree(&we);
}

static void test_command_too_small(void **state)
{
	struct settings set;
	char cmd[40];

	(void)state;
	support_settings(&set, 500, 4);
	assert_int_equal(command_format(cmd, sizeof(cmd), "scene.txt", RT_DIALECT_AUTO, &set),
			 -RT_E_RANGE);
	assert_int_equal(command_format(cmd, 9, "scene.txt", RT_DIALECT_AUTO, &set), -RT_E_RANGE);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_command_round_trips_camera, test_command_default_text,
			   test_command_carries_image_options, test_command_nearfar_round_trip,
			   test_command_carries_dialect_and_floor, test_command_quotes_scene,
			   test_command_quotes_texture_paths, test_command_too_small))
