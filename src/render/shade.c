/* The shading model of scene-format.md: the colour a ray sees at its
 * nearest hit (ambient, diffuse and tinted specular light from coloured
 * point lights and spotlights with shadows and falloff, recursive
 * reflection, clamping).  It runs for every ray: it allocates nothing and
 * takes no locks.  Each ray carries its weight in the pixel (the product
 * of kr, kt along its path) for the tree's bound (ray_tree.h). */
#include <math.h>

#include "accel/accel.h"
#include "render/glass_stack.h"
#include "render/light_dirs.h"
#include "render/ray_tree.h"
#include "render/shade_hit.h"
#include "render/shade_math.h"
#include "render/shade_rules.h"
#include "scene/scene_impl.h"
#include "whitted/render.h"

/* Inline in every caller, past GCC's size limits, where the comment above
 * a function says why; elsewhere C99 has no way to ask, and it is only
 * inline. */
#if defined(__GNUC__)
#define SHADE_ALWAYS_INLINE __attribute__((always_inline))
#else
#define SHADE_ALWAYS_INLINE
#endif

/* ks max(R.L, 0)^shininess. */
static inline double render_specular(const struct material *m, struct vec3 refl, struct vec3 l)
{
	double rl = vec3_dot(refl, l);

	return rl > 0.0 ? m->ks * render_specular_power(rl, m->shininess) : 0.0;
}

/* One light's term a Lc (C diffuse + S specular), diffuse being kd (N.L)
 * and specular ks max(R.L, 0)^shininess, where the highlight's colour S
 * is C unless spec says otherwise (a textured floor's cell colour under
 * its texel; see shape_specular_color_at), and a = exp(-d^2 falloff) at
 * the light's distance d, neither computed nor multiplied for a light
 * without falloff. */
static inline struct color render_light_term(const struct light *lt, struct color base,
					     const struct color *spec, double diffuse,
					     double specular, double dist)
{
	double k;

	if (spec) {
		struct color term = color_add(color_scale(color_mul(lt->color, base), diffuse),
					      color_scale(color_mul(lt->color, *spec), specular));
		return lt->falloff > 0.0 ? color_scale(term, exp(-dist * dist * lt->falloff)) : term;
	}
	k = diffuse + specular;
	if (lt->falloff > 0.0)
		k *= exp(-dist * dist * lt->falloff);
	return color_scale(color_mul(lt->color, base), k);
}

static struct color render_trace_in(const struct scene *s, const struct render_settings *rs,
				   const struct ray *r, int level, struct render_tree *tree,
				   const struct glass_stack *glass, double weight);
static struct color rules_trace_in(const struct scene *s, const struct render_settings *rs,
				   unsigned rules, const struct shade_floor *fl, const struct ray *r,
				   int level, struct render_tree *tree, const struct glass_stack *glass,
				   double weight);

/* A ray the sum sends on (a reflection, a transmission), traced with the
 * sum's rules: a render's trace where they are none, compare's else. */
static inline struct color render_trace_on(const struct scene *s, const struct render_settings *rs,
					   unsigned rules, const struct shade_floor *fl,
					   const struct ray *r, int level, struct render_tree *tree,
					   const struct glass_stack *glass, double weight)
{
	return rules || fl ? rules_trace_in(s, rs, rules, fl, r, level, tree, glass, weight)
			   : render_trace_in(s, rs, r, level, tree, glass, weight);
}

/* The transmitted term kt I(P + eps T, T) of glass, one more level, as
 * a reflection is, with the glass the ray is in once through (black when
 * the tree leaves the ray out). */
static struct color render_transmit(const struct scene *s, const struct render_settings *rs,
				    unsigned rules, const struct shade_floor *fl,
				    struct vec3 p, struct vec3 dir, double kt, double eps,
				    int level, struct render_tree *tree,
				    const struct glass_stack *glass, double weight)
{
	struct ray through;

	if (render_tree_cuts(tree, s, rs, weight * kt, level + 1))
		return color_make(0.0, 0.0, 0.0);
	through.origin = vec3_add_scaled(p, dir, eps);
	through.dir = dir;
	if (tree->counts)
		tree->counts->refraction++;
	return color_scale(render_trace_on(s, rs, rules, fl, &through, level + 1, tree, glass,
					   weight * kt),
			   kt);
}

/* Lights handled together; see render_trace. */
#define RENDER_LIGHT_BATCH 8

