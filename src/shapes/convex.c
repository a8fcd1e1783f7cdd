/* The methods of the solids bounded by planes (convex.h): the ray's
 * origin and the point are moved to the planes' reference point first. */
#include "shapes/convex.h"

bool convex_intersect(const struct shape *s, const struct ray *r, double t_min, double *t_max)
{
	const struct convex_solid *c = (const struct convex_solid *)s;
	struct ray local = { vec3_sub(r->origin, c->at), r->dir };
	double t;

	if (!solve_ray_convex(&local, c->face, c->faces, t_min, *t_max, &t))
		return false;
	*t_max = t;
	return true;
}

struct vec3 convex_normal(const struct shape *s, struct vec3 p)
{
	const struct convex_solid *c = (const struct convex_solid *)s;

	return c->face[solve_convex_face(c->face, c->faces, vec3_sub(p, c->at))].n;
}

bool convex_bounds(const struct shape *s, struct aabb *out)
{
	*out = ((const struct convex_solid *)s)->box;
	return true;
}

bool convex_flat(const struct shape *s)
{
	const struct aabb *b = &((const struct convex_solid *)s)->box;

	return !(b->max.x > b->min.x) || !(b->max.y > b->min.y) || !(b->max.z > b->min.z);
}
