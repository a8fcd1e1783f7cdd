/* The library's allocator.  Every allocation goes through here so that the
 * tests can make the Nth one fail and check that each failure path frees
 * what it took and reports RT_E_NOMEM. */
#ifndef RT_ALLOC_H
#define RT_ALLOC_H

#include <stddef.h>

void *rt_malloc(size_t size);
void *rt_calloc(size_t count, size_t size);
/* Like realloc, but fails (returning NULL, leaving p alone) when
 * count * size overflows. */
void *rt_reallocarray(void *p, size_t count, size_t size);
/* count * size bytes aligned to align (a power of two, a multiple of
 * sizeof(void *)), freed by rt_free; NULL on overflow or failure. */
void *rt_aligned_array(size_t align, size_t count, size_t size);
/* Shrinks rt_aligned_array's p to count elements, keeping them; NULL (p
 * untouched) on failure.  Still aligned, unless the block moved and no
 * aligned one could be had (then the moved, unaligned block). */
void *rt_aligned_shrink(void *p, size_t align, size_t count, size_t size);
void rt_free(void *p);
/* rt_aligned_array for a big block written end to end: from 32 MiB on,
 * aligned to 2 MiB and advised to live in huge pages (Linux's
 * transparent huge pages; elsewhere plain pages), one fault a huge page,
 * not 512.  align as rt_aligned_array's, at most 2 MiB.  Freed by rt_free
 * (and shrunk by rt_aligned_shrink). */
void *rt_array_huge(size_t align, size_t count, size_t size);
/* rt_calloc so, from 2 MiB on, for a block written whole (an image). */
void *rt_calloc_huge(size_t count, size_t size);
/* Gives the pages of freed memory back to the system where the C library
 * can (glibc's malloc_trim), so that a big phase's temporaries (the
 * hierarchy's build) do not stay resident under the next phase. */
void rt_release_free_memory(void);
char *rt_strdup(const char *s);

/* Test hook: the allocation numbered n (1-based, counted from this call)
 * and every later one fail; n = 0 turns failures off.  Returns how many
 * allocations were made since the previous call.  Call it while no other
 * thread allocates; from the first call on, allocations are counted under
 * a lock. */
#ifdef RT_TEST_HOOKS
unsigned long rt_alloc_fail_from(unsigned long n);
#endif

#endif
