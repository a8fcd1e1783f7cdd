/* The viewer's meshes: vertices on the surface, unit normals that point the
 * way the shape's normal does, windings that agree with them, and clipped
 * quadrics that stay inside their box. */
#include <math.h>

#include "support.h"
#include "mesh.h"

static struct vec3 vertex(const struct mesh *m, size_t i, struct vec3 *normal)
{
	const float *v = m->data + i * RT_MESH_FLOATS_PER_VERTEX;

	*normal = vec3_make(v[3], v[4], v[5]);
	return vec3_make(v[0], v[1], v[2]);
}

/* Every triangle: unit normals, counter-clockwise about them, and not
 * degenerate. */
static void assert_well_formed(const struct mesh *m)
{
	size_t i;

	assert_true(m->n_vertices > 0);
	assert_int_equal(m->n_vertices % 3, 0);
	for (i = 0; i < m->n_vertices; i += 3) {
		struct vec3 n[3], p[3], face;
		int k;
		for (k = 0; k < 3; k++) {
			p[k] = vertex(m, i + k, &n[k]);
			assert_near(vec3_length(n[k]), 1.0, 1e-6);
		}
		face = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
		assert_true(vec3_dot(face, vec3_add(n[0], vec3_add(n[1], n[2]))) >= 0.0);
	}
}

static void test_mesh_sphere(void **state)
{
	struct vec3 centre = vec3_make(40, 0, 10);
	struct mesh m;
	size_t i;

	(void)state;
	mesh_init(&m);
	assert_int_equal(mesh_sphere(&m, centre, 10.0, 24, 12), 0);
	/* Two triangles per quad, one per quad at each pole. */
	assert_int_equal(m.n_vertices, 3 * (2 * 24 * 12 - 2 * 24));
	assert_well_formed(&m);
	for (i = 0; i < m.n_vertices; i++) {
		struct vec3 n, p = vertex(&m, i, &n);
		assert_near(vec3_length(vec3_sub(p, centre)), 10.0, 1e-5);
		assert_vec3_near(n, vec3_normalize(vec3_sub(p, centre)), 1e-5);
	}
	mesh_free(&m);
}

/* The course's example general: the sphere of radius 10 about (10,10,10),
 * 1 1 1 0 0 0 -20 -20 -20 200. */
static const double ball[10] = { 1, 1, 1, 0, 0, 0, -20, -20, -20, 200 };

static void test_mesh_quadric_sphere(void **state)
{
	struct aabb box = { { -5, -5, -5 }, { 25, 25, 25 } };
	const int cells[3] = { 30, 30, 30 };
	struct vec3 centre = vec3_make(10, 10, 10);
	struct mesh m;
	size_t i;

	(void)state;
	assert_near(mesh_quadric_value(ball, vec3_make(20, 10, 10)), 0.0, 0.0);
	assert_vec3_near(mesh_quadric_gradient(ball, vec3_make(20, 10, 10)), vec3_make(20, 0, 0), 0.0);
	mesh_init(&m);
	assert_int_equal(mesh_quadric(&m, ball, box, cells), 0);
	assert_well_formed(&m);
	for (i = 0; i < m.n_vertices; i++) {
		struct vec3 n, p = vertex(&m, i, &n);
		/* Linear interpolation across 1-unit cells: within a cell's
		 * sagitta of the true surface. */
		assert_near(vec3_length(vec3_sub(p, centre)), 10.0, 0.1);
		assert_true(vec3_dot(n, vec3_normalize(vec3_sub(p, centre))) > 0.99);
	}
	mesh_free(&m);
}

static void test_mesh_quadric_clipped(void **state)
{
	struct shape_geometry g = { .kind = RT_SHAPE_QUADRIC };
	struct aabb around = { { -100, -100, -100 }, { 100, 100, 100 } }, box;
	const int cells[3] = { 40, 40, 10 };
	struct mesh m;
	size_t i;
	int k;

	(void)state;
	for (k = 0; k < 10; k++)
		g.u.quadric.coef[k] = ball[k];
	g.u.quadric.lo = vec3_make(0, 0, 0);
	g.u.quadric.hi = vec3_make(0, 0, 5);
	g.u.quadric.clipped[2] = true;
	box = mesh_quadric_region(&g, around);
	assert_vec3_near(box.min, vec3_make(-100, -100, 0), 0.0);
	assert_vec3_near(box.max, vec3_make(100, 100, 5), 0.0);
	mesh_init(&m);
	assert_int_equal(mesh_quadric(&m, ball, box, cells), 0);
	assert_well_formed(&m);
	for (i = 0; i < m.n_vertices; i++) {
		struct vec3 n, p = vertex(&m, i, &n);
		assert_true(p.z >= 0.0 && p.z <= 5.0);
	}
	mesh_free(&m);
}

/* A plane (x = 3) and a surface that misses the box. */
static void test_mesh_quadric_plane_and_empty(void **state)
{
	const double plane[10] = { 0, 0, 0, 0, 0, 0, 1, 0, 0, -3 };
	struct aabb box = { { -10, -10, -10 }, { 10, 10, 10 } };
	const int cells[3] = { 7, 5, 5 };
	struct mesh m;
	size_t i;

	(void)state;
	mesh_init(&m);
	assert_int_equal(mesh_quadric(&m, plane, box, cells), 0);
	assert_well_formed(&m);
	for (i = 0; i < m.n_vertices; i++) {
		struct vec3 n, p = vertex(&m, i, &n);
		assert_near(p.x, 3.0, 1e-5);
		assert_vec3_near(n, vec3_make(1, 0, 0), 0.0);
	}
	mesh_free(&m);
	box.min.x = 50;
	box.max.x = 60;
	assert_int_equal(mesh_quadric(&m, ball, box, cells), 0);
	assert_int_equal(m.n_vertices, 0);
	mesh_free(&m);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_mesh_sphere),
		cmocka_unit_test(test_mesh_quadric_sphere),
		cmocka_unit_test(test_mesh_quadric_clipped),
		cmocka_unit_test(test_mesh_quadric_plane_and_empty),
	};
	return SUPPORT_RUN(tests, argc, argv);
}
