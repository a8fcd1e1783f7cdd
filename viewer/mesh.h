/* Triangle meshes for the viewer to draw: the shapes that OpenGL has no
 * primitive for, tessellated once at start-up.  No GL here. */
#ifndef RT_MESH_H
#define RT_MESH_H

#include <stddef.h>

#include "aabb.h"
#include "shape.h"
#include "vec3.h"

/* Three vertices per triangle, each x y z nx ny nz.  A triangle is counter-
 * clockwise seen from the side its vertex normals point to, so that
 * OpenGL's two-sided lighting lights each side with the right normal. */
struct mesh {
	float *data;
	size_t n_vertices, cap_vertices;
};

#define RT_MESH_FLOATS_PER_VERTEX 6

void mesh_init(struct mesh *m);
void mesh_free(struct mesh *m);
/* Adds a triangle, turned so that its winding agrees with the sum of its
 * normals. */
int mesh_add_triangle(struct mesh *m, const struct vec3 p[3], const struct vec3 n[3]);

/* A UV sphere: slices around the pole axis (z), stacks from pole to pole. */
int mesh_sphere(struct mesh *m, struct vec3 centre, double radius, int slices, int stacks);

/* F(p) = A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J
 * and its gradient. */
double mesh_quadric_value(const double coef[10], struct vec3 p);
struct vec3 mesh_quadric_gradient(const double coef[10], struct vec3 p);
/* The box a quadric is drawn in: its clip box on the clipped axes, and
 * `around` (a region around the scene) on the others. */
struct aabb mesh_quadric_region(const struct shape_geometry *g, struct aabb around);
/* The surface F = 0 inside box, by marching tetrahedra over a grid of
 * cells[0] x cells[1] x cells[2] cubes (each >= 1) split into six
 * tetrahedra; normals are the gradient. */
int mesh_quadric(struct mesh *m, const double coef[10], struct aabb box, const int cells[3]);

#endif
