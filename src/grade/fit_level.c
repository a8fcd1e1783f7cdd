/* The camera fit's levels: the submission seen through a few thousand
 * of its own pixels, and a candidate camera's colours through the same
 * pixels.  Each cell holds the mean of ss x ss pixels of the full image,
 * taken at those pixels' centres on both sides, so that the camera that
 * made the image scores 0 however coarse the level; a Gaussian blur of
 * both sides widens the valley around it (a checkerboard seen without
 * blur has a needle there, and one every two cells beside it). */
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

#include "base/alloc.h"
#include "accel/accel.h"
#include "grade/fit.h"
#include "render/ray_tree.h"
#include "render/render_packet.h"
#include "scene/scene_impl.h"

#define FIT_PI 3.14159265358979323846

void fit_view_of(const struct camera_params *p, double v[FIT_DIM])
{
	struct vec3 f = vec3_normalize(vec3_sub(p->look, p->eye));
	struct vec3 right = vec3_cross(f, vec3_make(0.0, 0.0, 1.0)), level_up, up;
	double rl = vec3_length(right);

	v[FIT_X] = p->eye.x;
	v[FIT_Y] = p->eye.y;
	v[FIT_Z] = p->eye.z;
	v[FIT_YAW] = atan2(f.y, f.x) * 180.0 / FIT_PI;
	v[FIT_PITCH] = asin(f.z < -1.0 ? -1.0 : f.z > 1.0 ? 1.0 : f.z) * 180.0 / FIT_PI;
	v[FIT_FOV] = p->fov_deg;
	v[FIT_ROLL] = 0.0;
	if (rl < 1e-9)
		return;
	right = vec3_scale(right, 1.0 / rl);
	level_up = vec3_cross(right, f);
	up = vec3_sub(p->up, vec3_scale(f, vec3_dot(p->up, f)));
	v[FIT_ROLL] = atan2(vec3_dot(up, right), vec3_dot(up, level_up)) * 180.0 / FIT_PI;
}

void fit_params_of(const double v[FIT_DIM], const struct camera_params *base,
		   struct camera_params *out)
{
	double yaw = v[FIT_YAW] * FIT_PI / 180.0, pitch = v[FIT_PITCH] * FIT_PI / 180.0;
	double roll = v[FIT_ROLL] * FIT_PI / 180.0;
	struct vec3 f = vec3_make(cos(pitch) * cos(yaw), cos(pitch) * sin(yaw), sin(pitch));
	struct vec3 right = vec3_make(sin(yaw), -cos(yaw), 0.0), level_up = vec3_cross(right, f);

	*out = *base;
	out->eye = vec3_make(v[FIT_X], v[FIT_Y], v[FIT_Z]);
	out->look = vec3_add_scaled(out->eye, f, 100.0);
	out->up = vec3_add(vec3_scale(level_up, cos(roll)), vec3_scale(right, sin(roll)));
	out->fov_deg = v[FIT_FOV];
}

/* v rotated by angle (radians) about the unit axis a (Rodrigues). */
static struct vec3 fit_rotate(struct vec3 v, struct vec3 a, double angle)
{
	double c = cos(angle), s = sin(angle);

	return vec3_add(vec3_add(vec3_scale(v, c), vec3_scale(vec3_cross(a, v), s)),
			vec3_scale(a, vec3_dot(a, v) * (1.0 - c)));
}

