/* The check of one submitted image: at its own size, against the
 * reference with its ties left out, then (when it differs) the likely
 * causes, the camera that took it and the causes at that camera, and
 * where it differs object by object. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "cli/check.h"

/* A cause "comes close" when its image is CHECK_CLOSE_GAIN dB nearer the
 * submission than the reference is and at least CHECK_CLOSE_PSNR, or
 * CHECK_FAR_GAIN dB nearer whatever its PSNR: a second mistake (or a tie
 * broken otherwise along a tile edge) can keep the right cause from
 * explaining every pixel. */
#define CHECK_CLOSE_GAIN 3.0
#define CHECK_CLOSE_PSNR 30.0
#define CHECK_FAR_GAIN 6.0

/* The camera found counts as another one when it shows the scene's
 * points more than CHECK_MOVED_PIXELS from where the given one does
 * (check_displacement) and comes at least CHECK_MOVED_GAIN dB nearer
 * the submission. */
#define CHECK_MOVED_PIXELS 1.5
#define CHECK_MOVED_GAIN 3.0
/* ... and reaches at least this: below it, the camera is as unknown as
 * before (another scene, another renderer). */
#define CHECK_MOVED_PSNR 20.0
/* ... or its grey mean squared difference on the fit's last level is at
 * most this share of the given camera's (3 dB less: half) and at most
 * CHECK_MOVED_GREY_MSE (20 dB). */
#define CHECK_MOVED_GREY 0.5
/* A camera taken on greys alone that the plain reference found and that
 * does not quarter the given camera's grey difference (6 dB) is weak
 * evidence: it stands only where, at that camera, the image matches or a
 * cause comes close.  r02 of tests/data/student-renders-more, a view
 * from nearer the objects, "found" a camera far back (0.43 of the given
 * camera's greys, 17 dB in colour) where nothing explained it; two gamma
 * images of the moved-camera set found their right cameras as weakly
 * (0.34), and gamma is named there at 44 dB.  A camera fitted with a
 * mistake rendered is borne out by that mistake's coming nearer. */
#define CHECK_MOVED_GREY_FIRM 0.25
#define CHECK_MOVED_GREY_MSE 650.0

const struct check_view *check_result_view(const struct check_reference *ref,
					   const struct check_result *res)
{
	if (res->moved)
		return &res->found;
	return res->own.image.pixels ? &res->own : &ref->view;
}

/* The figures of sub against the view's reference, ties left out; and
 * against its truncated conversion when that is nearer.  Sets res's
 * figures when fig is res->fig. */
static int check_figures(struct check_view *v, const struct image *sub, struct grade_figures *fig,
			 struct grade_figures *rounded, bool *truncated, struct diag *d)
{
	struct grade_figures tfig;
	int rc;

	grade_figures_skipping(&v->image, sub, v->ties, fig);
	*rounded = *fig;
	*truncated = false;
	if (fig->match)
		return 0;
	/* The course's code writes (unsigned char)(255 c), a truncation: an
	 * image that matches the reference converted that way is right. */
	if (!v->truncated.pixels && (rc = grade_render_truncated(&v->job, &v->truncated, d)) < 0)
		return rc;
	grade_figures_skipping(&v->truncated, sub, v->ties, &tfig);
	*truncated = tfig.psnr > fig->psnr;
	if (tfig.match)
		*fig = tfig;
	return 0;
}

static void check_explain(struct check_result *res, const struct grade_figures *plain)
{
	const struct grade_figures *best = res->n_ranks > 0 ? &res->ranks[0].fig : NULL;

	res->explained = CHECK_NONE;
	if (!best)
		return;
	if (best->match)
		res->explained = CHECK_EXPLAINED;
	else if ((best->psnr >= CHECK_CLOSE_PSNR && best->psnr >= plain->psnr + CHECK_CLOSE_GAIN) ||
		 best->psnr >= plain->psnr + CHECK_FAR_GAIN)
		res->explained = CHECK_CLOSE;
}

/* The nearest the image comes to the reference (plain) or to the first
 * cause ranked. */
