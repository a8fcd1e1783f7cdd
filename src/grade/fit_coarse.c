/* The camera fit's first look: where the eye might be.  A camera that only
 * turns (or zooms) sees a warp of what it saw: so for each eye of a grid
 * around the start, one wide render (150 degrees, the start's direction)
 * stands for every direction, roll and field of view near the start's,
 * each scored by resampling it onto a small blurred copy of the
 * submission, and the best few cameras go on to the fine search. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "base/thread.h"
#include "grade/fit.h"
#include "render/ray_tree.h"
#include "render/render_packet.h"
#include "scene/scene_impl.h"

#define COARSE_WIDE_PX 72		/* the wide render's side */
#define COARSE_WIDE_FOV 150.0		/* its field of view, degrees */
#define COARSE_CELLS 20			/* the submission's copy, across its wider side */
#define COARSE_MAX_THREADS 64

/* The directions tried at each eye, relative to the start's: first yaw
 * and pitch offsets and fields of view on a coarse grid, unrolled; then
 * around the best COARSE_REFINE of those, finer steps with rolls. */
static const double coarse_turns[] = { -16.0, -8.0, 0.0, 8.0, 16.0 };
static const double coarse_fovs[] = { 55.0, 75.0, 95.0 };
static const double coarse_fine_turns[] = { -4.0, 0.0, 4.0 };
static const double coarse_fine_rolls[] = { -8.0, 0.0, 8.0 };
static const double coarse_fine_fovs[] = { -10.0, 0.0, 10.0 };
#define COARSE_REFINE 3
#define COARSE_LEN(a) (sizeof(a) / sizeof((a)[0]))

struct coarse_target {
	int w, h;
	float *cells;			/* 3 a cell, blurred */
	double *u, *v;			/* each cell centre's pixel coordinates in the full image */
	int full_w, full_h;
};

struct coarse_eye {
	struct vec3 eye;
	struct vec3 dir;		/* the direction its turns are about */
	int order;			/* its place in the grid, for ties */
	double score;
	double view[FIT_DIM];
};

struct coarse_work {
	const struct grade_job *job;
	const struct grade_variant *variant;	/* rendered in the reference's place, or NULL */
	const struct camera_params *start;
	const struct coarse_target *t;
	struct coarse_eye *eyes;
	int n_eyes, next;
};

/* The wide render from eye e along the start's direction, blurred. */
static void coarse_wide(const struct coarse_work *w, struct vec3 e, struct vec3 dir, float *img,
			float *tmp)
{
	const int n = COARSE_WIDE_PX;
	struct camera_params p = *w->start;
	struct camera cam;
	struct render_job rj;
	struct ray_counts counts;
	struct render_tree tree;
	struct ray rays[COARSE_WIDE_PX];
	struct color col[COARSE_WIDE_PX];
	struct diag d;
	int x, y;

	p.look = vec3_add(e, dir);
	p.eye = e;
	p.fov_deg = COARSE_WIDE_FOV;
	p.near = 0.0;
	p.aspect = 0.0;
	if (camera_init_rect(&cam, &p, n, n, &d) < 0) {
		memset(img, 0, sizeof(float) * 3 * n * n);
		return;
	}
	render_job_init(&rj, w->job->scene, &cam, 1);
	rj.settings = w->job->settings;

	memset(&counts, 0, sizeof(counts));
	render_tree_unbound(&tree, &counts);
	for (y = 0; y < n; y++) {
		for (x = 0; x < n; x++)
			rays[x] = camera_ray(&cam, x, y);
		fit_trace_rays(&rj, &tree, w->job, w->variant, rays, n, col);
		for (x = 0; x < n; x++) {
			struct color c = color_clamp(col[x]);
			float *o = img + 3 * (y * n + x);
			fit_colour(255.0 * c.r, 255.0 * c.g, 255.0 * c.b, o);
		}
	}
	fit_blur(img, tmp, n, n, 1.0);
}

/* The score of camera p (at eye e) by resampling the wide render: the
 * mean squared difference with the target; a cell whose direction falls
 * outside the wide render counts as 128 levels off.  The sum only grows:
 * once it passes `limit` (a score some kept camera has), the rest is not
 * summed and INFINITY returned, which changes no choice. */
