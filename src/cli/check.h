/* What `whitted compare` and `whitted grade` share: their options, the
 * reference render, and the check of one submitted image (its figures
 * against the gate, the camera that took it when it is not the given one,
 * and the likely causes when it differs). */
#ifndef RT_CLI_CHECK_H
#define RT_CLI_CHECK_H

#include <stdbool.h>

#include "cli/scene_opts.h"
#include "whitted/grade.h"

/* Exit statuses besides tool.h's: the image differs from the reference. */
#define CHECK_EXIT_DIFFERS 3

#define CHECK_MAX_SCENES 16

struct check_options {
	struct cli_scene scene;
	int threads;
	bool grade;			/* whitted grade (else compare) */
	const char *diff_path;		/* compare --diff */
	bool json;			/* compare --json */
	bool no_fit;			/* --no-camera-fit: judge at the given camera only */
	const char *report_path;	/* grade -o */
	const char *csv_path;		/* grade --csv */
	const char *marks_path;		/* grade --marks: the points table */
	const char *scenes[CHECK_MAX_SCENES];	/* grade --scene, in order */
	int n_scenes;
	char **images;			/* the IMAGE operands */
	int n_images;
};

/* Fills o from argv (argv[0] is the subcommand).  Returns 0, or the exit
 * status to stop with (usage error printed: 2; --help: -1 for exit 0). */
int check_args_parse(int argc, char **argv, bool grade, struct check_options *o);

/* The reference at one camera and size: its render, that render converted
 * by truncation (made when first needed) and its ties. */
struct check_view {
	struct camera_params params;
	struct camera camera;
	struct grade_job job;
	struct image image;
	struct image truncated;
	uint8_t *ties;			/* a byte a pixel: either colour is right */
	long n_ties;
	double tie_angle;		/* the camera's uncertainty the ties allow for */
};

struct check_reference {
	struct scene *scene;
	struct camera_params params;	/* the camera given (or the dialect's) */
	bool camera_given;		/* --eye, --look, --up or --fov */
	bool lenient;			/* read by the count-driven rule */
	bool fit;			/* find the camera when the given one does not fit */
	struct check_view view;		/* at the scene's size (or --size) */
	struct grade_job base;		/* settings, samples, threads, cancel */
};

/* Loads the scene and renders the reference; on failure prints the error
 * and returns the exit status (1, or 2 for a bad camera). */
int check_reference_make(struct check_options *o, struct check_reference *ref);
void check_reference_free(struct check_reference *ref);

/* The reference of ref's scene seen by camera p at width x height, with
 * ties for a camera known within angle radians; *v freed with
 * check_view_free. */
int check_view_make(const struct check_reference *ref, const struct camera_params *p, int width,
		    int height, double angle, struct check_view *v, struct diag *d);
void check_view_free(struct check_view *v);
/* Takes out of a found camera's ties the pixels whose submitted colour no
 * camera within a pixel gives (outside the reference's 3 x 3
 * neighbourhood's range); returns how many (check_geometry.c). */
long check_ties_outside(struct check_view *v, const struct image *sub);
/* The view at a camera found, the ties allowing for the fit's own
 * uncertainty (check_geometry.c). */
int check_found_view(const struct check_reference *ref, const struct check_view *v,
		     const struct camera_params *p, struct check_view *out, struct diag *d);
/* Whether sub is the plain reference seen from the camera found turned a
 * quarter about the vertical axis through the origin (a symmetric scene's
 * tiles swapped); then found becomes that view and *fig its figures
 * (check_geometry.c). */
int check_quarter_turn(const struct check_reference *ref, struct check_view *found,
		       const struct image *sub, struct grade_figures *fig, struct diag *d);
/* Moves view from into to (its job's camera is its own: a plain copy
 * would point at from's); from is left empty. */
void check_view_move(struct check_view *to, struct check_view *from);

/* How far camera b shows what camera a shows at its pixels, in pixels
 * (the median of a grid of a's hits seen through b; check_geometry.c). */
double check_displacement(const struct check_view *a, const struct check_view *b);
/* The image as it is (res->fig may have judged a textured floor as the
 * reference's) against the references at two cameras, on the same
 * pixels: neither camera's ties (a found camera's take in every edge,
 * where a wrong camera differs most).  With a cause (the one the fit
 * found the camera with, and its second: the floor's width and cells),
 * its render at each camera in the reference's place: the floor's tiles
 * swapped at the true camera are farther from the plain reference than a
 * wrong camera's plain view can be. */
int check_compare_cameras(const struct check_view *a, const struct check_view *b,
			  const struct image *sub, const struct grade_fit *fit,
			  struct grade_figures *fa, struct grade_figures *fb, struct diag *d);
/* Whether sub's floor is textured where ref's (ids: ref's object ids) is
 * a plain checker. */
bool check_floor_textured(const struct image *ref, const struct image *sub, const int32_t *ids);

