/* The renders of broken rules (shade.c's sum with shade_rules.h's flags,
 * through shade_rules_trace, its own instance): with no rule broken, the
 * same colour as render_trace bit for bit over the whole course scene in
 * both clamping modes, and over scene files with glass and textured
 * floors at recursion 6; each rule broken, single rays through tiny scenes
 * against values computed by hand from the rule as the cause states it. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "course_scene.h"
#include "render/shade_rules.h"
#include "scene/scene_impl.h"
#include "whitted/camera.h"
#include "whitted/render.h"
#include "whitted/scenefile.h"
#include "support.h"

static struct color trace(const char *text, unsigned rules, struct ray r, bool floor)
{
	struct scene *s = support_prepared(text, floor);
	struct render_settings rs;
	struct color c;

	memset(&rs, 0, sizeof(rs));
	rs.recursion = s->recursion;
	rs.clamp = RT_CLAMP_LEVEL;
	r.dir = vec3_normalize(r.dir);
	c = shade_rules_trace(s, &rs, rules, &r, 1);
	scene_destroy(s);
	return c;
}

static void assert_color(struct color c, double r, double g, double b)
{
	assert_near(c.r, r, 1e-9);
	assert_near(c.g, g, 1e-9);
	assert_near(c.b, b, 1e-9);
}

/* render_trace and shade_rules_trace (no rules) give the same colour, bit
 * for bit, for every pixel of a size x size image through cam, under
 * both clamps. */
static void assert_rules_trace(const struct scene *s, const struct camera *cam, int size)
{
	int x, y, mode;

	for (mode = 0; mode < 2; mode++) {
		struct render_settings rs;
		memset(&rs, 0, sizeof(rs));
		rs.recursion = s->recursion;
		rs.clamp = mode ? RT_CLAMP_FINAL : RT_CLAMP_LEVEL;
		for (y = 0; y < size; y++) {
			for (x = 0; x < size; x++) {
				struct ray r = camera_ray(cam, x, y);
				struct color a = render_trace(s, &rs, &r, 1, NULL);
				struct color b = shade_rules_trace(s, &rs, 0, &r, 1);
				assert_memory_equal(&a, &b, sizeof(a));
			}
		}
	}
}

static void test_shade_rules_none_is_render_trace(void **state)
{
	struct scene *s = support_prepared(course_scene, true);
	struct camera_params p;
	struct camera cam;
	struct diag d;

	(void)state;
	camera_params_default(&p);
	assert_int_equal(camera_init(&cam, &p, 64, &d), 0);
	assert_rules_trace(s, &cam, 64);
	scene_destroy(s);
}

/* A scene file of the repository (the tests run in its root) with glass
 * objects and the floor textured as --glass and --floor-texture make it,
 * its camera that of the file's view (nearfar's near plane). */
struct file_case {
	const char *path;
	size_t glass[2];	/* 1-based; 0: none */
	const char *texture[2];
	int recursion;
};

static struct scene *load_case(const struct file_case *fc, struct camera *cam)
{
	struct scene *s = NULL;
	struct scene_view v;
	struct camera_params p;
	struct diag d;
	int i;

