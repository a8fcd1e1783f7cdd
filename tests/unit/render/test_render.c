/* The renderer: single rays through tiny scenes against values computed by
 * hand from scene-format.md's shading rules (with more lights than one
 * batch of the light loop), the absence of shadow acne and light leaks
 * (also far up the z axis and with the eye far away), pixel rounding, ray
 * counts, and whole images that do not depend on the number of threads or
 * on the region rendered. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "course_scene.h"
#include "scene/scene_impl.h"
#include "whitted/render.h"
#include "render_fixture.h"
#include "support.h"

static struct ray ray_make(double ox, double oy, double oz, double dx, double dy, double dz)
{
	struct ray r;

	r.origin = vec3_make(ox, oy, oz);
	r.dir = vec3_normalize(vec3_make(dx, dy, dz));
	return r;
}

/* The colour along r in the scene of text (no floor), with the file's
 * recursion level and the given clamping. */
static struct color trace_counted(const char *text, enum clamp_mode clamp, struct ray r,
				  struct ray_counts *counts)
{
	struct scene *s = support_prepared(text, false);
	struct render_settings rs;
	struct color c;

	rs.recursion = s->recursion;
	rs.clamp = clamp;
	if (counts)
		memset(counts, 0, sizeof(*counts));
	c = render_trace(s, &rs, &r, 1, counts);
	scene_destroy(s);
	return c;
}

static struct color trace(const char *text, struct ray r)
{
	return trace_counted(text, RT_CLAMP_LEVEL, r, NULL);
}

#define assert_color(c, r_, g_, b_, eps) \
	assert_vec3_near(vec3_make((c).r, (c).g, (c).b), vec3_make((r_), (g_), (b_)), (eps))

/* The top of a radius-10 sphere at the origin, seen from straight above:
 * P = (0, 0, 10), N = (0, 0, 1), d = (0, 0, -1), R = (0, 0, 1). */
static struct ray from_above(void)
{
	return ray_make(0, 0, 100, 0, 0, -1);
}

static void test_render_background_is_black(void **state)
{
	struct color c = trace("1 1 1 sphere 0 0 0 10  1 1 1  1 1 1 1  1  1 0 0 50 1 1 1",
			       ray_make(0, 0, 100, 0, 0, 1));

	(void)state;
	assert_color(c, 0, 0, 0, 0.0);
}

static void test_render_ambient_only(void **state)
{
	/* No lights: c = KA C = 0.4 (0.5, 0.25, 1) = (0.2, 0.1, 0.4). */
	struct color c = trace("1 1 1 sphere 0 0 0 10  0.5 0.25 1  0.4 0.7 0.6 0  3  0", from_above());

	(void)state;
	assert_color(c, 0.2, 0.1, 0.4, 1e-15);
}

static void test_render_diffuse_head_on(void **state)
{
	/* Light straight above at (0, 0, 50): L = (0, 0, 1), N.L = 1.
	 * c = KA C + KD (N.L) C = (0.4 + 0.5) (0.5, 0.25, 1). */
	struct color c = trace("1 1 1 sphere 0 0 0 10  0.5 0.25 1  0.4 0.5 0 0  3  1 0 0 50 1 1 1",
			       from_above());

	(void)state;
	assert_color(c, 0.45, 0.225, 0.9, 1e-12);
}

static void test_render_specular_is_tinted(void **state)
{
	/* KA = KD = 0, KS = 0.3: R = (0, 0, 1) = L, R.L = 1, so
	 * c = KS (R.L)^10 C = 0.3 (0.5, 0.25, 1); an untinted highlight would
	 * be (0.3, 0.3, 0.3). */
	struct color c = trace("1 1 1 sphere 0 0 0 10  0.5 0.25 1  0 0 0.3 0  10  1 0 0 50 1 1 1",
			       from_above());

	(void)state;
	assert_color(c, 0.15, 0.075, 0.3, 1e-12);
}

static void test_render_diffuse_and_specular_at_an_angle(void **state)
{
	/* Light at (0, 30, 50): P = (0, 0, 10), Lp - P = (0, 30, 40), |.| = 50,
	 * L = (0, 0.6, 0.8).  N.L = 0.8, R.L = 0.8.  KA 0.1, KD 0.5, KS 0.3,
	 * shininess 2: c = (0.1 + 0.5 * 0.8 + 0.3 * 0.64) C = 0.692 C. */
	struct color c = trace("1 1 1 sphere 0 0 0 10  0.5 0.25 1  0.1 0.5 0.3 0  2  1 0 30 50 1 1 1",
			       from_above());

	(void)state;
	assert_color(c, 0.346, 0.173, 0.692, 1e-12);
}

static void test_render_coloured_light(void **state)
{
	/* A white object, light colour (1, 0.5, 0), head on: c = KA C +
	 * Lc KD C = 0.1 + (1, 0.5, 0) * 0.5 = (0.6, 0.35, 0.1).  The ambient
	 * term does not take the light's colour. */
	struct color c = trace("1 1 1 sphere 0 0 0 10  1 1 1  0.1 0.5 0 0  1  1 0 0 50 1 0.5 0",
			       from_above());

	(void)state;
	assert_color(c, 0.6, 0.35, 0.1, 1e-12);
}

static void test_render_lights_add_up(void **state)
{
	/* Two lights, red and blue, both straight above: each adds KD C Lc. */
	struct color c = trace("1 1 1 sphere 0 0 0 10  1 1 1  0.1 0.5 0 0  1  "
			       "2 0 0 50 1 0 0  0 0 80 0 0 1", from_above());

	(void)state;
	assert_color(c, 0.6, 0.1, 0.6, 1e-12);
}

/* The plane scenes: the triangle (-50,-50,0) (50,-50,0) (0,50,0) in z = 0
 * ((b - a) x (c - a) = (100,0,0) x (50,100,0) = (0,0,10000): N = +z),
 * seen from (0, -100, 100) at its point P = (0, 0, 0):
 * d = (0, 1, -1) / sqrt(2), N.d < 0 so N stays +z, and
 * R = d - 2 (d.N) N = (0, 1, 1) / sqrt(2). */
#define PLANE "triangle -50 -50 0  50 -50 0  0 50 0  "
static struct ray at_plane(void)
{
	return ray_make(0, -100, 100, 0, 1, -1);
}

static void test_render_plane_lit(void **state)
{
	/* Light at (0, 0, 50): L = (0, 0, 1), N.L = 1, R.L = 1/sqrt(2);
	 * colour (1, 0.5, 0.25), KA 0.1, KD 0.5, KS 0.4, shininess 2:
	 * c = (0.1 + 0.5 + 0.4 * 0.5) C = 0.8 C. */
	struct color c = trace("1 1 1 " PLANE "1 0.5 0.25  0.1 0.5 0.4 0  2  1 0 0 50 1 1 1", at_plane());

	(void)state;
	assert_color(c, 0.8, 0.4, 0.2, 1e-12);
}

