/* imgfilter: makes the altered images that imgcmp's own tests compare.
 *   imgfilter gamma G IN OUT.png     v' = 255 (v / 255)^(1 / G), rounded
 *   imgfilter gama1 IN OUT.png       the same samples, tagged with gAMA 1.0
 *   imgfilter poke X Y DELTA IN OUT.png   one pixel's channels moved by DELTA
 *   imgfilter box N IN OUT.png       reduced N times by N x N box averaging:
 *                                    each channel the rounded mean of its block
 * Exit status 0, 1 on an I/O error, 2 on a bad command line. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imgio.h"

static int bad_usage(void)
{
	fprintf(stderr, "usage: imgfilter gamma G IN OUT | gama1 IN OUT | poke X Y DELTA IN OUT | box N IN OUT\n");
	return 2;
}

static uint8_t clamp_level(double v)
{
	return (uint8_t)(v < 0.0 ? 0.0 : v > 255.0 ? 255.0 : v);
}

int main(int argc, char **argv)
{
	struct imgio_image img;
	char msg[IMGIO_MSG_MAX];
	const char *in, *out;
	bool gama1 = false;
	size_t i, n;
	int rc;

	if (argc == 5 && strcmp(argv[1], "gamma") == 0) {
		in = argv[3];
		out = argv[4];
	} else if (argc == 4 && strcmp(argv[1], "gama1") == 0) {
		in = argv[2];
		out = argv[3];
		gama1 = true;
	} else if (argc == 5 && strcmp(argv[1], "box") == 0) {
		in = argv[3];
		out = argv[4];
	} else if (argc == 7 && strcmp(argv[1], "poke") == 0) {
		in = argv[5];
		out = argv[6];
	} else {
		return bad_usage();
	}
	if (imgio_read(in, &img, msg) < 0) {
		fprintf(stderr, "imgfilter: %s: %s\n", in, msg);
		return 1;
	}
	n = (size_t)img.width * (size_t)img.height * 3;
	if (strcmp(argv[1], "box") == 0) {
		int f = atoi(argv[2]), w = img.width, x, y, k, dx, dy;
		if (f < 1 || img.width % f || img.height % f) {
			fprintf(stderr, "imgfilter: %s: %dx%d is not a multiple of %s\n", in,
				img.width, img.height, argv[2]);
			imgio_free(&img);
			return 2;
		}
		/* In place: block (x, y) is read only after every block before it. */
		for (y = 0; y < img.height / f; y++)
			for (x = 0; x < w / f; x++)
				for (k = 0; k < 3; k++) {
					long sum = 0;
					for (dy = 0; dy < f; dy++)
						for (dx = 0; dx < f; dx++)
							sum += img.rgb[((size_t)(y * f + dy) * (size_t)w +
									(size_t)(x * f + dx)) * 3 + (size_t)k];
					img.rgb[((size_t)y * (size_t)(w / f) + (size_t)x) * 3 + (size_t)k] =
						(uint8_t)((2 * sum + f * f) / (2 * f * f));
				}
		img.width /= f;
		img.height /= f;
	} else if (strcmp(argv[1], "gamma") == 0) {
		double g = atof(argv[2]);
		if (!(g > 0.0)) {
			imgio_free(&img);
			return bad_usage();
		}
		for (i = 0; i < n; i++)
			img.rgb[i] = clamp_level(floor(255.0 * pow(img.rgb[i] / 255.0, 1.0 / g) + 0.5));
	} else if (!gama1) {
		int x = atoi(argv[2]), y = atoi(argv[3]), delta = atoi(argv[4]), k;
		if (x < 0 || y < 0 || x >= img.width || y >= img.height) {
			imgio_free(&img);
			return bad_usage();
		}
		for (k = 0; k < 3; k++) {
			uint8_t *p = &img.rgb[((size_t)y * (size_t)img.width + (size_t)x) * 3 + (size_t)k];
			*p = clamp_level((double)*p + delta);
		}
	}
	rc = imgio_write_png(out, &img, gama1, msg);
	if (rc < 0)
		fprintf(stderr, "imgfilter: %s: %s\n", out, msg);
	imgio_free(&img);
	return rc < 0 ? 1 : 0;
}