static double coarse_score(const struct coarse_work *w, const struct camera_params *p,
			   const struct camera *wide, const float *img, double limit)
{
	const struct coarse_target *t = w->t;
	const int n = COARSE_WIDE_PX;
	const double cells = 3.0 * t->w * t->h;
	struct camera cam;
	struct diag d;
	double e = 0.0;
	int i, k, c;

	if (camera_init_rect(&cam, p, t->full_w, t->full_h, &d) < 0)
		return INFINITY;
	for (i = 0; i < t->w * t->h; i++) {
		/* Bottom row first: the sky at the top is alike for most
		 * cameras, the floor and the objects below tell them apart, so
		 * a camera that cannot win is cut off early. */
		k = (t->h - 1 - i / t->w) * t->w + i % t->w;
		if (i % t->w == 0 && e / cells > limit)
			return INFINITY;
		struct vec3 dir = camera_plane_point(&cam, t->u[k], t->v[k]);
		double fx, fy, ax, ay;
		/* The wide render's pixel coordinates of dir. */
		double df = camera_project(wide, dir, &fx, &fy);
		const float *q = t->cells + 3 * k;
		int ix, iy;

		if (df <= 0.0) {
			e += 3.0 * 128.0 * 128.0;
			continue;
		}
		fx -= 0.5;
		fy -= 0.5;
		if (!(fx >= 0.0 && fy >= 0.0 && fx <= n - 1 && fy <= n - 1)) {
			e += 3.0 * 128.0 * 128.0;
			continue;
		}
		ix = (int)fx;
		iy = (int)fy;
		ix = ix > n - 2 ? n - 2 : ix;
		iy = iy > n - 2 ? n - 2 : iy;
		ax = fx - ix;
		ay = fy - iy;
		for (c = 0; c < 3; c++) {
			const float *p00 = img + 3 * (iy * n + ix) + c;
			double s = (1 - ay) * ((1 - ax) * p00[0] + ax * p00[3]) +
				   ay * ((1 - ax) * p00[3 * n] + ax * p00[3 * n + 3]);
			e += (s - q[c]) * (s - q[c]);
		}
	}
	return e / cells;
}

/* The camera at eye e turned from the start's direction by yaw (about
 * the start's up) and pitch (about its right), rolled and zoomed. */
static void coarse_camera(const struct camera *start, struct vec3 e, double yaw, double pitch,
			  double roll, double fov, const struct camera_params *base,
			  struct camera_params *p)
{
	const double rad = 3.14159265358979323846 / 180.0;
	struct vec3 f = start->forward, r = start->right, u = start->up, f1, r1, u1;
	double cy = cos(yaw * rad), sy = sin(yaw * rad), cp = cos(pitch * rad), sp = sin(pitch * rad);
	double cr = cos(roll * rad), sr = sin(roll * rad);

	/* yaw: f and r turn about u; then pitch: f and u about r. */
	f1 = vec3_add(vec3_scale(f, cy), vec3_scale(r, sy));
	r1 = vec3_sub(vec3_scale(r, cy), vec3_scale(f, sy));
	u1 = vec3_add(vec3_scale(u, cp), vec3_scale(f1, -sp));
	f1 = vec3_add(vec3_scale(f1, cp), vec3_scale(u, sp));
	*p = *base;
	p->eye = e;
	p->look = vec3_add_scaled(e, f1, 100.0);
	p->up = vec3_add(vec3_scale(u1, cr), vec3_scale(r1, sr));
	p->fov_deg = fov;
}

/* Long: one eye's wide render warped to every orientation of the grid and
 * scored, in one loop over the orientations. */
