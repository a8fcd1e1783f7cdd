/* Triangle meshes for the primitives' tessellate methods.  Besides the
 * growing vertex array and its texture, one general tool: an implicit
 * surface F = 0 (a general quadric has no parametric form that covers every
 * case: ellipsoids, hyperboloids, cones, planes, cylinders, clipped or not)
 * is extracted by marching tetrahedra.  F is sampled on a grid over a box, and
 * in each tetrahedron the points where F changes sign along an edge (linear
 * interpolation) give one triangle or a quad.  Tetrahedra rather than cubes
 * need no case table and leave no ambiguous faces. */
#include <math.h>
#include <string.h>

#include "base/alloc.h"
#include "whitted/diag.h"
#include "whitted/mesh.h"

void mesh_init(struct mesh *m)
{
	memset(m, 0, sizeof(*m));
}

void mesh_free(struct mesh *m)
{
	rt_free(m->data);
	mesh_init(m);
}

void mesh_clear(struct mesh *m)
{
	m->n_vertices = 0;
	m->texture.width = m->texture.height = 0;
}

static int mesh_reserve(struct mesh *m, size_t more)
{
	size_t cap = m->cap_vertices;
	float *data;

	if (m->n_vertices + more <= cap)
		return 0;
	while (cap < m->n_vertices + more)
		cap = cap ? 2 * cap : 1024;
	data = rt_reallocarray(m->data, cap, RT_MESH_FLOATS_PER_VERTEX * sizeof(float));
	if (!data)
		return -RT_E_NOMEM;
	m->data = data;
	m->cap_vertices = cap;
	return 0;
}

static void mesh_put(struct mesh *m, struct vec3 p, struct vec3 n, struct mesh_uv uv)
{
	float *v = m->data + m->n_vertices++ * RT_MESH_FLOATS_PER_VERTEX;

	v[0] = (float)p.x;
	v[1] = (float)p.y;
	v[2] = (float)p.z;
	v[3] = (float)n.x;
	v[4] = (float)n.y;
	v[5] = (float)n.z;
	v[6] = (float)uv.u;
	v[7] = (float)uv.v;
}

int mesh_add_triangle_uv(struct mesh *m, const struct vec3 p[3], const struct vec3 n[3],
			 const struct mesh_uv uv[3])
{
	struct vec3 face = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
	struct vec3 sum = vec3_add(n[0], vec3_add(n[1], n[2]));
	int rc;

	if ((rc = mesh_reserve(m, 3)) < 0)
		return rc;
	mesh_put(m, p[0], n[0], uv[0]);
	if (vec3_dot(face, sum) >= 0.0) {
		mesh_put(m, p[1], n[1], uv[1]);
		mesh_put(m, p[2], n[2], uv[2]);
	} else {
		mesh_put(m, p[2], n[2], uv[2]);
		mesh_put(m, p[1], n[1], uv[1]);
	}
	return 0;
}

int mesh_add_triangle(struct mesh *m, const struct vec3 p[3], const struct vec3 n[3])
{
	static const struct mesh_uv none[3];

	return mesh_add_triangle_uv(m, p, n, none);
}

/* Corner c of the box: bit 0 picks max.x, bit 1 max.y, bit 2 max.z. */
static struct vec3 box_corner(struct aabb box, int c)
{
	return vec3_make(c & 1 ? box.max.x : box.min.x, c & 2 ? box.max.y : box.min.y,
			 c & 4 ? box.max.z : box.min.z);
}

