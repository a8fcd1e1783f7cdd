/* The plugins' unit tests: a plugin of build/plugins/ loaded through the
 * loader as the programs load it, and one shape of it parsed from scene
 * text.  Included by one test file each (static functions). */
#ifndef RT_TESTS_PLUGIN_FIXTURE_H
#define RT_TESTS_PLUGIN_FIXTURE_H

#include <stdio.h>
#include <string.h>

#include "plugin/loader.h"
#include "support.h"

/* Loads RT_TEST_PLUGIN_DIR/name.so once for the group. */
static int fixture_load(const char *name)
{
	char path[4096];
	struct diag d;

	snprintf(path, sizeof(path), "%s/%s.so", RT_TEST_PLUGIN_DIR, name);
	diag_clear(&d);
	if (plugin_load(path, &d) < 0) {
		fprintf(stderr, "%s\n", d.msg);
		return -1;
	}
	return 0;
}

static int fixture_unload(void **state)
{
	(void)state;
	plugin_unload_all();
	return 0;
}

/* The program's main (SUPPORT_MAIN_AROUND): loads the plugin `name` before
 * the tests, a failure to load failing the program, and unloads it after. */
#define FIXTURE_MAIN(name, ...) \
	static int fixture_load_group(void **state) \
	{ \
		(void)state; \
		return fixture_load(name); \
	} \
	SUPPORT_MAIN_AROUND(fixture_load_group, fixture_unload, __VA_ARGS__)

/* A classic scene of the one object `object` (keyword to shininess) and
 * no light; *state is the scene, its only shape the one tested. */
static struct scene *fixture_scene(const char *object)
{
	char text[2048];

	snprintf(text, sizeof(text), "1\n64\n\n1\n%s\n0\n", object);
	return support_parse(text);
}

static const struct shape *fixture_shape(void **state)
{
	return scene_shape(*state, 0);
}

static int fixture_destroy(void **state)
{
	scene_destroy(*state);
	return 0;
}

/* The nearest hit of the ray in (1e-9, inf), or -1 for a miss. */
static double fixture_hit(const struct shape *s, struct ray r)
{
	double t = INFINITY;

	return shape_intersect(s, &r, 1e-9, &t) ? t : -1.0;
}

#endif
