/* shape_tessellate: each primitive's mesh lies on its surface, with unit
 * normals that agree with shape_normal and the shape's colours; the
 * sphere's grid, the quadric's region, the floor's texture, the infinite
 * floor's region; and a primitive without the method falls back to its
 * bounding box, or to nothing. */
#include <math.h>

#include "support.h"
#include "whitted/mesh.h"

static const struct mesh_options options = { { { -20, -20, -20 }, { 30, 30, 30 } }, 32 };

/* A shape of each primitive, quadrics clipped on every axis, on some and
 * on none. */
static const char scene_text[] =
	"1 10 5\n"
	"sphere 1 2 3 4  1 0 0  0.4 0.2 0.2 0.2 10\n"
	"triangle 0 0 0  1 0 0  0 1 5  0 1 0  0.4 0.2 0.2 0.2 10\n"
	"general 1 1 1 0 0 0 -20 -20 -20 200  -1 -2 0  4 0 5  0 0 1  0.4 0.2 0.1 0.3 3\n"
	"general 1 1 0 0 0 0 0 0 0 -25  0 0 0  0 0 0  0 0 1  0.4 0.2 0.1 0.3 3\n"
	"general 1 1 -1 0 0 0 0 0 0 -16  -15 -15 -10  30 30 20  0 0 1  0.4 0.2 0.1 0.3 3\n"
	"0\n";

/* The point at barycentric weights w of the triangle whose first vertex
 * is i, and its texture coordinates. */
static struct vec3 mesh_point(const struct mesh *m, size_t i, const double w[3],
			      struct mesh_uv *uv)
{
	struct vec3 p = vec3_make(0, 0, 0);
	size_t k;

	uv->u = uv->v = 0.0;
	for (k = 0; k < 3; k++) {
		struct mesh_uv vk;
		p = vec3_add_scaled(p, mesh_vertex(m, i + k, NULL, &vk), w[k]);
		uv->u += w[k] * vk.u;
		uv->v += w[k] * vk.v;
	}
	return p;
}

static const double centroid_w[3] = { 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0 };

static bool near_face(double x, double lo, double hi, double tol)
{
	return hi - lo > tol && (fabs(x - lo) < tol || fabs(x - hi) < tol);
}

/* Within the shape's bounds on the axes it has them, and within the
 * region around it on the others. */
static void assert_inside(const struct shape *s, const struct mesh_options *opt, struct vec3 p)
{
	struct aabb b;
	int axis;

	shape_bounds(s, &b);
	for (axis = 0; axis < 3; axis++) {
		double x = vec3_component(p, axis), lo = vec3_component(b.min, axis);
		double hi = vec3_component(b.max, axis);
		if (!isfinite(lo)) {
			lo = vec3_component(opt->around.min, axis);
			hi = vec3_component(opt->around.max, axis);
		}
		assert_true(x >= lo - 1e-4 && x <= hi + 1e-4);
	}
}

/* A ray from h outside the triangle's centroid back along its normal meets
 * the shape about h away: the mesh lies on the surface.  Centroids at the
 * edge of a clipped shape are left out, where the ray may fall just past
 * the clip. */
static void assert_centroid_on_surface(const struct shape *s, const struct mesh *m, size_t i)
{
	const double h = 1.0, tol = 0.1;
	struct mesh_uv uv;
	struct vec3 n0, n1, n2, c = mesh_point(m, i, centroid_w, &uv), n;
	struct ray r;
	struct aabb b;
	double t = 2.0 * h;
	int axis;

	shape_bounds(s, &b);
	for (axis = 0; axis < 3; axis++)
		if (near_face(vec3_component(c, axis), vec3_component(b.min, axis),
			      vec3_component(b.max, axis), tol))
			return;
	mesh_vertex(m, i, &n0, NULL);
	mesh_vertex(m, i + 1, &n1, NULL);
	mesh_vertex(m, i + 2, &n2, NULL);
	n = vec3_normalize(vec3_add(n0, vec3_add(n1, n2)));
	r.origin = vec3_add_scaled(c, n, h);
	r.dir = vec3_scale(n, -1.0);
	assert_true(shape_intersect(s, &r, 0.0, &t));
	assert_near(t, h, tol);
}