void fit_view_move(const double v[FIT_DIM], const double q[FIT_DIM], double pivot,
		   double out[FIT_DIM])
{
	const double rad = FIT_PI / 180.0;
	struct camera_params base, p;
	struct vec3 e, f, u, r, c;
	double t0, t1, dist;

	memset(&base, 0, sizeof(base));
	fit_params_of(v, &base, &p);
	e = p.eye;
	f = vec3_normalize(vec3_sub(p.look, p.eye));
	r = vec3_normalize(vec3_cross(f, p.up));
	u = vec3_cross(r, f);
	c = vec3_add_scaled(e, f, pivot);
	/* Orbits: the eye and the view turn about the pivot. */
	e = vec3_add(c, fit_rotate(vec3_sub(e, c), u, -q[FIT_ORBIT_YAW] * rad));
	f = fit_rotate(f, u, -q[FIT_ORBIT_YAW] * rad);
	r = fit_rotate(r, u, -q[FIT_ORBIT_YAW] * rad);
	e = vec3_add(c, fit_rotate(vec3_sub(e, c), r, q[FIT_ORBIT_PITCH] * rad));
	f = fit_rotate(f, r, q[FIT_ORBIT_PITCH] * rad);
	u = fit_rotate(u, r, q[FIT_ORBIT_PITCH] * rad);
	u = fit_rotate(u, f, q[FIT_TURN_ROLL] * rad);
	r = vec3_cross(f, u);
	e = vec3_add_scaled(e, r, q[FIT_PAN_X]);
	e = vec3_add_scaled(e, u, q[FIT_PAN_Y]);
	/* The dolly: the pivot's half-height D tan(fov / 2) kept. */
	dist = pivot - q[FIT_DOLLY];
	dist = dist > 0.05 * pivot ? dist : 0.05 * pivot;
	e = vec3_add_scaled(e, f, pivot - dist);
	t0 = tan(v[FIT_FOV] * rad / 2.0);
	t1 = t0 * pivot / dist;
	p.eye = e;
	p.look = vec3_add_scaled(e, f, 100.0);
	p.up = u;
	p.fov_deg = 2.0 * atan(t1) / rad + q[FIT_ZOOM];
	fit_view_of(&p, out);
}

void fit_colour(double r, double g, double b, float out[3])
{
	out[0] = (float)((r + g + b) / 3.0);
	out[1] = (float)fabs(r - b);
	out[2] = (float)(g - 0.5 * (r + b));
}

static int fit_level_alloc(struct fit_level *l, int n_cells, int ss, struct diag *d)
{
	size_t ns = (size_t)n_cells * (size_t)ss * (size_t)ss;

	l->n_cells = n_cells;
	l->n_samples = (int)ns;
	l->sx = rt_reallocarray(NULL, ns, sizeof(*l->sx));
	l->sy = rt_reallocarray(NULL, ns, sizeof(*l->sy));
	l->target = rt_reallocarray(NULL, (size_t)n_cells * 3, sizeof(*l->target));
	if (!l->sx || !l->sy || !l->target) {
		fit_level_free(l);
		return diag_fail(d, RT_E_NOMEM, "out of memory for the camera fit");
	}
	return 0;
}

/* Whether neighbours a and b of sub differ by more than FIT_ALIAS_STEP
 * levels in a channel. */
#define FIT_ALIAS_STEP 40
#define FIT_ALIAS_WINDOW 6

static bool fit_step(const uint8_t *a, const uint8_t *b)
{
	return abs(a[0] - b[0]) > FIT_ALIAS_STEP || abs(a[1] - b[1]) > FIT_ALIAS_STEP ||
	       abs(a[2] - b[2]) > FIT_ALIAS_STEP;
}

/* The cells' weights: 0 where the submission is a texture finer than its
 * pixels (a checkerboard towards the horizon, whose pixels flip with the
 * least move of the camera: every offset there is as good as the true
 * one), 1 elsewhere.  A cell's window (at least FIT_ALIAS_WINDOW pixels
 * across) is aliased when more than a quarter of its neighbours differ
 * sharply both across and down; an edge, however sharp, crosses far
 * fewer. */