static double check_best_psnr(const struct check_result *res, const struct grade_figures *plain)
{
	return res->n_ranks > 0 && res->ranks[0].fig.psnr > plain->psnr ? res->ranks[0].fig.psnr
									 : plain->psnr;
}

/* Whether the first cause only moves the pixels about (a mirror, a flip,
 * a transposition): another camera may explain the image as well. */
static bool check_first_is_geometric_of(const struct grade_rank *ranks, size_t n)
{
	const struct grade_rank *r = &ranks[0];
	bool a = grade_cause_moves_pixels(r->cause);
	bool b = r->also != RT_CAUSE_NONE && grade_cause_moves_pixels(r->also);

	return n > 0 && (a || b);
}

/* The camera that took the image, when it is not the given one: fitted
 * from the given camera and the dialect's own. */
static int check_fit(struct check_reference *ref, const struct check_view *v,
		     struct check_result *res, bool *weak, struct diag *d)
{
	struct camera_params starts[2];
	struct grade_fit fit;
	struct grade_figures rounded, given, found;
	bool truncated, nearer_in_colour;
	int n = 1, rc;

	starts[0] = v->params;
	if (ref->camera_given) {
		camera_params_default(&starts[1]);
		starts[1].fov_deg = scene_view_of(ref->scene)->fov_deg;
		starts[1].near = v->params.near;
		starts[1].aspect = v->params.aspect;
		n = 2;
	}
	if ((rc = grade_fit_camera(&v->job, starts, n, &res->image, &fit, d)) < 0)
		return rc;
	res->fitted = true;
	res->fit = fit;
	res->fit_evals = fit.evals;
	if ((rc = check_found_view(ref, v, &fit.camera, &res->found, d)) < 0)
		return rc;
	if ((rc = check_figures(&res->found, &res->image, &res->fig_found, &rounded, &truncated, d)) < 0)
		return rc;
	if ((rc = check_compare_cameras(v, &res->found, &res->image, &fit, &given,
					 &found, d)) < 0)
		return rc;
	/* Nearer in colour, or in grey (the fit's own figures: an image
	 * with a colour mistake on top, red and blue swapped, fits its
	 * camera as well) and not farther in colour: an image of another
	 * scene can find a camera whose greys are nearer while its colours
	 * are farther than the given camera's. */
	nearer_in_colour = found.psnr >= given.psnr + CHECK_MOVED_GAIN && found.psnr >= CHECK_MOVED_PSNR;
	res->moved = check_displacement(v, &res->found) > CHECK_MOVED_PIXELS &&
		     (nearer_in_colour ||
		      (fit.score <= CHECK_MOVED_GREY * fit.start_score &&
		       fit.score <= CHECK_MOVED_GREY_MSE && found.psnr > given.psnr));
	*weak = res->moved && !nearer_in_colour && fit.cause == RT_CAUSE_NONE &&
		fit.score > CHECK_MOVED_GREY_FIRM * fit.start_score;
	if (res->moved) {
		bool shows;
		if ((rc = check_shows_objects(ref->scene, &res->found, &shows, d)) < 0)
			return rc;
		res->moved = shows;
		res->floor_alone = !shows;
	}
	if (!res->moved)
		check_view_free(&res->found);
	return 0;
}

static int check_objects(const struct check_reference *ref, struct check_result *res,
			 struct diag *d)
{
	const struct check_view *v = check_result_view(ref, res);
	const struct image *shown = res->truncated && v->truncated.pixels ? &v->truncated : &v->image;
	size_t total = (size_t)v->camera.width * (size_t)v->camera.height;
	int rc;

	if (!(res->ids = rt_reallocarray(NULL, total, sizeof(*res->ids))))
		return diag_fail(d, RT_E_NOMEM, "out of memory for the object ids");
	rc = grade_object_ids(&v->job, res->ids, d);
	if (rc == 0)
		rc = grade_objects(&v->job, res->ids, shown, &res->image, v->ties, &res->objects,
				   &res->n_objects, d);
	return rc;
}

/* The figures and causes of the submission at view v (judged as
 * check_judged says): whether it matches, and if not its ranking. */