static void test_render_shadowed_point(void **state)
{
	/* A sphere of radius 2 at (0, 0, 25) between P and the light at
	 * (0, 0, 50) (and 17.7 away from the view ray): only the ambient
	 * 0.1 C is left. */
	struct color c = trace("1 1 2 " PLANE "1 0.5 0.25  0.1 0.5 0.4 0  2  "
			       "sphere 0 0 25 2  1 1 1  0 0 0 0 1  1 0 0 50 1 1 1", at_plane());

	(void)state;
	assert_color(c, 0.1, 0.05, 0.025, 1e-12);
}

static void test_render_blocker_beyond_light(void **state)
{
	/* The same sphere at (0, 0, 80), beyond the light: no shadow, the
	 * value of test_render_plane_lit. */
	struct color c = trace("1 1 2 " PLANE "1 0.5 0.25  0.1 0.5 0.4 0  2  "
			       "sphere 0 0 80 2  1 1 1  0 0 0 0 1  1 0 0 50 1 1 1", at_plane());

	(void)state;
	assert_color(c, 0.8, 0.4, 0.2, 1e-12);
}

static void test_render_light_behind_open_surface(void **state)
{
	struct color c;

	(void)state;
	/* Light below the triangle at (0, 0, -50): N.L = -1, nothing. */
	c = trace("1 1 1 " PLANE "1 0.5 0.25  0.1 0.5 0.4 0  2  1 0 0 -50 1 1 1", at_plane());
	assert_color(c, 0.1, 0.05, 0.025, 1e-15);
	/* Light at (0, 100, -1), just below the plane: N.L = -1/sqrt(10001)
	 * < 0 but R.L = (100 - 1) / sqrt(2 * 10001) = 0.70 > 0.  Without the
	 * N.L check a highlight 0.4 * 0.70^2 C would show. */
	c = trace("1 1 1 " PLANE "1 0.5 0.25  0.1 0.5 0.4 0  2  1 0 100 -1 1 1 1", at_plane());
	assert_color(c, 0.1, 0.05, 0.025, 1e-15);
}

static void test_render_highlight_needs_positive_r_dot_l(void **state)
{
	/* Light at (0, -100, 14), on the viewer's side and low: Lp - P =
	 * (0, -100, 14), N.L = 14 / sqrt(10196) > 0, but R.L = (-100 + 14) /
	 * sqrt(2 * 10196) < 0: no highlight, even though (R.L)^2 > 0.
	 * c = (0.1 + 0.5 * 14 / sqrt(10196)) C. */
	struct color c = trace("1 1 1 " PLANE "1 0.5 0.25  0.1 0.5 0.4 0  2  1 0 -100 14 1 1 1",
			       at_plane());
	double k = 0.1 + 0.5 * 14.0 / sqrt(10196.0);

	(void)state;
	assert_color(c, k, 0.5 * k, 0.25 * k, 1e-12);
}

/* A mirror: the plane triangle with colour (0, 0, 1), KA 0.2, KR 0.5;
 * the reflected ray leaves P along (0, 1, 1) / sqrt(2) and meets a red
 * sphere of radius 5 centred on it at (0, 50, 50), which shows only its
 * ambient KA C.  No lights. */
#define MIRROR_SCENE(level, ka) \
	#level " 1 2 " PLANE "0 0 1  0.2 0 0 0.5  1  sphere 0 50 50 5  1 0.5 0  " #ka " 0 0 0 1  0"

static void test_render_one_reflection_bounce(void **state)
{
	struct ray_counts n;
	struct color c;

	(void)state;
	/* Recursion 2: c = (0, 0, 0.2) + 0.5 * 0.6 (1, 0.5, 0). */
	c = trace_counted(MIRROR_SCENE(2, 0.6), RT_CLAMP_LEVEL, at_plane(), &n);
	assert_color(c, 0.3, 0.15, 0.2, 1e-12);
	assert_int_equal(n.reflection, 1);
	assert_int_equal(n.shadow, 0);
	/* Recursion 1 means no reflection rays: just the mirror's ambient. */
	c = trace_counted(MIRROR_SCENE(1, 0.6), RT_CLAMP_LEVEL, at_plane(), &n);
	assert_color(c, 0, 0, 0.2, 1e-15);
	assert_int_equal(n.reflection, 0);
	/* Recursion 5: the sphere's KR is 0, so still one bounce. */
	c = trace_counted(MIRROR_SCENE(5, 0.6), RT_CLAMP_LEVEL, at_plane(), &n);
	assert_color(c, 0.3, 0.15, 0.2, 1e-12);
	assert_int_equal(n.reflection, 1);
}

static void test_render_reflection_level_argument(void **state)
{
	struct scene *s = support_prepared(MIRROR_SCENE(2, 0.6), false);
	struct render_settings rs = { 2, RT_CLAMP_LEVEL };
	struct ray r = at_plane();
	struct color c;

	(void)state;
	/* A ray already at level 2 of 2 reflects no further. */
	c = render_trace(s, &rs, &r, 2, NULL);
	assert_color(c, 0, 0, 0.2, 1e-15);
	scene_destroy(s);
}

static void test_render_clamp_level_versus_final(void **state)
{
	struct color c;

	(void)state;
	/* The sphere's KA of 2 makes it (2, 1, 0) before clamping.
	 * Per level: it is clamped to (1, 1, 0), then
	 * c = (0, 0, 0.2) + 0.5 (1, 1, 0) = (0.5, 0.5, 0.2).
	 * Final: (0, 0, 0.2) + 0.5 (2, 1, 0) = (1, 0.5, 0.2). */
	c = trace_counted(MIRROR_SCENE(2, 2), RT_CLAMP_LEVEL, at_plane(), NULL);
	assert_color(c, 0.5, 0.5, 0.2, 1e-12);
	c = trace_counted(MIRROR_SCENE(2, 2), RT_CLAMP_FINAL, at_plane(), NULL);
	assert_color(c, 1.0, 0.5, 0.2, 1e-12);
	/* With KA 0.6 nothing exceeds 1 and the two agree. */
	c = trace_counted(MIRROR_SCENE(2, 0.6), RT_CLAMP_FINAL, at_plane(), NULL);
	assert_color(c, 0.3, 0.15, 0.2, 1e-12);
	/* Seen directly, the bright sphere is (1, 1, 0) clamped per level
	 * and (2, 1, 0) unclamped, which the pixel conversion clamps: the
	 * same pixel. */
	{
		struct ray r = ray_make(0, 50, 100, 0, 0, -1);
		uint8_t a[3], b[3];
		c = trace_counted(MIRROR_SCENE(2, 2), RT_CLAMP_LEVEL, r, NULL);
		assert_color(c, 1, 1, 0, 0.0);
		render_color_to_rgb8(c, a);
		c = trace_counted(MIRROR_SCENE(2, 2), RT_CLAMP_FINAL, r, NULL);
		assert_color(c, 2, 1, 0, 1e-15);
		render_color_to_rgb8(c, b);
		assert_memory_equal(a, b, 3);
		assert_int_equal(a[0], 255);
		assert_int_equal(a[1], 255);
		assert_int_equal(a[2], 0);
	}
}

