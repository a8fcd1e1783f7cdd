/* imgcmp: compares two images sample by sample and gates the result, for
 * the cross-validation against POV-Ray.  Prints PSNR, mean and maximum
 * error and the share of pixels off by more than 2 and more than 8 levels
 * (a pixel's error is its largest channel difference); exits 0 when every
 * gate holds, 1 when one fails or an image cannot be read, 2 on a bad
 * command line.  On failure it writes an amplified difference image and
 * says where the worst pixel is. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "imgio.h"

struct gate {
	double min_psnr;	/* dB */
	double max_off2;	/* percent of pixels off by more than 2 levels */
	double max_off8;	/* percent of pixels off by more than 8 levels */
};

struct stats {
	double psnr, mean;	/* psnr is INFINITY for identical images */
	int max;
	double off2, off8;	/* percent */
	int worst_x, worst_y;
	int box[4];		/* x0 y0 x1 y1 of the pixels off by more than 2 */
};

static void usage(FILE *f)
{
	fprintf(f,
		"Usage: imgcmp [OPTIONS] A B\n"
		"Compares two images (PNG read raw, ignoring gAMA; binary PPM; 24-bit BMP)\n"
		"of the same size and checks the differences against a gate.\n"
		"\n"
		"  --min-psnr DB       fail below this PSNR (default 60)\n"
		"  --max-off2 PERCENT  fail when more pixels are off by more than 2 levels\n"
		"                      (default 0.2)\n"
		"  --max-off8 PERCENT  fail when more pixels are off by more than 8 levels\n"
		"                      (default 0.02)\n"
		"  --diff FILE         write the difference image (|A - B| x AMP, PNG) here,\n"
		"                      pass or fail (default: on failure only, as B's name\n"
		"                      with -diff.png)\n"
		"  --amplify AMP       difference amplification (default 32)\n"
		"  -q, --quiet         print nothing when the gate passes\n"
		"  -h, --help          show this help\n"
		"\n"
		"Exit status: 0 the gate passes, 1 it fails or an image cannot be read,\n"
		"2 bad command line.\n");
}

static int usage_error(const char *what, const char *arg)
{
	fprintf(stderr, "imgcmp: error: %s '%s'\nTry 'imgcmp --help' for more information.\n",
		what, arg);
	return 2;
}

static int parse_nonneg(const char *arg, double *out)
{
	char *end;
	double v = strtod(arg, &end);

	if (end == arg || *end != '\0' || !isfinite(v) || v < 0.0)
		return -1;
	*out = v;
	return 0;
}

static void compare(const struct imgio_image *a, const struct imgio_image *b, struct stats *st)
{
	size_t n = (size_t)a->width * (size_t)a->height, i, off2 = 0, off8 = 0;
	double sum = 0.0, sq = 0.0;
	int k;

	memset(st, 0, sizeof(*st));
	st->box[0] = a->width;
	st->box[1] = a->height;
	st->box[2] = st->box[3] = -1;
	for (i = 0; i < n; i++) {
		int worst = 0;
		for (k = 0; k < 3; k++) {
			int dv = abs((int)a->rgb[3 * i + k] - (int)b->rgb[3 * i + k]);
			sum += dv;
			sq += (double)dv * dv;
			if (dv > worst)
				worst = dv;
		}
		if (worst > st->max) {
			st->max = worst;
			st->worst_x = (int)(i % (size_t)a->width);
			st->worst_y = (int)(i / (size_t)a->width);
		}
		if (worst > 2) {
			int x = (int)(i % (size_t)a->width), y = (int)(i / (size_t)a->width);
			off2++;
			st->box[0] = x < st->box[0] ? x : st->box[0];
			st->box[1] = y < st->box[1] ? y : st->box[1];
			st->box[2] = x > st->box[2] ? x : st->box[2];
			st->box[3] = y > st->box[3] ? y : st->box[3];
		}
		if (worst > 8)
			off8++;
	}
	st->mean = sum / (3.0 * (double)n);
	sq /= 3.0 * (double)n;
	st->psnr = sq == 0.0 ? INFINITY : 10.0 * log10(255.0 * 255.0 / sq);
	st->off2 = 100.0 * (double)off2 / (double)n;
	st->off8 = 100.0 * (double)off8 / (double)n;
}

static int write_diff(const char *path, const struct imgio_image *a, const struct imgio_image *b,
		      double amplify)
{
	struct imgio_image d;
	char msg[IMGIO_MSG_MAX];
	size_t n = (size_t)a->width * (size_t)a->height * 3, i;
	int rc;

	d.width = a->width;
	d.height = a->height;
	d.rgb = malloc(n);
	if (!d.rgb) {
		fprintf(stderr, "imgcmp: error: out of memory\n");
		return -1;
	}
	for (i = 0; i < n; i++) {
		double v = fabs((double)a->rgb[i] - (double)b->rgb[i]) * amplify;
		d.rgb[i] = (uint8_t)(v > 255.0 ? 255.0 : v);
	}
	rc = imgio_write_png(path, &d, false, msg);
	if (rc < 0)
		fprintf(stderr, "imgcmp: error: %s: %s\n", path, msg);
	free(d.rgb);
	return rc;
}

