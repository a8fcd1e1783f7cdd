/* Checking a student's image against the reference render: the figures of
 * the gate (PSNR, mean error, the shares of pixels off by more than 2, 8
 * and 32 levels) and the likely mistake, found by rendering the scene with
 * one rule of the assignment broken (or transforming the reference) and
 * ranking those images by how close each comes to the submission. */
#ifndef RT_GRADE_H
#define RT_GRADE_H

#include <signal.h>
#include <stdbool.h>
#include <stddef.h>

#include "camera.h"
#include "diag.h"
#include "image.h"
#include "render.h"
#include "scene.h"

/* The gate of tests/povcheck.sh: an image matches the reference when all
 * three hold, the PSNR taken without the worst 0.02 % of the pixels (which
 * the third clause allows to be off by any amount). */
#define RT_GRADE_MIN_PSNR 60.0
#define RT_GRADE_MAX_OFF2 0.002		/* share of pixels off by more than 2 levels */
#define RT_GRADE_MAX_OFF8 0.0002	/* ... by more than 8 */

struct grade_figures {
	double psnr;			/* dB over the channels; INFINITY when identical */
	double psnr_gate;		/* the same without the worst pixels the > 8 clause
					 * allows (at most 0.02 %): the gate's PSNR clause */
	long left_out;			/* how many pixels psnr_gate leaves out */
	double mean_error;		/* mean |a - b| over the channels, in levels */
	double off2, off8, off32;	/* shares (0..1) of pixels whose worst channel is off by more */
	long pixels;			/* compared */
	bool match;			/* the gate holds */
};

/* a and b of the same size; every pixel, or with stride > 1 those at
 * (x, y) with x % stride == ox and y % stride == oy. */
void grade_figures_of(const struct image *a, const struct image *b, int stride, int ox, int oy,
		      struct grade_figures *f);

/* The mistakes, in the order of their table (ties rank in this order). */
enum grade_cause {
	RT_CAUSE_MIRRORED,
	RT_CAUSE_UPSIDE_DOWN,
	RT_CAUSE_TRANSPOSED,
	RT_CAUSE_RED_BLUE,
	RT_CAUSE_GAMMA,
	RT_CAUSE_WHITE_SPECULAR,
	RT_CAUSE_NO_SHADOWS,
	RT_CAUSE_LIGHT_BEHIND,
	RT_CAUSE_RECURSION_FEWER,
	RT_CAUSE_RECURSION_MORE,
	RT_CAUSE_CLAMP_OTHER,
	RT_CAUSE_NEVER_CLAMP,
	RT_CAUSE_PIXEL_CORNERS,
	RT_CAUSE_UNIT_STARTS,
	RT_CAUSE_FLOOR_SWAPPED,
	RT_CAUSE_COUNT
};

struct grade_cause_text {
	const char *id;		/* short, for scripts: "white-highlight" */
	const char *with;	/* after "matches the reference with ": "the highlight left white" */
	const char *fix;	/* one line in the course's terms */
};

/* The texts of a cause; clamp is the reference's mode (RT_CAUSE_CLAMP_OTHER
 * is the other one). */
const struct grade_cause_text *grade_cause_text(enum grade_cause c, enum clamp_mode clamp);

/* What a reference is rendered with. */
struct grade_job {
	const struct scene *scene;
	const struct camera *camera;
	struct render_settings settings;
	int samples;		/* --samples N: N x N rays a pixel; 0 or 1: one */
	int threads;
	const volatile sig_atomic_t *cancel;	/* may be NULL */
};

struct grade_rank {
	enum grade_cause cause;
	struct grade_figures fig;	/* the cause's image against the submission */
	bool estimated;			/* fig from a sample of the pixels only */
	bool truncated;			/* fig of the image converted by truncation */
	bool first_equal;		/* the same figures as the first: no preference */
};

/* The reference image, cam->size square. */
int grade_render_reference(const struct grade_job *job, struct image *ref, struct diag *d);

/* The reference converted by truncation, floor(255 c) of each clamped
 * channel, as the course's own code writes it (rather than rounding). */
int grade_render_truncated(const struct grade_job *job, struct image *out, struct diag *d);

/* The causes that change the image, best first (highest PSNR against sub):
 * transforms of ref exactly; renders first on a sample of the pixels, then
 * the best few again on every pixel.  With tref (the truncated reference,
 * or NULL) each cause's image is made both ways and the nearer counts.
 * Causes whose figures equal the first's are marked first_equal.  *n is
 * their number (<= RT_CAUSE_COUNT). */
int grade_rank_causes(const struct grade_job *job, const struct image *ref,
		      const struct image *tref, const struct image *sub,
		      struct grade_rank out[RT_CAUSE_COUNT], size_t *n, struct diag *d);

/* The image of one cause, at full size (for the report). */
int grade_cause_image(const struct grade_job *job, const struct image *ref, enum grade_cause c,
		      struct image *out, struct diag *d);

/* The picture of the difference: 2w x h, on the left |a - b| amplified 8
 * times, on the right the reference dimmed with the pixels off by more
 * than 2 levels in yellow and by more than 8 in red. */
int grade_diff_image(const struct image *ref, const struct image *sub, struct image *out,
		     struct diag *d);

#endif
