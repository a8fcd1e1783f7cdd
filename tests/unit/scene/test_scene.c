/* The scene model's lights and view: the dialects' names, the checks and
 * the completion of scene_add_light_full, the default view and its
 * accessors, and the floor each view describes. */
#include <math.h>
#include <string.h>

#include "support.h"

static const double pi = 3.14159265358979323846;

static struct light spot_make(struct vec3 pos, struct vec3 axis, double cutoff)
{
	struct light l;

	memset(&l, 0, sizeof(l));
	l.pos = pos;
	l.color = color_make(1, 1, 1);
	l.spot = true;
	l.axis = axis;
	l.cutoff_deg = cutoff;
	return l;
}

static void test_scene_dialect_names(void **state)
{
	(void)state;
	assert_string_equal(scene_dialect_name(RT_DIALECT_AUTO), "auto");
	assert_string_equal(scene_dialect_name(RT_DIALECT_CLASSIC), "classic");
	assert_string_equal(scene_dialect_name(RT_DIALECT_SPOT), "spot");
	assert_string_equal(scene_dialect_name(RT_DIALECT_PYRAMID), "pyramid");
	assert_string_equal(scene_dialect_name(RT_DIALECT_NEARFAR), "nearfar");
	assert_null(scene_dialect_name((enum scene_dialect)99));
	/* The masks of different dialects do not meet. */
	assert_int_equal(RT_DIALECT_BIT(RT_DIALECT_SPOT) & RT_DIALECT_BIT(RT_DIALECT_NEARFAR), 0);
	assert_int_equal(RT_DIALECT_BIT(RT_DIALECT_CLASSIC), 2u);
}

/* scene_add_light is scene_add_light_full of a point light without
 * falloff; both keep the order of adding. */
static void test_scene_lights_in_order(void **state)
{
	struct scene *s = scene_create("t");
	struct light l = spot_make(vec3_make(1, 2, 3), vec3_make(0, 0, -2), 30);
	struct diag d;

	(void)state;
	assert_int_equal(scene_add_light(s, vec3_make(4, 5, 6), color_make(1, 0.5, 0), &d), 0);
	assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	assert_int_equal(scene_light_count(s), 2);
	assert_vec3_near(scene_light(s, 0)->pos, vec3_make(4, 5, 6), 0);
	assert_false(scene_light(s, 0)->spot);
	assert_true(scene_light(s, 0)->falloff == 0.0);
	assert_true(scene_light(s, 1)->spot);
	assert_vec3_near(scene_light(s, 1)->pos, vec3_make(1, 2, 3), 0);
	assert_null(scene_light(s, 2));
	scene_destroy(s);
}

/* The axis is made unit and cos_cutoff filled, exactly at the right
 * angles; a point light's spot members are zeroed whatever they held. */
static void test_scene_light_full_completes(void **state)
{
	struct scene *s = scene_create("t");
	struct light l = spot_make(vec3_make(0, 0, 0), vec3_make(3, 0, 4), 60);
	struct diag d;

	(void)state;
	assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	assert_vec3_near(scene_light(s, 0)->axis, vec3_make(0.6, 0, 0.8), 1e-15);
	assert_near(scene_light(s, 0)->cos_cutoff, cos(60 * pi / 180), 0);
	assert_near(scene_light(s, 0)->cutoff_deg, 60, 0);
	l.cutoff_deg = 90;
	assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	assert_true(scene_light(s, 1)->cos_cutoff == 0.0);
	l.cutoff_deg = 180;
	assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	assert_true(scene_light(s, 2)->cos_cutoff == -1.0);
	l.spot = false;
	l.falloff = 2e-6;
	assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	assert_false(scene_light(s, 3)->spot);
	assert_true(scene_light(s, 3)->cutoff_deg == 0.0 && scene_light(s, 3)->cos_cutoff == 0.0);
	assert_vec3_near(scene_light(s, 3)->axis, vec3_make(0, 0, 0), 0);
	assert_true(scene_light(s, 3)->falloff == 2e-6);
	/* The caller's struct is not changed. */
	assert_vec3_near(l.axis, vec3_make(3, 0, 4), 0);
	scene_destroy(s);
}

static void expect_range(struct scene *s, const struct light *l, const char *words)
{
	struct diag d;

	diag_clear(&d);
	assert_int_equal(scene_add_light_full(s, l, &d), -RT_E_RANGE);
	if (!strstr(d.msg, words)) {
		print_error("message '%s' does not mention '%s'\n", d.msg, words);
		fail();
	}
}

