/* The image writers: PNG, BMP and PPM read back byte for byte, format
 * selection, and image_write's safe replacement (no partial or temporary
 * files) and its direct writes to pipes and devices. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <png.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "whitted/image.h"
#include "support.h"

struct tmp {
	char dir[64];
};

static int setup_dir(void **state)
{
	struct tmp *t = malloc(sizeof(*t));

	if (!t)
		return -1;
	snprintf(t->dir, sizeof(t->dir), "/tmp/whitted-image-XXXXXX");
	if (!mkdtemp(t->dir)) {
		free(t);
		return -1;
	}
	*state = t;
	return 0;
}

/* Removes the directory's entries (and, recursively, subdirectories). */
static void remove_tree(const char *dir)
{
	DIR *dp = opendir(dir);
	struct dirent *e;
	char path[512];

	if (!dp)
		return;
	while ((e = readdir(dp)) != NULL) {
		struct stat st;
		if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
			continue;
		snprintf(path, sizeof(path), "%s/%s", dir, e->d_name);
		if (lstat(path, &st) == 0 && S_ISDIR(st.st_mode))
			remove_tree(path);
		else
			unlink(path);
	}
	closedir(dp);
	rmdir(dir);
}

static int teardown_dir(void **state)
{
	struct tmp *t = *state;

	remove_tree(t->dir);
	free(t);
	return 0;
}

/* The names in dir, sorted and joined by spaces. */
static void list_dir(const char *dir, char *out, size_t size)
{
	char names[16][256];
	int n = 0, i, j;
	DIR *dp = opendir(dir);
	struct dirent *e;

	assert_non_null(dp);
	while ((e = readdir(dp)) != NULL && n < 16)
		if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
			snprintf(names[n++], sizeof(names[0]), "%s", e->d_name);
	closedir(dp);
	for (i = 1; i < n; i++)
		for (j = i; j > 0 && strcmp(names[j - 1], names[j]) > 0; j--) {
			char tmp[256];
			memcpy(tmp, names[j], sizeof(tmp));
			memcpy(names[j], names[j - 1], sizeof(tmp));
			memcpy(names[j - 1], tmp, sizeof(tmp));
		}
	out[0] = '\0';
	for (i = 0; i < n; i++) {
		if (i > 0)
			strncat(out, " ", size - strlen(out) - 1);
		strncat(out, names[i], size - strlen(out) - 1);
	}
}

/* A 5 x 3 image (odd width: BMP rows need padding) with distinct bytes. */
static void make_image(struct image *img, int w, int h)
{
	struct diag d;
	size_t i;

	assert_int_equal(image_alloc(img, w, h, &d), 0);
	for (i = 0; i < (size_t)w * (size_t)h * 3; i++)
		img->pixels[i] = (uint8_t)(i * 37 + 11);
}

static uint32_t le32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

static unsigned le16(const unsigned char *p)
{
	return (unsigned)p[0] | (unsigned)p[1] << 8;
}

static void check_ppm(const unsigned char *buf, size_t len, const struct image *img)
{
	char header[32];
	int n = snprintf(header, sizeof(header), "P6\n%d %d\n255\n", img->width, img->height);
	size_t bytes = (size_t)img->width * (size_t)img->height * 3;

	assert_int_equal(len, (size_t)n + bytes);
	assert_memory_equal(buf, header, (size_t)n);
	assert_memory_equal(buf + n, img->pixels, bytes);
}

