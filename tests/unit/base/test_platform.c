/* The platform layer (base/platform.h) as this system's file implements
 * it: processors counted, aligned blocks aligned and resized with their
 * bytes kept, renaming over an existing file, absolute paths, lstat not
 * following a link, a shared object that cannot be opened named with a
 * reason, the peak memory known. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "base/platform.h"
#include "support.h"

static void test_platform_cpu_count(void **state)
{
	(void)state;
	assert_true(rt_cpu_count() >= 1);
}

static void test_platform_aligned_blocks(void **state)
{
	static const size_t aligns[] = { 16, 64, 4096, (size_t)2 << 20 };
	size_t k, i;

	(void)state;
	for (k = 0; k < sizeof(aligns) / sizeof(aligns[0]); k++) {
		unsigned char *p = rt_sys_aligned(aligns[k], 10000), *q;
		assert_non_null(p);
		assert_int_equal((uintptr_t)p % aligns[k], 0);
		for (i = 0; i < 10000; i++)
			p[i] = (unsigned char)(i * 7);
		q = rt_sys_aligned_realloc(p, aligns[k], 10000, 3000);
		assert_non_null(q);
		assert_int_equal((uintptr_t)q % aligns[k], 0);
		for (i = 0; i < 3000; i++)
			assert_int_equal(q[i], (unsigned char)(i * 7));
		rt_sys_free(q);
	}
	{
		unsigned char *z = rt_sys_calloc(100, 8);
		assert_non_null(z);
		for (i = 0; i < 800; i++)
			assert_int_equal(z[i], 0);
		rt_sys_free(z);
	}
}

static void test_platform_rename_over(void **state)
{
	char a[] = "/tmp/whitted-platform-a-XXXXXX", b[] = "/tmp/whitted-platform-b-XXXXXX";
	char text[8] = "";
	int fa = mkstemp(a), fb = mkstemp(b);
	FILE *f;

	(void)state;
	assert_true(fa >= 0 && fb >= 0);
	assert_int_equal(write(fa, "new", 3), 3);
	assert_int_equal(write(fb, "old!", 4), 4);
	close(fa);
	close(fb);
	assert_int_equal(rt_rename_over(a, b), 0);
	assert_non_null(f = fopen(b, "rb"));
	assert_int_equal(fread(text, 1, sizeof(text) - 1, f), 3);
	fclose(f);
	assert_string_equal(text, "new");
	assert_int_not_equal(access(a, F_OK), 0);
	remove(b);
}

static void test_platform_paths(void **state)
{
	char *abs = rt_real_path(".");
	struct stat st;

	(void)state;
	assert_non_null(abs);
	assert_true(abs[0] == '/');
	free(abs);
	errno = 0;
	assert_null(rt_real_path("/no/such/whitted/file"));
	assert_int_not_equal(errno, 0);
	assert_int_equal(rt_lstat("/", &st), 0);
	assert_true(S_ISDIR(st.st_mode));
}

static void test_platform_shared_object_refused(void **state)
{
	char why[256] = "";

	(void)state;
	assert_null(rt_dl_open("/no/such/whitted/plugin.so", why, sizeof(why)));
	assert_true(strlen(why) > 0);
}

static void test_platform_peak_memory(void **state)
{
	(void)state;
	assert_true(rt_peak_resident_bytes() > 0.0);
	assert_string_equal(rt_platform_note(), "");
}

SUPPORT_MAIN(SUPPORT_TESTS(test_platform_cpu_count, test_platform_aligned_blocks,
			   test_platform_rename_over, test_platform_paths,
			   test_platform_shared_object_refused, test_platform_peak_memory))