static void test_scene_light_full_range(void **state)
{
	static const double bad_cutoff[] = { 0.0, -1.0, 180.000001, 360.0 };
	struct scene *s = scene_create("t");
	struct light l = spot_make(vec3_make(0, 0, 10), vec3_make(0, 0, -1), 30);
	size_t i;

	(void)state;
	l.axis = vec3_make(0, 0, 0);
	expect_range(s, &l, "axis is zero");
	l.axis = vec3_make(NAN, 0, 1);
	expect_range(s, &l, "axis");
	l.axis = vec3_make(1e308, 1e308, 0);
	expect_range(s, &l, "axis");
	l.axis = vec3_make(0, 0, -1);
	for (i = 0; i < sizeof(bad_cutoff) / sizeof(bad_cutoff[0]); i++) {
		l.cutoff_deg = bad_cutoff[i];
		expect_range(s, &l, "cutoff");
	}
	l.cutoff_deg = NAN;
	expect_range(s, &l, "cutoff");
	l.cutoff_deg = 30;
	l.falloff = -1e-9;
	expect_range(s, &l, "falloff");
	l.falloff = INFINITY;
	expect_range(s, &l, "falloff");
	l.falloff = 0;
	l.color = color_make(1, -0.1, 0);
	expect_range(s, &l, "colour");
	l.color = color_make(1, 1, 1);
	l.pos.x = INFINITY;
	expect_range(s, &l, "position");
	/* A point light's axis and cutoff are not looked at. */
	l.pos.x = 0;
	l.spot = false;
	l.axis = vec3_make(0, 0, 0);
	l.cutoff_deg = -5;
	assert_int_equal(scene_add_light_full(s, &l, NULL), 0);
	assert_int_equal(scene_light_count(s), 1);
	scene_destroy(s);
}

/* A scene counts its lights with a cone or a falloff: the renderer's
 * classic path is taken only when there is none. */
static void test_scene_special_lights_counted(void **state)
{
	struct scene *s = scene_create("t");
	struct light l = spot_make(vec3_make(0, 0, 10), vec3_make(0, 0, -1), 30);
	struct diag d;

	(void)state;
	assert_int_equal(scene_add_light(s, vec3_make(0, 0, 1), color_make(1, 1, 1), &d), 0);
	l.spot = false;
	assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	assert_int_equal(s->n_special_lights, 0);
	l.falloff = 1e-3;
	assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	assert_int_equal(s->n_special_lights, 1);
	l.falloff = 0;
	l.spot = true;
	assert_int_equal(scene_add_light_full(s, &l, &d), 0);
	assert_int_equal(s->n_special_lights, 2);
	scene_destroy(s);
}

static void assert_classic_floor_mat(const struct material *m)
{
	assert_true(m->ka == 0.4 && m->kd == 0.2 && m->ks == 0.2 && m->kr == 0.2 &&
		    m->shininess == 1.0);
}

static void test_scene_view_default(void **state)
{
	struct scene_view v;
	struct scene *s = scene_create("t");

	(void)state;
	scene_view_default(&v);
	assert_int_equal(v.dialect, RT_DIALECT_CLASSIC);
	assert_true(v.fov_deg == 80.0);
	assert_true(v.near == 0.0 && v.far == 0.0 && v.aspect == 0.0);
	assert_true(v.floor_width == RT_FLOOR_WIDTH && v.floor_cell == RT_FLOOR_TILE);
	assert_classic_floor_mat(&v.floor_mat);
	/* A new scene has it. */
	assert_memory_equal(scene_view_of(s), &v, sizeof(v));
	scene_destroy(s);
}

static void test_scene_set_view(void **state)
{
	struct scene_view v;
	struct scene *s = scene_create("t");

	(void)state;
	scene_view_default(&v);
	v.dialect = RT_DIALECT_NEARFAR;
	v.fov_deg = 70;
	v.near = 1;
	v.far = 1000;
	v.aspect = 1.5;
	v.floor_width = INFINITY;
	v.floor_cell = 50;
	v.floor_mat.ka = 0.1;
	scene_set_view(s, &v);
	v.fov_deg = 10;
	assert_int_equal(scene_view_of(s)->dialect, RT_DIALECT_NEARFAR);
	assert_true(scene_view_of(s)->fov_deg == 70 && scene_view_of(s)->aspect == 1.5);
	assert_true(scene_view_of(s)->floor_width == INFINITY);
	scene_destroy(s);
}

/* The view's floor: nearfar's infinite checkerboard with the file's
 * coefficients (cell (floor(x / CELL), floor(y / CELL)), white when even),
 * the pyramid dialect's 30-wide tiles, and the checks. */