int mesh_box(struct mesh *m, struct aabb box)
{
	/* Each face: its axis, its side, and its corners in order around it. */
	static const struct {
		int axis, side, corner[4];
	} faces[6] = {
		{ 0, 0, { 0, 2, 6, 4 } }, { 0, 1, { 1, 3, 7, 5 } },
		{ 1, 0, { 0, 1, 5, 4 } }, { 1, 1, { 2, 3, 7, 6 } },
		{ 2, 0, { 0, 1, 3, 2 } }, { 2, 1, { 4, 5, 7, 6 } },
	};
	int f, k, rc;

	for (f = 0; f < 6; f++) {
		struct vec3 n = vec3_make(0, 0, 0), p[4], tri_p[3], tri_n[3];
		double *nc = faces[f].axis == 0 ? &n.x : faces[f].axis == 1 ? &n.y : &n.z;

		*nc = faces[f].side ? 1.0 : -1.0;
		for (k = 0; k < 4; k++)
			p[k] = box_corner(box, faces[f].corner[k]);
		tri_n[0] = tri_n[1] = tri_n[2] = n;
		tri_p[0] = p[0], tri_p[1] = p[1], tri_p[2] = p[2];
		if ((rc = mesh_add_triangle(m, tri_p, tri_n)) < 0)
			return rc;
		tri_p[0] = p[0], tri_p[1] = p[2], tri_p[2] = p[3];
		if ((rc = mesh_add_triangle(m, tri_p, tri_n)) < 0)
			return rc;
	}
	return 0;
}

struct vec3 mesh_vertex(const struct mesh *m, size_t i, struct vec3 *normal, struct mesh_uv *uv)
{
	const float *v = m->data + i * RT_MESH_FLOATS_PER_VERTEX;

	if (normal)
		*normal = vec3_make(v[3], v[4], v[5]);
	if (uv) {
		uv->u = v[6];
		uv->v = v[7];
	}
	return vec3_make(v[0], v[1], v[2]);
}

int mesh_set_texture(struct mesh *m, int width, int height, const struct color *texels)
{
	int k;

	if (width < 1 || height < 1 || width > RT_MESH_TEXELS_MAX / height)
		return -RT_E_RANGE;
	m->texture.width = width;
	m->texture.height = height;
	for (k = 0; k < width * height; k++)
		m->texture.texels[k] = texels[k];
	return 0;
}

/* floor(x * n) mod n, in 0 .. n - 1 for negative x too (0 for inf and
 * NaN). */
static int texel_index(double x, int n)
{
	double i = fmod(floor(x * n), n);

	if (!isfinite(i))
		return 0;
	return (int)(i < 0.0 ? i + n : i);
}

struct color mesh_texture_at(const struct mesh *m, struct mesh_uv uv)
{
	const struct mesh_texture *t = &m->texture;

	return t->texels[texel_index(uv.v, t->height) * t->width + texel_index(uv.u, t->width)];
}

void mesh_grid_cells(struct aabb box, int longest, int cells[3])
{
	struct vec3 e = vec3_sub(box.max, box.min);
	double side = fmax(e.x, fmax(e.y, e.z));
	int axis;

	for (axis = 0; axis < 3; axis++) {
		double n = side > 0.0 ? ceil(longest * vec3_component(e, axis) / side) : 0.0;
		cells[axis] = n < 4 ? 4 : (int)n;
	}
}

/* The six tetrahedra around the cube's diagonal from corner 0 to corner 7
 * (corner bit 0 is +x, bit 1 +y, bit 2 +z).  Neighbouring cubes split
 * their shared face along the same diagonal, so the surface has no cracks. */
static const int cube_tets[6][4] = {
	{ 0, 1, 3, 7 }, { 0, 3, 2, 7 }, { 0, 2, 6, 7 },
	{ 0, 6, 4, 7 }, { 0, 4, 5, 7 }, { 0, 5, 1, 7 },
};

/* The point on edge (a, b) where the linear interpolation of F is zero;
 * fa and fb have opposite signs (one may be zero). */
static struct vec3 edge_point(struct vec3 a, struct vec3 b, double fa, double fb)
{
	double t = fa / (fa - fb);

	return vec3_add_scaled(a, vec3_sub(b, a), t);
}

static int march_emit(struct mesh *m, const struct mesh_field *f, const struct vec3 p[3])
{
	struct vec3 n[3];
	int k;

	for (k = 0; k < 3; k++) {
		struct vec3 g = f->gradient(f->ctx, p[k]);
		if (g.x == 0.0 && g.y == 0.0 && g.z == 0.0)
			g = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
		n[k] = vec3_normalize(g);
	}
	return mesh_add_triangle(m, p, n);
}