/* The mesh's colour (the material's, or the texture's) is the shape's,
 * at the centroid and near each corner. */
static void assert_colours(const struct shape *s, const struct mesh *m, size_t i)
{
	static const double w[4][3] = {
		{ 1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0 },
		{ 0.98, 0.01, 0.01 }, { 0.01, 0.98, 0.01 }, { 0.01, 0.01, 0.98 },
	};
	size_t k;

	for (k = 0; k < 4; k++) {
		struct mesh_uv uv;
		struct vec3 p = mesh_point(m, i, w[k], &uv);
		struct color want = shape_color_at(s, p);
		struct color got = m->texture.width ? mesh_texture_at(m, uv) : s->mat.color;
		assert_true(got.r == want.r && got.g == want.g && got.b == want.b);
	}
}

/* Everything a mesh promises, for any shape. */
static void assert_mesh_of(const struct shape *s, const struct mesh_options *opt)
{
	struct mesh m;
	size_t i;

	mesh_init(&m);
	assert_true(shape_tessellates(s));
	assert_int_equal(shape_tessellate(s, opt, &m), 0);
	assert_true(m.n_vertices > 0);
	assert_int_equal(m.n_vertices % 3, 0);
	for (i = 0; i < m.n_vertices; i += 3) {
		struct vec3 p[3], n[3], face;
		int k;
		for (k = 0; k < 3; k++) {
			p[k] = mesh_vertex(&m, i + k, &n[k], NULL);
			assert_near(vec3_length(n[k]), 1.0, 1e-6);
			assert_inside(s, opt, p[k]);
		}
		/* The shape's normal at each corner, taken a little way in
		 * towards the centroid: at a solid's edge or corner, where
		 * faces meet, its normal may be any of theirs. */
		for (k = 0; k < 3; k++) {
			struct vec3 c = vec3_scale(vec3_add(p[0], vec3_add(p[1], p[2])), 1.0 / 3.0);
			struct vec3 in = vec3_add_scaled(p[k], vec3_sub(c, p[k]), 1e-4);
			assert_true(vec3_dot(n[k], shape_normal(s, in)) > 0.999);
		}
		face = vec3_cross(vec3_sub(p[1], p[0]), vec3_sub(p[2], p[0]));
		assert_true(vec3_dot(face, vec3_add(n[0], vec3_add(n[1], n[2]))) >= 0.0);
		assert_centroid_on_surface(s, &m, i);
		assert_colours(s, &m, i);
	}
	mesh_free(&m);
}

/* Tessellating s over o (into m, cleared first) gives no vertex. */
static void assert_meshes_nothing(const struct shape *s, const struct mesh_options *o,
				  struct mesh *m)
{
	mesh_clear(m);
	assert_int_equal(shape_tessellate(s, o, m), 0);
	assert_int_equal(m->n_vertices, 0);
}

static void test_shape_tessellate_every_primitive(void **state)
{
	struct scene *s = support_parse(scene_text);
	/* Quads of side 1 over cells of 3: the points assert_colours takes
	 * are never within float rounding of a cell's edge. */
	struct shape *fl = floor_create(96.0, 3.0);
	/* nearfar's floor, pyramid and cube, and the pyramid dialect's
	 * pyramid (no scene text: each dialect reads its own). */
	const struct material mat = { { 1, 0, 0 }, 0.4, 0.2, 0.2, 0.2, 10, 0.0, 1.0 };
	struct shape *more[4];
	size_t i;

	(void)state;
	more[0] = floor_create_view(INFINITY, 3.0, &mat);
	more[1] = pyramid_create(vec3_make(-5, 2, 1), 8.0, 12.0, &mat);
	more[2] = pyramid_create_centred(vec3_make(10, -3, -2), 6.0, 4.0, &mat);
	more[3] = cube_create(vec3_make(-10, -12, 3), 7.0, &mat);
	assert_non_null(fl);
	assert_int_equal(s->n_shapes, 5);
	for (i = 0; i < s->n_shapes; i++)
		assert_mesh_of(s->shapes[i], &options);
	assert_mesh_of(fl, &options);
	for (i = 0; i < 4; i++) {
		assert_non_null(more[i]);
		assert_mesh_of(more[i], &options);
		shape_destroy(more[i]);
	}
	shape_destroy(fl);
	scene_destroy(s);
}