	assert_int_equal(scene_load(fc->path, NULL, NULL, NULL, &s, &d), 0);
	assert_int_equal(scene_set_recursion(s, fc->recursion, &d), 0);
	for (i = 0; i < 2; i++)
		if (fc->glass[i])
			assert_int_equal(scene_set_glass(s, fc->glass[i] - 1, i ? 1.33 : 1.5,
							 i ? 0.6 : 0.8, &d), 0);
	v = *scene_view_of(s);
	v.floor_texture[0] = fc->texture[0];
	v.floor_texture[1] = fc->texture[1];
	scene_set_view(s, &v);
	assert_int_equal(scene_add_view_floor(s, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	camera_params_default(&p);
	p.fov_deg = v.fov_deg;
	p.near = v.near;
	p.aspect = v.aspect;
	assert_int_equal(camera_init(cam, &p, 48, &d), 0);
	return s;
}

static void test_shade_rules_none_is_render_trace_glass_texture(void **state)
{
	static const struct file_case cases[] = {
		{ "scenes/sphere.txt", { 2, 0 }, { "tests/textures/white.bmp", NULL }, 6 },
		{ "scenes/nearfar.txt", { 1, 3 }, { "tests/textures/white.bmp",
						    "tests/textures/black.png" }, 6 },
		{ "scenes/spot.txt", { 1, 0 }, { NULL, "tests/textures/black.png" }, 6 },
		{ "scenes/falloff.txt", { 1, 2 }, { "tests/textures/white.png", NULL }, 6 },
		{ "tests/scenes/glass-prism.txt", { 1, 0 }, { "tests/textures/white.bmp",
							      "tests/textures/black.png" }, 6 },
	};
	size_t k;

	(void)state;
	for (k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
		struct camera cam;
		struct scene *s = load_case(&cases[k], &cam);

		assert_rules_trace(s, &cam, 48);
		scene_destroy(s);
	}
}

/* A sphere of colour C = (0.5, 0.2, 0.1), ka 0.1 kd 0.3 ks 0.4, seen head
 * on at (0, -1, 0) with the light straight behind the eye: N.L = R.L = 1. */
#define LIT_SPHERE \
	"1\n8\n%s\nsphere\n0 0 0\n1\n0.5 0.2 0.1\n0.1 0.3 0.4 0\n7\n" \
	"1\n0 -10 0\n1 1 1\n"

static const char *scene_text(const char *fmt, int objects, const char *extra)
{
	static char buf[1024];
	char count[8];

	snprintf(count, sizeof(count), "%d", objects);
	snprintf(buf, sizeof(buf), fmt, count);
	if (extra) {
		/* The extra object goes after the sphere, before the lights. */
		char *lights = strstr(buf, "\n1\n0 -10 0");
		char tail[256];
		snprintf(tail, sizeof(tail), "%s", lights);
		snprintf(lights, sizeof(buf) - (size_t)(lights - buf), "\n%s%s", extra, tail);
	}
	return buf;
}

static void test_shade_rules_white_specular(void **state)
{
	struct ray r = support_ray(0, -3, 0, 0, 1, 0);
	const char *t = scene_text(LIT_SPHERE, 1, NULL);

	(void)state;
	/* ka C + (kd + ks) C, and with the highlight white ka C + kd C + ks. */
	assert_color(trace(t, 0, r, false), 0.8 * 0.5, 0.8 * 0.2, 0.8 * 0.1);
	assert_color(trace(t, RT_RULE_WHITE_SPECULAR, r, false), 0.4 * 0.5 + 0.4, 0.4 * 0.2 + 0.4,
		     0.4 * 0.1 + 0.4);
}

static void test_shade_rules_no_shadows(void **state)
{
	/* A blocker at y = -6 between the sphere and the light. */
	const char *t = scene_text(LIT_SPHERE, 2, "sphere\n0 -6 0\n0.5\n1 1 1\n0 0 0 0\n1\n");
	struct ray r = support_ray(0, -3, 0, 0, 1, 0);

	(void)state;
	assert_color(trace(t, 0, r, false), 0.1 * 0.5, 0.1 * 0.2, 0.1 * 0.1);
	assert_color(trace(t, RT_RULE_NO_SHADOWS, r, false), 0.8 * 0.5, 0.8 * 0.2, 0.8 * 0.1);
}

static void test_shade_rules_unit_starts(void **state)
{
	/* The light at (-10, -11, 0) seen from P = (0, -1, 0): L = (-1, -1, 0) / sqrt 2;
	 * a blocker of radius 0.1 half a unit along L is skipped by a start
	 * one unit along L.  N.L = R.L = 1 / sqrt 2, shininess 7. */
	const char *t = "1\n8\n2\nsphere\n0 0 0\n1\n0.5 0.2 0.1\n0.1 0.3 0.4 0\n7\n"
			"sphere\n-0.35355339 -1.35355339 0\n0.1\n1 1 1\n0 0 0 0\n1\n"
			"1\n-10 -11 0\n1 1 1\n";
	struct ray r = support_ray(0, -3, 0, 0, 1, 0);
	double nl = 1.0 / sqrt(2.0), k = 0.1 + 0.3 * nl + 0.4 * pow(nl, 7.0);

	(void)state;
	assert_color(trace(t, 0, r, false), 0.1 * 0.5, 0.1 * 0.2, 0.1 * 0.1);
	assert_color(trace(t, RT_RULE_UNIT_STARTS, r, false), k * 0.5, k * 0.2, k * 0.1);
}

static void test_shade_rules_light_behind(void **state)
{
	/* A triangle in the plane y = 0 hit at the origin along (0.6, 0.8, 0):
	 * N = (0, -1, 0), R = (0.6, -0.8, 0); the light at (8, 1, 0) is behind
	 * it (N.L = -1 / sqrt 65) yet R.L = 4 / sqrt 65 > 0: only the
	 * highlight comes through, ks (R.L)^2 C. */
	const char *t = "1\n8\n1\ntriangle\n-50 0 -50\n50 0 -50\n0 0 50\n0.5 0.2 0.1\n0.1 0.3 0.4 0\n2\n"
			"1\n8 1 0\n1 1 1\n";
	struct ray r = support_ray(-3, -4, 0, 0.6, 0.8, 0);
	double rl = 4.0 / sqrt(65.0), k = 0.1 + 0.4 * rl * rl;

	(void)state;
	assert_color(trace(t, 0, r, false), 0.1 * 0.5, 0.1 * 0.2, 0.1 * 0.1);
	assert_color(trace(t, RT_RULE_LIGHT_BEHIND, r, false), k * 0.5, k * 0.2, k * 0.1);
	/* Two-sided: the diffuse term with |N.L| = 1 / sqrt 65 as well. */
	k += 0.3 / sqrt(65.0);
	assert_color(trace(t, RT_RULE_LIGHT_BEHIND | RT_RULE_TWO_SIDED, r, false), k * 0.5, k * 0.2,
		     k * 0.1);
	/* Signed (no test at all): kd N.L = -0.3 / sqrt 65 darkens instead. */
	k -= 0.6 / sqrt(65.0);
	assert_color(trace(t, RT_RULE_LIGHT_BEHIND | RT_RULE_SIGNED_DIFFUSE, r, false), k * 0.5,
		     k * 0.2, k * 0.1);
}

static void test_shade_rules_never_clamp(void **state)
{
	/* ka 3 on a grey of 0.5, no light: 1.5, the byte round(382.5) = 383 wraps to 127. */
	const char *t = "1\n8\n1\nsphere\n0 0 0\n1\n0.5 0.5 0.5\n3 0 0 0\n1\n0\n";
	struct ray r = support_ray(0, -3, 0, 0, 1, 0);
	uint8_t rgb[3];

	(void)state;
	render_color_to_rgb8(trace(t, 0, r, false), rgb);
	assert_int_equal(rgb[0], 255);
	render_color_to_rgb8(trace(t, RT_RULE_NEVER_CLAMP, r, false), rgb);
	assert_int_equal(rgb[0], 127);
	assert_int_equal(rgb[2], 127);
}

static void test_shade_rules_floor_swapped(void **state)
{
	/* Straight down onto (5, 5, 0): tile (25, 25), white; swapped, black,
	 * so only ka of nothing is left. */
	const char *t = "1\n8\n0\n0\n";
	struct ray r = support_ray(5, 5, 10, 0, 0, -1);

	(void)state;
	assert_color(trace(t, 0, r, true), 0.4, 0.4, 0.4);
	assert_color(trace(t, RT_RULE_FLOOR_SWAPPED, r, true), 0.0, 0.0, 0.0);
}

/* A spotlight at (0, -10, 0) with a cone of 30 degrees lighting the
 * origin of the plane y = 0, seen head on from (0, -3, 0): N.L = R.L = 1,
 * lit ka C + (kd + ks) C = 0.8 C, unlit ka C = 0.1 C (the point light
 * behind the plane never lights it).  axis_deg is the angle between the
 * cone's axis and the direction to P. */
static const char *spot_text(double axis_deg, char *buf, size_t size)
{
	const double a = axis_deg * 3.14159265358979323846 / 180.0;

	snprintf(buf, size, "1\n8\n1\ntriangle\n-50 0 -50\n50 0 -50\n0 0 50\n0.5 0.2 0.1\n"
		 "0.1 0.3 0.4 0\n2\n1\n0 10 0\n1 1 1\n1\n0 -10 0\n1 1 1\n%.17g %.17g 0\n30\n",
		 sin(a), cos(a));
	return buf;
}

static void assert_spot_lit(const char *t, unsigned rules, bool lit)
{
	const double k = lit ? 0.8 : 0.1;

	assert_color(trace(t, rules, support_ray(0, -3, 0, 0, 1, 0), false), k * 0.5, k * 0.2,
		     k * 0.1);
}

static void test_shade_rules_spot_cone(void **state)
{
	char buf[512];
	const char *t = spot_text(20.0, buf, sizeof(buf));

	(void)state;
	/* 20 degrees off the axis: inside the cone of 30. */
	assert_spot_lit(t, 0, true);
	assert_spot_lit(t, RT_RULE_SPOT_NO_CONE, true);
	assert_spot_lit(t, RT_RULE_SPOT_UNLIT, false);
	/* cos(30 radians) = 0.154: a cone of 81.1 degrees. */
	assert_spot_lit(t, RT_RULE_SPOT_COS_DEGREES, true);
	/* The full angle 30: 20 > 15. */
	assert_spot_lit(t, RT_RULE_SPOT_FULL_ANGLE, false);
	/* 20 * pi^2 / 4 = 49.3 > 30. */
	assert_spot_lit(t, RT_RULE_SPOT_PI_MACRO, false);
	/* 12 degrees: 12 * pi^2 / 4 = 29.6 <= 30, and 12 <= 15. */
	t = spot_text(12.0, buf, sizeof(buf));
	assert_spot_lit(t, RT_RULE_SPOT_PI_MACRO, true);
	assert_spot_lit(t, RT_RULE_SPOT_FULL_ANGLE, true);
	/* 85 degrees: outside the cone, and outside cos(30 rad)'s 81.1; no
	 * cone lights it still.  80 degrees: inside 81.1. */
	t = spot_text(85.0, buf, sizeof(buf));
	assert_spot_lit(t, 0, false);
	assert_spot_lit(t, RT_RULE_SPOT_COS_DEGREES, false);
	assert_spot_lit(t, RT_RULE_SPOT_NO_CONE, true);
	t = spot_text(80.0, buf, sizeof(buf));
	assert_spot_lit(t, 0, false);
	assert_spot_lit(t, RT_RULE_SPOT_COS_DEGREES, true);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_shade_rules_none_is_render_trace,
			   test_shade_rules_none_is_render_trace_glass_texture,
			   test_shade_rules_white_specular, test_shade_rules_no_shadows,
			   test_shade_rules_unit_starts, test_shade_rules_light_behind,
			   test_shade_rules_never_clamp, test_shade_rules_floor_swapped,
			   test_shade_rules_spot_cone))
