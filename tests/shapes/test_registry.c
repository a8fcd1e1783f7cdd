/* The registry: every keyword found, unknown ones not, the keyword list,
 * and each table's required members. */
#include <string.h>

#include "support.h"

static void test_registry_finds_every_keyword(void **state)
{
	static const char *const keywords[] = { "sphere", "triangle", "general" };
	size_t i;

	(void)state;
	for (i = 0; i < 3; i++) {
		const struct shape_ops *ops = shape_ops_find(keywords[i], strlen(keywords[i]));
		assert_non_null(ops);
		assert_string_equal(ops->keyword, keywords[i]);
	}
}

static void test_registry_unknown_is_null(void **state)
{
	static const char *const unknown[] = {
		"", "s", "spher", "spheres", "Sphere", "SPHERE", "floor", "plane", "cube", "general ",
	};
	size_t i;

	(void)state;
	for (i = 0; i < sizeof(unknown) / sizeof(unknown[0]); i++)
		assert_null(shape_ops_find(unknown[i], strlen(unknown[i])));
	/* The length bounds the comparison: "sphere" within "spheres". */
	assert_non_null(shape_ops_find("spheres", 6));
	assert_null(shape_ops_find("sphere", 5));
}

static void test_registry_keyword_list(void **state)
{
	(void)state;
	assert_string_equal(shape_keywords(), "sphere, triangle, general");
	/* The list is built once and stays the same. */
	assert_ptr_equal(shape_keywords(), shape_keywords());
}

static void test_registry_tables_complete(void **state)
{
	const struct shape_ops *const *all = shape_ops_all();
	size_t i, j, n = 0;

	(void)state;
	for (i = 0; all[i]; i++) {
		const struct shape_ops *ops = all[i];
		assert_non_null(ops->keyword);
		assert_true(ops->keyword[0] != '\0');
		assert_non_null(ops->parse);
		assert_non_null(ops->intersect);
		assert_non_null(ops->normal);
		assert_non_null(ops->export_pov);
		assert_non_null(ops->destroy);
		/* Found by its own keyword, and the keyword is in the list. */
		assert_ptr_equal(shape_ops_find(ops->keyword, strlen(ops->keyword)), ops);
		assert_non_null(strstr(shape_keywords(), ops->keyword));
		for (j = 0; j < i; j++)
			assert_string_not_equal(all[j]->keyword, ops->keyword);
		n++;
	}
	assert_int_equal(n, 3);
}

static void test_registry_every_keyword_parses(void **state)
{
	/* Each registered keyword reads from a file. */
	struct scene *s = support_parse(
		"1 1 3\n"
		"sphere 0 0 0 1  1 1 1  0 0 0 0 0\n"
		"triangle 0 0 0 1 0 0 0 1 0  1 1 1  0 0 0 0 0\n"
		"general 1 1 1 0 0 0 0 0 0 -1  0 0 0 0 0 0  1 1 1  0 0 0 0 0\n"
		"0\n");

	(void)state;
	assert_int_equal(s->n_shapes, 3);
	assert_ptr_equal(s->shapes[0]->ops, shape_ops_find("sphere", 6));
	assert_ptr_equal(s->shapes[1]->ops, shape_ops_find("triangle", 8));
	assert_ptr_equal(s->shapes[2]->ops, shape_ops_find("general", 7));
	scene_destroy(s);
}

int main(int argc, char **argv)
{
	const struct CMUnitTest tests[] = {
		cmocka_unit_test(test_registry_finds_every_keyword),
		cmocka_unit_test(test_registry_unknown_is_null),
		cmocka_unit_test(test_registry_keyword_list),
		cmocka_unit_test(test_registry_tables_complete),
		cmocka_unit_test(test_registry_every_keyword_parses),
	};
	return SUPPORT_RUN(tests, argc, argv);
}
