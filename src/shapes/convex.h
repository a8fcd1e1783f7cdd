/* The solids bounded by a few planes (nearfar's cube, the pyramids): their
 * intersect, normal and bounds methods, written once over the planes and
 * the box.  A shape of this kind starts with a struct convex_solid and
 * sets its planes and its box when it is made. */
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
	/* The smallest box around the solid: a cube's own; a pyramid's base
	 * raised to its apex's height. */
	struct aabb box;
};

/* The methods of struct shape_ops over a struct convex_solid: the nearest
 * crossing of its surface (solve_ray_convex) and the normal of the face a
 * point is on (solve_convex_face). */
bool convex_intersect(const struct shape *s, const struct ray *r, double t_min, double *t_max);
struct vec3 convex_normal(const struct shape *s, struct vec3 p);
/* The bounds method: the box. */
bool convex_bounds(const struct shape *s, struct aabb *out);
/* Whether the box is flat on some axis (or NaN): the test of the
 * degenerate methods, since only rounding can flatten a solid whose sizes
 * are > 0, a size so small next to its coordinates that adding it changes
 * nothing.  Each shape words its own message. */
bool convex_flat(const struct shape *s);

#endif