static bool render_shadowed(const struct scene *s, struct vec3 p, struct vec3 l,
			    double dist, double eps)
{
	struct ray shadow;

	shadow.origin = vec3_add_scaled(p, l, eps);
	shadow.dir = l;
	/* Only blockers nearer than the light count. */
	return accel_occluded(s->accel, &shadow, eps, dist - eps);
}

/* A shadow ray's answer: from the packets render_packet.c traced for the
 * point's block (the same ray, made by the same arithmetic), or traced
 * here. */
SHADE_ALWAYS_INLINE
static inline bool render_blocked(const struct scene *s, const struct render_shadows *pre,
			   size_t light, struct vec3 p, struct vec3 l, double dist, double eps)
{
	if (pre && light < RENDER_SHADOW_LIGHTS && (pre->traced[light] >> pre->bit & 1))
		return pre->blocked[light] >> pre->bit & 1;
	return render_shadowed(s, p, l, dist, eps);
}

/* The direct light at p: for each light L not shadowed and in front of the
 * surface (N.L > 0), Lc * C * (kd (N.L) + ks max(R.L, 0)^shininess). */
SHADE_ALWAYS_INLINE	/* as it was when it had one caller */
static inline struct color render_direct(const struct scene *s, const struct material *m,
				  struct color base, const struct color *spec, struct vec3 p,
				  struct vec3 n, struct vec3 refl, double eps,
				  struct ray_counts *counts, const struct render_shadows *pre)
{
	struct color c = color_make(0.0, 0.0, 0.0);
	size_t i, i0;

	for (i0 = 0; i0 < s->n_lights; i0 += RENDER_LIGHT_BATCH) {
		size_t nb = s->n_lights - i0 < RENDER_LIGHT_BATCH ? s->n_lights - i0 : RENDER_LIGHT_BATCH;
		struct vec3 l[RENDER_LIGHT_BATCH];
		double dist[RENDER_LIGHT_BATCH], nl[RENDER_LIGHT_BATCH];

		/* The directions to a batch of lights first: their square roots
		 * and divisions then overlap, where one light's used to wait for
		 * the previous light's shadow ray.  (A light at the point gives
		 * an infinite l here, which the test below never uses.) */
		for (i = 0; i < nb; i++) {
			struct vec3 to_light;

			if (pre && i0 + i < RENDER_SHADOW_KEPT) {
				const struct light_dirs *dl = &pre->dirs[i0 + i];
				l[i] = vec3_make(dl->lx[pre->bit], dl->ly[pre->bit], dl->lz[pre->bit]);
				dist[i] = dl->dist[pre->bit];
				nl[i] = dl->nl[pre->bit];
				continue;
			}
			to_light = vec3_sub(s->lights[i0 + i].pos, p);
			dist[i] = vec3_length(to_light);
			l[i] = vec3_scale(to_light, 1.0 / dist[i]);
			nl[i] = vec3_dot(n, l[i]);
		}
		for (i = 0; i < nb; i++) {
			if (!(dist[i] > eps))
				continue;
			if (nl[i] <= 0.0)
				continue;
			if (counts)
				counts->shadow++;
			if (render_blocked(s, pre, i0 + i, p, l[i], dist[i], eps))
				continue;
			c = color_add(c, render_light_term(&s->lights[i0 + i], base, spec, m->kd * nl[i],
							   render_specular(m, refl, l[i]), dist[i]));
		}
	}
	return c;
}

/* render_direct for scenes with spotlights or falloffs, and with the
 * rules broken (shade_rules.h; 0 on a render's path), one light at a
 * time in the order added: a spotlight lights p only when the angle
 * between p - Lp and its axis is at most the cutoff (cos >= cos_cutoff;
 * tested before the shadow ray, which it spares), and a light's term is
 * scaled by a = exp(-|Lp - p|^2 falloff) when the falloff is not 0.
 * Inline in its two instances below, a render's (compare false, the rules
 * 0) and compare's (through the rules' hooks), so that a render's keeps no
 * test of them (4% of a spotlit scene's render otherwise). */
