/* The registry: scene-file keywords to primitive tables, each table with
 * the dialects that name it and where it came from.  The built-in tables
 * come in by the same shape_registry_add as the plugins' do, on the first
 * call of any function here; a new built-in primitive is one file under
 * src/shapes/ and one line of RT_SHAPES.  Look-ups take a read lock (they
 * run while a scene is parsed, never per ray); adding takes the write lock
 * and rebuilds the keyword lists. */
#define _POSIX_C_SOURCE 200809L
#include <assert.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

#include "shapes/registry.h"
#include "whitted/scene.h"
#include "whitted/shape.h"

/* The built-in tables, in the order of the keyword lists, one line each:
 * X(name) is the table name_ops that a file of src/shapes/ exports (the
 * pyramid's two placements, pyramid_ops and pyramid_centred_ops, are two
 * tables of pyramid.c with one keyword and disjoint dialects). */
#define RT_SHAPES(X) \
	X(sphere) \
	X(triangle) \
	X(quadric) \
	X(pyramid) \
	X(pyramid_centred) \
	X(cube)

#define RT_SHAPE_DECLARE(name) extern const struct shape_ops name##_ops;
#define RT_SHAPE_ENTRY(name) &name##_ops,
RT_SHAPES(RT_SHAPE_DECLARE)

static const struct shape_ops *const builtin[] = {
	RT_SHAPES(RT_SHAPE_ENTRY)
	NULL,
};

/* Every mask of the dialects' bits, RT_DIALECT_BIT(0) to that of the last
 * dialect: the masks the keyword lists are built for. */
#define RT_DIALECT_MASKS (1u << RT_DIALECT_COUNT)

static pthread_rwlock_t lock = PTHREAD_RWLOCK_INITIALIZER;
static pthread_once_t builtin_once = PTHREAD_ONCE_INIT;
/* NULL-terminated; origins[i] is registry[i]'s (NULL: built-in). */
static const struct shape_ops *registry[RT_REGISTRY_MAX + 1];
static char *origins[RT_REGISTRY_MAX];
static size_t count;
static char keyword_lists[RT_DIALECT_MASKS][RT_KEYWORD_LIST_MAX];

/* A table is named in the dialects of a query when either mask is 0 or
 * they share a dialect; bits past the last dialect's are not dialects. */
static bool registry_meets(const struct shape_ops *ops, unsigned dialects)
{
	dialects &= RT_DIALECT_MASKS - 1;
	return dialects == 0 || ops->dialects == 0 || (ops->dialects & dialects) != 0;
}

static bool registry_is(const struct shape_ops *ops, const char *keyword, size_t len)
{
	return strlen(ops->keyword) == len && memcmp(ops->keyword, keyword, len) == 0;
}

/* The list for one mask: the keywords of the tables it meets, each once
 * (the pyramid's two tables give one "pyramid"), joined by ", ". */
static void registry_list(char *list, size_t size, unsigned dialects)
{
	size_t i, j, n = 0;

	for (i = 0; registry[i]; i++) {
		size_t len = strlen(registry[i]->keyword);
		bool seen = false;

		if (!registry_meets(registry[i], dialects))
			continue;
		for (j = 0; j < i && !seen; j++)
			seen = registry_meets(registry[j], dialects) &&
			       strcmp(registry[j]->keyword, registry[i]->keyword) == 0;
		if (seen)
			continue;
		/* RT_KEYWORD_LIST_MAX has room for every table's keyword. */
		assert(n + len + 3 <= size);
		if (n > 0) {
			memcpy(list + n, ", ", 2);
			n += 2;
		}
		memcpy(list + n, registry[i]->keyword, len);
		n += len;
	}
	list[n] = '\0';
}

static void registry_build_lists(void)
{
	unsigned m;

	for (m = 0; m < RT_DIALECT_MASKS; m++)
		registry_list(keyword_lists[m], sizeof(keyword_lists[m]), m);
}

static bool registry_same_origin(const char *a, const char *b)
{
	return a == b || (a && b && strcmp(a, b) == 0);
}

static bool registry_is_word(const char *k)
{
	const char *c;

	if (!((*k >= 'a' && *k <= 'z') || (*k >= 'A' && *k <= 'Z')))
		return false;
	for (c = k; *c; c++)
		if (!((*c >= 'a' && *c <= 'z') || (*c >= 'A' && *c <= 'Z') ||
		      (*c >= '0' && *c <= '9') || *c == '_'))
			return false;
	return c - k <= RT_SHAPE_KEYWORD_MAX;
}

/* Why the table cannot come in beside the registered ones and those of
 * tables[0..i), or 0. */
static int registry_check(const struct shape_ops *const *tables, size_t i, const char *origin,
			  struct diag *d)
{
	const struct shape_ops *ops = tables[i];
	size_t j;