static void test_scene_add_view_floor(void **state)
{
	struct scene_view v;
	struct scene *s = scene_create("t");
	const struct shape *fl;
	struct ray down = support_ray(-1e6, 3e5, 10, 0, 0, -1);
	double t = INFINITY;
	struct diag d;

	(void)state;
	scene_view_default(&v);
	v.floor_width = INFINITY;
	v.floor_cell = 50;
	v.floor_mat.ka = 0.1;
	v.floor_mat.kd = 0.3;
	v.floor_mat.ks = 0;
	v.floor_mat.kr = 0.6;
	scene_set_view(s, &v);
	assert_int_equal(scene_add_view_floor(s, &d), 0);
	assert_int_equal(scene_shape_count(s), 1);
	fl = scene_shape(s, 0);
	assert_true(fl->mat.ka == 0.1 && fl->mat.kd == 0.3 && fl->mat.ks == 0 && fl->mat.kr == 0.6);
	/* Far beyond any finite floor. */
	assert_true(shape_intersect(fl, &down, 1e-9, &t));
	assert_near(t, 10, 1e-9);
	/* (-1e6 / 50, 3e5 / 50) = (-20000, 6000): even, white; one cell over,
	 * black; and across x = 0, y = 0 the parity follows floor(). */
	assert_true(shape_color_at(fl, vec3_make(-1e6 + 1, 3e5 + 1, 0)).r == 1.0);
	assert_true(shape_color_at(fl, vec3_make(-1e6 - 1, 3e5 + 1, 0)).r == 0.0);
	assert_true(shape_color_at(fl, vec3_make(1, 1, 0)).r == 1.0);
	assert_true(shape_color_at(fl, vec3_make(-1, 1, 0)).r == 0.0);
	assert_true(shape_color_at(fl, vec3_make(-1, -1, 0)).r == 1.0);
	assert_true(shape_color_at(fl, vec3_make(49, -49, 0)).r == 0.0);
	assert_true(shape_color_at(fl, vec3_make(49, -51, 0)).r == 1.0);

	/* The pyramid view's floor: 1000 wide, 30-wide tiles from -500. */
	scene_view_default(&v);
	v.dialect = RT_DIALECT_PYRAMID;
	v.floor_cell = 30;
	scene_set_view(s, &v);
	assert_int_equal(scene_add_view_floor(s, &d), 0);
	fl = scene_shape(s, 1);
	assert_classic_floor_mat(&fl->mat);
	/* x = -500 + 15: tile 0; x = -500 + 45: tile 1. */
	assert_true(shape_color_at(fl, vec3_make(-485, -485, 0)).r == 1.0);
	assert_true(shape_color_at(fl, vec3_make(-455, -485, 0)).r == 0.0);
	t = INFINITY;
	down = support_ray(600, 0, 10, 0, 0, -1);
	assert_false(shape_intersect(fl, &down, 1e-9, &t));

	v.floor_cell = 0;
	scene_set_view(s, &v);
	assert_int_equal(scene_add_view_floor(s, &d), -RT_E_RANGE);
	v.floor_cell = INFINITY;
	scene_set_view(s, &v);
	assert_int_equal(scene_add_view_floor(s, &d), -RT_E_RANGE);
	v.floor_cell = 20;
	v.floor_width = -INFINITY;
	scene_set_view(s, &v);
	assert_int_equal(scene_add_view_floor(s, &d), -RT_E_RANGE);
	v.floor_width = NAN;
	scene_set_view(s, &v);
	assert_int_equal(scene_add_view_floor(s, &d), -RT_E_RANGE);
	v.floor_width = 1000;
	v.floor_mat.kr = -0.5;
	scene_set_view(s, &v);
	assert_int_equal(scene_add_view_floor(s, &d), -RT_E_RANGE);
	assert_non_null(strstr(d.msg, "coefficients"));
	assert_int_equal(scene_shape_count(s), 2);
	scene_destroy(s);
}

/* The classic view's floor is scene_add_floor's, field for field. */
static void test_scene_view_floor_is_classic_floor(void **state)
{
	struct scene *a = scene_create("a"), *b = scene_create("b");
	struct diag d;
	int i;

	(void)state;
	assert_int_equal(scene_add_view_floor(a, &d), 0);
	assert_int_equal(scene_add_floor(b, RT_FLOOR_WIDTH, RT_FLOOR_TILE, &d), 0);
	assert_memory_equal(&scene_shape(a, 0)->mat, &scene_shape(b, 0)->mat,
			    sizeof(struct material));
	for (i = -30; i <= 30; i++) {
		struct vec3 p = vec3_make(i * 17.3, i * -11.9, 0);
		struct color ca = shape_color_at(scene_shape(a, 0), p);
		struct color cb = shape_color_at(scene_shape(b, 0), p);
		assert_memory_equal(&ca, &cb, sizeof(ca));
	}
	scene_destroy(a);
	scene_destroy(b);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_scene_dialect_names, test_scene_lights_in_order,
			   test_scene_light_full_completes, test_scene_light_full_range,
			   test_scene_special_lights_counted, test_scene_view_default,
			   test_scene_set_view, test_scene_add_view_floor,
			   test_scene_view_floor_is_classic_floor))
