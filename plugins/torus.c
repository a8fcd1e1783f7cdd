/* The torus plugin: a ring torus,
 *     torus
 *     CX CY CZ        the centre
 *     AX AY AZ        the axis (any length but 0)
 *     MAJOR MINOR     the radius of the tube's centre circle, and the tube's
 *     R G B / KA KD KS KR / SHININESS
 * In the torus's own frame (centre at the origin, axis z) the surface is
 *     (|p|^2 + R^2 - r^2)^2 - 4 R^2 (px^2 + py^2) = 0,
 * and a ray p = o + s d (|d| = 1, o moved to the point of the line nearest
 * the centre, so that the coefficients stay small) meets it at the real
 * roots of a quartic in s.  The roots are isolated, not solved in closed
 * form (Ferrari's formulas lose every digit where a ray grazes the tube):
 * the roots of the derivative, found the same way, cut the interval
 * where the ray is inside the bounding sphere into pieces on which the
 * quartic is monotonic, and each sign change is closed in by Newton steps
 * kept inside a shrinking bracket.  Exported as POV-Ray's torus (with its
 * sturm solver, for the same reason) moved by a matrix. */
#include <math.h>

#include "whitted/mesh.h"
#include "whitted/plugin.h"
#include "whitted/pov.h"

WHITTED_PLUGIN_ABI_SYMBOL;

static const struct whitted_plugin_host *host;

struct torus {
	struct shape base;
	struct vec3 centre;
	struct vec3 u, v, w;	/* orthonormal, w the axis: the local frame */
	double major, minor;
};

/* c[0] + c[1] x + ... + c[n] x^n. */
static double torus_poly(const double *c, int n, double x)
{
	double y = c[n];

	while (n-- > 0)
		y = y * x + c[n];
	return y;
}

/* The root in [lo, hi] of the polynomial, which is monotonic there and
 * changes sign (f(lo) f(hi) < 0): Newton steps that stay inside the
 * bracket, bisection where one would leave it. */
static double torus_bracketed(const double *c, const double *dc, int n, double lo, double hi)
{
	double flo = torus_poly(c, n, lo), x = 0.5 * (lo + hi);
	int i;

	for (i = 0; i < 100; i++) {
		double f = torus_poly(c, n, x), df = torus_poly(dc, n - 1, x), next;

		if (f == 0.0)
			return x;
		if ((f < 0.0) == (flo < 0.0)) {
			lo = x;
			flo = f;
		} else {
			hi = x;
		}
		next = df != 0.0 ? x - f / df : lo;
		if (!(next > lo && next < hi))
			next = 0.5 * (lo + hi);
		if (next == x || lo >= hi || next == lo || next == hi)
			return next;
		x = next;
	}
	return x;
}

/* The real roots in [lo, hi] of the polynomial of degree n (c[n] != 0,
 * n <= 4), ascending; how many.  A double root counts when the polynomial
 * is exactly 0 there or changes sign across it.  Pure maths with no
 * access to the host, tested on its own on quartics of known roots
 * (tests/unit/plugins/test_torus_roots.c). */
static int torus_roots(const double *c, int n, double lo, double hi, double *out)
{
	double dc[4], cut[6], flo, fhi;
	int k = 0, m, i;

	if (n == 1) {
		double x = -c[0] / c[1];

		if (x >= lo && x <= hi)
			out[k++] = x;
		return k;
	}
	for (i = 1; i <= n; i++)
		dc[i - 1] = i * c[i];
	cut[0] = lo;
	m = 1 + torus_roots(dc, n - 1, lo, hi, cut + 1);
	cut[m++] = hi;
	for (i = 0; i + 1 < m; i++) {
		flo = torus_poly(c, n, cut[i]);
		fhi = torus_poly(c, n, cut[i + 1]);
		if (flo == 0.0) {
			if (k == 0 || out[k - 1] != cut[i])
				out[k++] = cut[i];
		} else if ((flo < 0.0) != (fhi < 0.0) && fhi != 0.0) {
			out[k++] = torus_bracketed(c, dc, n, cut[i], cut[i + 1]);
		}
	}
	if (torus_poly(c, n, hi) == 0.0 && (k == 0 || out[k - 1] != hi))
		out[k++] = hi;
	return k;
}

/* The ray's origin and direction in the local frame. */
static struct vec3 torus_local(const struct torus *tr, struct vec3 p)
{
	return vec3_make(vec3_dot(p, tr->u), vec3_dot(p, tr->v), vec3_dot(p, tr->w));
}