/* More lights than one batch of the renderer's light loop (it takes them
 * eight at a time): the plane point P lit only by lights 9 and up, each
 * with its own colour, while lights 1 to 8 (of other colours) lie below
 * the plane (N.L < 0: nothing).  White surface, KA 0.1, KD 0.5, KS 0.
 *   light  9 at (0, 0, 50), L = (0, 0, 1), N.L = 1, colour (0.2, 0, 0):
 *            adds 0.5 * 0.2 = 0.1 to red;
 *   light 10 at (0, 30, 40), |Lp - P| = 50, N.L = 0.8, colour (0, 0.4, 0):
 *            adds 0.5 * 0.8 * 0.4 = 0.16 to green;
 *   light 11 at (0, 0, 80), white, but behind the radius-2 sphere at
 *            (0, 0, 65) (46 away from the view ray, beyond light 9): nothing;
 *   light 12 at (-30, 0, 40), N.L = 0.8, colour (0, 0, 0.5): adds 0.2 to blue.
 * c = (0.1 + 0.1, 0.1 + 0.16, 0.1 + 0.2); 4 shadow rays (lights 9 to 12). */
static void test_render_lights_past_the_first_batch(void **state)
{
	char text[2048];
	size_t len;
	struct ray_counts n;
	struct color c;
	int i;

	(void)state;
	len = (size_t)snprintf(text, sizeof(text), "1 1 2 " PLANE "1 1 1  0.1 0.5 0 0  1  "
			       "sphere 0 0 65 2  1 1 1  0 0 0 0 1  12\n");
	for (i = 1; i <= 8; i++)
		len += (size_t)snprintf(text + len, sizeof(text) - len, "%d %d -%d  %g 0.3 %g\n",
					10 * i, 5 * i, 20 + i, 0.1 * i, 0.05 * i);
	snprintf(text + len, sizeof(text) - len, "0 0 50  0.2 0 0\n0 30 40  0 0.4 0\n"
		 "0 0 80  1 1 1\n-30 0 40  0 0 0.5\n");
	c = trace_counted(text, RT_CLAMP_LEVEL, at_plane(), &n);
	assert_color(c, 0.2, 0.26, 0.3, 1e-12);
	assert_int_equal(n.shadow, 4);
}

static void test_render_only_the_last_light_lights(void **state)
{
	/* N lights for N = 9 to 17: all but the last below the plane (blue,
	 * each at its own place), the last straight above P at (0, 0, 50) with
	 * colour (0.6, 0.2, 0.4): c = 0.1 + 0.5 (0.6, 0.2, 0.4) whichever
	 * place in a batch of 8 the last light takes. */
	int count;

	(void)state;
	for (count = 9; count <= 17; count++) {
		char text[2048];
		size_t len;
		struct ray_counts n;
		struct color c;
		int i;

		len = (size_t)snprintf(text, sizeof(text), "1 1 1 " PLANE "1 1 1  0.1 0.5 0 0  1  %d\n",
				       count);
		for (i = 1; i < count; i++)
			len += (size_t)snprintf(text + len, sizeof(text) - len, "%d 7 -%d  0 0 1\n",
						3 * i, 10 + i);
		snprintf(text + len, sizeof(text) - len, "0 0 50  0.6 0.2 0.4\n");
		c = trace_counted(text, RT_CLAMP_LEVEL, at_plane(), &n);
		if (fabs(c.r - 0.4) > 1e-12 || fabs(c.g - 0.2) > 1e-12 || fabs(c.b - 0.3) > 1e-12) {
			print_error("%d lights: (%.17g, %.17g, %.17g), expected (0.4, 0.2, 0.3)\n", count,
				    c.r, c.g, c.b);
			fail();
		}
		assert_int_equal(n.shadow, 1);
	}
}

/* The hit of r with the sphere |P - c| = rad, by the textbook formula
 * (the test's own, not the library's): the near root or -1. */
static double hit_sphere(struct ray r, struct vec3 c, double rad)
{
	struct vec3 oc = vec3_sub(r.origin, c);
	double b = vec3_dot(oc, r.dir), q = vec3_dot(oc, oc) - rad * rad;
	double disc = b * b - q;

	return disc < 0 ? -1 : -b - sqrt(disc);
}

/* Every ray that hits the lit side of the sphere gets its full diffuse
 * term: c = 0.1 + 0.9 (N.L) (white object, white light, no highlight). */
static void check_no_acne(struct vec3 centre, double radius)
{
	char text[512];
	struct scene *s;
	struct render_settings rs = { 1, RT_CLAMP_LEVEL };
	struct vec3 eye = vec3_add(centre, vec3_make(0, -4 * radius, radius));
	struct vec3 light = vec3_add(centre, vec3_make(3 * radius, -3 * radius, 4 * radius));
	int i, j, lit = 0;

	snprintf(text, sizeof(text), "1 1 1 sphere %.17g %.17g %.17g %.17g  1 1 1  0.1 0.9 0 0  1  "
		 "1 %.17g %.17g %.17g 1 1 1", centre.x, centre.y, centre.z, radius,
		 light.x, light.y, light.z);
	s = support_prepared(text, false);
	for (i = 0; i < 40; i++) {
		for (j = 0; j < 40; j++) {
			struct vec3 target = vec3_add(centre, vec3_make(radius * (i - 19.5) / 20.0, 0,
									 radius * (j - 19.5) / 20.0));
			struct ray r = ray_make(eye.x, eye.y, eye.z, target.x - eye.x,
						target.y - eye.y, target.z - eye.z);
			double t = hit_sphere(r, centre, radius), nl;
			struct vec3 p, n;
			struct color c;

			if (t < 0)
				continue;
			p = ray_at(&r, t);
			n = vec3_normalize(vec3_sub(p, centre));
			nl = vec3_dot(n, vec3_normalize(vec3_sub(light, p)));
			c = render_trace(s, &rs, &r, 1, NULL);
			if (nl > 1e-3) {
				lit++;
				assert_near(c.r, 0.1 + 0.9 * nl, 1e-6);
			} else if (nl < -1e-3) {
				assert_near(c.r, 0.1, 1e-9);
			}
		}
	}
	assert_true(lit > 100);
	scene_destroy(s);
}

static void test_render_no_shadow_acne(void **state)
{
	(void)state;
	check_no_acne(vec3_make(0, 0, 0), 10);
	check_no_acne(vec3_make(40, 0, 10), 10);
	/* Far from the origin, where the coordinates' rounding is large. */
	check_no_acne(vec3_make(1e4, -2e4, 3e3), 50);
	check_no_acne(vec3_make(1e6, 1e6, 1e6), 0.5);
}

