/* The wrappers around the primitive tables, with the defaults of their
 * optional members in one place. */
#include <math.h>

#include "base/alloc.h"
#include "whitted/diag.h"
#include "whitted/mesh.h"
#include "whitted/parser.h"
#include "whitted/pov.h"
#include "shapes/shapes.h"
#include "whitted/shape.h"
#include "syntax/parser_impl.h"

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

void *shape_alloc(size_t size, const struct shape_ops *ops, const struct material *m)
{
	struct shape *s = rt_malloc(size);

	if (!s)
		return NULL;
	s->ops = ops;
	s->mat = *m;
	return s;
}

void shape_destroy_block(struct shape *s)
{
	rt_free(s);
}

void shape_pov_begin(FILE *out, const char *open, const struct vec3 *v, int n)
{
	int i;

	fputs(open, out);
	for (i = 0; i < n; i++) {
		if (i > 0)
			fputs(", ", out);
		pov_write_vector(out, v[i].x, v[i].y, v[i].z);
	}
}

int shape_pov_finish(const struct shape *s, FILE *out, const struct pov_options *opt)
{
	fputs("\n  ", out);
	pov_write_texture(out, &s->mat, opt);
	fputs("\n}\n", out);
	return ferror(out) ? -RT_E_IO : 0;
}

int shape_parse_point_size(struct parser *p, const char *what_point, const char *what_size,
			   shape_point_size_create *create, struct shape **out)
{
	struct material m;
	struct vec3 point;
	double size;
	int rc;

	*out = NULL;
	if ((rc = parser_vec3(p, what_point, &point)) < 0 ||
	    (rc = parser_size(p, what_size, &size)) < 0 ||
	    (rc = parser_material(p, &m)) < 0)
		return rc;
	*out = create(point, size, &m);
	return *out ? 0 : parser_fail(p, RT_E_NOMEM, "out of memory");
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
