/* What the operating system gives beyond C99, in one place: the number of
 * processors, huge pages, the C library's aligned blocks, the signals that
 * stop a run, the peak memory, a file's permissions, renaming over a file,
 * absolute paths and shared objects.  Two files implement it, one a
 * system, and the Makefile compiles one: platform_posix.c (Linux, other
 * POSIX systems and emscripten) and platform_windows.c (MinGW-w64).
 * Nothing else in src/ asks which system it is on. */
#ifndef RT_PLATFORM_H
#define RT_PLATFORM_H

#include <fcntl.h>
#include <stdbool.h>
#include <stddef.h>
#include <sys/stat.h>

/* What POSIX names and Windows lacks, given the value that makes the
 * test or the flag mean nothing there. */
#ifndef S_ISSOCK
#define S_ISSOCK(m) 0
#endif
#ifndef O_NONBLOCK
#define O_NONBLOCK 0
#endif
#ifdef O_BINARY
#define RT_O_BINARY O_BINARY
#else
#define RT_O_BINARY 0
#endif

/* The processors online, at least 1. */
int rt_cpu_count(void);

/* The C library's blocks for base/alloc.c: every block from these four is
 * freed by rt_sys_free (Windows keeps aligned blocks apart).  Alignment:
 * a power of two, a multiple of sizeof(void *). */
void *rt_sys_malloc(size_t size);
void *rt_sys_calloc(size_t count, size_t size);
void *rt_sys_realloc(void *p, size_t size);
void *rt_sys_aligned(size_t align, size_t size);
/* Resizes an rt_sys_aligned block, keeping its start's bytes and (where
 * a block can be had) its alignment; NULL, p untouched, on failure. */
void *rt_sys_aligned_realloc(void *p, size_t align, size_t old_size, size_t size);
void rt_sys_free(void *p);
/* Gives the C library's free memory back to the system, where it can. */
void rt_sys_trim(void);

/* Asks for p[0, size) to live in huge pages; a refusal (or a system
 * without them) leaves small ones: slower, not wrong. */
void rt_advise_huge(void *p, size_t size);

/* fn(signal) on the signals that ask a run to stop: SIGINT, SIGTERM and
 * (unless ignored, as under nohup) SIGHUP; a file-size limit becomes an
 * error of the write (SIGXFSZ ignored) where there is one. */
void rt_on_stop_signals(void (*fn)(int));

/* The process's peak resident memory in bytes (0 when unknown). */
double rt_peak_resident_bytes(void);
/* The memory this process may use, in bytes: the machine's physical
 * memory, or the process's address-space limit where that is lower (0
 * when neither is known). */
unsigned long long rt_memory_bytes(void);

/* Gives the open file fd the permission bits mode (0 or -1 with errno);
 * nothing where files have none. */
int rt_file_set_mode(int fd, unsigned mode);
/* rename(from, to), replacing `to` where it exists (0 or -1 with errno). */
int rt_rename_over(const char *from, const char *to);
/* The absolute, resolved path of an existing file, from malloc (free
 * with free), or NULL with errno. */
char *rt_real_path(const char *path);
/* stat for a directory's entries: a symbolic link is not followed. */
int rt_lstat(const char *path, struct stat *st);

/* Shared objects (plugins): a handle, or NULL with why[] filled. */
void *rt_dl_open(const char *path, char *why, size_t why_size);
void *rt_dl_sym(void *handle, const char *name);
void rt_dl_close(void *handle);
/* What this build leaves out, for --version ("" when nothing). */
const char *rt_platform_note(void);

#endif