static bool torus_hit(const struct torus *tr, const struct ray *r, double t_min, double t_max,
		      double *t)
{
	double len = vec3_length(r->dir), R2 = tr->major * tr->major, bound, half, s0;
	double c[5], roots[4], b, k;
	struct vec3 d, o;
	int n, i;

	if (!(len > 0.0) || !isfinite(len))
		return false;
	d = torus_local(tr, vec3_scale(r->dir, 1.0 / len));
	o = torus_local(tr, vec3_sub(r->origin, tr->centre));
	/* s0: the point of the line nearest the centre; the torus lies
	 * within the sphere of radius R + r, so the roots within s0 +- half. */
	s0 = -vec3_dot(o, d);
	o = vec3_add_scaled(o, d, s0);
	bound = tr->major + tr->minor;
	half = bound * bound - vec3_dot(o, o);
	if (half < 0.0)
		return false;
	half = sqrt(half) * (1.0 + 1e-9) + 1e-12 * bound;
	b = vec3_dot(o, d);
	k = vec3_dot(o, o) + R2 - tr->minor * tr->minor;
	c[4] = 1.0;
	c[3] = 4.0 * b;
	c[2] = 4.0 * b * b + 2.0 * k - 4.0 * R2 * (d.x * d.x + d.y * d.y);
	c[1] = 4.0 * b * k - 8.0 * R2 * (o.x * d.x + o.y * d.y);
	c[0] = k * k - 4.0 * R2 * (o.x * o.x + o.y * o.y);
	n = torus_roots(c, 4, -half, half, roots);
	for (i = 0; i < n; i++) {
		double tt = (s0 + roots[i]) / len;

		if (tt > t_min && tt < t_max) {
			*t = tt;
			return true;
		}
	}
	return false;
}

static bool torus_intersect(const struct shape *s, const struct ray *r, double t_min,
			    double *t_max)
{
	double t;

	if (!torus_hit((const struct torus *)s, r, t_min, *t_max, &t))
		return false;
	*t_max = t;
	return true;
}

/* From the nearest point of the tube's centre circle to p. */
static struct vec3 torus_normal(const struct shape *s, struct vec3 p)
{
	const struct torus *tr = (const struct torus *)s;
	struct vec3 q = torus_local(tr, vec3_sub(p, tr->centre));
	double rho = sqrt(q.x * q.x + q.y * q.y);
	struct vec3 n, world;

	if (rho > 0.0)
		n = vec3_make(q.x - tr->major * q.x / rho, q.y - tr->major * q.y / rho, q.z);
	else
		n = vec3_make(0.0, 0.0, q.z);
	world = vec3_add(vec3_add(vec3_scale(tr->u, n.x), vec3_scale(tr->v, n.y)),
			 vec3_scale(tr->w, n.z));
	world = vec3_normalize(world);
	return vec3_is_finite(world) ? world : tr->w;
}

/* The ring spans R + r across the axis and r along it: per world axis k,
 * (R + r) sqrt(1 - w_k^2) + r |w_k|. */
static bool torus_bounds(const struct shape *s, struct aabb *out)
{
	const struct torus *tr = (const struct torus *)s;
	double big = tr->major + tr->minor, r = tr->minor;
	struct vec3 w = tr->w;
	struct vec3 e = vec3_make(big * sqrt(fmax(0.0, 1.0 - w.x * w.x)) + r * fabs(w.x),
				  big * sqrt(fmax(0.0, 1.0 - w.y * w.y)) + r * fabs(w.y),
				  big * sqrt(fmax(0.0, 1.0 - w.z * w.z)) + r * fabs(w.z));

	out->min = vec3_sub(tr->centre, e);
	out->max = vec3_add(tr->centre, e);
	return true;
}

/* POV-Ray's torus lies round its y axis: the matrix (its rows the images
 * of x, y, z, then the translation) takes x, y, z to u, w, -v, a rotation
 * (u . (w x -v) = u . (v x w) = 1), and the origin to the centre. */
static int torus_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct torus *tr = (const struct torus *)s;
	const struct vec3 rows[4] = { tr->u, tr->w, vec3_neg(tr->v), tr->centre };
	int i;

	fputs("torus { ", out);
	host->pov_number(out, tr->major);
	fputs(", ", out);
	host->pov_number(out, tr->minor);
	fputs(" sturm\n  ", out);
	host->pov_texture(out, &s->mat, opt);
	fputs("\n  matrix <", out);
	for (i = 0; i < 4; i++) {
		fputs(i ? ", " : "", out);
		host->pov_number(out, rows[i].x);
		fputs(", ", out);
		host->pov_number(out, rows[i].y);
		fputs(", ", out);
		host->pov_number(out, rows[i].z);
	}
	fputs(">\n}\n", out);
	return ferror(out) ? -RT_E_IO : 0;
}

static struct vec3 torus_point(const struct torus *tr, double a, double b, struct vec3 *n)
{
	struct vec3 radial = vec3_add(vec3_scale(tr->u, cos(a)), vec3_scale(tr->v, sin(a)));

	*n = vec3_add(vec3_scale(radial, cos(b)), vec3_scale(tr->w, sin(b)));
	return vec3_add(vec3_add_scaled(tr->centre, radial, tr->major), vec3_scale(*n, tr->minor));
}