static void check_bmp(const unsigned char *buf, size_t len, const struct image *img)
{
	size_t row = ((size_t)img->width * 3 + 3) / 4 * 4;
	int x, y;

	assert_int_equal(len, 54 + row * (size_t)img->height);
	assert_memory_equal(buf, "BM", 2);
	assert_int_equal(le32(buf + 2), len);		/* file size */
	assert_int_equal(le32(buf + 10), 54);		/* pixel data offset */
	assert_int_equal(le32(buf + 14), 40);		/* BITMAPINFOHEADER */
	assert_int_equal(le32(buf + 18), (uint32_t)img->width);
	assert_int_equal(le32(buf + 22), (uint32_t)img->height);	/* > 0: bottom up */
	assert_int_equal(le16(buf + 26), 1);		/* planes */
	assert_int_equal(le16(buf + 28), 24);		/* bits per pixel */
	assert_int_equal(le32(buf + 30), 0);		/* BI_RGB */
	assert_int_equal(le32(buf + 34), row * (size_t)img->height);
	for (y = 0; y < img->height; y++) {
		/* File row y is image row height - 1 - y, in BGR order. */
		const unsigned char *src = buf + 54 + (size_t)y * row;
		const uint8_t *want = img->pixels + (size_t)(img->height - 1 - y) * (size_t)img->width * 3;
		size_t k;
		for (x = 0; x < img->width; x++) {
			assert_int_equal(src[3 * x + 0], want[3 * x + 2]);
			assert_int_equal(src[3 * x + 1], want[3 * x + 1]);
			assert_int_equal(src[3 * x + 2], want[3 * x + 0]);
		}
		for (k = (size_t)img->width * 3; k < row; k++)
			assert_int_equal(src[k], 0);	/* padding */
	}
}

static void check_png(const char *path, const struct image *img)
{
	png_image png;
	size_t bytes = (size_t)img->width * (size_t)img->height * 3;
	unsigned char *buf;

	memset(&png, 0, sizeof(png));
	png.version = PNG_IMAGE_VERSION;
	assert_true(png_image_begin_read_from_file(&png, path));
	assert_int_equal(png.width, (png_uint_32)img->width);
	assert_int_equal(png.height, (png_uint_32)img->height);
	/* Stored as 8-bit RGB without alpha or colour map. */
	assert_int_equal(png.format, PNG_FORMAT_RGB);
	png.format = PNG_FORMAT_RGB;
	buf = malloc(PNG_IMAGE_SIZE(png));
	assert_non_null(buf);
	assert_int_equal(PNG_IMAGE_SIZE(png), bytes);
	assert_true(png_image_finish_read(&png, NULL, buf, 0, NULL));
	assert_memory_equal(buf, img->pixels, bytes);
	free(buf);
}

static void test_image_alloc(void **state)
{
	struct image img;
	struct diag d;
	size_t i;

	(void)state;
	assert_int_equal(image_alloc(&img, 7, 2, &d), 0);
	assert_int_equal(img.width, 7);
	assert_int_equal(img.height, 2);
	for (i = 0; i < 7 * 2 * 3; i++)
		assert_int_equal(img.pixels[i], 0);
	image_free(&img);
	assert_null(img.pixels);
	/* Freeing twice is harmless. */
	image_free(&img);
	assert_int_equal(image_alloc(&img, 0, 5, &d), -RT_E_INVALID);
	assert_null(img.pixels);
	assert_int_equal(image_alloc(&img, 5, -1, &d), -RT_E_INVALID);
	assert_null(img.pixels);
}

static void test_image_format_from_path(void **state)
{
	(void)state;
	assert_int_equal(image_format_from_path("out.png"), RT_FORMAT_PNG);
	assert_int_equal(image_format_from_path("a/b/scene.BMP"), RT_FORMAT_BMP);
	assert_int_equal(image_format_from_path("x.Ppm"), RT_FORMAT_PPM);
	assert_int_equal(image_format_from_path("../dir.v2/out.ppm"), RT_FORMAT_PPM);
	assert_int_equal(image_format_from_path("noext"), RT_FORMAT_UNKNOWN);
	assert_int_equal(image_format_from_path("dir.png/file"), RT_FORMAT_UNKNOWN);
	assert_int_equal(image_format_from_path("file.jpg"), RT_FORMAT_UNKNOWN);
	assert_int_equal(image_format_from_path("file."), RT_FORMAT_UNKNOWN);
	assert_int_equal(image_format_from_path("file.png.txt"), RT_FORMAT_UNKNOWN);
	assert_int_equal(image_format_from_path("file.pngx"), RT_FORMAT_UNKNOWN);
	assert_int_equal(image_format_from_path(""), RT_FORMAT_UNKNOWN);
	assert_int_equal(image_format_from_name("PNG"), RT_FORMAT_PNG);
	assert_int_equal(image_format_from_name("bmp"), RT_FORMAT_BMP);
	assert_int_equal(image_format_from_name("ppm"), RT_FORMAT_PPM);
	assert_int_equal(image_format_from_name("gif"), RT_FORMAT_UNKNOWN);
}

