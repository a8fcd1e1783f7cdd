/* A PNG file's structure checked before any decoder allocates for it
 * (png_check.c): the readers of submitted images and textures (stb_image)
 * and of tiles (libpng) call it first. */
#ifndef RT_PNG_CHECK_H
#define RT_PNG_CHECK_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "whitted/diag.h"

/* What png_check found. */
struct png_facts {
	uint32_t width, height;
	int bit_depth, color_type, interlace;
	uint64_t raw_bytes;	/* the image data inflated: rows with their filter bytes */
	size_t end;		/* the offset just past IEND: the file's length unless junk follows */
};

/* Checks the PNG b[0..len) named `name` in messages, in time linear in
 * len and the header's image size and in constant memory: the signature;
 * every chunk whole and its CRC right ("damaged PNG file (bad CRC in its
 * IDAT chunk)"); IHDR first and valid; width x height at most max_pixels
 * ("30000x30000 is over the limit of 67108864 pixels (8192x8192)"); the
 * compressed data able to hold the header's image (deflate expands at most
 * 1032 times: a 400-byte file cannot claim 16384x16384); the data inflating
 * (zlib) to exactly the bytes the header describes, stopping at the first
 * byte more ("too much image data"; only when `data`: a reader of the
 * header alone skips it); an IEND.  RT_E_SYNTAX or RT_E_RANGE (the size),
 * with *out filled on success. */
int png_check(const unsigned char *b, size_t len, const char *name, uint64_t max_pixels,
	      bool data, struct png_facts *out, struct diag *d);

#endif
