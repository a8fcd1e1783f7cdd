/* The wrappers around the primitive tables, with the defaults of their
 * optional members in one place. */
#include <math.h>

#include "whitted/diag.h"
#include "whitted/mesh.h"
#include "shapes/shapes.h"
#include "whitted/shape.h"

bool shape_is_textured(const struct shape *s)
{
	return s->ops->color_at != NULL;
}

bool shape_bounds(const struct shape *s, struct aabb *out)
{
	out->min = vec3_make(-INFINITY, -INFINITY, -INFINITY);
	out->max = vec3_make(INFINITY, INFINITY, INFINITY);
	return s->ops->bounds ? s->ops->bounds(s, out) : false;
}

const char *shape_degenerate(const struct shape *s)
{
	return s->ops->degenerate ? s->ops->degenerate(s) : NULL;
}

bool shape_closed_always(const struct shape *s)
{
	(void)s;
	return true;
}

bool shape_closed(const struct shape *s)
{
	return s->ops->closed && s->ops->closed(s);
}

bool shape_tessellates(const struct shape *s)
{
	return s->ops->tessellate != NULL;
}

int shape_tessellate(const struct shape *s, const struct mesh_options *opt, struct mesh *out)
{
	struct aabb box;

	if (s->ops->tessellate)
		return s->ops->tessellate(s, opt, out);
	return shape_bounds(s, &box) ? mesh_box(out, box) : 0;
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