static void test_render_no_acne_on_floor_and_triangle(void **state)
{
	/* The floor lit from (0, 0, 100), seen from straight above at points
	 * of white tiles: N.L and R.L are both (0, 0, 1).(L): with P =
	 * (x, y, 0), L = (-x, -y, 100) / |.|, c = 0.4 + 0.2 N.L + 0.2 R.L
	 * where R = (0, 0, 1), so c = 0.4 + 0.4 * 100 / |Lp - P|. */
	struct scene *s = support_prepared("1 1 0 1 0 0 100 1 1 1", true);
	struct render_settings rs = { 1, RT_CLAMP_LEVEL };
	int i, j;

	(void)state;
	for (i = -20; i < 20; i++) {
		for (j = -20; j < 20; j++) {
			/* Tile centres with i + j even: white. */
			double x = 20 * i + 10, y = 20 * j + 10 + (i + j) % 2 * 20.0;
			struct ray r = ray_make(x + 0.37, y - 0.29, 50, 0, 0, -1);
			struct color c = render_trace(s, &rs, &r, 1, NULL);
			double dist = sqrt((x + 0.37) * (x + 0.37) + (y - 0.29) * (y - 0.29) + 1e4);
			assert_near(c.r, 0.4 + 0.4 * 100 / dist, 1e-9);
		}
	}
	scene_destroy(s);
}

/* A floor point P = (x, 0, 0) right beside a blocker standing on the floor
 * at the origin, lit from behind the blocker at (-100, 0, 5): shadowed,
 * so only the ambient 0.4 of the white tile is left.  (P lies in tile
 * (25, 25), white.)  The view ray reaches P from O = (x + 1, 0, x / 10),
 * a slope of x / 10 that stays under a sphere resting on the floor (its
 * surface is at least X^2 / 20 high, and X^2 / 20 > (X - x) x / 10 for
 * every X > x). */
static void check_no_leak(const char *blocker, double x)
{
	char text[256];
	struct scene *s;
	struct render_settings rs = { 1, RT_CLAMP_LEVEL };
	struct vec3 p = vec3_make(x, 0, 0), o = vec3_make(x + 1, 0, x / 10);
	struct vec3 lp = vec3_make(-100, 0, 5);
	struct ray r = ray_make(o.x, o.y, o.z, p.x - o.x, p.y - o.y, p.z - o.z);
	struct vec3 l = vec3_normalize(vec3_sub(lp, p));
	struct vec3 refl = vec3_make(r.dir.x, r.dir.y, -r.dir.z);
	struct color c;

	snprintf(text, sizeof(text), "1 1 1 %s  1 1 1  0 0 0 0 1  1 -100 0 5 1 1 1", blocker);
	s = support_prepared(text, true);
	c = render_trace(s, &rs, &r, 1, NULL);
	if (fabs(c.r - 0.4) > 1e-12) {
		print_error("light leaks at (%g, 0, 0) beside %s: %g\n", x, blocker, c.r);
		fail();
	}
	scene_destroy(s);
	/* The control: without the blocker the point is lit.  N = +z faces
	 * the ray, R = d - 2 (d.N) N mirrors d's z, and the floor's 0.4 0.2
	 * 0.2, shininess 1 give c = 0.4 + 0.2 N.L + 0.2 R.L. */
	s = support_prepared("1 1 0 1 -100 0 5 1 1 1", true);
	c = render_trace(s, &rs, &r, 1, NULL);
	assert_true(vec3_dot(refl, l) > 0);
	assert_near(c.r, 0.4 + 0.2 * l.z + 0.2 * vec3_dot(refl, l), 1e-9);
	scene_destroy(s);
}

static void test_render_no_light_leaks(void **state)
{
	static const double xs[] = { 0.5, 0.1, 0.01, 1e-3, 1e-4 };
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(xs) / sizeof(xs[0]); i++) {
		/* A sphere resting on the floor. */
		check_no_leak("sphere 0 0 10 10", xs[i]);
		/* A triangle standing on the floor in the plane x = 0. */
		check_no_leak("triangle 0 -10 0  0 10 0  0 0 20", xs[i]);
	}
}

/* Far up the z axis, where the coordinates' rounding (ulp(1e10) = 2e-6)
 * is larger than RT_EPSILON: the offset must grow with |z| as with |x|
 * and |y|, or shadow rays start below the surface and the surface shadows
 * itself.  A radius-1 sphere centred at (0, 0, z) (so |x|, |y| <= 1 on
 * it), white, KA 0.1, KD 0.9, lit from centre + 1e5 (3, -3, 4) and seen
 * from centre + 1e5 (0, -4, 1), both much further than the offset
 * (1e-6 z): at each visible point Q = centre + N of a grid of normals,
 * c = 0.1 + 0.9 max(N.L, 0), where nothing but the sphere itself could
 * shadow Q. */
static void check_lit_far_up(double z)
{
	char text[512];
	struct scene *s;
	struct render_settings rs = { 1, RT_CLAMP_LEVEL };
	struct vec3 centre = vec3_make(0, 0, z);
	struct vec3 eye = vec3_add(centre, vec3_make(0, -4e5, 1e5));
	struct vec3 light = vec3_add(centre, vec3_make(3e5, -3e5, 4e5));
	int i, j, lit = 0;

	snprintf(text, sizeof(text), "1 1 1 sphere 0 0 %.17g 1  1 1 1  0.1 0.9 0 0  1  "
		 "1 %.17g %.17g %.17g 1 1 1", z, light.x, light.y, light.z);
	s = support_prepared(text, false);
	for (i = 0; i < 24; i++) {
		for (j = 0; j < 48; j++) {
			double th = 3.14159265358979 * (i + 0.5) / 24, ph = 6.28318530717959 * j / 48;
			struct vec3 n = vec3_make(sin(th) * cos(ph), sin(th) * sin(ph), cos(th));
			struct vec3 q = vec3_add(centre, n);
			struct vec3 to_eye = vec3_sub(eye, q);
			struct ray r;
			struct color c;
			double nl = vec3_dot(n, vec3_normalize(vec3_sub(light, q)));

			/* Seen (N faces the eye) and lit well enough that acne
			 * shows: N.L > 0.02, a loss of at least 0.018. */
			if (vec3_dot(n, to_eye) <= 0.05 * vec3_length(to_eye) || nl < 0.02)
				continue;
			r = ray_make(eye.x, eye.y, eye.z, -to_eye.x, -to_eye.y, -to_eye.z);
			c = render_trace(s, &rs, &r, 1, NULL);
			lit++;
			if (fabs(c.r - (0.1 + 0.9 * nl)) > 1e-4) {
				print_error("sphere at z = %g, normal (%.3f, %.3f, %.3f): %.9g, expected "
					    "%.9g (N.L = %.6f)\n", z, n.x, n.y, n.z, c.r, 0.1 + 0.9 * nl, nl);
				fail();
			}
		}
	}
	assert_true(lit > 100);
	scene_destroy(s);
}

/* The same far up with a plane: the triangle (-1, -1, z - 1) (1, -1, z - 1)
 * (0, 1, z + 1), whose normal is (0, -4, 4) / |.| = (0, -1, 1) / sqrt(2),
 * seen from (0, -2e5, z + 2e5) at points P = (x, y, z + y) and lit from
 * (0, 3e5, z + 4e5): c = 0.1 + 0.9 N.L with L = (Lp - P) / |.|. */
