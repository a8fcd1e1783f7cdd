/* The solids bounded by a few planes (nearfar's cube, the pyramids): their
 * intersect and normal methods, written once over the planes.  A shape of
 * this kind starts with a struct convex_solid and sets its planes when it
 * is made. */
#ifndef RT_SHAPES_CONVEX_H
#define RT_SHAPES_CONVEX_H

#include "whitted/shape.h"
#include "shapes/solve.h"

enum { CONVEX_FACES_MAX = 6 };

struct convex_solid {
	struct shape base;
	/* The planes are placed relative to this point (a corner, the apex),
	 * so that their d stay small and exact; their normals are unit
	 * length and point out. */
	struct vec3 at;
	int faces;
	struct solve_plane face[CONVEX_FACES_MAX];
};

/* The methods of struct shape_ops over a struct convex_solid: the nearest
 * crossing of its surface (solve_ray_convex) and the normal of the face a
 * point is on (solve_convex_face). */
bool convex_intersect(const struct shape *s, const struct ray *r, double t_min, double *t_max);
struct vec3 convex_normal(const struct shape *s, struct vec3 p);

#endif
