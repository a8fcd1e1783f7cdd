/* whitted explain's library half (whitted/explain.h): the Whitted sum of
 * shade.c traced once more for one pixel, each step recorded.  The colour
 * is made by the same operations in the same order as render_trace's
 * (render_trace_in, render_shade_from, render_direct and
 * render_direct_full, render_transmit) on the same helpers (render_point_at,
 * render_bounce, render_refract, glass_stack_pass, render_clamp), so its
 * bytes are the image's; the breakdown into diffuse and specular terms is
 * computed beside it for the reader, never summed.  The tree is traced
 * whole, without the render's cut-off (ray_tree.h): the render's bytes are
 * the whole tree's, and a pixel's tree is refused above
 * RT_EXPLAIN_MAX_RAYS rays. */
#include <math.h>
#include <string.h>

#include "accel/accel.h"
#include "base/alloc.h"
#include "render/glass_stack.h"
#include "render/shade_hit.h"
#include "render/shade_math.h"
#include "scene/scene_impl.h"
#include "whitted/explain.h"

struct explainer {
	const struct scene *s;
	const struct render_settings *rs;
	struct explanation *e;
	size_t cap_rays, cap_lights;
	int sample;
	int rc;			/* the first failure, or 0 */
	struct diag *d;
};

const char *explain_light_state_name(enum explain_light_state s)
{
	static const char *const names[] = { "lit", "at-point", "behind", "outside-cone", "shadowed" };

	return (unsigned)s < sizeof(names) / sizeof(names[0]) ? names[s] : "?";
}

const char *explain_ray_kind_name(enum explain_ray_kind k)
{
	static const char *const names[] = { "primary", "reflected", "refracted" };

	return (unsigned)k < sizeof(names) / sizeof(names[0]) ? names[k] : "?";
}

/* The object sh is: its place in the file, keyword and line. */
static struct explain_object explain_object_of(const struct scene *s, const struct shape *sh)
{
	struct explain_object o = { 0, sh->ops->keyword, 0, false };
	size_t i;

	if (sh == s->floor) {
		o.floor = true;
		return o;
	}
	for (i = 0; i < s->n_shapes; i++)
		if (s->shapes[i] == sh) {
			o.index = (long)i + 1;
			o.line = scene_shape_line(s, i);
			break;
		}
	return o;
}

static long explain_new_ray(struct explainer *x)
{
	struct explanation *e = x->e;

	if (x->rc < 0)
		return -1;
	if (e->n_rays >= RT_EXPLAIN_MAX_RAYS) {
		x->rc = diag_fail(x->d, RT_E_RANGE,
				  "pixel %d,%d: its tree has more than %d rays (glass at recursion %d); "
				  "explain it at a lower recursion (-r)", e->x, e->y, RT_EXPLAIN_MAX_RAYS,
				  x->rs->recursion);
		return -1;
	}
	if (e->n_rays == x->cap_rays) {
		size_t cap = x->cap_rays ? 2 * x->cap_rays : 16;
		struct explain_ray *r = rt_reallocarray(e->rays, cap, sizeof(*r));
		if (!r) {
			x->rc = diag_fail(x->d, RT_E_NOMEM, "out of memory");
			return -1;
		}
		e->rays = r;
		x->cap_rays = cap;
	}
	memset(&e->rays[e->n_rays], 0, sizeof(e->rays[0]));
	return (long)e->n_rays++;
}

static struct explain_light *explain_new_light(struct explainer *x)
{
	struct explanation *e = x->e;

	if (x->rc < 0)
		return NULL;
	if (e->n_lights == x->cap_lights) {
		size_t cap = x->cap_lights ? 2 * x->cap_lights : 16;
		struct explain_light *l = rt_reallocarray(e->lights, cap, sizeof(*l));
		if (!l) {
			x->rc = diag_fail(x->d, RT_E_NOMEM, "out of memory");
			return NULL;
		}
		e->lights = l;
		x->cap_lights = cap;
	}
	memset(&e->lights[e->n_lights], 0, sizeof(e->lights[0]));
	return &e->lights[e->n_lights++];
}

/* The nearest object on the blocked shadow ray, for the reader (the
 * answer that counts is accel_occluded's). */
static void explain_blocker(const struct scene *s, const struct ray *shadow, double eps,
			    double t_max, struct explain_light *out)
{
	double t = t_max;
	const struct shape *hit = accel_intersect(s->accel, shadow, eps, &t);

	out->blocker_known = hit != NULL;
	if (hit)
		out->blocker = explain_object_of(s, hit);
}

/* One light at the hit h, as render_direct (full: render_direct_full)
 * treats it: its term in *term (black unless lit), recorded in *l.
 * Long: one light's term with each quantity recorded, in render_direct's
 * order. */
static void explain_one_light(const struct scene *s, const struct light *lt,
			      const struct render_point *h, bool full, struct explain_light *l,
			      struct color *term)
{
	const struct material *m = &h->hit->mat;
	struct vec3 to_light = vec3_sub(lt->pos, h->p);
	struct ray shadow;
	struct color lcb = color_mul(lt->color, h->base);
	double dist = vec3_length(to_light), nl, rl, pw = 0.0, k;

