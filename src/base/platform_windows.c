/* The platform layer (platform.h) on Windows, built with MinGW-w64: no
 * plugins (a plugin is an ELF shared object, see plugin/elf_check.c) and
 * no huge pages (large pages need a privilege a user rarely has); the
 * C library's aligned blocks need their own free, so every block of the
 * library's allocator is one of them. */
#include <errno.h>
#include <io.h>
#include <malloc.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <windows.h>
#include <psapi.h>

#include "base/platform.h"

/* What malloc aligns to on 64-bit Windows. */
#define RT_SYS_ALIGN 16

int rt_cpu_count(void)
{
	DWORD n = GetActiveProcessorCount(ALL_PROCESSOR_GROUPS);

	return n < 1 ? 1 : n > 4096 ? 4096 : (int)n;
}

void *rt_sys_malloc(size_t size)
{
	return _aligned_malloc(size ? size : 1, RT_SYS_ALIGN);
}

void *rt_sys_calloc(size_t count, size_t size)
{
	void *p;

	if (size != 0 && count > (size_t)-1 / size)
		return NULL;
	p = rt_sys_malloc(count * size);
	if (p)
		memset(p, 0, count * size);
	return p;
}

void *rt_sys_realloc(void *p, size_t size)
{
	return _aligned_realloc(p, size ? size : 1, RT_SYS_ALIGN);
}

void *rt_sys_aligned(size_t align, size_t size)
{
	return _aligned_malloc(size ? size : 1, align < RT_SYS_ALIGN ? RT_SYS_ALIGN : align);
}

void *rt_sys_aligned_realloc(void *p, size_t align, size_t old_size, size_t size)
{
	(void)old_size;
	return _aligned_realloc(p, size ? size : 1, align < RT_SYS_ALIGN ? RT_SYS_ALIGN : align);
}

void rt_sys_free(void *p)
{
	_aligned_free(p);
}

void rt_sys_trim(void)
{
}

void rt_advise_huge(void *p, size_t size)
{
	(void)p;
	(void)size;
}

void rt_on_stop_signals(void (*fn)(int))
{
	/* Ctrl-C and Ctrl-Break reach the C library as SIGINT (and SIGBREAK,
	 * not a C99 name); SIGTERM is raised only by the program itself. */
	signal(SIGINT, fn);
	signal(SIGTERM, fn);
}

unsigned long long rt_memory_bytes(void)
{
	MEMORYSTATUSEX ms;

	ms.dwLength = sizeof(ms);
	if (!GlobalMemoryStatusEx(&ms))
		return 0;
	return (unsigned long long)ms.ullTotalPhys;
}

double rt_peak_resident_bytes(void)
{
	PROCESS_MEMORY_COUNTERS pmc;

	if (!GetProcessMemoryInfo(GetCurrentProcess(), &pmc, sizeof(pmc)))
		return 0.0;
	return (double)pmc.PeakWorkingSetSize;
}

int rt_file_set_mode(int fd, unsigned mode)
{
	(void)fd;
	(void)mode;
	return 0;
}

int rt_rename_over(const char *from, const char *to)
{
	if (MoveFileExA(from, to, MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH))
		return 0;
	errno = GetLastError() == ERROR_ACCESS_DENIED ? EACCES : EIO;
	return -1;
}

char *rt_real_path(const char *path)
{
	char *abs = _fullpath(NULL, path, 0);
	struct stat st;

	if (abs && stat(abs, &st) != 0) {
		free(abs);
		return NULL;
	}
	return abs;
}

int rt_lstat(const char *path, struct stat *st)
{
	return stat(path, st);
}

void *rt_dl_open(const char *path, char *why, size_t why_size)
{
	(void)path;
	snprintf(why, why_size, "plugins are not supported by the Windows build (they are Linux "
		 "shared objects); use whitted on Linux for --plugin");
	return NULL;
}

void *rt_dl_sym(void *handle, const char *name)
{
	(void)handle;
	(void)name;
	return NULL;
}

void rt_dl_close(void *handle)
{
	(void)handle;
}

const char *rt_platform_note(void)
{
	return "Windows build: no plugins (--plugin), no huge pages";
}
