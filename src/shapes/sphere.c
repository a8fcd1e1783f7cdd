/* The sphere: |P - centre| = radius. */
#include <math.h>

#include "alloc.h"
#include "diag.h"
#include "parse.h"
#include "pov.h"
#include "shape.h"
#include "shapes/solve.h"

struct sphere {
	struct shape base;
	struct vec3 centre;
	double radius, radius_sq, inv_radius;
};

static bool sphere_intersect(const struct shape *s, const struct ray *r,
			     double t_min, double *t_max)
{
	const struct sphere *sp = (const struct sphere *)s;
	double t;

	if (!solve_ray_sphere(r, sp->centre, sp->radius_sq, t_min, *t_max, &t))
		return false;
	*t_max = t;
	return true;
}

static struct vec3 sphere_normal(const struct shape *s, struct vec3 p)
{
	const struct sphere *sp = (const struct sphere *)s;

	return vec3_scale(vec3_sub(p, sp->centre), sp->inv_radius);
}

static bool sphere_bounds(const struct shape *s, struct aabb *out)
{
	const struct sphere *sp = (const struct sphere *)s;
	struct vec3 r = vec3_make(sp->radius, sp->radius, sp->radius);

	out->min = vec3_sub(sp->centre, r);
	out->max = vec3_add(sp->centre, r);
	return true;
}

static int sphere_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct sphere *sp = (const struct sphere *)s;

	fputs("sphere { ", out);
	pov_write_vector(out, sp->centre.x, sp->centre.y, sp->centre.z);
	fputs(", ", out);
	pov_write_number(out, sp->radius);
	fputs("\n  ", out);
	pov_write_texture(out, &s->mat, opt);
	fputs("\n}\n", out);
	return ferror(out) ? -RT_E_IO : 0;
}

static void sphere_destroy(struct shape *s)
{
	rt_free(s);
}

static int sphere_parse(struct parser *p, struct shape **out);

static void sphere_geometry(const struct shape *s, struct shape_geometry *out)
{
	const struct sphere *sp = (const struct sphere *)s;

	out->kind = RT_SHAPE_SPHERE;
	out->u.sphere.centre = sp->centre;
	out->u.sphere.radius = sp->radius;
}

const struct shape_ops sphere_ops = {
	.keyword = "sphere",
	.parse = sphere_parse,
	.intersect = sphere_intersect,
	.normal = sphere_normal,
	.export_pov = sphere_export_pov,
	.destroy = sphere_destroy,
	.bounds = sphere_bounds,
	.geometry = sphere_geometry,
};

struct shape *sphere_create(struct vec3 centre, double radius, const struct material *m)
{
	struct sphere *sp = rt_malloc(sizeof(*sp));

	if (!sp)
		return NULL;
	sp->base.ops = &sphere_ops;
	sp->base.mat = *m;
	sp->centre = centre;
	sp->radius = radius;
	sp->radius_sq = radius * radius;
	sp->inv_radius = 1.0 / radius;
	return &sp->base;
}

static int sphere_parse(struct parser *p, struct shape **out)
{
	struct material m;
	struct vec3 centre;
	double radius;
	int rc;

	*out = NULL;
	if ((rc = parser_vec3(p, "sphere centre", &centre)) < 0)
		return rc;
	if ((rc = parser_number(p, "sphere radius", &radius)) < 0)
		return rc;
	if (!(radius > 0.0))
		return parser_fail(p, RT_E_RANGE, "sphere radius must be > 0, found %g", radius);
	if (radius > 1e150)
		return parser_fail(p, RT_E_RANGE, "sphere radius is too large (%g)", radius);
	if ((rc = parser_material(p, &m)) < 0)
		return rc;
	*out = sphere_create(centre, radius, &m);
	return *out ? 0 : parser_fail(p, RT_E_NOMEM, "out of memory");
}
