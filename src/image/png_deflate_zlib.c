/* png_deflate.h over zlib: a raw deflate stream at level 1 (the fastest
 * that still matches strings), reset for each strip, which ends with a
 * sync flush (an empty stored block that ends on a byte), or the stream's
 * end for the last.  Compiled where the build did not find ISA-L
 * (png_deflate_isal.c). */
#ifndef RT_HAVE_ISAL
#include <limits.h>
#include <string.h>
#include <zlib.h>

#include "base/alloc.h"
#include "image/png_deflate.h"
#include "whitted/diag.h"

struct png_deflate {
	/* Reset rather than made anew a strip: deflateInit2 itself ends
	 * in deflateReset, so the stream is the same, and the ~270 KiB of
	 * state are not allocated, faulted in and freed each time. */
	z_stream z;
};

static voidpf png_deflate_zalloc(voidpf opaque, uInt items, uInt size)
{
	(void)opaque;
	return rt_reallocarray(NULL, items, size);
}

static void png_deflate_zfree(voidpf opaque, voidpf p)
{
	(void)opaque;
	rt_free(p);
}

int png_deflate_new(struct png_deflate **out)
{
	struct png_deflate *c = rt_malloc(sizeof(*c));

	*out = NULL;
	if (!c)
		return RT_E_NOMEM;
	memset(&c->z, 0, sizeof(c->z));
	c->z.zalloc = png_deflate_zalloc;
	c->z.zfree = png_deflate_zfree;
	if (deflateInit2(&c->z, 1, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK) {
		rt_free(c);
		return RT_E_NOMEM;
	}
	*out = c;
	return 0;
}

void png_deflate_free(struct png_deflate *c)
{
	if (!c)
		return;
	deflateEnd(&c->z);
	rt_free(c);
}

int png_deflate_strip(struct png_deflate *c, const unsigned char *in, size_t n, bool last,
		      unsigned char *out, size_t cap, size_t *len)
{
	int rc;

	*len = 0;
	if (n > UINT_MAX || cap > UINT_MAX || deflateReset(&c->z) != Z_OK)
		return RT_E_NOMEM;
	c->z.next_in = (Bytef *)in;
	c->z.avail_in = (uInt)n;
	c->z.next_out = out;
	c->z.avail_out = (uInt)cap;
	rc = deflate(&c->z, last ? Z_FINISH : Z_SYNC_FLUSH);
	/* cap is png_deflate_bound's, above deflateBound's worst case and
	 * the flush's block, so one call always finishes. */
	if (!(rc == Z_STREAM_END || (rc == Z_OK && c->z.avail_in == 0 && c->z.avail_out > 0)))
		return RT_E_NOMEM;
	*len = cap - c->z.avail_out;
	return 0;
}

uint32_t png_deflate_adler32(uint32_t adler, const unsigned char *p, size_t n)
{
	uLong a = adler;

	/* zlib's length is an unsigned int: long inputs in pieces. */
	while (n > 0) {
		uInt k = n > (1u << 30) ? (1u << 30) : (uInt)n;

		a = adler32(a, p, k);
		p += k;
		n -= k;
	}
	return (uint32_t)a;
}

const char *png_deflate_library(void)
{
	return "zlib";
}
#else
/* ISO C wants something in a translation unit. */
typedef int png_deflate_zlib_not_built;
#endif