SHADE_ALWAYS_INLINE
static inline struct color render_direct_full(const struct scene *s, bool compare, unsigned rules,
				       const struct material *m, struct color base,
				       const struct color *spec, struct vec3 p, struct vec3 n,
				       struct vec3 refl, double eps, struct ray_counts *counts,
				       const struct render_shadows *pre)
{
	struct color c = color_make(0.0, 0.0, 0.0);
	size_t i;

	for (i = 0; i < s->n_lights; i++) {
		const struct light *lt = &s->lights[i];
		struct vec3 to_light = vec3_sub(lt->pos, p), l;
		double dist = vec3_length(to_light), nl, specular;

		if (!(dist > eps))
			continue;
		l = vec3_scale(to_light, 1.0 / dist);
		nl = vec3_dot(n, l);
		if (nl <= 0.0 && !(rules & RT_RULE_LIGHT_BEHIND))
			continue;
		/* p - Lp is -dist l. */
		if (lt->spot && !(compare ? shade_rules_spot_lights(lt, rules, l)
					: -vec3_dot(l, lt->axis) >= lt->cos_cutoff))
			continue;
		if (counts)
			counts->shadow++;
		if (compare ? shade_rules_shadowed(s, rules, p, l, dist, eps)
			  : render_blocked(s, pre, i, p, l, dist, eps))
			continue;
		specular = render_specular(m, refl, l);
		if (rules & RT_RULE_WHITE_SPECULAR) {
			/* The highlight Lc ks (R.L)^n, not times the colour. */
			double a = lt->falloff > 0.0 ? exp(-dist * dist * lt->falloff) : 1.0;
			c = color_add(c, color_scale(color_mul(lt->color, base),
						     shade_rules_diffuse(m, rules, nl) * a));
			c = color_add(c, color_scale(lt->color, specular * a));
			continue;
		}
		c = color_add(c, render_light_term(lt, base, spec,
						   compare ? shade_rules_diffuse(m, rules, nl) : m->kd * nl,
						   specular, dist));
	}
	return c;
}

static struct color render_direct_spot(const struct scene *s, const struct material *m,
				       struct color base, const struct color *spec, struct vec3 p,
				       struct vec3 n, struct vec3 refl, double eps,
				       struct ray_counts *counts, const struct render_shadows *pre)
{
	return render_direct_full(s, false, 0, m, base, spec, p, n, refl, eps, counts, pre);
}

static struct color render_direct_rules(const struct scene *s, unsigned rules,
					const struct material *m, struct color base,
					const struct color *spec, struct vec3 p, struct vec3 n,
					struct vec3 refl, double eps)
{
	return render_direct_full(s, true, rules, m, base, spec, p, n, refl, eps, NULL, NULL);
}

/* The direct light at the point h: render_direct, or one light at a time
 * where the scene has spotlights or falloffs, or compare renders it
 * (rules broken or another floor: its diffuse as shade_rules_diffuse
 * takes it, 0 where N.L is not a number, as compare's renders always
 * had it). */
SHADE_ALWAYS_INLINE
static inline struct color render_direct_at(const struct scene *s, unsigned rules,
					    const struct shade_floor *fl, const struct material *m,
					    const struct render_point *h, const struct color *spec,
					    struct ray_counts *counts, const struct render_shadows *pre)
{
	if (rules || fl)
		return render_direct_rules(s, rules, m, h->base, spec, h->p, h->n, h->refl, h->eps);
	if (s->n_special_lights)
		return render_direct_spot(s, m, h->base, spec, h->p, h->n, h->refl, h->eps, counts, pre);
	return render_direct(s, m, h->base, spec, h->p, h->n, h->refl, h->eps, counts, pre);
}

/* The Whitted sum of scene-format.md ("Shading") at the nearest hit P of
 * the ray, with C the colour at P, N the unit normal turned to face the
 * ray and R = d - 2 (d.N) N its mirror direction:
 *   I(ray) = clamp( ka C
 *                 + sum over lights L visible from P with N.L > 0 of
 *                       a Lc C (kd (N.L) + ks max(R.L, 0)^shininess)
 *                 + kr I(P + eps R, R)      while level < recursion
 *                 + kt I(P + eps T, T)      while level < recursion, for glass )
 * clamped to [0, 1] at every level (RT_CLAMP_LEVEL) or by the caller only
 * (RT_CLAMP_FINAL); a ray that hits nothing sees black.  The attenuation
 * a is exp(-d^2 falloff) at the distance d to the light (1 for a falloff
 * of 0), and a spotlight is also dark at P outside its cone.  A scene
 * without either (every classic scene) takes render_direct, where a = 1
 * is neither tested nor multiplied, so its pixels are what they were.
 * T is the refracted direction (render_refract), kt and the index of
 * refraction those --glass gives (kt 0 for every object of a scene file,
 * which skips the term).  Under total internal reflection no light passes
 * and the surface is a whole mirror on that side: the two terms become
 * I(P + eps R, R), weight 1 (as in POV-Ray 3.7, whose totally reflected
 * light is not filtered and skips the finish's reflection).  Shadows stay
 * the contract's: glass blocks a shadow ray like any object.  Whether a
 * hit enters or leaves glass, and between which indices, is the glass
 * stack's (glass_stack.h), not the normal's sign: N is only turned to face
 * the ray. */