static int march_tet(struct mesh *m, const struct mesh_field *f, const struct vec3 v[4],
		     const double fv[4])
{
	int in[4], out[4], n_in = 0, n_out = 0, k;
	struct vec3 t[3];

	for (k = 0; k < 4; k++) {
		if (fv[k] < 0.0)
			in[n_in++] = k;
		else
			out[n_out++] = k;
	}
	if (n_in == 0 || n_out == 0)
		return 0;
	if (n_in == 1 || n_out == 1) {
		int lone = n_in == 1 ? in[0] : out[0];
		const int *others = n_in == 1 ? out : in;
		for (k = 0; k < 3; k++)
			t[k] = edge_point(v[lone], v[others[k]], fv[lone], fv[others[k]]);
		return march_emit(m, f, t);
	}
	{
		/* Two in, two out: the quad through the four crossing edges,
		 * in order around it. */
		struct vec3 q[4] = {
			edge_point(v[in[0]], v[out[0]], fv[in[0]], fv[out[0]]),
			edge_point(v[in[0]], v[out[1]], fv[in[0]], fv[out[1]]),
			edge_point(v[in[1]], v[out[1]], fv[in[1]], fv[out[1]]),
			edge_point(v[in[1]], v[out[0]], fv[in[1]], fv[out[0]]),
		};
		int rc;

		t[0] = q[0], t[1] = q[1], t[2] = q[2];
		if ((rc = march_emit(m, f, t)) < 0)
			return rc;
		t[0] = q[0], t[1] = q[2], t[2] = q[3];
		return march_emit(m, f, t);
	}
}

/* A grid of sample points over a box. */
struct grid {
	struct vec3 min, step;
	int nx, ny, nz;		/* points per axis: cells + 1 */
	double *f;		/* F at point (i, j, k), x fastest */
};

static struct vec3 grid_point(const struct grid *g, int i, int j, int k)
{
	return vec3_make(g->min.x + i * g->step.x, g->min.y + j * g->step.y, g->min.z + k * g->step.z);
}

static size_t grid_index(const struct grid *g, int i, int j, int k)
{
	return ((size_t)k * g->ny + j) * g->nx + i;
}

/* The six tetrahedra of the cube whose lowest corner is point (i, j, k). */
static int march_cube(struct mesh *m, const struct mesh_field *f, const struct grid *g,
		      int i, int j, int k)
{
	struct vec3 cv[8];
	double cf[8];
	int c, t, rc = 0;

	for (c = 0; c < 8; c++) {
		int ci = i + (c & 1), cj = j + (c >> 1 & 1), ck = k + (c >> 2 & 1);
		cv[c] = grid_point(g, ci, cj, ck);
		cf[c] = g->f[grid_index(g, ci, cj, ck)];
	}
	for (c = 0; c < 6 && rc == 0; c++) {
		struct vec3 tv[4];
		double tf[4];
		for (t = 0; t < 4; t++) {
			tv[t] = cv[cube_tets[c][t]];
			tf[t] = cf[cube_tets[c][t]];
		}
		rc = march_tet(m, f, tv, tf);
	}
	return rc;
}

int mesh_implicit(struct mesh *m, const struct mesh_field *f, struct aabb box, const int cells[3])
{
	struct grid g;
	int i, j, k, rc = 0;

	g.min = box.min;
	g.step = vec3_make((box.max.x - box.min.x) / cells[0], (box.max.y - box.min.y) / cells[1],
			   (box.max.z - box.min.z) / cells[2]);
	g.nx = cells[0] + 1;
	g.ny = cells[1] + 1;
	g.nz = cells[2] + 1;
	g.f = rt_reallocarray(NULL, (size_t)g.nx * g.ny * g.nz, sizeof(*g.f));
	if (!g.f)
		return -RT_E_NOMEM;
	for (k = 0; k < g.nz; k++)
		for (j = 0; j < g.ny; j++)
			for (i = 0; i < g.nx; i++)
				g.f[grid_index(&g, i, j, k)] = f->value(f->ctx, grid_point(&g, i, j, k));
	for (k = 0; k < cells[2] && rc == 0; k++)
		for (j = 0; j < cells[1] && rc == 0; j++)
			for (i = 0; i < cells[0] && rc == 0; i++)
				rc = march_cube(m, f, &g, i, j, k);
	rt_free(g.f);
	return rc;
}