static int fit_level_weigh(struct fit_level *l, const struct image *sub, struct diag *d)
{
	const size_t w = (size_t)sub->width;
	int x, y, cell = 0;

	if (!(l->weight = rt_reallocarray(NULL, (size_t)l->n_cells, sizeof(*l->weight))))
		return diag_fail(d, RT_E_NOMEM, "out of memory for the camera fit");
	for (y = 0; y < l->h; y++)
		for (x = 0; x < l->w; x++, cell++) {
			int x0 = (int)((long)x * sub->width / l->w), x1 = (int)((long)(x + 1) * sub->width / l->w);
			int y0 = (int)((long)y * sub->height / l->h), y1 = (int)((long)(y + 1) * sub->height / l->h);
			int X, Y, nx = 0, ny = 0, cx = 0, cy = 0;
			double fx, fy, m;
			while (x1 - x0 < FIT_ALIAS_WINDOW && (x0 > 0 || x1 < sub->width)) {
				x0 -= x0 > 0;
				x1 += x1 < sub->width;
			}
			while (y1 - y0 < FIT_ALIAS_WINDOW && (y0 > 0 || y1 < sub->height)) {
				y0 -= y0 > 0;
				y1 += y1 < sub->height;
			}
			for (Y = y0; Y < y1; Y++)
				for (X = x0; X < x1; X++) {
					const uint8_t *p = sub->pixels + 3 * ((size_t)Y * w + (size_t)X);
					if (X + 1 < x1) {
						nx++;
						cx += fit_step(p, p + 3);
					}
					if (Y + 1 < y1) {
						ny++;
						cy += fit_step(p, p + 3 * w);
					}
				}
			fx = nx ? (double)cx / nx : 0.0;
			fy = ny ? (double)cy / ny : 0.0;
			m = fx < fy ? fx : fy;
			l->weight[cell] = (float)(m <= 0.15 ? 1.0 : m >= 0.25 ? 0.0 : (0.25 - m) / 0.1);
		}
	return 0;
}

int fit_level_grid(struct fit_level *l, const struct image *sub, int w, int h, int ss,
		   double sigma, struct diag *d)
{
	int x, y, i, j, k = 0, rc;
	float *tmp;

	memset(l, 0, sizeof(*l));
	l->w = w;
	l->h = h;
	l->ss = ss;
	l->sigma = sigma;
	if ((rc = fit_level_alloc(l, w * h, ss, d)) < 0)
		return rc;
	for (y = 0; y < h; y++)
		for (x = 0; x < w; x++) {
			int x0 = (int)((long)x * sub->width / w), x1 = (int)((long)(x + 1) * sub->width / w);
			int y0 = (int)((long)y * sub->height / h), y1 = (int)((long)(y + 1) * sub->height / h);
			double s[3] = { 0.0, 0.0, 0.0 };
			for (j = 0; j < ss; j++)
				for (i = 0; i < ss; i++, k++) {
					int px = x0 + (int)((i + 0.5) * (x1 - x0) / ss);
					int py = y0 + (int)((j + 0.5) * (y1 - y0) / ss);
					const uint8_t *q = sub->pixels + 3 * ((size_t)py * (size_t)sub->width + (size_t)px);
					float f[3];
					l->sx[k] = px;
					l->sy[k] = py;
					/* Each pixel's, then their mean: as the
					 * candidate's cells are made. */
					fit_colour(q[0], q[1], q[2], f);
					s[0] += f[0];
					s[1] += f[1];
					s[2] += f[2];
				}
			for (i = 0; i < 3; i++)
				l->target[3 * (y * w + x) + i] = (float)(s[i] / (ss * ss));
		}
	if (sigma > 0.0) {
		if (!(tmp = rt_reallocarray(NULL, (size_t)w * (size_t)h * 3, sizeof(*tmp)))) {
			fit_level_free(l);
			return diag_fail(d, RT_E_NOMEM, "out of memory for the camera fit");
		}
		fit_blur(l->target, tmp, w, h, sigma);
		rt_free(tmp);
	}
	return fit_level_weigh(l, sub, d);
}

void fit_level_free(struct fit_level *l)
{
	rt_free(l->sx);
	rt_free(l->sy);
	rt_free(l->target);
	rt_free(l->weight);
	memset(l, 0, sizeof(*l));
}

int fit_scratch_alloc(struct fit_scratch *s, const struct fit_level *l, struct diag *d)
{
	s->points = NULL;
	s->cells = rt_reallocarray(NULL, (size_t)l->n_cells * 3, sizeof(float));
	s->tmp = rt_reallocarray(NULL, (size_t)l->n_cells * 3, sizeof(float));
	if (!s->cells || !s->tmp) {
		fit_scratch_free(s);
		return diag_fail(d, RT_E_NOMEM, "out of memory for the camera fit");
	}
	return 0;
}

void fit_scratch_free(struct fit_scratch *s)
{
	rt_free(s->cells);
	rt_free(s->tmp);
	rt_free(s->points);
	s->cells = s->tmp = NULL;
	s->points = NULL;
}

