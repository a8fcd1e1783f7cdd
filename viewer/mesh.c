/* Tessellation for the viewer.  A sphere is a UV grid.  A general quadric
 * has no parametric form that covers every case (ellipsoids, hyperboloids,
 * cones, planes, cylinders, clipped or not), so its implicit surface F = 0
 * is extracted by marching tetrahedra: F is sampled on a grid over the box,
 * and in each tetrahedron the points where F changes sign along an edge
 * (linear interpolation) give one triangle or a quad.  Tetrahedra rather
 * than cubes need no case table and leave no ambiguous faces. */
#include <math.h>
#include <string.h>

#include "alloc.h"
#include "diag.h"
#include "mesh.h"

void mesh_init(struct mesh *m)
{
	memset(m, 0, sizeof(*m));
}

void mesh_free(struct mesh *m)
{
	rt_free(m->data);
	mesh_init(m);
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

static void mesh_put(struct mesh *m, struct vec3 p, struct vec3 n)
{
	float *v = m->data + m->n_vertices++ * RT_MESH_FLOATS_PER_VERTEX;

	v[0] = (float)p.x;
	v[1] = (float)p.y;
	v[2] = (float)p.z;
	v[3] = (float)n.x;
	v[4] = (float)n.y;
	v[5] = (float)n.z;
}

int mesh_add_triangle(struct mesh *m, const struct vec3 p[3], const struct vec3 n[3])
{
	struct vec3 face = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
	struct vec3 sum = vec3_add(n[0], vec3_add(n[1], n[2]));
	int rc;

	if ((rc = mesh_reserve(m, 3)) < 0)
		return rc;
	mesh_put(m, p[0], n[0]);
	if (vec3_dot(face, sum) >= 0.0) {
		mesh_put(m, p[1], n[1]);
		mesh_put(m, p[2], n[2]);
	} else {
		mesh_put(m, p[2], n[2]);
		mesh_put(m, p[1], n[1]);
	}
	return 0;
}

/* The unit direction at longitude i / slices, latitude j / stacks from the
 * +z pole. */
static struct vec3 sphere_direction(int i, int j, int slices, int stacks)
{
	const double pi = 3.14159265358979323846;
	double lon = 2.0 * pi * i / slices, lat = pi * j / stacks;

	return vec3_make(sin(lat) * cos(lon), sin(lat) * sin(lon), cos(lat));
}

int mesh_sphere(struct mesh *m, struct vec3 centre, double radius, int slices, int stacks)
{
	int i, j, rc;

	for (j = 0; j < stacks; j++) {
		for (i = 0; i < slices; i++) {
			struct vec3 n[4] = {
				sphere_direction(i, j, slices, stacks),
				sphere_direction(i, j + 1, slices, stacks),
				sphere_direction(i + 1, j + 1, slices, stacks),
				sphere_direction(i + 1, j, slices, stacks),
			};
			struct vec3 p[4], tri_p[3], tri_n[3];
			int k;

			for (k = 0; k < 4; k++)
				p[k] = vec3_add_scaled(centre, n[k], radius);
			/* The quads at the poles have two equal corners: one
			 * triangle each. */
			if (j < stacks - 1) {
				tri_p[0] = p[0], tri_p[1] = p[1], tri_p[2] = p[2];
				tri_n[0] = n[0], tri_n[1] = n[1], tri_n[2] = n[2];
				if ((rc = mesh_add_triangle(m, tri_p, tri_n)) < 0)
					return rc;
			}
			if (j > 0) {
				tri_p[0] = p[0], tri_p[1] = p[2], tri_p[2] = p[3];
				tri_n[0] = n[0], tri_n[1] = n[2], tri_n[2] = n[3];
				if ((rc = mesh_add_triangle(m, tri_p, tri_n)) < 0)
					return rc;
			}
		}
	}
	return 0;
}

double mesh_quadric_value(const double q[10], struct vec3 p)
{
	return q[0] * p.x * p.x + q[1] * p.y * p.y + q[2] * p.z * p.z +
	       q[3] * p.x * p.y + q[4] * p.x * p.z + q[5] * p.y * p.z +
	       q[6] * p.x + q[7] * p.y + q[8] * p.z + q[9];
}

struct vec3 mesh_quadric_gradient(const double q[10], struct vec3 p)
{
	return vec3_make(2.0 * q[0] * p.x + q[3] * p.y + q[4] * p.z + q[6],
			 2.0 * q[1] * p.y + q[3] * p.x + q[5] * p.z + q[7],
			 2.0 * q[2] * p.z + q[4] * p.x + q[5] * p.y + q[8]);
}

struct aabb mesh_quadric_region(const struct shape_geometry *g, struct aabb around)
{
	struct aabb box = around;

	if (g->u.quadric.clipped[0]) {
		box.min.x = g->u.quadric.lo.x;
		box.max.x = g->u.quadric.hi.x;
	}
	if (g->u.quadric.clipped[1]) {
		box.min.y = g->u.quadric.lo.y;
		box.max.y = g->u.quadric.hi.y;
	}
	if (g->u.quadric.clipped[2]) {
		box.min.z = g->u.quadric.lo.z;
		box.max.z = g->u.quadric.hi.z;
	}
	return box;
}

/* The six tetrahedra around the cube's diagonal from corner 0 to corner 7
 * (corner bit 0 is +x, bit 1 +y, bit 2 +z).  Neighbouring cubes split
 * their shared face along the same diagonal, so the surface has no cracks. */
static const int cube_tets[6][4] = {
	{ 0, 1, 3, 7 }, { 0, 3, 2, 7 }, { 0, 2, 6, 7 },
	{ 0, 6, 4, 7 }, { 0, 4, 5, 7 }, { 0, 5, 1, 7 },
};

struct march {
	struct mesh *m;
	const double *coef;
};

/* The point on edge (a, b) where the linear interpolation of F is zero;
 * fa and fb have opposite signs (one may be zero). */
static struct vec3 edge_point(struct vec3 a, struct vec3 b, double fa, double fb)
{
	double t = fa / (fa - fb);

	return vec3_add_scaled(a, vec3_sub(b, a), t);
}

static int march_emit(const struct march *mc, const struct vec3 p[3])
{
	struct vec3 n[3];
	int k;

	for (k = 0; k < 3; k++) {
		n[k] = vec3_normalize(mesh_quadric_gradient(mc->coef, p[k]));
		/* At a singular point (a cone's apex) use the face normal. */
		if (n[k].x == 0.0 && n[k].y == 0.0 && n[k].z == 0.0)
			n[k] = vec3_normalize(vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0])));
	}
	return mesh_add_triangle(mc->m, p, n);
}

