/* The pure maths of ray/primitive intersection, separate from the shape
 * tables so that it can be tested on its own. */
#ifndef RT_SHAPES_SOLVE_H
#define RT_SHAPES_SOLVE_H

#include <stdbool.h>

#include "whitted/material.h"
#include "whitted/ray.h"

/* Real roots of a t^2 + b t + c = 0 in ascending order, computed without
 * cancellation (the larger-magnitude root first, the other from the product
 * of the roots); a = 0 is the linear case.  Returns how many (0, 1 or 2). */
int solve_quadratic(double a, double b, double c, double roots[2]);

/* The nearest t in (t_min, t_max) where the ray meets the sphere
 * |P - centre|^2 = radius_sq. */
bool solve_ray_sphere(const struct ray *r, struct vec3 centre, double radius_sq,
		      double t_min, double t_max, double *t);

/* Moller-Trumbore: the t in (t_min, t_max) where the ray meets the triangle
 * v0 + u e1 + v e2 (u, v >= 0, u + v <= 1), from either side. */
bool solve_ray_triangle(const struct ray *r, struct vec3 v0, struct vec3 e1, struct vec3 e2,
			double t_min, double t_max, double *t);

/* A half-space n . p <= d (n need not be unit length). */
struct solve_plane {
	struct vec3 n;
	double d;
};

/* The convex solid where every one of the n half-spaces holds: the nearest
 * t in (t_min, t_max) where the ray crosses its surface, which is where it
 * enters or, for a ray that starts inside, where it leaves.  The ray enters
 * at t0 = max of (d - n.o) / (n.dir) over the planes it crosses inwards
 * (n.dir < 0) and leaves at t1 = min over those it crosses outwards; it
 * misses when t0 > t1, or when it runs parallel to a plane outside it.  A
 * ray through an edge or a corner (t0 = t1) hits. */
bool solve_ray_convex(const struct ray *r, const struct solve_plane *planes, int n,
		      double t_min, double t_max, double *t);
/* The index of the plane that p lies nearest to, outside it or least
 * inside (the largest n . p - d, so the normals should be unit length):
 * for a point on the solid's surface, the face it is on; on an edge,
 * either of the two. */
int solve_convex_face(const struct solve_plane *planes, int n, struct vec3 p);


#endif
