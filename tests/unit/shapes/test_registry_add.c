/* The registry's one way in, shape_registry_add, as plugins use it: a
 * table comes in with its origin and is found in every dialect, the
 * keyword lists grow, a table with a keyword already registered (a
 * built-in's, even in other dialects, or another origin's) or a missing
 * method or a keyword that is no word is refused with a message and
 * nothing added, all or none of a set comes in, and removing an origin
 * takes its tables out again. */
#include <stdio.h>
#include <string.h>

#include "shapes/registry.h"
#include "support.h"

static int fake_parse(struct parser *p, struct shape **out)
{
	(void)p;
	*out = NULL;
	return -RT_E_SYNTAX;
}

static bool fake_intersect(const struct shape *s, const struct ray *r, double t_min, double *t_max)
{
	(void)s, (void)r, (void)t_min, (void)t_max;
	return false;
}

static struct vec3 fake_normal(const struct shape *s, struct vec3 p)
{
	(void)s;
	return p;
}

static int fake_export(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	(void)s, (void)out, (void)opt;
	return 0;
}

static void fake_destroy(struct shape *s)
{
	(void)s;
}

#define FAKE(kw, mask) { .keyword = kw, .dialects = mask, .parse = fake_parse, \
	.intersect = fake_intersect, .normal = fake_normal, .export_pov = fake_export, \
	.destroy = fake_destroy }

static const struct shape_ops blob = FAKE("blob", 0);
static const struct shape_ops drop = FAKE("drop", 0);
static const struct shape_ops cube_classic = FAKE("cube", RT_DIALECT_BIT(RT_DIALECT_CLASSIC));
static const struct shape_ops sphere_again = FAKE("sphere", 0);
static const struct shape_ops no_word = FAKE("9ball", 0);
static const struct shape_ops no_parse = { .keyword = "lazy", .intersect = fake_intersect,
	.normal = fake_normal, .export_pov = fake_export, .destroy = fake_destroy };

static void test_registry_add_and_remove(void **state)
{
	const struct shape_ops *const set[] = { &blob, &drop, NULL };
	char before[2048];
	struct diag d;

	(void)state;
	snprintf(before, sizeof(before), "%s", shape_keywords());
	assert_null(shape_ops_find("blob", 4));
	assert_int_equal(shape_registry_add(set, "/x/blob.so", &d), 0);
	assert_ptr_equal(shape_ops_find("blob", 4), &blob);
	assert_ptr_equal(shape_ops_find_in("drop", 4, RT_DIALECT_BIT(RT_DIALECT_NEARFAR)), &drop);
	assert_string_equal(shape_registry_origin(&blob), "/x/blob.so");
	assert_null(shape_registry_origin(shape_ops_find("sphere", 6)));
	/* After the built-ins, in the order given, in every dialect's list. */
	{
		char want[2100];

		snprintf(want, sizeof(want), "%s, blob, drop", before);
		assert_string_equal(shape_keywords(), want);
	}
	assert_non_null(strstr(shape_keywords_in(RT_DIALECT_BIT(RT_DIALECT_PYRAMID)), ", blob, drop"));
	shape_registry_remove("/x/blob.so");
	assert_null(shape_ops_find("blob", 4));
	assert_null(shape_registry_origin(&blob));
	assert_string_equal(shape_keywords(), before);
}

