/* What the viewer draws for a light and how OpenGL lights with it, as plain
 * geometry (no GL here, so that it can be tested): a spotlight's marker is
 * a cone of lines from the light along its axis, opening at its cutoff,
 * and its GL light is a GL spotlight when GL can have that cutoff. */
#ifndef RT_LIGHT_MARKER_H
#define RT_LIGHT_MARKER_H

#include "whitted/scene.h"
#include "whitted/vec3.h"

/* Lines from the apex to the rim, and around the rim. */
#define RT_LIGHT_MARKER_RIM 12

struct light_marker {
	struct vec3 apex;	/* the light's position */
	struct vec3 tip;	/* apex + length * axis: the end of the axis line */
	/* A spotlight's rim, each at distance length from the apex and at
	 * the angle cutoff_deg from the axis, evenly around it; n_rim is 0
	 * for a point light (its marker is the apex alone). */
	struct vec3 rim[RT_LIGHT_MARKER_RIM];
	int n_rim;
};

/* A unit vector perpendicular to the unit vector a. */
struct vec3 light_marker_perpendicular(struct vec3 a);

/* The marker of l with lines of the given length (> 0): for a spotlight of
 * unit axis a, cutoff c and the unit vectors e1 = perpendicular(a),
 * e2 = a x e1, rim point k is
 *   apex + length (cos c a + sin c (cos p e1 + sin p e2)),  p = 2 pi k / n,
 * and tip = apex + length a; for a point light tip = apex and n_rim = 0. */
void light_marker_make(const struct light *l, double length, struct light_marker *out);

/* GL_SPOT_CUTOFF for l: its cutoff in degrees when it is a spotlight of
 * cutoff <= 90 (GL allows [0, 90] and 180), else 180, a point light (a
 * cone wider than a half space lights nearly everything). */
double light_marker_gl_cutoff(const struct light *l);

/* GL's attenuation 1 / (1 + q d^2) for the format's exp(-falloff d^2):
 * q = falloff, equal to first order (and exact for falloff 0). */
double light_marker_gl_quadratic(const struct light *l);

#endif
