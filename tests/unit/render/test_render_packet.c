/* A block's rays in packets (render_packet.c) against one ray at a time:
 * the same image to the byte and the same ray counts, for scenes big
 * enough that packets are the default, with the classic lights and with a
 * spotlight and a falloff (render_direct_full), reflective shapes, glass
 * that reflects nothing, a light in the floor's plane (N.L = 0), a
 * region whose edges cut the 4x4 packets, and several threads. */
#define _POSIX_C_SOURCE 200809L	/* setenv */
#include <stdlib.h>
#include <string.h>

#include "accel/accel.h"
#include "accel/accel_tree.h"
#include "course_scene.h"
#include "render_fixture.h"
#include "support.h"
#include "whitted/camera.h"
#include "whitted/image.h"
#include "whitted/render.h"

static uint64_t rng_state;

static double rng(void)
{
	rng_state ^= rng_state >> 12;
	rng_state ^= rng_state << 25;
	rng_state ^= rng_state >> 27;
	return (double)((rng_state * 0x2545f4914f6cdd1du) >> 11) / 9007199254740992.0;
}

static double uniform(double lo, double hi)
{
	return lo + (hi - lo) * rng();
}

/* The course scene and 600 small spheres and triangles over it (some of
 * them mirrors, and with `glass` some of them glass that reflects nothing,
 * kr 0, whose hits only the shading one ray at a time can shade), the
 * floor, with `special` a spotlight with a falloff, and with `in_plane` a
 * light more in the floor's plane z = 0 (N.L = 0 on the whole floor). */
static struct scene *busy_scene(bool special, bool glass, bool in_plane)
{
	static const struct material dull = { { 0.8, 0.6, 0.4 }, 0.1, 0.6, 0.3, 0.0, 8, 0.0, 1.0 };
	static const struct material mirror = { { 0.9, 0.9, 1 }, 0.1, 0.4, 0.4, 0.5, 20, 0.0, 1.0 };
	static const struct material clear = { { 0.8, 1, 0.9 }, 0.1, 0.3, 0.5, 0.0, 40, 0.8, 1.5 };
	struct scene *s = support_parse(course_scene);
	struct diag d;
	int i;