/* The formats' table read back: names, the message's list, and the
 * signature bytes (a PPM's P of any kind; a BMP's BM; PNG's eight). */
static void test_image_format_table(void **state)
{
	static const unsigned char png[] = { 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0 };
	char buf[64], small[6];

	(void)state;
	assert_string_equal(image_format_name(RT_FORMAT_PNG), "png");
	assert_string_equal(image_format_name(RT_FORMAT_BMP), "bmp");
	assert_string_equal(image_format_name(RT_FORMAT_PPM), "ppm");
	assert_string_equal(image_format_name(RT_FORMAT_UNKNOWN), "?");
	assert_string_equal(image_format_names(buf, sizeof(buf), ""), "png, bmp or ppm");
	assert_string_equal(image_format_names(buf, sizeof(buf), "."), ".png, .bmp or .ppm");
	assert_string_equal(image_format_names(small, sizeof(small), "."), ".png,");
	assert_int_equal(image_format_of_bytes(png, sizeof(png)), RT_FORMAT_PNG);
	assert_int_equal(image_format_of_bytes(png, 7), RT_FORMAT_UNKNOWN);
	assert_int_equal(image_format_of_bytes((const unsigned char *)"BM\x36", 3), RT_FORMAT_BMP);
	assert_int_equal(image_format_of_bytes((const unsigned char *)"P3\n", 3), RT_FORMAT_PPM);
	assert_int_equal(image_format_of_bytes((const unsigned char *)"GIF89a", 6), RT_FORMAT_UNKNOWN);
	assert_int_equal(image_format_of_bytes((const unsigned char *)"", 0), RT_FORMAT_UNKNOWN);
}

static void write_and_check(const char *dir, enum image_format fmt, const char *name,
			    int w, int h)
{
	char path[256], names[1024];
	struct image img;
	struct diag d;
	unsigned char *buf;
	size_t len;

	make_image(&img, w, h);
	snprintf(path, sizeof(path), "%s/%s", dir, name);
	diag_clear(&d);
	assert_int_equal(image_write(&img, path, fmt, NULL, &d), 0);
	list_dir(dir, names, sizeof(names));
	assert_string_equal(names, name);
	if (fmt == RT_FORMAT_PNG) {
		check_png(path, &img);
	} else {
		buf = support_read_file(path, &len);
		if (fmt == RT_FORMAT_BMP)
			check_bmp(buf, len, &img);
		else
			check_ppm(buf, len, &img);
		free(buf);
	}
	unlink(path);
	image_free(&img);
}

static void test_image_png_round_trip(void **state)
{
	const struct tmp *t = *state;

	write_and_check(t->dir, RT_FORMAT_PNG, "out.png", 5, 3);
	write_and_check(t->dir, RT_FORMAT_PNG, "one.png", 1, 1);
	write_and_check(t->dir, RT_FORMAT_PNG, "wide.png", 130, 7);
}