struct color render_trace(const struct scene *s, const struct render_settings *rs,
			  const struct ray *r, int level, struct ray_counts *counts)
{
	struct render_tree tree;
	struct color c;

	render_tree_init(&tree, s, rs, 0, NULL, NULL, counts);
	do
		c = render_trace_tree(s, rs, r, level, &tree);
	while (render_tree_again(&tree, c, 1));
	return c;
}

struct color render_trace_tree(const struct scene *s, const struct render_settings *rs,
			       const struct ray *r, int level, struct render_tree *tree)
{
	static const struct glass_stack outside = { 0, { NULL } };

	render_tree_ray(tree);
	return render_trace_in(s, rs, r, level, tree, &outside, 1.0);
}

/* Inline, so that render_trace_in keeps the point in registers as it did
 * before the packets needed it apart (3% more instructions on the course
 * example otherwise). */
SHADE_ALWAYS_INLINE
static inline void render_point_in(const struct ray *r, double t, const struct shape *hit,
				   struct render_point *h)
{
	h->hit = hit;
	h->t = t;
	h->p = ray_at(r, t);
	h->base = shape_color_at(hit, h->p);
	h->spec = shape_specular_color_at(hit, h->p, &h->spec_color);
	h->n = shape_normal(hit, h->p);
	h->dn = vec3_dot(r->dir, h->n);
	if (h->dn > 0.0) {
		h->n = vec3_neg(h->n);
		h->dn = -h->dn;
	}
	h->refl = vec3_add_scaled(r->dir, h->n, -2.0 * h->dn);
	h->eps = render_offset(h->p);
}

/* The sum at the ray's nearest hit, the point h shaded with the finish
 * m, with the rules broken (shade_rules.h; 0 on a render's path) and the
 * other floor fl (NULL: the scene's), the answers to its shadow rays that
 * pre has (NULL: each traced here) and the colour its reflection sees
 * where `reflected` has it (NULL: traced here).  Inline in its callers,
 * the point's values then stay in registers as they did before the
 * packets needed the sum apart from the search (a shared function cost
 * the course example 3% more instructions), and a render's rules, the
 * constant 0, leave no test behind. */
SHADE_ALWAYS_INLINE
static inline struct color render_shade_from(const struct scene *s,
					     const struct render_settings *rs, unsigned rules,
					     const struct shade_floor *fl, const struct ray *r,
					     int level, struct render_tree *tree,
					     const struct glass_stack *glass,
					     const struct render_point *hp, const struct material *m,
					     const struct render_shadows *pre,
					     const struct color *reflected_pre, double weight)
{
	struct ray_counts *counts = tree->counts;
	const struct shape *hit = hp->hit;
	const struct color *spec;
	struct color c;
	bool tir = false;
	struct vec3 through = { 0.0, 0.0, 0.0 };
	struct glass_stack beyond;

	spec = hp->spec ? &hp->spec_color : NULL;
	c = color_scale(hp->base, m->ka);
	c = color_add(c, render_direct_at(s, rules, fl, m, hp, spec, counts, pre));
	if (level < rs->recursion && m->kt > 0.0) {
		double eta;

		glass_stack_pass(glass, hit, &beyond, &eta);
		tir = !render_refract(r->dir, hp->n, hp->dn, eta, &through);
	}
	if (level < rs->recursion && (m->kr > 0.0 || tir)) {
		struct ray bounce;
		struct color reflected;
		double k = tir ? 1.0 : m->kr;

		if (reflected_pre && !tir) {
			if (counts)
				counts->reflection++;
			reflected = *reflected_pre;
		} else if (render_tree_cuts(tree, s, rs, weight * k, level + 1)) {
			reflected = color_make(0.0, 0.0, 0.0);
		} else {
			if (counts)
				counts->reflection++;
			render_bounce(hp, &bounce);
			if (rules & RT_RULE_UNIT_STARTS)
				bounce.origin = vec3_add_scaled(hp->p, hp->refl, 1.0);
			reflected = render_trace_on(s, rs, rules, fl, &bounce, level + 1, tree, glass,
						    weight * k);
		}
		c = color_add(c, color_scale(reflected, k));
	}
	if (level < rs->recursion && m->kt > 0.0 && !tir)
		c = color_add(c, render_transmit(s, rs, rules, fl, hp->p, through, m->kt, hp->eps, level,
						 tree, &beyond, weight));
	if (rules & RT_RULE_NEVER_CLAMP)
		return level == 1 ? shade_rules_wrap(c) : c;
	return rs->clamp == RT_CLAMP_LEVEL ? render_clamp(c) : c;
}

