/* The Whitted sum of scene-format.md, as render_trace computes it, with
 * each rule of shade_rules.h breakable: the renders `whitted compare` needs
 * to name a student's mistake.  It repeats shade.c's formulas operation for
 * operation (so that an unbroken rule gives the same bits) rather than
 * adding tests to the per-ray path of every render; its ray tree is bound
 * as render_trace's (ray_tree.h), ray for ray. */
#include <math.h>
#include <string.h>

#include "accel/accel.h"
#include "render/glass_stack.h"
#include "render/ray_tree.h"
#include "render/shade_math.h"
#include "render/shade_rules.h"
#include "scene/scene_impl.h"

static bool rules_shadowed(const struct scene *s, unsigned rules, struct vec3 p, struct vec3 l,
			   double dist, double eps)
{
	struct ray shadow;

	if (rules & RT_RULE_NO_SHADOWS)
		return false;
	shadow.dir = l;
	if (rules & RT_RULE_UNIT_STARTS) {
		/* The literal start is one unit along L: a blocker within that
		 * unit is missed, and the light's distance is measured from P. */
		shadow.origin = vec3_add_scaled(p, l, 1.0);
		return dist > 1.0 && accel_occluded(s->accel, &shadow, eps, dist - 1.0);
	}
	shadow.origin = vec3_add_scaled(p, l, eps);
	return accel_occluded(s->accel, &shadow, eps, dist - eps);
}

/* Whether spotlight lt lights along l (unit, from P to the light) as the
 * rules' cone says: the contract's test, cos(angle) >= cos(cutoff), when
 * no spot rule is broken. */
static bool rules_spot_lights(const struct light *lt, unsigned rules, struct vec3 l)
{
	const double pi = 3.14159265358979323846;
	double c = -vec3_dot(l, lt->axis), angle;

	switch (rules & RT_RULE_SPOT_MASK) {
	case RT_RULE_SPOT_UNLIT:
		return false;
	case RT_RULE_SPOT_NO_CONE:
		return true;
	case RT_RULE_SPOT_COS_DEGREES:
		return c >= cos(lt->cutoff_deg);
	case RT_RULE_SPOT_FULL_ANGLE:
		return c >= cos(lt->cutoff_deg * pi / 360.0);
	case RT_RULE_SPOT_PI_MACRO:
		/* acos(c) * 180 / PI with PI `2*acos(0.0)`: acos(c) * 90 * pi / 2. */
		angle = acos(c < -1.0 ? -1.0 : c > 1.0 ? 1.0 : c) * 180.0 / 2.0 * (pi / 2.0);
		return angle <= lt->cutoff_deg;
	default:
		return c >= lt->cos_cutoff;
	}
}

/* spec: NULL, or the highlight's colour where it is not the surface's (a
 * textured floor's cell under its texel), as in shade.c. */
static struct color rules_direct(const struct scene *s, unsigned rules, const struct material *m,
				 struct color base, const struct color *spec, struct vec3 p,
				 struct vec3 n, struct vec3 refl, double eps)
{
	struct color c = color_make(0.0, 0.0, 0.0);
	size_t i;

	for (i = 0; i < s->n_lights; i++) {
		const struct light *lt = &s->lights[i];
		struct vec3 to_light = vec3_sub(lt->pos, p), l;
		double dist = vec3_length(to_light), nl, rl, diffuse, specular = 0.0, a = 1.0;

		if (!(dist > eps))
			continue;
		l = vec3_scale(to_light, 1.0 / dist);
		nl = vec3_dot(n, l);
		if (nl <= 0.0 && !(rules & RT_RULE_LIGHT_BEHIND))
			continue;
		if (lt->spot && !rules_spot_lights(lt, rules, l))
			continue;
		if (rules_shadowed(s, rules, p, l, dist, eps))
			continue;
		diffuse = nl > 0.0 ? m->kd * nl : (rules & RT_RULE_TWO_SIDED) ? -m->kd * nl : 0.0;
		if (rules & RT_RULE_SIGNED_DIFFUSE)
			diffuse = m->kd * nl;
		rl = vec3_dot(refl, l);
		if (rl > 0.0)
			specular = m->ks * render_specular_power(rl, m->shininess);
		if (lt->falloff > 0.0)
			a = exp(-dist * dist * lt->falloff);
		if (rules & RT_RULE_WHITE_SPECULAR) {
			c = color_add(c, color_scale(color_mul(lt->color, base), diffuse * a));
			c = color_add(c, color_scale(lt->color, specular * a));
		} else if (spec) {
			/* shade.c's render_light_split, scaled after as there. */
			struct color term = color_add(color_scale(color_mul(lt->color, base), diffuse),
						      color_scale(color_mul(lt->color, *spec), specular));
			c = color_add(c, lt->falloff > 0.0 ? color_scale(term, a) : term);
		} else if (lt->falloff > 0.0) {
			c = color_add(c, color_scale(color_mul(lt->color, base),
						     (diffuse + specular) * a));
		} else {
			c = color_add(c, color_scale(color_mul(lt->color, base), diffuse + specular));
		}
	}
	return c;
}

/* The low 8 bits of round(255 v), over 255: what a byte cast of an
 * unclamped channel stores. */
static double rules_wrap(double v)
{
	double b = floor(255.0 * v + 0.5);

	if (!(b > 0.0))
		return 0.0;
	return fmod(b, 256.0) / 255.0;
}

static struct color rules_trace_in(const struct scene *s, const struct render_settings *rs,
				   unsigned rules, const struct shade_floor *fl, const struct ray *r,
				   int level, struct render_tree *tree, const struct glass_stack *glass,
				   double weight);

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

