/* floor_set_textures: the texel under a point of each kind of floor, one
 * image over each cell, upright (the image's top row along the cell's +y
 * edge, its left column along -x), nearest texel, bytes over 255; a black
 * cell keeps black without its own image; the highlight's colour stays the
 * cell's (shape_specular_color_at), and an untextured floor has none of
 * its own; an image that cannot be read is RT_E_IO naming it. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "whitted/image.h"
#include "support.h"

static char dir[] = "/tmp/test_floor_texture.XXXXXX";
static char white_path[64], black_path[64];

/* 2 x 2, top row (255, 0, 0) (0, 255, 0), bottom row (0, 0, 255) (51, 102, 153). */
static const uint8_t white_px[12] = { 255, 0, 0, 0, 255, 0, 0, 0, 255, 51, 102, 153 };
static const uint8_t black_px[3] = { 10, 20, 30 };

/* Writes the size x size image of these pixels to path; -1 where it
 * cannot. */
static int write_image(const char *path, enum image_format format, int size, const uint8_t *px)
{
	struct image img;
	struct diag d;
	int rc;

	if (image_alloc(&img, size, size, &d) < 0)
		return -1;
	memcpy(img.pixels, px, (size_t)size * size * 3);
	rc = image_write(&img, path, format, NULL, &d);
	image_free(&img);
	return rc < 0 ? -1 : 0;
}

static int setup(void **state)
{
	(void)state;
	if (!mkdtemp(dir))
		return -1;
	snprintf(white_path, sizeof(white_path), "%s/w.bmp", dir);
	snprintf(black_path, sizeof(black_path), "%s/b.png", dir);
	if (write_image(white_path, RT_FORMAT_BMP, 2, white_px) < 0 ||
	    write_image(black_path, RT_FORMAT_PNG, 1, black_px) < 0)
		return -1;
	return 0;
}

static int teardown(void **state)
{
	(void)state;
	unlink(white_path);
	unlink(black_path);
	return rmdir(dir);
}

static void assert_rgb(struct color c, int r, int g, int b)
{
	assert_near(c.r, r / 255.0, 1e-15);
	assert_near(c.g, g / 255.0, 1e-15);
	assert_near(c.b, b / 255.0, 1e-15);
}

static void test_floor_texture_classic(void **state)
{
	struct shape *fl = floor_create(1000, 20);
	struct color spec;
	struct diag d;

	(void)state;
	assert_false(shape_specular_color_at(fl, vec3_make(-495, -495, 0), &spec));
	assert_int_equal(floor_set_textures(fl, white_path, NULL, &d), 0);
	/* Cell (0, 0) is [-500, -480)^2, white: its four quarters. */
	assert_rgb(shape_color_at(fl, vec3_make(-495, -485, 0)), 255, 0, 0);
	assert_rgb(shape_color_at(fl, vec3_make(-485, -485, 0)), 0, 255, 0);
	assert_rgb(shape_color_at(fl, vec3_make(-495, -495, 0)), 0, 0, 255);
	assert_rgb(shape_color_at(fl, vec3_make(-485, -495, 0)), 51, 102, 153);
	/* The same image over cell (2, 0), 40 further along x. */
	assert_rgb(shape_color_at(fl, vec3_make(-455, -485, 0)), 255, 0, 0);
	/* Cell (1, 0) is black and has no image. */
	assert_rgb(shape_color_at(fl, vec3_make(-475, -485, 0)), 0, 0, 0);
	assert_true(shape_specular_color_at(fl, vec3_make(-485, -485, 0), &spec));
	assert_rgb(spec, 255, 255, 255);
	assert_true(shape_specular_color_at(fl, vec3_make(-475, -485, 0), &spec));
	assert_rgb(spec, 0, 0, 0);
	shape_destroy(fl);
}

static void test_floor_texture_infinite_and_black(void **state)
{
	struct shape *fl = floor_create_view(INFINITY, 10, &floor_classic_material);
	struct diag d;

	(void)state;
	assert_int_equal(floor_set_textures(fl, white_path, black_path, &d), 0);
	/* Cell (0, 0) is [0, 10)^2; cell (-1, -1) is white too. */
	assert_rgb(shape_color_at(fl, vec3_make(2, 8, 0)), 255, 0, 0);
	assert_rgb(shape_color_at(fl, vec3_make(-8, -2, 0)), 255, 0, 0);
	assert_rgb(shape_color_at(fl, vec3_make(-2, -8, 0)), 51, 102, 153);
	/* Cell (-1, 0) is black: its image, one texel. */
	assert_rgb(shape_color_at(fl, vec3_make(-5, 5, 0)), 10, 20, 30);
	shape_destroy(fl);
}

static void test_floor_texture_unreadable(void **state)
{
	struct shape *fl = floor_create(1000, 20);
	char path[96];
	struct diag d;

	(void)state;
	snprintf(path, sizeof(path), "%s/missing.png", dir);
	assert_int_equal(floor_set_textures(fl, white_path, path, &d), -RT_E_IO);
	assert_string_equal(d.file, path);
	shape_destroy(fl);
}

SUPPORT_MAIN_AROUND(setup, teardown,
		    SUPPORT_TESTS(test_floor_texture_classic,
				  test_floor_texture_infinite_and_black,
				  test_floor_texture_unreadable))
