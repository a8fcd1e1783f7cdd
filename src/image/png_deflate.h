/* The deflate of a PNG's strips (png_idat.c): each strip's filtered rows
 * compressed on their own, no history crossing from one strip to the
 * next, every strip but the last ending on a byte and not final, the last
 * ending the stream; so the strips' outputs, one after the other, are one
 * raw deflate stream, whichever thread compressed which.  Built on Intel's
 * ISA-L (igzip, Debian's libisal-dev) where the build found it
 * (RT_HAVE_ISAL): on a 1536x1536 render it compresses the rows seven
 * times as fast as zlib's fastest level, to a smaller file; else on
 * zlib at level 1. */
#ifndef RT_PNG_DEFLATE_H
#define RT_PNG_DEFLATE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* One thread's compressor, kept from strip to strip. */
struct png_deflate;

/* 0, or RT_E_NOMEM (*out NULL). */
int png_deflate_new(struct png_deflate **out);
void png_deflate_free(struct png_deflate *c);

/* A strip's output never exceeds this for n bytes in, with either
 * library (its stored blocks' 5 bytes a 64 KiB, zlib's compressBound and
 * the sync flush's 5 bytes, ISA-L's largest block header). */
static inline size_t png_deflate_bound(size_t n)
{
	return n + n / 1024 + 1024;
}

/* in[0, n) into out (cap at least png_deflate_bound(n)); *len the bytes
 * written.  0, or RT_E_NOMEM when the library failed (it allocates
 * nothing here: only a broken state can fail). */
int png_deflate_strip(struct png_deflate *c, const unsigned char *in, size_t n, bool last,
		      unsigned char *out, size_t cap, size_t *len);

/* The Adler-32 of p[0, n) continued from adler (1 for none). */
uint32_t png_deflate_adler32(uint32_t adler, const unsigned char *p, size_t n);

/* "isa-l" or "zlib": which library the build compresses with. */
const char *png_deflate_library(void);

#endif
