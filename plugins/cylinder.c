/* The cylinder plugin: a capped cylinder between two points,
 *     cylinder
 *     X1 Y1 Z1        the centre of one cap
 *     X2 Y2 Z2        the centre of the other
 *     RADIUS
 *     R G B / KA KD KS KR / SHININESS
 * the solid x with |x - A - ((x - A).u) u| <= r and 0 <= (x - A).u <= L,
 * u = (B - A) / L.  Its surface is the side (a quadratic in t, solved
 * without cancellation) and two discs; exported as POV-Ray's cylinder,
 * which is capped too. */
#include <math.h>

#include "whitted/mesh.h"
#include "whitted/plugin.h"
#include "whitted/pov.h"

WHITTED_PLUGIN_ABI_SYMBOL;

static const struct whitted_plugin_host *host;

struct cylinder {
	struct shape base;
	struct vec3 a, b, axis;	/* axis: unit, from a to b */
	double length, radius;
};

/* The nearest t in (t_min, t_max) on the side or a cap. */
static bool cylinder_hit(const struct cylinder *c, const struct ray *r, double t_min,
			 double t_max, double *t)
{
	struct vec3 oc = vec3_sub(r->origin, c->a);
	double dd = vec3_dot(r->dir, c->axis), od = vec3_dot(oc, c->axis);
	/* The components across the axis. */
	struct vec3 dp = vec3_add_scaled(r->dir, c->axis, -dd);
	struct vec3 op = vec3_add_scaled(oc, c->axis, -od);
	double roots[2], best = t_max;
	int n, i;
	bool hit = false;

	n = host->solve_quadratic(vec3_dot(dp, dp), 2.0 * vec3_dot(dp, op),
				  vec3_dot(op, op) - c->radius * c->radius, roots);
	for (i = 0; i < n; i++) {
		double h = od + roots[i] * dd;

		if (roots[i] > t_min && roots[i] < best && h >= 0.0 && h <= c->length) {
			best = roots[i];
			hit = true;
		}
	}
	if (dd != 0.0) {
		for (i = 0; i < 2; i++) {
			double tc = ((i ? c->length : 0.0) - od) / dd;
			struct vec3 q = vec3_add_scaled(op, dp, tc);

			if (tc > t_min && tc < best && vec3_dot(q, q) <= c->radius * c->radius) {
				best = tc;
				hit = true;
			}
		}
	}
	if (hit)
		*t = best;
	return hit;
}

static bool cylinder_intersect(const struct shape *s, const struct ray *r, double t_min,
			       double *t_max)
{
	double t;

	if (!cylinder_hit((const struct cylinder *)s, r, t_min, *t_max, &t))
		return false;
	*t_max = t;
	return true;
}

/* The side's radial direction, or a cap's axis, whichever surface p is
 * nearest. */
static struct vec3 cylinder_normal(const struct shape *s, struct vec3 p)
{
	const struct cylinder *c = (const struct cylinder *)s;
	struct vec3 ap = vec3_sub(p, c->a);
	double h = vec3_dot(ap, c->axis);
	struct vec3 radial = vec3_add_scaled(ap, c->axis, -h);
	double side = fabs(vec3_length(radial) - c->radius);

	if (fabs(h) < side && fabs(h) <= fabs(h - c->length))
		return vec3_neg(c->axis);
	if (fabs(h - c->length) < side)
		return c->axis;
	radial = vec3_normalize(radial);
	return vec3_is_finite(radial) ? radial : c->axis;
}

/* Each cap's disc spans r sqrt(1 - u_k^2) along axis k. */
static bool cylinder_bounds(const struct shape *s, struct aabb *out)
{
	const struct cylinder *c = (const struct cylinder *)s;
	struct vec3 e = vec3_make(c->radius * sqrt(fmax(0.0, 1.0 - c->axis.x * c->axis.x)),
				  c->radius * sqrt(fmax(0.0, 1.0 - c->axis.y * c->axis.y)),
				  c->radius * sqrt(fmax(0.0, 1.0 - c->axis.z * c->axis.z)));

	out->min = vec3_sub(vec3_min(c->a, c->b), e);
	out->max = vec3_add(vec3_max(c->a, c->b), e);
	return true;
}

static int cylinder_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct cylinder *c = (const struct cylinder *)s;

	fputs("cylinder { ", out);
	host->pov_vector(out, c->a.x, c->a.y, c->a.z);
	fputs(", ", out);
	host->pov_vector(out, c->b.x, c->b.y, c->b.z);
	fputs(", ", out);
	host->pov_number(out, c->radius);
	fputs("\n  ", out);
	host->pov_texture(out, &s->mat, opt);
	fputs("\n}\n", out);
	return ferror(out) ? -RT_E_IO : 0;
}