/* The colour ray r sees (see render_shade_from): black where it hits
 * nothing, or where the tree no longer takes it (the trace is stopping,
 * and the pixel is thrown away). */
SHADE_ALWAYS_INLINE
static inline struct color render_trace_with(const struct scene *s,
					     const struct render_settings *rs, unsigned rules,
					     const struct shade_floor *fl, const struct ray *r,
					     int level, struct render_tree *tree,
					     const struct glass_stack *glass, double weight)
{
	double t = INFINITY;
	const struct shape *hit;
	const struct material *m;
	struct render_point h;

	if (!render_tree_take(tree))
		return color_make(0.0, 0.0, 0.0);
	hit = fl ? shade_rules_intersect(s, fl, r, render_offset(r->origin), &t)
		 : accel_intersect(s->accel, r, render_offset(r->origin), &t);
	if (!hit)
		return color_make(0.0, 0.0, 0.0);
	render_point_in(r, t, hit, &h);
	m = rules || fl ? shade_rules_point(s, rules, fl, level, &h) : &hit->mat;
	return render_shade_from(s, rs, rules, fl, r, level, tree, glass, &h, m, NULL, NULL, weight);
}

/* A render's trace (the rules 0) and compare's (shade_rules.h), each
 * the one sum with its rules. */
static struct color render_trace_in(const struct scene *s, const struct render_settings *rs,
				   const struct ray *r, int level, struct render_tree *tree,
				   const struct glass_stack *glass, double weight)
{
	return render_trace_with(s, rs, 0, NULL, r, level, tree, glass, weight);
}

static struct color rules_trace_in(const struct scene *s, const struct render_settings *rs,
				   unsigned rules, const struct shade_floor *fl, const struct ray *r,
				   int level, struct render_tree *tree, const struct glass_stack *glass,
				   double weight)
{
	return render_trace_with(s, rs, rules, fl, r, level, tree, glass, weight);
}

struct color shade_rules_trace(const struct scene *s, const struct render_settings *rs,
			       unsigned rules, const struct ray *r, int level)
{
	return shade_rules_trace_floor(s, rs, rules, NULL, r, level);
}

struct color shade_rules_trace_floor(const struct scene *s, const struct render_settings *rs,
				     unsigned rules, const struct shade_floor *fl,
				     const struct ray *r, int level)
{
	static const struct glass_stack outside = { 0, { NULL } };
	struct render_tree tree;
	struct color c;

	render_tree_init(&tree, s, rs, 0, NULL, NULL, NULL);
	do {
		render_tree_ray(&tree);
		c = rules_trace_in(s, rs, rules, fl, r, level, &tree, &outside, 1.0);
	} while (render_tree_again(&tree, c, 1));
	return c;
}

void render_point_at(const struct ray *r, double t, const struct shape *hit,
		     struct render_point *h)
{
	render_point_in(r, t, hit, h);
}

struct color render_shade_point(const struct scene *s, const struct render_settings *rs,
				const struct ray *r, const struct render_point *h, int level,
				struct ray_counts *counts, const struct render_shadows *pre,
				const struct color *reflected)
{
	struct render_tree tree;

	render_tree_unbound(&tree, counts);
	return render_shade_point_tree(s, rs, r, h, level, &tree, 1.0, pre, reflected);
}

struct color render_shade_point_tree(const struct scene *s, const struct render_settings *rs,
				     const struct ray *r, const struct render_point *h, int level,
				     struct render_tree *tree, double weight,
				     const struct render_shadows *pre, const struct color *reflected)
{
	static const struct glass_stack outside = { 0, { NULL } };

	return render_shade_from(s, rs, 0, NULL, r, level, tree, &outside, h, &h->hit->mat, pre,
				 reflected, weight);
}
