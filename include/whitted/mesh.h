/* Triangle meshes of shapes, for tools that draw rather than trace (the
 * OpenGL viewer).  A primitive makes its mesh in its optional tessellate
 * method with the helpers below; nothing here knows about OpenGL. */
#ifndef RT_MESH_H
#define RT_MESH_H

#include <stddef.h>

#include "aabb.h"
#include "material.h"
#include "vec3.h"

/* An image repeated over a mesh by its vertices' texture coordinates:
 * texel (floor(u * width) mod width, floor(v * height) mod height), row
 * after row, sampled without filtering.  Sizes 0: no texture. */
/* 32 x 32: a textured floor's two cells by two at 16 texels a cell. */
#define RT_MESH_TEXELS_MAX 1024

struct mesh_texture {
	int width, height;
	struct color texels[RT_MESH_TEXELS_MAX];
};

/* Three vertices per triangle, each x y z nx ny nz u v with a unit normal
 * and texture coordinates (0 without a texture).  A triangle is counter-
 * clockwise seen from the side its vertex normals point to, so that
 * two-sided lighting lights each side with the right normal.  The colour
 * is the shape's material colour, or the texture's where there is one. */
struct mesh {
	float *data;
	size_t n_vertices, cap_vertices;
	struct mesh_texture texture;
};

#define RT_MESH_FLOATS_PER_VERTEX 8

struct mesh_uv {
	double u, v;
};

/* What a tessellation is asked for. */
struct mesh_options {
	/* The region around the scene: an unbounded shape is meshed where it
	 * lies inside it (on the axes it has no bounds of its own). */
	struct aabb around;
	/* The fineness: a full turn of a curved surface is cut into about
	 * this many edges, and a sampled or flat surface into cells of a
	 * similar size (a viewer that lights per vertex needs vertices under
	 * the highlights).  At least 4. */
	int segments;
};

void mesh_init(struct mesh *m);
void mesh_free(struct mesh *m);
/* Empties the mesh (triangles and texture) and keeps its memory for the
 * next one. */
void mesh_clear(struct mesh *m);
/* Adds a triangle, turned so that its winding agrees with the sum of its
 * normals; mesh_add_triangle_uv with texture coordinates.  0 or
 * -RT_E_NOMEM. */
int mesh_add_triangle(struct mesh *m, const struct vec3 p[3], const struct vec3 n[3]);
int mesh_add_triangle_uv(struct mesh *m, const struct vec3 p[3], const struct vec3 n[3],
			 const struct mesh_uv uv[3]);
/* Adds the twelve triangles of the box's faces, normals outwards. */
int mesh_box(struct mesh *m, struct aabb box);
/* Vertex i's position, and its normal and texture coordinates where
 * those pointers are not NULL. */
struct vec3 mesh_vertex(const struct mesh *m, size_t i, struct vec3 *normal, struct mesh_uv *uv);
/* Sets the texture: width x height texels (at most RT_MESH_TEXELS_MAX),
 * row after row.  0, or -RT_E_RANGE when there are too many. */
int mesh_set_texture(struct mesh *m, int width, int height, const struct color *texels);
/* The texture's colour at (u, v); the mesh must have a texture. */
struct color mesh_texture_at(const struct mesh *m, struct mesh_uv uv);

/* An implicit surface F(p) = 0 with its gradient (not necessarily unit). */
struct mesh_field {
	double (*value)(const void *ctx, struct vec3 p);
	struct vec3 (*gradient)(const void *ctx, struct vec3 p);
	const void *ctx;
};

/* Cells per axis of a grid over box: `longest` along its longest side and
 * the others in proportion, at least 4 on each. */
void mesh_grid_cells(struct aabb box, int longest, int cells[3]);
/* Adds the surface F = 0 inside box, by marching tetrahedra over a grid of
 * cells[0] x cells[1] x cells[2] cubes (each >= 1) split into six
 * tetrahedra; vertex normals are the unit gradient (the face's normal where
 * the gradient is zero, as at a cone's apex). */
int mesh_implicit(struct mesh *m, const struct mesh_field *f, struct aabb box, const int cells[3]);

#endif
