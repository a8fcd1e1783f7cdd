/* The floor as triangles for the viewer (whitted-view draws with OpenGL):
 * a grid over the square, or over the region around the scene for
 * nearfar's endless floor, under a texture of the cells' colours. */
#include "shapes/floor_impl.h"
#include "whitted/mesh.h"

/* The quad p[0..3] (in order around it) as two triangles split along its
 * 1-3 diagonal, as OpenGL's Mesa splits a quad: the viewer's Gouraud
 * shading is then what it was when the floor was drawn as quads. */
static int floor_add_quad(struct mesh *out, const struct vec3 p[4], const struct vec3 n[3],
			  const struct mesh_uv uv[4])
{
	const struct vec3 p1[3] = { p[0], p[1], p[3] };
	const struct mesh_uv uv1[3] = { uv[0], uv[1], uv[3] };
	const struct vec3 p2[3] = { p[1], p[2], p[3] };
	const struct mesh_uv uv2[3] = { uv[1], uv[2], uv[3] };
	int rc;

	if ((rc = mesh_add_triangle_uv(out, p1, n, uv1)) < 0)
		return rc;
	return mesh_add_triangle_uv(out, p2, n, uv2);
}

/* The viewer's texels along a cell: 1 for plain cells, else the larger
 * side of the textures, at most 16 (the mesh's texture holds two cells
 * by two), which shows textures up to 16 texels wide exactly and larger
 * ones sampled. */
static int floor_texels_per_cell(const struct shape *s)
{
	const struct floor *fl = (const struct floor *)s;
	int n = 1, k;

	for (k = 0; k < 2; k++) {
		if (fl->tex[k].width > n)
			n = fl->tex[k].width;
		if (fl->tex[k].height > n)
			n = fl->tex[k].height;
	}
	return n > 16 ? 16 : n;
}

/* A grid of 3 * segments quads a side over the area's x and y (a viewer
 * that lights per vertex needs vertices under the highlights) under a
 * 2 x 2 texture of the cells' colours, repeated every two cells: u and v
 * count cell pairs from the corner (cx, cy) of a cell (0, 0) of even
 * parity, as the cell index does, so the texture's cells fall on the
 * floor's whatever their number. */
static int floor_grid(const struct shape *s, const struct mesh_options *opt, struct aabb area,
		      double cx, double cy, double cell, struct mesh *out)
{
	const struct vec3 up = vec3_make(0.0, 0.0, 1.0), n[3] = { up, up, up };
	const int quads = 3 * opt->segments;
	const double x0 = area.min.x, y0 = area.min.y, period = 2.0 * cell;
	const double side_x = (area.max.x - x0) / quads, side_y = (area.max.y - y0) / quads;
	const int per_cell = floor_texels_per_cell(s), side = 2 * per_cell;
	struct color texels[RT_MESH_TEXELS_MAX];
	int i, j, k, rc;

	for (k = 0; k < side * side; k++)
		texels[k] = shape_color_at(s, vec3_make(cx + (k % side + 0.5) * cell / per_cell,
							cy + (k / side + 0.5) * cell / per_cell, 0.0));
	if ((rc = mesh_set_texture(out, side, side, texels)) < 0)
		return rc;
	for (j = 0; j < quads; j++) {
		for (i = 0; i < quads; i++) {
			static const int corner[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
			struct vec3 p[4];
			struct mesh_uv uv[4];
			for (k = 0; k < 4; k++) {
				p[k] = vec3_make(x0 + (i + corner[k][0]) * side_x,
						 y0 + (j + corner[k][1]) * side_y, 0.0);
				uv[k].u = (p[k].x - cx) / period;
				uv[k].v = (p[k].y - cy) / period;
			}
			if ((rc = floor_add_quad(out, p, n, uv)) < 0)
				return rc;
		}
	}
	return 0;
}

/* The whole square, its cell (0, 0) at the corner (-w/2, -w/2). */
int floor_tessellate(const struct shape *s, const struct mesh_options *opt, struct mesh *out)
{
	const struct floor *fl = (const struct floor *)s;
	const double h = fl->half;
	struct aabb area = { { -h, -h, 0.0 }, { h, h, 0.0 } };

	return floor_grid(s, opt, area, -h, -h, fl->cell, out);
}
/* The plane over the x and y extent of the region around the scene, at
 * z = 0 even when the region lies above or below it (the floor under a
 * scene of objects in the air is still drawn). */
int floor_infinite_tessellate(const struct shape *s, const struct mesh_options *opt,
			      struct mesh *out)
{
	const struct floor *fl = (const struct floor *)s;
	struct aabb area = opt->around;

	area.min.z = area.max.z = 0.0;
	if (!(area.min.x < area.max.x && area.min.y < area.max.y) ||
	    !vec3_is_finite(area.min) || !vec3_is_finite(area.max))
		return 0;
	return floor_grid(s, opt, area, 0.0, 0.0, fl->cell, out);
}
