/* The floor's parts, private to its files: the shape (floor.c), its
 * POV-Ray export (floor_pov.c) and its mesh for the viewer
 * (floor_mesh.c). */
#ifndef RT_SHAPES_FLOOR_IMPL_H
#define RT_SHAPES_FLOOR_IMPL_H

#include <stdio.h>

#include "whitted/image.h"
#include "whitted/mesh.h"
#include "whitted/pov.h"
#include "whitted/shape.h"

struct floor {
	struct shape base;
	double half, cell;
	/* The white cells' and the black cells' textures: no pixels (and a
	 * NULL path) for the plain colour. */
	struct image tex[2];
	char *tex_path[2];		/* absolute, for the POV-Ray export */
	enum image_format tex_format[2];
};

/* export_pov of the square and of the endless plane. */
int floor_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt);
int floor_infinite_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt);
/* tessellate of the square and of the endless plane. */
int floor_tessellate(const struct shape *s, const struct mesh_options *opt, struct mesh *out);
int floor_infinite_tessellate(const struct shape *s, const struct mesh_options *opt,
			      struct mesh *out);

#endif
