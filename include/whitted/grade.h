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
#include <stdint.h>

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

/* The same over the pixels whose skip[y * width + x] is 0 (the ties of
 * grade_tie_mask: either colour is right there). */
void grade_figures_skipping(const struct image *a, const struct image *b, const uint8_t *skip,
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
	RT_CAUSE_NO_REFLECTIONS,	/* recursion level 1 */
	RT_CAUSE_RECURSION_LEVEL,	/* another level than one more or one fewer */
	RT_CAUSE_FLOOR_HORIZON,		/* the floor without an edge */
	RT_CAUSE_FLOOR_SIZE,		/* the floor of another width */
	RT_CAUSE_FLOOR_CELL,		/* the checker's cells of another size */
	RT_CAUSE_CHECKER_PHASE,		/* the cells counted from another origin */
	RT_CAUSE_FLOOR_PLACE,		/* the floor with a corner at the origin */
	RT_CAUSE_SPOT_CONE,		/* a spotlight's cone of another width, or none */
	RT_CAUSE_FLOOR_FINISH,		/* the floor's coefficients and shininess another
					 * (the job's floor_finish, fitted) */
	RT_CAUSE_COUNT
};

/* No second cause (struct grade_rank's also). */
#define RT_CAUSE_NONE RT_CAUSE_COUNT

struct grade_cause_text {
	const char *id;		/* short, for scripts: "white-highlight" */
	const char *with;	/* after "matches the reference with ": "the highlight left white" */
	const char *fix;	/* one line in the course's terms */
};

/* The texts of a cause; clamp is the reference's mode (RT_CAUSE_CLAMP_OTHER
 * is the other one). */
const struct grade_cause_text *grade_cause_text(enum grade_cause c, enum clamp_mode clamp);

/* True for the causes that transform the reference's pixels (a mirror,
 * a flip, a transposition, red and blue swapped) rather than render it. */
bool grade_cause_is_transform(enum grade_cause c);
/* True for those of them that move the pixels about (a mirror, a flip, a
 * transposition): another camera may explain such an image as well. */
bool grade_cause_moves_pixels(enum grade_cause c);

/* What a reference is rendered with. */
struct grade_job {
	const struct scene *scene;
	const struct camera *camera;
	struct render_settings settings;
	int samples;		/* --samples N: N x N rays a pixel; 0 or 1: one */
	int threads;
	const volatile sig_atomic_t *cancel;	/* may be NULL */
	/* The floor's finishes found from a submission (grade_fit_floor_finish),
	 * which RT_CAUSE_FLOOR_FINISH renders (its forms): the fit's values
	 * rounded, and as they came; none when n_floor_finishes is 0. */
	int n_floor_finishes;
	struct material floor_finishes[2];
};

struct grade_rank {
	enum grade_cause cause;
	enum grade_cause also;		/* a second cause at once, or RT_CAUSE_NONE */
	/* The form of each cause that came nearest, for its detail
	 * (grade_cause_detail): a recursion level, a width, ... */
	int form, also_form;
	struct grade_figures fig;	/* the cause's image against the submission */
	bool estimated;			/* fig from a sample of the pixels only */
	bool truncated;			/* fig of the image converted by truncation */
	bool first_equal;		/* the same figures as the first: no preference */
};

/* What form `form` of cause c is, in words, for this job ("recursion
 * level 2 instead of 4", "a floor 2000 wide instead of 1000"), into buf;
 * "" when the cause has one form only. */
void grade_cause_detail(const struct grade_job *job, enum grade_cause c, int form, char *buf,
			size_t size);

/* The reference image, the job's camera's size. */
int grade_render_reference(const struct grade_job *job, struct image *ref, struct diag *d);

/* The reference converted by truncation, floor(255 c) of each clamped
 * channel, as the course's own code writes it (rather than rounding). */
int grade_render_truncated(const struct grade_job *job, struct image *out, struct diag *d);

/* The ties of the reference ref (job's render): the pixels whose colour
 * changes when the camera turns by angle (radians) either way about its
 * up or right axis, or zooms by 1 +- angle, marked 1 in mask (a byte a
 * pixel; *n_ties of them): a ray on a checker cell's edge, a shadow ray
 * grazing an occluder, two objects at the same distance, where a tiny
 * change of the ray (another renderer's rounding) changes the colour and
 * either colour is right.  With the angle of the camera fit's precision,
 * the pixels its error may change. */