static void test_shape_tessellate_sphere_grid(void **state)
{
	const struct mesh_options opt = { options.around, 24 };
	const struct material mat = { { 1, 1, 1 }, 0.4, 0.2, 0.2, 0.2, 10, 0.0, 1.0 };
	struct vec3 centre = vec3_make(40, 0, 10);
	struct shape *s = sphere_create(centre, 10.0, &mat);
	struct mesh m;
	size_t i;

	(void)state;
	assert_non_null(s);
	mesh_init(&m);
	assert_int_equal(shape_tessellate(s, &opt, &m), 0);
	/* 24 slices and 12 stacks: two triangles per quad, one per quad at
	 * each pole. */
	assert_int_equal(m.n_vertices, 3 * (2 * 24 * 12 - 2 * 24));
	for (i = 0; i < m.n_vertices; i++) {
		struct vec3 n, p = mesh_vertex(&m, i, &n, NULL);
		assert_near(vec3_length(vec3_sub(p, centre)), 10.0, 1e-5);
		assert_vec3_near(n, vec3_normalize(vec3_sub(p, centre)), 1e-5);
	}
	mesh_free(&m);
	shape_destroy(s);
}

static void test_shape_tessellate_triangle(void **state)
{
	const struct material mat = { { 1, 1, 1 }, 0.4, 0.2, 0.2, 0.2, 10, 0.0, 1.0 };
	struct shape *t = triangle_create(vec3_make(0, 0, 0), vec3_make(2, 0, 0), vec3_make(0, 3, 0),
					  &mat);
	struct shape *flat = triangle_create(vec3_make(0, 0, 0), vec3_make(1, 1, 1),
					     vec3_make(2, 2, 2), &mat);
	struct mesh m;

	(void)state;
	assert_non_null(t);
	assert_non_null(flat);
	mesh_init(&m);
	assert_int_equal(shape_tessellate(t, &options, &m), 0);
	assert_int_equal(m.n_vertices, 3);
	assert_vec3_near(mesh_vertex(&m, 0, NULL, NULL), vec3_make(0, 0, 0), 0.0);
	assert_vec3_near(mesh_vertex(&m, 1, NULL, NULL), vec3_make(2, 0, 0), 0.0);
	assert_vec3_near(mesh_vertex(&m, 2, NULL, NULL), vec3_make(0, 3, 0), 0.0);
	/* A degenerate triangle has nothing to draw. */
	assert_meshes_nothing(flat, &options, &m);
	mesh_free(&m);
	shape_destroy(t);
	shape_destroy(flat);
}

/* The course's example general, the sphere of radius 10 about (10,10,10):
 * unclipped, it is meshed whole inside the region; clipped in z, only the
 * slab; in a region that misses it, not at all. */
