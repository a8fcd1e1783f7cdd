/* The floor's shape fitted with the camera.  A student who made the floor
 * another width, or its cells another size, and then moved the camera,
 * hands in an image that no camera of the scene's floor comes near: the
 * checkerboard is every cue the fit has.  So, when the plain and pulled
 * passes all end far (fit_camera.c), the floor's widths are looked at first
 * (cheaply, up to the first guarded level: the blurred levels see where
 * the floor ends, not its cells), then at the nearest width every cell
 * size by a whole pass, each bounded by the nearest so far. */
#include <math.h>
#include <string.h>

#include "grade/fit_search.h"
#include "scene/scene_impl.h"

/* The widths looked at (best_w indexes them): the floor of another width
 * (RT_CAUSE_FLOOR_SIZE's forms) and the floor reaching the horizon.  The
 * wider ones are looked at only when the horizon comes nearer: a floor
 * wider than the scene's shows only where the scene's ends, and the
 * horizon's covers all of that (on the shared renders whose floor ends
 * out of view, every wider width screened the same as the scene's, and
 * six screens took sr20 40 s, three 17 s). */
static const struct {
	enum grade_cause cause;
	int form;
	bool wide;
} fit_floor_widths[] = {
	{ RT_CAUSE_FLOOR_SIZE, 0, false }, { RT_CAUSE_FLOOR_SIZE, 1, false },
	{ RT_CAUSE_FLOOR_HORIZON, 0, false }, { RT_CAUSE_FLOOR_SIZE, 2, true },
	{ RT_CAUSE_FLOOR_SIZE, 3, true }, { RT_CAUSE_FLOOR_SIZE, 4, true },
};
#define FIT_FLOOR_WIDTHS (sizeof(fit_floor_widths) / sizeof(fit_floor_widths[0]))
/* A width is taken when its screen is at most this share of the scene
 * floor's: sr04 (a floor 400 wide) 0.70; the renders whose floor is the
 * scene's, 0.94 to 1. */
#define FIT_FLOOR_WIDTH_GAIN 0.85
/* Below this many pixels on the image's shorter side the cells are a
 * pixel or less wherever the floor's shape could show (and each screen and
 * pass costs nearly what it costs at 768): not looked at. */
#define FIT_FLOOR_MIN_PIXELS 64
/* RT_CAUSE_FLOOR_CELL's forms, each a cell size (the scene's own has none). */
#define FIT_FLOOR_CELLS GRADE_VARIANTS

/* The variant of width w with cells c (c < 0: the scene's); false when
 * the scene has no such floor. */
static bool fit_floor_variant(const struct grade_job *job, int w, int c, struct grade_variant *v)
{
	struct grade_variant width, cells;

	if (!grade_variant_of(job, fit_floor_widths[w].cause, fit_floor_widths[w].form, &width))
		return false;
	if (c < 0) {
		*v = width;
		return true;
	}
	return grade_variant_of(job, RT_CAUSE_FLOOR_CELL, c, &cells) &&
	       grade_variant_combine(&width, &cells, v);
}

/* A whole pass with width w (>= 0) and cells c (< 0: the scene's),
 * abandoned where it is farther than bound; kept in out (and its variant
 * in *shape) when it comes nearer, and then bound is tightened to its
 * levels: a shape farther on a level than the nearest so far is not the
 * one.  1 when kept, 0 when not, < 0 on failure. */
static int fit_floor_try(const struct grade_job *job, const struct camera_params *starts,
			 int n_starts, const struct image *sub, int w, int c, double *bound,
			 struct grade_fit *out, struct grade_variant *shape, struct diag *d)
{
	struct grade_variant v;
	struct grade_fit again;
	double levels[GRADE_FIT_LEVELS];
	int k, rc;

	if (!fit_floor_variant(job, w, c, &v))
		return 0;
	if ((rc = fit_passes(job, starts, n_starts, sub, &v, FIT_REACH_NEAR, bound, &again, d)) < 0)
		return rc;
	memcpy(levels, again.levels, sizeof(levels));
	again.cause = fit_floor_widths[w].cause;
	again.form = fit_floor_widths[w].form;
	again.also = c >= 0 ? RT_CAUSE_FLOOR_CELL : RT_CAUSE_NONE;
	again.also_form = c >= 0 ? c : 0;
	if (!fit_keep_better(out, &again))
		return 0;
	*shape = v;
	for (k = 0; k < GRADE_FIT_LEVELS; k++)
		bound[k] = levels[k] < bound[k] ? levels[k] : bound[k];
	return 1;
}

int fit_floor_shape(const struct grade_job *job, const struct camera_params *starts,
		    int n_starts, const struct image *sub, struct grade_fit *out,
		    struct grade_variant *shape, struct diag *d)
{
	const struct scene_view *sv = scene_view_of(job->scene);
	const double scene_screen = out->levels[FIT_GUARD_FIRST_STAGE];
	double best_screen = scene_screen, bound[GRADE_FIT_LEVELS];
	int best_w = -1, best_c = -2, w, c, rc;
	bool horizon_nearer = false;

	if (!job->scene->floor || sv->floor_width == INFINITY || sub->width < FIT_FLOOR_MIN_PIXELS ||
	    sub->height < FIT_FLOOR_MIN_PIXELS)
		return 0;
	for (w = 0; w < (int)FIT_FLOOR_WIDTHS; w++) {
		struct grade_variant v;
		double score;
		if (!fit_floor_variant(job, w, -1, &v) ||
		    (fit_floor_widths[w].wide && !horizon_nearer))
			continue;
		if ((rc = fit_screen(job, starts, n_starts, sub, &v, &score, d)) < 0)
			return rc;
		if (fit_floor_widths[w].cause == RT_CAUSE_FLOOR_HORIZON)
			horizon_nearer = score <= FIT_FLOOR_WIDTH_GAIN * scene_screen;
		if (score < best_screen) {
			best_screen = score;
			best_w = w;
		}
	}
	/* Cells alone do not show on the blurred levels (the screens of
	 * every cell size at one width were within a fifth of each other),
	 * and a whole pass for each is seconds: they are tried only where
	 * the floor's end is clearly elsewhere. */
	if (best_w < 0 || !(best_screen <= FIT_FLOOR_WIDTH_GAIN * scene_screen))
		return 0;
	memcpy(bound, out->levels, sizeof(bound));
	for (c = -1; c < FIT_FLOOR_CELLS; c++) {
		if ((rc = fit_floor_try(job, starts, n_starts, sub, best_w, c, bound, out, shape, d)) < 0)
			return rc;
		best_c = rc > 0 ? c : best_c;
	}
	/* The width stays the screen's: it tells a narrow floor from a wide
	 * one, not 400 from 500 (sr04's 400 screened farther than 500), yet
	 * at 500 the camera is found, and the ranking there names 400.
	 * Passes at the other widths with the cells found moved nothing on
	 * sr04 or comparereal's floor-shape-moved, for 10 s more. */
	return best_c >= -1;
}