int grade_tie_mask(const struct grade_job *job, const struct image *ref, double angle,
		   uint8_t *mask, long *n_ties, struct diag *d);

/* The most ranks grade_rank_causes gives: each cause, and pairs. */
#define GRADE_MAX_PAIRS 12
#define GRADE_MAX_RANKS (RT_CAUSE_COUNT + GRADE_MAX_PAIRS)

/* The causes that change the image, best first (highest PSNR against sub):
 * transforms of ref exactly; renders first on a sample of the pixels, then
 * the best few again on every pixel.  With tref (the truncated reference,
 * or NULL) each cause's image is made both ways and the nearer counts.
 * When no single cause explains sub, pairs of the likeliest causes (and
 * the compositions of two transforms: a half turn, a flip with red and
 * blue swapped) are ranked too.  Causes whose figures equal the first's
 * are marked first_equal.  The pixels skip marks (ties; may be NULL) are
 * left out of every figure.  *n is their number (<= GRADE_MAX_RANKS). */
int grade_rank_causes(const struct grade_job *job, const struct image *ref,
		      const struct image *tref, const struct image *sub, const uint8_t *skip,
		      struct grade_rank out[GRADE_MAX_RANKS], size_t *n, struct diag *d);

/* The floor's finish (ambient, diffuse, specular and reflection
 * coefficients, shininess) that brings the job's render nearest sub on a
 * sample of the floor's pixels (those skip, which may be NULL, does not
 * mark; sub's bytes taken as truncated or rounded): a least-squares fit
 * for each of a list of exponents, with the ranked cause `also` (one or a
 * pair, in its forms) rendered too (NULL: the reference; another cause
 * pulls a fit made without it, and the tiles swapped defeat it).  Sets
 * job->floor_finishes (the values rounded to 0.05, then as they came when
 * they differ) when it fits clearly better than the scene floor's own
 * finish and explains the floor (RT_CAUSE_FLOOR_FINISH then renders
 * them), else job->n_floor_finishes to 0; none for a textured floor,
 * --samples, or causes the rules' trace does not render whole.  0, or
 * < 0 with d filled. */
int grade_fit_floor_finish(struct grade_job *job, const struct image *sub, const uint8_t *skip,
			   bool truncated, const struct grade_rank *also, struct diag *d);

/* grade_rank_causes with the floor's finish fitted first
 * (grade_fit_floor_finish, sub's bytes taken as truncated or rounded);
 * then the finish is fitted again with the likeliest rendered too (the
 * cause a finish is paired with, or the likeliest without one: the tiles
 * swapped hide a finish from a fit made without them), and when one is
 * found the causes are ranked again, which stands when its best comes
 * nearer.  The job keeps the finishes its ranking rendered (for
 * grade_cause_detail and grade_cause_image). */
int grade_rank_with_finish(struct grade_job *job, const struct image *ref,
			   const struct image *tref, const struct image *sub, const uint8_t *skip,
			   bool truncated, struct grade_rank out[GRADE_MAX_RANKS], size_t *n,
			   struct diag *d);

/* The image of a ranked cause (or pair), at full size (for the report). */
int grade_cause_image(const struct grade_job *job, const struct image *ref,
		      const struct grade_rank *r, struct image *out, struct diag *d);

/* The camera fit's levels of the image, coarse to fine. */
#define GRADE_FIT_LEVELS 7

/* The camera found from an image (grade_fit_camera). */
struct grade_fit {
	struct camera_params camera;	/* the camera found */
	double score;			/* its mean squared difference on the fit's last
					 * stage's level, before the polish on the
					 * image's own pixels (grey levels: the fit
					 * looks at shapes) */
	double start_score;		/* the first start's on the same level */
	long evals;			/* candidates rendered */
	enum grade_cause cause;		/* the mistake rendered in place of the
					 * reference for the camera found, or
					 * RT_CAUSE_NONE (the plain reference) */
	int form;			/* its form */
	enum grade_cause also;		/* a second one rendered with it (the floor's
					 * shape: its width, then its cells), or
					 * RT_CAUSE_NONE */
	int also_form;
	double levels[GRADE_FIT_LEVELS];	/* the best score on each level
					 * in the search from the starts
					 * (INFINITY where it did not go); of
					 * grade_fit_camera, the plain
					 * reference's: a refit's bound */
};

