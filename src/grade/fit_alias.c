/* The floor's aliases: a checkerboard looks the same from eyes a whole
 * diagonal cell apart, so the fit tries those eyes by name instead of
 * hoping a local search crosses from one to the next. */
#include <math.h>
#include <string.h>

#include "grade/fit_search.h"
#include "scene/scene_impl.h"

/* The middle of the scene's objects (the floor and unbounded shapes
 * aside): the point the alias moves keep in view. */
struct vec3 fit_scene_centre(const struct scene *s)
{
	struct vec3 sum = vec3_make(0.0, 0.0, 0.0);
	size_t i, n = 0;

	for (i = 0; i < s->n_shapes; i++) {
		struct aabb box;
		if (s->shapes[i] == s->floor || !shape_bounds(s->shapes[i], &box) ||
		    !vec3_is_finite(box.min) || !vec3_is_finite(box.max))
			continue;
		sum = vec3_add(sum, vec3_scale(vec3_add(box.min, box.max), 0.5));
		n++;
	}
	return n ? vec3_scale(sum, 1.0 / (double)n) : sum;
}

/* The checkerboard looks the same from eyes a whole diagonal cell apart
 * (white where i + j is even): the blurred levels cannot tell them apart
 * by the floor, only by the objects, which are small.  So each such
 * neighbour of x, up to FIT_ALIAS_REACH cells each way along both
 * diagonals, is scored, turned to keep the scene's middle where x sees
 * it and zoomed to keep its size, and x moves to the best.
 * Long: the aliases made both ways (as they are, and turned and zoomed) in
 * one loop over the cells, then the best picked from the same arrays. */
#define FIT_ALIAS_REACH 4

int fit_floor_aliases(struct fit_batch *b, const double *x, double out[][FIT_DIM], double *fout,
		      int n_out, long *evals)
{
	const struct scene_view *v = scene_view_of(b->job->scene);
	enum { N = 2 * (2 * FIT_ALIAS_REACH + 1) * (2 * FIT_ALIAS_REACH + 1) };
	double xs[N * FIT_DIM], fs[N], c = v->floor_cell, dist0;
	struct vec3 eye0;
	struct camera_params base, p;
	struct vec3 centre, f0;
	int i, j, n = 0, k, m, best = -1;

	if (!scene_has_floor(b->job->scene) || !(c > 0.0) || !isfinite(c))
		return 0;
	memset(&base, 0, sizeof(base));
	fit_params_of(x, &base, &p);
	eye0 = p.eye;
	centre = fit_scene_centre(b->job->scene);
	f0 = vec3_normalize(vec3_sub(p.look, p.eye));
	dist0 = vec3_dot(vec3_sub(centre, eye0), f0);
	for (i = -FIT_ALIAS_REACH; i <= FIT_ALIAS_REACH; i++)
		for (j = -FIT_ALIAS_REACH; j <= FIT_ALIAS_REACH; j++) {
			struct camera_params q = p;
			struct vec3 shift = vec3_make(c * (i + j), c * (i - j), 0.0), f;
			double dist;
			if (i == 0 && j == 0)
				best = n;
			q.eye = vec3_add(p.eye, shift);
			/* As it is, which keeps the floor where it was; and turned
			 * to the scene, which keeps the objects. */
			q.look = vec3_add(q.eye, f0);
			fit_view_of(&q, xs + n * FIT_DIM);
			n++;
			if (i == 0 && j == 0)
				continue;
			/* The ray to the centre turns as much as the eye moved
			 * round it; the field scales with its distance along
			 * the view. */
			f = vec3_normalize(vec3_sub(vec3_add_scaled(eye0, f0, dist0 > 1.0 ? dist0 : 1.0), q.eye));
			q.look = vec3_add(q.eye, f);
			dist = vec3_dot(vec3_sub(centre, q.eye), f);
			if (dist0 > 1.0 && dist > 1.0)
				q.fov_deg = 2.0 * atan(tan(p.fov_deg * 3.14159265358979323846 / 360.0) * dist0 / dist) *
					    360.0 / (2.0 * 3.14159265358979323846);
			fit_view_of(&q, xs + n * FIT_DIM);
			n++;
		}
	fit_batch_run(b, xs, fs, n);
	*evals += n;
	/* The best n_out, x itself among them whatever its place (the
	 * blurred level may not yet tell x from its aliases). */
	memcpy(out[0], xs + best * FIT_DIM, sizeof(double) * FIT_DIM);
	fout[0] = fs[best];
	fs[best] = INFINITY;
	for (m = 1; m < n_out; m++) {
		int pick = -1;
		for (k = 0; k < n; k++)
			if (fs[k] < INFINITY && (pick < 0 || fs[k] < fs[pick]))
				pick = k;
		if (pick < 0)
			break;
		memcpy(out[m], xs + pick * FIT_DIM, sizeof(double) * FIT_DIM);
		fout[m] = fs[pick];
		fs[pick] = INFINITY;
	}
	return m;
}

