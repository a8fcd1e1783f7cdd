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

enum { CUBE_FACES = 6 };

/* The planes relative to lo (solid.at): -x, +x, -y, +y, -z, +z. */
struct cube {
	struct convex_solid solid;
	struct vec3 lo, hi;
};

static bool cube_bounds(const struct shape *s, struct aabb *out)
{
	const struct cube *cu = (const struct cube *)s;

	out->min = cu->lo;
	out->max = cu->hi;
	return true;
}

/* Only rounding can flatten a cube whose side is > 0: a side so small
 * next to the corner's coordinates that adding it changes nothing. */
static const char *cube_degenerate(const struct shape *s)
{
	const struct cube *cu = (const struct cube *)s;

	if (!(cu->hi.x > cu->lo.x) || !(cu->hi.y > cu->lo.y) || !(cu->hi.z > cu->lo.z))
		return "is too small for its coordinates (its side vanishes when added to them) "
		       "and will not be visible";
	return NULL;
}

static int cube_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct cube *cu = (const struct cube *)s;

	fputs("box { ", out);
	pov_write_vector(out, cu->lo.x, cu->lo.y, cu->lo.z);
	fputs(", ", out);
	pov_write_vector(out, cu->hi.x, cu->hi.y, cu->hi.z);
	return shape_pov_finish(s, out, opt);
}

/* The box's twelve triangles, normals outwards. */
static int cube_tessellate(const struct shape *s, const struct mesh_options *opt,
			   struct mesh *out)
{
	const struct cube *cu = (const struct cube *)s;
	struct aabb box = { cu->lo, cu->hi };

	(void)opt;
	if (cube_degenerate(s))
		return 0;
	return mesh_box(out, box);
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
	.bounds = cube_bounds,
	.degenerate = cube_degenerate,
	.tessellate = cube_tessellate,
	.closed = shape_closed_always,
};

struct shape *cube_create(struct vec3 corner, double side, const struct material *m)
{
	struct cube *cu = shape_alloc(sizeof(*cu), &cube_ops, m);
	struct vec3 e;
	int axis;

	if (!cu)
		return NULL;
	cu->lo = corner;
	cu->hi = vec3_make(corner.x + side, corner.y + side, corner.z + side);
	cu->solid.at = cu->lo;
	cu->solid.faces = CUBE_FACES;
	e = vec3_sub(cu->hi, cu->lo);
	for (axis = 0; axis < 3; axis++) {
		struct vec3 n = vec3_make(axis == 0, axis == 1, axis == 2);
		cu->solid.face[2 * axis].n = vec3_neg(n);
		cu->solid.face[2 * axis].d = 0.0;
		cu->solid.face[2 * axis + 1].n = n;
		cu->solid.face[2 * axis + 1].d = vec3_component(e, axis);
	}
	return &cu->solid.base;
}

static int cube_parse(struct parser *p, struct shape **out)
{
	return shape_parse_point_size(p, "cube corner", "cube side", cube_create, out);
}
