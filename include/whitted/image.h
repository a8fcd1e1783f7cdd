/* 8-bit RGB images and their writers (PNG, 24-bit BMP, binary PPM). */
#ifndef RT_IMAGE_H
#define RT_IMAGE_H

#include <signal.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

#include "diag.h"

struct image {
	int width, height;
	uint8_t *pixels;	/* rows top to bottom, 3 bytes per pixel */
};

enum image_format {
	RT_FORMAT_UNKNOWN = 0,
	RT_FORMAT_PNG,
	RT_FORMAT_BMP,
	RT_FORMAT_PPM,
};

/* Reads a PNG, a BMP (24 or 32 bits, bottom-up or top-down, padded rows)
 * or a PPM (binary P6 or ASCII P3; also P5) into 8-bit RGB.  A file that is
 * not one of them, is truncated or corrupt fails with RT_E_SYNTAX (its
 * name and why in the diag), an unreadable one with RT_E_IO. */
int image_read(const char *path, struct image *img, enum image_format *format, struct diag *d);
/* The same from bytes in memory; name is for the messages.  *format (when
 * format is not NULL) is the file's kind, told by its first bytes. */
int image_read_memory(const unsigned char *data, size_t len, const char *name, struct image *img,
		      enum image_format *format, struct diag *d);

/* The image as PNG bytes in *out (rt_malloc; free with rt_free or free). */
int image_encode_png(const struct image *img, unsigned char **out, size_t *out_len,
		     struct diag *d);

int image_alloc(struct image *img, int width, int height, struct diag *d);
void image_free(struct image *img);

/* The format named by a path's extension (case-insensitive), or UNKNOWN. */
enum image_format image_format_from_path(const char *path);
/* "png", "bmp", "ppm" to the format, or UNKNOWN. */
enum image_format image_format_from_name(const char *name);
/* The format's name ("png"; "?" for UNKNOWN): --format's word, the file
 * extension, POV-Ray's image_map keyword. */
const char *image_format_name(enum image_format fmt);
/* The formats' names for a message, each after prefix ("." for the
 * extensions): "png, bmp or ppm"; returns buf. */
const char *image_format_names(char *buf, size_t size, const char *prefix);
/* The format whose signature bytes start data, or UNKNOWN. */
enum image_format image_format_of_bytes(const unsigned char *data, size_t len);

/* Writers to an open stream; they report I/O errors through the diag. */
int image_write_png(const struct image *img, FILE *f, struct diag *d);
int image_write_bmp(const struct image *img, FILE *f, struct diag *d);
int image_write_ppm(const struct image *img, FILE *f, struct diag *d);

/* Writes img to path.  A regular (or new) file is written to a temporary
 * file in the same directory and renamed over path, so that a failure never
 * leaves a partial image; anything else (a pipe, a device) is written
 * directly.  When cancel becomes non-zero during the write, it fails with
 * RT_E_INTERRUPTED and leaves nothing behind. */
int image_write(const struct image *img, const char *path, enum image_format fmt,
		const volatile sig_atomic_t *cancel, struct diag *d);

/* Writes a file's contents to a stream, for image_write_file. */
typedef int image_fill_fn(void *ctx, FILE *f, struct diag *d);

/* Writes whatever fill writes to path, with the same safety as
 * image_write (which is this with an image writer as fill). */
int image_write_file(const char *path, image_fill_fn *fill, void *ctx,
		     const volatile sig_atomic_t *cancel, struct diag *d);

/* A PNG whose image data is compressed while the image is being made:
 * the rows are cut into bands of image_png_writer_band_rows() rows from
 * the top, and a thread that has made a band's rows final (the render's:
 * render_job.band_done) calls image_png_writer_band_done(w, band, thread)
 * with a thread number in [0, threads), once per band, never twice at
 * once with the same number; the band is then compressed on that thread
 * as soon as the band above it is final too.  image_png_writer_write,
 * once no thread calls any more, compresses whatever is left and writes
 * the file as image_write does: the very same bytes.  img stays in place,
 * its bands told unchanged, until image_png_writer_free. */
struct image_png_writer;

int image_png_writer_open(const struct image *img, int threads, struct image_png_writer **out,
			  struct diag *d);
int image_png_writer_band_rows(void);
void image_png_writer_band_done(void *w, int band, int thread);
int image_png_writer_write(struct image_png_writer *w, const char *path,
			   const volatile sig_atomic_t *cancel, struct diag *d);
void image_png_writer_free(struct image_png_writer *w);

/* True when image_write writes path in place rather than through a
 * temporary file: an existing non-regular file (a pipe, a device) or a path
 * under /dev/ or /proc/ (/dev/stdout, /dev/fd/N, /proc/self/fd/N). */
bool image_path_is_direct(const char *path);

#endif
