/* Stable quadratic roots, ray/sphere, Moller-Trumbore ray/triangle and the
 * ray through a convex solid of planes. */
#include <math.h>

#include "shapes/solve.h"

int solve_quadratic(double a, double b, double c, double roots[2])
{
	double disc, q, t0, t1;

	if (a == 0.0) {
		if (b == 0.0)
			return 0;
		roots[0] = -c / b;
		return 1;
	}
	disc = b * b - 4.0 * a * c;
	if (disc < 0.0)
		return 0;
	q = -0.5 * (b + copysign(sqrt(disc), b));
	if (q == 0.0) {
		/* b = 0 and c = 0: a double root at zero. */
		roots[0] = roots[1] = 0.0;
		return 2;
	}
	t0 = q / a;
	t1 = c / q;
	roots[0] = fmin(t0, t1);
	roots[1] = fmax(t0, t1);
	return 2;
}

bool solve_ray_sphere(const struct ray *r, struct vec3 centre, double radius_sq,
		      double t_min, double t_max, double *t)
{
	/* |o + t d - c|^2 = r^2 with oc = o - c:
	 * (d.d) t^2 + 2 (oc.d) t + oc.oc - r^2 = 0.  The discriminant is taken
	 * as a (r^2 - |oc - (oc.d / d.d) d|^2), which keeps its precision when
	 * the sphere is small and far away. */
	struct vec3 oc = vec3_sub(r->origin, centre);
	double a = vec3_dot(r->dir, r->dir);
	double half_b = vec3_dot(oc, r->dir);
	struct vec3 perp = vec3_add_scaled(oc, r->dir, -half_b / a);
	double disc = a * (radius_sq - vec3_dot(perp, perp));
	double c = vec3_dot(oc, oc) - radius_sq;
	double q, t0, t1;

	if (disc < 0.0)
		return false;
	q = -(half_b + copysign(sqrt(disc), half_b));
	if (q == 0.0) {
		t0 = t1 = 0.0;
	} else {
		t0 = q / a;
		t1 = c / q;
		if (t0 > t1) {
			double tmp = t0;
			t0 = t1;
			t1 = tmp;
		}
	}
	if (t0 > t_min && t0 < t_max) {
		*t = t0;
		return true;
	}
	if (t1 > t_min && t1 < t_max) {
		*t = t1;
		return true;
	}
	return false;
}

bool solve_ray_triangle(const struct ray *r, struct vec3 v0, struct vec3 e1, struct vec3 e2,
			double t_min, double t_max, double *t)
{
	struct vec3 pvec = vec3_cross(r->dir, e2);
	double det = vec3_dot(e1, pvec);
	struct vec3 tvec, qvec;
	double inv, u, v, hit;

	if (det == 0.0)
		return false;
	inv = 1.0 / det;
	tvec = vec3_sub(r->origin, v0);
	u = vec3_dot(tvec, pvec) * inv;
	if (u < 0.0 || u > 1.0)
		return false;
	qvec = vec3_cross(tvec, e1);
	v = vec3_dot(r->dir, qvec) * inv;
	if (v < 0.0 || u + v > 1.0)
		return false;
	hit = vec3_dot(e2, qvec) * inv;
	if (!(hit > t_min && hit < t_max))
		return false;
	*t = hit;
	return true;
}

bool solve_ray_convex(const struct ray *r, const struct solve_plane *planes, int n,
		      double t_min, double t_max, double *t)
{
	double t0 = -INFINITY, t1 = INFINITY;
	int i;

	for (i = 0; i < n; i++) {
		/* n.(o + t dir) <= d  <=>  t (n.dir) <= d - n.o */
		double den = vec3_dot(planes[i].n, r->dir);
		double num = planes[i].d - vec3_dot(planes[i].n, r->origin);

		if (den == 0.0) {
			if (num < 0.0)
				return false;
		} else if (den < 0.0) {
			t0 = fmax(t0, num / den);
		} else {
			t1 = fmin(t1, num / den);
		}
		if (t0 > t1)
			return false;
	}
	if (t0 > t_min && t0 < t_max) {
		*t = t0;
		return true;
	}
	if (t1 > t_min && t1 < t_max) {
		*t = t1;
		return true;
	}
	return false;
}

int solve_convex_face(const struct solve_plane *planes, int n, struct vec3 p)
{
	double best = -INFINITY;
	int i, face = 0;

	for (i = 0; i < n; i++) {
		double dist = vec3_dot(planes[i].n, p) - planes[i].d;
		if (dist > best) {
			best = dist;
			face = i;
		}
	}
	return face;
}
