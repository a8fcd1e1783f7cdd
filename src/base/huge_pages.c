/* Zeroed buffers in huge pages, for the big ones that are written end to
 * end (the rendered image).  On a virtual machine the first write to each
 * 4 KiB page costs a fault of some microseconds: the 1728 pages of a
 * 1536x1536 image took 17 ms of a 90 ms render, and more where two
 * threads writing neighbouring blocks fault on one page at once.  A 2 MiB
 * page is one fault, and zeroing the whole image then costs about 0.4 ms.
 * Linux's transparent huge pages in "madvise" mode (Debian's default)
 * give them only to ranges advised so, and only to whole, aligned 2 MiB
 * extents: hence the alignment and the size rounded up. */
#define _DEFAULT_SOURCE
#include <stdint.h>
#include <string.h>
#include <sys/mman.h>

#include "base/alloc.h"

#define HUGE_PAGE ((size_t)2 << 20)

void *rt_calloc_huge(size_t count, size_t size)
{
	size_t n, rounded;
	void *p;

	if (size != 0 && count > SIZE_MAX / size)
		return NULL;
	n = count * size;
	if (n > SIZE_MAX - HUGE_PAGE)
		return NULL;
	if (n < HUGE_PAGE)
		return rt_calloc(count, size);
	rounded = (n + HUGE_PAGE - 1) & ~(HUGE_PAGE - 1);
	p = rt_aligned_array(HUGE_PAGE, rounded, 1);
	if (!p)
		return NULL;
#ifdef MADV_HUGEPAGE
	/* A refusal (a kernel without them) leaves small pages: slower,
	 * not wrong. */
	(void)madvise(p, rounded, MADV_HUGEPAGE);
#endif
	memset(p, 0, n);
	return p;
}
