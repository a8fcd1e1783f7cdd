/* Axis-aligned bounding boxes, for shapes that have bounds and for the BVH. */
#ifndef RT_AABB_H
#define RT_AABB_H

#include "vec3.h"

struct aabb {
	struct vec3 min, max;
};

static inline struct aabb aabb_union(struct aabb a, struct aabb b)
{
	struct aabb u = { vec3_min(a.min, b.min), vec3_max(a.max, b.max) };
	return u;
}

static inline struct vec3 aabb_centre(struct aabb a)
{
	return vec3_scale(vec3_add(a.min, a.max), 0.5);
}

static inline double aabb_area(struct aabb a)
{
	struct vec3 e = vec3_sub(a.max, a.min);
	return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

#endif