enum check_verdict {
	CHECK_MATCH,		/* within the gate (at the given camera, or at the one found) */
	CHECK_DIFFERS,
	CHECK_UNREADABLE,	/* not an image, or truncated */
};

/* How well the best explanation explains a differing image. */
enum check_explained {
	CHECK_EXPLAINED,	/* its image matches the submission within the gate */
	CHECK_CLOSE,		/* much closer than the reference, not within the gate */
	CHECK_NONE,		/* nothing comes close */
};
/* With nothing close, an image this near the reference (at the camera
 * found) is said to nearly match: a person sees the same picture (about 4
 * levels root mean square), and what remains is as likely a camera found
 * a little off as a mistake. */
#define CHECK_NEAR_PSNR 35.0

struct check_result {
	enum check_verdict verdict;
	struct grade_figures fig;	/* against the reference at the given camera (for a
					 * truncated match, its truncated conversion) */
	struct grade_figures fig_rounded;	/* against the rounded reference */
	bool truncated;			/* nearer the reference converted by truncation */
	char size_note[200];		/* "" or why it was compared at another size */
	bool floor_textured;		/* the floor is no two-colour checker: judged without it */
	bool floor_alone;		/* the camera fit found a view of no object (not taken) */
	struct check_view own;		/* the reference at the image's size when it is
					 * not the scene's (else empty) */
	/* The camera: fitted when the image does not fit the given one. */
	bool fitted, moved;
	struct check_view found;	/* at the camera found (when moved) */
	struct grade_figures fig_found;	/* against the reference there */
	long fit_evals;
	struct grade_fit fit;		/* the fit (when fitted): its levels bound
					 * the refits with a cause */
	/* The causes, at the camera of the explanation (found when moved). */
	struct grade_rank ranks[GRADE_MAX_RANKS];
	size_t n_ranks;
	enum check_explained explained;
	/* Object by object, at that camera. */
	struct grade_object *objects;
	size_t n_objects;
	int32_t *ids;			/* the object-id buffer there */
	struct image image;		/* the submission (empty when unreadable) */
	struct diag error;		/* why it is unreadable */
};

/* The view of the explanation: the camera found when it moved, else the
 * given one at the image's size. */
const struct check_view *check_result_view(const struct check_reference *ref,
					   const struct check_result *res);

/* Reads and checks one image.  Returns 0 with res filled (an unreadable
 * image is a verdict, not a failure), or a negative status when the check
 * itself failed (out of memory, interrupted) with d filled. */
int check_image(struct check_reference *ref, const char *path, struct check_result *res,
		struct diag *d);
/* The same for an image in memory (a zip file's entry); name for the
 * messages. */
int check_image_data(struct check_reference *ref, const char *name, const unsigned char *data,
		     size_t len, struct check_result *res, struct diag *d);
void check_result_free(struct check_result *res);
/* Whether view v shows the scene's objects on CHECK_MOVED_OBJECT_SHARE of
 * its pixels, or the scene has none to show (*shows). */
int check_shows_objects(const struct scene *scene, const struct check_view *v, bool *shows,
			struct diag *d);
/* The submission as it is judged at view v: itself (judged left empty),
 * or with a textured floor's pixels taken from the reference (that floor
 * is not judged); sets res->floor_textured. */
int check_judged(const struct check_view *v, struct check_result *res, struct image *judged,
		 struct diag *d);

/* The difference picture of res: against the reference of its
 * explanation's camera, in the conversion its verdict used, with the ties
 * and the outlines of the objects that differ, and a legend. */
int check_diff_picture(const struct check_reference *ref, const struct check_result *res,
		       struct image *out, struct diag *d);

/* The camera found, as whitted's options ("--eye X,Y,Z --look ...
 * --up ... --fov F"). */
void check_camera_options(const struct camera_params *p, char *buf, size_t size);

/* A cause (or pair) of the ranking in words: "the highlight left white",
 * "no shadows and the floor's tiles swapped", with each cause's form
 * ("another recursion level (recursion level 2 instead of 4)"). */
void check_cause_words(const struct check_reference *ref, const struct check_result *res,
		       const struct grade_rank *r, char *buf, size_t size);
/* Its id for scripts: "white-highlight", "no-shadows+floor-swapped". */
void check_cause_id(const struct check_reference *ref, const struct grade_rank *r, char *buf,
		    size_t size);
/* Its fix, or both fixes joined by "; and ". */
void check_cause_fix(const struct check_reference *ref, const struct grade_rank *r, char *buf,
		     size_t size);

/* One sentence on the likely cause ("matches the reference with ...: fix
 * ...", "your camera differs: found ...; at that camera ...", "none of
 * the known mistakes comes close"). */
void check_diagnosis(const struct check_reference *ref, const struct check_result *res,
		     char *buf, size_t size);
/* One line on where it differs, object by object ("the 3 spheres and 2
 * triangles match; the floor differs in 41% of its pixels"), or "". */
void check_objects_line(const struct check_result *res, char *buf, size_t size);

#endif
