/* The square pyramid, a closed solid: four triangular sides that meet at
 * the apex above the centre of a square base, and the base.  One primitive
 * with two placements, each its own table of keyword "pyramid": the
 * pyramid dialect gives the base's lowest corner and its side B (base
 * [x, x+B] x [y, y+B] at height z, apex (x + B/2, y + B/2, z + H)), nearfar
 * the base's centre and its width W (base [x-W/2, x+W/2] x [y-W/2, y+W/2],
 * apex (x, y, z + H)).  The solid is the intersection of five half-spaces;
 * a ray meets it where it enters or, from inside, where it leaves. */
#include <math.h>

#include "whitted/diag.h"
#include "whitted/mesh.h"
#include "whitted/parser.h"
#include "whitted/pov.h"
#include "whitted/scene.h"
#include "shapes/shapes.h"
#include "whitted/shape.h"
#include "syntax/parser_impl.h"
#include "shapes/convex.h"

enum { PYRAMID_FACES = 5 };

/* The planes relative to the apex (solid.at): the base, then the sides
 * facing -x, +x, -y, +y. */
struct pyramid {
	struct convex_solid solid;
	struct vec3 lo, hi;		/* the base's corners, both at the base's height */
	struct vec3 apex;
};

/* The unit outward normal n and offset d of n . q <= d, in coordinates q
 * relative to the apex; a zero normal (a pyramid too thin for its
 * coordinates to tell its sides apart) constrains nothing. */
static struct solve_plane pyramid_plane(double nx, double ny, double nz, double d)
{
	struct solve_plane pl;
	double len = sqrt(nx * nx + ny * ny + nz * nz);

	if (!(len > 0.0) || !isfinite(len)) {
		pl.n = vec3_make(0.0, 0.0, 0.0);
		pl.d = 0.0;
		return pl;
	}
	pl.n = vec3_make(nx / len, ny / len, nz / len);
	pl.d = d / len;
	return pl;
}

/* A new pyramid (NULL when out of memory) with the faces from the corners
 * and the apex.  With h the apex's height over
 * the base and e the distance from the apex's foot to a side's base edge,
 * that side holds h q_axis + e q_z <= 0 (it passes through the apex and
 * the edge at q_axis = e, q_z = -h); the base holds -q_z <= h. */
static struct shape *pyramid_new(const struct shape_ops *ops, struct vec3 lo, struct vec3 hi,
				 struct vec3 apex, const struct material *m)
{
	struct pyramid *py = shape_alloc(sizeof(*py), ops, m);
	double h = apex.z - lo.z;

	if (!py)
		return NULL;
	py->lo = lo;
	py->hi = hi;
	py->apex = apex;
	py->solid.at = apex;
	py->solid.box.min = lo;
	py->solid.box.max = vec3_make(hi.x, hi.y, apex.z);
	py->solid.faces = PYRAMID_FACES;
	py->solid.face[0] = pyramid_plane(0.0, 0.0, -1.0, h);
	py->solid.face[1] = pyramid_plane(-h, 0.0, apex.x - lo.x, 0.0);
	py->solid.face[2] = pyramid_plane(h, 0.0, hi.x - apex.x, 0.0);
	py->solid.face[3] = pyramid_plane(0.0, -h, apex.y - lo.y, 0.0);
	py->solid.face[4] = pyramid_plane(0.0, h, hi.y - apex.y, 0.0);
	return &py->solid.base;
}

static const char *pyramid_degenerate(const struct shape *s)
{
	if (convex_flat(s))
		return "is too small for its coordinates (a size vanishes when added to them) "
		       "and will not be visible";
	return NULL;
}

/* The base's corners counter-clockwise seen from above, then the apex. */
static void pyramid_corners(const struct pyramid *py, struct vec3 v[5])
{
	v[0] = py->lo;
	v[1] = vec3_make(py->hi.x, py->lo.y, py->lo.z);
	v[2] = vec3_make(py->hi.x, py->hi.y, py->lo.z);
	v[3] = vec3_make(py->lo.x, py->hi.y, py->lo.z);
	v[4] = py->apex;
}

/* The six triangles of the surface, counter-clockwise seen from outside,
 * with the face each lies in: the four sides, then the base in two. */
static const int pyramid_triangles[6][4] = {
	{ 0, 1, 4, 3 }, { 1, 2, 4, 2 }, { 2, 3, 4, 4 }, { 3, 0, 4, 1 },
	{ 0, 2, 1, 0 }, { 0, 3, 2, 0 },
};

/* A mesh of the six triangles with the very corners whitted uses, so the
 * geometry is exact; inside_vector makes it a solid, as whitted's is. */
