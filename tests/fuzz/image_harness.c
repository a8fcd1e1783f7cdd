/* The fuzz target of the image readers (stb_image and the checks and the
 * P3 reader around it; the tile reader, libpng behind the same PNG
 * checks), shared by libFuzzer and the replay driver. */
#include "grade/grade_impl.h"
#include "harness.h"
#include "whitted/image.h"
#include "whitted/tile.h"

/* The bytes as a tile: its head alone, then with its pixels. */
static void fuzz_tile(const uint8_t *data, size_t size)
{
	struct tile_info info;
	struct image img;
	struct diag d;

	if (tile_read_memory(data, size, "fuzz", &info, NULL, &d) < 0)
		return;
	if (tile_read_memory(data, size, "fuzz", &info, &img, &d) == 0)
		image_free(&img);
}

int fuzz_image_one(const uint8_t *data, size_t size)
{
	struct image img, t, diff;
	struct grade_figures f;
	struct diag d;

	fuzz_tile(data, size);
	if (image_read_memory(data, size, "fuzz", &img, NULL, &d) < 0)
		return 0;
	/* A big image (a few KB of zeros can hold millions of pixels) is
	 * only read: its figures would take the fuzzer's time, not test more. */
	if ((long)img.width * img.height > (1L << 20)) {
		image_free(&img);
		return 0;
	}
	if (grade_transform_map(&img, GRADE_MAP_MIRROR, &t, &d) == 0) {
		grade_figures_of(&img, &t, 1, 0, 0, &f);
		if (grade_diff_image(&img, &t, &diff, &d) == 0)
			image_free(&diff);
		image_free(&t);
	}
	image_free(&img);
	return 0;
}