int fit_scratch_points(struct fit_scratch *s, const struct fit_level *l, struct diag *d)
{
	if (!(s->points = rt_reallocarray(NULL, (size_t)l->n_cells * 4, sizeof(double))))
		return diag_fail(d, RT_E_NOMEM, "out of memory for the camera fit");
	return 0;
}

void fit_trace_rays(const struct render_job *rj, struct render_tree *tree,
		    const struct grade_job *job, const struct grade_variant *var,
		    const struct ray *rays, int n, struct color *col)
{
	const bool plain = grade_variant_traces_plain(job, var);
	int i;

	if (plain && render_packets_wanted(job->scene->accel) && !job->scene->glass)
		render_rays_packets(rj, rays, n, tree, col);
	else if (plain)
		for (i = 0; i < n; i++)
			col[i] = render_trace(job->scene, &rj->settings, &rays[i], 1, NULL);
	else
		for (i = 0; i < n; i++)
			col[i] = grade_variant_trace(job, var, &rays[i]);
	if (var)
		for (i = 0; i < n; i++)
			col[i] = grade_variant_encode(var, col[i]);
}

/* The rays a level's cells are made of, RT_FIT_RAYS at a time.
 * Long: the level's rays made, traced and summed into cells in batches, the
 * three sharing the batch's arrays. */
#define FIT_RAYS 64

int fit_level_render(const struct fit_level *l, const struct grade_job *job,
		      const struct camera_params *base, const double v[FIT_DIM],
		      struct fit_scratch *s)
{
	const struct camera *full = job->camera;
	const int per = l->ss * l->ss;
	struct camera_params p;
	struct camera cam;
	struct render_job rj;
	struct ray_counts counts;
	struct render_tree tree;
	struct ray rays[FIT_RAYS];
	struct color col[FIT_RAYS];
	struct diag d;
	int k, i, m;

	if (!(v[FIT_FOV] > 1.0 && v[FIT_FOV] < 170.0) || !(fabs(v[FIT_PITCH]) < 89.0))
		return -1;
	fit_params_of(v, base, &p);
	if (base->aspect > 0.0 && !(p.aspect * p.fov_deg < 179.0))
		return -1;
	if (camera_init_rect(&cam, &p, full->width, full->height, &d) < 0)
		return -1;
	render_job_init(&rj, job->scene, &cam, 1);
	rj.settings = job->settings;
	rj.settings.recursion = l->recursion > 0 && l->recursion < rj.settings.recursion
					? l->recursion : rj.settings.recursion;
	memset(&counts, 0, sizeof(counts));
	render_tree_unbound(&tree, &counts);
	memset(s->cells, 0, sizeof(float) * 3 * (size_t)l->n_cells);
	for (k = 0; k < l->n_samples; k += m) {
		m = l->n_samples - k < FIT_RAYS ? l->n_samples - k : FIT_RAYS;
		for (i = 0; i < m; i++)
			rays[i] = camera_ray(&cam, l->sx[k + i], l->sy[k + i]);
		fit_trace_rays(&rj, &tree, job, l->variant, rays, m, col);
		for (i = 0; i < m; i++) {
			float *c = s->cells + 3 * ((k + i) / per);
			struct color q = color_clamp(col[i]);
			double wt = 1.0 / per;
			float f[3];
			fit_colour(255.0 * q.r, 255.0 * q.g, 255.0 * q.b, f);
			c[0] += (float)(f[0] * wt);
			c[1] += (float)(f[1] * wt);
			c[2] += (float)(f[2] * wt);
		}
	}
	fit_blur(s->cells, s->tmp, l->w, l->h, l->sigma);
	if (s->points)
		for (k = 0; k < l->n_cells; k++) {
			int mid = k * per + per / 2;
			struct ray r = camera_ray(&cam, l->sx[mid], l->sy[mid]);
			double t = INFINITY;
			double *q = s->points + 4 * (size_t)k;
			if (accel_intersect(job->scene->accel, &r, 0.0, &t)) {
				q[0] = r.origin.x + t * r.dir.x;
				q[1] = r.origin.y + t * r.dir.y;
				q[2] = r.origin.z + t * r.dir.z;
				q[3] = 1.0;
			} else {
				q[0] = r.dir.x;
				q[1] = r.dir.y;
				q[2] = r.dir.z;
				q[3] = 0.0;
			}
		}
	return 0;
}

