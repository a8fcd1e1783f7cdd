/* The mesh helpers (src/shapes/mesh.c): windings that agree with the
 * normals, the box, the texture, the grid's cells, and marching tetrahedra
 * over fields of the test's own: vertices on the surface, unit normals
 * along the gradient, and nothing outside the box. */
#include <math.h>

#include "support.h"
#include "whitted/mesh.h"

static struct vec3 centroid(const struct mesh *m, size_t i)
{
	struct vec3 sum = vec3_add(mesh_vertex(m, i, NULL, NULL),
				   vec3_add(mesh_vertex(m, i + 1, NULL, NULL),
					    mesh_vertex(m, i + 2, NULL, NULL)));

	return vec3_scale(sum, 1.0 / 3.0);
}

/* Every triangle: unit normals, and counter-clockwise about them. */
static void assert_well_formed(const struct mesh *m)
{
	size_t i;

	assert_true(m->n_vertices > 0);
	assert_int_equal(m->n_vertices % 3, 0);
	for (i = 0; i < m->n_vertices; i += 3) {
		struct vec3 n[3], p[3], face;
		int k;
		for (k = 0; k < 3; k++) {
			p[k] = mesh_vertex(m, i + k, &n[k], NULL);
			assert_near(vec3_length(n[k]), 1.0, 1e-6);
		}
		face = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
		assert_true(vec3_dot(face, vec3_add(n[0], vec3_add(n[1], n[2]))) >= 0.0);
	}
}