static void coarse_eye_search(const struct coarse_work *w, struct coarse_eye *ce, float *img,
			      float *tmp)
{
	struct camera_params p = *w->start, best;
	struct camera wide, start;
	struct diag d;
	double top[COARSE_REFINE][3], top_score[COARSE_REFINE];
	size_t a, b, r, f, k;

	struct camera_params base = *w->start;

	coarse_wide(w, ce->eye, ce->dir, img, tmp);
	p.look = vec3_add(ce->eye, ce->dir);
	p.eye = ce->eye;
	p.fov_deg = COARSE_WIDE_FOV;
	p.near = 0.0;
	p.aspect = 0.0;
	ce->score = INFINITY;
	base.eye = ce->eye;
	base.look = vec3_add(ce->eye, ce->dir);
	if (camera_init_rect(&wide, &p, COARSE_WIDE_PX, COARSE_WIDE_PX, &d) < 0 ||
	    camera_init_rect(&start, &base, w->t->full_w, w->t->full_h, &d) < 0)
		return;
	best = *w->start;
	for (k = 0; k < COARSE_REFINE; k++)
		top_score[k] = INFINITY;
	/* The coarse grid, its best few kept in order. */
	for (a = 0; a < COARSE_LEN(coarse_turns); a++)
		for (b = 0; b < COARSE_LEN(coarse_turns); b++)
			for (f = 0; f < COARSE_LEN(coarse_fovs); f++) {
				double s;
				coarse_camera(&start, ce->eye, coarse_turns[a], coarse_turns[b], 0.0,
					      coarse_fovs[f], w->start, &p);
				s = coarse_score(w, &p, &wide, img, top_score[COARSE_REFINE - 1]);
				for (k = 0; k < COARSE_REFINE; k++)
					if (s < top_score[k]) {
						memmove(top_score + k + 1, top_score + k,
							sizeof(top_score[0]) * (COARSE_REFINE - k - 1));
						memmove(top + k + 1, top + k, sizeof(top[0]) * (COARSE_REFINE - k - 1));
						top_score[k] = s;
						top[k][0] = coarse_turns[a];
						top[k][1] = coarse_turns[b];
						top[k][2] = coarse_fovs[f];
						break;
					}
			}
	for (k = 0; k < COARSE_REFINE && top_score[k] < INFINITY; k++)
		for (a = 0; a < COARSE_LEN(coarse_fine_turns); a++)
			for (b = 0; b < COARSE_LEN(coarse_fine_turns); b++)
				for (r = 0; r < COARSE_LEN(coarse_fine_rolls); r++)
					for (f = 0; f < COARSE_LEN(coarse_fine_fovs); f++) {
						double s;
						coarse_camera(&start, ce->eye, top[k][0] + coarse_fine_turns[a],
							      top[k][1] + coarse_fine_turns[b],
							      coarse_fine_rolls[r],
							      top[k][2] + coarse_fine_fovs[f], w->start, &p);
						/* The best of the grid is the steps'
						 * middle: a step worse than it is not
						 * the best, and stops early. */
						s = coarse_score(w, &p, &wide, img,
								 fmin(ce->score, top_score[0]));
						if (s < ce->score) {
							ce->score = s;
							best = p;
						}
					}
	fit_view_of(&best, ce->view);
}

static void *coarse_worker(void *arg)
{
	struct coarse_work *w = arg;
	float *img = rt_reallocarray(NULL, 3 * COARSE_WIDE_PX * COARSE_WIDE_PX, sizeof(float));
	float *tmp = rt_reallocarray(NULL, 3 * COARSE_WIDE_PX * COARSE_WIDE_PX, sizeof(float));
	int i;

	while (img && tmp && !(w->job->cancel && *w->job->cancel) &&
	       (i = __atomic_fetch_add(&w->next, 1, __ATOMIC_RELAXED)) < w->n_eyes)
		coarse_eye_search(w, &w->eyes[i], img, tmp);
	rt_free(img);
	rt_free(tmp);
	return NULL;
}

static int coarse_target_make(struct coarse_target *t, const struct image *sub, struct diag *d)
{
	float *tmp;
	int x, y, X, Y, c;

	memset(t, 0, sizeof(*t));
	t->full_w = sub->width;
	t->full_h = sub->height;
	t->w = sub->width >= sub->height ? COARSE_CELLS : (int)lround((double)COARSE_CELLS * sub->width / sub->height);
	t->h = sub->height >= sub->width ? COARSE_CELLS : (int)lround((double)COARSE_CELLS * sub->height / sub->width);
	t->w = t->w < 1 ? 1 : t->w > sub->width ? sub->width : t->w;
	t->h = t->h < 1 ? 1 : t->h > sub->height ? sub->height : t->h;
	t->cells = rt_reallocarray(NULL, (size_t)t->w * t->h * 3, sizeof(float));
	t->u = rt_reallocarray(NULL, (size_t)t->w * t->h, sizeof(double));
	t->v = rt_reallocarray(NULL, (size_t)t->w * t->h, sizeof(double));
	tmp = rt_reallocarray(NULL, (size_t)t->w * t->h * 3, sizeof(float));
	if (!t->cells || !t->u || !t->v || !tmp) {
		rt_free(tmp);
		return diag_fail(d, RT_E_NOMEM, "out of memory for the camera fit");
	}
	for (y = 0; y < t->h; y++)
		for (x = 0; x < t->w; x++) {
			int x0 = (int)((long)x * sub->width / t->w), x1 = (int)((long)(x + 1) * sub->width / t->w);
			int y0 = (int)((long)y * sub->height / t->h), y1 = (int)((long)(y + 1) * sub->height / t->h);
			double s[3] = { 0.0, 0.0, 0.0 };
			for (Y = y0; Y < y1; Y++)
				for (X = x0; X < x1; X++) {
					const uint8_t *q = sub->pixels + 3 * ((size_t)Y * sub->width + X);
					float f[3];
					fit_colour(q[0], q[1], q[2], f);
					for (c = 0; c < 3; c++)
						s[c] += f[c];
				}
			for (c = 0; c < 3; c++)
				t->cells[3 * (y * t->w + x) + c] = (float)(s[c] / ((double)(x1 - x0) * (y1 - y0)));
			t->u[y * t->w + x] = 0.5 * (x0 + x1);
			t->v[y * t->w + x] = 0.5 * (y0 + y1);
		}
	fit_blur(t->cells, tmp, t->w, t->h, 1.0);
	rt_free(tmp);
	return 0;
}