static int check_at(struct check_view *v, struct check_result *res, struct grade_figures *fig,
		    bool rank, struct diag *d)
{
	struct image judged;
	const struct image *sub;
	int rc;

	if ((rc = check_judged(v, res, &judged, d)) < 0)
		return rc;
	sub = judged.pixels ? &judged : &res->image;
	rc = check_figures(v, sub, fig, &res->fig_rounded, &res->truncated, d);
	if (rc == 0 && rank && !fig->match) {
		rc = grade_rank_with_finish(&v->job, &v->image, &v->truncated, sub, v->ties,
					    res->truncated, res->ranks, &res->n_ranks, d);
		if (rc == 0)
			check_explain(res, fig);
	}
	image_free(&judged);
	return rc;
}

static int check_image_read(struct check_reference *ref, struct check_result *res,
			    struct diag *d);

/* A match at the camera found may owe its ties what no camera within a
 * pixel gives (a white highlight on a small sphere is all edges, all
 * ties): those pixels leave the ties and the image is judged again,
 * which stands only when a cause explains them or comes close (else the
 * match stands, ties and all).  Not under CHECK_UNTIE_MIN pixels a side,
 * where a camera found to a fraction of a pixel still moves edges by one
 * (correct renders: 3 such pixels of 2304 at 48, 8 of 4096 at 64, where a
 * floor cause came 2.9 dB nearer; 0 at 129); nor on a textured floor. */
#define CHECK_UNTIE_MIN 128
static int check_untie_outside(struct check_result *res, struct diag *d)
{
	struct check_view *v = &res->found;
	const size_t total = (size_t)v->image.width * (size_t)v->image.height;
	const struct grade_figures fig = res->fig_found, rounded = res->fig_rounded;
	const bool truncated = res->truncated;
	const enum check_explained was = res->explained;
	const long n_ties = v->n_ties;
	uint8_t *ties;
	int rc = 0;

	if (res->floor_textured || v->image.width < CHECK_UNTIE_MIN ||
	    v->image.height < CHECK_UNTIE_MIN)
		return 0;
	if (!(ties = rt_malloc(total)))
		return diag_fail(d, RT_E_NOMEM, "out of memory for the ties");
	memcpy(ties, v->ties, total);
	if (check_ties_outside(v, &res->image) > 0) {
		res->n_ranks = 0;
		rc = check_at(v, res, &res->fig_found, true, d);
		if (rc == 0 && (res->fig_found.match || res->explained == CHECK_NONE)) {
			memcpy(v->ties, ties, total);
			v->n_ties = n_ties;
			res->fig_found = fig;
			res->fig_rounded = rounded;
			res->truncated = truncated;
			res->explained = was;
			res->n_ranks = 0;
		}
	}
	rt_free(ties);
	return rc;
}

/* A camera and a mistake at once.  A shading mistake pulls the fit of
 * the plain reference off the true camera (missing shadows, a white
 * highlight), and the floor's tiles swapped look like a camera a cell
 * away: so the camera found is refitted with each of the first causes
 * ranked there, and with the tiles swapped, rendered in place of the
 * reference.  A cause whose image at its own camera comes nearer than
 * the best explanation so far by CHECK_REFIT_GAIN moves the camera found
 * there, where the submission is judged again (or, when that camera is
 * the given one, at the given camera).  The refitted image is
 * measured on every pixel, the ranks with the ties left out: a refit
 * must beat them with that handicap, so it moves the camera only when it
 * is clearly better.
 * Long: the causes tried in turn, each fitted, rendered and judged, and the
 * best kept, with one exit that frees the images. */
#define CHECK_REFIT_CAUSES 3
#define CHECK_REFIT_GAIN 1.0

static int check_refit(struct check_reference *ref, const struct check_view *given,
		       struct check_result *res, struct diag *d)
{
	enum grade_cause causes[CHECK_REFIT_CAUSES + 1];
	int forms[CHECK_REFIT_CAUSES + 1], n = 0, k, i, rc;
	double best = res->n_ranks > 0 ? res->ranks[0].fig.psnr : res->fig_found.psnr;
	struct camera_params best_camera;
	bool better = false;
	struct check_view view;

