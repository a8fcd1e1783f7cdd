/* The registry: scene-file keywords to primitive tables.  A new primitive
 * is one file under src/shapes/ and one line here. */
#include <string.h>

#include "shape.h"

extern const struct shape_ops sphere_ops;
extern const struct shape_ops triangle_ops;
extern const struct shape_ops quadric_ops;

static const struct shape_ops *const registry[] = {
	&sphere_ops,
	&triangle_ops,
	&quadric_ops,
	NULL,
};

const struct shape_ops *shape_ops_find(const char *keyword, size_t len)
{
	size_t i;

	for (i = 0; registry[i]; i++)
		if (strlen(registry[i]->keyword) == len &&
		    memcmp(registry[i]->keyword, keyword, len) == 0)
			return registry[i];
	return NULL;
}

const struct shape_ops *const *shape_ops_all(void)
{
	return registry;
}

const char *shape_keywords(void)
{
	static char list[256];
	size_t i, n = 0;

	if (list[0] != '\0')
		return list;
	for (i = 0; registry[i]; i++) {
		size_t len = strlen(registry[i]->keyword);
		if (n + len + 3 >= sizeof(list))
			break;
		if (i > 0) {
			memcpy(list + n, ", ", 2);
			n += 2;
		}
		memcpy(list + n, registry[i]->keyword, len);
		n += len;
	}
	list[n] = '\0';
	return list;
}