/* opt->segments quads round the side and two fans for the caps. */
static int cylinder_tessellate(const struct shape *s, const struct mesh_options *opt,
			       struct mesh *out)
{
	const struct cylinder *c = (const struct cylinder *)s;
	struct vec3 u = fabs(c->axis.x) < 0.9 ? vec3_make(1, 0, 0) : vec3_make(0, 1, 0), w;
	int n = opt->segments < 8 ? 8 : opt->segments, i, rc;

	u = vec3_normalize(vec3_cross(c->axis, u));
	w = vec3_cross(c->axis, u);
	for (i = 0; i < n; i++) {
		double a0 = 6.283185307179586 * i / n, a1 = 6.283185307179586 * (i + 1) / n;
		struct vec3 r0 = vec3_add(vec3_scale(u, cos(a0)), vec3_scale(w, sin(a0)));
		struct vec3 r1 = vec3_add(vec3_scale(u, cos(a1)), vec3_scale(w, sin(a1)));
		struct vec3 p0 = vec3_add_scaled(c->a, r0, c->radius);
		struct vec3 p1 = vec3_add_scaled(c->a, r1, c->radius);
		struct vec3 q0 = vec3_add_scaled(c->b, r0, c->radius);
		struct vec3 q1 = vec3_add_scaled(c->b, r1, c->radius);
		const struct vec3 s1[3] = { p0, p1, q1 }, n1[3] = { r0, r1, r1 };
		const struct vec3 s2[3] = { p0, q1, q0 }, n2[3] = { r0, r1, r0 };
		const struct vec3 c0[3] = { c->a, p1, p0 };
		const struct vec3 c1[3] = { c->b, q0, q1 };
		const struct vec3 m0[3] = { vec3_neg(c->axis), vec3_neg(c->axis), vec3_neg(c->axis) };
		const struct vec3 m1[3] = { c->axis, c->axis, c->axis };

		if ((rc = host->mesh_triangle(out, s1, n1)) < 0 ||
		    (rc = host->mesh_triangle(out, s2, n2)) < 0 ||
		    (rc = host->mesh_triangle(out, c0, m0)) < 0 ||
		    (rc = host->mesh_triangle(out, c1, m1)) < 0)
			return rc;
	}
	return 0;
}

static void cylinder_destroy(struct shape *s)
{
	host->free(s);
}

static const struct shape_ops cylinder_ops;

static int cylinder_parse(struct parser *p, struct shape **out)
{
	struct cylinder *c;
	struct vec3 a, b, d;
	double radius, length;
	int rc;

	*out = NULL;
	if ((rc = host->vec3(p, "cylinder end", &a)) < 0 ||
	    (rc = host->vec3(p, "cylinder end", &b)) < 0)
		return rc;
	d = vec3_sub(b, a);
	length = vec3_length(d);
	if (!isfinite(length))
		return host->fail(p, RT_E_RANGE, "cylinder ends are too far apart");
	if (length == 0.0)
		return host->fail(p, RT_E_RANGE, "cylinder ends are the same point (it has no axis)");
	if ((rc = host->number(p, "cylinder radius", &radius)) < 0)
		return rc;
	/* The side is solved with r^2: a radius whose square underflows to 0
	 * (or overflows) would be a line (or everything). */
	if (!(radius > 0.0) || !(radius * radius > 0.0) || !isfinite(radius * radius))
		return host->fail(p, RT_E_RANGE,
				  "cylinder radius must be > 0, with a square that is finite and not 0 (about 1e-154 to 1e154), found %g",
				  radius);
	c = (struct cylinder *)whitted_plugin_new_shape(host, p, &cylinder_ops, sizeof(*c), &rc);
	if (!c)
		return rc;
	c->a = a;
	c->b = b;
	c->axis = vec3_scale(d, 1.0 / length);
	c->length = length;
	c->radius = radius;
	*out = &c->base;
	return 0;
}

static const struct shape_ops cylinder_ops = {
	.keyword = "cylinder",
	.parse = cylinder_parse,
	.intersect = cylinder_intersect,
	.normal = cylinder_normal,
	.export_pov = cylinder_export_pov,
	.destroy = cylinder_destroy,
	.bounds = cylinder_bounds,
	.tessellate = cylinder_tessellate,
	/* Glass through it is exact: the capped cylinder bounds a solid. */
	.closed = whitted_plugin_closed_always,
};

static const struct shape_ops *const cylinder_shapes[] = { &cylinder_ops, NULL };

int whitted_plugin_init(const struct whitted_plugin_host *h)
{
	static const struct whitted_plugin plugin = { "cylinder", "1.0", cylinder_shapes };

	return whitted_plugin_start(h, &host, &plugin);
}