static int pyramid_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	const struct pyramid *py = (const struct pyramid *)s;
	struct vec3 v[5];
	int i;

	pyramid_corners(py, v);
	fputs("mesh {\n", out);
	for (i = 0; i < 6; i++) {
		const int *tri = pyramid_triangles[i];
		const struct vec3 p[3] = { v[tri[0]], v[tri[1]], v[tri[2]] };

		shape_pov_begin(out, "  triangle { ", p, 3);
		fputs(" }\n", out);
	}
	fputs("  inside_vector <0,0,1>", out);
	return shape_pov_finish(s, out, opt);
}

static int pyramid_tessellate(const struct shape *s, const struct mesh_options *opt,
			      struct mesh *out)
{
	const struct pyramid *py = (const struct pyramid *)s;
	struct vec3 v[5];
	int i, rc;

	(void)opt;
	if (pyramid_degenerate(s))
		return 0;
	pyramid_corners(py, v);
	for (i = 0; i < 6; i++) {
		const int *tri = pyramid_triangles[i];
		const struct vec3 n = py->solid.face[tri[3]].n;
		const struct vec3 p[3] = { v[tri[0]], v[tri[1]], v[tri[2]] };
		const struct vec3 normals[3] = { n, n, n };
		if ((rc = mesh_add_triangle(out, p, normals)) < 0)
			return rc;
	}
	return 0;
}

static int pyramid_parse(struct parser *p, struct shape **out);
static int pyramid_centred_parse(struct parser *p, struct shape **out);

/* The methods both placements share: a macro, since C99 cannot
 * initialise one static table from another. */
#define PYRAMID_METHODS                            \
	.keyword = "pyramid",                      \
	.intersect = convex_intersect,             \
	.normal = convex_normal,                   \
	.export_pov = pyramid_export_pov,          \
	.destroy = shape_destroy_block,            \
	.bounds = convex_bounds,                   \
	.degenerate = pyramid_degenerate,          \
	.tessellate = pyramid_tessellate,          \
	.closed = shape_closed_always

const struct shape_ops pyramid_ops = {
	PYRAMID_METHODS,
	.dialects = RT_DIALECT_BIT(RT_DIALECT_PYRAMID),
	.parse = pyramid_parse,
};

/* nearfar's placement: the same methods, read from the base's centre. */
const struct shape_ops pyramid_centred_ops = {
	PYRAMID_METHODS,
	.dialects = RT_DIALECT_BIT(RT_DIALECT_NEARFAR),
	.parse = pyramid_centred_parse,
};

struct shape *pyramid_create(struct vec3 corner, double base, double height,
			     const struct material *m)
{
	struct vec3 hi = vec3_make(corner.x + base, corner.y + base, corner.z);
	struct vec3 apex = vec3_make(corner.x + 0.5 * base, corner.y + 0.5 * base, corner.z + height);

	return pyramid_new(&pyramid_ops, corner, hi, apex, m);
}

struct shape *pyramid_create_centred(struct vec3 centre, double width, double height,
				     const struct material *m)
{
	double half = 0.5 * width;
	struct vec3 lo = vec3_make(centre.x - half, centre.y - half, centre.z);
	struct vec3 hi = vec3_make(centre.x + half, centre.y + half, centre.z);
	struct vec3 apex = vec3_make(centre.x, centre.y, centre.z + height);

	return pyramid_new(&pyramid_centred_ops, lo, hi, apex, m);
}

/* The geometry and the material after the keyword: a point, the base's
 * side and the height; `centred` says whether the point is the base's
 * centre (nearfar) or its lowest corner. */
static int pyramid_read(struct parser *p, bool centred, struct shape **out)
{
	const char *what_point = centred ? "pyramid base centre" : "pyramid corner";
	const char *what_base = centred ? "pyramid base width" : "pyramid base length";
	struct material m;
	struct vec3 point;
	double base, height;
	int rc;

	*out = NULL;
	if ((rc = parser_vec3(p, what_point, &point)) < 0 ||
	    (rc = parser_size(p, what_base, &base)) < 0 ||
	    (rc = parser_size(p, "pyramid height", &height)) < 0 ||
	    (rc = parser_material(p, &m)) < 0)
		return rc;
	*out = centred ? pyramid_create_centred(point, base, height, &m)
		       : pyramid_create(point, base, height, &m);
	return *out ? 0 : parser_fail(p, RT_E_NOMEM, "out of memory");
}

static int pyramid_parse(struct parser *p, struct shape **out)
{
	return pyramid_read(p, false, out);
}

static int pyramid_centred_parse(struct parser *p, struct shape **out)
{
	return pyramid_read(p, true, out);
}