static void coarse_target_free(struct coarse_target *t)
{
	rt_free(t->cells);
	rt_free(t->u);
	rt_free(t->v);
}

/* Scores eyes [first, n) of w on the job's threads. */
static void coarse_run(struct coarse_work *w, int first, int n)
{
	int nt = w->job->threads < 1 ? 1 : w->job->threads > COARSE_MAX_THREADS ? COARSE_MAX_THREADS
										 : w->job->threads;

	w->next = first;
	w->n_eyes = n;
	rt_run_shared(nt, coarse_worker, w);
}

static int coarse_eye_cmp(const void *a, const void *b)
{
	const struct coarse_eye *x = a, *y = b;

	if (x->score != y->score)
		return x->score < y->score ? -1 : 1;
	/* Equal scores in the grid's order: the same answer every time. */
	return x->order < y->order ? -1 : x->order > y->order;
}

/* The second look: around each of the best COARSE_SECOND eyes, the
 * neighbours at a spacing COARSE_SECOND_SHRINK times finer (a near eye's
 * view changes faster with its position than the first grid's steps). */
#define COARSE_SECOND 6
#define COARSE_SECOND_SHRINK 2.5

/* The second grid: eyes around the scene's middle, looking at it.  Near
 * (FIT_REACH_NEAR): at distances about the start's, from azimuths up to 60
 * degrees either side of the start's and elevations from the floor up (a
 * student turns the camera to keep the objects in view); not all round,
 * since the checkerboard looks the same turned by a right angle, and the
 * views from the other sides are false friends more often than true ones.
 * All round (FIT_REACH_ROUND), nearer, farther and higher too: the last
 * look, only for an image no nearer camera comes near (a student who
 * walked the camera to the other side of the objects, or over them). */
static const double coarse_near_dists[] = { 0.6, 0.85, 1.15, 1.6 };
static const double coarse_near_azimuths[] = { -60, -40, -20, 0, 20, 40, 60 };
static const double coarse_near_elevations[] = { 3, 12, 24, 38, 55 };
static const double coarse_round_dists[] = { 0.4, 0.6, 0.85, 1.15, 1.6, 2.2 };
static const double coarse_round_azimuths[] = { -150, -120, -90, -60, -30, 0, 30, 60, 90, 120, 150, 180 };
static const double coarse_round_elevations[] = { 3, 12, 24, 38, 55, 70 };

static const struct coarse_orbit {
	const double *dists, *azimuths, *elevations;
	size_t n_dists, n_azimuths, n_elevations;
	bool box;			/* the grid of eyes about the start, too */
} coarse_orbits[] = {
	[FIT_REACH_NEAR] = { coarse_near_dists, coarse_near_azimuths, coarse_near_elevations,
			     COARSE_LEN(coarse_near_dists), COARSE_LEN(coarse_near_azimuths),
			     COARSE_LEN(coarse_near_elevations), true },
	[FIT_REACH_ROUND] = { coarse_round_dists, coarse_round_azimuths, coarse_round_elevations,
			      COARSE_LEN(coarse_round_dists), COARSE_LEN(coarse_round_azimuths),
			      COARSE_LEN(coarse_round_elevations), false },
};

static size_t coarse_orbit_size(const struct coarse_orbit *o)
{
	return o->n_dists * o->n_azimuths * o->n_elevations;
}

