/* The general quadric A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y
 * + I z + J = 0, clipped to a box on the axes whose extent is not zero.  Its
 * roots are tried nearest first and each must lie in the box, so a clipped
 * near root falls through to the far one. */
#include <math.h>

#include "alloc.h"
#include "diag.h"
#include "parse.h"
#include "pov.h"
#include "shape.h"
#include "shapes/solve.h"

struct quadric {
	struct shape base;
	double a, b, c, d, e, f, g, h, i, j;
	struct vec3 lo, hi;		/* the clip box, inclusive */
	bool clipped[3];
};

/* F(P) for the coefficients, with P = o + t dir substituted:
 * F = qa t^2 + qb t + qc. */
static void quadric_coefficients(const struct quadric *q, const struct ray *r,
				 double *qa, double *qb, double *qc)
{
	struct vec3 o = r->origin, d = r->dir;

	*qa = q->a * d.x * d.x + q->b * d.y * d.y + q->c * d.z * d.z +
	      q->d * d.x * d.y + q->e * d.x * d.z + q->f * d.y * d.z;
	*qb = 2.0 * (q->a * o.x * d.x + q->b * o.y * d.y + q->c * o.z * d.z) +
	      q->d * (o.x * d.y + o.y * d.x) + q->e * (o.x * d.z + o.z * d.x) +
	      q->f * (o.y * d.z + o.z * d.y) +
	      q->g * d.x + q->h * d.y + q->i * d.z;
	*qc = q->a * o.x * o.x + q->b * o.y * o.y + q->c * o.z * o.z +
	      q->d * o.x * o.y + q->e * o.x * o.z + q->f * o.y * o.z +
	      q->g * o.x + q->h * o.y + q->i * o.z + q->j;
}

static bool quadric_in_clip(const struct quadric *q, struct vec3 p)
{
	return (!q->clipped[0] || (p.x >= q->lo.x && p.x <= q->hi.x)) &&
	       (!q->clipped[1] || (p.y >= q->lo.y && p.y <= q->hi.y)) &&
	       (!q->clipped[2] || (p.z >= q->lo.z && p.z <= q->hi.z));
}

static bool quadric_intersect(const struct shape *s, const struct ray *r,
			      double t_min, double *t_max)
{
	const struct quadric *q = (const struct quadric *)s;
	double qa, qb, qc, roots[2];
	int n, k;

	quadric_coefficients(q, r, &qa, &qb, &qc);
	n = solve_quadratic(qa, qb, qc, roots);
	for (k = 0; k < n; k++) {
		double t = roots[k];
		if (t > t_min && t < *t_max && quadric_in_clip(q, ray_at(r, t))) {
			*t_max = t;
			return true;
		}
	}
	return false;
}

static struct vec3 quadric_normal(const struct shape *s, struct vec3 p)
{
	const struct quadric *q = (const struct quadric *)s;
	struct vec3 grad = vec3_make(2.0 * q->a * p.x + q->d * p.y + q->e * p.z + q->g,
				     2.0 * q->b * p.y + q->d * p.x + q->f * p.z + q->h,
				     2.0 * q->c * p.z + q->e * p.x + q->f * p.y + q->i);

	/* At a singular point (a cone's apex) any direction will do. */
	if (grad.x == 0.0 && grad.y == 0.0 && grad.z == 0.0)
		return vec3_make(0.0, 0.0, 1.0);
	return vec3_normalize(grad);
}

static bool quadric_bounds(const struct shape *s, struct aabb *out)
{
	const struct quadric *q = (const struct quadric *)s;

	if (!q->clipped[0] || !q->clipped[1] || !q->clipped[2])
		return false;
	out->min = q->lo;
	out->max = q->hi;
	return true;
}

static void quadric_write_clip(const struct quadric *q, FILE *out)
{
	static const char *const axis_name[3] = { "x", "y", "z" };
	int axis;

	if (!q->clipped[0] && !q->clipped[1] && !q->clipped[2])
		return;
	fputs("\n  clipped_by { intersection {", out);
	for (axis = 0; axis < 3; axis++) {
		if (!q->clipped[axis])
			continue;
		fprintf(out, " plane { %s, ", axis_name[axis]);
		pov_write_number(out, vec3_component(q->hi, axis));
		fprintf(out, " } plane { -%s, ", axis_name[axis]);
		pov_write_number(out, -vec3_component(q->lo, axis));
		fputs(" }", out);
	}
	fputs(" } }", out);
}