static int march_tet(const struct march *mc, const struct vec3 v[4], const double f[4])
{
	int in[4], out[4], n_in = 0, n_out = 0, k;
	struct vec3 t[3];

	for (k = 0; k < 4; k++) {
		if (f[k] < 0.0)
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
			t[k] = edge_point(v[lone], v[others[k]], f[lone], f[others[k]]);
		return march_emit(mc, t);
	}
	{
		/* Two in, two out: the quad through the four crossing edges,
		 * in order around it. */
		struct vec3 q[4] = {
			edge_point(v[in[0]], v[out[0]], f[in[0]], f[out[0]]),
			edge_point(v[in[0]], v[out[1]], f[in[0]], f[out[1]]),
			edge_point(v[in[1]], v[out[1]], f[in[1]], f[out[1]]),
			edge_point(v[in[1]], v[out[0]], f[in[1]], f[out[0]]),
		};
		int rc;

		t[0] = q[0], t[1] = q[1], t[2] = q[2];
		if ((rc = march_emit(mc, t)) < 0)
			return rc;
		t[0] = q[0], t[1] = q[2], t[2] = q[3];
		return march_emit(mc, t);
	}
}

int mesh_quadric(struct mesh *m, const double coef[10], struct aabb box, const int cells[3])
{
	const int nx = cells[0] + 1, ny = cells[1] + 1, nz = cells[2] + 1;
	struct vec3 step = vec3_make((box.max.x - box.min.x) / cells[0],
				     (box.max.y - box.min.y) / cells[1],
				     (box.max.z - box.min.z) / cells[2]);
	struct march mc = { m, coef };
	double *f;
	int i, j, k, c, rc = 0;

	f = rt_reallocarray(NULL, (size_t)nx * ny * nz, sizeof(*f));
	if (!f)
		return -RT_E_NOMEM;
	for (k = 0; k < nz; k++)
		for (j = 0; j < ny; j++)
			for (i = 0; i < nx; i++)
				f[((size_t)k * ny + j) * nx + i] = mesh_quadric_value(coef,
					vec3_make(box.min.x + i * step.x, box.min.y + j * step.y,
						  box.min.z + k * step.z));
	for (k = 0; k < cells[2] && rc == 0; k++) {
		for (j = 0; j < cells[1] && rc == 0; j++) {
			for (i = 0; i < cells[0] && rc == 0; i++) {
				struct vec3 cv[8];
				double cf[8];
				for (c = 0; c < 8; c++) {
					int ci = i + (c & 1), cj = j + (c >> 1 & 1), ck = k + (c >> 2 & 1);
					cv[c] = vec3_make(box.min.x + ci * step.x, box.min.y + cj * step.y,
							  box.min.z + ck * step.z);
					cf[c] = f[((size_t)ck * ny + cj) * nx + ci];
				}
				for (c = 0; c < 6 && rc == 0; c++) {
					struct vec3 tv[4];
					double tf[4];
					int t;
					for (t = 0; t < 4; t++) {
						tv[t] = cv[cube_tets[c][t]];
						tf[t] = cf[cube_tets[c][t]];
					}
					rc = march_tet(&mc, tv, tf);
				}
			}
		}
	}
	rt_free(f);
	return rc;
}
