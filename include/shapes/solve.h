/* The pure maths of ray/primitive intersection, separate from the shape
 * tables so that it can be tested on its own. */
#ifndef RT_SHAPES_SOLVE_H
#define RT_SHAPES_SOLVE_H

#include <stdbool.h>

#include "material.h"
#include "ray.h"
#include "shape.h"

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

/* Constructors for the tests and the built-in scenes. */
struct shape *sphere_create(struct vec3 centre, double radius, const struct material *m);
struct shape *triangle_create(struct vec3 a, struct vec3 b, struct vec3 c,
			      const struct material *m);
/* coef = A..J of A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J;
 * extent 0 on an axis means no clipping along it. */
struct shape *quadric_create(const double coef[10], struct vec3 clip_ref,
			     struct vec3 clip_extent, const struct material *m);

#endif