static void test_image_bmp_round_trip(void **state)
{
	const struct tmp *t = *state;

	/* Widths 5, 1, 2 and 3 need 1, 1, 2 and 3 bytes of padding; 4 none. */
	write_and_check(t->dir, RT_FORMAT_BMP, "out.bmp", 5, 3);
	write_and_check(t->dir, RT_FORMAT_BMP, "one.bmp", 1, 1);
	write_and_check(t->dir, RT_FORMAT_BMP, "two.bmp", 2, 5);
	write_and_check(t->dir, RT_FORMAT_BMP, "three.bmp", 3, 2);
	write_and_check(t->dir, RT_FORMAT_BMP, "four.bmp", 4, 4);
}

static void test_image_ppm_round_trip(void **state)
{
	const struct tmp *t = *state;

	write_and_check(t->dir, RT_FORMAT_PPM, "out.ppm", 5, 3);
	write_and_check(t->dir, RT_FORMAT_PPM, "one.ppm", 1, 1);
}

static void test_image_writers_to_streams(void **state)
{
	struct image img;
	struct diag d;
	unsigned char buf[256];
	FILE *f;
	size_t n;

	(void)state;
	make_image(&img, 5, 3);
	f = tmpfile();
	assert_non_null(f);
	assert_int_equal(image_write_ppm(&img, f, &d), 0);
	rewind(f);
	n = fread(buf, 1, sizeof(buf), f);
	check_ppm(buf, n, &img);
	fclose(f);
	f = tmpfile();
	assert_non_null(f);
	assert_int_equal(image_write_bmp(&img, f, &d), 0);
	rewind(f);
	n = fread(buf, 1, sizeof(buf), f);
	check_bmp(buf, n, &img);
	fclose(f);
	image_free(&img);
}

static void test_image_write_replaces_existing(void **state)
{
	const struct tmp *t = *state;
	char path[256], names[1024];
	struct image img;
	struct diag d;
	struct stat st;
	unsigned char *buf;
	size_t len;
	FILE *f;

	snprintf(path, sizeof(path), "%s/out.ppm", t->dir);
	f = fopen(path, "wb");
	assert_non_null(f);
	fputs("an older, longer file that must be replaced completely ..........", f);
	fclose(f);
	assert_int_equal(chmod(path, 0640), 0);
	make_image(&img, 5, 3);
	assert_int_equal(image_write(&img, path, RT_FORMAT_PPM, NULL, &d), 0);
	buf = support_read_file(path, &len);
	check_ppm(buf, len, &img);
	free(buf);
	/* The old file's permissions are kept, and no temporary file remains. */
	assert_int_equal(stat(path, &st), 0);
	assert_int_equal(st.st_mode & 07777, 0640);
	list_dir(t->dir, names, sizeof(names));
	assert_string_equal(names, "out.ppm");
	image_free(&img);
}

static void test_image_write_new_file_mode(void **state)
{
	const struct tmp *t = *state;
	char path[256];
	struct image img;
	struct diag d;
	struct stat st;
	mode_t old = umask(022);

	snprintf(path, sizeof(path), "%s/new.bmp", t->dir);
	make_image(&img, 2, 2);
	assert_int_equal(image_write(&img, path, RT_FORMAT_BMP, NULL, &d), 0);
	umask(old);
	/* As if created in place: 0666 & ~022 (mkstemp alone gives 0600). */
	assert_int_equal(stat(path, &st), 0);
	assert_int_equal(st.st_mode & 07777, 0644);
	image_free(&img);
}

static void test_image_write_missing_directory(void **state)
{
	const struct tmp *t = *state;
	char path[256], names[1024];
	struct image img;
	struct diag d;

	snprintf(path, sizeof(path), "%s/missing/out.png", t->dir);
	make_image(&img, 2, 2);
	diag_clear(&d);
	assert_int_equal(image_write(&img, path, RT_FORMAT_PNG, NULL, &d), -RT_E_IO);
	assert_string_equal(d.file, path);
	assert_non_null(strstr(d.msg, "cannot write"));
	/* Nothing was created anywhere. */
	list_dir(t->dir, names, sizeof(names));
	assert_string_equal(names, "");
	image_free(&img);
}