	*term = color_make(0.0, 0.0, 0.0);
	l->attenuation = 1.0;
	l->distance = dist;
	l->l = vec3_scale(to_light, 1.0 / dist);
	nl = l->n_dot_l = vec3_dot(h->n, l->l);
	rl = l->r_dot_l = vec3_dot(h->refl, l->l);
	if (!(dist > h->eps)) {
		l->state = EXPLAIN_AT_POINT;
		return;
	}
	if (nl <= 0.0) {
		l->state = EXPLAIN_BEHIND;
		return;
	}
	if (full && lt->spot && !(-vec3_dot(l->l, lt->axis) >= lt->cos_cutoff)) {
		l->state = EXPLAIN_OUTSIDE_CONE;
		return;
	}
	shadow.origin = vec3_add_scaled(h->p, l->l, h->eps);
	shadow.dir = l->l;
	if (accel_occluded(s->accel, &shadow, h->eps, dist - h->eps)) {
		l->state = EXPLAIN_SHADOWED;
		explain_blocker(s, &shadow, h->eps, dist - h->eps, l);
		return;
	}
	l->state = EXPLAIN_LIT;
	if (rl > 0.0)
		pw = render_specular_power(rl, m->shininess);
	if (full && lt->falloff > 0.0)
		l->attenuation = exp(-dist * dist * lt->falloff);
	/* The reader's breakdown. */
	l->diffuse = color_scale(lcb, m->kd * nl * l->attenuation);
	l->specular = color_scale(color_mul(lt->color, h->spec ? h->spec_color : h->base),
				  rl > 0.0 ? m->ks * pw * l->attenuation : 0.0);
	/* The term, as the renderer makes it. */
	if (h->spec) {
		*term = color_scale(lcb, m->kd * nl);
		if (rl > 0.0)
			*term = color_add(*term, color_scale(color_mul(lt->color, h->spec_color),
							     m->ks * pw));
		if (full && lt->falloff > 0.0)
			*term = color_scale(*term, exp(-dist * dist * lt->falloff));
	} else {
		k = m->kd * nl;
		if (rl > 0.0)
			k += m->ks * pw;
		if (full && lt->falloff > 0.0)
			k *= exp(-dist * dist * lt->falloff);
		*term = color_scale(lcb, k);
	}
	l->term = *term;
}

static struct color explain_trace(struct explainer *x, const struct ray *r, int level,
				  const struct glass_stack *glass, double weight, long parent,
				  enum explain_ray_kind kind);

/* The sum at the hit of ray `id` (render_shade_from).
 * Long: render_trace's sum again, each step recorded, in render_trace's
 * order. */
static struct color explain_shade(struct explainer *x, long id, const struct ray *r, int level,
				  const struct glass_stack *glass, double weight,
				  const struct render_point *h)
{
	const struct scene *s = x->s;
	const struct render_settings *rs = x->rs;
	const struct material *m = &h->hit->mat;
	bool full = s->n_special_lights != 0, tir = false;
	struct vec3 through = { 0.0, 0.0, 0.0 };
	struct glass_stack beyond;
	struct color c, direct = color_make(0.0, 0.0, 0.0);
	struct explain_ray *node;
	size_t i, first = x->e->n_lights;
	double eta = 1.0;
	long child;

	c = color_scale(h->base, m->ka);
	for (i = 0; i < s->n_lights; i++) {
		struct explain_light *l = explain_new_light(x);
		struct color term;
		if (!l)
			return color_make(0.0, 0.0, 0.0);
		explain_one_light(s, &s->lights[i], h, full, l, &term);
		if (l->state == EXPLAIN_LIT)
			direct = color_add(direct, term);
	}
	c = color_add(c, direct);
	node = &x->e->rays[id];
	node->first_light = first;
	node->n_lights = s->n_lights;
	node->ambient = color_scale(h->base, m->ka);
	node->direct = direct;
	node->reflected = node->refracted = -1;
	if (level < rs->recursion && m->kt > 0.0) {
		glass_stack_pass(glass, h->hit, &beyond, &eta);
		tir = !render_refract(r->dir, h->n, h->dn, eta, &through);
		node->eta = eta;
		node->total_internal_reflection = tir;
	}
	if (level < rs->recursion && (m->kr > 0.0 || tir)) {
		struct ray bounce;
		struct color seen;
		double k = tir ? 1.0 : m->kr;

		render_bounce(h, &bounce);
		child = (long)x->e->n_rays;
		seen = explain_trace(x, &bounce, level + 1, glass, weight * k, id, EXPLAIN_REFLECTED);
		if (x->rc < 0)
			return c;
		node = &x->e->rays[id];
		node->reflected = child;
		node->k_reflected = k;
		node->reflected_color = seen;
		c = color_add(c, color_scale(seen, k));
	}
	if (level < rs->recursion && m->kt > 0.0 && !tir) {
		struct ray ray_through;
		struct color seen;

		ray_through.origin = vec3_add_scaled(h->p, through, h->eps);
		ray_through.dir = through;
		child = (long)x->e->n_rays;
		seen = explain_trace(x, &ray_through, level + 1, &beyond, weight * m->kt, id,
				     EXPLAIN_REFRACTED);
		if (x->rc < 0)
			return c;
		node = &x->e->rays[id];
		node->refracted = child;
		node->refracted_color = seen;
		c = color_add(c, color_scale(seen, m->kt));
	}
	x->e->rays[id].sum = c;
	return rs->clamp == RT_CLAMP_LEVEL ? render_clamp(c) : c;
}