/* Where camera c sees point q (w 1) or direction q (w 0), in the full
 * image's pixel coordinates; false behind the eye. */
static bool fit_project(const struct camera *c, const double *q, double *px, double *py)
{
	struct vec3 d = vec3_make(q[0], q[1], q[2]);

	if (q[3] != 0.0)
		d = vec3_sub(d, c->eye);
	if (!(camera_project(c, d, px, py) > 1e-12))
		return false;
	*px -= 0.5;
	*py -= 0.5;
	return true;
}

void fit_level_jacobian(const struct fit_level *l, const struct grade_job *job,
			const struct camera_params *base, const double v[FIT_DIM],
			const double h[FIT_DIM], double pivot, const struct fit_scratch *s, float *jac)
{
	const size_t n = 3 * (size_t)l->n_cells;
	const double cw = (double)job->camera->width / l->w, ch = (double)job->camera->height / l->h;
	struct camera cam[FIT_DIM + 1];
	struct camera_params p;
	struct diag d;
	bool ok[FIT_DIM + 1];
	int k, x, y, c;

	for (k = 0; k <= FIT_DIM; k++) {
		double vk[FIT_DIM], q[FIT_DIM] = { 0 };
		if (k > 0)
			q[k - 1] = h[k - 1];
		fit_view_move(v, q, pivot, vk);
		fit_params_of(vk, base, &p);
		ok[k] = camera_init_rect(&cam[k], &p, job->camera->width, job->camera->height, &d) == 0;
	}
	memset(jac, 0, sizeof(float) * n * FIT_DIM);
	if (!ok[0])
		return;
	for (y = 0; y < l->h; y++)
		for (x = 0; x < l->w; x++) {
			int cell = y * l->w + x;
			const double *q = s->points + 4 * (size_t)cell;
			const float *xa = s->cells + 3 * (size_t)(y * l->w + (x > 0 ? x - 1 : x));
			const float *xb = s->cells + 3 * (size_t)(y * l->w + (x + 1 < l->w ? x + 1 : x));
			const float *ya = s->cells + 3 * (size_t)((y > 0 ? y - 1 : y) * l->w + x);
			const float *yb = s->cells + 3 * (size_t)((y + 1 < l->h ? y + 1 : y) * l->w + x);
			double gx[3], gy[3], u0, v0;
			int dx = (x > 0) + (x + 1 < l->w), dy = (y > 0) + (y + 1 < l->h);

			for (c = 0; c < 3; c++) {
				gx[c] = dx ? (xb[c] - xa[c]) / dx : 0.0;
				gy[c] = dy ? (yb[c] - ya[c]) / dy : 0.0;
			}
			if (!fit_project(&cam[0], q, &u0, &v0))
				continue;
			for (k = 0; k < FIT_DIM; k++) {
				double u1, v1, fx, fy;
				if (!ok[k + 1] || !fit_project(&cam[k + 1], q, &u1, &v1))
					continue;
				/* The flow in cells for a unit of number k. */
				fx = (u1 - u0) / (cw * h[k]);
				fy = (v1 - v0) / (ch * h[k]);
				for (c = 0; c < 3; c++)
					jac[(size_t)k * n + 3 * (size_t)cell + c] = (float)-(gx[c] * fx + gy[c] * fy);
			}
		}
}

double fit_level_score(const struct fit_level *l, const struct grade_job *job,
		       const struct camera_params *base, const double v[FIT_DIM],
		       struct fit_scratch *s)
{
	double e = 0.0, wsum = 0.0;
	int cell;

	if (fit_level_render(l, job, base, v, s) < 0)
		return INFINITY;
	for (cell = 0; cell < l->n_cells; cell++) {
		const float *a = s->cells + 3 * cell, *b = l->target + 3 * cell;
		double w = l->weight ? l->weight[cell] : 1.0;
		double d0 = a[0] - b[0], d1 = a[1] - b[1], d2 = a[2] - b[2];
		e += w * (d0 * d0 + d1 * d1 + d2 * d2);
		wsum += w;
	}
	return e / (3.0 * (wsum > 0.0 ? wsum : 1.0));
}