/* opt->segments round the ring, a quarter of that (at least 8) round the
 * tube. */
static int torus_tessellate(const struct shape *s, const struct mesh_options *opt,
			    struct mesh *out)
{
	const struct torus *tr = (const struct torus *)s;
	const double turn = 6.283185307179586;
	int na = opt->segments < 8 ? 8 : opt->segments, nb = na / 4 < 8 ? 8 : na / 4, i, j, rc;

	for (i = 0; i < na; i++) {
		for (j = 0; j < nb; j++) {
			struct vec3 n[4], p[4];

			p[0] = torus_point(tr, turn * i / na, turn * j / nb, &n[0]);
			p[1] = torus_point(tr, turn * (i + 1) / na, turn * j / nb, &n[1]);
			p[2] = torus_point(tr, turn * (i + 1) / na, turn * (j + 1) / nb, &n[2]);
			p[3] = torus_point(tr, turn * i / na, turn * (j + 1) / nb, &n[3]);
			{
				const struct vec3 t1[3] = { p[0], p[1], p[2] }, m1[3] = { n[0], n[1], n[2] };
				const struct vec3 t2[3] = { p[0], p[2], p[3] }, m2[3] = { n[0], n[2], n[3] };

				if ((rc = host->mesh_triangle(out, t1, m1)) < 0 ||
				    (rc = host->mesh_triangle(out, t2, m2)) < 0)
					return rc;
			}
		}
	}
	return 0;
}

static void torus_destroy(struct shape *s)
{
	host->free(s);
}

static const struct shape_ops torus_ops;

/* Normalises *a; false when it is zero or not finite.  Divided first by
 * its largest component, so that neither a tiny axis (5e-324, 0, 0) nor a
 * huge one (1e300, 1e300, 0) loses its length to underflow or overflow. */
static bool torus_unit_axis(struct vec3 *a)
{
	double big = fmax(fabs(a->x), fmax(fabs(a->y), fabs(a->z)));
	struct vec3 s;

	if (!(big > 0.0) || !isfinite(big))
		return false;
	s = vec3_make(a->x / big, a->y / big, a->z / big);
	*a = vec3_scale(s, 1.0 / vec3_length(s));
	return vec3_is_finite(*a);
}

static int torus_parse(struct parser *p, struct shape **out)
{
	struct torus *tr;
	struct vec3 centre, axis, helper;
	double major, minor;
	int rc;

	*out = NULL;
	if ((rc = host->vec3(p, "torus centre", &centre)) < 0 ||
	    (rc = host->vec3(p, "torus axis", &axis)) < 0)
		return rc;
	if (!torus_unit_axis(&axis))
		return host->fail(p, RT_E_RANGE, "torus axis must be a non-zero, finite vector");
	if ((rc = host->number(p, "torus major radius", &major)) < 0)
		return rc;
	if (!(major > 0.0) || !isfinite(major * major * major * major))
		return host->fail(p, RT_E_RANGE, "torus major radius must be > 0 (and below 1e75), found %g",
				  major);
	if ((rc = host->number(p, "torus minor radius", &minor)) < 0)
		return rc;
	if (!(minor > 0.0) || !(minor * minor > 0.0))
		return host->fail(p, RT_E_RANGE,
				  "torus minor radius must be > 0, with a square that is not 0 (above about 1e-154), found %g",
				  minor);
	if (!(minor < major))
		return host->fail(p, RT_E_RANGE,
				  "torus minor radius must be > 0 and below the major radius %g (a ring torus), found %g",
				  major, minor);
	tr = (struct torus *)whitted_plugin_new_shape(host, p, &torus_ops, sizeof(*tr), &rc);
	if (!tr)
		return rc;
	tr->centre = centre;
	tr->w = axis;
	helper = fabs(axis.x) < 0.9 ? vec3_make(1.0, 0.0, 0.0) : vec3_make(0.0, 1.0, 0.0);
	tr->u = vec3_normalize(vec3_cross(helper, axis));
	tr->v = vec3_cross(axis, tr->u);
	tr->major = major;
	tr->minor = minor;
	*out = &tr->base;
	return 0;
}

static const struct shape_ops torus_ops = {
	.keyword = "torus",
	.parse = torus_parse,
	.intersect = torus_intersect,
	.normal = torus_normal,
	.export_pov = torus_export_pov,
	.destroy = torus_destroy,
	.bounds = torus_bounds,
	.tessellate = torus_tessellate,
	/* Glass through it is exact: a torus bounds a solid ring. */
	.closed = whitted_plugin_closed_always,
};

static const struct shape_ops *const torus_shapes[] = { &torus_ops, NULL };

int whitted_plugin_init(const struct whitted_plugin_host *h)
{
	static const struct whitted_plugin plugin = { "torus", "1.0", torus_shapes };

	return whitted_plugin_start(h, &host, &plugin);
}
