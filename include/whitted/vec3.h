/* Three-component vectors in double precision, used for points, directions
 * and (through struct color) radiance.  Everything is inline because these
 * run on every ray. */
#ifndef RT_VEC3_H
#define RT_VEC3_H

#include <math.h>

struct vec3 {
	double x, y, z;
};

static inline struct vec3 vec3_make(double x, double y, double z)
{
	struct vec3 v = { x, y, z };
	return v;
}

static inline struct vec3 vec3_add(struct vec3 a, struct vec3 b)
{
	return vec3_make(a.x + b.x, a.y + b.y, a.z + b.z);
}

static inline struct vec3 vec3_sub(struct vec3 a, struct vec3 b)
{
	return vec3_make(a.x - b.x, a.y - b.y, a.z - b.z);
}

static inline struct vec3 vec3_scale(struct vec3 a, double s)
{
	return vec3_make(a.x * s, a.y * s, a.z * s);
}

/* a + s * b, the ray-point form used everywhere. */
static inline struct vec3 vec3_add_scaled(struct vec3 a, struct vec3 b, double s)
{
	return vec3_make(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s);
}

static inline struct vec3 vec3_neg(struct vec3 a)
{
	return vec3_make(-a.x, -a.y, -a.z);
}

static inline double vec3_dot(struct vec3 a, struct vec3 b)
{
	return a.x * b.x + a.y * b.y + a.z * b.z;
}

static inline struct vec3 vec3_cross(struct vec3 a, struct vec3 b)
{
	return vec3_make(a.y * b.z - a.z * b.y,
			 a.z * b.x - a.x * b.z,
			 a.x * b.y - a.y * b.x);
}

static inline double vec3_length(struct vec3 a)
{
	return sqrt(vec3_dot(a, a));
}

/* The zero vector stays zero rather than becoming NaN; callers that need a
 * direction check for that case themselves. */
static inline struct vec3 vec3_normalize(struct vec3 a)
{
	double len = vec3_length(a);
	return len > 0.0 ? vec3_scale(a, 1.0 / len) : a;
}

static inline double vec3_component(struct vec3 a, int axis)
{
	return axis == 0 ? a.x : axis == 1 ? a.y : a.z;
}

static inline struct vec3 vec3_min(struct vec3 a, struct vec3 b)
{
	return vec3_make(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z));
}

static inline struct vec3 vec3_max(struct vec3 a, struct vec3 b)
{
	return vec3_make(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z));
}

static inline int vec3_is_finite(struct vec3 a)
{
	return isfinite(a.x) && isfinite(a.y) && isfinite(a.z);
}

#endif
