/* nearfar's cube, a closed solid: the axis-aligned box [x, x+S] x [y, y+S]
 * x [z, z+S] from its bottom lower-left corner and its side.  The box is
 * the intersection of six half-spaces (the slabs); a ray meets it where it
 * enters or, from inside, where it leaves. */
#include <math.h>

#include "whitted/diag.h"
#include "whitted/mesh.h"
#include "whitted/parser.h"
#include "whitted/pov.h"
#include "whitted/scene.h"
#include "shapes/shapes.h"
#include "whitted/shape.h"
#include "shapes/convex.h"

/* A cube is a struct convex_solid alone: the box is the cube, its lower
 * corner the planes' reference point (solid.at), its planes -x, +x, -y,
 * +y, -z, +z. */
enum { CUBE_FACES = 6 };

static const char *cube_degenerate(const struct shape *s)
{
	if (convex_flat(s))
		return "is too small for its coordinates (its side vanishes when added to them) "
		       "and will not be visible";
	return NULL;
}

static int cube_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct aabb *box = &((const struct convex_solid *)s)->box;
	const struct vec3 corners[2] = { box->min, box->max };

	shape_pov_begin(out, "box { ", corners, 2);
	return shape_pov_finish(s, out, opt);
}

/* The box's twelve triangles, normals outwards. */
static int cube_tessellate(const struct shape *s, const struct mesh_options *opt,
			   struct mesh *out)
{
	(void)opt;
	if (cube_degenerate(s))
		return 0;
	return mesh_box(out, ((const struct convex_solid *)s)->box);
}

static int cube_parse(struct parser *p, struct shape **out);

const struct shape_ops cube_ops = {
	.keyword = "cube",
	.dialects = RT_DIALECT_BIT(RT_DIALECT_NEARFAR),
	.parse = cube_parse,
	.intersect = convex_intersect,
	.normal = convex_normal,
	.export_pov = cube_export_pov,
	.destroy = shape_destroy_block,
	.bounds = convex_bounds,
	.degenerate = cube_degenerate,
	.tessellate = cube_tessellate,
	.closed = shape_closed_always,
};

struct shape *cube_create(struct vec3 corner, double side, const struct material *m)
{
	struct convex_solid *cu = shape_alloc(sizeof(*cu), &cube_ops, m);
	struct vec3 e;
	int axis;

	if (!cu)
		return NULL;
	cu->box.min = corner;
	cu->box.max = vec3_make(corner.x + side, corner.y + side, corner.z + side);
	cu->at = corner;
	cu->faces = CUBE_FACES;
	e = vec3_sub(cu->box.max, cu->box.min);
	for (axis = 0; axis < 3; axis++) {
		struct vec3 n = vec3_make(axis == 0, axis == 1, axis == 2);
		cu->face[2 * axis].n = vec3_neg(n);
		cu->face[2 * axis].d = 0.0;
		cu->face[2 * axis + 1].n = n;
		cu->face[2 * axis + 1].d = vec3_component(e, axis);
	}
	return &cu->base;
}

static int cube_parse(struct parser *p, struct shape **out)
{
	return shape_parse_point_size(p, "cube corner", "cube side", cube_create, out);
}
