/* The registry: every keyword found, unknown ones not, the keyword list,
 * and each table's required members; the dialects: each table found in
 * its own dialects and only there, one table per keyword in each, and the
 * keyword list of each dialect. */
#include <pthread.h>
#include <stdio.h>
#include <string.h>

#include "support.h"

/* The dialects a file can be read as (not RT_DIALECT_AUTO). */
static const enum scene_dialect dialects[] = {
	RT_DIALECT_CLASSIC, RT_DIALECT_SPOT, RT_DIALECT_PYRAMID, RT_DIALECT_NEARFAR,
};
#define N_DIALECTS (sizeof(dialects) / sizeof(dialects[0]))

/* True when the table is named in dialect d. */
static bool in_dialect(const struct shape_ops *ops, enum scene_dialect d)
{
	return ops->dialects == 0 || (ops->dialects & RT_DIALECT_BIT(d)) != 0;
}

/* True when word is one of the ", "-separated entries of list. */
static bool listed(const char *list, const char *word)
{
	size_t len = strlen(word);
	const char *at = list;

	while ((at = strstr(at, word)) != NULL) {
		bool starts = at == list || (at >= list + 2 && at[-2] == ',' && at[-1] == ' ');
		bool ends = at[len] == '\0' || at[len] == ',';
		if (starts && ends)
			return true;
		at++;
	}
	return false;
}

/* Every registered table is found by its keyword in each of its dialects,
 * and a keyword names one table in each dialect; the course's three
 * primitives are among them.  shape_ops_find gives the first table of a
 * keyword. */
static void test_registry_finds_every_keyword(void **state)
{
	static const char *const course[] = { "sphere", "triangle", "general" };
	const struct shape_ops *const *all = shape_ops_all();
	size_t i, j, k, n = 0;

	(void)state;
	for (i = 0; all[i]; i++, n++) {
		const char *kw = all[i]->keyword;
		const struct shape_ops *first = NULL;
		for (j = 0; j <= i && !first; j++)
			if (strcmp(all[j]->keyword, kw) == 0)
				first = all[j];
		assert_ptr_equal(shape_ops_find(kw, strlen(kw)), first);
		assert_ptr_equal(shape_ops_find_in(kw, strlen(kw), 0), first);
		for (k = 0; k < N_DIALECTS; k++) {
			if (!in_dialect(all[i], dialects[k]))
				continue;
			assert_ptr_equal(shape_ops_find_in(kw, strlen(kw), RT_DIALECT_BIT(dialects[k])),
					 all[i]);
			for (j = 0; j < i; j++)
				if (in_dialect(all[j], dialects[k]))
					assert_string_not_equal(all[j]->keyword, kw);
		}
	}
	assert_true(n >= 3);
	for (i = 0; i < 3; i++)
		assert_non_null(shape_ops_find(course[i], strlen(course[i])));
}

/* The masks the contract gives the course's keywords: sphere everywhere;
 * triangle and general in classic, spot and pyramid; pyramid in the
 * pyramid dialect (from a corner) and nearfar (from the base's centre),
 * two tables; cube in nearfar only. */
static void test_registry_dialect_masks(void **state)
{
	static const struct {
		const char *keyword;
		bool in[4];	/* classic, spot, pyramid, nearfar */
	} want[] = {
		{ "sphere", { true, true, true, true } },
		{ "triangle", { true, true, true, false } },
		{ "general", { true, true, true, false } },
		{ "pyramid", { false, false, true, true } },
		{ "cube", { false, false, false, true } },
	};
	const struct shape_ops *sphere = shape_ops_find("sphere", 6);
	const struct shape_ops *pyr = shape_ops_find_in("pyramid", 7, RT_DIALECT_BIT(RT_DIALECT_PYRAMID));
	const struct shape_ops *nf = shape_ops_find_in("pyramid", 7, RT_DIALECT_BIT(RT_DIALECT_NEARFAR));
	size_t i, k;

	(void)state;
	for (i = 0; i < sizeof(want) / sizeof(want[0]); i++) {
		const char *kw = want[i].keyword;
		for (k = 0; k < N_DIALECTS; k++) {
			const struct shape_ops *ops =
				shape_ops_find_in(kw, strlen(kw), RT_DIALECT_BIT(dialects[k]));
			if ((ops != NULL) != want[i].in[k]) {
				print_error("%s in the %s dialect: %s\n", kw, scene_dialect_name(dialects[k]),
					    ops ? "found" : "not found");
				fail();
			}
			if (!listed(shape_keywords_in(RT_DIALECT_BIT(dialects[k])), kw) == want[i].in[k]) {
				print_error("%s in the %s dialect's list \"%s\"\n", kw,
					    scene_dialect_name(dialects[k]),
					    shape_keywords_in(RT_DIALECT_BIT(dialects[k])));
				fail();
			}
		}
		/* Any dialect (0): found, and listed once. */
		assert_non_null(shape_ops_find_in(kw, strlen(kw), 0));
		assert_true(listed(shape_keywords(), kw));
	}
	/* The sphere's table is for every dialect; the pyramid's two differ. */
	assert_int_equal(sphere->dialects, 0);
	assert_non_null(pyr);
	assert_non_null(nf);
	assert_ptr_not_equal(pyr, nf);
	assert_int_equal(pyr->dialects & nf->dialects, 0);
	/* A mask of several dialects finds the first table of any of them. */
	assert_ptr_equal(shape_ops_find_in("pyramid", 7, RT_DIALECT_BIT(RT_DIALECT_CLASSIC) |
							       RT_DIALECT_BIT(RT_DIALECT_NEARFAR)), nf);
	assert_null(shape_ops_find_in("cube", 4, RT_DIALECT_BIT(RT_DIALECT_CLASSIC) |
						 RT_DIALECT_BIT(RT_DIALECT_SPOT)));
	/* Bits past the last dialect's are no dialect: ignored. */
	assert_ptr_equal(shape_ops_find_in("cube", 4, 1u << 20), shape_ops_find("cube", 4));
	assert_ptr_equal(shape_keywords_in(1u << 20), shape_keywords());
}