static void test_image_write_unknown_format_and_cancel(void **state)
{
	const struct tmp *t = *state;
	char path[256], names[1024];
	struct image img;
	struct diag d;
	volatile sig_atomic_t cancel = 1;
	unsigned char *buf;
	size_t len;
	FILE *f;

	snprintf(path, sizeof(path), "%s/out.xyz", t->dir);
	make_image(&img, 2, 2);
	assert_int_equal(image_write(&img, path, RT_FORMAT_UNKNOWN, NULL, &d), -RT_E_INVALID);
	list_dir(t->dir, names, sizeof(names));
	assert_string_equal(names, "");
	/* Cancelled: interrupted, and an existing output is left as it was. */
	snprintf(path, sizeof(path), "%s/keep.ppm", t->dir);
	f = fopen(path, "wb");
	assert_non_null(f);
	fputs("old", f);
	fclose(f);
	assert_int_equal(image_write(&img, path, RT_FORMAT_PPM, &cancel, &d), -RT_E_INTERRUPTED);
	buf = support_read_file(path, &len);
	assert_int_equal(len, 3);
	assert_memory_equal(buf, "old", 3);
	free(buf);
	list_dir(t->dir, names, sizeof(names));
	assert_string_equal(names, "keep.ppm");
	image_free(&img);
}

static void test_image_write_dev_null(void **state)
{
	struct image img;
	struct diag d;
	struct stat st;

	(void)state;
	make_image(&img, 3, 3);
	assert_int_equal(image_write(&img, "/dev/null", RT_FORMAT_PNG, NULL, &d), 0);
	/* Still the device, not a file renamed over it. */
	assert_int_equal(stat("/dev/null", &st), 0);
	assert_true(S_ISCHR(st.st_mode));
	image_free(&img);
}

struct reader {
	const char *path;
	unsigned char buf[1024];
	size_t len;
};

static void *read_fifo(void *arg)
{
	struct reader *r = arg;
	FILE *f = fopen(r->path, "rb");
	size_t n;

	if (!f)
		return NULL;
	while ((n = fread(r->buf + r->len, 1, sizeof(r->buf) - r->len, f)) > 0)
		r->len += n;
	fclose(f);
	return NULL;
}

static void test_image_write_fifo_directly(void **state)
{
	const struct tmp *t = *state;
	char path[256], names[1024];
	struct reader r;
	struct image img;
	struct diag d;
	struct stat st;
	pthread_t th;

	snprintf(path, sizeof(path), "%s/pipe", t->dir);
	assert_int_equal(mkfifo(path, 0600), 0);
	memset(&r, 0, sizeof(r));
	r.path = path;
	assert_int_equal(pthread_create(&th, NULL, read_fifo, &r), 0);
	make_image(&img, 5, 3);
	assert_int_equal(image_write(&img, path, RT_FORMAT_PPM, NULL, &d), 0);
	pthread_join(th, NULL);
	check_ppm(r.buf, r.len, &img);
	/* The FIFO is still there, alone. */
	assert_int_equal(lstat(path, &st), 0);
	assert_true(S_ISFIFO(st.st_mode));
	list_dir(t->dir, names, sizeof(names));
	assert_string_equal(names, "pipe");
	image_free(&img);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_image_alloc, test_image_format_from_path,
			   test_image_format_table),
	     SUPPORT_FIXTURE_TESTS(setup_dir, teardown_dir, test_image_png_round_trip,
				   test_image_bmp_round_trip, test_image_ppm_round_trip),
	     SUPPORT_TESTS(test_image_writers_to_streams),
	     SUPPORT_FIXTURE_TESTS(setup_dir, teardown_dir, test_image_write_replaces_existing,
				   test_image_write_new_file_mode,
				   test_image_write_missing_directory,
				   test_image_write_unknown_format_and_cancel),
	     SUPPORT_TESTS(test_image_write_dev_null),
	     SUPPORT_FIXTURE_TESTS(setup_dir, teardown_dir, test_image_write_fifo_directly))
