/* Big blocks in huge pages: the rendered image and the hierarchy build's
 * arrays, written end to end.  On a virtual machine the first write to
 * each 4 KiB page costs a fault of some microseconds: the 1728 pages of a
 * 1536x1536 image took 17 ms of a 90 ms render (more where two threads
 * writing neighbouring blocks fault on one page at once), and the 33,000
 * pages of a 1M-primitive build about a third of its 0.5 s.  A 2 MiB page
 * is one fault.  Linux's transparent huge pages in "madvise" mode
 * (Debian's default) give them only to ranges advised so, and only to
 * whole, aligned 2 MiB extents: hence the alignment and the size rounded
 * up (address space only: the pages past what is written are never
 * touched but for the last huge page's rest). */
#include <stdint.h>
#include <string.h>

#include "base/alloc.h"
#include "base/platform.h"
#include "base/thread.h"

#define HUGE_PAGE ((size_t)2 << 20)
/* The most threads that zero one block (zero_huge). */
#define ZERO_THREADS 8

/* rt_array_huge's blocks from `min` bytes on. */
static void *huge_block(size_t align, size_t count, size_t size, size_t min)
{
	size_t n, rounded;
	void *p;

	if (size != 0 && count > SIZE_MAX / size)
		return NULL;
	n = count * size;
	if (n > SIZE_MAX - HUGE_PAGE)
		return NULL;
	if (n < min)
		return rt_aligned_array(align, count, size);
	rounded = (n + HUGE_PAGE - 1) & ~(HUGE_PAGE - 1);
	p = rt_aligned_array(HUGE_PAGE, rounded, 1);
	if (p)
		rt_advise_huge(p, rounded);
	return p;
}

void *rt_array_huge(size_t align, size_t count, size_t size)
{
	/* Where a block is written in parts (the build's refs block holds
	 * the tree at its start and the leaf order at its end), each edge
	 * of a written part may fault a huge page that is mostly unused:
	 * from 32 MiB on, that is at most an eighth more.  (From 2 MiB on,
	 * gen-100k's peak grew by 5.6 MiB, 56 bytes a primitive.) */
	return huge_block(align, count, size, 16 * HUGE_PAGE);
}

struct zero_part {
	unsigned char *p;
	size_t n;
};

static void *zero_part_main(void *arg)
{
	struct zero_part *z = arg;

	memset(z->p, 0, z->n);
	return NULL;
}

/* p[0, n) zeroed, its huge pages shared out among up to one thread a
 * processor.  The first write to a huge page faults it in, and on this
 * project's virtual machines a page the host has taken back (Linux
 * reports free blocks to the host, which drops them) costs it some
 * milliseconds, during which the processor runs nothing else: a lone
 * thread paid for every page while the other processors waited.  The
 * 1536 px image's four pages took 5-16 ms so in about one run in two a
 * second apart; on two threads about half that (and 0.8 ms for 0.7 when
 * the pages are at hand).  A thread that cannot be started leaves its
 * part to the calling one (rt_run_parts). */
static void zero_huge(unsigned char *p, size_t n)
{
	struct zero_part part[ZERO_THREADS];
	size_t pages = (n + HUGE_PAGE - 1) / HUGE_PAGE, each, at = 0;
	int cpus = rt_cpu_count();
	int k = cpus > ZERO_THREADS ? ZERO_THREADS : cpus, i;

	if ((size_t)k > pages)
		k = (int)pages;
	each = (pages + (size_t)k - 1) / (size_t)k;
	/* No thread for nothing: 9 pages on 8 processors are 5 parts of 2. */
	k = (int)((pages + each - 1) / each);
	each *= HUGE_PAGE;
	for (i = 0; i < k; i++) {
		part[i].p = p + at;
		part[i].n = n - at < each ? n - at : each;
		at += part[i].n;
	}
	rt_run_parts(part, sizeof(part[0]), k, zero_part_main);
}

void *rt_calloc_huge(size_t count, size_t size)
{
	void *p;

	/* Zeroed here, not left to a fresh mapping's zeros: the C library
	 * may hand back memory it had before. */
	if (size != 0 && count > SIZE_MAX / size)
		return NULL;
	if (count * size < HUGE_PAGE)
		return rt_calloc(count, size);
	/* Written whole: only the rounding is unused. */
	p = huge_block(sizeof(void *), count, size, HUGE_PAGE);
	if (p)
		zero_huge(p, count * size);
	return p;
}