static void check_plane_lit_far_up(double z)
{
	char text[512];
	struct scene *s;
	struct render_settings rs = { 1, RT_CLAMP_LEVEL };
	struct vec3 eye = vec3_make(0, -2e5, z + 2e5), light = vec3_make(0, 3e5, z + 4e5);
	struct vec3 n = vec3_make(0, -sqrt(0.5), sqrt(0.5));
	int i, j;

	snprintf(text, sizeof(text), "1 1 1 triangle -1 -1 %.17g  1 -1 %.17g  0 1 %.17g  "
		 "1 1 1  0.1 0.9 0 0  1  1 0 %.17g %.17g 1 1 1", z - 1, z - 1, z + 1, light.y,
		 light.z);
	s = support_prepared(text, false);
	for (i = 0; i < 20; i++) {
		for (j = 0; j < 20; j++) {
			/* Inside the triangle: y in (-1, 1), |x| < (1 - y) / 2. */
			double y = -0.95 + 1.8 * i / 19.0, x = (1 - y) / 2 * (-0.9 + 1.8 * j / 19.0);
			struct vec3 p = vec3_make(x, y, z + y);
			double nl = vec3_dot(n, vec3_normalize(vec3_sub(light, p)));
			struct ray r = ray_make(eye.x, eye.y, eye.z, p.x - eye.x, p.y - eye.y, p.z - eye.z);
			struct color c = render_trace(s, &rs, &r, 1, NULL);

			if (fabs(c.r - (0.1 + 0.9 * nl)) > 1e-4) {
				print_error("plane at z = %g, point (%.3f, %.3f): %.9g, expected %.9g\n", z,
					    x, y, c.r, 0.1 + 0.9 * nl);
				fail();
			}
		}
	}
	scene_destroy(s);
}

/* Below about 1e9 the rounding of a point is still under RT_EPSILON, so
 * that an offset blind to |z| shows no acne yet; those heights check the
 * lighting alone.  At 1e10 and 3e10 it must have grown with |z|. */
static void test_render_no_acne_far_up_the_z_axis(void **state)
{
	static const double zs[] = { 1e6, 1e7, 1e8, 1e9, 1e10, 3e10 };
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(zs) / sizeof(zs[0]); i++) {
		check_lit_far_up(zs[i]);
		check_plane_lit_far_up(zs[i]);
	}
}

/* An eye very far away (1e7 from the scene): the offsets of the shadow and
 * reflection rays belong to the hit point P = (0, 0, 0), not to the eye,
 * whose size would make them 10 units long and let them jump over what
 * lies close to P.  The view ray comes along (0, 1, -1) / sqrt(2) to P on
 * the plane triangle, as at_plane(). */
static struct ray at_plane_from_afar(void)
{
	return ray_make(0, -1e7, 1e7, 0, 1, -1);
}

static void test_render_far_eye_shadow_and_reflection(void **state)
{
	struct color c;

	(void)state;
	/* The light at (0, 0, 50) behind a radius-2 sphere at (0, 0, 4), 2
	 * above P (and 4 / sqrt(2) = 2.8 from the view ray): in shadow, only
	 * the ambient 0.1 C of test_render_shadowed_point. */
	c = trace("1 1 2 " PLANE "1 0.5 0.25  0.1 0.5 0.4 0  2  "
		  "sphere 0 0 4 2  1 1 1  0 0 0 0 1  1 0 0 50 1 1 1", at_plane_from_afar());
	assert_color(c, 0.1, 0.05, 0.025, 1e-12);
	/* Without the sphere the point is lit (test_render_plane_lit). */
	c = trace("1 1 1 " PLANE "1 0.5 0.25  0.1 0.5 0.4 0  2  1 0 0 50 1 1 1", at_plane_from_afar());
	assert_color(c, 0.8, 0.4, 0.2, 1e-9);
	/* The mirror of MIRROR_SCENE with its red sphere (radius 2, KA 0.6)
	 * at (0, 3, 3), 3 sqrt(2) = 4.2 from P along R = (0, 1, 1) / sqrt(2)
	 * (and 4.2 from the view ray): c = (0, 0, 0.2) + 0.5 * 0.6 (1, 0.5, 0). */
	c = trace("2 1 2 " PLANE "0 0 1  0.2 0 0 0.5  1  sphere 0 3 3 2  1 0.5 0  0.6 0 0 0 1  0",
		  at_plane_from_afar());
	assert_color(c, 0.3, 0.15, 0.2, 1e-12);
}

static void test_render_color_to_rgb8(void **state)
{
	static const struct {
		double v;
		uint8_t want;
	} cases[] = {
		{ 0.0, 0 }, { 1.0, 255 }, { 1.5, 255 }, { -0.5, 0 },
		{ 0.5, 128 },		/* 127.5 rounds away from zero */
		{ 0.25, 64 },		/* 63.75 */
		{ 0.2, 51 },		/* 51 */
		{ 0.001, 0 },		/* 0.255 */
		{ 0.002, 1 },		/* 0.51 */
		{ 0.998, 254 },		/* 254.49 */
		{ 0.999, 255 },		/* 254.745 */
		{ NAN, 0 }, { -0.0, 0 }, { INFINITY, 255 }, { -INFINITY, 0 },
		{ 1e-300, 0 }, { 4.9e-324, 0 }, { -4.9e-324, 0 },
		{ 0x1.0000000000001p0, 255 }, { 0x1.fffffffffffffp-1, 255 },
		{ 127.5 / 255.0, 128 },
		{ 0x1.fffffffffffffp-2, 127 },	/* just below 1/2: 127.49999... */
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(cases) / sizeof(cases[0]); i++) {
		uint8_t out[3];
		render_color_to_rgb8(color_make(cases[i].v, 0.25, 1.0), out);
		if (out[0] != cases[i].want) {
			print_error("%g -> %d, expected %d\n", cases[i].v, out[0], cases[i].want);
			fail();
		}
		assert_int_equal(out[1], 64);
		assert_int_equal(out[2], 255);
	}
}

static void test_render_ray_counts(void **state)
{
	struct ray_counts n;

	(void)state;
	/* Two lights in front of P and one behind: two shadow rays (a light
	 * behind the surface needs none). */
	trace_counted("1 1 1 " PLANE "1 1 1  0.1 0.5 0 0  1  3 0 0 50 1 1 1  10 0 50 1 1 1  "
		      "0 0 -50 1 1 1", RT_CLAMP_LEVEL, at_plane(), &n);
	assert_int_equal(n.shadow, 2);
	assert_int_equal(n.reflection, 0);
	assert_int_equal(n.primary, 0);
	/* A miss: nothing at all. */
	trace_counted("1 1 1 " PLANE "1 1 1  0.1 0.5 0 0  1  1 0 0 50 1 1 1", RT_CLAMP_LEVEL,
		      ray_make(0, -100, 100, 0, -1, 0), &n);
	assert_int_equal(n.shadow, 0);
}

/* Renders a region of the course scene (with its floor) at size px. */
static void render_region(const struct scene *s, const struct camera *cam, int threads,
			  int x0, int y0, int x1, int y1, struct image *img,
			  struct ray_counts *counts)
{
	struct render_job job;

	render_job_init(&job, s, cam, threads);
	render_fixture_region(&job, x0, y0, x1, y1, img, counts);
}