/* A cause's floor (the tiles swapped) fits a cell off the plain one's:
 * the eye one cell along x or y, which swaps the tiles. */
static const int fit_odd_cells[4][2] = { { 1, 0 }, { -1, 0 }, { 0, 1 }, { 0, -1 } };

void fit_odd_alias(struct fit_batch *b, double *x, long *evals)
{
	const struct scene_view *v = scene_view_of(b->job->scene);
	double xs[5 * FIT_DIM], fs[5], c = v->floor_cell;
	int k, best = 0;

	if (!scene_has_floor(b->job->scene) || !(c > 0.0) || !isfinite(c))
		return;
	for (k = 0; k < 5; k++) {
		memcpy(xs + k * FIT_DIM, x, sizeof(double) * FIT_DIM);
		if (k > 0) {
			xs[k * FIT_DIM + FIT_X] += c * fit_odd_cells[k - 1][0];
			xs[k * FIT_DIM + FIT_Y] += c * fit_odd_cells[k - 1][1];
		}
	}
	fit_batch_run(b, xs, fs, 5);
	*evals += 5;
	for (k = 1; k < 5; k++)
		if (fs[k] < fs[best])
			best = k;
	memcpy(x, xs + best * FIT_DIM, sizeof(double) * FIT_DIM);
}

/* Once the camera is sharp, the floor's aliases once more, as they are
 * (the same direction and field of view): an eye two cells off along the
 * view is what the blurred levels could not tell apart, and the sharp one
 * can by the objects.  True when x moved (to a better alias). */
bool fit_final_alias(struct fit_batch *b, double *x, double *fx, long *evals)
{
	const struct scene_view *v = scene_view_of(b->job->scene);
	double xs[28 * FIT_DIM], fs[28], c = v->floor_cell;
	int i, j, n = 0, k, best = -1;

	if (!scene_has_floor(b->job->scene) || !(c > 0.0) || !isfinite(c))
		return false;
	for (i = -2; i <= 2; i++)
		for (j = -2; j <= 2; j++) {
			if (i == 0 && j == 0)
				continue;
			memcpy(xs + n * FIT_DIM, x, sizeof(double) * FIT_DIM);
			xs[n * FIT_DIM + FIT_X] += c * (i + j);
			xs[n * FIT_DIM + FIT_Y] += c * (i - j);
			n++;
		}
	for (k = 0; b->level->variant && k < 4; k++) {
		memcpy(xs + n * FIT_DIM, x, sizeof(double) * FIT_DIM);
		xs[n * FIT_DIM + FIT_X] += c * fit_odd_cells[k][0];
		xs[n * FIT_DIM + FIT_Y] += c * fit_odd_cells[k][1];
		n++;
	}
	fit_batch_run(b, xs, fs, n);
	*evals += n;
	for (k = 0; k < n; k++)
		if (fs[k] < *fx && (best < 0 || fs[k] < fs[best]))
			best = k;
	if (best < 0)
		return false;
	memcpy(x, xs + best * FIT_DIM, sizeof(double) * FIT_DIM);
	*fx = fs[best];
	return true;
}