static int quadric_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct quadric *q = (const struct quadric *)s;

	fputs("quadric { ", out);
	pov_write_vector(out, q->a, q->b, q->c);
	fputs(", ", out);
	pov_write_vector(out, q->d, q->e, q->f);
	fputs(", ", out);
	pov_write_vector(out, q->g, q->h, q->i);
	fputs(", ", out);
	pov_write_number(out, q->j);
	quadric_write_clip(q, out);
	fputs("\n  ", out);
	pov_write_texture(out, &s->mat, opt);
	fputs("\n}\n", out);
	return ferror(out) ? -RT_E_IO : 0;
}

static void quadric_destroy(struct shape *s)
{
	rt_free(s);
}

static int quadric_parse(struct parser *p, struct shape **out);

static void quadric_geometry(const struct shape *s, struct shape_geometry *out)
{
	const struct quadric *q = (const struct quadric *)s;
	const double coef[10] = { q->a, q->b, q->c, q->d, q->e, q->f, q->g, q->h, q->i, q->j };
	int k;

	out->kind = RT_SHAPE_QUADRIC;
	for (k = 0; k < 10; k++)
		out->u.quadric.coef[k] = coef[k];
	out->u.quadric.lo = q->lo;
	out->u.quadric.hi = q->hi;
	for (k = 0; k < 3; k++)
		out->u.quadric.clipped[k] = q->clipped[k];
}

const struct shape_ops quadric_ops = {
	.keyword = "general",
	.parse = quadric_parse,
	.intersect = quadric_intersect,
	.normal = quadric_normal,
	.export_pov = quadric_export_pov,
	.destroy = quadric_destroy,
	.bounds = quadric_bounds,
	.geometry = quadric_geometry,
};

struct shape *quadric_create(const double coef[10], struct vec3 clip_ref,
			     struct vec3 clip_extent, const struct material *m)
{
	struct quadric *q = rt_malloc(sizeof(*q));

	if (!q)
		return NULL;
	q->base.ops = &quadric_ops;
	q->base.mat = *m;
	q->a = coef[0];
	q->b = coef[1];
	q->c = coef[2];
	q->d = coef[3];
	q->e = coef[4];
	q->f = coef[5];
	q->g = coef[6];
	q->h = coef[7];
	q->i = coef[8];
	q->j = coef[9];
	q->lo = clip_ref;
	q->hi = vec3_add(clip_ref, clip_extent);
	q->clipped[0] = clip_extent.x != 0.0;
	q->clipped[1] = clip_extent.y != 0.0;
	q->clipped[2] = clip_extent.z != 0.0;
	return &q->base;
}

static int quadric_parse(struct parser *p, struct shape **out)
{
	static const char *const extent_name[3] = {
		"clip box length", "clip box width", "clip box height"
	};
	double coef[10], extent[3];
	struct vec3 ref;
	struct material m;
	bool any = false;
	int rc, k;

	*out = NULL;
	for (k = 0; k < 10; k++) {
		if ((rc = parser_number(p, "quadric coefficient", &coef[k])) < 0)
			return rc;
		any = any || coef[k] != 0.0;
	}
	if (!any)
		return parser_fail(p, RT_E_RANGE, "all ten quadric coefficients are zero");
	if ((rc = parser_vec3(p, "clip box reference point", &ref)) < 0)
		return rc;
	for (k = 0; k < 3; k++) {
		if ((rc = parser_number(p, extent_name[k], &extent[k])) < 0)
			return rc;
		if (extent[k] < 0.0)
			return parser_fail(p, RT_E_RANGE, "%s must be >= 0 (0 means no clipping), found %g",
					   extent_name[k], extent[k]);
		if (!isfinite(vec3_component(ref, k) + extent[k]))
			return parser_fail(p, RT_E_RANGE, "clip box is too large");
	}
	if ((rc = parser_material(p, &m)) < 0)
		return rc;
	*out = quadric_create(coef, ref, vec3_make(extent[0], extent[1], extent[2]), &m);
	return *out ? 0 : parser_fail(p, RT_E_NOMEM, "out of memory");
}