/* Whether the other floor fl covers the point p of the plane z = 0. */
static bool rules_floor_covers(const struct shade_floor *fl, struct vec3 p)
{
	double x = p.x - fl->cx, y = p.y - fl->cy;

	return fl->half == INFINITY || (x >= -fl->half && x < fl->half && y >= -fl->half && y < fl->half);
}

/* The nearest hit with the other floor fl in place of the scene's: the
 * scene's floor where fl covers its point, else what lies beyond it; and
 * fl's plane where it covers a point nearer than any other hit. */
static const struct shape *rules_intersect(const struct scene *s, const struct shade_floor *fl,
					   const struct ray *r, double eps, double *t)
{
	const struct shape *hit = accel_intersect(s->accel, r, eps, t);
	double tf;

	if (!fl || !fl->moved || !s->floor)
		return hit;
	while (hit == s->floor && !rules_floor_covers(fl, ray_at(r, *t))) {
		double t_min = *t;
		*t = INFINITY;
		hit = accel_intersect(s->accel, r, t_min, t);
	}
	if (hit != s->floor && r->dir.z != 0.0) {
		tf = -r->origin.z / r->dir.z;
		if (tf > eps && tf < *t && rules_floor_covers(fl, ray_at(r, tf))) {
			*t = tf;
			hit = s->floor;
		}
	}
	return hit;
}

/* shade.c's render_trace_in, with the rules.
 * Long: render_trace's sum with each rule's hook where the rule bends it, in
 * render_trace's order, so that the two read side by side. */
static struct color rules_trace_in(const struct scene *s, const struct render_settings *rs,
				   unsigned rules, const struct shade_floor *fl, const struct ray *r,
				   int level, struct render_tree *tree, const struct glass_stack *glass,
				   double weight)
{
	double t = INFINITY, eps = render_offset(r->origin);
	const struct shape *hit;
	const struct material *m;
	struct vec3 p, n, refl, through = { 0.0, 0.0, 0.0 };
	struct color base, c, spec_color;
	const struct color *spec = NULL;
	bool tir = false;
	double dn, start;
	struct glass_stack beyond;

	if (!render_tree_take(tree))
		return color_make(0.0, 0.0, 0.0);
	hit = rules_intersect(s, fl, r, eps, &t);
	if (!hit)
		return color_make(0.0, 0.0, 0.0);
	m = &hit->mat;
	if (fl && fl->own_finish && hit == s->floor)
		m = level > 1 && fl->own_deeper ? &fl->deeper : &fl->finish;
	p = ray_at(r, t);
	base = shape_color_at(hit, p);
	if (shape_specular_color_at(hit, p, &spec_color))
		spec = &spec_color;
	if (fl && fl->moved && hit == s->floor) {
		double i = floor((p.x - fl->ox) / fl->cell), j = floor((p.y - fl->oy) / fl->cell);
		double white = fmod(fabs(i + j), 2.0) == 0.0 ? 1.0 : 0.0;
		base = color_make(white, white, white);
		spec = NULL;
	}
	if ((rules & RT_RULE_FLOOR_SWAPPED) && strcmp(hit->ops->keyword, "floor") == 0) {
		/* The cells' colours swapped: white for black and back (a texel
		 * belongs to its cell and is not swapped, only the highlight). */
		if (spec)
			spec_color = color_make(1.0 - spec_color.r, 1.0 - spec_color.g, 1.0 - spec_color.b);
		else
			base = color_make(1.0 - base.r, 1.0 - base.g, 1.0 - base.b);
	}
	c = color_scale(base, m->ka);
	n = shape_normal(hit, p);
	dn = vec3_dot(r->dir, n);
	if (dn > 0.0) {
		n = vec3_neg(n);
		dn = -dn;
	}
	refl = vec3_add_scaled(r->dir, n, -2.0 * dn);
	eps = render_offset(p);
	c = color_add(c, rules_direct(s, rules, m, base, spec, p, n, refl, eps));
	start = (rules & RT_RULE_UNIT_STARTS) ? 1.0 : eps;
	if (level < rs->recursion && m->kt > 0.0) {
		double eta;

		glass_stack_pass(glass, hit, &beyond, &eta);
		tir = !render_refract(r->dir, n, dn, eta, &through);
	}
	if (level < rs->recursion && (m->kr > 0.0 || tir)) {
		struct ray bounce;
		double k = tir ? 1.0 : m->kr;
		struct color seen = color_make(0.0, 0.0, 0.0);

		bounce.origin = vec3_add_scaled(p, refl, start);
		bounce.dir = refl;
		if (!render_tree_cuts(tree, s, rs, weight * k, level + 1))
			seen = rules_trace_in(s, rs, rules, fl, &bounce, level + 1, tree, glass, weight * k);
		c = color_add(c, color_scale(seen, k));
	}
	if (level < rs->recursion && m->kt > 0.0 && !tir &&
	    !render_tree_cuts(tree, s, rs, weight * m->kt, level + 1)) {
		struct ray ray_through;

		ray_through.origin = vec3_add_scaled(p, through, eps);
		ray_through.dir = through;
		c = color_add(c, color_scale(rules_trace_in(s, rs, rules, fl, &ray_through, level + 1,
							    tree, &beyond, weight * m->kt),
					     m->kt));
	}
	if (rules & RT_RULE_NEVER_CLAMP) {
		if (level == 1)
			c = color_make(rules_wrap(c.r), rules_wrap(c.g), rules_wrap(c.b));
		return c;
	}
	return rs->clamp == RT_CLAMP_LEVEL ? color_clamp(c) : c;
}
