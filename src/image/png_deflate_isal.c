/* png_deflate.h over ISA-L's igzip: each strip one stateless call at
 * level 0 (one pass) with Huffman tables made for the strip from its own
 * histogram, a full flush (byte-aligned, no history kept) for every strip
 * but the last, whose end_of_stream ends the stream.  On a 1536x1536
 * render: 3 ms for the rows against zlib level 1's 12 ms, the file 6%
 * larger.  ISA-L's level 1 (two passes) is faster still and smaller, but
 * its bytes depend on where the compressor and the rows lie in memory (2
 * to 51 strips in 6000 came out otherwise, each valid, at other
 * addresses): the file would change from run to run.  Compiled only where
 * the build found ISA-L (RT_HAVE_ISAL). */
#ifdef RT_HAVE_ISAL
#include <isa-l/igzip_lib.h>
#include <limits.h>
#include <stdint.h>
#include <string.h>

#include "base/alloc.h"
#include "image/png_deflate.h"
#include "whitted/diag.h"

/* About 100 KiB: on the heap, not a stack. */
struct isal_coder {
	struct isal_zstream z;
	struct isal_hufftables tables;
	struct isal_huff_histogram histogram;
};

static int isal_make(void **out)
{
	*out = rt_calloc(1, sizeof(struct isal_coder));
	return *out ? 0 : RT_E_NOMEM;
}

static void isal_free(void *c)
{
	rt_free(c);
}

static int isal_strip(void *coder, const unsigned char *in, size_t n, bool last,
		      unsigned char *out, size_t cap, size_t *len)
{
	struct isal_coder *c = coder;
	struct isal_zstream *z = &c->z;

	*len = 0;
	if (n > INT_MAX || cap > UINT32_MAX)
		return RT_E_NOMEM;
	/* Every strip from a zeroed compressor, so that nothing of the
	 * strips it did before can reach its bytes (isal_deflate_stateless_
	 * init leaves some fields alone: hist_bits, the hash table). */
	memset(c, 0, sizeof(*c));
	isal_update_histogram((uint8_t *)in, (int)n, &c->histogram);
	/* The subset variant: codes for the symbols the strip has only,
	 * smaller headers than the full table's. */
	if (isal_create_hufftables_subset(&c->tables, &c->histogram) != 0)
		return RT_E_NOMEM;
	isal_deflate_stateless_init(z);
	z->level = 0;
	if (isal_deflate_set_hufftables(z, &c->tables, IGZIP_HUFFTABLE_CUSTOM) != COMP_OK)
		return RT_E_NOMEM;
	z->flush = FULL_FLUSH;
	z->end_of_stream = last;
	z->next_in = (uint8_t *)in;
	z->avail_in = (uint32_t)n;
	z->next_out = out;
	z->avail_out = (uint32_t)cap;
	if (isal_deflate_stateless(z) != COMP_OK || z->avail_in != 0)
		return RT_E_NOMEM;
	*len = z->total_out;
	return 0;
}

static uint32_t isal_adler(uint32_t adler, const unsigned char *p, size_t n)
{
	return isal_adler32(adler, p, n);
}

/* ISA-L picks its code for the processor at each function's first call,
 * storing a pointer no lock guards (helgrind saw two threads' first calls
 * race on it): one strip of each kind, and a checksum, on the thread
 * that starts the others, before it does. */
static void isal_prepare(void)
{
	static const unsigned char row[64] = { 2, 1, 1, 1, 7, 7, 7, 7 };
	unsigned char out[sizeof(row) + 1024 + 64];	/* png_deflate_bound's and more */
	size_t len;
	void *c;

	(void)isal_adler(1, row, sizeof(row));
	if (isal_make(&c) != 0)
		return;
	(void)isal_strip(c, row, sizeof(row), false, out, sizeof(out), &len);
	(void)isal_strip(c, row, sizeof(row), true, out, sizeof(out), &len);
	isal_free(c);
}

const struct png_deflate_ops png_deflate_isal = {
	.name = "isa-l",
	.prepare = isal_prepare,
	.make = isal_make,
	.free = isal_free,
	.strip = isal_strip,
	.adler32 = isal_adler,
};
#else
/* ISO C wants something in a translation unit. */
typedef int png_deflate_isal_not_built;
#endif