	if (!ops->keyword || !registry_is_word(ops->keyword))
		return diag_fail(d, RT_E_INVALID,
				 "shape keyword '%s' is not a word (a letter, then letters, digits or '_'; at most %d)",
				 ops->keyword ? ops->keyword : "(null)", RT_SHAPE_KEYWORD_MAX);
	if (!ops->parse || !ops->intersect || !ops->normal || !ops->export_pov || !ops->destroy)
		return diag_fail(d, RT_E_INVALID,
				 "shape '%s' lacks a required method (parse, intersect, normal, export_pov, destroy)",
				 ops->keyword);
	for (j = 0; j < count; j++) {
		if (strcmp(registry[j]->keyword, ops->keyword) != 0)
			continue;
		if (!registry_same_origin(origins[j], origin) ||
		    registry_meets(registry[j], ops->dialects ? ops->dialects : RT_DIALECT_MASKS - 1))
			return diag_fail(d, RT_E_INVALID, "shape keyword '%s' is already defined by %s",
					 ops->keyword, origins[j] ? origins[j] : "whitted (built in)");
	}
	for (j = 0; j < i; j++)
		if (strcmp(tables[j]->keyword, ops->keyword) == 0 &&
		    registry_meets(tables[j], ops->dialects ? ops->dialects : RT_DIALECT_MASKS - 1))
			return diag_fail(d, RT_E_INVALID, "shape keyword '%s' is registered twice",
					 ops->keyword);
	return 0;
}

static int registry_add_locked(const struct shape_ops *const *tables, const char *origin,
			       struct diag *d)
{
	size_t i, n = 0;
	char *copy = NULL;
	int rc;

	while (tables[n])
		n++;
	if (count + n > RT_REGISTRY_MAX)
		return diag_fail(d, RT_E_RANGE, "too many shapes (at most %d)", RT_REGISTRY_MAX);
	for (i = 0; i < n; i++)
		if ((rc = registry_check(tables, i, origin, d)) < 0)
			return rc;
	for (i = 0; i < n; i++) {
		if (origin) {
			/* One copy per table, so that removing is one free each. */
			copy = malloc(strlen(origin) + 1);
			if (!copy) {
				while (i-- > 0)
					free(origins[--count]), registry[count] = NULL;
				return diag_fail(d, RT_E_NOMEM, "out of memory");
			}
			strcpy(copy, origin);
		}
		origins[count] = copy;
		registry[count++] = tables[i];
	}
	registry[count] = NULL;
	registry_build_lists();
	return 0;
}

static void registry_add_builtin(void)
{
	struct diag d;

	pthread_rwlock_wrlock(&lock);
	/* Cannot fail: the built-in tables are complete and distinct
	 * (tests/unit/shapes/test_registry.c). */
	registry_add_locked(builtin, NULL, &d);
	pthread_rwlock_unlock(&lock);
}

static void registry_ready(void)
{
	pthread_once(&builtin_once, registry_add_builtin);
}

int shape_registry_add(const struct shape_ops *const *tables, const char *origin,
		       struct diag *d)
{
	int rc;

	registry_ready();
	pthread_rwlock_wrlock(&lock);
	rc = registry_add_locked(tables, origin, d);
	pthread_rwlock_unlock(&lock);
	return rc;
}

void shape_registry_remove(const char *origin)
{
	size_t i, n = 0;

	registry_ready();
	pthread_rwlock_wrlock(&lock);
	for (i = 0; i < count; i++) {
		if (origin && origins[i] && strcmp(origins[i], origin) == 0) {
			free(origins[i]);
			continue;
		}
		origins[n] = origins[i];
		registry[n++] = registry[i];
	}
	for (i = n; i <= count; i++)
		registry[i] = NULL;
	count = n;
	registry_build_lists();
	pthread_rwlock_unlock(&lock);
}

const char *shape_registry_origin(const struct shape_ops *ops)
{
	const char *origin = NULL;
	size_t i;

	registry_ready();
	pthread_rwlock_rdlock(&lock);
	for (i = 0; i < count; i++)
		if (registry[i] == ops)
			origin = origins[i];
	pthread_rwlock_unlock(&lock);
	return origin;
}

bool shape_registry_has(const char *keyword, const char *origin)
{
	bool has = false;
	size_t i;

	registry_ready();
	pthread_rwlock_rdlock(&lock);
	for (i = 0; i < count && !has; i++)
		has = origins[i] && strcmp(origins[i], origin) == 0 &&
		      strcmp(registry[i]->keyword, keyword) == 0;
	pthread_rwlock_unlock(&lock);
	return has;
}

const struct shape_ops *shape_ops_find_in(const char *keyword, size_t len, unsigned dialects)
{
	const struct shape_ops *found = NULL;
	size_t i;

	registry_ready();
	pthread_rwlock_rdlock(&lock);
	for (i = 0; registry[i] && !found; i++)
		if (registry_meets(registry[i], dialects) && registry_is(registry[i], keyword, len))
			found = registry[i];
	pthread_rwlock_unlock(&lock);
	return found;
}

const struct shape_ops *shape_ops_find(const char *keyword, size_t len)
{
	return shape_ops_find_in(keyword, len, 0);
}

const struct shape_ops *const *shape_ops_all(void)
{
	registry_ready();
	return registry;
}

const char *shape_keywords_in(unsigned dialects)
{
	registry_ready();
	return keyword_lists[dialects & (RT_DIALECT_MASKS - 1)];
}

const char *shape_keywords(void)
{
	return shape_keywords_in(0);
}