/* At 99 pixels the last blocks of 16 are cut to 3 pixels on both axes. */
static void test_render_threads_bit_identical(void **state)
{
	static const int threads[] = { 2, 3, 7 };
	struct scene *s = support_prepared(course_scene, true);
	struct camera cam;
	struct ray_counts n1, n;
	struct image one, other;
	size_t i, lit = 0;

	(void)state;
	support_default_camera(&cam, 99);
	render_region(s, &cam, 1, 0, 0, 99, 99, &one, &n1);
	assert_int_equal(n1.primary, 99 * 99);
	assert_true(n1.shadow > 0);
	assert_true(n1.reflection > 0);
	for (i = 0; i < 99 * 99 * 3; i++)
		lit += one.pixels[i] != 0;
	assert_true(lit > 1000);
	for (i = 0; i < sizeof(threads) / sizeof(threads[0]); i++) {
		render_region(s, &cam, threads[i], 0, 0, 99, 99, &other, &n);
		assert_memory_equal(one.pixels, other.pixels, 99 * 99 * 3);
		assert_same_ray_counts(n, n1);
		image_free(&other);
	}
	image_free(&one);
	scene_destroy(s);
}

static void test_render_region_matches_full_image(void **state)
{
	static const int regions[][4] = {
		{ 10, 20, 50, 33 }, { 0, 0, 1, 1 }, { 95, 95, 96, 96 }, { 0, 40, 96, 41 }, { 30, 0, 31, 96 },
	};
	struct scene *s = support_prepared(course_scene, true);
	struct camera cam;
	struct ray_counts n;
	struct image full, part;
	size_t k;
	int y;

	(void)state;
	support_default_camera(&cam, 96);
	render_region(s, &cam, 3, 0, 0, 96, 96, &full, NULL);
	for (k = 0; k < sizeof(regions) / sizeof(regions[0]); k++) {
		const int *g = regions[k];
		render_region(s, &cam, 2, g[0], g[1], g[2], g[3], &part, &n);
		assert_int_equal(n.primary, (uint64_t)(g[2] - g[0]) * (uint64_t)(g[3] - g[1]));
		for (y = g[1]; y < g[3]; y++)
			assert_memory_equal(part.pixels + (size_t)(y - g[1]) * (size_t)part.width * 3,
					    full.pixels + ((size_t)y * 96 + (size_t)g[0]) * 3,
					    (size_t)part.width * 3);
		image_free(&part);
	}
	image_free(&full);
	scene_destroy(s);
}

/* What band_done saw: each band's rows as they were when it was told. */
struct band_log {
	const struct image *img;
	int band_rows, threads;
	int calls[128];
	uint8_t *seen;			/* a copy of the image, band by band */
	int bad_thread;
};

static void band_log_done(void *ctx, int band, int thread)
{
	struct band_log *log = ctx;
	size_t stride = (size_t)log->img->width * 3;
	int y0 = band * log->band_rows, y1 = y0 + log->band_rows;

	if (y1 > log->img->height)
		y1 = log->img->height;
	if (thread < 0 || thread >= log->threads)
		__atomic_store_n(&log->bad_thread, 1, __ATOMIC_RELAXED);
	__atomic_add_fetch(&log->calls[band], 1, __ATOMIC_RELAXED);
	memcpy(log->seen + (size_t)y0 * stride, log->img->pixels + (size_t)y0 * stride,
	       (size_t)(y1 - y0) * stride);
}

/* Every band is told once, by a thread of the job, when its rows are
 * final (the copy taken then is the finished image), for bands of any
 * height against the 16-row blocks, any number of threads, and regions;
 * the image is the one rendered without bands. */
static void test_render_bands_told_when_final(void **state)
{
	static const int band_rows[] = { 1, 10, 16, 64, 1000 };
	static const int threads[] = { 1, 2, 3, 7 };
	static const int regions[][4] = { { 0, 0, 99, 99 }, { 5, 17, 90, 80 }, { 40, 3, 41, 99 } };
	struct scene *s = support_prepared(course_scene, true);
	struct camera cam;
	struct diag d;
	size_t r, b, t;

	(void)state;
	support_default_camera(&cam, 99);
	for (r = 0; r < sizeof(regions) / sizeof(regions[0]); r++) {
		const int *g = regions[r];
		struct image plain;

		render_region(s, &cam, 1, g[0], g[1], g[2], g[3], &plain, NULL);
		for (b = 0; b < sizeof(band_rows) / sizeof(band_rows[0]); b++) {
			for (t = 0; t < sizeof(threads) / sizeof(threads[0]); t++) {
				size_t bytes = (size_t)plain.width * (size_t)plain.height * 3;
				int n_bands = (plain.height + band_rows[b] - 1) / band_rows[b], k;
				struct render_job job;
				struct band_log log;
				struct image img;

				memset(&log, 0, sizeof(log));
				log.img = &img;
				log.band_rows = band_rows[b];
				log.threads = threads[t];
				log.seen = calloc(1, bytes);
				assert_non_null(log.seen);
				render_job_init(&job, s, &cam, threads[t]);
				job.x0 = g[0];
				job.y0 = g[1];
				job.x1 = g[2];
				job.y1 = g[3];
				job.band_rows = band_rows[b];
				job.band_done = band_log_done;
				job.band_ctx = &log;
				assert_int_equal(image_alloc(&img, g[2] - g[0], g[3] - g[1], &d), 0);
				assert_int_equal(render_image(&job, &img, NULL, &d), 0);
				assert_memory_equal(img.pixels, plain.pixels, bytes);
				assert_memory_equal(log.seen, plain.pixels, bytes);
				assert_int_equal(log.bad_thread, 0);
				for (k = 0; k < 128; k++)
					assert_int_equal(log.calls[k], k < n_bands ? 1 : 0);
				free(log.seen);
				image_free(&img);
			}
		}
		image_free(&plain);
	}
	scene_destroy(s);
}

static void test_render_pixel_matches_trace(void **state)
{
	/* The image's pixel (px, py) is render_trace of camera_ray(px, py). */
	struct scene *s = support_prepared(course_scene, true);
	struct render_settings rs = { 4, RT_CLAMP_LEVEL };
	struct camera cam;
	struct image img;
	int px, py;

	(void)state;
	support_default_camera(&cam, 32);
	render_region(s, &cam, 1, 0, 0, 32, 32, &img, NULL);
	for (py = 0; py < 32; py += 5) {
		for (px = 0; px < 32; px += 3) {
			struct ray r = camera_ray(&cam, px, py);
			uint8_t want[3];
			render_color_to_rgb8(render_trace(s, &rs, &r, 1, NULL), want);
			assert_memory_equal(img.pixels + ((size_t)py * 32 + (size_t)px) * 3, want, 3);
		}
	}
	image_free(&img);
	scene_destroy(s);
}

