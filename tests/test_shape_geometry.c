/* shape_geometry: each primitive describes itself with its file's numbers. */
#include "support.h"
#include "shape.h"

static const char scene_text[] =
	"1 10 3\n"
	"sphere 1 2 3 4  1 0 0  0.4 0.2 0.2 0.2 10\n"
	"triangle 0 0 0  1 0 0  0 1 5  0 1 0  0.4 0.2 0.2 0.2 10\n"
	"general 1 1 1 0 0 0 -20 -20 -20 200  -1 -2 0  4 0 5  0 0 1  0.4 0.2 0.1 0.3 3\n"
	"0\n";

static void test_shape_geometry_primitives(void **state)
{
	struct scene *s = support_parse(scene_text);
	static const double coef[10] = { 1, 1, 1, 0, 0, 0, -20, -20, -20, 200 };
	struct shape_geometry g;
	int k;

	(void)state;
	assert_int_equal(s->n_shapes, 3);
	shape_geometry(s->shapes[0], &g);
	assert_int_equal(g.kind, RT_SHAPE_SPHERE);
	assert_vec3_near(g.u.sphere.centre, vec3_make(1, 2, 3), 0.0);
	assert_near(g.u.sphere.radius, 4.0, 0.0);

	shape_geometry(s->shapes[1], &g);
	assert_int_equal(g.kind, RT_SHAPE_TRIANGLE);
	assert_vec3_near(g.u.triangle.v[0], vec3_make(0, 0, 0), 0.0);
	assert_vec3_near(g.u.triangle.v[1], vec3_make(1, 0, 0), 0.0);
	assert_vec3_near(g.u.triangle.v[2], vec3_make(0, 1, 5), 0.0);

	shape_geometry(s->shapes[2], &g);
	assert_int_equal(g.kind, RT_SHAPE_QUADRIC);
	for (k = 0; k < 10; k++)
		assert_near(g.u.quadric.coef[k], coef[k], 0.0);
	assert_vec3_near(g.u.quadric.lo, vec3_make(-1, -2, 0), 0.0);
	assert_vec3_near(g.u.quadric.hi, vec3_make(3, -2, 5), 0.0);
	assert_true(g.u.quadric.clipped[0]);
	assert_false(g.u.quadric.clipped[1]);
	assert_true(g.u.quadric.clipped[2]);
	scene_destroy(s);
}

static void test_shape_geometry_floor(void **state)
{
	struct shape *fl = floor_create(600.0, 15.0);
	struct shape_geometry g;

	(void)state;
	assert_non_null(fl);
	shape_geometry(fl, &g);
	assert_int_equal(g.kind, RT_SHAPE_FLOOR);
	assert_near(g.u.floor.width, 600.0, 0.0);
	assert_near(g.u.floor.tile, 15.0, 0.0);
	shape_destroy(fl);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_shape_geometry_primitives),
		cmocka_unit_test(test_shape_geometry_floor),
	};
	return SUPPORT_RUN(tests, argc, argv);
}