static int coarse_orbit_eyes(struct coarse_work *w, const struct coarse_orbit *o, struct vec3 centre,
			     int n)
{
	const double rad = 3.14159265358979323846 / 180.0;
	struct vec3 off = vec3_sub(w->start->eye, centre);
	double dist = vec3_length(off), az0 = atan2(off.y, off.x);
	size_t a, b, c;

	if (!(dist > 1.0))
		return n;
	for (a = 0; a < o->n_dists; a++)
		for (b = 0; b < o->n_azimuths; b++)
			for (c = 0; c < o->n_elevations; c++) {
				double r = dist * o->dists[a], az = az0 + o->azimuths[b] * rad;
				double el = o->elevations[c] * rad;
				struct vec3 e = vec3_add(centre, vec3_make(r * cos(el) * cos(az), r * cos(el) * sin(az),
									   r * sin(el)));
				if (e.z < 1.0)
					continue;
				w->eyes[n].order = n;
				w->eyes[n].eye = e;
				w->eyes[n].dir = vec3_sub(centre, e);
				n++;
			}
	return n;
}

/* Long: the coarse search's two looks (the grid of eyes, then around the
 * best) and the merge of their candidates, over one work struct. */
int fit_coarse_search(const struct grade_job *job, const struct grade_variant *variant,
		      enum fit_reach reach, const struct camera_params *start, const struct image *sub, double radius,
		      double spacing, struct vec3 centre,
		      double out[][FIT_DIM], double *scores, int n_out, struct diag *d)
{
	const struct coarse_orbit *orbit = &coarse_orbits[reach];
	struct coarse_target t;
	struct coarse_work w;
	/* Without the box, steps -1 leaves its loops empty. */
	int steps = orbit->box ? (int)floor(radius / spacing) : -1, i, j, k, n = 0, m, first_n;
	size_t side = orbit->box ? (size_t)(2 * steps + 1) : 0;
	size_t cap = side * side * side + COARSE_SECOND * 27 + coarse_orbit_size(orbit);
	int rc;

	if ((rc = coarse_target_make(&t, sub, d)) < 0) {
		coarse_target_free(&t);
		return rc;
	}
	memset(&w, 0, sizeof(w));
	w.job = job;
	w.variant = variant;
	w.start = start;
	w.t = &t;
	w.eyes = rt_reallocarray(NULL, cap, sizeof(*w.eyes));
	if (!w.eyes) {
		coarse_target_free(&t);
		return diag_fail(d, RT_E_NOMEM, "out of memory for the camera fit");
	}
	for (i = -steps; i <= steps; i++)
		for (j = -steps; j <= steps; j++)
			for (k = -steps; k <= steps; k++) {
				struct vec3 e = vec3_add(start->eye, vec3_make(i * spacing, j * spacing, k * spacing));
				if ((double)(i * i + j * j + k * k) * spacing * spacing > radius * radius * 1.01)
					continue;
				if (e.z < 1.0 && !(k == 0 && e.z == start->eye.z))
					continue;
				w.eyes[n].order = n;
				w.eyes[n].dir = vec3_sub(start->look, start->eye);
				w.eyes[n++].eye = e;
			}
	n = coarse_orbit_eyes(&w, orbit, centre, n);
	coarse_run(&w, 0, n);
	qsort(w.eyes, (size_t)n, sizeof(*w.eyes), coarse_eye_cmp);
	first_n = n;
	for (m = 0; m < COARSE_SECOND && m < first_n; m++)
		for (i = -1; i <= 1; i++)
			for (j = -1; j <= 1; j++)
				for (k = -1; k <= 1; k++) {
					double s2 = spacing / COARSE_SECOND_SHRINK;
					struct vec3 e = vec3_add(w.eyes[m].eye, vec3_make(i * s2, j * s2, k * s2));
					if ((i == 0 && j == 0 && k == 0) || e.z < 1.0)
						continue;
					w.eyes[n].order = n;
					w.eyes[n].dir = w.eyes[m].dir;
					w.eyes[n++].eye = e;
				}
	coarse_run(&w, first_n, n);
	qsort(w.eyes, (size_t)n, sizeof(*w.eyes), coarse_eye_cmp);
	for (i = 0; i < n_out; i++) {
		scores[i] = i < n ? w.eyes[i].score : INFINITY;
		if (i < n)
			memcpy(out[i], w.eyes[i].view, sizeof(out[i]));
	}
	rt_free(w.eyes);
	coarse_target_free(&t);
	if (job->cancel && *job->cancel)
		return diag_fail(d, RT_E_INTERRUPTED, "interrupted");
	return 0;
}