/* Finds the camera that took sub, whose size the job's camera has: the
 * camera whose render (job's scene and settings) comes nearest sub,
 * searched from the n_starts cameras given (the first one's near plane
 * and aspect are kept).  When no camera comes near the plain reference,
 * the search is made again with each mistake that changes most of an
 * image rendered in its place (gamma; the floor's tiles swapped: they
 * pull a fit of the plain reference away), and the nearest kept; then,
 * if none came near either, with the floor of other widths and cells (a
 * floor of another shape and a moved camera at once).  The score is then
 * that render's, and cause and form (and also, also_form for the floor's
 * cells) say which.  Deterministic: the same answer for any number of threads. */
int grade_fit_camera(const struct grade_job *job, const struct camera_params *starts,
		     int n_starts, const struct image *sub, struct grade_fit *out, struct diag *d);

/* The camera refined from start on the fit's finer levels with form
 * `form` of cause c rendered in place of the reference: a camera and a
 * shading mistake at once (the mistake pulls a fit of the plain
 * reference away).  Abandoned (score INFINITY) on the first level where
 * it comes farther from sub than bound's levels say the plain reference
 * came (bound NULL: never): such a cause explains less than no cause.
 * -RT_E_INVALID for a transform, a form the cause does not have, or one
 * the fit cannot render (rays through the pixels' corners, bytes that
 * wrap).  Deterministic as grade_fit_camera. */
int grade_fit_camera_with(const struct grade_job *job, const struct camera_params *start,
			  enum grade_cause cause, int form, const struct image *sub,
			  const struct grade_fit *bound, struct grade_fit *out, struct diag *d);

/* The nearest hit of a ray in the job's scene, at *t (t in (0, *t)). */
bool grade_primary_hit(const struct grade_job *job, const struct ray *r, double *t);

/* The object-id buffer: for each pixel (y * width + x) of the job's
 * camera, the index in the scene (0-based, file order) of the object its
 * primary ray hits first, GRADE_ID_FLOOR for the floor or
 * GRADE_ID_BACKGROUND for none. */
#define GRADE_ID_BACKGROUND (-1)
#define GRADE_ID_FLOOR (-2)
int grade_object_ids(const struct grade_job *job, int32_t *ids, struct diag *d);

/* Where sub differs from ref, object by object (ids from
 * grade_object_ids; the pixels skip marks left out). */
struct grade_object {
	long index;		/* 1-based in the file; 0 for the floor and the background */
	const char *keyword;	/* "sphere", ...; "floor", "background" */
	long pixels, differ;	/* its pixels, and of them those off by more than 2 levels */
	double off2;		/* differ / pixels */
	double psnr;		/* over its pixels; INFINITY when identical */
};
/* The background, the floor and each object that has pixels, in that
 * order (objects by index), into *out (rt_free it), *n of them. */
int grade_objects(const struct grade_job *job, const int32_t *ids, const struct image *ref,
		  const struct image *sub, const uint8_t *skip, struct grade_object **out,
		  size_t *n, struct diag *d);

/* The picture of compare --diff: grade_diff_image's two halves, with the
 * ties (ties[i] set; may be NULL) in blue on the right and the outline of
 * each object whose slot is set in differs (slot 0 the background, 1 the
 * floor, 2 + i object i of ids; ids and differs may be NULL) in cyan, and
 * a legend in a band under them. */
int grade_diff_picture(const struct image *ref, const struct image *sub, const uint8_t *ties,
		       const int32_t *ids, const uint8_t *differs, struct image *out,
		       struct diag *d);

/* The picture of the difference: 2w x h, on the left |a - b| amplified 8
 * times, on the right the reference dimmed with the pixels off by more
 * than 2 levels in yellow and by more than 8 in red. */
int grade_diff_image(const struct image *ref, const struct image *sub, struct image *out,
		     struct diag *d);

#endif
