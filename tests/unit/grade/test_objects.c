/* The object-id buffer (which object each pixel's primary ray meets, the
 * floor and the background apart), the figures object by object, and
 * the difference picture's ties, outlines and legend. */
#include <math.h>
#include <string.h>

#include "base/alloc.h"
#include "grade/grade_impl.h"
#include "grade_fixture.h"
#include "support.h"

/* A red sphere of radius 25 at the origin, half under the floor, seen from the
 * default camera (0, -200, 10) at 41 pixels: the middle pixel sees the
 * sphere, the top row the sky, the bottom row the floor. */
static const char one_sphere[] =
	"1\n41\n1\nsphere\n0 0 0\n25\n1 0 0\n0.4 0.2 0.2 0.2\n5\n1\n0 -100 100\n";

struct world {
	struct scene *s;
	struct camera cam;
	struct grade_job job;
	struct image ref;
	int32_t ids[41 * 41];
};

static void world_make(struct world *w)
{
	struct camera_params p;
	struct diag d;

	w->s = grade_fixture_scene(one_sphere, &p);
	assert_int_equal(camera_init(&w->cam, &p, 41, &d), 0);
	grade_fixture_job(&w->job, w->s, &w->cam, 1, 2);
	assert_int_equal(grade_render_reference(&w->job, &w->ref, &d), 0);
	assert_int_equal(grade_object_ids(&w->job, w->ids, &d), 0);
}

static void world_free(struct world *w)
{
	image_free(&w->ref);
	scene_destroy(w->s);
}

static void test_grade_object_ids(void **state)
{
	struct world w;
	int x;

	(void)state;
	world_make(&w);
	assert_int_equal(w.ids[20 * 41 + 20], 0);
	for (x = 0; x < 41; x++) {
		assert_int_equal(w.ids[x], GRADE_ID_BACKGROUND);
		assert_int_equal(w.ids[40 * 41 + x], GRADE_ID_FLOOR);
	}
	/* A pixel's id is the object whose colour it has: red where 0. */
	for (x = 0; x < 41 * 41; x++)
		if (w.ids[x] == 0)
			assert_true(w.ref.pixels[3 * x] > w.ref.pixels[3 * x + 1]);
	world_free(&w);
}

static void test_grade_objects_figures(void **state)
{
	struct world w;
	struct grade_object *o;
	struct image sub;
	size_t n, k, i;
	long sphere = 0;
	struct diag d;

	(void)state;
	world_make(&w);
	assert_int_equal(image_alloc(&sub, 41, 41, &d), 0);
	memcpy(sub.pixels, w.ref.pixels, 41 * 41 * 3);
	/* Every pixel of the sphere 10 levels greener. */
	for (i = 0; i < 41 * 41; i++)
		if (w.ids[i] == 0) {
			sub.pixels[3 * i + 1] += 10;
			sphere++;
		}
	assert_int_equal(grade_objects(&w.job, w.ids, &w.ref, &sub, NULL, &o, &n, &d), 0);
	assert_int_equal(n, 3);
	assert_string_equal(o[0].keyword, "background");
	assert_string_equal(o[1].keyword, "floor");
	assert_string_equal(o[2].keyword, "sphere");
	assert_int_equal(o[2].index, 1);
	assert_int_equal(o[2].pixels, sphere);
	assert_int_equal(o[2].differ, sphere);
	assert_near(o[2].off2, 1.0, 0.0);
	assert_near(o[2].psnr, 10.0 * log10(255.0 * 255.0 * 3.0 / 100.0), 1e-9);
	for (k = 0; k < 2; k++) {
		assert_true(isinf(o[k].psnr));
		assert_int_equal(o[k].differ, 0);
	}
	assert_int_equal(o[0].pixels + o[1].pixels + o[2].pixels, 41 * 41);
	rt_free(o);
	image_free(&sub);
	world_free(&w);
}

static void test_grade_diff_picture(void **state)
{
	static const uint8_t blue[3] = { 30, 50, 110 }, cyan[3] = { 0, 230, 230 };
	struct world w;
	struct image sub, out;
	uint8_t ties[41 * 41] = { 0 }, differs[3] = { 0, 0, 1 };
	struct diag d;
	size_t i;
	int x, y, outline = 0, legend = 0;

	(void)state;
	world_make(&w);
	assert_int_equal(image_alloc(&sub, 41, 41, &d), 0);
	memcpy(sub.pixels, w.ref.pixels, 41 * 41 * 3);
	ties[5] = 1;
	assert_int_equal(grade_diff_picture(&w.ref, &sub, ties, w.ids, differs, &out, &d), 0);
	assert_int_equal(out.width, 82);
	assert_int_equal(out.height, 41 + 11);
	/* The tie, blue, on the right. */
	assert_memory_equal(out.pixels + 3 * (41 + 5), blue, 3);
	/* The sphere's outline in cyan, and only at an edge of its pixels. */
	for (y = 0; y < 41; y++)
		for (x = 0; x < 41; x++) {
			const uint8_t *p = out.pixels + 3 * ((size_t)y * 82 + 41 + (size_t)x);
			if (memcmp(p, cyan, 3) != 0)
				continue;
			outline++;
			i = (size_t)y * 41 + (size_t)x;
			assert_int_equal(w.ids[i], 0);
			assert_true(w.ids[i - 1] != 0 || w.ids[i + 1] != 0 || w.ids[i - 41] != 0 || w.ids[i + 41] != 0);
		}
	assert_true(outline > 10);
	/* The legend: something drawn in the band. */
	for (i = (size_t)41 * 82 * 3; i < (size_t)out.height * 82 * 3; i++)
		legend += out.pixels[i] != 0;
	assert_true(legend > 100);
	image_free(&out);
	image_free(&sub);
	world_free(&w);
}

SUPPORT_MAIN(SUPPORT_TESTS(test_grade_object_ids, test_grade_objects_figures,
			   test_grade_diff_picture))