/* B's name without its extension, plus -diff.png. */
static char *default_diff_path(const char *b)
{
	const char *slash = strrchr(b, '/'), *dot = strrchr(b, '.');
	size_t len = dot && (!slash || dot > slash + 1) ? (size_t)(dot - b) : strlen(b);
	char *out = malloc(len + sizeof("-diff.png"));

	if (out) {
		memcpy(out, b, len);
		strcpy(out + len, "-diff.png");
	}
	return out;
}

int main(int argc, char **argv)
{
	struct gate g = { 60.0, 0.2, 0.02 };
	struct imgio_image a = { 0, 0, NULL }, b = { 0, 0, NULL };
	const char *paths[2] = { NULL, NULL }, *diff = NULL;
	char *diff_owned = NULL;
	char msg[IMGIO_MSG_MAX];
	struct stats st;
	double amplify = 32.0;
	bool quiet = false, pass;
	int i, npaths = 0, status = 1;

	for (i = 1; i < argc; i++) {
		const char *o = argv[i];
		double *target = NULL;
		if (strcmp(o, "-h") == 0 || strcmp(o, "--help") == 0) {
			usage(stdout);
			return 0;
		}
		if (strcmp(o, "-q") == 0 || strcmp(o, "--quiet") == 0) {
			quiet = true;
			continue;
		}
		if (strcmp(o, "--min-psnr") == 0)
			target = &g.min_psnr;
		else if (strcmp(o, "--max-off2") == 0)
			target = &g.max_off2;
		else if (strcmp(o, "--max-off8") == 0)
			target = &g.max_off8;
		else if (strcmp(o, "--amplify") == 0)
			target = &amplify;
		if (target || strcmp(o, "--diff") == 0) {
			if (++i == argc)
				return usage_error("option needs a value:", o);
			if (!target)
				diff = argv[i];
			else if (parse_nonneg(argv[i], target) < 0)
				return usage_error("expected a number >= 0, found", argv[i]);
			continue;
		}
		if (o[0] == '-' && o[1] != '\0')
			return usage_error("unknown option", o);
		if (npaths == 2)
			return usage_error("two images expected, found also", o);
		paths[npaths++] = o;
	}
	if (npaths != 2) {
		fprintf(stderr, "imgcmp: error: two images expected\nTry 'imgcmp --help' for more information.\n");
		return 2;
	}
	if (imgio_read(paths[0], &a, msg) < 0) {
		fprintf(stderr, "imgcmp: error: %s: %s\n", paths[0], msg);
		goto out;
	}
	if (imgio_read(paths[1], &b, msg) < 0) {
		fprintf(stderr, "imgcmp: error: %s: %s\n", paths[1], msg);
		goto out;
	}
	if (a.width != b.width || a.height != b.height) {
		fprintf(stderr, "imgcmp: FAIL: %s is %dx%d, %s is %dx%d\n", paths[0], a.width,
			a.height, paths[1], b.width, b.height);
		goto out;
	}
	compare(&a, &b, &st);
	pass = st.psnr >= g.min_psnr && st.off2 <= g.max_off2 && st.off8 <= g.max_off8;
	if (!pass || !quiet)
		printf("psnr=%.2f mean=%.4f max=%d off2=%.4f%% off8=%.4f%% %s\n", st.psnr, st.mean,
		       st.max, st.off2, st.off8, pass ? "PASS" : "FAIL");
	if (!pass) {
		fprintf(stderr, "imgcmp: FAIL: %s vs %s: gate PSNR >= %g dB, <= %g%% off by >2, <= %g%% off by >8\n",
			paths[0], paths[1], g.min_psnr, g.max_off2, g.max_off8);
		fprintf(stderr, "imgcmp: worst pixel (%d,%d) off by %d", st.worst_x, st.worst_y, st.max);
		if (st.box[2] >= 0)
			fprintf(stderr, "; pixels off by >2 lie in x %d..%d, y %d..%d", st.box[0],
				st.box[2], st.box[1], st.box[3]);
		fputc('\n', stderr);
		if (!diff)
			diff = diff_owned = default_diff_path(paths[1]);
	}
	status = pass ? 0 : 1;
	if (diff) {
		if (write_diff(diff, &a, &b, amplify) < 0)
			status = 1;
		else if (!pass)
			fprintf(stderr, "imgcmp: difference (x%g) written to %s\n", amplify, diff);
	}
out:
	imgio_free(&a);
	imgio_free(&b);
	free(diff_owned);
	return status;
}