/* A table of mask 0 (the sphere's, a plugin's, or one that does not say)
 * is in every dialect, and under any mask at all. */
static void test_registry_mask_zero_is_every_dialect(void **state)
{
	const struct shape_ops *sphere = shape_ops_find("sphere", 6);
	size_t k;

	(void)state;
	for (k = 0; k < N_DIALECTS; k++)
		assert_ptr_equal(shape_ops_find_in("sphere", 6, RT_DIALECT_BIT(dialects[k])), sphere);
	assert_ptr_equal(shape_ops_find_in("sphere", 6, RT_DIALECT_BIT(RT_DIALECT_AUTO)), sphere);
}

/* Each dialect's list: the keywords of the tables it finds, in the
 * registry's order, each once, joined by ", "; the same pointer each time
 * (built once). */
static void test_registry_keyword_list_per_dialect(void **state)
{
	const struct shape_ops *const *all = shape_ops_all();
	unsigned mask;

	(void)state;
	for (mask = 0; mask < 2u * RT_DIALECT_BIT(RT_DIALECT_NEARFAR); mask++) {
		char expected[512] = "";
		size_t i, j;
		for (i = 0; all[i]; i++) {
			const char *kw = all[i]->keyword;
			bool seen = false;
			if (shape_ops_find_in(kw, strlen(kw), mask) != all[i])
				continue;
			for (j = 0; j < i; j++)
				seen = seen || (strcmp(all[j]->keyword, kw) == 0 &&
						shape_ops_find_in(kw, strlen(kw), mask) == all[j]);
			if (seen)
				continue;
			if (expected[0])
				strcat(expected, ", ");
			strcat(expected, kw);
		}
		assert_string_equal(shape_keywords_in(mask), expected);
		assert_ptr_equal(shape_keywords_in(mask), shape_keywords_in(mask));
	}
	/* nearfar's list has no triangle, classic's no pyramid or cube. */
	assert_false(listed(shape_keywords_in(RT_DIALECT_BIT(RT_DIALECT_NEARFAR)), "triangle"));
	assert_true(listed(shape_keywords_in(RT_DIALECT_BIT(RT_DIALECT_NEARFAR)), "cube"));
	assert_false(listed(shape_keywords_in(RT_DIALECT_BIT(RT_DIALECT_CLASSIC)), "pyramid"));
	assert_false(listed(shape_keywords_in(RT_DIALECT_BIT(RT_DIALECT_CLASSIC)), "cube"));
	assert_ptr_equal(shape_keywords_in(0), shape_keywords());
}

/* The lists are built once, whichever thread asks first. */
static void *keywords_thread(void *arg)
{
	unsigned mask;

	(void)arg;
	for (mask = 0; mask < 2u * RT_DIALECT_BIT(RT_DIALECT_NEARFAR); mask++)
		if (strstr(shape_keywords_in(mask), "sphere") != shape_keywords_in(mask))
			return (void *)1;
	return NULL;
}

static void test_registry_keyword_lists_threads(void **state)
{
	pthread_t th[4];
	void *rc;
	int i;

	(void)state;
	for (i = 0; i < 4; i++)
		assert_int_equal(pthread_create(&th[i], NULL, keywords_thread, NULL), 0);
	for (i = 0; i < 4; i++) {
		assert_int_equal(pthread_join(th[i], &rc), 0);
		assert_null(rc);
	}
}

static void test_registry_unknown_is_null(void **state)
{
	static const char *const unknown[] = {
		"", "s", "spher", "spheres", "Sphere", "SPHERE", "floor", "nosuchshape", "sphere2", "general ",
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
	char expected[512];

	/* The registry's keywords in its order, each once (the pyramid's
	 * two tables give one entry), joined by ", ". */
	support_keyword_list(expected, sizeof(expected));
	(void)state;
	assert_string_equal(shape_keywords(), expected);
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
		/* Found by its own keyword in its own dialects, and the
		 * keyword is in the list; only the dialects of enum
		 * scene_dialect (RT_DIALECT_AUTO is none). */
		assert_ptr_equal(shape_ops_find_in(ops->keyword, strlen(ops->keyword), ops->dialects),
				 ops);
		assert_true(listed(shape_keywords(), ops->keyword));
		assert_int_equal(ops->dialects & ~(2u * RT_DIALECT_BIT(RT_DIALECT_NEARFAR) - 1u), 0);
		assert_int_equal(ops->dialects & RT_DIALECT_BIT(RT_DIALECT_AUTO), 0);
		for (j = 0; j < i; j++)
			if (strcmp(all[j]->keyword, ops->keyword) == 0) {
				assert_true(all[j]->dialects != 0 && ops->dialects != 0);
				assert_int_equal(all[j]->dialects & ops->dialects, 0);
			}
		n++;
	}
	assert_true(n >= 3);
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

SUPPORT_MAIN(SUPPORT_TESTS(test_registry_finds_every_keyword, test_registry_dialect_masks,
			   test_registry_mask_zero_is_every_dialect,
			   test_registry_keyword_list_per_dialect,
			   test_registry_keyword_lists_threads, test_registry_unknown_is_null,
			   test_registry_keyword_list, test_registry_tables_complete,
			   test_registry_every_keyword_parses))
