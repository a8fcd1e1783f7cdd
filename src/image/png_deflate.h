/* The deflate of a PNG's strips (png_idat.c): each strip's filtered rows
 * compressed on their own, no history crossing from one strip to the
 * next, every strip but the last ending on a byte and not final, the last
 * ending the stream; so the strips' outputs, one after the other, are one
 * raw deflate stream, whichever thread compressed which.  Two libraries
 * do it, behind one table: Intel's ISA-L (igzip, Debian's libisal-dev),
 * where the build found it (RT_HAVE_ISAL), four times as fast as zlib's
 * level 1 on a 1536x1536 render for a file 6% larger; and zlib at level 1,
 * always built (the fallback, and tested beside ISA-L).  A file's bytes
 * are the same for any thread count with either, but differ between them
 * (and may between ISA-L's code for different processors): the pixels do
 * not. */
#ifndef RT_PNG_DEFLATE_H
#define RT_PNG_DEFLATE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

struct png_deflate_ops {
	const char *name;	/* "isa-l", "zlib" */
	/* Readies the library for use from several threads: called once,
	 * before any thread compresses (ISA-L picks its code for the
	 * processor at its functions' first calls, writing pointers no lock
	 * guards).  May be NULL. */
	void (*prepare)(void);
	/* One thread's compressor, kept from strip to strip: 0, or
	 * RT_E_NOMEM (*out NULL).  free takes NULL. */
	int (*make)(void **out);
	void (*free)(void *c);
	/* in[0, n) into out (cap at least png_deflate_bound(n)); *len the
	 * bytes written.  0, or RT_E_NOMEM when the library failed (a strip
	 * over INT_MAX bytes, or a broken state: it allocates nothing). */
	int (*strip)(void *c, const unsigned char *in, size_t n, bool last, unsigned char *out,
		     size_t cap, size_t *len);
	/* The Adler-32 of p[0, n) continued from adler (1 for none). */
	uint32_t (*adler32)(uint32_t adler, const unsigned char *p, size_t n);
};

extern const struct png_deflate_ops png_deflate_zlib;
#ifdef RT_HAVE_ISAL
extern const struct png_deflate_ops png_deflate_isal;
#endif

/* The fastest the build has, prepared (thread-safe; call it before
 * starting the threads that compress). */
const struct png_deflate_ops *png_deflate_best(void);

/* A strip's output never exceeds this for n bytes in, with either
 * library (its stored blocks' 5 bytes a 64 KiB, zlib's compressBound and
 * the sync flush's 5 bytes, ISA-L's largest block header). */
static inline size_t png_deflate_bound(size_t n)
{
	return n + n / 1024 + 1024;
}

#endif