static void test_mesh_add_triangle_turns_to_the_normals(void **state)
{
	const struct vec3 p[3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
	const struct vec3 down[3] = { { 0, 0, -1 }, { 0, 0, -1 }, { 0, 0, -1 } };
	const struct mesh_uv uv[3] = { { 0, 0 }, { 0.5, 0 }, { 0, 0.25 } };
	struct mesh_uv got;
	struct vec3 n;
	struct mesh m;

	(void)state;
	mesh_init(&m);
	assert_int_equal(mesh_add_triangle_uv(&m, p, down, uv), 0);
	assert_int_equal(m.n_vertices, 3);
	assert_well_formed(&m);
	/* The first vertex stays; the other two swap, with their normals and
	 * texture coordinates. */
	assert_vec3_near(mesh_vertex(&m, 0, &n, NULL), p[0], 0.0);
	assert_vec3_near(mesh_vertex(&m, 1, &n, &got), p[2], 0.0);
	assert_vec3_near(n, down[2], 0.0);
	assert_near(got.u, 0.0, 0.0);
	assert_near(got.v, 0.25, 0.0);
	assert_vec3_near(mesh_vertex(&m, 2, &n, &got), p[1], 0.0);
	assert_near(got.u, 0.5, 0.0);
	assert_near(got.v, 0.0, 0.0);
	/* Without texture coordinates: 0. */
	assert_int_equal(mesh_add_triangle(&m, p, down), 0);
	mesh_vertex(&m, 5, NULL, &got);
	assert_near(got.u, 0.0, 0.0);
	assert_near(got.v, 0.0, 0.0);
	mesh_free(&m);
	assert_null(m.data);
	assert_int_equal(m.n_vertices, 0);
}

static void test_mesh_clear_keeps_the_memory(void **state)
{
	const struct vec3 p[3] = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
	const struct vec3 up[3] = { { 0, 0, 1 }, { 0, 0, 1 }, { 0, 0, 1 } };
	const struct color white = { 1, 1, 1 };
	struct mesh m;
	float *data;

	(void)state;
	mesh_init(&m);
	assert_int_equal(mesh_add_triangle(&m, p, up), 0);
	assert_int_equal(mesh_set_texture(&m, 1, 1, &white), 0);
	data = m.data;
	mesh_clear(&m);
	assert_int_equal(m.n_vertices, 0);
	assert_int_equal(m.texture.width, 0);
	assert_int_equal(mesh_add_triangle(&m, p, up), 0);
	assert_ptr_equal(m.data, data);
	assert_int_equal(m.n_vertices, 3);
	mesh_free(&m);
}

static void test_mesh_box_faces(void **state)
{
	struct aabb box = { { -1, 2, 3 }, { 4, 5, 9 } };
	struct mesh m;
	size_t i;

	(void)state;
	mesh_init(&m);
	assert_int_equal(mesh_box(&m, box), 0);
	assert_int_equal(m.n_vertices, 36);
	assert_well_formed(&m);
	for (i = 0; i < m.n_vertices; i += 3) {
		struct vec3 n, c = centroid(&m, i), p;
		int k;
		for (k = 0; k < 3; k++) {
			/* A corner of the box. */
			p = mesh_vertex(&m, i + k, &n, NULL);
			assert_true(p.x == box.min.x || p.x == box.max.x);
			assert_true(p.y == box.min.y || p.y == box.max.y);
			assert_true(p.z == box.min.z || p.z == box.max.z);
		}
		/* The normal points out of the box: from its centre to the face. */
		assert_true(vec3_dot(n, vec3_sub(c, aabb_centre(box))) > 0.0);
		assert_near(fabs(n.x) + fabs(n.y) + fabs(n.z), 1.0, 0.0);
	}
	mesh_free(&m);
}

/* Texel (floor(u w) mod w, floor(v h) mod h), row after row, negative
 * coordinates included; too many texels are refused. */
static void test_mesh_texture_repeats(void **state)
{
	static const struct color texels[6] = {
		{ 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 1, 1, 0 }, { 1, 1, 1 },
	};
	static const struct {
		struct mesh_uv uv;
		int texel;
	} cases[] = {
		{ { 0.0, 0.0 }, 0 }, { { 0.4, 0.0 }, 1 }, { { 0.7, 0.3 }, 2 },
		{ { 0.1, 0.6 }, 3 }, { { 0.5, 0.99 }, 4 }, { { 1.9, 2.9 }, 5 },
		{ { -0.1, 0.0 }, 2 }, { { 0.0, -0.1 }, 3 }, { { -2.5, -1.1 }, 4 },
	};
	struct mesh m;
	size_t k;

	(void)state;
	mesh_init(&m);
	assert_int_equal(mesh_set_texture(&m, 3, 2, texels), 0);
	for (k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
		struct color c = mesh_texture_at(&m, cases[k].uv), want = texels[cases[k].texel];
		assert_true(c.r == want.r && c.g == want.g && c.b == want.b);
	}
	assert_int_equal(mesh_set_texture(&m, RT_MESH_TEXELS_MAX / 8 + 1, 8, texels), -RT_E_RANGE);
	assert_int_equal(mesh_set_texture(&m, 0, 1, texels), -RT_E_RANGE);
	assert_int_equal(m.texture.width, 3);
	mesh_free(&m);
}

static void test_mesh_grid_cells_in_proportion(void **state)
{
	struct aabb box = { { 0, 0, 0 }, { 100, 50, 1 } };
	struct aabb flat = { { 0, 0, 0 }, { 0, 0, 0 } };
	int cells[3];

	(void)state;
	mesh_grid_cells(box, 64, cells);
	assert_int_equal(cells[0], 64);
	assert_int_equal(cells[1], 32);
	assert_int_equal(cells[2], 4);	/* ceil(0.64), raised to 4 */
	mesh_grid_cells(flat, 64, cells);
	assert_int_equal(cells[0], 4);
	assert_int_equal(cells[1], 4);
	assert_int_equal(cells[2], 4);
}

/* The test's own fields: the ball |p - c| = r, and the plane x = 3. */
struct ball {
	struct vec3 centre;
	double radius;
};

static double ball_value(const void *ctx, struct vec3 p)
{
	const struct ball *b = ctx;
	struct vec3 d = vec3_sub(p, b->centre);

	return vec3_dot(d, d) - b->radius * b->radius;
}

static struct vec3 ball_gradient(const void *ctx, struct vec3 p)
{
	const struct ball *b = ctx;

	return vec3_scale(vec3_sub(p, b->centre), 2.0);
}

static double plane_value(const void *ctx, struct vec3 p)
{
	(void)ctx;
	return p.x - 3.0;
}

static struct vec3 plane_gradient(const void *ctx, struct vec3 p)
{
	(void)ctx;
	(void)p;
	return vec3_make(1, 0, 0);
}

static const struct ball ball = { { 10, 10, 10 }, 10 };
static const struct mesh_field ball_field = { ball_value, ball_gradient, &ball };

/* mesh_implicit of field f over box in cells succeeds with a well-formed
 * mesh, and check holds for each of its vertices and their normals. */
static void check_implicit(const struct mesh_field *f, struct aabb box, const int cells[3],
			   void (*check)(struct vec3 p, struct vec3 n))
{
	struct mesh m;
	size_t i;

	mesh_init(&m);
	assert_int_equal(mesh_implicit(&m, f, box, cells), 0);
	assert_well_formed(&m);
	for (i = 0; i < m.n_vertices; i++) {
		struct vec3 n, p = mesh_vertex(&m, i, &n, NULL);
		check(p, n);
	}
	mesh_free(&m);
}

/* Linear interpolation across 1-unit cells: within a cell's sagitta of
 * the true surface. */
static void on_ball(struct vec3 p, struct vec3 n)
{
	assert_near(vec3_length(vec3_sub(p, ball.centre)), 10.0, 0.1);
	assert_true(vec3_dot(n, vec3_normalize(vec3_sub(p, ball.centre))) > 0.99);
}

static void test_mesh_implicit_ball(void **state)
{
	struct aabb box = { { -5, -5, -5 }, { 25, 25, 25 } };
	const int cells[3] = { 30, 30, 30 };

	(void)state;
	check_implicit(&ball_field, box, cells, on_ball);
}

static void in_slab(struct vec3 p, struct vec3 n)
{
	(void)n;
	assert_true(p.z >= 0.0 && p.z <= 5.0);
}

/* Only the part of the surface inside the box: a slab of the ball. */
static void test_mesh_implicit_stays_in_the_box(void **state)
{
	struct aabb box = { { -100, -100, 0 }, { 100, 100, 5 } };
	const int cells[3] = { 40, 40, 10 };

	(void)state;
	check_implicit(&ball_field, box, cells, in_slab);
}

static void on_plane(struct vec3 p, struct vec3 n)
{
	assert_near(p.x, 3.0, 1e-5);
	assert_vec3_near(n, vec3_make(1, 0, 0), 0.0);
}

/* A plane, exact for linear interpolation, and a surface that misses the
 * box. */
static void test_mesh_implicit_plane_and_empty(void **state)
{
	const struct mesh_field plane = { plane_value, plane_gradient, NULL };
	struct aabb box = { { -10, -10, -10 }, { 10, 10, 10 } };
	const int cells[3] = { 7, 5, 5 };
	struct mesh m;

	(void)state;
	check_implicit(&plane, box, cells, on_plane);
	box.min.x = 50;
	box.max.x = 60;
	mesh_init(&m);
	assert_int_equal(mesh_implicit(&m, &ball_field, box, cells), 0);
	assert_int_equal(m.n_vertices, 0);
	mesh_free(&m);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_mesh_add_triangle_turns_to_the_normals,
			   test_mesh_clear_keeps_the_memory, test_mesh_box_faces,
			   test_mesh_texture_repeats, test_mesh_grid_cells_in_proportion,
			   test_mesh_implicit_ball, test_mesh_implicit_stays_in_the_box,
			   test_mesh_implicit_plane_and_empty))
