/* The library's allocator: the C library's, plus (in the test build only,
 * RT_TEST_HOOKS) a switch that makes allocations fail from a chosen one on,
 * for the allocation-failure tests. */
#define _POSIX_C_SOURCE 200809L
#include <pthread.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "base/alloc.h"
#include "base/platform.h"

#ifdef RT_TEST_HOOKS
/* Only the tests set these, from one thread, before any render starts.
 * Until the first call of rt_alloc_fail_from nothing is counted, and no
 * lock is taken; after it the count is kept under a lock, since the parse,
 * the build and the render may allocate from several threads at once. */
static bool alloc_armed;
static unsigned long alloc_count;
static unsigned long alloc_fail_at;

static pthread_mutex_t alloc_lock = PTHREAD_MUTEX_INITIALIZER;

static int alloc_should_fail(void)
{
	int fail;

	if (!alloc_armed)
		return 0;
	pthread_mutex_lock(&alloc_lock);
	alloc_count++;
	fail = alloc_fail_at != 0 && alloc_count >= alloc_fail_at;
	pthread_mutex_unlock(&alloc_lock);
	return fail;
}

unsigned long rt_alloc_fail_from(unsigned long n)
{
	unsigned long made;

	pthread_mutex_lock(&alloc_lock);
	made = alloc_count;
	alloc_count = 0;
	alloc_fail_at = n;
	pthread_mutex_unlock(&alloc_lock);
	alloc_armed = true;
	return made;
}
#else
/* The installed library has no failure switch. */
static int alloc_should_fail(void)
{
	return 0;
}
#endif

void *rt_malloc(size_t size)
{
	if (alloc_should_fail())
		return NULL;
	return rt_sys_malloc(size ? size : 1);
}

void *rt_calloc(size_t count, size_t size)
{
	if (alloc_should_fail())
		return NULL;
	return rt_sys_calloc(count ? count : 1, size ? size : 1);
}

void *rt_reallocarray(void *p, size_t count, size_t size)
{
	if (size != 0 && count > SIZE_MAX / size)
		return NULL;
	if (alloc_should_fail())
		return NULL;
	return rt_sys_realloc(p, count != 0 && size != 0 ? count * size : 1);
}

void *rt_aligned_array(size_t align, size_t count, size_t size)
{
	if (size != 0 && count > SIZE_MAX / size)
		return NULL;
	if (alloc_should_fail())
		return NULL;
	return rt_sys_aligned(align, count != 0 && size != 0 ? count * size : 1);
}

void *rt_aligned_shrink(void *p, size_t align, size_t count, size_t size)
{
	if (alloc_should_fail())
		return NULL;
	/* count * size is at most the block's size, which did not overflow. */
	return rt_sys_aligned_realloc(p, align, count * size, count != 0 && size != 0 ? count * size : 1);
}

void rt_free(void *p)
{
	rt_sys_free(p);
}

void rt_release_free_memory(void)
{
	rt_sys_trim();
}

char *rt_strdup(const char *s)
{
	size_t n = strlen(s) + 1;
	char *copy = rt_malloc(n);

	if (copy)
		memcpy(copy, s, n);
	return copy;
}