	rng_state = 0x1234567u;
	for (i = 0; i < 600; i++) {
		struct vec3 c = vec3_make(uniform(-60, 60), uniform(-40, 60), uniform(2, 60));
		const struct material *m = rng() < 0.3 ? &mirror : glass && i % 5 == 1 ? &clear : &dull;
		struct shape *sh;

		if (i % 2)
			sh = sphere_create(c, uniform(0.5, 3), m);
		else
			sh = triangle_create(c, vec3_add(c, vec3_make(uniform(-4, 4), 0, uniform(-4, 4))),
					     vec3_add(c, vec3_make(uniform(-4, 4), uniform(-4, 4), 0)), m);
		assert_non_null(sh);
		assert_int_equal(scene_add_shape(s, sh, &d), 0);
	}
	if (special) {
		struct light l;

		memset(&l, 0, sizeof(l));
		l.pos = vec3_make(20, -60, 90);
		l.color = color_make(0.6, 0.5, 0.4);
		l.spot = true;
		l.axis = vec3_make(-0.2, 0.6, -1);
		l.cutoff_deg = 35;
		l.falloff = 1e-5;
		assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	}
	if (in_plane)
		assert_int_equal(scene_add_light(s, vec3_make(0, 150, 0), color_make(1, 1, 1), &d), 0);
	assert_int_equal(scene_add_floor(s, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	/* Big enough for the SIMD walks, under which packets run by
	 * default, where the processor has them. */
	if (accel_walk_usable(RT_SIMD_AVX2))
		assert_true(accel_packets_pay(s->accel));
	return s;
}

/* The region [x0, x1) x [y0, y1) at size 90 with WHITTED_PACKETS set to
 * `packets` ("0", "1" or NULL: the default). */
static void render_with(const struct scene *s, const char *packets, int threads, int x0,
			int y0, int x1, int y1, struct image *img, struct ray_counts *counts)
{
	struct camera cam;
	struct render_job job;

	if (packets)
		assert_int_equal(setenv("WHITTED_PACKETS", packets, 1), 0);
	else
		assert_int_equal(unsetenv("WHITTED_PACKETS"), 0);
	support_default_camera(&cam, 90);
	render_job_init(&job, s, &cam, threads);
	render_fixture_region(&job, x0, y0, x1, y1, img, counts);
	assert_int_equal(unsetenv("WHITTED_PACKETS"), 0);
}

static void check_same(bool special, bool glass, bool in_plane)
{
	static const char *const modes[] = { "1", NULL };
	static const int threads[] = { 1, 3 };
	struct scene *s = busy_scene(special, glass, in_plane);
	struct image one, other;
	struct ray_counts n1, n;
	size_t i, j, lit = 0, bytes = (size_t)(87 - 3) * (size_t)(79 - 6) * 3;

	render_with(s, "0", 1, 3, 6, 87, 79, &one, &n1);
	for (i = 0; i < bytes; i++)
		lit += one.pixels[i] != 0;
	/* The view's upper part is sky: about a third of the bytes lit. */
	assert_true(lit > bytes / 4);
	assert_true(n1.shadow > n1.primary && n1.reflection > 1000);
	assert_true(!glass || n1.refraction > 100);
	for (i = 0; i < sizeof(modes) / sizeof(modes[0]); i++)
		for (j = 0; j < sizeof(threads) / sizeof(threads[0]); j++) {
			render_with(s, modes[i], threads[j], 3, 6, 87, 79, &other, &n);
			assert_memory_equal(one.pixels, other.pixels, bytes);
			assert_same_ray_counts(n, n1);
			image_free(&other);
		}
	image_free(&one);
	scene_destroy(s);
}

static void test_render_packet_classic_lights_same_image(void **state)
{
	(void)state;
	check_same(false, false, false);
}

static void test_render_packet_spot_and_falloff_same_image(void **state)
{
	(void)state;
	check_same(true, false, false);
}

/* Glass that reflects nothing (kr 0): its hits need the transmitted ray,
 * which the packets' shading a hit a lane does not trace; they must go
 * to the shading of one ray at a time, whose image and counts these are. */
static void test_render_packet_glass_same_image(void **state)
{
	(void)state;
	check_same(false, true, false);
}

/* A light in the floor's plane: N.L is exactly 0 (+0 or -0) at every
 * floor point, where the light adds nothing and asks no shadow ray, in
 * the packets' shading as in one ray's (the same image and ray counts),
 * on the big tree's packets and on the course scene's small one. */
static void test_render_packet_light_in_a_surface_plane(void **state)
{
	struct scene *s = support_parse(course_scene);
	struct image one, other;
	struct ray_counts n1, n;
	struct diag d;

	(void)state;
	check_same(false, false, true);
	assert_int_equal(scene_add_light(s, vec3_make(0, 150, 0), color_make(1, 1, 1), &d), 0);
	assert_int_equal(scene_add_floor(s, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	render_with(s, "0", 1, 0, 0, 90, 90, &one, &n1);
	render_with(s, "1", 2, 0, 0, 90, 90, &other, &n);
	assert_memory_equal(one.pixels, other.pixels, (size_t)90 * 90 * 3);
	assert_same_ray_counts(n, n1);
	image_free(&one);
	image_free(&other);
	scene_destroy(s);
}

/* On a small tree (the course scene alone: packets a ray a lane by
 * default where the processor has AVX2, one ray at a time with SSE2
 * alone) the packets forced on give the same image too. */
static void test_render_packet_forced_on_a_small_tree(void **state)
{
	struct scene *s = support_parse(course_scene);
	struct image one, other;
	struct diag d;

	(void)state;
	assert_int_equal(scene_add_floor(s, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	render_with(s, "0", 2, 0, 0, 90, 90, &one, NULL);
	render_with(s, "1", 2, 0, 0, 90, 90, &other, NULL);
	assert_memory_equal(one.pixels, other.pixels, (size_t)90 * 90 * 3);
	image_free(&one);
	image_free(&other);
	scene_destroy(s);
}

/* A small tree's packets, a ray a lane in each set of instructions this
 * processor runs, with mirrors' reflections in packets down to the depth
 * limit and beyond (recursion 12), glass (whose reflections the shading
 * traces itself) and mirrors of every kind: the image and the ray counts
 * of one ray at a time. */
/* The course scene, 40 mirrors and some glass over it at recursion 12,
 * with `extra` more point lights (past RENDER_SHADOW_KEPT, the packets'
 * shading a hit a lane stands aside) and with `spot` a spotlight: the
 * packets' image and ray counts are single rays', in every set of
 * instructions the small tree's packets go in. */
static void check_small_tree(int extra, bool spot)
{
	static const struct material mirror = { { 0.9, 0.9, 1 }, 0.1, 0.4, 0.4, 0.6, 20, 0.0, 1.0 };
	static const struct material glass = { { 0.9, 1, 0.9 }, 0.1, 0.3, 0.4, 0.2, 30, 0.7, 1.5 };
	static const struct material clear = { { 0.8, 1, 0.9 }, 0.1, 0.3, 0.5, 0.0, 40, 0.8, 1.5 };
	static const enum rt_simd lanes[] = { RT_SIMD_BASE, RT_SIMD_AVX2, RT_SIMD_AVX512 };
	struct scene *s = support_parse(course_scene);
	struct image one, other;
	struct ray_counts n1, n;
	struct diag d;
	size_t k;
	int i, tested = 0;

	rng_state = 0x9876543u;
	for (i = 0; i < 40; i++) {
		struct vec3 c = vec3_make(uniform(-50, 50), uniform(-30, 50), uniform(2, 50));
		const struct material *m = i % 7 == 0 ? &glass : i % 7 == 3 ? &clear : &mirror;
		struct shape *sh = i % 2 ? sphere_create(c, uniform(2, 8), m)
				   : triangle_create(c, vec3_add(c, vec3_make(uniform(-9, 9), 0, uniform(-9, 9))),
						     vec3_add(c, vec3_make(uniform(-9, 9), uniform(-9, 9), 0)), m);
		assert_non_null(sh);
		assert_int_equal(scene_add_shape(s, sh, &d), 0);
	}
	for (i = 0; i < extra; i++)
		assert_int_equal(scene_add_light(s, vec3_make(uniform(-90, 90), uniform(-90, 90), uniform(20, 90)),
						 color_make(0.2, 0.15, 0.1), &d),
				 0);
	if (spot) {
		struct light l;

		memset(&l, 0, sizeof(l));
		l.pos = vec3_make(-20, -50, 80);
		l.color = color_make(0.5, 0.5, 0.6);
		l.spot = true;
		l.axis = vec3_make(0.1, 0.5, -1);
		l.cutoff_deg = 30;
		assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	}
	assert_int_equal(scene_set_recursion(s, 12, &d), 0);
	assert_int_equal(scene_add_floor(s, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_int_equal(scene_prepare(s, 1, &d), 0);
	assert_int_equal(s->accel->walk_set, RT_SIMD_BASE);
	render_with(s, "0", 1, 0, 0, 90, 90, &one, &n1);
	assert_true(n1.reflection > n1.primary / 2 && n1.refraction > 0);
	for (k = 0; k < sizeof(lanes) / sizeof(lanes[0]); k++) {
		if (k > 0 && !support_isa_part(k == 1 ? RT_SIMD_AVX2 : RT_SIMD_AVX512,
						accel_walk_usable(lanes[k])))
			continue;
		accel_set_rays(s->accel, lanes[k]);
		assert_int_equal(accel_packets_scatter_pay(s->accel), lanes[k] != RT_SIMD_BASE);
		render_with(s, "1", k == 1 ? 3 : 1, 0, 0, 90, 90, &other, &n);
		assert_memory_equal(one.pixels, other.pixels, (size_t)90 * 90 * 3);
		assert_same_ray_counts(n, n1);
		assert_int_equal(n.refraction, n1.refraction);
		image_free(&other);
		tested++;
	}
	assert_true(tested >= 1);
	image_free(&one);
	scene_destroy(s);
}

static void test_render_packet_small_tree_reflections(void **state)
{
	(void)state;
	check_small_tree(0, false);
}

static void test_render_packet_small_tree_many_lights_and_a_spot(void **state)
{
	(void)state;
	check_small_tree(5, false);	/* nine lights */
	check_small_tree(0, true);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_render_packet_classic_lights_same_image,
			   test_render_packet_spot_and_falloff_same_image,
			   test_render_packet_glass_same_image,
			   test_render_packet_light_in_a_surface_plane,
			   test_render_packet_forced_on_a_small_tree,
			   test_render_packet_small_tree_reflections,
			   test_render_packet_small_tree_many_lights_and_a_spot))
