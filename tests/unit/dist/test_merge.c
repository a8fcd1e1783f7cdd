/* The merge of region renders at the unit level: tiles written with
 * tile_write from a known image, cut unevenly (a last row and a last
 * column one pixel wide), must merge back to that image pixel for pixel,
 * and a missing last row or column of tiles must be reported as a gap
 * naming that region. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "whitted/merge.h"
#include "whitted/settings.h"
#include "whitted/tile.h"
#include "support.h"

#define FULL_W 37
#define FULL_H FULL_W

/* Cuts on each axis: the last row of cells is one pixel tall, the last
 * column one pixel wide. */
static const int cut_x[] = { 0, 16, 36, FULL_W };
static const int cut_y[] = { 0, 9, 36, FULL_H };
#define COLS 3
#define ROWS 3

/* A pixel value no two pixels share and that is never 0 0 0, so a pixel
 * left out shows. */
static void pattern(int x, int y, uint8_t out[3])
{
	out[0] = (uint8_t)(1 + x);
	out[1] = (uint8_t)(1 + y);
	out[2] = (uint8_t)(1 + (x * 7 + y * 3) % 250);
}

struct tiles {
	char dir[64];
	char path[COLS * ROWS][96];
	const char *paths[COLS * ROWS];
};

static void write_tiles(struct tiles *t)
{
	struct settings st;
	struct diag d;
	int i, j, x, y;
	char dir[64] = "/tmp/whitted-test-merge-XXXXXX";

	assert_non_null(mkdtemp(dir));
	memcpy(t->dir, dir, sizeof(dir));
	support_settings(&st, FULL_W, 1);
	for (j = 0; j < ROWS; j++) {
		for (i = 0; i < COLS; i++) {
			int k = j * COLS + i;
			struct tile_info info;
			struct image img;

			assert_int_equal(image_alloc(&img, cut_x[i + 1] - cut_x[i],
						     cut_y[j + 1] - cut_y[j], &d), 0);
			for (y = 0; y < img.height; y++)
				for (x = 0; x < img.width; x++)
					pattern(cut_x[i] + x, cut_y[j] + y,
						img.pixels + ((size_t)y * (size_t)img.width + (size_t)x) * 3);
			tile_info_init(&info, &st, 0x1234, cut_x[i], cut_y[j], cut_x[i + 1],
				       cut_y[j + 1]);
			snprintf(t->path[k], sizeof(t->path[k]), "%s/tile-%d.png", dir, k);
			assert_int_equal(tile_write(t->path[k], &img, &info, NULL, &d), 0);
			t->paths[k] = t->path[k];
			image_free(&img);
		}
	}
}

static void remove_tiles(struct tiles *t)
{
	int k;

	for (k = 0; k < COLS * ROWS; k++)
		unlink(t->path[k]);
	rmdir(t->dir);
}

static void test_merge_every_pixel_back_in_place(void **state)
{
	struct tiles t;
	struct image img;
	struct diag d;
	int x, y;

	(void)state;
	write_tiles(&t);
	assert_int_equal(merge_tiles(t.paths, COLS * ROWS, &img, NULL, &d), 0);
	assert_int_equal(img.width, FULL_W);
	assert_int_equal(img.height, FULL_H);
	for (y = 0; y < FULL_H; y++) {
		for (x = 0; x < FULL_W; x++) {
			uint8_t want[3];
			const uint8_t *got = img.pixels + ((size_t)y * FULL_W + (size_t)x) * 3;

			pattern(x, y, want);
			if (memcmp(got, want, 3) != 0) {
				print_error("pixel (%d, %d) is %d %d %d, expected %d %d %d\n", x, y, got[0],
					    got[1], got[2], want[0], want[1], want[2]);
				fail();
			}
		}
	}
	image_free(&img);
	/* In any order of the files. */
	{
		const char *rev[COLS * ROWS];
		int k;

		for (k = 0; k < COLS * ROWS; k++)
			rev[k] = t.paths[COLS * ROWS - 1 - k];
		assert_int_equal(merge_tiles(rev, COLS * ROWS, &img, NULL, &d), 0);
		for (y = 0; y < FULL_H; y++) {
			for (x = 0; x < FULL_W; x++) {
				uint8_t want[3];
				pattern(x, y, want);
				assert_memory_equal(img.pixels + ((size_t)y * FULL_W + (size_t)x) * 3, want, 3);
			}
		}
		image_free(&img);
	}
	remove_tiles(&t);
}

static void test_merge_gap_in_last_row_or_column(void **state)
{
	struct tiles t;
	struct image img;
	struct diag d;
	const char *some[COLS * ROWS];
	int k, n;

	(void)state;
	write_tiles(&t);
	/* Without the bottom-right tile (the last row's and the last
	 * column's): the gap is the pixel 36,36,37,37. */
	assert_int_equal(merge_tiles(t.paths, COLS * ROWS - 1, &img, NULL, &d), -RT_E_INVALID);
	assert_non_null(strstr(d.msg, "missing tile"));
	assert_non_null(strstr(d.msg, "36,36,37,37"));
	/* Without the last row: the first gap is 0,36,16,37. */
	assert_int_equal(merge_tiles(t.paths, COLS * (ROWS - 1), &img, NULL, &d), -RT_E_INVALID);
	assert_non_null(strstr(d.msg, "0,36,16,37"));
	/* Without the last column: 36,0,37,9. */
	for (k = 0, n = 0; k < COLS * ROWS; k++)
		if (k % COLS != COLS - 1)
			some[n++] = t.paths[k];
	assert_int_equal(merge_tiles(some, (size_t)n, &img, NULL, &d), -RT_E_INVALID);
	assert_non_null(strstr(d.msg, "36,0,37,9"));
	remove_tiles(&t);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_merge_every_pixel_back_in_place,
			   test_merge_gap_in_last_row_or_column))
