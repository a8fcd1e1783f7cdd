/* Image files for the comparison tools: raw 8-bit RGB samples from PNG
 * (whatever gAMA or sRGB chunk it carries), binary PPM and 24-bit BMP,
 * and PNG output. */
#ifndef RT_IMGIO_H
#define RT_IMGIO_H

#include <stdbool.h>
#include <stdint.h>

#define IMGIO_MSG_MAX 512

struct imgio_image {
	int width, height;
	uint8_t *rgb;		/* rows top to bottom, 3 bytes per pixel */
};

/* Reads path by its content (PNG, P6 PPM with maxval 255, or uncompressed
 * 24-bit BMP).  Returns 0, or -1 with a message in msg. */
int imgio_read(const char *path, struct imgio_image *img, char msg[IMGIO_MSG_MAX]);
/* Writes an 8-bit RGB PNG; with gama1 it carries a gAMA chunk saying the
 * samples are linear, as POV-Ray's do.  Returns 0 or -1 with msg. */
int imgio_write_png(const char *path, const struct imgio_image *img, bool gama1,
		    char msg[IMGIO_MSG_MAX]);
void imgio_free(struct imgio_image *img);

#endif
