/* The hooks by which each rule of shade_rules.h bends the one Whitted sum
 * of shade.c: the renders `whitted compare` needs to name a student's
 * mistake.  The sum calls them only where a rule is broken or another
 * floor given, so that an ordinary render, whose rules are the constant
 * 0, never reaches them. */
#include <math.h>
#include <string.h>

#include "accel/accel.h"
#include "render/shade_rules.h"
#include "scene/scene_impl.h"

bool shade_rules_shadowed(const struct scene *s, unsigned rules, struct vec3 p, struct vec3 l,
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

bool shade_rules_spot_lights(const struct light *lt, unsigned rules, struct vec3 l)
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

double shade_rules_diffuse(const struct material *m, unsigned rules, double nl)
{
	if (rules & RT_RULE_SIGNED_DIFFUSE)
		return m->kd * nl;
	return nl > 0.0 ? m->kd * nl : (rules & RT_RULE_TWO_SIDED) ? -m->kd * nl : 0.0;
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

struct color shade_rules_wrap(struct color c)
{
	return color_make(rules_wrap(c.r), rules_wrap(c.g), rules_wrap(c.b));
}

/* Whether the other floor fl covers the point p of the plane z = 0. */
static bool rules_floor_covers(const struct shade_floor *fl, struct vec3 p)
{
	double x = p.x - fl->cx, y = p.y - fl->cy;

	return fl->half == INFINITY || (x >= -fl->half && x < fl->half && y >= -fl->half && y < fl->half);
}

const struct shape *shade_rules_intersect(const struct scene *s, const struct shade_floor *fl,
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

const struct material *shade_rules_point(const struct scene *s, unsigned rules,
					 const struct shade_floor *fl, int level,
					 struct render_point *h)
{
	const struct shape *hit = h->hit;

	if (fl && fl->moved && hit == s->floor) {
		double i = floor((h->p.x - fl->ox) / fl->cell), j = floor((h->p.y - fl->oy) / fl->cell);
		double white = fmod(fabs(i + j), 2.0) == 0.0 ? 1.0 : 0.0;
		h->base = color_make(white, white, white);
		h->spec = false;
	}
	if ((rules & RT_RULE_FLOOR_SWAPPED) && strcmp(hit->ops->keyword, "floor") == 0) {
		/* The cells' colours swapped: white for black and back (a texel
		 * belongs to its cell and is not swapped, only the highlight). */
		struct color *c = h->spec ? &h->spec_color : &h->base;
		*c = color_make(1.0 - c->r, 1.0 - c->g, 1.0 - c->b);
	}
	if (fl && fl->own_finish && hit == s->floor)
		return level > 1 && fl->own_deeper ? &fl->deeper : &fl->finish;
	return &hit->mat;
}