static void test_render_errors_and_cancel(void **state)
{
	struct scene *s = support_parse(course_scene);
	struct render_job job;
	struct camera cam;
	struct image img;
	struct diag d;
	volatile sig_atomic_t cancel = 1;

	(void)state;
	support_default_camera(&cam, 8);
	assert_int_equal(image_alloc(&img, 8, 8, &d), 0);
	memset(&job, 0, sizeof(job));
	job.scene = s;
	job.camera = &cam;
	job.settings.recursion = 1;
	job.threads = 2;
	job.x1 = job.y1 = 8;
	/* Not prepared. */
	assert_int_equal(render_image(&job, &img, NULL, &d), -RT_E_INVALID);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	/* Regions outside the image, empty, or not the image's size. */
	job.x1 = 9;
	assert_int_equal(render_image(&job, &img, NULL, &d), -RT_E_INVALID);
	job.x1 = 8;
	job.x0 = 8;
	assert_int_equal(render_image(&job, &img, NULL, &d), -RT_E_INVALID);
	job.x0 = 0;
	job.y1 = 7;
	assert_int_equal(render_image(&job, &img, NULL, &d), -RT_E_INVALID);
	job.y1 = 8;
	/* Cancelled before it starts: interrupted. */
	job.cancel = &cancel;
	assert_int_equal(render_image(&job, &img, NULL, &d), -RT_E_INTERRUPTED);
	cancel = 0;
	assert_int_equal(render_image(&job, &img, NULL, &d), 0);
	image_free(&img);
	scene_destroy(s);
}

/* Spotlights and falloff: scenes built through the API (the classic
 * reader has neither), each value by hand from scene-format.md. */

/* text's scene (no floor) plus the light l, prepared. */
static struct scene *with_light(const char *text, const struct light *l)
{
	struct scene *s = support_parse(text);
	struct diag d;

