/* png_deflate.h over zlib: a raw deflate stream at level 1 (the fastest
 * that still matches strings), reset for each strip, which ends with a
 * sync flush (an empty stored block that ends on a byte), or the stream's
 * end for the last.  Built always: the fallback where the build has no
 * ISA-L, and tested beside it. */
#include <limits.h>
#include <string.h>
#include <zlib.h>

#include "base/alloc.h"
#include "image/png_deflate.h"
#include "whitted/diag.h"

static voidpf zlib_alloc(voidpf opaque, uInt items, uInt size)
{
	(void)opaque;
	return rt_reallocarray(NULL, items, size);
}

static void zlib_free_memory(voidpf opaque, voidpf p)
{
	(void)opaque;
	rt_free(p);
}

/* The stream is reset rather than made anew a strip: deflateInit2 itself
 * ends in deflateReset, so the stream is the same, and the ~270 KiB of
 * state are not allocated, faulted in and freed each time. */
static int zlib_make(void **out)
{
	z_stream *z = rt_malloc(sizeof(*z));

	*out = NULL;
	if (!z)
		return RT_E_NOMEM;
	memset(z, 0, sizeof(*z));
	z->zalloc = zlib_alloc;
	z->zfree = zlib_free_memory;
	if (deflateInit2(z, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
		rt_free(z);
		return RT_E_NOMEM;
	}
	*out = z;
	return 0;
}

static void zlib_free(void *c)
{
	if (!c)
		return;
	deflateEnd(c);
	rt_free(c);
}

static int zlib_strip(void *c, const unsigned char *in, size_t n, bool last, unsigned char *out,
		      size_t cap, size_t *len)
{
	z_stream *z = c;
	int rc;

	*len = 0;
	if (n > UINT_MAX || cap > UINT_MAX || deflateReset(z) != Z_OK)
		return RT_E_NOMEM;
	z->next_in = (Bytef *)in;
	z->avail_in = (uInt)n;
	z->next_out = out;
	z->avail_out = (uInt)cap;
	rc = deflate(z, last ? Z_FINISH : Z_SYNC_FLUSH);
	/* cap is png_deflate_bound's, above deflateBound's worst case and
	 * the flush's block, so one call always finishes. */
	if (!(rc == Z_STREAM_END || (rc == Z_OK && z->avail_in == 0 && z->avail_out > 0)))
		return RT_E_NOMEM;
	*len = cap - z->avail_out;
	return 0;
}

static uint32_t zlib_adler32(uint32_t adler, const unsigned char *p, size_t n)
{
	return (uint32_t)adler32_z(adler, p, n);
}

const struct png_deflate_ops png_deflate_zlib = {
	.name = "zlib",
	.make = zlib_make,
	.free = zlib_free,
	.strip = zlib_strip,
	.adler32 = zlib_adler32,
};