static void test_shape_tessellate_quadric_region(void **state)
{
	static const double ball[10] = { 1, 1, 1, 0, 0, 0, -20, -20, -20, 200 };
	const struct material mat = { { 1, 1, 1 }, 0.4, 0.2, 0.2, 0.2, 10, 0.0, 1.0 };
	struct shape *whole = quadric_create(ball, vec3_make(0, 0, 0), vec3_make(0, 0, 0), &mat);
	struct shape *slab = quadric_create(ball, vec3_make(0, 0, 0), vec3_make(0, 0, 5), &mat);
	struct mesh_options far = { { { 50, 50, 50 }, { 60, 60, 60 } }, 32 };
	struct mesh m;
	size_t i;

	(void)state;
	assert_non_null(whole);
	assert_non_null(slab);
	assert_mesh_of(whole, &options);
	assert_mesh_of(slab, &options);
	mesh_init(&m);
	assert_int_equal(shape_tessellate(whole, &options, &m), 0);
	for (i = 0; i < m.n_vertices; i++)
		assert_near(vec3_length(vec3_sub(mesh_vertex(&m, i, NULL, NULL), vec3_make(10, 10, 10))),
			    10.0, 0.1);
	mesh_clear(&m);
	assert_int_equal(shape_tessellate(slab, &options, &m), 0);
	for (i = 0; i < m.n_vertices; i++) {
		struct vec3 p = mesh_vertex(&m, i, NULL, NULL);
		assert_true(p.z >= 0.0 && p.z <= 5.0);
	}
	assert_meshes_nothing(whole, &far, &m);
	mesh_free(&m);
	shape_destroy(whole);
	shape_destroy(slab);
}

/* The triangles' total area. */
static double mesh_area(const struct mesh *m)
{
	double area = 0.0;
	size_t i;

	for (i = 0; i < m->n_vertices; i += 3) {
		struct vec3 a = mesh_vertex(m, i, NULL, NULL), b = mesh_vertex(m, i + 1, NULL, NULL);
		struct vec3 c = mesh_vertex(m, i + 2, NULL, NULL);
		area += 0.5 * vec3_length(vec3_cross(vec3_sub(b, a), vec3_sub(c, a)));
	}
	return area;
}

/* The floor is covered by 3 * segments quads a side, and its 2 x 2
 * texture gives each point the colour of its cell, however small the
 * cells are (here 1536 a side, under quads of side 4: exact in floats, and
 * assert_colours's points stay 0.04 or more from the cells' edges). */
static void test_shape_tessellate_floor_texture(void **state)
{
	struct shape *fl = floor_create(100.0, 7.0), *fine = floor_create(384.0, 0.25);
	const struct mesh_options coarse = { options.around, 10 };
	struct mesh m;
	size_t i;

	(void)state;
	assert_non_null(fl);
	assert_non_null(fine);
	mesh_init(&m);
	assert_int_equal(shape_tessellate(fl, &coarse, &m), 0);
	assert_int_equal(m.n_vertices, 6 * 30 * 30);
	assert_near(mesh_area(&m), 100.0 * 100.0, 1e-2);
	assert_int_equal(m.texture.width, 2);
	assert_int_equal(m.texture.height, 2);
	mesh_clear(&m);
	assert_int_equal(shape_tessellate(fine, &options, &m), 0);
	assert_int_equal(m.n_vertices, 6 * 96 * 96);
	for (i = 0; i < m.n_vertices; i += 3)
		assert_colours(fine, &m, i);
	mesh_free(&m);
	shape_destroy(fl);
	shape_destroy(fine);
}

/* The infinite floor is meshed over the x and y of the region around the
 * scene, at z = 0 even when the region lies above it, with the texture of
 * its own cells (cell (0, 0) from the origin); a region without extent
 * gives nothing. */
