/* The camera fit's parts: the seven numbers a camera is moved by, and the
 * levels of the image it is fitted on. */
#ifndef RT_GRADE_FIT_H
#define RT_GRADE_FIT_H

#include <stdint.h>

#include "grade/grade_impl.h"
#include "whitted/grade.h"

/* A camera as the fit moves it: the eye (x, y, z), the direction of view
 * as yaw (degrees about +z from +x) and pitch (degrees above the floor's
 * plane), the roll of up about the view (degrees, 0: up in the vertical
 * plane of the view, as the default camera's) and the vertical field of
 * view (degrees).  A camera looking straight up or down has no yaw. */
enum { FIT_X, FIT_Y, FIT_Z, FIT_YAW, FIT_PITCH, FIT_ROLL, FIT_FOV, FIT_DIM };

void fit_view_of(const struct camera_params *p, double v[FIT_DIM]);
/* The camera of v, with base's near plane and aspect; the look-at point
 * 100 units along the view. */
void fit_params_of(const double v[FIT_DIM], const struct camera_params *base,
		   struct camera_params *out);

/* Moves of a camera for the fine search, about the point at distance
 * pivot along its view, each nearly independent of the others in the
 * image: orbits about the pivot (degrees, about the camera's up and right
 * axes), roll (degrees), pans along right and up (scene units), a dolly
 * along the view that keeps the pivot's scale (scene units; the field of
 * view widens as the eye comes nearer) and a zoom (degrees of field). */
enum { FIT_ORBIT_YAW, FIT_ORBIT_PITCH, FIT_TURN_ROLL, FIT_PAN_X, FIT_PAN_Y, FIT_DOLLY, FIT_ZOOM };
void fit_view_move(const double v[FIT_DIM], const double q[FIT_DIM], double pivot,
		   double out[FIT_DIM]);

/* What the fit compares of a colour (levels 0..255): grey, |red - blue|
 * and green against their mean, the same when red and blue are swapped
 * (a BMP's byte order does not move the camera), yet telling a red sphere
 * from a green one of the same grey. */
void fit_colour(double r, double g, double b, float out[3]);

/* A level: cells, each the mean of ss x ss pixels of the full image (the
 * submission's pixels there, and the candidate's colours of the rays
 * through those very pixels, so that the true camera gives the target
 * exactly), laid out w x h and blurred by a Gaussian of sigma cells. */
struct fit_level {
	int w, h, ss;
	int n_cells, n_samples;
	int32_t *sx, *sy;		/* the samples' pixels, ss * ss a cell */
	float *target;			/* 3 a cell, 0..255, blurred */
	float *weight;			/* a cell's weight (NULL: 1) */
	double sigma;
	int recursion;			/* the rays' recursion level */
	/* NULL: the reference's colours; else a cause's form, rendered as
	 * its program renders (a camera and a mistake fitted at once). */
	const struct grade_variant *variant;
};

/* A level of sub (the submission) in cells of w x h. */
int fit_level_grid(struct fit_level *l, const struct image *sub, int w, int h, int ss,
		   double sigma, struct diag *d);
void fit_level_free(struct fit_level *l);

/* What a thread needs to score candidates on a level. */
struct fit_scratch {
	float *cells, *tmp;
	/* When not NULL (fit_scratch_points): each cell's middle sample's
	 * primary hit (x, y, z, 1), or its direction (x, y, z, 0) when the ray
	 * hits nothing, filled by fit_level_render. */
	double *points;
};
int fit_scratch_alloc(struct fit_scratch *s, const struct fit_level *l, struct diag *d);
void fit_scratch_free(struct fit_scratch *s);
int fit_scratch_points(struct fit_scratch *s, const struct fit_level *l, struct diag *d);

/* The Jacobian of a grid level's cells at v for the moves of
 * fit_view_move (about pivot), from the render in s (cells and points):
 * the image's gradient times the flow each move (of step h[k]) gives
 * each cell's point, jac[k * 3 n_cells + 3 cell + c]. */
void fit_level_jacobian(const struct fit_level *l, const struct grade_job *job,
			const struct camera_params *base, const double v[FIT_DIM],
			const double h[FIT_DIM], double pivot, const struct fit_scratch *s, float *jac);

/* The colours of the n rays as the fit sees them: the renderer's (packets
 * where it uses them) for the reference and for a variant that traces as
 * it does, the variant's own trace otherwise; the variant's encoding
 * (gamma) on top.  The one place the fit's levels and its coarse search
 * colour a ray. */
struct render_job;
struct render_tree;
void fit_trace_rays(const struct render_job *rj, struct render_tree *tree,
		    const struct grade_job *job, const struct grade_variant *var,
		    const struct ray *rays, int n, struct color *col);
/* The colours camera v sees in the level's cells, blurred, into s->cells;
 * -1 for a camera that cannot be. */
int fit_level_render(const struct fit_level *l, const struct grade_job *job,
		      const struct camera_params *base, const double v[FIT_DIM],
		      struct fit_scratch *s);
/* The mean squared difference (levels^2, over the channels) between the
 * level's target and the colours of the camera v sees there, rendered
 * as job says; INFINITY for a camera that cannot be. */
double fit_level_score(const struct fit_level *l, const struct grade_job *job,
		       const struct camera_params *base, const double v[FIT_DIM],
		       struct fit_scratch *s);

/* How far the first look goes: the box about the start and an orbit of
 * the scene's middle on the start's side (FIT_REACH_NEAR), or the orbit
 * all round, nearer and farther, and no box (FIT_REACH_ROUND: the last
 * pass, for a camera moved far). */
enum fit_reach { FIT_REACH_NEAR, FIT_REACH_ROUND };

/* The first look: eyes on a grid of the spacing within radius of the
 * start's (turned about the start's direction) and on an orbit about the
 * scene's centre (looking at it), as far as reach says, each with the
 * best of a few directions, rolls and fields of view scored on warps of
 * one wide render (with the variant's colours when not NULL: a gamma
 * image is searched for with gamma on); the best n_out cameras (views)
 * and their scores, best first. */
int fit_coarse_search(const struct grade_job *job, const struct grade_variant *variant,
		      enum fit_reach reach,
		      const struct camera_params *start, const struct image *sub, double radius,
		      double spacing, struct vec3 centre,
		      double out[][FIT_DIM], double *scores, int n_out, struct diag *d);
/* The middle of the scene's objects (the floor and unbounded shapes
 * aside; the origin when there are none). */
struct vec3 fit_scene_centre(const struct scene *s);

/* Blurs 3-channel cells (w x h) in place by a Gaussian of sigma cells. */
void fit_blur(float *cells, float *tmp, int w, int h, double sigma);

#endif