	assert_int_equal(scene_add_light_full(s, l, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	return s;
}

static struct color trace_scene(const struct scene *s, struct ray r, struct ray_counts *counts)
{
	struct render_settings rs;

	rs.recursion = s->recursion;
	rs.clamp = RT_CLAMP_LEVEL;
	if (counts)
		memset(counts, 0, sizeof(*counts));
	return render_trace(s, &rs, &r, 1, counts);
}

static struct color trace_with_light(const char *text, const struct light *l, struct ray r,
				     struct ray_counts *counts)
{
	struct scene *s = with_light(text, l);
	struct color c = trace_scene(s, r, counts);

	scene_destroy(s);
	return c;
}

static struct light light_at(double x, double y, double z)
{
	struct light l;

	memset(&l, 0, sizeof(l));
	l.pos = vec3_make(x, y, z);
	l.color = color_make(1, 1, 1);
	return l;
}

static struct light spot_at(double x, double y, double z, struct vec3 axis, double cutoff)
{
	struct light l = light_at(x, y, z);

	l.spot = true;
	l.axis = axis;
	l.cutoff_deg = cutoff;
	return l;
}

/* The sphere of test_render_diffuse_and_specular_at_an_angle (KA 0.1,
 * KD 0.5, KS 0.3, shininess 2) without its light. */
#define SPHERE_NO_LIGHT "1 1 1 sphere 0 0 0 10  0.5 0.25 1  0.1 0.5 0.3 0  2  0"

/* A spotlight at (0, 30, 50) aimed straight down: P - Lp = (0, -30, -40)
 * makes acos(40 / 50) = 36.8699 degrees with the axis.  Inside the cone P
 * is lit as by a point light there (0.692 C); outside, a hard edge: the
 * ambient 0.1 C alone, and no shadow ray. */
static void test_render_spot_cone_hard_edge(void **state)
{
	struct light l = spot_at(0, 30, 50, vec3_make(0, 0, -7), 36.87);
	struct ray_counts n;
	struct color c;

	(void)state;
	c = trace_with_light(SPHERE_NO_LIGHT, &l, from_above(), &n);
	assert_color(c, 0.346, 0.173, 0.692, 1e-12);
	assert_int_equal(n.shadow, 1);
	l.cutoff_deg = 36.86;
	c = trace_with_light(SPHERE_NO_LIGHT, &l, from_above(), &n);
	assert_color(c, 0.05, 0.025, 0.1, 1e-15);
	assert_int_equal(n.shadow, 0);
	/* Aimed away: nothing; aimed along P - Lp, lit with a cone of 1e-3. */
	l.axis = vec3_make(0, 0, 1);
	l.cutoff_deg = 90;
	c = trace_with_light(SPHERE_NO_LIGHT, &l, from_above(), NULL);
	assert_color(c, 0.05, 0.025, 0.1, 1e-15);
	l.axis = vec3_make(0, -30, -40);
	l.cutoff_deg = 1e-3;
	c = trace_with_light(SPHERE_NO_LIGHT, &l, from_above(), NULL);
	assert_color(c, 0.346, 0.173, 0.692, 1e-12);
}

/* The edge cases of the cone: a cutoff of exactly 90 lights the points at
 * right angles to the axis (the plane's P = (0, 0, 0) under a light at
 * (0, 0, 50) aimed along +x), 89.99 does not; 180 lights even the point
 * straight behind the axis, 179.99 does not.  Lit: 0.8 C, as in
 * test_render_plane_lit; dark: 0.1 C. */
static void test_render_spot_right_angle_and_180(void **state)
{
	const char *plane = "1 1 1 " PLANE "1 0.5 0.25  0.1 0.5 0.4 0  2  0";
	struct light l = spot_at(0, 0, 50, vec3_make(1, 0, 0), 90);
	struct color c;

	(void)state;
	c = trace_with_light(plane, &l, at_plane(), NULL);
	assert_color(c, 0.8, 0.4, 0.2, 1e-12);
	l.cutoff_deg = 89.99;
	c = trace_with_light(plane, &l, at_plane(), NULL);
	assert_color(c, 0.1, 0.05, 0.025, 1e-15);
	l.axis = vec3_make(0, 0, 1);
	l.cutoff_deg = 180;
	c = trace_with_light(plane, &l, at_plane(), NULL);
	assert_color(c, 0.8, 0.4, 0.2, 1e-12);
	l.cutoff_deg = 179.99;
	c = trace_with_light(plane, &l, at_plane(), NULL);
	assert_color(c, 0.1, 0.05, 0.025, 1e-15);
}

/* A spotlight is shadowed like a point light: the sphere of
 * test_render_shadowed_point blocks it. */
static void test_render_spot_shadowed(void **state)
{
	struct light l = spot_at(0, 0, 50, vec3_make(0, 0, -1), 20);
	struct ray_counts n;
	struct color c;

	(void)state;
	c = trace_with_light("1 1 2 " PLANE "1 0.5 0.25  0.1 0.5 0.4 0  2  "
			     "sphere 0 0 25 2  1 1 1  0 0 0 0 1  0", &l, at_plane(), &n);
	assert_color(c, 0.1, 0.05, 0.025, 1e-12);
	assert_int_equal(n.shadow, 1);
}

/* Falloff: the light at (0, 0, 50) is d = 40 from P = (0, 0, 10); with a
 * falloff of 1/1600, a = exp(-1) on the diffuse term (KA 0.4, KD 0.5:
 * c = (0.4 + 0.5 / e) C) and on the specular one (KS 0.3, R.L = 1:
 * c = 0.3 / e C), never on the ambient. */
static void test_render_falloff_scales_diffuse_and_specular(void **state)
{
	struct light l = light_at(0, 0, 50);
	const double a = exp(-1.0);
	struct color c;

	(void)state;
	l.falloff = 1.0 / 1600.0;
	c = trace_with_light("1 1 1 sphere 0 0 0 10  0.5 0.25 1  0.4 0.5 0 0  3  0", &l,
			     from_above(), NULL);
	assert_color(c, 0.5 * (0.4 + 0.5 * a), 0.25 * (0.4 + 0.5 * a), 0.4 + 0.5 * a, 1e-15);
	c = trace_with_light("1 1 1 sphere 0 0 0 10  0.5 0.25 1  0 0 0.3 0  10  0", &l,
			     from_above(), NULL);
	assert_color(c, 0.15 * a, 0.075 * a, 0.3 * a, 1e-15);
	/* The angle case: d = 50, falloff 1e-4: a = exp(-0.25) on 0.6 C. */
	l = light_at(0, 30, 50);
	l.falloff = 1e-4;
	c = trace_with_light(SPHERE_NO_LIGHT, &l, from_above(), NULL);
	assert_color(c, 0.5 * (0.1 + 0.592 * exp(-0.25)), 0.25 * (0.1 + 0.592 * exp(-0.25)),
		     0.1 + 0.592 * exp(-0.25), 1e-12);
}

/* A point light without falloff and a spotlight with one, in that order:
 * the terms add, each with its own attenuation and cone, and a coloured
 * light keeps its colour. */
static void test_render_point_then_spot_add_up(void **state)
{
	struct scene *s = support_parse("1 1 1 sphere 0 0 0 10  1 1 1  0.1 0.5 0 0  1  "
					"1 0 0 50 1 0 0");
	struct light l = spot_at(0, 0, 80, vec3_make(0, 0, -1), 5);
	struct color c;
	struct diag d;

	(void)state;
	l.color = color_make(0, 0, 1);
	l.falloff = 1e-3;
	assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	l.pos = vec3_make(0, 100, 10.5);	/* its cone misses P */
	l.color = color_make(0, 1, 0);
	assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	/* Red: 0.1 + 0.5; blue: 0.1 + 0.5 exp(-70^2 1e-3); green: 0.1. */
	c = trace_scene(s, from_above(), NULL);
	assert_color(c, 0.6, 0.1, 0.1 + 0.5 * exp(-4.9), 1e-12);
	scene_destroy(s);
}

/* Lights that cone and falloff leave alone give the classic path's bits:
 * the course scene with one of its lights added again as a spotlight of
 * cutoff 180 (which lights everything) renders as with it added as a
 * point light, byte for byte, through the other code path. */
static void test_render_full_path_matches_classic(void **state)
{
	struct scene *a = support_parse(course_scene), *b = support_parse(course_scene);
	struct light l = spot_at(70, 70, 70, vec3_make(-1, -1, -1), 180);
	struct camera cam;
	struct image ia, ib;
	struct diag d;

	(void)state;
	l.color = color_make(0.3, 0.2, 0.1);
	assert_int_equal(scene_add_light_full(a, &l, &d), 0);
	assert_int_equal(scene_add_light(b, l.pos, l.color, &d), 0);
	assert_int_equal(scene_add_floor(a, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_add_floor(b, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_prepare(a, 1, &d), 0);
	assert_int_equal(scene_prepare(b, 1, &d), 0);
	assert_int_equal(a->n_special_lights, 1);
	assert_int_equal(b->n_special_lights, 0);
	support_default_camera(&cam, 48);
	render_region(a, &cam, 2, 0, 0, 48, 48, &ia, NULL);
	render_region(b, &cam, 2, 0, 0, 48, 48, &ib, NULL);
	assert_memory_equal(ia.pixels, ib.pixels, (size_t)48 * 48 * 3);
	image_free(&ia);
	image_free(&ib);
	scene_destroy(a);
	scene_destroy(b);
}

/* The nearfar camera sees nothing nearer than its plane: a sphere between
 * the eye and the plane (y in [-197, -193], the plane at y = -190 on the
 * axis) vanishes from the image, which is then the image without it; with
 * no near plane it fills the view.  Ambient light only, so that it casts
 * no shadow. */
static void test_render_near_plane_hides_near_objects(void **state)
{
	const char *base = "1 1 1 sphere 0 0 0 30  0 1 0  0.5 0 0 0  1  0";
	const char *with_near = "1 1 2 sphere 0 0 0 30  0 1 0  0.5 0 0 0  1  "
				"sphere 0 -195 10 2  1 0 0  1 0 0 0  1  0";
	struct scene *a = support_prepared(base, false), *b = support_prepared(with_near, false);
	struct camera_params cp;
	struct camera cam;
	struct image ia, ib;
	struct diag d;

	(void)state;
	camera_params_default(&cp);
	cp.near = 10;
	cp.aspect = 1;
	assert_int_equal(camera_init(&cam, &cp, 16, &d), 0);
	render_region(a, &cam, 1, 0, 0, 16, 16, &ia, NULL);
	render_region(b, &cam, 1, 0, 0, 16, 16, &ib, NULL);
	assert_memory_equal(ia.pixels, ib.pixels, (size_t)16 * 16 * 3);
	/* The green sphere's centre pixel: 0.5 green. */
	assert_int_equal(ia.pixels[(8 * 16 + 8) * 3 + 1], 128);
	image_free(&ib);
	cp.near = 0;
	assert_int_equal(camera_init(&cam, &cp, 16, &d), 0);
	render_region(b, &cam, 1, 0, 0, 16, 16, &ib, NULL);
	assert_int_equal(ib.pixels[(8 * 16 + 8) * 3 + 0], 255);
	assert_int_equal(ib.pixels[(8 * 16 + 8) * 3 + 1], 0);
	image_free(&ia);
	image_free(&ib);
	scene_destroy(a);
	scene_destroy(b);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_render_background_is_black, test_render_ambient_only,
			   test_render_diffuse_head_on, test_render_specular_is_tinted,
			   test_render_diffuse_and_specular_at_an_angle,
			   test_render_coloured_light, test_render_lights_add_up,
			   test_render_lights_past_the_first_batch,
			   test_render_only_the_last_light_lights, test_render_plane_lit,
			   test_render_shadowed_point, test_render_blocker_beyond_light,
			   test_render_light_behind_open_surface,
			   test_render_highlight_needs_positive_r_dot_l,
			   test_render_one_reflection_bounce,
			   test_render_reflection_level_argument,
			   test_render_clamp_level_versus_final, test_render_no_shadow_acne,
			   test_render_no_acne_on_floor_and_triangle,
			   test_render_no_light_leaks, test_render_no_acne_far_up_the_z_axis,
			   test_render_far_eye_shadow_and_reflection, test_render_color_to_rgb8,
			   test_render_ray_counts, test_render_threads_bit_identical,
			   test_render_region_matches_full_image,
			   test_render_bands_told_when_final, test_render_pixel_matches_trace,
			   test_render_errors_and_cancel, test_render_spot_cone_hard_edge,
			   test_render_spot_right_angle_and_180, test_render_spot_shadowed,
			   test_render_falloff_scales_diffuse_and_specular,
			   test_render_point_then_spot_add_up,
			   test_render_full_path_matches_classic,
			   test_render_near_plane_hides_near_objects))