	/* A textured floor is judged as the reference's: the refit, on the
	 * image as it is, could not be measured against that. */
	if (res->floor_textured)
		return 0;

	for (k = 0; k < (int)res->n_ranks && n < CHECK_REFIT_CAUSES; k++) {
		const struct grade_rank *r = &res->ranks[k];
		if (r->also != RT_CAUSE_NONE || grade_cause_is_transform(r->cause))
			continue;
		for (i = 0; i < n && causes[i] != r->cause; i++)
			;
		if (i == n) {
			causes[n] = r->cause;
			forms[n++] = r->form;
		}
	}
	for (i = 0; i < n && causes[i] != RT_CAUSE_FLOOR_SWAPPED; i++)
		;
	if (i == n && scene_has_floor(ref->scene)) {
		causes[n] = RT_CAUSE_FLOOR_SWAPPED;
		forms[n++] = 0;
	}
	for (k = 0; k < n; k++) {
		struct grade_fit fit;
		struct grade_job job = res->found.job;
		struct grade_rank r;
		struct grade_figures f;
		struct camera cam;
		struct image img;

		rc = grade_fit_camera_with(&res->found.job, &res->found.params, causes[k], forms[k],
					   &res->image, &res->fit, &fit, d);
		if (rc == -RT_E_INVALID) {
			diag_clear(d);
			continue;
		}
		if (rc < 0)
			return rc;
		res->fit_evals += fit.evals;
		if (isinf(fit.score))
			continue;	/* farther than no cause: abandoned */
		if ((rc = camera_init_rect(&cam, &fit.camera, given->camera.width, given->camera.height, d)) < 0)
			return rc;
		job.camera = &cam;
		memset(&r, 0, sizeof(r));
		r.cause = causes[k];
		r.form = forms[k];
		r.also = RT_CAUSE_NONE;
		if ((rc = grade_cause_image(&job, &res->found.image, &r, &img, d)) < 0)
			return rc;
		grade_figures_of(&img, &res->image, 1, 0, 0, &f);
		image_free(&img);
		if (f.psnr >= best + CHECK_REFIT_GAIN) {
			best = f.psnr;
			best_camera = fit.camera;
			better = true;
		}
	}
	if (!better)
		return 0;
	if ((rc = check_found_view(ref, given, &best_camera, &view, d)) < 0)
		return rc;
	check_view_free(&res->found);
	/* The cause's camera may be the given one after all (the mistake had
	 * pulled the plain fit away): then the camera did not move. */
	if (check_displacement(given, &view) <= CHECK_MOVED_PIXELS) {
		check_view_free(&view);
		res->moved = false;
		return 0;
	}
	check_view_move(&res->found, &view);
	res->n_ranks = 0;
	rc = check_at(&res->found, res, &res->fig_found, true, d);
	return rc < 0 || !res->fig_found.match ? rc : check_untie_outside(res, d);
}

/* After the submission's read (status rc): out of memory is an error of
 * the run, an unreadable image a verdict, and a read image is checked. */
static int check_image_loaded(struct check_reference *ref, struct check_result *res, int rc,
			      struct diag *d)
{
	if (rc == -RT_E_NOMEM)
		return diag_fail(d, RT_E_NOMEM, "%s", res->error.msg);
	if (rc < 0) {
		res->verdict = CHECK_UNREADABLE;
		return 0;
	}
	return check_image_read(ref, res, d);
}

int check_image(struct check_reference *ref, const char *path, struct check_result *res,
		struct diag *d)
{
	int rc;

	memset(res, 0, sizeof(*res));
	diag_clear(&res->error);
	rc = image_read(path, &res->image, NULL, &res->error);
	return check_image_loaded(ref, res, rc, d);
}

int check_image_data(struct check_reference *ref, const char *name, const unsigned char *data,
		     size_t len, struct check_result *res, struct diag *d)
{
	int rc;

	memset(res, 0, sizeof(*res));
	diag_clear(&res->error);
	rc = image_read_memory(data, len, name, &res->image, NULL, &res->error);
	return check_image_loaded(ref, res, rc, d);
}

/* The check of res->image, read.
 * Long: the check's phases (given camera, causes, fit, causes at the found
 * camera, objects) in order, each a call. */
