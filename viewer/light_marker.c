/* The lights' markers and GL light parameters (light_marker.h).  The rim
 * of a spotlight's cone is the circle of directions at the angle cutoff
 * from the axis, cos c a + sin c (cos p e1 + sin p e2) for p around a turn,
 * scaled to the lines' length. */
#include <math.h>

#include "light_marker.h"

struct vec3 light_marker_perpendicular(struct vec3 a)
{
	/* Crossing with the world axis least along a keeps the product far
	 * from zero: its length is at least sqrt(2/3). */
	double x = fabs(a.x), y = fabs(a.y), z = fabs(a.z);
	struct vec3 w = x <= y && x <= z ? vec3_make(1, 0, 0)
		      : y <= z ? vec3_make(0, 1, 0) : vec3_make(0, 0, 1);

	return vec3_normalize(vec3_cross(a, w));
}

void light_marker_make(const struct light *l, double length, struct light_marker *out)
{
	const double pi = 3.14159265358979323846;
	struct vec3 a, e1, e2;
	double co, si;
	int k;

	out->apex = l->pos;
	out->tip = l->pos;
	out->n_rim = 0;
	if (!l->spot)
		return;
	a = vec3_normalize(l->axis);
	e1 = light_marker_perpendicular(a);
	e2 = vec3_cross(a, e1);
	co = cos(l->cutoff_deg * pi / 180.0);
	si = sin(l->cutoff_deg * pi / 180.0);
	out->tip = vec3_add_scaled(l->pos, a, length);
	for (k = 0; k < RT_LIGHT_MARKER_RIM; k++) {
		double p = 2.0 * pi * k / RT_LIGHT_MARKER_RIM;
		struct vec3 around = vec3_add_scaled(vec3_scale(e1, cos(p)), e2, sin(p));
		struct vec3 dir = vec3_add_scaled(vec3_scale(a, co), around, si);

		out->rim[k] = vec3_add_scaled(l->pos, dir, length);
	}
	out->n_rim = RT_LIGHT_MARKER_RIM;
}

double light_marker_gl_cutoff(const struct light *l)
{
	return l->spot && l->cutoff_deg <= 90.0 ? l->cutoff_deg : 180.0;
}

double light_marker_gl_quadratic(const struct light *l)
{
	return l->falloff;
}
