/* A ray: origin and direction.  Shapes accept any non-zero direction; the
 * renderer always passes unit directions so that t is a distance. */
#ifndef RT_RAY_H
#define RT_RAY_H

#include "vec3.h"

struct ray {
	struct vec3 origin;
	struct vec3 dir;
};

static inline struct vec3 ray_at(const struct ray *r, double t)
{
	return vec3_add_scaled(r->origin, r->dir, t);
}

#endif
