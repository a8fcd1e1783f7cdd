/* The platform layer (platform.h) on POSIX systems: Linux, the BSDs,
 * macOS and emscripten. */
#define _DEFAULT_SOURCE
#include <dlfcn.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include "base/platform.h"

int rt_cpu_count(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);

	return n < 1 ? 1 : n > 4096 ? 4096 : (int)n;
}

void *rt_sys_malloc(size_t size)
{
	return malloc(size);
}

void *rt_sys_calloc(size_t count, size_t size)
{
	return calloc(count, size);
}

void *rt_sys_realloc(void *p, size_t size)
{
	return realloc(p, size);
}

void *rt_sys_aligned(size_t align, size_t size)
{
	void *p = NULL;

	return posix_memalign(&p, align, size) == 0 ? p : NULL;
}

void *rt_sys_aligned_realloc(void *p, size_t align, size_t old_size, size_t size)
{
	void *q;

	/* A shrink is in place in practice (glibc keeps the start of the
	 * block); should it move, the copy goes to a block aligned anew. */
	q = realloc(p, size);
	if (!q || (uintptr_t)q % align == 0)
		return q;
	p = q;
	if (posix_memalign(&q, align, size) != 0)
		return p;
	memcpy(q, p, size < old_size ? size : old_size);
	free(p);
	return q;
}

void rt_sys_free(void *p)
{
	free(p);
}

void rt_sys_trim(void)
{
#if defined(__GLIBC__)
	malloc_trim(0);
#endif
}

void rt_advise_huge(void *p, size_t size)
{
#ifdef MADV_HUGEPAGE
	(void)madvise(p, size, MADV_HUGEPAGE);
#else
	(void)p;
	(void)size;
#endif
}

void rt_on_stop_signals(void (*fn)(int))
{
	struct sigaction sa, old_sa;

	memset(&sa, 0, sizeof(sa));
	sa.sa_handler = fn;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	/* A closed terminal stops the render cleanly too, unless the hang-up
	 * is ignored (nohup). */
	if (sigaction(SIGHUP, NULL, &old_sa) == 0 && old_sa.sa_handler != SIG_IGN)
		sigaction(SIGHUP, &sa, NULL);
	/* A file-size limit then fails the write with EFBIG instead of killing
	 * us with a temporary file left behind. */
	signal(SIGXFSZ, SIG_IGN);
}

unsigned long long rt_memory_bytes(void)
{
	unsigned long long mem = 0;
	struct rlimit rl;
#ifdef _SC_PHYS_PAGES
	long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);

	if (pages > 0 && size > 0)
		mem = (unsigned long long)pages * (unsigned long long)size;
#endif
	if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY &&
	    (mem == 0 || (unsigned long long)rl.rlim_cur < mem))
		mem = (unsigned long long)rl.rlim_cur;
	return mem;
}

double rt_peak_resident_bytes(void)
{
	struct rusage ru;

	if (getrusage(RUSAGE_SELF, &ru) != 0)
		return 0.0;
	return ru.ru_maxrss * 1024.0;
}

int rt_file_set_mode(int fd, unsigned mode)
{
	return fchmod(fd, (mode_t)mode);
}

int rt_rename_over(const char *from, const char *to)
{
	return rename(from, to);
}

char *rt_real_path(const char *path)
{
	return realpath(path, NULL);
}

int rt_lstat(const char *path, struct stat *st)
{
	return lstat(path, st);
}

void *rt_dl_open(const char *path, char *why, size_t why_size)
{
	void *h = dlopen(path, RTLD_NOW | RTLD_LOCAL);

	if (!h) {
		const char *e = dlerror();
		snprintf(why, why_size, "%s", e ? e : "dlopen failed");
	}
	return h;
}

void *rt_dl_sym(void *handle, const char *name)
{
	return dlsym(handle, name);
}

void rt_dl_close(void *handle)
{
	dlclose(handle);
}

const char *rt_platform_note(void)
{
	return "";
}