/* render_trace_in, recorded: the ray's node, its hit and its sum. */
static struct color explain_trace(struct explainer *x, const struct ray *r, int level,
				  const struct glass_stack *glass, double weight, long parent,
				  enum explain_ray_kind kind)
{
	long id = explain_new_ray(x);
	struct explain_ray *node;
	struct render_point h;
	struct color c;
	double t = INFINITY;
	const struct shape *hit;

	if (id < 0)
		return color_make(0.0, 0.0, 0.0);
	node = &x->e->rays[id];
	node->kind = kind;
	node->sample = x->sample;
	node->parent = parent;
	node->level = level;
	node->weight = weight;
	node->ray = *r;
	node->reflected = node->refracted = -1;
	hit = accel_intersect(x->s->accel, r, render_offset(r->origin), &t);
	if (!hit)
		return color_make(0.0, 0.0, 0.0);
	render_point_at(r, t, hit, &h);
	node->hit = true;
	node->object = explain_object_of(x->s, hit);
	node->t = t;
	node->point = h.p;
	node->normal = h.n;
	node->turned = vec3_dot(h.n, shape_normal(hit, h.p)) < 0.0;
	node->surface = h.base;
	node->highlight_own = h.spec;
	node->highlight = h.spec ? h.spec_color : h.base;
	node->mat = hit->mat;
	c = explain_shade(x, id, r, level, glass, weight, &h);
	x->e->rays[id].color = c;
	return c;
}

void explanation_free(struct explanation *e)
{
	rt_free(e->rays);
	rt_free(e->lights);
	rt_free(e->sample_colors);
	memset(e, 0, sizeof(*e));
}

int explain_pixel(const struct scene *s, const struct camera *cam,
		  const struct render_settings *rs, int samples, int x, int y,
		  struct explanation *out, struct diag *d)
{
	static const struct glass_stack outside = { 0, { NULL } };
	struct explainer ex;
	int n = samples > 1 ? samples : 1, nn = n * n, k;

	memset(out, 0, sizeof(*out));
	if (!s->accel)
		return diag_fail(d, RT_E_INVALID, "the scene was not prepared");
	if (x < 0 || y < 0 || x >= cam->width || y >= cam->height)
		return diag_fail(d, RT_E_INVALID, "pixel %d,%d is outside the %dx%d image", x, y,
				 cam->width, cam->height);
	if (n > RT_MAX_SAMPLES)
		return diag_fail(d, RT_E_INVALID, "at most %d samples", RT_MAX_SAMPLES);
	out->x = x;
	out->y = y;
	out->width = cam->width;
	out->height = cam->height;
	out->settings = *rs;
	out->samples = n;
	if (!(out->sample_colors = rt_calloc((size_t)nn, sizeof(*out->sample_colors))))
		return diag_fail(d, RT_E_NOMEM, "out of memory");
	memset(&ex, 0, sizeof(ex));
	ex.s = s;
	ex.rs = rs;
	ex.e = out;
	ex.d = d;
	if (n == 1) {
		struct ray r = camera_ray(cam, x, y);
		out->color = out->sample_colors[0] = explain_trace(&ex, &r, 1, &outside, 1.0, -1,
								   EXPLAIN_PRIMARY);
	} else {
		/* samples.c: the sub-pixels' centres in order, each sample
		 * clamped, summed, the sum divided once. */
		const double inv_nn = 1.0 / ((double)n * n);
		double offset[RT_MAX_SAMPLES];
		struct color sum = color_make(0.0, 0.0, 0.0);

		for (k = 0; k < n; k++)
			offset[k] = (k + 0.5) / n;
		for (k = 0; k < nn && ex.rc == 0; k++) {
			struct ray r = camera_ray_at(cam, x + offset[k % n], y + offset[k / n]);
			ex.sample = k;
			out->sample_colors[k] = explain_trace(&ex, &r, 1, &outside, 1.0, -1,
							      EXPLAIN_PRIMARY);
			sum = color_add(sum, color_clamp(out->sample_colors[k]));
		}
		out->color = color_scale(sum, inv_nn);
	}
	if (ex.rc < 0) {
		explanation_free(out);
		return ex.rc;
	}
	out->clamped = render_clamp(out->color);
	render_color_to_rgb8(out->color, out->value);
	return 0;
}