static int check_image_read(struct check_reference *ref, struct check_result *res,
			    struct diag *d)
{
	struct check_view *v = &ref->view;
	struct grade_rank given[GRADE_MAX_RANKS];
	size_t n_given;
	enum check_explained was;
	bool textured, weak;
	double best_given;
	int rc;

	if (res->image.width != v->camera.width || res->image.height != v->camera.height) {
		/* Compared at its own size: the file's size may not be what the
		 * student rendered (a window's size, another -s). */
		snprintf(res->size_note, sizeof(res->size_note),
			 "the image is %dx%d, the scene's size %dx%d: compared with the reference "
			 "rendered at %dx%d", res->image.width, res->image.height, v->camera.width,
			 v->camera.height, res->image.width, res->image.height);
		if ((rc = check_view_make(ref, &ref->params, res->image.width, res->image.height,
					  v->tie_angle, &res->own, d)) < 0)
			return rc;
		v = &res->own;
	}
	if ((rc = check_at(v, res, &res->fig, true, d)) < 0)
		return rc;
	res->verdict = res->fig.match ? CHECK_MATCH : CHECK_DIFFERS;
	/* An image a cause explains keeps it, a mirror or a flip too (a
	 * camera can make a mirror image only of a symmetric scene, whose
	 * mirror image is then the same). */
	if (res->fig.match || !ref->fit || res->explained == CHECK_EXPLAINED)
		return check_objects(ref, res, d);
	/* The image does not fit the camera given: find the one that took
	 * it, and judge it there. */
	memcpy(given, res->ranks, sizeof(given));
	n_given = res->n_ranks;
	was = res->explained;
	textured = res->floor_textured;
	best_given = res->n_ranks > 0 ? res->ranks[0].fig.psnr : res->fig.psnr;
	if ((rc = check_fit(ref, v, res, &weak, d)) < 0)
		return rc;
	if (res->moved) {
		res->n_ranks = 0;
		if ((rc = check_at(&res->found, res, &res->fig_found, true, d)) < 0 ||
		    (res->fig_found.match && (rc = check_untie_outside(res, d)) < 0))
			return rc;
		/* A mirror or a flip that comes close stays, unless the camera
		 * found comes as close with what is ranked there (a gamma image
		 * of a symmetric scene: mirrored and gamma at the given camera
		 * 15.6 dB, gamma at the camera found exact). */
		if (check_first_is_geometric_of(given, n_given) &&
		    check_best_psnr(res, &res->fig_found) < best_given) {
			res->moved = false;
			check_view_free(&res->found);
		} else if (!res->fig_found.match && res->explained != CHECK_EXPLAINED &&
			   (rc = check_refit(ref, v, res, d)) < 0) {
			return rc;
		}
		/* Exactly the tiles swapped: a quarter turn away, maybe no mistake. */
		if (res->moved && !res->fig_found.match && res->n_ranks > 0 && res->ranks[0].fig.match &&
		    res->ranks[0].cause == RT_CAUSE_FLOOR_SWAPPED && res->ranks[0].also == RT_CAUSE_NONE &&
		    (rc = check_quarter_turn(ref, &res->found, &res->image, &res->fig_found, d)) < 0)
			return rc;
		res->n_ranks = res->fig_found.match ? 0 : res->n_ranks;
		if (res->moved && weak && !res->fig_found.match && res->explained == CHECK_NONE) {
			res->moved = false;
			check_view_free(&res->found);
		}
	}
	if (res->moved) {
		if (res->fig_found.match) {
			res->verdict = CHECK_MATCH;
			res->explained = CHECK_EXPLAINED;
		}
	} else {
		memcpy(res->ranks, given, sizeof(given));
		res->n_ranks = n_given;
		res->explained = was;
		res->floor_textured = textured;
	}
	return check_objects(ref, res, d);
}

void check_result_free(struct check_result *res)
{
	image_free(&res->image);
	check_view_free(&res->own);
	check_view_free(&res->found);
	rt_free(res->objects);
	rt_free(res->ids);
	res->objects = NULL;
	res->ids = NULL;
}