static void test_shape_tessellate_infinite_floor(void **state)
{
	const struct material mat = { { 1, 1, 1 }, 0.1, 0.3, 0, 0.6, 1, 0.0, 1.0 };
	struct shape *fl = floor_create_view(INFINITY, 2.0, &mat);
	const struct mesh_options above = { { { -30, 10, 5 }, { -6, 34, 29 } }, 8 };
	const struct mesh_options flat = { { { 1, 1, 1 }, { 1, 1, 1 } }, 8 };
	struct mesh m;
	size_t i;

	(void)state;
	assert_non_null(fl);
	mesh_init(&m);
	assert_true(shape_tessellates(fl));
	assert_int_equal(shape_tessellate(fl, &above, &m), 0);
	assert_int_equal(m.n_vertices, 6 * 24 * 24);
	assert_near(mesh_area(&m), 24.0 * 24.0, 1e-6);
	assert_int_equal(m.texture.width, 2);
	for (i = 0; i < m.n_vertices; i++) {
		struct vec3 p = mesh_vertex(&m, i, NULL, NULL);
		assert_true(p.x >= -30 && p.x <= -6 && p.y >= 10 && p.y <= 34 && p.z == 0);
	}
	for (i = 0; i < m.n_vertices; i += 3)
		assert_colours(fl, &m, i);
	assert_meshes_nothing(fl, &flat, &m);
	mesh_free(&m);
	shape_destroy(fl);
}

/* Primitives of the test's own without a tessellate method: one bounded,
 * one not. */
static bool boxed_bounds(const struct shape *s, struct aabb *out)
{
	(void)s;
	out->min = vec3_make(-1, 2, 3);
	out->max = vec3_make(4, 5, 9);
	return true;
}

static const struct shape_ops boxed_ops = { .keyword = "boxed", .bounds = boxed_bounds };
static const struct shape_ops endless_ops = { .keyword = "endless" };

static void test_shape_tessellate_fallback(void **state)
{
	const struct material mat = { { 1, 1, 1 }, 0.4, 0.2, 0.2, 0.2, 10, 0.0, 1.0 };
	const struct shape boxed = { &boxed_ops, mat }, endless = { &endless_ops, mat };
	struct mesh m;
	size_t i;

	(void)state;
	assert_false(shape_tessellates(&boxed));
	assert_false(shape_tessellates(&endless));
	mesh_init(&m);
	/* The bounding box's twelve triangles. */
	assert_int_equal(shape_tessellate(&boxed, &options, &m), 0);
	assert_int_equal(m.n_vertices, 36);
	for (i = 0; i < m.n_vertices; i++) {
		struct vec3 p = mesh_vertex(&m, i, NULL, NULL);
		assert_true(p.x == -1 || p.x == 4);
		assert_true(p.y == 2 || p.y == 5);
		assert_true(p.z == 3 || p.z == 9);
	}
	/* Unbounded: nothing. */
	assert_meshes_nothing(&endless, &options, &m);
	mesh_free(&m);
}

/* An unbounded shape's bounds hold the axes it is bounded along, and
 * -inf .. inf on the others. */
static void test_shape_bounds_partial_axes(void **state)
{
	struct scene *s = support_parse(scene_text);
	const struct material mat = { { 1, 1, 1 }, 0.4, 0.2, 0.2, 0.2, 10, 0.0, 1.0 };
	const struct shape endless = { &endless_ops, mat };
	struct aabb b;

	(void)state;
	assert_false(shape_bounds(s->shapes[2], &b));
	assert_near(b.min.x, -1.0, 0.0);
	assert_near(b.max.x, 3.0, 0.0);
	assert_true(b.min.y == -INFINITY && b.max.y == INFINITY);
	assert_near(b.min.z, 0.0, 0.0);
	assert_near(b.max.z, 5.0, 0.0);
	assert_false(shape_bounds(&endless, &b));
	assert_true(b.min.x == -INFINITY && b.min.y == -INFINITY && b.min.z == -INFINITY);
	assert_true(b.max.x == INFINITY && b.max.y == INFINITY && b.max.z == INFINITY);
	scene_destroy(s);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_shape_tessellate_every_primitive,
			   test_shape_tessellate_sphere_grid, test_shape_tessellate_triangle,
			   test_shape_tessellate_quadric_region,
			   test_shape_tessellate_floor_texture,
			   test_shape_tessellate_infinite_floor, test_shape_tessellate_fallback,
			   test_shape_bounds_partial_axes))
