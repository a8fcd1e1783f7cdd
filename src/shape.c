/* The wrappers around the primitive tables, with the defaults of their
 * optional members in one place. */
#include <string.h>

#include "diag.h"
#include "shape.h"

struct color shape_color_at(const struct shape *s, struct vec3 p)
{
	return s->ops->color_at ? s->ops->color_at(s, p) : s->mat.color;
}

bool shape_is_textured(const struct shape *s)
{
	return s->ops->color_at != NULL;
}

bool shape_bounds(const struct shape *s, struct aabb *out)
{
	return s->ops->bounds ? s->ops->bounds(s, out) : false;
}

const char *shape_degenerate(const struct shape *s)
{
	return s->ops->degenerate ? s->ops->degenerate(s) : NULL;
}

void shape_geometry(const struct shape *s, struct shape_geometry *out)
{
	memset(out, 0, sizeof(*out));
	if (s->ops->geometry)
		s->ops->geometry(s, out);
}

int shape_export_pov(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	return s->ops->export_pov(s, out, opt);
}

void shape_destroy(struct shape *s)
{
	if (s)
		s->ops->destroy(s);
}
