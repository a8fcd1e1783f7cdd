/* The triangle, hit from both sides (Moller-Trumbore). */
#include "alloc.h"
#include "diag.h"
#include "parse.h"
#include "pov.h"
#include "shape.h"
#include "shapes/solve.h"

struct triangle {
	struct shape base;
	struct vec3 v0, e1, e2;		/* e1 = v1 - v0, e2 = v2 - v0 */
	struct vec3 normal;		/* unit e1 x e2; zero when degenerate */
};

static bool triangle_intersect(const struct shape *s, const struct ray *r,
			       double t_min, double *t_max)
{
	const struct triangle *tr = (const struct triangle *)s;
	double t;

	if (!solve_ray_triangle(r, tr->v0, tr->e1, tr->e2, t_min, *t_max, &t))
		return false;
	*t_max = t;
	return true;
}

static struct vec3 triangle_normal(const struct shape *s, struct vec3 p)
{
	(void)p;
	return ((const struct triangle *)s)->normal;
}

static bool triangle_bounds(const struct shape *s, struct aabb *out)
{
	const struct triangle *tr = (const struct triangle *)s;
	struct vec3 v1 = vec3_add(tr->v0, tr->e1), v2 = vec3_add(tr->v0, tr->e2);

	out->min = vec3_min(tr->v0, vec3_min(v1, v2));
	out->max = vec3_max(tr->v0, vec3_max(v1, v2));
	return true;
}

static const char *triangle_degenerate(const struct shape *s)
{
	const struct triangle *tr = (const struct triangle *)s;

	if (tr->normal.x == 0.0 && tr->normal.y == 0.0 && tr->normal.z == 0.0)
		return "is degenerate (its vertices are collinear) and will not be visible";
	return NULL;
}

static int triangle_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct triangle *tr = (const struct triangle *)s;
	struct vec3 v1 = vec3_add(tr->v0, tr->e1), v2 = vec3_add(tr->v0, tr->e2);

	if (triangle_degenerate(s)) {
		fputs("// a degenerate triangle, invisible in whitted and POV-Ray alike\n", out);
		return ferror(out) ? -RT_E_IO : 0;
	}
	fputs("triangle { ", out);
	pov_write_vector(out, tr->v0.x, tr->v0.y, tr->v0.z);
	fputs(", ", out);
	pov_write_vector(out, v1.x, v1.y, v1.z);
	fputs(", ", out);
	pov_write_vector(out, v2.x, v2.y, v2.z);
	fputs("\n  ", out);
	pov_write_texture(out, &s->mat, opt);
	fputs("\n}\n", out);
	return ferror(out) ? -RT_E_IO : 0;
}

static void triangle_destroy(struct shape *s)
{
	rt_free(s);
}

static int triangle_parse(struct parser *p, struct shape **out);

static void triangle_geometry(const struct shape *s, struct shape_geometry *out)
{
	const struct triangle *tr = (const struct triangle *)s;

	out->kind = RT_SHAPE_TRIANGLE;
	out->u.triangle.v[0] = tr->v0;
	out->u.triangle.v[1] = vec3_add(tr->v0, tr->e1);
	out->u.triangle.v[2] = vec3_add(tr->v0, tr->e2);
}

const struct shape_ops triangle_ops = {
	.keyword = "triangle",
	.parse = triangle_parse,
	.intersect = triangle_intersect,
	.normal = triangle_normal,
	.export_pov = triangle_export_pov,
	.destroy = triangle_destroy,
	.bounds = triangle_bounds,
	.degenerate = triangle_degenerate,
	.geometry = triangle_geometry,
};

struct shape *triangle_create(struct vec3 a, struct vec3 b, struct vec3 c,
			      const struct material *m)
{
	struct triangle *tr = rt_malloc(sizeof(*tr));

	if (!tr)
		return NULL;
	tr->base.ops = &triangle_ops;
	tr->base.mat = *m;
	tr->v0 = a;
	tr->e1 = vec3_sub(b, a);
	tr->e2 = vec3_sub(c, a);
	tr->normal = vec3_normalize(vec3_cross(tr->e1, tr->e2));
	if (!vec3_is_finite(tr->normal))
		tr->normal = vec3_make(0.0, 0.0, 0.0);
	return &tr->base;
}

static int triangle_parse(struct parser *p, struct shape **out)
{
	struct vec3 v[3];
	struct material m;
	int rc, i;

	*out = NULL;
	for (i = 0; i < 3; i++)
		if ((rc = parser_vec3(p, "triangle vertex", &v[i])) < 0)
			return rc;
	for (i = 0; i < 3; i++)
		if (!vec3_is_finite(vec3_sub(v[i], v[(i + 1) % 3])))
			return parser_fail(p, RT_E_RANGE, "triangle vertices are too far apart");
	if ((rc = parser_material(p, &m)) < 0)
		return rc;
	*out = triangle_create(v[0], v[1], v[2], &m);
	return *out ? 0 : parser_fail(p, RT_E_NOMEM, "out of memory");
}
