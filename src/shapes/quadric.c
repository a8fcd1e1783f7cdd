/* The general quadric A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y
 * + I z + J = 0, clipped to a box on the axes whose extent is not zero.  Its
 * roots are tried nearest first and each must lie in the box, so a clipped
 * near root falls through to the far one.  F and its gradient are written
 * once, for the roots, the normal and the mesh alike. */
#include <math.h>

#include "whitted/diag.h"
#include "whitted/mesh.h"
#include "whitted/parser.h"
#include "whitted/pov.h"
#include "whitted/scene.h"
#include "shapes/shapes.h"
#include "whitted/shape.h"
#include "shapes/solve.h"

struct quadric {
	struct shape base;
	double a, b, c, d, e, f, g, h, i, j;
	struct vec3 lo, hi;		/* the clip box, inclusive */
	bool clipped[3];
};

/* F(p) = A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J:
 * the one place the surface's function is written. */
static double quadric_value(const struct quadric *q, struct vec3 p)
{
	return q->a * p.x * p.x + q->b * p.y * p.y + q->c * p.z * p.z +
	       q->d * p.x * p.y + q->e * p.x * p.z + q->f * p.y * p.z +
	       q->g * p.x + q->h * p.y + q->i * p.z + q->j;
}

/* The gradient of F: the normal, and the mesh's vertex normals. */
static struct vec3 quadric_gradient(const struct quadric *q, struct vec3 p)
{
	return vec3_make(2.0 * q->a * p.x + q->d * p.y + q->e * p.z + q->g,
			 2.0 * q->b * p.y + q->d * p.x + q->f * p.z + q->h,
			 2.0 * q->c * p.z + q->e * p.x + q->f * p.y + q->i);
}

/* F(P) for the coefficients, with P = o + t dir substituted:
 * F = qa t^2 + qb t + qc, where qc = F(o). */
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
	*qc = quadric_value(q, o);
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
	struct vec3 grad = quadric_gradient((const struct quadric *)s, p);

	/* At a singular point (a cone's apex) any direction will do. */
	if (grad.x == 0.0 && grad.y == 0.0 && grad.z == 0.0)
		return vec3_make(0.0, 0.0, 1.0);
	return vec3_normalize(grad);
}

/* The clip box on the clipped axes; the wrapper (or the caller) has set
 * the others. */
static bool quadric_bounds(const struct shape *s, struct aabb *out)
{
	const struct quadric *q = (const struct quadric *)s;

	if (q->clipped[0]) {
		out->min.x = q->lo.x;
		out->max.x = q->hi.x;
	}
	if (q->clipped[1]) {
		out->min.y = q->lo.y;
		out->max.y = q->hi.y;
	}
	if (q->clipped[2]) {
		out->min.z = q->lo.z;
		out->max.z = q->hi.z;
	}
	return q->clipped[0] && q->clipped[1] && q->clipped[2];
}

/* A whole ellipsoid: the quadratic part x^T M x (M symmetric, its off
 * diagonal D/2, E/2, F/2) definite, taken positive by the sign of A
 * (Sylvester: the leading minors > 0), F < 0 at the centre c = -M^-1 (G,
 * H, I) / 2 (a real ellipsoid, not a point or nothing), and on each
 * clipped axis the box holding its extent c_i +- sqrt(-F(c) (M^-1)_ii). */
static bool quadric_closed(const struct shape *s)
{
	const struct quadric *q = (const struct quadric *)s;
	double k = q->a > 0.0 ? 1.0 : -1.0;
	double a = k * q->a, b = k * q->b, c = k * q->c, d = k * q->d / 2.0,
	       e = k * q->e / 2.0, f = k * q->f / 2.0;
	double inv[3][3], det, lin[3] = { k * q->g, k * q->h, k * q->i }, ctr[3], fc;
	double lo[3] = { q->lo.x, q->lo.y, q->lo.z }, hi[3] = { q->hi.x, q->hi.y, q->hi.z };
	int i, j;

	if (q->a == 0.0)
		return false;
	/* The adjugate of M ((M^-1) det). */
	inv[0][0] = b * c - f * f;
	inv[0][1] = e * f - d * c;
	inv[0][2] = d * f - b * e;
	inv[1][1] = a * c - e * e;
	inv[1][2] = d * e - a * f;
	inv[2][2] = a * b - d * d;
	inv[1][0] = inv[0][1];
	inv[2][0] = inv[0][2];
	inv[2][1] = inv[1][2];
	det = a * inv[0][0] + d * inv[0][1] + e * inv[0][2];
	if (!(a > 0.0 && inv[2][2] > 0.0 && det > 0.0))
		return false;
	fc = k * q->j;
	for (i = 0; i < 3; i++) {
		ctr[i] = 0.0;
		for (j = 0; j < 3; j++)
			ctr[i] -= inv[i][j] * lin[j] / (2.0 * det);
		fc += lin[i] * ctr[i] / 2.0;
	}
	if (!(fc < 0.0) || !isfinite(fc))
		return false;
	for (i = 0; i < 3; i++) {
		double ext = sqrt(-fc * inv[i][i] / det);

		if (q->clipped[i] && !(lo[i] <= ctr[i] - ext && ctr[i] + ext <= hi[i]))
			return false;
	}
	return true;
}

static double quadric_field_value(const void *ctx, struct vec3 p)
{
	return quadric_value(ctx, p);
}

static struct vec3 quadric_field_gradient(const void *ctx, struct vec3 p)
{
	return quadric_gradient(ctx, p);
}

/* F = 0 sampled in the clip box, and in opt->around along the axes that
 * are not clipped, with 2 * segments cells along the longest side: marching
 * tetrahedra needs finer cells than a UV grid needs facets. */
static int quadric_tessellate(const struct shape *s, const struct mesh_options *opt,
			      struct mesh *out)
{
	const struct mesh_field field = { quadric_field_value, quadric_field_gradient, s };
	struct aabb box = opt->around;
	int cells[3];

	quadric_bounds(s, &box);
	mesh_grid_cells(box, 2 * opt->segments, cells);
	return mesh_implicit(out, &field, box, cells);
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
	/* POV-Ray's order: the squares, the cross terms, the linear terms. */
	const struct vec3 coef[3] = { { q->a, q->b, q->c }, { q->d, q->e, q->f },
				      { q->g, q->h, q->i } };

	shape_pov_begin(out, "quadric { ", coef, 3);
	fputs(", ", out);
	pov_write_number(out, q->j);
	quadric_write_clip(q, out);
	return shape_pov_finish(s, out, opt);
}

static int quadric_parse(struct parser *p, struct shape **out);

const struct shape_ops quadric_ops = {
	.keyword = "general",
	.dialects = RT_DIALECT_CLASSIC_FAMILY,
	.parse = quadric_parse,
	.intersect = quadric_intersect,
	.normal = quadric_normal,
	.export_pov = quadric_export_pov,
	.destroy = shape_destroy_block,
	.bounds = quadric_bounds,
	.tessellate = quadric_tessellate,
	.closed = quadric_closed,
};

struct shape *quadric_create(const double coef[10], struct vec3 clip_ref,
			     struct vec3 clip_extent, const struct material *m)
{
	struct quadric *q = shape_alloc(sizeof(*q), &quadric_ops, m);

	if (!q)
		return NULL;
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