static void test_registry_add_refuses(void **state)
{
	const struct shape_ops *const clash_builtin[] = { &sphere_again, NULL };
	const struct shape_ops *const other_dialect[] = { &cube_classic, NULL };
	const struct shape_ops *const half[] = { &drop, &no_word, NULL };
	const struct shape_ops *const lazy[] = { &no_parse, NULL };
	const struct shape_ops *const first[] = { &blob, NULL };
	char before[2048];
	struct diag d;

	(void)state;
	snprintf(before, sizeof(before), "%s", shape_keywords());
	assert_int_equal(shape_registry_add(clash_builtin, "a.so", &d), -RT_E_INVALID);
	assert_string_equal(d.msg, "shape keyword 'sphere' is already defined by whitted (built in)");
	/* The built-in cube is nearfar's only, but a plugin's keyword must
	 * be its own in every dialect of other origins too. */
	assert_int_equal(shape_registry_add(other_dialect, "a.so", &d), -RT_E_INVALID);
	assert_string_equal(d.msg, "shape keyword 'cube' is already defined by whitted (built in)");
	assert_int_equal(shape_registry_add(half, "a.so", &d), -RT_E_INVALID);
	assert_string_equal(d.msg,
			    "shape keyword '9ball' is not a word (a letter, then letters, digits or '_'; at most 64)");
	assert_null(shape_ops_find("drop", 4));
	assert_int_equal(shape_registry_add(lazy, "a.so", &d), -RT_E_INVALID);
	assert_non_null(strstr(d.msg, "shape 'lazy' lacks a required method"));
	assert_int_equal(shape_registry_add(first, "/p/one.so", &d), 0);
	assert_int_equal(shape_registry_add(first, "/p/two.so", &d), -RT_E_INVALID);
	assert_string_equal(d.msg, "shape keyword 'blob' is already defined by /p/one.so");
	shape_registry_remove("/p/one.so");
	assert_string_equal(shape_keywords(), before);
}

/* A full registry of the longest keywords: every keyword is in the lists,
 * none cut off (the lists have room for them all), then one more table is
 * refused as too many; a keyword one letter too long is no word. */
static char long_keywords[RT_REGISTRY_MAX][RT_SHAPE_KEYWORD_MAX + 1];
static struct shape_ops long_tables[RT_REGISTRY_MAX];
static const struct shape_ops *long_set[RT_REGISTRY_MAX + 1];

static void test_registry_full_of_long_keywords(void **state)
{
	static char expected[RT_KEYWORD_LIST_MAX + 1];
	const struct shape_ops *const *all;
	const struct shape_ops tail = FAKE("tail", 0), *const one_more[] = { &tail, NULL };
	char too_long[RT_SHAPE_KEYWORD_MAX + 2];
	const struct shape_ops longer = FAKE(too_long, 0), *const longer_set[] = { &longer, NULL };
	size_t i, n_builtin, room;
	struct diag d;

	(void)state;
	for (n_builtin = 0, all = shape_ops_all(); all[n_builtin]; n_builtin++)
		;
	room = RT_REGISTRY_MAX - n_builtin;
	for (i = 0; i < room; i++) {
		const struct shape_ops fake = FAKE(long_keywords[i], 0);

		/* k0000000...0042: 64 characters, each its own. */
		snprintf(long_keywords[i], sizeof(long_keywords[i]), "k%0*zu", RT_SHAPE_KEYWORD_MAX - 1, i);
		long_tables[i] = fake;
		long_set[i] = &long_tables[i];
	}
	long_set[room] = NULL;
	assert_int_equal(strlen(long_keywords[0]), RT_SHAPE_KEYWORD_MAX);
	assert_int_equal(shape_registry_add(long_set, "/p/many.so", &d), 0);
	/* The expected list, built from the tables themselves. */
	assert_int_equal(support_keyword_list(expected, sizeof(expected)), RT_REGISTRY_MAX);
	assert_string_equal(shape_keywords(), expected);
	assert_non_null(strstr(shape_keywords(), long_keywords[room - 1]));
	assert_true(strlen(shape_keywords()) > 2048);
	assert_int_equal(shape_registry_add(one_more, "/p/tail.so", &d), -RT_E_RANGE);
	shape_registry_remove("/p/many.so");
	assert_null(strstr(shape_keywords(), long_keywords[0]));
	memset(too_long, 'k', sizeof(too_long) - 1);
	too_long[sizeof(too_long) - 1] = '\0';
	assert_int_equal(shape_registry_add(longer_set, "/p/long.so", &d), -RT_E_INVALID);
	assert_non_null(strstr(d.msg, "is not a word"));
}

SUPPORT_MAIN(SUPPORT_TESTS(test_registry_add_and_remove, test_registry_add_refuses,
			   test_registry_full_of_long_keywords))
